"""Seatings of a segment-load log on the virtual segment-load bench (known truth).

Expected ratios come from :mod:`pipeline.theory.tooth_segments` applied to the
truth's geometry here, not from the bench's own properties.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.segment_load import (
    IMBALANCE_TOLERANCE,
    MIN_EVENTS,
    SegmentImbalanceWarning,
    condition_segment_load,
)
from pipeline.errors import SignalError
from pipeline.simulate.segment_load import SegmentLoadTruth, simulate_segment_load
from pipeline.theory.tooth_segments import (
    contact_force_ratio,
    contact_radius,
    opening_angle,
    side_force_ratio,
)

QUIET = {"noise_chain": 0.0, "noise_segment": 0.0, "noise_side": 0.0}
SEEDS = range(20)


def expected(t: SegmentLoadTruth) -> tuple[float, float]:
    """F_K / F and F_P / F of the truth's geometry (Paper 003, eqs. (1)-(4))."""
    psi = opening_angle(t.s, contact_radius(t.r_outer, t.d, t.beta, t.eps_n), t.groove_width)
    return float(contact_force_ratio(psi)), float(side_force_ratio(psi))


def condition(log: pd.DataFrame, **kwargs):
    """Condition a simulated log, its channels by name."""
    return condition_segment_load(log["time"], log["F"], log["F_K1"], log["F_K2"],
                                  log.get("F_P"), **kwargs)


def test_noiseless_log_gives_the_exact_ratios():
    for t in (SegmentLoadTruth(**QUIET), SegmentLoadTruth(**QUIET, beta=math.radians(80),
                                                          s=45e-3, seatings=12),
              SegmentLoadTruth(**QUIET, eps_n=math.radians(6), s=70e-3, seatings=12)):
        result = condition(simulate_segment_load(t))
        k_ratio, p_ratio = expected(t)
        events = result.events
        assert len(events) == t.seatings and (events["status"] == "ok").all()
        for name in ("F_K/F", "F_K1/F", "F_K2/F"):
            assert np.allclose(events[name], k_ratio, rtol=1e-12)
        assert np.allclose(events["F_P/F"], p_ratio, rtol=1e-12)
        assert np.allclose(events["F"], t.chain_force[0])
        assert np.allclose(events["imbalance"], 0.0, atol=1e-12)
        assert result.statistics["F_K/F"].median == pytest.approx(k_ratio, rel=1e-12)
        assert not result.imbalanced and result.messages == ()


def test_plateaus_lie_inside_the_true_plateaus():
    t = SegmentLoadTruth(seatings=10)
    events = condition(simulate_segment_load(t, seed=4)).events
    lead = (t.seating_period - t.busy) / 2
    seating = np.arange(t.seatings) * t.seating_period + lead
    assert (events["plateau_start"] >= seating + t.transition).all()
    assert (events["plateau_stop"] <= seating + t.transition + t.plateau).all()
    # most of the plateau is kept: the trim takes 10 % at each end, the band a little more
    kept = (events["plateau_stop"] - events["plateau_start"]) / t.plateau
    assert (kept > 0.7).all()
    assert (events["start"] > seating).all() and (events["stop"] < seating + t.busy).all()


@pytest.mark.parametrize("changes", [
    {},
    {"chain_force": (40e3, 120e3, 200e3), "seatings": 30},
    {"seating_rate": 2.0, "plateau": 0.2, "transition": 0.05, "seatings": 50},
    {"with_side_force": False},
])
def test_event_count_equals_the_simulated_seatings(changes):
    t = SegmentLoadTruth(**changes)
    result = condition(simulate_segment_load(t, seed=11))
    assert len(result.events) == t.seatings
    assert (result.events["status"] == "ok").all() and result.statistics["F_K/F"].count == \
        t.seatings
    assert ("F_P/F" in result.events) == t.with_side_force


def test_medians_within_one_percent_of_truth_over_20_seeds():
    t = SegmentLoadTruth()
    k_ratio, p_ratio = expected(t)
    for seed in SEEDS:
        stats = condition(simulate_segment_load(t, seed=seed)).statistics
        assert stats["F_K/F"].median == pytest.approx(k_ratio, rel=0.01)
        assert stats["F_P/F"].median == pytest.approx(p_ratio, rel=0.01)
        assert stats["F_K1/F"].median == pytest.approx(k_ratio, rel=0.01)
        assert stats["F_K2/F"].median == pytest.approx(k_ratio, rel=0.01)


