"""The row index of long text logs against a line-by-line count in Python."""

from hypothesis import given, settings
from hypothesis import strategies as st

from pipeline.ingest import rowindex
from pipeline.ingest.rowindex import first_comment, index_rows
from pipeline.ingest.source import BufferSource

#: Pieces of text: cells (one with a letter that is two bytes in UTF-8), a comment mark, and
#: every line end.
PIECES = st.lists(st.sampled_from(["1,5", "ab", "ł", "x;y", "# c", "\n", "\r\n", "\r", "\n\n",
                                   "\r\n\r\n", "\r\r"]), min_size=1, max_size=60)
CODECS = ["utf-8", "cp1250", "utf-16-le", "utf-16-be"]


def expected(text: str) -> tuple[list[int], list[int], list[int]]:
    """Characters to each data row (a non-empty line not opened by ``#``), to each line
    end and to each comment line, one by one."""
    starts, ends, comments = [], [], []
    for position, char in enumerate(text):
        follows = text[position + 1 : position + 2]
        if char == "\n" or (char == "\r" and follows != "\n"):
            ends.append(position)
        if char not in "\r\n" and (position == 0 or text[position - 1] in "\r\n"):
            if char == "#":
                comments.append(position)
            else:
                starts.append(position)
    return starts, ends, comments


@settings(max_examples=300, deadline=None)
@given(pieces=PIECES, codec=st.sampled_from(CODECS), every=st.integers(1, 5),
       block=st.sampled_from([2, 4, 6, 64]))
def test_rows_lines_and_offsets(pieces, codec, every, block):
    text = "".join(pieces).lstrip("\r\n#") or "x"  # the first line is a data row
    content = b"##" + text.encode(codec)  # rows start after a 2-byte head
    source = BufferSource(content, "t")
    starts, ends, comments = expected(text)
    offset = [2 + len(text[:start].encode(codec)) for start in starts]
    index = index_rows(source, 2, len(content), codec, every=every, block=block)
    assert (index.rows, index.lines, index.comments) == (len(starts), len(ends),
                                                         len(comments))
    first = comments and (2 + len(text[:comments[0]].encode(codec)),
                          sum(end < comments[0] for end in ends))
    assert index.first_comment == (first or None)
    assert first_comment(source, 2, len(content), codec, block=block) == (first or None)
    assert index.offsets.tolist() == offset[::every]
    assert index.line_ends.tolist() == [sum(end < start for end in ends)
                                        for start in starts[::every]]
    for row in range(len(starts)):
        assert index.locate(source, row) == (offset[row],
                                             sum(end < starts[row] for end in ends))
    assert index.locate(source, len(starts)) == (len(content), len(ends))


def test_locate_crosses_blocks(monkeypatch):
    monkeypatch.setattr(rowindex, "BLOCK", 4)
    content = "".join(f"{row},{row * row}\r\n" for row in range(200)).encode()
    source = BufferSource(content, "t")
    index = index_rows(source, 0, len(content), "utf-8", every=64, block=16)
    for row in (0, 1, 63, 64, 65, 130, 199):
        offset, lines = index.locate(source, row)
        assert (content.count(b"\n", 0, offset), lines) == (row, row)
        assert content[offset:].startswith(f"{row},".encode())


def test_an_index_is_small():
    content = b"1.5,2.5\n" * 300_000
    index = index_rows(BufferSource(content, "t"), 0, len(content), "utf-8")
    assert index.rows == 300_000 and index.offsets.size == index.line_ends.size == 5
    assert index.offsets.tolist() == [8 * row for row in range(0, 300_000, 65_536)]
