"""Cycles and branches of a cyclic load record, from the force alone.

The force is first oriented by the sign of its dominant load (compression-
negative records are flipped), lightly smoothed, and passed through a Schmitt
trigger at 30 % and 70 % of its range: each excursion above the upper level
after one below the lower level is a cycle, so noise and dwells at the peaks or
valleys cannot create or merge cycles. Inside each excursion the turning points
are where the smoothed force comes within a tolerance of its extreme (a few
times the noise, at least 0.2 % of the range): a dwell at a peak becomes a
``hold`` between the loading and the unloading branch.

Branch labels (:data:`BRANCHES`)
--------------------------------
``preload``
    samples before the first loading branch (cycle 0).
``loading`` / ``unloading``
    from the last valley sample to the first peak sample, and from the last
    peak sample to the first sample of the next valley.
``hold``
    dwell at a peak, and the valley after a cycle's unloading (up to the next
    loading branch, or the end of the record), labelled with that cycle.
``beyond_peak`` / ``after_fracture``
    given by :func:`pipeline.condition.tensile.condition_tensile`: the fall of
    force after the peak of a single pull that is no unloading (necking), and
    everything after a fracture (not analysed).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.ndimage import uniform_filter1d

from pipeline.errors import SignalError

#: Branch labels of the samples, in the order a cycle passes through them.
BRANCHES = ("preload", "loading", "hold", "unloading", "beyond_peak", "after_fracture")

#: Schmitt-trigger levels as fractions of the force range (lower, upper).
TRIGGER_LEVELS = (0.3, 0.7)

#: Loadings before the first one to the upper trigger level count as cycles when they rise by
#: this fraction of the whole force range (a preload is some 2 to 5 % of it; a chain's proof
#: load, some 60 % of its breaking force; a stiffness test's cycles, 10 to 30 %).
EARLIER_SHARE = 0.1

#: Width of the moving average used to locate the turning points [samples].
SMOOTHING = 5


@dataclass(frozen=True)
class Segmentation:
    """Cycles and branches of a force record.

    Attributes
    ----------
    sign : int
        +1 when the dominant load is positive (tension), -1 when negative
        (compression-negative records); ``sign * force`` rises on loading.
    cycle : numpy.ndarray
        Cycle number of each sample (int, 1-based; 0 before the first loading).
    branch : numpy.ndarray
        Branch label of each sample, one of :data:`BRANCHES`.
    turns : numpy.ndarray
        Per cycle, the sample indices ``(load_start, load_end, unload_start,
        unload_end)`` (int, shape ``(n_cycles, 4)``, inclusive).
    valleys : list of (int, int) or None
        Index ranges (inclusive) of the samples resting at the lower force:
        before cycle 1, then after each cycle; None after a cycle whose
        unloading the record does not complete.
    noise : float
        Estimated standard deviation of the force noise [N].
    tolerance : float
        Force band [N] within which a sample counts as at a peak or valley.
    """

    sign: int
    cycle: np.ndarray
    branch: np.ndarray
    turns: np.ndarray
    valleys: list[tuple[int, int] | None]
    noise: float
    tolerance: float

    @property
    def n_cycles(self) -> int:
        """Number of cycles found."""
        return len(self.turns)

    @property
    def complete(self) -> np.ndarray:
        """Whether each cycle's unloading returns to the lower force (bool per cycle)."""
        return np.array([valley is not None for valley in self.valleys[1:]], dtype=bool)


def load_sign(force: np.ndarray) -> int:
    """Sign of the dominant load: +1 if the largest force magnitude is positive, else -1."""
    finite = force[np.isfinite(force)]
    if finite.size == 0:
        return 1
    return 1 if finite.max() + finite.min() >= 0 else -1


def noise_level(signal: np.ndarray) -> float:
    """Robust standard deviation of white noise on a piecewise-smooth `signal`.

    From the median absolute deviation of second differences, which cancel
    ramps: ``sigma = 1.4826 MAD(d2) / sqrt(6)``.
    """
    if signal.size < 3:
        return 0.0
    second = signal[2:] - 2 * signal[1:-1] + signal[:-2]
    return float(1.4826 * np.median(np.abs(second - np.median(second))) / np.sqrt(6.0))


