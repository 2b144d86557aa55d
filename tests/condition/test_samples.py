"""The summary of a log's samples: gaps, clipping, offset and preview, the same in any cut."""

from __future__ import annotations

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from pipeline.condition.samples import (
    clipping_levels,
    merge_summaries,
    runs_of,
    summarise_samples,
)


def test_a_chunk_summary_keeps_no_view_of_the_chunk():
    time, force = np.arange(1000.0), np.ones(1000)
    summary = summarise_samples(time, force, 0, n_samples=10**8, preview_stride=10)
    for kept in (summary.offset_sample, summary.preview_time, summary.preview_force):
        assert kept.base is None  # a view would hold the chunk's memory for the whole log


def test_pieces_merge_into_the_summary_of_the_whole_log():
    rng = np.random.default_rng(4)
    force = rng.normal(size=10_000)
    force[[100, 101, 102]] = force.max() + 1  # a flat top held three samples
    force[5000:5003] = np.nan
    time = np.arange(force.size) / 1e3
    whole = merge_summaries([summarise_samples(time, force, 0, n_samples=force.size,
                                               preview_stride=7)])
    cuts = [0, 101, 3333, 5001, 10_000]
    pieces = merge_summaries([
        summarise_samples(time[a:b], force[a:b], a, n_samples=force.size, preview_stride=7)
        for a, b in zip(cuts, cuts[1:], strict=False)])
    starts, width = np.arange(0, 9_900, 37), 50
    assert pieces.clip_levels == whole.clip_levels == (None, force[100])
    np.testing.assert_array_equal(pieces.clipped(starts, width), whole.clipped(starts, width))
    np.testing.assert_array_equal(pieces.missing(starts, width), whole.missing(starts, width))
    assert pieces.missing(np.array([4990]), 20)[0] and not pieces.missing(np.array([5003]), 9)[0]
    assert pieces.offset == whole.offset == np.median(force[np.isfinite(force)])
    np.testing.assert_array_equal(pieces.preview[1], force[::7])


def test_clipping_needs_a_flat_extreme():
    force = np.sin(np.linspace(0, 20, 2000))
    assert clipping_levels(force) == (None, None)
    assert clipping_levels(np.clip(force, -0.5, 0.9)) == (-0.5, 0.9)


def _runs_by_walking(flags: np.ndarray) -> tuple[list[int], list[int]]:
    """Runs of set flags, found sample by sample: the reference for runs_of."""
    starts, stops = [], []
    for index, flag in enumerate(flags):
        if flag and (index == 0 or not flags[index - 1]):
            starts.append(index)
        if flag and (index == flags.size - 1 or not flags[index + 1]):
            stops.append(index + 1)
    return starts, stops


@given(arrays(bool, st.integers(0, 60)), st.integers(0, 10**9))
def test_runs_are_the_stretches_of_set_flags(flags, origin):
    starts, stops = runs_of(flags, origin)
    expected_starts, expected_stops = _runs_by_walking(flags)
    assert starts.tolist() == [start + origin for start in expected_starts]
    assert stops.tolist() == [stop + origin for stop in expected_stops]
    assert starts.dtype == stops.dtype == np.int64
