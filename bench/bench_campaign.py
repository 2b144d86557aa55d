"""Benchmark: the campaign-level figures of docs/quality.md on a generated campaign.

On the campaign written by ``bench/large_campaign.py`` (a tensile and an
engagement campaign folder), each figure against its baseline measured in the
same run, every measurement in a fresh process (peak memory its own):

stiffness fits
    :func:`pipeline.campaign.process_campaign` on the tensile campaign, with
    the stiffness fits (:data:`FIT_FUNCTIONS` of :mod:`pipeline.fit.stiffness`)
    timed by wrapping them in this benchmark (the package is unchanged): their
    total time over the end-to-end time of ``process_campaign`` (target < 10 %).
peak memory
    ``process_campaign`` on the engagement campaign: peak memory over the
    process's after-import memory, over the decoded arrays of its largest log
    (``read_table`` and ``open_log`` are wrapped to see them: a log read by rows counts
    as its whole decoded table; target < 3x).
re-run with nothing changed
    ``chainbench run`` on both campaigns, twice into the same output folder:
    the second run's wall time over the first's (target < 5 %).
scale-out
    ``chainbench run --workers 1`` and ``--workers 2`` on the engagement
    campaign (many runs; with ``--force`` when the CLI has it), each into a
    fresh output folder, interleaved for ``--rounds`` rounds: the speed-up of
    the fastest of each (target >= 1.6x), and whether both wrote the same
    results. Reported as not available when ``chainbench run`` has no
    ``--workers``. Where the time goes: ``bench/profile_scale_out.py`` and
    ``bench/SCALE_OUT.md``.

The machine's load average is printed before and after. ::

    .venv/bin/python bench/large_campaign.py --out /tmp/large --quick
    .venv/bin/python bench/bench_campaign.py /tmp/large/bench-tensile /tmp/large/bench-engagement
    .venv/bin/python bench/bench_campaign.py /tmp/large/bench-tensile \
        /tmp/large/bench-engagement --scale-out-only --rounds 3
"""

from __future__ import annotations

import argparse
import functools
import json
import os
import re
import sys
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from _common import KIB, Timed, peak_kib, reset_peak, run_json, run_timed

#: The stiffness fits of a tensile run and of a campaign, in pipeline.fit.stiffness.
FIT_FUNCTIONS = ("fit_stiffness", "specimen_stiffness", "combine_specimens")

#: The ``chainbench`` command of this environment.
CHAINBENCH = Path(sys.executable).with_name("chainbench")

#: Rounds of ``--workers 1`` and ``--workers 2`` whose fastest give the scale-out figure.
SCALE_OUT_ROUNDS = 2


class StageTimer:
    """Total wall time and number of calls of the functions it wraps."""

    def __init__(self) -> None:
        self.seconds = 0.0
        self.calls = 0

    def wrap(self, function: Callable[..., Any]) -> Callable[..., Any]:
        """`function`, timed into this timer."""

        @functools.wraps(function)
        def timed(*args: Any, **kwargs: Any) -> Any:
            start = time.perf_counter()
            try:
                return function(*args, **kwargs)
            finally:
                self.seconds += time.perf_counter() - start
                self.calls += 1

        return timed


def replace_everywhere(function: Callable[..., Any], replacement: Callable[..., Any]) -> int:
    """Replace `function` by `replacement` in every loaded ``pipeline`` module.

    Catches it under every name a module imported it as, wherever the package's
    flow lives; returns the number of names replaced.
    """
    replaced = 0
    for name, module in list(sys.modules.items()):
        if name != "pipeline" and not name.startswith("pipeline."):
            continue
        for attribute, value in list(vars(module).items()):
            if value is function:
                setattr(module, attribute, replacement)
                replaced += 1
    return replaced


