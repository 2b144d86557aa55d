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

Some models write no X column (``CH1,CH2,Start,Increment,`` over
``Volt,Volt,-6.0e-02,1.0e-04``): the time of the i-th row (from 0) is then
``Start + i * Increment``, given as a ``Time`` column after the channels (in
the empty field the rows end with).

Refused, with a hint: a ``Start`` or ``Increment`` that is not a number.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout, read_contiguous
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, is_number, split_fields

LAYOUT = "rigol"

#: The names of the time axis's values, in the names row after the channels'.
AXIS = ("Start", "Increment")
#: The first cell of the units row (the X column counts samples).
SEQUENCE = "Sequence"
#: The name given to the X column, once it holds the time.
TIME_NAME = "Time"


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a Rigol export: ``X``, channels, ``Start``, ``Increment``
    over a units row that begins with ``Sequence``; or, without the ``X`` column, the
    channels, ``Start`` and ``Increment`` over their units and two numbers."""
    if len(head.lines) < 3:
        return False
    names, units = _cells(head.lines[0]), _cells(head.lines[1])
    if names[0] == "X":
        return all(name in names[2:] for name in AXIS) and units[0] == SEQUENCE
    return (all(name in names[1:] for name in AXIS)
            and names.index(AXIS[1]) == names.index(AXIS[0]) + 1
            and all(is_number(text, ".") for text in _axis_cells(head)))


#: The rows below the headers as delimited text, read whole (the X column becomes the
#: time in :func:`read`), the time axis's values as the preamble.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the table of a Rigol export sits, its channels and their units.

    Raises
    ------
    LayoutError
        If ``Start`` or ``Increment`` is not a number, or without an ``X`` column the
        rows do not end with an empty field to give the time in.
    """
    names, units = _cells(head.lines[0]), _cells(head.lines[1])
    _axis(head)
    channels = names.index(AXIS[0])
    width = len(split_fields(head.lines[2], ","))
    if _has_x(head):
        columns, column_units = [TIME_NAME, *names[1:channels]], ["s", *units[1:channels]]
    elif width > channels:  # the time in the empty field after the channels
        columns, column_units = [*names[:channels], TIME_NAME], [*units[:channels], "s"]
    else:
        raise LayoutError(
            "the export has no X column, and its rows no field to give the time in",
            file=head.name, row=3, hint="export the waveform again from the oscilloscope "
            "(CSV), or give the time as a column of its own")
    pad = [""] * (width - len(columns))
    return TableSpec(
        delimiter=",", decimal=".", names=columns + pad, header_index=0, units_index=1,
        data_index=2, width=width, units=[unit or None for unit in column_units + pad],
        preamble=[f"{name},{value}" for name, value in zip(AXIS, _axis_cells(head),
                                                           strict=True)],
    )


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a Rigol export sniffed as `head` / `spec`: the X column becomes the time, or
    without one the time is built from the rows' places."""
    raw = read_contiguous(head, spec, TEXT.header(head, spec, columns))
    time = spec.names.index(TIME_NAME)
    if time in raw.arrays:
        start, increment = _axis(head)
        place = (raw.arrays[time] if _has_x(head)
                 else raw.first_row + np.arange(raw.rows, dtype=float))
        raw.arrays[time] = start + increment * place
    return raw


def _has_x(head: Head) -> bool:
    return _cells(head.lines[0])[0] == "X"


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
