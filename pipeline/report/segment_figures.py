"""Figure of the report's segment-load section: Paper 003 measured against the model.

:func:`contact_ratios_vs_s` draws, per drum of the campaign (from ``summary.nc``,
:mod:`pipeline.segment_summary`), the model's F_K / F and F_P / F over the
contact distance s (Paper 003, eqs. (1)-(4)) for the campaign's chain and
drum, with the measured medians of every operating point at the fitted s, and
the friction increase 2 F_K / F - 1 against Paper 003's claim of over 50 %.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pipeline.fit.segment_load import contact_ratios
from pipeline.report.render import report_style
from pipeline.report.stiffness_figures import plain

#: Points of a model curve over s.
CURVE_POINTS = 200


def _curve(row: xr.Dataset, beta: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """s [m], F_K / F and F_P / F [1] of the model from the groove width c to c + 0.85 (2 k - c)."""
    chain = {"r_outer": float(row["segment_torus_radius"]),
             "d": float(row["segment_bar_diameter"]),
             "groove_width": float(row["segment_groove_width"])}
    eps_n = float(row["segment_link_inclination"])
    low = chain["groove_width"]
    high = 2 * contact_ratios(chain, beta=beta, s=low, eps_n=eps_n).k
    s = np.linspace(low, low + 0.85 * (high - low), CURVE_POINTS)
    ratios = [contact_ratios(chain, beta=beta, s=float(value), eps_n=eps_n) for value in s]
    return (s, np.array([r.contact_force for r in ratios]),
            np.array([r.side_force for r in ratios]))


def contact_ratios_vs_s(summary: xr.Dataset) -> Figure:
    """F_K / F, F_P / F and the friction increase over s: model curves, measured points.

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign summary with dimension ``segment_point``.

    Returns
    -------
    matplotlib.figure.Figure
        Left: per drum the model's F_K / F (solid) and F_P / F (dashed) over s
        at the fitted beta (or the run sheet's, when s is fitted), the measured
        medians of each run at the fitted s (or the run sheet's, when beta is
        fitted) with their standard errors, and the run sheet's s. Right: the
        friction increase 2 F_K / F - 1 of the same model and the measured
        points, with Paper 003's claimed 50 %.
    """
    drums = list(dict.fromkeys(summary["segment_drum"].values.astype(str)))
    with report_style():
        figure = Figure(figsize=(11.0, 4.6), layout="constrained")
        ratio_ax, friction_ax = figure.subplots(1, 2)
        for index, drum in enumerate(drums):
            rows = summary.isel(segment_point=np.flatnonzero(
                summary["segment_drum"].values.astype(str) == drum))
            first = rows.isel(segment_point=0)
            fitted = str(first["segment_fitted"].values)
            beta = (float(first["segment_fit_beta"]) if fitted == "beta"
                    else float(first["segment_flank_inclination"]))
            if math.isnan(beta):  # beta could not be fitted: the run sheet's curve alone
                beta = float(first["segment_flank_inclination"])
            s, contact, side = _curve(first, beta)
            colour = f"C{index % 10}"
            label = f"drum {plain(drum)}, β = {math.degrees(beta):.3g}°"
            ratio_ax.plot(1e3 * s, contact, color=colour, label=f"F_K/F model, {label}")
            ratio_ax.plot(1e3 * s, side, color=colour, linestyle="--",
                          label="F_P/F model")
            friction_ax.plot(1e3 * s, 100 * (2 * contact - 1), color=colour, label=label)
            at = (float(first["segment_fit_s"]) if fitted == "s"
                  else float(first["segment_contact_distance"]))
            if not math.isnan(at):
                x = np.full(rows.sizes["segment_point"], 1e3 * at)
                ratio_ax.errorbar(x, rows["segment_contact_ratio"].values,
                                  yerr=rows["segment_contact_ratio_stderr"].values, fmt="o",
                                  color=colour, markersize=4, label="F_K/F measured (runs)")
                ratio_ax.errorbar(x, rows["segment_side_ratio"].values,
                                  yerr=rows["segment_side_ratio_stderr"].values, fmt="s",
                                  color=colour, markersize=4, mfc="none",
                                  label="F_P/F measured (runs)")
                friction_ax.errorbar(x, 100 * rows["segment_friction_increase"].values,
                                     yerr=200 * rows["segment_contact_ratio_stderr"].values,
                                     fmt="o", color=colour, markersize=4)
            for ax in (ratio_ax, friction_ax):
                ax.axvline(1e3 * float(first["segment_contact_distance"]), color=colour,
                           linestyle=":", linewidth=0.9)
        friction_ax.axhline(100 * float(summary["segment_friction_claim"][0]), color="0.3",
                            linestyle="--", label="Paper 003's claim: over 50 %")
        ratio_ax.set_ylabel("load ratio [-]")
        friction_ax.set_ylabel("friction increase 2 F_K/F − 1 [%]")
        for ax in (ratio_ax, friction_ax):
            ax.set_xlabel("contact distance s [mm]")
            ax.legend(loc="upper left", fontsize="small")
        figure.suptitle("Segment loads (Paper 003, eqs. (1)-(4)): model curves, measured medians "
                        "at the fitted geometry; dotted: the run sheet's s")
    return figure


#: Colours of the logged channels on a run's page.
_CHANNEL_COLOURS = {"F": "0.2", "F_K1": "C0", "F_K2": "C1", "F_P": "C2"}
#: Labels of the logged channels.
_CHANNEL_LABELS = {"F": "chain force F", "F_K1": "segment 1 F_K1", "F_K2": "segment 2 F_K2",
                   "F_P": "side force F_P"}
#: The zero each channel's plateau median was taken from (None: the chain force has none).
_ZEROS = {"F": None, "F_K1": "zero_K1", "F_K2": "zero_K2", "F_P": "zero_P"}


def _plateaus(ax, run: xr.Dataset, start: float, end: float) -> None:
    """The detected plateaus within [start, end] [s]: shaded, each channel's median drawn."""
    valid = run["status"].values.astype(str) == "ok"
    for index in np.flatnonzero((run["plateau_stop"].values >= start)
                                & (run["plateau_start"].values <= end)):
        left, right = (float(run[name][index]) for name in ("plateau_start", "plateau_stop"))
        ax.axvspan(left, right, color="C2" if valid[index] else "0.6", alpha=0.15, linewidth=0)
        for channel, zero in _ZEROS.items():
            if channel not in run or f"trace_{channel}" not in run:
                continue
            level = float(run[channel][index]) + (0.0 if zero is None else float(run[zero][index]))
            ax.hlines(level / 1e3, left, right, color=_CHANNEL_COLOURS[channel], linewidth=2.2)


def segment_run(run: xr.Dataset) -> Figure:
    """A segment-load run: its log with the detected plateaus, and the ratio per seating.

    Parameters
    ----------
    run : xarray.Dataset
        One segment-load run file (:class:`pipeline.results.segment_load.SegmentLoadResult`):
        ``trace_*`` on ``sample``, the seatings' times, plateau medians, zeros,
        ratios and ``status`` on ``seating``, the medians and the model's ratios.

    Returns
    -------
    matplotlib.figure.Figure
        Top: the chain force and the segment forces [kN] as logged around the
        first seatings, the plateaus the ratios were taken over shaded (grey:
        excluded seatings) with each channel's plateau median as a thick line.
        Bottom: F_K / F (and F_P / F) of every seating (Paper 003, eqs. (3)-(4)),
        excluded seatings open, with the run's medians and the model's ratios
        at the run sheet's geometry.
    """
    with report_style():
        figure = Figure(figsize=(10.0, 7.0), layout="constrained")
        log_ax, ratio_ax = figure.subplots(2, 1)
        time = run["trace_time"].values
        for channel in _CHANNEL_COLOURS:
            if f"trace_{channel}" in run:
                log_ax.plot(time, run[f"trace_{channel}"].values / 1e3, linewidth=0.8,
                            color=_CHANNEL_COLOURS[channel], label=_CHANNEL_LABELS[channel])
        if time.size:
            _plateaus(log_ax, run, float(time[0]), float(time[-1]))
        log_ax.set_xlabel("time [s]")
        log_ax.set_ylabel("force [kN]")
        log_ax.legend(loc="center right", fontsize="small")
        log_ax.set_title("log around the first seatings; shaded: the plateaus, thick: their "
                         "medians", fontsize="medium")
        seating = run["seating"].values
        valid = run["status"].values.astype(str) == "ok"
        for name, label, colour in (("contact_force_ratio", "F_K/F", "C0"),
                                    ("side_force_ratio", "F_P/F", "C2")):
            if name not in run:
                continue
            values = run[name].values
            ratio_ax.plot(seating[valid], values[valid], "o", color=colour, markersize=4,
                          label=f"{label} per seating")
            ratio_ax.plot(seating[~valid], values[~valid], "o", color=colour, mfc="none",
                          markersize=4, label=f"{label} excluded" if (~valid).any() else None)
            ratio_ax.axhline(float(run[f"{name}_median"]), color=colour,
                             label=f"{label} median of the run")
            ratio_ax.axhline(float(run[f"model_{name}"]), color=colour, linestyle="--",
                             label=f"{label} model, run sheet's geometry")
        ratio_ax.set_xlabel("seating [-]")
        ratio_ax.set_ylabel("load ratio [-]")
        ratio_ax.legend(loc="center right", fontsize="small")
        figure.suptitle("Segment-load run (Paper 003, eqs. (3)-(4))")
    return figure
