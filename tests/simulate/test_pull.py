"""The virtual single pull: its truth is what its docstring says, and its logs read back."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.ingest import read_table
from pipeline.simulate.export import write_pull_table
from pipeline.simulate.pull import (
    REMOVAL_JUMP,
    PullTruth,
    pull_curve,
    simulate_pull,
)
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si

#: Noise-free and unquantised: the log shows the model itself.
EXACT = {"force_noise": 0.0, "extensometer_noise": 0.0, "extensometer_resolution": 0.0,
         "crosshead_noise": 0.0, "crosshead_resolution": 0.0}

KN = 1e3


def bench(**settings) -> PullTruth:
    return PullTruth.for_chain("18x64", **settings)


def dense(truth: PullTruth, rate: float = 200.0):
    """Noise-free channels at `rate` samples per second over the whole test."""
    time = np.arange(0.0, truth.sample_times()[-1], 1 / rate)
    return (time, *pull_curve(truth, time))


def test_for_chain_takes_documented_defaults():
    truth = bench()
    assert truth.E0 == pytest.approx(table_1()["18x64"].E0_exp_kgf * 9.80665)  # Table 1
    assert truth.max_force == pytest.approx(1.1 * 410 * KN)
    assert truth.yield_force == pytest.approx(0.65 * truth.max_force)
    assert truth.preload == pytest.approx(to_si(1000, "kgf"))
    assert truth.gauge_length == pytest.approx(5 * 0.064)
    assert truth.free_length == pytest.approx(9 * 0.064)
    assert 1000 < truth.sample_times().size < 5000


def test_log_is_canonical_and_reproducible():
    truth = bench()
    log = simulate_pull(truth, seed=7)
    assert list(log.columns) == ["time", "force", "extensometer", "crosshead"]
    assert all(log.dtypes == np.float64)
    assert np.all(np.diff(log["time"]) > 0)
    assert log.equals(simulate_pull(truth, seed=7))
    assert not log.equals(simulate_pull(truth, seed=8))


def test_linear_region_has_slope_E0_and_the_toe_is_softer():
    truth = bench(**EXACT)
    _, force, extensometer, _ = dense(truth)
    strain = extensometer / truth.gauge_length
    rising = np.arange(force.size) < np.argmax(force)
    linear = rising & (force > truth.toe_force) & (force < truth.yield_force)
    slope, intercept = np.polyfit(strain[linear], force[linear], 1)
    assert slope == pytest.approx(truth.E0, rel=1e-9)
    toe = rising & (force < truth.preload + (truth.toe_force - truth.preload) / 3)
    assert np.polyfit(strain[toe], force[toe], 1)[0] < 0.8 * truth.E0
    above = rising & (force > 1.05 * truth.yield_force)
    assert np.all(force[above] < slope * strain[above] + intercept)  # it bends away


def test_the_slope_falls_continuously_from_E0_to_zero_at_the_maximum():
    truth = bench()
    e = np.linspace(truth.yield_strain, truth.fracture_strain, 200001)
    slope = np.gradient(truth.force_at(e), e)
    assert slope[0] == pytest.approx(truth.E0, rel=1e-3)
    assert np.all(np.diff(slope) <= 1e-6 * truth.E0)
    assert e[np.argmax(truth.force_at(e))] == pytest.approx(truth.max_force_strain, abs=1e-6)
    assert truth.force_at(truth.max_force_strain) == pytest.approx(truth.max_force)
    assert truth.force_at(truth.fracture_strain) == pytest.approx(truth.fracture_force)


def test_the_curve_peaks_at_the_strain_at_max_force():
    truth = bench(**EXACT)
    _, force, extensometer, _ = dense(truth)
    peak = np.argmax(force)
    assert force[peak] == pytest.approx(truth.max_force, rel=1e-6)
    strain = extensometer / truth.gauge_length
    assert strain[peak] == pytest.approx(truth.strain_at_max_force, abs=2e-4)


def test_machine_is_30_percent_of_the_crosshead_compliance():
    truth = bench(**EXACT)
    assert truth.machine_share == 0.3
    _, force, extensometer, crosshead = dense(truth)
    rising = np.arange(force.size) < np.argmax(force)
    linear = rising & (force > truth.toe_force) & (force < truth.yield_force)
    compliance = np.polyfit(force[linear], crosshead[linear], 1)[0]
    assert compliance == pytest.approx(truth.crosshead_compliance, rel=1e-9)
    specimen = np.polyfit(force[linear], extensometer[linear], 1)[0] * (
        truth.free_length / truth.gauge_length)
    assert 1 - specimen / compliance == pytest.approx(0.3, rel=1e-9)


def test_crosshead_runs_at_constant_speed():
    truth = bench(**EXACT)
    log = simulate_pull(truth, seed=0)
    speed = np.diff(log["crosshead"]) / np.diff(log["time"])
    np.testing.assert_allclose(speed, truth.crosshead_speed, rtol=1e-4)


def test_fracture_drops_the_force_within_a_few_samples():
    truth = bench(**EXACT)
    log = simulate_pull(truth, seed=0)
    index = truth.fracture_index
    force, strain = log["force"].to_numpy(), log["extensometer"].to_numpy() / truth.gauge_length
    assert force[index - 1] == pytest.approx(truth.fracture_force, rel=2e-3)
    assert strain[index - 1] == pytest.approx(truth.strain_at_fracture, abs=1e-3)
    assert force[index] < force[index - 1]
    after = force[index + truth.fracture_samples:]
    np.testing.assert_allclose(after, truth.fracture_residue * truth.max_force)
    assert truth.elongation_at_fracture == pytest.approx(
        truth.strain_at_fracture * truth.gauge_length)
    assert np.all(force[:index] > 0.02 * truth.max_force)


def test_offset_yield_force_is_where_the_curve_leaves_the_offset_line():
    truth = bench(**EXACT)
    _, force, extensometer, _ = dense(truth, rate=2000.0)
    strain = extensometer / truth.gauge_length
    rising = np.arange(force.size) < np.argmax(force)
    linear = rising & (force > truth.toe_force) & (force < truth.yield_force)
    intercept = np.mean(strain[linear] - force[linear] / truth.E0)
    for offset in (0.001, 0.002, 0.005):
        gap = force - truth.E0 * (strain - intercept - offset)
        crossing = np.flatnonzero(rising[1:] & (gap[:-1] > 0) & (gap[1:] <= 0))[0]
        measured = np.interp(0.0, gap[[crossing + 1, crossing]], force[[crossing + 1, crossing]])
        assert truth.offset_yield_force(offset) == pytest.approx(measured, rel=1e-5)
    assert truth.yield_force < truth.offset_yield_force(0.002) < truth.max_force


def test_proof_load_test_holds_unloads_and_keeps_a_set():
    truth = bench(proof_force=320 * KN, to_fracture=False, **EXACT)
    time, force, extensometer, _ = dense(truth)
    hold = (time >= truth.event_time("hold")) & (time < truth.event_time("unload"))
    np.testing.assert_allclose(force[hold], truth.proof_force)
    np.testing.assert_allclose(extensometer[hold], truth.elongation_at_proof)
    assert np.ptp(time[hold]) == pytest.approx(truth.proof_hold, abs=0.01)
    log = simulate_pull(truth, seed=0)
    assert log["force"].iloc[-1] == pytest.approx(truth.preload, abs=2 * KN)
    ends = pull_curve(truth, np.array([truth.event_time("unload") + 1e3]))
    assert ends[0][0] == pytest.approx(truth.preload)
    assert ends[1][0] == pytest.approx(truth.permanent_set)
    assert truth.permanent_set > truth.slack  # some plastic strain: the proof is above F_y
    assert truth.fracture_index is None and truth.max_force_time is None


def test_proof_then_fracture_reloads_on_the_elastic_line():
    truth = bench(proof_force=320 * KN, **EXACT)
    time, force, extensometer, _ = dense(truth)
    reload = (time > truth.event_time("unload")) & (time < truth.event_time("pull"))
    after = reload & (force > truth.preload + 10 * KN)
    slope = np.polyfit(extensometer[after] / truth.gauge_length, force[after], 1)[0]
    assert slope == pytest.approx(truth.E0, rel=1e-9)
    assert force.max() == pytest.approx(truth.max_force, rel=1e-6)
    assert simulate_pull(truth, 0)["force"].iloc[truth.fracture_index - 1] == pytest.approx(
        truth.fracture_force, rel=2e-3)


@pytest.mark.parametrize("mode", ["jump", "freeze", "reverse"])
def test_removed_extensometer_misbehaves_from_its_index(mode):
    truth = bench(extensometer_removed_at=0.95, removal_mode=mode)
    log = simulate_pull(truth, seed=4)
    index = truth.removal_index
    force = pull_curve(truth, truth.sample_times())[0]
    assert force[index - 1] < 0.95 * truth.max_force <= force[index] == truth.removal_force
    _, true_extensometer, _ = pull_curve(truth, log["time"].to_numpy())
    reading = log["extensometer"].to_numpy()
    np.testing.assert_allclose(reading[:index], true_extensometer[:index], atol=10e-6)
    last, after = reading[index - 1], reading[index:]
    if mode == "jump":
        assert np.all(after - last > 0.5 * REMOVAL_JUMP)
    elif mode == "freeze":
        assert np.all(np.abs(after - last) < 10e-6)
        assert true_extensometer[-1] - last > 0.01  # the specimen went on stretching
    else:
        assert np.all(np.diff(after) <= 0) and after[-1] == pytest.approx(-last)
    assert np.argmax(log["force"].to_numpy()) > index  # removed before the maximum


def test_repeated_first_time_and_strain_channel():
    truth = bench(repeated_first_time=True, strain_channel=True)
    log = simulate_pull(truth, seed=3)
    assert list(log.columns) == ["time", "force", "extensometer_strain", "crosshead"]
    assert log["time"].iloc[0] == log["time"].iloc[1] == 0.0
    assert np.all(np.diff(log["time"].iloc[1:]) > 0)
    assert len(log) == truth.sample_times().size == bench().sample_times().size + 1
    plain = simulate_pull(truth.with_(strain_channel=False), seed=3)
    np.testing.assert_allclose(log["extensometer_strain"],
                               plain["extensometer"] / truth.gauge_length)


def test_summary_is_json_ready():
    summary = bench(proof_force=320 * KN, extensometer_removed_at=0.9).summary()
    assert summary["offset_yield_force_N"] == bench().offset_yield_force(0.002)
    assert all(isinstance(value, float | int) for value in summary.values())


@pytest.mark.parametrize(
    "settings",
    [{"E0": -1.0}, {"yield_force": 500 * KN}, {"max_force_strain": 0.01},
     {"fracture_strain": 0.05}, {"neck_drop": 1.0}, {"machine_share": 1.0},
     {"free_length": 0.1}, {"proof_force": 460 * KN}, {"to_fracture": False},
     {"extensometer_removed_at": 1.2}, {"removal_mode": "fly"},
     {"proof_force": 320 * KN, "extensometer_removed_at": 0.5}, {"force_noise": -1.0}],
)
def test_invalid_settings_raise(settings):
    with pytest.raises(ValueError):
        bench(**settings)


def test_chain_without_defaults_needs_them():
    with pytest.raises(ValueError, match="give E0"):
        PullTruth.for_chain("34x126")
    with pytest.raises(ValueError, match="give max_force"):
        PullTruth.for_chain("13x50")
    roller = PullTruth.for_chain("16B", E0=5e6)
    assert roller.max_force == pytest.approx(1.1 * to_si(60, "kN"), rel=0.2)


# -- the writer ----------------------------------------------------------------------------


@pytest.fixture(scope="module")
def logs() -> dict[str, pd.DataFrame]:
    truth = bench(sample_rate=5.0)
    return {"mm": simulate_pull(truth, seed=2),
            "strain": simulate_pull(truth.with_(strain_channel=True, repeated_first_time=True),
                                    seed=2)}


LAYOUTS = [
    # (log, write_pull_table settings, encoding, header lines)
    ("mm", {}, "utf-8", ["time [s],force [kN],extensometer [mm],crosshead [mm]"]),
    ("strain", {}, "utf-8", ["time [s],force [kN],strain [%],crosshead [mm]"]),
    ("mm", {"layout": "european"}, "cp1250",
     ["Czas [s];Siła [kN];Ekstensometr [mm];Trawersa [mm]"]),
    ("strain", {"layout": "european"}, "cp1250",
     ["Czas [s];Siła [kN];Odkształcenie [%];Trawersa [mm]"]),
    ("mm", {"layout": "european", "language": "de"}, "latin-1",
     ["Zeit [s];Standardkraft [kN];Feindehnung [mm];Traversenweg [mm]"]),
    ("strain", {"layout": "european", "language": "de"}, "latin-1",
     ["Zeit [s];Standardkraft [kN];Dehnung [%];Traversenweg [mm]"]),
    ("strain", {"layout": "machine", "preamble": [("Text Inputs", 'Specimen label,"A"')]},
     "ascii", ['Text Inputs : Specimen label,"A"', "", "Time,Extension,Load,Strain 1",
               "(sec),(mm),(kN),(%)"]),
    ("mm", {"layout": "machine"}, "ascii",
     ["Time,Extension,Load,Strain 1", "(sec),(mm),(kN),(mm)"]),
    ("strain", {"layout": "machine", "language": "de",
                "preamble": [("Allgemein", 'Prüfer,"Müller"')]}, "latin-1",
     ['Allgemein : Prüfer,"Müller"', "", "Zeit;Traversenweg;Last;Dehnung 1",
      "(sec);(mm);(kN);(%)"]),
    ("strain", {"layout": "machine", "quote": True}, "ascii",
     ['"Time","Extension","Load","Strain 1"', '"(sec)","(mm)","(kN)","(%)"']),
]


@pytest.mark.parametrize(("log", "settings", "encoding", "header"), LAYOUTS)
def test_layouts_write_their_headers_and_read_back(tmp_path, logs, log, settings, encoding,
                                                   header):
    table = logs[log]
    path = write_pull_table(table, tmp_path / "run.csv", **settings)
    machine = settings.get("layout") == "machine"
    lines = path.read_bytes().decode(encoding).split("\r\n" if machine else "\n")
    assert lines[:len(header)] == header
    assert len(lines) == len(header) + len(table) + 1  # and the last line end
    if settings.get("quote"):
        assert lines[len(header)].startswith('"0","')
    # strain columns in % are left to the reader's own tests; rows and force are checked here
    read, meta = read_table(path, strict=log == "mm")
    assert len(read) == len(table)
    np.testing.assert_allclose(read["force"], table["force"], rtol=0, atol=1e-3)
    np.testing.assert_allclose(read["time"], table["time"], rtol=0, atol=1e-9)
    if log == "mm":
        assert read.shape[1] == 4
        gauges = np.sort(read[["gauge_1", "gauge_2"]].to_numpy(), axis=1)
        expected = np.sort(table[["extensometer", "crosshead"]].to_numpy(), axis=1)
        np.testing.assert_allclose(gauges, expected, rtol=0, atol=1e-9)


def test_machine_layout_writes_crlf_and_the_crosshead_first(tmp_path, logs):
    path = write_pull_table(logs["mm"], tmp_path / "m.csv", layout="machine", length_unit="in",
                            force_unit="lbf")
    raw = path.read_bytes()
    assert raw.count(b"\r\n") == raw.count(b"\n")
    read = pd.read_csv(path, skiprows=[1])
    np.testing.assert_allclose(read["Extension"] * 0.0254, logs["mm"]["crosshead"], atol=1e-9)
    assert len(read) == len(logs["mm"])
    np.testing.assert_allclose(read["Load"] * 4.4482216152605, logs["mm"]["force"], atol=3e-3)


def test_strain_is_written_in_percent(tmp_path, logs):
    path = write_pull_table(logs["strain"], tmp_path / "s.csv")
    read = pd.read_csv(path)
    np.testing.assert_allclose(read["strain [%]"] / 100, logs["strain"]["extensometer_strain"],
                               rtol=0, atol=1e-12)


def test_without_crosshead_and_as_xlsx(tmp_path, logs):
    table = logs["mm"].drop(columns="crosshead")
    path = write_pull_table(table, tmp_path / "x.xlsx", layout="xlsx")
    read = pd.read_excel(path, engine="openpyxl")
    assert list(read.columns) == ["time [s]", "force [kN]", "extensometer [mm]"]
    np.testing.assert_allclose(read["extensometer [mm]"] / 1000, table["extensometer"])


def test_written_files_are_reproducible(tmp_path):
    truth = bench(strain_channel=True, extensometer_removed_at=0.9, repeated_first_time=True)
    first = write_pull_table(simulate_pull(truth, seed=11), tmp_path / "a.csv",
                             layout="machine", quote=True)
    second = write_pull_table(simulate_pull(truth, seed=11), tmp_path / "b.csv",
                              layout="machine", quote=True)
    assert first.read_bytes() == second.read_bytes()


@pytest.mark.parametrize(
    ("settings", "words"),
    [({"layout": "tdms"}, "layout"), ({"layout": "machine", "language": "pl"}, "language"),
     ({"layout": "european", "language": "en"}, "language"), ({"force_unit": "kp"}, "force_unit")],
)
def test_bad_writer_settings_raise(tmp_path, logs, settings, words):
    with pytest.raises(ValueError, match=words):
        write_pull_table(logs["mm"], tmp_path / "x.csv", **settings)
