"""Workbooks: ``.xlsx`` (openpyxl through pandas), OpenDocument ``.ods`` and old
binary Excel ``.xls`` (calamine through pandas), the same tables as the text layouts.

The table is looked for on the first sheet, or on the sheet the run sheet
names, exactly as in a text file (when the first sheet holds no log, on the one
other sheet that does, with a note: a results sheet exported before the raw
data): an optional preamble, a names row, an
optional units row, then data rows. Line numbers in messages are sheet rows.

File defects handled
--------------------
* empty sheet, or a sheet name that does not exist (error listing the sheets);
* the table not in ``A1``: empty rows and columns around it are skipped;
* a preamble, a separate units row, units in brackets in the names row;
* numbers stored as text, with a ``.`` or ``,`` decimal mark;
* a time column of clock readings (time cells, or text such as
  ``14:03:27.125``): seconds after the first row's (:mod:`pipeline.ingest.clock`);
* a non-numeric cell (error naming the sheet row and the column);
* empty rows inside the table (skipped), empty cells (NaN);
* a file that is not a valid workbook (error).
"""

from __future__ import annotations

import math
import numbers
import warnings
from collections.abc import Mapping

import numpy as np
import pandas as pd
import pyarrow as pa

from pipeline.errors import ChainbenchError, EmptyFileError, LayoutError, ValueParseError
from pipeline.ingest.clock import ClockColumn
from pipeline.ingest.delimited import (
    header_columns,
    names_line,
    numeric_candidates,
    time_clocks,
    units_line,
)
from pipeline.ingest.preamble import parse_preamble
from pipeline.ingest.raw import RawTable
from pipeline.ingest.roles import display_name, find_candidates
from pipeline.ingest.sniff import (
    RESULTS_ROWS,
    cell_hint,
    detect_dialect,
    find_table,
    is_missing,
    is_number,
    require_names,
)
from pipeline.ingest.source import Source
from pipeline.ingest.table import TableMetadata

#: The workbook layouts, each with the engine pandas reads it with.
LAYOUTS = {"xlsx": "openpyxl", "ods": "calamine", "xls": "calamine"}

#: Sheet rows looked at to find the table.
HEAD_ROWS = 200


def _text(value: object) -> str:
    """A cell as the text sniffing sees (numbers in Python's notation)."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return repr(float(value))
    return str(value).replace("\t", " ").replace("\r", " ").replace("\n", " ")


def _sniffed(text: str) -> str:
    """A cell's text as the table sniffer sees it: a decimal comma becomes a point.

    Each cell of a sheet is typed on its own, so a number stored as text with a
    decimal comma (``"1,5"``) is a number next to real numbers (``1.5``); seen
    as text it would make its row look like a names row.
    """
    return text.replace(",", ".") if is_number(text, ",") else text


def _unreadable(name: str, layout: str, error: Exception) -> LayoutError:
    """The error for a workbook of `layout` its engine cannot read."""
    return LayoutError(
        f"not a readable .{layout} workbook ({type(error).__name__}: {error})",
        file=name, hint="open it in a spreadsheet program and save it again as .xlsx",
    )


def _open_sheet(source: Source, sheet: str | int | None, layout: str
                ) -> tuple[pd.DataFrame, str, list[str]]:
    """The sheet `sheet` (the first by default) of a workbook of `layout`, its name, and
    notes: another sheet than the first taken (:func:`_the_log_sheet`), and what the
    workbook's reader warned of (openpyxl on a damaged part it leaves out), which
    would otherwise reach the console only."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", UserWarning)
        frame, name, note = _sheet(source, sheet, layout)
    told = [warning for warning in caught if issubclass(warning.category, UserWarning)]
    for other in caught:  # a library's deprecation, say: warned as it would have been
        if other not in told:
            warnings.warn_explicit(other.message, other.category, other.filename, other.lineno)
    return frame, name, [*([note] if note else []),
                         *(f"the workbook's reader ({LAYOUTS[layout]}): {warning.message}"
                           for warning in told)]


