"""Figures of the report's impact section: engagement logs against Paper 000's model.

Each function takes processed data (a run dataset of
:mod:`pipeline.results.engagement` or the campaign summary of
:func:`pipeline.compare.impact_summary`) and returns a
:class:`matplotlib.figure.Figure`; the caller builds them inside
:func:`pipeline.report.render.report_style` and renders them with
:func:`pipeline.report.render.svg`.

The model lines are computed by :func:`pipeline.fit.impact_model.model_tensions`
(Paper 000, eq. (16) with (1)-(2)) over fine grids of omega or psi, with the k
the summary's theory used (its attribute ``k_theory``, Ryabov's 2) and the
fitted ``k_fit``; they need the model's inputs per operating point, which the
summary carries: ``teeth``,
``apex_angle`` [degree], ``omega`` [1/s], the chain's pitch ``t`` [m], bar
diameter ``d`` [m] and ``mass_per_length`` [kg/m], ``E0`` [N] and
``branch_length`` [m].

Error bars of the measured medians are their standard errors (``N_u1_stderr``,
``N_u2_stderr``): the uncertainty the fit of k weighs every point with, not the
spread of the single events (the interquartile range, in the summary tables).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import xarray as xr
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from pipeline.fit.impact_model import POINT_COLUMNS, model_tensions
from pipeline.report.recorded import recorded
from pipeline.theory._published import parse_inputs
from pipeline.theory.wheel_impact import compare_published
from pipeline.units import from_si

#: Most points drawn per line; longer signals are reduced to a min/max envelope.
MAX_LINE_POINTS = 4000
#: Seating periods shown by :func:`impact_zoom`.
ZOOM_PERIODS = 3
#: Part of a seating period shown before the first impact of the zoom.
ZOOM_LEAD = 0.25
#: Points of the model lines over omega and over psi.
GRID_POINTS = 200
#: Apex angles of Paper 000's Figs. 3 and 4 [degree].
PAPER_APEX_RANGE = (20.0, 60.0)
#: Columns that, with omega, identify a wheel and its branch (one panel each).
_WHEEL = ("teeth", "apex_angle", "t", "d", "mass_per_length", "E0", "branch_length")
#: Columns that, with z and psi, identify the conditions of one apex-angle panel.
_CONDITIONS = ("omega", "t", "d", "mass_per_length", "E0", "branch_length")
_IMPACT_COLORS = {"N_u1": "C0", "N_u2": "C3"}
_IMPACT_TEXT = {"N_u1": "impact 1 (idle flank)", "N_u2": "impact 2 (working flank)"}


def _envelope(x: np.ndarray, y: np.ndarray, max_points: int = MAX_LINE_POINTS
              ) -> tuple[np.ndarray, np.ndarray]:
    """`x`, `y` reduced to at most `max_points` keeping each bucket's minimum and maximum.

    Unlike a plain stride, the envelope keeps every peak of the signal.
    """
    n = x.size
    if n <= max_points:
        return x, y
    stride = math.ceil(2 * n / max_points)
    index = np.minimum(np.arange(math.ceil(n / stride) * stride), n - 1).reshape(-1, stride)
    values = y[index]
    rows = np.arange(index.shape[0])
    low = index[rows, np.where(np.isnan(values), np.inf, values).argmin(axis=1)]
    high = index[rows, np.where(np.isnan(values), -np.inf, values).argmax(axis=1)]
    keep = np.sort(np.stack([low, high], axis=1), axis=1).ravel()
    return x[keep], y[keep]


def _zoom_window(run: xr.Dataset) -> tuple[float, float]:
    """Start and end [s] of the zoom: from just before the first valid impact."""
    period = float(run["seating_period"])
    valid = run["event_time"].values[run["status"].values == "ok"]
    start = valid[0] - ZOOM_LEAD * period if valid.size else float(run["time"][0])
    return start, start + ZOOM_PERIODS * period


def _first_peak_delay(run: xr.Dataset) -> float:
    """Time from a strike's onset to its first peak [s], acos(zeta) / omega_d (0 if unknown)."""
    omega_n, zeta = float(run["omega_n"]), float(run["zeta"])
    if not (np.isfinite(omega_n) and np.isfinite(zeta) and 0 <= zeta < 1):
        return 0.0
    return math.acos(zeta) / (omega_n * math.sqrt(1 - zeta**2))


