"""The lab's acceptance checks of tensile specimens and chains.

A chain in the run sheet may declare the limits of the standard the lab tests
to; only declared limits are checked:

``proof_force_kN``
    the specimen carried the proof force (its maximum force reached it);
``min_breaking_force_kN``
    its maximum (breaking) force is at least this (not measured when it did not
    break below the limit, as in a proof-load test);
``max_elongation_at_proof_pct``
    its elongation at the proof force, relative to the gauge length, is at most
    this (not measured when the proof force was not reached);
``min_elongation_at_fracture_pct``
    its elongation at fracture (total, under load) is at least this (not
    measured when it did not break).

Each verdict is 1 (pass), 0 (fail) or -1 (declared but not measured on this
specimen) and :data:`NOT_DECLARED` where the chain declares no such limit. A
chain passes a check when every specimen measured passes it.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

#: Verdict codes.
PASS, FAIL, NOT_MEASURED, NOT_DECLARED = 1, 0, -1, -2

#: Check name -> (figure compared [SI], which side passes, run-sheet key of the limit).
CHECKS = {
    "proof_force": ("max_force", "at_least", "proof_force_kN"),
    "breaking_force": ("max_force", "at_least", "min_breaking_force_kN"),
    "elongation_at_proof": ("strain_at_proof", "at_most", "max_elongation_at_proof_pct"),
    "elongation_at_fracture": ("strain_at_fracture", "at_least",
                               "min_elongation_at_fracture_pct"),
}

#: Meanings of the verdict codes, in flag order -2..1 (CF ``flag_meanings``).
VERDICTS = ("not_declared", "not_measured", "fail", "pass")


def limits_si(declared: Mapping[str, float | None]) -> dict[str, float]:
    """The declared limits in SI: forces [N], elongations as strains [1].

    Parameters
    ----------
    declared : mapping
        Run-sheet key (``"proof_force_kN"``...) -> value or None.

    Returns
    -------
    dict
        Check name -> limit, for the declared limits only.

    Examples
    --------
    >>> limits_si({"min_breaking_force_kN": 410, "max_elongation_at_proof_pct": 1.6})
    {'breaking_force': 410000.0, 'elongation_at_proof': 0.016}
    """
    limits = {}
    for check, (_, _, key) in CHECKS.items():
        value = declared.get(key)
        if value is not None:
            limits[check] = float(value) * (1e3 if key.endswith("_kN") else 1e-2)
    return limits


def specimen_verdicts(figures: Mapping[str, float], limits: Mapping[str, float]) -> dict[str, int]:
    """Verdict of each check on one specimen.

    Parameters
    ----------
    figures : mapping
        The specimen's figures [SI] (:class:`~pipeline.fit.strength.Strength`).
    limits : mapping
        Check name -> limit [SI], from :func:`limits_si`.

    Returns
    -------
    dict
        Check name -> :data:`PASS`, :data:`FAIL`, :data:`NOT_MEASURED` or
        :data:`NOT_DECLARED`, for every check of :data:`CHECKS`.

    Examples
    --------
    >>> verdicts = specimen_verdicts(
    ...     {"max_force": 4.2e5, "strain_at_proof": np.nan, "strain_at_fracture": 0.15,
    ...      "fracture_force": 4.1e5},
    ...     {"breaking_force": 4.1e5, "elongation_at_proof": 0.016})
    >>> verdicts["breaking_force"], verdicts["elongation_at_proof"], verdicts["proof_force"]
    (1, -1, -2)
    """
    verdicts = {}
    for check, (figure, side, _) in CHECKS.items():
        if check not in limits:
            verdicts[check] = NOT_DECLARED
            continue
        value = float(figures.get(figure, np.nan))
        if not np.isfinite(value):
            verdicts[check] = NOT_MEASURED
            continue
        passed = value >= limits[check] if side == "at_least" else value <= limits[check]
        unbroken = not np.isfinite(float(figures.get("fracture_force", np.nan)))
        if check == "breaking_force" and not passed and unbroken:
            verdicts[check] = NOT_MEASURED  # it was not taken to fracture
            continue
        verdicts[check] = PASS if passed else FAIL
    return verdicts


def chain_verdict(verdicts: Sequence[int]) -> int:
    """A chain's verdict on one check from its specimens': fail if any failed, pass if every
    measured one passed, else not measured (or not declared)."""
    codes = set(verdicts)
    if not codes or codes == {NOT_DECLARED}:
        return NOT_DECLARED
    if FAIL in codes:
        return FAIL
    return PASS if PASS in codes else NOT_MEASURED