def _sheet(source: Source, sheet: str | int | None, layout: str
           ) -> tuple[pd.DataFrame, str, str | None]:
    """:func:`_open_sheet` without the reader's warnings: the note is the other sheet
    taken, if any."""
    file = source.name
    try:
        workbook = pd.ExcelFile(source.file(), engine=LAYOUTS[layout])
    except Exception as error:  # openpyxl / zipfile raise many kinds on a broken file
        raise _unreadable(file, layout, error) from error
    with workbook:
        names = workbook.sheet_names
        wanted = 0 if sheet is None else sheet
        if (isinstance(wanted, int) and not 0 <= wanted < len(names)) or (
            isinstance(wanted, str) and wanted not in names
        ):
            raise LayoutError(
                f"no sheet {wanted!r} in the workbook",
                file=file, hint="the workbook has the sheets: " + ", ".join(map(repr, names)),
            )
        name = names[wanted] if isinstance(wanted, int) else wanted
        note = None
        try:
            frame = pd.read_excel(workbook, sheet_name=name, header=None)
            if sheet is None and len(names) > 1 and not _holds_a_log(frame):
                frame, name, note = _the_log_sheet(workbook, frame, name, file)
        except ChainbenchError:
            raise
        except Exception as error:  # the sheet's XML is parsed only now, and may be broken
            raise _unreadable(file, layout, error) from error
    frame = frame.dropna(axis=1, how="all")
    if frame.empty:
        raise EmptyFileError(
            f"sheet {name!r} is empty", file=file,
            hint="give the sheet holding the data in the run sheet (sheet = \"...\")",
        )
    return frame, name, note


def _holds_a_log(frame: pd.DataFrame) -> bool:
    """Whether a sheet holds more rows of two numbers or more than a results table does
    (:data:`~pipeline.ingest.sniff.RESULTS_ROWS`), among the rows the table is looked for
    in (:data:`HEAD_ROWS`): a long log is not converted twice."""
    head = frame.head(HEAD_ROWS)
    numbers = head.apply(pd.to_numeric, errors="coerce").notna().sum(axis=1) >= 2
    return int(numbers.sum()) > RESULTS_ROWS


def _the_log_sheet(workbook: pd.ExcelFile, first: pd.DataFrame, name: str, file: str
                   ) -> tuple[pd.DataFrame, str, str | None]:
    """The one sheet of `workbook` that holds a log when its first sheet (`first`, named
    `name`) does not (a results sheet before the raw data, as Bluehill and testXpert
    export to Excel), with a note; the first sheet when no other holds one; an error
    naming them when several do (one file is one run)."""
    logs = {other: frame for other, frame in pd.read_excel(
        workbook, sheet_name=workbook.sheet_names[1:], header=None).items()
        if _holds_a_log(frame)}
    if not logs:
        return first, name, None
    if len(logs) > 1:
        raise LayoutError(
            f"sheet {name!r} holds no log, and sheets {', '.join(map(repr, logs))} hold one "
            "each: the workbook holds several specimens or tests", file=file,
            hint="give the sheet of this run in the run sheet (sheet = \"...\"); one file is "
                 "one run: a run per sheet may name the same file")
    (other, frame), = logs.items()
    return frame, other, (f"sheet {other!r} read: the first sheet, {name!r}, holds no log "
                          "(a results table); name the sheet in the run sheet to read another")


def _to_float(cells: pd.Series, file: str, column: str) -> np.ndarray:
    """A column of cells as float64; raises on a cell that is not a number.

    Numbers stored as text may use either decimal mark (``"1,5"`` or ``"1.5"``).
    """
    values = pd.to_numeric(cells, errors="coerce").to_numpy(dtype=float, copy=True)
    for position in np.flatnonzero(np.isnan(values)):
        cell = cells.iloc[position]
        text = _text(cell).strip()
        if is_missing(text):
            continue
        if isinstance(cell, str) and (is_number(text, ".") or is_number(text, ",")):
            values[position] = float(text.replace(",", "."))
            continue
        raise ValueParseError(
            f"{text[:40]!r} is not a number",
            file=file, row=int(cells.index[position]) + 1, column=column,
            hint=cell_hint(text, "fix or delete the cell (missing values may be left empty)"),
        )
    return values


