"""Parsing the body of a delimited text export with pyarrow, and locating its defects.

The body (every line from the first data row on) is handed to
:func:`pyarrow.csv.read_csv` as one stream: no Python loop runs over its rows.
Python reads lines only on the error path (to say which line and column is
wrong) and to turn a row number into a line number for a warning.
"""

from __future__ import annotations

import math
import re
import threading
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import pyarrow as pa
import pyarrow.compute as pc
import pyarrow.csv as pacsv

from pipeline.errors import LayoutError, ValueParseError
from pipeline.ingest.clock import ClockColumn, date_columns, fraction_columns, looks_like_clock
from pipeline.ingest.roles import display_name
from pipeline.ingest.rowindex import first_comment
from pipeline.ingest.sniff import (
    BLANKS,
    COMMENT_MARK,
    NULL_VALUES,
    THOUSANDS,
    cell_hint,
    is_comment,
    is_missing,
    is_number,
    is_out_of_range,
    row_kind,
    split_fields,
)
from pipeline.ingest.source import BufferSource, Source, contains, text_lines

#: Bytes of the file's end searched for a truncated last line.
TAIL_BYTES = 1 << 16
#: Bytes read to quote a comment line in a warning (its first 60 characters are quoted).
_QUOTED_BYTES = 512

#: The allocator of the tables the body parser makes: the C library's, so that the memory a
#: converted column frees is at once free for the next numpy array. pyarrow's default pool
#: keeps freed pages for itself until asked to release them, a pass over its heaps per column.
POOL = pa.system_memory_pool()

_INVALID = re.compile(r"column #(\d+).*invalid value '(.*)'", re.DOTALL)
_WRONG_WIDTH = re.compile(r"Expected \d+ columns, got \d+: (.*)", re.DOTALL)
#: The thousands separators removed, by decimal mark.
_GROUPING = {".": (",", "'"), ",": (".", " ", "\u00a0", "\u202f")}
#: A cell of points grouping thousands before a decimal comma: the points are no decimal
#: marks in its column (``1.017,11``).
_GROUPED_DECIMALS = r"\d\.\d{3}(?:\.\d{3})*,"
#: A run of blanks between the fields of a table aligned by blanks, and blanks around a line.
_BLANK_RUN = re.compile(rb"[ \t]+")
_BLANKS_AROUND_A_LINE = re.compile(rb"(?m)^[ \t]+|[ \t]+(?=\r?$)")
#: A number without exponent; group 1 or 2 holds its decimals.
_PLAIN_NUMBER = {
    mark: re.compile(rf" *[+-]?(?:\d+(?:{re.escape(mark)}(\d*))?|{re.escape(mark)}(\d+)) *")
    for mark in ".,"
}


def column_label(index: int) -> str:
    """The name pyarrow gives field `index` of a body (the file's names are kept apart)."""
    return f"c{index}"