def _schmitt(smooth: np.ndarray) -> tuple[np.ndarray, np.ndarray, float, float]:
    """Rising and falling edges of the two-level trigger, and the force floor and range."""
    low, high = np.percentile(smooth, [1.0, 99.0])
    span = high - low
    if not span > 0:
        return np.array([], dtype=int), np.array([], dtype=int), float(low), 0.0
    lower, upper = low + TRIGGER_LEVELS[0] * span, low + TRIGGER_LEVELS[1] * span
    marker = np.where(smooth >= upper, 1, np.where(smooth <= lower, 0, -1))
    marked = np.where(marker >= 0, np.arange(smooth.size), 0)
    last = np.maximum.accumulate(marked)
    state = np.where(marker[last] == 1, 1, 0)
    change = np.diff(state)
    rising = np.flatnonzero(change == 1) + 1
    if state[0] == 1:
        rising = np.concatenate([[0], rising])
    falling = np.flatnonzero(change == -1) + 1
    return rising, falling, float(low), float(span)


def _edges(smooth: np.ndarray, least: float | None = None
           ) -> tuple[np.ndarray, np.ndarray, float, float]:
    """The edges of :func:`_schmitt`, with those of the loadings to a lower force before the
    first one it finds (a proof load before the pull to break: three real loadings to 32 %
    of the maximum were no cycle of the two-level trigger set on the whole range).

    The record before the first loading rises through the lower level is triggered again at
    its own levels, and so on; its loadings that come back down, and rise by `least` [N]
    at least (:data:`EARLIER_SHARE` of the whole range), are loadings too (a ramp to the
    preload is none)."""
    rising, falling, low, span = _schmitt(smooth)
    least = EARLIER_SHARE * span if least is None else least
    if not rising.size or not span >= least:
        return rising, falling, low, span
    below = np.flatnonzero(smooth[: rising[0]] <= low + TRIGGER_LEVELS[0] * span)
    if not below.size:
        return rising, falling, low, span
    head_rising, head_falling, _, head_span = _edges(smooth[: below[-1] + 1], least)
    if not head_rising.size or head_span < least:
        return rising, falling, low, span
    head_falling = head_falling[head_falling > head_rising[0]]
    complete = head_falling.size  # each rising edge is followed by a falling one but the last
    return (np.concatenate([head_rising[:complete], rising]),
            np.concatenate([head_falling, falling]), low, span)


def count_cycles(force: np.ndarray) -> int:
    """Number of load cycles in a force record (cheap; used by ``chainbench inspect``).

    Parameters
    ----------
    force : numpy.ndarray
        Force samples [any unit], tension- or compression-positive; NaNs are
        ignored.

    Returns
    -------
    int
        Excursions of the oriented force above 70 % of its range, each after a
        visit below 30 % (or at the start), and the loadings to a lower force before
        them (:func:`_edges`); none when the range is within ten times
        the noise, or that of the rounding of a force logged in steps (a gauge's
        whole counts: 0, 2, 0, 2 gf is no load cycle).

    Examples
    --------
    >>> triangle = np.concatenate([np.linspace(0, 10, 20), np.linspace(10, 0, 20)])
    >>> count_cycles(np.tile(triangle, 3))
    3
    """
    force = np.asarray(force, dtype=float)
    force = force[np.isfinite(force)]
    if force.size < 3:
        return 0
    smooth = uniform_filter1d(load_sign(force) * force, SMOOTHING, mode="nearest")
    rising, _, _, span = _edges(smooth)
    steps = np.abs(np.diff(force))
    steps = steps[steps > 0]
    rounding = float(steps.min()) / np.sqrt(12.0) if steps.size else 0.0
    return (int(rising.size) if span > 10 * noise_level(force)
            and np.ptp(force) > 10 * rounding else 0)


