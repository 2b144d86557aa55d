"""The virtual wear bench: its log is the curve and the noise its docstring states."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pipeline.simulate.wear import WearTruth, simulate_wear

HOUR = 3600.0
QUIET = {"noise": 0.0}


def true_elongation(truth: WearTruth, time: np.ndarray) -> np.ndarray:
    """delta_t0 + A (1 - exp(-tau / tau0)) + w tau, written out here [m]."""
    return (truth.initial_error + truth.run_in * (1 - np.exp(-time / truth.run_in_time))
            + truth.wear_rate * time)


def test_defaults_are_the_documented_test():
    truth = WearTruth()
    assert truth.pitch == 0.01905 and truth.pitches == 10
    assert truth.initial_error == pytest.approx(0.001 * 0.01905)
    assert truth.run_in == pytest.approx(0.03e-3) and truth.run_in_time == 10 * HOUR
    assert truth.wear_rate == pytest.approx(0.75e-6 / HOUR)
    assert truth.noise == 10e-6
    np.testing.assert_allclose(truth.reading_times(), np.arange(61) * 5 * HOUR)


def test_log_is_canonical_and_reproducible():
    truth = WearTruth()
    log = simulate_wear(truth, seed=3)
    assert list(log.columns) == ["time", "cycles", "length"]
    assert all(log.dtypes == np.float64)
    assert log.equals(simulate_wear(truth, seed=3))
    assert not log.equals(simulate_wear(truth, seed=4))


def test_noise_free_length_is_the_true_curve():
    truth = WearTruth(**QUIET)
    log = simulate_wear(truth, seed=0)
    time = log["time"].to_numpy()
    expected = truth.pitches * (truth.pitch + true_elongation(truth, time))
    np.testing.assert_allclose(log["length"], expected, rtol=1e-14)
    np.testing.assert_allclose(truth.elongation(time), true_elongation(truth, time), rtol=1e-14)
    np.testing.assert_allclose(log["cycles"], truth.cycle_rate * time)


def test_elongation_channel_is_the_length_less_its_nominal():
    truth = WearTruth(channel="elongation", load=5e3, speed=1.2)
    log = simulate_wear(truth, seed=5)
    length = simulate_wear(truth.with_(channel="length", load=None, speed=None), seed=5)
    assert list(log.columns) == ["time", "cycles", "elongation", "load", "speed"]
    nominal = truth.pitches * truth.pitch
    np.testing.assert_allclose(log["elongation"], length["length"] - nominal, atol=1e-15)
    assert (log["load"] == 5e3).all() and (log["speed"] == 1.2).all()


def test_noise_has_the_stated_standard_deviation():
    # 6001 readings: the sample standard deviation errs by 1/sqrt(2 n) = 0.9 % (1 sigma)
    truth = WearTruth(interval=0.05 * HOUR)
    log = simulate_wear(truth, seed=11)
    length = truth.pitches * (truth.pitch + true_elongation(truth, log["time"].to_numpy()))
    residual = log["length"] - length
    assert residual.size == 6001
    assert residual.std(ddof=0) == pytest.approx(truth.noise, rel=4 / math.sqrt(2 * 6001))
    assert abs(residual.mean()) < 4 * truth.noise / math.sqrt(6001)


def test_readings_stop_at_the_duration():
    truth = WearTruth(duration=12 * HOUR, interval=5 * HOUR)
    np.testing.assert_allclose(truth.reading_times(), [0.0, 5 * HOUR, 10 * HOUR])


def test_time_to_a_limit_without_run_in_is_a_ratio():
    truth = WearTruth(run_in=0.0)
    limit = 0.03 * truth.pitch
    assert truth.time_to(limit) == pytest.approx(
        (limit - truth.initial_error) / truth.wear_rate, rel=1e-12)


def test_time_to_a_limit_lies_on_the_true_curve():
    truth = WearTruth()
    limit = 0.03 * truth.pitch
    tau = truth.time_to(limit)
    assert true_elongation(truth, np.array(tau)) == pytest.approx(limit, rel=1e-12)
    # past the run-in, the line delta_t0 + A + w tau reaches the limit at the same time
    assert tau == pytest.approx((limit - truth.initial_error - truth.run_in) / truth.wear_rate,
                                rel=1e-12)


@pytest.mark.parametrize("limit", [0.0, 0.001 * 0.01905])
def test_time_to_a_limit_reached_at_the_start_raises(limit):
    with pytest.raises(ValueError, match="never reaches"):
        WearTruth().time_to(limit)


def test_time_to_a_limit_without_wear_raises():
    with pytest.raises(ValueError, match="never reaches"):
        WearTruth(wear_rate=0.0).time_to(0.03 * 0.01905)


@pytest.mark.parametrize("changes", [
    {"pitch": 0.0}, {"pitches": 0}, {"pitches": 10.0}, {"run_in": -1e-6},
    {"run_in_time": 0.0}, {"wear_rate": -1e-12}, {"noise": math.nan}, {"duration": -1.0},
    {"interval": 400 * HOUR}, {"cycle_rate": 0.0}, {"channel": "force"}, {"load": 0.0},
    {"speed": -1.0}, {"initial_error": math.inf},
])
def test_invalid_truth_raises(changes):
    with pytest.raises(ValueError):
        WearTruth(**changes)
