"""KEYENCE NR-series data logger CSV (NR-500, NR-600): a header between ``#BeginHeader`` and
``#EndHeader``, then the samples, each stamped to the second with the microseconds within
it in the next column.

::

    #BeginHeader,57
    #FormatType,NR-500\\NORMAL
    サンプリング周期,50ms
    ...
    チャンネル番号,,(1)HA-V01
    単位,,"V"
    ...
    #EndHeader,日時(μs),(1)HA-V01
    2023/05/08 16:16:52,979000,-0.127
    2023/05/08 16:16:53,029000,-0.125

The header is the preamble. The ``#EndHeader`` line is the names row: its first
cell, the header's end mark, stands over the stamps; the next names them (``日時``,
date and time) and gives, in brackets, the unit its own counts are in: the
fraction of a second of the stamp before it (:func:`~pipeline.ingest.clock.fraction_column`),
so the time is the stamp plus the count. The channels take the units of the
header's ``単位`` (unit) line, one cell a column. Read as written, the counts were
the time: it stepped back at every second.
"""

from __future__ import annotations

from dataclasses import replace

from pipeline.ingest.clock import fraction_column
from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.names import split_name_unit
from pipeline.ingest.sniff import Head, TableSpec, detect_dialect, find_table, split_fields

LAYOUT = "keyence"

#: The marks of the header's first and last lines.
BEGIN, END = "#BeginHeader", "#EndHeader"
#: Keys of the header's line of the channels' units, folded.
UNIT_KEYS = frozenset({"単位", "unit", "units"})


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a KEYENCE NR export: ``#BeginHeader`` first, an ``#EndHeader``
    line over the samples."""
    return bool(head.lines) and head.lines[0].startswith(BEGIN) and any(
        line.startswith(END) for line in head.lines)


#: The export as delimited text, its header the preamble: read whole, or by row range.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the samples of a KEYENCE NR export sit, their names, units and clock."""
    end = next(index for index, line in enumerate(head.lines) if line.startswith(END))
    delimiter, decimal, width = detect_dialect(head.lines[end + 1:], head.name, (",", "\t"))
    spec = find_table(head.lines, head.name, delimiter, decimal, width)
    names = list(spec.names)
    if len(names) < 2 or spec.header_index != end:
        return spec
    stamp, counted_in = split_name_unit(names[1])
    names[:2] = [stamp, counted_in or names[1]]
    units = list(spec.units)
    for line in head.lines[:end]:
        cells = [cell.strip().strip('"') for cell in split_fields(line, delimiter)]
        if cells and cells[0].casefold() in UNIT_KEYS:
            units = [None, None, *(cell or None for cell in cells[2:width])]
            units += [None] * (width - len(units))
    clocks = dict(spec.clocks)
    if 0 in clocks:
        rows = [split_fields(line, delimiter) for line in head.lines[spec.data_index:]
                if line.strip()]
        clocks[0] = replace(clocks[0], fraction=fraction_column(rows[0][0], 0, names, rows))
    return replace(spec, names=names, units=units, clocks=clocks,
                   preamble=[line for line in head.lines[:end] if line.strip()])