def impact_zoom(run: xr.Dataset) -> Figure:
    """A few seating periods of an engagement log with the detected impacts marked.

    Parameters
    ----------
    run : xarray.Dataset
        One engagement run file (:meth:`pipeline.results.EngagementResult.to_dataset`):
        ``time``, ``force`` on ``sample``; ``event_time``, ``impact2_time``,
        ``baseline``, ``N_u1``, ``N_u2``, ``status`` on ``event``; the scalars
        ``seating_period``, ``omega_n``, ``zeta``, ``omega_measured``.

    Returns
    -------
    matplotlib.figure.Figure
        Branch tension [kN] over time [ms] for :data:`ZOOM_PERIODS` seating
        periods from just before the first valid event: the onsets of impact 1
        (idle flank) and impact 2 (working flank) as dashed lines, the slow
        baseline tension of each event, and the strike amplitudes N_u1, N_u2
        (the measured counterparts of Paper 000's impact tensions) as arrows
        from the baseline, drawn at the strike's first peak. Onsets of events
        excluded from the statistics are grey. A long window is reduced to a
        min/max envelope of at most :data:`MAX_LINE_POINTS` points.
    """
    start, end = _zoom_window(run)
    time, force = run["time"].values, run["force"].values
    shown = (time >= start) & (time <= end)
    x, y = _envelope((time[shown] - start) * 1e3, force[shown] / 1e3)

    figure = Figure(layout="constrained")
    ax = figure.add_subplot()
    ax.plot(x, y, color="0.2", linewidth=0.8, label="branch tension (measured)")

    events = run[["event_time", "impact2_time", "baseline", "N_u1", "N_u2", "status"]]
    events = events.to_dataframe()
    events = events[events["event_time"].between(start, end)]
    valid = events[events["status"] == "ok"]
    excluded = events[events["status"] != "ok"]
    delay = _first_peak_delay(run)
    for impact, onset, style in (("N_u1", "event_time", "--"), ("N_u2", "impact2_time", "-.")):
        color = _IMPACT_COLORS[impact]
        onsets = valid[onset][valid[onset].between(start, end)]
        for number, value in enumerate(onsets):
            ax.axvline((value - start) * 1e3, color=color, linestyle=style, linewidth=1.0,
                       label=f"onset of {_IMPACT_TEXT[impact]}" if number == 0 else None)
        drawn = valid[np.isfinite(valid["baseline"]) & np.isfinite(valid[impact])
                      & valid[onset].between(start, end - delay)]
        if drawn.empty:
            continue
        tips_x = (drawn[onset].to_numpy() + delay - start) * 1e3
        bases = drawn["baseline"].to_numpy() / 1e3
        tips = bases + drawn[impact].to_numpy() / 1e3
        ax.vlines(tips_x, bases, tips, color=color, linewidth=1.8,
                  label=f"{impact}: strike amplitude above the baseline")
        ax.plot(tips_x, tips, linestyle="none", marker="^", markersize=6, color=color)
    based = valid[np.isfinite(valid["baseline"])]
    ax.hlines(based["baseline"] / 1e3, (based["event_time"] - start) * 1e3,
              (np.minimum(based["event_time"] + float(run["seating_period"]), end) - start) * 1e3,
              color="C2", linestyle=":", linewidth=1.5, label="baseline (slow tension)")
    for number, value in enumerate(excluded["event_time"]):
        ax.axvline((value - start) * 1e3, color="0.6", linestyle=":",
                   label="excluded event" if number == 0 else None)

    ax.set_xlabel(f"time since t = {start:.4g} s of the log [ms]")
    ax.set_ylabel("branch tension [kN]")
    n_valid = int((run["status"].values == "ok").sum())
    run_id = run.attrs.get("run_id", "engagement run")
    ax.set_title(f"Run {run_id}: chain tension while links seat on the wheel\n"
                 f"{ZOOM_PERIODS} seatings at ω = {float(run['omega_measured']):.3g} 1/s; "
                 f"{n_valid} of {run.sizes['event']} impacts valid")
    figure.legend(loc="outside lower center", ncols=2)
    return figure


def _operating_points(summary: xr.Dataset) -> pd.DataFrame:
    """The model's inputs per operating point of a campaign summary, in SI units.

    Parameters
    ----------
    summary : xarray.Dataset
        Campaign summary on dimension ``operating_point``.

    Returns
    -------
    pandas.DataFrame
        The columns of :data:`pipeline.fit.impact_model.POINT_COLUMNS` (apex
        angle in rad) and the measured and model tensions of the summary.

    Raises
    ------
    KeyError
        When the summary lacks a model input (e.g. the chain's ``t``, ``d``,
        ``mass_per_length``), naming it.
    """
    missing = [name for name in POINT_COLUMNS if name not in summary]
    if missing:
        raise KeyError(
            f"the summary has no {', '.join(missing)} on 'operating_point': the model lines "
            "of Paper 000 need every input of pipeline.fit.impact_model.POINT_COLUMNS "
            "(pipeline.compare.impact_summary must store them)")
    names = [name for name in summary.data_vars if summary[name].dims == ("operating_point",)]
    points = summary[names].to_dataframe()
    points["apex_angle"] = np.radians(points["apex_angle"])
    return points


