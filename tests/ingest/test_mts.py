"""MTS TestWare cyclic-acquisition exports: repeating block headers."""

import numpy as np
import pytest

from pipeline.errors import SpecimensError, ValueParseError
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


def mts_teststar(blocks: int, points: int, scan_time: bool = False) -> str:
    """An MTS TestStar export as a real one: each block opened by "Axial Counts<TAB>0", the
    names and units over the first block only, the points counted again in each; with
    `scan_time`, the time within each block beside the elapsed time, and the later
    blocks' opening lines with a second count further right (as a three-point bending
    rig's export)."""
    lines = ["C:\\Documents and Settings\\USERS\\4.TXT\t\t\t\t", "\t\t\t\t"]
    for block in range(blocks):
        lines.append("Axial Counts\t0\t\t\t" + ("\t0" if scan_time and block else ""))
        if block == 0:
            lines += ["Points\tElapsed Time \t" + ("Scan Time \t" if scan_time else "")
                      + "Disp 1\tLoad 1 ",
                      "      \tSec   \t" + ("Sec   \t" if scan_time else "") + "mm  \tN   "]
        lines += [f"{point + 1}\t{(block * points + point) * 0.005:g}\t"
                  + (f"{point * 0.005:g}\t" if scan_time else "")
                  + f"{-0.001 * point:g}\t{-0.5 - 0.01 * point:g}" for point in range(points)]
    return "\r\n".join(lines) + "\r\n"


def test_a_teststar_exports_block_lines_are_no_rows(write):
    # read as rows, each "Axial Counts<TAB>0" put a sample at time 0 between the blocks
    table, meta = read_table(write("4.TXT", mts_teststar(blocks=3, points=200)), kind="engagement")
    assert meta.layout == "mts" and meta.preamble["blocks"] == "3" and len(table) == 600
    np.testing.assert_allclose(table["time"], 0.005 * np.arange(600), atol=1e-12)
    assert meta.time_monotonic and not any("missing" in w for w in meta.warnings)


def test_a_teststar_exports_scan_time_starts_again_in_each_block_of_one_test(write):
    # a bending rig's TestStar export: each block's own 'Scan Time' beside the 'Elapsed
    # Time', and a second count on the later blocks' opening lines; read as rows, these
    # lines were samples at time 0, and taken as names rows, the blocks as tests
    text = mts_teststar(blocks=3, points=200, scan_time=True)
    table, meta = read_table(write("1.TXT", text), kind="engagement")
    assert meta.layout == "mts" and meta.preamble["blocks"] == "3" and len(table) == 600
    np.testing.assert_allclose(table["time"], 0.005 * np.arange(600), atol=1e-12)
    assert [column.name for column in meta.columns if column.role == "time"] == [
        "Elapsed Time"]
    assert any(warning.startswith("column 'Scan Time' is named as a part's of the test")
               for warning in meta.warnings)


def test_line_numbers_refer_to_the_file(write):
    with pytest.raises(ValueParseError) as caught:
        read_table(write("m.dat", mts(bad="0,02\tx\t-0,21\t99"), "latin-1"))
    assert (caught.value.row, caught.value.column) == (10, "Fuerza")


def test_a_block_of_other_columns_is_left_out_with_its_lines(write):
    # the second of three blocks names a strain where the others name the displacement
    text = mts().replace("Desplazamiento", "Deformación", 2).replace("Deformación",
                                                                     "Desplazamiento", 1)
    table, meta = read_table(write("m.dat", text, "latin-1"))
    assert len(table) == 8 and meta.preamble["blocks"] == "2"
    np.testing.assert_allclose(table["time"], [0, 0.01, 0.02, 0.03, 20, 20.01, 20.02, 20.03])
    assert ("lines 13 to 22: a block of other columns than the first (Tiempo, Fuerza, "
            "Deformación, Recuento: 4 row(s), another acquisition of the test, such as its "
            "peaks) is left out") in meta.warnings[0]


