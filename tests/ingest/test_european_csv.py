"""European CSV: ';' or tab delimiter, decimal comma, cp1250 / latin-1 / BOM."""

import numpy as np
import pytest

from pipeline.errors import LayoutError, ValueParseError
from pipeline.ingest import read_table
from pipeline.units import STANDARD_GRAVITY

POLISH = (
    "czas [s];siła [kN];wydłużenie 1 [mm];wydłużenie 2 [mm]\r\n"
    "0,0;0,892;0,010;0,011\r\n"
    "0,5;1,784;0,020;0,021\r\n"
)


@pytest.mark.parametrize("encoding", ["cp1250", "utf-8", "utf-8-sig", "utf-16"])
def test_polish_export(write, encoding):
    table, meta = read_table(write("p.csv", POLISH, encoding))
    assert (meta.layout, meta.delimiter, meta.decimal) == ("european_csv", ";", ",")
    np.testing.assert_allclose(table["force"], [892.0, 1784.0])
    np.testing.assert_allclose(table["gauge_2"], [1.1e-5, 2.1e-5])
    assert meta.columns[1].name == "siła"


def test_a_russian_export_in_cp1251_is_read_by_its_names_and_units(write):
    # Russian Windows writes cp1251: read as latin-1, 'Нагрузка' and 'кН' were 'Íàãðóçêà'
    # and 'êÍ', no role and no unit, and the units row was taken for the names row
    text = ("Время\tНагрузка\tПеремещение\r\nс\tкН\tмм\r\n"
            "0,0\t0,892\t0,010\r\n0,5\t1,784\t0,020\r\n")
    table, meta = read_table(write("r.txt", text, "cp1251"))
    assert meta.encoding == "cp1251"
    assert [column.name for column in meta.columns] == ["Время", "Нагрузка", "Перемещение"]
    np.testing.assert_allclose(table["force"], [892.0, 1784.0])
    np.testing.assert_allclose(table["gauge_1"], [1e-5, 2e-5])


def test_german_export_latin1_with_quotes(write):
    text = ('"Zeit [s]";"Standardkraft [kgf]";"Weg [mm]"\n'
            '"0,0";"100,0";"0,5"\n"1,0";"200,0";"1,5"\n')
    table, meta = read_table(write("g.csv", text, "latin-1"))
    np.testing.assert_allclose(table["force"], [100 * STANDARD_GRAVITY, 200 * STANDARD_GRAVITY])
    assert meta.encoding == "utf-8"


def test_tab_decimal_comma(write):
    table, meta = read_table(write("t.txt", POLISH.replace(";", "\t")))
    assert meta.delimiter == "\t" and meta.layout == "european_csv"
    assert table.shape == (2, 4)


def test_quoted_decimal_comma_with_comma_delimiter(write):
    text = 'time [s],force [kN],gauge [mm]\n"0,5","1,25","0,01"\n"1,5","2,25","0,02"\n'
    table, meta = read_table(write("q.csv", text))
    assert (meta.delimiter, meta.decimal) == (",", ",")
    np.testing.assert_allclose(table["force"], [1250.0, 2250.0])


def test_unquoted_decimal_comma_with_comma_delimiter_is_rejoined(write):
    text = "time [s],force [kN],gauge [mm]\n0,5,1,25,0,01\n1,5,-2,25,0,02\n"
    table, meta = read_table(write("c.csv", text))
    np.testing.assert_allclose(table["time"], [0.5, 1.5])
    np.testing.assert_allclose(table["force"], [1250.0, -2250.0])
    np.testing.assert_allclose(table["gauge_1"], [1e-5, 2e-5])
    assert meta.decimal == "," and "rejoined" in meta.warnings[0]


def test_a_sample_number_beside_a_reading_is_no_decimal_comma_pair(write):
    # a real dynamometer's log under a key=value line (LineScale's "Unit=N"): the number
    # and the load were joined as 0.1000, 1.1007, 2.1014
    text = "Unit=N\n0,1000\n1,1007\n2,1014\n3,1021\n"
    with pytest.raises(LayoutError, match="no names row above the first data row"):
        read_table(write("log.csv", text))
    # a time in whole seconds with a decimal comma is still rejoined
    table, _ = read_table(write("c.csv", "time [s],force [kN]\n0,0,1,5\n1,0,1,6\n2,0,1,7\n"),
                          kind="engagement")
    np.testing.assert_allclose(table["time"], [0.0, 1.0, 2.0])
    np.testing.assert_allclose(table["force"], [1500.0, 1600.0, 1700.0])


