"""Stiffness E0 of a tensile run: linear fits of force over strain per cycle and branch.

Paper 001 defines the chain stiffness ``E0 = P / eps`` [N], the force over the
relative elongation (strain) of the segment; the experiment measures it as the
slope of force over mean-gauge strain on the loading branches of repeated
cycles between the preload and the upper load.

The fit window
--------------
Each branch is fitted with ``force = E0 * strain + intercept`` on a force
window, by default chosen automatically (:func:`scan_windows`):

1. as in ASTM E3076 (least normalised residual): every candidate window
   ``[lo, hi]`` on a grid of :data:`WINDOW_STEP` of the branch's force range,
   ``hi - lo >= min_span``, is fitted by least squares from cumulative sums
   (O(1) per window) and the one with the least residual RMS over its force
   span is kept. A curved region (the slack take-up toe at low load) raises
   the residual and is left out; on a straight branch the widest window wins.
2. a curvature guard: the normalised residual cannot see a curvature below
   the noise (the tail of a toe), however many samples there are, while the
   slope's standard error keeps shrinking. So each limit is moved inward by
   one step while that changes the slope by more than :data:`GUARD_Z`
   standard deviations of the change between nested windows.

A window can also be given in newtons or as a fraction of the branch's range.
The reported fit on the window is made with :class:`lmfit.models.LinearModel`.

Uncertainty
-----------
Two parts, added in quadrature into ``E0_stderr``:

``E0_stderr_stat``
    The ordinary least-squares standard error (``E0_stderr_ols``) assumes
    independent residuals. Gauge quantisation (0.01 mm on a 0.9 m segment) and
    slow disturbances make neighbouring samples err alike, so it is multiplied
    by ``sqrt(tau)``, ``tau = 1 + 2 sum rho_k`` the integrated autocorrelation
    of the residuals in time order (summed while ``rho_k > 0``, Geyer's initial
    positive sequence), the variance inflation of a slope under serially
    correlated errors; ``n_eff = n / tau``.
``E0_stderr_window``
    The largest change of the slope when either window limit moves inward by
    one step (:func:`window_sensitivity`): what is left of a toe inside the
    window shows here, and nowhere else.

The interval uses Student's t with the Welch-Satterthwaite degrees of freedom
(``n_eff - 2`` for the statistical part, the window part taken as exact).

A specimen's ``E0`` is the mean of the loading slopes of cycles ``2..n`` (the
first, seating cycle and the unloading branches are reported beside it); of a
single pull (one loading, ``cycles = 1``), the slope of its loading below the
onset of yield (:func:`yield_onset`), with that fit's interval. Its
statistical part is ``sqrt(sum se_k^2) / m``, scaled up by the Birge ratio
``sqrt(chi^2 / (m - 1))`` when the cycles scatter more than their errors allow
(the Particle Data Group's scale factor); its window part, common to all
cycles, is the mean of theirs. A chain's ``E0`` is the mean over its specimens
with a Student-t interval from their spread.

On the virtual bench (18x64, Paper 001's loads, default noise; 400 seeds) the
specimen ``E0`` errs by 0.007 % RMS (at most 0.02 %), its standard uncertainty
averages 0.010 %, and the 95 % interval covers the truth in 98.8 % of seeds:
slightly conservative, mostly from the Birge scaling of two cycles.

The results table
-----------------
:func:`fit_stiffness` returns a tidy :class:`pandas.DataFrame`, one row per
``(cycle, branch)`` (MultiIndex), with the columns of :class:`LinearFit`:
``E0``, ``E0_stderr``, ``E0_stderr_stat``, ``E0_stderr_window``,
``E0_stderr_ols``, ``E0_ci_low``, ``E0_ci_high``, ``intercept`` [N],
``window_low`` and ``window_high`` [N] (force limits of the window, magnitudes
in the direction of the load), ``n_points``, ``n_eff``, ``r2`` and
``residual_rms`` [N]. ``fits.to_xarray()`` gives the Dataset on dims
``(cycle, branch)``.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import asdict, dataclass

import numpy as np
import pandas as pd
from lmfit.models import LinearModel
from scipy import stats

from pipeline.condition.tensile import TensileRun
from pipeline.errors import FitError

#: Grid step of the candidate window limits, as a fraction of the branch's force range.
WINDOW_STEP = 0.05

#: Default smallest window, as a fraction of the branch's force range.
MIN_SPAN = 0.4

#: Fewest samples a fit window may hold.
MIN_POINTS = 10

#: Z-score above which a slope change moves a window limit inward (curvature guard).
GUARD_Z = 2.0

#: Branches fitted by default.
FITTED_BRANCHES = ("loading", "unloading")

#: Width of the force bands on which the tangent slope of a loading is measured, as a
#: fraction of its force range (:func:`yield_onset`).
TANGENT_BAND = 0.1

#: Step between the tangent bands, as a fraction of the force range.
TANGENT_STEP = 0.025

#: The curve has left its linear region where the tangent slope has fallen by more than
#: this fraction below its linear-region (largest) value, beyond its noise.
YIELD_SLOPE_DROP = 0.05

#: The part of a loading's force range [1] over which a start steeper than what follows
#: (an extensometer's knife edges seating) is looked for by :func:`yield_onset`.
SEATING_SPAN = 0.25

#: Bands of one slope that must follow a steep start for it to be a seating, not a
#: specimen softening from its start (see :func:`yield_onset`).
SEATED_BANDS = 4

#: Level of every interval of this module: of a fit, of a specimen's and of a chain's E0.
CONFIDENCE = 0.95


@dataclass(frozen=True)
class LinearFit:
    """A straight-line fit of force over strain on one window (SI units)."""

    E0: float  #: slope [N]
    E0_stderr: float  #: combined standard uncertainty [N]: statistical and window
    E0_stderr_stat: float  #: autocorrelation-corrected standard error [N]
    E0_stderr_window: float  #: standard uncertainty from the window choice [N]
    E0_stderr_ols: float  #: ordinary least-squares standard error [N]
    E0_ci_low: float  #: lower limit of the confidence interval [N]
    E0_ci_high: float  #: upper limit of the confidence interval [N]
    intercept: float  #: force at zero strain [N]
    window_low: float  #: lower force limit of the window [N]
    window_high: float  #: upper force limit of the window [N]
    n_points: int  #: samples in the window
    n_eff: float  #: effective number of independent samples
    dof: float  #: degrees of freedom of the interval (Welch-Satterthwaite)
    r2: float  #: coefficient of determination
    residual_rms: float  #: root-mean-square residual [N]


def integrated_autocorrelation(residuals: np.ndarray) -> float:
    """Integrated autocorrelation time ``tau = 1 + 2 sum rho_k`` of a series [samples].

    The sum runs over lags while the autocorrelation stays positive (Geyer's
    initial positive sequence); ``tau = 1`` for white noise, ``(1 + rho) / (1 -
    rho)`` for an AR(1) series. Never below 1.
    """
    centred = residuals - residuals.mean()
    size = centred.size
    variance = np.dot(centred, centred)
    if size < 3 or variance == 0:
        return 1.0
    spectrum = np.fft.rfft(centred, 2 * size)
    autocovariance = np.fft.irfft(spectrum * np.conj(spectrum))[:size]
    rho = autocovariance[1 : size // 2] / variance
    stop = np.flatnonzero(rho <= 0)
    positive = rho[: stop[0]] if stop.size else rho
    return float(max(1.0, 1.0 + 2.0 * positive.sum()))


class _Windows:
    """Least-squares lines of a branch on many force windows at once.

    The samples are sorted by force and the sums of a straight-line fit are
    read off cumulative sums, so each window costs O(1) after one sort.
    """

    def __init__(self, force: np.ndarray, strain: np.ndarray) -> None:
        order = np.argsort(force, kind="stable")
        self.force = force[order]
        self.scale = np.ptp(strain) or 1.0
        y = self.force - force.mean()
        x = (strain[order] - strain.mean()) / self.scale
        sums = np.vstack([np.ones_like(x), x, y, x * x, y * y, x * y])
        self.cumulative = np.concatenate([np.zeros((6, 1)), np.cumsum(sums, axis=1)], axis=1)

    def fit(
        self, lower: np.ndarray, upper: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Slope [N], its OLS variance [N^2] and the residual RMS [N] per window.

        Windows ``[lower, upper]`` [N] (arrays) with fewer than
        :data:`MIN_POINTS` samples or no spread of strain get NaN.
        """
        start = np.searchsorted(self.force, np.atleast_1d(lower), side="left")
        stop = np.searchsorted(self.force, np.atleast_1d(upper), side="right")
        n, sx, sy, sxx, syy, sxy = self.cumulative[:, stop] - self.cumulative[:, start]
        with np.errstate(divide="ignore", invalid="ignore"):
            cxx = sxx - sx * sx / n
            cxy = sxy - sx * sy / n
            residual = np.maximum(syy - sy * sy / n - cxy * cxy / cxx, 0.0) / (n - 2)
            slope = cxy / cxx / self.scale
            variance = residual / cxx / self.scale**2
        bad = (n < MIN_POINTS) | ~(cxx > 0)
        for values in (slope, variance, residual):
            values[bad] = np.nan
        return slope, variance, np.sqrt(residual)

    def inward(
        self, window: tuple[float, float], step: float, tau: float, min_width: float
    ) -> tuple[np.ndarray, np.ndarray, list[tuple[float, float]]]:
        """Slope changes [N] and their z-scores when either limit moves inward by `step`.

        The change between nested least-squares windows has the variance
        ``V(narrow) - V(wide)`` (times `tau` for correlated residuals); moves
        that would leave a window narrower than `min_width` [N] are skipped.
        """
        low, high = window
        if high - low - step < min_width - 1e-9 * step:
            return np.array([]), np.array([]), []
        moves = [(low + step, high), (low, high - step)]
        slope, variance, _ = self.fit(
            np.array([low, *(move[0] for move in moves)]),
            np.array([high, *(move[1] for move in moves)]),
        )
        change = slope[1:] - slope[0]
        spread = np.sqrt(tau * np.maximum(variance[1:] - variance[0], 0.0))
        with np.errstate(divide="ignore", invalid="ignore"):
            score = np.abs(change) / spread
        usable = np.isfinite(change)
        return change[usable], score[usable], [m for m, u in zip(moves, usable, strict=True) if u]