@dataclass(frozen=True)
class Region:
    """A byte range of a text file or buffer holding table rows.

    Attributes
    ----------
    source : Source
        The file or buffer.
    start, end : int
        Byte offsets of the first data line and of the end of the rows.
    first_line : int
        1-based line number of the line at `start`.
    codec : str
        Codec of the text.
    is_data : callable, optional
        Tells a data line from a line pyarrow does not see (blank lines by
        default; block headers for layouts that filter them out). Comment lines
        (:data:`~pipeline.ingest.sniff.COMMENT_MARK` first) are never rows.
    left_out : frozenset of int
        Line numbers of lines that are no rows whatever they hold (the blocks of
        other columns an MTS export interleaves, taken out before parsing).
    """

    source: Source
    start: int
    end: int
    first_line: int
    codec: str
    is_data: Callable[[str], bool] | None = None
    left_out: frozenset[int] = frozenset()

    @property
    def name(self) -> str:
        """The file's or buffer's name, for messages."""
        return self.source.name

    def lines(self) -> Iterator[tuple[int, str]]:
        """``(line number, text)`` of every data line, in order (Python speed: error path)."""
        keep = self.is_data or bool
        lines = text_lines(self.source, self.start, self.end, self.codec)
        for number, line in enumerate(lines, start=self.first_line):
            if keep(line) and number not in self.left_out:
                yield number, line

    def read(self, start: int, stop: int) -> bytes:
        """The source's bytes from `start` to `stop`."""
        return self.source.read(start, stop)

    def open(self) -> pa.NativeFile:
        """A pyarrow stream of the region's bytes (read in blocks, not copied whole)."""
        return self.source.stream(self.start, self.end)

    def line_of(self, row: int) -> int | None:
        """1-based line number of table row `row` (0-based), or None if past the end."""
        if self.is_data is None and not self.left_out and not self._has_skipped_lines:
            return self.first_line + row
        rows = (number for number, line in self.lines() if not line.startswith(COMMENT_MARK))
        for index, number in enumerate(rows):
            if index == row:
                return number
        return None

    @cached_property
    def _has_skipped_lines(self) -> bool:
        """Whether the region holds blank or comment lines (not rows to pyarrow)."""
        end = self.end
        while end > self.start:
            tail = self.read(max(self.start, end - TAIL_BYTES), end)
            kept = tail.rstrip(b"\r\n\x00")
            end -= len(tail) - len(kept)
            if kept:
                break
        patterns = tuple(pattern.encode(self.codec) for pattern in (
            "\n\n", "\r\n\r\n", "\r\r", "\n" + COMMENT_MARK, "\r" + COMMENT_MARK))
        return contains(self.source, patterns, self.start, end)


def _tail_lines(region: Region) -> tuple[int, str, list[str], bool]:
    """The region's last :data:`TAIL_BYTES` as text: where they start, the text, its lines
    (line ends dropped) and whether the first line may start mid-line."""
    single_byte = not region.codec.startswith("utf-16")
    start = max(region.start, region.end - TAIL_BYTES)
    if not single_byte:
        start += (start - region.start) % 2
    raw = region.read(start, region.end)
    text = raw.decode("latin-1" if single_byte else region.codec, errors="replace")
    return start, text, re.split(r"\r\n|\r|\n", text), start > region.start


def _byte_length(text: str, codec: str) -> int:
    return len(text) if not codec.startswith("utf-16") else len(text.encode(codec))


def trim_trailer(
    region: Region, width: int, delimiter: str, decimal: str
) -> tuple[Region, str | None]:
    """Cut text lines after the table off the region: a results block, an end-of-test line.

    The lines after the last data row (a row of `width` fields, mostly numbers)
    are a trailer if the first of them that is not blank holds no number at
    all (``Results``, ``Test ended``): they are left out, and a warning names
    them. Anything else after the last data row (a row with a bad cell or too
    few fields) is left to the parser, which reports it. Only the last
    :data:`TAIL_BYTES` of the region are searched.

    Returns
    -------
    region : Region
        The region without the trailer.
    warning : str or None
        What was left out, or None if there is no trailer.
    """
    start, text, lines, cut_first = _tail_lines(region)
    after = []  # (offset in text, line) of the lines after the last data row, last first
    offset = len(text)
    for position in range(len(lines) - 1, -1, -1):
        line = lines[position]
        offset -= len(line)
        fields = split_fields(line, delimiter)
        if row_kind(fields, line, decimal, delimiter == BLANKS) == "numeric" and len(
                fields) == width:
            break
        if position == 0 and cut_first:
            return region, None
        after.append((offset, line))
        offset -= _line_end_length(text, offset)
    else:
        return region, None
    shown = [line for _, line in reversed(after) if line.strip()]
    if not shown or not _is_text(shown[0], delimiter, decimal):
        return region, None
    cut = replace(region, end=start + _byte_length(text[: after[-1][0]], region.codec))
    return cut, (f"{len(shown)} line(s) after the last data row left out, from "
                 f"{shown[0].strip()[:40]!r}: not data rows")


