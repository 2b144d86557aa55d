"""Single pulls through a whole campaign, in the layouts real machines write.

Each run's E0 is compared with an independent least-squares slope of force over the
extensometer's strain between 10 % and 40 % of the maximum force, computed from the
file parsed here with pandas (or from the simulated log), never through chainbench's
readers: within 5 %, and never from an average of different kinds of channel.
"""

from __future__ import annotations

import dataclasses
import re
import shutil
import textwrap

import numpy as np
import pandas as pd
import pytest

from pipeline.campaign import process_campaign
from pipeline.simulate.pull import PullTruth, simulate_pull
from pipeline.store.netcdf import read_dataset

GERMAN = "AschenPhoenix__Simulation_mit_Python__Specimen_RawData_1.csv"


def independent_slope(force: np.ndarray, strain: np.ndarray) -> float:
    """Least-squares slope of force over strain between 10 % and 40 % of the maximum force,
    on the loading (the samples up to the maximum)."""
    loading = np.arange(force.size) <= np.argmax(force)
    inside = loading & (force >= 0.1 * force.max()) & (force <= 0.4 * force.max())
    return float(np.polyfit(strain[inside], force[inside], 1)[0])


def campaign(folder, file: str, extra: str = "", chain: str = 'catalog = "18x64"') -> None:
    (folder / "campaign.toml").write_text(textwrap.dedent(f"""\
        [campaign]
        id = "{folder.name}"
        [chains.c]
        {chain}
        [[runs]]
        id = "P1"
        kind = "tensile"
        file = "{file}"
        chain = "c"
        cycles = 1
        """) + extra, encoding="utf-8")


def processed(folder, tmp_path):
    result = process_campaign(folder, tmp_path / "processed" / folder.name)
    assert result.ok, [failure.message for failure in result.failures]
    return read_dataset(result.output / "P1.nc"), result.warnings.get("P1", [])


@pytest.mark.realdata
def test_german_bluehill_single_pull(realdata, tmp_path):
    folder = tmp_path / "german"
    folder.mkdir()
    shutil.copy(realdata / GERMAN, folder / GERMAN)
    campaign(folder, GERMAN, chain="")  # a specimen of 3.45 mm^2, no catalogue chain
    run, warnings = processed(folder, tmp_path)
    table = pd.read_csv(realdata / GERMAN, sep=";", decimal=",", skiprows=[0, 1, 2, 3, 5])
    force, strain = table["Last"].to_numpy() * 1e3, table["Dehnung 1"].to_numpy() / 100
    expected = independent_slope(force, strain)
    assert float(run["specimen_E0"]) == pytest.approx(expected, rel=0.05)
    assert run["channel_column"].values[run["channel_used"].values == 1].tolist() == [
        "Dehnung 1"]
    assert any("'Traversenweg'" in warning and "not used" in warning for warning in warnings)
    assert any("'Dehnung 1' runs backwards at 5.262 kN" in warning for warning in warnings)
    assert float(run["max_force"]) == pytest.approx(force.max())
    # the first sudden drop: 8.230 kN then 7.849 kN at 186.95 s (row 1870 of the data)
    assert int(run["fracture_sample"]) == 1869 and float(run["fracture_force"]) == 8230.0


def polish_bluehill(log: pd.DataFrame, gauge_length: float) -> bytes:
    """A Polish Bluehill export as the machine writes it: cp1250, ';', every number quoted."""
    lines = ['Test : Tempo 1;"15,00000";mm/min',
             'Właściwości próbki : Etykietka próbki;"18x64-1"', "",
             "Godzina;Przemieszczenie;Obciążenie;Odkształcenie 1", "(s);(mm);(kN);(mm/mm)"]
    for row in log.itertuples():
        values = (f"{row.time:.5f}", f"{row.crosshead * 1e3:.5f}", f"{row.force / 1e3:.5f}",
                  f"{row.extensometer / gauge_length:.8f}")
        lines.append(";".join(f'"{value.replace(".", ",")}"' for value in values))
    return ("\r\n".join(lines) + "\r\n").encode("cp1250")


def catman(log: pd.DataFrame, gauge_length: float) -> bytes:
    """An HBM catman ASCII export: tab, decimal comma, units in the names row."""
    lines = ["Datei: zugversuch.bin", "",
             "Zeit  1 - Standardmessrate [s]\tKraft [kN]\tMaytec [mm]\t"
             "Standardwegaufnehmer [mm]"]
    for row in log.itertuples():
        values = (f"{row.time:.4f}", f"{row.force / 1e3:.4f}", f"{row.extensometer * 1e3:.5f}",
                  f"{row.crosshead * 1e3:.5f}")
        lines.append("\t".join(value.replace(".", ",") for value in values))
    return ("\r\n".join(lines) + "\r\n").encode("latin-1")