def test_peaks_between_and_after_the_samples_are_left_out(write):
    """A real German MTS 793 export: the acquisition of the test's peaks (two rows of two
    channels) between two blocks of timed samples, and at the end one of the channels
    reordered; the lines of a bad value after them are still the file's."""
    def timed(first: int, rows: int) -> list[str]:
        return ["Datenerfassung\t\t\tZeit:\t233,6\ts\t18.03.2014 14:44:26",
                "Laufzeit\tCh 1 Kraft\tCh 1 Weg", "s\tkN\tmm"] + [
            f"{0.2 * row:.1f}\t-{row},5\t-0,0{row}".replace(".", ",")
            for row in range(first, first + rows)] + [""]
    peaks = ["Datenerfassung\t\t\tZeit:\t272,1\ts\t18.03.2014 14:45:04",
             "Ch 1 Weg\tCh 1 Kraft", "mm\tkN", "1,9872092\t1,5674793",
             "-1,2559063\t-942,45343", ""]
    reordered = ["Datenerfassung\t\t\tZeit:\t272,2\ts\t18.03.2014 14:45:04",
                 "Laufzeit\tCh 1 Weg\tCh 1 Kraft", "s\tmm\tkN", "272,1\t4,84\t-0,02",
                 "43,85\t-0,41\t-119,56"]
    lines = ["MTS793|MPT|DEU|1|2|,|.|:|49|1|1|A", "", *timed(0, 5), *peaks, *timed(5, 5),
             *reordered]
    table, meta = read_table(write("specimen.dat", "\r\n".join(lines) + "\r\n", "latin-1"),
                             kind="engagement")
    np.testing.assert_allclose(table["time"], 0.2 * np.arange(10))
    np.testing.assert_allclose(table["force"], -(np.arange(10) + 0.5) * 1e3)
    assert [warning.split(":")[0] for warning in meta.warnings[:2]] == [
        "lines 12 to 17", "lines 27 to 31"]
    assert "(Ch 1 Weg, Ch 1 Kraft: 2 row(s)," in meta.warnings[0]
    with pytest.raises(ValueParseError) as caught:
        read_table(write("bad.dat", "\r\n".join(lines).replace("1,4\t-7,5", "1,4\tx")
                         + "\r\n", "latin-1"), kind="engagement")
    assert caught.value.row == 23 and lines[22].startswith("1,4\t")


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


def test_peaks_of_the_same_columns_are_no_samples(write):
    """A real MTS 793 export ends with the peaks' acquisition in the samples' own columns:
    each column's largest value, then its smallest (the time steps back). Read as rows,
    they put the peak force beside other channels' extremes; they are left out."""
    names = ["Laufzeit\tCh 1 Kraft\tCh 1 Weg", "Sec\tkN\tmm"]
    samples = [f"{110 + 0.5 * row:.1f}\t-{row}0,5\t-0,{row}1".replace(".", ",")
               for row in range(8)]
    lines = ["MTS793|MPT|DEU|1|2|,|.|:|49|1|1|A", "",
             "Datenerfassung\t\t\tZeit:\t556,4\tSec\t05.07.2010 15:30:12", *names, *samples,
             "", "Datenerfassung\t\t\tZeit:\t556,5\tSec\t05.07.2010 15:30:12", *names,
             "113,5\t0,34\t0,98", "110,0\t-71,36\t-0,74"]
    table, meta = read_table(write("specimen.dat", "\r\n".join(lines) + "\r\n", "latin-1"),
                             kind="engagement")
    np.testing.assert_allclose(table["time"], 110 + 0.5 * np.arange(8))
    assert meta.time_monotonic
    assert meta.warnings == ["lines 15 to 19: a block of two rows, each column's largest value "
                             "then its smallest, is the test's peaks, not samples: left out"]