def _residual_tau(force: np.ndarray, strain: np.ndarray, window: tuple[float, float]) -> float:
    """Integrated autocorrelation of the straight-line residuals inside `window`."""
    inside = (force >= window[0]) & (force <= window[1])
    if inside.sum() < MIN_POINTS:
        return 1.0
    coefficients = np.polyfit(strain[inside] - strain[inside].mean(), force[inside], 1)
    residuals = force[inside] - np.polyval(coefficients, strain[inside] - strain[inside].mean())
    return integrated_autocorrelation(residuals)


def scan_windows(
    force: np.ndarray, strain: np.ndarray, *, min_span: float = MIN_SPAN
) -> tuple[float, float]:
    """Automatic fit window of a branch (ASTM E3076 in spirit, with a curvature guard).

    Parameters
    ----------
    force : numpy.ndarray
        Force on the branch [N] in time order, in the direction of the load.
    strain : numpy.ndarray
        Strain on the branch [1], same orientation.
    min_span : float
        Smallest window as a fraction of the branch's force range.

    Returns
    -------
    (float, float)
        Lower and upper force limits [N].

    Notes
    -----
    1. Every window on a grid of :data:`WINDOW_STEP` of the branch's force
       range, at least `min_span` wide, is fitted; the one with the least
       residual RMS over its force span (normalised residual) is kept.
    2. The normalised residual cannot see a curvature smaller than the noise,
       such as the end of a toe, however many samples there are. So each limit
       is then moved inward by one step while that changes the slope by more
       than :data:`GUARD_Z` standard deviations of the change between nested
       windows (which shrink as samples accumulate).

    Raises
    ------
    FitError
        When no candidate window holds enough samples.
    """
    low, span = force.min(), np.ptp(force)
    grid = np.round(np.arange(0.0, 1.0 + WINDOW_STEP / 2, WINDOW_STEP), 10)
    lower, upper = np.meshgrid(grid, grid, indexing="ij")
    keep = upper - lower >= min_span - 1e-9
    lower, upper = low + lower[keep] * span, low + upper[keep] * span
    windows = _Windows(force, strain)
    _, _, rms = windows.fit(lower, upper)
    normalised = np.where(np.isfinite(rms), rms / (upper - lower), np.inf)
    best = int(np.argmin(normalised))
    if not np.isfinite(normalised[best]):
        raise FitError(
            "no fit window of the branch holds enough samples",
            hint=f"log at a higher rate: a window needs at least {MIN_POINTS} samples",
        )
    window = (float(lower[best]), float(upper[best]))
    tau = _residual_tau(force, strain, window)
    while True:
        _, score, moves = windows.inward(window, WINDOW_STEP * span, tau, min_span * span)
        if not moves or np.max(score) <= GUARD_Z:
            return window
        window = moves[int(np.argmax(score))]


