"""The engagement pipeline: a log cut into chunks gives what the whole log gives (virtual bench).

Tolerance: N_u1, N_u2 per event (and every other fitted column) agree to
1e-6 relative. Both fit the same samples in the same windows with the same
ringing; they differ by rounding only (a chunk's sample times are counted from
its own first sample), which leaves about 1e-9 at most. A window one sample
off would change N_u by some 1e-3 at this noise, so 1e-6 tells a real
difference from rounding. Event times: within one sample (they agree to
about 1e-11 s).
"""

from __future__ import annotations

import math
import warnings
from itertools import pairwise

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.engagement import SpeedMismatchWarning
from pipeline.condition.scan import engagement_setup, plan_chunks, setup_samples
from pipeline.engagement_log import (
    TableSource,
    analyse_log,
    detect_events,
    extract_impacts,
    preview_stride,
)
from pipeline.simulate.engagement import EngagementSettings, simulate_engagement

RELATIVE = 1e-6
RATE = 10e3
#: 30 s at 10 kHz: 300 001 samples, 763 seatings.
BASE = {"duration": 30.0, "sample_rate": RATE, "snr": 10.0, "amplitude_scatter": 0.05}
FITTED = ["N_u1", "N_u2", "N_u1_stderr", "N_u2_stderr", "peak1", "peak2", "baseline",
          "residual_rms"]


def simulated(seed: int = 7, **settings) -> pd.DataFrame:
    return simulate_engagement(EngagementSettings(**{**BASE, **settings}), seed=seed)[0]


def whole(table: pd.DataFrame, **kwargs):
    analysis = analyse_log(TableSource(table), z=kwargs.pop("z", 8),
                           omega=kwargs.pop("omega", 20.0), **kwargs)
    return analysis.events, analysis.impacts


def assert_same(table, chunk_samples, reference, **kwargs):
    events, result = reference
    chunked_events, chunked = whole(table, chunk_samples=chunk_samples, **kwargs)
    a, b = result.events, chunked.events
    assert len(b) == len(a) == events.count == chunked_events.count
    assert np.all(np.abs(b["event_time"] - a["event_time"]) < 1 / RATE)
    assert np.all(np.abs(b["impact2_time"] - a["impact2_time"]) < 1 / RATE)
    assert list(b["status"]) == list(a["status"])
    assert chunked.excluded == result.excluded
    for name in FITTED:  # NaN where not fitted (truncated, gap, clipped)
        assert np.allclose(b[name], a[name], rtol=RELATIVE, atol=0, equal_nan=True)
    assert chunked.ringing.omega_n == pytest.approx(result.ringing.omega_n, rel=RELATIVE)
    assert chunked.ringing.zeta == pytest.approx(result.ringing.zeta, rel=RELATIVE)
    for name, stats in result.statistics.items():
        other = chunked.statistics[name]
        assert other.count == stats.count
        for key in ("median", "iqr", "mad", "stderr"):
            assert getattr(other, key) == pytest.approx(getattr(stats, key), rel=RELATIVE)
    assert chunked.clip_levels == result.clip_levels
    assert chunked_events.seating_period == pytest.approx(events.seating_period, rel=1e-12)
    assert chunked_events.messages == events.messages
    return chunked_events, chunked


def setup_of(table):
    head = table.iloc[: setup_samples(RATE, 8, 20.0)]
    return engagement_setup(head, n_samples=len(table),
                            end_time=float(table["time"].iloc[-1]), z=8, omega=20.0)


def borders_in_strikes(table, chunk_samples, events) -> int:
    """Chunk borders falling inside a seating's strikes (impact 1 to a tau after impact 2)."""
    borders = table["time"].to_numpy()[np.arange(chunk_samples, len(table), chunk_samples)]
    inside = [np.any((events.impact1_time <= border)
                     & (border < events.impact2_time + events.tau)) for border in borders]
    return int(np.sum(inside))


@pytest.fixture(scope="module")
def log():
    table = simulated()
    return table, whole(table)


@pytest.mark.parametrize("chunk_samples", [37_813, 100_003, 150_001, 300_001 - 5, 300_001])
def test_chunked_equals_whole_log(log, chunk_samples):
    table, reference = log
    if chunk_samples < len(table) - 5:  # the borders do cut strikes
        assert borders_in_strikes(table, chunk_samples, reference[0]) >= 1
    assert_same(table, chunk_samples, reference)


@pytest.mark.parametrize("impact", [1, 2])
@pytest.mark.parametrize("shift", [-1, 0, 1])
def test_border_at_an_impact_onset(log, impact, shift):
    table, reference = log
    events = reference[0]
    onsets = events.impact1_time if impact == 1 else events.impact2_time
    sample = np.ceil((onsets - events.start_time) * events.sample_rate - 1e-9).astype(int)
    # the first onset past 20 000 samples: every border of that chunk size sits on an onset
    chunk_samples = int(sample[np.searchsorted(sample, 20_000)]) + shift
    assert_same(table, chunk_samples, reference)


def test_chunked_without_angle_channel():
    table = simulated(with_angle=False)
    assert_same(table, 41_111, whole(table))


