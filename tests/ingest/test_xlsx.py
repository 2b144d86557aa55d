"""Workbooks (`.xlsx`, `.ods` and `.xls`): first or named sheet, table anywhere on the sheet."""

import numpy as np
import openpyxl
import pandas as pd
import pytest

from pipeline.errors import EmptyFileError, LayoutError, ValueParseError
from pipeline.ingest import read_table


@pytest.fixture
def workbook(tmp_path):
    """Write sheets (name -> rows, placed from the cell given) to a workbook; return its path."""

    def _workbook(sheets: dict, origin=(1, 1), name="w.xlsx"):
        book = openpyxl.Workbook()
        book.remove(book.active)
        for title, rows in sheets.items():
            sheet = book.create_sheet(title)
            for r, row in enumerate(rows):
                for c, value in enumerate(row):
                    if value is not None:
                        sheet.cell(origin[0] + r, origin[1] + c, value)
        path = tmp_path / name
        book.save(path)
        return path

    return _workbook


ROWS = [["time [s]", "force [kN]", "gauge [mm]"], [0.0, 1.5, 0.1], [0.1, 2.5, 0.2]]


def test_first_sheet(workbook):
    table, meta = read_table(workbook({"Data": ROWS, "Other": [["x"]]}))
    assert (meta.layout, meta.sheet, meta.header_line, meta.first_data_line) == (
        "xlsx", "Data", 1, 2)
    np.testing.assert_allclose(table["force"], [1500.0, 2500.0])


def test_named_sheet_offset_table_with_preamble_and_units_row(workbook):
    rows = [["Specimen", "18-A"], [], ["Zeit", "Kraft", "Weg"], ["s", "kN", "mm"],
            [0.0, "1,5", 0.1], [None, None, None], [0.1, 2.5, 0.2]]
    table, meta = read_table(workbook({"Cover": [["x"]], "Run 1": rows}, origin=(3, 2)),
                             sheet="Run 1")
    np.testing.assert_allclose(table["force"], [1500.0, 2500.0])
    assert meta.preamble == {"Specimen": "18-A"} and meta.first_data_line == 7
    assert meta.columns[0].unit == "s"


def test_empty_sheet(workbook):
    with pytest.raises(EmptyFileError, match="sheet 'Empty' is empty"):
        read_table(workbook({"Empty": []}))


def test_missing_sheet_lists_sheets(workbook):
    with pytest.raises(LayoutError, match="no sheet 'Run 2'") as caught:
        read_table(workbook({"Run 1": ROWS}), sheet="Run 2")
    assert "'Run 1'" in caught.value.hint


def test_non_numeric_cell_gives_sheet_row(workbook):
    rows = [*ROWS, [0.2, "broken", 0.3]]
    with pytest.raises(ValueParseError) as caught:
        read_table(workbook({"Data": rows}))
    assert (caught.value.row, caught.value.column) == (4, "force")


def test_header_only_sheet(workbook):
    with pytest.raises(EmptyFileError):
        read_table(workbook({"Data": ROWS[:1]}))


def test_broken_workbook(write):
    with pytest.raises(LayoutError, match="not a readable .xlsx"):
        read_table(write("w.xlsx", b"PK\x03\x04 this is not a zip file"))


def test_a_sheet_without_names_is_read_by_the_run_sheets_positions(workbook):
    path = workbook({"Data": [[0.0, 1.5, 0.01], [0.1, 2.5, 0.02], [0.2, 3.5, 0.03]]})
    with pytest.raises(LayoutError, match="no names row"):
        read_table(path, kind="tensile")
    table, meta = read_table(
        path, kind="tensile", columns={"force": "column 2", "gauges": ["column 3"]},
        units={"force": "kN", "gauges": "mm"})
    np.testing.assert_allclose(table["force"], [1500.0, 2500.0, 3500.0])
    np.testing.assert_allclose(table["gauge_1"], [1e-5, 2e-5, 3e-5])
    assert (meta.header_line, meta.first_data_line, meta.preamble) == (None, 1, {})


#: A results sheet, as Bluehill and testXpert export one before the raw data.
RESULTS = [["Specimen", "Max load [kN]", "Modulus [MPa]"], ["1", 12.3, 2100.0],
           ["2", 12.9, 2080.0]]
#: A log of 30 rows: more than a results table holds.
LOG = [["time [s]", "force [kN]", "gauge [mm]"]] + [[0.1 * i, 0.5 * i, 0.01 * i]
                                                   for i in range(30)]


def test_a_results_sheet_first_and_the_log_after_it(workbook):
    table, meta = read_table(workbook({"Results": RESULTS, "Specimen 1": LOG}))
    assert meta.sheet == "Specimen 1" and len(table) == 30
    np.testing.assert_allclose(table["force"], 500.0 * np.arange(30))
    assert meta.warnings[0] == ("sheet 'Specimen 1' read: the first sheet, 'Results', holds "
                                "no log (a results table); name the sheet in the run sheet "
                                "to read another")


