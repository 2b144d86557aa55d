"""Benchmark: a 10^7-row log read as row ranges (open_log) against read_table of the whole file.

Writes the engagement log of :mod:`bench_ingest` (time [s], force [N], wheel
angle [rad], 20 kHz, ``--rows`` samples) as plain CSV, as a European lab PC's
export (semicolons, decimal comma, cp1250) and as TDMS, then for each file,
measured in the same run:

* the baseline: ``read_table(file, kind="engagement")``, the whole table at once;
* by ranges: ``open_log(file)``, then ``reader.read(a, a + n)`` for ``--chunks``
  consecutive ranges, each table dropped before the next is read (as the
  chunked engagement pipeline holds one chunk at a time).

Each measurement runs in a fresh process (runs interleaved, so that load from
other processes hits both alike). Prints, per file, the best of ``--repeat``
wall times of each, their ratio (target for the CSV layouts: by ranges within
1.3x of the baseline) and the time of the open (the index pass), then the peak
memory of each: traced by :mod:`tracemalloc` (numpy arrays and Python objects,
in an untimed call; target for ranges: about one chunk's table, far below the
whole table) and the growth of the process's peak RSS (pyarrow's buffers
included, which tracemalloc does not see)::

    .venv/bin/python bench/bench_stream.py                 # 10^7 rows, 10 ranges
    .venv/bin/python bench/bench_stream.py --rows 2e6 --chunks 4
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
import tracemalloc
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

from _common import KIB, best_of, peak_kib, reset_peak, run_json
from bench_ingest import write_files

#: Largest time of the reads by range over read_table's (the CSV layouts).
TIME_TARGET = 1.3


def _whole(file: str) -> dict[str, Any]:
    """read_table of the whole file."""
    from pipeline.ingest import read_table

    table, _ = read_table(file, kind="engagement")
    return {"rows": len(table), "table_mib": table.memory_usage(index=False).sum() / KIB**2}


def _by_ranges(file: str, chunks: int) -> dict[str, Any]:
    """open_log, then the rows in `chunks` consecutive ranges, one table held at a time."""
    from pipeline.ingest import open_log

    start = time.perf_counter()
    reader = open_log(file)
    opened = time.perf_counter() - start
    size = -(-reader.n_rows // chunks)
    rows = largest = 0
    for first in range(0, reader.n_rows, size):
        table, _ = reader.read(first, min(first + size, reader.n_rows))
        rows += len(table)
        largest = max(largest, table.memory_usage(index=False).sum() / KIB**2)
        del table
    return {"rows": rows, "table_mib": largest, "open_seconds": opened}


#: The two reads: name -> (file, ranges) -> figures.
READS: dict[str, Callable[[str, int], dict[str, Any]]] = {
    "whole": lambda file, chunks: _whole(file), "ranges": _by_ranges}


def _worker(which: str, file: str, chunks: int) -> None:
    """Time one read in this process, then trace a second one; print the figures as JSON."""
    import pipeline.ingest  # noqa: F401  (imports are not part of the read)

    read = partial(READS[which], file, chunks)
    base = reset_peak()
    start = time.perf_counter()
    figures = read()
    figures.update(seconds=time.perf_counter() - start, rss_growth_mib=(peak_kib() - base) / KIB)
    tracemalloc.start()
    read()
    figures["traced_peak_mib"] = tracemalloc.get_traced_memory()[1] / KIB**2
    tracemalloc.stop()
    print(json.dumps(figures))


def _measure(which: str, *, file: Path, chunks: int) -> dict[str, Any]:
    return run_json([sys.executable, __file__, "--worker", which, "--file", str(file),
                     "--chunks", str(chunks)])


def main() -> None:
    """Write the logs, measure both reads on each, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=float, default=1e7)
    parser.add_argument("--chunks", type=int, default=10)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--worker", choices=tuple(READS))
    parser.add_argument("--file")
    args = parser.parse_args()
    if args.worker:
        _worker(args.worker, args.file, args.chunks)
        return
    with tempfile.TemporaryDirectory(prefix="chainbench-bench-") as folder:
        for name, file in write_files("engagement", int(args.rows), Path(folder)).items():
            best = best_of(partial(_measure, file=file, chunks=args.chunks),
                           tuple(READS), args.repeat)
            whole, ranges = best["whole"], best["ranges"]
            assert whole["rows"] == ranges["rows"], (whole, ranges)
            ratio = ranges["seconds"] / whole["seconds"]
            verdict = ("no target, reported" if name == "tdms" else
                       f"target <= {TIME_TARGET}: "
                       f"{'met' if ratio <= TIME_TARGET else 'SLOWER THAN TARGET'}")
            print(f"{name}: {whole['rows']:,} rows, {file.stat().st_size / 1e6:.0f} MB, "
                  f"{args.chunks} ranges")
            print(f"  read_table (whole)  : {whole['seconds']:7.3f} s")
            print(f"  open_log + reads    : {ranges['seconds']:7.3f} s "
                  f"(open, the index pass: {ranges['open_seconds']:.3f} s)")
            print(f"  time ratio {ratio:.2f} ({verdict})")
            for label, figures in (("whole", whole), ("ranges", ranges)):
                print(f"  peak memory, {label:6s}: traced {figures['traced_peak_mib']:6.0f} MiB, "
                      f"RSS growth {figures['rss_growth_mib']:6.0f} MiB "
                      f"(largest table held {figures['table_mib']:.0f} MiB)")
            print(f"  traced peak ratio ranges / whole: "
                  f"{ranges['traced_peak_mib'] / whole['traced_peak_mib']:.2f}")


if __name__ == "__main__":
    main()