def _clock_seconds(cells: pd.Series, clock: ClockColumn, file: str, column: str) -> np.ndarray:
    """A time column of clock readings as seconds after the first; raises on another cell."""
    texts = [_text(value).strip() for value in cells]
    for position, text in enumerate(texts):
        if not (is_missing(text) or clock.matches(text)):
            raise ValueParseError(
                clock.mismatch(text), file=file, row=int(cells.index[position]) + 1,
                column=column, hint="fix or delete the cell (missing values may be left empty)",
            )
    return clock.seconds_of_texts([None if is_missing(text) else text for text in texts])


def parse(
    source: Source, sheet: str | int | None = None, columns: Mapping | None = None,
    layout: str = "xlsx",
) -> RawTable:
    """Read the table of one sheet of a workbook.

    Parameters
    ----------
    source : Source
        The workbook (a file or a buffer).
    sheet : str or int, optional
        Sheet name or 0-based index; the first sheet by default.
    columns : mapping, optional
        Run-sheet ``columns`` (see :func:`~pipeline.ingest.roles.find_candidates`).
    layout : str
        ``"xlsx"``, ``"ods"`` or ``"xls"`` (:data:`LAYOUTS`).

    Returns
    -------
    RawTable
    """
    file = source.name
    frame, sheet_name, sheet_notes = _open_sheet(source, sheet, layout)
    cells = [[_text(value) for value in row]
             for row in frame.head(HEAD_ROWS).itertuples(index=False)]
    lines = ["\t".join(_sniffed(text) for text in row) for row in cells]
    _, point, width = detect_dialect(lines, file, delimiters=("\t",))
    spec = find_table(lines, file, "\t", point, width)
    decimal = "," if any(_sniffed(text) != text for row in cells[spec.data_index:]
                         for text in row) else "."
    require_names(spec, file, columns)
    skipped = range(*spec.results) if spec.results else range(0)
    preamble = [line for index, line in enumerate("\t".join(row) for row in cells[
        : spec.header_index or 0]) if line.strip() and index not in skipped]
    names, units = header_columns(spec)
    notes = sheet_notes + spec.results_warning()
    found, set_aside = numeric_candidates(
        spec, find_candidates(names, units, columns, file=file, header_line=names_line(spec)),
        names, cells[spec.data_index], notes)
    body = frame.iloc[spec.data_index:, : len(names)].dropna(axis=0, how="all")
    if body.empty:
        raise EmptyFileError(
            f"sheet {sheet_name!r} has a header but no data rows",
            file=file, row=spec.data_index + 1, hint="the sheet holds no measurements",
        )
    sheet_rows = body.index.to_numpy() + 1
    clocks = time_clocks(spec, found, names, units, notes)
    arrays = {
        index: _clock_seconds(body.iloc[:, index], clocks[index], file, display_name(names, index))
        if index in clocks else _to_float(body.iloc[:, index], file, display_name(names, index))
        for index in sorted(found.indexes())
    }
    for index, clock in clocks.items():  # the fraction of a second and the date beside it
        if clock.fraction is not None:
            column = clock.fraction.column
            counts = _to_float(body.iloc[:, column], file, display_name(names, column))
            arrays[index] = clock.with_fraction(pa.chunked_array([arrays[index]]),
                                                pa.chunked_array([counts])).to_numpy()
        if clock.date is not None:  # a time of day, its date in the column before
            dates = [_text(value).strip() or None for value in body.iloc[:, clock.date.column]]
            arrays[index] = clock.with_date(pa.chunked_array([arrays[index]]),
                                            pa.chunked_array([dates], pa.string())).to_numpy()
    empty = {
        index for index in range(len(names))
        if index not in arrays and body.iloc[:, index].isna().all()
    }
    meta = TableMetadata(
        file=file,
        layout=layout,
        decimal=decimal,
        preamble=parse_preamble(preamble, "\t"),
        sheet=sheet_name,
        header_line=names_line(spec),
        first_data_line=int(sheet_rows[0]),
        warnings=notes,
        specimens=list(spec.specimens),
    )
    return RawTable(
        names=names,
        units=units,
        arrays=arrays,
        rows=len(body),
        candidates=found,
        metadata=meta,
        line_of=lambda row: int(sheet_rows[row]) if 0 <= row < len(sheet_rows) else None,
        empty=empty,
        units_line=units_line(spec),
        clocks=clocks,
        set_aside=set_aside,
    )
