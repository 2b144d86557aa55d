"""The linear model of an engagement event's window, fitted to many events at once (fit stage).

The model and its vectorised least squares of :mod:`pipeline.fit.impact` (see
its notes, "The model of one event"): once the branch's ringing (omega_n, zeta)
and the strikes' onsets are known, the window model is linear, and all windows
share a basis whose event-specific part is a mask start and a complex scale.
:class:`WindowModel` gathers the windows once and assembles every event's
normal equations from one matrix product, suffix sums of the basis and a few
samples around the masks; :func:`settle_onsets` refines the onsets from the
phases of free-phase fits; :func:`fit_amplitudes` fits the strikes with their
phases fixed by the onsets; :class:`FreePhaseResiduals` gives the residuals the
fit of the ringing minimises.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

from pipeline.condition.engagement import EngagementEvents

#: Window start before impact 1, as a fraction of tau.
WINDOW_PRE = 0.4
#: Gap left between the window's end and the next seating, as a fraction of tau.
WINDOW_GUARD = 0.15
#: Largest accepted move of an onset from its detected time [ringing periods].
MAX_ONSET_SHIFT = 0.25
#: Events per block of the vectorised fit (bounds the memory to ~blocks x window).
_CHUNK = 2048


@dataclass(frozen=True)
class Ringing:
    """Natural frequency and damping of the branch, fitted per run.

    Attributes
    ----------
    omega_n : float
        Undamped natural angular frequency [rad/s].
    zeta : float
        Damping ratio [-].
    omega_n_stderr, zeta_stderr : float
        Standard errors from lmfit (NaN when given rather than fitted).
    correlation : float
        Correlation of the omega_n and zeta estimates (0 when given).
    n_events : int
        Events the fit used (0 when given).
    """

    omega_n: float
    zeta: float
    omega_n_stderr: float = math.nan
    zeta_stderr: float = math.nan
    correlation: float = 0.0
    n_events: int = 0

    @property
    def omega_d(self) -> float:
        """Damped natural angular frequency omega_n sqrt(1 - zeta^2) [rad/s]."""
        return self.omega_n * math.sqrt(1.0 - self.zeta**2)

    @property
    def pole(self) -> complex:
        """lambda = -zeta omega_n + i omega_d [1/s]."""
        return complex(-self.zeta * self.omega_n, self.omega_d)

    @property
    def peak_factor(self) -> float:
        """First-peak height of ``exp(-zeta omega_n s) sin(omega_d s)`` [-]."""
        root = math.sqrt(1.0 - self.zeta**2)
        return root * math.exp(-self.zeta * math.acos(self.zeta) / root)

    @property
    def fitted(self) -> bool:
        """Whether the values carry standard errors (fitted, not given)."""
        return math.isfinite(self.omega_n_stderr) and math.isfinite(self.zeta_stderr)


@dataclass(frozen=True)
class WindowGeometry:
    """Sampling of a log and the shared window of its events."""

    start: float  # time of sample 0 [s]
    rate: float  # [Hz]
    period: float  # seating period [s]
    pre: int  # window samples before the first sample after impact 1
    width: int  # window samples
    origin: int = 0  # sample of the log at index 0 of the array the windows are cut from

    @classmethod
    def of(cls, events: EngagementEvents) -> WindowGeometry:
        """The window of `events`' seatings (:data:`WINDOW_PRE`, :data:`WINDOW_GUARD`)."""
        tau, rate = events.tau, events.sample_rate
        pre = max(2, int(round(WINDOW_PRE * tau * rate)))
        width = pre + int(round((2 - WINDOW_GUARD) * tau * rate))
        return cls(events.start_time, rate, events.seating_period, pre, width)

    def first_sample(self, time: np.ndarray) -> np.ndarray:
        """Index (in the array from :attr:`origin` on) of the first sample at or after `time`."""
        return np.ceil((time - self.start) * self.rate - 1e-9).astype(np.int64) - self.origin

    def time_of(self, index: np.ndarray) -> np.ndarray:
        """Time [s] of the samples at `index` of the array from :attr:`origin` on."""
        return self.start + (index + self.origin) / self.rate

    def basis(self, pole: complex) -> np.ndarray:
        """Columns of the window model before the masks (width x 10).

        ``1, r/W, cos, sin`` (slow tension, W the window length), ``Re, Im
        exp(lambda r)`` (earlier strikes), and the same pair twice more (impact 1
        and impact 2, each masked per event from its onset on); ``r`` is the time
        from sample :attr:`pre` of the window.
        """
        r = (np.arange(self.width) - self.pre) / self.rate
        ring = np.exp(pole * r)
        phase = 2 * np.pi * r / self.period
        return np.column_stack([
            np.ones_like(r), r * self.rate / self.width, np.cos(phase), np.sin(phase),
            ring.real, ring.imag, ring.real, ring.imag, ring.real, ring.imag,
        ])