@pytest.mark.parametrize("data", [
    "10,0\n9,3\n8,12\n6,20\n5,31\n",  # distances and forces in whole numbers
    "0.05,12.4\n0.10,13.1\n0.15,14.0\n",  # decimal points: the comma only splits
])
def test_a_section_mark_over_two_columns_makes_no_decimal_comma_pairs(write, data):
    # a real force-curve (FCV) file: a section mark, one field, over distance,force rows;
    # 10,0 and 9,3 were joined as forces of 10.0 and 9.3
    text = "Distance Units: mm\nForce    Units: gf\n\n[Recorded Forward]\n" + data
    with pytest.raises(LayoutError, match="no names row above the first data row"):
        read_table(write("example.fcv", text))


def test_unsplittable_pairs(write):
    text = "time [s],force [kN],gauge [mm]\n0,5,1,25,0,01\n1,5,2,-25,0,02\n"
    with pytest.raises(LayoutError, match="cannot be split") as caught:
        read_table(write("c.csv", text))
    assert (caught.value.row, caught.value.column) == (3, "force")


def test_mixed_decimal_mark(write):
    with pytest.raises(ValueParseError, match="'1.784'") as caught:
        read_table(write("m.csv", POLISH.replace("1,784", "1.784")))
    assert (caught.value.row, caught.value.column) == (3, "siła")
    assert "decimal mark" in caught.value.hint


FIXED = "czas [s];siła [kN];wydłużenie [mm]\n0,00;0,012;0,000\n0,10;0,020;0,010\n"


@pytest.mark.parametrize(
    "tail",
    ["0,20;0,030;0,", "0,20;0,030;0,0", "0,20;0,030;0", "0,20;0,030;", "0,20;0,030", "0,2"],
)
def test_truncated_last_line_is_dropped(write, tail):
    table, meta = read_table(write("t.csv", FIXED + tail))
    np.testing.assert_allclose(table["force"], [12.0, 20.0])
    np.testing.assert_allclose(table["gauge_1"], [0.0, 1e-5])
    assert meta.warnings == ["line 4 is truncated (a half-written last row): dropped"]


@pytest.mark.parametrize(
    ("text", "last"),
    [
        (FIXED + "0,20;0,030;0,020", 2e-5),  # complete, no line end
        (FIXED + "0,20;0,030;2,5e-3", 2.5e-6),
        (FIXED.replace("0,010", "1") + "0,20;0,030;2,", 2e-3),  # the column also has integers
        (FIXED.replace("0,010", "0,01") + "0,20;0,030;2", 2e-3),  # as many decimals as needed
    ],
)
def test_complete_last_line_without_line_end_is_kept(write, text, last):
    table, meta = read_table(write("t.csv", text))
    assert len(table) == 3 and meta.warnings == []
    assert table["gauge_1"].iloc[-1] == pytest.approx(last)


def excel_german(rows: int) -> str:
    """A rig's log re-saved by a spreadsheet in a German locale: decimal commas, and times
    from 1,000 ms on written with a point between the thousands (``1.056``)."""
    lines = ["Time (ms);Force (N);Flow (ml/s);Counts"]
    swap = str.maketrans(",.", ".,")
    lines += [f"{91 * row:,};{-3.5 - 0.001 * row:.5f};{0.01 * row:.5f};{row - 122_443:,}"
              .translate(swap) for row in range(rows)]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("reader", ["read_table", "open_log"])
def test_thousands_separated_by_points_in_a_file_of_decimal_commas(write, reader):
    from pipeline.ingest import open_log

    path = write("loadcell.csv", excel_german(60))
    table = (read_table(path, kind="engagement")[0] if reader == "read_table"
             else open_log(path, kind="engagement").read(0, 60)[0])
    assert path.read_text().splitlines()[12].split(";")[0] == "1.001"  # row 11: 1,001 ms
    np.testing.assert_allclose(table["time"], 0.091 * np.arange(60), rtol=1e-12)
    np.testing.assert_allclose(table["force"], -3.5 - 0.001 * np.arange(60), rtol=1e-12)


@pytest.mark.parametrize("cell", ["1.05", "1.0045"])
def test_a_point_that_is_no_thousands_separator_is_still_refused(write, cell):
    text = excel_german(60).replace("\n1.001;", f"\n{cell};")
    with pytest.raises(ValueParseError, match=f"'{cell}' is not a number"):
        read_table(write("loadcell.csv", text), kind="engagement")
