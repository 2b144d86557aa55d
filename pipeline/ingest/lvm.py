"""LabVIEW measurement files (``.lvm``), as the Write To Measurement File express VI writes them.

Example (tab-separated; the header lines are ``tag<TAB>value``)::

    LabVIEW Measurement
    Writer_Version   2
    Separator        Tab
    Decimal_Separator    .
    X_Columns        One
    ***End_of_Header***

    Channels         2
    Y_Unit_Label     N           mm
    X_Dimension      Time        Time
    X0               0.0E+0      0.0E+0
    Delta_X          0.010000    0.010000
    ***End_of_Header***
    X_Value          Force       Extension   Comment
    0.000000         1.234       0.001

The file header says the delimiter (``Separator``: ``Tab`` or ``Comma``), the
decimal mark (``Decimal_Separator``, ``.`` when absent) and the X column
(``X_Columns``); the segment header gives each channel's unit
(``Y_Unit_Label``) and the X axis (``X_Dimension``, ``X0``, ``Delta_X``).

File defects handled
--------------------
* ``X_Columns One``: the first column holds the X values; an X axis of
  ``Time`` is the time in seconds;
* ``X_Columns No``: the first field of every row is empty, and the time is
  ``X0 + Delta_X * i`` of the first channel (``Delta_X * i`` when ``X0`` is a clock
  reading, :data:`ABSOLUTE_X0`, with a note);
* the ``Comment`` column of the names row: rows that carry a comment have a
  field more than the others; the comments are left out, with a warning
  quoting the first;
* a decimal comma (``Decimal_Separator ,``), either separator;
* fewer rows than the segment header's ``Samples``: a warning, the file may be
  cut short (more rows are no defect: under one header, each write of the VI
  adds ``Samples`` rows);
* everything the delimited readers handle in the rows themselves
  (:mod:`pipeline.ingest.delimited`): missing values, a truncated last line,
  text after the last row.

A file with its X column and no row comment is delimited text below its
headers (:data:`TEXT`): a long log is then read by row range, as a CSV log is
(:mod:`pipeline.ingest.stream`). Whether a row has a comment is settled with
numpy over blocks of bytes (a row with more delimiters than the channels
need); only then are the rows searched for the comments themselves.

``X_Columns Multi`` (an X column per channel) is read when every channel's X
axis is alike (one ``X0``, ``Delta_X`` and number of ``Samples``): the first
X column is the time, the others are named ``X_Value 2``, ``X_Value 3``...
and take no role. Refused, with a hint: ``X_Columns Multi`` of unlike X axes, and a
file of several segments (a header again after the rows).
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import numpy as np

from pipeline.errors import EmptyFileError, LayoutError
from pipeline.ingest.delimited import TextLayout, read_contiguous
from pipeline.ingest.names import match_role
from pipeline.ingest.raw import RawTable
from pipeline.ingest.rowindex import code_unit
from pipeline.ingest.sniff import Head, TableSpec, read_head, split_fields
from pipeline.ingest.source import BLOCK, BufferSource, contains

LAYOUT = "lvm"

#: The first line of every LabVIEW measurement file.
MAGIC = "LabVIEW Measurement"
#: The line that ends the file header and each segment header.
END_OF_HEADER = "***End_of_Header***"
#: The last name of the names row: a column for the rows' comments, not a channel.
COMMENT = "Comment"
#: Delimiters by the name the ``Separator`` tag gives them.
SEPARATORS = {"tab": "\t", "comma": ","}
#: The name given to the X column when the X axis is time (``X_Dimension Time``).
TIME_NAME = "Time"
#: An ``X0`` of this many seconds or more is a clock reading (``Time_Pref Absolute``:
#: seconds since 1904, some 3.6e9), no start of a test's time: added to the samples' times,
#: it would round a 25.6 kHz step of 39.0625 µs to 39.1006 µs.
ABSOLUTE_X0 = 1e6


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """True for a file whose first line is ``LabVIEW Measurement``."""
    return bool(head.lines) and head.lines[0].lstrip("\ufeff").startswith(MAGIC)


#: The rows below the headers as delimited text, the headers as its preamble.
TEXT = TextLayout(LAYOUT, matches=matches, preamble=True)


def _tags(lines: list[str], delimiter: str) -> dict[str, list[str]]:
    """``tag -> values`` of header lines (the first occurrence of each tag)."""
    tags: dict[str, list[str]] = {}
    for line in lines:
        fields = [field.strip() for field in split_fields(line, delimiter)]
        if fields and fields[0]:
            tags.setdefault(fields[0], [field for field in fields[1:] if field])
    return tags


def _headers(head: Head) -> list[int]:
    """Indexes of the head's ``***End_of_Header***`` lines."""
    return [index for index, line in enumerate(head.lines)
            if line.strip().split("\t")[0].split(",")[0].strip() == END_OF_HEADER]