def test_imbalance_is_flagged_and_recorded_never_averaged_silently():
    t = SegmentLoadTruth(**QUIET, gain_imbalance=0.1)
    with pytest.warns(SegmentImbalanceWarning, match="disagree by more than 5 %"):
        result = condition(simulate_segment_load(t))
    k_ratio, _ = expected(t)
    events = result.events
    assert events["imbalanced"].all() and result.imbalanced
    assert np.allclose(events["imbalance"], 0.1)
    assert np.allclose(events["F_K1/F"], 1.05 * k_ratio) and np.allclose(events["F_K2/F"],
                                                                         0.95 * k_ratio)
    assert np.allclose(events["F_K/F"], k_ratio)  # gains of 1 +- 0.05 average out
    assert len(result.messages) == 1 and "30 of 30 seatings" in result.messages[0]
    assert result.point()["imbalanced"] is True


def test_imbalance_within_tolerance_is_not_flagged():
    t = SegmentLoadTruth(gain_imbalance=IMBALANCE_TOLERANCE / 2)
    with warnings.catch_warnings():
        warnings.simplefilter("error", SegmentImbalanceWarning)
        result = condition(simulate_segment_load(t, seed=2))
    assert not result.imbalanced
    assert result.statistics["imbalance"].median == pytest.approx(IMBALANCE_TOLERANCE / 2,
                                                                  rel=0.1)


def test_drifting_zero_of_the_segments_is_removed():
    t = SegmentLoadTruth(**QUIET, zero_offset=3e3, zero_drift=40.0)
    events = condition(simulate_segment_load(t)).events
    k_ratio, p_ratio = expected(t)
    assert np.allclose(events["F_K/F"], k_ratio, rtol=1e-12)
    assert np.allclose(events["F_P/F"], p_ratio, rtol=1e-12)
    # each zero is read in the idle stretch just before its seating
    lead = (t.seating_period - t.busy) / 2
    before = np.arange(t.seatings) * t.seating_period + lead
    assert (np.abs(events["zero_K1"] - (3e3 + 40.0 * before)) < 40.0 * t.seating_period).all()


def test_gap_truncation_and_spike_are_excluded():
    t = SegmentLoadTruth(seatings=12)
    log = simulate_segment_load(t, seed=6)
    middle = 5.5 * t.seating_period  # the plateau of seating 5
    log.loc[(log["time"] > middle) & (log["time"] < middle + 0.01), "F"] = np.nan
    spike = 7 * t.seating_period  # idle, between seatings 6 and 7
    log.loc[(log["time"] - spike).abs() < 1e-9, ["F_K1", "F_K2"]] = 50e3
    first_plateau = t.seating_period / 2
    cut = log[log["time"] >= first_plateau].reset_index(drop=True)  # starts mid-plateau
    result = condition(cut)
    status = result.events["status"].tolist()
    assert status[0] == "truncated" and status.count("truncated") == 1
    assert status.count("gap") == 1 and status.count("short") == 1
    assert status.count("ok") == t.seatings - 2
    assert result.excluded == {"truncated": 1, "gap": 1, "short": 1, "no_zero": 0}
    assert result.statistics["F_K/F"].count == t.seatings - 2


def test_a_seating_without_idle_after_it_has_no_zero():
    t = SegmentLoadTruth(seatings=8)
    lead = (t.seating_period - t.busy) / 2
    end = (t.seatings - 1) * t.seating_period + lead + t.busy  # the last seating's end
    log = simulate_segment_load(t, seed=3)
    result = condition(log[log["time"] <= end + 3 / t.sample_rate])
    assert result.events["status"].tolist() == ["ok"] * (t.seatings - 1) + ["no_zero"]
    assert result.excluded["no_zero"] == 1


