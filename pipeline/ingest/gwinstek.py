"""GW Instek oscilloscope CSV (GDS series): the scope's settings above the samples.

::

    Memory Length,4000,
    Source,CH1,
    Vertical Units,V,
    Horizontal Units,S,
    Sampling Period,4.00000e-07,
    ...
    Mode,Detail,
    Waveform Data,
    -4.000000e-4,3.28e+0,
    -3.996000e-4,3.28e+0,

The settings (one per row, each row ending with a comma) are the preamble.
There is no names row: below ``Waveform Data`` each row holds a sample's time
and the channel's value (the export's ``Detail`` mode). The time takes the name
``Time`` and the unit ``Horizontal Units`` (written ``S``: seconds, not
siemens); the channel the name ``Source`` (``CH1``) and the unit ``Vertical
Units``. The layout is known by its first setting (``Memory Length``) and the
``Waveform Data`` row.

Refused, with a hint: an export in ``Fast`` mode, or of an older firmware
that writes no ``Mode`` (V1.14), whose rows hold one number each: the
converter's raw codes without their time.
"""

from __future__ import annotations

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.sniff import Head, TableSpec, split_fields

LAYOUT = "gwinstek"

#: The setting in the first field of the first row.
FIRST_SETTING = "Memory Length"
#: The row above the samples.
DATA_MARK = "Waveform Data"
#: The name of the time column.
TIME_NAME = "Time"
#: How the scope writes the unit of its time axis, and the unit it means.
HORIZONTAL_UNITS = {"S": "s"}


def _cells(line: str) -> list[str]:
    return [cell.strip() for cell in split_fields(line, ",")]


def _mark(head: Head) -> int | None:
    """The index of the ``Waveform Data`` row among the head's lines, or None."""
    return next((index for index, line in enumerate(head.lines)
                 if _cells(line)[0] == DATA_MARK), None)


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a GW Instek export: ``Memory Length`` first, a ``Waveform Data``
    row above the samples."""
    return bool(head.lines) and _cells(head.lines[0])[0] == FIRST_SETTING and (
        _mark(head) is not None)


#: The layout as delimited text (its settings the preamble): read whole, or by row range.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def table_spec(head: Head) -> TableSpec:
    """Where the samples of a GW Instek export sit, their names and units.

    Raises
    ------
    LayoutError
        For an export of raw codes (in ``Fast`` mode, or one number a row), or one with no
        row below ``Waveform Data``.
    """
    mark = _mark(head)
    settings = {cells[0]: cells[1] for line in head.lines[:mark]
                if len(cells := _cells(line)) > 1 and cells[0]}
    codes_only = mark + 1 < len(head.lines) and sum(
        bool(cell) for cell in _cells(head.lines[mark + 1])) == 1
    if settings.get("Mode") == "Fast" or codes_only:
        saved = ("in Fast mode" if settings.get("Mode") == "Fast"
                 else "one number a row (no Mode written)")
        raise LayoutError(
            f"the oscilloscope saved the waveform {saved}: its rows hold the converter's raw "
            "codes, without their time",
            file=head.name, row=mark + 1,
            hint="save the waveform again in Detail mode, which writes each sample's time "
                 "and value")
    if mark + 1 >= len(head.lines):
        raise LayoutError("no samples below 'Waveform Data'", file=head.name, row=mark + 1,
                          hint="the oscilloscope wrote no samples: save the waveform again")
    width = len(_cells(head.lines[mark + 1]))
    names, units = [""] * width, [None] * width
    names[0], units[0] = TIME_NAME, _horizontal_unit(settings.get("Horizontal Units"))
    if width > 1:
        names[1], units[1] = settings.get("Source", ""), settings.get("Vertical Units") or None
    return TableSpec(
        delimiter=",", decimal=".", names=names, header_index=mark, units_index=None,
        data_index=mark + 1, width=width, units=units,
        preamble=[line for line in head.lines[:mark] if line.strip()],
    )


def _horizontal_unit(written: str | None) -> str | None:
    """The unit of the time axis as written (``S``), as meant (``s``)."""
    return HORIZONTAL_UNITS.get(written, written) if written else None
