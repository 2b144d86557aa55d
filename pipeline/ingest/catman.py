"""HBM catman ASCII export with its channel information (``HBM_CATMAN_DATAFILE_40``).

::

    HBM_CATMAN_DATAFILE_40

    2017-11-13
    11:24
    CHANNELS: 11
    SEPARATOR: 9
    MAXLINES: 38730

    Time DEVICE_1 (Sample rate 1) CH=1<Tab>Load CH=2<Tab>Stroke CH=3<Tab>...
    s<Tab>kN<Tab>mm<Tab>...
    2017-11-10-17:06<Tab>2017-11-10-17:06<Tab>...
    T0 =10.11.17 16:53:58<Tab>...
    dt =20 ms<Tab>...
    ... one line per setting of every channel: amplifier, scaling, zero, tare ...
    Cable length correction Not available<Tab>...

    0.000000<Tab>-19.79<Tab>-21.191<Tab>...

The first line names the format. The settings above the names row (the export's
date and time, the number of channels, the field separator as a character
code, ``9`` for a tab) are the preamble. The names row carries each channel's
number after its name (``Load CH=2``), which the reader drops; the units row
follows. Then come as many rows of each channel's settings (its acquisition
date, start time ``T0``, interval ``dt``, amplifier, scaling, zero and tare
values, gauge factor) as the export holds, which a generic reader would take
for the names: the data are the first row of numbers after them.

Refused, with a hint: a file whose first row of numbers is not within the head
of the file (settings of so many channels that they fill it).
"""

from __future__ import annotations

import re

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.sniff import (
    HEAD_BYTES,
    Head,
    TableSpec,
    is_number,
    row_kind,
    split_fields,
)

LAYOUT = "catman"

#: The first line's start: the format's name and version.
MAGIC = "HBM_CATMAN_DATAFILE"
#: The setting that gives the field separator, as a character code (``SEPARATOR: 9``).
_SEPARATOR = re.compile(r"SEPARATOR:\s*(\d+)", re.IGNORECASE)
#: The channel number catman writes after each name (``Load CH=2``).
_CHANNEL_NUMBER = re.compile(r"\s+CH=\d+\s*$")
#: The separator when the export does not give one.
DEFAULT_DELIMITER = "\t"


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a catman ASCII export: its first line names the format."""
    return bool(head.lines) and head.lines[0].strip().startswith(MAGIC)


#: The rows below the settings as delimited text, the export's settings the preamble.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the data of a catman export sit, the channels' names and units.

    Raises
    ------
    LayoutError
        If there is no names row, or no row of numbers within the file's head.
    """
    delimiter = _delimiter(head)
    names_index = next((index for index, line in enumerate(head.lines[1:], start=1)
                        if len(split_fields(line, delimiter)) > 1), None)
    if names_index is None:
        raise LayoutError(
            "no row of channel names below the export's settings", file=head.name,
            hint="export the measurement again from catman as ASCII, with the channel "
                 "names")
    data_index, decimal = _first_data(head, delimiter, names_index + 1)
    names = [_CHANNEL_NUMBER.sub("", cell).strip()
             for cell in split_fields(head.lines[names_index], delimiter)]
    units_index = names_index + 1 if names_index + 1 < data_index else None
    units = (split_fields(head.lines[units_index], delimiter) if units_index is not None
             else [])
    width = len(split_fields(head.lines[data_index], delimiter))
    names = (names + [""] * width)[:width]
    units = [unit.strip() or None for unit in (units + [""] * width)[:width]]
    return TableSpec(
        delimiter=delimiter, decimal=decimal, names=names, header_index=names_index,
        units_index=units_index, data_index=data_index, width=width, units=units,
        preamble=[line for line in head.lines[1:names_index] if line.strip()],
    )


def _delimiter(head: Head) -> str:
    """The field separator the settings give (``SEPARATOR: 9``), a tab by default."""
    for line in head.lines[1:]:
        if match := _SEPARATOR.match(line.strip()):
            return chr(int(match.group(1)))
    return DEFAULT_DELIMITER


def _first_data(head: Head, delimiter: str, start: int) -> tuple[int, str]:
    """The index of the first row of numbers from line `start` on, and its decimal mark.

    A row of the channels' acquisition dates (``2017-11-10-17:06``) reads as clock
    readings: a data row holds numbers besides any clock reading."""
    for index in range(start, len(head.lines)):
        row = split_fields(head.lines[index], delimiter)
        for decimal in (".", ","):
            if (row_kind(row, head.lines[index], decimal) == "numeric"
                    and any(is_number(cell, decimal) for cell in row)):
                return index, decimal
    raise LayoutError(
        f"no row of numbers in the first {HEAD_BYTES // 1024} KiB of the file, below the "
        "channels' settings",
        file=head.name, row=start + 1,
        hint="export the measurement again from catman as ASCII without the channel "
             "information, or with fewer channels per file")
