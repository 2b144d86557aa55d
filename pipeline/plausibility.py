"""Plausibility of a run's results: is a value off by a unit slip?

A column in N labelled kN, or a gauge in mm labelled m, passes every fit and
gives a result off by a factor 1000. The checks here compare each result with
what is known beforehand, flag the run when it is far out, and name the unit
slip that would explain the factor. All values are SI: forces and E0 [N],
strains [1] (a fraction, not %).

The checks and their bands
--------------------------
``E0`` against the theory
    outside [1/3, 3] x the chain's theoretical E0. Paper 001's Table 1 has
    experiment and theory 3-8 % apart; a factor 3 is far beyond any genuine
    discrepancy and well below the smallest unit slip (9.81).
``E0`` against the chain's other specimens
    with at least :data:`MIN_SPECIMENS` specimens with an E0 on the chain,
    outside [1/2, 2] x the median of the largest group of them that agree with
    each other within that band, when that group is a majority. Specimens of
    one chain scatter by a few % in E0, so a factor 2 is only a slip or a broken
    measurement. A flagged specimen is never in the group, so it is judged
    against the others only. The group, not the plain median of the others, is
    the reference because with three specimens the "median" of two others is
    their mean, which one slipped specimen drags 500-fold. Specimens flagged
    against the theory (and not accepted) take no part, so a slip shared by
    most specimens falls on them and not on the good one; without a theory such
    a majority cannot be told from a good minority, which is then flagged.
``max_force`` against the chain's breaking force
    above 3 x or below 1/100 x the (minimum) breaking force. A test to fracture
    legitimately exceeds the minimum breaking force by 10-40 %, hence the factor
    3. A proof-load test stops near half of it and a stiffness test cycles up
    to 10-30 % of it, so the low side is judged loosely: below 1 % of the
    breaking force a test has not even reached the usual preload (2-5 %), while
    a force in kN read as N lands at 0.15 % or less.
``max_force`` against the machine's capacity
    above 1.05 x the capacity (5 % for an overload the machine lets through).
strains
    ``strain_at_max_force`` or ``strain_at_fracture`` above 0.5 (50 %): steel
    chains break at some 10-30 % total elongation.
``N_u1``, ``N_u2`` against the impact model
    the measured median outside [1/3, 3] x the model with Ryabov's k = 2: as for
    E0, far beyond the model's error and well below the smallest slip.

NaN (not measured) and missing references are not checked.

The probable slip
-----------------
The known factors (:data:`SLIPS`), in order of how often they happen in a lab
(for each kind of quantity: the first applies to strains only, the second is
the commonest for forces):

* 100: a strain in % read as a fraction (for strains and E0; for E0 it cannot
  be told from kgf and kN, factor 102, which the same entry names);
* 1000: N and kN; mm and m (or µm and mm) for elongations;
* 9.80665: kgf and N (or tf and kN) for forces and E0;
* 1000 / 9.80665 = 102: kgf and kN for forces;
* 25.4: inches and mm for elongations, hence strains and E0, never forces;
* 10^6: N and MN for forces, a strain in µm/m (microstrain, the unit of strain
  gauges) read as a fraction; kept because microstrain channels are common
  and nothing else comes near the factor.

A slip is named when undoing it brings the ratio value / reference within the
spread a genuine value can have: by default ``[1/1.5, 1.5]``, which takes a
genuine discrepancy of up to 50 % on top of the slip (a factor 1000 on a 5 %
discrepancy gives 1050) and is the widest round tolerance that keeps 9.81 and
25.4 apart (their windows would touch at 1.61). A ratio of 3.5 is then
explained by nothing. The forces and strains of a test spread wider (a test
may stop at any fraction of the breaking force), so their checks pass wider
spreads; when several factors fit, the most common slip is named.

Examples
--------
>>> flags = check_specimens(
...     {"T1": {"chain": "c18", "E0": 1.05e10, "max_force": 2.0e8,
...             "strain_at_max_force": 0.02, "strain_at_fracture": float("nan")}},
...     E0_theory={"c18": 1.0e7}, breaking_force={"c18": 4.1e5}, capacity=5.0e5,
...     accepted=set())
>>> [(flag.quantity, flag.against, round(flag.ratio)) for flag in flags]
... # doctest: +NORMALIZE_WHITESPACE
[('E0', 'theory', 1050), ('max_force', 'breaking force', 488),
 ('max_force', 'machine capacity', 400)]
>>> print(flags[0].message)  # doctest: +NORMALIZE_WHITESPACE
T1: E0 = 1.05e+07 kN is 1050 x the theory (10000 kN): probably a force in N labelled kN,
or an elongation in mm labelled µm (or m labelled mm) (factor 1000). Check the units of
the run's columns, or set accept_implausible = true on the run if the value is right.
>>> sorted(excluded(flags))
['T1']
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.units import STANDARD_GRAVITY

#: Band of value / theory (E0, impact tensions) inside which nothing is flagged.
THEORY_BAND = (1 / 3, 3.0)
#: Band of E0 / the chain's other specimens.
PEER_BAND = (1 / 2, 2.0)
#: Fewest specimens with an E0 on a chain for the check against the others.
MIN_SPECIMENS = 3
#: Band of max_force / the chain's minimum breaking force.
BREAKING_BAND = (1 / 100, 3.0)
#: max_force / the machine's capacity above which a run is flagged.
CAPACITY_TOLERANCE = 1.05
#: Strain [1] above which a strain is flagged.
STRAIN_LIMIT = 0.5

#: Spread of value / reference a genuine value can have, after undoing a slip:
#: against a theory or the other specimens (a genuine discrepancy up to 50 %),
TIGHT_SPREAD = (1 / 1.5, 1.5)
#: max force against the breaking force (from a stiffness test at 10 % to a fracture at 150 %),
BREAKING_SPREAD = (0.1, 1.5)
#: max force against the capacity (1 % is the usual bottom of a machine's verified range),
CAPACITY_SPREAD = (0.01, CAPACITY_TOLERANCE)
#: strain against :data:`STRAIN_LIMIT` (a genuine strain of 0.05 % to 50 %).
STRAIN_SPREAD = (0.001, 1.0)

#: Quantity -> (what it is a measure of, its label in messages).
QUANTITIES = {
    "E0": ("stiffness", "E0"),
    "max_force": ("force", "max force"),
    "strain_at_max_force": ("strain", "strain at max force"),
    "strain_at_fracture": ("strain", "strain at fracture"),
    "N_u1": ("force", "N_u1"),
    "N_u2": ("force", "N_u2"),
}

_HINT = ("Check the units of the run's columns, or set accept_implausible = true on the run "
         "if the value is right.")
_ACCEPTED = "Accepted: accept_implausible = true on the run."


@dataclass(frozen=True)
class Slip:
    """A known unit slip: a factor and what causes it, per kind of quantity.

    ``up`` and ``down`` map ``"force"``, ``"stiffness"`` or ``"strain"`` to the
    cause when the value is `factor` times too large, respectively too small;
    a kind it cannot apply to is absent.
    """

    factor: float
    up: Mapping[str, str]
    down: Mapping[str, str]


#: The known slips, most common first (a strain's % first: for forces it does not apply).
SLIPS = (
    Slip(100.0,
         up={"stiffness": "a strain given as a fraction but labelled %, or a force in kgf "
                          "labelled kN (factor 102)",
             "strain": "a strain in % read as a fraction"},
         down={"stiffness": "a strain in % read as a fraction, or a force in kN labelled kgf "
                            "(factor 1/102)",
               "strain": "a strain given as a fraction but labelled %"}),
    Slip(1000.0,
         up={"force": "a force in N labelled kN",
             "stiffness": "a force in N labelled kN, or an elongation in mm labelled µm "
                          "(or m labelled mm)",
             "strain": "an elongation in mm labelled m (or µm labelled mm), or a gauge length "
                       "in m written as mm"},
         down={"force": "a force in kN labelled N",
               "stiffness": "a force in kN labelled N, or an elongation in mm labelled m "
                            "(or µm labelled mm)",
               "strain": "an elongation in m labelled mm"}),
    Slip(STANDARD_GRAVITY,
         up={"force": "a force in N labelled kgf (or kN labelled tf)",
             "stiffness": "a force in N labelled kgf (or kN labelled tf)"},
         down={"force": "a force in kgf labelled N (or tf labelled kN)",
               "stiffness": "a force in kgf labelled N (or tf labelled kN)"}),
    Slip(1000.0 / STANDARD_GRAVITY,
         up={"force": "a force in kgf labelled kN"},
         down={"force": "a force in kN labelled kgf"}),
    Slip(25.4,
         up={"stiffness": "an elongation in inches labelled mm",
             "strain": "an elongation in mm labelled inches, or a gauge length in inches "
                       "written as mm"},
         down={"stiffness": "an elongation in mm labelled inches, or a gauge length in inches "
                            "written as mm",
               "strain": "an elongation in inches labelled mm"}),
    Slip(1e6,
         up={"force": "a force in N labelled MN",
             "stiffness": "a force in N labelled MN",
             "strain": "a strain in µm/m read as a fraction, or an elongation in µm labelled m"},
         down={"force": "a force in MN labelled N",
               "stiffness": "a strain in µm/m read as a fraction, or a force in MN labelled N",
               "strain": "a strain given as a fraction but labelled µm/m"}),
)


def _number(value: float) -> str:
    """`value` to 3 significant digits, without an exponent where it is short.

    >>> _number(1050.4), _number(1.0204e7), _number(0.000123)
    ('1050', '1.02e+07', '0.000123')
    """
    return f"{float(f'{value:.3g}'):g}"


def _times(ratio: float) -> str:
    """A ratio in words: ``"1050 x"`` above 1, ``"1/1000 of"`` below."""
    if 0 < ratio < 1:
        return f"1/{_number(1 / ratio)} of"
    return f"{_number(ratio)} x"


def _with_unit(value: float, quantity: str) -> str:
    """A value of `quantity` [SI] as a technician reads it: forces in kN, strains in %."""
    if QUANTITIES[quantity][0] == "strain":
        return f"{_number(100 * value)} %"
    return f"{_number(value / 1e3)} kN"


#: Reference kind -> how a message names it.
_REFERENCES = {
    "theory": "the theory",
    "breaking force": "the chain's breaking force",
    "machine capacity": "the machine's capacity",
    "the chain's other specimens": "the median of the chain's other specimens",
    "strain limit": "the strain limit",
    "impact model": "the impact model with k = 2",
}


@dataclass(frozen=True)
class Flag:
    """A result far from what is known, with the unit slip that probably caused it."""

    run_id: str
    quantity: str  #: a key of :data:`QUANTITIES`
    value: float  #: the flagged value [N] or [1]
    reference: float  #: what it was judged against [N] or [1]
    against: str  #: "theory", "breaking force", "machine capacity", ...
    ratio: float  #: value / reference [1]
    slip: str | None  #: the probable slip, None when no known one explains the ratio
    accepted: bool  #: the run sheet accepts the run (``accept_implausible = true``)

    @property
    def message(self) -> str:
        """One line for the technician: the numbers, the probable slip, what to do."""
        label = QUANTITIES[self.quantity][1]
        text = (f"{self.run_id}: {label} = {_with_unit(self.value, self.quantity)} is "
                f"{_times(self.ratio)} {_REFERENCES.get(self.against, self.against)} "
                f"({_with_unit(self.reference, self.quantity)})")
        cause = (f"probably {self.slip}" if self.slip
                 else "no known unit slip explains the factor")
        return f"{text}: {cause}. {_ACCEPTED if self.accepted else _HINT}"


def _kind(quantity: str) -> str:
    """What `quantity` is a measure of: ``"force"``, ``"stiffness"`` or ``"strain"``."""
    if quantity not in QUANTITIES:
        raise ValueError(f"unknown quantity {quantity!r}; known: {', '.join(QUANTITIES)}")
    return QUANTITIES[quantity][0]


def probable_slip(ratio: float, quantity: str, *,
                  spread: tuple[float, float] = TIGHT_SPREAD) -> str | None:
    """The known unit slip that best explains a value `ratio` times its reference.

    Parameters
    ----------
    ratio : float
        The value over its reference [1].
    quantity : str
        A key of :data:`QUANTITIES`: which slips can apply (inches never to
        forces, kgf never to strains).
    spread : tuple of float
        The range [1] of value / reference a genuine value can have: a slip of
        factor f is a candidate when ``ratio / f`` falls within it.

    Returns
    -------
    str or None
        The cause and the factor (``"a force in N labelled kN (factor 1000)"``)
        of every candidate, the most common first (the order of :data:`SLIPS`),
        or None: a value far off within a wide spread may fit more than one.

    Examples
    --------
    >>> probable_slip(1050, "max_force")
    'a force in N labelled kN (factor 1000)'
    >>> probable_slip(1 / 9.81, "N_u1")
    'a force in kgf labelled N (or tf labelled kN) (factor 1/9.81)'
    >>> probable_slip(25.4, "max_force") is None  # inches do not apply to forces
    True
    >>> probable_slip(3.5, "E0") is None
    True
    """
    kind = _kind(quantity)
    if not (math.isfinite(ratio) and ratio > 0):
        return None
    low, high = spread
    found = [f"{causes[kind]} (factor {shown})" for slip in SLIPS
             for factor, causes, shown in ((slip.factor, slip.up, _number(slip.factor)),
                                           (1 / slip.factor, slip.down,
                                            f"1/{_number(slip.factor)}"))
             if kind in causes and low <= ratio / factor <= high]
    return ", or ".join(found) or None


def _outside(ratio: float, band: tuple[float, float]) -> bool:
    """Whether `ratio` lies outside `band` (bounds inclusive, up to rounding)."""
    low, high = band
    return not (low * (1 - 1e-9) <= ratio <= high * (1 + 1e-9))


def _finite(value: object) -> float | None:
    """`value` as a float, or None when it is missing or NaN."""
    if value is None:
        return None
    value = float(value)
    return value if math.isfinite(value) else None


def _judge(run_id: str, quantity: str, value: object, reference: object, against: str,
           band: tuple[float, float], accepted: Collection[str],
           spread: tuple[float, float] = TIGHT_SPREAD) -> Flag | None:
    """A flag when `value` / `reference` falls outside `band`; None when inside or not
    measured (NaN) or without a (positive) reference."""
    value, reference = _finite(value), _finite(reference)
    if value is None or reference is None or reference <= 0:
        return None
    ratio = value / reference
    if not _outside(ratio, band):
        return None
    return Flag(run_id=run_id, quantity=quantity, value=value, reference=reference,
                against=against, ratio=ratio, slip=probable_slip(ratio, quantity, spread=spread),
                accepted=run_id in accepted)


def _specimen_flags(run_id: str, row: Mapping, *, E0_theory: Mapping[str, float | None],
                    breaking_force: Mapping[str, float | None], capacity: float | None,
                    accepted: Collection[str]) -> list[Flag]:
    """The checks of one specimen that need no other specimen."""
    chain = row.get("chain")
    max_force = row.get("max_force")
    checks = [
        ("E0", row.get("E0"), E0_theory.get(chain), "theory", THEORY_BAND, TIGHT_SPREAD),
        ("max_force", max_force, breaking_force.get(chain), "breaking force", BREAKING_BAND,
         BREAKING_SPREAD),
        ("max_force", max_force, capacity, "machine capacity", (-math.inf, CAPACITY_TOLERANCE),
         CAPACITY_SPREAD),
        *[(name, row.get(name), STRAIN_LIMIT, "strain limit", (-math.inf, 1.0), STRAIN_SPREAD)
          for name in ("strain_at_max_force", "strain_at_fracture")],
    ]
    found = [_judge(run_id, quantity, value, reference, against, band, accepted, spread)
             for quantity, value, reference, against, band, spread in checks]
    return [flag for flag in found if flag is not None]


def consensus(values: Sequence[float], band: tuple[float, float] = PEER_BAND) -> float | None:
    """The median of the largest group of `values` that agree within `band` of one of
    them, when that group is a majority; else None.

    Parameters
    ----------
    values : sequence of float
        The chain's specimen E0 [N].
    band : tuple of float
        Ratios [1] to a member within which another value agrees with it.

    Returns
    -------
    float or None
        The reference [N] the chain's specimens are judged against.

    Examples
    --------
    >>> consensus([1.0e7, 1.02e7, 1.0e10])  # one slipped of three
    10100000.0
    >>> consensus([1.0e7, 1.0e7, 1.0e10, 1.0e10]) is None  # two against two: cannot tell
    True
    """
    positive = [value for value in values if value > 0]
    groups = [[other for other in positive if not _outside(other / value, band)]
              for value in positive]
    best = max(groups, key=len, default=[])
    return float(np.median(best)) if len(best) > len(values) / 2 else None


def _peer_flags(rows: Mapping[str, Mapping], skip: Collection[str],
                accepted: Collection[str]) -> list[Flag]:
    """E0 of each specimen against the chain's other specimens (not those in `skip`)."""
    chains: dict[str, dict[str, float]] = {}
    for run_id, row in rows.items():
        E0 = _finite(row.get("E0"))
        if E0 is not None and run_id not in skip:
            chains.setdefault(row.get("chain"), {})[run_id] = E0
    flags = []
    for values in chains.values():
        if len(values) < MIN_SPECIMENS:
            continue
        reference = consensus(list(values.values()))
        for run_id, E0 in values.items():
            flag = _judge(run_id, "E0", E0, reference, "the chain's other specimens",
                          PEER_BAND, accepted)
            flags += [flag] if flag else []
    return flags