def _worker(campaign: str, output: str) -> None:
    """Process `campaign` into `output` in this process, fits timed; print JSON."""
    import pipeline.cli  # noqa: F401  (everything ``chainbench run`` loads, before patching)
    import pipeline.fit.stiffness as stiffness
    from pipeline.campaign import process_campaign
    from pipeline.ingest import open_log, read_table

    fits = StageTimer()
    for name in FIT_FUNCTIONS:
        function = getattr(stiffness, name)
        replace_everywhere(function, fits.wrap(function))
    largest = {"rows": 0, "bytes": 0}

    def record(rows: int, size: int) -> None:
        if size > largest["bytes"]:
            largest.update(rows=rows, bytes=size)

    @functools.wraps(read_table)
    def read_and_record(*args: Any, **kwargs: Any) -> Any:
        result = read_table(*args, **kwargs)
        record(len(result[0]), int(result[0].memory_usage(index=False).sum()))
        return result

    @functools.wraps(open_log)
    def open_and_record(*args: Any, **kwargs: Any) -> Any:
        reader = open_log(*args, **kwargs)  # a log read by rows: its arrays as if read whole
        row = reader.read(0, 1)[0].memory_usage(index=False).sum()
        record(reader.n_rows, int(row) * reader.n_rows)
        return reader

    replace_everywhere(read_table, read_and_record)
    replace_everywhere(open_log, open_and_record)
    base = reset_peak()
    start = time.perf_counter()
    result = process_campaign(campaign, output)
    seconds = time.perf_counter() - start
    print(json.dumps({
        "seconds": seconds, "fit_seconds": fits.seconds, "fit_calls": fits.calls,
        "peak_kib": peak_kib(), "base_kib": base, "largest_rows": largest["rows"],
        "largest_bytes": largest["bytes"], "failures": len(result.failures),
    }))


def process_in_worker(campaign: Path, output: Path) -> dict[str, Any]:
    """Process `campaign` into `output` in a fresh process (see :func:`_worker`)."""
    return run_json([sys.executable, __file__, "--worker", "--campaign", str(campaign),
                     "--output", str(output)])


def chainbench(*arguments: str | Path) -> Timed:
    """Run ``chainbench`` with `arguments`, timed, peak memory from ``wait4``."""
    return run_timed([str(CHAINBENCH), *map(str, arguments)])


def run_options() -> tuple[set[str], float]:
    """The options ``chainbench run`` has, and the wall time of ``chainbench run --help``."""
    shown = chainbench("run", "--help")
    return set(re.findall(r"--[a-z][a-z-]*", shown.output)), shown.seconds


@dataclass(frozen=True)
class FitShare:
    """Stiffness fits against the end-to-end time of processing the tensile campaign."""

    fit_seconds: float
    fit_calls: int
    end_to_end_seconds: float  #: process_campaign, wall
    peak_mib: float
    failures: int

    @property
    def share(self) -> float:
        """Fits' share of the end-to-end time."""
        return self.fit_seconds / self.end_to_end_seconds


def fit_share(tensile: Path, output: Path) -> FitShare:
    """Process the tensile campaign into the fresh folder `output`, fits timed."""
    run = process_in_worker(tensile, output)
    if not run["fit_calls"]:
        raise RuntimeError("no stiffness fit ran in the measuring process: has the flow "
                           "moved the fits out of process?")
    return FitShare(run["fit_seconds"], run["fit_calls"], run["seconds"],
                    run["peak_kib"] / KIB, run["failures"])


@dataclass(frozen=True)
class PeakMemory:
    """Peak memory of processing the engagement campaign, against its largest log."""

    growth_mb: float  #: peak over the after-import memory [MB]
    peak_mib: float
    largest_rows: int
    decoded_mb: float  #: decoded arrays of the largest log [MB]
    seconds: float
    failures: int

    @property
    def ratio(self) -> float:
        """Peak memory growth over the largest log's decoded arrays."""
        return self.growth_mb / self.decoded_mb


def peak_memory(engagement: Path, output: Path) -> PeakMemory:
    """Process the engagement campaign into the fresh folder `output`, memory watched."""
    run = process_in_worker(engagement, output)
    return PeakMemory((run["peak_kib"] - run["base_kib"]) * KIB / 1e6, run["peak_kib"] / KIB,
                      run["largest_rows"], run["largest_bytes"] / 1e6, run["seconds"],
                      run["failures"])


@dataclass(frozen=True)
class Pair:
    """Two ``chainbench run`` measurements: the figure and its baseline."""

    measured: Timed
    baseline: Timed
    identical: bool | None = None  #: whether both wrote the same results (None: not compared)


def rerun(campaigns: Sequence[Path], output: Path) -> Pair:
    """``chainbench run`` twice into `output` (fresh): the second, and the first as baseline."""
    first = chainbench("run", *campaigns, "--output", output)
    return Pair(chainbench("run", *campaigns, "--output", output), first)


def scale_out(campaigns: Sequence[Path], folder: Path, options: set[str],
              rounds: int = SCALE_OUT_ROUNDS) -> Pair | None:
    """``--workers 2`` against ``--workers 1``, the fastest of `rounds` each, interleaved
    (1, 2, 1, 2...) so that load from other processes hits both alike, each into a fresh
    output folder; None without ``--workers``."""
    if "--workers" not in options:
        return None
    force = ["--force"] if "--force" in options else []
    runs: dict[int, list[Timed]] = {1: [], 2: []}
    for round_number in range(rounds):
        for workers, found in runs.items():
            found.append(chainbench("run", *campaigns, "--output",
                                    folder / f"workers-{workers}-{round_number}",
                                    "--workers", str(workers), *force))
    one, two = (min(found, key=lambda run: run.seconds) for found in runs.values())
    return Pair(two, one, same_results(folder / "workers-1-0", folder / "workers-2-0"))


