"""An engagement log in, its seatings and impact tensions out: the engagement pipeline.

The one composition of the detection (:mod:`pipeline.condition.scan`) and the
extraction (:mod:`pipeline.fit.impact`), in map-reduce shape::

    set-up (head of the log) -> scan (per chunk) -> merge -> plan
        -> ringing (windows of up to 64 events) -> fit (per chunk) -> result

A log is a :class:`LogSource`: anything with ``n_rows`` and ``read(start,
stop)`` giving the canonical table of those rows and the warnings reading
them gave. :class:`TableSource` wraps a table in memory;
:func:`pipeline.ingest.open_log` opens a file and reads only the rows asked
for, so the memory is bounded by the chunk size. A whole log is one chunk
(the default); cut into chunks of ``chunk_samples`` the result is the same, to
rounding, because every per-chunk step is a pure function of the chunk's rows
(with enough overlap, :func:`~pipeline.condition.scan.required_overlap`) and
every run-level choice is made once.

The steps are functions of a :class:`LogJob` (:func:`start_log`: the set-up
and the chunks) and of the steps before them: :func:`scan_step` per chunk,
:func:`detect_step`, :func:`ringing_step`, :func:`fit_step` per chunk and
:func:`finish_step`. :func:`analyse_job` runs them here;
:func:`submit_analysis` submits them all at once as tasks to a dask cluster
(a task per chunk for the scans and the fits, each reading its own rows)
without waiting, so that a campaign can drive a long log's chunks beside its
other runs.

:func:`detect_events` and :func:`extract_impacts` are the two halves on a
table in memory, for notebooks and tests.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
import pandas as pd

from pipeline.condition.engagement import (
    PERIOD_TOLERANCE,
    EngagementEvents,
    SpeedMismatchWarning,
    sampling,
)
from pipeline.condition.samples import LogSamples, merge_summaries, summarise_samples
from pipeline.condition.scan import (
    Chunk,
    ChunkScan,
    EngagementSetup,
    engagement_setup,
    merge_scans,
    plan_chunks,
    scan_chunk,
    setup_samples,
)
from pipeline.fit.impact import (
    EventFits,
    ExtractionPlan,
    ImpactResult,
    Ringing,
    fit_chunk,
    fit_ringing,
    impact_result,
    plan_extraction,
)
from pipeline.tasks import submit as submit_task

if TYPE_CHECKING:
    from distributed import Client, Future


class LogSource(Protocol):
    """A log that can be read a range of rows at a time."""

    @property
    def n_rows(self) -> int:
        """Rows (samples) in the log."""

    def read(self, start: int, stop: int) -> tuple[pd.DataFrame, list[str]]:
        """Rows ``[start, stop)`` as the canonical table, and the warnings reading them gave."""


@dataclass(frozen=True)
class TableSource:
    """A log already in memory, as a canonical table (``time`` [s], ``force`` [N], ...)."""

    table: pd.DataFrame

    @property
    def n_rows(self) -> int:
        """Rows in the table."""
        return len(self.table)

    def read(self, start: int, stop: int) -> tuple[pd.DataFrame, list[str]]:
        """Rows ``[start, stop)`` of the table (no warnings)."""
        return self.table.iloc[start:stop], []


@dataclass(frozen=True)
class LogAnalysis:
    """Everything the pipeline finds in one engagement log.

    Attributes
    ----------
    events : EngagementEvents
        The seatings.
    impacts : ImpactResult
        The impact tensions per event and their run statistics.
    preview_time, preview_force : numpy.ndarray
        Every ``preview_stride``-th sample of the log: time [s], force [N].
    preview_stride : int
        Stride of the preview [samples].
    warnings : tuple of str
        What reading the log's rows said, each once, in order.
    """

    events: EngagementEvents
    impacts: ImpactResult
    preview_time: np.ndarray
    preview_force: np.ndarray
    preview_stride: int
    warnings: tuple[str, ...] = ()


def preview_stride(n_rows: int, preview_samples: int | None) -> int:
    """The smallest stride keeping at most `preview_samples` of `n_rows` samples (only the
    first without a number).

    >>> preview_stride(450_000, 200_000), preview_stride(200_000, 200_000)
    (3, 1)
    """
    return max(1, n_rows if preview_samples is None else math.ceil(n_rows / preview_samples))


def _setup(source: LogSource, *, z: int, omega: float, natural_frequency: float | None,
           impact_angle: float | None, use_angle: bool, preview_samples: int | None,
           clip_level: float | None, file: str | Path | None) -> EngagementSetup:
    """The set-up of a log from its head and its last sample's time."""
    n = source.n_rows
    last = source.read(n - 1, n)[0] if n >= 3 else None
    if last is None or "time" not in last:
        sampling(source.read(0, n)[0], file)  # raises the error that says what is missing
    end_time = float(last["time"].iloc[0])
    start_time = float(source.read(0, 1)[0]["time"].iloc[0])
    step = (end_time - start_time) / (n - 1)
    head_rows = setup_samples(1.0 / step, z, omega) if step > 0 else 3
    head = source.read(0, min(n, head_rows))[0]
    return engagement_setup(head, n_samples=n, end_time=end_time, z=z, omega=omega,
                            natural_frequency=natural_frequency, impact_angle=impact_angle,
                            use_angle=use_angle,
                            preview_stride=preview_stride(n, preview_samples),
                            clip_level=clip_level,
                            file=None if file is None else str(file))