def _is_text(line: str, delimiter: str, decimal: str) -> bool:
    """True if no field of `line` is a number (with either decimal mark) and one is text."""
    fields = split_fields(line, delimiter)
    return row_kind(fields, line, decimal, delimiter == BLANKS) == "text" and not any(
        is_number(field, mark) for field in fields for mark in ".,")


def _line_end_length(text: str, offset: int) -> int:
    """Length of the line end just before `offset` in `text` (0 at its start)."""
    if offset >= 2 and text[offset - 2: offset] == "\r\n":
        return 2
    return 1 if offset >= 1 and text[offset - 1] in "\r\n" else 0


def trim_truncated_tail(
    region: Region, width: int, delimiter: str, decimal: str
) -> tuple[Region, bool]:
    """Cut a truncated last line off the region.

    A last line without a line end is a half-written row if it has fewer
    fields than the data rows, if it stops right after a delimiter (last field
    empty where the row before has a value), or if its last number stops short
    of the decimals its column always has (``0,`` or ``0,0`` where the column
    writes ``0,000``). A short line that does end with a line end is left to
    the parser, which reports it.

    Parameters
    ----------
    region : Region
        The rows.
    width : int
        Fields per row.
    delimiter, decimal : str
        The field delimiter and the decimal mark.

    Returns
    -------
    region : Region
        The region without the truncated line.
    truncated : bool
        True if a line was cut off.
    """
    start, text, lines, cut_first = _tail_lines(region)
    body = text.rstrip("\r\n")
    if len(body) < len(text) or not lines[-1]:
        return region, False
    complete = lines[1 if cut_first else 0 : -1]  # the first may start mid-line
    rows = [split_fields(line, delimiter) for line in complete if line]
    if not _is_half_written(split_fields(lines[-1], delimiter), rows, width, decimal):
        return region, False
    kept = body[: len(body) - len(lines[-1])]
    end = start + _byte_length(kept, region.codec)
    return replace(region, end=end), True


def truncated_warning(line: int | None) -> str:
    """The warning of a half-written last row at `line`, dropped."""
    return f"line {line} is truncated (a half-written last row): dropped"


def _is_half_written(last: list[str], rows: list[list[str]], width: int, decimal: str) -> bool:
    """True if `last`, the fields of a last line without line end, is a cut row.

    `rows` are the fields of the data rows above it, in order.
    """
    if len(last) < width:
        return True
    before = rows[-1] if rows else []
    if not last[-1].strip():
        return len(before) == len(last) and bool(before[-1].strip())
    column = [row[-1] for row in rows if len(row) == len(last)]
    return _is_cut_number(last[-1], column, decimal)


def _is_cut_number(cell: str, column: list[str], decimal: str) -> bool:
    """True if `cell` looks like a number cut short, by comparison with the rest of its column.

    A plain number (no exponent) is cut if it has fewer decimals than every
    other value of `column`, and either ends with the decimal mark (``12,``
    where the column always has digits after its mark) or the column writes
    a fixed number of decimals (``0,0`` or ``0`` where it always has three).
    A column that writes as many decimals as needed (``99``, ``99,5``) leaves
    ``12,`` and ``12`` as they are.

    Parameters
    ----------
    cell : str
        The last field of a file without a final line end.
    column : list of str
        The other values of its column (missing values and texts are ignored).
    decimal : str
        The decimal mark.
    """
    digits = _decimals(cell, decimal)
    others = {_decimals(value, decimal) for value in column} - {None}
    if digits is None or not others or digits >= min(others):
        return False
    return cell.rstrip().endswith(decimal) or len(others) == 1


def _decimals(cell: str, decimal: str) -> int | None:
    """Digits after the decimal mark of a plain number (0 without mark), None if not one."""
    match = _PLAIN_NUMBER[decimal].fullmatch(cell)
    return None if match is None else len(match.group(1) or match.group(2) or "")


