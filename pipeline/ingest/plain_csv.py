"""Plain CSV: one names row with units in brackets, ``,`` delimiter, ``.`` decimal mark.

Example::

    time [s],force [kN],gauge1 [mm],gauge2 [mm]
    0.00,0.012,0.000,0.001

File defects handled
--------------------
* units in ``[...]`` or ``(...)`` after the name, or none (then from the run sheet);
* a UTF-8 BOM, or cp1250 / latin-1 text in the header;
* CRLF, LF or CR line ends; blank lines inside the table;
* quoted cells (``"1.5"``), blanks and ``NaN``/``N/A`` cells (missing values);
* a trailing delimiter on data rows (an extra empty column, dropped);
* a truncated last line (dropped with a warning);
* a non-numeric cell (error naming line and column); a row with too many or
  too few fields (error naming the line);
* tab or ``|`` delimiters with a ``.`` decimal mark.
"""

from __future__ import annotations

from collections.abc import Mapping

from pipeline.ingest.delimited import metadata, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec

LAYOUT = "plain_csv"


def matches(head: Head, spec: TableSpec) -> bool:
    """True for a single header row with a ``.`` decimal mark and no ``;`` delimiter."""
    return spec.decimal == "." and spec.delimiter != ";"


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a plain CSV file sniffed as `head` / `spec` (see the module docstring)."""
    return read_contiguous(head, spec, columns, metadata(head, spec, LAYOUT, {}))
