"""Readers: one raw file in, one canonical table (SI units, role-named columns) out.

Three entry points, one set of readers:

* :func:`read_table` reads a file: it recognises the file's format and
  layout and hands it to the reader of that layout;
* :func:`parse_table` reads the same from bytes in memory (an upload, a zip
  member, a test's literal); errors name the buffer's ``name``. It is the
  parse path of ``read_table``, which only opens the file, hands it on
  (:class:`~pipeline.ingest.source.FileSource`, read in blocks as the parsers
  ask) and closes it, so that ``parse_table(path.read_bytes())`` and
  ``read_table(path)`` give the same table and metadata;
* :func:`open_log` opens a long log to read it by row ranges
  (:class:`LogReader`, :mod:`pipeline.ingest.stream`): roles and units settled
  once at open, then ``reader.read(start, stop)`` gives rows ``[start, stop)``
  as ``read_table`` would, with the memory of those rows; picklable, for
  chunks read by dask tasks.

One module per layout, each reading a :class:`~pipeline.ingest.source.Source`
(a file or a buffer):

==================  =========================================================
layout              reader
==================  =========================================================
``mts``             :mod:`pipeline.ingest.mts` (MTS TestWare cyclic acquisition)
``machine_export``  :mod:`pipeline.ingest.delimited` (Instron Bluehill...)
``european_csv``    :mod:`pipeline.ingest.delimited`
``plain_csv``       :mod:`pipeline.ingest.delimited`
``xlsx``            :mod:`pipeline.ingest.xlsx` (also ``ods`` and ``xls``)
``tdms``            :mod:`pipeline.ingest.tdms`
==================  =========================================================

The three delimited layouts share one reader and differ only in how they are
recognised (:data:`pipeline.ingest.delimited.LAYOUTS`); which reader reads a
file is decided in :mod:`pipeline.ingest.formats`. By row range, delimited
text is read through an index of every 65,536th row
(:mod:`pipeline.ingest.rowindex`), TDMS through npTDMS's channel slices, and
MTS and workbooks (small logs) by reading the whole file and slicing it.

Nothing here knows physics: the table says what the file holds, in SI units,
and the warnings say what looked odd; the conditioning stage decides.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from pipeline.ingest import canonical, continuation
from pipeline.ingest.formats import FORMATS, check_options, read_raw, sniff
from pipeline.ingest.source import BufferSource, Source, opened
from pipeline.ingest.stream import LogReader, open_log
from pipeline.ingest.table import ROLES, ColumnInfo, TableMetadata

__all__ = ["FORMATS", "ROLES", "ColumnInfo", "LogReader", "TableMetadata", "open_log",
           "parse_table", "read_table"]


def read_table(
    path: str | Path,
    kind: str = "tensile",
    columns: Mapping | None = None,
    units: Mapping | None = None,
    format: str = "auto",
    sheet: str | int | None = None,
    *,
    specimen: str | int | None = None,
    sample_rate_hz: float | None = None,
    strict: bool = True,
) -> tuple[pd.DataFrame, TableMetadata]:
    """Read a raw test-machine file into the canonical table.

    The file is opened, handed to the parse path of :func:`parse_table`
    (read in blocks as the parsers ask, never whole nor mapped), and closed.

    Parameters
    ----------
    path : str or Path
        The file.
    kind : {"tensile", "engagement", "wear", "segment-load"}
        The run kind: a tensile log needs force and at least one gauge, an
        engagement log time and force, a wear log time or cycles and a
        section length or a gauge (the section's elongation), a segment-load
        log time, the chain force and the forces on both tooth segments.
    columns : mapping, optional
        Run-sheet ``columns``: role -> the file's column name (``"Load"``) or
        TDMS channel (``"Channel"`` or ``"Group/Channel"``); ``gauges`` may be
        a list. Roles not given are recognised from English, German, Polish
        and Spanish names, or from the unit.
    units : mapping, optional
        Run-sheet ``units``: role -> unit (``{"force": "kN", "gauges": "mm"}``),
        for files whose header carries none; it overrides the file's unit.
    format : str
        ``"auto"`` (by content, then suffix), ``"csv"`` (any text layout),
        ``"xlsx"``, ``"ods"``, ``"xls"``, ``"tdms"``, or one text layout (``"plain_csv"``,
        ``"european_csv"``, ``"machine_export"``, ``"mts"``).
    sheet : str or int, optional
        Sheet of a workbook (name or 0-based index); the first by default.
    specimen : str or int, optional
        Run-sheet ``specimen_in_file``: of the specimens whose columns stand side by
        side in the file (the same names repeated; Shimadzu Trapezium, Mecmesin
        Emperor), the one read: its label over the columns, or its place from 1 at
        the left. Such a file is refused without it.
    sample_rate_hz : float, optional
        Run-sheet ``sample_rate_hz`` [Hz]: the rate the rows were sampled at, for a
        file with no time column (the time of row ``i`` is ``i / sample_rate_hz``,
        over any rate its header states); a file with a time column is refused with
        it.
    strict : bool
        If False, role and unit problems become warnings and the table holds
        what could be converted (used by ``chainbench inspect``).

    Returns
    -------
    table : pandas.DataFrame
        Columns ``time`` [s], ``force`` [N], ``gauge_1``... [m], ``angle``
        [rad], ``cycle_count``, ``length`` [m], ``speed`` [m/s] (those
        present), float64, in file order.
    metadata : TableMetadata
        What was detected, and the warnings.

    Notes
    -----
    Choices made for defects that could go either way:

    * a half-written last row (no line end, and too few fields or a last
      number with fewer decimals than its column always has) is dropped with
      a warning; a short row that ends with a line end is an error;
    * a truncated TDMS file is read up to the cut with a warning saying where
      it stops (an error if nothing precedes the cut); npTDMS's own warnings
      join the table's instead of being printed;
    * time stepping backwards and time gaps are reported (warnings,
      ``metadata.time_monotonic`` and ``metadata.time_gaps``), never raised nor
      repaired: the conditioning stage decides;
    * NaN stretches are kept as NaN with a warning giving their count;
    * all-empty channels are dropped, sentinel values (-1e6, -999999, 9.9e37, ±999999999)
      become NaN, both with a warning.

    Raises
    ------
    IngestError
        Or one of its subclasses (:class:`~pipeline.errors.EmptyFileError`,
        :class:`~pipeline.errors.EncodingError`,
        :class:`~pipeline.errors.LayoutError`,
        :class:`~pipeline.errors.ColumnError`,
        :class:`~pipeline.errors.UnitError`,
        :class:`~pipeline.errors.ValueParseError`), each naming the file, the
        line and column where known, and what to do; a file that cannot be
        opened or read gives an :class:`~pipeline.errors.IngestError`.
    ValueError
        For an unknown `kind` or `format`.
    """
    check_options(kind, format)

    def read(path: Path) -> tuple[pd.DataFrame, TableMetadata]:
        with opened(path) as source:
            return _table(source, kind, columns, units, format, sheet, specimen,
                          sample_rate_hz, strict)

    table, metadata = read(Path(path))
    reading = {"kind": kind, "columns": columns, "units": units, "format": format,
               "sheet": sheet, "specimen": specimen, "sample_rate_hz": sample_rate_hz}
    return continuation.join_parts(Path(path), table, metadata, reading, read), metadata


def parse_table(
    buffer: bytes | bytearray | memoryview,
    kind: str = "tensile",
    columns: Mapping | None = None,
    units: Mapping | None = None,
    format: str = "auto",
    sheet: str | int | None = None,
    *,
    specimen: str | int | None = None,
    sample_rate_hz: float | None = None,
    strict: bool = True,
    name: str = "<buffer>",
) -> tuple[pd.DataFrame, TableMetadata]:
    """Parse the bytes of a raw test-machine file into the canonical table.

    The same readers as :func:`read_table`, on bytes in memory (an upload, a
    member of a zip archive, a test's literal): ``parse_table(path.read_bytes())``
    gives what ``read_table(path)`` gives, but for the file's name.

    Parameters
    ----------
    buffer : bytes-like
        The file's content (``bytes``, ``bytearray``, ``memoryview`` or
        ``mmap``), read without a copy; it must not change during the call.
        pyarrow's reading threads may hold a view of it for a moment after
        the call returns, so an ``mmap`` closed at once may refuse
        (``BufferError``): read from ``bytes``, or let the map be collected.
    kind, columns, units, format, sheet, specimen, sample_rate_hz, strict
        As for :func:`read_table`.
    name : str
        The name errors and :attr:`TableMetadata.file` give the buffer; its
        suffix counts as a file's would (``"run.tdms"``) when ``format="auto"``.

    Returns
    -------
    table : pandas.DataFrame
        As :func:`read_table`.
    metadata : TableMetadata
        As :func:`read_table`, with ``file`` = `name`.

    Raises
    ------
    IngestError
        As :func:`read_table`, naming `name` instead of a path.
    ValueError
        For an unknown `kind` or `format`.
    """
    check_options(kind, format)
    return _table(BufferSource(buffer, name), kind, columns, units, format, sheet, specimen,
                  sample_rate_hz, strict)


def _table(
    source: Source,
    kind: str,
    columns: Mapping | None,
    units: Mapping | None,
    format: str,
    sheet: str | int | None,
    specimen: str | int | None,
    sample_rate_hz: float | None,
    strict: bool,
) -> tuple[pd.DataFrame, TableMetadata]:
    """The parse path of :func:`read_table` and :func:`parse_table`."""
    raw = read_raw(source, sniff(source, format), columns, sheet, specimen)
    return canonical.build(raw, kind=kind, units=units, strict=strict, specimen=specimen,
                           sample_rate_hz=sample_rate_hz)
