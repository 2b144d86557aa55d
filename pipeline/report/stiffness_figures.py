"""Figures of the report's stiffness section: tensile runs, their fits and the chain E0.

Each function takes the processed datasets (a tensile run file of
:mod:`pipeline.results.tensile`, the campaign ``summary.nc`` of
:func:`pipeline.compare.stiffness_summary`) and returns a matplotlib
:class:`~matplotlib.figure.Figure`; :func:`pipeline.report.render.svg` renders
it. Forces are drawn in kN, strain in per mille; long signals are decimated to
at most :data:`MAX_POINTS` points per line, so that the report stays small.

Strings from the inputs (specimen names, chain keys) are drawn as plain text:
:func:`plain` keeps matplotlib from reading ``$...$`` in them as mathtext, and
the SVG backend escapes them as XML.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from pipeline.report.recorded import level
from pipeline.report.render import report_style

#: Most points drawn per line; longer signals are decimated by an integer stride.
MAX_POINTS = 600

#: Force bins over which the residuals of one fit are averaged.
RESIDUAL_BINS = 30

#: Most specimens of a chain named on the stiffness overview's axis; more are numbered by
#: their place alone (the run table names them).
MAX_SPECIMEN_LABELS = 24
#: Longest specimen label drawn whole [characters]: a longer one (an id drafted from a file
#: name) keeps its start and end around an ellipsis; the run table names it whole.
MAX_LABEL_CHARS = 16

#: The variables of a tensile run file the stiffness overview draws.
OVERVIEW_VARIABLES = ("fit_E0", "fit_E0_ci_low", "fit_E0_ci_high", "single_pull")

#: Newtons per kilonewton: forces are drawn in kN.
KN = 1e3

#: Strain is drawn in per mille.
PER_MILLE = 1e-3


def plain(text: str) -> str:
    """`text` as matplotlib draws it literally: ``$`` escaped (no mathtext)."""
    return text.replace("$", r"\$")


def _stride(n: int) -> int:
    """Integer stride that leaves at most :data:`MAX_POINTS` of `n` samples."""
    return max(1, math.ceil(n / MAX_POINTS))


def _branch_codes(run: xr.Dataset) -> dict[str, int]:
    """Branch name -> flag value of ``sample_branch`` (CF ``flag_meanings``)."""
    attrs = run["sample_branch"].attrs
    return dict(zip(attrs["flag_meanings"].split(), (int(v) for v in attrs["flag_values"]),
                    strict=True))


def _cycle_colour(cycle: int) -> str:
    """Colour of a load cycle: grey before the first loading, then the tab10 cycle."""
    return "0.55" if cycle == 0 else f"C{(cycle - 1) % 10}"


def _cycle_label(cycle: int) -> str:
    if cycle == 0:
        return "preload (before cycle 1)"
    return "cycle 1 (seating, not counted)" if cycle == 1 else f"cycle {cycle}"


def _fits(run: xr.Dataset):
    """The finite fits of a run as ``(cycle, branch, E0, intercept, low, high)`` [N]."""
    for cycle in run["cycle"].values:
        for branch in run["branch"].values:
            fit = run.sel(cycle=cycle, branch=branch)
            values = [float(fit[f"fit_{name}"]) for name in
                      ("E0", "intercept", "window_low", "window_high")]
            if all(np.isfinite(values)):
                yield int(cycle), str(branch), *values


def _in_window(run: xr.Dataset, cycle: int, branch: str, low: float, high: float) -> np.ndarray:
    """Mask of the samples of one fit: its cycle and branch, force inside its window."""
    force = run["force"].values
    return ((run["sample_cycle"].values == cycle)
            & (run["sample_branch"].values == _branch_codes(run)[branch])
            & (force >= low) & (force <= high))


_BRANCH_STYLE = {"loading": "--", "unloading": ":"}


def force_strain(run: xr.Dataset) -> Figure:
    """Force over strain of a tensile run, cycles coloured, fit lines over their windows.

    Parameters
    ----------
    run : xarray.Dataset
        A processed tensile run file (:meth:`pipeline.results.TensileResult.to_dataset`).

    Returns
    -------
    matplotlib.figure.Figure
        Force [kN] over strain [per mille]; each fitted line (black, dashed for
        loading, dotted for unloading) is drawn across its force window only.
    """
    with report_style():
        figure = Figure(figsize=(5.6, 3.8))
        ax = figure.subplots()
        strain, force = run["strain"].values / PER_MILLE, run["force"].values / KN
        cycles = run["sample_cycle"].values
        pull = "single_pull" in run and bool(int(run["single_pull"]))
        for cycle in np.unique(cycles):
            index = np.flatnonzero(cycles == cycle)[::_stride(int(np.sum(cycles == cycle)))]
            ax.plot(strain[index], force[index], color=_cycle_colour(int(cycle)), lw=1.0,
                    label="single pull" if pull and cycle == 1 else _cycle_label(int(cycle)))
        for _cycle, branch, e0, intercept, low, high in _fits(run):
            forces = np.array([low, high])
            ax.plot((forces - intercept) / e0 / PER_MILLE, forces / KN, color="black", lw=1.4,
                    ls=_BRANCH_STYLE.get(branch, "-"))
        handles, _ = ax.get_legend_handles_labels()
        handles += [Line2D([], [], color="black", lw=1.4, ls=style,
                           label=f"fitted line, {branch} (over its fit window)")
                    for branch, style in _BRANCH_STYLE.items()]
        ax.legend(handles=handles, loc="upper left")
        ax.set_xlabel("strain ε = elongation / gauge length [‰]")
        ax.set_ylabel("force [kN]")
        ax.set_title("Force against strain, by load cycle")
    return figure


def _binned_mean(x: np.ndarray, y: np.ndarray, bins: int) -> tuple[np.ndarray, np.ndarray]:
    """Means of `x` and `y` in `bins` equal-width bins of `x` (empty bins left out)."""
    edges = np.linspace(x.min(), x.max(), bins + 1)
    which = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, bins - 1)
    counts = np.bincount(which, minlength=bins)
    keep = counts > 0
    return tuple(np.bincount(which, weights=v, minlength=bins)[keep] / counts[keep]
                 for v in (x, y))


def fit_residuals(run: xr.Dataset) -> Figure:
    """Residuals of every stiffness fit of a tensile run inside its fit window.

    The residuals are averaged in :data:`RESIDUAL_BINS` force bins per fit:
    the noise is given by the RMS residual in the legend, and what is left is
    the systematic part (a curved toe shows as a bow).

    Parameters
    ----------
    run : xarray.Dataset
        A processed tensile run.

    Returns
    -------
    matplotlib.figure.Figure
        Measured minus fitted force [N], mean per force bin, over force [kN];
        one line per cycle and branch (colour: cycle; dashed: loading, dotted:
        unloading), with the RMS residual of each fit in the legend.
    """
    with report_style():
        figure = Figure(figsize=(5.6, 3.8))
        ax = figure.subplots()
        strain, force = run["strain"].values, run["force"].values
        ax.axhline(0.0, color="black", lw=0.8)
        for cycle, branch, e0, intercept, low, high in _fits(run):
            inside = _in_window(run, cycle, branch, low, high)
            if not inside.any():
                continue
            residual = force[inside] - (e0 * strain[inside] + intercept)
            centres, means = _binned_mean(force[inside], residual, RESIDUAL_BINS)
            rms = float(run["fit_residual_rms"].sel(cycle=cycle, branch=branch))
            ax.plot(centres / KN, means, color=_cycle_colour(cycle), lw=1.2,
                    ls=_BRANCH_STYLE.get(branch, "-"),
                    label=f"cycle {cycle}, {branch} (RMS {rms:.0f} N)")
        if ax.get_legend_handles_labels()[0]:
            ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.16), ncols=2)
        ax.set_xlabel("force [kN]")
        ax.set_ylabel("measured − fitted force [N]")
        ax.set_title(f"Fit residuals, mean in {RESIDUAL_BINS} force bins")
    return figure


def _specimen_label(run: xr.Dataset) -> str:
    """The specimen's name, shortened in the middle past :data:`MAX_LABEL_CHARS`.

    >>> _specimen_label(xr.Dataset(attrs={"specimen": "Specimen_RawData_12_Zugversuch"}))
    'Specimen…versuch'
    """
    label = plain(str(run.attrs.get("specimen") or run.attrs.get("run_id", "?")))
    if len(label) <= MAX_LABEL_CHARS:
        return label
    head = MAX_LABEL_CHARS // 2
    return label[:head] + "…" + label[len(label) - (MAX_LABEL_CHARS - head) + 1:]


def _loading_points(runs: Sequence[xr.Dataset]) -> dict[tuple[bool, int], np.ndarray]:
    """The finite loading fits of `runs` grouped by (single pull, cycle).

    Each group holds one row per fit: position on the specimen axis (the run's
    index, the cycles of a run spread over +-0.2 around it), E0, and the lower
    and upper ends of its interval [N]; groups in the order they first appear.
    """
    groups: dict[tuple[bool, int], list[np.ndarray]] = {}
    for position, run in enumerate(runs):
        pull = "single_pull" in run and bool(int(run["single_pull"]))
        loading = {name: run[name].sel(branch="loading").values
                   for name in ("fit_E0", "fit_E0_ci_low", "fit_E0_ci_high")}
        cycles = run["cycle"].values
        offsets = np.linspace(-0.2, 0.2, cycles.size) if cycles.size > 1 else np.zeros(1)
        for index, cycle in enumerate(cycles):
            row = np.array([position + offsets[index], *(values[index]
                                                         for values in loading.values())])
            if np.isfinite(row[1]):
                groups.setdefault((pull, int(cycle)), []).append(row)
    return {key: np.array(rows) for key, rows in groups.items()}


def _specimen_axis(ax, runs: Sequence[xr.Dataset]) -> None:
    """One tick per specimen, labelled up to :data:`MAX_SPECIMEN_LABELS` specimens."""
    ax.set_xlim(-0.6, len(runs) - 0.4)
    labels = [_specimen_label(run) for run in runs]
    if len(runs) <= MAX_SPECIMEN_LABELS and len(set(labels)) == len(labels):
        ax.set_xticks(range(len(runs)), labels, rotation=30 if len(runs) > 3 else 0,
                      ha="right" if len(runs) > 3 else "center")
        ax.set_xlabel("specimen")
    else:
        ax.set_xticks([])
        ax.set_xlabel(f"{len(runs)} specimens, in the order of the run table")


def _chain_panel(ax, summary: xr.Dataset, chain: str, runs: Sequence[xr.Dataset],
                 band: tuple[float, float]) -> None:
    """One chain: per-cycle loading E0 of its specimens, mean, interval, theory and band."""
    row = summary.sel(chain=chain)
    theory = float(row["E0_theory"])
    if np.isfinite(theory):
        ax.axhspan(theory * (1 + band[0]) / KN, theory * (1 + band[1]) / KN, color="C2",
                   alpha=0.18, lw=0, label=f"lab band: theory +{100 * band[0]:g} to "
                                           f"+{100 * band[1]:g} %")
        ax.axhline(theory / KN, color="black", lw=1.2, label="theory, Paper 001 eq. (20)")
    mean = float(row["E0_exp"])
    if np.isfinite(mean):
        ax.axhspan(float(row["E0_exp_ci_low"]) / KN, float(row["E0_exp_ci_high"]) / KN,
                   color="C0", alpha=0.25, lw=0,
                   label=f"{level(summary['E0_exp_ci_low'].attrs)} interval of the chain mean")
        ax.axhline(mean / KN, color="C0", lw=1.4, label="chain mean of the specimens")
    for (pull, cycle), points in _loading_points(runs).items():
        x, e0, low, high = points.T
        error = np.array([e0 - low, high - e0]) / KN
        if pull:  # its one loading is its E0
            ax.errorbar(x, e0 / KN, yerr=error, fmt="s", ms=5, capsize=2, color="C3",
                        label="single pull (its loading)")
            continue
        ax.errorbar(x, e0 / KN, yerr=error, fmt="o", ms=5, capsize=2,
                    color=_cycle_colour(cycle),
                    mfc="white" if cycle == 1 else _cycle_colour(cycle),
                    label=_cycle_label(cycle))
    _specimen_axis(ax, runs)
    ax.set_ylabel("stiffness E0 [kN]")
    ax.set_title(f"chain {plain(chain)}")
    if np.isfinite(theory):
        ax.secondary_yaxis("right", functions=(
            lambda kn: 100 * (kn * KN / theory - 1), lambda pct: theory * (1 + pct / 100) / KN,
        )).set_ylabel("deviation from theory [%]")


def stiffness_by_specimen(summary: xr.Dataset, runs: Sequence[xr.Dataset]) -> Figure:
    """E0 per specimen and cycle for every chain, against its mean, theory and band.

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign summary with the ``chain`` table (the level of its
        intervals in their ``confidence_level``) and attribute ``band``
        (``"0.03 0.06"``).
    runs : sequence of xarray.Dataset
        The processed tensile runs, or their :data:`OVERVIEW_VARIABLES` alone
        (attribute ``chain`` names their chain).

    Returns
    -------
    matplotlib.figure.Figure
        One panel per chain: the loading stiffness of every cycle of every
        specimen with its interval (cycle 1, the seating cycle, hollow:
        not counted), the chain mean with its interval, the theoretical
        E0 and the lab's band shaded; right axis: deviation from theory [%].
    """
    band = tuple(float(value) for value in summary.attrs["band"].split())
    chains = [str(chain) for chain in summary["chain"].values]
    columns = min(2, len(chains))
    rows = math.ceil(len(chains) / columns)
    with report_style():
        figure = Figure(figsize=(5.0 * columns, 3.6 * rows + 0.9), layout="constrained")
        axes = np.atleast_1d(figure.subplots(rows, columns, squeeze=False)).ravel()
        by_chain: dict[str, list[xr.Dataset]] = {chain: [] for chain in chains}
        for run in runs:
            by_chain.get(run.attrs.get("chain"), []).append(run)
        for ax, chain in zip(axes, chains, strict=False):
            _chain_panel(ax, summary, chain, by_chain[chain], band)
        for ax in axes[len(chains):]:
            ax.set_visible(False)
        labels: dict[str, object] = {}
        for ax in axes[:len(chains)]:
            for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
                labels.setdefault(label, handle)
        figure.legend(labels.values(), labels.keys(), loc="outside lower center", ncols=3)
        figure.suptitle("Chain stiffness E0 per specimen and load cycle (loading branches)")
    return figure