def segment_cycles(
    force: np.ndarray, *, preload: float | None = None, n_cycles: int | None = None
) -> Segmentation:
    """Split a cyclic force record into cycles and preload/loading/hold/unloading branches.

    Parameters
    ----------
    force : numpy.ndarray
        Force samples [N] in time order, finite, at least 3.
    preload : float, optional
        Magnitude of the preload [N] in the direction of the load. When given,
        the record must rise above it, and the loading branches start where the
        force leaves it (a ramp from zero to the preload stays ``preload``).
    n_cycles : int, optional
        Number of cycles the test should have; fewer is an error.

    Returns
    -------
    Segmentation
        Per-sample cycle and branch labels and the turning points.

    Raises
    ------
    SignalError
        When the record is too short or not finite, when the force never rises
        above the preload, when there is no cycle, or fewer than `n_cycles`.
    """
    force = np.asarray(force, dtype=float)
    if force.size < 3:
        raise SignalError(
            f"the force record holds only {force.size} usable sample(s)",
            column="force",
            hint="a tensile test needs its whole load history: check that the file is complete",
        )
    if not np.all(np.isfinite(force)):
        raise SignalError(
            f"the force record holds {int(np.sum(~np.isfinite(force)))} missing or infinite "
            "value(s)",
            column="force",
            hint="check the force channel of the file around the missing values",
        )
    sign = load_sign(force)
    oriented = sign * force
    noise = noise_level(oriented)
    smooth = uniform_filter1d(oriented, SMOOTHING, mode="nearest")
    if preload is not None and smooth.max() <= preload + 4 * noise:
        peak = float(np.max(oriented))
        raise SignalError(
            f"the force never rises above the preload ({peak:.6g} N <= {preload:.6g} N)",
            column="force",
            hint="check the force column and its unit, and the preload of the run",
        )
    rising, falling, _, span = _edges(smooth)
    if not span > 10 * noise or rising.size == 0:
        raise SignalError(
            "no load cycle found in the force record",
            column="force",
            hint="the force must rise from the preload to the upper load and back",
        )
    found = len(rising)
    if n_cycles is not None and found < n_cycles:
        raise SignalError(
            f"found {found} load cycle(s), the test should have {n_cycles}",
            column="force",
            hint="check that the whole test was logged, or set the run's number of cycles",
        )
    tolerance = max(4 * noise, 2e-3 * span)
    floor = -np.inf if preload is None else preload
    size = force.size
    downs = [int(falling[falling > up][0]) if np.any(falling > up) else size for up in rising]

    def valley(start: int, stop: int) -> np.ndarray:
        if stop <= start:
            return np.array([], dtype=int)
        level = max(smooth[start:stop].min(), floor) + tolerance
        return start + np.flatnonzero(smooth[start:stop] <= level)

    turns = np.zeros((found, 4), dtype=int)
    valleys: list[tuple[int, int] | None] = []
    previous_down = 0
    for number, (up, down) in enumerate(zip(rising, downs, strict=True)):
        before = valley(previous_down, int(up))
        if number > 0:
            turns[number - 1, 3] = before[0] if before.size else up
        turns[number, 0] = before[-1] if before.size else up
        valleys.append((int(before[0]), int(before[-1])) if before.size else None)
        top = smooth[up:down].max() - tolerance
        at_top = up + np.flatnonzero(smooth[up:down] >= top)
        turns[number, 1], turns[number, 2] = at_top[0], at_top[-1]
        previous_down = down
    after = valley(previous_down, size)
    turns[-1, 3] = after[0] if after.size else size - 1
    valleys.append((int(after[0]), int(after[-1])) if after.size else None)

    cycle = np.zeros(size, dtype=int)
    branch = np.full(size, "preload", dtype=object)
    for number, (load_start, load_end, unload_start, unload_end) in enumerate(turns, start=1):
        stop = turns[number, 0] if number < found else size
        cycle[load_start:stop] = number
        branch[load_start:stop] = "hold"
        branch[load_start : load_end + 1] = "loading"
        branch[unload_start : unload_end + 1] = "unloading"
    return Segmentation(
        sign=sign,
        cycle=cycle,
        branch=branch.astype(str),
        turns=turns,
        valleys=valleys,
        noise=noise,
        tolerance=float(tolerance),
    )
