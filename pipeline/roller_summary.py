"""The ``sprocket_point`` table of a campaign summary: roller chains on sprockets (Paper 002).

One row per roller-engagement run (labels: run ids; each run is one speed of
one sprocket), built from its result
(:class:`~pipeline.results.roller_engagement.RollerEngagementResult`, read
back from its run file). xi is fitted across the runs of one sprocket
(:func:`pipeline.fit.roller_engagement.fit_roller_engagement`) and its values
are repeated on every row of that sprocket:

measured
    the run's speed ``roller_omega`` [rad/s] and ``roller_n`` [rpm] (run
    sheet), ``roller_omega_measured`` (in the log), the strike amplitude
    ``strike_amplitude`` with its IQR, standard error [N] and count; the
    fitted ``xi_fit`` with its standard error and interval, the reduced
    chi-square, and the straight line of the amplitudes in omega
    (``amplitude_slope`` [N s], ``amplitude_intercept`` [N], ``amplitude_r2``);
model
    ``xi_model`` of the sprocket's involute (Paper 002, eqs. (3)-(5)), its
    bounds ``xi_min``, ``xi_max`` = sin(pi/z), cos(pi/z) (eq. (3)), and with
    the fitted xi the model amplitude ``strike_amplitude_model`` [N], the
    impact velocity ``impact_velocity`` [m/s] (eqs. (2), (5)), the impact energy
    ``impact_energy`` [J] (eq. (6)), the specific energy ``specific_impact_energy``
    [J/m^2] (eq. (7)), the lab's limit ``g_lim`` [J/m^2] and the speed limit
    ``n_max`` [rpm] of eq. (8) (``n_max_model``: with the model's xi);
checks
    ``above_n_max`` (the run's speed above n_max), ``xi_within_bounds`` (the
    fitted xi within the bounds) and ``xi_model_covered`` (the model's xi
    inside the fitted interval): 1 yes, 0 no, -1 not evaluated.

A sprocket whose runs cannot give xi (one speed, runs on different chains or
branches, no valid strike) keeps its rows, NaN where the fit would be, and
the reason is a note of the summary.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import xarray as xr

from pipeline.errors import FitError
from pipeline.fit.impact_model import CONFIDENCE
from pipeline.fit.roller_engagement import RollerEngagementFit, fit_roller_engagement
from pipeline.results.roller_engagement import RollerEngagementResult
from pipeline.runs import roller_engagement_inputs
from pipeline.runsheet import RunDef, RunSheet
from pipeline.summary_rows import table_dataset
from pipeline.theory.roller_impact import max_angular_velocity
from pipeline.units import from_si

#: The texts of a row.
TEXTS = {"roller_sprocket": "sprocket of the run (run-sheet key)",
         "roller_chain": "roller chain of the run (run-sheet key)"}

#: The numbers of a row: units and long names.
NUMBERS = {
    "roller_teeth": ("1", "teeth z of the sprocket"),
    "roller_omega": ("rad s-1", "sprocket angular velocity (run sheet)"),
    "roller_n": ("min-1", "sprocket speed (run sheet)"),
    "roller_omega_measured": ("rad s-1", "sprocket angular velocity measured in the log"),
    "strike_amplitude": ("N", "roller strike amplitude, median of the run"),
    "strike_amplitude_iqr": ("N", "interquartile range of the strike amplitudes"),
    "strike_amplitude_stderr": ("N", "standard error of strike_amplitude"),
    "strike_count": ("1", "strikes pooled"),
    "strike_amplitude_model": ("N", "strike amplitude of the model with the fitted xi"),
    "impact_velocity": ("m s-1", "impact velocity V_y = omega t xi with the fitted xi, "
                                 "Paper 002 eqs. (2), (5)"),
    "impact_energy": ("J", "impact energy with the fitted xi, Paper 002 eq. (6)"),
    "specific_impact_energy": ("J m-2", "specific impact energy with the fitted xi, "
                                        "Paper 002 eq. (7)"),
    "xi_fit": ("1", "impact-velocity coefficient xi fitted over the sprocket's runs"),
    "xi_fit_stderr": ("1", "standard error of xi_fit"),
    "xi_fit_ci_low": ("1", "lower limit of the {level} interval of xi_fit"),
    "xi_fit_ci_high": ("1", "upper limit of the {level} interval of xi_fit"),
    "xi_fit_chi2_reduced": ("1", "reduced chi-square of the fit of xi"),
    "amplitude_slope": ("N s", "slope of the straight line of the amplitudes in omega"),
    "amplitude_intercept": ("N", "intercept of that line (0 for the model)"),
    "amplitude_r2": ("1", "R^2 of that line (NaN below three speeds)"),
    "xi_model": ("1", "xi of the sprocket's involute, Paper 002 eqs. (3)-(5)"),
    "xi_min": ("1", "lower bound of xi, sin(pi/z), Paper 002 eq. (3)"),
    "xi_max": ("1", "upper bound of xi, cos(pi/z), Paper 002 eq. (3)"),
    "g_lim": ("J m-2", "the lab's limit of the specific impact energy G_lim"),
    "n_max": ("min-1", "speed limit of Paper 002 eq. (8) with the fitted xi"),
    "n_max_model": ("min-1", "speed limit of Paper 002 eq. (8) with the model's xi"),
}

#: The checks of a row: 1 yes, 0 no, -1 not evaluated.
CHECKS = {
    "above_n_max": "the run's speed is above n_max of eq. (8) (fitted xi)",
    "xi_within_bounds": "the fitted xi lies within [sin(pi/z), cos(pi/z)]",
    "xi_model_covered": "the model's xi lies inside the interval of the fitted xi",
}


def roller_row(run: RunDef, result: RollerEngagementResult, E0: float) -> dict[str, Any]:
    """A roller-engagement run's measured values (SI), before the fit of its sprocket.

    Parameters
    ----------
    run : RunDef
        The run.
    result : RollerEngagementResult
        Its result.
    E0 : float
        The chain stiffness it was processed with [N].
    """
    strike = result.strike
    return {"roller_sprocket": run.sprocket, "roller_chain": run.chain, "E0": E0,
            "branch_length": run.branch_length_m,
            "roller_teeth": float(result.attrs["sprocket_teeth"]), "roller_omega": run.omega,
            "roller_n": float(from_si(run.omega, "rpm")),
            "roller_omega_measured": result.omega_measured,
            "strike_amplitude": strike.median, "strike_amplitude_iqr": strike.iqr,
            "strike_amplitude_stderr": strike.stderr, "strike_count": float(strike.count)}


def _fit(sheet: RunSheet, key: str, ids: list[str], rows: Mapping[str, Mapping[str, Any]]
         ) -> tuple[RollerEngagementFit | None, list[str]]:
    """xi of sprocket `key` over its runs `ids`, or None and why not."""
    branches = {(rows[i]["roller_chain"], rows[i]["branch_length"], rows[i]["E0"]) for i in ids}
    if len(branches) > 1:
        return None, [f"sprocket {key}: xi not fitted: its runs differ in chain, "
                      "branch_length_m or E0, and one xi is fitted to one branch; give each "
                      "branch its own [sprockets.<key>]"]
    measured = [i for i in ids if np.isfinite(rows[i]["strike_amplitude_stderr"])
                and rows[i]["strike_amplitude_stderr"] > 0]
    notes = [f"sprocket {key}: run {i} has no measured strike amplitude and is left out "
             "of the fit of xi" for i in ids if i not in measured]
    run = next(run for run in sheet.runs if run.id == ids[0])
    sprocket, branch, g_lim = roller_engagement_inputs(sheet, run, rows[ids[0]]["E0"])
    try:
        fit = fit_roller_engagement([rows[i]["roller_omega"] for i in measured],
                                    [rows[i]["strike_amplitude"] for i in measured],
                                    [rows[i]["strike_amplitude_stderr"] for i in measured],
                                    sprocket=sprocket, branch=branch, g_lim=g_lim)
    except FitError as error:
        return None, [*notes, f"sprocket {key}: xi not fitted: {error}"]
    if fit.xi_model_reason:
        notes.append(f"sprocket {key}: no model xi: {fit.xi_model_reason}")
    if math.isfinite(fit.xi_model) and not fit.covers(fit.xi_model):
        notes.append(f"sprocket {key}: the measured xi = {fit.xi:.4g} "
                     f"({fit.ci_low:.4g} .. {fit.ci_high:.4g}) does not cover the involute "
                     f"model's xi = {fit.xi_model:.4g}")
    if not fit.within_bounds:
        notes.append(f"sprocket {key}: the measured xi = {fit.xi:.4g} lies outside Paper "
                     f"002's bounds [{fit.xi_bounds[0]:.4g}, {fit.xi_bounds[1]:.4g}]")
    return fit, notes


def _fitted(fit: RollerEngagementFit, row: Mapping[str, Any]) -> dict[str, float]:
    """The values of a row that come from the fit of its sprocket (SI)."""
    points = fit.points.set_index("omega")
    found = row["roller_omega"] in points.index and math.isfinite(row["strike_amplitude"])
    point = points.loc[row["roller_omega"]] if found else None
    if point is not None and point.ndim > 1:  # two runs at one speed: the same model values
        point = point.iloc[0]
    values = {"strike_amplitude_model": "model", "impact_velocity": "impact_velocity",
              "impact_energy": "energy", "specific_impact_energy": "specific_energy"}
    cells = {name: float(point[column]) if point is not None else math.nan
             for name, column in values.items()}
    cells.update(
        xi_fit=fit.xi, xi_fit_stderr=fit.stderr, xi_fit_ci_low=fit.ci_low,
        xi_fit_ci_high=fit.ci_high, xi_fit_chi2_reduced=fit.chi2_reduced,
        amplitude_slope=fit.slope, amplitude_intercept=fit.intercept, amplitude_r2=fit.r2,
        n_max=fit.n_max_rpm, above_n_max=float(row["roller_n"] > fit.n_max_rpm),
        xi_within_bounds=float(fit.within_bounds),
        xi_model_covered=float(fit.covers(fit.xi_model)) if math.isfinite(fit.xi_model)
        else -1.0)
    return cells


def _sprocket_values(sheet: RunSheet, run_id: str, row: Mapping[str, Any]) -> dict[str, float]:
    """The model's values of a row's sprocket, fitted or not (SI)."""
    run = next(run for run in sheet.runs if run.id == run_id)
    sprocket, branch, g_lim = roller_engagement_inputs(sheet, run, row["E0"])
    xi_model, _ = sprocket.involute_xi(branch.pitch)
    n_max_model = (from_si(max_angular_velocity(branch.mass_per_length, branch.pitch, xi_model,
                                                branch.roller_diameter, branch.roller_length,
                                                g_lim), "rpm")
                   if math.isfinite(xi_model) else math.nan)
    return {"xi_model": xi_model, "xi_min": math.sin(math.pi / sprocket.teeth),
            "xi_max": math.cos(math.pi / sprocket.teeth), "g_lim": g_lim,
            "n_max_model": float(n_max_model)}


def roller_summary(sheet: RunSheet, rows: Mapping[str, Mapping[str, Any]]
                   ) -> tuple[xr.Dataset, list[str]]:
    """The ``sprocket_point`` table of a campaign summary, and its notes.

    Parameters
    ----------
    sheet : RunSheet
        The run sheet (the sprockets, chains and branches of the runs).
    rows : mapping
        Run id -> its measured values (:func:`roller_row`), in run-sheet order.

    Returns
    -------
    dataset : xarray.Dataset
        On dimension ``sprocket_point`` (labels: run ids): the texts of
        :data:`TEXTS`, the numbers of :data:`NUMBERS` (NaN where a sprocket's
        xi could not be fitted) and the checks of :data:`CHECKS` as int8.
    notes : list of str
        Why a sprocket's xi was not fitted, runs left out, and the model's xi
        or the bounds not met.
    """
    ids, notes = list(rows), []
    table = {i: {**rows[i], **_sprocket_values(sheet, i, rows[i])} for i in ids}
    for key in dict.fromkeys(rows[i]["roller_sprocket"] for i in ids):
        members = [i for i in ids if rows[i]["roller_sprocket"] == key]
        fit, said = _fit(sheet, key, members, rows)
        notes += said
        for i in members:
            table[i].update(_fitted(fit, rows[i]) if fit is not None else
                            {name: -1.0 for name in CHECKS})
    numbers = {**NUMBERS, **{name: ("1", text) for name, text in CHECKS.items()}}
    return table_dataset("sprocket_point", table, TEXTS, numbers, CHECKS, CONFIDENCE), notes
