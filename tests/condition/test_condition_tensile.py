"""Conditioning of tensile runs: gauges, strain, loop energy, permanent set, bad records."""

from __future__ import annotations

import re

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.tensile import condition_tensile, loop_energy
from pipeline.errors import SignalError
from pipeline.simulate.pull import PullTruth, simulate_pull
from pipeline.simulate.tensile import TensileTruth, simulate_tensile

LOW, HIGH = 1e3, 11e3  # N
STIFFNESS = 1e7  # N/m: 1 mm between LOW and HIGH
SET = 0.2e-3  # m


def constructed_run(shape: str, cycles: int = 3, ramp: int = 100, hold: int = 20,
                    dwell: int = 0) -> pd.DataFrame:
    """Cycles whose force-elongation loops are exact triangles or parallelograms.

    triangle: loading along x = x0 + (F - LOW) / STIFFNESS, unloading straight from the peak
    to x0 + SET: area SET (HIGH - LOW) / 2. parallelogram: the gauges creep by SET during a
    dwell at HIGH, unloading parallel to loading: area SET (HIGH - LOW). Holds at LOW
    between cycles; every cycle leaves a permanent set SET.
    """
    delta = (HIGH - LOW) / STIFFNESS
    forces, elongations = [np.full(hold, LOW)], [np.zeros(hold)]
    x0 = 0.0
    for _ in range(cycles):
        up = np.linspace(LOW, HIGH, ramp, endpoint=False)
        down = np.linspace(HIGH, LOW, ramp, endpoint=False)
        forces += [up, np.full(dwell, HIGH), down, np.full(hold, LOW)]
        if shape == "triangle":
            back = x0 + SET + (down - LOW) * (delta - SET) / (HIGH - LOW)
            creep = np.full(dwell, x0 + delta)
        else:
            back = x0 + SET + (down - LOW) / STIFFNESS
            creep = np.linspace(x0 + delta, x0 + delta + SET, dwell, endpoint=False)
        x0 += SET
        elongations += [x0 - SET + (up - LOW) / STIFFNESS, creep, back, np.full(hold, x0)]
    force, elongation = np.concatenate(forces), np.concatenate(elongations)
    return pd.DataFrame({"time": np.arange(force.size) * 0.1, "force": force,
                         "gauge_1": 1.1 * elongation, "gauge_2": 0.9 * elongation})


def test_loop_energy_of_hand_made_polygons():
    # triangle (0, 0), (2 mm, 1 kN), (1 mm, 0): area 0.5 * 1 mm * 1 kN = 0.5 J, clockwise
    assert loop_energy(np.array([0, 1e3, 0.0]), np.array([0, 2e-3, 1e-3])) == pytest.approx(0.5)
    # unit square traversed counter-clockwise in (x, F): negative
    assert loop_energy(np.array([0, 0, 1.0, 1]), np.array([0, 1.0, 1, 0])) == pytest.approx(-1.0)


@pytest.mark.parametrize(("shape", "dwell", "area"),
                         [("triangle", 0, SET * (HIGH - LOW) / 2),
                          ("triangle", 30, SET * (HIGH - LOW) / 2),
                          ("parallelogram", 30, SET * (HIGH - LOW))])
def test_hysteresis_energy_is_the_loop_area(shape, dwell, area):
    run = condition_tensile(constructed_run(shape, dwell=dwell), gauge_length=0.5,
                            preload=LOW, n_cycles=3)
    np.testing.assert_allclose(run.cycles["hysteresis_energy"], area, rtol=1e-9)
    np.testing.assert_allclose(run.cycles["permanent_set"], SET, rtol=1e-9)
    assert run.cycles["complete"].all()
    np.testing.assert_allclose(run.cycles["peak_force"], HIGH, rtol=1e-3)
    np.testing.assert_allclose(run.cycles["valley_force"], LOW, rtol=1e-9)


def test_gauges_strain_and_disagreement():
    run = condition_tensile(constructed_run("triangle"), gauge_length=0.5)
    samples = run.samples
    np.testing.assert_allclose(samples["elongation"], (samples["gauge_1"] + samples["gauge_2"]) / 2)
    np.testing.assert_allclose(samples["strain"], samples["elongation"] / 0.5)
    np.testing.assert_allclose(samples["gauge_spread"], 0.2 * samples["elongation"], atol=1e-15)
    assert run.gauge_disagreement == pytest.approx(0.2)  # 1.1 x and 0.9 x
    assert str(samples["branch"].dtype) == "category"
    assert run.warnings == []


