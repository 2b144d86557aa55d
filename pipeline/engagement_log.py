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
every run-level choice is made once. With a dask ``client`` the per-chunk
steps are tasks that read their own rows.

:func:`detect_events` and :func:`extract_impacts` are the two halves on a
table in memory, for notebooks and tests.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

import numpy as np
import pandas as pd

from pipeline.condition.engagement import PERIOD_TOLERANCE, EngagementEvents, sampling
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
    ImpactResult,
    Ringing,
    fit_chunk,
    fit_ringing,
    impact_result,
    plan_extraction,
)
from pipeline.tasks import map_tasks

if TYPE_CHECKING:
    from distributed import Client


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


def _scan(source: LogSource, setup: EngagementSetup, chunk: Chunk
          ) -> tuple[ChunkScan, list[str]]:
    """Read one chunk and scan it (a task)."""
    data, warnings = source.read(chunk.data_start, chunk.data_stop)
    return scan_chunk(data, chunk, setup), warnings


def _fit(source: LogSource, plan, ringing: Ringing, chunk: Chunk) -> EventFits:
    """Read one chunk's force and fit its events (a task)."""
    data = source.read(chunk.data_start, chunk.data_stop)[0]
    return fit_chunk(data["force"].to_numpy(dtype=float), chunk.data_start, chunk.start,
                     chunk.stop, plan, ringing)


def _detect(source: LogSource, setup: EngagementSetup, chunks: list[Chunk],
            period_tolerance: float, client: Client | None
            ) -> tuple[EngagementEvents, LogSamples, list[str]]:
    """Scan every chunk and merge: the seatings, the samples' summary, the read warnings."""
    scanned = map_tasks(partial(_scan, source, setup), chunks, client)
    scans = [scan for scan, _ in scanned]
    warnings = list(dict.fromkeys(text for _, said in scanned for text in said))
    events = merge_scans(scans, setup, period_tolerance)
    return events, merge_summaries([scan.samples for scan in scans], setup.clip_level), warnings


def _extract(source: LogSource, chunks: list[Chunk], events: EngagementEvents,
             samples: LogSamples, ringing: Ringing | None, file: str | Path | None,
             client: Client | None) -> ImpactResult:
    """Plan, fit the ringing on its events' windows, fit every chunk, merge."""
    plan = plan_extraction(events, samples, file)
    windows = [source.read(start, start + plan.span)[0]["force"].to_numpy(dtype=float)
               for start in plan.reach_start[plan.ringing_events]]
    ringing, relative_errors = fit_ringing(windows, plan, ringing)
    fits = map_tasks(partial(_fit, source, plan, ringing), chunks, client)
    return impact_result(plan, fits, ringing, relative_errors)


def analyse_log(
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
    file: str | Path | None = None,
    client: Client | None = None,
) -> LogAnalysis:
    """Detect the seatings of an engagement log and extract N_u1, N_u2 of every one.

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
    file : str or Path, optional
        The log's file, named in errors and warnings.
    client : distributed.Client, optional
        Run the per-chunk steps as tasks on this dask cluster.

    Returns
    -------
    LogAnalysis

    Raises
    ------
    ValueError
        When `chunk_samples` is smaller than the overlap, or `overlap_samples`
        below the minimum.
    SignalError
        When the log is not uniformly sampled, holds no force data, fewer than
        five seating periods, or no seating.
    FitError
        When no event can be fitted.

    Warns
    -----
    SpeedMismatchWarning
        When the measured seating period differs from ``2 pi / (z omega)`` by
        more than `period_tolerance`.

    References
    ----------
    Paper 000 (``docs/models/paper-000-wheel-impact.md``): the seating period
    of eq. (9), tau = pi / (z omega); v_u2 > v_u1 from eqs. (1)-(2); N_u of
    eq. (16), whose measured counterpart is the strike amplitude.
    """
    setup = _setup(source, z=z, omega=omega, natural_frequency=natural_frequency,
                   impact_angle=impact_angle, use_angle=use_angle,
                   preview_samples=preview_samples, clip_level=clip_level, file=file)
    chunks = plan_chunks(setup, chunk_samples, overlap_samples)
    events, samples, warnings = _detect(source, setup, chunks, period_tolerance, client)
    impacts = _extract(source, chunks, events, samples, ringing, file, client)
    time, force = samples.preview
    return LogAnalysis(events, impacts, time, force, setup.preview_stride, tuple(warnings))


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
    source = TableSource(table)
    setup = _setup(source, z=z, omega=omega, natural_frequency=natural_frequency,
                   impact_angle=impact_angle, use_angle=use_angle, preview_samples=None,
                   clip_level=None, file=file)
    return _detect(source, setup, plan_chunks(setup), period_tolerance, None)[0]


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
    return _extract(TableSource(table), [Chunk(0, n, 0, n)], events,
                    merge_summaries([summary], clip_level), ringing, file, None)