def window_sensitivity(force: np.ndarray, strain: np.ndarray, window: tuple[float, float]) -> float:
    """Standard uncertainty [N] of a slope from the choice of its window.

    Each limit of `window` is moved inward by one grid step
    (:data:`WINDOW_STEP` of the branch's force range); the largest change of
    the slope is taken as a possible bias of the chosen window. A toe partly
    inside the window shows here, while the fit's own standard error cannot
    see it; on a straight branch the change is noise, a fraction of the
    standard error.
    """
    windows = _Windows(force, strain)
    change, _, _ = windows.inward(window, WINDOW_STEP * np.ptp(force), 1.0, 0.0)
    return float(np.max(np.abs(change))) if change.size else 0.0


def yield_onset(force: np.ndarray, strain: np.ndarray) -> float:
    """Force [N] below which a loading branch is still on its linear region.

    The upper end of :func:`linear_region`.

    Examples
    --------
    Linear to 60 N, then a slope a third as steep:

    >>> force = np.linspace(0, 100, 1001)
    >>> strain = np.where(force < 60, force, 60 + 3 * (force - 60)) * 1e-5
    >>> round(yield_onset(force, strain), 1)
    52.5
    """
    return linear_region(force, strain)[1]


def _seated_band(slope: np.ndarray, near_start: np.ndarray) -> int:
    """The first band of the straight stretch after a steeper start, or 0 without one.

    The first band among `near_start` from which :data:`SEATED_BANDS` bands hold one slope
    (within :data:`YIELD_SLOPE_DROP` of the first), when a band before it is steeper than
    that by more than :data:`YIELD_SLOPE_DROP`: an extensometer's knife edges seating, at
    once or over several bands (a real pull's tangent slope fell by 3 to 4 % a band over its
    first tenth, then held). A start flatter than the stretch, a toe, is none.
    """
    for band in np.flatnonzero(near_start):
        plateau = slope[band : band + SEATED_BANDS]
        with np.errstate(invalid="ignore"):
            flat = plateau.size == SEATED_BANDS and bool(np.all(
                np.abs(plateau - plateau[0]) <= YIELD_SLOPE_DROP * plateau[0]))
        if flat:
            before = slope[:band][np.isfinite(slope[:band])]
            steeper = before.size > 0 and before.max() > (1.0 + YIELD_SLOPE_DROP) * plateau[0]
            return int(band) if steeper else 0
    return 0