def test_compression_negative_run_gives_the_same_loops():
    table = constructed_run("parallelogram", dwell=30)
    flipped = table.assign(force=-table["force"], gauge_1=-table["gauge_1"],
                           gauge_2=-table["gauge_2"])
    run = condition_tensile(flipped, gauge_length=0.5, preload=LOW, n_cycles=3)
    assert run.sign == -1
    np.testing.assert_allclose(run.cycles["hysteresis_energy"], SET * (HIGH - LOW), rtol=1e-9)
    np.testing.assert_allclose(run.cycles["permanent_set"], SET, rtol=1e-9)
    np.testing.assert_allclose(run.cycles["peak_force"], HIGH, rtol=1e-3)


def test_simulated_run_matches_its_truth():
    truth = TensileTruth.for_chain("18x64", dwell=10.0)
    run = condition_tensile(simulate_tensile(truth, seed=4), truth.gauge_length,
                            preload=truth.preload, n_cycles=3)
    for cycle in (1, 2, 3):
        row = run.cycles.loc[cycle]
        assert row["hysteresis_energy"] == pytest.approx(truth.hysteresis_energy(cycle), rel=0.03)
        # read to the gauges' division (0.01 mm)
        assert row["permanent_set"] == pytest.approx(truth.permanent_set(cycle), abs=1e-5)
    assert run.gauge_disagreement == pytest.approx(2 * truth.bending, rel=0.05)
    counts = run.samples.groupby(["cycle", "branch"], observed=True).size()
    assert counts.loc[(2, "loading")] > 0.95 * (truth.upper_force - truth.preload) / 100


def test_isolated_missing_samples_are_dropped_with_a_warning():
    table = constructed_run("triangle")
    table.loc[[50, 51, 300], "gauge_2"] = np.nan
    run = condition_tensile(table, gauge_length=0.5)
    assert len(run.samples) == len(table) - 3
    assert "dropped 3 sample(s)" in run.warnings[0]


def test_empty_gauge_column_is_left_out():
    table = constructed_run("triangle").assign(gauge_3=np.nan)
    run = condition_tensile(table, gauge_length=0.5)
    assert "gauge_3" not in run.samples.columns
    assert "gauge_3" in run.warnings[0]


def test_over_range_codes_in_a_gauge_are_left_out_and_the_cycles_stand():
    """A simulated 18x64 test whose second extensometer writes two samples of Bluehill's
    over-range code (21474.83648 mm, 2^31 / 10^5): they are no readings, so the run gives
    the cycles of the same record without them, and says which samples it left out."""
    truth = TensileTruth.for_chain("18x64")
    table = simulate_tensile(truth, seed=4)
    clean = condition_tensile(table.drop([300, 700]), truth.gauge_length,
                              preload=truth.preload, n_cycles=3)
    table.loc[[300, 700], "gauge_2"] = 2**31 / 1e5 * 1e-3
    run = condition_tensile(table, truth.gauge_length, preload=truth.preload, n_cycles=3,
                            columns={"gauge_2": "Strain 2"})
    pd.testing.assert_frame_equal(run.cycles, clean.cycles)
    assert "'Strain 2': 2 sample(s)" in run.warnings[0]
    assert "(sample 300, 700)" in run.warnings[0]


def bad(kind: str) -> pd.DataFrame:
    table = constructed_run("triangle")
    if kind == "nan":
        table.loc[400:409, "force"] = np.nan
    elif kind == "clipping":
        table["gauge_2"] = np.minimum(table["gauge_2"], 0.5 * table["gauge_2"].max())
    elif kind == "columns":
        table = table.drop(columns=["gauge_1", "gauge_2"])
    elif kind == "all_gauges_empty":
        table[["gauge_1", "gauge_2"]] = np.nan
    return table