def parse_body(
    body: Region,
    region: Region,
    *,
    names: list[str],
    width: int,
    delimiter: str,
    decimal: str,
    float_columns: set[int],
    clocks: Mapping[int, ClockColumn] | None = None,
    as_text: bool = False,
) -> tuple[pa.Table, int]:
    """Parse the rows of `source` with pyarrow.

    Parameters
    ----------
    body : Region
        The body's bytes (data lines only, or data lines and blank lines).
    region : Region
        Where the rows sit in the file (for error messages).
    names : list of str
        The file's column names, for messages.
    width : int
        Fields per row.
    delimiter, decimal : str
        The dialect.
    float_columns : set of int
        Fields parsed as float64; the others are left to pyarrow's inference.
    clocks : mapping of int -> ClockColumn, optional
        Fields among `float_columns` written as clock readings, parsed as
        their :attr:`~pipeline.ingest.clock.ClockColumn.arrow_type` instead; the
        fields counting their fractions of a second are parsed as float64.
    as_text : bool
        Read every field as a string (a decimal comma that is also the delimiter;
        see :mod:`pipeline.ingest.delimited`).

    Returns
    -------
    table : pyarrow.Table
        Columns named by :func:`column_label`.
    comments : int
        Comment lines passed over (:class:`CommentLines`).

    Raises
    ------
    ValueParseError
        A cell of a float column is not a number, or a cell of a clock column not
        a clock reading (line and column named).
    LayoutError
        A row has the wrong number of fields, or pyarrow cannot read the body.
    """
    labels = [column_label(index) for index in range(width)]
    kind = pa.string() if as_text else pa.float64()
    clocks = {} if as_text or clocks is None else clocks
    dates = date_columns(clocks)
    read_options = pacsv.ReadOptions(
        column_names=labels,
        encoding=(region.codec if region.codec.startswith("utf-16") and delimiter != BLANKS
                  else "utf8"),
    )
    fractions = fraction_columns(clocks)
    convert_options = pacsv.ConvertOptions(
        column_types={
            labels[index]: clocks[index].arrow_type if index in clocks
            else pa.string() if index in dates else kind
            for index in (range(width) if as_text else float_columns | fractions | dates)
        },
        decimal_point=decimal,
        null_values=sorted(NULL_VALUES),
        strings_can_be_null=True,
    )
    skip_comments, thousands = False, None
    hours = [labels[index] for index, clock in clocks.items()
             if pa.types.is_time(clock.arrow_type)]
    try:
        while True:  # a retry passes over comment lines, reads thousands separators, or
            # reads a time of day as text (its hours may pass 24: a time elapsed)
            comments = CommentLines() if skip_comments else None
            try:
                table = _read(body, delimiter, decimal, read_options, convert_options,
                              comments, thousands)
                break
            except pa.ArrowInvalid as error:
                if not skip_comments and _comment_row(error):
                    skip_comments = True
                elif thousands is None and not as_text and _thousands_cell(error, decimal):
                    thousands = [labels[index] for index in float_columns - set(clocks)]
                elif hours:
                    convert_options.column_types = {**convert_options.column_types,
                                                    **dict.fromkeys(hours, pa.string())}
                    hours = []
                else:
                    raise
        for index, clock in clocks.items():  # readings not in pyarrow's form: read as text
            position = table.schema.get_field_index(labels[index])
            table = table.set_column(position, labels[index],
                                     clock.readings(table.column(position)))
        return table, 0 if comments is None else comments.count
    except (pa.ArrowException, UnicodeDecodeError) as error:
        raise locate_defect(
            region, names, width, delimiter, decimal, float_columns | fractions, error, clocks
        ) from error


