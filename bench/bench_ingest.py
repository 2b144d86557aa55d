"""Benchmark: reading a 10^7-sample log, against pyarrow's and npTDMS's raw reads.

Writes one log into a temporary folder in each format, then times, for each
file, :func:`pipeline.ingest.read_table` and the baseline on the same file:

=================  ================================================  ===========
format             baseline                                          target
=================  ================================================  ===========
``plain``          ``pyarrow.csv.read_csv`` (told the delimiter)     <= 1.5x
``decimal_comma``  ``pyarrow.csv.read_csv`` (told delimiter and      <= 2x
                   decimal mark)
``tdms``           ``nptdms.TdmsFile.read`` and every channel's      reported
                   array (``channel[:]``)                            (no target)
=================  ================================================  ===========

``--log engagement`` (default; the figure of docs/quality.md): time [s], force [N] and
wheel angle [rad] from the virtual engagement bench (20 kHz, SNR 10), as plain
CSV, as a European lab PC's export (semicolons, decimal comma, cp1250, Polish
header) and as NI TDMS (time from the waveform properties). ``--log tensile``:
time, force and two gauges, in the two CSV layouts.

Each measurement runs in a fresh process, so that its peak memory (VmHWM) is
its own. Prints, per format, the best of ``--repeat`` wall times of each (runs
interleaved, so that load from other processes hits both alike), their ratio,
and the reader's peak memory over its imports as a multiple of the decoded
arrays (target: under 3x)::

    .venv/bin/python bench/bench_ingest.py                  # 10^7 samples
    .venv/bin/python bench/bench_ingest.py --rows 1e6       # quicker
    .venv/bin/python bench/bench_ingest.py --log tensile
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
from _common import CSV_LAYOUTS, KIB, best_of, peak_kib, reset_peak, run_json, write_delimited

from pipeline.simulate.engagement import (
    EngagementSettings,
    simulate_engagement,
    write_engagement_tdms,
)

#: Sampling rate of the engagement log [Hz].
ENGAGEMENT_RATE = 20e3


class LogKind(NamedTuple):
    """How a kind of log is written: its CSV headers, decimals and formats."""

    headers: dict[str, tuple[str, ...]]  #: CSV layout -> column names with units
    digits: tuple[int, ...]  #: decimals of each column in the CSV files
    formats: tuple[str, ...]  #: CSV layouts of :data:`_common.CSV_LAYOUTS`, and "tdms"


LOGS = {
    "engagement": LogKind(
        headers={"plain": ("time [s]", "force [N]", "angle [rad]"),
                 "decimal_comma": ("czas [s]", "siła [N]", "kąt [rad]")},
        digits=(5, 2, 5),
        formats=("plain", "decimal_comma", "tdms"),
    ),
    "tensile": LogKind(
        headers={"plain": ("time [s]", "force [kN]", "gauge1 [mm]", "gauge2 [mm]"),
                 "decimal_comma": ("czas [s]", "siła [kN]", "wydłużenie 1 [mm]",
                                   "wydłużenie 2 [mm]")},
        digits=(4, 4, 5, 5),
        formats=("plain", "decimal_comma"),
    ),
}

#: Baseline of each format: the worker's name for it, and what it is.
BASELINES = {
    "plain": ("pyarrow", "pyarrow.csv.read_csv"),
    "decimal_comma": ("pyarrow", "pyarrow.csv.read_csv"),
    "tdms": ("nptdms", "npTDMS TdmsFile.read + channel arrays"),
}


def make_log(log: str, rows: int) -> pd.DataFrame:
    """A synthetic log of kind `log` with about `rows` samples (columns in header order)."""
    if log == "engagement":
        settings = EngagementSettings(sample_rate=ENGAGEMENT_RATE,
                                      duration=(rows - 1) / ENGAGEMENT_RATE, snr=10.0)
        return simulate_engagement(settings, seed=1)[0]
    rng = np.random.default_rng(0)
    time_s = np.arange(rows) * 1e-4
    force = 60 + 40 * np.sin(2 * np.pi * 0.05 * time_s) + rng.normal(0, 0.05, rows)
    return pd.DataFrame({
        "time": time_s, "force": force,
        "gauge_1": force * 0.012 + rng.normal(0, 0.002, rows),
        "gauge_2": force * 0.011 + rng.normal(0, 0.002, rows),
    })


def write_files(log: str, rows: int, folder: Path) -> dict[str, Path]:
    """Write a log of kind `log` in each of its formats into `folder`; format -> file."""
    kind, table = LOGS[log], make_log(log, rows)
    files = {}
    for name in kind.formats:
        if name == "tdms":
            files[name] = write_engagement_tdms(table, folder / f"{log}.tdms")
            continue
        files[name] = folder / f"{log}_{name}.csv"
        write_delimited(files[name], kind.headers[name],
                        [table[column].to_numpy() for column in table.columns],
                        kind.digits, CSV_LAYOUTS[name])
    return files


def _reader(which: str, file_format: str, log: str) -> Callable[[str], tuple[int, int]]:
    """The read to time, imports done: file -> (rows, bytes of the decoded arrays)."""
    if which == "reader":
        from pipeline.ingest import read_table

        def read(file: str) -> tuple[int, int]:
            table, _ = read_table(file, kind=log)
            return len(table), int(table.memory_usage(index=False).sum())
    elif which == "nptdms":
        from nptdms import TdmsFile

        def read(file: str) -> tuple[int, int]:
            tdms = TdmsFile.read(file)
            arrays = [channel[:] for group in tdms.groups() for channel in group.channels()]
            return max(len(array) for array in arrays), sum(array.nbytes for array in arrays)
    else:
        import pyarrow.csv as pa_csv

        layout = CSV_LAYOUTS[file_format]

        def read(file: str) -> tuple[int, int]:
            table = pa_csv.read_csv(
                file,
                parse_options=pa_csv.ParseOptions(delimiter=layout.delimiter),
                convert_options=pa_csv.ConvertOptions(decimal_point=layout.decimal),
            )
            # Every column parses as float64 (and table.nbytes would decode the
            # header, which the baseline reads as UTF-8 whatever the file's encoding).
            return table.num_rows, 8 * table.num_rows * table.num_columns
    return read


def _worker(which: str, file: str, file_format: str, log: str) -> None:
    """Run one measurement in this process and print it as JSON."""
    read = _reader(which, file_format, log)
    base = reset_peak()
    start = time.perf_counter()
    rows, decoded = read(file)
    seconds = time.perf_counter() - start
    print(json.dumps({"seconds": seconds, "peak_kib": peak_kib(),
                      "base_kib": base, "rows": rows, "decoded_bytes": decoded}))


def _measure(which: str, *, file: Path, file_format: str, log: str) -> dict[str, Any]:
    return run_json([sys.executable, __file__, "--worker", which, "--file", str(file),
                     "--format", file_format, "--log", log])


@dataclass(frozen=True)
class ReadFigure:
    """read_table against its baseline on one file (best wall times, peak memory)."""

    log: str
    format: str
    rows: int
    file_mb: float
    baseline: str  #: what the baseline is
    baseline_seconds: float
    baseline_peak_mib: float
    reader_seconds: float
    reader_peak_mib: float
    reader_growth_mb: float  #: the reader's peak memory over its imports [MB]
    decoded_mb: float  #: the reader's decoded arrays [MB]
    target: float | None  #: largest ratio allowed (None: no target, reported only)

    @property
    def ratio(self) -> float:
        """read_table time over the baseline's."""
        return self.reader_seconds / self.baseline_seconds

    @property
    def memory_ratio(self) -> float:
        """The reader's peak memory over its imports, over the decoded arrays."""
        return self.reader_growth_mb / self.decoded_mb


