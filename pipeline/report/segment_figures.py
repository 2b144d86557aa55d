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