class CommentLines:
    """pyarrow's handler of the rows whose field count is not the table's: a comment line
    (:func:`~pipeline.ingest.sniff.is_comment`) is passed over and counted, any other
    row is an error."""

    def __init__(self) -> None:
        self.count = 0
        self._lock = threading.Lock()  # pyarrow's parsing threads call it

    def __call__(self, row: pacsv.InvalidRow) -> str:
        if not row.text.startswith(COMMENT_MARK):
            return "error"
        with self._lock:
            self.count += 1
        return "skip"


def _read(body: Region, delimiter: str, decimal: str, read_options: pacsv.ReadOptions,
          convert_options: pacsv.ConvertOptions, comments: CommentLines | None,
          thousands: list[str] | None) -> pa.Table:
    """One pyarrow read of `body`, passing over comment lines if `comments` counts them,
    with the columns `thousands` read as numbers with thousands separators."""
    parse_options = pacsv.ParseOptions(delimiter="\t" if delimiter == BLANKS else delimiter,
                                       invalid_row_handler=comments)
    if thousands is not None:
        return _with_thousands(_stream(body, delimiter), read_options, parse_options,
                               convert_options, thousands, decimal)
    with _stream(body, delimiter) as source:
        return pacsv.read_csv(source, read_options=read_options, parse_options=parse_options,
                              convert_options=convert_options, memory_pool=POOL)


def _comment_row(error: Exception) -> bool:
    """Whether pyarrow stopped at a row of another field count that is a comment line (it
    quotes the row: ``Expected 3 columns, got 1: # missing reply``)."""
    found = _WRONG_WIDTH.search(str(error))
    return found is not None and found.group(1).startswith(COMMENT_MARK)


def comment_warning(region: Region, count: int,
                    first: tuple[int, int] | None = None) -> str:
    """What to say of the `count` comment lines passed over among the rows of `region`.

    `first` is where the first of them starts, as :func:`~pipeline.ingest.rowindex.
    first_comment` gives it (looked for when not given).
    """
    first = first or first_comment(region.source, region.start, region.end, region.codec)
    if first is None:
        return f"{count} comment line(s) among the data rows passed over"
    offset, line_ends = first
    text = region.read(offset, min(offset + _QUOTED_BYTES, region.end)).decode(
        region.codec, errors="replace")
    quoted = re.split(r"[\r\n]", text, maxsplit=1)[0].strip()[:60]
    return (f"{count} comment line(s) among the data rows passed over, the first at line "
            f"{region.first_line + line_ends}: {quoted!r}")


def _stream(body: Region, delimiter: str) -> pa.NativeFile:
    """The body's bytes for pyarrow; of a table aligned by blanks (:data:`BLANKS`), as UTF-8
    with each run of blanks one tab and none around a line (read whole: such tables are
    small)."""
    if delimiter != BLANKS:
        return body.open()
    data = body.read(body.start, body.end)
    if body.codec.startswith("utf-16"):
        data = data.decode(body.codec).encode()
    return pa.BufferReader(_BLANK_RUN.sub(b"\t", _BLANKS_AROUND_A_LINE.sub(b"", data)))


def _thousands_cell(error: Exception, decimal: str) -> bool:
    """Whether the cell pyarrow could not read is a number with thousands separators."""
    reported = _INVALID.search(str(error))
    return reported is not None and THOUSANDS[decimal].fullmatch(reported.group(2)) is not None


