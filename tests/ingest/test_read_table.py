"""The dispatcher: format detection and forcing, file-system errors."""

import pytest

from pipeline.errors import IngestError, LayoutError
from pipeline.ingest import FORMATS, read_table


def test_formats_listed():
    assert FORMATS == ("auto", "csv", "xlsx", "ods", "xls", "tdms", "lvm", "catman", "rigol",
                       "tektronix", "gwinstek", "isomme", "linescale", "labchart", "keyence",
                       "merlin", "mts",
                       "machine_export", "european_csv", "plain_csv")


def test_unknown_format(write):
    with pytest.raises(ValueError, match="format"):
        read_table(write("a.csv", "t,f\n1,2\n"), format="json")


def test_missing_file(tmp_path):
    with pytest.raises(IngestError, match="cannot read the file") as caught:
        read_table(tmp_path / "nope.csv")
    assert caught.value.file.endswith("nope.csv")


def test_a_broken_old_excel_file(write):
    with pytest.raises(LayoutError, match=r"not a readable \.xls workbook"):
        read_table(write("old.xls", b"\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1" + bytes(100)))


def test_content_beats_suffix(write):
    path = write("log.dat", "time [s],force [kN],gauge [mm]\n0,1,2\n")
    _, meta = read_table(path, format="csv")
    assert meta.layout == "plain_csv"
    with pytest.raises(LayoutError, match="xlsx"):
        read_table(write("log.xlsx", "time [s],force [kN]\n0,1\n"))