def check_specimens(rows: Mapping[str, Mapping], *,
                    E0_theory: Mapping[str, float | None],
                    breaking_force: Mapping[str, float | None],
                    capacity: float | None,
                    accepted: Collection[str]) -> list[Flag]:
    """Flag the tensile specimens whose results are implausible.

    Parameters
    ----------
    rows : mapping
        Run id -> mapping with ``chain`` (the run-sheet key), ``E0`` [N],
        ``max_force`` [N], ``strain_at_max_force`` [1] and ``strain_at_fracture``
        [1]; NaN (or a missing key) where not measured.
    E0_theory : mapping
        Chain key -> theoretical E0 [N], None or NaN when the chain has none.
    breaking_force : mapping
        Chain key -> the chain's minimum breaking force [N], or None.
    capacity : float or None
        The testing machine's force capacity [N].
    accepted : collection of str
        Run ids the run sheet accepts (``accept_implausible = true``).

    Returns
    -------
    list of Flag
        In the order of `rows`, each run's flags in the order of the checks
        (theory, breaking force, capacity, strains), then those against the
        chain's other specimens.

    Examples
    --------
    >>> rows = {run: {"chain": "c", "E0": E0} for run, E0 in
    ...         [("A", 1.00e7), ("B", 1.03e7), ("C", 0.98e7), ("D", 1.01e4)]}
    >>> flags = check_specimens(rows, E0_theory={}, breaking_force={}, capacity=None,
    ...                         accepted={"D"})
    >>> [(flag.run_id, flag.against, _number(flag.ratio), flag.accepted) for flag in flags]
    [('D', "the chain's other specimens", '0.00101', True)]
    >>> print(flags[0].slip)  # doctest: +NORMALIZE_WHITESPACE
    a force in kN labelled N, or an elongation in mm labelled m (or µm labelled mm)
    (factor 1/1000)
    """
    flags = []
    for run_id, row in rows.items():
        flags += _specimen_flags(run_id, row, E0_theory=E0_theory,
                                 breaking_force=breaking_force, capacity=capacity,
                                 accepted=accepted)
    off_theory = {flag.run_id for flag in flags
                  if flag.quantity == "E0" and flag.against == "theory" and not flag.accepted}
    return flags + _peer_flags(rows, off_theory, accepted)


