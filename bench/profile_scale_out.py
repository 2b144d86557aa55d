"""Profile: where the wall time of ``chainbench run --workers N`` goes, against a serial run.

Each mode processes the campaign as the command does (:func:`pipeline.cli.run._process`,
``--force``) into a fresh output folder, in a fresh process, the modes interleaved
round by round (so that load from other processes hits them alike), and is cut
into phases:

start
    the command's process up to a connected client of its local cluster
    (:func:`pipeline.cli._cluster.dask_client`, the same settings), the workers
    starting in the background; for ``serial``, nothing;
ready
    until the driver task starts on the first worker up (its imports done); for
    ``serial``, the stages' import in this process;
runs
    from then until the last run's task ends (the driver plans and submits them);
report
    the summary, the report's tasks and the printed text, until the driver ends;
close
    shutting the cluster down;

with, on a cluster, each worker's seconds spent in tasks other than the driver
and the share of the machine's cores the whole run kept busy (CPU time of this
process and of its workers), and whether this process loaded the stages (it
must not: the scheduler lives here, and the workers need both cores). A mode is
``serial`` (no cluster) or a number of workers; ``ENV=VALUE,...`` after a colon
runs it with those environment variables (e.g. ``PYTHONPATH`` of another copy
of the package, to compare versions)::

    .venv/bin/python bench/profile_scale_out.py /tmp/large/bench-engagement
    .venv/bin/python bench/profile_scale_out.py /tmp/large/bench-engagement --repeat 3 \\
        --modes 1 2 1:PYTHONPATH=/tmp/before 2:PYTHONPATH=/tmp/before
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path
from typing import Any

#: Phases printed, in order.
PHASES = ("start", "ready", "runs", "report", "close", "total")
#: Modules whose presence in the command's process says it loaded the stages.
STAGE_MODULES = ("pipeline.campaign", "pandas", "scipy", "xarray", "matplotlib")
#: Tasks that process runs (the rest, after them, are the report's).
RUN_TASKS = ("_process-", "_finish_long_log-", "scan_step-", "detect_step-",
             "ringing_step-", "fit_step-", "finish_step-")


def _cluster_phases(stream: list[dict[str, Any]], origin: float) -> dict[str, Any]:
    """From dask's task stream: when the driver started and ended, when the last run task
    ended [s after `origin`, wall clock], and each worker's seconds in other tasks."""
    computes = [(str(task["key"]), task["worker"], part) for task in stream
                for part in task["startstops"] if part["action"] == "compute"]
    driver = next(part for key, _, part in computes if key.startswith("_processed-"))
    runs_end = max(part["stop"] for key, _, part in computes if key.startswith(RUN_TASKS))
    busy: dict[str, float] = {}
    for key, worker, part in computes:
        if not key.startswith("_processed-"):
            busy[worker] = busy.get(worker, 0.0) + part["stop"] - part["start"]
    return {"driver_start": driver["start"] - origin, "runs_end": runs_end - origin,
            "driver_end": driver["stop"] - origin, "busy": sorted(busy.values(), reverse=True)}


def profile(mode: str, campaign: str, output: str) -> dict[str, Any]:
    """Process `campaign` into `output` as `mode` (``serial`` or workers), phases timed."""
    start, wall = time.perf_counter(), time.time()
    from pipeline.cli._cluster import dask_client
    from pipeline.cli.run import _process

    figures: dict[str, Any] = {}
    with dask_client(None if mode == "serial" else int(mode), None) as client:
        began = time.perf_counter() - start
        if client is None:
            from pipeline.cli._stages import load_stages

            load_stages()
            ready = time.perf_counter() - start
            outcome = _process(Path(campaign), Path(output), True, False, False, None, True)
            ended = time.perf_counter() - start
            phases = {"start": began, "ready": ready - began, "runs": float("nan"),
                      "report": float("nan")}
        else:
            from distributed import get_task_stream

            loaded = [name for name in STAGE_MODULES if name in sys.modules]
            with get_task_stream(client) as stream:
                outcome = _process(Path(campaign), Path(output), True, False, False, client,
                                   True)
            ended = time.perf_counter() - start
            figures = _cluster_phases(stream.data, wall)
            phases = {"start": began, "ready": figures["driver_start"] - began,
                      "runs": figures["runs_end"] - figures["driver_start"],
                      "report": figures["driver_end"] - figures["runs_end"]}
            figures["loaded"] = loaded + [name for name in STAGE_MODULES
                                          if name in sys.modules and name not in loaded]
    phases.update(close=time.perf_counter() - start - ended, total=time.perf_counter() - start)
    own = os.times()
    cpu = {"user": own.user, "sys": own.system, "workers_user": own.children_user,
           "workers_sys": own.children_system}
    document = outcome.document
    return {"mode": mode, "phases": phases, "cpu": cpu, **figures,
            "failures": document["failed"], "report": document["report"]}


