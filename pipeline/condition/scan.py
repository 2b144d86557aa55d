"""Seatings of an engagement log, chunk by chunk: set-up, scan, merge (condition stage).

The detection of :mod:`pipeline.condition.engagement` in map-reduce shape, so
that a log of any length is read a chunk at a time and chunks can be dask
tasks. A whole log is one chunk; cut into more, the result is the same:

1. **Set-up** (:func:`engagement_setup`), from the head of the log only: the
   natural-frequency estimate, the block size of the onset strength, the
   period guess (force source) or the strikes' angular phase (angle channel),
   the value missing force samples are filled with in the detection, and the
   overlap chunks need (:func:`required_overlap`).
2. **Scan** of a chunk (:func:`scan_chunk`, a pure function of the chunk's
   samples and the set-up): the onset strength of the chunk plus overlap
   (blocks and angle samples aligned with the log's, so they are the same
   numbers whatever the cut), the candidate seatings whose impact-2 block lies
   in the chunk's own span, the angle's moments, and the summary of the
   samples (:mod:`pipeline.condition.samples`).
3. **Merge** (:func:`merge_scans`): the seatings of all chunks, the run-level
   choices (a fifth of the median peak strength, the seating period from all
   onsets or from the angle's least-squares slope) and the check against the
   stated speed, giving the :class:`~pipeline.condition.engagement.EngagementEvents`.

The head fixes two choices for the whole log: the angle channel is used when
the head's holds data, and missing force samples are filled with the head's
median in the detection (events near a gap are excluded as ``gap`` anyway).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

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
from pipeline.condition.samples import SampleSummary, summarise_samples
from pipeline.errors import SignalError
from pipeline.theory.wheel_impact import seating_period

#: Seating periods of overlap on each side of a chunk: the strongest onset of a
#: period beats its neighbours within 0.7 periods, and they theirs (chains of at
#: most two), plus the strikes' windows of the extraction.
OVERLAP_PERIODS = 3.0
#: Head of the log the set-up reads, in stated seating periods (:data:`HEAD_PERIODS`
#: plus room for a measured period up to 25 % longer).
SETUP_PERIODS = 1.25 * HEAD_PERIODS


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
class EngagementSetup:
    """The run-level choices of the detection, made on the head of a log.

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
        Estimate of the branch's natural angular frequency [rad/s].
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
    preview_stride : int
        Stride of the stored preview of the signal.
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
    preview_stride: int = 1
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
        """Samples between the angle samples the detection reads (one per ringing period)."""
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
    samples : SampleSummary
        The summary of the own span's samples (gaps, extremes, offset, preview).
    """

    chunk: Chunk
    impact1: np.ndarray
    impact2: np.ndarray
    heights: np.ndarray
    moments: tuple[float, ...]
    samples: SampleSummary


def setup_samples(sample_rate: float, z: int, omega: float) -> int:
    """Samples at the head of a log that :func:`engagement_setup` reads.

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
        The spectrum's :data:`~pipeline.condition.engagement.SPECTRUM_SEGMENTS`
        segments and :data:`SETUP_PERIODS` seating periods, whichever is longer.
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


