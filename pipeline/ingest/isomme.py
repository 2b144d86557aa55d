"""ISO-MME channel file (ISO/TS 13499, as crash, sled and drop-tower data systems write
it): one channel's header, then its samples, one a line.

::

    Channel code                :24NECKUP00P2MOZP
    Name of the channel         :Neck Upper Moment Z, IDN P1.5
    Sampling interval           :0.0001
    Unit                        :Nm
    Time of first sample        :-0.1
    Number of samples           :6000
    Data status                 :ok
    -6.774550E-4
    1.642828E-2
    ...

Each header line is a key, padded with blanks, a colon and its value; the
header is the preamble. The samples have no time beside them: the time is
built, ``Time of first sample + i · Sampling interval`` in seconds (ISO-MME
states its times in seconds), and is negative before the trigger. The channel
takes the name ``Name of the channel`` and the unit ``Unit``. The layout is
known by its ``Sampling interval`` and ``Time of first sample`` lines above a
line holding one number.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.onechannel import read_samples, settings_over_samples
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec

LAYOUT = "isomme"

#: A header line: a key, blanks, a colon and the value.
_SETTING = re.compile(r"(?P<key>[^:\d][^:]*?)\s*:(?P<value>.*)")
#: The settings that make a file an ISO-MME channel, folded, and those it is read by.
INTERVAL, FIRST_TIME, NAME, UNIT = ("sampling interval", "time of first sample",
                                    "name of the channel", "unit")
#: The name of the time column.
TIME_NAME = "Time"


def _settings(head: Head) -> tuple[dict[str, str], int | None]:
    """The header's settings (keys folded) and the index of the first sample's line (None
    when no line of one number follows the header)."""
    return settings_over_samples(head, _SETTING)


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is an ISO-MME channel file: its sampling interval and the time of
    its first sample in the header, a line of one number below it."""
    settings, first = _settings(head)
    return first is not None and {INTERVAL, FIRST_TIME} <= settings.keys()


def table_spec(head: Head) -> TableSpec:
    """The channel's samples: one column, named and with the unit its header gives."""
    settings, first = _settings(head)
    return TableSpec(
        delimiter="\t", decimal=".", names=[TIME_NAME, settings.get(NAME, "") or "channel"],
        header_index=first - 1, units_index=None, data_index=first, width=2,
        units=["s", _unit(settings.get(UNIT))],
        preamble=[line for line in head.lines[:first] if line.strip()],
    )


def _unit(written: str | None) -> str | None:
    """The channel's unit as written, or None (ISO-MME writes ``NOVALUE``)."""
    return None if not written or written.upper() == "NOVALUE" else written


#: The channel file as delimited text, its header the preamble (:func:`read` reads it).
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read an ISO-MME channel file sniffed as `head` / `spec` (see the module docstring).

    Raises
    ------
    LayoutError
        If the sampling interval or the time of the first sample is no number.
    """
    settings, _ = _settings(head)
    try:
        interval, start = (float(settings[key]) for key in (INTERVAL, FIRST_TIME))
    except ValueError as error:
        raise LayoutError(
            f"the header's {INTERVAL!r} and {FIRST_TIME!r} are no numbers ({error})",
            file=head.name, hint="check the channel file's header") from error
    return read_samples(TEXT, head, spec, columns, start, interval)
