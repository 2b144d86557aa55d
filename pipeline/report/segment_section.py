"""The report's segment-load section: Paper 003 measured against the model, per drum.

Reads the ``segment_point`` table of ``summary.nc`` (:mod:`pipeline.segment_summary`):
per run its measured F_K / F and F_P / F against the model at the run sheet's
geometry, per drum the fitted s (or beta) with its interval, and the checks.
:func:`segment_run_page` is what a segment-load run's own page shows, from its
run file, and :func:`segment_numbers` its line in the run table.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import xarray as xr

from pipeline.condition.segment_load import EXCLUSIONS
from pipeline.report.formatting import MISSING, number, percent, plain_number
from pipeline.report.recorded import level
from pipeline.report.render import svg
from pipeline.report.segment_figures import segment_run


def _ratio(value: float, stderr: float) -> str:
    """A measured ratio ± its standard error (MISSING when not measured)."""
    if math.isnan(float(value)):
        return MISSING
    return f"{number(value, 4)} ± {number(stderr, 2)}"


def _fitted(row: xr.Dataset) -> str:
    """The fitted parameter with its interval: s in mm, beta in degrees."""
    name = str(row["segment_fitted"].values)
    value = float(row[f"segment_fit_{name}"])
    if math.isnan(value):
        return MISSING
    scale, unit = (1e3, " mm") if name == "s" else (180 / math.pi, "°")
    low, high = (scale * float(row[f"segment_fit_{name}_ci_{end}"]) for end in ("low", "high"))
    return (f"{name} = {number(scale * value, 4)}{unit} ({number(low, 4)} .. "
            f"{number(high, 4)}{unit})")


def segment_rows(summary: xr.Dataset) -> list[dict[str, str]]:
    """One row per segment-load run: measured against the run sheet's model."""
    rows = []
    for run in summary["segment_point"].values:
        row = summary.sel(segment_point=run)
        rows.append({
            "run": str(run), "drum": str(row["segment_drum"].values),
            "force": f"{number(float(row['segment_chain_force']) / 1e3, 4)} kN",
            "seatings": f"{int(row['segment_seatings'])}",
            "contact": _ratio(row["segment_contact_ratio"], row["segment_contact_ratio_stderr"]),
            "contact_model": number(row["segment_model_contact_ratio"], 4),
            "contact_fitted": number(row["segment_fitted_contact_ratio"], 4),
            "side": _ratio(row["segment_side_ratio"], row["segment_side_ratio_stderr"]),
            "side_model": number(row["segment_model_side_ratio"], 4),
            "friction": f"{number(100 * float(row['segment_friction_increase']), 3)} %",
            "fitted": _fitted(row),
            "agrees": "yes" if int(row["segment_model_agrees"]) else "no"})
    return rows


def segment_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    """The checks of the segment-load runs, for the campaign page's table of checks."""
    for run in summary["segment_point"].values:
        row = summary.sel(segment_point=run)
        agrees = bool(int(row["segment_model_agrees"]))
        yield {"check": f"run {run}: measured F_K/F, F_P/F against the run sheet's geometry "
                        "(Paper 003, eqs. (1)-(4))",
               "result": "agrees" if agrees else "differs",
               "status": "pass" if agrees else "info",
               "detail": f"F_K/F {number(row['segment_contact_ratio'], 4)} against "
                         f"{number(row['segment_model_contact_ratio'], 4)} "
                         f"({number(row['segment_contact_normalized'], 3)} standard errors); "
                         f"fitted {_fitted(row)}"}


def tested(summary: xr.Dataset) -> str:
    """What the segment-load runs tested, as a phrase."""
    drums = set(summary["segment_drum"].values.astype(str))
    return (f"segment-load tests at {summary.sizes['segment_point']} operating point(s) of "
            f"{len(drums)} drum(s) for the loads on the tooth segments (Paper 003)")


def segment_section(summary: xr.Dataset, figure: str) -> dict[str, Any]:
    """What the campaign page's segment-load section shows (the figure rendered)."""
    fitted = [name for name in ("segment_fit_s_ci_low", "segment_fit_beta_ci_low")
              if name in summary]
    return {"figure_svg": figure, "runs": segment_rows(summary),
            "level": level(summary[fitted[0]].attrs)}


#: The ratios a run's page tabulates: run-file stem, label.
_RATIOS = {"contact_force_ratio": "F_K/F", "side_force_ratio": "F_P/F"}


def segment_numbers(summary: xr.Dataset, run_id: str) -> str:
    """A segment-load run's key values for the run table: chain force and F_K/F."""
    if run_id not in summary.indexes.get("segment_point", []):
        return MISSING
    row = summary.sel(segment_point=run_id)
    return (f"F = {number(float(row['segment_chain_force']) / 1e3, 4)} kN, F_K/F = "
            f"{_ratio(row['segment_contact_ratio'], row['segment_contact_ratio_stderr'])}")


def segment_run_page(run: xr.Dataset) -> dict[str, Any]:
    """What a segment-load run's page shows besides its status and raw file.

    Parameters
    ----------
    run : xarray.Dataset
        The run file (:class:`pipeline.results.segment_load.SegmentLoadResult`).

    Returns
    -------
    dict
        ``figure_svg`` (:func:`pipeline.report.segment_figures.segment_run`),
        ``drum``, ``fitted``, ``seatings`` and ``valid`` (counts), ``excluded``
        (per reason, or "none"), ``ratios`` (per ratio its median, IQR and
        standard error against the model at the run sheet's geometry),
        ``force`` (median chain force [kN]), ``imbalance`` (median, and the
        ``tolerance``, in %), ``imbalanced`` (seatings flagged beyond it) and
        ``geometry`` (the run sheet's s [mm], beta and eps_n [deg]). The
        conditioning's notes on the imbalance are the page's warnings.
    """
    attrs = run.attrs
    excluded = [f"{reason.replace('_', ' ')}: {int(run[f'excluded_{reason}'])}"
                for reason in EXCLUSIONS if int(run[f"excluded_{reason}"])]
    ratios = [{"ratio": label, "median": number(run[f"{stem}_median"], 4),
               "iqr": number(run[f"{stem}_iqr"], 2), "stderr": number(run[f"{stem}_stderr"], 2),
               "model": number(run[f"model_{stem}"], 4)}
              for stem, label in _RATIOS.items() if f"{stem}_median" in run]
    return {
        "figure_svg": svg(segment_run(run)),
        "drum": str(attrs.get("drum", "")), "fitted": str(attrs.get("fitted", "")),
        "seatings": str(run.sizes["seating"]),
        "valid": plain_number(run["contact_force_ratio_count"]),
        "excluded": ", ".join(excluded) or "none",
        "ratios": ratios,
        "force": number(float(run["F_median"]) / 1e3, 4),
        "imbalance": percent(run["imbalance_median"], 2),
        "tolerance": percent(attrs["imbalance_tolerance"], 1),
        "imbalanced": plain_number(int(run["imbalanced"].sum())),
        "geometry": {"s": number(1e3 * float(run["contact_distance"]), 4),
                     "beta": number(math.degrees(float(run["flank_inclination"])), 4),
                     "eps_n": number(math.degrees(float(run["link_inclination"])), 4)},
    }
