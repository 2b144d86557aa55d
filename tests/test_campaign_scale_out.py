"""``chainbench run --workers N``: how the local cluster runs a campaign.

Its workers use one thread for the numerical libraries and glibc's own memory
handling, and import the stages as they start; the runs are submitted largest
raw file first; the run files and the summary are written with no lock on the
cluster; an engagement campaign gives the serial result (docs/quality.md,
scale-out).
"""

from __future__ import annotations

import gc
import hashlib
import json
import os
import re
import shutil
import sys
from collections.abc import Iterator
from datetime import UTC, datetime
from pathlib import Path

import dask
import pytest
import xarray as xr
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.cli._cluster import dask_client
from pipeline.errors import EmptyFileError
from pipeline.report.build import build_report
from pipeline.store.netcdf import read_dataset
from pipeline.tasks import submit

#: The environment variables the workers are started with, and their expected values.
WORKER_ENVIRONMENT = {"OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1",
                      "MKL_NUM_THREADS": "1", "MALLOC_TRIM_THRESHOLD_": None}
#: The tensile runs of the campaign, by their raw files, largest first (asserted below).
FILES_BY_SIZE = ["T18-1.csv", "T18-2.csv", "T18-3.csv", "T18-4.csv"]


def test_an_engagement_campaign_on_two_workers_gives_the_serial_result(simulated, tmp_path):
    campaign = simulated("engagement", "--omega", "15", "25", "--seed", "5")
    serial = process_campaign(campaign, tmp_path / "serial")
    cli = CliRunner().invoke(app, ["run", str(campaign), "--output", str(tmp_path / "dask"),
                                   "--workers", "2"])
    assert cli.exit_code == 0, cli.output
    assert not serial.failures and len(serial.run_files) == 2
    parallel = tmp_path / "dask" / serial.campaign_id
    xr.testing.assert_identical(read_dataset(parallel / "summary.nc").drop_attrs(),
                                serial.summary.drop_attrs())
    for run_id, path in serial.run_files.items():
        xr.testing.assert_identical(read_dataset(parallel / f"{run_id}.nc").drop_attrs(),
                                    read_dataset(path).drop_attrs())


@pytest.fixture(scope="module")
def client() -> Iterator:
    """The CLI's local cluster of one worker (started as ``chainbench run`` starts it)."""
    with pytest.MonkeyPatch.context() as patch:
        # an earlier cluster of the session leaves dask's defaults in os.environ
        patch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
        with dask_client(1, None) as client:
            client.wait_for_workers(1)
            yield client


def _worker_state(dask_worker) -> tuple[dict[str, str | None], bool, int, bool, int]:
    """A worker's environment, whether it has loaded the stages, the objects frozen out of
    its garbage collector, whether it profiles its tasks, and its tasks run."""
    environment = {name: os.environ.get(name) for name in WORKER_ENVIRONMENT}
    return (environment, "pipeline.runs" in sys.modules, gc.get_freeze_count(),
            dask.config.get("distributed.worker.profile.enabled"),
            dask_worker.state.executed_count)


def test_workers_start_with_one_thread_and_the_stages_loaded(client):
    (environment, stages_loaded, frozen, profiling, tasks_run), = client.run(
        _worker_state).values()
    assert tasks_run == 0
    assert environment == WORKER_ENVIRONMENT
    assert stages_loaded
    assert frozen > 100_000  # the stages' objects, out of the collector's passes
    assert profiling is False


def _unreadable(path: str) -> None:
    raise EmptyFileError("no data rows", file=path, hint="export the test again")


def test_a_failed_task_is_the_commands_to_report_not_the_workers_to_log(client):
    # The command reports a run's or a campaign's error on its own line; the worker's own
    # record of the failure (its traceback) would otherwise be printed over the output.
    with pytest.raises(EmptyFileError):
        submit(client, _unreadable, "W16-A.csv").result()
    logged = [message for records in client.get_worker_logs().values()
              for _, message in records]
    assert not [message for message in logged if "Compute Failed" in message]


