"""Figures of the report's wear section: elongation against running time, fit and limits.

Each function takes wear run files (:mod:`pipeline.results.wear`) and returns a
matplotlib :class:`~matplotlib.figure.Figure`; :func:`pipeline.report.render.svg`
renders it. The elongation per pitch is drawn as a percentage of the pitch
(delta_t / t), the running time in hours, cycles in millions. Every value
drawn is read from the run files: the readings, the fitted curve with its
band, the limits and the lives with their intervals.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pipeline.report.recorded import level, recorded
from pipeline.report.render import report_style
from pipeline.report.stiffness_figures import plain

#: How the running coordinate is drawn, by abscissa: axis label and SI units per unit drawn.
RUNNING_AXIS = {"time": ("running time [h]", 3600.0), "cycles": ("cycles [10⁶]", 1e6)}

#: Line style of each limit: Paper 004's eq. (3) and the lab's.
LIMIT_STYLE = {"eq3": {"color": "C3", "linestyle": "--"},
               "lab": {"color": "C2", "linestyle": ":"}}

#: What each limit is called on a figure.
LIMIT_LABEL = {"eq3": "jump-off limit, Paper 004 eq. (3)", "lab": "the lab's limit"}

#: The variables of a wear run file the campaign overview draws.
OVERVIEW_VARIABLES = ("tau", "relative_elongation", "curve_tau", "curve_elongation",
                      "limit_relative", "life")


def _percent(run: xr.Dataset, elongation: np.ndarray) -> np.ndarray:
    """Elongation per pitch [m] as a percentage of the run's pitch."""
    return 100 * np.asarray(elongation, dtype=float) / float(recorded(run.attrs, "pitch"))


def _running(run: xr.Dataset) -> tuple[str, float]:
    """Axis label and scale of the run's running coordinate."""
    return RUNNING_AXIS[str(recorded(run.attrs, "abscissa"))]


def _span(run: xr.Dataset) -> float:
    """The running time (or cycles) a run's figure spans [SI]: its log and its lives."""
    lives = run["life_ci_high"].values if "life_ci_high" in run else run["life"].values
    finite = [value for value in lives if math.isfinite(value)]
    return 1.05 * max([float(run["tau"].values[-1]), *finite])


def _limits(ax, run: xr.Dataset, scale: float, *, label: bool) -> None:
    """The run's limits as horizontal lines, and its lives on them (with their intervals)."""
    for index, name in enumerate(run["limit"].values.astype(str)):
        limit = run.sel(limit=name)
        value = 100 * float(limit["limit_relative"])
        ax.axhline(value, label=f"{LIMIT_LABEL[name]}: {value:.3g} %" if label else None,
                   **LIMIT_STYLE[name])
        life = float(limit["life"])
        if not math.isfinite(life):
            continue
        low, high = float(limit["life_ci_low"]), float(limit["life_ci_high"])
        ax.errorbar([life / scale], [value], xerr=[[(life - low) / scale],
                                                   [(high - life) / scale]],
                    fmt="o", color=LIMIT_STYLE[name]["color"], capsize=4,
                    label=f"life to a limit, {level(limit['life_ci_low'].attrs)} interval"
                    if label and not index else None)


def wear_run(run: xr.Dataset) -> Figure:
    """One wear run: readings, fit with its band, both limits and the lives; residuals.

    Parameters
    ----------
    run : xarray.Dataset
        A wear run file.

    Returns
    -------
    matplotlib.figure.Figure
        Left: delta_t / t [%] against the running time (or cycles), the
        readings, the fitted curve and its pointwise band, the limits and the
        life to each with its interval. Right: the residuals [um per pitch].
    """
    with report_style():
        figure = Figure(figsize=(10.0, 4.2), layout="constrained")
        ax, residuals = figure.subplots(1, 2, width_ratios=(2, 1))
        label, scale = _running(run)
        tau = run["tau"].values / scale
        ax.plot(tau, _percent(run, run["elongation"].values), "o", markersize=3, color="C0",
                label="readings")
        curve = run["curve_tau"].values / scale
        ax.plot(curve, _percent(run, run["curve_elongation"].values), color="black",
                label=f"{recorded(run.attrs, 'model')} model")
        ax.fill_between(curve, _percent(run, run["curve_ci_low"].values),
                        _percent(run, run["curve_ci_high"].values), color="0.6", alpha=0.35,
                        label=f"{level(run['curve_ci_low'].attrs)} band of the fit")
        _limits(ax, run, scale, label=True)
        ax.set_xlim(0, _span(run) / scale)
        ax.set_xlabel(label)
        ax.set_ylabel("elongation per pitch Δt / t [%]")
        ax.legend(loc="upper left")
        residuals.plot(tau, 1e6 * run["residual"].values, "o", markersize=3, color="C0")
        residuals.axhline(0.0, color="black", linewidth=0.8)
        residuals.set_xlabel(label)
        residuals.set_ylabel("residual per pitch [µm]")
        figure.suptitle(plain(f"Run {run.attrs.get('run_id', '')}: wear of chain "
                              f"{run.attrs.get('chain', '')}"))
    return figure


def wear_overview(runs: Sequence[xr.Dataset]) -> Figure:
    """Every wear run of a campaign: readings and fits against the running coordinate.

    Parameters
    ----------
    runs : sequence of xarray.Dataset
        The wear run files (their :data:`OVERVIEW_VARIABLES` and attributes).

    Returns
    -------
    matplotlib.figure.Figure
        One panel per running coordinate the runs use (time, cycles): per run
        its readings and fitted curve, delta_t / t [%], and its limits as
        lines in the run's colour (dashed: eq. (3); dotted: the lab's).
    """
    abscissae = [name for name in RUNNING_AXIS
                 if any(recorded(run.attrs, "abscissa") == name for run in runs)]
    with report_style():
        figure = Figure(figsize=(max(7.0, 5.5 * len(abscissae)), 4.6), layout="constrained")
        axes = dict(zip(abscissae, np.atleast_1d(figure.subplots(1, len(abscissae))),
                        strict=True))
        for index, run in enumerate(runs):
            ax = axes[str(recorded(run.attrs, "abscissa"))]
            label, scale = _running(run)
            colour = f"C{index % 10}"
            ax.plot(run["tau"].values / scale, 100 * run["relative_elongation"].values, "o",
                    markersize=2.5, color=colour)
            ax.plot(run["curve_tau"].values / scale,
                    _percent(run, run["curve_elongation"].values), color=colour,
                    label=plain(str(run.attrs.get("run_id", ""))))
            for name in run["limit"].values.astype(str):
                ax.axhline(100 * float(run["limit_relative"].sel(limit=name)), color=colour,
                           linestyle=LIMIT_STYLE[name]["linestyle"], linewidth=0.9)
            ax.set_xlabel(label)
        for ax in axes.values():
            ax.set_xlim(left=0)
            ax.set_ylabel("elongation per pitch Δt / t [%]")
            ax.legend(loc="upper left", ncols=2)
        figure.suptitle("Wear runs: readings (points), fits (lines), limits (dashed: Paper "
                        "004 eq. (3); dotted: the lab's)")
    return figure
