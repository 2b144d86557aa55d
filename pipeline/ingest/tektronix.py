"""Tektronix oscilloscope CSV (TDS, TBS1000 and others): settings beside the samples.

::

    Record Length,2.500000e+03,,  -0.000480000000,  -0.86000,
    Sample Interval,2.000000e-06,,  -0.000478000000,  -0.86000,
    Trigger Point,2.400000000000e+02,,  -0.000476000000,  -0.88000,
    ,,,  -0.000474000000,  -0.86000,
    Source,CH2,,  -0.000468000000,  -0.86000,
    Vertical Units,V,,  -0.000466000000,  -0.86000,
    Horizontal Units,s,,  -0.000460000000,  -0.88000,
    ...
    ,,,-00.000444000000,  -0.86000,

Every row holds a sample in its fourth and fifth fields, the time and the
channel's value; the first rows also hold the scope's settings in their first
two (older scopes write each setting's unit in the third: ``"Sample
Interval",8.0e-009,s``), which are the preamble. There is no names row: the
time takes the name ``Time`` and the unit ``Horizontal Units`` (else the
sample interval's); the channel the name ``Source`` (``CH2``) and the unit
``Vertical Units``. The layout is known by its first row (``Record Length``
beside a sample).
"""

from __future__ import annotations

from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.sniff import Head, TableSpec, is_number, split_fields

LAYOUT = "tektronix"

#: The setting in the first field of the first row.
FIRST_SETTING = "Record Length"
#: The fields of a row that hold its sample: the time and the channel's value.
SAMPLE = (3, 4)
#: The name of the time column.
TIME_NAME = "Time"
#: The setting whose unit is the time's when no ``Horizontal Units`` is given.
INTERVAL = "Sample Interval"


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a Tektronix export: ``Record Length`` beside a sample."""
    if not head.lines:
        return False
    cells = [cell.strip() for cell in split_fields(head.lines[0], ",")]
    return (len(cells) > max(SAMPLE) and cells[0] == FIRST_SETTING
            and all(is_number(cells[index], ".") for index in SAMPLE))


#: The layout as delimited text (its settings the preamble): read whole, or by row range.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the samples of a Tektronix export sit, their names and units."""
    rows = [[cell.strip() for cell in split_fields(line, ",")] for line in head.lines]
    settings = {row[0]: " ".join(filter(None, row[1:SAMPLE[0]])) for row in rows
                if len(row) > 1 and row[0]}
    width = len(rows[0])
    names, units = [""] * width, [None] * width
    names[SAMPLE[0]], names[SAMPLE[1]] = TIME_NAME, settings.get("Source", "")
    units[SAMPLE[0]] = settings.get("Horizontal Units") or _unit_of(settings.get(INTERVAL))
    units[SAMPLE[1]] = settings.get("Vertical Units") or None
    return TableSpec(
        delimiter=",", decimal=".", names=names, header_index=0, units_index=None,
        data_index=0, width=width, units=units,
        preamble=[f"{key},{value}" for key, value in settings.items()],
    )


def _unit_of(setting: str | None) -> str | None:
    """The unit after a setting's value (``8.0e-009 s``), as older scopes write the sample
    interval in place of ``Horizontal Units``; None without one."""
    return (setting or "").partition(" ")[2] or None
