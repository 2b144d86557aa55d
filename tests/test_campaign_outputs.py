"""The campaign outputs are always current, where they belong, and complete.

Interrupted writes, renamed runs, edits that change no result, a changed code
base, an output folder that cannot be written, and where the outputs go however
the campaign is named.
"""

from __future__ import annotations

import hashlib
import os
import re
import shutil
from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

from pipeline.campaign import default_output, process_campaign
from pipeline.errors import OutputError
from pipeline.store import layout
from pipeline.store.netcdf import read_dataset

runner = CliRunner()


@pytest.fixture(scope="module")
def source(simulated) -> Path:
    """A 2-specimen tensile campaign from the virtual bench."""
    return simulated("tensile", "--specimens", "2", "--seed", "3", "--campaign", "c18")


@pytest.fixture
def campaign(source, tmp_path) -> Path:
    folder = tmp_path / "project" / "raw" / "c18"
    shutil.copytree(source, folder)
    return folder


def without_creation_time(report: str) -> str:
    """The report without the lines that name when it was made."""
    return re.sub(r"\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ", "<time>", report)


def campaign_outputs(folder: Path) -> dict[str, bytes]:
    """The campaign-level outputs of a processed folder, with times blanked."""
    found = {}
    for name in (layout.CHAIN_TABLE, layout.SPECIMEN_TABLE, layout.REPORT):
        text = (folder / name).read_text(encoding="utf-8")
        found[name] = without_creation_time(text)
    return found


def results(folder: Path) -> dict[str, bytes]:
    """The bytes of every result in `folder` (not the lock and manifest files)."""
    return {path.name: path.read_bytes() for path in folder.iterdir()
            if path.is_file() and not path.name.startswith(".")}


class Killed(BaseException):
    """Stands for the process being killed: nothing after it runs."""


def kill_after(monkeypatch, renames: int) -> None:
    """Make the process 'die' right after its `renames`-th output is renamed into place."""
    real_replace, done = os.replace, []

    def replace(source, target):
        real_replace(source, target)
        done.append(target)
        if len(done) == renames:
            raise Killed(target)

    monkeypatch.setattr(os, "replace", replace)


#: Renames of a re-run after one raw file changed: the raw-file hash cache, that run,
#: summary.nc, 2 tables, the runs' pages (2), report, manifest.
RENAMES = 9


@pytest.mark.parametrize("renames", range(1, RENAMES + 1))
def test_a_kill_at_any_write_boundary_leaves_outputs_consistent_after_the_rerun(
        campaign, tmp_path, monkeypatch, renames):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    changed = campaign / "T18-2.csv"
    changed.write_bytes((campaign / "T18-1.csv").read_bytes())  # a raw file edited
    with monkeypatch.context() as patch:
        kill_after(patch, renames)
        with pytest.raises(Killed):
            process_campaign(campaign, out)
    rerun = process_campaign(campaign, out)
    reference = process_campaign(campaign, tmp_path / "reference", force=True)
    xr.testing.assert_identical(rerun.summary.drop_attrs(deep=True),
                                reference.summary.drop_attrs(deep=True))
    assert campaign_outputs(out) == campaign_outputs(tmp_path / "reference")
    new_hash = hashlib.sha256(changed.read_bytes()).hexdigest()
    assert new_hash in (out / layout.REPORT).read_text(encoding="utf-8")


def test_a_rerun_after_one_change_renames_as_many_outputs_as_the_kill_test_covers(
        campaign, tmp_path, monkeypatch):
    process_campaign(campaign, tmp_path / "out")
    (campaign / "T18-2.csv").write_bytes((campaign / "T18-1.csv").read_bytes())
    real_replace, done = os.replace, []
    monkeypatch.setattr(os, "replace", lambda a, b: (real_replace(a, b), done.append(b)))
    process_campaign(campaign, tmp_path / "out")
    assert len(done) == RENAMES


def test_a_stale_manifest_is_never_trusted_after_a_kill(campaign, tmp_path, monkeypatch):
    """Inputs A, killed while writing B's outputs, inputs back to A: rebuilt, not reused."""
    out = tmp_path / "out"
    process_campaign(campaign, out)
    original = (campaign / "T18-2.csv").read_bytes()
    (campaign / "T18-2.csv").write_bytes((campaign / "T18-1.csv").read_bytes())
    with monkeypatch.context() as patch:
        kill_after(patch, 2)  # the changed run and summary.nc of B written
        with pytest.raises(Killed):
            process_campaign(campaign, out)
    (campaign / "T18-2.csv").write_bytes(original)
    rerun = process_campaign(campaign, out)
    assert rerun.redone == ["T18-2"]
    summary = read_dataset(out / layout.SUMMARY)
    reference = process_campaign(campaign, tmp_path / "reference")
    xr.testing.assert_identical(summary.drop_attrs(deep=True),
                                reference.summary.drop_attrs(deep=True))


