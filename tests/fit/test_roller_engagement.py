"""xi of a roller chain on a sprocket fitted to strike amplitudes (Paper 002 with Paper 000's law).

Virtual bench: ISO 606 16B on an involute sprocket of 18 teeth (m = 8 mm,
alpha = 20 deg: xi = 0.535), runs at 100, 200 and 300 rpm (strikes of 167,
333 and 500 N), 80 strikes per run, sampled at 10 kHz. Measurement noise:
5 N rms white noise on the force (0.05 % of a 10 kN load cell), 5 % strike-to-
strike amplitude scatter, 0.1 ms jitter of the strike times; no polygon effect
(its effect on the extraction is the expected failure below).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import stats

from pipeline.engagement_log import detect_events, extract_impacts
from pipeline.errors import FitError
from pipeline.fit.roller_engagement import (
    RollerBranch,
    Sprocket,
    engagement_teeth,
    fit_roller_engagement,
    strike_amplitude,
    strike_statistics,
)
from pipeline.simulate.roller_engagement import (
    RollerEngagementTruth,
    simulate_roller_engagement,
)
from pipeline.theory.roller_impact import ENERGY_CONSTANT, impact_energy_paper

BRANCH = RollerBranch(pitch=0.0254, mass_per_length=2.7, E0=1.0e7, branch_length=1.0, k=2.0,
                      roller_diameter=0.01588, roller_length=0.01702)
TEETH, MODULE, ALPHA = 18, 0.008, math.radians(20.0)
SPROCKET = Sprocket(TEETH, module=MODULE, profile_angle=ALPHA)
RPM = np.array([100.0, 200.0, 300.0])
OMEGA = RPM * 2 * math.pi / 60
SEEDS = range(20)


def involute_xi_by_hand(teeth: int, r_b: float, pitch: float) -> float:
    """Paper 002, eqs. (3), (5), written out."""
    return math.sin(math.pi / teeth + math.acos(2 * r_b * math.sin(math.pi / teeth) / pitch))


XI = involute_xi_by_hand(TEETH, MODULE * TEETH * math.cos(ALPHA) / 2, BRANCH.pitch)


def amplitude_by_hand(omega, xi: float, b: RollerBranch = BRANCH):
    """N = omega t xi sqrt(k q t E0 / L), written out."""
    return omega * b.pitch * xi * math.sqrt(b.k * b.mass_per_length * b.pitch * b.E0
                                            / b.branch_length)


def fit_exact(xi: float = XI, **kwargs):
    amplitude = amplitude_by_hand(OMEGA, xi)
    return fit_roller_engagement(OMEGA, amplitude, 0.01 * amplitude, sprocket=SPROCKET,
                                 branch=BRANCH, **kwargs)


# --- hand checks ----------------------------------------------------------------------------


def test_strike_amplitude_is_paper_000_law_at_paper_002_velocity():
    assert strike_amplitude(OMEGA, XI, BRANCH) == pytest.approx(amplitude_by_hand(OMEGA, XI),
                                                                rel=1e-12)


def test_noiseless_amplitudes_give_xi_exactly():
    fit = fit_exact()
    assert fit.xi == pytest.approx(XI, rel=1e-9)
    assert fit.chi2_reduced < 1e-12 and not fit.scaled and fit.dof == 2
    assert fit.covers(XI) and fit.ci_low < fit.xi < fit.ci_high
    assert np.allclose(fit.points["residual"], 0, atol=1e-6 * fit.points["amplitude"].max())
    assert fit.r2 == pytest.approx(1.0, abs=1e-12)
    assert fit.intercept == pytest.approx(0.0, abs=1e-9 * fit.points["amplitude"].max())
    assert fit.slope == pytest.approx(fit.model_slope, rel=1e-9)
    assert fit.model_slope == pytest.approx(amplitude_by_hand(1.0, XI), rel=1e-9)


def test_weighted_fit_and_birge_scaling_match_the_closed_form():
    amplitude = amplitude_by_hand(OMEGA, XI) * np.array([1.03, 0.98, 1.01])
    error = np.array([2.0, 3.0, 4.0])
    fit = fit_roller_engagement(OMEGA, amplitude, error, sprocket=SPROCKET, branch=BRANCH)
    per_xi, weight = amplitude_by_hand(OMEGA, 1.0), 1 / error**2
    xi = np.sum(weight * per_xi * amplitude) / np.sum(weight * per_xi**2)
    chi2_reduced = np.sum(weight * (amplitude - xi * per_xi) ** 2) / 2
    assert chi2_reduced > 1  # the points scatter more than their errors say
    stderr = math.sqrt(chi2_reduced / np.sum(weight * per_xi**2))
    assert fit.xi == pytest.approx(xi, rel=1e-9)
    assert fit.scaled and fit.chi2_reduced == pytest.approx(chi2_reduced, rel=1e-6)
    assert fit.stderr == pytest.approx(stderr, rel=1e-6)
    assert fit.ci_high - fit.xi == pytest.approx(stats.t.ppf(0.975, 2) * stderr, rel=1e-6)


def test_interval_uses_the_normal_quantile_when_errors_explain_the_scatter():
    amplitude = amplitude_by_hand(OMEGA, XI) + np.array([1.0, -1.0, 0.5])
    error = np.full(3, 10.0)
    fit = fit_roller_engagement(OMEGA, amplitude, error, sprocket=SPROCKET, branch=BRANCH)
    stderr = 10.0 / math.sqrt(np.sum(amplitude_by_hand(OMEGA, 1.0) ** 2))
    assert not fit.scaled and fit.stderr == pytest.approx(stderr, rel=1e-6)
    assert fit.ci_high - fit.xi == pytest.approx(stats.norm.ppf(0.975) * stderr, rel=1e-6)


def test_energy_and_specific_energy_agree_with_paper_002_eq_6_in_its_units():
    fit = fit_exact()
    q, t_mm = BRANCH.mass_per_length, 1e3 * BRANCH.pitch
    diameter_mm, width_mm = 1e3 * BRANCH.roller_diameter, 1e3 * BRANCH.roller_length
    energy = impact_energy_paper(q, fit.xi, RPM, t_mm)
    assert np.allclose(fit.points["n_rpm"], RPM, rtol=1e-12)
    assert np.allclose(fit.points["energy"], energy, rtol=1e-9)
    # G in J/mm^2 by hand, against the module's J/m^2
    assert np.allclose(1e-6 * fit.points["specific_energy"], energy / (diameter_mm * width_mm),
                       rtol=1e-9)
    assert np.allclose(fit.points["impact_velocity"], OMEGA * BRANCH.pitch * fit.xi, rtol=1e-12)


def test_n_max_agrees_with_paper_002_eq_8_and_flags_faster_runs():
    q, t_mm = BRANCH.mass_per_length, 1e3 * BRANCH.pitch
    area_mm2 = 1e6 * BRANCH.roller_diameter * BRANCH.roller_length
    default = fit_exact()
    n_max = (math.sqrt(3e-4 / ENERGY_CONSTANT) / (default.xi * t_mm)
             * math.sqrt(area_mm2 / (q * t_mm)))  # eq. (8): 7400 / (xi t) sqrt(D B / (q t))
    assert default.n_max_rpm == pytest.approx(n_max, rel=1e-9)
    assert default.g_lim == pytest.approx(300.0) and not default.points["above_n_max"].any()
    # a lab limit that puts n_max at 250 rpm: G at 250 rpm by hand, in J/m^2
    g_lim = 1e6 * impact_energy_paper(q, default.xi, 250.0, t_mm) / area_mm2
    strict = fit_exact(g_lim=g_lim)
    assert strict.n_max_rpm == pytest.approx(250.0, rel=1e-9)
    assert list(strict.points["above_n_max"]) == [False, False, True]


def test_model_xi_and_bounds_of_the_involute():
    fit = fit_exact()
    assert fit.xi_model == pytest.approx(XI, rel=1e-12) and fit.xi_model_reason == ""
    assert fit.xi_bounds == pytest.approx((math.sin(math.pi / 18), math.cos(math.pi / 18)))
    assert fit.within_bounds and fit.interval_within_bounds
    r_b = 0.065
    xi, reason = Sprocket(TEETH, base_radius=r_b).involute_xi(BRANCH.pitch)
    assert xi == pytest.approx(involute_xi_by_hand(TEETH, r_b, BRANCH.pitch), rel=1e-12)
    assert reason == ""


def test_model_xi_not_determined_says_why():
    unknown = fit_roller_engagement(OMEGA, amplitude_by_hand(OMEGA, XI), np.ones(3),
                                    sprocket=Sprocket(TEETH), branch=BRANCH)
    assert math.isnan(unknown.xi_model) and "no involute geometry" in unknown.xi_model_reason
    too_large = BRANCH.pitch / (2 * math.sin(math.pi / TEETH)) * 1.01  # beyond eq. (3)'s acos
    xi, reason = Sprocket(TEETH, base_radius=too_large).involute_xi(BRANCH.pitch)
    assert math.isnan(xi) and "does not engage" in reason


def test_measured_xi_outside_the_bounds_is_reported():
    fit = fit_exact(xi=0.995)  # above cos(pi / 18) = 0.985
    assert fit.xi == pytest.approx(0.995, rel=1e-9)
    assert not fit.within_bounds and not fit.interval_within_bounds


@pytest.mark.parametrize(("omega", "amplitude", "stderr", "message"), [
    ([20.0, 20.0], [300.0, 310.0], [3.0, 3.0], "2 speeds or more"),
    ([20.0], [300.0], [3.0], "2 speeds or more"),
    ([0.0, 20.0], [1.0, 300.0], [3.0, 3.0], "every omega"),
    ([-10.0, 20.0], [150.0, 300.0], [3.0, 3.0], "every omega"),
    ([10.0, 20.0], [0.0, 300.0], [3.0, 3.0], "every amplitude"),
    ([10.0, 20.0], [-150.0, 300.0], [3.0, 3.0], "every amplitude"),
    ([10.0, 20.0], [150.0, math.nan], [3.0, 3.0], "every amplitude"),
    ([10.0, 20.0], [150.0, 300.0], [0.0, 3.0], "every stderr"),
    ([10.0, 20.0], [150.0, 300.0], [3.0], "one length"),
])
def test_bad_points_are_refused_with_a_hint(omega, amplitude, stderr, message):
    with pytest.raises(FitError, match=message) as caught:
        fit_roller_engagement(omega, amplitude, stderr, sprocket=SPROCKET, branch=BRANCH)
    assert caught.value.hint


def test_xi_above_one_is_refused_with_a_hint():
    amplitude = amplitude_by_hand(OMEGA, 1.3)  # e.g. E0 or L off by a factor 1.7
    with pytest.raises(FitError, match=r"outside \(0, 1\]") as caught:
        fit_roller_engagement(OMEGA, amplitude, np.ones(3), sprocket=SPROCKET, branch=BRANCH)
    assert "E0" in caught.value.hint


def test_geometry_and_branch_are_checked():
    with pytest.raises(ValueError, match="together"):
        Sprocket(TEETH, module=MODULE)
    with pytest.raises(ValueError, match="not both"):
        Sprocket(TEETH, module=MODULE, profile_angle=ALPHA, base_radius=0.06)
    with pytest.raises(ValueError, match="teeth"):
        Sprocket(3)
    with pytest.raises(ValueError, match="E0"):
        RollerBranch(0.0254, 2.7, 0.0, 1.0, 2.0, 0.01588, 0.01702)


def test_engagement_teeth_pairs_two_strikes_per_seating():
    assert engagement_teeth(18) == 9 and engagement_teeth(6) == 3
    for teeth in (17, 4):
        with pytest.raises(FitError, match=f"{teeth} teeth") as caught:
            engagement_teeth(teeth)
        assert "even number of teeth" in caught.value.hint


# --- virtual bench through the existing engagement pipeline ---------------------------------


def measured_points(truth: RollerEngagementTruth, seed: int):
    """Each run's pooled strike median and its standard error, as the pipeline gives them."""
    omega, median, stderr = [], [], []
    for index, speed in enumerate(truth.speeds):
        table, _ = simulate_roller_engagement(truth, speed, seed=100 * seed + index)
        events = detect_events(table, z=engagement_teeth(truth.teeth), omega=speed)
        statistics = strike_statistics(extract_impacts(table, events))
        omega.append(speed)
        median.append(statistics.median)
        stderr.append(statistics.stderr)
    return omega, median, stderr


