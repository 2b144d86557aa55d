"""MTS TestWare cyclic-acquisition export: repeating blocks of header lines and points.

Example (Spanish, latin-1, tab-separated, decimal comma, CRLF)::

    MTS***|MPT|**|*|*|*|*|*|*|*|*|*

    Adquisición cíclica      Tiempo  20,061279  Sec  13/12/2021 10:22:42
    Parado en:  100  cycle   Parado para:  1  cycles   Relativo a:  1  cycle
    Puntos:  51
    Tiempo  Channel 1 Displacement  Channel 1 Force  Channel 1 Recuento
    Sec     mm                      kgf              cycles
    10,016357  -0,095496617  -4,1995568  99
    ... 51 points, a blank line, then the next block's header lines ...

File defects handled
--------------------
* block header lines repeated before every block: removed in one regular
  expression pass over the bytes, the points of all blocks parsed by pyarrow
  as one table (line numbers in messages still refer to the file);
* a later block naming other columns than the first: error naming the line;
* Spanish or English names (``Tiempo``, ``Fuerza``, ``Desplazamiento``,
  ``Recuento``, ``Count``) and a separate units row (``Sec``, ``mm``, ``kgf``);
* the counter in ``cycles`` (half cycles as ``99,5``) or ``segments`` (two per
  cycle): kept as counted in ``cycle_count`` with its unit;
* the time gap between blocks (reported as time gaps, see
  :mod:`pipeline.ingest.canonical`);
* no line end after the last point; a truncated last point (dropped, warned).
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Mapping

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import raw_table, text_header
from pipeline.ingest.preamble import parse_preamble
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, split_fields
from pipeline.ingest.source import BufferSource
from pipeline.ingest.textbody import (
    Region,
    parse_body,
    split_table,
    trim_truncated_tail,
    truncated_warning,
)

LAYOUT = "mts"

# A data line starts with a number, a missing-value token or an empty first field.
_DATA_START = r"[ \t]*(?:[-+.\d]|(?i:nan|n/a|na|null) *(?=[\t;,|\r\n]|$)|(?=[\t;,|\r\n]|$))"
_HEADER_LINE = re.compile(rb"(?m)^(?!" + _DATA_START.encode() + rb")[^\r\n]*(?:\r\n|\r|\n|\Z)")
_DATA_LINE = re.compile(_DATA_START)


def _is_data(line: str) -> bool:
    """True for a line pyarrow reads as a row (not a block header, not empty)."""
    return bool(line) and _DATA_LINE.match(line) is not None


def matches(head: Head, spec: TableSpec) -> bool:
    """True for an ``MTS`` first line, or a names row or a line that opens a block (MTS
    TestStar: ``Axial Counts<TAB>0`` above the names) repeated below the first block."""
    if spec.header_index is None:
        return False
    later = head.lines[spec.data_index:]
    openers = _block_openers(head, spec)
    return (head.lines[0].lstrip().startswith("MTS") or head.lines[spec.header_index] in later
            or any(line.strip() in openers for line in later))


def _block_openers(head: Head, spec: TableSpec) -> set[str]:
    """The lines above the names row with a letter in them, stripped: repeated below the
    data, each opens a block."""
    return {line.strip() for line in head.lines[:spec.header_index]
            if any(char.isalpha() for char in line)}


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read an MTS cyclic-acquisition export sniffed as `head` / `spec`."""
    header = text_header(head, spec, LAYOUT, parse_preamble(spec.preamble, spec.delimiter), columns)
    start = head.offsets[spec.data_index]
    data = head.source.read(start, head.size)
    if not head.ascii_compatible:
        data = data.decode(head.codec, errors="replace").encode("utf-8")
    header.metadata.preamble["blocks"] = str(1 + _check_blocks(head, spec, data))
    points = BufferSource(_HEADER_LINE.sub(b"", data), head.name)
    del data
    kept, truncated = trim_truncated_tail(Region(points, 0, points.size, 1, "utf-8"),
                                          spec.width, spec.delimiter, spec.decimal)
    region = Region(head.source, start, head.size, spec.data_index + 1, head.codec, _is_data)
    table, _ = parse_body(  # comment lines are not data lines: filtered out above
        kept,
        region,
        names=header.names,
        width=spec.width,
        delimiter=spec.delimiter,
        decimal=spec.decimal,
        float_columns=header.candidates.indexes(),
        clocks=header.clocks,
    )
    parsed = split_table(table, header.candidates.indexes(), spec.width, header.clocks)
    del table
    if truncated:
        header.metadata.warnings.append(truncated_warning(region.line_of(parsed[1])))
    return raw_table(parsed, region, header)


def _check_blocks(head: Head, spec: TableSpec, data: bytes) -> int:
    """Count the later blocks (by their names rows, else by the lines that open them); raise
    if one names other columns than the first."""
    names_row = head.lines[spec.header_index].strip()
    units_row = head.lines[spec.units_index].strip() if spec.units_index is not None else None
    openers = _block_openers(head, spec)
    codec = head.codec if head.ascii_compatible else "utf-8"
    later, opened = 0, Counter()
    for match in _HEADER_LINE.finditer(data):
        line = match.group().decode(codec, errors="replace").strip()
        if line in openers:
            opened[line] += 1
            continue
        if len(split_fields(line, spec.delimiter)) != spec.width or line == units_row:
            continue
        if line != names_row:
            raise LayoutError(
                "a block names other columns than the first block",
                file=head.name, row=spec.data_index + 1 + data.count(b"\n", 0, match.start()),
                hint="the export joins different tests: split it into one file per test",
            )
        later += 1
    return later or max(opened.values(), default=0)