def check_operating_points(points: pd.DataFrame, *, accepted: Collection[str]) -> list[Flag]:
    """Flag the engagement runs whose measured impact tensions are far from the model.

    Parameters
    ----------
    points : pandas.DataFrame
        Indexed by run id, with ``N_u1_meas``, ``N_u1_theory``, ``N_u2_meas``,
        ``N_u2_theory`` [N] (the model with Ryabov's k = 2).
    accepted : collection of str
        Run ids the run sheet accepts (``accept_implausible = true``).

    Returns
    -------
    list of Flag
        Measured medians outside [1/3, 3] x the model, against ``"impact model"``.

    Examples
    --------
    >>> points = pd.DataFrame({"N_u1_meas": [2.1e3, 2.0e6], "N_u1_theory": [2.0e3, 2.0e3],
    ...                        "N_u2_meas": [1.0e3, 1.0e6], "N_u2_theory": [1.1e3, 1.1e3]},
    ...                       index=["E1", "E2"])
    >>> [(flag.run_id, flag.quantity, round(flag.ratio)) for flag in
    ...  check_operating_points(points, accepted=())]
    [('E2', 'N_u1', 1000), ('E2', 'N_u2', 909)]
    """
    flags = []
    for run_id, point in points.iterrows():
        for quantity in ("N_u1", "N_u2"):
            flag = _judge(str(run_id), quantity, point.get(f"{quantity}_meas"),
                          point.get(f"{quantity}_theory"), "impact model", THEORY_BAND,
                          accepted)
            flags += [flag] if flag else []
    return flags


