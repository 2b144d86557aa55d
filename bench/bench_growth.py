"""Benchmark: a campaign of many small runs at two sizes; time per run flat, report usable.

For a small and a large number of small runs of both kinds (100 and 1,000;
``--quick``: 30 and 300), written by :func:`large_campaign.write_many_small`,
each measured in a fresh process:

time per run
    the wall time of ``chainbench run`` on the campaign (everything: runs,
    summary, tables, report) over its number of runs, at each size; the large
    size's over the small one's (target <= 1.2).
summary and report build
    the campaign's outputs rebuilt with every run reused (the manifest deleted,
    then :func:`pipeline.campaign.process_campaign`), the report's share timed
    by wrapping ``build_report``; per run at each size, and the ratio (linear:
    about 1). The summary's share includes reading every run back.
report size
    the campaign page ``report.html`` at the large size (target < 5 MB), and
    the total size of the runs' pages (``report-runs/``).
browser
    whether headless Chromium, launched as the report's browser test
    (``tests/report/test_report.py``) launches it, loads the large campaign
    page within that test's time limit, and in how long.

The machine's load average is printed before and after: other work on the
machine slows the measurements. Every process runs a copy of ``pipeline/``
taken at the start (first on ``PYTHONPATH``), so that an edit in the checkout
meanwhile changes neither the code measured nor its fingerprint (which would
redo every run in the rebuild). The campaigns, their outputs and the copy live
in a temporary folder unless ``--out`` keeps them::

    .venv/bin/python bench/bench_growth.py --quick
    .venv/bin/python bench/bench_growth.py              # 100 and 1,000 runs
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, NamedTuple

from _common import KIB, run_json, run_timed
from large_campaign import write_many_small

#: The ``chainbench`` command of this environment.
CHAINBENCH = Path(sys.executable).with_name("chainbench")
#: The repository.
ROOT = Path(__file__).resolve().parents[1]
#: The report's browser test, whose way of launching Chromium and time limit are reused.
BROWSER_TEST = ROOT / "tests" / "report" / "test_report.py"

#: Campaign sizes [runs]: small and large.
SIZES = {"quick": (30, 300), "full": (100, 1_000)}
#: Largest time per run at the large size over that at the small one.
TIME_TARGET = 1.2
#: Largest campaign page [bytes].
PAGE_TARGET = 5e6
MB = 1e6


class Growth(NamedTuple):
    """The figures of one campaign size."""

    runs: int
    run_seconds: float  #: ``chainbench run``, first run, wall time
    peak_mib: float  #: its peak memory
    outputs_seconds: float  #: summary, tables and report rebuilt, runs reused
    report_seconds: float  #: of which the report
    page_bytes: int  #: ``report.html``
    run_pages_bytes: int  #: every page of ``report-runs/``
    run_pages: int

    @property
    def per_run(self) -> float:
        return self.run_seconds / self.runs

    @property
    def report_per_run(self) -> float:
        return self.report_seconds / self.runs

    @property
    def summary_per_run(self) -> float:
        return (self.outputs_seconds - self.report_seconds) / self.runs


def rebuild(raw: Path, output: Path) -> dict[str, float]:
    """Worker: rebuild the campaign's outputs with every run reused; their times [s]."""
    import pipeline.campaign

    report = {"seconds": 0.0}
    build_report = pipeline.campaign.build_report

    def timed(*args: Any, **kwargs: Any) -> Any:
        start = time.perf_counter()
        try:
            return build_report(*args, **kwargs)
        finally:
            report["seconds"] += time.perf_counter() - start

    pipeline.campaign.build_report = timed
    (output / ".outputs.json").unlink()
    start = time.perf_counter()
    result = pipeline.campaign.process_campaign(raw, output)
    seconds = time.perf_counter() - start
    if result.redone or result.failures or result.report_error:
        raise RuntimeError(f"the rebuild was not a rebuild: {len(result.redone)} run(s) "
                           f"redone, {len(result.failures)} failed, report error: "
                           f"{result.report_error}")
    return {"seconds": seconds, "report_seconds": report["seconds"]}


def measure(root: Path, runs: int) -> Growth:
    """Write a campaign of `runs` small runs under `root`, process it and rebuild its outputs."""
    campaign = f"bench-many-{runs}"
    raw = root / "raw" / campaign
    start = time.perf_counter()
    write_many_small(raw, runs, campaign)
    print(f"{runs} runs: campaign written in {time.perf_counter() - start:.0f} s", flush=True)
    timed = run_timed([str(CHAINBENCH), "run", str(raw)])
    if timed.returncode != 0:
        raise RuntimeError(f"chainbench run failed ({timed.returncode}):\n{timed.output}")
    print(f"{runs} runs: chainbench run {timed.seconds:.1f} s ({timed.seconds / runs:.3f} s "
          f"a run, peak {timed.peak_kib / KIB:.0f} MiB)", flush=True)
    output = root / "processed" / campaign
    outputs = run_json([sys.executable, __file__, "--rebuild", str(raw), str(output)])
    print(f"{runs} runs: outputs rebuilt in {outputs['seconds']:.1f} s, of which the report "
          f"{outputs['report_seconds']:.1f} s", flush=True)
    pages = list((output / "report-runs").glob("*.html"))
    return Growth(runs, timed.seconds, timed.peak_kib / KIB, outputs["seconds"],
                  outputs["report_seconds"], (output / "report.html").stat().st_size,
                  sum(page.stat().st_size for page in pages), len(pages))