def linear_region(force: np.ndarray, strain: np.ndarray) -> tuple[float, float]:
    """Forces [N] between which a loading branch is on its linear region.

    The tangent slope is measured by least squares on force bands of
    :data:`TANGENT_BAND` of the branch's range, every :data:`TANGENT_STEP`.
    Over a toe it rises, on the linear region it is at its largest, and past
    the onset of yield it falls. The onset is the lower edge of the first band
    above the steepest one whose slope is more than :data:`YIELD_SLOPE_DROP`
    below the steepest, and by more than three standard errors of the two.
    A start steeper than a straight stretch that follows it (:func:`_seated_band`:
    :data:`SEATED_BANDS` bands of one slope, starting within :data:`SEATING_SPAN` of
    the range), an extensometer's knife edges seating, is no linear region, as a toe
    flatter than what follows is none: the region starts at the stretch, and its
    steepest band is looked for from there.

    Parameters
    ----------
    force : numpy.ndarray
        Force on the branch [N], in the direction of the load.
    strain : numpy.ndarray
        Strain on the branch [1], same orientation.

    Returns
    -------
    (float, float)
        The lowest force of the region (the branch's lowest, or the straight stretch's
        start after a steeper start) and the onset of yield (``inf`` when the branch
        stays linear to its top) [N].
    """
    low, span = float(force.min()), float(np.ptp(force))
    if not span > 0:
        return low, np.inf
    lower = low + np.arange(0.0, 1.0 - TANGENT_BAND + 1e-9, TANGENT_STEP) * span
    slope, variance, _ = _Windows(force, strain).fit(lower, lower + TANGENT_BAND * span)
    if not np.any(np.isfinite(slope)):
        return low, np.inf
    seated = _seated_band(slope, lower - low <= SEATING_SPAN * span)
    steepest = seated + int(np.nanargmax(slope[seated:]))
    with np.errstate(invalid="ignore"):
        fallen = ((slope < (1.0 - YIELD_SLOPE_DROP) * slope[steepest])
                  & (slope[steepest] - slope > 3.0 * np.sqrt(variance + variance[steepest])))
    fallen[: steepest + 1] = False
    found = np.flatnonzero(fallen)
    return float(lower[seated]), float(lower[found[0]]) if found.size else np.inf


