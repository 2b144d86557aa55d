"""MTS TestWare cyclic-acquisition export: repeating blocks of header lines and points.

Example (Spanish, latin-1, tab-separated, decimal comma, CRLF)::

    MTS***|MPT|**|*|*|*|*|*|*|*|*|*

    Adquisición cíclica      Tiempo  20,061279  Sec  13/12/2021 10:22:42
    Parado en:  100  cycle   Parado para:  1  cycles   Relativo a:  1  cycle
    Puntos:  51
    Tiempo  Channel 1 Displacement  Channel 1 Force  Channel 1 Recuento
    Sec     mm                      kgf              cycles
    10,016357  -0,095496617  -4,1995568  99
    ... 51 points, a blank line, then the next block's header lines ...

File defects handled
--------------------
* block header lines repeated before every block: removed in one regular
  expression pass over the bytes, the points of all blocks parsed by pyarrow
  as one table (line numbers in messages still refer to the file);
* a later block of other columns than the first (MTS 793 interleaves the
  acquisition of the test's peaks, two rows of other channels, with the
  timed samples; a last block may add or reorder channels): left out, with a
  warning naming its lines, columns and rows; so is a block of two rows in the
  first block's columns that are each column's largest and smallest value (the
  peaks again);
* Spanish or English names (``Tiempo``, ``Fuerza``, ``Desplazamiento``,
  ``Recuento``, ``Count``) and a separate units row (``Sec``, ``mm``, ``kgf``);
* the counter in ``cycles`` (half cycles as ``99,5``) or ``segments`` (two per
  cycle): kept as counted in ``cycle_count`` with its unit;
* the time gap between blocks (reported as time gaps, see
  :mod:`pipeline.ingest.canonical`);
* a later block whose time starts again (at or before the first block's first
  time): several tests one after another, as a logger writes that appends
  each test to one file with its names row, or a press's software each
  specimen of a series (Form+Test: a line of the specimen's results, the
  names row and the units row over each table): the specimens one below the
  other, of which the run sheet's ``specimen_in_file`` names the one read (its
  place from 1 at the top); without it the file is refused, listing them,
  rather than read as one test whose time steps back. A units row repeated
  over a later block, and a line of another width just above a repeated names
  row (a specimen's results), are that block's header;
* no line end after the last point; a truncated last point (dropped, warned).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from itertools import islice
from typing import NamedTuple

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import raw_table, text_header
from pipeline.ingest.names import says_part
from pipeline.ingest.preamble import parse_preamble
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, split_fields
from pipeline.ingest.source import BufferSource
from pipeline.ingest.specimens import choose
from pipeline.ingest.textbody import (
    Region,
    parse_body,
    split_table,
    trim_truncated_tail,
    truncated_warning,
)

LAYOUT = "mts"

# A data line starts with a number (perhaps quoted, as Shimadzu Trapezium quotes every
# field), a missing-value token or an empty first field (not a rule of dashes under a
# title: a BAM export's ``-----``, which opens the next export).
_DATA_START = (r"[ \t]*(?:\"?[-+]?\.?\d|[-+.] *(?=[\t;,|\r\n]|$)"
               r"|(?i:nan|n/a|na|null) *(?=[\t;,|\r\n]|$)|(?=[\t;,|\r\n]|$))")
_HEADER_LINE = re.compile(rb"(?m)^(?!" + _DATA_START.encode() + rb")[^\r\n]*(?:\r\n|\r|\n|\Z)")
_DATA_LINE = re.compile(_DATA_START)
#: Put before a line that reads as data but belongs to a block's header.
HEADER_MARK = b"#"
#: A line that is not blank.
_ROW = re.compile(rb"[^\r\n]*[^\s][^\r\n]*")


def _is_data(line: str) -> bool:
    """True for a line pyarrow reads as a row (not a block header, not empty)."""
    return bool(line) and _DATA_LINE.match(line) is not None


def matches(head: Head, spec: TableSpec) -> bool:
    """True for an ``MTS`` first line, or a names row (perhaps with another specimen's
    number in front: :func:`_unlabelled`) or a line that opens a block (MTS TestStar:
    ``Axial Counts<TAB>0`` above the names) repeated below the first block."""
    if spec.header_index is None:
        return False
    later = head.lines[spec.data_index:]
    openers = _block_openers(head, spec)
    names = _unlabelled(head.lines[spec.header_index], spec.delimiter)
    return (head.lines[0].lstrip().startswith("MTS")
            or any(names in line and _unlabelled(line, spec.delimiter) == names
                   for line in later)
            or any(_opens(line, openers, spec.delimiter) for line in later))


#: A field that starts as a number does.
_NUMBER_START = re.compile(r"\s*[-+]?\.?\d")
#: A specimen's number as a names row's first field (Bluehill's sample export: ``1,Time,
#: Displacement,...`` over the first specimen's rows, ``2,Time,...`` over the second's).
_LABEL = re.compile(r"[ \t]*\d+[ \t]*")


def _unlabelled(line: str, delimiter: str) -> str:
    """`line` stripped, without the specimen's number in its first field
    (:data:`_LABEL`) when the fields after it hold no number: the names the blocks of a
    sample's specimens share."""
    fields = split_fields(line.strip(), delimiter)
    if len(fields) > 2 and _LABEL.fullmatch(fields[0]) and not any(
            _NUMBER_START.match(field) for field in fields[1:]):
        return line.strip().lstrip("0123456789 \t")
    return line.strip()