def _with_thousands(body: pa.NativeFile, read_options: pacsv.ReadOptions,
                    parse_options: pacsv.ParseOptions, convert_options: pacsv.ConvertOptions,
                    labels: list[str], decimal: str) -> pa.Table:
    """The `body` stream read again, the columns `labels` as text (`convert_options` changed so),
    their thousands separators (``"1,004.80328"``, Bluehill's quoted forces; ``1.056`` in a
    column of whole numbers of a file of decimal commas) removed, then as float64.

    Raises
    ------
    pyarrow.ArrowInvalid
        If a cell with a separator is not a number so grouped, another cell is no number, or
        (with decimal commas) a column with grouped cells holds decimals: ``1.784`` beside
        ``0,012`` is a decimal point among commas, not a thousand.
    """
    convert_options.column_types = (dict(convert_options.column_types)
                                    | dict.fromkeys(labels, pa.string()))
    with body as source:
        table = pacsv.read_csv(source, read_options=read_options, parse_options=parse_options,
                               convert_options=convert_options, memory_pool=POOL)
    for label in labels:
        position = table.schema.get_field_index(label)
        text = table.column(position)
        grouped = pc.match_substring_regex(
            text, "[" + "".join(re.escape(mark) for mark in _GROUPING[decimal]) + "]")
        if pc.any(pc.and_kleene(grouped, pc.invert(pc.match_substring_regex(
                text, f"^{THOUSANDS[decimal].pattern}$")))).as_py():
            raise pa.ArrowInvalid(f"column {label}: a separator in a number that is not a "
                                  "thousands separator")
        if decimal != "." and pc.any(pc.match_substring(text, ".")).as_py() and pc.any(
                pc.match_substring(text, decimal)).as_py() and not pc.any(
                pc.match_substring_regex(text, _GROUPED_DECIMALS)).as_py():
            raise pa.ArrowInvalid(f"column {label}: grouped whole numbers beside decimals")
        ungrouped = text
        for mark in _GROUPING[decimal]:
            ungrouped = pc.replace_substring(ungrouped, mark, "")
        if decimal != ".":
            ungrouped = pc.replace_substring(ungrouped, decimal, ".")
        numbers = pc.cast(ungrouped, pa.float64())
        table = table.set_column(position, label, numbers)
    return table


def locate_defect(
    region: Region,
    names: list[str],
    width: int,
    delimiter: str,
    decimal: str,
    float_columns: set[int],
    error: Exception,
    clocks: Mapping[int, ClockColumn] | None = None,
) -> LayoutError | ValueParseError:
    """Find the first line pyarrow could not read and describe it as a typed error."""
    clocks = clocks or {}
    reported = _INVALID.search(str(error))
    for number, line in region.lines():
        fields = split_fields(line, delimiter)
        if is_comment(line, delimiter, width):
            continue
        names_row = _names_row(fields, decimal)
        if names_row and (len(fields) != width or any(
                not is_number(fields[index], decimal) for index in float_columns)):
            return LayoutError(
                f"a second table starts here, its names {names_row}: the rows above it were "
                "read as the data",
                file=region.name, row=number,
                hint="keep one table per file: export each specimen's raw data alone, or "
                     "delete the other table's lines",
            )
        if len(fields) != width:
            return LayoutError(
                f"the row has {len(fields)} fields where the data rows have {width}",
                file=region.name, row=number,
                hint="a row is broken, or two tables were joined: fix or delete the line",
            )
        for index in sorted(float_columns):
            cell = fields[index]
            if index in clocks:
                if not (clocks[index].matches(cell) or is_missing(cell)):
                    return _bad_clock(region, names, number, index, cell, clocks[index])
            elif not (is_number(cell, decimal) or is_missing(cell)
                      or decimal == "." and THOUSANDS["."].fullmatch(cell.strip())):
                return _bad_cell(region, names, number, index, cell, decimal)
    if reported is not None:
        index = int(reported.group(1))
        return _bad_cell(region, names, None, index, reported.group(2), decimal)
    return LayoutError(
        f"the table cannot be read: {error}",
        file=region.name, row=region.first_line,
        hint="check the export; give columns and units in the run sheet if detection failed",
    )


#: A line with its end, in bytes of an ASCII-compatible codec.
_LINE = re.compile(rb"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+")
#: The share of a body's lines that may be event lines (:func:`without_events`).
EVENTS_SHARE = 0.1