def _below_yield(force: np.ndarray, strain: np.ndarray) -> np.ndarray:
    """The samples of a loading branch on its linear region (:func:`linear_region`).

    Raises
    ------
    FitError
        When fewer than :data:`MIN_POINTS` are: the branch bends almost from its start.
    """
    start, onset = linear_region(force, strain)
    linear = (force >= start) & (force <= onset)
    if np.count_nonzero(linear) < MIN_POINTS:
        raise FitError(
            f"the loading bends from {onset / 1e3:.4g} kN on, next to its start at "
            f"{start / 1e3:.4g} kN (its tangent slope falls {100 * YIELD_SLOPE_DROP:g} % "
            f"below the steepest): below that, {np.count_nonzero(linear)} samples, and a fit "
            f"needs {MIN_POINTS}",
            hint="a specimen curved from the start has no linear region to fit: give the "
                 "window in the run sheet, fit_window = {force_low_kN = ..., "
                 "force_high_kN = ...}, or log at a higher rate")
    return linear


def fit_line(
    force: np.ndarray,
    strain: np.ndarray,
    window: tuple[float, float],
    *,
    confidence: float = CONFIDENCE,
) -> LinearFit:
    """Fit ``force = E0 * strain + intercept`` with lmfit on the samples inside `window`.

    Parameters
    ----------
    force : numpy.ndarray
        Force [N] in time order, in the direction of the load.
    strain : numpy.ndarray
        Strain [1], same orientation.
    window : (float, float)
        Force limits [N].
    confidence : float
        Level of the interval.

    Returns
    -------
    LinearFit
        Slope, its standard errors and interval, and the fit's quality figures.

    Raises
    ------
    FitError
        When the window holds fewer than :data:`MIN_POINTS` samples or no
        spread of strain.
    """
    inside = (force >= window[0]) & (force <= window[1])
    y, x = force[inside], strain[inside]
    if y.size < MIN_POINTS or not np.ptp(x) > 0:
        raise FitError(
            f"the fit window {window[0]:.6g} N to {window[1]:.6g} N holds {y.size} samples "
            "or no change of elongation",
            hint=f"widen the window or log faster (at least {MIN_POINTS} samples)",
        )
    model = LinearModel()
    result = model.fit(y, model.guess(y, x=x), x=x)
    slope = result.params["slope"]
    residuals = y - result.best_fit
    tau = integrated_autocorrelation(residuals)
    ols = float(slope.stderr) if slope.stderr is not None else np.nan
    statistical = ols * np.sqrt(tau)
    from_window = window_sensitivity(force, strain, window)
    stderr = float(np.hypot(statistical, from_window))
    n_eff = y.size / tau
    dof = max(n_eff - 2, 1.0) * (stderr / statistical) ** 4 if statistical > 0 else np.inf
    quantile = stats.t.ppf(0.5 + confidence / 2, dof)
    total = np.sum((y - y.mean()) ** 2)
    return LinearFit(
        E0=float(slope.value),
        E0_stderr=stderr,
        E0_stderr_stat=statistical,
        E0_stderr_window=from_window,
        E0_stderr_ols=ols,
        E0_ci_low=float(slope.value - quantile * stderr),
        E0_ci_high=float(slope.value + quantile * stderr),
        intercept=float(result.params["intercept"].value),
        window_low=float(window[0]),
        window_high=float(window[1]),
        n_points=int(y.size),
        n_eff=float(n_eff),
        dof=float(dof),
        r2=float(1.0 - np.sum(residuals**2) / total),
        residual_rms=float(np.sqrt(np.mean(residuals**2))),
    )