def excluded(flags: Iterable[Flag]) -> set[str]:
    """The run ids to leave out of the chain means: flagged and not accepted.

    >>> excluded([Flag("A", "E0", 1e10, 1e7, "theory", 1e3, None, False),
    ...           Flag("B", "E0", 1e10, 1e7, "theory", 1e3, None, True)])
    {'A'}
    """
    return {flag.run_id for flag in flags if not flag.accepted}


#: Variable of :func:`flags_dataset` -> (Flag attribute, attrs).
_VARIABLES = {
    "flag_run": ("run_id", {"long_name": "run flagged as implausible"}),
    "flag_quantity": ("quantity", {"long_name": "quantity flagged"}),
    "flag_value": ("value", {"long_name": "flagged value, in SI units (see flag_units)"}),
    "flag_reference": ("reference", {"long_name": "what the value was judged against, in SI "
                                                  "units (see flag_units)"}),
    "flag_units": ("units", {"long_name": "SI unit of flag_value and flag_reference"}),
    "flag_against": ("against", {"long_name": "kind of reference"}),
    "flag_ratio": ("ratio", {"units": "1", "long_name": "flagged value over its reference"}),
    "flag_slip": ("slip", {"long_name": "probable unit slip (empty when none is known)"}),
    "flag_accepted": ("accepted", {"long_name": "run accepted by the run sheet "
                                                "(accept_implausible)",
                                   "flag_values": np.array([0, 1], dtype="int8"),
                                   "flag_meanings": "not_accepted accepted"}),
    "flag_message": ("message", {"long_name": "what the technician reads"}),
}

