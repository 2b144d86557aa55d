"""A test written in parts: the files its samples go on in.

Some machines split a long test's export over several files: MTS TestSuite
writes ``DAQ- Crosshead, … - (Timed).txt``, then ``… (Timed)1.txt``,
``… (Timed)2.txt``, each with the same header, the time running on from one
file to the next. A reader that met only the first part would give, without a
word, a test that stops where the file stops: :func:`join_parts` reads the
parts after the file (``read_table``), :func:`note_unread_parts` names them
with a warning where only the file is read (``open_log``, by row ranges).

A file counts as going on in a sibling named as it is with a number after its
stem (``1``, then ``2``...) when the sibling has the same columns and its time
starts after this file's last: specimens exported one to a file
(``Specimen_RawData_1.csv`` beside ``Specimen_RawData_11.csv``) each start
their time again, and do not count.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterator, Mapping
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.errors import IngestError
from pipeline.ingest import canonical
from pipeline.ingest.formats import TEXT_LAYOUTS, read_raw, sniff
from pipeline.ingest.source import BufferSource
from pipeline.ingest.table import GAP_FACTOR, TableMetadata

#: Bytes of a sibling read to find its columns and its first time (a header and some rows).
HEAD_BYTES = 1 << 16


def numbered_after(path: Path) -> Iterator[Path]:
    """The files named as `path` with 1, 2, ... after its stem, as long as they exist."""
    number = 1
    while (sibling := path.with_name(f"{path.stem}{number}{path.suffix}")).is_file():
        yield sibling
        number += 1


def head_of(path: Path) -> bytes:
    """The first :data:`HEAD_BYTES` of `path`, cut after its last whole line."""
    with path.open("rb") as file:
        head = file.read(HEAD_BYTES + 1)
    if len(head) <= HEAD_BYTES:
        return head
    return head[:head.rfind(b"\n") + 1]


def find_parts(path: Path, metadata: TableMetadata, last_time: Callable[[], float],
               reading: Mapping) -> list[tuple[Path, float]]:
    """The files the test of `path` goes on in, in order, with their first times [s].

    Parameters
    ----------
    path : Path
        The file read.
    metadata : TableMetadata
        Its metadata.
    last_time : callable
        Its last time [s] (NaN: no time, and no part is looked for), asked only
        when a numbered sibling exists.
    reading : mapping
        How it was read: ``kind``, ``columns``, ``units``, ``format``, ``sheet``,
        ``specimen``, ``sample_rate_hz``, as given to :func:`~pipeline.ingest.read_table`.
    """
    if metadata.layout not in TEXT_LAYOUTS or next(numbered_after(path), None) is None:
        return []
    names = [column.name for column in metadata.columns]
    return parts_after(path, names, last_time(), lambda sibling: first_of(sibling, reading))


def note_unread_parts(path: Path, metadata: TableMetadata, last_time: Callable[[], float],
                      reading: Mapping) -> None:
    """Name in `metadata` the parts of the test of `path` (:func:`find_parts`), which are
    not read, with a warning saying so."""
    last_time = functools.cache(last_time)
    parts = find_parts(path, metadata, last_time, reading)
    if parts:
        metadata.continued_in = [part.name for part, _ in parts]
        listed = ", ".join(f"'{part.name}'" for part, _ in parts)
        metadata.warnings.append(
            f"the test goes on in {listed}: {_runs_on(last_time(), parts[0][1])}; only this "
            "file is read, so the rest of the test is not in this run (join the parts in "
            "order into one file, with one names row, and name that file in the run sheet)")


def join_parts(path: Path, table: pd.DataFrame, metadata: TableMetadata, reading: Mapping,
               read: Callable[[Path], tuple[pd.DataFrame, TableMetadata]]) -> pd.DataFrame:
    """`table` with the tables of the parts the test of `path` goes on in, read by `read`.

    A part is joined when it has the columns (names, roles, units) of `path`
    and its time starts after the last time before it; the first that does
    not ends the test, with a warning. `metadata` gets the parts joined
    (``continued_in``), their rows, warnings (each naming its part), time
    steps back and gaps (also a gap between two files), and a note.
    """
    parts = find_parts(path, metadata, lambda: last_time_of(table), reading)
    if not parts:
        return table
    tables, times = [table], _finite_times(table)
    step = float(np.median(np.diff(times))) if times.size > 1 else math.nan
    for part, _ in parts:
        part_table, part_metadata = read(part)
        first, last = _finite_times(part_table), last_time_of(tables[-1])
        if part_metadata.columns != metadata.columns or not (first.size and first[0] > last):
            metadata.warnings.append(
                f"'{part.name}' is not read as a further part of the test: its columns or "
                "its time do not run on from the file before")
            break
        if first[0] - last > GAP_FACTOR * step:
            metadata.time_gaps += 1
            metadata.warnings.append(f"time: a gap of {first[0] - last:g} s before the part "
                                     f"'{part.name}'")
        tables.append(part_table)
        metadata.continued_in.append(part.name)
        metadata.rows += part_metadata.rows
        metadata.time_gaps += part_metadata.time_gaps
        if part_metadata.time_monotonic is False:
            metadata.time_monotonic = False
        metadata.warnings += [f"in '{part.name}': {warning}"
                              for warning in part_metadata.warnings]
    if len(tables) == 1:
        return table
    listed = ", ".join(f"'{name}'" for name in metadata.continued_in)
    metadata.warnings.insert(0, f"read with the parts the test goes on in, {listed}: "
                                f"{_runs_on(last_time_of(table), parts[0][1])}")
    return pd.concat(tables, ignore_index=True)


def _runs_on(last: float, next_first: float) -> str:
    return (f"the time runs on from this file's last ({last:g} s) to {next_first:g} s in the "
            "next, as a machine writes a long test in parts")


def first_of(path: Path, reading: Mapping) -> tuple[list[str], float] | None:
    """The column names and first time [s] of `path`'s head, read as `reading` says; None
    where it cannot be read so, or has no time."""
    source = BufferSource(head_of(path), str(path))
    try:
        raw = read_raw(source, sniff(source, reading["format"]), reading["columns"],
                       reading["sheet"], reading["specimen"])
        table, metadata = canonical.build(raw, kind=reading["kind"], units=reading["units"],
                                          strict=False, specimen=reading["specimen"],
                                          sample_rate_hz=reading["sample_rate_hz"])
    except IngestError:
        return None
    times = _finite_times(table)
    if times.size == 0:
        return None
    return [column.name for column in metadata.columns], float(times[0])


def last_time_of(table: pd.DataFrame) -> float:
    """The last finite time [s] of a canonical table (NaN without one)."""
    times = _finite_times(table)
    return float(times[-1]) if times.size else math.nan


def _finite_times(table: pd.DataFrame) -> np.ndarray:
    times = table["time"].to_numpy() if "time" in table else np.array([])
    return times[np.isfinite(times)]


def parts_after(path: Path, names: list[str], last_time: float,
                start: Callable[[Path], tuple[list[str], float] | None]
                ) -> list[tuple[Path, float]]:
    """The files the test of `path` goes on in, in order, with their first times [s].

    Each numbered sibling in turn counts if it has the same columns and starts
    after the time before: this file's last, then the part before's first.

    Parameters
    ----------
    path : Path
        The file read.
    names : list of str
        Its columns' names.
    last_time : float
        Its last time [s] (NaN: no time, and no part is looked for).
    start : callable
        A sibling's column names and first time [s], or None where it cannot
        be read as such.
    """
    parts: list[tuple[Path, float]] = []
    if math.isnan(last_time):
        return parts
    for sibling in numbered_after(path):
        found = start(sibling)
        if found is None or found[0] != names or not found[1] > last_time:
            break
        parts.append((sibling, found[1]))
        last_time = found[1]
    return parts
