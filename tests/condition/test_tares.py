"""A channel zeroed during the test: found, and joined again."""

import numpy as np
import pytest

from pipeline.condition.tares import ZERO_LANDING, Tare, find_tares, join_tares

#: An extensometer's noise and resolution [m], a 13x50 chain's stiffness over a 0.9 m
#: gauge [m/N], as in the removal tests.
NOISE, RESOLUTION, COMPLIANCE = 2e-6, 1e-5, 0.9 / 1.1e7


#: A hold at 5 kN for 300 samples, then a loading to 34 kN, with the force's noise [N].
FORCE = (np.concatenate([np.full(300, 5e3), np.linspace(5e3, 34e3, 3000)])
         + np.random.default_rng(0).normal(0.0, 50.0, 3300))


def _zeroed_at_preload(seed: int, reading_at_zero: float) -> tuple[np.ndarray, np.ndarray]:
    """The gauge of :data:`FORCE` reading `reading_at_zero` [m] until it is zeroed at sample
    300, quantised: the record, and the same gauge never zeroed."""
    rng = np.random.default_rng(seed)
    moved = (FORCE - 5e3) * COMPLIANCE + rng.normal(0.0, NOISE, FORCE.size)
    zeroed = np.where(np.arange(FORCE.size) < 300, reading_at_zero, 0.0) + moved
    return (np.round(zeroed / RESOLUTION) * RESOLUTION,
            np.round((moved + reading_at_zero) / RESOLUTION) * RESOLUTION)


@pytest.mark.parametrize("reading_at_zero", [0.8e-3, -2.5e-3, 41e-3])
def test_a_zeroing_at_the_preload_is_found_and_joined(reading_at_zero):
    for seed in range(20):
        record, never_zeroed = _zeroed_at_preload(seed, reading_at_zero)
        joined, tares = join_tares(record, FORCE)
        assert [tare.position for tare in tares] == [300]
        assert tares[0].step == pytest.approx(reading_at_zero, abs=2 * RESOLUTION)
        # the joined channel differs from the one never zeroed by a constant only
        np.testing.assert_allclose(np.diff(joined), np.diff(never_zeroed), atol=2 * RESOLUTION)
        np.testing.assert_allclose(joined[300:], record[300:])


def test_a_zeroing_as_the_loading_begins_is_found():
    # a real MTS TestSuite export [mm], [kN]: the zero is taken as the force begins to rise
    # and the specimen has moved a little by the next sample, so the reading lands near
    # zero, not on it
    hold = np.array([-2.528, -2.500, -2.531, -2.475, -2.412])
    loading = -0.13 - 0.3 * np.arange(120)
    force = np.concatenate([[-40.41, -40.45, -40.39, -40.46, -40.86],
                            -41.59 - 0.76 * np.arange(120)])
    record = np.concatenate([hold, loading])
    assert abs(loading[0]) <= ZERO_LANDING * abs(loading[0] - hold[-1])
    assert find_tares(record, force) == [Tare(5, pytest.approx(hold[-1] - loading[0]))]


def test_a_gauge_dropping_to_zero_while_the_force_rises_is_no_zeroing():
    # unplugged halfway up the loading: a removal, not a zeroing
    record, _ = _zeroed_at_preload(0, 0.0)
    record[1800:] = 0.0
    assert find_tares(record, FORCE) == []


@pytest.mark.parametrize("record", [
    np.linspace(0.0, 1.0, 200),  # a ramp from zero: no step
    np.concatenate([np.zeros(100), np.full(100, 0.5)]),  # a step away from zero
    np.concatenate([np.full(100, 0.5), np.linspace(0.05, 0.5, 100)]),  # lands short of zero
    np.concatenate([np.full(50, 1.0), np.linspace(1.0, 0.0, 20)]),  # a fall, not one step
    np.array([1.0, 1.0, 0.0, 0.0]),  # too few steps before to tell
])
def test_steps_that_are_no_zeroing(record):
    assert find_tares(record, np.full(record.size, 1e3)) == []


def test_a_reading_landing_near_zero_after_the_maximum_is_no_zeroing():
    # a real displacement-controlled MTS test in its slow fall after the maximum [kN], [mm]:
    # the mean of three transducers jumps with one of them and lands near zero by chance
    # (0.1 kN a sample: over a fiftieth of the record, less than 1 % of the force's range)
    force = np.concatenate([np.linspace(0.0, 405.0, 400), np.linspace(405.0, 300.0, 1000)])
    mean = np.concatenate([np.linspace(0.2, -0.03, 1300), np.linspace(0.002, 0.01, 100)])
    assert find_tares(mean, force) == []
