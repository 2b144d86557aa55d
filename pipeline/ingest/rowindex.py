"""Byte offsets of the data rows of a long text log, to read any range of its rows.

One pass at open (:func:`index_rows`) records the byte offset and line of
every :data:`EVERY`-th data row; the offset of any other row is found by
scanning forward from the indexed row before it (:meth:`RowIndex.locate`),
at most EVERY rows. A 10^8-row log's index holds some 1,500 rows (24 KB).

Both scan blocks of bytes with numpy, never a Python loop over rows, with
the line rules pyarrow's CSV parser follows:

* a line ends at LF, or at CR not followed by LF (LF, CRLF and CR files);
* a data row starts at the first byte after a line end that is not itself
  CR or LF: blank lines are not rows; nor are comment lines, which start with
  :data:`~pipeline.ingest.sniff.COMMENT_MARK` (the body parser passes over
  them);
* UTF-16 text is scanned in 2-byte code units (little- or big-endian), every
  other codec the readers know in bytes (its CR and LF are never part of
  another character).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

import numpy as np

from pipeline.ingest.sniff import COMMENT_MARK
from pipeline.ingest.source import BLOCK, Source

#: Data rows between two indexed rows.
EVERY = 65_536

_LF, _CR, _COMMENT = 10, 13, ord(COMMENT_MARK)
_UNITS = {"utf-16-le": "<u2", "utf-16-be": ">u2"}


def code_unit(codec: str) -> np.dtype:
    """The numpy type of one code unit of text in `codec`."""
    return np.dtype(_UNITS.get(codec, "u1"))


@dataclass(frozen=True, eq=False)
class RowIndex:
    """Where every :attr:`every`-th data row of a text region starts.

    Attributes
    ----------
    start, end : int
        Byte offsets of the first data row and of the end of the rows.
    rows : int
        Data rows between them.
    lines : int
        Line ends between them.
    comments : int
        Comment lines between them.
    first_comment : tuple of int, or None
        Byte offset of the first comment line and the line ends before it
        (:func:`first_comment`).
    every : int
        Rows from one indexed row to the next.
    offsets : numpy.ndarray
        Byte offset of rows 0, `every`, 2 `every`... (int64).
    line_ends : numpy.ndarray
        Line ends between `start` and each of those rows (int64).
    unit : numpy.dtype
        A code unit of the text (:func:`code_unit`).
    """

    start: int
    end: int
    rows: int
    lines: int
    comments: int
    first_comment: tuple[int, int] | None
    every: int
    offsets: np.ndarray
    line_ends: np.ndarray
    unit: np.dtype

    def locate(self, source: Source, row: int) -> tuple[int, int]:
        """The byte offset where data row `row` starts and the line ends before it.

        Parameters
        ----------
        source : Source
            The file or buffer the index was built on.
        row : int
            0-based data row, ``0 <= row <= rows`` (`rows` gives the end).

        Returns
        -------
        offset : int
            Byte offset of the row in `source`.
        line_ends : int
            Line ends between :attr:`start` and the row.
        """
        if row == self.rows:
            return self.end, self.lines
        indexed = row // self.every
        offset, lines = int(self.offsets[indexed]), int(self.line_ends[indexed])
        skip = row - indexed * self.every
        if skip == 0:
            return offset, lines
        blocks = _scan(source, offset, self.end, self.unit, BLOCK)
        begin, starts, ends, _ = next(blocks)
        while skip > starts.size:
            skip -= starts.size
            lines += ends.size
            begin, starts, ends, _ = next(blocks)
        found = int(starts[skip - 1])
        return begin + found * self.unit.itemsize, lines + int(np.searchsorted(ends, found))


def index_rows(
    source: Source, start: int, end: int, codec: str, every: int = EVERY, block: int = BLOCK
) -> RowIndex:
    """Count the data rows between two offsets and index every `every`-th.

    Parameters
    ----------
    source : Source
        The file or buffer.
    start, end : int
        Byte offsets of the first data row and of the end of the rows.
    codec : str
        The text's codec.
    every : int
        Rows from one indexed row to the next.
    block : int
        Bytes scanned at a time [bytes].

    Returns
    -------
    RowIndex
    """
    unit = code_unit(codec)
    offsets, line_ends = [np.array([start])], [np.array([0])]
    rows, lines, comments, first = int(start < end), 0, 0, None
    for begin, starts, ends, passed in _scan(source, start, end, unit, block):
        picked = starts[(-rows) % every :: every]
        offsets.append(begin + picked * unit.itemsize)
        line_ends.append(lines + np.searchsorted(ends, picked))
        if first is None and passed.size:
            first = _located(begin, int(passed[0]), ends, lines, unit)
        rows += starts.size
        lines += ends.size
        comments += passed.size
    return RowIndex(start, end, rows, lines, comments, first, every,
                    np.concatenate(offsets).astype(np.int64),
                    np.concatenate(line_ends).astype(np.int64), unit)


def first_comment(
    source: Source, start: int, end: int, codec: str, block: int = BLOCK
) -> tuple[int, int] | None:
    """Where the first comment line between two offsets starts, scanning no further.

    The parameters are those of :func:`index_rows`.

    Returns
    -------
    tuple of int, or None
        The comment line's byte offset and the line ends between `start` and
        it; None when no line there is a comment.
    """
    unit, lines = code_unit(codec), 0
    for begin, _, ends, passed in _scan(source, start, end, unit, block):
        if passed.size:
            return _located(begin, int(passed[0]), ends, lines, unit)
        lines += ends.size
    return None


def _located(begin: int, position: int, ends: np.ndarray, lines: int, unit: np.dtype
             ) -> tuple[int, int]:
    """Byte offset and line ends before a line `position` code units into a block at `begin`,
    `lines` line ends before the block, `ends` those in it."""
    return begin + position * unit.itemsize, lines + int(np.searchsorted(ends, position))


def _scan(
    source: Source, start: int, end: int, unit: np.dtype, block: int
) -> Iterator[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
    """Data-row starts and line ends, block by block, from `start` (a row start) to `end`.

    Yields
    ------
    begin : int
        Byte offset of the block.
    starts : numpy.ndarray
        Code units from `begin` to each data row that a line end in the block
        starts (the row may start at the block's end), in order.
    ends : numpy.ndarray
        Code units from `begin` to each line end in the block, in order.
    comments : numpy.ndarray
        Code units from `begin` to each comment line a line end in the block
        starts (not among `starts`), in order.
    """
    size = unit.itemsize
    block -= block % size
    begin = start
    while begin < end:
        stop = min(begin + block, end)
        last = end - stop < size
        window = source.read(begin, stop if last else stop + size)  # a unit of the next block
        count = (stop - begin) // size
        units = np.frombuffer(window, unit, count=len(window) // size)
        if last:
            units = np.append(units[:count], units.dtype.type(0))  # no line end after the rows
        line_feed = units == _LF
        carriage = units == _CR
        breaks = line_feed | carriage
        starts = np.flatnonzero(breaks[:-1] > breaks[1:]) + 1
        if last:
            starts = starts[starts < count]
        comment = units[starts] == _COMMENT
        ends = np.flatnonzero(line_feed[:-1] | (carriage[:-1] > line_feed[1:]))
        yield begin, starts[~comment], ends, starts[comment]
        begin = stop
