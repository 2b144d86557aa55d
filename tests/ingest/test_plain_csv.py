"""Plain CSV: one header row with units, ',' delimiter, '.' decimal mark."""

import numpy as np
import pytest

from pipeline.errors import ColumnError, LayoutError, UnitError, ValueParseError
from pipeline.ingest import open_log, read_table
from pipeline.ingest.delimited import time_unit_named
from pipeline.ingest.sniff import detect_dialect

PLAIN = (
    "time [s],force [kN],gauge1 [mm],gauge2 [mm]\n"
    "0.0,0.10,0.000,0.001\n"
    "0.1,0.20,0.010,0.011\n"
    "0.2,0.30,0.020,0.021\n"
)


def test_reads_roles_and_si_units(write):
    table, meta = read_table(write("t.csv", PLAIN))
    assert list(table.columns) == ["time", "force", "gauge_1", "gauge_2"]
    np.testing.assert_allclose(table["force"], [100.0, 200.0, 300.0])
    np.testing.assert_allclose(table["gauge_2"], [1e-6, 1.1e-5, 2.1e-5])
    assert (meta.layout, meta.delimiter, meta.decimal, meta.rows) == ("plain_csv", ",", ".", 3)
    assert [(c.name, c.role, c.unit, c.si_unit) for c in meta.columns] == [
        ("time", "time", "s", "s"), ("force", "force", "kN", "N"),
        ("gauge1", "gauge_1", "mm", "m"), ("gauge2", "gauge_2", "mm", "m"),
    ]
    assert (meta.header_line, meta.first_data_line, meta.warnings) == (1, 2, [])
    assert table["force"].dtype == np.float64


def test_parenthesised_units_crlf_and_cr(write):
    text = PLAIN.replace("[", "(").replace("]", ")")
    for newline in ("\r\n", "\r"):
        table, _ = read_table(write("t.csv", text.replace("\n", newline)))
        np.testing.assert_allclose(table["time"], [0.0, 0.1, 0.2])


def test_tab_and_pipe_delimiters(write):
    for delimiter in ("\t", "|"):
        table, meta = read_table(write("t.csv", PLAIN.replace(",", delimiter)))
        assert meta.delimiter == delimiter and meta.layout == "plain_csv"
        assert table.shape == (3, 4)