def appended(tests: int, points: int, runs_on: bool = False) -> str:
    """Blocks as a logger writes that appends each test to one file: a title, the names
    row, and the test's samples from time 0 again (`runs_on`: from where the last ended)."""
    lines = []
    for test in range(tests):
        lines += [f"Specimen {test + 1}", "Time [s];Force [kN];Extension [mm]"]
        start = test * points if runs_on else 0
        lines += [f"{(start + point) / 10:.1f};{(test + 1) * point:.1f};{point / 100:.2f}"
                  .replace(".", ",") for point in range(points)]
        lines.append("")
    return "\n".join(lines)


def test_tests_one_after_another_are_read_one_at_a_time_not_joined(write):
    # joined, the second pull followed the first as one test whose time steps back once
    # (a warning only), and its force drop read as the fracture
    path = write("appended.csv", appended(tests=3, points=20))
    with pytest.raises(SpecimensError) as caught:
        read_table(path)
    assert caught.value.row == 24  # "Specimen 2": 2 lines, 20 samples and a blank line above
    assert caught.value.message.startswith(
        "the file holds 3 tests (specimens, or a test's steps) one below the other, each "
        "timed from its own start: the time starts again in the blocks from lines 24, 47")
    assert "a file of its own" in caught.value.hint
    for test in (1, 2, 3):
        table, meta = read_table(path, specimen=test)
        np.testing.assert_allclose(table["time"], np.arange(20) / 10)
        np.testing.assert_allclose(table["force"], 1e3 * test * np.arange(20))
        assert (meta.specimen, meta.first_data_line) == (str(test), 3 + 23 * (test - 1))
        assert meta.warnings == []


# a Form+Test press's export of a series (its layout; our numbers): over each specimen's
# table a line of its results, the names row and the units row (its first fields empty)
PRESS = ("HiLo floors\nDouble Punch;22.10.2019;09:23;29.11.2019;09:56;38;00:33;\n"
         "1;150.000;150.000;7716;2911;106.9;6.1;0.66\n"
         "Index;Element;Markierung;Zeit;Kraft;Weg\n;;;s;kN;mm\n{rows}\n"
         "2;150.000;150.000;7728;2915;141.7;8.0;1.31\n"
         "Index;Element;Markierung;Zeit;Kraft;Weg\n;;;s;kN;mm\n{rows}")


def test_a_press_series_specimens_under_their_results_lines_are_read_one_at_a_time(write):
    rows = "\n".join(f"{i + 1};100;100;{0.5 * i:.4f};{5 + i:.2f};{0.01 * i:.3f}"
                     for i in range(25))
    path = write("Double_Punch.txt", PRESS.format(rows=rows))
    with pytest.raises(SpecimensError, match="the file holds 2 tests") as caught:
        read_table(path)
    assert caught.value.row == 31  # the second specimen's results line
    table, meta = read_table(path, specimen=2)
    assert meta.first_data_line == 34 and len(table) == 25
    np.testing.assert_allclose(table["force"], 1e3 * (5 + np.arange(25)))
    np.testing.assert_allclose(table["time"], 0.5 * np.arange(25))


# a Dia-Stron fibre tester's report (its layout; our numbers): each specimen's table
# under the report's two lines and the names, no time column
FIBRES = ("Tensile Data Report Version: 1.0\nSource File: C:\\HR_Tensile.uvc\n"
          "Record\t% Strain\tgmf\t\n{first}\n"
          "Tensile Data Report Version: 1.0\nSource File: C:\\HR_Tensile.uvc\n"
          "Record\t% Strain\tgmf\t\n{second}\n")


