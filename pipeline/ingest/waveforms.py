"""The x columns of a file of waveforms side by side (an NI DAQ CSV).

NI's data-acquisition software writes each channel as a waveform of two
columns, its x values then its readings, under a header of key and value
pairs that stand over those two columns::

    Timestamp,2/7/2024 3:58:30 PM,Timestamp,2/7/2024 3:58:30 PM
    Interval,0.0001,Interval,0.0001
    Channel name,"Force",Channel name,"Input 1"
    Unit,"V",Unit,"V"
    0,0.1384,0,0.0250
    0.0001,0.1384,0.0001,0.0430

The names row and the units row thus name every x column ``Channel name``
in ``Unit``. The x values are the time in seconds from the waveform's
``Timestamp``: the first x column is named ``Time`` (in ``s`` when it holds
numbers), the others ``X_Value 2``, ``X_Value 3``... (no role, as a LabVIEW
measurement file's further X columns). Channels sampled at different
``Interval``, or started at different ``Timestamp``, have no common time:
such a file is refused.
"""

from __future__ import annotations

from pipeline.errors import LayoutError
from pipeline.ingest.names import fold
from pipeline.ingest.sniff import Head, TableSpec, is_number, split_fields

#: The names-row and units-row cells over a waveform's x column, folded.
X_KEYS = ("channel name", "unit")
#: The header rows of a waveform's time axis (first cell folded), with what differing
#: values of them say.
AXIS_KEYS = {"timestamp": "started at different times",
             "interval": "were sampled at different intervals"}


def x_columns(names: list[str], units: list[str | None]) -> list[int]:
    """The columns named as a waveform's x values (:data:`X_KEYS`)."""
    return [index for index, (name, unit) in enumerate(zip(names, units, strict=True))
            if (fold(name.strip()), fold((unit or "").strip())) == X_KEYS]


def time_columns(head: Head, spec: TableSpec, names: list[str], units: list[str | None],
                 warnings: list[str]) -> tuple[list[str], list[str | None]]:
    """`names` and `units` with the waveforms' x columns named as the module says.

    Raises
    ------
    LayoutError
        When the waveforms' intervals differ.
    """
    xs = x_columns(names, units)
    if not xs:
        return names, units
    _require_one_axis(head, spec, xs)
    first = split_fields(head.lines[spec.data_index], spec.delimiter)[xs[0]].strip()
    names, units = list(names), list(units)
    for number, index in enumerate(xs, start=1):
        names[index] = "Time" if number == 1 else f"X_Value {number}"
        units[index] = "s" if number == 1 and is_number(first, spec.decimal) else None
    warnings.append(
        f"{len(xs)} waveform(s) side by side, each with its x column ('Channel name'): the "
        "first x column read as the time" + (", the others take no role" if len(xs) > 1
                                             else ""))
    return names, units


def _require_one_axis(head: Head, spec: TableSpec, xs: list[int]) -> None:
    """Refuse waveforms of different :data:`AXIS_KEYS` values (right of each x column's
    key) in the lines over the names row."""
    for number, line in enumerate(head.lines[:spec.header_index], start=1):
        cells = [cell.strip().strip('"') for cell in split_fields(line, spec.delimiter)]
        what = AXIS_KEYS.get(fold(cells[0])) if cells else None
        values = {cells[index + 1] for index in xs if index + 1 < len(cells)}
        if what is not None and len(values) > 1:
            raise LayoutError(
                f"the waveforms side by side {what} (" + ", ".join(sorted(values))
                + "): they have no common time", file=head.name, row=number,
                hint="export the channels of one start and interval together, others to "
                     "files of their own")
