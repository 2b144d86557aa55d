"""LabChart text export (ADInstruments PowerLab): a header of ``Key=<TAB>values`` lines,
then the samples, the time first.

::

    Interval=	0.001 s
    ExcelDateTime=	4.5855649139942347e+04	07/17/25 15:34:45.691019
    TimeFormat=	StartOfBlock
    DateFormat=
    ChannelTitle=	Force	Displacement
    Range=	10.000 V	5.000 V
    UnitName=	N	mm
    TopValue=	500.0	50.0
    BottomValue=	-500.0	-50.0
    0	12.50	0.012
    0.001	12.61	0.013

The header is the preamble. The channels take the names of ``ChannelTitle=`` and
the units of ``UnitName=`` (``*``: none, to be given in the run sheet). A first
column more than the titles is the time, named ``Time``, in seconds from the
block's start (``TimeFormat= StartOfBlock``); without it the header's ``Interval``
makes the time (see :mod:`pipeline.ingest.statedrate`). The layout is known by its
``Interval=`` and ``ChannelTitle=`` lines above the first row of numbers.
"""

from __future__ import annotations

from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.sniff import Head, TableSpec, is_number, split_fields

LAYOUT = "labchart"

#: The header's keys the layout is known by, and those it is read by.
INTERVAL, TITLES, UNITS = "Interval", "ChannelTitle", "UnitName"
#: The name of the time column.
TIME_NAME = "Time"
#: LabChart's cell for a channel without a unit.
NO_UNIT = "*"


def _header(head: Head) -> tuple[dict[str, list[str]], dict[str, int], int | None]:
    """The header's keys with their values (cells after the key), the line of each, and the
    index of the first row of numbers (None: no such row right below the header)."""
    values: dict[str, list[str]] = {}
    lines: dict[str, int] = {}
    for index, line in enumerate(head.lines):
        cells = split_fields(line, "\t")
        key = cells[0].strip()
        if key.endswith("=") and len(key) > 1:
            values[key[:-1]] = [cell.strip() for cell in cells[1:]]
            lines[key[:-1]] = index
        elif values and (filled := [cell.strip() for cell in cells if cell.strip()]) and all(
                is_number(cell, ".") for cell in filled):
            return values, lines, index
        else:
            return values, lines, None
    return values, lines, None


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a LabChart text export: ``Interval=`` and ``ChannelTitle=`` over
    a row of numbers."""
    values, _, first = _header(head)
    return first is not None and {INTERVAL, TITLES} <= values.keys()


#: The export as delimited text, its header the preamble: read whole, or by row range.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the samples of a LabChart export sit, their names and units."""
    values, lines, first = _header(head)
    titles = values[TITLES]
    units = _padded([None if unit in ("", NO_UNIT) else unit
                     for unit in values.get(UNITS, [])], len(titles), None)
    width = len(split_fields(head.lines[first], "\t"))
    if width == len(titles) + 1:  # the time first: in seconds from the block's start, a
        # time of day left to the clock readers
        seconds = values.get("TimeFormat", [""])[:1] in ([""], ["StartOfBlock"])
        titles, units = [TIME_NAME, *titles], ["s" if seconds else None, *units]
    return TableSpec(
        delimiter="\t", decimal=".", names=_padded(titles, width, ""),
        header_index=lines[TITLES], units_index=None, data_index=first, width=width,
        units=_padded(units, width, None),
        preamble=[line for line in head.lines[:first] if line.strip()],
    )


def _padded(items: list, length: int, fill: object) -> list:
    """`items` cut or padded with `fill` to `length`."""
    return (list(items) + [fill] * length)[:length]
