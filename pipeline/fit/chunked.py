"""Impact extraction of a long engagement log, chunk by chunk (the same result as in one piece).

A log of 10^7 samples or more (``docs/file-formats.md``) is processed in chunks of
`chunk_samples` samples, each read with `overlap` samples of its neighbours on
either side. Every step that looks at samples is a pure function of one chunk
(chunk data in, small results out: a dask task each); the steps that look at the
whole run reduce those small results. The result equals
:func:`pipeline.condition.engagement.detect_events` followed by
:func:`pipeline.fit.impact.extract_impacts` on the whole log, up to rounding:

1. **Setup** (:func:`chunk_setup`), from the head of the log only, exactly as the
   unchunked detector finds them there: the natural-frequency estimate, the
   block size of the onset strength, the period guess (force) or the strikes'
   angular phase (angle channel); and the overlap the chunks need
   (:func:`required_overlap`).
2. **Scan** each chunk (:func:`scan_chunk`): the onset strength of chunk plus
   overlap (blocks and angle samples aligned with the whole log's, so they are
   the same numbers), the candidate seatings whose impact-2 block lies in the
   chunk's own span ``[start, stop)``, the angle's moments, the runs of missing,
   extreme and clipped samples and the samples of the offset.
3. **Merge** (:func:`merge_scans`): the seatings of all chunks, the run-level
   choices (a fifth of the median peak strength, the seating period from all
   onsets or from the angle's least-squares slope, clipping levels, offset),
   the events' statuses before the fits.
4. **Ringing**, once per run: fitted on the same up to 64 events spread over
   the log as :func:`~pipeline.fit.impact.extract_impacts` picks, from their
   windows only (:func:`ringing_sample`); it is passed to every chunk.
5. **Fit** each chunk (:func:`fit_chunk`): the events whose impact-1 onset lies
   in the chunk's own span, so each event is fitted once.
6. **Statistics** on the merged event table, by the code of
   :func:`~pipeline.fit.impact.extract_impacts` (the failed-fit and overlap
   rules compare an event with the run and its neighbours, so they run there).

Where the result can differ from the unchunked one: the angle-channel period
used for the search half-width (``period / 8``) and the fold comes from the head
(the unchunked detector uses the whole log's; the same unless the speed drifts);
missing force samples are filled with the head's median (the whole log's in the
unchunked detector: the events near a gap, which are excluded as ``gap``, may be
placed differently); an angle channel is used when its head holds data.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.condition.engagement import (
    HEAD_PERIODS,
    PERIOD_TOLERANCE,
    SAMPLES_PER_RINGING,
    SPECTRUM_SEGMENTS,
    EngagementEvents,
    angle_slope,
    angle_track,
    block_size,
    check_duration,
    check_uniform,
    collect_events,
    fill_missing,
    force_channel,
    impact_phase,
    natural_frequency_estimate,
    onset_peaks,
    onset_strength,
    period_from_autocorrelation,
    period_from_onsets,
    sampling,
    seatings_on_track,
    spectrum_segment,
    strong_peaks,
    unwrapped_angle,
)
from pipeline.errors import SignalError
from pipeline.fit.impact import (
    EventFits,
    ImpactResult,
    Ringing,
    _event_table,
    _fit_events,
    _Geometry,
    _levels,
    _offset_of,
    _offset_stride,
    _relative,
    _ringing_pick,
    _run_ringing,
    _run_statistics,
    _slack,
    _usable,
    _window_status,
)
from pipeline.theory.wheel_impact import seating_period

#: Seating periods of overlap on each side of a chunk for the detection: the
#: strongest onset of a period beats its neighbours within 0.7 periods, and they
#: theirs (chains of at most two), plus the strikes' windows.
OVERLAP_PERIODS = 3.0
#: Head of the log the setup reads, in stated seating periods (:data:`HEAD_PERIODS`
#: plus room for a measured period up to 25 % longer).
SETUP_PERIODS = 1.25 * HEAD_PERIODS
#: Consecutive samples at an extreme that mark clipping (as :func:`clipping_levels`).
_CLIP_RUN = 3

#: Runs of flagged samples: first samples and ends (exclusive) in the log, sorted.
Runs = tuple[np.ndarray, np.ndarray]


@dataclass(frozen=True)
class Chunk:
    """One chunk of a log, in samples of the log.

    Attributes
    ----------
    start, stop : int
        The chunk's own span ``[start, stop)``: the events whose impact 2 (scan)
        or impact 1 (fit) falls there are the chunk's.
    data_start, data_stop : int
        The samples read, own span plus overlap: ``data_start`` is a multiple of
        the angle stride (so blocks and angle samples align with the log's).
    """

    start: int
    stop: int
    data_start: int
    data_stop: int


@dataclass(frozen=True)
class ChunkSetup:
    """What every chunk needs to know of its run, found on the head of the log.

    Attributes
    ----------
    z : int
        Number of teeth [-].
    omega : float
        Wheel speed stated in the run sheet [1/s].
    start_time : float
        Time of the log's first sample [s].
    step : float
        Mean time step of the whole log [s].
    n_samples : int
        Samples in the log.
    natural_frequency : float
        The detector's estimate of the branch's natural angular frequency [rad/s].
    block : int
        Samples per block of the onset strength.
    fill : float
        Value of missing force samples in the detection [N].
    source : str
        ``"angle"`` or ``"force"``: where the seatings come from.
    period : float
        Seating period found on the head [s]: the autocorrelation guess (force)
        or from the angle's slope (angle).
    phase1 : float
        Angle of impact 1 modulo the tooth pitch on the forward angle track
        [rad] (NaN for the force source).
    overlap : int
        Fewest samples of overlap the chunks need (:func:`required_overlap`).
    clip_level : float or None
        Upper saturation level given for the force [N].
    file : str or None
        The log's file, named in errors.
    """

    z: int
    omega: float
    start_time: float
    step: float
    n_samples: int
    natural_frequency: float
    block: int
    fill: float
    source: str
    period: float
    phase1: float
    overlap: int
    clip_level: float | None = None
    file: str | None = None

    @property
    def rate(self) -> float:
        """Sampling rate [Hz]."""
        return float(1.0 / self.step)

    @property
    def dt(self) -> float:
        """Duration of a block [s] (the onsets' resolution)."""
        return self.block / self.rate

    @property
    def stride(self) -> int:
        """Samples between the angle samples the detector reads (one per ringing period)."""
        return self.block * SAMPLES_PER_RINGING


@dataclass(frozen=True)
class ChunkScan:
    """What :func:`scan_chunk` finds in one chunk (everything in the chunk's own span).

    Attributes
    ----------
    chunk : Chunk
    impact1, impact2 : numpy.ndarray
        Angle source: onsets of impact 1 and 2 [s]. Force source: ``impact1``
        empty, ``impact2`` the blocks' times of the period peaks (without the
        half-block lead) [s].
    heights : numpy.ndarray
        Force source: onset strengths of the peaks [N^2] (empty for the angle).
    moments : tuple of float
        Angle source: count, mean time [s], mean unwrapped angle [rad], sum of
        squared time deviations [s^2], sum of time x angle deviations [s rad],
        first and last unwrapped angle [rad] of the angle samples in the own
        span, unwrapped within the chunk (empty for the force).
    missing, at_max, at_min, above_clip : Runs
        Runs of missing samples, of samples at the chunk's maximum and minimum,
        and at or above the given clip level (empty without one).
    maximum, minimum : float
        Extremes of the force in the own span [N] (NaN when it holds no number).
    offset_sample : numpy.ndarray
        The force at the samples the run's offset is the median of [N].
    """

    chunk: Chunk
    impact1: np.ndarray
    impact2: np.ndarray
    heights: np.ndarray
    moments: tuple[float, ...]
    missing: Runs
    at_max: Runs
    at_min: Runs
    above_clip: Runs
    maximum: float
    minimum: float
    offset_sample: np.ndarray


@dataclass(frozen=True)
class ChunkFitPlan:
    """What :func:`fit_chunk` needs of its run.

    Attributes
    ----------
    prior1, prior2 : numpy.ndarray
        Detected onsets of impact 1 and 2 of the run's usable events [s].
    first : numpy.ndarray
        Sample of the log at or after each ``prior1``.
    geometry : _Geometry
        Sampling and window of the run's events.
    ringing : Ringing
        The run's ringing.
    margin : float
        Mask margin of the first pass [s].
    offset : float
        The run's offset [N].
    """

    prior1: np.ndarray
    prior2: np.ndarray
    first: np.ndarray
    geometry: _Geometry
    ringing: Ringing
    margin: float
    offset: float

    def events_of(self, chunk: Chunk) -> slice:
        """The usable events whose impact-1 onset lies in the chunk's own span."""
        lo, hi = np.searchsorted(self.first, [chunk.start, chunk.stop])
        return slice(int(lo), int(hi))


def setup_samples(sample_rate: float, z: int, omega: float) -> int:
    """Samples at the head of a log that :func:`chunk_setup` reads.

    Parameters
    ----------
    sample_rate : float
        Sampling rate [Hz].
    z : int
        Number of teeth [-].
    omega : float
        Stated wheel speed [1/s].

    Returns
    -------
    int
        What the detector's estimates read on the whole log: the spectrum's
        :data:`SPECTRUM_SEGMENTS` segments and :data:`SETUP_PERIODS` seating periods.
    """
    stated = float(seating_period(z, omega))
    segment = spectrum_segment(sample_rate, stated)
    return max(SPECTRUM_SEGMENTS * segment + 1, math.ceil(SETUP_PERIODS * stated * sample_rate))


def required_overlap(period: float, natural_frequency: float, sample_rate: float,
                     stride: int) -> int:
    """Fewest samples of overlap on each side of a chunk for a chunk-independent result.

    Parameters
    ----------
    period : float
        Seating period [s].
    natural_frequency : float
        Natural angular frequency of the branch [rad/s].
    sample_rate : float
        Sampling rate [Hz].
    stride : int
        Alignment of the chunks' data [samples].

    Returns
    -------
    int
        :data:`OVERLAP_PERIODS` seating periods (the detection's reach, which
        holds an event's window, ``2.25 tau`` plus slack) plus two ringing
        periods (the edges of the onset strength) plus `stride`.
    """
    ringing_period = 2 * np.pi / natural_frequency
    return math.ceil((OVERLAP_PERIODS * period + 2 * ringing_period) * sample_rate) + stride


def chunk_setup(head: pd.DataFrame, *, n_samples: int, end_time: float, z: int, omega: float,
                natural_frequency: float | None = None, impact_angle: float | None = None,
                use_angle: bool = True, clip_level: float | None = None,
                file: str | Path | None = None) -> ChunkSetup:
    """The run-level choices of the detector, from the head of a log.

    Parameters
    ----------
    head : pandas.DataFrame
        The first :func:`setup_samples` samples of the log (or all), canonical
        columns ``time`` [s], ``force`` [N], optional ``angle`` [rad].
    n_samples : int
        Samples in the whole log.
    end_time : float
        Time of the log's last sample [s].
    z, omega, natural_frequency, impact_angle, use_angle
        As in :func:`pipeline.condition.engagement.detect_events`.
    clip_level : float, optional
        Upper saturation level of the force [N] (see
        :func:`pipeline.fit.impact.extract_impacts`).
    file : str or Path, optional
        The log's file, named in errors.

    Returns
    -------
    ChunkSetup

    Raises
    ------
    SignalError
        As :func:`~pipeline.condition.engagement.detect_events` for the head, and
        when the log's time does not increase or it holds too few periods.
    """
    start, _ = sampling(head, file)
    step = (end_time - start) / (n_samples - 1)
    if not (math.isfinite(step) and step > 0):
        raise SignalError("the time channel does not increase", file=file, column="time",
                          hint="check the time column and its unit")
    rate = float(1.0 / step)
    stated = float(seating_period(z, omega))
    check_duration(n_samples / rate, stated, z, omega, file)
    raw = force_channel(head, file)
    force = fill_missing(raw, file=file)
    fill = float(np.median(raw[np.isfinite(raw)]))
    omega_n = natural_frequency_estimate(force, rate, stated, natural_frequency, file)
    block = block_size(rate, omega_n)
    dt = block / rate
    strength = onset_strength(force, block, rate, omega_n)
    block_time = start + dt * np.arange(strength.size)
    stride = block * SAMPLES_PER_RINGING
    angle = head["angle"].to_numpy(dtype=float)[::stride] if "angle" in head else None
    if use_angle and angle is not None and np.isfinite(angle).any():
        t, theta = unwrapped_angle(angle, start + np.arange(angle.size) * stride / rate, file)
        slope = angle_slope(t, theta)
        track = angle_track(t, theta, slope, z, file)
        period = 2 * np.pi / z / abs(slope)
        phase1 = (impact_phase(strength, t, track, block_time, period, z) if impact_angle is None
                  else float(np.sign(slope) * impact_angle))
        source = "angle"
    else:
        period = period_from_autocorrelation(strength, dt, stated)
        phase1, source = math.nan, "force"
    overlap = required_overlap(max(period, stated), omega_n, rate, stride)
    return ChunkSetup(z=int(z), omega=float(omega), start_time=start, step=step,
                      n_samples=int(n_samples), natural_frequency=omega_n, block=block, fill=fill,
                      source=source, period=float(period), phase1=phase1, overlap=overlap,
                      clip_level=clip_level, file=None if file is None else str(file))


def plan_chunks(setup: ChunkSetup, chunk_samples: int,
                overlap_samples: int | None = None) -> list[Chunk]:
    """Cut a log into chunks of `chunk_samples` with overlap on either side.

    Parameters
    ----------
    setup : ChunkSetup
        The run's setup.
    chunk_samples : int
        Samples of each chunk's own span (the last one may be shorter).
    overlap_samples : int, optional
        Samples read on each side beyond the own span; default and minimum
        :attr:`ChunkSetup.overlap`.

    Returns
    -------
    list of Chunk

    Raises
    ------
    ValueError
        When the overlap is below the minimum or `chunk_samples` below the overlap.
    """
    chunk_samples = int(chunk_samples)
    overlap = setup.overlap if overlap_samples is None else int(overlap_samples)
    if overlap < setup.overlap:
        raise ValueError(
            f"overlap_samples={overlap} is below the {setup.overlap} samples a chunk border "
            f"needs ({OVERLAP_PERIODS:g} seating periods of {setup.period:.4g} s and two ringing "
            f"periods at {setup.rate:g} Hz); leave it out to use the minimum")
    if not chunk_samples >= overlap:
        raise ValueError(
            f"chunk_samples={chunk_samples} is smaller than the overlap of {overlap} samples on "
            "each side: most of every chunk would be overlap; use larger chunks")
    stride, n = setup.stride, setup.n_samples
    return [Chunk(start, min(n, start + chunk_samples),
                  max(0, (start - overlap) // stride * stride),
                  min(n, start + chunk_samples + overlap))
            for start in range(0, n, chunk_samples)]


def _runs(flags: np.ndarray, origin: int) -> Runs:
    """Runs of set `flags`, as samples of the log (`origin` the sample of ``flags[0]``)."""
    edges = np.diff(flags.astype(np.int8), prepend=0, append=0)
    return np.flatnonzero(edges == 1) + origin, np.flatnonzero(edges == -1) + origin


_NO_RUNS: Runs = (np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64))


def _angle_moments(t: np.ndarray, theta: np.ndarray) -> tuple[float, ...]:
    """Count, means, centred sums and end values of angle samples (see :class:`ChunkScan`)."""
    if t.size == 0:
        return (0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    dtime, dtheta = t - t.mean(), theta - theta.mean()
    return (t.size, float(t.mean()), float(theta.mean()), float(np.dot(dtime, dtime)),
            float(np.dot(dtime, dtheta)), float(theta[0]), float(theta[-1]))


def scan_chunk(data: pd.DataFrame, chunk: Chunk, setup: ChunkSetup) -> ChunkScan:
    """Seatings, flagged samples and offset samples of one chunk (a pure function).

    Parameters
    ----------
    data : pandas.DataFrame
        Samples ``data_start`` to ``data_stop`` of the log (canonical columns).
    chunk : Chunk
        Where they lie in the log.
    setup : ChunkSetup
        The run's setup.

    Returns
    -------
    ChunkScan

    Raises
    ------
    SignalError
        When the chunk's time is not uniformly sampled at the log's step, or its
        angle channel holds no data or advances by less than a tooth pitch.
    """
    file, rate, block, stride = setup.file, setup.rate, setup.block, setup.stride
    check_uniform(data["time"].to_numpy(dtype=float), setup.step, file, chunk.data_start)
    raw = force_channel(data, file)
    own = raw[chunk.start - chunk.data_start: chunk.stop - chunk.data_start]
    maximum, minimum = float(np.fmax.reduce(own)), float(np.fmin.reduce(own))
    offset_stride = _offset_stride(setup.n_samples)
    first_offset = -(-chunk.start // offset_stride) * offset_stride

    force = fill_missing(raw, setup.fill)
    strength = onset_strength(force, block, rate, setup.natural_frequency)
    first_block = chunk.data_start // block
    block_time = setup.start_time + setup.dt * np.arange(first_block, first_block + strength.size)
    impact1 = heights = np.zeros(0)
    moments: tuple[float, ...] = ()
    if setup.source == "angle":
        angle = data["angle"].to_numpy(dtype=float)[::stride]
        index = chunk.data_start + stride * np.arange(angle.size)
        t, theta = unwrapped_angle(angle, setup.start_time + index / rate, file)
        slope = angle_slope(t, theta)
        track = angle_track(t, theta, slope, setup.z, file)
        impact1, impact2 = seatings_on_track(strength, t, track, block_time, setup.z,
                                             setup.phase1, setup.period)
        peak = first_block + np.rint((impact2 - block_time[0]) / setup.dt).astype(np.int64)
        mine = (peak * block >= chunk.start) & (peak * block < chunk.stop)
        impact1, impact2 = impact1[mine], impact2[mine]
        inside = ((index >= chunk.start) & (index < chunk.stop))[np.isfinite(angle)]
        moments = _angle_moments(t[inside], theta[inside])
    else:
        peaks, heights = onset_peaks(strength, setup.dt, setup.period)
        mine = ((first_block + peaks) * block >= chunk.start) & (
            (first_block + peaks) * block < chunk.stop)
        impact2, heights = block_time[peaks[mine]], heights[mine]
    return ChunkScan(
        chunk, impact1, impact2, heights, moments,
        missing=_runs(~np.isfinite(own), chunk.start),
        at_max=_runs(own == maximum, chunk.start), at_min=_runs(own == minimum, chunk.start),
        above_clip=(_NO_RUNS if setup.clip_level is None
                    else _runs(own >= setup.clip_level, chunk.start)),
        maximum=maximum, minimum=minimum,
        offset_sample=raw[first_offset - chunk.data_start: chunk.stop - chunk.data_start:
                          offset_stride])


def _speed(scans: list[ChunkScan]) -> float:
    """Least-squares slope of the whole log's unwrapped angle over time [1/s].

    Each chunk's angle is unwrapped on its own: its turns relative to the log's
    follow from the step between the last angle sample of the chunk before and
    its first (unwrapped like any other step); the moments then combine.
    """
    parts, previous = [], None
    for moments in (scan.moments for scan in scans):
        count, t_mean, theta_mean, stt, sttheta, first, last = moments
        if count == 0:
            continue
        turns = 0.0
        if previous is not None:
            joined = np.unwrap([previous, first])[1]
            turns = 2 * np.pi * round((joined - first) / (2 * np.pi))
        parts.append((count, t_mean, theta_mean + turns, stt, sttheta))
        previous = last + turns
    count, t_mean, theta_mean, stt, sttheta = (np.array(column) for column in zip(*parts,
                                                                                   strict=True))
    t_all = np.dot(count, t_mean) / count.sum()
    theta_all = np.dot(count, theta_mean) / count.sum()
    return float((sttheta.sum() + np.dot(count, (t_mean - t_all) * (theta_mean - theta_all)))
                 / (stt.sum() + np.dot(count, (t_mean - t_all) ** 2)))


def _merge_runs(runs: list[Runs]) -> Runs:
    """Runs of several chunks (in order) as one sorted list, touching runs joined."""
    starts = np.concatenate([run[0] for run in runs])
    stops = np.concatenate([run[1] for run in runs])
    if starts.size == 0:
        return _NO_RUNS
    keep = np.ones(starts.size, dtype=bool)
    keep[1:] = starts[1:] != stops[:-1]
    return starts[keep], stops[np.append(keep[1:], True)]


def _run_hits(runs: Runs, start: np.ndarray, width: int) -> np.ndarray:
    """Whether each window ``[start, start + width)`` holds a sample of `runs`."""
    starts, stops = runs
    if starts.size == 0:
        return np.zeros(start.size, dtype=bool)
    index = np.searchsorted(stops, start, side="right")  # the first run ending after `start`
    return (index < starts.size) & (starts[np.minimum(index, starts.size - 1)] < start + width)


def _extreme(values: list[float], runs: list[Runs], pick: Callable[[list[float]], float]
             ) -> tuple[float | None, Runs]:
    """The log's extreme (`pick` of the chunks'), when held for :data:`_CLIP_RUN` samples."""
    finite = [value for value in values if math.isfinite(value)]
    if not finite:
        return None, _NO_RUNS
    extreme = pick(finite)
    merged = _merge_runs([run for value, run in zip(values, runs, strict=True)
                          if value == extreme])
    flat = bool(np.any(merged[1] - merged[0] >= _CLIP_RUN))
    return (extreme if flat else None), merged


@dataclass(frozen=True)
class RunScan:
    """The run-level results of the scan (:func:`merge_scans`).

    Attributes
    ----------
    events : EngagementEvents
        The seatings of the whole log.
    status : numpy.ndarray
        Status of each event before the fits (``ok``, ``truncated``, ``gap``,
        ``clipped``).
    reach_start : numpy.ndarray
        First sample of each event's reach (window plus slack).
    span : int
        Samples of the reach.
    clip_levels : tuple of (float or None)
        Lower and upper clipping levels used [N].
    offset : float
        The run's offset [N].
    """

    events: EngagementEvents
    status: np.ndarray
    reach_start: np.ndarray
    span: int
    clip_levels: tuple[float | None, float | None]
    offset: float


def merge_scans(scans: list[ChunkScan], setup: ChunkSetup,
                period_tolerance: float = PERIOD_TOLERANCE) -> RunScan:
    """The seatings, statuses, clipping levels and offset of the whole log.

    Parameters
    ----------
    scans : list of ChunkScan
        Every chunk's scan, in order.
    setup : ChunkSetup
        The run's setup.
    period_tolerance : float, optional
        See :func:`pipeline.condition.engagement.detect_events`.

    Returns
    -------
    RunScan

    Raises
    ------
    SignalError, FitError
        As :func:`~pipeline.condition.engagement.detect_events` and
        :func:`~pipeline.fit.impact.extract_impacts` (no seating, no usable event).

    Warns
    -----
    SpeedMismatchWarning
        As :func:`~pipeline.condition.engagement.detect_events`.
    """
    lead = 0.5 * setup.dt
    impact2 = np.concatenate([scan.impact2 for scan in scans])
    if setup.source == "angle":
        impact1 = np.concatenate([scan.impact1 for scan in scans]) + lead
        impact2 = impact2 + lead
        measured_omega = abs(_speed(scans))
        period = 2 * np.pi / (setup.z * measured_omega)
    else:
        impact2 = impact2[strong_peaks(np.concatenate([scan.heights for scan in scans]))]
        period = period_from_onsets(impact2, setup.period)
        impact2 = impact2 + lead
        impact1 = impact2 - period / 2
        measured_omega = 2 * np.pi / (setup.z * period)
    events = collect_events(
        impact1, impact2, period, measured_omega, z=setup.z, omega=setup.omega,
        duration=setup.n_samples / setup.rate, sample_rate=setup.rate,
        start_time=setup.start_time, natural_frequency=setup.natural_frequency,
        source=setup.source, onset_resolution=setup.dt, period_tolerance=period_tolerance,
        file=setup.file)

    geo = _Geometry.of(events)
    slack = _slack(events, geo, setup.file)
    reach_start = geo.first_sample(events.impact1_time) - geo.pre - slack
    span = geo.width + 2 * slack
    high, at_max = _extreme([scan.maximum for scan in scans], [scan.at_max for scan in scans],
                            max)
    low, at_min = _extreme([scan.minimum for scan in scans], [scan.at_min for scan in scans], min)
    low, high = _levels((low, high), setup.clip_level)
    clipped = None
    if low is not None or high is not None:
        above = (_merge_runs([scan.above_clip for scan in scans]) if high == setup.clip_level
                 else at_max)
        clipped = np.zeros(reach_start.size, dtype=bool)
        if high is not None:
            clipped |= _run_hits(above, reach_start, span)
        if low is not None:
            clipped |= _run_hits(at_min, reach_start, span)
    missing = _merge_runs([scan.missing for scan in scans])
    status = _window_status(reach_start, span, setup.n_samples,
                            _run_hits(missing, reach_start, span), clipped)
    offset = _offset_of(np.concatenate([scan.offset_sample for scan in scans]))
    return RunScan(events, status, reach_start, span, (low, high), offset)


def ringing_sample(windows: list[np.ndarray], run: RunScan, pick: np.ndarray,
                   ringing: Ringing | None = None) -> tuple[Ringing, dict[str, float]]:
    """The run's ringing, fitted on the windows of a sample of its events (a pure function).

    Parameters
    ----------
    windows : list of numpy.ndarray
        The force [N] over the reach of each event `pick` (samples
        ``run.reach_start[e]`` to ``+ run.span``).
    run : RunScan
        The merged scan.
    pick : numpy.ndarray
        The events (:func:`~pipeline.fit.impact._ringing_pick` of the usable ones).
    ringing : Ringing, optional
        The ringing when given (then only its relative errors are computed).

    Returns
    -------
    ringing : Ringing
    relative_errors : dict of str to float
        Relative standard errors of the medians due to the ringing.

    Notes
    -----
    The windows are laid end to end and each event's onsets shifted by as much,
    so the fit sees the same samples around each event as on the whole log.
    """
    events, span = run.events, run.span
    geo = _Geometry.of(events)
    shift = (run.reach_start[pick] - span * np.arange(pick.size)) / geo.rate
    y = np.concatenate(windows) - run.offset  # (usable events hold no missing sample)
    return _run_ringing(y, events.impact1_time[pick] - shift, events.impact2_time[pick] - shift,
                        geo, events.natural_frequency, 0.5 * events.onset_resolution, ringing)


def fit_chunk(force: np.ndarray, chunk: Chunk, plan: ChunkFitPlan) -> EventFits:
    """Final fits of the events whose impact 1 lies in a chunk's own span (a pure function).

    Parameters
    ----------
    force : numpy.ndarray
        Samples ``data_start`` to ``data_stop`` of the force [N].
    chunk : Chunk
        Where they lie in the log.
    plan : ChunkFitPlan
        The run's events, ringing and geometry.

    Returns
    -------
    EventFits
        Onsets, amplitudes, variances, residuals and baselines of those events
        (none when no event is the chunk's).
    """
    events = plan.events_of(chunk)
    if events.start == events.stop:
        return EventFits.none()
    geo = replace(plan.geometry, origin=chunk.data_start)
    y = _relative(force, plan.offset, ~np.isfinite(force))
    return _fit_events(y, plan.prior1[events], plan.prior2[events], plan.margin, geo,
                       plan.ringing, plan.offset)


def extract_impacts_chunked(
    table: pd.DataFrame,
    *,
    z: int,
    omega: float,
    chunk_samples: int,
    overlap_samples: int | None = None,
    natural_frequency: float | None = None,
    impact_angle: float | None = None,
    use_angle: bool = True,
    period_tolerance: float = PERIOD_TOLERANCE,
    ringing: Ringing | None = None,
    clip_level: float | None = None,
    file: str | Path | None = None,
) -> tuple[EngagementEvents, ImpactResult]:
    """Detect the seatings of an engagement log and extract N_u1, N_u2, chunk by chunk.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table: ``time`` [s], ``force`` (branch tension) [N], optional
        ``angle`` [rad].
    z, omega, natural_frequency, impact_angle, use_angle, period_tolerance
        As in :func:`pipeline.condition.engagement.detect_events`.
    chunk_samples : int
        Samples of each chunk's own span.
    overlap_samples : int, optional
        Samples read on each side of a chunk; default and minimum the setup's
        (:func:`required_overlap`: three seating periods and two ringing periods).
    ringing, clip_level, file
        As in :func:`pipeline.fit.impact.extract_impacts`.

    Returns
    -------
    events : EngagementEvents
        The seatings of the whole log (as :func:`detect_events` finds them).
    result : ImpactResult
        As :func:`extract_impacts` gives it on the whole log.

    Raises
    ------
    ValueError
        When `chunk_samples` is smaller than the overlap, or `overlap_samples`
        below the minimum.
    SignalError, FitError
        As :func:`detect_events` and :func:`extract_impacts`.
    """
    size = len(table)
    if "time" not in table or size < 3:
        sampling(table, file)  # the detector's error
    time = table["time"]
    end_time = float(time.iloc[-1])
    step = (end_time - float(time.iloc[0])) / (size - 1)
    head = table.iloc[: setup_samples(1.0 / step, z, omega) if step > 0 else 3]
    setup = chunk_setup(head, n_samples=size, end_time=end_time, z=z, omega=omega,
                        natural_frequency=natural_frequency, impact_angle=impact_angle,
                        use_angle=use_angle, clip_level=clip_level, file=file)
    chunks = plan_chunks(setup, chunk_samples, overlap_samples)
    scans = [scan_chunk(table.iloc[chunk.data_start: chunk.data_stop], chunk, setup)
             for chunk in chunks]
    run = merge_scans(scans, setup, period_tolerance)
    events = run.events
    usable = _usable(run.status, file)
    pick = _ringing_pick(usable)
    force = table["force"]
    ringing, relative_errors = ringing_sample(
        [force.iloc[start: start + run.span].to_numpy(dtype=float)
         for start in run.reach_start[pick]], run, pick, ringing)

    geo = _Geometry.of(events)
    prior1, prior2 = events.impact1_time[usable], events.impact2_time[usable]
    plan = ChunkFitPlan(prior1, prior2, geo.first_sample(prior1), geo, ringing,
                        0.5 * events.onset_resolution, run.offset)
    fits = EventFits.concatenate([
        fit_chunk(force.iloc[chunk.data_start: chunk.data_stop].to_numpy(dtype=float), chunk,
                  plan) for chunk in chunks])
    frame = _event_table(events.impact1_time, events.impact2_time, run.status.copy(), usable,
                         fits, geo, ringing)
    statistics, excluded = _run_statistics(frame, relative_errors, file)
    return events, ImpactResult(frame, ringing, statistics, excluded, run.clip_levels,
                                messages=events.messages)

