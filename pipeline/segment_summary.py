"""The ``segment_point`` table of a campaign summary: Paper 003 measured against the model.

Every segment-load run is one operating point of a drum's tooth (labels: run
ids). Its row, built from its result
(:class:`~pipeline.results.segment_load.SegmentLoadResult`), holds

measured
    the median chain force ``segment_chain_force`` [N], the valid seatings
    ``segment_seatings``, the medians over them of F_K / F
    (``segment_contact_ratio``) and F_P / F (``segment_side_ratio``, NaN when
    not logged) with IQR and standard error, the segments' median
    ``segment_imbalance`` and the friction increase 2 F_K / F - 1
    ``segment_friction_increase`` [1];
model
    eqs. (1)-(4) at the run sheet's geometry (``segment_model_*``) and at the
    geometry fitted across the drum's runs (``segment_fitted_*``); the fit
    itself, repeated on each run of the drum: ``segment_fit_s`` [m] or
    ``segment_fit_beta`` [rad] (the parameter fitted; the other is NaN) with
    standard error and interval, ``segment_fit_chi2_reduced``,
    ``segment_fit_dof``, and the drum's measured friction increase (weighted
    mean) ``segment_drum_friction_increase`` with its standard error;
checks
    ``segment_contact_normalized`` and ``segment_side_normalized``, measured
    less the run sheet's model in standard errors, and ``segment_model_agrees``
    (1: both within :data:`AGREEMENT` standard errors; 0: not).

The fit runs per drum and chain (:func:`pipeline.fit.segment_load.fit_segment_load`)
with the parameter the drum's ``fitted`` names; a drum whose ratios no
geometry gives gets NaN fit values and a note that says why.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import pandas as pd
import xarray as xr

from pipeline.errors import FitError
from pipeline.fit.segment_load import CONFIDENCE, FRICTION_CLAIM, fit_segment_load
from pipeline.results.segment_load import SegmentLoadResult
from pipeline.summary_rows import YES_NO_FLAGS, table_dataset

#: Largest |measured - model| in standard errors taken as agreement [1].
AGREEMENT = 3.0

#: The texts of a row.
TEXTS = {
    "segment_drum": "drum of the segment-load run (run-sheet key)",
    "segment_chain": "chain of the segment-load run (run-sheet key)",
    "segment_fitted": "parameter fitted across the drum's runs: s or beta",
}

#: The numbers of a row: units and long names.
NUMBERS = {
    "segment_chain_force": ("N", "median chain force F over the valid seatings"),
    "segment_seatings": ("1", "valid seatings"),
    "segment_contact_ratio": ("1", "measured F_K / F, median over the seatings"),
    "segment_contact_ratio_iqr": ("1", "interquartile range of F_K / F"),
    "segment_contact_ratio_stderr": ("1", "standard error of the median F_K / F"),
    "segment_side_ratio": ("1", "measured F_P / F, median over the seatings"),
    "segment_side_ratio_iqr": ("1", "interquartile range of F_P / F"),
    "segment_side_ratio_stderr": ("1", "standard error of the median F_P / F"),
    "segment_imbalance": ("1", "median (F_K1 - F_K2) / F_K of the seatings"),
    "segment_friction_increase": ("1", "measured friction increase 2 F_K / F - 1"),
    "segment_model_contact_ratio": ("1", "F_K / F of eqs. (1)-(3), run sheet's geometry"),
    "segment_model_side_ratio": ("1", "F_P / F of eqs. (1)-(4), run sheet's geometry"),
    "segment_model_friction_increase": ("1", "2 F_K / F - 1 of the model, run sheet's geometry"),
    "segment_torus_radius": ("m", "outer torus radius r of the horizontal link"),
    "segment_bar_diameter": ("m", "link bar thickness d"),
    "segment_groove_width": ("m", "groove width c between the segments"),
    "segment_contact_distance": ("m", "contact distance s of the run sheet"),
    "segment_flank_inclination": ("rad", "flank inclination beta of the run sheet"),
    "segment_link_inclination": ("rad", "link inclination eps_n of the run sheet"),
    "segment_fit_s": ("m", "contact distance s fitted across the drum's runs"),
    "segment_fit_s_stderr": ("m", "standard error of the fitted s"),
    "segment_fit_s_ci_low": ("m", "lower limit of the {level} interval of s"),
    "segment_fit_s_ci_high": ("m", "upper limit of the {level} interval of s"),
    "segment_fit_beta": ("rad", "flank inclination beta fitted across the drum's runs"),
    "segment_fit_beta_stderr": ("rad", "standard error of the fitted beta"),
    "segment_fit_beta_ci_low": ("rad", "lower limit of the {level} interval of beta"),
    "segment_fit_beta_ci_high": ("rad", "upper limit of the {level} interval of beta"),
    "segment_fit_chi2_reduced": ("1", "weighted chi-square per degree of freedom of the fit"),
    "segment_fit_dof": ("1", "residual degrees of freedom of the fit"),
    "segment_fitted_contact_ratio": ("1", "F_K / F of the model at the fitted geometry"),
    "segment_fitted_side_ratio": ("1", "F_P / F of the model at the fitted geometry"),
    "segment_fitted_friction_increase": ("1", "2 F_K / F - 1 at the fitted geometry"),
    "segment_drum_friction_increase": ("1", "measured 2 F_K / F - 1 over the drum's runs "
                                            "(weighted mean)"),
    "segment_drum_friction_increase_stderr": ("1", "standard error of that mean"),
    "segment_friction_claim": ("1", "Paper 003's claimed friction increase (over it)"),
    "segment_contact_normalized": ("1", "(measured - model) F_K / F in standard errors"),
    "segment_side_normalized": ("1", "(measured - model) F_P / F in standard errors"),
}

#: The checks of a row: 1 yes, 0 no.
CHECKS = {"segment_model_agrees": f"measured ratios within {AGREEMENT:g} standard errors of "
                                  "the run sheet's model"}

#: The fit's values per fitted parameter (NaN for the other).
_FIT = ("", "_stderr", "_ci_low", "_ci_high")


def segment_row(result: SegmentLoadResult) -> dict[str, Any]:
    """A segment-load run's row of the ``segment_point`` table, before the drum's fit."""
    stats, model, attrs = result.statistics, result.model, result.attrs
    point = result.point()
    side = point.get("F_P/F", math.nan)
    row: dict[str, Any] = {
        "segment_drum": str(attrs["drum"]), "segment_chain": str(attrs["chain"]),
        "segment_fitted": str(attrs["fitted"]),
        "segment_chain_force": point["F"], "segment_seatings": stats["F_count"],
        "segment_contact_ratio": point["F_K/F"],
        "segment_contact_ratio_iqr": stats["contact_force_ratio_iqr"],
        "segment_contact_ratio_stderr": point["F_K/F_stderr"],
        "segment_side_ratio": side,
        "segment_side_ratio_iqr": stats.get("side_force_ratio_iqr", math.nan),
        "segment_side_ratio_stderr": point.get("F_P/F_stderr", math.nan),
        "segment_imbalance": stats["imbalance_median"],
        "segment_friction_increase": 2 * point["F_K/F"] - 1,
        "segment_friction_claim": FRICTION_CLAIM,
        **{f"segment_{name}": model[name] for name in (
            "torus_radius", "bar_diameter", "groove_width", "contact_distance",
            "flank_inclination", "link_inclination")},
        "segment_model_contact_ratio": model["model_contact_force_ratio"],
        "segment_model_side_ratio": model["model_side_force_ratio"],
        "segment_model_friction_increase": model["model_friction_increase"],
    }
    contact = (row["segment_contact_ratio"] - row["segment_model_contact_ratio"]) \
        / row["segment_contact_ratio_stderr"]
    side_off = (side - row["segment_model_side_ratio"]) / row["segment_side_ratio_stderr"]
    row["segment_contact_normalized"], row["segment_side_normalized"] = contact, side_off
    row["segment_model_agrees"] = float(
        abs(contact) <= AGREEMENT and (math.isnan(side_off) or abs(side_off) <= AGREEMENT))
    return row


def _fit_values(rows: list[dict[str, Any]]) -> tuple[dict[str, float], str]:
    """The fit of one drum's rows (:data:`NUMBERS` ``segment_fit*``), and its note."""
    first = rows[0]
    measured = pd.DataFrame({
        "F_K/F": [row["segment_contact_ratio"] for row in rows],
        "F_K/F_stderr": [row["segment_contact_ratio_stderr"] for row in rows],
        "F_P/F": [row["segment_side_ratio"] for row in rows],
        "F_P/F_stderr": [row["segment_side_ratio_stderr"] for row in rows]})
    geometry = {"r_outer": first["segment_torus_radius"], "d": first["segment_bar_diameter"],
                "groove_width": first["segment_groove_width"]}
    vary = first["segment_fitted"]
    values = {f"segment_fit_{name}{end}": math.nan for name in ("s", "beta") for end in _FIT}
    label = f"drum {first['segment_drum']} (chain {first['segment_chain']})"
    try:
        fit = fit_segment_load(measured, geometry,
                               beta=first["segment_flank_inclination"],
                               s=first["segment_contact_distance"],
                               eps_n=first["segment_link_inclination"], vary=vary)
    except FitError as error:
        values.update(dict.fromkeys(
            [*(name for name in NUMBERS if name.startswith(("segment_fitted_", "segment_drum_"))),
             "segment_fit_chi2_reduced", "segment_fit_dof"], math.nan))
        return values, f"segment-load {label}: no {vary} fitted: {error.message}"
    values.update({f"segment_fit_{vary}": fit.value, f"segment_fit_{vary}_stderr": fit.stderr,
                   f"segment_fit_{vary}_ci_low": fit.ci_low,
                   f"segment_fit_{vary}_ci_high": fit.ci_high,
                   "segment_fit_chi2_reduced": fit.chi2_reduced, "segment_fit_dof": fit.dof,
                   "segment_fitted_contact_ratio": fit.fitted.contact_force,
                   "segment_fitted_side_ratio": fit.fitted.side_force,
                   "segment_fitted_friction_increase": fit.fitted.friction_increase,
                   "segment_drum_friction_increase": fit.measured["friction_increase"],
                   "segment_drum_friction_increase_stderr":
                       fit.measured["friction_increase_stderr"]})
    return values, f"segment-load {label}: {fit.claim_note()}"


