"""Single pulls on the virtual bench: conditioning and fit recover the simulated truth.

20 seeds each: E0 within 1 % of the truth with its 95 % interval covering it in at
least 90 % of seeds; with an extensometer beside a crosshead whose machine takes 30 %
of the travel, E0 is the extensometer's and the run says so; fracture and a removed
extensometer are found in every seed.
"""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.condition.tensile import condition_tensile
from pipeline.fit.stiffness import fit_stiffness, specimen_stiffness
from pipeline.fit.strength import specimen_strength
from pipeline.simulate.pull import PullTruth, simulate_pull

SEEDS = range(20)
KINDS = {"gauge_1": "extensometer", "gauge_2": "crosshead"}
COLUMNS = {"gauge_1": "Ext", "gauge_2": "Crosshead"}


def analyse(truth: PullTruth, seed: int, *, crosshead: bool = True):
    log = simulate_pull(truth, seed=seed).rename(
        columns={"extensometer": "gauge_1", "crosshead": "gauge_2"})
    if not crosshead:
        log = log.drop(columns="gauge_2")
    run = condition_tensile(log, truth.gauge_length, n_cycles=1, kinds=KINDS, columns=COLUMNS)
    fits = fit_stiffness(run)
    return run, fits, specimen_stiffness(fits, single_pull=run.single_pull)


@pytest.fixture(scope="module")
def pulls():
    truth = PullTruth.for_chain("18x64")
    return truth, [analyse(truth, seed) for seed in SEEDS]


def test_single_pull_E0_within_1_percent_and_covered_in_90_percent(pulls):
    truth, results = pulls
    errors = np.array([specimen.E0 / truth.E0 - 1 for _, _, specimen in results])
    covered = [specimen.E0_ci_low <= truth.E0 <= specimen.E0_ci_high
               for _, _, specimen in results]
    assert np.max(np.abs(errors)) < 0.01
    assert np.mean(covered) >= 0.9


def test_the_window_stays_below_the_onset_of_yield(pulls):
    truth, results = pulls
    for _, fits, _ in results:
        assert fits.loc[(1, "loading"), "window_high"] <= truth.yield_force


def test_the_extensometer_is_used_and_the_crosshead_named_in_a_warning(pulls):
    truth, results = pulls
    assert truth.machine_share == pytest.approx(0.3)
    for run, _, _ in results:
        assert run.channels["used"].to_dict() == {"gauge_1": True, "gauge_2": False}
        ratio = run.channels.loc["gauge_2", "slope"] / run.channels.loc["gauge_1", "slope"]
        assert ratio < 0.8  # the crosshead's stiffness includes the machine's
        assert any("'Crosshead' (crosshead) not used" in warning for warning in run.warnings)


def test_fracture_found_in_every_seed_and_nothing_after_it_analysed(pulls):
    truth, results = pulls
    for run, fits, _ in results:
        assert run.fracture == truth.fracture_index - 1  # the last sample before the drop
        assert set(fits.index) == {(1, "loading")}  # no branch after the peak is fitted
        after = run.samples["branch"].to_numpy()[run.fracture + 1:]
        assert after.size and set(after) == {"after_fracture"}


@pytest.mark.parametrize("mode", ["jump", "freeze", "reverse"])
def test_removed_extensometer_found_in_every_seed(mode):
    truth = PullTruth.for_chain("18x64", extensometer_removed_at=0.9, removal_mode=mode)
    for seed in SEEDS:
        run, _, specimen = analyse(truth, seed)
        removed_at = run.channels.loc["gauge_1", "removed_at"]
        # a frozen channel is cut where it last moved beyond its noise: a few samples early
        assert truth.removal_index - 10 <= removed_at <= truth.removal_index + 2, seed
        assert np.isnan(run.samples["strain"].to_numpy()[removed_at:]).all()
        assert specimen.E0 == pytest.approx(truth.E0, rel=0.01)


def test_strength_figures_match_the_truth(pulls):
    truth, results = pulls
    for run, fits, _ in results:
        strength = specimen_strength(run, fits)
        assert strength.max_force == pytest.approx(truth.max_force, rel=0.005)
        assert strength.strain_at_fracture == pytest.approx(truth.strain_at_fracture, rel=0.01)
        assert strength.yield_force == pytest.approx(truth.offset_yield_force(0.002), rel=0.01)


def test_proof_load_test_gives_the_elongation_at_proof_and_the_set():
    truth = PullTruth.for_chain("18x64", proof_force=320e3, to_fracture=False)
    run, fits, _ = analyse(truth, seed=3, crosshead=False)
    strength = specimen_strength(run, fits, proof_force=320e3)
    assert run.fracture is None and run.single_pull
    assert strength.elongation_at_proof == pytest.approx(truth.elongation_at_proof, rel=0.01)
    assert strength.permanent_set_after_proof == pytest.approx(truth.permanent_set, rel=0.05)


@pytest.mark.parametrize("channel", ["crosshead", "extensometer"])
def test_a_crosshead_alone_gives_its_own_E0_and_says_so(channel):
    truth = PullTruth.for_chain("18x64")
    log = simulate_pull(truth, seed=5)[["time", "force", channel]].rename(
        columns={channel: "gauge_1"})
    run = condition_tensile(log, truth.gauge_length, n_cycles=1,
                            kinds={"gauge_1": channel}, columns={"gauge_1": "Travel"})
    specimen = specimen_stiffness(fit_stiffness(run), single_pull=True)
    warned = [w for w in run.warnings if w.startswith("E0 from the crosshead travel 'Travel'")]
    if channel == "crosshead":  # strain = travel / L, travel = C_crosshead * F
        assert specimen.E0 == pytest.approx(truth.gauge_length / truth.crosshead_compliance,
                                            rel=0.01)
        assert len(warned) == 1
    else:
        assert specimen.E0 == pytest.approx(truth.E0, rel=0.01)
        assert not warned
