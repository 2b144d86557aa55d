"""Reading a long log by row ranges: :func:`open_log` and :class:`LogReader`.

A 10^8-sample engagement log does not fit in memory as one table. The
reader opened by :func:`open_log` settles once, from the file's header, what
:func:`~pipeline.ingest.read_table` settles (layout, roles, SI units), then
reads any range of rows as the canonical table, with the memory of those rows:
``pd.concat([reader.read(a, b) ...])`` over a partition of the rows equals
``read_table(...)[0]``. It holds no open file between calls and is
picklable, so that a dask task can read its own rows.

How each layout reads rows ``[start, stop)``:

* delimited text (every :class:`~pipeline.ingest.delimited.TextLayout`, a
  Tektronix oscilloscope's export among them): one
  pass at open indexes every :data:`~pipeline.ingest.rowindex.EVERY`-th data
  row (:mod:`pipeline.ingest.rowindex`, numpy over blocks of bytes, about
  1 GB/s); a read finds its first and last byte from the nearest indexed
  rows and parses only those bytes with the body parser of ``read_table``
  (:func:`~pipeline.ingest.delimited.parse_rows`);
* TDMS: the file is opened per read (npTDMS streaming mode) and only the
  rows asked for are read from the channels that take a role;
* a LabVIEW ``.lvm`` file with its X column and no row comment
  (:func:`~pipeline.ingest.lvm.by_rows`): as delimited text; any other is read
  whole per call and sliced;
* MTS, Instron Merlin, workbooks and a Rigol oscilloscope's export (its time built from the
  sample number): the whole file is read per call and sliced (those layouts
  hold small logs).

At open, the columns that take a role are read until each has shown a value
(the first :data:`~pipeline.ingest.rowindex.EVERY` rows, as a rule): a column
empty in the whole file is dropped, as ``read_table`` drops it. Columns that
take no role are not scanned.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Protocol

import pandas as pd

from pipeline.errors import IngestError
from pipeline.ingest import continuation, delimited, lvm, tdms
from pipeline.ingest.canonical import (
    LONE_ROWS,
    Conversion,
    clean,
    convert_rows,
    empty_warning,
    first_values,
    lone_warning,
    settle,
    unlike_stated,
)
from pipeline.ingest.formats import TEXT_LAYOUTS, Sniffed, check_options, read_raw, sniff
from pipeline.ingest.raw import RawColumns, RawTable
from pipeline.ingest.rowindex import EVERY, RowIndex, index_rows
from pipeline.ingest.sniff import TableSpec
from pipeline.ingest.source import FileSource, Source, opened
from pipeline.ingest.table import TableMetadata
from pipeline.ingest.textbody import (
    Region,
    comment_warning,
    trim_truncated_tail,
    truncated_warning,
)

#: Rows read at a time at open, after the first :data:`~pipeline.ingest.rowindex.EVERY`, while
#: a column that takes a role has shown no value.
SCAN_ROWS = 1_000_000


class _Rows(Protocol):
    """How one layout reads its rows (see the module docstring).

    Attributes
    ----------
    header : RawColumns
        Names, units, role candidates, and the metadata with the whole-file
        warnings known at open.
    rows : int
        Data rows of the whole file.
    empty : set of int
        Columns known to hold no value without reading the rows.
    """

    header: RawColumns
    rows: int
    empty: set[int]

    def read(self, source: Source, start: int, stop: int) -> tuple[RawTable, list[str]]:
        """Rows ``[start, stop)`` of `source` (open) as read, and the reader's own warnings."""


@dataclass(frozen=True, eq=False)
class _TextRows:
    """Rows of a delimited text log, found through a :class:`RowIndex`."""

    header: RawColumns
    spec: TableSpec
    codec: str
    index: RowIndex

    @property
    def rows(self) -> int:
        return self.index.rows

    @property
    def empty(self) -> set[int]:
        return set()

    def read(self, source: Source, start: int, stop: int) -> tuple[RawTable, list[str]]:
        first, lines = self.index.locate(source, start)
        end = self.index.locate(source, stop)[0]
        region = Region(source, first, end, self.spec.data_index + 1 + lines, self.codec)
        parsed, _ = delimited.parse_rows(region, self.spec, self.header)  # said at open
        return delimited.raw_table(parsed, region, self.header, first_row=start), []


def _text_rows(
    source: Source, layout: delimited.TextLayout, sniffed: Sniffed, columns: Mapping | None
) -> _TextRows:
    """Index a delimited text log (see the module docstring)."""
    head, spec = sniffed.head, sniffed.spec
    header = layout.header(head, spec, columns)
    whole = delimited.body(head, spec, header.metadata.warnings)
    region, truncated = trim_truncated_tail(whole, spec.width, spec.delimiter, spec.decimal)
    index = index_rows(source, region.start, region.end, head.codec)
    delimited.require_rows(index.rows, region)
    if index.comments:
        header.metadata.warnings.append(
            comment_warning(region, index.comments, index.first_comment))
    if spec.pairs:
        header.metadata.warnings.append(delimited.PAIRS_WARNING)
    if truncated:
        header.metadata.warnings.append(truncated_warning(whole.first_line + index.lines))
    return _TextRows(header, spec, head.codec, index)


