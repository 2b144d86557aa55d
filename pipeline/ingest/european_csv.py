"""European CSV: ``;`` or tab delimiter, decimal comma, as Polish and German lab PCs write.

Example (cp1250)::

    czas [s];siła [kN];wydłużenie [mm]
    0,00;0,012;0,000

File defects handled
--------------------
* decimal comma (``0,892``), parsed by pyarrow (``decimal_point=","``);
* cp1250, latin-1, UTF-8 with or without BOM, UTF-16 with BOM;
* quoted numbers (``"0,892"``);
* a decimal comma that is also the delimiter: read if quoted, or if every
  value splits unambiguously into an integer and a fraction field
  (``0,5,1,25`` under ``time,force``), else an error with a hint;
* a mixed decimal mark (a ``0.5`` in a decimal-comma file): error naming the
  line and column;
* a half-written last line (no line end after it): too few fields, or a last
  number that stops short of the decimals its column always has (``0,`` or
  ``0,0`` where the column writes ``0,000``; ``12,`` where it always has
  digits after the comma): dropped with a warning. A complete last line
  without line end is kept, and so is ``12,`` in a column that also holds
  integers;
* German and Polish names (``Standardkraft``, ``Weg``, ``siła``, ``wydłużenie``);
* everything :mod:`pipeline.ingest.plain_csv` handles.
"""

from __future__ import annotations

from collections.abc import Mapping

from pipeline.ingest.delimited import metadata, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec

LAYOUT = "european_csv"


def matches(head: Head, spec: TableSpec) -> bool:
    """True for a decimal comma or a ``;`` delimiter."""
    return spec.decimal == "," or spec.delimiter == ";"


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a European CSV file sniffed as `head` / `spec` (see the module docstring)."""
    return read_contiguous(head, spec, columns, metadata(head, spec, LAYOUT, {}))