def _delimiter(head: Head, first_end: int) -> str:
    """The file header's ``Separator`` (tab when it says none)."""
    for line in head.lines[:first_end]:
        for delimiter in ("\t", ","):
            fields = [field.strip() for field in line.split(delimiter)]
            if len(fields) > 1 and fields[0] == "Separator":
                # an empty value after a tab: the tab itself was written as the value
                separator = fields[1].lower() or ("tab" if delimiter == "\t" else "")
                if separator not in SEPARATORS:
                    raise LayoutError(
                        f"separator {fields[1]!r} is not read", file=head.name,
                        hint="write the file with the Tab or Comma separator")
                return SEPARATORS[separator]
    return "\t"


def table_spec(head: Head) -> TableSpec:
    """Where the table of a LabVIEW measurement file sits, and its dialect and units.

    Raises
    ------
    LayoutError
        If the headers are incomplete, the file has an X column per channel,
        or it holds several segments.
    """
    ends = _headers(head)
    if len(ends) == 1 and not any(line.strip(" \t,;") for line in head.lines[ends[0] + 1:]):
        raise EmptyFileError(
            "the file holds its file header only: no segment, no samples", file=head.name,
            row=ends[0] + 1, hint="LabVIEW wrote no measurements: record the test again")
    if len(ends) < 2 or ends[1] + 2 > len(head.lines):
        raise LayoutError(
            "the file header or the segment header does not end (no second "
            f"{END_OF_HEADER} line followed by the names row)", file=head.name,
            hint="the file may be cut short: copy it again from the rig")
    delimiter = _delimiter(head, ends[0])
    file_tags = _tags(head.lines[: ends[0]], delimiter)
    segment = _tags(head.lines[ends[0] + 1: ends[1]], delimiter)
    names_index = ends[1] + 1
    names = [field.strip() for field in split_fields(head.lines[names_index], delimiter)]
    x_columns = (file_tags.get("X_Columns") or ["One"])[0]
    if x_columns.lower() == "multi" and names.count("X_Value") > 1:
        if not _one_x_axis(segment):
            row = next((index + 1 for index, line in enumerate(head.lines[: ends[0]])
                        if line.strip().startswith("X_Columns")), None)
            raise LayoutError(
                "X_Columns Multi (an X column for every channel), the channels' X axes not "
                "alike, is not read", file=head.name, row=row,
                hint="write the file with one X column (X_Columns One) or none")
        numbers = iter(range(2, len(names) + 1))
        names = [f"X_Value {next(numbers)}" if name == "X_Value" and index > 0 else name
                 for index, name in enumerate(names)]
    data_index = names_index + 1
    data_lines = [line for line in head.lines[data_index:] if line.strip()]
    if not data_lines:
        raise LayoutError("no data rows after the segment header", file=head.name,
                          row=data_index + 1, hint="the acquisition wrote no samples")
    if len(ends) > 2 or contains(head.source, (END_OF_HEADER.encode(head.codec),),
                                 head.offsets[data_index], head.size):
        raise LayoutError(
            "the file holds several segments, each with its own header", file=head.name,
            row=(ends[2] + 1) if len(ends) > 2 else None,
            hint="write one header only (Segment Headers: One header only), or split the file")
    width = len(split_fields(data_lines[0], delimiter))
    while len(names) > 1 and names[-1] == "" and names[-2] in ("", COMMENT):
        names.pop()  # LabVIEW pads the names row with empty fields after the comment's
    if names[-1] == COMMENT:  # the data's width: rows with a comment have one field more
        names.pop()
        width = min(width, len(names))
    while len(names) > width and names[-1] == "":
        names.pop()
    names += [""] * (width - len(names))
    time_axis = (segment.get("X_Dimension") or [""])[0].lower() == "time"
    if time_axis and names[0] == "X_Value":
        names[0] = TIME_NAME
    labels = iter(segment.get("Y_Unit_Label", []))  # the channels', not the X columns'
    units = [("s" if time_axis else None), *(
        None if name.startswith("X_Value") else next(labels, None) for name in names[1:])]
    return TableSpec(
        delimiter=delimiter,
        decimal=(file_tags.get("Decimal_Separator") or ["."])[0],
        names=names,
        header_index=names_index,
        units_index=None,
        data_index=data_index,
        width=width,
        units=[unit or None for unit in units],
        preamble=[line for line in head.lines[:names_index]
                  if line.strip() and line.strip() != END_OF_HEADER],
    )


