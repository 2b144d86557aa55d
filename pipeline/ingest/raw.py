"""What a layout reader hands to :func:`pipeline.ingest.canonical.build`."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from pipeline.ingest.clock import ClockColumn
from pipeline.ingest.roles import Candidates
from pipeline.ingest.table import TableMetadata


@dataclass(kw_only=True)
class RawColumns:
    """A file's columns as its header gives them, before roles and SI units are settled.

    Attributes
    ----------
    names : list of str
        Column names as in the file, without units.
    units : list of str or None
        Each column's unit as found in the file (header, units row, channel
        property), None where there is none.
    candidates : Candidates
        The columns that may take each role.
    metadata : TableMetadata
        What the reader detected (layout, encoding...); ``columns`` is filled
        by :func:`~pipeline.ingest.canonical.build`.
    units_line : int or None
        Line of the names or units row, for unit messages.
    clocks : dict of int -> ClockColumn
        Time columns written as clock readings, which the reader turns into
        seconds (their unit is ``"s"``, whatever the run sheet says).
    set_aside : tuple of (str, str)
        Roles a column would have taken by its name but does not, each with why
        (it holds text, or clock readings of a form not read): for the message
        when the role is missing.
    """

    names: list[str]
    units: list[str | None]
    candidates: Candidates
    metadata: TableMetadata
    units_line: int | None = None
    clocks: dict[int, ClockColumn] = field(default_factory=dict)
    set_aside: tuple[tuple[str, str], ...] = ()

    def header(self) -> RawColumns:
        """These columns without data (the header of a :class:`RawTable`)."""
        return RawColumns(**self._header_fields())

    def table(self, **data: Any) -> RawTable:
        """These columns with their data (the other attributes of :class:`RawTable`)."""
        return RawTable(**self._header_fields(), **data)

    def _header_fields(self) -> dict[str, Any]:
        return {item.name: getattr(self, item.name) for item in fields(RawColumns)}


@dataclass(kw_only=True)
class RawTable(RawColumns):
    """A file's columns as read (or some of its rows), before roles and SI units are settled.

    Attributes
    ----------
    arrays : dict of int -> numpy.ndarray
        The candidate columns (see :attr:`candidates`) as float64, NaN where
        missing, in the file's units; writable, owned by the table.
    rows : int
        Number of data rows.
    line_of : callable
        Maps a 0-based row to its 1-based line (or sheet row) in the file.
    empty : set of int
        Non-candidate columns holding no value.
    first_row : int
        The file's 0-based row number of the first row (0 unless the table
        holds some rows of a file, see :mod:`pipeline.ingest.stream`).
    """

    arrays: dict[int, np.ndarray]
    rows: int
    line_of: Callable[[int], int | None]
    empty: set[int] = field(default_factory=set)
    first_row: int = 0

    def where(self, row: int) -> str:
        """``"line N"`` of a 0-based row, or ``"sample N"`` (1-based, counted in the file) if
        the file has no lines."""
        line = self.line_of(row)
        return f"line {line}" if line is not None else f"sample {self.first_row + row + 1}"