@pytest.mark.parametrize(
    ("kind", "settings", "column", "words"),
    [
        ("nan", {}, "force", "10 missing values in a row (samples 400 to 409)"),
        ("clipping", {}, "gauge_2", "saturated"),
        ("columns", {}, None, "needs a force column and at least one gauge"),
        ("all_gauges_empty", {}, None, "every gauge column is empty"),
        ("ok", {"preload": 20e3}, "force", "never rises above the preload"),
        ("ok", {"n_cycles": 4}, "force", "found 3 load cycle(s), the test should have 4"),
    ],
)
def test_bad_records_raise_signal_errors_with_a_hint(kind, settings, column, words):
    with pytest.raises(SignalError) as error:
        condition_tensile(bad(kind), gauge_length=0.5, **settings)
    assert words in str(error.value)
    assert error.value.column == column
    assert error.value.hint


@pytest.mark.parametrize("time", ["repeated", "reset", "none"])
def test_time_is_not_needed_for_stiffness(time):
    table = constructed_run("triangle")
    if time == "repeated":
        table.loc[1, "time"] = table.loc[0, "time"]
    elif time == "reset":
        table.loc[200:, "time"] -= table.loc[200, "time"]
    else:
        table = table.drop(columns="time")
    run = condition_tensile(table, gauge_length=0.5, preload=LOW, n_cycles=3)
    reference = condition_tensile(constructed_run("triangle"), gauge_length=0.5, preload=LOW,
                                  n_cycles=3)
    np.testing.assert_array_equal(run.samples["strain"], reference.samples["strain"])
    np.testing.assert_array_equal(run.segmentation.turns, reference.segmentation.turns)


def test_gauge_length_must_be_positive():
    with pytest.raises(ValueError, match="gauge_length"):
        condition_tensile(constructed_run("triangle"), gauge_length=0.0)


def test_channels_all_cut_early_say_where_in_the_refusal():
    """A single pull whose two gauges each run backwards within the first tenth of the
    loading: the refusal says which channel was cut, how and from what force."""
    force = np.linspace(0.0, 100e3, 200)

    def backwards_from(sample):
        return np.where(np.arange(200) < sample, force / 2e8,
                        force[sample - 1] / 2e8 - (force - force[sample - 1]) / 1e8)

    table = pd.DataFrame({"force": force, "gauge_1": backwards_from(14),
                          "gauge_2": backwards_from(18)})
    with pytest.raises(SignalError, match="grows with the force") as caught:
        condition_tensile(table, gauge_length=0.1, n_cycles=1,
                          columns={"gauge_1": "Weg", "gauge_2": "Traverse"})
    said = re.findall(r"; '(\w+)' runs backwards from ([\d.]+) kN on", caught.value.message)
    assert [name for name, _ in said] == ["Weg", "Traverse"]
    for (_, kilonewtons), sample in zip(said, (14, 18), strict=True):  # within two samples
        assert force[sample - 1] <= float(kilonewtons) * 1e3 <= force[sample + 2]


@pytest.mark.parametrize("sign", [1, -1])
def test_gauges_zeroed_at_the_preload_read_as_if_zeroed_from_the_start(sign):
    """The lab zeroes both gauges during the first hold at the preload (sample 10), as an
    MTS controller writes it into the log: the conditioned run is the one never zeroed
    late, and the zeroing is told."""
    reference = constructed_run("triangle")
    table = reference.copy()
    table.loc[:9, "gauge_1"] += 0.8e-3
    table.loc[:9, "gauge_2"] -= 41e-3
    flip = {name: sign * table[name] for name in ("force", "gauge_1", "gauge_2")}
    run = condition_tensile(table.assign(**flip), gauge_length=0.5, preload=LOW, n_cycles=3,
                            columns={"gauge_1": "Weg", "gauge_2": "1470533"})
    expected = condition_tensile(reference.assign(
        **{name: sign * reference[name] for name in flip}), gauge_length=0.5, preload=LOW,
        n_cycles=3)
    np.testing.assert_allclose(run.samples["strain"], expected.samples["strain"], atol=1e-15)
    np.testing.assert_allclose(run.cycles["permanent_set"], SET, rtol=1e-9)
    assert run.channels["zeroed"].all() and not expected.channels["zeroed"].any()
    compression = ["the force is negative as it loads (a compression test, or a machine that "
                   "logs tension negative): forces, elongations and E0 are read in the "
                   "direction of the load, as magnitudes"] if sign < 0 else []
    assert run.warnings == [
        f"'Weg' is zeroed at sample 10 (1 kN, the force holding): it stepped by "
        f"{-sign * 0.8:.4g} mm to zero; its readings before are moved by as much, to join "
        "those after",
        f"'1470533' is zeroed at sample 10 (1 kN, the force holding): it stepped by "
        f"{sign * 41:.4g} mm to zero; its readings before are moved by as much, to join those "
        "after", *compression]


