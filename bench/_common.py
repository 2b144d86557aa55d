"""Helpers shared by the benchmark scripts of ``bench/``.

* peak memory of this process (:func:`peak_kib`, :func:`reset_peak`),
* measurements in a fresh interpreter, so that each peak memory is its own
  (:func:`run_json` for a worker printing JSON, :func:`run_timed` for any
  command, e.g. ``chainbench run``, through this module as a light launcher),
* timing (:func:`best_cpu_time`, :func:`best_of`),
* delimited text logs in the layouts the ingest figures are measured on
  (:data:`CSV_LAYOUTS`, :func:`write_delimited`).

The scripts import this module as ``_common`` (``bench/`` is on ``sys.path``
when one of them runs). Run as a script, ``python bench/_common.py COMMAND...``
runs COMMAND and prints its wall time, peak memory and exit code as JSON (see
:func:`run_timed`); numpy and pyarrow are imported only where used, so that
the launcher stays small.
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, NamedTuple, TypeVar

if TYPE_CHECKING:
    import numpy as np

T = TypeVar("T")


class CsvLayout(NamedTuple):
    """A delimited text layout and its ingest target (docs/quality.md)."""

    delimiter: str
    decimal: str
    encoding: str
    target: float  #: largest read_table time over pyarrow.csv.read_csv on the same file


#: The two CSV layouts of docs/quality.md: a plain CSV, and a European lab PC's export
#: (semicolons, decimal comma, cp1250).
CSV_LAYOUTS = {
    "plain": CsvLayout(",", ".", "utf-8", 1.5),
    "decimal_comma": CsvLayout(";", ",", "cp1250", 2.0),
}

#: Rows formatted at a time by :func:`write_delimited`.
CHUNK = 1_000_000

KIB = 1024


def peak_kib() -> int:
    """Peak resident memory of this process [KiB] (VmHWM on Linux, else ru_maxrss)."""
    status = Path("/proc/self/status")
    if status.exists():
        for line in status.read_text().splitlines():
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def reset_peak() -> int:
    """Reset the peak to the current resident memory where Linux allows; return it [KiB]."""
    try:
        Path("/proc/self/clear_refs").write_text("5")
    except OSError:
        pass
    return peak_kib()


def run_json(command: Sequence[str]) -> dict[str, Any]:
    """Run `command` (a worker) to completion; its last line on stdout is a JSON object.

    Raises
    ------
    RuntimeError
        When the worker fails, with its stderr.
    """
    done = subprocess.run(list(command), capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}):\n{done.stderr}")
    return json.loads(done.stdout.strip().splitlines()[-1])


class Timed(NamedTuple):
    """Outcome of :func:`run_timed`."""

    seconds: float  #: wall time [s]
    peak_kib: int  #: peak RSS of the largest process of the command's tree that was waited for
    returncode: int
    output: str  #: stdout and stderr


def run_timed(command: Sequence[str]) -> Timed:
    """Run `command`, timed, its peak memory from ``wait4`` in a launcher (:func:`_launch`).

    A process started by a large one inherits its high-water mark at ``exec``:
    the launcher, a small fresh interpreter, starts `command` instead.
    """
    done = subprocess.run([sys.executable, __file__, *command], stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT)
    *output, last = done.stdout.decode("utf-8", errors="replace").rstrip("\n").split("\n")
    figures = json.loads(last)
    return Timed(figures["seconds"], figures["peak_kib"], figures["returncode"],
                 "\n".join(output))


def _launch(command: Sequence[str]) -> None:
    """Run `command` (its output passed through), then print its figures as JSON."""
    start = time.perf_counter()
    with subprocess.Popen(list(command)) as process:
        _, status, usage = os.wait4(process.pid, 0)
        seconds = time.perf_counter() - start
        process.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen
    print(json.dumps({"seconds": seconds, "peak_kib": usage.ru_maxrss,
                      "returncode": process.returncode}), flush=True)


def best_cpu_time(function: Callable[[], T], repeat: int) -> tuple[float, T]:
    """Best CPU time [s] of `repeat` calls of `function`, and its last result."""
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.process_time()
        result = function()
        best = min(best, time.process_time() - start)
    return best, result


def best_of(measure: Callable[[str], dict[str, Any]], names: Sequence[str],
            repeat: int) -> dict[str, dict[str, Any]]:
    """Per name, the fastest (``"seconds"``) of `repeat` calls of ``measure(name)``.

    The rounds are interleaved (all names, then all names again...), so that load
    from other processes hits every name alike.
    """
    runs: dict[str, list[dict[str, Any]]] = {name: [] for name in names}
    for _ in range(repeat):
        for name in names:
            runs[name].append(measure(name))
    return {name: min(found, key=lambda run: run["seconds"]) for name, found in runs.items()}


def write_delimited(path: Path, header: Sequence[str], columns: Sequence[np.ndarray],
                    digits: Sequence[int], layout: CsvLayout) -> None:
    """Write `columns` as a delimited text log in `layout` (pyarrow-vectorised, CRLF).

    Parameters
    ----------
    path : Path
        File to write.
    header : sequence of str
        Column names (with units), one a column.
    columns : sequence of numpy.ndarray
        Equal-length float columns.
    digits : sequence of int
        Decimals each column is rounded to.
    layout : CsvLayout
        Delimiter, decimal mark and encoding.
    """
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc

    rows = len(columns[0])
    with path.open("wb") as stream:
        stream.write((layout.delimiter.join(header) + "\r\n").encode(layout.encoding))
        for start in range(0, rows, CHUNK):
            cells = []
            for values, places in zip(columns, digits, strict=True):
                text = pc.cast(pa.array(np.round(values[start:start + CHUNK], places)),
                               pa.string())
                if layout.decimal != ".":
                    text = pc.replace_substring(text, ".", layout.decimal)
                cells.append(text)
            lines = pc.binary_join_element_wise(*cells, layout.delimiter)
            stream.write(("\r\n".join(lines.to_pylist()) + "\r\n").encode("ascii"))


if __name__ == "__main__":
    _launch(sys.argv[1:])
