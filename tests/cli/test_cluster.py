"""The command line's cluster: a campaign driven from a worker (:mod:`pipeline.cli._cluster`)."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from pipeline.cli._cluster import drive_on_cluster
from pipeline.errors import RunSheetError

distributed = pytest.importorskip("distributed")

#: Modules the command's own process must not load when a cluster does the work.
STAGE_MODULES = ("pipeline.campaign", "pipeline.runs", "pandas", "scipy", "xarray", "lmfit",
                 "matplotlib")


class _Heard:
    """A listener that keeps what it is told."""

    def __init__(self) -> None:
        self.calls: list[tuple] = []

    def runs(self, total: int) -> None:
        self.calls.append(("runs", total))

    def step(self, run_id: str, stage: str) -> None:
        self.calls.append(("step", run_id, stage))


def _count_up(limit: int, *, listener, client) -> int:
    """A driver: tells its listener of every step, and sums squares computed as tasks."""
    from pipeline.tasks import Mapped

    listener.runs(limit)
    for number in range(limit):
        listener.step(f"R{number}", "done")
    return sum(Mapped(pow, range(limit), client, exp=2).results())


def _refuse(*, listener, client) -> None:
    raise RunSheetError("no runs", file="campaign.toml", column="runs", hint="add one")


@pytest.fixture(scope="module")
def client():
    with distributed.Client(processes=False, n_workers=1, threads_per_worker=1,
                            dashboard_address=":0", set_as_default=False) as client:
        yield client


def test_the_driver_submits_tasks_to_its_own_worker_and_returns_its_result(client):
    heard = _Heard()
    # one worker of one thread: the driver's tasks run only once it has left that thread
    assert drive_on_cluster(client, _count_up, 4, listener=heard) == 0 + 1 + 4 + 9
    assert heard.calls == [("runs", 4), *(("step", f"R{n}", "done") for n in range(4))]


def test_an_error_of_the_driver_arrives_whole(client):
    with pytest.raises(RunSheetError) as raised:
        drive_on_cluster(client, _refuse, listener=_Heard())
    assert (raised.value.file, raised.value.column, raised.value.hint) == (
        "campaign.toml", "runs", "add one")


@pytest.mark.slow
def test_run_on_workers_leaves_the_command_without_the_stages(simulated, tmp_path):
    # The command's process (the scheduler's too) only forwards progress and prints: it
    # never loads the stages, whose import would compete with the workers' on two cores.
    campaign = simulated("tensile", "--specimens", "2", "--seed", "4")
    script = tmp_path / "command.py"
    script.write_text(textwrap.dedent(f"""
        import json, sys

        def main():
            from pipeline.cli import main as chainbench
            sys.argv = ["chainbench", "run", {str(campaign)!r}, "--output",
                        {str(tmp_path / "out")!r}, "--workers", "1"]
            try:
                chainbench()
            except SystemExit as end:
                code = end.code
            print(json.dumps({{"code": code, "loaded": [
                name for name in {STAGE_MODULES!r} if name in sys.modules]}}))

        if __name__ == "__main__":
            main()
    """), encoding="utf-8")
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                          timeout=300, cwd=tmp_path)
    *printed, last = done.stdout.splitlines()
    assert json.loads(last) == {"code": 0, "loaded": []}, done.stdout + done.stderr
    counts = next(index for index, line in enumerate(printed) if "run(s) processed" in line)
    finished = [line.strip() for line in printed[:counts] if line.endswith(": done")]
    assert sorted(finished) == ["T18-1: done", "T18-2: done"]  # progress, before the tables
    assert Path(tmp_path / "out").is_dir()