def segment_summary(rows: Mapping[str, Mapping[str, Any]]
                    ) -> tuple[xr.Dataset, list[str]]:
    """The ``segment_point`` table of a campaign summary, with the fit per drum.

    Parameters
    ----------
    rows : mapping
        Run id -> its row (:func:`segment_row`).

    Returns
    -------
    summary : xarray.Dataset
        On dimension ``segment_point`` (labels: run ids): the texts of
        :data:`TEXTS`, the numbers of :data:`NUMBERS` and the checks of
        :data:`CHECKS` (int8).
    notes : list of str
        Per drum the friction increase against Paper 003's claim, or why no
        geometry was fitted.

    References
    ----------
    Paper 003, eqs. (1)-(4); section 4 (Fig. 9) for the claim.
    """
    filled = {run_id: dict(row) for run_id, row in rows.items()}
    groups: dict[tuple[str, str], list[str]] = {}
    for run_id, row in filled.items():
        groups.setdefault((row["segment_drum"], row["segment_chain"]), []).append(run_id)
    notes = []
    for ids in groups.values():
        values, note = _fit_values([filled[run_id] for run_id in ids])
        notes.append(note)
        for run_id in ids:
            filled[run_id].update(values)
    numbers = {**NUMBERS, **{name: ("1", text) for name, text in CHECKS.items()}}
    return table_dataset("segment_point", filled, TEXTS, numbers, CHECKS, CONFIDENCE,
                         YES_NO_FLAGS), notes
