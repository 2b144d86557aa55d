"""``chainbench run`` with nothing changed prints the last run's results without computing."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.store import layout

runner = CliRunner()
#: The console script's entry point, as the installed ``chainbench`` runs it.
CHAINBENCH = [sys.executable, "-c", "import sys; from pipeline.cli import main; sys.exit(main())"]
UNCHANGED = "unchanged run sheet, raw files, code and outputs are as the last run left them"


@pytest.fixture
def project(simulated, tmp_path, monkeypatch) -> Path:
    """A project holding a copy of a 3-specimen tensile campaign, processed once."""
    source = simulated("tensile", "--specimens", "3", "--seed", "5", "--campaign", "t5")
    shutil.copytree(source, tmp_path / "raw" / "t5")
    monkeypatch.chdir(tmp_path)
    first = runner.invoke(app, ["run"])
    assert first.exit_code == 0, first.output
    return tmp_path


def run(*args: str):
    return runner.invoke(app, ["run", *args])


def without_header(output: str) -> list[str]:
    """The printed lines after the campaign's header, without the 'unchanged' line and
    the full path's progress lines (``  T18-1: unchanged``)."""
    return [line for line in output.splitlines()[1:]
            if not line.startswith(("unchanged ", "  T18-"))]


def test_a_rerun_prints_what_the_full_path_prints_when_nothing_changed(project):
    fast = run()
    assert fast.exit_code == 0 and UNCHANGED in fast.output
    assert "0 run(s) processed, 3 unchanged, 0 failed" in fast.output
    (project / "processed" / "t5" / layout.RERUN).unlink()  # down the full path
    full = run()
    assert full.exit_code == 0 and UNCHANGED not in full.output
    assert without_header(fast.output) == without_header(full.output)
    fast_json, full_json = (json.loads(result.output) for result in (run("--json"),
                                                                      run("--json", "--rehash")))
    assert fast_json == full_json


@pytest.mark.parametrize("change", ["raw_file", "run_sheet", "report_deleted"])
def test_a_change_is_computed_not_served(project, change):
    campaign, output = project / "raw" / "t5", project / "processed" / "t5"
    if change == "raw_file":
        (campaign / "T18-2.csv").write_bytes((campaign / "T18-1.csv").read_bytes())
    elif change == "run_sheet":
        sheet = campaign / "campaign.toml"
        sheet.write_text(sheet.read_text(encoding="utf-8") + "\n", encoding="utf-8")
    else:
        (output / layout.REPORT).unlink()
    result = run()
    assert result.exit_code == 0 and UNCHANGED not in result.output
    assert (output / layout.REPORT).is_file()
    expected = "1 run(s) processed, 2 unchanged" if change == "raw_file" else "0 run(s) processed"
    assert expected in result.output
    assert UNCHANGED in run().output  # and the next run is fast again


@pytest.mark.parametrize("option", ["--force", "--rehash"])
def test_force_and_rehash_take_the_full_path(project, option):
    result = run(option)
    assert result.exit_code == 0 and UNCHANGED not in result.output


def test_rehash_reads_every_raw_file_again(project, monkeypatch):
    from pipeline.store import freshness

    reads = []
    real = freshness.sha256_file
    monkeypatch.setattr(freshness, "sha256_file", lambda path: reads.append(Path(path).name)
                        or real(path))
    (project / "processed" / "t5" / layout.RERUN).unlink()
    assert run().exit_code == 0
    assert sorted(name for name in reads if name.endswith(".csv")) == []  # cached hashes
    assert run("--rehash").exit_code == 0
    assert sorted(name for name in reads if name.endswith(".csv")) == [
        "T18-1.csv", "T18-2.csv", "T18-3.csv"]


def test_the_console_script_answers_without_loading_the_stages(project):
    code = ("import sys; from pipeline.cli import main; sys.argv = ['chainbench', 'run']\n"
            "try:\n    main()\nexcept SystemExit as stop:\n    code = stop.code\n"
            "heavy = {'numpy', 'pandas', 'xarray', 'lmfit', 'matplotlib', 'dask', 'scipy',"
            " 'pint', 'pipeline.campaign', 'pipeline.runsheet'}\n"
            "print(code, sorted(heavy & set(sys.modules)))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True, cwd=project, env={**os.environ, "COLUMNS": "100"})
    assert done.stdout.strip().splitlines()[-1] == "0 []"
    assert UNCHANGED in done.stdout


def test_the_console_script_runs_every_command(project):
    done = subprocess.run([*CHAINBENCH, "--version"], capture_output=True, text=True,
                          cwd=project)
    assert done.returncode == 0 and done.stdout.strip()
    done = subprocess.run([*CHAINBENCH, "run", "--help"], capture_output=True, text=True,
                          cwd=project)
    assert done.returncode == 0 and "--rehash" in done.stdout


def test_a_part_the_test_goes_on_in_appearing_is_computed_not_served(project):
    """A file named as a raw file with a number after its stem, whose time runs on from
    the raw file's (a test written in parts), is read with it: its appearing is a change."""
    raw = project / "raw" / "t5" / "T18-1.csv"
    header, *rows = raw.read_text(encoding="utf-8").splitlines()
    last = float(rows[-1].split(",")[0])
    later = [f"{last + 0.1 * (i + 1):.1f},{row.split(',', 1)[1]}" for i, row in
             enumerate(rows[-20:])]
    (raw.parent / "T18-11.csv").write_text("\n".join([header, *later]) + "\n",
                                           encoding="utf-8")
    again = run()
    assert again.exit_code == 0, again.output
    assert UNCHANGED not in again.output
    assert "1 run(s) processed, 2 unchanged, 0 failed" in again.output
    assert "T18-1: read with the parts the test goes on in, 'T18-11.csv'" in again.output


def test_a_chain_without_specimens_prints_when_its_outputs_are_read_back(simulated,
                                                                         tmp_path,
                                                                         monkeypatch):
    """Its 'in band' is stored as the fill value: read back, it is shown as not checked."""
    source = simulated("tensile", "--specimens", "1", "--seed", "5", "--campaign", "t1")
    campaign = shutil.copytree(source, tmp_path / "raw" / "t1")
    raw = campaign / "T18-1.csv"
    header, rest = raw.read_text(encoding="utf-8").split("\n", 1)
    # gauges in mm headed m: E0 a thousandth of the theory, the specimen left out
    raw.write_text(header.replace("[mm]", "[m]") + "\n" + rest, encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    first = run()
    assert "implausible T18-1" in first.output
    os.utime(raw)  # touched: the full path, whose runs and outputs are current
    again = run()
    assert again.exception is None or isinstance(again.exception, SystemExit), again.output
    assert again.exit_code == first.exit_code
    chain_row = next(line for line in again.output.splitlines() if "│ c18x64 " in line)
    assert chain_row.split("│")[1:-1][-1].strip() == "-"