def test_tables_one_below_the_other_without_a_time_are_not_joined(write):
    # joined, the second fibre read as a second load cycle of the first
    first, second = (np.arange(30) * 1.5, np.arange(20) * 2.0)
    rows = ["\n".join(f"{record}\t{0.5 * i:.1f}\t{force:.1f}\t" for i, force in
                      enumerate(forces)) for record, forces in ((1, first), (2, second))]
    path = write("Tensile_Data.txt", FIBRES.format(first=rows[0], second=rows[1]))
    with pytest.raises(SpecimensError) as caught:
        read_table(path, kind="tensile")
    assert caught.value.row == 34 and caught.value.message.startswith(
        "the file holds 2 tables one below the other, each under its own names")
    table, meta = read_table(path, kind="tensile", specimen=2)
    np.testing.assert_allclose(table["force"], second * 9.80665e-3)
    np.testing.assert_allclose(table["strain_1"], 0.005 * np.arange(20))
    # a logger that writes its names again as the last line, no rows under them: one table
    once = FIBRES.split("Tensile Data Report")[0] + FIBRES.format(first=rows[0], second="")
    table, _ = read_table(write("once.txt", once.rstrip("\n") + "\n"), kind="tensile")
    np.testing.assert_allclose(table["force"], first * 9.80665e-3)


def bluehill_sample(specimens: int, points: int) -> str:
    """A Bluehill Universal sample export (its layout; our numbers): the results of each
    specimen, then each specimen's rows under a names row led by its number."""
    lines = ["Results Table 1,,", ",Maximum Force,Rate 1", ",(N),(mm/min)",
             *(f"{n},{1000 * n},50" for n in range(1, specimens + 1)), ",,",
             "Results Table 2,,", ",,"]
    for n in range(1, specimens + 1):
        lines += [f"{n},Time,Displacement,Force", ",(s),(mm),(N)"]
        lines += [f",{0.02 * i:.2f},{0.01 * i:.2f},{n * 10.0 * i:.1f}" for i in range(points)]
    return "\n".join(lines) + "\n"


def test_a_bluehill_samples_specimens_led_by_their_numbers_are_read_one_at_a_time(write):
    path = write("Sample.csv", bluehill_sample(specimens=3, points=12))
    with pytest.raises(SpecimensError, match="the file holds 3 tests") as caught:
        read_table(path, kind="tensile")
    assert caught.value.row == 24  # the second specimen's names row
    for n in (1, 2, 3):
        table, meta = read_table(path, kind="tensile", specimen=n)
        np.testing.assert_allclose(table["force"], n * 10.0 * np.arange(12))
        np.testing.assert_allclose(table["gauge_1"], 1e-5 * np.arange(12))
        assert meta.first_data_line == 12 + 14 * (n - 1)


def test_exports_appended_under_a_rule_of_dashes_are_read_one_at_a_time(write):
    # a BAM creep rig's export: a title, a rule of dashes, a [data] line over the names;
    # two exports appended to one file
    def export(force: float) -> str:
        return ("BAM 5.2 Loading.LIS\t\t\n------------------\t\t\n[data]\t\t\n"
                "Time\tForce\tExtension\ns\tkN\t%\n" + "".join(
                    f"{0.5 * i:.1f}\t{force * i:.3f}\t{0.01 * i:.4f}\n" for i in range(10)))
    path = write("Loading.LIS", export(0.1) + export(0.2))
    with pytest.raises(SpecimensError, match="the file holds 2 tests"):
        read_table(path, kind="tensile")
    for specimen, force in ((1, 0.1), (2, 0.2)):
        table, _ = read_table(path, kind="tensile", specimen=specimen)
        np.testing.assert_allclose(table["force"], 1e3 * force * np.arange(10))


def test_blocks_whose_time_runs_on_are_one_test(write):
    table, meta = read_table(write("blocks.csv", appended(tests=2, points=20, runs_on=True)))
    assert meta.layout == "mts" and meta.preamble["blocks"] == "2" and len(table) == 40
    np.testing.assert_allclose(table["time"], np.arange(40) / 10)


