"""Every figure of the performance table of docs/quality.md, in one command.

Each figure against a baseline measured in the same run, with the absolute
numbers and the peak memory beside, then the target and the verdict:

==========================  ====================================================
figure                      measured against
==========================  ====================================================
CSV ingest (plain,          ``pyarrow.csv.read_csv`` on the same engagement log
decimal comma)              (:mod:`bench_ingest`)
TDMS ingest                 ``nptdms.TdmsFile.read`` + channel arrays, same log
detection + extraction      the target 2e7 samples/s; the ratio is to one numpy
                            pass ``np.abs(np.diff(force))`` (:mod:`bench_engagement`)
stiffness fits              the end-to-end time of the 16-run tensile campaign
                            (:mod:`bench_campaign`)
re-run, nothing changed     the first ``chainbench run`` of the generated campaign
demo re-run                 the first ``chainbench run`` of a copy of the
                            repository's demo campaigns (also: under 0.5 s wall)
peak memory                 the decoded arrays of the campaign's largest log
scale-out                   ``chainbench run --workers 1`` on the engagement
                            campaign (many runs)
growth                      the time per run of a campaign of 100 small runs,
                            against 1,000 (``--quick``: 30 and 300); with the
                            campaign page's size and whether headless Chromium
                            opens it (:mod:`bench_growth`)
==========================  ====================================================

The machine's load average is printed with the figures: other work on the
machine slows some measurements more than their baselines.

Every measurement runs in a fresh process. The generated campaign
(:mod:`large_campaign`) and the logs live in a temporary folder unless ``--out``
keeps them. ``--quick`` measures on 2e6-sample logs and the quick campaign (about
6 minutes on 2 cores); without it, on 10^7-sample logs and the full campaign
(several 10^7-sample logs): the real figures::

    .venv/bin/python bench/run_all.py --quick
    .venv/bin/python bench/run_all.py --json bench/results.json
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import shutil
import sys
import tempfile
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, NamedTuple

from _common import KIB, run_json
from bench_campaign import (
    FitShare,
    Pair,
    PeakMemory,
    chainbench,
    failures,
    fit_share,
    peak_memory,
    rerun,
    run_options,
    scale_out,
)
from bench_engagement import TARGET as DETECTION_TARGET
from bench_growth import PAGE_TARGET, TIME_TARGET, measure, open_in_chromium
from bench_growth import SIZES as GROWTH_SIZES
from bench_ingest import ReadFigure
from bench_ingest import measure as measure_reads
from large_campaign import SIZES, CampaignSize, write_campaign

import pipeline

BENCH = Path(__file__).resolve().parent
#: The repository's demo campaigns.
DEMOS = BENCH.parent / "raw"
#: Largest wall time of a demo re-run with nothing changed [s].
DEMO_RERUN_TARGET = 0.5

#: Names of the ingest formats in the table.
FORMAT_LABELS = {"plain": "CSV ingest, plain", "decimal_comma": "CSV ingest, decimal comma",
                 "tdms": "TDMS ingest"}


class Mode(NamedTuple):
    """Sizes of one mode of the benchmark."""

    samples: int  #: samples of the log of the ingest and detection figures
    #: best of this many measurements of those figures: a read of a 2e6-row file in a
    #: fresh process takes 0.1 to 0.3 s (pyarrow's threads, fresh pages), as its baseline does
    repeat: int
    campaign: CampaignSize


MODES = {
    "quick": Mode(samples=2_000_000, repeat=5, campaign=SIZES["quick"]),
    "full": Mode(samples=10_000_000, repeat=3, campaign=SIZES["full"]),
}


@dataclass
class Row:
    """One printed row: a figure, its baseline, ratio, target and verdict."""

    figure: str
    measured: str
    baseline: str
    ratio: str
    target: str
    verdict: str
    peak: str
    note: str = ""
    values: dict[str, Any] = field(default_factory=dict)  #: the numbers, for --json


def verdict(met: bool) -> str:
    """The verdict of a figure against its target."""
    return "met" if met else "MISSED"


def ingest_rows(figures: list[ReadFigure]) -> list[Row]:
    """Rows of the ingest figures (read_table against pyarrow / npTDMS)."""
    rows = []
    for figure in figures:
        memory = (f"peak memory over imports {figure.reader_growth_mb:.0f} MB = "
                  f"{figure.memory_ratio:.2f}x the {figure.decoded_mb:.0f} MB of decoded "
                  f"arrays (target < 3x: {verdict(figure.memory_ratio < 3)}); "
                  f"{figure.file_mb:.0f} MB file; baseline peak "
                  f"{figure.baseline_peak_mib:.0f} MiB")
        rows.append(Row(
            figure=FORMAT_LABELS[figure.format],
            measured=f"read_table {figure.reader_seconds:.3f} s",
            baseline=f"{figure.baseline} {figure.baseline_seconds:.3f} s",
            ratio=f"{figure.ratio:.2f}x",
            target="-" if figure.target is None else f"<= {figure.target:g}x",
            verdict="no target" if figure.target is None
            else verdict(figure.ratio <= figure.target),
            peak=f"{figure.reader_peak_mib:.0f} MiB",
            note=memory,
            values={**asdict(figure), "ratio": figure.ratio,
                    "memory_ratio": figure.memory_ratio},
        ))
    return rows


def detection_row(samples: int, repeat: int) -> Row:
    """Row of detection + extraction throughput (one core, its own process)."""
    figures = run_json([sys.executable, str(BENCH / "bench_engagement.py"), "--samples",
                        str(samples), "--repeat", str(repeat), "--json"])
    rates = {label: figures[label]["samples_per_second"]
             for label in ("with_angle", "without_angle")}
    slower = min(rates, key=rates.__getitem__)
    run = figures[slower]
    total = run["detection_seconds"] + run["extraction_seconds"]
    return Row(
        figure="detection + extraction",
        measured=f"{rates[slower]:.3g} samples/s ({total:.3f} s)",
        baseline=f"np.abs(np.diff) {figures['baseline_seconds']:.4f} s",
        ratio=f"{total / figures['baseline_seconds']:.0f}x the numpy pass",
        target=f">= {DETECTION_TARGET:.0e} samples/s",
        verdict=verdict(rates[slower] >= DETECTION_TARGET),
        peak=f"{figures['peak_mib']:.0f} MiB",
        note=f"{figures['samples']:.3g}-sample log, one core, best CPU time of {repeat}; the "
             f"slower of with angle ({rates['with_angle']:.3g} samples/s) and without "
             f"({rates['without_angle']:.3g}): {slower.replace('_', ' ')}; peak memory "
             "includes simulating the log",
        values=figures,
    )


def _cli_values(pair: Pair) -> dict[str, Any]:
    """The numbers of a pair of ``chainbench run`` measurements (not their output)."""
    return {which: {"seconds": timed.seconds, "peak_kib": timed.peak_kib,
                    "returncode": timed.returncode}
            for which, timed in (("measured", pair.measured), ("baseline", pair.baseline))}


def fits_row(fits: FitShare, size: CampaignSize) -> Row:
    """Row of the stiffness fits' share of the tensile campaign's end-to-end time."""
    return Row(
        figure="stiffness fits share",
        measured=f"fits {fits.fit_seconds:.2f} s",
        baseline=f"end to end {fits.end_to_end_seconds:.2f} s",
        ratio=f"{fits.share:.1%}",
        target="< 10 %",
        verdict=verdict(fits.share < 0.10) if not fits.failures else "ERROR",
        peak=f"{fits.peak_mib:.0f} MiB",
        note=f"16-run tensile campaign at {size.tensile_rate:g} Hz; end to end = "
             "process_campaign (ingest, fits, store, summary, report) in one process, "
             f"start-up excluded; fits = {fits.fit_calls} calls of fit_stiffness, "
             "specimen_stiffness, combine_specimens, timed by wrapping them"
             + (f"; {fits.failures} runs FAILED" if fits.failures else ""),
        values=asdict(fits) | {"share": fits.share},
    )


def rerun_row(again: Pair, startup: float, size: CampaignSize) -> Row:
    """Row of the second ``chainbench run`` against the first."""
    share = again.measured.seconds / again.baseline.seconds
    problems = failures(again.baseline, again.measured)
    return Row(
        figure="re-run, nothing changed",
        measured=f"2nd run {again.measured.seconds:.2f} s",
        baseline=f"1st run {again.baseline.seconds:.2f} s",
        ratio=f"{share:.1%}",
        target="< 5 %",
        verdict="ERROR" if problems else verdict(share < 0.05),
        peak=f"{again.measured.peak_kib / KIB:.0f} MiB",
        note=f"chainbench run on both campaigns (16 tensile runs at {size.tensile_rate:g} Hz, "
             f"{size.runs + size.large_runs} engagement runs: {size.runs} of "
             f"{size.samples:.0e} and {size.large_runs} of {size.large_samples:.0e} samples); "
             f"CLI start-up alone (chainbench run --help) {startup:.2f} s = "
             f"{startup / again.baseline.seconds:.1%} of the first run; 1st run peak "
             f"{again.baseline.peak_kib / KIB:.0f} MiB" + (f"; {problems}" if problems else ""),
        values=_cli_values(again) | {"ratio": share, "startup_seconds": startup},
    )


def demo_rerun_row(folder: Path) -> Row:
    """Row of ``chainbench run`` twice on a copy of the demo campaigns: the second's wall time."""
    raw = folder / "demo-project" / "raw"
    shutil.copytree(DEMOS, raw)
    campaigns = sorted(sheet.parent for sheet in raw.glob("*/campaign.toml"))
    first, second = chainbench("run", *campaigns), chainbench("run", *campaigns)
    share = second.seconds / first.seconds
    problems = failures(first, second)
    return Row(
        figure="demo re-run, nothing changed",
        measured=f"2nd run {second.seconds:.2f} s",
        baseline=f"1st run {first.seconds:.2f} s",
        ratio=f"{share:.1%}",
        target=f"< 5 %, < {DEMO_RERUN_TARGET:g} s",
        verdict="ERROR" if problems else verdict(share < 0.05
                                                 and second.seconds < DEMO_RERUN_TARGET),
        peak=f"{second.peak_kib / KIB:.0f} MiB",
        note=f"chainbench run on a copy of {len(campaigns)} demo campaigns, twice; the second "
             "finds nothing changed and prints the recorded results"
             + (f"; {problems}" if problems else ""),
        values=_cli_values(Pair(second, first)) | {"ratio": share},
    )