@pytest.fixture(scope="module")
def reordered(simulated, tmp_path_factory) -> Path:
    """The 4-run tensile campaign with the raw files given to the runs in reverse: run
    T18-1 reads the smallest file, T18-4 the largest."""
    folder = tmp_path_factory.mktemp("raw") / "c18"
    shutil.copytree(simulated("tensile", "--specimens", "4", "--seed", "3", "--campaign",
                              "c18"), folder)
    sizes = [(folder / name).stat().st_size for name in FILES_BY_SIZE]
    assert sizes == sorted(sizes, reverse=True) and len(set(sizes)) == 4
    reverse = dict(zip(FILES_BY_SIZE, reversed(FILES_BY_SIZE), strict=True))
    sheet = folder / "campaign.toml"
    text = re.sub(r'file = "(T18-\d\.csv)"', lambda match: f'file = "{reverse[match[1]]}"',
                  sheet.read_text(encoding="utf-8"))
    sheet.write_text(text, encoding="utf-8")
    return folder


def test_runs_start_largest_raw_file_first(client, reordered, tmp_path):
    finished = []
    result = process_campaign(reordered, tmp_path / "out", client=client,
                              progress=lambda run_id, stage: finished.append(run_id))
    assert not result.failures
    assert finished == ["T18-4", "T18-3", "T18-2", "T18-1"]  # one worker: in submission order


def _semaphores(dask_scheduler) -> list[str]:
    """The names of the locks taken on the cluster (dask semaphores)."""
    return list(dask_scheduler.extensions["semaphores"].max_leases)


def test_outputs_are_written_with_no_lock_on_the_cluster(client, reordered, tmp_path):
    out = tmp_path / "out"
    result = process_campaign(reordered, out, client=client)
    assert sorted(result.redone) == ["T18-1", "T18-2", "T18-3", "T18-4"]
    assert (out / "summary.nc").is_file()
    assert [name for name in client.run_on_scheduler(_semaphores)
            if Path(name).parent == out] == []


def _tasks_run(dask_worker) -> int:
    return dask_worker.state.executed_count


def test_report_rendered_on_the_cluster_is_the_serial_report(client, reordered, tmp_path):
    out = tmp_path / "out"
    process_campaign(reordered, out, client=client)
    created = datetime(2026, 1, 2, tzinfo=UTC)
    serial = build_report(out, created=created)
    expected = {path.name: path.read_bytes() for path in (serial.page, *serial.run_pages)}
    before, = client.run(_tasks_run).values()
    parallel = build_report(out, created=created, client=client)
    after, = client.run(_tasks_run).values()
    assert {path.name: path.read_bytes() for path in (parallel.page, *parallel.run_pages)
            } == expected
    assert after - before == 4 + 2  # a task per run page, per figure of the campaign page


def test_summary_of_reused_runs_read_back_on_the_cluster(client, reordered, tmp_path):
    out = tmp_path / "out"
    first = process_campaign(reordered, out, client=client)
    (out / ".outputs.json").unlink()  # the summary is rebuilt from the stored runs
    again = process_campaign(reordered, out, client=client)
    assert again.redone == [] and sorted(again.reused) == sorted(first.redone)
    xr.testing.assert_identical(again.summary.drop_attrs(), first.summary.drop_attrs())


def test_raw_files_are_hashed_in_the_runs_tasks(client, reordered, tmp_path, monkeypatch):
    from pipeline.store import freshness

    hashed_here = []
    monkeypatch.setattr(freshness, "sha256_file", hashed_here.append)
    out = tmp_path / "out"
    result = process_campaign(reordered, out, client=client)
    assert not result.failures and hashed_here == []  # not in this process
    cache = json.loads((out / ".hashes.json").read_text(encoding="utf-8"))
    expected = {str((reordered / name).resolve()): hashlib.sha256(
        (reordered / name).read_bytes()).hexdigest() for name in FILES_BY_SIZE}
    assert {path: entry["sha256"] for path, entry in cache.items()} == expected
    for path in result.run_files.values():
        attrs = read_dataset(path).attrs
        assert attrs["raw_sha256"] == expected[str((reordered / attrs["raw_file"]).resolve())]


@pytest.fixture
def long_log(simulated, monkeypatch) -> Path:
    """An engagement campaign of one 8 s log at 10 kHz (80 001 samples), a long log cut
    into chunks of 20 000 samples (in this process: seen by an in-process cluster)."""
    from pipeline import runs

    monkeypatch.setattr(runs, "WHOLE_SAMPLES", 20_000)
    monkeypatch.setattr(runs, "CHUNK_SAMPLES", 20_000)
    return simulated("engagement", "--teeth", "8", "--omega", "20", "--duration", "8",
                     "--sample-rate", "10000", "--format", "csv", "--seed", "3")