def _block_openers(head: Head, spec: TableSpec) -> set[str]:
    """The lines above the names row with a letter in them, stripped, and their first fields:
    a line below the data that is one of them, or begins with one, numbers or nothing after,
    opens a block."""
    lines = [line.strip() for line in head.lines[:spec.header_index]
             if any(char.isalpha() for char in line)]
    firsts = (_first_field(line, spec.delimiter) for line in lines)
    return {*lines, *(first for first in firsts if any(char.isalpha() for char in first))}


def _first_field(line: str, delimiter: str) -> str:
    """The first field of `line`, stripped."""
    return (split_fields(line.strip(), delimiter) or [""])[0].strip()


def _opens(line: str, openers: set[str], delimiter: str) -> bool:
    """Whether `line` opens a block: it is one of `openers` (:func:`_block_openers`), or
    begins with one, the numbers of a counter or nothing after (TestStar's ``Axial
    Counts<TAB>0``, with a second count further right in some exports)."""
    fields = split_fields(line.strip(), delimiter) or [""]
    return line.strip() in openers or (fields[0].strip() in openers and all(
        not field.strip() or field.strip().isdecimal() for field in fields[1:]))


def read(head: Head, spec: TableSpec, columns: Mapping | None = None,
         specimen: str | int | None = None) -> RawTable:
    """Read an MTS cyclic-acquisition export sniffed as `head` / `spec`; of several tests
    one below the other, the one `specimen` (the run sheet's ``specimen_in_file``) names.

    Raises
    ------
    SpecimensError
        When the file holds several tests and `specimen` does not say which.
    """
    header = text_header(head, spec, LAYOUT, parse_preamble(spec.preamble, spec.delimiter), columns)
    start = head.offsets[spec.data_index]
    data = head.source.read(start, head.size)
    if not head.ascii_compatible:
        data = data.decode(head.codec, errors="replace").encode("utf-8")
    first_line = spec.data_index + 1
    marked = _marked_headers(head, spec, data, first_line)
    data = marked.data
    # the time, if one column may be it: of several, one not named as a part's (TestStar's
    # Scan Time starts again in each block of a test, its Elapsed Time goes on)
    times = header.candidates.roles.get("time", [])
    times = [time for time in times if not says_part(header.names[time])] or times
    blocks = _later_blocks(head, spec, data, times[0] if len(times) == 1 else None)
    tests = [block for block in blocks if block.restarts and not block.other]
    part = range(start, head.size)
    if tests:
        data, blocks, part, first_line = _one_test(head, marked, blocks, tests, start,
                                                   first_line, specimen, header.metadata,
                                                   timed=len(times) == 1)
    same = [block for block in blocks if not block.other]
    header.metadata.preamble["blocks"] = str(1 + sum(block.opens for block in same))
    header.metadata.warnings += [block.note for block in blocks if block.other]
    if any(block.other for block in blocks):
        ends = [block.start for block in blocks] + [len(data)]
        data = b"".join([data[: ends[0]]] + [data[block.start : end] for block, end
                                             in zip(blocks, ends[1:], strict=True)
                                             if not block.other])
    points = BufferSource(_HEADER_LINE.sub(b"", data), head.name)
    del data
    kept, truncated = trim_truncated_tail(Region(points, 0, points.size, 1, "utf-8"),
                                          spec.width, spec.delimiter, spec.decimal)
    region = Region(head.source, part.start, part.stop, first_line, head.codec, _is_data,
                    frozenset(line for block in blocks if block.other for line in block.lines)
                    | marked.lines)
    table, _ = parse_body(  # comment lines are not data lines: filtered out above
        kept,
        region,
        names=header.names,
        width=spec.width,
        delimiter=spec.delimiter,
        decimal=spec.decimal,
        float_columns=header.candidates.indexes(),
        clocks=header.clocks,
    )
    parsed = split_table(table, header.candidates.indexes(), spec.width, header.clocks)
    del table
    if truncated:
        header.metadata.warnings.append(truncated_warning(region.line_of(parsed[1])))
    if tests:
        header.metadata.first_data_line = region.line_of(0)
    return raw_table(parsed, region, header)