def fit_stiffness(
    run: TensileRun,
    *,
    force_window: tuple[float, float] | None = None,
    fraction_window: tuple[float, float] | None = None,
    min_span: float = MIN_SPAN,
    branches: Sequence[str] = FITTED_BRANCHES,
    confidence: float = CONFIDENCE,
) -> pd.DataFrame:
    """Stiffness fits of every cycle and branch of a conditioned tensile run.

    Parameters
    ----------
    run : TensileRun
        The conditioned run.
    force_window : (float, float), optional
        Fixed window [N], magnitudes in the direction of the load.
    fraction_window : (float, float), optional
        Fixed window as fractions of each branch's force range (0 at its lowest
        force, 1 at its highest). Without either window, each branch's window
        is chosen by :func:`scan_windows`, on a loading branch below the onset
        of yield (:func:`yield_onset`).
    min_span : float
        Smallest automatic window as a fraction of the branch's range.
    branches : sequence of str
        Branches to fit.
    confidence : float
        Level of the per-fit intervals.

    Returns
    -------
    pandas.DataFrame
        One row per ``(cycle, branch)``, the columns of :class:`LinearFit`
        (see the module docstring).

    Raises
    ------
    FitError
        When a window holds too few samples (the message names the cycle
        and branch), or both windows are given.
    """
    if force_window is not None and fraction_window is not None:
        raise FitError("give either a force window or a fraction window, not both")
    samples = run.samples
    force = run.sign * samples["force"].to_numpy()
    strain = run.sign * samples["strain"].to_numpy()
    cycle = samples["cycle"].to_numpy()
    branch = samples["branch"].to_numpy()
    rows, keys, fullest = [], [], 0
    usable = np.isfinite(strain)  # a channel taken off, or the samples after a fracture
    for number in range(1, run.segmentation.n_cycles + 1):
        for name in branches:
            chosen = (cycle == number) & (branch == name) & usable
            count = int(chosen.sum())
            fullest = max(fullest, count)
            if count < MIN_POINTS:
                continue
            f, e = force[chosen], strain[chosen]
            try:
                if force_window is not None:
                    window = force_window
                elif fraction_window is not None:
                    low, span = f.min(), np.ptp(f)
                    window = (low + fraction_window[0] * span, low + fraction_window[1] * span)
                else:
                    linear = _below_yield(f, e) if name == "loading" else slice(None)
                    window = scan_windows(f[linear], e[linear], min_span=min_span)
                rows.append(asdict(fit_line(f, e, window, confidence=confidence)))
            except FitError as error:
                raise FitError(
                    f"cycle {number}, {name} branch: {error.message}", hint=error.hint
                ) from error
            keys.append((number, name))
    if not rows:
        raise FitError(
            f"no branch of the run holds enough samples to fit: the fullest holds {fullest} "
            f"with a strain, a fit needs {MIN_POINTS}",
            hint=f"each loading and unloading needs {MIN_POINTS} samples between its turning "
            "points: a machine that logs a few samples per cycle (a fatigue test's logged "
            "cycles) must log more of them; check too that the gauge channel reads through "
            "the cycles")
    index = pd.MultiIndex.from_tuples(keys, names=["cycle", "branch"])
    return pd.DataFrame(rows, index=index)


