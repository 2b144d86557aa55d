"""Time columns written as clock readings: times of day, ISO 8601 date-times, elapsed
minutes and seconds.

Some loggers stamp each row with the wall-clock time (``14:03:27.125``, or
``2024-03-05 14:03:27.125``, or a TDMS timestamp channel) or the time elapsed in
minutes and seconds (``12:03.4``) instead of seconds since the start. Such a
column is read by pyarrow (or npTDMS) as a time of day or a timestamp and
becomes seconds after the first data row's stamp, so that every chunk of a long
log counts from the same origin. Nothing is guessed:

* only these three forms are read: hours of one or two digits (a time of day; up to
  four as a test clock counts the time elapsed past 24 hours), ``.`` or ``,`` before
  the fraction of a second (``9:03:27,125``, as a logger set to a decimal comma
  writes it), or ``:`` before three digits of milliseconds (``09:39:48:776``, as a
  press's software writes them), the date's parts joined by ``-`` or, as some
  loggers write it, by ``/`` (``2024/03/05 14:03:27.125``: the year first, so still
  one reading), or the day first with dots as German and Central European software
  writes it (``05.03.2024 14:03:27,125``: a dotted date is always day, month, year),
  with or without its offset from UTC (``2021-02-26T16:41:09+01:00``, ``...Z``: read
  as UTC, so that summer time beginning or ending is no step); minutes and seconds
  with the fraction of a second (``0:00.1``, ``75:12.3``, hours in front once past
  the hour, as Measurement Computing's DAQami writes its elapsed time: without the
  fraction, ``5:14`` could be hours and minutes); a 12-hour clock (``2:03:27 PM``:
  12 AM is midnight) and, in front of a time of day, a date of slashes (``3/5/2024
  2:03:27 PM``, as a spreadsheet saves a date and time: March or May, told as a date
  column's are, :func:`carried_order`). Other forms (``3/5/2024 2:03 PM``, without
  seconds) are not read: such a column is set aside as text
  (:func:`is_unread_clock`), and a run that needs the time is refused;
* a column whose first reading is in pyarrow's own form (two-digit hours,
  ``.``, ISO dashes) is parsed by its CSV reader; any other is read as text
  and rewritten to that form with pyarrow's string functions first;
* a fraction of a second that counts milliseconds without zero padding, as a
  microcontroller's logger writes ``millis() % 1000`` (``21.99`` then
  ``21.100``: 99 ms, then 100 ms), is read as milliseconds, with a note, when the
  head of the column shows it: within one second a fraction grows by a digit
  while its decimal value drops, and every fraction has at most three digits;
* a clock reading in whole seconds followed by a column named ``ms`` or ``us``
  that counts the milliseconds or microseconds within the second (a Graphtec
  midi logger's ``Date&Time,ms`` or ``Time,us``) has that count added, with a
  note (:func:`fraction_column`): only when every count in the head is a whole
  number below one second;
* a time of day with the date in the column before it (``Date,Time``, as
  Graphtec and other data loggers write them) is joined to that date, with a
  note (:func:`date_column`), when every date in the head has one reading: year
  first (``2026/06/01``), dotted day first (``01.06.2026``), or of slashes
  with a day past the 12th that says the order (``13/06/2026``). Slashes whose
  parts are all 12 or less in the head (``05/03/2026``) are read in the one
  order under which the rows read's dates follow one another day by day
  (:func:`slash_order`): the other order turns a change of day into a change
  of month. Where neither order does so (a log that stops for a day), the date
  is not joined: a time of day that passes midnight then steps back by a day,
  which is reported as a time step back (:mod:`pipeline.ingest.canonical`),
  not repaired. A date-time carries its date, so it simply goes on counting.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import NamedTuple

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc

from pipeline.errors import LayoutError

#: The clock forms read, by kind: a time of day, a date (year first) and time, and an
#: elapsed time in minutes and seconds (hours in front once past the hour).
_FORMS = {
    "time of day": re.compile(
        r" *(?:\d{1,2}/\d{1,2}/(?:\d{4}|\d{2})[ T]+)?(?:\d{1,4}:\d{2}:\d{2}(?:[.,]\d+|:\d{3})?"
        r"|(?:0?[1-9]|1[0-2]):\d{2}:\d{2}(?:[.,]\d+)? *[AaPp]\.?[Mm]\.?) *"),
    "date and time": re.compile(
        r" *(?:\d{4}(?P<sep>[-/])\d{2}(?P=sep)\d{2}|\d{2}\.\d{2}\.\d{4})"
        r"[T _-]\d{1,2}:\d{2}:\d{2}(?:[.,]\d+)?(?:Z|[+-]\d{2}:?\d{2}| ?UTC)? *"),
    "minutes and seconds": re.compile(r" *(?:\d+:)?\d+:\d{2}[.,]\d+ *"),
}
#: The parts of an elapsed time (RE2, for pyarrow), its decimal comma made a point.
_ELAPSED_PARTS = r"^(?P<hours>\d+:)?(?P<minutes>\d+):(?P<seconds>\d{2}\.\d+)$"
#: The parts of a time of day, read as the time since midnight: past 24 hours too, as a
#: rig's clock of the time elapsed writes them (``25:13:02``), or of a 12-hour clock
#: (``2:03:27 PM``).
_HOURS_PARTS = (r"^(?P<hours>\d+:)(?P<minutes>\d{2}):(?P<seconds>\d{2}(?:\.\d+)?)"
                r"(?: *(?P<half>[AaPp])\.?[Mm]\.?)?$")
#: A date of slashes before a time of day in one cell (``3/5/2024 2:03:27 PM``, as a
#: spreadsheet writes a date and time; a logger's ``11/17/18 12:37:17 PM`` with a
#: two-digit year): its date, and the time of day after it.
_CARRIED_DATE = r"^(?P<date>\d{1,2}/\d{1,2}/(?:\d{4}|\d{2}))[ T]+(?P<time>.*)$"
#: The same date before a time, for the head's cells (Python's regex): its three parts.
_SLASHED_DATE_FIRST = re.compile(r" *(\d{1,2})/(\d{1,2})/(\d{4}|\d{2})[ T]")
#: The forms pyarrow's CSV reader parses itself: two-digit hours, ``.``, ISO 8601 dashes
#: (a column whose hours pass 24 is read again as text: :meth:`ClockColumn.readings`).
_ARROW_FORMS = {
    "time of day": re.compile(r" *\d{2}:\d{2}:\d{2}(?:\.\d+)? *"),
    "date and time": re.compile(r" *\d{4}-\d{2}-\d{2}[T ]\d{2}:\d{2}:\d{2}(?:\.\d+)? *"),
}
#: How a reading of another form is rewritten to pyarrow's: the date's parts joined by
#: "/", a decimal comma (each the only "/" or "," a reading can hold), then a one-digit
#: hour (a regular expression and its replacement, RE2 reading ``\10`` as group 1, "0").
_PLAIN_REWRITES = (("/", "-"), (",", "."))
_ONE_DIGIT_HOUR = (r"([T ])(\d):", r"\10\2:")
#: A date and time's offset from UTC (ISO 8601: ``Z``, ``+01:00``, ``-0500``; a cloud
#: logger's ``UTC``, as ThingSpeak writes ``2021-03-04 10:15:02 UTC``).
_UTC_OFFSET = re.compile(r"(?:Z|[+-]\d{2}:?\d{2}| ?UTC) *$")
#: ``UTC`` after a date and time, rewritten as ISO 8601's ``Z`` (RE2).
_UTC_WORD = (r" ?UTC$", "Z")
#: Milliseconds after a colon (a press's ``09:39:48:776``), rewritten after a point.
_COLON_MILLISECONDS = (r"^(.*\d:\d{2}:\d{2}):(\d{3})$", r"\1.\2")
#: A date joined to its time by "-" or "_" (a load-cell logger's ``2018-11-15-09:30:25.349``),
#: rewritten with a blank (after :data:`_PLAIN_REWRITES`).
_DATE_TIME_JOINT = (r"^(\d{4}-\d{2}-\d{2})[_-]", r"\1 ")
#: A dotted date, day first (``05.03.2024``), rewritten year first (before the others).
_DAY_FIRST_DATE = (r"^(\d{2})\.(\d{2})\.(\d{4})", r"\3-\2-\1")
#: Anything with hours and minutes: a clock reading, read or not.
_CLOCK_LIKE = re.compile(r"\d{1,2}:\d{2}")
#: The hint for a clock reading in a form that is not read.
READ_FORMS = ("H:MM:SS.fff (or H:MM:SS:fff), YYYY-MM-DD H:MM:SS.fff (also with a UTC "
              "offset or UTC), YYYY/MM/DD H:MM:SS.fff, DD.MM.YYYY H:MM:SS.fff, D/M/YYYY or "
              "M/D/YYYY (or YY) H:MM:SS.fff, each also with AM or PM, and M:SS.fff, with "
              "'.' or ',' before the fraction")
UNREAD_FORM_HINT = (
    f"the column holds clock readings in a form the reader does not guess (it reads "
    f"{READ_FORMS}): export the time in seconds, or name another time column in the run "
    "sheet")
#: A reading that stops at the minute (``3/5/2024 2:03 PM``): its last hours and minutes
#: have no seconds after them.
_STOPS_AT_MINUTE = re.compile(r"(?:^|[^:\d])\d{1,2}:\d{2}(?: *[AaPp]\.?[Mm]\.?)? *$")
#: Why clock readings to the minute do not time a log, and what to do.
MINUTE_READINGS = (
    "the samples of a minute share one reading, so they cannot time the log (a "
    "spreadsheet saves a date and time as it shows them: show the seconds, h:mm:ss, "
    "before saving, or export from the machine)")
#: The arrow type each kind is parsed as.
_ARROW_TYPES = {"time of day": pa.time64("ns"), "date and time": pa.timestamp("ns"),
                "minutes and seconds": pa.timestamp("ns")}
#: Nanoseconds per second.
_NS = 1_000_000_000
#: Names of a column counting the fraction of a second beside a clock column, and the
#: seconds one count stands for.
_FRACTION_NAMES = {"ms": 1e-3, "msec": 1e-3, "us": 1e-6, "usec": 1e-6, "µs": 1e-6, "μs": 1e-6}
_WHOLE_COUNT = re.compile(r" *\+?\d+(?:\.0+)? *")  # "250.0": a spreadsheet's number
#: The forms of a date in a column of its own, as the head's cells must match them: year
#: first (a workbook's date cell adds a midnight), dotted day first, and slashes whose
#: order the head must decide (:func:`date_column`).
_DATE_FORMS = {
    "ymd": re.compile(r"\d{4}([-/])\d{1,2}\1\d{1,2}(?: 00:00:00)?"),
    "dmy": re.compile(r"\d{1,2}\.\d{1,2}\.\d{4}"),
    "slashes": re.compile(r"\d{1,2}/\d{1,2}/(?:\d{4}|\d{2})"),
}
#: The parts of a date of each order (RE2, for pyarrow); a cell of another form is null.
_DATE_PARTS = {
    "ymd": r"^(?P<year>\d{4})[-/](?P<month>\d{1,2})[-/](?P<day>\d{1,2})(?: 00:00:00)?$",
    "dmy": r"^(?P<day>\d{1,2})[./](?P<month>\d{1,2})[./](?P<year>\d{4}|\d{2})$",
    "mdy": r"^(?P<month>\d{1,2})/(?P<day>\d{1,2})/(?P<year>\d{4}|\d{2})$",
}
_ORDER_NAMES = {"ymd": "year first", "dmy": "day first", "mdy": "month first",
                "slashes": "day or month first, whichever makes the dates follow one "
                           "another day by day"}
#: A two-digit year below it is of this century, from it of the last (as POSIX reads
#: ``%y``): only the days between dates count, so only a log across the first of January
#: 2069 would step by a century, and not be read as a log day by day.
_TWO_DIGIT_PIVOT = "69"
#: Seconds per day.
_DAY_SECONDS = 86_400.0
#: A time of day or date and time split at its fraction of a second.
_FRACTION = re.compile(r" *(?P<whole>.*\d:\d{2})[.,](?P<fraction>\d+) *")
#: How fractions of one and two digits are zero-padded to milliseconds (RE2 rewrites).
_PAD_MILLISECONDS = ((r"\.(\d)$", r".00\1"), (r"\.(\d\d)$", r".0\1"))


def clock_kind(text: str) -> str | None:
    """``"time of day"``, ``"date and time"`` or ``"minutes and seconds"`` if `text` is a
    clock reading, else None.

    Examples
    --------
    >>> clock_kind("9:03:27,125"), clock_kind("2024/03/05 14:03:27"), clock_kind("1.5")
    ('time of day', 'date and time', None)
    >>> clock_kind("12:03.4"), clock_kind("12:03")
    ('minutes and seconds', None)
    """
    for kind, form in _FORMS.items():
        if form.fullmatch(text):
            return kind
    return None


def looks_like_clock(text: str) -> bool:
    """True if `text` holds hours and minutes (``5:14 PM``, ``05.03.2024 14:03``).

    >>> looks_like_clock("3/5/2024 2:03:27 PM"), looks_like_clock("1.5")
    (True, False)
    """
    return _CLOCK_LIKE.search(text) is not None


def is_unread_clock(text: str) -> bool:
    """True if `text` holds hours and minutes in a form not read (see :func:`clock_kind`):
    a column of them is text.

    >>> is_unread_clock("3/5/2024 2:03 PM"), is_unread_clock("3/5/2024 2:03:27 PM")
    (True, False)
    """
    return looks_like_clock(text) and clock_kind(text) is None


def stops_at_minute(text: str) -> bool:
    """True if the clock reading `text` has hours and minutes but no seconds.

    >>> stops_at_minute("3/5/2024 2:03 PM"), stops_at_minute("05.03.2024 14:03:27")
    (True, False)
    """
    return _STOPS_AT_MINUTE.search(text) is not None


def unread_clock_hint(text: str) -> str:
    """The hint for a clock reading `text` that is not read: why, and what to do."""
    if stops_at_minute(text):
        return f"the column holds clock readings to the minute: {MINUTE_READINGS}"
    return UNREAD_FORM_HINT


class Fraction(NamedTuple):
    """A column counting the fraction of a second of the clock column before it."""

    column: int  # its index among the table's fields
    seconds: float  # seconds per count (1e-3 for milliseconds)
    first: float  # the first data row's count: the origin, with the clock's first reading
    name: str  # the column's name, for the note


class DateColumn(NamedTuple):
    """A column of dates before a time-of-day column: the day of each reading."""

    column: int  # its index among the table's fields
    order: str  # "ymd", "dmy", "mdy", or "slashes": dmy or mdy by :func:`slash_order`
    first: str  # the first data row's date: the origin, with the clock's first reading
    name: str  # the column's name, for the note


@dataclass(frozen=True)
class ClockColumn:
    """A column of clock readings: their kind and the first data row's reading.

    Attributes
    ----------
    kind : str
        ``"time of day"``, ``"date and time"`` or ``"minutes and seconds"`` (see
        :func:`clock_kind`).
    first : str
        The first data row's cell: the origin of the seconds.
    unpadded : str or None
        Where the fraction of a second is milliseconds written without zero padding,
        the two readings that show it (``"'21.99' then '21.100' (line 81)"``): see
        :func:`unpadded_milliseconds`.
    fraction : Fraction or None
        The column beside it that counts the fraction of a second, if the readings are
        whole seconds (see :func:`fraction_column`).
    date : DateColumn or None
        The column before a time of day that gives its date (see :func:`date_column`).
    carried : str or None
        The order of the date of slashes each time of day carries in its cell
        (``"3/5/2024 2:03:27 PM"``): ``"dmy"``, ``"mdy"`` or ``"slashes"`` (see
        :func:`carried_order`); None when the cells hold no date.
    """

    kind: str
    first: str
    unpadded: str | None = None
    fraction: Fraction | None = None
    date: DateColumn | None = None
    carried: str | None = None

    @property
    def arrow_type(self) -> pa.DataType:
        """The type pyarrow parses the column's cells as: text when the first reading is
        in a form its CSV reader does not parse (see :data:`_ARROW_FORMS`)."""
        return pa.string() if self._as_text else _ARROW_TYPES[self.kind]

    def readings(self, cells: pa.ChunkedArray) -> pa.ChunkedArray:
        """The column as pyarrow's CSV reader gave it (:attr:`arrow_type`, or text where
        the hours of a time of day pass 24), as times of day or timestamps (a time of
        day read as text: the time since midnight, as a timestamp since 1970); raises
        :class:`pyarrow.ArrowInvalid` on a cell that is not a reading."""
        if not (self._as_text or pa.types.is_string(cells.type)):
            return cells
        return pc.cast(self._nanoseconds(cells), pa.timestamp("ns"))

    def seconds(self, readings: pa.ChunkedArray) -> pa.ChunkedArray:
        """`readings` (times of day or timestamps, any resolution) as float64 seconds after
        :attr:`first`."""
        unit = pa.time64("ns") if pa.types.is_time(readings.type) else pa.timestamp("ns")
        return self._after_first(pc.cast(pc.cast(readings, unit), pa.int64()))

    def with_fraction(self, seconds: pa.ChunkedArray, counts: pa.ChunkedArray
                      ) -> pa.ChunkedArray:
        """`seconds` (:meth:`seconds`) plus the fraction of a second in `counts`, the cells
        of :attr:`fraction`'s column, after the first row's (a clock with a fraction)."""
        fraction = pc.subtract(pc.cast(counts, pa.float64()), self.fraction.first)
        return pc.add(seconds, pc.multiply(fraction, self.fraction.seconds))

    def with_date(self, seconds: pa.ChunkedArray, dates: pa.ChunkedArray) -> pa.ChunkedArray:
        """`seconds` (:meth:`seconds`) plus the days from :attr:`date`'s first date to the
        dates `dates` of the same rows (a clock with a date); null where a date is not of
        its form (a missing value, or a cell of another form: the time is then missing)."""
        days = _day_offsets(self.date.first, dates, self.date.order, self.date.name)
        if days is None:
            return seconds
        return pc.add(seconds, pc.multiply(pc.cast(days, pa.float64()), _DAY_SECONDS))

    def seconds_of_texts(self, texts: list[str | None]) -> np.ndarray:
        """Cells written as text (a spreadsheet's), as float64 seconds after :attr:`first`;
        NaN where a cell is None."""
        return self._after_first(self._nanoseconds(
            pa.chunked_array([pa.array(texts, pa.string())]))).to_numpy()

    @cached_property
    def _as_text(self) -> bool:
        """Whether the column is read as text and rewritten (:data:`_ARROW_FORMS`)."""
        form = _ARROW_FORMS.get(self.kind)
        return form is None or form.fullmatch(self.first) is None or self.unpadded is not None

    def _nanoseconds(self, texts: pa.ChunkedArray) -> pa.ChunkedArray:
        """Texts as int64 nanoseconds: since midnight, since 1970 for a date and time, or
        the time elapsed."""
        column = pc.utf8_trim_whitespace(texts)
        if self.kind == "minutes and seconds":
            return _elapsed_nanoseconds(column, _ELAPSED_PARTS)
        if self._as_text and self.kind == "date and time":
            column = pc.replace_substring_regex(column, *_DAY_FIRST_DATE)
            for old, new in _PLAIN_REWRITES:
                column = pc.replace_substring(column, old, new)
            column = pc.replace_substring_regex(column, *_DATE_TIME_JOINT)
            column = pc.replace_substring_regex(column, *_ONE_DIGIT_HOUR)
            column = pc.replace_substring_regex(column, *_UTC_WORD)
        if self.unpadded is not None:
            for pattern, padded in _PAD_MILLISECONDS:
                column = pc.replace_substring_regex(column, pattern, padded)
        if self.kind == "time of day":
            column = pc.replace_substring_regex(column, *_COLON_MILLISECONDS)
            return self._carried_days(column) if self.carried else _elapsed_nanoseconds(
                column, _HOURS_PARTS)
        return pc.cast(pc.cast(column, pa.timestamp("ns", tz="UTC" if self._zoned else None)),
                       pa.int64())

    @cached_property
    def _zoned(self) -> bool:
        """Whether the readings carry their offset from UTC (read as UTC: a change of
        offset, summer time beginning or ending, is no step of the time)."""
        return self.kind == "date and time" and _UTC_OFFSET.search(self.first) is not None

    def _carried_days(self, column: pa.ChunkedArray) -> pa.ChunkedArray:
        """Times of day that carry a date of slashes (:attr:`carried`) as int64 nanoseconds
        since midnight of :attr:`first`'s date; only the times of day when the date's order
        is not decided (:func:`slash_order`: the time then steps back past midnight)."""
        parts = pc.extract_regex(column, _CARRIED_DATE)
        if parts.null_count > column.null_count:
            raise pa.ArrowInvalid("a cell is no date and time of the column's form")
        dates, times = (pc.struct_field(parts, name) for name in ("date", "time"))
        nanoseconds = _elapsed_nanoseconds(times, _HOURS_PARTS)
        days = _day_offsets(self.first.strip().split()[0], dates, self.carried, "the time")
        if days is None:
            return nanoseconds
        return pc.add(nanoseconds, pc.multiply(days, int(_DAY_SECONDS) * _NS))

    @cached_property
    def _origin(self) -> int:
        """:attr:`first` in nanoseconds, parsed once (every row range subtracts it)."""
        return self._nanoseconds(pa.chunked_array([[self.first]]))[0].as_py()

    def _after_first(self, nanoseconds: pa.ChunkedArray) -> pa.ChunkedArray:
        return pc.divide(pc.cast(pc.subtract(nanoseconds, self._origin), pa.float64()),
                         float(_NS))

    def matches(self, text: str) -> bool:
        """True if `text` is a clock reading of this column's kind that the column reads
        (in pyarrow's own form only, unless the column is read as text)."""
        return _FORMS[self.kind].fullmatch(text) is not None and (
            self._as_text or _ARROW_FORMS[self.kind].fullmatch(text) is not None) and (
            self.kind != "time of day"
            or (self.carried is not None) == bool(_SLASHED_DATE_FIRST.match(text)))

    def mismatch(self, text: str) -> str:
        """The message for a cell `text` of this column that is not a clock reading like it."""
        return (f"{text.strip()[:40]!r} is not a clock reading like the first row's "
                f"{self.first.strip()!r}")

    def note(self, name: str) -> str:
        """What the reader tells the user about column `name`."""
        kind = ("date and time" if self.carried else "a time elapsed, from zero"
                if self.kind == "time of day" and _FROM_ZERO.fullmatch(self.first)
                else self.kind)
        note = (f"column {name!r} holds clock readings ({kind}, first "
                f"{self.first.strip()!r}): read as seconds after the first row's")
        if self.unpadded is not None:
            note += (f"; the fraction of a second counts milliseconds without zero padding "
                     f"({self.unpadded}): read as milliseconds")
        if self.fraction is not None:
            unit = "milliseconds" if self.fraction.seconds == 1e-3 else "microseconds"
            note += (f", plus the {unit} within the second that column "
                     f"{self.fraction.name!r} counts")
        if self.date is not None:
            note += (f", on the dates of column {self.date.name!r} (first "
                     f"{self.date.first.strip()!r}, {_ORDER_NAMES[self.date.order]})")
        if self.carried is not None:
            note += f", on the date each reading carries ({_ORDER_NAMES[self.carried]})"
        if self._zoned:
            note += ", each at its offset from UTC"
        return note


#: A first reading of a clock that counts from zero (a logger's elapsed ``00:00:00``): no
#: time of day.
_FROM_ZERO = re.compile(r"\s*0?0:00:0\d(?:[.,]\d+)?\s*")


def fraction_columns(clocks: Mapping[int, ClockColumn]) -> frozenset[int]:
    """The columns counting the fraction of a second of the clock columns `clocks`: part
    of the time, not a quantity of their own."""
    return frozenset(clock.fraction.column for clock in clocks.values()
                     if clock.fraction is not None)


def date_columns(clocks: Mapping[int, ClockColumn]) -> frozenset[int]:
    """The columns giving the dates of the clock columns `clocks` (read as text)."""
    return frozenset(clock.date.column for clock in clocks.values() if clock.date is not None)


def fraction_column(first: str, index: int, names: list[str], rows: list[list[str]]
                    ) -> Fraction | None:
    """The column after clock column `index` that counts its fraction of a second, or None.

    A logger that stamps its rows to the whole second may count the milliseconds
    (or microseconds) within the second in the next column (Graphtec's
    ``Date&Time,ms``; ``Time,us``). That column is taken as the fraction only when
    its name says so (:data:`_FRACTION_NAMES`), the clock's first reading `first`
    has no fraction of its own and every count in `rows` (the head's data rows)
    is a whole number below one second.

    Examples
    --------
    >>> rows = [["1", "2024/03/05 14:03:27", "0"], ["2", "2024/03/05 14:03:27", "500"]]
    >>> fraction_column(rows[0][1], 1, ["No.", "Date&Time", "ms"], rows)
    Fraction(column=2, seconds=0.001, first=0.0, name='ms')
    >>> fraction_column(rows[0][1], 1, ["No.", "Date&Time", "force"], rows) is None
    True
    """
    column = index + 1
    if column >= len(names) or _FRACTION.fullmatch(first) is not None:
        return None
    seconds = _FRACTION_NAMES.get(names[column].strip().lower())
    counts = [row[column] if column < len(row) else "" for row in rows]
    if (seconds is None or not counts or not counts[0].strip()
            or not all(_WHOLE_COUNT.fullmatch(count) and float(count) * seconds < 1
                       for count in counts if count.strip())):
        return None
    return Fraction(column, seconds, float(counts[0]), names[column].strip())


def date_column(kind: str, index: int, names: list[str], rows: list[list[str]]
                ) -> DateColumn | None:
    """The column beside time-of-day column `index` that gives the date of its readings
    (the one before it, else the one after, as IMADA's Force Recorder writes ``Time,Date``),
    or None.

    Taken only when every cell of that column in `rows` (the head's data rows) is a
    date: year first (``2026/06/01``, ``2026-06-01``), dotted and day first
    (``01.06.2026``), or of slashes (``01/06/2026``). The order of slashes is
    the head's when a day past the 12th says which part is the day
    (``13/06/2026``: day first); otherwise it is ``"slashes"``, decided from the
    rows read (:func:`slash_order`).

    Examples
    --------
    >>> rows = [["13/06/2026", "23:59:59"], ["14/06/2026", "00:00:00"]]
    >>> date_column("time of day", 1, ["Date", "Time"], rows)
    DateColumn(column=0, order='dmy', first='13/06/2026', name='Date')
    >>> date_column("time of day", 1, ["Date", "Time"], [["01/06/2026", "12:00:00"]])
    DateColumn(column=0, order='slashes', first='01/06/2026', name='Date')
    """
    if kind != "time of day":
        return None
    return next(filter(None, (_dates_in(column, names, rows)
                              for column in (index - 1, index + 1) if 0 <= column)), None)


def _dates_in(column: int, names: list[str], rows: list[list[str]]) -> DateColumn | None:
    """Column `column` as the dates of a time of day, if every cell of it is a date that
    can be read one way (see :func:`date_column`)."""
    cells = [row[column].strip() for row in rows if column < len(row) and row[column].strip()]
    if not cells or column >= len(names):
        return None
    order = next((order for order, form in _DATE_FORMS.items()
                  if all(form.fullmatch(cell) for cell in cells)), None)
    if order == "slashes":
        order = _order_of_slashes([cell.split("/") for cell in cells])
    return None if order is None else DateColumn(column, order, cells[0], names[column].strip())


def carried_order(kind: str, index: int, rows: list[list[str]]) -> str | None:
    """The order of the date of slashes that the times of day of column `index` carry in
    their cells (``3/5/2024 2:03:27 PM``, as a spreadsheet writes a date and time), or
    None when its first cell (in `rows`, the head's data rows) carries none.

    ``"dmy"`` or ``"mdy"`` when a part past 12 in the head says which is the day;
    otherwise ``"slashes"``, decided from the rows read (:func:`slash_order`).

    Examples
    --------
    >>> carried_order("time of day", 0, [["3/5/2024 11:59:59 PM"], ["3/6/2024 12:00:00 AM"]])
    'slashes'
    >>> carried_order("time of day", 0, [["13/05/2024 14:03:27"]])
    'dmy'
    """
    cells = [row[index] for row in rows if index < len(row)]
    if kind != "time of day" or not cells or not _SLASHED_DATE_FIRST.match(cells[0]):
        return None
    # None where no order reads them: the cells are then refused as no readings
    return _order_of_slashes([found.groups() for cell in cells
                              if (found := _SLASHED_DATE_FIRST.match(cell))])


def _order_of_slashes(parts: list) -> str | None:
    """The order of dates of slashes from their three `parts` (texts of numbers) in the
    head: ``"dmy"`` or ``"mdy"`` when a part past 12 says which is the day,
    ``"slashes"`` when none does (:func:`slash_order` decides later), None when parts
    past 12 on both sides leave no date.

    A two-digit year always leaves the order to the dates' steps (``"slashes"``): it
    may as well be first (``18/11/17``, year, month, day), where a part past 12 is no
    day."""
    day_first, month_first = (any(int(part[i]) > 12 for part in parts) for i in (0, 1))
    if day_first and month_first:
        return None
    if any(len(part[2]) == 2 for part in parts):
        return "slashes"
    return "dmy" if day_first else "mdy" if month_first else "slashes"


def slash_order(first: str, dates: pa.ChunkedArray, name: str = "Date") -> str | None:
    """``"dmy"`` or ``"mdy"``: the order under which `dates` (the cells of slashes of date
    column `name`, rows in order; `first` the file's first) step by no day or one day
    from row to row, not before `first`; None if neither order does.

    Read in the wrong order, a change of day becomes a change of month (``05/03`` to
    ``06/03``: a day, or a month) or no date at all (a part past 12). A log that
    stops for a day or more is not decided. Rows of a long log that begin days after
    `first` with one date all along can be read in both orders: that is refused.

    Raises
    ------
    LayoutError
        If both orders read `dates` so, with different days.

    Examples
    --------
    >>> dates = pa.chunked_array([["05/03/2026", "05/03/2026", "06/03/2026"]])
    >>> slash_order("05/03/2026", dates)
    'dmy'
    >>> slash_order("05/03/2026", pa.chunked_array([["05/03/2026", "07/03/2026"]])) is None
    True
    """
    cells = pa.chunked_array([[first], *dates.cast(pa.string()).chunks])
    offsets = {}
    for order in ("dmy", "mdy"):
        try:
            days = _days(cells, order).to_numpy(zero_copy_only=False)
        except pa.ArrowInvalid:  # a part past 12 where the month is: not this order
            continue
        days = days[~np.isnan(days)] if days.dtype.kind == "f" else days
        steps = np.diff(days)
        if steps.size == 0 or (steps[0] >= 0 and np.isin(steps[1:], (0, 1)).all()):
            offsets[order] = days - days[0]
    if len(offsets) < 2 or np.array_equal(*offsets.values()):
        return next(iter(offsets), None)  # both alike: one date all along
    raise LayoutError(
        f"the dates from {first.strip()!r} on read as whole days both day first and month "
        "first: these rows do not show which", column=name,
        hint="export the date year first, or the date and time in one column, or the time "
             "in seconds")


def unpadded_milliseconds(cells: list[str], first_line: int) -> str | None:
    """The two readings of `cells` (a clock column's, one per line from `first_line`) that
    show its fraction of a second to be milliseconds without zero padding, or None.

    Such a fraction grows by a digit within one second while its decimal value
    drops (``21.99`` then ``21.100``: 99 ms, then 100 ms, read as decimals 0.99 s
    then 0.1 s). It is taken for milliseconds only when every fraction has at most
    three digits and, so read, no reading within a second steps back.

    Examples
    --------
    >>> unpadded_milliseconds(["03:15:21.98", "03:15:21.99", "03:15:21.100"], 80)
    "'03:15:21.99' then '03:15:21.100' (line 82)"
    >>> unpadded_milliseconds(["03:15:21.5", "03:15:21.75", "03:15:22.25"], 1) is None
    True
    """
    shown, previous = None, None
    for offset, cell in enumerate(cells):
        match = _FRACTION.fullmatch(cell)
        if match is None:
            previous = None
            continue
        whole, fraction = match["whole"], match["fraction"]
        if len(fraction) > 3:
            return None
        if previous is not None and previous[0] == whole:
            if int(fraction) < int(previous[1]):
                return None  # a step back as milliseconds: decimals, or no clock at all
            if (shown is None and len(fraction) > len(previous[1])
                    and float(f"0.{fraction}") < float(f"0.{previous[1]}")):
                shown = (f"{previous[2].strip()!r} then {cell.strip()!r} "
                         f"(line {first_line + offset})")
        previous = (whole, fraction, cell)
    return shown


def _day_offsets(first: str, dates: pa.ChunkedArray, order: str, name: str
                 ) -> pa.ChunkedArray | None:
    """The days from date `first` to each of `dates` (int64), both written in `order`
    (``"slashes"``: decided by :func:`slash_order` for column `name`); None when that
    order is not decided."""
    if order == "slashes":
        order = slash_order(first, dates, name)
        if order is None:
            return None
    return pc.subtract(_days(dates, order),
                       _days(pa.chunked_array([[first]]), order)[0].as_py())


def _days(dates: pa.ChunkedArray, order: str) -> pa.ChunkedArray:
    """Dates written in `order` (:data:`_DATE_PARTS`) as int64 days since 1970; null where
    a date is missing or of another form."""
    parts = pc.extract_regex(pc.utf8_trim_whitespace(dates), _DATE_PARTS[order])
    year, month, day = (pc.utf8_lpad(pc.struct_field(parts, name), 2, "0")
                        for name in ("year", "month", "day"))
    century = pc.if_else(pc.less(year, _TWO_DIGIT_PIVOT), "20", "19")
    year = pc.if_else(pc.equal(pc.utf8_length(year), 2),
                      pc.binary_join_element_wise(century, year, ""), year)
    iso = pc.binary_join_element_wise(year, month, day, "-")
    seconds = pc.cast(pc.cast(iso, pa.timestamp("s")), pa.int64())
    return pc.divide(seconds, 86_400)


def _elapsed_nanoseconds(texts: pa.ChunkedArray, pattern: str) -> pa.ChunkedArray:
    """Times of hours, minutes and seconds as int64 nanoseconds: elapsed times
    (``[H:]M:SS.fff``, :data:`_ELAPSED_PARTS`) or times of day (``H:MM:SS[.fff]``, or on
    a 12-hour clock ``H:MM:SS[.fff] AM``, :data:`_HOURS_PARTS`); raises
    :class:`pyarrow.ArrowInvalid` on a cell of another form, or of a 12-hour clock's hour
    outside 1 to 12."""
    parts = pc.extract_regex(pc.replace_substring(texts, ",", "."), pattern)
    if parts.null_count > texts.null_count:  # a cell that does not match comes back null
        raise pa.ArrowInvalid("a cell is no clock reading of the column's form")
    hours = pc.utf8_rtrim(pc.struct_field(parts, "hours"), characters=":")
    hours = pc.cast(pc.if_else(pc.equal(hours, ""), "0", hours), pa.int64())
    if parts.type.get_field_index("half") >= 0:  # a 12-hour clock: 12 AM is midnight
        half = pc.utf8_lower(pc.struct_field(parts, "half"))
        twelve = pc.not_equal(half, "")
        if pc.any(pc.and_(twelve, pc.or_(pc.less(hours, 1), pc.greater(hours, 12)))).as_py():
            raise pa.ArrowInvalid("an hour of a 12-hour clock outside 1 to 12")
        hours = pc.if_else(twelve, pc.add(pc.if_else(pc.equal(hours, 12), 0, hours),
                                          pc.if_else(pc.equal(half, "p"), 12, 0)), hours)
    seconds = pc.add(pc.multiply(pc.cast(hours, pa.float64()), 3600.0),
                     pc.add(pc.multiply(pc.cast(pc.struct_field(parts, "minutes"),
                                                pa.float64()), 60.0),
                            pc.cast(pc.struct_field(parts, "seconds"), pa.float64())))
    return pc.cast(pc.round(pc.multiply(seconds, float(_NS))), pa.int64())


def declare_seconds(clocks: dict[int, ClockColumn], names: list[str], units: list[str | None],
                    warnings: list[str]) -> None:
    """Give each clock column of `clocks` the unit ``"s"`` in `units` (the reader turns it
    into seconds) and a note in `warnings`."""
    for index, clock in clocks.items():
        units[index] = "s"
        warnings.append(clock.note(names[index] or f"column {index + 1}"))
