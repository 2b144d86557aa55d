"""Readers: one raw file in, one canonical table (SI units, role-named columns) out.

:func:`read_table` is the entry point: it recognises the file's format and
layout and hands it to the reader of that layout, one module each:

==================  =========================================================
layout              reader
==================  =========================================================
``mts``             :mod:`pipeline.ingest.mts` (MTS TestWare cyclic acquisition)
``machine_export``  :mod:`pipeline.ingest.delimited` (Instron Bluehill...)
``european_csv``    :mod:`pipeline.ingest.delimited`
``plain_csv``       :mod:`pipeline.ingest.delimited`
``xlsx``            :mod:`pipeline.ingest.xlsx`
``tdms``            :mod:`pipeline.ingest.tdms`
==================  =========================================================

The three delimited layouts share one reader and differ only in how they are
recognised (:data:`pipeline.ingest.delimited.LAYOUTS`).

Nothing here knows physics: the table says what the file holds, in SI units,
and the warnings say what looked odd; the conditioning stage decides.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

import pandas as pd

from pipeline.errors import IngestError, LayoutError
from pipeline.ingest import canonical, delimited, mts, tdms, xlsx
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import detect_dialect, find_table, read_head
from pipeline.ingest.table import ROLES, ColumnInfo, TableMetadata

__all__ = ["FORMATS", "ROLES", "ColumnInfo", "TableMetadata", "read_table"]

#: Text layouts, in the order they are tried on a file.
TEXT_LAYOUTS = {mts.LAYOUT: mts, **{layout.name: layout for layout in delimited.LAYOUTS}}

#: Values of ``format``: auto-detection, a file format, or one text layout.
FORMATS = ("auto", "csv", "xlsx", "tdms", *TEXT_LAYOUTS)

_MAGIC = {b"PK\x03\x04": "xlsx", b"TDSm": "tdms"}
_OLD_EXCEL = b"\xd0\xcf\x11\xe0"


def read_table(
    path: str | Path,
    kind: str = "tensile",
    columns: Mapping | None = None,
    units: Mapping | None = None,
    format: str = "auto",
    sheet: str | int | None = None,
    *,
    strict: bool = True,
) -> tuple[pd.DataFrame, TableMetadata]:
    """Read a raw test-machine file into the canonical table.

    Parameters
    ----------
    path : str or Path
        The file.
    kind : {"tensile", "engagement"}
        The run kind: a tensile log needs force and at least one gauge, an
        engagement log time and force.
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
        ``"xlsx"``, ``"tdms"``, or one text layout (``"plain_csv"``,
        ``"european_csv"``, ``"machine_export"``, ``"mts"``).
    sheet : str or int, optional
        Sheet of an ``.xlsx`` workbook (name or 0-based index); the first by default.
    strict : bool
        If False, role and unit problems become warnings and the table holds
        what could be converted (used by ``chainbench inspect``).

    Returns
    -------
    table : pandas.DataFrame
        Columns ``time`` [s], ``force`` [N], ``gauge_1``... [m], ``angle``
        [rad], ``cycle_count`` (those present), float64, in file order.
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
    * all-empty channels are dropped, sentinel values (-1e6, -999999, 9.9e37)
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
        line and column where known, and what to do.
    """
    path = Path(path)
    if format not in FORMATS:
        raise ValueError(f"format must be one of {FORMATS}, not {format!r}")
    if kind not in canonical.REQUIRED:
        raise ValueError(f"kind must be one of {tuple(canonical.REQUIRED)}, not {kind!r}")
    try:
        resolved = _format_of(path) if format == "auto" else format
        if resolved == "xlsx":
            raw = xlsx.read(path, sheet, columns)
        elif resolved == "tdms":
            raw = tdms.read(path, columns)
        else:
            raw = _read_text(path, resolved, columns)
    except OSError as error:
        raise IngestError(
            f"cannot read the file: {error.strerror or error}",
            file=path, hint="check the run sheet's file entry and the file's permissions",
        ) from error
    return canonical.build(raw, kind=kind, units=units, strict=strict)


def _format_of(path: Path) -> str:
    """``"xlsx"``, ``"tdms"`` or ``"csv"`` from the file's first bytes, then its suffix."""
    with path.open("rb") as stream:
        magic = stream.read(4)
    if magic == _OLD_EXCEL or path.suffix.lower() == ".xls":
        raise LayoutError(
            "old binary Excel files (.xls) are not read",
            file=path, hint="save the workbook as .xlsx, or export the sheet as CSV",
        )
    suffix = {".xlsx": "xlsx", ".xlsm": "xlsx", ".tdms": "tdms"}.get(path.suffix.lower())
    return _MAGIC.get(magic, suffix or "csv")


def _read_text(path: Path, layout: str, columns: Mapping | None) -> RawTable:
    head = read_head(path)
    delimiter, decimal, width = detect_dialect(head.lines, path)
    spec = find_table(head.lines, path, delimiter, decimal, width)
    if layout == "csv":
        layout = next(name for name, reader in TEXT_LAYOUTS.items()
                      if reader.matches(head, spec))
    return TEXT_LAYOUTS[layout].read(head, spec, columns)
