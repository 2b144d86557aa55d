"""One run's stages: an engagement run may take its chain stiffness from a stiffness campaign."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.store.netcdf import read_dataset

runner = CliRunner()


def simulate(kind: str, out: Path, *options: str) -> None:
    result = runner.invoke(app, ["simulate", kind, "--out", str(out), *options])
    assert result.exit_code == 0, result.output


@pytest.fixture(scope="module")
def lab(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("lab")
    simulate("tensile", root / "raw" / "stiff", "--specimens", "2", "--campaign", "stiff")
    simulate("engagement", root / "raw" / "wheel", "--teeth", "8", "--omega", "20",
             "--duration", "1", "--sample-rate", "10000", "--campaign", "wheel")
    return root


def wheel_using(lab: Path, target: Path, reference: str) -> Path:
    """A copy of the engagement campaign whose runs take E0 from `reference`."""
    target.mkdir(parents=True)
    for path in (lab / "raw" / "wheel").iterdir():
        (target / path.name).write_bytes(path.read_bytes())
    sheet = target / "campaign.toml"
    sheet.write_text(re.sub(r"^E0_N = .*$", f'stiffness_from = "{reference}"',
                            sheet.read_text(), flags=re.M))
    return target


def test_engagement_run_uses_the_measured_stiffness(lab, tmp_path):
    process_campaign(lab / "raw" / "stiff", lab / "processed" / "stiff")
    wheel = wheel_using(lab, tmp_path / "wheel", "stiff/c18x64")
    result = process_campaign(wheel, lab / "processed" / "wheel")
    assert result.failures == []
    measured = read_dataset(lab / "processed" / "stiff" / "summary.nc")
    E0_exp = float(measured["E0_exp"].sel(chain="c18x64"))
    assert result.summary["E0"].values.tolist() == [E0_exp]


@pytest.mark.parametrize(("reference", "words"), [
    ("nowhere/c18x64", "no processed stiffness campaign"),
    ("stiff/c99", "has no chain 'c99'"),
])
def test_missing_stiffness_source_fails_the_run_with_its_key(lab, tmp_path, reference, words):
    process_campaign(lab / "raw" / "stiff", lab / "processed" / "stiff")
    wheel = wheel_using(lab, tmp_path / "wheel", reference)
    result = process_campaign(wheel, lab / "processed" / f"wheel-{reference.split('/')[0]}")
    (failure,) = result.failures
    assert words in failure.message
    assert failure.error.column == "stiffness_from"


def test_a_log_longer_than_a_chunk_is_read_from_its_file_in_chunks_with_the_same_result(
        lab, tmp_path, monkeypatch):

    from pipeline import runs

    wheel = lab / "raw" / "wheel"
    whole = process_campaign(wheel, tmp_path / "whole")
    reads = []
    real_read = runs.open_log

    def counting(*args, **kwargs):
        reader = real_read(*args, **kwargs)
        reads.append(reader.n_rows)
        return reader

    monkeypatch.setattr(runs, "open_log", counting)
    monkeypatch.setattr(runs, "WHOLE_SAMPLES", 3_000)  # the 1 s logs hold 10 001 samples
    monkeypatch.setattr(runs, "CHUNK_SAMPLES", 3_000)
    chunked = process_campaign(wheel, tmp_path / "chunked")
    assert reads and all(n > 3_000 for n in reads)
    assert chunked.failures == [] and whole.failures == []
    for name in ("N_u1_meas", "N_u2_meas"):
        np.testing.assert_allclose(chunked.summary[name], whole.summary[name], rtol=1e-6)
    run_id = next(iter(chunked.run_files))
    a, b = (read_dataset(result.run_files[run_id]) for result in (whole, chunked))
    np.testing.assert_allclose(a["event_time"], b["event_time"], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(a["time"], b["time"])  # the stored preview


def processed_tdms_wheel(lab: Path, tmp_path: Path):
    """A copy of the engagement campaign with its stiffness given, processed: the folder,
    its run sheet, the result, and its TDMS log's canonical table."""
    from pipeline.ingest import read_table

    wheel = wheel_using(lab, tmp_path / "wheel", "unused")
    sheet = wheel / "campaign.toml"
    sheet.write_text(re.sub(r'^stiffness_from = .*$', "E0_N = 22600000", sheet.read_text(),
                            flags=re.M))
    whole = process_campaign(wheel, tmp_path / "tdms")
    table, _ = read_table(next(wheel.glob("*.tdms")), kind="engagement")
    return wheel, sheet, whole, table