def test_a_gauge_unplugged_to_zero_in_a_loading_is_cut_where_it_dropped():
    """A simulated 18x64 test whose second extensometer drops to a zero reading halfway up
    the first loading and stays there: no zeroing (the force rises), the channel is cut at
    the drop and the other gauge carries the cycles."""
    truth = TensileTruth.for_chain("18x64")
    table = simulate_tensile(truth, seed=4)
    drop = int(np.argmax(table["force"].to_numpy() > (truth.preload + truth.upper_force) / 2))
    table.loc[drop:, "gauge_2"] = np.round(np.random.default_rng(1).normal(
        0.0, 2e-6, len(table) - drop) / 1e-5) * 1e-5
    run = condition_tensile(table, truth.gauge_length, preload=truth.preload, n_cycles=3)
    assert not any("zeroed" in warning for warning in run.warnings)
    assert run.channels.loc["gauge_2", "removed_at"] == drop
    assert np.isnan(run.channel_strains["gauge_2"].to_numpy()[drop:]).all()


def bluehill_pull(seed: int = 2) -> tuple[pd.DataFrame, PullTruth]:
    """A simulated 18x64 pull as a Bluehill export without an extensometer logs it: the
    crosshead's ``Extension`` (gauge_1) and the method's ``Tensile strain`` (strain_1), that
    extension over 50 mm printed to 6 decimals."""
    truth = PullTruth.for_chain("18x64")
    log = simulate_pull(truth, seed)
    crosshead = log["crosshead"].to_numpy()
    table = pd.DataFrame({"time": log["time"], "force": log["force"], "gauge_1": crosshead,
                          "strain_1": np.round(crosshead / 0.05, 6)})
    return table, truth


BLUEHILL = {"kinds": {"gauge_1": "crosshead", "strain_1": "extensometer"},
            "columns": {"gauge_1": "Extension", "strain_1": "Tensile strain"}}


def test_a_strain_worked_out_from_the_crosshead_is_the_crosshead_whatever_its_name():
    # 'Tensile strain' is named like an extensometer's strain; its readings are the
    # crosshead's over 50 mm, and E0 from it includes the machine
    table, _ = bluehill_pull()
    run = condition_tensile(table, None, n_cycles=1, **BLUEHILL)
    assert run.channels.loc["strain_1", "kind"] == "crosshead"
    assert run.channels.loc["strain_1", "used"]
    assert ("channel 'Tensile strain' is 'Extension' (crosshead) over 50 mm to the last digit: "
            "a strain worked out from it, not measured by itself; E0 from it is the "
            "crosshead's") in run.warnings
    assert any(warning.startswith("E0 from the crosshead travel 'Tensile strain'")
               for warning in run.warnings)


def test_an_extensometers_strain_that_turns_into_the_crosshead_is_cut_where_it_does():
    # a real Bluehill export: once the extensometer was taken off, the software went on
    # writing the crosshead's Extension over 26 mm in the extensometer's column; read as
    # the extensometer's, its strain at the maximum force was the crosshead's
    truth = PullTruth.for_chain("18x64")
    log = simulate_pull(truth, 2)
    crosshead = np.round(log["crosshead"].to_numpy(), 7)
    strain = np.round(log["extensometer"].to_numpy() / truth.gauge_length, 6)
    strain[900:] = np.round((crosshead[900:] - 0.004) / truth.gauge_length, 6)
    table = pd.DataFrame({"time": log["time"], "force": log["force"], "gauge_1": crosshead,
                          "strain_1": strain})
    run = condition_tensile(table, truth.gauge_length, n_cycles=1, **BLUEHILL)
    assert run.channels.loc["strain_1", "removed_at"] == 900
    assert run.channels.loc["strain_1", "removal"] == "turns into 'Extension' over 320 mm"
    assert any(warning.startswith("channel 'Tensile strain' turns into 'Extension' over 320 mm"
                                  " at ") for warning in run.warnings)
    # over another length than the gauge's, the two agree by chance (proportional travel)
    run = condition_tensile(table, 0.9 * truth.gauge_length, n_cycles=1, **BLUEHILL)
    assert run.channels.loc["strain_1", "removal"] != "turns into 'Extension' over 320 mm"