def without_events(region: Region, delimiter: str, decimal: str
                   ) -> tuple[Region, Region, list[tuple[int, str]]] | None:
    """The rows of `region` without the lines a rig writes among its readings to log an
    event (``6724,Switched from 1 to 2,,,``): its first cell a number (the time) between
    those of the rows around it, one text beside it, the other cells empty. A line of text
    alone (``Second test``) is none: it may open another table.

    Returns
    -------
    body : Region
        The rows without the event lines (in memory), to parse.
    region : Region
        `region` with the event lines left out, for line numbers.
    events : list of (int, str)
        Line number and text of each event line.

    None when `region` holds no event line, or more than :data:`EVENTS_SHARE` of its lines
    (two at least) are (another layout), or its codec is not ASCII-compatible.
    """
    if region.codec.startswith("utf-16"):
        return None
    kept, firsts, events, starts = [], [], [], []  # firsts: the kept lines' first numbers
    previous = -math.inf
    lines = _LINE.findall(region.read(region.start, region.end))
    for number, line in enumerate(lines, start=region.first_line):
        text = line.decode(region.codec, errors="replace")
        fields = split_fields(text, delimiter)
        first = _number(fields[0], decimal)
        if _is_event(fields, decimal) and first >= previous:
            events.append((number, text.strip()))
            starts.append((first, len(kept)))
            continue
        kept.append(line)
        firsts.append(first)
        previous = previous if math.isnan(first) else first
    if not events or len(events) > max(2, EVENTS_SHARE * len(lines)) or any(
            at < len(firsts) and not first <= firsts[at] for first, at in starts):
        return None
    data = b"".join(kept)
    body = Region(BufferSource(data, region.name), 0, len(data), region.first_line,
                  region.codec)
    return body, replace(region, left_out=region.left_out | {n for n, _ in events}), events


def _number(cell: str, decimal: str) -> float:
    """The number of `cell`, NaN if it holds none."""
    return float(cell.strip().replace(decimal, ".")) if is_number(cell, decimal) else math.nan


def _is_event(fields: list[str], decimal: str) -> bool:
    """Whether `fields` are of an event line (:func:`without_events`): a number first, one
    text of a word after it, the other cells missing."""
    rest = [cell for cell in fields[1:] if not is_missing(cell)]
    return (is_number(fields[0], decimal) and len(rest) == 1
            and not is_number(rest[0], decimal) and _WORD.search(rest[0]) is not None)


#: Two letters: a word, not a unit's letter or a stray mark.
_WORD = re.compile(r"[^\W\d_]{2}")


def _names_row(fields: list[str], decimal: str) -> str:
    """The first names of a row that holds two texts or more and fewer numbers (a names
    row, not a data row with a bad cell), quoted; empty otherwise."""
    texts = [cell.strip() for cell in fields
             if not (is_number(cell, decimal) or is_missing(cell) or looks_like_clock(cell)
                     or is_out_of_range(cell))]
    numbers = sum(is_number(cell, decimal) for cell in fields)
    if len(texts) < 2 or numbers >= len(texts):
        return ""
    return ", ".join(repr(text if len(text) <= 30 else text[:29] + "…") for text in texts[:4]
                     ) + (", ..." if len(texts) > 4 else "")


def _bad_cell(
    region: Region, names: list[str], line: int | None, index: int, cell: str, decimal: str
) -> ValueParseError:
    other = "," if decimal == "." else "."
    hint = (
        f"the file's decimal mark is {decimal!r} but this cell uses {other!r}: "
        "re-export with one decimal mark"
        if is_number(cell, other)
        else "the number is grouped in thousands in a form not read here (a no-break space "
             "is read in a file saved as UTF-8 only): save the file as UTF-8, or its numbers "
             "without grouping" if THOUSANDS[decimal].fullmatch(cell.strip())
        else cell_hint(cell, "fix or delete the cell (missing values may be left empty or "
                             "written NaN)")
    )
    return ValueParseError(
        f"{cell.strip()[:40]!r} is not a number",
        file=region.name, row=line, column=display_name(names, index), hint=hint,
    )