def test_chunked_clipped_log_and_missing_samples():
    table = simulated(seed=3, clip_level=23.6e3, amplitude_scatter=0.1)
    table.loc[100_000:100_400, "force"] = np.nan
    table.loc[200_123:200_130, "force"] = np.nan
    reference = whole(table)
    assert reference[1].excluded["clipped"] > 10 and reference[1].excluded["gap"] >= 2
    for chunk_samples in (37_813, 100_200):
        assert_same(table, chunk_samples, reference)


def test_chunked_other_wheel_and_given_angle():
    settings = {"z": 6, "omega": 35.0, "sample_rate": RATE, "jitter": 5e-4,
                "damping_ratio": 0.06, "duration": 20.0}
    table, truth = simulate_engagement(EngagementSettings(**{**BASE, **settings}), seed=2)
    angle = truth["impact_angle"]
    reference = whole(table, z=6, omega=35.0, impact_angle=angle)
    assert_same(table, 27_777, reference, z=6, omega=35.0, impact_angle=angle)


def test_speed_mismatch_is_reported_alike(log):
    table, _ = log
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SpeedMismatchWarning)
        reference = whole(table, omega=21.0)
    with pytest.warns(SpeedMismatchWarning):
        events, _ = assert_same(table, 50_000, reference, omega=21.0)
    assert len(events.messages) == 1


def test_chunks_smaller_than_the_overlap_are_refused(log):
    table, _ = log
    setup = setup_of(table)
    # three seating periods of 39 ms and two ringing periods of 6.8 ms at 10 kHz, and more
    assert setup.overlap >= math.ceil((3 * 0.0393 + 2 * 0.0068) * RATE)
    with pytest.raises(ValueError, match="smaller than the overlap"):
        plan_chunks(setup, setup.overlap - 1)
    with pytest.raises(ValueError, match="smaller than the overlap"):
        whole(table, chunk_samples=1000)
    with pytest.raises(ValueError, match="below the"):
        whole(table, chunk_samples=50_000, overlap_samples=setup.overlap // 2)


def test_chunks_tile_the_log_and_read_aligned_overlaps(log):
    table, _ = log
    setup = setup_of(table)
    chunks = plan_chunks(setup, 37_813)
    assert chunks[0].start == 0 and chunks[-1].stop == len(table)
    assert all(left.stop == right.start for left, right in pairwise(chunks))
    assert all(chunk.data_start % setup.stride == 0 for chunk in chunks)
    assert all(chunk.data_start <= chunk.start - setup.overlap or chunk.data_start == 0
               for chunk in chunks)
    assert all(chunk.data_stop == min(len(table), chunk.stop + setup.overlap)
               for chunk in chunks)


def test_the_two_halves_on_a_table_give_the_whole_pipeline(log):
    table, (events, result) = log
    detected = detect_events(table, z=8, omega=20.0)
    extracted = extract_impacts(table, detected)
    np.testing.assert_array_equal(detected.impact1_time, events.impact1_time)
    pd.testing.assert_frame_equal(extracted.events, result.events)


class CountingSource(TableSource):
    """A table that records the rows of every read."""

    def __init__(self, table):
        super().__init__(table)
        object.__setattr__(self, "reads", [])

    def read(self, start, stop):
        self.reads.append((start, stop))
        return super().read(start, stop)


def test_no_read_is_longer_than_a_chunk_and_its_overlaps(log):
    table, reference = log
    source = CountingSource(table)
    chunk_samples = 40_000
    analysis = analyse_log(source, z=8, omega=20.0, chunk_samples=chunk_samples)
    setup = setup_of(table)
    head = setup_samples(RATE, 8, 20.0)  # the set-up reads the head once, whatever the log
    assert source.reads.count((0, head)) == 1
    longest = max(stop - start for start, stop in source.reads if (start, stop) != (0, head))
    assert longest <= chunk_samples + 2 * setup.overlap + setup.stride
    assert analysis.events.count == reference[0].count


@pytest.mark.parametrize("chunk_samples", [None, 37_813])
def test_the_preview_is_every_stride_th_sample(log, chunk_samples):
    table, _ = log
    analysis = analyse_log(TableSource(table), z=8, omega=20.0, chunk_samples=chunk_samples,
                           preview_samples=10_000)
    stride = math.ceil(len(table) / 10_000)
    assert analysis.preview_stride == stride
    np.testing.assert_array_equal(analysis.preview_time, table["time"].to_numpy()[::stride])
    np.testing.assert_array_equal(analysis.preview_force, table["force"].to_numpy()[::stride])


def test_chunks_as_dask_tasks_give_the_same_result(log):
    distributed = pytest.importorskip("distributed")
    table, reference = log
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=2,
                            dashboard_address=":0") as client:
        analysis = analyse_log(TableSource(table), z=8, omega=20.0, chunk_samples=100_003,
                               client=client)
    in_process = whole(table, chunk_samples=100_003)[1]
    pd.testing.assert_frame_equal(analysis.impacts.events, in_process.events)
    assert analysis.events.count == reference[0].count


@pytest.mark.parametrize(("rows", "stride"), [(200_000, 1), (200_001, 2), (1_000_007, 6)])
def test_the_preview_keeps_at_most_the_samples_asked_for_with_the_smallest_stride(rows, stride):
    assert preview_stride(rows, 200_000) == stride
    assert -(-rows // stride) <= 200_000  # samples kept
    assert stride == 1 or -(-rows // (stride - 1)) > 200_000  # a smaller stride keeps too many