@dataclass(frozen=True)
class LogJob:
    """A log set up for analysis and cut into chunks: what every step needs.

    Made by :func:`start_log`; picklable when its source is (a
    :class:`TableSource`, a :class:`~pipeline.ingest.LogReader`), so that each
    step can be a task that reads its own rows.

    Attributes
    ----------
    source : LogSource
        The log.
    setup : EngagementSetup
        Everything decided once from the log's head and length.
    chunks : tuple of Chunk
        The chunks, in order (one for a log analysed whole).
    period_tolerance : float
        As in :func:`analyse_log`.
    ringing : Ringing or None
        The ringing when known; None: fitted on the log.
    warn_speed : bool
        Give the :class:`~pipeline.condition.engagement.SpeedMismatchWarning`
        (False: its message is kept in the events' messages only).
    file : str or None
        The log's file, named in errors and warnings.
    """

    source: LogSource
    setup: EngagementSetup
    chunks: tuple[Chunk, ...]
    period_tolerance: float = PERIOD_TOLERANCE
    ringing: Ringing | None = None
    warn_speed: bool = True
    file: str | None = None


@dataclass(frozen=True)
class Detection:
    """The merged scans of a log: its seatings, the summary of its samples, and what
    reading its chunks said (each once, in order)."""

    events: EngagementEvents
    samples: LogSamples
    warnings: tuple[str, ...]


@dataclass(frozen=True)
class Extraction:
    """Where each event's window lies (the plan), and the run's ringing with its
    relative standard errors."""

    plan: ExtractionPlan
    ringing: Ringing
    relative_errors: dict[str, float]


def start_log(
    source: LogSource,
    *,
    z: int,
    omega: float,
    chunk_samples: int | None = None,
    overlap_samples: int | None = None,
    natural_frequency: float | None = None,
    impact_angle: float | None = None,
    use_angle: bool = True,
    period_tolerance: float = PERIOD_TOLERANCE,
    ringing: Ringing | None = None,
    clip_level: float | None = None,
    preview_samples: int | None = None,
    warn_speed: bool = True,
    file: str | Path | None = None,
) -> LogJob:
    """Set a log up from its head and cut it into chunks: the first step of :func:`analyse_log`.

    Parameters
    ----------
    source : LogSource
        The log (:class:`TableSource`, or :func:`pipeline.ingest.open_log` of a file).
    z, omega, natural_frequency, impact_angle, use_angle
        Teeth [-], stated speed [1/s], expected natural frequency [rad/s], wheel
        angle at impact 1 [rad], whether to use the angle channel: as in
        :func:`~pipeline.condition.scan.engagement_setup`.
    chunk_samples : int, optional
        Samples of each chunk's own span; by default the log is one chunk.
    overlap_samples : int, optional
        Samples read on each side of a chunk; default and minimum
        :func:`~pipeline.condition.scan.required_overlap`.
    period_tolerance : float, optional
        Relative disagreement between measured and stated seating period that
        gives a :class:`~pipeline.condition.engagement.SpeedMismatchWarning`.
    ringing : Ringing, optional
        Natural frequency and damping of the branch; by default fitted on up
        to 64 events of the log.
    clip_level : float, optional
        Upper saturation level of the force channel [N]; clipping is also
        detected from flat tops and bottoms.
    preview_samples : int, optional
        Keep about this many evenly spaced samples of the log as its preview
        (by default only the first).
    warn_speed : bool, optional
        Give the speed-mismatch warning (default); False keeps its message in
        ``events.messages`` only.
    file : str or Path, optional
        The log's file, named in errors and warnings.

    Returns
    -------
    LogJob

    Raises
    ------
    ValueError
        When `chunk_samples` is smaller than the overlap, or `overlap_samples`
        below the minimum.
    SignalError
        When the log is not uniformly sampled or holds no force data.
    """
    setup = _setup(source, z=z, omega=omega, natural_frequency=natural_frequency,
                   impact_angle=impact_angle, use_angle=use_angle,
                   preview_samples=preview_samples, clip_level=clip_level, file=file)
    return LogJob(source, setup, tuple(plan_chunks(setup, chunk_samples, overlap_samples)),
                  period_tolerance, ringing, warn_speed, None if file is None else str(file))


