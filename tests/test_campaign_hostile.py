"""One campaign holding the faults a hostile new user makes, all at once.

Good runs beside run-sheet faults (reserved and colliding ids, strings for
numbers, a chain that cannot exist, an unknown chain whose hint holds
brackets), a unit slip, a cut-off file and a missing one: ``chainbench run``
processes the good runs, lists every fault with its file, line or key and a
hint, flags the slip, exits 1, prints no traceback and leaves raw/ as it was.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.cli import app

runner = CliRunner()
BAD = Path(__file__).parent / "data" / "bad"
WIDE = {"COLUMNS": "250"}

#: Run-sheet entries after the simulated good runs: id -> the TOML of the entry.
HOSTILE_RUNS = {
    "summary": 'file = "T18-1.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
    "Report": 'file = "T18-1.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
    "t18-1": 'file = "T18-1.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
    "quoted": 'file = "T18-1.csv"\nchain = "c18x64"\ngauge_length_mm = "900"',
    "no-link": 'file = "T18-1.csv"\nchain = "tiny"\ngauge_length_mm = 900',
    "undefined": 'file = "T18-1.csv"\nchain = "c99"\ngauge_length_mm = 900',
    "bracketed": 'file = "T18-2.csv"\nchain = "[/bold]"\ngauge_length_mm = 900',
    "slip": 'file = "slip.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
    "cut": 'file = "cut.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
    "missing": 'file = "gone.csv"\nchain = "c18x64"\ngauge_length_mm = 900',
}
CHAINS = ('\n[chains.tiny]\ncatalog = "18x64"\nt_mm = 1e-9\n'
          '\n[chains."[/bold]"]\ncatalog = "18x64"\n')


@pytest.fixture
def project(tmp_path) -> Path:
    campaign = tmp_path / "raw" / "hostile"
    written = runner.invoke(app, ["simulate", "tensile", "--out", str(campaign), "--specimens",
                                  "3", "--seed", "4", "--campaign", "hostile"])
    assert written.exit_code == 0, written.output
    log = (campaign / "T18-3.csv").read_text(encoding="utf-8")
    (campaign / "slip.csv").write_text(log.replace("[mm]", "[m]"), encoding="utf-8")
    shutil.copy(BAD / "european_truncated_last_field.csv", campaign / "cut.csv")
    sheet = campaign / "campaign.toml"
    text = sheet.read_text(encoding="utf-8").replace("\n[[runs]]", CHAINS + "\n[[runs]]", 1)
    for run_id, entry in HOSTILE_RUNS.items():
        text += f'\n[[runs]]\nid = "{run_id}"\nkind = "tensile"\ncycles = 3\n{entry}\n'
    sheet.write_text(text, encoding="utf-8")
    return tmp_path


def snapshot(folder: Path) -> dict[str, bytes]:
    return {str(path.relative_to(folder)): path.read_bytes() for path in sorted(folder.rglob("*"))
            if path.is_file()}


def failed_lines(output: str) -> list[str]:
    return [line for line in output.splitlines() if line.startswith("failed ")]


def test_every_fault_is_listed_the_good_runs_processed_and_raw_untouched(project,
                                                                        monkeypatch):
    monkeypatch.chdir(project)
    before = snapshot(project / "raw")
    result = runner.invoke(app, ["run"], env=WIDE)
    assert result.exit_code == 1
    assert "Traceback" not in result.output and result.exception is None or isinstance(
        result.exception, SystemExit)
    assert snapshot(project / "raw") == before
    failed = failed_lines(result.output)
    expected = {"chains.tiny", "cut", "missing", *(f"runs[{index}]" for index in (
        3, 4, 5, 6, 7, 8))}  # runs[0..2] are the good runs
    assert {line.split()[1].rstrip(":") for line in failed} == expected
    for line in failed:  # where and what to do
        assert "hint:" in line or ", line " in line, line
        assert "campaign.toml, key " in line or ".csv" in line, line
    text = "\n".join(failed)
    assert "define [chains.c99]" in text  # brackets shown, not eaten as markup
    assert "names a campaign output" in text and "letter case" in text
    assert "expected a number, got the string '900'" in text
    assert "line 5 is truncated" in result.output or "cut.csv" in text
    assert "implausible" in result.output and "slip" in result.output
    assert "5 run(s) processed, 0 unchanged, 9 failed" in result.output  # slip: flagged
    processed = project / "processed" / "hostile"
    assert sorted(path.name for path in processed.glob("*.nc")) == [
        "T18-1.nc", "T18-2.nc", "T18-3.nc", "bracketed.nc", "slip.nc", "summary.nc"]
    assert (processed / "report.html").is_file()


def test_an_output_path_that_is_a_file_is_one_clear_error(project, monkeypatch):
    monkeypatch.chdir(project)
    (project / "out").write_text("in the way", encoding="utf-8")
    result = runner.invoke(app, ["run", "--output", "out"], env=WIDE)
    assert result.exit_code == 1
    assert "lies under a file" in result.output
    assert "Traceback" not in result.output
    assert (project / "out").read_text(encoding="utf-8") == "in the way"


def test_validate_finds_what_run_finds_and_writes_nothing(project, monkeypatch):
    monkeypatch.chdir(project)
    checked = runner.invoke(app, ["validate"], env=WIDE)
    assert not (project / "processed").exists()
    ran = runner.invoke(app, ["run"], env=WIDE)
    assert checked.exit_code == ran.exit_code == 1
    refused = sorted(line.removeprefix("failed ") for line in failed_lines(ran.output))
    found = sorted(line.removeprefix("error ") for line in checked.output.splitlines()
                   if line.startswith("error "))
    assert found == refused
    implausible = sorted(line for line in ran.output.splitlines()
                         if line.startswith("implausible "))
    assert implausible and implausible == sorted(
        line for line in checked.output.splitlines() if line.startswith("implausible "))
