"""Figures of the report's roller-chain section: strike amplitude against speed per sprocket.

:func:`amplitude_vs_speed` takes the campaign summary (its ``sprocket_point``
table, :mod:`pipeline.roller_summary`) and returns a matplotlib
:class:`~matplotlib.figure.Figure`, one panel per sprocket: the measured
strike amplitudes with their standard errors, the model with the fitted xi
and with the involute's xi (Paper 002), and the speed limit n_max of eq. (8).
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from pipeline.report.render import report_style


def _sprockets(summary: xr.Dataset) -> list[str]:
    """The sprockets of the table, in its order."""
    return list(dict.fromkeys(summary["roller_sprocket"].values.astype(str)))


def amplitude_vs_speed(summary: xr.Dataset) -> Figure:
    """Measured strike amplitude against sprocket speed, one panel per sprocket.

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign summary with its ``sprocket_point`` table.

    Returns
    -------
    matplotlib.figure.Figure
        Amplitudes [N] against speed [rpm]: the measured medians with two
        standard errors, the model's proportional law for the fitted xi and for
        the involute's xi, and n_max of Paper 002 eq. (8) as a vertical line.
    """
    sprockets = _sprockets(summary)
    with report_style():
        figure = Figure(figsize=(4.2 * len(sprockets), 3.4), layout="constrained")
        axes = np.atleast_1d(figure.subplots(1, len(sprockets), squeeze=False)[0])
        for ax, key in zip(axes, sprockets, strict=True):
            rows = summary.where(summary["roller_sprocket"] == key, drop=True)
            n, amplitude = rows["roller_n"].values, rows["strike_amplitude"].values
            ax.errorbar(n, amplitude, yerr=2 * rows["strike_amplitude_stderr"].values, fmt="o",
                        color="C0", label="measured (±2 standard errors)")
            grid = np.linspace(0.0, 1.1 * np.nanmax(n), 50)
            slope = float(rows["strike_amplitude_model"].values[0] / n[0]) if n.size else math.nan
            xi_fit, xi_model = float(rows["xi_fit"].values[0]), float(rows["xi_model"].values[0])
            if math.isfinite(xi_fit):
                ax.plot(grid, slope * grid, color="C1", label=f"model, fitted ξ = {xi_fit:.4g}")
                if math.isfinite(xi_model):
                    ax.plot(grid, slope * xi_model / xi_fit * grid, color="C2", linestyle="--",
                            label=f"model, involute ξ = {xi_model:.4g}")
                n_max = float(rows["n_max"].values[0])
                if n_max < 1.1 * np.nanmax(n):
                    ax.axvline(n_max, color="C3", linestyle=":",
                               label=f"n_max = {n_max:.4g} rpm, eq. (8)")
            ax.set(title=f"sprocket {key}, z = {int(rows['roller_teeth'].values[0])}",
                   xlabel="sprocket speed n [rpm]", ylabel="strike amplitude [N]")
            ax.set_xlim(left=0)
            ax.set_ylim(bottom=0)
            ax.legend(fontsize="small")
    return figure