def test_an_engagement_log_with_a_rigs_event_lines_is_read_as_inspect_reads_it(lab, tmp_path):
    wheel, sheet, whole, table = processed_tdms_wheel(lab, tmp_path)
    rows = [f"{t},{f},{a}" for t, f, a in table[["time", "force", "angle"]].to_numpy()]
    rows.insert(5000, f"{table['time'][4999]},Speed set to 20 rad/s,")
    (wheel / "log.csv").write_text("time [s],force [N],angle [rad]\n" + "\n".join(rows) + "\n")
    sheet.write_text(re.sub(r'^file = .*$', 'file = "log.csv"', sheet.read_text(), flags=re.M))
    with_event = process_campaign(wheel, tmp_path / "csv")
    assert whole.failures == [] and with_event.failures == []
    for name in ("N_u1_meas", "N_u2_meas"):
        np.testing.assert_allclose(with_event.summary[name], whole.summary[name], rtol=1e-12)
    (run_file,) = with_event.run_files.values()
    assert "line 5002: '0.4999,Speed set to 20 rad/s,'" in read_dataset(run_file).attrs[
        "ingest_warnings"]


class _Sheet:
    """The run sheet as _check_counter asks it: where a run's file is."""

    @staticmethod
    def run_file(run) -> Path:
        return Path(run)


@pytest.mark.parametrize(("header", "refused"), [
    ("Cycles", None), ("Count (cycles)", None),
    ("Axial Segment Count", "counts segments"),  # MTS: two a cycle, kept as counted
    ("Count (segments)", "counts segments"),
    ("Count (kcycles)", "cannot scale"),
    # a counter in thousands by its name: read as cycles, a wear rate 1000 times too high
    ("Cycles x1000", "cannot scale"), ("Zyklen in Tsd", "cannot scale"),
    ("Thousand cycles", "cannot scale"),
])
def test_a_wear_logs_counter_of_segments_or_of_scaled_cycles_is_refused(
        tmp_path, header, refused):
    from pipeline.errors import UnitError
    from pipeline.ingest import read_table
    from pipeline.runs import _check_counter

    path = tmp_path / "wear.csv"
    path.write_text(f"{header},Length (mm)\n" + "".join(
        f"{cycle},{500 + 0.001 * cycle}\n" for cycle in range(0, 1000, 100)))
    _, metadata = read_table(path, kind="wear")
    if refused is None:
        _check_counter(_Sheet(), "w1", metadata)
        return
    with pytest.raises(UnitError, match=refused):
        _check_counter(_Sheet(), "w1", metadata)


def test_an_engagement_log_without_time_is_read_at_the_run_sheets_sample_rate(lab, tmp_path):
    # a logger that writes one row a sample and no time: the run sheet gives the rate
    wheel, sheet, whole, table = processed_tdms_wheel(lab, tmp_path)
    step = np.diff(table["time"].to_numpy())
    assert table["time"].iloc[0] == 0 and np.allclose(step, 1e-4, rtol=1e-9, atol=0)
    rows = [f"{f},{a}" for f, a in table[["force", "angle"]].to_numpy()]
    (wheel / "log.csv").write_text("force [N],angle [rad]\n" + "\n".join(rows) + "\n")
    sheet.write_text(re.sub(r'^file = .*$', 'file = "log.csv"\nsample_rate_hz = 10000',
                            sheet.read_text(), flags=re.M))
    untimed = process_campaign(wheel, tmp_path / "csv")
    assert whole.failures == [] and untimed.failures == []
    for name in ("N_u1_meas", "N_u2_meas"):
        np.testing.assert_allclose(untimed.summary[name], whole.summary[name], rtol=1e-9)
    (run_file,) = untimed.run_files.values()
    assert ("the file has no time column: time is built from the run sheet's sample_rate_hz = "
            "10000") in read_dataset(run_file).attrs["ingest_warnings"]