def same_results(first: Path, second: Path) -> bool:
    """Whether the folders hold the same netCDF files with the same values (attributes
    aside: they record when and from what each was made)."""
    import xarray as xr

    names = sorted(path.relative_to(first) for path in first.rglob("*.nc"))
    if not names or names != sorted(path.relative_to(second) for path in second.rglob("*.nc")):
        return False
    for name in names:
        with xr.open_dataset(first / name) as one, xr.open_dataset(second / name) as two:
            if not one.drop_attrs().identical(two.drop_attrs()):
                return False
    return True


def load_average() -> str:
    """The machine's load average over 1, 5 and 15 minutes."""
    return " ".join(f"{load:.2f}" for load in os.getloadavg())


def failures(*runs: Timed) -> str:
    """What went wrong in `runs` (exit code, last lines of output); '' when nothing did."""
    return "; ".join(
        f"exit code {run.returncode}: {' | '.join(run.output.strip().splitlines()[-3:])}"
        for run in runs if run.returncode != 0)


def print_campaign_figures(tensile: Path, engagement: Path, out: Path) -> None:
    """Measure and print the stiffness fits' share, the peak memory and the re-run."""
    fits = fit_share(tensile, out / "fits")
    print(f"stiffness fits: {fits.fit_seconds:.2f} s in {fits.fit_calls} calls of "
          f"{fits.end_to_end_seconds:.2f} s end to end = {fits.share:.1%} (target < 10 %)")
    memory = peak_memory(engagement, out / "memory")
    print(f"peak memory: {memory.growth_mb:.0f} MB over imports = {memory.ratio:.2f}x the "
          f"{memory.decoded_mb:.0f} MB of decoded arrays of the largest log "
          f"({memory.largest_rows:,} samples; target < 3x)")
    options, startup = run_options()
    again = rerun((tensile, engagement), out / "rerun")
    share = again.measured.seconds / again.baseline.seconds
    print(f"re-run: {again.measured.seconds:.2f} s after a first run of "
          f"{again.baseline.seconds:.2f} s = {share:.1%} (target < 5 %; CLI start-up "
          f"alone {startup:.2f} s) {failures(again.baseline, again.measured)}")


def print_scale_out(engagement: Path, out: Path, rounds: int) -> None:
    """Measure and print the scale-out figure on the engagement campaign."""
    workers = scale_out((engagement,), out, run_options()[0], rounds)
    if workers is None:
        print("scale-out: not available (chainbench run has no --workers)")
        return
    print(f"scale-out: --workers 1 {workers.baseline.seconds:.2f} s, --workers 2 "
          f"{workers.measured.seconds:.2f} s (fastest of {rounds} each) = "
          f"{workers.baseline.seconds / workers.measured.seconds:.2f}x (target >= 1.6x); "
          f"results {'identical' if workers.identical else 'DIFFER'} "
          f"{failures(workers.baseline, workers.measured)}")


def main() -> None:
    """Measure the campaign figures on the given campaign and print them."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("tensile", type=Path, nargs="?", help="the 16-run tensile campaign")
    parser.add_argument("engagement", type=Path, nargs="?", help="the engagement campaign")
    parser.add_argument("--scale-out-only", action="store_true",
                        help="measure the scale-out figure alone")
    parser.add_argument("--rounds", type=int, default=SCALE_OUT_ROUNDS,
                        help="rounds of --workers 1 and 2 for the scale-out figure")
    parser.add_argument("--worker", action="store_true")
    parser.add_argument("--campaign")
    parser.add_argument("--output")
    args = parser.parse_args()
    if args.worker:
        _worker(args.campaign, args.output)
        return
    if args.tensile is None or args.engagement is None:
        parser.error("give the tensile and the engagement campaign folders")
    print(f"load average before: {load_average()}")
    with tempfile.TemporaryDirectory(prefix="chainbench-bench-") as folder:
        if not args.scale_out_only:
            print_campaign_figures(args.tensile, args.engagement, Path(folder))
        print_scale_out(args.engagement, Path(folder), args.rounds)
    print(f"load average after: {load_average()}")


if __name__ == "__main__":
    main()