def read(head: Head, spec: TableSpec, columns: Mapping | None = None) -> RawTable:
    """Read a LabVIEW measurement file sniffed as `head` / `spec` (see the module docstring)."""
    header = TEXT.header(head, spec, columns)
    head, said = _without_comments(head, spec)
    header.metadata.warnings.extend(said)
    raw = read_contiguous(head, spec, header)
    tags = _tags(spec.preamble, spec.delimiter)
    stated = {value.strip() for value in tags.get("Samples", []) if value.strip()}
    if len(stated) == 1 and (count := stated.pop()).isdigit() and int(count) > raw.rows:
        header.metadata.warnings.append(  # more rows are many writes under one header
            f"the header says Samples = {count}, the file holds {raw.rows} rows: it may be cut "
            "short (copy it again from the machine)")
    if _without_x_column(spec) and 0 in raw.arrays:
        start, step = _axis(tags, spec.decimal, head.name)
        steps = list(dict.fromkeys(value.strip() for value in tags["Delta_X"] if value.strip()))
        timed = [name for name in header.names[1:] if match_role(name) == "time"]
        if len(steps) > 1 and timed:
            header.metadata.warnings.append(
                f"no time is built from the channels' Delta_X: they differ ({', '.join(steps)}), "
                f"and channel {timed[0]!r} holds a time")
            return raw
        if abs(start) >= ABSOLUTE_X0:  # counted from it: its digits would eat the step's
            header.metadata.warnings.append(
                f"X0 = {start:.10g} s is a clock reading (LabVIEW counts from 1904): the time "
                "is counted from it")
            start = 0.0
        raw.arrays[0] = start + step * np.arange(raw.rows)
        if len(steps) > 1:
            header.metadata.warnings.append(
                f"the time is built from the first channel's Delta_X ({steps[0]}), but the "
                f"channels' differ ({', '.join(steps)}): they were not sampled at one rate "
                "(name the time column in the run sheet if a channel holds the time)")
    return raw


def _one_x_axis(segment: Mapping[str, list[str]]) -> bool:
    """Whether every channel of a segment has the same X axis: one ``X0``, one ``Delta_X``,
    one number of ``Samples`` (an X column for every channel then repeats the first)."""
    return all(len({value.strip() for value in segment.get(tag, []) if value.strip()}) == 1
               for tag in ("X0", "Delta_X", "Samples"))


def by_rows(head: Head, spec: TableSpec) -> bool:
    """Whether the rows read by range as :data:`TEXT` are the rows :func:`read` reads: the
    file has its X column (the time is not built from ``X0`` and ``Delta_X``) and no row
    has a comment."""
    return not (_without_x_column(spec) or _field_more(head, spec))


def _without_x_column(spec: TableSpec) -> bool:
    """``X_Columns No``: the time is built from the segment header."""
    return (_tags(spec.preamble, spec.delimiter).get("X_Columns") or [""])[0].lower() == "no"


def _field_more(head: Head, spec: TableSpec) -> bool:
    """Whether a data row has more delimiters than the channels need (a comment's field).

    Counted with numpy over blocks of :data:`~pipeline.ingest.source.BLOCK` bytes: the
    delimiters before each line end (CR or LF), the count of the line a block ends in
    carried to the next.
    """
    unit = code_unit(head.codec)
    delimiter, most = ord(spec.delimiter), spec.width - 1
    position, end = head.offsets[spec.data_index], head.size
    carry = 0  # delimiters of the line the last block ended in
    while position < end:
        stop = min(position + BLOCK, end)
        units = np.frombuffer(head.source.read(position, stop), unit)
        position = stop
        delimiters = np.flatnonzero(units == delimiter)
        ends = np.flatnonzero((units == 10) | (units == 13))
        if ends.size:
            before = np.searchsorted(delimiters, ends)
            lines = np.diff(before, prepend=0)
            lines[0] += carry
            if lines.max() > most:
                return True
            carry = delimiters.size - int(before[-1])
        else:
            carry += delimiters.size
        if carry > most:
            return True
    return False


def _without_comments(head: Head, spec: TableSpec) -> tuple[Head, list[str]]:
    """The file with the comments of its rows cut off, and a warning quoting them.

    LabVIEW writes a comment as one more field at the end of the rows it was
    given for (often the first); the others end with the last channel. The rows
    are searched in memory only when a row has that field more
    (:func:`_field_more`), and a copy without the comments is made.
    """
    if not _field_more(head, spec):
        return head, []
    body = head.source.read(head.offsets[spec.data_index], head.size)
    delimiter = re.escape(spec.delimiter.encode(head.codec))
    fields = rb"[^\r\n%s]*" % delimiter
    row = re.compile(rb"^(%s(?:%s%s){%d})%s([^\r\n]*)(?=\r?$)" % (
        fields, delimiter, fields, spec.width - 1, delimiter), re.MULTILINE)
    if row.search(body) is None:
        return head, []
    comments = [(match.start(), match[2]) for match in row.finditer(body) if match[2].strip()]
    cleaned = head.source.read(0, head.offsets[spec.data_index]) + row.sub(rb"\1", body)
    start, text = comments[0] if comments else (0, b"")
    line = spec.data_index + 1 + body.count(b"\n", 0, start)
    said = ([f"{len(comments)} row comment(s) left out of the data, the first "
             f"{text.decode(head.codec, errors='replace').strip()[:40]!r} on line {line}"]
            if comments else [])
    return read_head(BufferSource(cleaned, head.name)), said


def _axis(tags: dict[str, list[str]], decimal: str, file: str) -> tuple[float, float]:
    """``X0`` and ``Delta_X`` of the first channel."""
    try:
        return tuple(float(tags[tag][0].replace(decimal, ".")) for tag in ("X0", "Delta_X"))
    except (KeyError, ValueError, IndexError) as error:
        raise LayoutError(
            "X_Columns No, but the segment header gives no X0 and Delta_X to build the time from",
            file=file, hint="write the file with its X column (X_Columns One)") from error