def _in_process_cluster():
    distributed = pytest.importorskip("distributed")
    return distributed.Client(processes=False, n_workers=2, threads_per_worker=1,
                              dashboard_address=":0")  # the module's cluster holds 8787


@pytest.mark.parametrize("split", [True, False])
def test_a_long_log_on_a_cluster_gives_the_serial_result(long_log, tmp_path, monkeypatch,
                                                         split):
    from dask.utils import key_split
    from distributed import get_task_stream

    from pipeline import campaign

    monkeypatch.setattr(campaign, "_worth_splitting", lambda *args: split)
    serial = process_campaign(long_log, tmp_path / "serial")
    with _in_process_cluster() as client, get_task_stream(client) as stream:
        clustered = process_campaign(long_log, tmp_path / "cluster", client=client)
    assert not serial.failures and not clustered.failures
    tasks = [key_split(task["key"]) for task in stream.data]
    chunks = -(-80_001 // 20_000) if split else 0  # 5: a task per chunk; or none
    assert tasks.count("scan_step") == tasks.count("fit_step") == chunks
    assert tasks.count("detect_step") == tasks.count("ringing_step") == int(split)
    assert tasks.count("finish_long_log") == 1  # dask's key_split drops the underscore
    (run_id, path), = serial.run_files.items()
    xr.testing.assert_identical(read_dataset(clustered.run_files[run_id]).drop_attrs(),
                                read_dataset(path).drop_attrs())
    xr.testing.assert_identical(clustered.summary.drop_attrs(), serial.summary.drop_attrs())


def test_a_bad_row_in_a_long_logs_chunk_fails_its_run_as_in_a_serial_run(long_log, tmp_path):
    campaign = shutil.copytree(long_log, tmp_path / "campaign")
    log, = campaign.glob("*.csv")
    lines = log.read_text(encoding="utf-8").splitlines(keepends=True)
    bad = 75_000  # beyond the rows read at open (pipeline.ingest.rowindex.EVERY)
    lines[bad] = re.sub(r"^([^,]*),[^,]*", r"\1,oops", lines[bad])
    log.write_text("".join(lines), encoding="utf-8")
    serial = process_campaign(campaign, tmp_path / "serial")
    with _in_process_cluster() as client:
        clustered = process_campaign(campaign, tmp_path / "cluster", client=client)
    (expected,), (found,) = serial.failures, clustered.failures
    assert "oops" in expected.message and f"line {bad + 1}" in expected.message
    assert found.message == expected.message
    assert clustered.run_files == {} and serial.run_files == {}


def test_a_dashboard_already_on_port_8787_gives_no_warning(recwarn):
    import socket

    busy = socket.socket()
    try:
        busy.bind(("127.0.0.1", 8787))  # as a dask dashboard of a notebook would
        busy.listen()
    except OSError:
        pass  # the port is taken already, which is the case under test
    try:
        with pytest.MonkeyPatch.context() as patch:
            patch.delenv("MALLOC_TRIM_THRESHOLD_", raising=False)
            with dask_client(1, None) as client:
                assert client.submit(sum, [1, 2]).result() == 3
    finally:
        busy.close()
    assert [str(warning.message) for warning in recwarn
            if "8787" in str(warning.message)] == []


@pytest.mark.parametrize(("long_mb", "others_mb", "slots", "split"), [
    (400, [50, 50, 50], 2, True),  # the others keep a second worker busy 150 of 400
    (400, [300, 200], 2, False),  # 500 of 400: both workers stay busy without it
    (400, [300, 200], 3, True),  # 500 over two other workers: 250 each, less than 400
    (400, [], 1, True),  # alone: its chunks are all there is to do
    (400, [500], 1, False),  # one worker, with other runs to do: nothing to gain
])
def test_a_long_log_is_split_when_it_would_finish_last_alone(long_mb, others_mb, slots, split):
    from pipeline.campaign import _LongLog, _Plan, _worth_splitting

    def plan(megabytes):
        return _Plan(None, Path("x"), None, {}, megabytes * 2**20, None)

    long = _LongLog(plan(long_mb), None, "", None)
    assert _worth_splitting(long, [plan(size) for size in others_mb], slots) is split
