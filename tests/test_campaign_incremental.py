"""Re-runs redo only what changed; crashes and concurrent runs corrupt nothing; dask = serial."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
import xarray as xr
from typer.testing import CliRunner

from pipeline.campaign import check_campaign, process_campaign
from pipeline.cli import app
from pipeline.store.lock import PID_NAME
from pipeline.store.netcdf import read_dataset

runner = CliRunner()
CHAINBENCH = [sys.executable, "-c", "from pipeline.cli import app; app()"]


@pytest.fixture(scope="module")
def source(simulated) -> Path:
    """A 4-specimen tensile campaign from the virtual bench."""
    return simulated("tensile", "--specimens", "4", "--seed", "3", "--campaign", "c18")


@pytest.fixture
def campaign(source, tmp_path) -> Path:
    folder = tmp_path / "raw" / "c18"
    shutil.copytree(source, folder)
    return folder


def numbers(summary: xr.Dataset) -> xr.Dataset:
    """The summary's values without its attributes (creation time, keys)."""
    return summary.drop_attrs(deep=True)


def outputs(folder: Path) -> dict[str, int]:
    """Modification times of the results (not of the lock file, rewritten by every run)."""
    return {path.name: path.stat().st_mtime_ns for path in folder.iterdir()
            if not path.name.startswith(".")}


def test_rerun_with_nothing_changed_redoes_nothing(campaign, tmp_path):
    out = tmp_path / "out"
    first = process_campaign(campaign, out)
    assert sorted(first.redone) == ["T18-1", "T18-2", "T18-3", "T18-4"]
    stamps = outputs(out)
    second = process_campaign(campaign, out)
    assert second.redone == [] and sorted(second.reused) == sorted(first.redone)
    assert outputs(out) == stamps  # nothing rewritten: no run, no summary, no report
    xr.testing.assert_identical(numbers(second.summary), numbers(first.summary))


def test_a_summary_rebuilt_from_the_stored_runs_is_the_fresh_one(campaign, tmp_path):
    # With the manifest gone the summary is rebuilt, from results read back from the run
    # files (from_dataset): the same numbers as from the runs processed in memory (validate).
    out = tmp_path / "out"
    first = process_campaign(campaign, out)
    (out / ".outputs.json").unlink()
    second = process_campaign(campaign, out)
    assert second.redone == [] and (out / ".outputs.json").is_file()
    xr.testing.assert_identical(numbers(second.summary), numbers(first.summary))
    checked = check_campaign(campaign, out)
    xr.testing.assert_identical(numbers(checked.summary), numbers(first.summary))
    assert checked.warnings == second.warnings == first.warnings


def test_changing_one_file_redoes_that_run_and_the_summary(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    untouched = (out / "T18-1.nc").stat().st_mtime_ns
    summary_before = (out / "summary.nc").stat().st_mtime_ns
    (campaign / "T18-2.csv").write_bytes((campaign / "T18-3.csv").read_bytes())  # new data
    result = process_campaign(campaign, out)
    assert result.redone == ["T18-2"]
    assert (out / "T18-1.nc").stat().st_mtime_ns == untouched
    assert (out / "summary.nc").stat().st_mtime_ns != summary_before
    assert process_campaign(campaign, out, force=True).redone == ["T18-1", "T18-2", "T18-3",
                                                                  "T18-4"]


def test_run_sheet_edit_of_one_entry_redoes_that_run(campaign, tmp_path):
    out = tmp_path / "out"
    process_campaign(campaign, out)
    sheet = campaign / "campaign.toml"
    text = sheet.read_text()
    head, tail = text.split('id = "T18-3"', 1)
    sheet.write_text(head + 'id = "T18-3"' + tail.replace("gauge_length_mm = 900",
                                                          "gauge_length_mm = 901", 1))
    assert process_campaign(campaign, out).redone == ["T18-3"]


def wait_for(condition, seconds: float = 60.0) -> None:
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.02)


def test_killed_mid_run_leaves_no_corrupt_file_and_rerun_completes(campaign, tmp_path):
    out = tmp_path / "processed"
    reference = process_campaign(campaign, tmp_path / "reference")
    process = subprocess.Popen([*CHAINBENCH, "run", str(campaign), "--output", str(out)],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wait_for(lambda: (out / "c18" / "T18-1.nc").exists())
    process.kill()
    process.wait()
    finished = [path for path in (out / "c18").glob("*.nc")]
    for path in finished:  # whatever was written is whole
        read_dataset(path)
    assert not (out / "c18" / "report.html").exists() or (out / "c18" / "summary.nc").exists()
    result = process_campaign(campaign, out / "c18")
    assert result.ok
    assert not list((out / "c18").glob(".*.tmp"))
    xr.testing.assert_allclose(numbers(result.summary), numbers(reference.summary), rtol=0)


def test_two_runs_at_once_never_interleave(campaign, tmp_path):
    out = tmp_path / "processed"
    first = subprocess.Popen([*CHAINBENCH, "run", str(campaign), "--output", str(out)],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    pid_file = out / "c18" / PID_NAME
    wait_for(lambda: pid_file.exists() and pid_file.read_text())
    second = subprocess.run([*CHAINBENCH, "run", str(campaign), "--output", str(out)],
                            capture_output=True, text=True, env={**os.environ, "COLUMNS": "200"})
    first_output, _ = first.communicate(timeout=120)
    if second.returncode == 0:  # the first had finished already: then it must have had the lock
        assert first.returncode == 0
        pytest.skip("the first run finished before the second started")
    assert "another chainbench run" in second.stdout
    assert first.returncode == 0, first_output
    assert process_campaign(campaign, out / "c18").redone == []


def test_dask_workers_give_the_serial_result(campaign, tmp_path):
    from distributed import Client, LocalCluster

    serial = process_campaign(campaign, tmp_path / "serial")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=":0") as cluster, Client(cluster) as client:
        parallel = process_campaign(campaign, tmp_path / "dask", client=client)
        cli = runner.invoke(app, ["run", str(campaign), "--output", str(tmp_path / "cli"),
                                  "--scheduler", cluster.scheduler_address])
    assert cli.exit_code == 0, cli.output
    assert sorted(parallel.redone) == sorted(serial.redone)
    xr.testing.assert_identical(numbers(parallel.summary), numbers(serial.summary))
    xr.testing.assert_identical(numbers(read_dataset(tmp_path / "cli" / "c18" / "summary.nc")),
                                numbers(serial.summary))
    for run_id in serial.run_files:
        xr.testing.assert_identical(numbers(read_dataset(parallel.run_files[run_id])),
                                    numbers(read_dataset(serial.run_files[run_id])))
