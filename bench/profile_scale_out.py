"""Profile: where the wall time of ``chainbench run --workers N`` goes, against a serial run.

Each mode runs ``process_campaign`` with ``force=True`` into a fresh output
folder, in a fresh process, the modes interleaved round by round (so that load
from other processes hits them alike), and is cut into phases:

cluster
    starting the CLI's local cluster (:func:`pipeline.cli.run._dask_client`, the
    same settings) up to a connected client, its workers starting in the
    background;
imports
    the stages (:mod:`pipeline.campaign`), loaded as ``chainbench run`` loads
    them (:func:`pipeline.cli._stages.load_stages`), after the cluster's start
    as there, so that they compete with the workers' start-up as there;
plan
    ``process_campaign`` up to the runs: run sheet, raw-file hashes, input keys;
runs
    the runs (``_execute``), with, on a cluster, when the first task started
    computing, the tasks' compute time per worker and their sum;
tail
    after the last run: read-back, summary and tables (``summary``), then the
    report (``report``);
close
    shutting the cluster down;

and the CPU time (user, system) of the process and of its worker processes, with
the share of the machine's cores they kept busy over the whole run.
A mode is ``serial`` (no cluster) or a number of workers; ``ENV=VALUE,...``
after a colon runs it with those environment variables (e.g. the workers'
environment for a serial baseline with the same settings, or ``PYTHONPATH`` of
another copy of the package to compare versions); ``--workers 2`` is compared
with ``--workers 1`` of the same settings::

    .venv/bin/python bench/profile_scale_out.py /tmp/large/bench-engagement
    .venv/bin/python bench/profile_scale_out.py /tmp/large/bench-engagement --repeat 3 \\
        --modes serial serial:OMP_NUM_THREADS=1,MALLOC_TRIM_THRESHOLD_=65536 1 2
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

#: The environment variables of a worker that the profile reports.
WORKER_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS",
                    "MALLOC_TRIM_THRESHOLD_")
#: Phases printed, in order.
PHASES = ("cluster", "imports", "plan", "runs", "summary", "report", "close", "total")


def _timed(function: Callable[..., Any], record: dict[str, float]) -> Callable[..., Any]:
    """`function`, recording the perf_counter at its start and end in `record`."""

    def timed(*args: Any, **kwargs: Any) -> Any:
        record["start"] = time.perf_counter()
        try:
            return function(*args, **kwargs)
        finally:
            record["end"] = time.perf_counter()

    return timed


def _worker_environment() -> dict[str, str | None]:
    """The variables of :data:`WORKER_VARIABLES` in this process (run on a worker)."""
    return {name: os.environ.get(name) for name in WORKER_VARIABLES}


def _tasks(stream: list[dict[str, Any]], origin: float) -> dict[str, Any]:
    """First compute start [s after `origin`, wall clock] and compute seconds per worker."""
    computes = [(task["worker"], part) for task in stream for part in task["startstops"]
                if part["action"] == "compute"]
    per_worker: dict[str, float] = {}
    for worker, part in computes:
        per_worker[worker] = per_worker.get(worker, 0.0) + part["stop"] - part["start"]
    return {"first_task": min(part["start"] for _, part in computes) - origin,
            "compute": sorted(per_worker.values(), reverse=True), "tasks": len(stream)}


def profile(mode: str, campaign: str, output: str) -> dict[str, Any]:
    """Process `campaign` into `output` as `mode` (``serial`` or workers), phases timed."""
    start = time.perf_counter()
    from pipeline.cli._stages import load_stages
    from pipeline.cli.run import _dask_client

    execute: dict[str, float] = {}
    report: dict[str, float] = {}
    figures: dict[str, Any] = {}
    with _dask_client(None if mode == "serial" else int(mode), None) as client:
        phases = {"cluster": time.perf_counter() - start}
        flow = load_stages()
        phases["imports"] = time.perf_counter() - start - phases["cluster"]
        flow._execute = _timed(flow._execute, execute)
        flow.build_report = _timed(flow.build_report, report)
        if client is not None:
            from distributed import get_task_stream

            with get_task_stream(client) as stream:
                began, wall = time.perf_counter(), time.time()
                result = flow.process_campaign(campaign, output, force=True, client=client)
            figures = _tasks(stream.data, wall + execute["start"] - began)
            figures["worker_env"] = next(iter(client.run(_worker_environment).values()))
        else:
            began = time.perf_counter()
            result = flow.process_campaign(campaign, output, force=True)
        finished = time.perf_counter()
    phases.update(plan=execute["start"] - began, runs=execute["end"] - execute["start"],
                  summary=report["start"] - execute["end"],
                  report=report["end"] - report["start"], close=time.perf_counter() - finished,
                  total=time.perf_counter() - start)
    own = os.times()
    cpu = {"user": own.user, "sys": own.system, "workers_user": own.children_user,
           "workers_sys": own.children_system}
    return {"mode": mode, "phases": phases, "cpu": cpu, **figures,
            "runs_done": len(result.redone), "failures": len(result.failures),
            "report_error": result.report_error}


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
    if "compute" in figures:
        line += (f" | first task at {figures['first_task']:.2f} s, compute per worker "
                 + " ".join(f"{seconds:.1f}" for seconds in figures["compute"])
                 + f", worker env {figures['worker_env']}")
    if figures["failures"] or figures["report_error"]:
        line += f" | {figures['failures']} runs FAILED, report: {figures['report_error']}"
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
                  f"{one['phases']['runs'] / best[mode]['phases']['runs']:.2f}x")


if __name__ == "__main__":
    main()