def bench_fits(truth: RollerEngagementTruth):
    return [fit_roller_engagement(*measured_points(truth, seed), sprocket=SPROCKET,
                                  branch=BRANCH) for seed in SEEDS]


@pytest.fixture(scope="module")
def fits():
    return bench_fits(RollerEngagementTruth(teeth=TEETH, xi=XI, branch=BRANCH, speeds=tuple(OMEGA)))


def test_xi_recovered_within_3_percent_and_interval_covers(fits):
    assert all(fit.xi == pytest.approx(XI, rel=0.03) for fit in fits)
    assert sum(fit.covers(XI) for fit in fits) >= 18  # 95 % intervals: >= 90 % of 20 seeds
    assert all(fit.dof == 2 and fit.stderr > 0 for fit in fits)


def test_bench_amplitudes_are_straight_in_omega_and_xi_matches_the_involute(fits):
    fit = fits[0]
    assert fit.r2 > 0.999
    assert fit.slope == pytest.approx(amplitude_by_hand(1.0, XI), rel=0.03)
    assert abs(fit.intercept) < 0.03 * fit.points["amplitude"].max()
    assert fit.xi_model == pytest.approx(fit.xi, rel=0.03) and fit.within_bounds


def test_strike_statistics_pool_both_strikes_of_every_valid_seating():
    truth = RollerEngagementTruth(teeth=TEETH, xi=XI, branch=BRANCH)
    table, run = simulate_roller_engagement(truth, OMEGA[1], seed=3)
    impacts = extract_impacts(table, detect_events(table, z=9, omega=OMEGA[1]))
    pooled = strike_statistics(impacts)
    valid = impacts.events[impacts.events["status"] == "ok"]
    assert pooled.count == 2 * len(valid)
    assert pooled.median == pytest.approx(np.median(np.r_[valid["N_u1"], valid["N_u2"]]))
    assert pooled.stderr_ringing == pytest.approx(
        (impacts.N_u1.stderr_ringing + impacts.N_u2.stderr_ringing) / 2)
    assert pooled.median == pytest.approx(run["amplitude"], rel=4 * pooled.stderr
                                          / run["amplitude"])


@pytest.mark.xfail(strict=True, reason=(
    "the extraction's slow-tension model has the seating period, two teeth here; a roller "
    "chain's polygon effect has the tooth period and leaks into the fitted damping and the "
    "amplitudes: with 10 N, xi +1.4 % on average and the intervals cover in 10 of 20 seeds"))
def test_polygon_effect_of_the_tooth_period_keeps_the_interval_honest():
    truth = RollerEngagementTruth(teeth=TEETH, xi=XI, branch=BRANCH, speeds=tuple(OMEGA),
                                  polygon_amplitude=10.0)
    fits = bench_fits(truth)
    assert all(fit.xi == pytest.approx(XI, rel=0.03) for fit in fits)
    assert sum(fit.covers(XI) for fit in fits) >= 18