def _environment(mode: str) -> tuple[str, dict[str, str]]:
    """The mode's name and its process environment (``MODE:NAME=VALUE,...``)."""
    name, _, settings = mode.partition(":")
    environment = dict(os.environ)
    environment.update(item.split("=", 1) for item in settings.split(",") if item)
    return name, environment


def measure(mode: str, campaign: Path, output: Path) -> dict[str, Any]:
    """Profile `mode` in a fresh process; its figures, labelled with the whole mode."""
    name, environment = _environment(mode)
    done = subprocess.run([sys.executable, __file__, "--child", name, str(campaign),
                           str(output)], capture_output=True, text=True, env=environment)
    if done.returncode != 0:
        raise RuntimeError(f"{mode} failed ({done.returncode}):\n{done.stderr[-3000:]}")
    return {**json.loads(done.stdout.strip().splitlines()[-1]), "mode": mode}


def describe(figures: dict[str, Any]) -> str:
    """One line of a measurement: its phases, CPU time and tasks."""
    phases = " ".join(f"{name} {figures['phases'][name]:5.2f}" for name in PHASES)
    cpu = figures["cpu"]
    busy = sum(cpu.values()) / ((os.cpu_count() or 1) * figures["phases"]["total"])
    line = (f"{figures['mode']:>12}: {phases} | cpu user {cpu['user']:.1f} sys "
            f"{cpu['sys']:.1f}, workers user {cpu['workers_user']:.1f} sys "
            f"{cpu['workers_sys']:.1f}, cores busy {busy:.0%}")
    if "busy" in figures:
        line += (" | in tasks per worker " + " ".join(f"{s:.2f}" for s in figures["busy"])
                 + f" s; stages in this process: {', '.join(figures['loaded']) or 'none'}")
    if figures["failures"] or figures["report"] is None:
        line += f" | {figures['failures']} runs FAILED, report: {figures['report']}"
    return line


def run_rounds(campaign: Path, modes: Sequence[str], repeat: int) -> dict[str, list[dict]]:
    """Every mode `repeat` times, interleaved; each measurement printed as it ends."""
    found: dict[str, list[dict[str, Any]]] = {mode: [] for mode in modes}
    with tempfile.TemporaryDirectory(prefix="chainbench-profile-") as folder:
        for round_number in range(repeat):
            for index, mode in enumerate(modes):
                figures = measure(mode, campaign, Path(folder) / f"{round_number}-{index}")
                found[mode].append(figures)
                print(describe(figures), flush=True)
    return found


def main() -> None:
    """Profile the modes on the campaign given; print every measurement and the best."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("campaign", type=Path, help="the campaign folder")
    parser.add_argument("output", nargs="?", help=argparse.SUPPRESS)
    parser.add_argument("--modes", nargs="+", default=["serial", "1", "2"])
    parser.add_argument("--repeat", type=int, default=2, help="rounds of every mode")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        print(json.dumps(profile(args.child, str(args.campaign), args.output)))
        return
    print(f"load average before: {' '.join(f'{load:.2f}' for load in os.getloadavg())}")
    found = run_rounds(args.campaign, args.modes, args.repeat)
    print(f"load average after: {' '.join(f'{load:.2f}' for load in os.getloadavg())}")
    print("fastest of each mode:")
    best = {mode: min(runs, key=lambda run: run["phases"]["total"])
            for mode, runs in found.items()}
    for figures in best.values():
        print(describe(figures))
    for mode in best:
        name, _, settings = mode.partition(":")
        one = best.get(":".join(filter(None, ("1", settings))))
        if name == "2" and one is not None:
            print(f"--workers 2 against --workers 1 {settings} (fastest of each): total "
                  f"{one['phases']['total'] / best[mode]['phases']['total']:.2f}x, runs "
                  f"{one['phases']['runs'] / best[mode]['phases']['runs']:.2f}x, report "
                  f"{one['phases']['report'] / best[mode]['phases']['report']:.2f}x")


if __name__ == "__main__":
    main()