class _Marked(NamedTuple):
    """The data with header marks (:func:`_marked_headers`), and where they stand."""

    data: bytes
    cuts: list[int]  #: offsets in the unmarked data of the lines marked, in order
    lines: frozenset[int]  #: their line numbers in the file

    def unmarked(self, offset: int) -> int:
        """The offset in the unmarked data of `offset` in the marked."""
        return offset - len(HEADER_MARK) * sum(
            cut + index * len(HEADER_MARK) < offset for index, cut in enumerate(self.cuts))


def _marked_headers(head: Head, spec: TableSpec, data: bytes, first_line: int) -> _Marked:
    """`data` (the file from its first data row, on line `first_line`) with the lines that
    belong to a later block's header though they read as data marked as header lines
    (:data:`HEADER_MARK` before them): the units row repeated when its first field is
    empty (``;;;s;kN;mm``), and a line of another width than the table's just above a
    repeated names row (a press's results of the next specimen); and a names row with the
    next specimen's number in front (:func:`_unlabelled`), which reads as data too."""
    names = head.lines[spec.header_index].strip()
    unlabelled = _unlabelled(names, spec.delimiter)
    units = (head.lines[spec.units_index].strip()
             if spec.units_index is not None else "")
    codec = head.codec if head.ascii_compatible else "utf-8"  # the data's, as read
    cuts = set()
    label = rb"\d+[ \t]*" if unlabelled != names else b""
    for found in re.finditer(rb"(?m)^[ \t]*" + label + re.escape(unlabelled.encode(codec))
                             + rb"[ \t]*\r?$", data):
        if label:
            cuts.add(found.start())
        line_start, line = _line_before(data, found.start())
        if line and _DATA_LINE.match(line) and len(split_fields(line, spec.delimiter)) != (
                spec.width):
            cuts.add(line_start)
    if units.strip(" \t;,|") and _DATA_LINE.match(units):
        cuts.update(found.start() for found in re.finditer(
            rb"(?m)^[ \t]*" + re.escape(units.encode(codec)) + rb"[ \t]*\r?$", data))
    ordered = sorted(cuts)
    bounds = [0, *ordered, len(data)]
    marked = b"".join(data[a:b] if index == 0 else HEADER_MARK + data[a:b]
                      for index, (a, b) in enumerate(zip(bounds[:-1], bounds[1:], strict=True)))
    lines, line = [], first_line
    for previous, cut in zip(bounds[:-2], ordered, strict=True):
        line += data.count(b"\n", previous, cut)
        lines.append(line)
    return _Marked(marked, ordered, frozenset(lines))


