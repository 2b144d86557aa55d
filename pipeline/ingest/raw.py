"""What a layout reader hands to :func:`pipeline.ingest.canonical.build`."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from pipeline.ingest.roles import Candidates
from pipeline.ingest.table import TableMetadata


@dataclass
class RawTable:
    """A file's columns as read, before roles and SI units are settled.

    Attributes
    ----------
    names : list of str
        Column names as in the file, without units.
    units : list of str or None
        Each column's unit as found in the file (header, units row, channel
        property), None where there is none.
    arrays : dict of int -> numpy.ndarray
        The candidate columns (see :attr:`candidates`) as float64, NaN where
        missing, in the file's units; writable, owned by the table.
    rows : int
        Number of data rows.
    candidates : Candidates
        The columns that may take each role.
    metadata : TableMetadata
        What the reader detected (layout, encoding...); ``columns`` is filled
        by :func:`~pipeline.ingest.canonical.build`.
    line_of : callable
        Maps a 0-based row to its 1-based line (or sheet row) in the file.
    empty : set of int
        Non-candidate columns holding no value.
    units_line : int or None
        Line of the names or units row, for unit messages.
    """

    names: list[str]
    units: list[str | None]
    arrays: dict[int, np.ndarray]
    rows: int
    candidates: Candidates
    metadata: TableMetadata
    line_of: Callable[[int], int | None]
    empty: set[int] = field(default_factory=set)
    units_line: int | None = None

    def where(self, row: int) -> str:
        """``"line N"`` of a 0-based row, or ``"sample N"`` (1-based) if the file has no lines."""
        line = self.line_of(row)
        return f"line {line}" if line is not None else f"sample {row + 1}"