def measure(log: str, rows: int, repeat: int, folder: Path) -> list[ReadFigure]:
    """Write the log of kind `log` into `folder` and measure each of its formats."""
    figures = []
    for file_format, file in write_files(log, rows, folder).items():
        baseline, label = BASELINES[file_format]
        best = best_of(partial(_measure, file=file, file_format=file_format, log=log),
                       (baseline, "reader"), repeat)
        reader = best["reader"]
        figures.append(ReadFigure(
            log=log, format=file_format, rows=reader["rows"],
            file_mb=file.stat().st_size / 1e6, baseline=label,
            baseline_seconds=best[baseline]["seconds"],
            baseline_peak_mib=best[baseline]["peak_kib"] / KIB,
            reader_seconds=reader["seconds"], reader_peak_mib=reader["peak_kib"] / KIB,
            reader_growth_mb=(reader["peak_kib"] - reader["base_kib"]) * KIB / 1e6,
            decoded_mb=reader["decoded_bytes"] / 1e6,
            target=CSV_LAYOUTS[file_format].target if file_format in CSV_LAYOUTS else None,
        ))
    return figures


def main() -> None:
    """Generate the log, measure, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--log", choices=tuple(LOGS), default="engagement")
    parser.add_argument("--rows", type=float, default=1e7)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--worker", choices=("reader", "pyarrow", "nptdms"))
    parser.add_argument("--file")
    parser.add_argument("--format", choices=tuple(BASELINES))
    args = parser.parse_args()
    if args.worker:
        _worker(args.worker, args.file, args.format, args.log)
        return
    with tempfile.TemporaryDirectory(prefix="chainbench-bench-") as folder:
        for figure in measure(args.log, int(args.rows), args.repeat, Path(folder)):
            if figure.target is None:
                verdict = "no target, reported"
            else:
                verdict = (f"target <= {figure.target}: "
                           f"{'met' if figure.ratio <= figure.target else 'SLOWER THAN TARGET'}")
            print(f"{figure.log} log, {figure.format}: {figure.rows:,} rows, "
                  f"{figure.file_mb:.0f} MB")
            print(f"  {figure.baseline:38s}: {figure.baseline_seconds:7.3f} s, "
                  f"peak RSS {figure.baseline_peak_mib:6.0f} MiB")
            print(f"  {'read_table':38s}: {figure.reader_seconds:7.3f} s, "
                  f"peak RSS {figure.reader_peak_mib:6.0f} MiB")
            print(f"  ratio {figure.ratio:.2f} ({verdict}); memory {figure.reader_growth_mb:.0f} "
                  f"MB over imports = {figure.memory_ratio:.2f}x the {figure.decoded_mb:.0f} MB "
                  "of decoded arrays (target < 3)")


if __name__ == "__main__":
    main()