def engagement_setup(head: pd.DataFrame, *, n_samples: int, end_time: float, z: int,
                     omega: float, natural_frequency: float | None = None,
                     impact_angle: float | None = None, use_angle: bool = True,
                     preview_stride: int = 1, clip_level: float | None = None,
                     file: str | None = None) -> EngagementSetup:
    """The run-level choices of the detection, from the head of a log.

    Parameters
    ----------
    head : pandas.DataFrame
        The first :func:`setup_samples` samples of the log (or all), canonical
        columns ``time`` [s], ``force`` (branch tension) [N], optional ``angle`` [rad].
    n_samples : int
        Samples in the whole log.
    end_time : float
        Time of the log's last sample [s].
    z : int
        Number of teeth of the wheel [-] (run sheet).
    omega : float
        Wheel speed stated in the run sheet [1/s].
    natural_frequency : float, optional
        Expected natural angular frequency of the branch [rad/s], e.g.
        ``sqrt(E0 / (L m_branch))``: narrows the search for the ringing.
    impact_angle : float, optional
        Wheel angle at impact 1, modulo ``2 pi / z`` [rad]; by default found
        from the force.
    use_angle : bool, optional
        Use the angle channel when the head holds angle data (default True).
    preview_stride : int, optional
        Stride of the stored preview of the signal (every sample by default).
    clip_level : float, optional
        Upper saturation level given for the force [N].
    file : str, optional
        The log's file, named in errors.

    Returns
    -------
    EngagementSetup

    Raises
    ------
    SignalError
        When the head is not uniformly sampled or holds no force data, the log's
        time does not increase, or it holds fewer than
        :data:`~pipeline.condition.engagement.MIN_PERIODS` seating periods.
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
    return EngagementSetup(
        z=int(z), omega=float(omega), start_time=start, step=step, n_samples=int(n_samples),
        natural_frequency=omega_n, block=block, fill=fill, source=source, period=float(period),
        phase1=phase1, overlap=overlap, preview_stride=int(preview_stride),
        clip_level=clip_level, file=None if file is None else str(file))


def plan_chunks(setup: EngagementSetup, chunk_samples: int | None = None,
                overlap_samples: int | None = None) -> list[Chunk]:
    """Cut a log into chunks of `chunk_samples` with overlap on either side.

    Parameters
    ----------
    setup : EngagementSetup
        The run's set-up.
    chunk_samples : int, optional
        Samples of each chunk's own span (the last one may be shorter); by
        default the whole log is one chunk.
    overlap_samples : int, optional
        Samples read on each side beyond the own span; default and minimum
        :attr:`EngagementSetup.overlap`.

    Returns
    -------
    list of Chunk

    Raises
    ------
    ValueError
        When the overlap is below the minimum or `chunk_samples` below the overlap.
    """
    n = setup.n_samples
    if chunk_samples is None:
        return [Chunk(0, n, 0, n)]
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
    stride = setup.stride
    return [Chunk(start, min(n, start + chunk_samples),
                  max(0, (start - overlap) // stride * stride),
                  min(n, start + chunk_samples + overlap))
            for start in range(0, n, chunk_samples)]


def _angle_moments(t: np.ndarray, theta: np.ndarray) -> tuple[float, ...]:
    """Count, means, centred sums and end values of angle samples (see :class:`ChunkScan`)."""
    if t.size == 0:
        return (0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    dtime, dtheta = t - t.mean(), theta - theta.mean()
    return (t.size, float(t.mean()), float(theta.mean()), float(np.dot(dtime, dtime)),
            float(np.dot(dtime, dtheta)), float(theta[0]), float(theta[-1]))


def scan_chunk(data: pd.DataFrame, chunk: Chunk, setup: EngagementSetup) -> ChunkScan:
    """Candidate seatings and the samples' summary of one chunk (a pure function).

    Parameters
    ----------
    data : pandas.DataFrame
        Samples ``data_start`` to ``data_stop`` of the log (canonical columns).
    chunk : Chunk
        Where they lie in the log.
    setup : EngagementSetup
        The run's set-up.

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
    time = data["time"].to_numpy(dtype=float)
    check_uniform(time, setup.step, file, chunk.data_start)
    raw = force_channel(data, file)
    own = slice(chunk.start - chunk.data_start, chunk.stop - chunk.data_start)
    samples = summarise_samples(time[own], raw[own], chunk.start, n_samples=setup.n_samples,
                                preview_stride=setup.preview_stride,
                                clip_level=setup.clip_level)

    strength = onset_strength(fill_missing(raw, setup.fill), block, rate,
                              setup.natural_frequency)
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
        block_start = (first_block + peaks) * block
        mine = (block_start >= chunk.start) & (block_start < chunk.stop)
        impact2, heights = block_time[peaks[mine]], heights[mine]
    return ChunkScan(chunk, impact1, impact2, heights, moments, samples)


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
    count, t_mean, theta_mean, stt, sttheta = (np.array(column)
                                               for column in zip(*parts, strict=True))
    t_all = np.dot(count, t_mean) / count.sum()
    theta_all = np.dot(count, theta_mean) / count.sum()
    return float((sttheta.sum() + np.dot(count, (t_mean - t_all) * (theta_mean - theta_all)))
                 / (stt.sum() + np.dot(count, (t_mean - t_all) ** 2)))


def merge_scans(scans: list[ChunkScan], setup: EngagementSetup,
                period_tolerance: float = PERIOD_TOLERANCE) -> EngagementEvents:
    """The seatings of the whole log from the scans of its chunks.

    Parameters
    ----------
    scans : list of ChunkScan
        Every chunk's scan, in order.
    setup : EngagementSetup
        The run's set-up.
    period_tolerance : float, optional
        Relative disagreement between measured and stated seating period that
        gives a :class:`~pipeline.condition.engagement.SpeedMismatchWarning`.

    Returns
    -------
    EngagementEvents

    Raises
    ------
    SignalError
        When the log holds fewer than
        :data:`~pipeline.condition.engagement.MIN_PERIODS` measured periods or
        no seating.

    Warns
    -----
    SpeedMismatchWarning
        When the measured seating period differs from ``2 pi / (z omega)`` by
        more than `period_tolerance`.
    """
    # The strike starts within the peak block or the one before it (strength sums two).
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
    return collect_events(
        impact1, impact2, period, measured_omega, z=setup.z, omega=setup.omega,
        n_samples=setup.n_samples, sample_rate=setup.rate,
        start_time=setup.start_time, natural_frequency=setup.natural_frequency,
        source=setup.source, onset_resolution=setup.dt, period_tolerance=period_tolerance,
        file=setup.file)
