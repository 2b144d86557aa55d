"""Impact extraction per event on the virtual engagement bench (known strikes)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from pipeline.condition.engagement import EngagementEvents
from pipeline.engagement_log import detect_events, extract_impacts
from pipeline.errors import FitError
from pipeline.fit.impact import EXCLUSIONS, Ringing, plan_extraction
from pipeline.simulate.engagement import EngagementSettings, simulate_engagement

#: The accuracy asked of a run's medians at SNR >= 10 (docs/quality.md).
MEDIAN_TOLERANCE = 0.03
SEEDS = range(20)


def run(seed: int = 1, ringing: Ringing | None = None, **settings):
    base = {"duration": 1.5, "sample_rate": 10e3, "snr": 10.0}
    s = EngagementSettings(**{**base, **settings})
    table, truth = simulate_engagement(s, seed=seed)
    events = detect_events(table, z=s.z, omega=s.omega)
    return extract_impacts(table, events, ringing=ringing), truth, table, events


def truth_of(result, truth) -> np.ndarray:
    """Index of the true seating of every extracted event."""
    index = np.searchsorted(truth["event_time"], result.events["event_time"] - truth["tau"] / 2)
    return np.clip(index, 0, truth["event_time"].size - 1)


@pytest.mark.parametrize("settings", [{}, {"omega": 35.0, "z": 6, "sample_rate": 5e3},
                                      {"damping_ratio": 0.08, "jitter": 5e-4}])
def test_noise_free_log_is_recovered_exactly(settings):
    s = EngagementSettings(**{"duration": 1.5, "sample_rate": 10e3, "snr": math.inf,
                              "amplitude_scatter": 0.1, **settings})
    exact = Ringing(s.omega_n, s.damping_ratio)
    result, truth, _, _ = run(ringing=exact, **{**dataclasses.asdict(s)})
    ok = result.events["status"] == "ok"
    assert ok.sum() >= truth["event_time"].size - 2
    events, index = result.events[ok], truth_of(result, truth)[ok]
    assert np.allclose(events["event_time"], truth["event_time"][index], rtol=0, atol=1e-10)
    assert np.allclose(events["impact2_time"], truth["impact2_time"][index], rtol=0, atol=1e-10)
    assert np.allclose(events["N_u1"], truth["N_u1_event"][index], rtol=1e-9)
    assert np.allclose(events["N_u2"], truth["N_u2_event"][index], rtol=1e-9)
    assert np.allclose(events["baseline"], truth["baseline_event"][index], rtol=0, atol=1e-6)
    # fitted, the ringing is found to lmfit's tolerance, the amplitudes to about as much
    fitted, _, _, _ = run(**dataclasses.asdict(s))
    assert fitted.ringing.omega_n == pytest.approx(s.omega_n, rel=1e-4)
    assert fitted.ringing.zeta == pytest.approx(s.damping_ratio, rel=1e-3)
    assert fitted.N_u2.median == pytest.approx(result.N_u2.median, rel=1e-4)


@pytest.mark.parametrize("with_angle", [True, False])
def test_run_medians_within_3_percent_with_honest_standard_errors(with_angle):
    errors, stderrs = {"N_u1": [], "N_u2": []}, {"N_u1": [], "N_u2": []}
    for seed in SEEDS:
        result, truth, _, _ = run(seed, with_angle=with_angle)
        for name in errors:
            stats = result.statistics[name]
            assert stats.median == pytest.approx(truth[name], rel=MEDIAN_TOLERANCE)
            assert stats.count >= 30 and stats.stderr > 0
            errors[name].append(stats.median - truth[name])
            stderrs[name].append(stats.stderr)
    for name in errors:
        # the standard error matches the actual scatter of the medians over the seeds
        # (rms ratio; 20 seeds give it to about +-16 %), and no seed is off by 3.5 of them
        ratio = math.sqrt(np.mean(np.square(errors[name])) / np.mean(np.square(stderrs[name])))
        assert 0.6 < ratio < 1.5
        assert np.all(np.abs(errors[name]) < 3.5 * np.array(stderrs[name]))


@pytest.mark.parametrize("settings", [{"damping_ratio": 0.015}, {"damping_ratio": 0.06},
                                      {"natural_frequency": 2 * math.pi * 210.0},
                                      {"snr": 30.0, "sample_rate": 50e3, "duration": 0.6}])
def test_ringing_is_fitted_per_run(settings):
    result, truth, _, _ = run(**settings)
    assert result.ringing.omega_n == pytest.approx(truth["omega_n"], rel=0.005)
    assert result.ringing.zeta == pytest.approx(truth["zeta"], rel=0.05)
    assert result.ringing.n_events > 10 and result.ringing.fitted
    for name in ("N_u1", "N_u2"):
        assert result.statistics[name].median == pytest.approx(truth[name], rel=MEDIAN_TOLERANCE)


def test_given_ringing_is_used_and_adds_no_error():
    result, truth, _, _ = run(ringing=Ringing(925.5, 0.03))
    assert result.ringing == Ringing(925.5, 0.03)
    assert result.N_u1.stderr_ringing == 0 and result.N_u1.stderr == result.N_u1.stderr_events


def test_amplitude_is_compared_and_first_peak_reported_beside_it():
    result, truth, _, _ = run()
    assert result.comparison == "amplitude"
    zeta, omega_n = result.ringing.zeta, result.ringing.omega_n
    s = np.linspace(0, 2 * np.pi / omega_n, 200_001)
    first_peak = np.max(np.exp(-zeta * omega_n * s) * np.sin(omega_n * math.sqrt(1 - zeta**2) * s))
    ok = result.events["status"] == "ok"
    assert np.allclose(result.events["peak2"][ok], first_peak * result.events["N_u2"][ok],
                       rtol=1e-8)
    assert result.statistics["peak1"].median < result.N_u1.median
    summary = result.summary()
    assert summary["comparison"] == "amplitude"
    assert summary["N_u2_median"] == result.N_u2.median
    assert summary["events_total"] == len(result.events)
    assert set(EXCLUSIONS) <= {key.removeprefix("excluded_") for key in summary}


def test_clipped_events_are_excluded_and_counted():
    level = 23.8e3  # pretension 20 kN + polygon 0.5 kN + part of the larger strikes
    result, truth, table, _ = run(amplitude_scatter=0.1, clip_level=level, duration=3.0)
    assert result.clip_levels == (None, level)  # found from the flat tops
    status = result.events["status"].to_numpy()
    index = truth_of(result, truth)
    clipped_truth = truth["clipped_event"][index] & (status != "truncated")
    assert clipped_truth.sum() >= 2
    assert np.all(status[clipped_truth] == "clipped")
    assert result.excluded["clipped"] == np.sum(status == "clipped")
    assert result.N_u1.count == np.sum(status == "ok")
    # no clipped sample inside a window that was averaged in
    time, force = table["time"].to_numpy(), table["force"].to_numpy()
    for start in result.events.loc[status == "ok", "event_time"]:  # the fit's windows
        inside = (time > start - 0.4 * truth["tau"]) & (time < start + 1.85 * truth["tau"])
        assert force[inside].max() < level
    assert result.N_u1.median == pytest.approx(truth["N_u1"], rel=MEDIAN_TOLERANCE)


def test_given_clip_level_excludes_events_reaching_it():
    result, _, _, _ = run(amplitude_scatter=0.1, duration=3.0)
    given, _, _, _ = run(amplitude_scatter=0.1, duration=3.0, ringing=result.ringing)
    assert given.excluded["clipped"] == 0
    table, truth = simulate_engagement(EngagementSettings(duration=3.0, sample_rate=10e3,
                                                          snr=10.0, amplitude_scatter=0.1), 1)
    events = detect_events(table, z=8, omega=20.0)
    clipped = extract_impacts(table, events, clip_level=23.8e3)
    assert 0 < clipped.excluded["clipped"] < len(clipped.events)
    assert clipped.clip_levels == (None, 23.8e3)


def test_missing_samples_and_log_ends_are_excluded():
    table, truth = simulate_engagement(EngagementSettings(duration=1.5, sample_rate=10e3,
                                                          snr=10.0), seed=2)
    table = table.copy()
    table.loc[7000:7040, "force"] = np.nan
    events = detect_events(table, z=8, omega=20.0)
    result = extract_impacts(table, events)
    assert result.excluded["gap"] >= 1
    starts = result.events["event_time"].to_numpy()
    truncated = result.events["status"].to_numpy() == "truncated"
    near_end = (starts < truth["seating_period"]) | (
        starts > table["time"].iloc[-1] - 2 * truth["seating_period"])
    assert truncated.sum() == result.excluded["truncated"] >= 1
    assert np.all(near_end[truncated])
    counted = sum(result.excluded.values()) + result.N_u1.count
    assert counted == len(result.events)
    assert result.N_u2.median == pytest.approx(truth["N_u2"], rel=MEDIAN_TOLERANCE)


def test_glitch_fails_its_event_only():
    table, truth = simulate_engagement(EngagementSettings(duration=1.5, sample_rate=10e3,
                                                          snr=10.0), seed=3)
    table = table.copy()
    glitch = np.searchsorted(table["time"], truth["event_time"][15] + 0.3 * truth["tau"])
    table.loc[glitch:glitch + 30, "force"] += 5 * truth["N_u2"]
    result = extract_impacts(table, detect_events(table, z=8, omega=20.0))
    assert result.excluded["fit_failed"] >= 1
    failed = result.events.loc[result.events["status"] == "fit_failed", "event_time"]
    assert np.min(np.abs(failed.to_numpy() - truth["event_time"][15])) < 1e-3
    assert result.N_u1.median == pytest.approx(truth["N_u1"], rel=MEDIAN_TOLERANCE)


def test_irregular_spacing_is_an_overlap():
    table, truth = simulate_engagement(EngagementSettings(duration=1.5, sample_rate=10e3,
                                                          snr=10.0), seed=4)
    events = detect_events(table, z=8, omega=20.0)
    extra = events.impact1_time[10] + 0.5 * events.seating_period  # a seating that is not there
    impact1 = np.sort(np.append(events.impact1_time, extra))
    spoiled = dataclasses.replace(events, impact1_time=impact1,
                                  impact2_time=impact1 + events.tau)
    result = extract_impacts(table, spoiled)
    assert result.excluded["overlap"] + result.excluded["fit_failed"] >= 3
    assert result.excluded["overlap"] >= 2
    assert result.N_u2.median == pytest.approx(truth["N_u2"], rel=MEDIAN_TOLERANCE)


def test_nothing_to_fit_is_a_fit_error():
    table, _ = simulate_engagement(EngagementSettings(duration=1.0, sample_rate=10e3,
                                                      clip_level=20.2e3), seed=1)
    events = detect_events(table, z=8, omega=20.0)
    with pytest.raises(FitError, match="no engagement event can be fitted") as error:
        extract_impacts(table, events, file="E8.tdms")
    assert error.value.file == "E8.tdms" and error.value.hint


def test_strikes_too_fast_at_a_period_off_the_run_sheet_say_so():
    # a real rocket motor's thrust, run as an engagement log: the "seatings" found every
    # 0.027 s where the run sheet's speed gives 0.105 s; the hint told only to check the
    # sheet, which was right
    onsets = np.arange(10) * 0.0266
    events = EngagementEvents(
        impact1_time=onsets, impact2_time=onsets + 0.0133, seating_period=0.0266,
        stated_period=2 * math.pi / (6 * 10.0), omega=39.4, stated_omega=10.0, z=6,
        sample_rate=2000.0, start_time=0.0, n_samples=1763,
        natural_frequency=2 * math.pi / 0.0122, source="force", onset_resolution=5e-4)
    with pytest.raises(FitError, match="run sheet's speed and teeth give 0.0524 s") as error:
        plan_extraction(events, None)
    assert "branch tension" in error.value.hint
    # at the stated period, nothing is said of it
    stated = dataclasses.replace(events, seating_period=events.stated_period,
                                 natural_frequency=2 * math.pi / 0.06)
    with pytest.raises(FitError) as error:
        plan_extraction(stated, None)
    assert "run sheet's speed" not in str(error.value)