def _model_over(points: pd.DataFrame, column: str, grid: np.ndarray, k: float
                ) -> tuple[np.ndarray, np.ndarray]:
    """N_u1, N_u2 [N] of the first row of `points` with `column` swept over `grid`."""
    sweep = pd.DataFrame({name: points[name].iloc[0] for name in POINT_COLUMNS},
                         index=range(grid.size))
    sweep[column] = grid
    return model_tensions(sweep, k=k)


def _conditions_text(row: pd.Series) -> str:
    """The chain and branch of an operating point, for titles."""
    return (f"chain {row['d'] * 1e3:g}x{row['t'] * 1e3:g} mm, {row['mass_per_length']:g} kg/m, "
            f"E0 = {row['E0']:.3g} N, L = {row['branch_length']:g} m")


def _panels(count: int, size: tuple[float, float]) -> tuple[Figure, list[Axes]]:
    """A constrained figure of `count` panels, at most three a row, sharing both axes."""
    columns = min(3, count)
    rows = math.ceil(count / columns)
    figure = Figure(figsize=(size[0] * columns + 0.6, size[1] * rows + 1.4),
                    layout="constrained")
    axes = figure.subplots(rows, columns, sharex=True, sharey=True, squeeze=False).ravel()
    for ax in axes[count:]:
        ax.remove()
    return figure, list(axes[:count])


def _errorbar(ax: Axes, x: np.ndarray, points: pd.DataFrame, impact: str, marker: str,
              color: str, label: str) -> None:
    """Measured medians of `impact` with their standard errors."""
    ax.errorbar(x, points[f"{impact}_meas"].to_numpy(), yerr=points[f"{impact}_stderr"].to_numpy(),
                linestyle="none", marker=marker, markersize=5, capsize=2, color=color,
                label=label)