def growth_row(folder: Path, mode: str) -> Row:
    """Row of the time per run of a large campaign of small runs against a small one."""
    small, large = (measure(folder / "growth", runs) for runs in GROWTH_SIZES[mode])
    browser = open_in_chromium(folder / "growth" / "processed" / f"bench-many-{large.runs}"
                               / "report.html")
    ratio = large.per_run / small.per_run
    met = ratio <= TIME_TARGET and large.page_bytes < PAGE_TARGET and browser.startswith(
        "opened")
    return Row(
        figure=f"growth, {small.runs} to {large.runs} runs",
        measured=f"{large.per_run:.3f} s a run",
        baseline=f"{small.per_run:.3f} s a run",
        ratio=f"{ratio:.2f}x",
        target=f"<= {TIME_TARGET:g}x; page < {PAGE_TARGET / 1e6:g} MB",
        verdict=verdict(met),
        peak=f"{large.peak_mib:.0f} MiB",
        note=f"chainbench run on campaigns of small tensile and engagement runs; campaign page "
             f"{large.page_bytes / 1e6:.2f} MB at {large.runs} runs, {large.run_pages} run pages "
             f"of {large.run_pages_bytes / 1e6:.1f} MB in all; report build "
             f"{1e3 * small.report_per_run:.0f} and {1e3 * large.report_per_run:.0f} ms a run; "
             f"headless Chromium: {browser}",
        values={"small": small._asdict(), "large": large._asdict(), "ratio": ratio,
                "browser": browser},
    )


