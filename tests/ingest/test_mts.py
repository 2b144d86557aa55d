"""MTS TestWare cyclic-acquisition exports: repeating block headers."""

import numpy as np
import pytest

from pipeline.errors import LayoutError, ValueParseError
from pipeline.ingest import read_table
from pipeline.units import STANDARD_GRAVITY


def mts(blocks: int = 3, points: int = 4, names: str = "Tiempo\tFuerza\tDesplazamiento\tRecuento",
        bad: str | None = None) -> str:
    lines = ["MTS***|MPT|**|*|*", ""]
    for block in range(blocks):
        lines += [f"Adquisición cíclica\t\t\tTiempo\t{10 * block},0\tSec",
                  f"Parado en: \t{100 * (block + 1)}\tcycle", f"Puntos: \t{points}",
                  names, "Sec\tkgf\tmm\tcycles"]
        for point in range(points):
            time = f"{10 * block + point / 100:.2f}".replace(".", ",")
            lines.append(f"{time}\t{point},5\t-0,{point}1\t{100 * (block + 1) - 1}")
        lines.append("")
    if bad:
        lines[9] = bad
    return "\r\n".join(lines[:-1])


def test_blocks_are_joined(write):
    table, meta = read_table(write("m.dat", mts(), "latin-1"))
    assert meta.layout == "mts" and meta.encoding == "latin-1" and meta.decimal == ","
    assert meta.preamble["blocks"] == "3" and meta.preamble["Puntos"] == "4"
    assert len(table) == 12
    np.testing.assert_allclose(table["force"][:2], [0.5 * STANDARD_GRAVITY, 1.5 * STANDARD_GRAVITY])
    np.testing.assert_allclose(table["time"][4:6], [10.0, 10.01])
    assert meta.time_gaps == 2 and "first before line 18" in meta.warnings[0]


def test_an_indented_first_line_is_still_an_mts_export(write):
    # a real MTS TestWorks export begins "    MTS793|MPT|ENU|..."
    table, meta = read_table(write("specimen.dat", "    " + mts(blocks=1), "latin-1"))
    assert meta.layout == "mts" and len(table) == 4


def mts_teststar(blocks: int, points: int) -> str:
    """An MTS TestStar export as a real one: each block opened by "Axial Counts<TAB>0", the
    names and units over the first block only, the points counted again in each."""
    lines = ["C:\\Documents and Settings\\USERS\\4.TXT\t\t\t\t", "\t\t\t\t"]
    for block in range(blocks):
        lines.append("Axial Counts\t0\t\t\t")
        if block == 0:
            lines += ["Points\tElapsed Time \tDisp 1\tLoad 1 ", "      \tSec   \tmm  \tN   "]
        lines += [f"{point + 1}\t{(block * points + point) * 0.005:g}\t{-0.001 * point:g}"
                  f"\t{-0.5 - 0.01 * point:g}" for point in range(points)]
    return "\r\n".join(lines) + "\r\n"


def test_a_teststar_exports_block_lines_are_no_rows(write):
    # read as rows, each "Axial Counts<TAB>0" put a sample at time 0 between the blocks
    table, meta = read_table(write("4.TXT", mts_teststar(blocks=3, points=200)), kind="engagement")
    assert meta.layout == "mts" and meta.preamble["blocks"] == "3" and len(table) == 600
    np.testing.assert_allclose(table["time"], 0.005 * np.arange(600), atol=1e-12)
    assert meta.time_monotonic and not any("missing" in w for w in meta.warnings)


def test_line_numbers_refer_to_the_file(write):
    with pytest.raises(ValueParseError) as caught:
        read_table(write("m.dat", mts(bad="0,02\tx\t-0,21\t99"), "latin-1"))
    assert (caught.value.row, caught.value.column) == (10, "Fuerza")


def test_block_naming_other_columns(write):
    text = mts().replace("Desplazamiento", "Deformación", 2).replace("Deformación",
                                                                     "Desplazamiento", 1)
    with pytest.raises(LayoutError, match="other columns") as caught:
        read_table(write("m.dat", text, "latin-1"))
    assert caught.value.row == 16


def test_truncated_last_point(write):
    table, meta = read_table(write("m.dat", mts() + "\r\n30,05\t1,", "latin-1"))
    assert len(table) == 12 and "line 32 is truncated" in meta.warnings[0]


def test_the_date_in_days_beside_the_running_time_is_not_the_time(write):
    # a real German MTS 793 export: the spreadsheet's day number (41893: 11.09.2014) with
    # its unit "d" in the first column, the running time in seconds beside it
    lines = ["MTS793|MPT|DEU|1|2|,|.|:|49|1|1|A", "",
             "Datenerfassung\t\t\t\t\t\tZeit:\t345,61914\ts\t11.09.2014 13:43:25",
             "Datum\tLaufzeit\tCh 1 Kraft Sollwert\tCh 1 Kraft\tCh 1 Weg",
             "d\ts\tkN\tkN\tmm"]
    lines += [f"41893\t{15.679688 + 0.5 * row:.6f}\t-0,{row}\t{row + 1},5\t0,{row}5".replace(
        ".", ",") for row in range(6)]
    table, meta = read_table(write("specimen.dat", "\r\n".join(lines) + "\r\n", "latin-1"),
                             kind="engagement")
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["time"], 15.679688 + 0.5 * np.arange(6))
    np.testing.assert_allclose(table["force"], (np.arange(6) + 1.5) * 1e3)
    assert not any("could be the time" in warning for warning in meta.warnings)
