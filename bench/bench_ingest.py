"""Benchmark: CSV ingest of a 10^7-row log against ``pyarrow.csv.read_csv``.

Writes a tensile-style log (time, force, two gauges) in two layouts into a
temporary folder, then times, for each file, :func:`pipeline.ingest.read_table`
and the baseline ``pyarrow.csv.read_csv`` on the same file (the baseline is
told the delimiter and decimal mark, nothing else). Each measurement runs in a
fresh process, so that its peak memory (``ru_maxrss``) is its own.

Prints, per layout, the best of ``--repeat`` wall times of each (runs
interleaved, so that load from other processes hits both alike), their ratio
(target: plain <= 1.5, decimal comma <= 2.0), and the peak memory beside the
size of the decoded arrays (target: under 3x)::

    .venv/bin/python bench/bench_ingest.py            # 10^7 rows
    .venv/bin/python bench/bench_ingest.py --rows 1e6 # quicker
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc

LAYOUTS = {
    "plain": {
        "header": "time [s],force [kN],gauge1 [mm],gauge2 [mm]",
        "delimiter": ",",
        "decimal": ".",
        "target": 1.5,
    },
    "decimal_comma": {
        "header": "czas [s];siła [kN];wydłużenie 1 [mm];wydłużenie 2 [mm]",
        "delimiter": ";",
        "decimal": ",",
        "target": 2.0,
    },
}
CHUNK = 1_000_000


def write_log(path: Path, rows: int, layout: dict, seed: int = 0) -> None:
    """Write a synthetic 4-column log of `rows` rows in `layout` (pyarrow-vectorised)."""
    rng = np.random.default_rng(seed)
    encoding = "cp1250" if layout["decimal"] == "," else "utf-8"
    with path.open("wb") as stream:
        stream.write((layout["header"] + "\r\n").encode(encoding))
        for start in range(0, rows, CHUNK):
            index = np.arange(start, min(start + CHUNK, rows))
            time_s = index * 1e-4
            force = 60 + 40 * np.sin(2 * np.pi * 0.05 * time_s) + rng.normal(0, 0.05, index.size)
            gauge1 = force * 0.012 + rng.normal(0, 0.002, index.size)
            gauge2 = force * 0.011 + rng.normal(0, 0.002, index.size)
            cells = []
            for values, digits in ((time_s, 4), (force, 4), (gauge1, 5), (gauge2, 5)):
                text = pc.cast(pa.array(np.round(values, digits)), pa.string())
                if layout["decimal"] == ",":
                    text = pc.replace_substring(text, ".", ",")
                cells.append(text)
            lines = pc.binary_join_element_wise(*cells, layout["delimiter"])
            stream.write(("\r\n".join(lines.to_pylist()) + "\r\n").encode("ascii"))


def _peak() -> int:
    """Peak resident memory of this process [KiB] (VmHWM on Linux, else ru_maxrss)."""
    status = Path("/proc/self/status")
    if status.exists():
        for line in status.read_text().splitlines():
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def _reset_peak() -> int:
    """Reset the peak to the current resident memory where Linux allows; return it [KiB]."""
    try:
        Path("/proc/self/clear_refs").write_text("5")
    except OSError:
        pass
    return _peak()


def _worker(which: str, file: str, layout: str) -> None:
    """Run one measurement in this process and print it as JSON."""
    import pyarrow.csv as pacsv

    from pipeline.ingest import read_table

    base = _reset_peak()
    spec = LAYOUTS[layout]
    start = time.perf_counter()
    if which == "reader":
        table, _ = read_table(file)
        rows, columns = table.shape
    else:
        table = pacsv.read_csv(
            file,
            parse_options=pacsv.ParseOptions(delimiter=spec["delimiter"]),
            convert_options=pacsv.ConvertOptions(decimal_point=spec["decimal"]),
        )
        rows, columns = table.num_rows, table.num_columns
    seconds = time.perf_counter() - start
    peak = _peak()
    print(json.dumps({"seconds": seconds, "peak_kib": peak, "base_kib": base,
                      "rows": rows, "columns": columns}))


def _measure(which: str, file: Path, layout: str) -> dict:
    output = subprocess.run(
        [sys.executable, __file__, "--worker", which, "--file", str(file), "--layout", layout],
        check=True, capture_output=True, text=True,
    ).stdout
    return json.loads(output.strip().splitlines()[-1])


def main() -> None:
    """Generate the logs, measure, print the figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=float, default=1e7)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--worker", choices=("reader", "baseline"))
    parser.add_argument("--file")
    parser.add_argument("--layout", choices=tuple(LAYOUTS))
    args = parser.parse_args()
    if args.worker:
        _worker(args.worker, args.file, args.layout)
        return
    rows = int(args.rows)
    with tempfile.TemporaryDirectory(prefix="chainbench-bench-") as folder:
        for name, layout in LAYOUTS.items():
            file = Path(folder) / f"log_{name}.csv"
            start = time.perf_counter()
            write_log(file, rows, layout)
            size_mb = file.stat().st_size / 1e6
            print(f"{name}: {rows:,} rows, {size_mb:.0f} MB written in "
                  f"{time.perf_counter() - start:.1f} s")
            runs: dict[str, list[dict]] = {"baseline": [], "reader": []}
            for _ in range(args.repeat):  # interleaved, so that load from elsewhere hits both
                for which in runs:
                    runs[which].append(_measure(which, file, name))
            best = {which: min(found, key=lambda run: run["seconds"])
                    for which, found in runs.items()}
            decoded_mb = best["reader"]["rows"] * best["reader"]["columns"] * 8 / 1e6
            ratio = best["reader"]["seconds"] / best["baseline"]["seconds"]
            verdict = "ok" if ratio <= layout["target"] else "SLOWER THAN TARGET"
            print(f"  pyarrow.csv.read_csv : {best['baseline']['seconds']:7.3f} s, "
                  f"peak RSS {best['baseline']['peak_kib'] / 1024:7.0f} MiB")
            print(f"  read_table           : {best['reader']['seconds']:7.3f} s, "
                  f"peak RSS {best['reader']['peak_kib'] / 1024:7.0f} MiB "
                  f"(after imports {best['reader']['base_kib'] / 1024:.0f} MiB)")
            growth = (best["reader"]["peak_kib"] - best["reader"]["base_kib"]) * 1024 / 1e6
            print(f"  ratio {ratio:.2f} (target <= {layout['target']}: {verdict}); "
                  f"memory {growth:.0f} MB over imports = {growth / decoded_mb:.2f} x the "
                  f"{decoded_mb:.0f} MB of decoded arrays (target < 3)")


if __name__ == "__main__":
    main()