@pytest.mark.parametrize(("writer", "extra"), [
    (polish_bluehill, ""),
    (catman, "gauge_length_mm = 320\n"),
])
def test_machine_layouts_with_extensometer_and_crosshead(tmp_path, writer, extra):
    truth = PullTruth.for_chain("18x64", extensometer_removed_at=0.9, removal_mode="reverse",
                                repeated_first_time=True)
    log = simulate_pull(truth, seed=5)
    folder = tmp_path / writer.__name__
    folder.mkdir()
    (folder / "log.txt").write_bytes(writer(log, truth.gauge_length))
    campaign(folder, "log.txt", extra)
    run, warnings = processed(folder, tmp_path)
    expected = independent_slope(log["force"].to_numpy(),
                                 log["extensometer"].to_numpy() / truth.gauge_length)
    assert float(run["specimen_E0"]) == pytest.approx(expected, rel=0.05)
    assert float(run["specimen_E0"]) == pytest.approx(truth.E0, rel=0.01)
    other = "'Przemieszczenie'" if writer is polish_bluehill else "'Standardwegaufnehmer'"
    assert any(other in warning and "not used" in warning for warning in warnings)
    assert any("repeated time stamp" in warning for warning in warnings)
    assert int(run["channel_removed_at"].sel(channel=run["channel"].values[
        run["channel_kind"].values == "extensometer"][0])) >= 0


def video_extensometer(log: pd.DataFrame, gauge_length: float) -> pd.DataFrame:
    """A coupon-lab export with a video extensometer's strains and no units (names as
    EPFL's CCFatigue files have them): the load along y, so ``eyy`` is the axial strain."""
    noise = np.random.default_rng(0).normal(0, 2e-5, len(log))
    return pd.DataFrame({"Machine_Displacement": log["crosshead"] * 1e3,
                         "Machine_Load": log["force"] / 1e3,
                         "exx--1": -0.3 * log["extensometer"] / gauge_length + noise,
                         "eyy--1 ": log["extensometer"] / gauge_length,
                         "Specimen Name": ["S-1"] + [""] * (len(log) - 1)})


@pytest.mark.parametrize("named", [False, True])
def test_a_strain_column_the_reader_does_not_know_can_be_named(tmp_path, named):
    """Unnamed, the strains are left alone and E0 comes from the crosshead, which a
    warning says, with the run-sheet key; named (one column, not a list), E0 is the
    extensometer's."""
    truth = PullTruth.for_chain("18x64", to_fracture=False, proof_force=300e3)
    log = simulate_pull(truth, seed=4)
    folder = tmp_path / "video"
    folder.mkdir()
    video_extensometer(log, truth.gauge_length).to_csv(folder / "qs.csv", index=False)
    extra = (f"gauge_length_mm = {truth.gauge_length * 1e3}\n"
             + ('columns = {force = "Machine_Load", gauges = "eyy--1"}\n'
                'units = {force = "kN", gauges = "1"}\n' if named
                else 'units = {force = "kN", gauges = "mm"}\n'))
    campaign(folder, "qs.csv", extra)
    run, warnings = processed(folder, tmp_path)
    crosshead = [w for w in warnings if w.startswith("E0 from the crosshead travel")]
    summary = read_dataset(tmp_path / "processed" / "video" / "summary.nc")
    assert int(summary["specimen_from_crosshead"].sel(specimen="P1")) == (not named)
    if named:
        assert float(run["specimen_E0"]) == pytest.approx(truth.E0, rel=0.01)
        assert crosshead == []
    else:
        assert float(run["specimen_E0"]) == pytest.approx(
            truth.gauge_length / truth.crosshead_compliance, rel=0.02)
        assert len(crosshead) == 1 and "'Machine_Displacement'" in crosshead[0]
        assert 'columns = {gauges = "..."}' in crosshead[0]


