"""LineScale dynamometer log (Ergonomic / Sense-Tek LineScale 3, as its app and PC software
save it): the device, date and time, its settings as ``Key=Value``, then one force reading
a line.

::

    6B:6C:05
    15.05.22
    16:14:25
    LogNo=002
    Unit=kN
    Mode=REL
    RelZero=0.02
    Speed=40
    Trig=0.70
    Stop=0.00
    Pre=3
    Catch=15
    Total=18
    1.41
    4.56
    ...

The header is the preamble. The readings have no time beside them: the time is
built, ``i / Speed`` [s], ``Speed`` being the sampling rate in Hz (10, 40, 640 or
1280), 0 at the first reading. The force takes the unit ``Unit`` (kN, kgf, lbf).
The layout is known by its ``Unit`` and ``Speed`` settings and two of LineScale's
others (``LogNo``, ``Mode``, ``RelZero``, ``Trig``, ``Stop``, ``Pre``, ``Catch``,
``Total``) above a line holding one number.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import TextLayout
from pipeline.ingest.onechannel import read_samples, settings_over_samples
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, is_number

LAYOUT = "linescale"

#: A setting's line: a key, ``=`` and its value, no blanks around it.
_SETTING = re.compile(r"(?P<key>[A-Za-z][A-Za-z0-9]*)=(?P<value>\S*)")
#: The settings the readings are read by, folded.
UNIT, SPEED = "unit", "speed"
#: LineScale's other settings, folded: two of them at least make the layout.
_OTHERS = frozenset({"logno", "mode", "relzero", "trig", "stop", "pre", "catch", "total"})
#: The names of the columns.
NAMES = ("Time", "Force")


def _settings(head: Head) -> tuple[dict[str, str], int | None]:
    """The header's settings (keys folded) and the index of the first reading's line (None
    when no line of one number follows the settings); the device, date and time above them
    are passed over."""
    return settings_over_samples(head, _SETTING, lead=True)


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a LineScale log: its unit, its speed and two other LineScale
    settings, then a line of one number."""
    settings, first = _settings(head)
    return (first is not None and {UNIT, SPEED} <= settings.keys()
            and len(_OTHERS & settings.keys()) >= 2)


def table_spec(head: Head) -> TableSpec:
    """The readings: one column, the force in the unit of the settings."""
    settings, first = _settings(head)
    return TableSpec(
        delimiter="\t", decimal=".", names=list(NAMES), header_index=first - 1,
        units_index=None, data_index=first, width=2, units=["s", settings[UNIT] or None],
        preamble=[line for line in head.lines[:first] if line.strip()],
    )


#: The log as delimited text, its header the preamble (:func:`read` reads it).
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a LineScale log sniffed as `head` / `spec` (see the module docstring).

    Raises
    ------
    LayoutError
        If the speed is no rate above 0.
    """
    speed = _settings(head)[0][SPEED]
    rate = float(speed) if is_number(speed, ".") else 0.0
    if not rate > 0:
        raise LayoutError(f"the log's Speed={speed} is no sampling rate", file=head.name,
                          hint="check the log's header: Speed is its rate in Hz")
    return read_samples(TEXT, head, spec, columns, 0.0, 1.0 / rate)