@dataclass(frozen=True)
class _TdmsRows:
    """Rows of a TDMS log, read from its channels per call."""

    layout: tdms.Layout

    @property
    def header(self) -> RawColumns:
        return self.layout.header

    @property
    def rows(self) -> int:
        return self.layout.rows

    @property
    def empty(self) -> set[int]:
        return self.layout.empty

    def read(self, source: Source, start: int, stop: int) -> tuple[RawTable, list[str]]:
        """The rows, and what npTDMS logs reading them that it did not log at open."""
        with tdms.reading(source, self.layout.cut) as (file, logged):
            raw = self.layout.read(file, start, stop)
        known = self.header.metadata.warnings
        return raw, [warning for warning in logged if warning not in known]


def _tdms_rows(source: Source, columns: Mapping | None) -> _TdmsRows:
    """Describe a TDMS log's channels (no sample read)."""
    cut = tdms.truncation(source)
    with tdms.reading(source, cut) as (file, logged):
        layout = tdms.describe(file, source.name, columns, cut)
    layout.header.metadata.warnings.extend(logged)
    return _TdmsRows(layout)


@dataclass(frozen=True)
class _WholeRows:
    """Rows of a small log (MTS, a workbook): the whole file read per call, then sliced."""

    header: RawColumns
    rows: int
    empty: set[int]
    layout: str
    columns: Mapping | None
    sheet: str | int | None
    specimen: str | int | None

    def read(self, source: Source, start: int, stop: int) -> tuple[RawTable, list[str]]:
        raw = read_raw(source, sniff(source, self.layout), self.columns, self.sheet,
                       self.specimen)
        arrays = {index: array[start:stop] for index, array in raw.arrays.items()}
        return replace(raw, arrays=arrays, rows=stop - start, first_row=start,
                       line_of=lambda row: raw.line_of(start + row)), []


def _whole_rows(
    source: Source, sniffed: Sniffed, columns: Mapping | None, sheet: str | int | None,
    specimen: str | int | None,
) -> _WholeRows:
    """Read a small log once, for its header, rows and empty columns."""
    raw = read_raw(source, sniffed, columns, sheet, specimen)
    return _WholeRows(raw.header(), raw.rows, raw.empty, sniffed.layout,
                      None if columns is None else dict(columns), sheet, specimen)


def _rows_reader(
    source: Source, sniffed: Sniffed, columns: Mapping | None, sheet: str | int | None,
    specimen: str | int | None,
) -> _Rows:
    """The row reader of the layout `sniffed` chose."""
    if sniffed.layout == "tdms":
        return _tdms_rows(source, columns)
    layout = TEXT_LAYOUTS.get(sniffed.layout)
    if layout is lvm and lvm.by_rows(sniffed.head, sniffed.spec):
        layout = lvm.TEXT
    if isinstance(layout, delimited.TextLayout):
        return _text_rows(source, layout, sniffed, columns)
    return _whole_rows(source, sniffed, columns, sheet, specimen)


@dataclass(eq=False)
class LogReader:
    """A log opened by :func:`open_log`: its rows read by range as the canonical table.

    Holds no open file between calls, and pickles small (about 4 KB for a
    10^7-row text log, mostly its index); a copy reads the same rows.

    Attributes
    ----------
    path : str
        The file.
    n_rows : int
        Data rows of the whole file (those :func:`~pipeline.ingest.read_table` returns).
    metadata : TableMetadata
        Layout, encoding, dialect, columns with roles and units, preamble, and
        the whole-file warnings known at open: a truncated last line or
        truncated TDMS file, values rejoined in pairs, unequal TDMS channels,
        units from the run sheet, empty columns that take a role (and TDMS
        channels without samples). ``time_monotonic`` and ``time_gaps`` stay
        unset: the warnings of :meth:`read` say what its rows show.
    """

    path: str
    n_rows: int
    metadata: TableMetadata
    _conversion: Conversion = field(repr=False)
    _rows: _Rows = field(repr=False)
    _stamp: tuple[int, int] = field(repr=False)

    def read(self, start: int, stop: int) -> tuple[pd.DataFrame, list[str]]:
        """Rows ``[start, stop)`` as the canonical table, and the warnings reading them gave.

        Parameters
        ----------
        start, stop : int
            0-based rows, ``0 <= start < stop <= n_rows``.

        Returns
        -------
        table : pandas.DataFrame
            The columns, SI units and float64 values of
            :func:`~pipeline.ingest.read_table`, indexed by file row
            (``start`` ... ``stop - 1``).
        warnings : list of str
            Sentinels, missing values, time steps back, repeated time stamps
            and time gaps within these rows (lines or samples counted in the
            file), and npTDMS's own.

        Raises
        ------
        ValueError
            If ``[start, stop)`` is empty or not within ``[0, n_rows)``.
        IngestError
            If the file cannot be read, has changed since it was opened, or
            its rows do not parse (naming the line and column, as ``read_table``).
        """
        start, stop = operator.index(start), operator.index(stop)
        if not 0 <= start < stop <= self.n_rows:
            raise ValueError(
                f"rows [{start}, {stop}) are not a non-empty range of the log's rows "
                f"[0, {self.n_rows})"
            )
        with opened(Path(self.path)) as source:
            if _stamp(source) != self._stamp:
                raise IngestError(
                    "the file has changed since it was opened", file=self.path,
                    hint="open it again (open_log) to read it as it is now",
                )
            raw, warnings = self._rows.read(source, start, stop)
            table, found = convert_rows(raw, self._conversion)
        return table, warnings + found

    def last_time(self) -> float:
        """The time of the last row [s]; NaN without a time, or where the row does not read
        (:meth:`read` of it raises then)."""
        if not self.n_rows:
            return math.nan
        try:
            return continuation.last_time_of(self.read(self.n_rows - 1, self.n_rows)[0])
        except IngestError:
            return math.nan


