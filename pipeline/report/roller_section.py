"""The report's roller-chain section: xi measured on sprockets against Paper 002.

Built from the campaign summary's ``sprocket_point`` table
(:mod:`pipeline.roller_summary`): per sprocket the fitted xi with its
interval against the involute model's xi and the bounds of eq. (3), and per
run its speed against the speed limit n_max of eq. (8). A campaign result,
unlike the catalogue chain of :mod:`pipeline.report.design_figures`.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import xarray as xr

from pipeline.report.formatting import MISSING, first_rows, interval, number, verdict_class
from pipeline.report.recorded import level


def _sprocket_rows(summary: xr.Dataset) -> list[xr.Dataset]:
    """The first row of every sprocket (its fit's values are repeated on its rows)."""
    return first_rows(summary, "sprocket_point", "roller_sprocket")


def tested(summary: xr.Dataset) -> str:
    """What the roller-engagement runs tested, as a phrase."""
    return (f"engagement logs of roller chains on {len(_sprocket_rows(summary))} sprocket(s) "
            f"at {summary.sizes['sprocket_point']} speed(s) for the impact-velocity "
            "coefficient xi (Paper 002)")


def roller_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    """The checks of the roller-engagement runs, for the campaign page's table of checks."""
    for row in _sprocket_rows(summary):
        key = str(row["roller_sprocket"].values)
        if int(row["xi_model_covered"]) >= 0:
            covered = bool(int(row["xi_model_covered"]))
            yield {"check": f"sprocket {key}: measured xi covers the involute's (Paper 002)",
                   "result": "pass" if covered else "fail", "status": verdict_class(covered),
                   "detail": f"xi = {number(row['xi_fit'])} ({_interval(row)}); model "
                             f"{number(row['xi_model'])}"}
    for run in summary["sprocket_point"].values:
        row = summary.sel(sprocket_point=run)
        if int(row["above_n_max"]) >= 0:
            above = bool(int(row["above_n_max"]))
            yield {"check": f"run {run}: speed within n_max of Paper 002 eq. (8)",
                   "result": "fail" if above else "pass", "status": verdict_class(not above),
                   "detail": f"n = {number(row['roller_n'])} rpm, n_max = "
                             f"{number(row['n_max'])} rpm"}


def _interval(row: xr.Dataset) -> str:
    return interval(float(row["xi_fit_ci_low"]), float(row["xi_fit_ci_high"]))


def roller_section(summary: xr.Dataset, amplitude_svg: str) -> dict[str, Any]:
    """What the roller-chain section shows: the figure, per sprocket xi, per run the check."""
    sprockets = [{
        "sprocket": str(row["roller_sprocket"].values), "z": f"{int(row['roller_teeth'])}",
        "xi": number(row["xi_fit"]),
        "interval": _interval(row) if math.isfinite(float(row["xi_fit"])) else MISSING,
        "model": number(row["xi_model"]),
        "bounds": interval(float(row["xi_min"]), float(row["xi_max"])),
        "within": {1: "yes", 0: "no", -1: MISSING}[int(row["xi_within_bounds"])],
        "r2": number(row["amplitude_r2"]), "g_lim": number(1e-6 * float(row["g_lim"])),
        "n_max": number(row["n_max"]), "n_max_model": number(row["n_max_model"]),
    } for row in _sprocket_rows(summary)]
    points = []
    for run in summary["sprocket_point"].values:
        row = summary.sel(sprocket_point=run)
        above = int(row["above_n_max"])
        points.append({
            "run": str(run), "sprocket": str(row["roller_sprocket"].values),
            "n": number(row["roller_n"]), "amplitude": number(row["strike_amplitude"]),
            "stderr": number(row["strike_amplitude_stderr"], 2),
            "model": number(row["strike_amplitude_model"]),
            "energy": number(row["impact_energy"]),
            "check": {1: "above n_max", 0: "below n_max", -1: MISSING}[above],
            "status": "fail" if above == 1 else "pass" if above == 0 else "info"})
    return {"figure_svg": amplitude_svg, "sprockets": sprockets, "points": points,
            "level": level(summary["xi_fit_ci_low"].attrs)}


def roller_numbers(summary: xr.Dataset, run_id: str) -> str:
    """A roller-engagement run's key values for the run table: speed, amplitude, check."""
    if run_id not in summary.indexes.get("sprocket_point", []):
        return MISSING
    row = summary.sel(sprocket_point=run_id)
    above = {1: ", above n_max", 0: "", -1: ""}[int(row["above_n_max"])]
    return (f"n = {number(row['roller_n'])} rpm, strike = {number(row['strike_amplitude'])} N"
            f"{above}")