def test_a_deleted_report_is_rebuilt(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    (out / layout.REPORT).unlink()
    assert process_campaign(campaign, out).report.is_file()


def test_renamed_and_removed_runs_leave_no_orphan_outputs(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    (out / "notes.nc").write_bytes(b"not ours")  # a file chainbench did not write: kept
    sheet = campaign / "campaign.toml"
    text = sheet.read_text(encoding="utf-8").replace('id = "T18-1"', 'id = "T18-1b"')
    sheet.write_text(text, encoding="utf-8")
    result = process_campaign(campaign, out)
    assert result.removed == ["T18-1"]
    assert sorted(path.stem for path in out.glob("T18-*.nc")) == ["T18-1b", "T18-2"]
    assert (out / "notes.nc").is_file()
    assert list(result.summary["run"].values) == ["T18-1b", "T18-2"]


def test_a_run_failing_now_loses_its_stale_output_and_counts_as_failed(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    (campaign / "T18-2.csv").write_text("time [s],force [kN]\n", encoding="utf-8")
    result = process_campaign(campaign, out, force=True)
    assert result.redone == ["T18-1"]
    assert [failure.run_id for failure in result.failures] == ["T18-2"]
    assert not (out / "T18-2.nc").exists() and result.removed == ["T18-2"]


def test_editing_the_title_redoes_no_run_but_the_report(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    sheet = campaign / "campaign.toml"
    text = sheet.read_text(encoding="utf-8")
    sheet.write_text(re.sub(r'title = "[^"]*"', 'title = "Renamed campaign"', text),
                     encoding="utf-8")
    result = process_campaign(campaign, out)
    assert result.redone == [] and len(result.reused) == 2
    assert "Renamed campaign" in (out / layout.REPORT).read_text(encoding="utf-8")


def test_changed_code_at_the_same_version_redoes_every_run(campaign, tmp_path, monkeypatch):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    monkeypatch.setattr("pipeline.campaign.code_fingerprint", lambda: "another algorithm")
    assert sorted(process_campaign(campaign, out).redone) == ["T18-1", "T18-2"]


@pytest.mark.parametrize("named_as", ["folder", "dot", "run sheet", "absolute", "relative"])
def test_outputs_go_to_project_processed_campaign_id_however_named(campaign, monkeypatch,
                                                                      named_as):
    project = campaign.parents[1]
    where, argument = {
        "folder": (project, Path("raw") / "c18"),
        "dot": (campaign, Path(".")),
        "run sheet": (project, Path("raw") / "c18" / "campaign.toml"),
        "absolute": (Path("/"), campaign),
        "relative": (campaign.parent, Path("c18")),
    }[named_as]
    monkeypatch.chdir(where)
    result = process_campaign(argument)
    assert result.output.resolve() == project / "processed" / "c18"
    assert (project / "processed" / "c18" / layout.REPORT).is_file()
    assert sorted(path.name for path in campaign.iterdir()) == [
        "T18-1.csv", "T18-2.csv", "campaign.toml", "truth.json"]


def test_the_output_is_named_by_the_campaign_id_not_the_folder(campaign):
    sheet = campaign / "campaign.toml"
    text = sheet.read_text(encoding="utf-8")
    sheet.write_text(text.replace('id = "c18"', 'id = "chain-18"', 1), encoding="utf-8")
    assert default_output(campaign) == campaign.parents[1] / "processed" / "chain-18"


def test_an_output_inside_raw_is_refused(campaign):
    with pytest.raises(OutputError, match="never written inside raw"):
        process_campaign(campaign, campaign / "processed")
    assert not (campaign / "processed").exists()


def test_an_output_folder_that_is_a_file_is_a_typed_error(campaign, tmp_path):
    target = tmp_path / "out"
    target.write_text("in the way", encoding="utf-8")
    with pytest.raises(OutputError, match="is a file"):
        process_campaign(campaign, target)
    assert target.read_text(encoding="utf-8") == "in the way"


def test_a_full_disk_is_a_typed_error_and_keeps_the_old_outputs(campaign, tmp_path,
                                                                monkeypatch):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    before = results(out)
    (campaign / "T18-2.csv").write_bytes((campaign / "T18-1.csv").read_bytes())

    def full(*args, **kwargs):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", full)
    result = None
    with pytest.raises(OutputError, match="No space left on device") as caught:
        result = process_campaign(campaign, out)
    assert result is None and caught.value.file.endswith("T18-2.nc")
    assert results(out) == before
    assert not list(out.glob(".*.tmp"))


def test_the_report_names_raw_files_relative_to_the_campaign(campaign, tmp_path):
    (campaign / "T18-2.csv").write_text("time [s],force [kN]\n", encoding="utf-8")
    process_campaign(campaign, tmp_path / "out")
    report = (tmp_path / "out" / layout.REPORT).read_text(encoding="utf-8")
    assert "T18-2.csv" in report
    assert str(tmp_path) not in report and str(campaign) not in report


def test_csv_text_cells_are_never_run_as_formulas(campaign, tmp_path):
    sheet = campaign / "campaign.toml"
    text = sheet.read_text(encoding="utf-8").replace("c18x64", "=HYPERLINK(1)")
    sheet.write_text(text.replace("[chains.=HYPERLINK(1)]", '[chains."=HYPERLINK(1)"]'),
                     encoding="utf-8")
    process_campaign(campaign, tmp_path / "out")
    table = (tmp_path / "out" / layout.CHAIN_TABLE).read_text(encoding="utf-8")
    assert "'=HYPERLINK(1)" in table
    assert not any(line.startswith("=") for line in table.splitlines())
