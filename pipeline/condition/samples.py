"""What a log's samples say about where it can be trusted: gaps, clipping, offset, a preview.

A chunk of a log (:mod:`pipeline.condition.scan`) is summarised by
:func:`summarise_samples` into a :class:`SampleSummary`: the runs of missing
samples, of samples at the chunk's extremes and above a given clipping level,
every n-th sample for the log's offset, and every m-th sample for the stored
preview of the signal. :func:`merge_summaries` joins the summaries of all
chunks, in order, into the :class:`LogSamples` of the whole log, which answers
per window of samples whether it holds a missing or a clipped sample. A whole
log summarised as one chunk gives the same numbers as any cut into chunks.

Clipping is read from the data: an extreme value held for
:data:`CLIP_RUN` consecutive samples or more is a saturated amplifier or
converter, and a window touching it is excluded.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

#: Consecutive samples at the log's extreme value that mark clipping.
CLIP_RUN = 3

#: Samples of a log that its median offset is taken from (every n-th, :func:`offset_stride`).
OFFSET_SAMPLES = 100_000

#: Runs of flagged samples: first samples and ends (exclusive) in the log, sorted.
Runs = tuple[np.ndarray, np.ndarray]

NO_RUNS: Runs = (np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64))


def offset_stride(n_samples: int) -> int:
    """Stride of the samples of an `n_samples` log that its offset is the median of."""
    return max(1, n_samples // OFFSET_SAMPLES)


def runs_of(flags: np.ndarray, origin: int = 0) -> Runs:
    """Runs of set `flags`, as samples of the log (`origin` the sample of ``flags[0]``).

    One pass over the flags: a log flags few samples (missing, at an extreme), and the
    runs are cut from their positions.

    >>> runs_of(np.array([1, 1, 0, 0, 1, 0, 1, 1, 1], dtype=bool), origin=10)
    (array([10, 14, 16]), array([12, 15, 19]))
    """
    flagged = np.flatnonzero(flags)
    breaks = np.flatnonzero(np.diff(flagged) != 1)
    starts = np.concatenate([flagged[:1], flagged[breaks + 1]])
    stops = np.concatenate([flagged[breaks], flagged[-1:]]) + 1
    return starts + origin, stops + origin


def merge_runs(runs: list[Runs]) -> Runs:
    """Runs of consecutive pieces of a log (in order) as one sorted list, touching runs joined."""
    starts = np.concatenate([NO_RUNS[0], *(run[0] for run in runs)])
    stops = np.concatenate([NO_RUNS[1], *(run[1] for run in runs)])
    if starts.size == 0:
        return NO_RUNS
    keep = np.ones(starts.size, dtype=bool)
    keep[1:] = starts[1:] != stops[:-1]
    return starts[keep], stops[np.append(keep[1:], True)]


def run_hits(runs: Runs, start: np.ndarray, width: int) -> np.ndarray:
    """Whether each window ``[start, start + width)`` of samples holds a sample of `runs`."""
    starts, stops = runs
    if starts.size == 0:
        return np.zeros(np.shape(start), dtype=bool)
    index = np.searchsorted(stops, start, side="right")  # the first run ending after `start`
    return (index < starts.size) & (starts[np.minimum(index, starts.size - 1)] < start + width)


@dataclass(frozen=True)
class SampleSummary:
    """The summary of the samples ``[start, stop)`` of a log (see :func:`summarise_samples`).

    Attributes
    ----------
    missing, at_max, at_min, above_clip : Runs
        Runs of missing samples, of samples at the piece's maximum and minimum,
        and at or above the given clipping level (empty without one).
    maximum, minimum : float
        Extremes of the piece [N] (NaN when it holds no number).
    offset_sample : numpy.ndarray
        The samples at the log's multiples of :func:`offset_stride` [N].
    preview_time, preview_force : numpy.ndarray
        The samples at the log's multiples of the preview stride: time [s] and force [N].
    """

    missing: Runs
    at_max: Runs
    at_min: Runs
    above_clip: Runs
    maximum: float
    minimum: float
    offset_sample: np.ndarray
    preview_time: np.ndarray
    preview_force: np.ndarray


def _multiples(start: int, stop: int, stride: int) -> slice:
    """The positions, relative to `start`, of the multiples of `stride` in ``[start, stop)``."""
    return slice(-(-start // stride) * stride - start, stop - start, stride)


def summarise_samples(time: np.ndarray, force: np.ndarray, start: int, *, n_samples: int,
                      preview_stride: int, clip_level: float | None = None) -> SampleSummary:
    """Summarise samples ``start`` to ``start + force.size`` of a log (a pure function).

    Parameters
    ----------
    time : numpy.ndarray
        Their times [s].
    force : numpy.ndarray
        The force channel [N], NaN where missing.
    start : int
        The log's index of the first sample.
    n_samples : int
        Samples in the whole log (sets the offset's stride).
    preview_stride : int
        Stride of the stored preview of the signal.
    clip_level : float, optional
        Upper saturation level given for the force [N].

    Returns
    -------
    SampleSummary
    """
    stop = start + force.size
    with np.errstate(invalid="ignore"):
        maximum = float(np.fmax.reduce(force)) if force.size else math.nan
        minimum = float(np.fmin.reduce(force)) if force.size else math.nan
    preview = _multiples(start, stop, preview_stride)
    return SampleSummary(
        missing=runs_of(~np.isfinite(force), start),
        at_max=runs_of(force == maximum, start), at_min=runs_of(force == minimum, start),
        above_clip=NO_RUNS if clip_level is None else runs_of(force >= clip_level, start),
        maximum=maximum, minimum=minimum,
        # copies: a view would keep the whole chunk alive as long as the summary
        offset_sample=force[_multiples(start, stop, offset_stride(n_samples))].copy(),
        preview_time=time[preview].copy(), preview_force=force[preview].copy())


def _flat_extreme(values: list[float], runs: list[Runs], pick) -> tuple[float | None, Runs]:
    """The log's extreme (`pick` of the pieces'), when held for :data:`CLIP_RUN` samples."""
    finite = [value for value in values if math.isfinite(value)]
    if not finite:
        return None, NO_RUNS
    extreme = pick(finite)
    merged = merge_runs([run for value, run in zip(values, runs, strict=True)
                         if value == extreme])
    flat = bool(np.any(merged[1] - merged[0] >= CLIP_RUN))
    return (extreme if flat else None), merged


@dataclass(frozen=True)
class LogSamples:
    """The summaries of all pieces of a log, joined (:func:`merge_summaries`).

    Attributes
    ----------
    parts : tuple of SampleSummary
        The pieces' summaries, in order.
    clip_level : float or None
        Upper saturation level given for the force [N].
    """

    parts: tuple[SampleSummary, ...]
    clip_level: float | None = None

    @cached_property
    def _high(self) -> tuple[float | None, Runs]:
        return _flat_extreme([p.maximum for p in self.parts], [p.at_max for p in self.parts], max)

    @cached_property
    def _low(self) -> tuple[float | None, Runs]:
        return _flat_extreme([p.minimum for p in self.parts], [p.at_min for p in self.parts], min)

    @property
    def clip_levels(self) -> tuple[float | None, float | None]:
        """Lower and upper clipping levels [N]: the flat extremes, the upper one lowered
        to the given `clip_level`; None where there is none."""
        low, high = self._low[0], self._high[0]
        if self.clip_level is not None:
            high = self.clip_level if high is None else min(high, self.clip_level)
        return low, high

    def clipped(self, start: np.ndarray, width: int) -> np.ndarray | None:
        """Whether each window ``[start, start + width)`` touches a clipping level (None: none)."""
        low, high = self.clip_levels
        if low is None and high is None:
            return None
        hits = np.zeros(np.shape(start), dtype=bool)
        if high is not None:
            above = (merge_runs([part.above_clip for part in self.parts])
                     if high == self.clip_level else self._high[1])
            hits |= run_hits(above, start, width)
        if low is not None:
            hits |= run_hits(self._low[1], start, width)
        return hits

    def missing(self, start: np.ndarray, width: int) -> np.ndarray:
        """Whether each window ``[start, start + width)`` holds a missing sample."""
        return run_hits(merge_runs([part.missing for part in self.parts]), start, width)

    @property
    def offset(self) -> float:
        """Median of the finite offset samples [N] (0 without any): subtracted before the fits.

        Only conditions the fits (the slow tension has a constant column): every
        result but the rounding is the same whatever the offset.
        """
        sample = np.concatenate([part.offset_sample for part in self.parts])
        sample = sample[np.isfinite(sample)]
        return float(np.median(sample)) if sample.size else 0.0

    @property
    def preview(self) -> tuple[np.ndarray, np.ndarray]:
        """Time [s] and force [N] of the preview samples of the whole log."""
        return (np.concatenate([part.preview_time for part in self.parts]),
                np.concatenate([part.preview_force for part in self.parts]))


def merge_summaries(parts: list[SampleSummary], clip_level: float | None = None) -> LogSamples:
    """The samples of a whole log from the summaries of its pieces, in order.

    Parameters
    ----------
    parts : list of SampleSummary
        :func:`summarise_samples` of consecutive pieces covering the log.
    clip_level : float, optional
        Upper saturation level given for the force [N] (as given to the pieces).
    """
    return LogSamples(tuple(parts), clip_level)


def clipping_levels(force: np.ndarray) -> tuple[float | None, float | None]:
    """Lower and upper clipping levels of a channel `force` [N], from flat extremes.

    The minimum / maximum when it is held for :data:`CLIP_RUN` samples in a row
    (a saturated amplifier or converter), else None.

    Examples
    --------
    >>> clipping_levels(np.array([0.0, 1.0, 1.0, 1.0, 0.5]))
    (None, 1.0)
    """
    summary = summarise_samples(np.zeros(force.size), force, 0, n_samples=force.size,
                                preview_stride=max(1, force.size))
    return merge_summaries([summary]).clip_levels
