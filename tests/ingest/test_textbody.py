"""Body parsing helpers: line numbers, truncated tails, comma pairs."""

import pyarrow as pa
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest.source import BufferSource
from pipeline.ingest.textbody import Region, join_comma_pairs, parse_body, trim_truncated_tail


def region_of(path, codec="utf-8", first_line=2, start=None):
    start = len("h,h\n".encode(codec)) if start is None else start
    source = BufferSource(path.read_bytes(), str(path))
    return Region(source, start, source.size, first_line, codec)


def test_line_of_contiguous_and_with_blank_lines(write):
    region = region_of(write("a.csv", "h,h\n1,2\n3,4\n5,6\n"))
    assert [region.line_of(row) for row in range(4)] == [2, 3, 4, 5]
    region = region_of(write("b.csv", "h,h\n1,2\n\n3,4\r\n\r\n5,6\n"))
    assert [region.line_of(row) for row in range(3)] == [2, 4, 6]
    assert region.line_of(3) is None


def test_line_of_utf16(write):
    path = write("c.csv", "h,h\n1,2\n\n3,4\n", "utf-16-le")
    assert region_of(path, "utf-16-le").line_of(1) == 4


@pytest.mark.parametrize(
    ("tail", "cut"),
    [("7,8", False), ("7,", True), ("7,8\n", False), ("7,\n", False), ("7", True)],
)
def test_trim_truncated_tail(write, tail, cut):
    path = write("t.csv", "h,h\n1,2\n3,4\n" + tail)
    region = region_of(path)
    trimmed, truncated = trim_truncated_tail(region, 2, ",", ".")
    assert truncated is cut
    assert trimmed.end == (path.stat().st_size - len(tail) if cut else region.end)


@pytest.mark.parametrize(
    ("rows", "tail", "cut"),
    [
        ("1.5,2.25\n3.5,4.25\n", "7.5,8.25", False),  # complete, no line end
        ("1.5,2.25\n3.5,4.25\n", "7.5,8.2", True),  # fixed decimals, one missing
        ("1.5,2.25\n3.5,4.25\n", "7.5,8.", True),
        ("1.5,2.25\n3.5,4.25\n", "7.5,8", True),
        ("1.5,2.25\n3.5,4.25\n", "7.5,8.25e-3", False),  # an exponent is not compared
        ("1.5,2.5\n3.5,4.25\n", "7.5,8.", True),  # the column always has decimals
        ("1.5,2.5\n3.5,4.25\n", "7.5,8", False),  # as many decimals as needed: 8.0 as 8
        ("1.5,2\n3.5,4.5\n", "7.5,8.", False),  # the column also has integers
    ],
)
def test_trim_number_cut_short(write, rows, tail, cut):
    path = write("t.csv", "h,h\n" + rows + tail)
    region = region_of(path)
    assert trim_truncated_tail(region, 2, ",", ".")[1] is cut


def test_trailing_empty_column_without_line_end_is_kept(write):
    path = write("t.csv", "h,h,h\n1,2,\n3,4,")
    region = region_of(path, start=len("h,h,h\n"))
    assert trim_truncated_tail(region, 3, ",", ".")[1] is False


def test_join_comma_pairs(write):
    path = write("p.csv", "h,h\n1,5,-2,25\n3,0,4,75\n")
    region = region_of(path)
    table, comments = parse_body(region, region, names=["a", "b"], width=4, delimiter=",",
                                 decimal=".", float_columns=set(), as_text=True)
    assert comments == 0
    joined = join_comma_pairs(table, region, ["a", "b"])
    assert joined.to_pydict() == {"c0": [1.5, 3.0], "c1": [-2.25, 4.75]}
    bad = pa.table({f"c{i}": pa.array(values) for i, values in
                    enumerate([["1", "3"], ["5", "x"], ["2", "4"], ["25", "75"]])})
    with pytest.raises(LayoutError) as caught:
        join_comma_pairs(bad, region, ["a", "b"])
    assert (caught.value.row, caught.value.column) == (3, "a")