def _bad_clock(
    region: Region, names: list[str], line: int, index: int, cell: str, clock: ClockColumn
) -> ValueParseError:
    return ValueParseError(
        clock.mismatch(cell), file=region.name, row=line, column=display_name(names, index),
        hint="fix or delete the cell (missing values may be left empty or written NaN)",
    )


def split_table(
    table: pa.Table, floats: set[int], width: int,
    clocks: Mapping[int, ClockColumn] | None = None,
) -> tuple[dict[int, pa.ChunkedArray], int, set[int]]:
    """The float columns of a parsed body, its row count and its other empty fields.

    Clock columns (`clocks`, among `floats`) become seconds after their first
    reading, with the fraction of a second of a column beside them added
    (:attr:`ClockColumn.fraction`) and the days of a date column before them
    (:attr:`ClockColumn.date`). The caller drops its reference to `table`
    next, so that :func:`float_arrays` can free each column as it converts it.
    """
    chunks = {index: table.column(column_label(index)) for index in floats}
    for index, clock in (clocks or {}).items():
        seconds = clock.seconds(chunks[index])
        if clock.fraction is not None:
            seconds = clock.with_fraction(seconds,
                                          table.column(column_label(clock.fraction.column)))
        if clock.date is not None:
            seconds = clock.with_date(seconds, table.column(column_label(clock.date.column)))
        chunks[index] = seconds
    return chunks, table.num_rows, empty_columns(table, set(range(width)) - floats)


def float_arrays(chunks: dict[int, pa.ChunkedArray]) -> dict[int, np.ndarray]:
    """Float columns as writable numpy arrays (NaN for missing), emptying `chunks`.

    Each pyarrow column is released as soon as it is converted (its memory, of
    :data:`POOL`, is then free for the next), so that the peak memory holds one
    column twice, not the whole table.
    """
    arrays = {}
    for index in sorted(chunks):
        array = chunks.pop(index).to_numpy()
        arrays[index] = array if array.flags.writeable else array.copy()
    return arrays


def empty_columns(table: pa.Table, columns: set[int]) -> set[int]:
    """Fields among `columns` holding no value at all."""
    return {
        index for index in columns
        if table.column(column_label(index)).null_count == table.num_rows
    }


def join_comma_pairs(table: pa.Table, region: Region, names: list[str]) -> pa.Table:
    """Rebuild values split by a decimal comma that is also the delimiter.

    ``0,5,1,25`` under the header ``time,force`` is read as four text fields
    and rejoined as 0.5 and 1.25. This is unambiguous only if every pair is an
    integer part and a digits-only fraction; otherwise the reader gives up.

    Parameters
    ----------
    table : pyarrow.Table
        The body read as text (:func:`parse_body` with ``as_text=True``), two
        fields per column.
    region : Region
        Where the rows sit in the file.
    names : list of str
        The file's column names.

    Returns
    -------
    pyarrow.Table
        One float64 column per name, labelled by :func:`column_label`.

    Raises
    ------
    LayoutError
        If a row cannot be paired unambiguously (line and column named).
    """
    joined = {}
    for index in range(table.num_columns // 2):
        whole = pc.utf8_trim_whitespace(table.column(column_label(2 * index)))
        fraction = pc.utf8_trim_whitespace(table.column(column_label(2 * index + 1)))
        fits = pc.fill_null(
            pc.and_(
                pc.match_substring_regex(whole, r"^[+-]?\d+$"),
                pc.match_substring_regex(fraction, r"^\d+$"),
            ),
            False,
        )
        if not pc.all(fits).as_py():
            row = pc.index(fits, False).as_py()
            raise LayoutError(
                "the decimal comma is also the delimiter and this value cannot be split "
                "unambiguously",
                file=region.name, row=region.line_of(row), column=names[index] or None,
                hint="export with ';' or tab as delimiter, or with quoted numbers",
            )
        joined[column_label(index)] = pc.cast(
            pc.binary_join_element_wise(whole, fraction, "."), pa.float64()
        )
    return pa.table(joined)