def scan_step(job: LogJob, chunk: Chunk) -> tuple[ChunkScan, list[str]]:
    """Read one chunk and scan it; with the warnings reading it gave (a task per chunk)."""
    data, warnings = job.source.read(chunk.data_start, chunk.data_stop)
    return scan_chunk(data, chunk, job.setup), warnings


def detect_step(job: LogJob, scanned: list[tuple[ChunkScan, list[str]]]) -> Detection:
    """Merge the scans of every chunk, in order (:func:`scan_step`), into the seatings."""
    scans = [scan for scan, _ in scanned]
    said = tuple(dict.fromkeys(text for _, texts in scanned for text in texts))
    with warnings.catch_warnings():
        if not job.warn_speed:
            warnings.simplefilter("ignore", SpeedMismatchWarning)  # kept in events.messages
        events = merge_scans(scans, job.setup, job.period_tolerance)
    return Detection(events, merge_summaries([scan.samples for scan in scans],
                                             job.setup.clip_level), said)


def ringing_step(job: LogJob, detection: Detection) -> Extraction:
    """Plan the extraction and fit the ringing on its events' windows (read here)."""
    return _extraction(job.source, detection.events, detection.samples, job.ringing, job.file)


def fit_step(job: LogJob, extraction: Extraction, chunk: Chunk) -> EventFits:
    """Read one chunk's force and fit its events (a task per chunk)."""
    return _fit(job.source, extraction, chunk)


def _extraction(source: LogSource, events: EngagementEvents, samples: LogSamples,
                ringing: Ringing | None, file: str | Path | None) -> Extraction:
    plan = plan_extraction(events, samples, file)
    windows = [source.read(start, start + plan.span)[0]["force"].to_numpy(dtype=float)
               for start in plan.reach_start[plan.ringing_events]]
    return Extraction(plan, *fit_ringing(windows, plan, ringing))


def _fit(source: LogSource, extraction: Extraction, chunk: Chunk) -> EventFits:
    data = source.read(chunk.data_start, chunk.data_stop)[0]
    return fit_chunk(data["force"].to_numpy(dtype=float), chunk.data_start, chunk.start,
                     chunk.stop, extraction.plan, extraction.ringing)


def finish_step(job: LogJob, detection: Detection, extraction: Extraction,
                fits: list[EventFits]) -> LogAnalysis:
    """Merge every chunk's fits, in order, into the log's analysis."""
    impacts = impact_result(extraction.plan, fits, extraction.ringing,
                            extraction.relative_errors)
    time, force = detection.samples.preview
    return LogAnalysis(detection.events, impacts, time, force, job.setup.preview_stride,
                       detection.warnings)


def analyse_job(job: LogJob, client: Client | None = None) -> LogAnalysis:
    """Every step of :func:`analyse_log` after the set-up, here or on `client` (waiting)."""
    if client is not None:
        return submit_analysis(job, client).result()
    detection = detect_step(job, [scan_step(job, chunk) for chunk in job.chunks])
    extraction = ringing_step(job, detection)
    return finish_step(job, detection, extraction,
                       [fit_step(job, extraction, chunk) for chunk in job.chunks])