def _line_before(data: bytes, offset: int) -> tuple[int, str]:
    """The offset and text of the last line of `data` before `offset` that is not blank
    (``(0, "")`` if none)."""
    end = offset
    while end > 0:
        start = data.rfind(b"\n", 0, end - 1) + 1
        text = data[start:end].strip()
        if text:
            return start, text.decode("utf-8", errors="replace")
        end = start
    return 0, ""


def _one_test(head: Head, marked: _Marked, blocks: list[_Block], tests: list[_Block],
              start: int, first_line: int, specimen: str | int | None,
              metadata, timed: bool) -> tuple[bytes, list[_Block], range, int]:
    """Of tests one below the other (`tests`: the later blocks whose time starts again, or
    that repeat the names without a time to tell, when not `timed`), the one `specimen`
    names: its part of the marked data (the file from offset `start` on, whose first line
    `first_line` is the first data row), its later blocks there, and where that part lies
    in the file (offsets, first line number)."""
    lines = [test.lines.start for test in tests]
    at = f"line{'s' if len(lines) > 1 else ''} {', '.join(map(str, lines))}"
    said = (f"the file holds {len(tests) + 1} tests (specimens, or a test's steps) one below "
            f"the other, each timed from its own start: the time starts again in the "
            f"block{'s' if len(lines) > 1 else ''} from {at}"
            if timed else
            f"the file holds {len(tests) + 1} tables one below the other, each under its "
            f"own names (at {at}), and without one time column to tell one test's blocks from "
            "several tests (a fibre tester's specimens)")
    if not head.ascii_compatible:  # its offsets in the file are not those of the data
        raise LayoutError(said, file=head.name, row=lines[0],
                          hint="save the file as UTF-8, or export each test to a file of "
                               "its own")
    chosen = choose([], len(tests) + 1, specimen, said, "from the top", file=head.name,
                    row=lines[0])
    metadata.specimen = str(chosen + 1)
    if chosen:  # the settings above its own block are its own (the top's, the first test's)
        after = tests[chosen - 2].start if chosen > 1 else -1
        own = [line for block in blocks if after < block.start <= tests[chosen - 1].start
               for line in block.settings]
        metadata.preamble.update(parse_preamble(own, metadata.delimiter))
    low = tests[chosen - 1].start if chosen else 0
    high = tests[chosen].start if chosen < len(tests) else len(marked.data)
    kept = [block._replace(start=block.start - low) for block in blocks
            if low < block.start < high]
    return (marked.data[low:high], kept,
            range(start + marked.unmarked(low), start + marked.unmarked(high)),
            lines[chosen - 1] if chosen else first_line)


class _Block(NamedTuple):
    """A block after the first: its header lines, then its points."""

    start: int  #: offset of its first header line in the data
    lines: range  #: its lines in the file
    opens: bool  #: whether its header repeats the first block's names or opening line
    other: bool  #: whether it holds other columns than the first block
    note: str  #: the warning that it is left out, when it is
    restarts: bool = False  #: whether its time starts again (a test of its own)
    #: its header's settings, as ``key: value`` lines (a tribometer's step: ``Data Count =
    #: 107``, ``Started at: 12:22:00.384``), those of its own test
    settings: tuple[str, ...] = ()


def _later_blocks(head: Head, spec: TableSpec, data: bytes, time: int | None) -> list[_Block]:
    """The blocks after the first in `data` (the file from the first block's points on):
    each a run of header lines and the points up to the next. `time` is the column of
    the time, if one column may be it."""
    codec = head.codec if head.ascii_compatible else "utf-8"
    groups: list[list[int]] = []  # [start, end) of each run of header lines
    for match in _HEADER_LINE.finditer(data):
        if groups and groups[-1][1] == match.start():
            groups[-1][1] = match.end()
        else:
            groups.append([match.start(), match.end()])
    ends = [start for start, _ in groups[1:]] + [len(data)] if groups else []
    first = _FirstBlock(head.lines[spec.header_index].strip(),
                        head.lines[spec.units_index].strip() if spec.units_index is not None
                        else None, _block_openers(head, spec), time,
                        _number(split_fields(head.lines[spec.data_index], spec.delimiter),
                                time, spec))
    view = memoryview(data)  # the blocks' points read in place, not copied
    blocks, line, counted = [], spec.data_index + 1, 0  # the file's line at offset `counted`
    for (start, header_end), end in zip(groups, ends, strict=True):
        line += data.count(b"\n", counted, start)
        last = line + data.count(b"\n", start, max(end - 1, start))
        blocks.append(_block(spec, first, data[start:header_end].decode(codec, errors="replace"),
                             view[header_end:end], start, range(line, last + 1)))
        counted = start
    return blocks


