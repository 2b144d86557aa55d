"""The virtual segment-load bench: its truth is what its docstring says it is.

The ratios are computed here from Paper 003's closed forms, eqs. (1)-(4)
(``docs/models/paper-003-tooth-segments.md``), written out with ``math``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from pipeline.simulate.segment_load import SegmentLoadTruth, load_shape, simulate_segment_load

QUIET = {"noise_chain": 0.0, "noise_segment": 0.0, "noise_side": 0.0}


def closed_form(t: SegmentLoadTruth) -> tuple[float, float]:
    """F_K / F and F_P / F of Paper 003, eqs. (1)-(4)."""
    k = t.r_outer - t.d / 2 * (1 - math.cos(math.pi / 2 - t.beta + t.eps_n))
    half = math.acos(t.s / (2 * k))
    return 1 / (2 * math.sin(half)), 1 / (2 * math.tan(half))


def plateau_mask(t: SegmentLoadTruth, time: np.ndarray) -> np.ndarray:
    """Samples where the link sits with the full load, from the docstring's timing."""
    lead = (t.seating_period - t.busy) / 2
    phase = np.mod(time, t.seating_period)
    return (phase >= lead + t.transition) & (phase <= lead + t.transition + t.plateau)


def test_ratios_are_paper_003_for_the_true_geometry():
    for t in (SegmentLoadTruth(), SegmentLoadTruth(beta=math.radians(80), s=45e-3),
              SegmentLoadTruth(eps_n=math.radians(6), s=70e-3)):
        k_ratio, p_ratio = closed_form(t)
        assert t.contact_force_ratio == pytest.approx(k_ratio, rel=1e-12)
        assert t.side_force_ratio == pytest.approx(p_ratio, rel=1e-12)
        assert t.friction_increase == pytest.approx(2 * k_ratio - 1, rel=1e-12)


def test_noiseless_log_holds_the_ratios_on_every_plateau():
    t = SegmentLoadTruth(**QUIET, seatings=6)
    log = simulate_segment_load(t, seed=0)
    assert list(log.columns) == ["time", "F", "F_K1", "F_K2", "F_P"]
    assert len(log) == round(t.seatings / t.seating_rate * t.sample_rate)
    assert np.allclose(np.diff(log["time"]), 1 / t.sample_rate)
    k_ratio, p_ratio = closed_form(t)
    sits = plateau_mask(t, log["time"].to_numpy())
    assert np.allclose(log["F"], 100e3)
    assert np.allclose(log["F_K1"][sits] / log["F"][sits], k_ratio, rtol=1e-12)
    assert np.allclose(log["F_K2"][sits] / log["F"][sits], k_ratio, rtol=1e-12)
    assert np.allclose(log["F_P"][sits] / log["F"][sits], p_ratio, rtol=1e-12)


def test_segments_are_idle_between_seatings_and_seatings_are_whole():
    t = SegmentLoadTruth(**QUIET, seatings=5)
    log = simulate_segment_load(t)
    loaded = (log["F_K1"] > 0).to_numpy()
    assert not loaded[0] and not loaded[-1]
    rises = np.flatnonzero(np.diff(loaded.astype(int)) == 1)
    assert rises.size == t.seatings
    # each seating loads the segments for 2 transitions + plateau
    widths = np.diff(np.flatnonzero(np.diff(loaded.astype(int)) != 0))[::2] / t.sample_rate
    assert np.allclose(widths, t.busy, atol=2 / t.sample_rate)


def test_load_shape_is_a_raised_cosine():
    t = SegmentLoadTruth()
    lead = (t.seating_period - t.busy) / 2
    at = lead + np.array([0.0, t.transition / 2, t.transition, t.transition + t.plateau,
                          t.busy - t.transition / 2, t.busy])
    assert np.allclose(load_shape(t, at), [0.0, 0.5, 1.0, 1.0, 0.5, 0.0])
    quarter = lead + t.transition / 4
    assert load_shape(t, np.array([quarter]))[0] == pytest.approx((1 - math.cos(math.pi / 4)) / 2)


def test_chain_force_levels_in_consecutive_blocks():
    t = SegmentLoadTruth(**QUIET, seatings=6, chain_force=(50e3, 150e3))
    log = simulate_segment_load(t)
    half = t.seatings / 2 * t.seating_period
    assert np.allclose(log["F"][log["time"] < half], 50e3)
    assert np.allclose(log["F"][log["time"] >= half], 150e3)
    sits = plateau_mask(t, log["time"].to_numpy())
    assert np.allclose(log["F_K1"][sits] / log["F"][sits], closed_form(t)[0], rtol=1e-12)


def test_gain_imbalance_and_zero():
    t = SegmentLoadTruth(**QUIET, seatings=4, gain_imbalance=0.1, zero_offset=2e3,
                         zero_drift=50.0)
    log = simulate_segment_load(t)
    time = log["time"].to_numpy()
    zero = 2e3 + 50.0 * time
    sits = plateau_mask(t, time)
    one, two = (log[name].to_numpy()[sits] - zero[sits] for name in ("F_K1", "F_K2"))
    assert np.allclose((one - two) / ((one + two) / 2), 0.1)
    assert np.allclose((one + two) / 2 / log["F"][sits], closed_form(t)[0], rtol=1e-12)
    idle = (log["F_K1"] - zero).abs().to_numpy() < 1e-9
    # between seatings, 1 - busy / period of the log, the channels read the drifting zero
    # (to a sample at either end of each seating)
    assert idle.mean() == pytest.approx(1 - t.busy / t.seating_period,
                                        abs=2 * t.seatings / idle.size)
    assert np.allclose(log["F_P"][idle], zero[idle])


def test_noise_per_channel():
    t = SegmentLoadTruth(noise_chain=300.0, noise_segment=500.0, noise_side=800.0)
    log = simulate_segment_load(t, seed=3)
    quiet = simulate_segment_load(t.with_(**QUIET))
    for name, sigma in (("F", 300.0), ("F_K1", 500.0), ("F_K2", 500.0), ("F_P", 800.0)):
        assert np.std(log[name] - quiet[name]) == pytest.approx(sigma, rel=0.02)


def test_reproducible_and_optional_side_force():
    t = SegmentLoadTruth(seatings=3)
    assert simulate_segment_load(t, seed=5).equals(simulate_segment_load(t, seed=5))
    assert not simulate_segment_load(t, seed=5).equals(simulate_segment_load(t, seed=6))
    assert "F_P" not in simulate_segment_load(t.with_(with_side_force=False))


@pytest.mark.parametrize("changes", [
    {"s": 44e-3},  # below the groove width c = 45 mm
    {"s": 97e-3},  # 2 k = 96.05 mm at beta = 50 deg
    {"plateau": 1.7},  # a seating longer than its period
    {"noise_segment": -1.0},
    {"chain_force": (100e3, 0.0)},
    {"chain_force": ()},
    {"seatings": 0},
    {"gain_imbalance": 2.0},
    {"sample_rate": math.nan},
])
def test_invalid_truth_is_refused(changes):
    with pytest.raises(ValueError):
        SegmentLoadTruth(**changes)
