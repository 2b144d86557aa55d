"""The virtual roller-chain engagement bench: one strike per tooth, of the stated amplitude."""

from __future__ import annotations

import math

import numpy as np
import pytest

from pipeline.engagement_log import detect_events, extract_impacts
from pipeline.fit.roller_engagement import RollerBranch, engagement_teeth, strike_statistics
from pipeline.simulate.roller_engagement import (
    RollerEngagementTruth,
    simulate_roller_engagement,
)

BRANCH = RollerBranch(pitch=0.0254, mass_per_length=2.7, E0=1.0e7, branch_length=1.0, k=2.0,
                      roller_diameter=0.01588, roller_length=0.01702)
TEETH, XI, RATE = 18, 0.5, 10e3
#: A speed whose tooth pitch is 20 ms: 200 samples at 10 kHz.
OMEGA = 2 * math.pi / (TEETH * 0.020)
QUIET = {"noise_std": 0.0, "amplitude_scatter": 0.0, "jitter": 0.0}


def truth_of(**changes) -> RollerEngagementTruth:
    return RollerEngagementTruth(teeth=TEETH, xi=XI, branch=BRANCH, sample_rate=RATE, **changes)


def amplitude_by_hand(omega: float) -> float:
    """omega t xi sqrt(k q t E0 / L), written out."""
    b = BRANCH
    return omega * b.pitch * XI * math.sqrt(b.k * b.mass_per_length * b.pitch * b.E0
                                            / b.branch_length)


def test_one_strike_per_tooth_of_the_stated_amplitude():
    table, run = simulate_roller_engagement(truth_of(**QUIET), OMEGA, seed=2)
    period = 2 * math.pi / (TEETH * OMEGA)
    assert run["strike_period"] == pytest.approx(period, rel=1e-12)
    assert run["amplitude"] == pytest.approx(amplitude_by_hand(OMEGA), rel=1e-12)
    assert run["impact_velocity"] == pytest.approx(OMEGA * BRANCH.pitch * XI, rel=1e-12)
    assert np.allclose(run["strike_amplitude"], run["amplitude"], rtol=1e-12)
    assert np.allclose(np.diff(run["strike_time"]), period, rtol=1e-9)
    assert run["strike_time"].size in (80, 81)  # 80 tooth pitches, the ends inclusive
    assert len(table) == int(80 * period * RATE) + 1
    assert np.allclose(np.diff(table["time"]), 1 / RATE)


def test_branch_rings_at_its_natural_frequency():
    truth = truth_of()
    assert truth.omega_n == pytest.approx(math.sqrt(BRANCH.E0 / (BRANCH.mass_per_length
                                                                 * BRANCH.branch_length**2)))
    assert truth_of(natural_frequency=1500.0).omega_n == 1500.0


def test_noise_is_white_with_the_stated_deviation():
    quiet, _ = simulate_roller_engagement(truth_of(**QUIET), OMEGA, seed=5)
    noisy, _ = simulate_roller_engagement(truth_of(**{**QUIET, "noise_std": 5.0}), OMEGA, seed=5)
    noise = (noisy["force"] - quiet["force"]).to_numpy()
    # sample standard deviation of n normal values: relative error sqrt(1 / (2 n))
    assert np.std(noise) == pytest.approx(5.0, rel=5 / math.sqrt(2 * noise.size))


def test_polygon_effect_has_the_tooth_period():
    quiet, _ = simulate_roller_engagement(truth_of(**QUIET), OMEGA, seed=4)
    polygon, _ = simulate_roller_engagement(truth_of(**QUIET, polygon_amplitude=10.0), OMEGA,
                                            seed=4)
    effect = (polygon["force"] - quiet["force"]).to_numpy()
    samples = 200  # one tooth pitch
    assert np.allclose(effect[samples:], effect[:-samples], atol=1e-9)
    assert np.max(np.abs(effect)) == pytest.approx(10.0, rel=1 - math.cos(math.pi / samples))


def test_angle_channel_turns_at_omega():
    table, _ = simulate_roller_engagement(truth_of(), OMEGA, seed=6)
    slope = np.polyfit(table["time"], np.unwrap(table["angle"]), 1)[0]
    assert slope == pytest.approx(OMEGA, rel=1e-9)
    assert "angle" not in simulate_roller_engagement(truth_of(with_angle=False), OMEGA)[0]


def test_noiseless_log_through_the_engagement_pipeline_gives_the_truth():
    table, run = simulate_roller_engagement(truth_of(**QUIET), OMEGA, seed=7)
    events = detect_events(table, z=engagement_teeth(TEETH), omega=OMEGA)
    impacts = extract_impacts(table, events)
    valid = impacts.events[impacts.events["status"] == "ok"]
    assert len(valid) >= 36  # of 40 seatings (two strikes each); the ends are truncated
    assert np.allclose(valid[["N_u1", "N_u2"]], run["amplitude"], rtol=1e-3)
    assert strike_statistics(impacts).median == pytest.approx(run["amplitude"], rel=1e-3)
    strikes = np.sort(np.r_[valid["event_time"], valid["impact2_time"]])
    nearest = np.abs(strikes[:, None] - run["strike_time"][None, :]).min(axis=1)
    assert np.all(nearest < 1 / RATE)


@pytest.mark.parametrize(("changes", "message"), [
    ({"xi": 0.0}, "xi"), ({"xi": 1.2}, "xi"), ({"speeds": ()}, "speeds"),
    ({"speeds": (10.0, -1.0)}, "speeds"), ({"noise_std": -1.0}, "noise_std"),
    ({"amplitude_scatter": math.nan}, "amplitude_scatter"), ({"damping_ratio": 1.0}, "damping"),
    ({"strikes": 0}, "strikes"), ({"sample_rate": 500.0}, "sample_rate"), ({"teeth": 2}, "teeth"),
])
def test_bad_settings_are_refused(changes, message):
    with pytest.raises(ValueError, match=message):
        RollerEngagementTruth(**{"teeth": TEETH, "xi": XI, "branch": BRANCH, **changes})