def test_a_true_strain_worked_out_from_the_crosshead_is_used_as_its_engineering_strain():
    # with no gauge length for 'Extension', the file's true strain ln(1 + extension / 50 mm)
    # is what there is: E0 from it is E0 from the extension over 50 mm
    table, _ = bluehill_pull()
    engineering = condition_tensile(table, None, n_cycles=1, **BLUEHILL)
    crosshead = table["gauge_1"].to_numpy()
    table = table.assign(strain_1=np.round(np.log1p(crosshead / 0.05), 8))
    run = condition_tensile(table, None, n_cycles=1, **BLUEHILL)
    assert ("channel 'Tensile strain' is ln(1 + 'Extension' (crosshead) over 50 mm) to the "
            "last digit: a strain worked out from it, not measured by itself; used as exp() - "
            "1 of it, the engineering strain; E0 from it is the crosshead's") in run.warnings
    assert run.channels.loc["strain_1", "slope"] == pytest.approx(
        engineering.channels.loc["strain_1", "slope"], rel=1e-4)


TESTSUITE = {"kinds": {"gauge_1": "crosshead", "gauge_2": "gauge"},
             "columns": {"gauge_1": "Crosshead", "gauge_2": "Extension"}}


def test_a_length_column_repeating_the_crosshead_is_left_out_and_e0_is_the_crosshead_s():
    # MTS TestSuite writes 'Extension' beside 'Crosshead', the same readings when no
    # extensometer is fitted; named as no kind, it was preferred to the crosshead, so that
    # E0 came from the crosshead without a word of the machine's compliance
    table, _ = bluehill_pull()
    table = table.drop(columns="strain_1").assign(gauge_2=table["gauge_1"])
    run = condition_tensile(table, 0.05, n_cycles=1, **TESTSUITE)
    assert run.channels["used"].to_dict() == {"gauge_1": True, "gauge_2": False}
    assert run.channels.loc["gauge_2", "kind"] == "crosshead"
    assert ("channel 'Extension' moves with 'Crosshead' (crosshead) to the last digit, its "
            "zero and sign aside: one transducer written twice; not used") in run.warnings
    assert any(warning.startswith("E0 from the crosshead travel 'Crosshead'")
               for warning in run.warnings)


def test_a_strain_worked_out_from_a_repeated_column_is_the_source_s():
    table, _ = bluehill_pull()
    table = table.assign(gauge_2=table["gauge_1"])
    run = condition_tensile(table, 0.05, n_cycles=1,
                            kinds={**TESTSUITE["kinds"], "strain_1": "extensometer"},
                            columns={**TESTSUITE["columns"], "strain_1": "Tensile strain"})
    assert run.channels["used"].to_dict() == {"gauge_1": True, "gauge_2": False,
                                              "strain_1": False}
    assert run.channels.loc["strain_1", "kind"] == "crosshead"


def test_a_strain_worked_out_from_a_channel_used_itself_is_left_out():
    table, _ = bluehill_pull()
    run = condition_tensile(table, 0.05, n_cycles=1, **BLUEHILL)
    assert run.channels["used"].to_dict() == {"gauge_1": True, "strain_1": False}
    assert [warning for warning in run.warnings if "Tensile strain" in warning] == [
        "channel 'Tensile strain' is 'Extension' (crosshead) over 50 mm to the last digit: a "
        "strain worked out from it, not measured by itself; not used"]


def test_a_run_sheets_gauge_length_unlike_the_files_is_warned_of():
    table, _ = bluehill_pull()
    run = condition_tensile(table, 0.0512, n_cycles=1, **BLUEHILL)
    assert ("the file divides 'Extension' by 50 mm for its strain 'Tensile strain', the run "
            "sheet's gauge_length_mm is 51.2: E0 scales with the gauge length, check which is "
            "right") in run.warnings