def fit_settings(
    *,
    force_window: tuple[float, float] | None = None,
    fraction_window: tuple[float, float] | None = None,
    min_span: float = MIN_SPAN,
    confidence: float = CONFIDENCE,
) -> dict[str, float | str]:
    """What :func:`fit_stiffness` applies with these arguments, as dataset attributes.

    Parameters
    ----------
    force_window : (float, float), optional
        Fixed window [N], as given to :func:`fit_stiffness`.
    fraction_window : (float, float), optional
        Fixed window as fractions [1] of each branch's force range.
    min_span : float
        Smallest automatic window [1], a fraction of the branch's range.
    confidence : float
        Level of the intervals [1].

    Returns
    -------
    dict
        ``confidence_level`` [1] and ``fit_window``: the window rule, in words.

    Examples
    --------
    >>> fit_settings(force_window=(10e3, 50e3))["fit_window"]
    'fixed force window 10 to 50 kN for every branch'
    """
    if force_window is not None:
        rule = (f"fixed force window {force_window[0] / 1e3:g} to {force_window[1] / 1e3:g} kN "
                "for every branch")
    elif fraction_window is not None:
        rule = (f"fixed window {100 * fraction_window[0]:g} to {100 * fraction_window[1]:g} % "
                "of each branch's force range")
    else:
        rule = (f"automatic per branch: the least normalised residual over windows on a grid of "
                f"{100 * WINDOW_STEP:g} % of the branch's force range, spanning at least "
                f"{100 * min_span:g} % of it (as ASTM E3076), each limit moved inward while the "
                f"slope changes by more than {GUARD_Z:g} standard deviations (curvature guard); "
                f"a loading below the onset of yield (tangent slope "
                f"{100 * YIELD_SLOPE_DROP:g} % below its linear-region value)")
    return {"confidence_level": confidence, "fit_window": rule}


@dataclass(frozen=True)
class SpecimenStiffness:
    """Stiffness of one specimen (one tensile run), SI units.

    ``E0`` is the mean loading stiffness of cycles ``2..n``; ``E0_first`` the
    loading stiffness of the seating cycle 1; ``E0_unloading`` the mean
    unloading stiffness of cycles ``2..n`` (secant slope on its window: the
    unloading branch of a chain is curved by hysteresis).
    """

    E0: float  #: [N]
    E0_stderr: float  #: [N]
    E0_ci_low: float  #: [N]
    E0_ci_high: float  #: [N]
    dof: float  #: degrees of freedom of the interval
    birge_ratio: float  #: scatter of the cycles over their errors (NaN for one cycle)
    n_cycles: int  #: loading branches counted
    E0_first: float  #: [N]
    E0_first_stderr: float  #: [N]
    E0_unloading: float  #: [N]

    def as_dict(self) -> dict[str, float]:
        """The fields as a plain dict."""
        return asdict(self)


def _value(fits: pd.DataFrame, key: tuple[int, str], column: str) -> float:
    return float(fits.loc[key, column]) if key in fits.index else float("nan")


def _single_pull(fits: pd.DataFrame) -> SpecimenStiffness:
    """A single pull's stiffness: the fit of its one loading, with the fit's interval."""
    if (1, "loading") not in fits.index:
        raise FitError(
            "a single pull gives E0 from its loading, and the run has no loading to fit",
            hint="check that the log holds the loading, and the gauge channels",
        )
    fit = fits.loc[(1, "loading")]
    if not fit["E0"] > 0:
        raise FitError(
            f"the loading gives a stiffness of {fit['E0']:.4g} N, not above 0",
            hint="the elongation does not grow with the force: check the gauge columns")
    return SpecimenStiffness(
        E0=float(fit["E0"]), E0_stderr=float(fit["E0_stderr"]),
        E0_ci_low=float(fit["E0_ci_low"]), E0_ci_high=float(fit["E0_ci_high"]),
        dof=float(fit["dof"]), birge_ratio=np.nan, n_cycles=1, E0_first=float(fit["E0"]),
        E0_first_stderr=float(fit["E0_stderr"]),
        E0_unloading=_value(fits, (1, "unloading"), "E0"),
    )