def test_several_logs_after_a_results_sheet_are_refused_each_readable_by_name(workbook):
    path = workbook({"Results": RESULTS, "Specimen 1": LOG, "Specimen 2": LOG[:25]})
    with pytest.raises(LayoutError, match="sheets 'Specimen 1', 'Specimen 2' hold one each"):
        read_table(path)
    table, meta = read_table(path, sheet="Specimen 2")
    assert len(table) == 24 and meta.warnings == []


def test_a_log_on_the_first_sheet_is_read_whatever_follows(workbook):
    table, meta = read_table(workbook({"Log": LOG, "Copy": LOG}))
    assert meta.sheet == "Log" and len(table) == 30


def test_an_old_binary_excel_workbook_reads_as_its_xlsx_would(tmp_path, workbook):
    """The same sheets as ``.xls`` (written with xlwt) and ``.xlsx``: the same table."""
    xlwt = pytest.importorskip("xlwt")
    sheets = {"Results": RESULTS, "Specimen 1": [["Zeit", "Kraft", "Weg"], ["s", "kN", "mm"],
                                                  *LOG[1:]]}
    book = xlwt.Workbook()
    for title, rows in sheets.items():
        sheet = book.add_sheet(title)
        for r, row in enumerate(rows):
            for c, value in enumerate(row):
                sheet.write(r, c, value)
    book.save(str(tmp_path / "old.xls"))
    table, meta = read_table(tmp_path / "old.xls")
    expected, _ = read_table(workbook(sheets))
    assert (meta.layout, meta.sheet) == ("xls", "Specimen 1")
    pd.testing.assert_frame_equal(table, expected)
    np.testing.assert_allclose(table["force"], 500.0 * np.arange(30))


def test_a_batch_of_specimens_side_by_side_on_a_sheet_is_read_one_a_run(workbook):
    """A Trapezium batch saved as a workbook: a label over each specimen's columns, the
    shorter one's cells empty below its end."""
    rows = [["CuivreC1", None, None, "AcierC70", None, None],
            ["Temps", "Force", "Stroke"] * 2, ["sec", "kN", "mm"] * 2,
            *([0.1 * i, 1.0 * i, 0.01 * i] + [0.1 * i, 1.5 * i, 0.02 * i] for i in range(20)),
            *([None] * 3 + [0.1 * i, 1.5 * i, 0.02 * i] for i in range(20, 25))]
    path = workbook({"Batch": rows})
    table, meta = read_table(path, specimen="CuivreC1")
    np.testing.assert_allclose(table["force"], 1e3 * np.arange(20))
    assert meta.specimen == "CuivreC1" and meta.rows == 20
    table, meta = read_table(path, specimen=2)
    np.testing.assert_allclose(table["gauge_1"], 2e-5 * np.arange(25))
    assert meta.specimen == "AcierC70"


def _ods(path, sheets: dict):
    """Write `sheets` (name -> rows) as an OpenDocument spreadsheet (odfpy, through pandas)."""
    pytest.importorskip("odf")
    with pd.ExcelWriter(path, engine="odf") as book:
        for title, rows in sheets.items():
            pd.DataFrame(rows).to_excel(book, sheet_name=title, header=False, index=False)
    return path


def test_an_opendocument_spreadsheet_reads_as_its_xlsx_would(tmp_path, workbook):
    """LibreOffice's ``.ods``, a results sheet first: the same table as the ``.xlsx``; the
    format is known by the zip's first entry, whatever the file is named."""
    sheets = {"Results": RESULTS, "Specimen 1": [["Zeit", "Kraft", "Weg"], ["s", "kN", "mm"],
                                                  *LOG[1:]]}
    expected, _ = read_table(workbook(sheets))
    for name in ("log.ods", "saved-as.xlsx"):
        table, meta = read_table(_ods(tmp_path / name, sheets))
        assert (meta.layout, meta.sheet) == ("ods", "Specimen 1")
        pd.testing.assert_frame_equal(table, expected)
    np.testing.assert_allclose(table["force"], 500.0 * np.arange(30))


def test_a_damaged_opendocument_spreadsheet_is_refused_as_such(tmp_path):
    path = _ods(tmp_path / "log.ods", {"Data": ROWS})
    path.write_bytes(path.read_bytes()[:200])
    with pytest.raises(LayoutError, match=r"not a readable \.ods workbook"):
        read_table(path)


def test_the_workbook_readers_warnings_are_the_tables(workbook, monkeypatch):
    """openpyxl warns of a damaged part it leaves out (a broken defined name): that goes
    to the table's warnings, not to the console; a library's deprecation is left alone."""
    import warnings

    from pipeline.ingest import xlsx

    opened = xlsx._sheet

    def damaged(*arguments):
        warnings.warn("File contains an invalid specification for 0.", UserWarning,
                      stacklevel=2)
        warnings.warn("this engine is deprecated", DeprecationWarning, stacklevel=2)
        return opened(*arguments)

    monkeypatch.setattr(xlsx, "_sheet", damaged)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        _, meta = read_table(workbook({"Data": ROWS}))
    assert [w.category for w in caught] == [DeprecationWarning]
    assert meta.warnings[0] == ("the workbook's reader (openpyxl): File contains an invalid "
                                "specification for 0.")