def test_two_specimens_side_by_side_in_one_file_are_two_runs(tmp_path):
    """A batch exported as Shimadzu Trapezium does: a label over each specimen's columns,
    the shorter specimen's left empty below its end. Each run reads its own specimen
    (by label, by place) and gets its own E0."""
    truths = [PullTruth.for_chain("18x64", to_fracture=False, proof_force=force)
              for force in (300e3, 250e3)]
    truths[1] = dataclasses.replace(truths[1], E0=0.8 * truths[1].E0)
    logs = [simulate_pull(truth, seed=seed) for seed, truth in enumerate(truths)]
    columns = [pd.DataFrame({"Temps": log["time"], "Force": log["force"] / 1e3,
                             "Ext.1": log["extensometer"] * 1e3}) for log in logs]
    table = pd.concat(columns, axis=1)  # the shorter one padded with empty cells
    folder = tmp_path / "batch"
    folder.mkdir()
    header = '"A-1",,,"B-2",,\n' + '"sec","kN","mm","sec","kN","mm"\n'
    text = table.to_csv(index=False, float_format="%.9g")
    names, body = text.split("\n", 1)
    (folder / "batch.csv").write_text(header.split("\n")[0] + "\n" + names + "\n"
                                      + header.split("\n")[1] + "\n" + body)
    assert len(logs[0]) != len(logs[1])
    gauge = f"gauge_length_mm = {truths[0].gauge_length * 1e3}\n"
    campaign(folder, "batch.csv", gauge + 'specimen_in_file = "A-1"\n' + textwrap.dedent("""\
        [[runs]]
        id = "P2"
        kind = "tensile"
        file = "batch.csv"
        chain = "c"
        cycles = 1
        specimen_in_file = 2
        """) + gauge)
    result = process_campaign(folder, tmp_path / "processed" / folder.name)
    assert result.ok, [failure.message for failure in result.failures]
    for run, truth in zip(("P1", "P2"), truths, strict=True):
        dataset = read_dataset(result.output / f"{run}.nc")
        assert float(dataset["specimen_E0"]) == pytest.approx(truth.E0, rel=0.01)


def test_two_gauges_of_one_kind_that_disagree_are_not_averaged(tmp_path):
    """Same kind, slopes 30 % apart: the stiffer is used, with a warning."""
    truth = PullTruth.for_chain("18x64", to_fracture=False, proof_force=300e3)
    log = simulate_pull(truth, seed=2)
    table = pd.DataFrame({"force [kN]": log["force"] / 1e3,
                          "gauge1 [mm]": log["extensometer"] * 1e3,
                          "gauge2 [mm]": log["extensometer"] * 1e3 / 0.7})
    folder = tmp_path / "two"
    folder.mkdir()
    table.to_csv(folder / "log.csv", index=False)
    campaign(folder, "log.csv", f"gauge_length_mm = {truth.gauge_length * 1e3}\n")
    run, warnings = processed(folder, tmp_path)
    assert run["channel_used"].values.tolist() == [1, 0]
    assert float(run["specimen_E0"]) == pytest.approx(truth.E0, rel=0.01)
    assert any("not used (the gauge channels' stiffnesses disagree beyond 20 %)" in warning
               for warning in warnings)


@pytest.mark.realdata
def test_catalogue_preload_above_a_small_specimen_is_set_aside_with_a_warning(realdata,
                                                                              tmp_path):
    """yadbor's Bluehill export peaks at 53 N; chain 18x64's catalogue preload is 9.8 kN."""
    name = "yadbor__bluer__Specimen_RawData_6.csv"
    folder = tmp_path / "small"
    folder.mkdir()
    shutil.copy(realdata / name, folder / name)
    (folder / "campaign.toml").write_text(textwrap.dedent(f"""\
        [campaign]
        id = "small"
        [chains.c]
        catalog = "18x64"
        [[runs]]
        id = "P1"
        kind = "tensile"
        file = "{name}"
        chain = "c"
        cycles = 3
        gauge_length_mm = 50
        accept_implausible = true
        """), encoding="utf-8")
    # a 53 N specimen is no 18x64 chain: flagged against its theory, accepted here
    run, warnings = processed(folder, tmp_path)
    assert int(run["specimen_n_cycles"]) == 2  # cycles 2 and 3 counted
    assert any("catalogue's preload of chain 18x64 (9.807 kN)" in warning
               for warning in warnings)


def test_a_fit_with_too_few_samples_says_where_its_only_channel_was_cut(tmp_path):
    # a real WaveMatrix export: its one position ran backwards early in a sparse log, and the run
    # failed as "the fullest branch holds 0 samples with a strain", saying not why
    truth = PullTruth.for_chain("18x64")
    log = simulate_pull(truth, seed=3).iloc[::40].reset_index(drop=True)
    force = log["force"].to_numpy()
    crosshead = log["crosshead"].to_numpy().copy()
    slip = int(np.argmax(force > 0.3 * force.max()))
    crosshead[slip:] = crosshead[slip] - np.linspace(0.0, 2e-3, crosshead.size - slip)
    folder = tmp_path / "slipped"
    folder.mkdir()
    pd.DataFrame({"Time": log["time"], "Load": force / 1e3,
                  "Crosshead": crosshead * 1e3}).to_csv(folder / "p.csv", index=False)
    campaign(folder, "p.csv", f"gauge_length_mm = {truth.gauge_length * 1e3}\n"
                              'units = {time = "s", force = "kN", gauges = "mm"}\n')
    result = process_campaign(folder, tmp_path / "processed" / "slipped")
    [failure] = result.failures
    # cut where it stopped following the specimen (frozen or running backwards)
    assert re.search(r"a fit needs 10; 'Crosshead' (freezes|runs backwards) from "
                     rf"{force[slip] / 1e3:.4g} kN on \(hint:", failure.message)