def specimen_stiffness(
    fits: pd.DataFrame, *, single_pull: bool = False, confidence: float = CONFIDENCE
) -> SpecimenStiffness:
    """Experimental E0 of a specimen from the fits of its run.

    Parameters
    ----------
    fits : pandas.DataFrame
        Result of :func:`fit_stiffness`.
    single_pull : bool
        The run is a single pull (one loading): its E0 is the fit of that
        loading, below the onset of yield, with the fit's own interval.
    confidence : float
        Level of the interval (of cycles ``2..n``; a single pull keeps its fit's).

    Returns
    -------
    SpecimenStiffness
        Mean loading stiffness of cycles ``2..n`` with its standard error and
        interval (see the module docstring), cycle 1 and unloading beside.

    Raises
    ------
    FitError
        When the run has no loading branch after the first cycle, or their mean
        slope is not positive (noise only, or a gauge reading against the load).
    """
    if single_pull:
        return _single_pull(fits)
    cycles = fits.index.get_level_values("cycle")
    branch = fits.index.get_level_values("branch")
    counted = fits[(cycles >= 2) & (branch == "loading")]
    m = len(counted)
    if m == 0:
        raise FitError(
            "E0 counts the loading branches of cycles 2..n, and the run has none",
            hint="a cyclic test needs at least two load cycles (Paper 001: three); for a "
            "single pull set cycles = 1 in the run sheet",
        )
    slopes = counted["E0"].to_numpy()
    errors = counted["E0_stderr_stat"].to_numpy()
    dofs = np.maximum(counted["n_eff"].to_numpy() - 2, 1.0)
    mean = float(slopes.mean())
    if not mean > 0:
        raise FitError(
            f"the loading branches of cycles 2..n give a stiffness of {mean:.4g} N, not above 0",
            hint="the elongation does not grow with the force: check the sign and wiring of "
            "the gauges, and the noise of the record",
        )
    with np.errstate(divide="ignore", invalid="ignore"):  # noise-free data: errors of 0
        chi2 = np.sum(((slopes - mean) / errors) ** 2)
        birge = float(np.sqrt(chi2 / (m - 1))) if m > 1 else np.nan
        scale = max(1.0, birge) if np.isfinite(birge) else 1.0
        statistical = scale * float(np.sqrt(np.sum(errors**2)) / m)
        stderr = float(np.hypot(statistical, counted["E0_stderr_window"].mean()))
        dof = float(np.divide(stderr**4, np.sum((scale * errors / m) ** 4 / dofs)))
    dof = dof if np.isfinite(dof) else np.inf
    half = float(stats.t.ppf(0.5 + confidence / 2, dof) * stderr)
    unloading = fits[(cycles >= 2) & (branch == "unloading")]["E0"]
    return SpecimenStiffness(
        E0=mean,
        E0_stderr=stderr,
        E0_ci_low=mean - half,
        E0_ci_high=mean + half,
        dof=dof,
        birge_ratio=birge,
        n_cycles=m,
        E0_first=_value(fits, (1, "loading"), "E0"),
        E0_first_stderr=_value(fits, (1, "loading"), "E0_stderr"),
        E0_unloading=float(unloading.mean()) if len(unloading) else float("nan"),
    )


@dataclass(frozen=True)
class ChainStiffness:
    """Stiffness of a chain from its specimens, SI units."""

    E0: float  #: mean over the specimens [N]
    E0_stderr: float  #: standard error of the mean [N]
    E0_ci_low: float  #: [N]
    E0_ci_high: float  #: [N]
    dof: float  #: degrees of freedom of the interval
    n_specimens: int

    def as_dict(self) -> dict[str, float]:
        """The fields as a plain dict."""
        return asdict(self)


def combine_specimens(
    specimens: Sequence[SpecimenStiffness], *, confidence: float = CONFIDENCE
) -> ChainStiffness:
    """Chain E0: mean over its specimens with a Student-t interval from their spread.

    Parameters
    ----------
    specimens : sequence of SpecimenStiffness
        One per specimen (Paper 001: four per chain).
    confidence : float
        Level of the interval.

    Returns
    -------
    ChainStiffness
        With a single specimen, its own standard error and degrees of freedom
        are used (there is no spread to learn from).

    Raises
    ------
    FitError
        When `specimens` is empty.
    """
    if not specimens:
        raise FitError("a chain needs at least one specimen to give an E0")
    values = np.array([specimen.E0 for specimen in specimens])
    n = values.size
    if n == 1:
        stderr, dof = specimens[0].E0_stderr, specimens[0].dof
    else:
        stderr, dof = float(values.std(ddof=1) / np.sqrt(n)), float(n - 1)
    half = float(stats.t.ppf(0.5 + confidence / 2, dof) * stderr)
    mean = float(values.mean())
    return ChainStiffness(
        E0=mean,
        E0_stderr=float(stderr),
        E0_ci_low=mean - half,
        E0_ci_high=mean + half,
        dof=float(dof),
        n_specimens=n,
    )