def trapezium(blocks: list[tuple[float, float]], names: str = '"Time","Force","Stroke"'
              ) -> str:
    """A Shimadzu Trapezium export (its layout, after a real loader; our numbers): the
    test's settings and the specimens' results above, then each block under its number,
    the names and the units, every field quoted. Each block: (first time [s], force scale
    [N]), 30 points 0.5 s apart."""
    lines = ['"Test Date","Test Name","Machine"', '"2019/11/01","Tensile","AG-X 300kN"', "",
             '"","Max","Max"', '"","Force","Stroke"', '"","N","mm"', '"Name","",""',
             '"1","143912","27.71"', '"2","139595","27.10"']
    for number, (start, scale) in enumerate(blocks, start=1):
        lines += ["", f'"{number}"', names, '"sec","N","mm"']
        lines += [f'"{start + 0.5 * i:g}","{scale * i:.1f}","{0.01 * i:.3f}"'
                  for i in range(30)]
    return "\r\n".join(lines) + "\r\n"


def test_a_trapezium_exports_quoted_specimens_are_read_one_at_a_time(write):
    # its quoted numbers were no data lines to the reader: the whole file, a header,
    # "Empty CSV file"
    path = write("trapezium.csv", trapezium([(0.0, 100.0), (0.0, 200.0)]))
    with pytest.raises(SpecimensError, match="the file holds 2 tests") as caught:
        read_table(path)
    assert caught.value.row == 45  # the second block's number
    for specimen in (1, 2):
        table, meta = read_table(path, specimen=specimen)
        assert meta.layout == "mts" and len(table) == 30
        np.testing.assert_allclose(table["force"], 100.0 * specimen * np.arange(30))
        np.testing.assert_allclose(table["time"], 0.5 * np.arange(30))


def test_a_trapezium_exports_japanese_cycles_whose_time_runs_on_are_one_test(write):
    # in Shift-JIS the names row was looked for in UTF-8 and not found: the second block's
    # number above it was read as a row of one field and the file refused
    names = '"時間","試験力","ストローク"'
    cycles = write("cycles.csv", trapezium([(0.0, 100.0), (15.0, 100.0), (30.0, 100.0)],
                                           names), "cp932")
    table, meta = read_table(cycles)
    assert meta.encoding == "cp932" and len(table) == 90
    np.testing.assert_allclose(table["time"], 0.5 * np.arange(90))
    np.testing.assert_allclose(table["force"], np.tile(100.0 * np.arange(30), 3))
    specimens = write("specimens.csv", trapezium([(0.0, 100.0), (0.0, 200.0)], names),
                      "cp932")
    table, _ = read_table(specimens, specimen=1)
    np.testing.assert_allclose(table["force"], 100.0 * np.arange(30))


def cetr(counts: tuple[int, ...]) -> str:
    """A CETR UMT tribometer's export of steps (its layout; our numbers): the run's
    settings, then each step's own (its count of rows, its start) over its names and
    units, each step timed from 0."""
    lines = ["Created by CETR Data Viewer ver.2.19.106 05/12/22 14:43:46",
             f"Total number of steps = {len(counts)}", ""]
    for step, count in enumerate(counts, start=1):
        lines += [f"Step No. {step}", "", f"Data Count   = {count}",
                  f"Started at: 12:2{step}:58.029 12 May 2022", "",
                  "Fx,Fz,Z,T,Ff,COF", "g,g,mm,sec,g,", ""]
        lines += [f"7.68,-198.96,-0.69{i % 10},{0.02 * i:.4f},7.68,0.0386" for i in range(count)]
        lines.append("")
    return "\n".join(lines)


def test_a_later_steps_own_settings_are_its_preamble(write):
    # a real CETR export's second step was given the first's: its count of 110 rows
    # against the 107 read said "it may be cut short", and its start was the first's
    path = write("HT-2n-6-4 2_001.csv", cetr((110, 107)))
    table, meta = read_table(path, kind="wear", specimen=2, strict=False)
    assert len(table) == 107
    assert meta.preamble["Data Count"] == "107"
    assert meta.preamble["Started at"] == "12:22:58.029 12 May 2022"
    assert not any("cut short" in warning for warning in meta.warnings)
    _, first = read_table(path, kind="wear", specimen=1, strict=False)
    assert first.preamble["Data Count"] == "110"