def submit_analysis(job: LogJob, client: Client, priority: int = 0) -> Future:
    """Submit every step of :func:`analyse_job` to `client` as tasks, without waiting.

    The scans and the fits are a task per chunk, the merges and the ringing fit a
    task each, all of them at `priority` (dask runs higher priorities first).

    Returns
    -------
    distributed.Future
        Of the :class:`LogAnalysis`.
    """
    submit = partial(submit_task, client, priority=priority)
    shared = client.scatter(job, hash=False)
    detection = submit(detect_step, shared, [submit(scan_step, shared, chunk)
                                             for chunk in job.chunks])
    extraction = submit(ringing_step, shared, detection)
    fits = [submit(fit_step, shared, extraction, chunk) for chunk in job.chunks]
    return submit(finish_step, shared, detection, extraction, fits)


def analyse_log(source: LogSource, *, client: Client | None = None, **options: Any
                ) -> LogAnalysis:
    """Detect the seatings of an engagement log and extract N_u1, N_u2 of every one.

    Parameters
    ----------
    source : LogSource
        The log (:class:`TableSource`, or :func:`pipeline.ingest.open_log` of a file).
    client : distributed.Client, optional
        Run the steps after the set-up as tasks on this dask cluster
        (:func:`submit_analysis`), a task per chunk for the scans and the fits.
    **options
        ``z`` and ``omega`` (required) and the options of :func:`start_log`.

    Returns
    -------
    LogAnalysis

    Raises
    ------
    ValueError
        For chunks or overlaps :func:`start_log` refuses.
    SignalError
        When the log is not uniformly sampled, holds no force data, fewer than
        five seating periods, or no seating.
    FitError
        When no event can be fitted.

    Warns
    -----
    SpeedMismatchWarning
        When the measured seating period differs from ``2 pi / (z omega)`` by
        more than `period_tolerance` (unless `warn_speed` is False).

    References
    ----------
    Paper 000 (``docs/models/paper-000-wheel-impact.md``): the seating period
    of eq. (9), tau = pi / (z omega); v_u2 > v_u1 from eqs. (1)-(2); N_u of
    eq. (16), whose measured counterpart is the strike amplitude.
    """
    return analyse_job(start_log(source, **options), client)


def detect_events(
    table: pd.DataFrame,
    *,
    z: int,
    omega: float,
    natural_frequency: float | None = None,
    impact_angle: float | None = None,
    use_angle: bool = True,
    period_tolerance: float = PERIOD_TOLERANCE,
    file: str | Path | None = None,
) -> EngagementEvents:
    """Locate the two strikes of every seating in an engagement log held as a table.

    The detection half of :func:`analyse_log` on a table in memory, one chunk.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table (:mod:`pipeline.ingest.table`): ``time`` [s], ``force``
        (branch tension) [N], optional ``angle`` [rad].
    z, omega, natural_frequency, impact_angle, use_angle, period_tolerance, file
        As in :func:`analyse_log`.

    Returns
    -------
    EngagementEvents

    Raises
    ------
    SignalError
        As :func:`analyse_log`.

    Warns
    -----
    SpeedMismatchWarning
        As :func:`analyse_log`.
    """
    job = start_log(TableSource(table), z=z, omega=omega, natural_frequency=natural_frequency,
                    impact_angle=impact_angle, use_angle=use_angle,
                    period_tolerance=period_tolerance, file=file)
    return detect_step(job, [scan_step(job, chunk) for chunk in job.chunks]).events


def extract_impacts(
    table: pd.DataFrame,
    events: EngagementEvents,
    *,
    ringing: Ringing | None = None,
    clip_level: float | None = None,
    file: str | Path | None = None,
) -> ImpactResult:
    """Impact amplitudes N_u1, N_u2 of the given seatings of a log held as a table.

    The extraction half of :func:`analyse_log` on a table in memory, one chunk.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table with ``time`` [s] and ``force`` (branch tension) [N],
        sampled as in `events`.
    events : EngagementEvents
        Seatings, e.g. from :func:`detect_events`.
    ringing, clip_level, file
        As in :func:`analyse_log`.

    Returns
    -------
    ImpactResult

    Raises
    ------
    FitError
        When no event can be fitted.
    """
    n = len(table)
    summary = summarise_samples(table["time"].to_numpy(dtype=float),
                                table["force"].to_numpy(dtype=float), 0, n_samples=n,
                                preview_stride=max(1, n), clip_level=clip_level)
    source = TableSource(table)
    extraction = _extraction(source, events, merge_summaries([summary], clip_level), ringing,
                             file)
    fits = _fit(source, extraction, Chunk(0, n, 0, n))
    return impact_result(extraction.plan, [fits], extraction.ringing, extraction.relative_errors)
