"""parse_table: every reader on bytes in memory gives what read_table gives on the file."""

from dataclasses import asdict
from pathlib import Path

import pandas as pd
import pytest

from pipeline.errors import EmptyFileError, IngestError, LayoutError
from pipeline.ingest import parse_table, read_table

BAD = Path(__file__).parents[1] / "data" / "bad"
#: Real exports and the options they need (see tests/ingest/test_realdata.py).
REALDATA_OPTIONS = {"EPFL-ENAC__CCFatiguePlatform__TST_2021-10_FA_22.csv":
                    {"units": {"force": "kN", "gauges": "mm"}}}


def outcome(read, *args, **options):
    """``(table, metadata as a dict without its file)`` of a read, or its error's fields."""
    try:
        table, meta = read(*args, **options)
    except IngestError as error:
        return type(error), error.file, (error.message, error.row, error.column, error.hint)
    return table, meta.file, {**asdict(meta), "file": None}


def assert_buffer_reads_as_file(path, **options):
    """parse_table of the file's bytes equals read_table of the file, but for the name."""
    name = f"upload of {path.name}"
    from_buffer = outcome(parse_table, path.read_bytes(), name=name, **options)
    from_file = outcome(read_table, path, **options)
    assert from_buffer[1] == name and from_file[1] == str(path)
    if isinstance(from_file[0], pd.DataFrame):
        pd.testing.assert_frame_equal(from_buffer[0], from_file[0], check_exact=True,
                                      obj=path.name)
    else:
        assert from_buffer[0] is from_file[0], path.name
    assert from_buffer[2] == from_file[2], path.name


def test_every_layout(corpus):
    for path, options in corpus.items():
        assert_buffer_reads_as_file(path, **options)


def test_broken_files():
    for path in sorted(BAD.iterdir()):
        assert_buffer_reads_as_file(path)


@pytest.mark.realdata
def test_real_exports(realdata):
    for path in sorted(realdata.glob("*.*")):
        if path.suffix != ".md":
            assert_buffer_reads_as_file(path, **REALDATA_OPTIONS.get(path.name, {}))


def test_errors_name_the_buffer():
    with pytest.raises(EmptyFileError) as caught:
        parse_table(b"")
    assert caught.value.file == "<buffer>"
    with pytest.raises(LayoutError, match="no names row") as caught:
        parse_table(b"1,2\n3,4\n", name="upload.csv")
    assert (caught.value.file, caught.value.row) == ("upload.csv", 1)
    assert str(caught.value).startswith("upload.csv, line 1: ")


@pytest.mark.parametrize("text, example", [
    (b"1,139302\t305,800815\t1,883096\n1,149302\t-16,572605\t0,317137\n",
     "'time [s]<Tab>force [kN]<Tab>gauge1 [mm]'"),
    (b"1,5;2,5\n3,5;4,5\n", "'time [s];force [kN];gauge1 [mm]'"),
    # aligned by blanks: names that hold a blank need two between them
    (b"  1.5   2.5\n  3.5   4.5\n", "'time [s]  force [kN]  gauge1 [mm]'"),
])
def test_the_header_row_suggested_is_separated_as_the_data_are(text, example):
    # a real headerless tab file with decimal commas: a comma-separated header
    # would have split into more fields than its rows
    with pytest.raises(LayoutError, match="no names row") as caught:
        parse_table(text, name="data.lvm")
    assert f"e.g. {example}, or name them in the run sheet by position" in caught.value.hint


def test_columns_of_text_in_every_row_are_passed_over():
    # a real fatigue-database export: more text columns than numbers in every row
    text = (b'"Cycle Label","Data State","Elapsed Time Sec","Qual State","Strain","Stress Mpa",'
            b'"Count","Sample","Alloy","Material_Form","Heat"\n' + b"".join(
                b'"Cycle %d","CapPass",%.2f,"Qualified",0.00002,6.47,%d,"43-13","Alloy 617",'
                b'"Plate",314626\n' % (1 + row // 2, row * 0.02, row + 1) for row in range(4)))
    table, meta = parse_table(text, name="cycles.csv", kind="wear",
                              columns={"length": "Strain"}, units={"length": "mm"})
    assert table["time"].tolist() == pytest.approx([0.0, 0.02, 0.04, 0.06])
    assert table["length"].tolist() == pytest.approx([2e-8] * 4)
    assert {info.name: info.role for info in meta.columns}["Data State"] is None


def test_columns_of_text_that_vary_by_row_are_named_as_the_reason():
    # the text stands in other columns from row to row: no columns of text to pass over
    text = b"a,b,c,d\n" + b"".join(b"1,x,y,2\n" if row % 2 else b"x,1,2,y\n"
                                   for row in range(4))
    with pytest.raises(LayoutError, match=r"every row holds text beside its numbers ") as caught:
        parse_table(text, name="mixed.csv")
    assert "columns of text" in caught.value.hint


def test_the_name_suffix_counts_as_a_file_suffix():
    # a .xls name on text is text (machines write tab-separated exports so)
    table, meta = parse_table(b"time [s]\tforce [kN]\n0\t1\n0.1\t2\n", name="old.xls",
                              kind="engagement")
    assert meta.layout == "plain_csv" and table["force"].tolist() == [1000.0, 2000.0]
    with pytest.raises(LayoutError, match="TDMS") as caught:
        parse_table(b"time [s],force [kN]\n0,1\n", name="log.tdms")
    assert caught.value.file == "log.tdms"
    _, meta = parse_table(b"time [s],force [kN],gauge [mm]\n0,1,2\n", name="log.dat")
    assert meta.layout == "plain_csv"


def test_options_are_checked():
    with pytest.raises(ValueError, match="format"):
        parse_table(b"t,f\n1,2\n", format="json")
    with pytest.raises(ValueError, match="kind"):
        parse_table(b"t,f\n1,2\n", kind="fatigue")


def test_bytes_like_buffers(corpus):
    path = next(path for path in corpus if path.name == "european.csv")
    whole, _ = read_table(path, kind="engagement")
    content = path.read_bytes()
    for buffer in (bytearray(content), memoryview(content)):
        table, _ = parse_table(buffer, kind="engagement")
        pd.testing.assert_frame_equal(table, whole, check_exact=True)