def _stamp(source: FileSource) -> tuple[int, int]:
    """Size [bytes] and modification time [ns] of an open file."""
    return source.size, source.modified


def open_log(
    path: str | Path,
    kind: str = "engagement",
    columns: Mapping | None = None,
    units: Mapping | None = None,
    format: str = "auto",
    sheet: str | int | None = None,
    specimen: str | int | None = None,
    sample_rate_hz: float | None = None,
) -> LogReader:
    """Open a log to read it by row ranges (see the module docstring).

    Parameters
    ----------
    path : str or Path
        The file.
    kind, columns, units, format, sheet, specimen, sample_rate_hz
        As for :func:`~pipeline.ingest.read_table` (but the empty rows below a
        shorter specimen's end are read, as missing values; ``kind`` defaults to
        ``"engagement"``); role and unit problems raise, as with ``strict=True``.

    Returns
    -------
    LogReader

    Raises
    ------
    IngestError
        What ``read_table`` raises for the file's header, layout, roles and
        units, or for a bad cell in the rows read at open (one further on is
        met by the :meth:`LogReader.read` that covers it).
    ValueError
        For an unknown `kind` or `format`.
    """
    check_options(kind, format)
    path = Path(path)
    with opened(path) as source:
        rows = _rows_reader(source, sniff(source, format), columns, sheet, specimen)
        empty, lone = _scan_candidates(source, rows)
        empty |= rows.empty
        stamp = _stamp(source)
    meta = rows.header.metadata
    if empty:
        meta.warnings.append(empty_warning(rows.header.names, empty))
    meta.warnings += [lone_warning(rows.header.names, index, value, line, rows.rows)
                      for index, (value, line) in lone.items()]
    conversion = settle(rows.header, empty | set(lone), kind=kind, units=units,
                        specimen=specimen, sample_rate_hz=sample_rate_hz)
    meta.rows = rows.rows
    meta.columns = list(conversion.infos)
    meta.warnings += unlike_stated(meta.preamble, meta.rows)
    reader = LogReader(str(path), rows.rows, meta, conversion, rows, stamp)
    continuation.note_unread_parts(path, meta, reader.last_time,
                                     {"kind": kind, "columns": columns, "units": units,
                                      "format": format, "sheet": sheet,
                                      "specimen": specimen, "sample_rate_hz": sample_rate_hz})
    return reader


def _scan_candidates(source: Source, rows: _Rows
                     ) -> tuple[set[int], dict[int, tuple[float, str]]]:
    """The columns that take a role and hold no value (after sentinels) in the whole file,
    and those holding one among :data:`~pipeline.ingest.canonical.LONE_ROWS` rows or more,
    with the value and where it stands (no channel, as ``read_table`` tells them:
    :func:`~pipeline.ingest.canonical.lone_warning`).

    Rows are read from the start until every such column has shown two values:
    the first :data:`~pipeline.ingest.rowindex.EVERY` rows, then
    :data:`SCAN_ROWS` at a time.
    """
    seen = dict.fromkeys(rows.header.candidates.indexes(), (0, math.nan, ""))
    start, size = 0, EVERY
    while start < rows.rows and any(count < 2 for count, _, _ in seen.values()):
        stop = min(start + size, rows.rows)
        raw = rows.read(source, start, stop)[0]
        clean(raw, [])
        for index, (count, value, line) in first_values(
                raw, {index for index, (count, _, _) in seen.items() if count < 2}).items():
            held = seen[index]
            seen[index] = (min(2, held[0] + count), *(held[1:] if held[0] else (value, line)))
        start, size = stop, SCAN_ROWS
    lone = ({index: (value, line) for index, (count, value, line) in seen.items() if count == 1}
            if rows.rows >= LONE_ROWS else {})
    return {index for index, (count, _, _) in seen.items() if count == 0}, lone