class _FirstBlock(NamedTuple):
    """What the later blocks are compared with: the first block's names and units rows,
    and the lines that open a block (:func:`_block_openers`)."""

    names: str
    units: str | None
    openers: set[str]
    time: int | None  #: the time's column, if one column may be it
    start_time: float | None  #: its first reading


def _block(spec: TableSpec, first: _FirstBlock, header_text: str, points: memoryview,
           start: int, lines: range) -> _Block:
    """The block at offset `start` of the data, on file `lines`: its header lines
    `header_text`, then its `points`."""
    openers = first.openers
    header = [line.strip().removeprefix(HEADER_MARK.decode()).strip()  # marked: as written
              for line in header_text.splitlines()]
    widths = {line: len(split_fields(line, spec.delimiter)) for line in header}
    rows = [row.group().decode("latin-1") for row in islice(_ROW.finditer(points), 3)]
    fields = split_fields(rows[0], spec.delimiter) if rows else []
    width = len(fields) if rows else spec.width
    names = _unlabelled(first.names, spec.delimiter)
    renamed = [line for line in header if widths[line] == spec.width
               and not _opens(line, openers, spec.delimiter)
               and _unlabelled(line, spec.delimiter) != names and line != first.units]
    opens = any(_unlabelled(line, spec.delimiter) == names
                or _opens(line, openers, spec.delimiter) for line in header)
    where = f"lines {lines.start} to {lines.stop - 1}"
    if renamed or width != spec.width:
        names = next((line for line in header if widths[line] == width
                      and not _opens(line, openers, spec.delimiter)),
                     header[-1] if header else "")
        return _Block(start, lines, opens, True, (
            f"{where}: a block of other columns than the first "
            f"({', '.join(split_fields(names, spec.delimiter))}: "
            f"{sum(1 for _ in _ROW.finditer(points))} row(s), another "
            "acquisition of the test, such as its peaks) is left out; the samples are the "
            "points of the blocks of the first block's columns"))
    if _peaks(rows, spec):
        return _Block(start, lines, opens, True, (
            f"{where}: a block of two rows, each column's largest value then its smallest, "
            "is the test's peaks, not samples: left out"))
    time = _number(fields, first.time, spec)
    restarts = (time is not None and first.start_time is not None
                and time <= first.start_time) or (first.time is None and opens and bool(rows))
    settings = tuple(line for line in header if line and line != first.units
                     and _unlabelled(line, spec.delimiter) != names)
    return _Block(start, lines, opens, False, "", restarts, settings)


def _number(fields: list[str], column: int | None, spec: TableSpec) -> float | None:
    """The number in `fields[column]` of a data row, or None (no column, not a number)."""
    if column is None or column >= len(fields):
        return None
    try:
        return float(fields[column].strip().replace(spec.decimal, "."))
    except ValueError:
        return None


def _peaks(rows: list[str], spec: TableSpec) -> bool:
    """Whether a block's `rows` are the peaks MTS 793 acquires: two rows, the first at
    least the second in every column (time included: it steps back)."""
    if len(rows) != 2:
        return False
    high, low = ([_number(fields, column, spec) for column in range(len(fields))]
                 for fields in (split_fields(row, spec.delimiter) for row in rows))
    return (len(high) == len(low) and None not in high + low
            and all(a >= b for a, b in zip(high, low, strict=True)))