def memory_row(memory: PeakMemory, size: CampaignSize) -> Row:
    """Row of the peak memory of processing the engagement campaign."""
    return Row(
        figure="peak memory",
        measured=f"{memory.growth_mb:.0f} MB over imports",
        baseline=f"decoded arrays {memory.decoded_mb:.0f} MB",
        ratio=f"{memory.ratio:.2f}x",
        target="< 3x",
        verdict=verdict(memory.ratio < 3) if not memory.failures else "ERROR",
        peak=f"{memory.peak_mib:.0f} MiB",
        note=f"process_campaign on the engagement campaign ({size.runs + size.large_runs} "
             "runs, summary and report); decoded arrays of its largest log "
             f"({memory.largest_rows:.3g} samples)"
             + (f"; {memory.failures} runs FAILED" if memory.failures else ""),
        values=asdict(memory) | {"ratio": memory.ratio},
    )


def scale_out_row(workers: Pair | None, forced: bool, size: CampaignSize) -> Row:
    """Row of ``--workers 2`` against ``--workers 1`` (None: the option is missing)."""
    if workers is None:
        return Row(figure="scale-out, 2 workers", measured="not available", baseline="-",
                   ratio="-", target=">= 1.6x", verdict="not available", peak="-",
                   note="chainbench run has no --workers option")
    speedup = workers.baseline.seconds / workers.measured.seconds
    problems = failures(workers.baseline, workers.measured)
    return Row(
        figure="scale-out, 2 workers",
        measured=f"--workers 2 {workers.measured.seconds:.2f} s",
        baseline=f"--workers 1 {workers.baseline.seconds:.2f} s",
        ratio=f"{speedup:.2f}x faster",
        target=">= 1.6x",
        verdict="ERROR" if problems else verdict(speedup >= 1.6),
        peak=f"{workers.measured.peak_kib / KIB:.0f} MiB",
        note=f"chainbench run{' --force' if forced else ''} on the engagement campaign "
             f"({size.runs + size.large_runs} runs), fresh output folders; "
             f"{os.cpu_count()} CPUs; peak RSS is the largest process (--workers 1: "
             f"{workers.baseline.peak_kib / KIB:.0f} MiB)" + (f"; {problems}" if problems else ""),
        values=_cli_values(workers) | {"speedup": speedup},
    )


