"""The virtual tensile bench: its truth is what its docstring says it is."""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.simulate.tensile import TensileTruth, mean_elongation, simulate_tensile
from pipeline.units import to_si

#: Noise-free, unquantised, unbent: the log shows the model itself.
EXACT = {"force_noise": 0.0, "gauge_noise": 0.0, "gauge_resolution": 0.0, "bending": 0.0}


def bench(**settings) -> TensileTruth:
    return TensileTruth.for_chain("18x64", **settings)


def branch_masks(truth: TensileTruth, time: np.ndarray, cycle: int):
    """Samples of the loading and unloading ramps of `cycle` (from the force programme)."""
    knot_time, _ = truth.knots()
    interval = np.searchsorted(knot_time, time, side="right") - 1
    first = 1 + 3 * (cycle - 1)
    return interval == first, interval == first + 2


def test_for_chain_takes_paper_001_loads_and_table_1_stiffness():
    truth = bench()
    # Paper 001, Fig. 11: 18x64 preload 1000 kgf, upper load 10000 kgf; Table 1: E0 2.26e6 kgf.
    assert truth.preload == pytest.approx(to_si(1000, "kgf"))
    assert truth.upper_force == pytest.approx(to_si(10000, "kgf"))
    assert truth.E0 == pytest.approx(2.26e6 * 9.80665)
    assert truth.gauge_length == 0.9 and truth.n_cycles == 3


def test_log_is_canonical_and_reproducible():
    truth = bench(sample_rate=2.0)
    log = simulate_tensile(truth, seed=7)
    assert list(log.columns) == ["time", "force", "gauge_1", "gauge_2"]
    assert all(log.dtypes == np.float64)
    assert np.all(np.diff(log["time"]) > 0)
    assert log.equals(simulate_tensile(truth, seed=7))
    assert not log.equals(simulate_tensile(truth, seed=8))


@pytest.mark.parametrize("reseat", [0.0, 0.03e-3])
def test_loading_branches_of_later_cycles_have_slope_E0_above_the_toe(reseat):
    truth = bench(sample_rate=5.0, reseat_slack=reseat, **EXACT)
    log = simulate_tensile(truth, seed=0)
    force, strain = log["force"].to_numpy(), log["gauge_1"].to_numpy() / truth.gauge_length
    u = (force - truth.preload) / (truth.upper_force - truth.preload)
    for cycle in range(2, truth.n_cycles + 1):
        loading, _ = branch_masks(truth, log["time"].to_numpy(), cycle)
        above = loading & (u >= truth.reseat_fraction)
        slope, _ = np.polyfit(strain[above], force[above], 1)
        assert slope == pytest.approx(truth.E0, rel=1e-9)


def test_first_cycle_has_a_soft_toe_then_slope_E0():
    truth = bench(sample_rate=5.0, **EXACT)
    log = simulate_tensile(truth, seed=0)
    force, strain = log["force"].to_numpy(), log["gauge_1"].to_numpy() / truth.gauge_length
    u = (force - truth.preload) / (truth.upper_force - truth.preload)
    loading, _ = branch_masks(truth, log["time"].to_numpy(), 1)
    above = loading & (u >= truth.toe_fraction)
    assert np.polyfit(strain[above], force[above], 1)[0] == pytest.approx(truth.E0, rel=1e-9)
    toe = loading & (u <= truth.toe_fraction / 3)
    assert np.polyfit(strain[toe], force[toe], 1)[0] < 0.8 * truth.E0


def test_gauges_are_bent_quantised_and_their_mean_cancels_bending():
    truth = bench(sample_rate=2.0, force_noise=0.0, gauge_noise=0.0)
    log = simulate_tensile(truth, seed=3)
    for name in ("gauge_1", "gauge_2"):
        divisions = log[name].to_numpy() / truth.gauge_resolution
        np.testing.assert_allclose(divisions, np.round(divisions), atol=1e-6)
    assert log["gauge_1"].max() > 1.08 * log["gauge_2"].max()  # 1.05 / 0.95
    _, true_mean = mean_elongation(truth, log["time"].to_numpy())
    mean = (log["gauge_1"] + log["gauge_2"]).to_numpy() / 2
    # each gauge errs by half a division of rounding plus its zero offset (< half a division)
    assert np.max(np.abs(mean - true_mean)) <= truth.gauge_resolution + 1e-12


def test_truth_helpers_match_the_simulated_loop():
    truth = bench(sample_rate=20.0, dwell=10.0, reseat_slack=0.02e-3, **EXACT)
    knot_time, _ = truth.knots()
    time = np.union1d(np.arange(0, knot_time[-1], 1 / truth.sample_rate), knot_time)
    force, elongation = mean_elongation(truth, time)
    for cycle in range(1, truth.n_cycles + 1):
        start, stop = knot_time[1 + 3 * (cycle - 1)], knot_time[4 + 3 * (cycle - 1)]
        path = (time >= start) & (time <= stop)
        f, x = force[path], elongation[path]
        assert x[-1] - x[0] == pytest.approx(truth.permanent_set(cycle), rel=1e-9)
        closed_f, closed_x = np.append(f, f[0]), np.append(x, x[0])
        area = np.sum(0.5 * (closed_f[1:] + closed_f[:-1]) * np.diff(closed_x))
        assert area == pytest.approx(truth.hysteresis_energy(cycle), rel=2e-3)
    assert truth.permanent_set(1) > truth.permanent_set(2) > truth.permanent_set(3) > 0


def test_dwell_holds_the_peak():
    truth = bench(sample_rate=2.0, dwell=30.0, **EXACT)
    log = simulate_tensile(truth, seed=0)
    at_peak = log["force"] == truth.upper_force
    assert at_peak.sum() >= truth.n_cycles * 30 * 2
    assert log.loc[at_peak, "gauge_1"].nunique() == truth.n_cycles


@pytest.mark.parametrize(
    "settings",
    [{"E0": -1.0}, {"preload": 2e5}, {"n_cycles": 0}, {"toe_fraction": 0.0},
     {"bending": 1.0}, {"force_noise": -1.0}, {"hysteresis": 1e-3}],
)
def test_invalid_settings_raise(settings):
    with pytest.raises(ValueError):
        bench(**settings)


def test_chain_without_table_1_stiffness_needs_E0():
    with pytest.raises(ValueError, match="give E0"):
        TensileTruth.for_chain("34x126")