class WindowModel:
    """The events' windows, gathered once, and their products with the model's basis.

    Window ``e`` holds samples ``start[e] ... start[e] + width - 1``. The strike
    columns of event ``e`` are masked from window sample ``j1[e]`` (impact 1) and
    ``j2[e]`` (impact 2) on, with ``j1`` in `range1` and ``j2`` in `range2`
    (half-open). The Gram matrix of any masks is assembled from suffix sums of
    the shared basis; ``X^T y`` from one matrix product with the masks at the
    ends of their ranges plus the samples inside the ranges, which are kept
    (``slabs``): refitting with other masks touches no window again.
    """

    def __init__(self, y: np.ndarray, start: np.ndarray, range1: tuple[int, int],
                 range2: tuple[int, int], geo: WindowGeometry, pole: complex) -> None:
        basis = geo.basis(pole)
        self.basis, self.range1, self.range2 = basis, range1, range2
        self.total = basis.T @ basis
        # suffix[j] = sum over j' >= j of B_j' B_j'^T, the strike columns (6-9) only
        outer = (basis[:, :, None] * basis[:, None, 6:10]).reshape(geo.width, 40)
        suffix = np.empty((geo.width + 1, 40))
        suffix[0] = self.total[:, 6:10].ravel()
        np.subtract(suffix[0], np.cumsum(outer, axis=0), out=suffix[1:])
        self.suffix = suffix.reshape(geo.width + 1, 10, 4)
        shared = basis.copy()
        shared[: range1[1], 6:8] = 0.0
        shared[: range2[1], 8:10] = 0.0
        size = start.size
        self.xty = np.empty((size, 10))
        self.yty = np.empty(size)
        self.slab1 = np.empty((size, range1[1] - range1[0]))
        self.slab2 = np.empty((size, range2[1] - range2[0]))
        windows = sliding_window_view(y, geo.width)
        buffer = np.empty((min(_CHUNK, size), geo.width))
        for lo in range(0, size, _CHUNK):
            part = slice(lo, lo + _CHUNK)
            block = buffer[: len(start[part])]
            block[...] = windows[start[part]]
            self.xty[part] = block @ shared
            self.yty[part] = np.einsum("ij,ij->i", block, block)
            self.slab1[part] = block[:, range1[0]: range1[1]]
            self.slab2[part] = block[:, range2[0]: range2[1]]

    def equations(self, j1: np.ndarray, j2: np.ndarray, rows: np.ndarray
                  ) -> tuple[np.ndarray, np.ndarray]:
        """Gram matrices (n, 10, 10) and X^T y (n, 10) of windows `rows` with masks j1, j2."""
        s1, s2 = self.suffix[j1, :, :2], self.suffix[j2, :, 2:]
        gram = np.repeat(self.total[None], rows.size, axis=0)
        gram[:, :, 6:8] = s1
        gram[:, 6:8, :] = np.swapaxes(s1, 1, 2)
        gram[:, :, 8:10] = s2  # j2 > j1: impact 2's block lies inside impact 1's
        gram[:, 8:10, :] = np.swapaxes(s2, 1, 2)
        xty = self.xty[rows].copy()
        for columns, slab, (lo, hi), mask in ((slice(6, 8), self.slab1, self.range1, j1),
                                              (slice(8, 10), self.slab2, self.range2, j2)):
            if hi > lo:
                inside = np.arange(lo, hi)[None, :] >= mask[:, None]
                xty[:, columns] += (slab[rows] * inside) @ self.basis[lo:hi, columns]
        return gram, xty