def campaign_rows(folder: Path, size: CampaignSize) -> list[Row]:
    """Rows of the campaign figures, on a campaign of `size` generated into `folder`."""
    campaigns = write_campaign(folder / "raw", size)
    rows = [fits_row(fit_share(campaigns.tensile, folder / "processed-fits"), size)]
    options, startup = run_options()
    again = rerun((campaigns.tensile, campaigns.engagement), folder / "processed-rerun")
    rows.append(rerun_row(again, startup, size))
    rows.append(demo_rerun_row(folder))
    rows.append(memory_row(peak_memory(campaigns.engagement, folder / "processed-memory"),
                           size))
    workers = scale_out((campaigns.engagement,), folder / "processed-workers", options)
    rows.append(scale_out_row(workers, "--force" in options, size))
    return rows


COLUMNS = (("figure", "figure"), ("measured", "measured"), ("baseline", "baseline (same run)"),
           ("ratio", "ratio"), ("target", "target"), ("verdict", "verdict"),
           ("peak", "peak RSS"))


def print_table(title: str, rows: list[Row]) -> None:
    """Print the rows as a table, their notes numbered below it."""
    widths = [max(len(heading), *(len(getattr(row, name)) for row in rows))
              for name, heading in COLUMNS]
    line = "  ".join
    print(title)
    print(line(heading.ljust(width) for (_, heading), width in zip(COLUMNS, widths,
                                                                     strict=True)))
    print(line("-" * width for width in widths))
    for row in rows:
        print(line(getattr(row, name).ljust(width)
                   for (name, _), width in zip(COLUMNS, widths, strict=True)).rstrip())
    print()
    for number, row in enumerate(rows, 1):
        if row.note:
            print(f"[{number}] {row.figure}: {row.note}")


def main() -> None:
    """Measure every figure, print the table, write it as JSON when asked."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="2e6-sample logs and the quick campaign (about 6 minutes)")
    parser.add_argument("--out", type=Path, help="keep the logs and campaign here")
    parser.add_argument("--json", type=Path, help="also write the table to this JSON file")
    args = parser.parse_args()
    name = "quick" if args.quick else "full"
    mode = MODES[name]
    start, load_before = time.perf_counter(), os.getloadavg()[0]

    def progress(message: str) -> None:
        print(f"[{time.perf_counter() - start:5.0f} s] {message}", file=sys.stderr, flush=True)

    with tempfile.TemporaryDirectory(prefix="chainbench-bench-") as temporary:
        folder = args.out or Path(temporary)
        (folder / "logs").mkdir(parents=True, exist_ok=True)
        progress(f"ingest: {mode.samples:.0e}-sample engagement log, best of {mode.repeat}")
        rows = ingest_rows(measure_reads("engagement", mode.samples, mode.repeat,
                                         folder / "logs"))
        progress("detection + extraction")
        rows.append(detection_row(mode.samples, mode.repeat))
        progress("campaign: generate, fits, re-run, memory, workers")
        rows += campaign_rows(folder, mode.campaign)
        progress("growth: campaigns of many small runs")
        rows.append(growth_row(folder, name))
    seconds, load_after = time.perf_counter() - start, os.getloadavg()[0]
    title = (f"chainbench {pipeline.__version__} performance ({name} mode, "
             f"{mode.samples:.0e}-sample logs; {os.cpu_count()} CPUs, Python "
             f"{platform.python_version()}; measured in {seconds:.0f} s; load average "
             f"{load_before:.1f} before, {load_after:.1f} after)")
    print_table(title, rows)
    if args.json:
        document = {
            "command": " ".join([os.path.relpath(sys.executable), *sys.argv]),
            "mode": name, "date": datetime.datetime.now(datetime.UTC).isoformat(
                timespec="seconds"),
            "chainbench": pipeline.__version__, "python": platform.python_version(),
            "cpus": os.cpu_count(), "machine": platform.platform(), "seconds": seconds,
            "load_average": {"before": load_before, "after": load_after},
            "sizes": {"samples": mode.samples, "repeat": mode.repeat,
                      "campaign": mode.campaign._asdict()},
            "rows": [asdict(row) for row in rows],
        }
        args.json.write_text(json.dumps(document, indent=2) + "\n")
        print(f"\nwritten to {args.json}")


if __name__ == "__main__":
    main()