def test_point_holds_medians_iqr_and_standard_errors():
    result = condition(simulate_segment_load(SegmentLoadTruth(), seed=9))
    point = result.point()
    ratios = result.valid["F_K/F"].to_numpy()
    assert point["F_K/F"] == pytest.approx(np.median(ratios))
    q1, q3 = np.percentile(ratios, [25, 75])
    assert point["F_K/F_iqr"] == pytest.approx(q3 - q1)
    mad = np.median(np.abs(ratios - np.median(ratios)))
    assert point["F_K/F_stderr"] == pytest.approx(
        math.sqrt(math.pi / 2) * 1.4826 * mad / math.sqrt(ratios.size))
    assert point["F_K/F_count"] == 30 and point["excluded_gap"] == 0


def test_standard_errors_describe_the_scatter():
    t = SegmentLoadTruth()
    k_ratio, _ = expected(t)
    pulls = []
    for seed in SEEDS:
        events = condition(simulate_segment_load(t, seed=seed)).valid
        pulls.append((events["F_K/F"] - k_ratio) / events["F_K/F_stderr"])
    pulls = np.concatenate(pulls)
    # 600 seatings: the standard deviation of a unit normal's sample is 1 +- 0.03
    assert np.std(pulls) == pytest.approx(1.0, abs=0.15)


def table(t: SegmentLoadTruth | None = None, seed: int = 1) -> pd.DataFrame:
    return simulate_segment_load(t or SegmentLoadTruth(seatings=8), seed=seed)


@pytest.mark.parametrize("column", ["F", "F_K1", "F_K2"])
def test_missing_or_empty_channel_is_refused(column):
    log = table()
    channels = {name: log[name] for name in ("time", "F", "F_K1", "F_K2")}
    with pytest.raises(SignalError, match=f"no {column} channel") as missing:
        condition_segment_load(**{**_arguments(channels), _argument(column): None})
    assert missing.value.column == column and missing.value.hint
    channels[column] = np.full(len(log), np.nan)
    with pytest.raises(SignalError, match="holds no number") as empty:
        condition_segment_load(**_arguments(channels))
    assert empty.value.column == column and empty.value.hint


def _argument(column: str) -> str:
    return {"time": "time", "F": "chain_force", "F_K1": "segment_force_1",
            "F_K2": "segment_force_2", "F_P": "side_force"}[column]


def _arguments(channels: dict) -> dict:
    return {_argument(name): values for name, values in channels.items()}


def test_all_missing_side_force_is_refused():
    log = table().assign(F_P=np.nan)
    with pytest.raises(SignalError, match="F_P channel holds no number") as error:
        condition(log)
    assert error.value.hint


def test_channels_of_other_lengths_are_refused():
    log = table()
    with pytest.raises(SignalError, match="samples, the time") as error:
        condition_segment_load(log["time"], log["F"][:-1], log["F_K1"], log["F_K2"])
    assert error.value.hint


def test_non_uniform_time_is_refused():
    log = table()
    log.loc[100:, "time"] += 0.05
    with pytest.raises(SignalError, match="not uniformly sampled") as error:
        condition(log)
    assert error.value.hint


def test_too_few_seatings_are_refused():
    log = table(SegmentLoadTruth(seatings=MIN_EVENTS - 1))
    with pytest.raises(SignalError, match=f"needs at least {MIN_EVENTS}") as error:
        condition(log)
    assert error.value.hint


def test_a_log_without_seatings_is_refused():
    rng = np.random.default_rng(0)
    n = 5000
    log = pd.DataFrame({"time": np.arange(n) / 1e3, "F": 100e3 + rng.normal(0, 500, n),
                        "F_K1": rng.normal(0, 500, n), "F_K2": rng.normal(0, 500, n)})
    with pytest.raises(SignalError, match="0 valid seatings") as error:
        condition(log)
    assert "segment forces rise" in error.value.hint


def test_negative_segment_forces_are_refused():
    log = table()
    log[["F_K1", "F_K2"]] *= -1  # plateaus would pass for idle stretches, and back
    with pytest.raises(SignalError, match="not about zero") as error:
        condition(log)
    assert "sign of F_K1 and F_K2" in error.value.hint


def test_chain_force_not_positive_is_refused():
    log = table()
    log["F"] *= -1
    with pytest.raises(SignalError, match="chain force is not positive") as error:
        condition(log)
    assert error.value.column == "F" and "sign" in error.value.hint