def test_a_strain_that_divides_by_no_gauges_length_is_warned_of():
    # a real export's 'Strain (%)' reads 8 where the extension is 0.00188 mm: over 0.0235 mm
    table, _ = bluehill_pull()
    table["strain_1"] = np.round(table["gauge_1"] / 2.35e-5, 2)
    run = condition_tensile(table, None, n_cycles=1, **BLUEHILL)
    assert ("no gauge is 0.0235 mm long: the numbers of 'Tensile strain' are likely off by a "
            "power of ten (a ratio written as %, a lost decimal mark); check its unit in the "
            "export") in run.warnings
    run = condition_tensile(bluehill_pull()[0], None, n_cycles=1, **BLUEHILL)
    assert not any(warning.startswith("no gauge is") for warning in run.warnings)


@pytest.mark.parametrize(("end", "said"), [(0.75, True), (0.02, False), (0.99, False)])
def test_a_single_pull_that_falls_with_no_fracture_found_says_so(end, said):
    # a real steel pull's record cut at 75 % of its maximum while necking gave no fracture
    # and no word of it; one stopped at its maximum (it ends within 3 % of it), or brought
    # back to nothing (a proof-load test, unloaded), needs none
    rise = np.linspace(0.0, 30e3, 300)
    fall = np.linspace(30e3, end * 30e3, 100)
    force = np.concatenate([rise, fall])
    elongation = np.arange(force.size) * 1e-5  # necking on, or the test stopped
    if end < 0.1:  # unloaded: the elastic part comes back
        elongation[300:] = elongation[299] - (30e3 - fall) / 1e7
    table = pd.DataFrame({"force": force, "gauge_1": elongation})
    run = condition_tensile(table, gauge_length=0.1, n_cycles=1)
    notes = [text for text in run.warnings if text.startswith("no fracture found")]
    assert notes == ([f"no fracture found: the force ends at {end * 30:.4g} kN, {end:.0%} of "
                      "its maximum (30 kN), after falling with no sudden drop (a record cut "
                      "before the break, or a test stopped while the force fell): nothing is "
                      "given at fracture"] if said else [])


@pytest.mark.parametrize("gives_way", [True, False])
def test_a_single_pull_that_gives_way_has_no_unloading(gives_way):
    # a real rope pull (MTS, 10 Hz): its crimp slipped, the force falling from 222 N to 22 N
    # while the crosshead ran on by 4 mm; the fall was fitted as an unloading, E0 -5.1 kN,
    # with a loop energy and a permanent set of 8 mm. A proof-load test brought back down
    # (its elongation returning by the elastic part) keeps its unloading.
    rise = np.linspace(0.0, 222.0, 880)
    fall = np.linspace(222.0, 22.0, 760)
    force = np.concatenate([rise, fall, np.full(20, 22.0)])
    up = rise / 51.0e3  # 51 N/mm [m]
    back = up[-1] + (4e-3 if gives_way else -3e-3) * np.linspace(0.0, 1.0, 760)
    elongation = np.concatenate([up, back, np.full(20, back[-1])])
    table = pd.DataFrame({"time": np.arange(force.size) * 0.1, "force": force,
                          "gauge_1": elongation})
    run = condition_tensile(table, gauge_length=0.2, n_cycles=1)
    branches = set(run.samples["branch"])
    assert ("unloading" in branches) is not gives_way
    assert ("beyond_peak" in branches) is gives_way
    cycle = run.cycles.iloc[0]
    assert bool(np.isnan(cycle["permanent_set"])) is gives_way
    assert bool(np.isnan(cycle["hysteresis_energy"])) is gives_way
    # ending at a tenth of its maximum, a pull that gave way was not unloaded: no fracture
    noted = any(text.startswith("no fracture found") for text in run.warnings)
    assert noted is gives_way
    if not gives_way:  # the valley's median holds the last steps of the fall too
        assert cycle["permanent_set"] == pytest.approx(up[-1] - 3e-3, abs=0.02e-3)


def test_a_record_too_short_to_compare_its_gauges_says_so():
    # a real Tokyo Sokki logger's sample file: three rows of numbers, two gauges; told that
    # no gauge grew with the force, though both did
    table = pd.DataFrame({"force": [0.0, 2900.0, 2900.0], "gauge_1": [0.0, 8e-5, 8e-5],
                          "gauge_2": [0.0, 5.6e-4, 6.1e-4]})
    with pytest.raises(SignalError, match="the first loading holds 2 samples: too few to tell "
                                          "which gauge channel grows with the force"):
        condition_tensile(table, gauge_length=0.05, n_cycles=1)