def use_a_copy_of_the_code(root: Path) -> None:
    """Copy ``pipeline/`` under `root` and put it first on ``PYTHONPATH`` for every process
    started from now on."""
    code = root / "code"
    shutil.copytree(ROOT / "pipeline", code / "pipeline",
                    ignore=shutil.ignore_patterns("__pycache__"))
    os.environ["PYTHONPATH"] = os.pathsep.join(
        filter(None, [str(code), os.environ.get("PYTHONPATH", "")]))


def _browser_test() -> Any:
    """The report's browser test module (its Chromium, flags and time limit)."""
    spec = importlib.util.spec_from_file_location("report_browser_test", BROWSER_TEST)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def open_in_chromium(page_file: Path) -> str:
    """Load `page_file` in headless Chromium as the browser test does; what happened."""
    test = _browser_test()
    if test.CHROMIUM is None:
        return "not measured: chromium is not installed"
    from playwright.sync_api import Error, sync_playwright

    limit = test.OPEN_TIMEOUT_MS / 1e3
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=test.CHROMIUM,
                                             args=test.CHROMIUM_ARGS)
        try:
            page = browser.new_page(viewport={"width": 1280, "height": 900})
            start = time.perf_counter()
            try:
                page.goto(page_file.as_uri(), timeout=test.OPEN_TIMEOUT_MS)
            except Error as error:
                return f"NOT opened within {limit:g} s ({str(error).splitlines()[0]})"
            seconds = time.perf_counter() - start
            figures = page.evaluate("document.querySelectorAll('svg').length")
            rows = page.evaluate("document.querySelectorAll('table.runs tbody tr').length")
        finally:
            browser.close()
    return (f"opened in {seconds:.1f} s (limit {limit:g} s): {figures} figures, "
            f"{rows} rows in the run table")


def verdict(met: bool) -> str:
    """The verdict of a figure against its target."""
    return "met" if met else "MISSED"


def report(small: Growth, large: Growth, browser: str) -> None:
    """Print the figures."""
    ratio = large.per_run / small.per_run
    print(f"\ntime per run: {small.per_run:.3f} s at {small.runs} runs, {large.per_run:.3f} s "
          f"at {large.runs}: ratio {ratio:.2f} (target <= {TIME_TARGET:g}: "
          f"{verdict(ratio <= TIME_TARGET)})")
    for name, attribute in (("summary (runs read back)", "summary_per_run"),
                            ("report (all pages)", "report_per_run")):
        low, high = getattr(small, attribute), getattr(large, attribute)
        print(f"{name} per run: {1e3 * low:.1f} ms at {small.runs} runs, {1e3 * high:.1f} ms "
              f"at {large.runs}: ratio {high / low:.2f} (linear: about 1)")
    print(f"peak memory of chainbench run: {small.peak_mib:.0f} MiB at {small.runs} runs, "
          f"{large.peak_mib:.0f} MiB at {large.runs}")
    print(f"campaign page at {large.runs} runs: {large.page_bytes / MB:.2f} MB (target < "
          f"{PAGE_TARGET / MB:g} MB: {verdict(large.page_bytes < PAGE_TARGET)}); at "
          f"{small.runs} runs: {small.page_bytes / MB:.2f} MB")
    print(f"run pages at {large.runs} runs: {large.run_pages} pages, "
          f"{large.run_pages_bytes / MB:.1f} MB in all "
          f"({large.run_pages_bytes / large.run_pages / 1e3:.0f} kB a page)")
    print(f"campaign page at {large.runs} runs in headless Chromium: {browser}")


def main() -> None:
    """Measure both sizes and print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="30 and 300 runs")
    parser.add_argument("--out", type=Path, help="keep the campaigns and outputs here")
    parser.add_argument("--rebuild", nargs=2, type=Path, metavar=("RAW", "OUTPUT"),
                        help=argparse.SUPPRESS)  # the worker of the outputs' rebuild
    args = parser.parse_args()
    if args.rebuild:
        print(json.dumps(rebuild(*args.rebuild)))
        return
    print(f"load average before: {' '.join(f'{load:.2f}' for load in os.getloadavg())}",
          flush=True)
    root = args.out or Path(tempfile.mkdtemp(prefix="bench-growth-"))
    try:
        use_a_copy_of_the_code(root)
        small, large = (measure(root, runs) for runs in SIZES["quick" if args.quick
                                                              else "full"])
        browser = open_in_chromium(root / "processed" / f"bench-many-{large.runs}"
                                   / "report.html")
        report(small, large, browser)
    finally:
        if args.out is None:
            shutil.rmtree(root, ignore_errors=True)
    print(f"load average after: {' '.join(f'{load:.2f}' for load in os.getloadavg())}")


if __name__ == "__main__":
    main()