_DTYPES = {"flag_value": float, "flag_reference": float, "flag_ratio": float,
           "flag_accepted": "int8"}


def _field(flag: Flag, name: str) -> str | float | bool:
    if name == "units":
        return "1" if QUANTITIES[flag.quantity][0] == "strain" else "N"
    value = getattr(flag, name)
    return "" if value is None else value


def flags_dataset(flags: Sequence[Flag]) -> xr.Dataset:
    """The flags as a dataset on dimension ``flag``, ready to merge into a summary.

    Parameters
    ----------
    flags : sequence of Flag
        From :func:`check_specimens` and :func:`check_operating_points`.

    Returns
    -------
    xarray.Dataset
        ``flag_run``, ``flag_quantity``, ``flag_value`` and ``flag_reference``
        (SI, in the unit of ``flag_units``: ``"N"`` or ``"1"``), ``flag_against``,
        ``flag_ratio`` [1], ``flag_slip`` (``""`` when none), ``flag_accepted``
        (int8, 1 accepted) and ``flag_message``; the dimension has size 0 when
        there are no flags. The bands the checks applied are its attributes
        (:func:`thresholds`).

    Examples
    --------
    >>> flags_dataset([]).sizes["flag"]
    0
    """
    data = {}
    for variable, (field, attrs) in _VARIABLES.items():
        values = [_field(flag, field) for flag in flags]
        dtype = _DTYPES.get(variable, str)
        data[variable] = ("flag", np.array(values, dtype=dtype), dict(attrs))
    return xr.Dataset(data, attrs=thresholds())


def thresholds() -> dict[str, float | np.ndarray]:
    """The bands the checks apply, as attributes of the outputs (all ratios [1] but strains).

    Returns
    -------
    dict
        ``plausibility_theory_band`` (value / theory: E0, N_u1, N_u2),
        ``plausibility_peer_band`` (E0 / the chain's other specimens, checked
        from ``plausibility_min_specimens`` specimens), ``plausibility_breaking_band``
        (max force / the chain's breaking force), ``plausibility_capacity_tolerance``
        (max force / the machine's capacity) and ``plausibility_strain_limit``
        (a strain [1]); a band as ``[low, high]``.

    Examples
    --------
    >>> thresholds()["plausibility_strain_limit"]
    0.5
    """
    return {"plausibility_theory_band": np.array(THEORY_BAND),
            "plausibility_peer_band": np.array(PEER_BAND),
            "plausibility_min_specimens": MIN_SPECIMENS,
            "plausibility_breaking_band": np.array(BREAKING_BAND),
            "plausibility_capacity_tolerance": CAPACITY_TOLERANCE,
            "plausibility_strain_limit": STRAIN_LIMIT}