def onsets_from_phases(coef: np.ndarray, ref: np.ndarray, prior1: np.ndarray, prior2: np.ndarray,
            ringing: Ringing) -> tuple[np.ndarray, np.ndarray]:
    """Onsets [s] from the phases of the free-phase strike amplitudes, nearest the priors.

    A strike ``A Im(exp(lambda (t - T)))`` fitted as ``g Re + d Im`` of
    ``exp(lambda (t - ref))`` has ``d + i g = A exp(lambda (ref - T))``, so
    ``T = ref - (arg(d + i g) + 2 pi m) / omega_d``.
    """
    omega_d = ringing.omega_d
    onsets = []
    for column, prior in ((6, prior1), (8, prior2)):
        phase = np.angle(coef[:, column + 1] + 1j * coef[:, column])
        turns = np.round(((ref - prior) * omega_d - phase) / (2 * np.pi))
        onsets.append(ref - (phase + 2 * np.pi * turns) / omega_d)
    return onsets[0], onsets[1]


def solve_normal_equations(gram: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Batched solution of normal equations, `rhs` (n, p) or (n, p, m); NaN where singular."""
    vector = rhs.ndim == 2
    rhs = rhs[..., None] if vector else rhs
    try:
        out = np.linalg.solve(gram, rhs)
    except np.linalg.LinAlgError:
        out = np.full(rhs.shape, np.nan)
        for i in range(rhs.shape[0]):
            try:
                out[i] = np.linalg.solve(gram[i], rhs[i])
            except np.linalg.LinAlgError:
                continue
    return out[..., 0] if vector else out


@dataclass
class SettledFits:
    """Free-phase normal equations of a set of events, with masks matching their onsets."""

    onset1: np.ndarray  # refined onsets [s]
    onset2: np.ndarray
    moved: np.ndarray  # an onset left the reach of its window (kept at its input)
    gram: np.ndarray  # (n, 10, 10)
    xty: np.ndarray  # (n, 10)
    yty: np.ndarray  # (n,)
    ref: np.ndarray  # time of sample `pre` of each window [s]


def settle_onsets(y: np.ndarray, onset1: np.ndarray, onset2: np.ndarray, margin: float,
            geo: WindowGeometry, ringing: Ringing, passes: int = 4) -> SettledFits:
    """Refine the onsets until every mask starts at the first sample after its onset.

    The windows are placed once, ``geo.pre`` samples before the first sample
    after ``onset1 + margin`` (`margin` [s] puts the first masks after the true
    onsets); each pass takes the onsets from the phases of the free-phase fit
    (:func:`onsets_from_phases`) and refits the events whose masks moved. An onset that
    moves more than :data:`MAX_ONSET_SHIFT` ringing periods keeps its input and
    is marked `moved`.
    """
    size = onset1.size
    start = geo.first_sample(onset1 + margin) - geo.pre
    reach = int(math.ceil(MAX_ONSET_SHIFT * 2 * np.pi / ringing.omega_d * geo.rate)) + 1
    j2 = geo.first_sample(onset2 + margin) - start
    range1 = (max(1, geo.pre - reach), geo.pre + reach + 1)
    range2 = (max(range1[0] + 1, int(j2.min()) - reach), min(geo.width, int(j2.max()) + reach + 1))
    windows = WindowModel(y, start, range1, range2, geo, ringing.pole)
    ref = geo.time_of(start + geo.pre)
    fits = SettledFits(onset1.copy(), onset2.copy(), np.zeros(size, dtype=bool),
                 np.empty((size, 10, 10)), np.empty((size, 10)), windows.yty, ref)
    j1 = np.full(size, geo.pre)
    todo = np.arange(size)
    for _ in range(passes):
        gram, xty = windows.equations(j1[todo], j2[todo], todo)
        t1, t2 = onsets_from_phases(solve_normal_equations(gram, xty), ref[todo],
                                    fits.onset1[todo], fits.onset2[todo], ringing)
        finite = np.isfinite(t1) & np.isfinite(t2)  # not so where a window is singular
        new1 = geo.first_sample(np.where(finite, t1, fits.onset1[todo])) - start[todo]
        new2 = geo.first_sample(np.where(finite, t2, fits.onset2[todo])) - start[todo]
        moved = ((new1 < range1[0]) | (new1 >= range1[1]) | (new2 < range2[0])
                 | (new2 >= range2[1]) | ~finite)
        fits.onset1[todo] = np.where(moved, onset1[todo], t1)
        fits.onset2[todo] = np.where(moved, onset2[todo], t2)
        fits.moved[todo] = moved
        fits.gram[todo], fits.xty[todo] = gram, xty
        new1, new2 = np.where(moved, j1[todo], new1), np.where(moved, j2[todo], new2)
        changed = (new1 != j1[todo]) | (new2 != j2[todo])
        j1[todo], j2[todo] = new1, new2
        todo = todo[changed]
        if todo.size == 0:
            break
    return fits


def fit_amplitudes(fits: SettledFits, ringing: Ringing, width: int
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fit with the strikes' phases fixed by their onsets: coefficients, variances, RSS.

    The free-phase columns of each strike (6-7 and 8-9) become one column
    ``Im(exp(lambda (t - T)))``: an 8-parameter model whose normal equations are
    ``L^T G L`` and ``L^T X^T y`` with ``L`` the 10 x 8 lifting of each event.
    Returns the coefficients (n, 8; 6 and 7 are A1 and A2), the variances of
    A1, A2 (n, 2) and the residual sums of squares (n,).
    """
    size = fits.onset1.size
    lifting = np.zeros((size, 10, 8))
    lifting[:, np.arange(6), np.arange(6)] = 1.0
    for column, onset, target in ((6, fits.onset1, 6), (8, fits.onset2, 7)):
        scale = np.exp(ringing.pole * (fits.ref - onset))
        lifting[:, column, target] = scale.imag
        lifting[:, column + 1, target] = scale.real
    transposed = np.swapaxes(lifting, 1, 2)
    gram = transposed @ fits.gram @ lifting
    rhs = (transposed @ fits.xty[:, :, None])[:, :, 0]
    # One factorisation gives the coefficients and the diagonal of the inverse.
    system = np.zeros((size, 8, 3))
    system[:, :, 0] = rhs
    system[:, 6, 1] = system[:, 7, 2] = 1.0
    solution = solve_normal_equations(gram, system)
    coef = solution[:, :, 0]
    rss = np.maximum(fits.yty - np.sum(coef * rhs, axis=1), 0.0)
    variance = np.stack([solution[:, 6, 1], solution[:, 7, 2]], axis=1)
    return coef, variance * (rss / (width - 8))[:, None], rss


class FreePhaseResiduals:
    """Residuals of the free-phase model on a few events, for the fit of the ringing.

    The windows are gathered once; each call refits them for a trial ringing.
    Impact 1's columns are masked before sample :attr:`WindowGeometry.pre` of
    every window, impact 2's before each event's first sample after its onset,
    so that the events share all of their normal equations but the block of
    impact 2, which is assembled per distinct mask start.

    Parameters
    ----------
    y : numpy.ndarray
        The force [N] the windows are cut from.
    onset1, onset2 : numpy.ndarray
        The events' onsets of impact 1 and impact 2 [s].
    geo : WindowGeometry
        The windows' geometry.
    """

    def __init__(self, y: np.ndarray, onset1: np.ndarray, onset2: np.ndarray,
                 geo: WindowGeometry) -> None:
        start = geo.first_sample(onset1) - geo.pre
        self.geo = geo
        self.windows = sliding_window_view(y, geo.width)[start]
        j2 = geo.first_sample(onset2) - start
        self.after2 = np.arange(geo.width)[None, :] >= j2[:, None]
        self.masked2 = np.where(self.after2, self.windows, 0.0)
        self.starts2, self.group2 = np.unique(j2, return_inverse=True)

    def __call__(self, ringing: Ringing) -> np.ndarray:
        """The residuals [N] of every window, one after the other, for `ringing`."""
        basis = self.geo.basis(ringing.pole)
        basis[: self.geo.pre, 6:8] = 0.0
        impact2 = np.stack([basis[start:].T @ basis[start:, 8:10] for start in self.starts2])
        gram = np.repeat((basis.T @ basis)[None], self.windows.shape[0], axis=0)
        gram[:, :, 8:10] = impact2[self.group2]
        gram[:, 8:10, :] = np.swapaxes(gram[:, :, 8:10], 1, 2)
        xty = np.concatenate([self.windows @ basis[:, :8], self.masked2 @ basis[:, 8:10]],
                             axis=1)
        coef = solve_normal_equations(gram, xty)
        residuals = coef[:, 8:10] @ basis[:, 8:10].T
        residuals *= self.after2
        residuals += coef[:, :8] @ basis[:, :8].T
        np.subtract(self.windows, residuals, out=residuals)
        return residuals.ravel()
