"""Rigol oscilloscope CSV (DS1000Z and others): the time as a start and an increment.

::

    X,CH1,CH2,Start,Increment,
    Sequence,Volt,Volt,-1.370000e-05,2.000000e-09
    0,-2.00e-02,1.80e+01,
    1,-1.20e-02,1.80e+01,

The names row names the sample number (``X``), the channels, and the time
axis's ``Start`` and ``Increment``, whose values stand below them in the
units row, in seconds; the units row gives the channels' units. The time of
sample X is ``Start + X * Increment`` [s]: the reader gives the X column as
``Time`` in seconds. Every data row ends with a delimiter.

Refused, with a hint: a ``Start`` or ``Increment`` that is not a number.
"""

from __future__ import annotations

from collections.abc import Mapping

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, split_fields

LAYOUT = "rigol"

#: The names of the time axis's values, in the names row after the channels'.
AXIS = ("Start", "Increment")
#: The first cell of the units row (the X column counts samples).
SEQUENCE = "Sequence"
#: The name given to the X column, once it holds the time.
TIME_NAME = "Time"


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a Rigol export: ``X``, channels, ``Start``, ``Increment``
    over a units row that begins with ``Sequence``."""
    if len(head.lines) < 3:
        return False
    names = _cells(head.lines[0])
    return (names[0] == "X" and all(name in names[2:] for name in AXIS)
            and _cells(head.lines[1])[0] == SEQUENCE)


#: The rows below the headers as delimited text, read whole (the X column becomes the
#: time in :func:`read`), the time axis's values as the preamble.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the table of a Rigol export sits, its channels and their units.

    Raises
    ------
    LayoutError
        If ``Start`` or ``Increment`` is not a number.
    """
    names, units = _cells(head.lines[0]), _cells(head.lines[1])
    _axis(head)
    channels = names.index(AXIS[0])
    width = len(split_fields(head.lines[2], ","))
    columns = [TIME_NAME, *names[1:channels]]
    column_units = ["s", *units[1:channels]]
    pad = [""] * (width - len(columns))
    return TableSpec(
        delimiter=",", decimal=".", names=columns + pad, header_index=0, units_index=1,
        data_index=2, width=width, units=[unit or None for unit in column_units + pad],
        preamble=[f"{name},{value}" for name, value in zip(AXIS, _axis_cells(head),
                                                           strict=True)],
    )


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a Rigol export sniffed as `head` / `spec`: the X column becomes the time."""
    raw = read_contiguous(head, spec, TEXT.header(head, spec, columns))
    if 0 in raw.arrays:
        start, increment = _axis(head)
        raw.arrays[0] = start + increment * raw.arrays[0]
    return raw


def _cells(line: str) -> list[str]:
    return [cell.strip() for cell in split_fields(line, ",")]


def _axis_cells(head: Head) -> list[str]:
    """The texts below ``Start`` and ``Increment``."""
    names, units = _cells(head.lines[0]), _cells(head.lines[1])
    return [units[names.index(name)] if names.index(name) < len(units) else ""
            for name in AXIS]


def _axis(head: Head) -> tuple[float, float]:
    """``Start`` and ``Increment`` [s]."""
    try:
        start, increment = (float(text) for text in _axis_cells(head))
    except ValueError:
        raise LayoutError(
            "the time axis's Start and Increment are not numbers", file=head.name, row=2,
            hint="export the waveform again from the oscilloscope (CSV)") from None
    return start, increment