def impact_vs_omega(summary: xr.Dataset) -> Figure:
    """Measured impact tensions against wheel speed, with the fitted model and k = 2.

    Parameters
    ----------
    summary : xarray.Dataset
        Campaign summary (:func:`pipeline.compare.impact_summary`) with the
        model inputs of every operating point (see :func:`_operating_points`),
        the scalar ``k_fit`` and the attribute ``k_theory``.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per wheel (z, psi; and chain and branch where they vary):
        the measured medians of N_u1 and N_u2 with their standard errors
        against the run sheet's omega, and Paper 000's eq. (16) over omega with
        the fitted k (solid) and the theory's k, Ryabov's 2 (dashed).
    """
    points = _operating_points(summary)
    wheels = [group for _, group in points.groupby(list(_WHEEL), sort=True)]
    k_fit, k_stderr = float(summary["k_fit"]), float(summary["k_fit_stderr"])
    k_theory = float(recorded(summary.attrs, "k_theory"))
    theory = f"k = {k_theory:g} (Ryabov)"
    grid = np.linspace(0.0, 1.1 * points["omega"].max(), GRID_POINTS)
    figure, axes = _panels(len(wheels), (3.0, 2.6))
    several = points[list(_WHEEL[2:])].drop_duplicates().shape[0] > 1
    for ax, wheel in zip(axes, wheels, strict=True):
        lines = {theory: _model_over(wheel, "omega", grid, k_theory)}
        if np.isfinite(k_fit):
            lines[f"fitted k = {k_fit:.3f} ± {k_stderr:.3f}"] = _model_over(
                wheel, "omega", grid, k_fit)
        for number, impact in enumerate(("N_u1", "N_u2")):
            color = _IMPACT_COLORS[impact]
            for name, model in lines.items():
                ax.plot(grid, model[number], color=color,
                        linestyle="--" if name == theory else "-", linewidth=1.0,
                        label=f"{impact} model, {name}")
            _errorbar(ax, wheel["omega"].to_numpy(), wheel, impact, "os"[number], color,
                      f"{impact} measured: median ± standard error")
        first = wheel.iloc[0]
        title = f"z = {first['teeth']:g}, ψ = {math.degrees(first['apex_angle']):g}°"
        ax.set_title(title + (f"\n{_conditions_text(first)}" if several else ""), fontsize=9)
        ax.set_xlabel("wheel speed ω [1/s]")
        ax.set_ylabel("impact tension [N]")
        ax.label_outer()
    figure.suptitle("Impact tensions against wheel speed: measured and Paper 000's model"
                    + ("" if several else f"\n{_conditions_text(points.iloc[0])}"))
    handles, labels = axes[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside lower center", ncols=2)
    return figure


def _published_smallest() -> tuple[dict[str, float], float]:
    """Paper 000's published smallest N_u2: its inputs [SI] and its value [N].

    The row ``N_u2_smallest`` of :func:`pipeline.theory.wheel_impact.compare_published`.
    """
    row = compare_published().set_index("quantity").loc["N_u2_smallest"]
    return parse_inputs(row["inputs"]), float(row["published"])


def impact_vs_apex(summary: xr.Dataset) -> Figure:
    """Impact tensions against the tooth apex angle per number of teeth (Paper 000, Figs. 3-4).

    Parameters
    ----------
    summary : xarray.Dataset
        Campaign summary with the model inputs of every operating point (see
        :func:`_operating_points`) and the attribute ``k_theory``.

    Returns
    -------
    matplotlib.figure.Figure
        One panel per measured omega (and chain and branch where they vary):
        Paper 000's eq. (16) with the theory's k (Ryabov's 2) over psi in 20..60 deg (widened to the
        campaign's wheels), N_u1 (the same for every z) and N_u2 for each z of
        the campaign, with the measured medians at that omega (standard errors
        as error bars). Where the panel's conditions are those of Paper 000's
        example (:func:`pipeline.theory.wheel_impact.compare_published`), its
        published smallest N_u2 is marked.
    """
    points = _operating_points(summary)
    psi_deg = np.degrees(points["apex_angle"])
    grid_deg = np.linspace(min(PAPER_APEX_RANGE[0], psi_deg.min()),
                           max(PAPER_APEX_RANGE[1], psi_deg.max()), GRID_POINTS)
    grid = np.radians(grid_deg)
    panels = [group for _, group in points.groupby(list(_CONDITIONS), sort=True)]
    several = points[list(_CONDITIONS[1:])].drop_duplicates().shape[0] > 1
    teeth = sorted(points["teeth"].unique())
    colors = {z: f"C{number}" for number, z in enumerate(teeth)}
    published, smallest = _published_smallest()
    case = {name: published[name] for name in _CONDITIONS}
    k = float(recorded(summary.attrs, "k_theory"))
    figure, axes = _panels(len(panels), (3.4, 3.2))
    for ax, panel in zip(axes, panels, strict=True):
        first = panel.iloc[0]
        n_u1, _ = _model_over(panel, "apex_angle", grid, k)
        ax.plot(grid_deg, n_u1, color="black", linewidth=1.2,
                label=f"N_u1 model, any z (k = {k:g})")
        for z in teeth:
            at_z = panel.assign(teeth=z)
            _, n_u2 = _model_over(at_z, "apex_angle", grid, k)
            ax.plot(grid_deg, n_u2, color=colors[z], linewidth=1.2,
                    label=f"N_u2 model, z = {z:g} (k = {k:g})")
            measured = panel[panel["teeth"] == z]
            x = np.degrees(measured["apex_angle"].to_numpy())
            _errorbar(ax, x, measured, "N_u1", "o", colors[z], f"N_u1 measured, z = {z:g}")
            _errorbar(ax, x, measured, "N_u2", "s", colors[z], f"N_u2 measured, z = {z:g}")
        if all(np.isclose(first[name], value) for name, value in case.items()):
            psi = from_si(published["psi"], "deg")
            ax.plot(psi, smallest, linestyle="none", marker="*",
                    markersize=12, markerfacecolor="none", markeredgecolor="black",
                    label=f"Paper 000 published: smallest N_u2 = {smallest:g} N "
                          f"(z = {published['z']:g}, ψ = {psi:g}°)")
        title = f"ω = {first['omega']:g} 1/s"
        ax.set_title(title + (f"\n{_conditions_text(first)}" if several else ""), fontsize=9)
        ax.set_xlabel("tooth apex angle ψ [°]")
        ax.set_ylabel("impact tension [N]")
        ax.label_outer()
    figure.suptitle("Impact tensions against tooth apex angle (Paper 000, Figs. 3-4), "
                    "measured medians ± standard error"
                    + ("" if several else f"\n{_conditions_text(points.iloc[0])}"))
    handles: dict[str, object] = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(label, handle)
    figure.legend(list(handles.values()), list(handles), loc="outside lower center", ncols=3)
    return figure
