"""Machine export: free-text preamble, names row, separate units row (Instron Bluehill).

Example (Bluehill 2 ``RawData``, CRLF)::

    Text Inputs : Specimen label,"22L.3"
    General : Start Date,13/11/2018 5:14 PM

    Time,Extension,Load,Segment ID,Total Cycle Count
    (sec),(mm),(N),,
    0.00000,-2.04726,-4.31900,22476,0

File defects handled
--------------------
* a preamble of ``key : value``, ``key: value``, ``"key","value"`` or
  ``key<TAB>value`` lines, and blank lines, before the names row (kept in
  :attr:`TableMetadata.preamble`);
* units in their own row (``(sec),(mm),(N),,``, ``Sec  mm  kgf``), empty for
  counters and IDs;
* the machine's cycle counter (``Total Cycle Count``) kept as ``cycle_count``;
* columns nobody maps (``Segment ID``) kept out of the table;
* any delimiter and decimal mark, and everything :mod:`pipeline.ingest.plain_csv`
  handles.
"""

from __future__ import annotations

from collections.abc import Mapping

from pipeline.ingest.delimited import metadata, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, split_fields

LAYOUT = "machine_export"


def matches(head: Head, spec: TableSpec) -> bool:
    """True if a preamble or a separate units row is found."""
    return bool(spec.preamble) or spec.units_index is not None


def parse_preamble(lines: list[str], delimiter: str) -> dict[str, str]:
    """``key -> value`` from free-text preamble lines.

    ``Category : Name,Value`` (Bluehill) gives ``Name -> Value``; ``key: a b``
    and ``key<delimiter>a<delimiter>b`` give ``key -> "a b"``; a line that is
    only text is kept as a key with an empty value. A repeated key is kept
    once per occurrence, numbered (``"key (2)"``).
    """
    preamble: dict[str, str] = {}
    for line in lines:
        if " : " in line:
            category, rest = (part.strip() for part in line.split(" : ", 1))
            fields = split_fields(rest, delimiter)
            key, values = (fields[0], fields[1:]) if len(fields) > 1 else (category, [rest])
        else:
            fields = [field.strip() for field in split_fields(line, delimiter) if field.strip()]
            first = fields[0] if fields else line.strip()
            if ":" in first:
                key, tail = first.split(":", 1)
                values = [tail, *fields[1:]]
            else:
                key, values = first, fields[1:]
        key = key.strip().rstrip(":").strip() or line.strip()
        value = " ".join(value.strip() for value in values if value.strip())
        unique, number = key, 1
        while unique in preamble:
            number += 1
            unique = f"{key} ({number})"
        preamble[unique] = value
    return preamble


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a machine export sniffed as `head` / `spec` (see the module docstring)."""
    meta = metadata(head, spec, LAYOUT, parse_preamble(spec.preamble, spec.delimiter))
    return read_contiguous(head, spec, columns, meta)
