"""Where a specimen's elongations count from: the first loading's start, or the lab's zero."""

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.tensile import condition_tensile
from pipeline.fit.stiffness import fit_stiffness, specimen_stiffness
from pipeline.fit.strength import specimen_strength
from pipeline.simulate.pull import PullTruth, simulate_pull

LOW, HIGH, STIFFNESS = 1e3, 11e3, 20e6  # N, N, N/m


def test_elongations_count_from_the_start_of_the_test_not_from_the_gauges_zero():
    # a crosshead position read from the machine's own zero (45 mm when the test starts):
    # the specimen gains no 45 mm, and its E0 does not change
    truth = PullTruth.for_chain("18x64")
    log = simulate_pull(truth, seed=4)[["time", "force", "extensometer"]].rename(
        columns={"extensometer": "gauge_1"})
    figures = []
    for offset in (0.0, 0.045):
        run = condition_tensile(log.assign(gauge_1=log["gauge_1"] + offset),
                                truth.gauge_length, n_cycles=1,
                                kinds={"gauge_1": "crosshead"}, columns={"gauge_1": "Position"})
        fits = fit_stiffness(run)
        figures.append((specimen_stiffness(fits, single_pull=True).E0,
                        specimen_strength(run, fits)))
    (E0, zeroed), (E0_offset, offset) = figures
    assert E0_offset == pytest.approx(E0, rel=1e-9)
    assert offset.elongation_at_max_force == pytest.approx(zeroed.elongation_at_max_force,
                                                           abs=1e-9)
    assert offset.elongation_at_fracture == pytest.approx(truth.strain_at_fracture
                                                          * truth.gauge_length, rel=0.01)


def test_a_gauge_the_lab_zeroed_at_the_preload_counts_from_that_zero():
    # the force rises to the preload while the gauge takes up 0.2 mm of slack; the lab
    # zeroes it during the hold, then pulls: the elongation at the peak is the pull's alone
    approach = np.linspace(0.0, LOW, 20, endpoint=False)
    up, down = np.linspace(LOW, HIGH, 100), np.linspace(HIGH, 0.0, 30)
    force = np.concatenate([approach, np.full(30, LOW), up, down])
    gauge = np.concatenate([np.linspace(0.0, 0.2e-3, 20, endpoint=False), np.full(20, 0.2e-3),
                            np.zeros(10), (up - LOW) / STIFFNESS,
                            (HIGH - LOW) / STIFFNESS + (down - HIGH) / STIFFNESS])
    log = pd.DataFrame({"time": 0.1 * np.arange(force.size), "force": force, "gauge_1": gauge})
    run = condition_tensile(log, gauge_length=0.5, n_cycles=1, columns={"gauge_1": "Weg"})
    assert run.channels.loc["gauge_1", "zeroed"] and run.segmentation.turns[0][0] < 40
    strength = specimen_strength(run, fit_stiffness(run))
    assert strength.elongation_at_max_force == pytest.approx((HIGH - LOW) / STIFFNESS,
                                                             rel=1e-9)