def test_quoted_cells_missing_tokens_and_trailing_delimiter(write):
    text = ('"time [s]","force [kN]","gauge [mm]",\n'
            '"0.0","0.1","0.0",\n"0.1",N/A,"0.01",\n"0.2",,0.02,\n')
    table, meta = read_table(write("t.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    assert np.isnan(table["force"][1:]).all()
    assert any("empty column" in warning and "column 4" in warning for warning in meta.warnings)


def test_blank_lines_inside_the_table_and_line_numbers(write):
    text = "time [s],force [kN],gauge [mm]\n0.0,1,0\n\n0.1,x,0\n"
    with pytest.raises(ValueParseError) as caught:
        read_table(write("t.csv", text))
    assert (caught.value.row, caught.value.column) == (4, "force")
    table, meta = read_table(write("t.csv", text.replace("x", "")))
    assert len(table) == 2 and "from line 4" in meta.warnings[0]


def test_a_loggers_comment_lines_are_passed_over_with_a_warning(write):
    text = ("# ./logger --rate 1000\ntime [s],force [kN],gauge [mm]\n# missing reply\n"
            "0.0,1,0\n# missing reply\n0.1,2,0\n\n# Skipped 1 cycles\n0.2,3,0\n")
    table, meta = read_table(write("t.csv", text))
    np.testing.assert_allclose(table["force"], [1e3, 2e3, 3e3])
    assert meta.warnings == ["2 comment line(s) among the data rows passed over, the first "
                             "at line 5: '# missing reply'"]
    assert meta.first_data_line == 4
    with pytest.raises(ValueParseError) as caught:  # line numbers count the comment lines
        read_table(write("t.csv", text.replace("0.2,3,0", "0.2,x,0")))
    assert (caught.value.row, caught.value.column) == (9, "force")


def test_a_rigs_event_lines_among_its_readings_are_left_out_with_a_warning(write):
    # a real shock dyno's log: the rig notes a change of speed between two readings
    text = ("Millis,Load_Cell [lbf],Linear_Pot [in]\n6714,-6.36,2.6\n6724,-6.31,2.448\n"
            "6724,Switched from 1 to 2,\n6735,-6.09,2.469\n6740,,Test paused\n6746,-6.02,2.419\n")
    table, meta = read_table(write("dyno.csv", text))
    np.testing.assert_allclose(table["force"] / 4.4482216152605, [-6.36, -6.31, -6.09, -6.02])
    assert ("2 line(s) among the data rows hold a text, not readings (events the machine "
            "logged), left out; the first at line 4: '6724,Switched from 1 to 2,'"
            in meta.warnings)
    with pytest.raises(ValueParseError) as caught:  # line numbers count the event lines
        read_table(write("dyno.csv", text.replace("-6.02", "x")))
    assert (caught.value.row, caught.value.column) == (7, "Load_Cell")
    with pytest.raises(LayoutError):  # a line of text alone may open another test
        read_table(write("dyno.csv", text.replace("6740,,Test paused", "Test 2")))
    with pytest.raises(ValueParseError):  # an event at a time the rows do not pass
        read_table(write("dyno.csv", text.replace("6740,,", "9999,,")))


def test_a_names_row_written_as_a_comment_is_the_names_row(write):
    table, meta = read_table(write("t.csv", "#time [s],force [kN],gauge [mm]\n0.0,1,0\n0.1,2,0\n"))
    np.testing.assert_allclose(table["force"], [1e3, 2e3])
    assert [column.name for column in meta.columns] == ["time", "force", "gauge"]


def test_text_column_is_kept_out(write):
    text = "date,force [kN],gauge [mm]\n2021-01-01,1.5,0.1\n2021-01-02,1.6,0.2\n"
    table, meta = read_table(write("t.csv", text))
    assert list(table.columns) == ["force", "gauge_1"]
    assert meta.columns[0].role is None


# the head of a real CellScale micro-tester export: "Cycle" holds the step's label
CELLSCALE = ("Set Name,Cycle,Time(ms),Force(uN),Tip Displacement(um)\n"
             "noise,1-Compress,0,9.11398,-0.22992\nnoise,1-Hold,200,9.11398,-0.22992\n"
             "noise,1-Hold,400,9.3,-0.2\n")


def test_a_column_of_labels_named_as_a_role_is_kept_out_with_a_warning(write):
    table, meta = read_table(write("cellscale.csv", CELLSCALE))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["time"], [0.0, 0.2, 0.4])
    assert meta.warnings == ["column 'Cycle' holds text ('1-Compress'...), not numbers: not "
                             "used as the cycle_count"]


def test_a_column_of_labels_named_in_the_run_sheet_is_refused_at_its_first_label(write):
    with pytest.raises(ValueParseError, match="'1-Compress' is not a number") as caught:
        read_table(write("cellscale.csv", CELLSCALE), columns={"cycle_count": "Cycle"})
    assert (caught.value.row, caught.value.column) == (2, "Cycle")


@pytest.mark.parametrize("rows", ["0,x,0\n", "0,x,0\n1,2,3\n"])
def test_a_bad_cell_is_no_column_of_labels(write, rows):
    with pytest.raises(ValueParseError, match="'x' is not a number"):
        read_table(write("t.csv", "time [s],force [kN],gauge [mm]\n" + rows))


# a real strain-gauge logger's export: quoted names, columns aligned by runs of spaces
SPACED = ('"Time"  "Strain_1a" "Strain_1b"\n0   -454.0928   122.4755\n'
          '0.005   -454.2175    121.9769\n0.01    -453.9680    121.9769\n')


def test_columns_aligned_by_spaces_are_read(write):
    table, meta = read_table(write("dataexample.txt", SPACED), kind="tensile", strict=False,
                             units={"time": "s", "gauges": ["1", "1"]})
    assert meta.delimiter == " "
    assert [column.name for column in meta.columns] == ["Time", "Strain_1a", "Strain_1b"]
    np.testing.assert_allclose(table["time"], [0.0, 0.005, 0.01])
    np.testing.assert_allclose(table["strain_2"], [122.4755, 121.9769, 121.9769])


# a real MTS 793 TestWare export (three-point bending): names apart by single blanks
TESTWARE = ("Ch 1 Displacement Ch 1 Force Time\nmm        kN        Sec\n"
            "0.00015497208 -1.6205013e-05 0.034179688\n0.0012874603 0.0040941238 0.13378906\n")


def test_names_apart_by_single_blanks_are_split_after_each_role_word(write):
    table, meta = read_table(write("1_3D850_s1.dat", TESTWARE), kind="tensile")
    assert [(c.name, c.role, c.unit) for c in meta.columns] == [
        ("Ch 1 Displacement", "gauge_1", "mm"), ("Ch 1 Force", "force", "kN"),
        ("Time", "time", "Sec")]
    np.testing.assert_allclose(table["force"], [-1.6205013e-02, 4.0941238])
    assert any("split after each word that names a role" in w for w in meta.warnings)


def test_names_that_do_not_split_into_the_columns_are_none(write):
    text = TESTWARE.replace("Ch 1 Force", "Ch 1 Status")  # the words give two names, not 3
    _, meta = read_table(write("t.dat", text), kind="tensile")
    assert [(c.name, c.role) for c in meta.columns] == [
        ("column 1", "gauge_1"), ("column 2", "force"), ("column 3", "time")]  # by unit
    assert any("does not split into the 3 columns" in w for w in meta.warnings)


def test_a_names_row_written_as_numpys_comment_over_columns_aligned_by_blanks(write):
    # a real impact-rig export written by numpy.savetxt: "# " before the names
    text = ("# time(s), \t \tacceleration(g)\n0.000000000000000000e+00 6.280757999999999619e+00\n"
            "2.000277970813059281e-05 6.519219999999999793e+00\n")
    table, meta = read_table(write("acc_base_a0.txt", text), kind="engagement", strict=False)
    assert [(c.name, c.unit) for c in meta.columns] == [("time", "s"), ("acceleration", "g")]
    np.testing.assert_allclose(table["time"], [0.0, 2.000277970813059281e-05])


def test_a_column_named_by_a_unit_of_time_holds_the_time_in_it(write):
    # a real oscilloscope export: the time column named by its unit
    text = "sec,Volt1,Volt2\n-5.000000E-03,-8.054398E-03,+25.523037E-03\n" \
           "-4.990000E-03,-8.054398E-03,+25.523037E-03\n"
    table, meta = read_table(write("scope_0.csv", text), kind="engagement",
                             columns={"force": "Volt1"}, units={"force": "kN"})
    np.testing.assert_allclose(table["time"], [-5e-3, -4.99e-3])
    assert "column 'sec': unit 'sec' from its name" in meta.warnings
    _, other = read_table(write("t.csv", "s,Force [kN]\n0.1,1.0\n0.2,1.1\n"), kind="tensile",
                          columns={"gauges": "s"}, units={"gauges": "mm"})
    assert not any("from its name" in w for w in other.warnings)  # "s": a German travel


def test_rows_labelled_one_by_one_without_a_time_are_told_as_specimens(write):
    # a lab's table of specimens (a DAQ's settings or a batch's results), not one test
    text = ("name,Peak load (N),Displacement at peak (mm)\n"
            "H1167L,400,0.3\nH1168R,420,0.35\nH1260R,500,2\n")
    _, meta = read_table(write("specimens.csv", text), kind="tensile")
    assert meta.warnings[0].startswith(
        "column 'name' gives each row a label of its own ('H1167L', 'H1168R', 'H1260R'...) "
        "and no column is a time")
    # a status that repeats, or labels beside a time, are a log's
    status = "state,Load (N),Extension (mm)\nRUN,1,0.1\nRUN,2,0.2\nHOLD,2,0.2\n"
    tagged = "tag,Time (s),Load (N),Extension (mm)\na,0,1,0.1\nb,1,2,0.2\nc,2,3,0.3\n"
    frames = ("Filename_0,Load (N),Extension (mm)\n" + "".join(
        f"D:/CT/S1-{i:05d}_0.tif,{i},{i / 10}\n" for i in range(3)))  # a DIC export's frames
    for text in (status, tagged, frames):
        _, meta = read_table(write("log.csv", text), kind="tensile")
        assert not any("label of its own" in warning for warning in meta.warnings)


def test_quoted_names_after_blanks_are_read_with_their_units(write):
    # VIC-3D writes ' "X",  "Y"': the quotes were kept, the units in brackets not read
    text = ' "Time [s]",  "Load [kN]",  "Crosshead [mm]"\n0,0.5,0.25\n1,10.5,1.25\n'
    table, meta = read_table(write("vic.csv", text), kind="tensile")
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Time", "s"), ("Load", "kN"), ("Crosshead", "mm")]
    np.testing.assert_allclose(table["force"], [500.0, 10500.0])


def test_a_log_of_two_sensors_read_in_turn_is_refused(write):
    # a real two-load-cell Arduino log in long format: once its value was named the force,
    # the left and right cells' readings were one zigzagging force signal
    rows = "".join(f"{1736440668 + i // 2 / 10},{'Left' if i % 2 == 0 else 'Right'},"
                   f"{30 + i % 2 * 5 + i / 100}\n" for i in range(12))
    text = "Unix Timestamp,Position,Force [kg]\n" + rows
    with pytest.raises(LayoutError, match=r"column 'Position' labels the rows in turn "
                                          r"\('Left', 'Right'\): each row is a reading of one "
                                          r"of 2 sensors"):
        read_table(write("serial.csv", text), kind="tensile")
    # a state held over several rows labels no sensor
    held = text.replace("Right", "Left", 3)
    table, _ = read_table(write("held.csv", held), kind="engagement", units={"time": "s"})
    assert table["force"].size == 12


def test_a_results_table_of_specimens_dated_at_midnight_is_refused_as_such(write):
    # a real filament-testing lab's table: one row per specimen, its test's date at
    # midnight (no time of a test), results beside it; it was read as a curve of yield
    # forces against break elongations, "3 cycles"
    text = ("Specimen ID,Test #,Test Date,Operator,Yield (N),Tensile (N),Break Elong [mm]\n"
            "SVA7P,500,2019-12-06 00:00:00,Taylor,2048.2,2048.35,6.23\n"
            "5ZB92,501,2019-12-06 00:00:00,Taylor,2033.12,2033.12,6.59\n"
            "Y35ZN,502,2019-12-09 00:00:00,Taylor,1615.57,1615.69,5.25\n")
    with pytest.raises(LayoutError, match=r"column 'Specimen ID' gives each row a label of "
                                          r"its own .* under names of results \('Yield \(N\)', "
                                          r"'Break Elong \[mm\]'\): the rows are specimens"):
        read_table(write("tensile.csv", text), kind="tensile")
    # a date and time that advances is a log's time: its labels are no specimens
    logged = text.replace("2019-12-06 00:00:00,Taylor,2033", "2019-12-06 00:00:01,Taylor,2033")
    _, meta = read_table(write("log.csv", logged), kind="tensile",
                         columns={"force": "Yield", "gauges": ["Break Elong"]})
    assert not any("label of its own" in warning for warning in meta.warnings)


def test_a_results_table_of_numbered_specimens_is_refused_as_such(write):
    # a real filament lab's table: specimens numbered 1, 2, 3 in 'no.', their results
    # beside; its max_force_N was taken as the force channel
    text = ("no.,width_mm,max_force_N,tensile_break_Mpa,elongation_at_break,modulus_Mpa\n"
            "1,10,50.76,6.94,573.4,94.4\n2,10,44.5,5.485,545.1,95.4\n"
            "3,10,44.25,6.193,531.4,87.6\n4,10,39.05,5.485,545.1,73.6\n")
    with pytest.raises(LayoutError, match=r"column 'no.' numbers the rows \(1, 2, 3...\) .* "
                                          r"under names of results"):
        read_table(write("tensile_data.csv", text), kind="tensile")
    # a log numbering its samples, without a time, beside one name of a result is read
    log = ("No.,Force (N),Extension (mm),Modulus (MPa)\n"
           + "".join(f"{i},{i * 2},{i / 100},0\n" for i in range(1, 6)))
    table, _ = read_table(write("log.csv", log), kind="tensile")
    np.testing.assert_allclose(table["force"], [2.0, 4.0, 6.0, 8.0, 10.0])


def test_an_arduino_clock_call_names_the_time_and_its_unit(write):
    # an HX711 thrust stand's serial log: millis() beside the thrust in grams (its weight)
    text = "millis,Thrust (g)\n1278,-0.1\n1373,12.4\n1468,25.0\n"
    table, meta = read_table(write("thrust.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], [1.278, 1.373, 1.468])
    np.testing.assert_allclose(table["force"], np.array([-0.1, 12.4, 25.0]) * 9.80665e-3)
    assert "column 'millis': unit 'ms' from its name" in meta.warnings


def test_a_machines_running_hours_hold_the_time_in_hours(write):
    # a chain wear rig's log: the elongation read at the running hours
    text = "Operating hours,Elongation (%)\n0,0.00\n50,0.12\n100,0.21\n"
    table, meta = read_table(write("wear.csv", text), kind="wear")
    np.testing.assert_allclose(table["time"], [0.0, 180_000.0, 360_000.0])
    assert "column 'Operating hours': unit 'hours' from its name" in meta.warnings


def test_a_unit_of_time_beside_elapsed_in_a_name(write):
    # a real phone-logger export (Sensor Logger): epoch nanoseconds beside seconds elapsed
    text = ("time,seconds_elapsed,z,y,x\n"
            "1727317818379557400,0.026557373046875,-0.0611,0.00027,0.0125\n"
            "1727317818389611300,0.036611328125,-0.0601,0.0155,0.0001\n")
    table, meta = read_table(write("Accelerometer.csv", text), kind="engagement",
                             columns={"time": "seconds_elapsed", "force": "z"},
                             units={"force": "N"})
    np.testing.assert_allclose(table["time"], [0.026557373046875, 0.036611328125])
    assert "column 'seconds_elapsed': unit 'seconds' from its name" in meta.warnings
    named = {name: time_unit_named(name) for name in (
        "Elapsed Seconds", "elapsed_ms", "ms_elapsed", "elapsed", "ms", "s", "Elapsed Time",
        "seconds elapsed total")}
    assert named == {"Elapsed Seconds": "Seconds", "elapsed_ms": "ms", "ms_elapsed": "ms",
                     "elapsed": None, "ms": None, "s": None, "Elapsed Time": None,
                     "seconds elapsed total": None}


# a real PicoLog ADC-24 export (its first six columns): no name over the time stamps, each
# statistic of a channel after its default name
PICOLOG = (
    '"","Single-ended 12 Ave. (V)","Differential 13 - 14 Last (V)","Differential 13 - 14 Ave. '
    '(V)","Differential 13 - 14 Min. (V)","Differential 13 - 14 Max. (V)"\n'
    '"00:00:00","0.029847","-0.000016","-0.000016","-0.000016","-0.000016"\n'
    '"00:00:01","0.029847","-0.000015","-0.000015","-0.000015","-0.000015"\n'
    '"00:00:02","0.029847","-0.000017","-0.000017","-0.000017","-0.000017"\n'
)


def test_an_unnamed_column_of_clock_readings_is_the_time(write):
    table, meta = read_table(write("sample_June3.csv", PICOLOG), kind="engagement",
                             columns={"force": "Differential 13 - 14 Last"},
                             units={"force": "kN"})
    np.testing.assert_allclose(table["time"], [0.0, 1.0, 2.0])
    np.testing.assert_allclose(table["force"], [-0.016, -0.015, -0.017])
    assert ("column 'column 1', which has no name, holds clock readings: taken as the time"
            in meta.warnings)
    roles = {column.name: column.role for column in meta.columns}
    assert roles["Single-ended 12 Ave."] is None  # a statistic, not Instron's extensometer


@pytest.mark.parametrize(("date", "clock"), [("Fecha", "Hora"), ("Date", "Heure"),
                                             ("Datum", "Uhrzeit"), ("Tarih", "Saat")])
def test_a_column_of_clock_readings_named_as_none_of_a_time_is_the_time(write, date, clock):
    # a real load-cell log's stamps, split into a date and a clock as Spanish, French,
    # German and Turkish loggers name them: no time was found, the hour's name (Hora,
    # Heure) being that of one part of a clock, the others none the readers know
    text = f"{date};{clock};Fuerza [N]\n" + "".join(
        f"02.04.2024;19:22:{30 + i:02d},{584 + 2 * i:03d};0,{392 + i:03d}\n" for i in range(5))
    table, meta = read_table(write("log.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], np.arange(5) * 1.002, atol=1e-9)
    assert (f"column {clock!r}, whose name the readers do not take for a time, holds clock "
            "readings: taken as the time") in meta.warnings
    # a name of another quantity keeps it from the role
    with pytest.raises(ColumnError, match="no time column found"):
        read_table(write("log.csv", text.replace(clock, "last_changed", 1)), kind="engagement")

def test_tabs_with_empty_cells_stay_tabs_not_blanks():
    # found by the round-trip property: read as blanks, the empty cells would vanish and
    # shift the fields; blanks are the delimiter only when no other gives a table
    lines = ["time\tforce\tgauge 2", "(s)\t(N)\t(mm)", "\t0.0\t0.0", "0.0\t0.0\t", "\t\t",
             "1.5\t1.5"]
    assert detect_dialect(lines, "valid.csv") == ("\t", ".", 3)


def test_names_holding_a_blank_over_columns_aligned_by_spaces(write):
    text = ("Test 12  (preload 20 N)\nTime [s]   Force [kN]   Ext [mm]\n"
            "  0.0   1.5   0.01\n  0.1   1.6   0.02\n\t0.2\t 1.7   0.03  \n")
    table, meta = read_table(write("aligned.txt", text), kind="tensile")
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Time", "s"), ("Force", "kN"), ("Ext", "mm")]
    np.testing.assert_allclose(table["force"], [1500.0, 1600.0, 1700.0])
    np.testing.assert_allclose(table["gauge_1"], [1e-5, 2e-5, 3e-5])


def test_names_apart_by_a_tab_and_blanks_over_columns_aligned_by_spaces(write):
    # a real drop-tower export: each name padded with blanks after its tab
    text = ("     Time [ms]\t  Force [N]\t     Ext [mm]\t\n"
            "    9.499000    12.062190    0.181723\n    9.500000    19.632190    0.221723\n")
    table, meta = read_table(write("T04.txt", text), kind="tensile")
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Time", "ms"), ("Force", "N"), ("Ext", "mm")]
    np.testing.assert_allclose(table["time"], [9.499e-3, 9.5e-3])


def test_blank_and_missing_cells_after_a_comma_and_a_space_are_missing_values(write):
    # a real TestResources export: ", " between the fields, an unused channel left blank
    text = ("\n\nTime (sec), Load (N), Stress (KPa), Strain (mm), Position (mm), Cycle\n"
            "0.000, 0.50, N/A, , 0.113, 1\n0.020, 0.61, N/A, , 0.018, 1\n"
            "0.040, 0.70, N/A, , NaN, 1\n")
    table, meta = read_table(write("sample 1.csv", text), kind="tensile")
    np.testing.assert_allclose(table["force"], [0.50, 0.61, 0.70])
    np.testing.assert_allclose(table["gauge_1"], [0.113e-3, 0.018e-3, np.nan])
    assert "2 empty column(s) dropped: Stress, Strain" in meta.warnings


def test_one_column_of_numbers_is_refused_as_such(write):
    # a logger's key=value settings (none of LineScale's, whose logs are read), then one
    # force per line
    text = "Device=HX711\nUnit=kN\nRate=80\n" + "1\n1.02\n1.05\n0.98\n" * 4
    with pytest.raises(LayoutError, match="one column of numbers") as caught:
        read_table(write("log.csv", text))
    assert "beside the force" in caught.value.hint
    # a short log: more settings lines than readings, the readings last
    short = ("6B:6C:05\n15.05.22\n16:14:25\nDevice=HX711\nUnit=kN\nRate=80\nGain=128\n"
             "Offset=8412\nScale=2280\nTare=1\nFilter=0\nMode=1\n0.12\n0.35\n0.61\n0.40\n0.08\n")
    with pytest.raises(LayoutError, match="one column of numbers"):
        read_table(write("log0.csv", short))


def test_a_table_saved_as_one_quoted_cell_a_line_is_refused_as_such(write):
    # a real transient recorder's export (Elsys TranAX, in German) passed through a
    # program that quoted each line whole: refused as text lines only, with a hint to
    # export the test again
    text = ('"Samplerate;10000000 Hz"\r\n"Zeit;Signal;Signal;"\r\n"s;V;V;"\r\n'
            + "".join(f'"2,{17620 + i}0000e-03;-26,{8750 + i}e-03;-29,3750e-03"\r\n'
                      for i in range(12)))
    with pytest.raises(LayoutError, match="each line is one quoted cell") as caught:
        read_table(write("marble.CSV", text))
    assert "a copy of the file with the quote at the start and at the end of each line " \
        "removed" in caught.value.hint


def test_a_lone_point_is_a_missing_value(write):
    # a real low-cycle fatigue table (SAS export): "." where a half cycle has no value
    text = ('"Cycle","Data State","Max Stress Mpa","Min Stress Mpa","Time Max Stress Sec"\n'
            '1,"CapPass",".",-265.69,"."\n2,"CapPass",283.85,-312.00,70.74\n'
            '3,"CapPass",294.43,-315.45,128.53\n')
    table, meta = read_table(write("HTM_A19_PeakStress.csv", text), kind="engagement",
                             columns={"force": "Max Stress Mpa"}, units={"force": "N"})
    np.testing.assert_allclose(table["force"], [np.nan, 283.85, 294.43])
    np.testing.assert_allclose(table["time"], [np.nan, 70.74, 128.53])
    assert meta.rows == 3


def test_a_quantitys_symbol_before_its_unit_after_an_underscore(write):
    # a script's log of an F/T sensor: t_sec (no time by its name alone), F_N (N alone may
    # number the samples, but after F it is the force's unit)
    table, meta = read_table(write("ft.csv", "t_sec,F_N,x_mm\n0,1,0\n0.1,2,0.1\n"))
    assert [(info.name, info.role, info.unit) for info in meta.columns] == [
        ("t", "time", "sec"), ("F", "force", "N"), ("x", "gauge_1", "mm")]
    np.testing.assert_allclose(table["time"], [0.0, 0.1])


def test_a_force_column_holding_zero_throughout_gives_way_to_the_one_that_moves(write):
    # a LabVIEW tensile log's NLoad (a net load never worked out) reads 0.000000 in every
    # row beside Load: it is no signal, so Load is the force; on fewer rows than it takes
    # to tell, the two are still asked about
    rows = "".join(f"0.000000\t{13.5 * i:.6f}\t{0.1 * i:.6f}\t{0.001 * i:.6f}\n"
                   for i in range(12))
    header = "NLoad\tLoad\tTime\tExt\n"
    units = {"force": "lbf", "gauges": "in"}
    table, meta = read_table(write("Lab10_spec1.dat", header + rows), units=units)
    assert [(column.name, column.role) for column in meta.columns] == [
        ("NLoad", None), ("Load", "force"), ("Time", "time"), ("Ext", "gauge_1")]
    np.testing.assert_allclose(table["force"], 13.5 * np.arange(12) * 4.4482216152605)
    assert ("column 'NLoad' holds one value in every row of the file: no signal, beside one "
            "that moves ('Load'): not used") in meta.warnings[0]
    short = header + "".join(rows.splitlines(keepends=True)[:9])
    with pytest.raises(ColumnError, match="2 columns could be the force: 'NLoad', 'Load'"):
        read_table(write("short.dat", short), units=units)


def test_a_load_loggers_units_after_underscores_and_its_held_peak(write):
    # a real load-cell logger (HX711): '#' before every settings line, the units after an
    # underscore, and the peak held so far beside the reading
    text = ("# Test Name: Test 1\n# Peak Force: 3.379 kN\n# Notes: \n#\n"
            "timestamp_s,current_kN,peak_kN\n0.294,0.068,0.068\n0.830,0.412,0.412\n"
            "1.278,0.250,0.412\n")
    table, meta = read_table(write("Test_1_210645.csv", text), kind="engagement")
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("timestamp", "time", "s"), ("current", "force", "kN"), ("peak", None, "kN")]
    np.testing.assert_allclose(table["force"], [68.0, 412.0, 250.0])
    assert meta.preamble == {"Test Name": "Test 1", "Peak Force": "3.379 kN", "Notes": ""}
    assert ("column 'peak' is a peak held beside the reading itself ('current'): not used "
            '(say otherwise in the run sheet, columns = {force = "..."})') in meta.warnings
    # a name that gives no role keeps a one-letter last word: N may number the samples
    table, meta = read_table(write("n.csv", "time_s,Sample_N,load_kN\n0,1,2\n1,2,3\n"),
                             kind="engagement")
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("time", "time", "s"), ("Sample_N", None, None), ("load", "force", "kN")]


def test_a_results_table_with_its_statistics_is_refused_as_such(write):
    # a real Bluehill Universal results export: one row per specimen, then the statistics
    text = ("TensileTest-Films(V1)\nSample,Young's Modulus (MPa),Max Load (N) (N),Break (%),"
            "Timestamp - Start ,Pellet ID\n17,539.674,11.767,5.621,2026-02-04 11:20:15,EV AB\n"
            "Mean,539.674,11.767,5.621\nSD,0.000,0.000,0.000\nMin,539.674,11.767,5.621\n"
            "Max,539.674,11.767,5.621\n")
    with pytest.raises(LayoutError, match=r"statistics of a batch's results \(Mean, SD, Min, "
                                          r"Max\), not a test's raw data"):
        read_table(write("tensile_sample.csv", text))


def test_a_results_table_numbering_its_rows_is_refused_by_its_statistics(write):
    # a Bluehill results table: the row number first, the specimens' labels numbers too
    # ('009'), the statistics labelled in the second cell; with a gauge-like 'Maximum
    # Extension' it was read as a seven-point curve, the standard deviation a sample
    text = ('"Results Table 1"\n"","Specimen label","Maximum Load","Maximum Extension"\n'
            '"","","(N)","(mm)"\n' + "".join(f'"{row}","00{8 + row}","38{row}0.5","0.45{row}"\n'
                                             for row in range(1, 6))
            + '"","Mean","3830.5","0.453"\n"","Standard Deviation","31.4","0.009"\n')
    with pytest.raises(LayoutError, match=r"statistics of a batch's results \(Mean, "
                                          r"Standard Deviation\)"):
        read_table(write("results.csv", text))


def test_short_row_in_the_middle(write):
    with pytest.raises(LayoutError, match="2 fields where the data rows have 3") as caught:
        read_table(write("t.csv", "time [s],force [kN],gauge [mm]\n0,1,2\n0,1\n0,1,2\n"))
    assert caught.value.row == 3


def test_truncated_last_line_is_dropped_with_a_warning(write):
    table, meta = read_table(write("t.csv", PLAIN + "0.3,0.4"))
    assert len(table) == 3
    assert meta.warnings == ["line 5 is truncated (a half-written last row): dropped"]
    table, meta = read_table(write("t.csv", PLAIN + "0.3,0.4,0.03,"))
    assert len(table) == 3 and "truncated" in meta.warnings[0]


def test_complete_last_line_without_line_end_is_kept(write):
    table, meta = read_table(write("t.csv", PLAIN + "0.3,0.40,0.030,0.031"))
    assert len(table) == 4 and meta.warnings == []


def test_forced_layout(write):
    _, meta = read_table(write("t.csv", PLAIN), format="plain_csv")
    assert meta.layout == "plain_csv"


# a real headerless export (LabVIEW "write to spreadsheet"): tab, decimal comma, no names
HEADERLESS = "1,139302\t305,800815\t1,883096\n1,149302\t-16,572605\t0,317137\n" \
             "1,159302\t-16,572605\t0,314587\n1,174673\t-8,921337\t0,355393\n"
HEADERLESS_SHEET = {
    "columns": {"time": "column 1", "force": "column 2", "gauges": ["column 3"]},
    "units": {"time": "s", "force": "N", "gauges": "mm"}}


def test_a_file_without_names_is_read_by_the_run_sheets_positions(write):
    path = write("data.lvm", HEADERLESS)
    table, meta = read_table(path, kind="tensile", format="csv", **HEADERLESS_SHEET)
    np.testing.assert_allclose(table["time"], [1.139302, 1.149302, 1.159302, 1.174673])
    np.testing.assert_allclose(table["force"], [305.800815, -16.572605, -16.572605, -8.921337])
    np.testing.assert_allclose(table["gauge_1"], [1.883096e-3, 0.317137e-3, 0.314587e-3,
                                                  0.355393e-3])
    assert (meta.header_line, meta.first_data_line) == (None, 1)
    assert [(column.name, column.role) for column in meta.columns] == [
        ("column 1", "time"), ("column 2", "force"), ("column 3", "gauge_1")]
    reader = open_log(path, kind="tensile", format="csv", **HEADERLESS_SHEET)
    np.testing.assert_array_equal(reader.read(1, 4)[0]["force"], table["force"][1:4])
    # a bad cell is in the column the run sheet calls it
    with pytest.raises(ValueParseError) as caught:
        read_table(write("bad.lvm", HEADERLESS.replace("-8,921337", "x")), kind="tensile",
                   format="csv", **HEADERLESS_SHEET)
    assert (caught.value.row, caught.value.column) == (4, "column 2")


def test_a_file_without_names_gets_no_role_from_a_position(write):
    path = write("data.csv", "0.0,1.5,0.01\n0.1,2.5,0.02\n")
    with pytest.raises(LayoutError, match="no names row") as caught:  # nothing named
        read_table(path, kind="tensile")
    assert 'columns = {time = "column 1", force = "column 2"}' in caught.value.hint
    # a mooring chain logger's columns are raw counts: the units are not theirs to give
    assert "raw counts or volts are converted to a force" in caught.value.hint
    # a role the run sheet names is read; the others are not guessed from their place
    with pytest.raises(ColumnError, match="no gauge column found") as missing:
        read_table(path, kind="tensile", columns={"force": "column 2"}, units={"force": "kN"})
    assert "the file has: column 1, column 2, column 3" in missing.value.hint


# a real Imada force recorder's high-rate export: its settings as KEY = value, then the
# force and displacement with no names row; its last setting was read as the names
IMADA = ("MAX FORCE = 195.5,3.965\nMIN FORCE = -1.4,0.000\nUNIT = gf,mm\n"
         "RECORDING RATE = 0.0005,\n1ST PEAK FORCE = ---,---\n2ND PEAK FORCE = ---,---\n"
         "0.0,0.000\n12.5,0.125\n25.1,0.250\n37.4,0.375\n")


def test_settings_as_key_equals_value_above_the_data_are_no_names_row(write):
    path = write("X_Green_HighResolutionRaw.csv", IMADA)
    with pytest.raises(LayoutError, match="no names row above the first data row") as caught:
        read_table(path, kind="tensile")
    assert caught.value.row == 7
    table, meta = read_table(path, kind="tensile",
                             columns={"force": "column 1", "gauges": ["column 2"]},
                             units={"force": "gf", "gauges": "mm"})
    np.testing.assert_allclose(table["force"], 9.80665e-3 * np.array([0.0, 12.5, 25.1, 37.4]))
    np.testing.assert_allclose(table["gauge_1"], [0.0, 1.25e-4, 2.5e-4, 3.75e-4])
    assert meta.header_line is None and meta.preamble["UNIT"] == "gf mm"


def test_a_record_of_another_width_opening_a_file_of_numbers_is_its_preamble(write):
    # a real Chinese controller's export: a count and a date serial, then rows of six
    # (force [N], two zeros, displacement [mm], rate, time [ms]); the leading record was
    # read as a data row, and the file refused until it was edited
    head = " 1.0E+0001  4.23738071504167E+0004  0.0E+0000  0.0E+0000  0.0E+0000\n"
    body = "".join(f" {8.0 + i}  0.0  0.0  {0.9e-3 * (i + 1):.6E}  0.3  {79 + 62 * i}\n"
                   for i in range(5))
    path = write("force-displacement.txt", head + body)
    with pytest.raises(LayoutError, match="no names row above the first data row") as caught:
        read_table(path, kind="tensile")
    assert caught.value.row == 2
    table, meta = read_table(path, kind="tensile",
                             columns={"time": "column 6", "force": "column 1",
                                      "gauges": ["column 4"]},
                             units={"time": "ms", "force": "N", "gauges": "mm"})
    np.testing.assert_allclose(table["force"], [8.0, 9.0, 10.0, 11.0, 12.0])
    np.testing.assert_allclose(table["time"], [0.079, 0.141, 0.203, 0.265, 0.327])
    assert ("line 1: a record of 5 numbers opens the file, before rows of 6: passed over as "
            "its preamble") in meta.warnings


def test_a_raw_reading_without_a_unit_gives_way_to_the_force_in_newtons(write):
    # a real DIY tensile tester (HX711): the load cell's counts before the force in N
    text = ("time_s;steps;displacement_mm;force_raw;force_N\n390.355;1;0.0050;1524;0.338\n"
            "390.455;1;0.0050;1491;0.331\n390.555;2;0.0100;2513;0.557\n")
    table, meta = read_table(write("PETG_522_001.CSV", text), kind="tensile")
    np.testing.assert_allclose(table["force"], [0.338, 0.331, 0.557])
    assert ("column 'force_raw' has no unit of force beside one that has ('force'): not used "
            '(say otherwise in the run sheet, columns = {force = "..."})') in meta.warnings


def test_a_column_named_by_a_unit_of_force_holds_the_force(write):
    # a real pull tester's log: its readings in newtons under "Newtons"
    table, meta = read_table(write("15022019-112813.csv",
                                   "Distance, Newtons\n0.00, 0.00\n0.10, 1.52\n"),
                             kind="engagement", columns={"time": "Distance"},
                             units={"time": "s"})
    np.testing.assert_allclose(table["force"], [0.0, 1.52])
    assert "column 'Newtons': unit 'Newtons' from its name" in meta.warnings


# a real Japanese logger's header (Tokyo Sokki): strain gauges in "μ", microstrain there
JAPANESE_STRAIN = ("名前,測定日時 ,荷重 kN,変位 mm,表-縦 {unit},表-横 {unit}\n"
                   "1,2019/11/01 17:06:57,0.064,-0.004,-0.947867,0.947418\n"
                   "2,2019/11/01 17:06:59,0.104,0,0.947867,0.947418\n")


def test_a_micro_sign_alone_is_no_unit_and_its_column_is_warned_of(write):
    path = write("H300CP_No1.csv", JAPANESE_STRAIN.format(unit="μ"), "cp932")
    _, meta = read_table(path, kind="tensile")
    assert [(column.name, column.role, column.unit) for column in meta.columns][2:] == [
        ("荷重", "force", "kN"), ("変位", "gauge_1", "mm"), ("表-縦", None, "μ"),
        ("表-横", None, "μ")]
    assert ("column '表-縦' reads in 'μ', a micro sign alone, micrometres (µm) or "
            "microstrain (µε), but its name is not one the readers know: not used (if it is "
            'an extensometer\'s strain, name it in the run sheet, columns = {gauges = '
            '["表-縦"]}, units = {gauges = ["µε"]})') in meta.warnings
    assert not any("表-横" in warning for warning in meta.warnings)  # transverse
    table, _ = read_table(path, kind="tensile", columns={"gauges": ["表-縦"]},
                          units={"gauges": "µε"})
    np.testing.assert_allclose(table["strain_1"], [-0.947867e-6, 0.947867e-6])
    with pytest.raises(UnitError, match="unknown unit 'μ' in the file: a micro sign alone"):
        read_table(path, kind="tensile", columns={"gauges": ["表-縦"]})


def test_a_ton_is_no_unit_for_the_tonne_force_or_the_short_ton_it_may_be(write):
    # a Spanish machine's "Carga (ton)" is in tonnes-force; pint's ton, 2000 lb, read it
    # 9 % low, told only as "the force of its weight"
    path = write("ensayo.csv", "Tiempo (s);Carga (ton);Desplazamiento (mm)\n"
                               "0,00;0,012248;0,00688\n0,10;0,012508;0,00723\n")
    with pytest.raises(UnitError, match=r"unknown unit 'ton' in the file: a ton, the metric "
                                        r"tonne \(write t or tf\), the US short ton"):
        read_table(path, kind="tensile")
    table, _ = read_table(path, kind="tensile", units={"force": "tf"})
    np.testing.assert_allclose(table["force"], [0.012248 * 9806.65, 0.012508 * 9806.65])


def test_microstrain_is_a_strain(write):
    text = JAPANESE_STRAIN.format(unit="με").replace("表-縦 με", "表-縦 ひずみ με")
    table, meta = read_table(write("H300CP_No1.csv", text, "cp932"), kind="tensile")
    np.testing.assert_allclose(table["strain_1"], [-0.947867e-6, 0.947867e-6])
    assert meta.columns[4].unit == "με"


def test_a_role_word_ending_a_name_is_no_unit(write):
    # a real logger's tab file: 'Ext Strain' in microstrain, no unit anywhere; 'Strain'
    # read as its unit (a ratio) made -46.5 µε a strain of -46.5
    text = "Time\tForce\tExt Strain\n0.0\t0.026\t-46.527\n1.0\t2.996\t-47.500\n"
    _, meta = read_table(write("log.txt", text), kind="tensile", strict=False)
    column = next(info for info in meta.columns if info.name == "Ext Strain")
    assert (column.role, column.unit) == ("gauge_1", None)
    table, _ = read_table(write("log.txt", text), kind="tensile",
                          units={"time": "s", "force": "N", "gauges": "µε"})
    np.testing.assert_allclose(table["strain_1"], [-46.527e-6, -47.5e-6])


@pytest.mark.parametrize(("name", "unit", "role"), [("load", "psi", "force"),
                                                    ("speed", "RPM", "speed")])
def test_a_unit_of_another_quantity_after_a_name_is_its_unit_and_refused(write, name, unit,
                                                                           role):
    # a hydraulic rig's 'load_psi' lost its unit ("the file gives none"), and a force unit
    # in the run sheet then read the pressure as a force without a word
    text = f"Time,{name}_{unit},Stroke\n0,1,0\n0.1,2,0.1\n"
    _, meta = read_table(write("rig.csv", text), kind="wear", strict=False)
    assert {info.name: info.unit for info in meta.columns}[name] == unit
    assert f"column {name!r}: unit {unit!r} is not a unit of {role}" in " ".join(meta.warnings)


def test_a_prefix_written_out_before_a_unit_is_part_of_it(write):
    # a real nanoindenter's export: micronewtons as load_micro_N, nanometres as depth_nm
    text = "depth_nm,load_micro_N,time_s\n0.5,1.0,0.0\n12.0,2.0,0.1\n25.0,3.0,0.2\n"
    table, meta = read_table(write("indent_1_1.csv", text), kind="tensile")
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("depth", "gauge_1", "nm"), ("load", "force", "µN"), ("time", "time", "s")]
    np.testing.assert_allclose(table["force"], [1e-6, 2e-6, 3e-6])
    np.testing.assert_allclose(table["gauge_1"], [0.5e-9, 12e-9, 25e-9])


def test_a_status_line_narrower_than_the_data_is_no_names_row(write):
    # a real home-built rig's log: a settings line and status lines, no names row
    text = ("L0 = 81,2;d = 2,25;Polymer PVC\n ;TEMP:;T:21.6 /0.0 B:0.0 @:0 B\n"
            "38354132;11:02:46;2,8;0,0\n57745416;11:02:47;1,4;0,5\n"
            "54460604;11:02:48;0,4;1,0\n")
    path = write("some 18 Nov 11,02,38.csv", text)
    with pytest.raises(LayoutError, match="no names row above the first data row") as caught:
        read_table(path, kind="tensile")
    assert caught.value.row == 3
    table, _ = read_table(path, kind="tensile",
                          columns={"force": "column 3", "gauges": ["column 4"]},
                          units={"force": "N", "gauges": "mm"})
    np.testing.assert_allclose(table["force"], [2.8, 1.4, 0.4])
    # a names row that names its columns stays one, an unnamed last column beside it
    table, meta = read_table(write("t.csv", "time [s],force [kN]\n0,1,7\n1,2,8\n"),
                             kind="engagement")
    np.testing.assert_allclose(table["force"], [1000.0, 2000.0])


@pytest.mark.parametrize("names, time", [
    # a rocket test stand's group.channel names: temps.T1 its thermocouple
    ("time.elapsedTime (s),temps.T1,loads.L1 (N)", "time.elapsedTime"),
    # its temperatures under the English plural, in a unit of temperature
    ("elapsed (s),temps (°C),load (N)", "elapsed"),
    # without a unit, beside a time that has one
    ("elapsed (s),temps,load (N)", "elapsed"),
])
def test_english_temps_are_no_french_time(write, names, time):
    text = names + "\n0.0,21.5,0\n0.1,21.6,40\n0.2,21.6,80\n0.3,21.7,40\n"
    table, meta = read_table(write("testData.csv", text), kind="engagement")
    assert [column.name for column in meta.columns if column.role == "time"] == [time]
    np.testing.assert_allclose(table["time"], [0.0, 0.1, 0.2, 0.3])
    assert not any("°C" in warning for warning in meta.warnings)


def test_a_force_plates_external_inputs_are_no_extensometers(write):
    # a force plate logger's trigger inputs, ExtIn1 and ExtIn2 (1 in every row), beside Fz
    text = "Fz (N),ExtIn1,ExtIn2,Disp (mm)\n10,1,1,0.0\n20,1,1,0.1\n30,1,1,0.2\n"
    _, meta = read_table(write("a05.csv", text), kind="tensile")
    assert [(column.name, column.role) for column in meta.columns] == [
        ("Fz", "force"), ("ExtIn1", None), ("ExtIn2", None), ("Disp", "gauge_1")]


def test_a_loggers_stamped_messages_are_no_names_and_units_rows(write):
    # a real gas-spring rig's serial log: every line stamped, messages above the readings;
    # "... - Load cell tared." was the names row (a force by its word Load) and
    # "... - Testing started..." its units row
    text = ("2025-01-17 13:06:19 - Parameters loaded from EEPROM.\n"
            "2025-01-17 13:06:19 - 1000\n2025-01-17 13:06:21 - Load cell tared.\n"
            "2025-01-17 13:06:26 - Testing started...\n"
            + "".join(f"2025-01-17 13:06:{26 + i} - 0, {i / 100}, 255\n" for i in range(6)))
    with pytest.raises(LayoutError, match="no names row above the first data row") as caught:
        read_table(write("data_logger_3.txt", text))
    assert caught.value.row == 5


def test_the_files_units_do_not_choose_a_time_whose_unit_the_run_sheet_gives(write):
    # the run sheet's unit is for the column the file left without one, maybe: which that
    # is, only the run sheet's columns can say
    text = "elapsed (s),time,load (N)\n0.0,0,0\n0.1,100,40\n0.2,200,80\n"
    with pytest.raises(ColumnError, match="2 columns could be the time: 'elapsed', 'time'"):
        read_table(write("testData.csv", text), kind="engagement", units={"time": "ms"})
    table, _ = read_table(write("testData.csv", text), kind="engagement",
                          columns={"time": "time"}, units={"time": "ms"})
    np.testing.assert_allclose(table["time"], [0.0, 0.1, 0.2])


def test_a_clock_beats_a_time_without_a_unit(write):
    # a smart insole's app export: its clock beside each step's Contact_time (ms, no unit,
    # up and down), which was taken as the time, read as seconds "counted"
    text = ("App_time;Insole_timer;Contact_time;S0_force (N)\n19:58:24.290;0;880;94\n"
            "19:58:25.308;1220;680;108\n19:58:26.309;2230;660;114\n")
    table, meta = read_table(write("insole.csv", text), kind="engagement")
    assert [column.name for column in meta.columns if column.role == "time"] == ["App_time"]
    np.testing.assert_allclose(table["time"], [0.0, 1.018, 2.019])
