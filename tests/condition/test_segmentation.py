"""Cycle and branch segmentation from the force alone."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from pipeline.condition.segmentation import BRANCHES, SMOOTHING, count_cycles, segment_cycles
from pipeline.errors import SignalError

#: A Bluehill export of a three-cycle compression test (real data, see the realdata fixture).
BLUEHILL = "yadbor__bluer__Specimen_RawData_6.csv"


def cyclic_force(cycles=3, low=10e3, high=100e3, ramp=200, dwell=0, hold=30, noise=0.0,
                 seed=0) -> np.ndarray:
    """Preload hold, `cycles` triangles (or trapezoids with `dwell` samples at the top), hold."""
    up = np.linspace(low, high, ramp, endpoint=False)
    cycle = np.concatenate([up, np.full(dwell, high), high - (up - low)])
    force = np.concatenate([np.full(hold, low), np.tile(cycle, cycles), np.full(hold, low)])
    return force + np.random.default_rng(seed).normal(0.0, noise, force.size)


@pytest.mark.parametrize("dwell", [0, 80])
@pytest.mark.parametrize("noise", [0.0, 300.0, 1500.0])
def test_finds_exactly_n_cycles_with_noise_and_dwell(dwell, noise):
    force = cyclic_force(cycles=3, dwell=dwell, noise=noise, seed=int(noise))
    assert count_cycles(force) == 3
    segmentation = segment_cycles(force, preload=10e3, n_cycles=3)
    assert segmentation.n_cycles == 3
    assert segmentation.sign == 1
    assert segmentation.complete.all()
    assert set(segmentation.branch) <= set(BRANCHES)
    for number, (load_start, load_end, unload_start, unload_end) in enumerate(
        segmentation.turns, start=1
    ):
        assert load_start < load_end <= unload_start < unload_end
        assert set(segmentation.branch[load_start + 1 : load_end]) == {"loading"}
        assert set(segmentation.branch[unload_start + 1 : unload_end]) == {"unloading"}
        assert set(segmentation.cycle[load_start:unload_end]) == {number}
        if dwell:  # the dwell at the peak is a hold, not part of a branch
            assert unload_start - load_end >= dwell * 0.8
    assert segmentation.branch[0] == "preload" and segmentation.cycle[0] == 0


def test_turning_points_of_a_clean_triangle_wave():
    force = cyclic_force(cycles=2, ramp=100, hold=20)
    segmentation = segment_cycles(force)
    # hold 0..20, peak of cycle 1 at 20 + 100, its valley at 20 + 200, and so on; the
    # corners are located on the force smoothed over SMOOTHING samples: within 2 samples
    corners = [[20, 120, 120, 220], [220, 320, 320, 420]]
    assert np.max(np.abs(segmentation.turns - np.array(corners))) <= SMOOTHING // 2
    first, *_, last = segmentation.valleys
    assert first[0] == 0 and abs(first[1] - 20) <= 2
    assert abs(last[0] - 420) <= 2 and last[1] == force.size - 1


def test_compression_negative_records_are_oriented():
    force = -cyclic_force(cycles=4, noise=200.0)
    assert count_cycles(force) == 4
    segmentation = segment_cycles(force, preload=10e3, n_cycles=4)
    assert segmentation.sign == -1
    load_start, load_end = segmentation.turns[0, :2]
    assert force[load_end] < force[load_start]  # loading makes the force more negative


def test_unfinished_last_cycle_is_flagged():
    force = cyclic_force(cycles=2, hold=10)[:-150]
    segmentation = segment_cycles(force)
    assert segmentation.n_cycles == 2
    assert segmentation.complete.tolist() == [True, False]


@pytest.mark.parametrize("share", [0.32, 0.625])
def test_loadings_to_a_lower_force_before_the_pull_to_break_are_cycles(share):
    # a real MTS 793 record: three loadings to 137 kN (32 % of the maximum), each unloaded
    # to 1 kN, then a pull to 426 kN; read as one pull, and refused with cycles = 4 as if
    # the test were not all logged. A chain's proof load is some 62.5 % of its break.
    earlier = cyclic_force(cycles=3, low=1e3, high=share * 426e3, hold=20, noise=200.0)
    pull = np.linspace(1e3, 426e3, 400) + np.random.default_rng(1).normal(0.0, 200.0, 400)
    force = np.concatenate([earlier, pull])
    segmentation = segment_cycles(force, n_cycles=4)
    assert segmentation.n_cycles == count_cycles(force) == 4
    peaks = [force[start : stop + 1].max() for start, _, _, stop in segmentation.turns]
    np.testing.assert_allclose(peaks, [share * 426e3] * 3 + [426e3], rtol=0.01)
    # a ramp to the preload and a hold there, before a pull, is no loading
    preload = np.concatenate([np.linspace(0.0, 0.05 * 426e3, 50), np.full(100, 0.05 * 426e3),
                              np.linspace(0.05 * 426e3, 426e3, 400)])
    assert count_cycles(preload) == 1


def test_ramp_from_zero_to_the_preload_stays_preload():
    force = np.concatenate([np.linspace(0.0, 10e3, 50), cyclic_force(cycles=2)])
    segmentation = segment_cycles(force, preload=10e3)
    assert set(segmentation.branch[:60]) == {"preload"}
    assert force[segmentation.turns[0, 0]] == pytest.approx(10e3)


def test_force_never_above_the_preload():
    with pytest.raises(SignalError, match="never rises above the preload") as error:
        segment_cycles(cyclic_force(high=9e3, low=1e3), preload=10e3)
    assert error.value.column == "force" and error.value.hint


def test_fewer_cycles_than_asked():
    with pytest.raises(SignalError, match="found 2 load cycle"):
        segment_cycles(cyclic_force(cycles=2, noise=100.0), n_cycles=3)


@pytest.mark.parametrize(
    "force",
    [np.full(500, 5e3), np.random.default_rng(1).normal(5e3, 10.0, 500), np.array([1.0, 2.0]),
     np.array([1.0, np.nan, 3.0, 4.0])],
)
def test_no_cycle_is_an_error(force):
    assert count_cycles(force) == 0 or np.isnan(force).any()
    with pytest.raises(SignalError):
        segment_cycles(force)


def test_a_force_flickering_between_two_counts_is_no_cycle():
    # a real force gauge logging whole counts of 2 gf at rest: 0, 2, 0, 2... The second
    # differences are mostly zero, so the noise estimate is zero and every flicker counted
    resting = np.array([2, 2, 0, 0, 2, 0, 2, 2, 2, 2, 0, 2, 2, 0, 0, 0, 2, 0, 0, 0, 2, 2, 2, 2,
                        2, 0] + [2] * 28 + [0, 0], dtype=float)
    assert count_cycles(resting) == 0
    pulls = np.tile(np.concatenate([np.arange(0, 12, 2.0), np.arange(12, 0, -2.0)]), 4)
    assert count_cycles(np.repeat(pulls, 10)) == 4  # the same counts over a real range


@settings(max_examples=60, deadline=None)
@given(arrays(np.float64, st.integers(0, 300),
              elements=st.one_of(st.floats(-1e6, 1e6), st.just(np.nan))))
def test_random_records_raise_only_signal_errors(force):
    assert count_cycles(force) >= 0
    try:
        segmentation = segment_cycles(force)
    except SignalError:
        return
    assert segmentation.cycle.shape == force.shape
    assert (segmentation.turns[:, 0] <= segmentation.turns[:, 3]).all()


@pytest.mark.realdata
def test_bluehill_export_has_three_compression_cycles(realdata):
    export = realdata / BLUEHILL
    lines = export.read_text(encoding="utf-8").splitlines()
    names = next(i for i, line in enumerate(lines) if line.startswith("Time,Extension,Load"))
    table = pd.read_csv(export, skiprows=[*range(names), names + 1])
    force = table["Load"].to_numpy(dtype=float)  # N, compression negative
    assert count_cycles(force) == 3
    segmentation = segment_cycles(force, n_cycles=3)
    assert segmentation.sign == -1
    # the machine's own counter agrees: each cycle starts where Total Cycle Count steps up
    counter = table["Total Cycle Count"].to_numpy()
    steps = np.flatnonzero(np.diff(counter)) + 1
    starts = segmentation.turns[1:, 0]
    assert np.all(np.abs(starts - steps) < 0.05 * force.size)
