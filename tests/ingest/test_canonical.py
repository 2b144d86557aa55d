"""Roles, SI units and the layout-independent checks of the canonical table."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pipeline.errors import ColumnError, UnitError
from pipeline.ingest import open_log, parse_table, read_table

HEADER = "time [s],force [kN],gauge1 [mm]\n"


def rows(*values):
    return "".join(",".join(str(v) for v in row) + "\n" for row in values)


def test_sentinels_become_nan_and_empty_channels_are_dropped(write):
    text = ("time [s],force [kN],gauge1 [mm],gauge2 [mm],Winkel [deg]\n"
            + rows((0, 1, 0.1, -999999, -1000000), (1, 2, 0.2, -999999, -1000000),
                   (2, -1000000, 0.3, -999999, -1000000)))
    table, meta = read_table(write("s.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    assert np.isnan(table["force"][2])
    assert sum("sentinel" in warning for warning in meta.warnings) == 3
    assert "2 empty column(s) dropped: gauge2, Winkel" in meta.warnings
    # a Yokogawa recorder's declared over-range codes are no readings either
    over = rows((0, 1, 0.1), (1, 999999999, 0.2), (2, 3, -999999999))
    table, meta = read_table(write("gp10.csv", "time [s],force [kN],gauge1 [mm]\n" + over))
    assert np.isnan(table["force"][1]) and np.isnan(table["gauge_1"][2])
    assert ("column 'gauge1': 1 sentinel values (-1e+09, Yokogawa recorder under-range "
            "marker) set to NaN") in meta.warnings


def test_nan_stretch_is_reported_with_count_and_longest_run(write):
    text = HEADER + rows((0, 1, 0), (1, "", 0), (2, "NaN", 0), (3, 4, 0), (4, "", 0), (5, 6, 0))
    table, meta = read_table(write("n.csv", text))
    assert int(table["force"].isna().sum()) == 3
    assert meta.warnings == [
        "force: 3 missing values kept as NaN; longest run 2 rows from line 3"
    ]


def test_a_second_pull_appended_without_time_is_told(write):
    # a real UTM's headerless force,displacement export: the next specimen's curve follows
    # the fracture, its displacement back at zero in one row
    first = [(20 * step, round(0.05 * step, 2)) for step in range(180)]
    second = [(5 * step, round(0.05 * step, 2)) for step in range(20)]
    text = "Force (N),Displacement (mm)\n" + rows(*first, *second)
    _, meta = read_table(write("spliced.csv", text))
    assert meta.warnings == [
        "gauge_1: crosses 100% of its range in one step, from 0.00895 m to 0 m at line 182, "
        "where its median step is 0.56% of it: a second test appended below the first, or a "
        "gauge taken off or reset? The file has no time to tell; give each test its own file"]


def test_a_gauge_of_peaks_and_valleys_jumps_without_a_word(write):
    # a fatigue log of the peak and valley of each cycle: every step crosses the range
    text = "Force (kN),Displacement (mm)\n" + rows(*[(10 * (row % 2), 2.0 * (row % 2))
                                                     for row in range(40)])
    _, meta = read_table(write("peaks.csv", text))
    assert not any("of its range in one step" in warning for warning in meta.warnings)


def test_a_row_of_settings_over_the_samples_is_told(write):
    # a real F/T sensor's script log: rate, samples per channel and timer over the forces
    text = "Fx [mm],Fz [N]\n150,500\n" + rows(*[(0.01 * (row % 7), 0.2 + 0.01 * row)
                                                for row in range(30)])
    table, meta = read_table(write("ft.csv", text), columns={"force": "Fz", "gauges": ["Fx"]})
    assert table["force"].iloc[0] == 500.0  # read, and told
    assert meta.warnings == [
        "line 2, the first data row, is unlike the rows below it: in 2 of 2 columns its value "
        "lies outside their range by over ten times it. A row of settings (a rate, a count) "
        "written above the samples? It is read as the first sample: delete it from a copy of "
        "the file if it is none"]


def test_a_pull_that_starts_with_a_jump_in_force_alone_is_no_settings_row(write):
    # the load cell tared at zero, the specimen preloaded from the second sample
    text = HEADER + rows(*[(0.1 * row, 0.0 if row == 0 else 10 + 0.001 * row, 0.01 * row)
                           for row in range(40)])
    _, meta = read_table(write("preload.csv", text))
    assert meta.warnings == []


def test_a_column_of_one_value_beside_the_first_sample_is_no_channel(write):
    # a real steel pull: the specimen's diameters written beside the first sample only,
    # read as gauges by their unit; the run refused them as channels that dropped out
    text = ("Time (s),Extension (mm),Load (kN),Original Diameter (mm)\n0,0,0.1,7.13\n"
            + rows(*[(0.5 * row, 0.03 * row, 0.1 + row, "") for row in range(1, 12)]))
    table, meta = read_table(write("steel.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    assert ("column 'Original Diameter' holds one value (7.13, line 2) over 12 rows: a "
            "specimen's dimension or a setting, no channel: not used") in meta.warnings


@pytest.mark.parametrize(("text", "said"), [
    # a real acoustic analyser's force spectrum: its rows are frequencies, and the hint
    # asked for a time without a word on them
    ("Frequency [Hz],Force [N],Phase [deg]\n20.0,96.77,36.74\n20.3,96.81,36.07\n",
     "column 'Frequency' is in Hz: a spectrum or a frequency sweep, whose rows are "
     "frequencies, has no time and is no test record"),
    # a real HX711 load-cell log's 'Value [kg]': the hint listed the columns, not that this
    # one may be the load (a temperature in kg is none)
    ("time [s],Value [kg],Temperature [kg]\n0,1.5,20\n1,2.5,21\n",
     "column 'Value' is in kg, a mass: if it is the load, name it as the force (read as "
     "the weight of that mass); the file has"),
    # a real pull-test dynamometer's 'time,weight' (kg, but the file does not say)
    ("time [s],weight\n0.0,5.35\n0.1,7.12\n",
     "column 'weight' is named as a weight, with no unit: if it is the load, name it as the "
     "force with its unit (a mass's, kg or g, is read as the weight of that mass); the file "
     "has"),
    # a real KEYENCE logger's input in volts: the hint asked for the force by name only
    ("time [s],Voltage01 [V]\n0.0,-0.127\n0.05,-0.125\n",
     "column 'Voltage01' is in V, a sensor's signal: if it is the load, convert it to a "
     "force with the sensor's calibration first (the readers apply none); the file has"),
    # a load cell's bridge output, which pint reads as a plain ratio
    ("time [s],Excitation [mV/V]\n0.0,0.127\n0.05,0.125\n",
     "column 'Excitation' is in mV/V, a sensor's signal: if it is the load, convert it to a "
     "force with the sensor's calibration first (the readers apply none); the file has"),
])
def test_the_hint_of_a_missing_role_says_what_a_column_may_be(write, text, said):
    with pytest.raises(ColumnError) as caught:
        read_table(write("log.txt", text), kind="engagement")
    assert said in caught.value.hint


def test_an_accelerometer_in_g_is_not_offered_as_a_load(write):
    # a real WitMotion drop-test logger's ax(g): the hint offered it as the load, read as the
    # weight of grams (its 6.4 g shock as 0.063 N)
    text = "Time(s)\tax(g)\tay(g)\taz(g)\n0.000\t-0.26\t-0.56\t1.06\n0.005\t-0.25\t-0.55\t1.05\n"
    with pytest.raises(ColumnError) as caught:
        read_table(write("drop.txt", text), kind="engagement")
    assert "a mass" not in caught.value.hint
    assert "ax" in caught.value.hint  # still listed among the file's columns


def test_time_backwards_and_gaps_are_warnings(write):
    text = HEADER + rows(*[(t, 1, 0) for t in (0.0, 0.1, 0.2, 0.15, 0.3, 0.4, 9.0, 9.1)])
    _, meta = read_table(write("t.csv", text))
    assert meta.time_monotonic is False and meta.time_gaps == 1
    assert "steps back 1 times, first at line 5" in meta.warnings[0]
    assert "first before line 8" in meta.warnings[1]


def test_a_time_stepping_back_often_is_told_as_maybe_no_time(write):
    # a real balance logger's 'elapsed_s': each request's latency, back in 21 of 29 steps;
    # told as a time starting again because one step landed near the first value
    latency = [0.112, 0.095, 0.131, 0.088, 0.125, 0.097, 0.14, 0.091, 0.118, 0.102]
    text = "elapsed_s,mass_g,stroke_mm\n" + rows(*[(value, 10 + row, 0.1 * row)
                                                  for row, value in enumerate(latency)])
    _, meta = read_table(write("balance.csv", text), kind="tensile", strict=False)
    assert ("time: steps back 5 times, first at line 3 (in 5 of 9 steps: a time runs "
            "forward, so the column may be no time; name the time in the run sheet, "
            "columns = {time = \"...\"})") in meta.warnings


def test_the_gaps_of_a_time_without_unit_are_told_without_one(write):
    # a DIC rig's camera clock with no unit: its gaps were told in seconds
    text = "Time\tKuvvet(N)\n" + "".join(f"{t}\t{f}\n" for t, f in ((0, 1), (1, 2), (2, 3),
                                                                       (3, 4), (40, 5)))
    _, meta = read_table(write("frames.txt", text), strict=False)
    assert ("time: 1 gap(s) longer than 10 x the median step (1 (no unit given)), the longest "
            "37 (no unit given), first before line 6") in meta.warnings


def test_a_time_without_unit_is_still_checked_for_steps_back(write):
    # a real Turkish rebar tester stacks its specimens one below the other, its time
    # column (Zaman) without a unit: what `chainbench inspect` shows of it (a run refuses
    # the file until the run sheet gives the unit) includes the second specimen's restart
    text = "Zaman\tKuvvet(N)\tCetvel(mm)\n" + "".join(
        f"{t}\t{f}\t{g}\n" for t, f, g in ((0.1, 1, 0), (0.2, 2, 1), (0.3, 3, 2), (0.1, 1, 0)))
    table, meta = read_table(write("stacked.dru", text), strict=False)
    assert "time" not in table
    assert meta.time_monotonic is False
    assert any("no unit for the time column" in warning for warning in meta.warnings)
    assert ("time: steps back 1 times, first at line 5 (back to the first sample's time: "
            "the time starts again, as a cycle's or a step's own time does, or as the next "
            "test's in a file of tests one after another)") in meta.warnings


def test_none_marks_a_missing_value(write):
    table, meta = read_table(write("none.csv", HEADER + rows((0, "none", 0), (1, 2, "None"))))
    assert table["force"].isna().tolist() == [True, False]
    assert table["gauge_1"].isna().tolist() == [False, True]


def test_infinite_values_are_told_with_their_first_line(write):
    # a script's log: numpy writes an overflow or a division by zero as inf, -inf
    text = HEADER + rows((0, -1, 0.1), (1, "inf", 0.2), (2, "", "-inf"), (3, "-inf", 0.4))
    table, meta = read_table(write("script.csv", text))
    assert np.isinf(table["force"]).sum() == 2 and np.isinf(table["gauge_1"]).sum() == 1
    assert ("force: 2 infinite values (Inf or -Inf, a script's overflow or division by "
            "zero), the first at line 3") in meta.warnings
    assert ("gauge_1: 1 infinite values (Inf or -Inf, a script's overflow or division by "
            "zero), the first at line 4") in meta.warnings


@pytest.mark.parametrize("error", ["#VALUE!", "#DIV/0!", "#REF!", "#NUM!", "#NAME?", "#NULL!"])
def test_a_spreadsheet_formulas_error_value_marks_a_missing_value(write, error):
    # a structures lab's record worked over in Excel: a failed formula in the first row was
    # taken for a second table's names row, and the file refused
    text = HEADER + rows((0, 1, error), (1, 2, 3), (2, 3, 4))
    table, meta = read_table(write("xl.csv", text))
    assert table["gauge_1"].isna().tolist() == [True, False, False]
    assert "gauge_1: 1 missing values kept as NaN; longest run 1 rows from line 2" in meta.warnings


def test_run_sheet_units_fill_missing_units_and_override_with_warning(write):
    text = "time,force [kN],gauge1\n" + rows((0, 1, 2), (1, 2, 3))
    table, meta = read_table(write("u.csv", text),
                             units={"time": "ms", "force": "daN", "gauges": ["um"]})
    np.testing.assert_allclose(table["time"], [0.0, 1e-3])
    np.testing.assert_allclose(table["force"], [10.0, 20.0])
    np.testing.assert_allclose(table["gauge_1"], [2e-6, 3e-6])
    assert "'daN' from the run sheet replaces 'kN'" in meta.warnings[0]


def test_a_run_sheet_unit_of_another_quantity_than_the_files_is_warned_of_as_such(write):
    # a logger's pressure channel named as the force: the run sheet's kN is used, and the
    # warning says the file's MPa is no force, not that one unit of force replaced another
    text = "time [s],p [MPa],gauge [mm]\n" + rows((0, 1, 2), (1, 2, 3))
    table, meta = read_table(write("p.csv", text), columns={"force": "p"},
                             units={"force": "kN"})
    np.testing.assert_allclose(table["force"], [1e3, 2e3])
    assert ("column 'p': the file gives it in 'MPa', no unit of force; read in 'kN' as the run "
            "sheet says: check that it is the force column (columns = ...) and that its "
            "numbers are in 'kN'") in meta.warnings


def test_missing_unit_error_names_column_and_run_sheet_key(write):
    with pytest.raises(UnitError) as caught:
        read_table(write("u.csv", "time [s],force,gauge1 [mm]\n" + rows((0, 1, 2))))
    error = caught.value
    assert (error.row, error.column) == (1, "force")
    assert 'units = {force = "..."}' in error.hint


def test_lenient_mode_keeps_going(write):
    table, meta = read_table(write("u.csv", "time [s],force,gauge1 [mm]\n" + rows((0, 1, 2))),
                             strict=False)
    assert list(table.columns) == ["time", "gauge_1"]
    assert meta.columns[1].role == "force" and meta.columns[1].unit is None
    assert "no unit for the force column" in meta.warnings[0]


def test_wrong_dimension_of_a_named_column_is_skipped_with_warning(write):
    text = "time [s],force [kN],gauge1 [mm],Weg [kN]\n" + rows((0, 1, 2, 3))
    table, meta = read_table(write("d.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    assert "unit 'kN' is not a unit of gauge" in meta.warnings[0]


@pytest.mark.parametrize(("unit", "factor"), [("%", 0.01), ("mm/mm", 1.0), ("µm/m", 1e-6)])
def test_a_gauge_in_a_ratio_unit_is_a_strain_channel(write, unit, factor):
    text = f"time [s],force [kN],Traverse [mm],Dehnung [{unit}]\n" + rows((0, 1, 2, 3))
    table, meta = read_table(write("d.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1", "strain_1"]
    assert table["strain_1"].iloc[0] == pytest.approx(3 * factor)
    kinds = {column.role: (column.kind, column.si_unit) for column in meta.columns}
    assert kinds["gauge_1"] == ("crosshead", "m") and kinds["strain_1"] == ("extensometer", "1")


@pytest.mark.parametrize("name", ["Dehnung", "strain"])
def test_a_strain_written_dimensionless_is_a_ratio_and_a_length_so_written_is_refused(
        write, name):
    """``Dehnung [-]``: an engineer's dimensionless strain; ``-`` over a length is no unit."""
    text = f"time [s],force [kN],{name} [-]\n" + rows((0, 1, 0.002), (1, 2, 0.004))
    table, meta = read_table(write("d.csv", text))
    assert table["strain_1"].tolist() == [0.002, 0.004]
    assert (f"column {name!r}: unit '-' read as a ratio (mm/mm): a strain written "
            "dimensionless") in meta.warnings
    with pytest.raises(UnitError, match="'-'"):
        read_table(write("e.csv", text.replace(f"{name} [-]", "Traverse [-]")))


def test_repeated_time_stamps_are_a_warning_with_the_line(write):
    table, meta = read_table(write("t.csv", "time [s],force [kN],gauge [mm]\n"
                                   + rows((0, 1, 2), (0, 2, 3), (1, 3, 4))))
    assert len(table) == 3 and meta.time_monotonic
    assert meta.warnings == ["time: 1 repeated time stamp(s), first at line 3"]


def test_unit_decides_role_of_an_unknown_name(write):
    table, _ = read_table(write("x.csv", "t [s];F [kN];s1 [mm];s2 [mm]\n0;1;2;3\n"))
    assert list(table.columns) == ["time", "force", "gauge_1", "gauge_2"]


def test_explicit_columns_and_gauge_order(write):
    text = "a [s],b [kN],c [mm],d [mm]\n" + rows((0, 1, 2, 3))
    table, meta = read_table(write("e.csv", text),
                             columns={"time": "A", "force": "b", "gauges": ["d", "c"]})
    np.testing.assert_allclose(table[["gauge_1", "gauge_2"]].to_numpy(), [[3e-3, 2e-3]])
    assert [c.role for c in meta.columns] == ["time", "force", "gauge_2", "gauge_1"]


def test_explicit_column_missing_lists_columns(write):
    with pytest.raises(ColumnError, match="no column 'Kraft'") as caught:
        read_table(write("e.csv", HEADER + rows((0, 1, 2))), columns={"force": "Kraft"})
    assert caught.value.hint == "the file has: time, force, gauge1"


def test_unknown_role_key(write):
    with pytest.raises(ColumnError, match="unknown role 'stress'"):
        read_table(write("e.csv", HEADER + rows((0, 1, 2))), columns={"stress": "force"})


def test_engagement_needs_time(write):
    with pytest.raises(ColumnError, match="no time column"):
        read_table(write("e.csv", "force [kN],gauge [mm]\n" + rows((1, 2))), kind="engagement")


def test_invalid_kind():
    with pytest.raises(ValueError, match="kind"):
        read_table(__file__, kind="fatigue")


def _time_warnings_step_by_step(time: list[float]) -> tuple[bool, int, list[str]]:
    """The time checks of the canonical table, step by step: the reference for the
    vectorised checks (rows from line 2, under a one-line header)."""
    steps = [later - earlier for earlier, later in zip(time, time[1:], strict=False)]
    found = []  # the step into row r (0-based) is on line r + 2
    back = [line for line, step in enumerate(steps, 3) if step < 0]
    if back:
        first_step = time[1] - time[0]  # row r is on line r + 2
        again = first_step > 0 and any(abs(time[line - 2] - time[0]) <= 2 * first_step
                                       for line in back)
        found.append(f"time: steps back {len(back)} times, first at line {back[0]}" + (
            f" (in {len(back)} of {len(steps)} steps: a time runs forward, so the column may "
            "be no time; name the time in the run sheet, columns = {time = \"...\"})"
            if len(back) >= 3 and 4 * len(back) >= len(steps) else
            " (back to the first sample's time: the time starts again, as a cycle's or a "
            "step's own time does, or as the next test's in a file of tests one after "
            "another)" if again else ""))
    repeated = [line for line, step in enumerate(steps, 3) if step == 0]
    if repeated:
        found.append(f"time: {len(repeated)} repeated time stamp(s), first at line "
                     f"{repeated[0]}")
    positive = [step for step in steps if step > 0]
    if not positive:
        return not back, 0, found
    median = float(np.median(positive))
    gaps = [line for line, step in enumerate(steps, 3) if step > 10 * median]
    if gaps:
        longest = max(step for step in steps if step > 10 * median)
        found.append(f"time: {len(gaps)} gap(s) longer than 10 x the median step "
                     f"({median:.3g} s), the longest {longest:.3g} s, first before line "
                     f"{gaps[0]}")
    return not back, len(gaps), found


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from([1.0, 1.0, 1.0, 0.0, -0.5, 25.0, math.nan]), min_size=2,
                max_size=30))
def test_time_checks_agree_with_a_step_by_step_reading(steps):
    time = [0.0]
    for step in steps:
        time.append(math.nan if math.isnan(step) else
                    (time[-1] if math.isfinite(time[-1]) else len(time)) + step)
    text = "time [s],force [kN],gauge1 [mm]\n" + "".join(
        f"{'' if math.isnan(t) else t},1,0\n" for t in time)
    _, meta = parse_table(text.encode())
    monotonic, gaps, expected = _time_warnings_step_by_step(time)
    assert (meta.time_monotonic, meta.time_gaps) == (monotonic, gaps)
    assert [w for w in meta.warnings
            if w.startswith("time: ") and "missing values" not in w] == expected


def test_instron_video_extensometer_is_the_strain_and_machine_displacement_the_crosshead(write):
    # Instron Bluehill and WaveMatrix: "AVE" (Advanced Video Extensometer) in %, beside the
    # actuator's travel; before, AVE was no role and E0 came from the crosshead unwarned
    text = ("Time (s),Displacement (mm),Force (kN),AVE 2 (%),Machine Displacement (mm)\n"
            + rows((0, 1, 2, 3, 4)))
    table, meta = read_table(write("ave.csv", text))
    assert sorted(table.columns) == ["force", "gauge_1", "gauge_2", "strain_1", "time"]
    assert table["strain_1"].iloc[0] == pytest.approx(0.03)
    kinds = {column.name: column.kind for column in meta.columns}
    assert kinds["AVE 2"] == "extensometer" and kinds["Machine Displacement"] == "crosshead"
    assert kinds["Displacement"] == "gauge"


def test_a_strain_without_unit_is_refused_with_a_hint_that_works(write):
    # a real Instron 8852 export: the extensometer in mm beside its strain with no unit
    text = ("Time,Displacement,Force,Engineering Strain\ns,mm,kN,\n"
            + rows((0, 0.1, 1, 0.004), (1, 0.2, 2, 0.008)))
    path = write("strain.csv", text)
    with pytest.raises(UnitError, match="no unit for the gauge column") as error:
        read_table(path, kind="tensile")
    hint = error.value.hint
    assert "ratio or in %" in hint and 'units = {gauges = ["mm", "1"' in hint
    table, _ = read_table(path, kind="tensile", units={"gauges": ["mm", "1"]})
    assert table["strain_1"].tolist() == [0.004, 0.008]
    table, _ = read_table(path, kind="tensile", columns={"gauges": ["Displacement"]})
    assert table["gauge_1"].tolist() == pytest.approx([1e-4, 2e-4])


def test_a_strain_column_of_an_unknown_name_is_warned_of_not_passed_over_silently(write):
    # a Dutch export whose extensometer's strain is named by its channel, 'Kanaal 3';
    # unread, the run takes its stiffness from the crosshead's 'Verlenging' without a word
    text = "Tijd [s],Verlenging [mm],Belasting [kN],Kanaal 3 [%],RH [%]\n" + "".join(
        f"{i / 10},{i / 100},{i / 2},{i / 50},45\n" for i in range(20))
    table, meta = read_table(write("nl.csv", text))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    assert meta.warnings == [
        "column 'Kanaal 3' reads in '%', a strain's unit, but its name is not one the readers "
        "know: not used (if it is an extensometer's strain, name it in the run sheet, "
        'columns = {gauges = ["Kanaal 3"]})']
    table, meta = read_table(write("nl.csv", text),
                             columns={"gauges": ["Verlenging", "Kanaal 3"]})
    assert "strain_1" in table and meta.warnings == []


@pytest.mark.parametrize("stated, warned", [(5, True), (3, False)])
def test_a_file_holding_fewer_rows_than_its_header_states_is_warned_of(write, stated, warned):
    # a force gauge's export states its row count ('Data Quantity'): a copy cut short at a
    # line end shows no other sign
    text = f"Data Quantity,{stated},,\n" + HEADER + rows((0, 1, 2), (1, 2, 3), (2, 3, 4))
    path = write("gauge.csv", text)
    message = (f"the header says Data Quantity = {stated}, the file holds 3 rows: it may be cut "
               "short (copy it again from the machine)")
    for meta in (read_table(path)[1], open_log(path).metadata):
        assert (message in meta.warnings) is warned


def test_a_kyowa_recorders_stated_rows_are_checked(write):
    # a real Kyowa PCD-400A export states the rows it recorded a channel
    text = '"集録データ数/CH",45100\n' + HEADER + rows((0, 1, 2), (1, 2, 3), (2, 3, 4))
    _, meta = read_table(write("kyowa.csv", text))
    assert ("the header says 集録データ数/CH = 45100, the file holds 3 rows: it may be cut "
            "short (copy it again from the machine)") in meta.warnings


@pytest.mark.parametrize("stated, warned", [(2, True), (3, False)])
def test_a_file_holding_more_rows_than_its_header_states_is_warned_of(write, stated, warned):
    # another test's row past the points the export states
    text = f"Number of points,{stated},,\n" + HEADER + rows((0, 1, 2), (1, 2, 3), (2, 3, 4))
    path = write("NANO_K_1.csv", text)
    message = (f"the header says Number of points = {stated}, the file holds 3 rows: the rows "
               "past the stated ones are read as samples (an end mark, or another test's "
               "rows): check the last rows")
    for meta in (read_table(path)[1], open_log(path).metadata):
        assert (message in meta.warnings) is warned


def test_an_end_mark_past_the_stated_rows_is_left_out(write):
    # a real Deben tester's export states its points, then writes an end mark of zeros as
    # one more row: read as a sample, it made a test stopped at 19.5 N end in a fracture
    text = "Number of points,2,,\n" + HEADER + rows((0, 1, 2), (1, 2, 3), (0, 0, 0))
    table, meta = read_table(write("NANO_K_1.csv", text))
    assert len(table) == meta.rows == 2 and table["force"].iloc[-1] == 2e3
    assert meta.warnings == ["the row at line 5, past the 2 the header states (Number of "
                             "points), holds only zeros: an end mark, left out"]


@pytest.mark.parametrize("copied, taken", [(True, True), (False, False)])
def test_a_counter_written_twice_takes_the_role_once(write, copied, taken):
    # a real MTS TestSuite export: its '_Cycle' index beside the 'Cycle Channel' it copies
    cycles = [1 + i // 4 for i in range(12)]
    counts = cycles if copied else cycles[:5] + [cycles[5] + 1] + cycles[6:]
    text = "_Cycle,Load,Time,Cycle Channel\n_Cycle,kN,sec,count\n" + rows(*(
        (cycle, i % 2, 0.1 * i, count)
        for i, (cycle, count) in enumerate(zip(cycles, counts, strict=True))))
    table, meta = read_table(write("cable.csv", text), kind="wear", strict=False)
    assert ("cycle_count" in table) is taken
    if taken:
        np.testing.assert_array_equal(table["cycle_count"], cycles)
        assert ("column 'Cycle Channel' holds the values of '_Cycle' row for row: one channel "
                "written twice, '_Cycle' is the cycle_count") in meta.warnings
    else:
        assert any("2 columns could be the cycle_count" in warning for warning in meta.warnings)


@pytest.mark.parametrize("count", [12, 4])
def test_columns_alike_by_chance_are_no_copy(write, count):
    # a jump analysis's results: two times equal over a few rows, or one value throughout
    times = [0.1 * (i % 3) for i in range(count)] if count < 10 else [0.5] * count
    text = "movement_time,propulsive_time,force [N],gauge [mm]\n" + rows(*(
        (t, t, i, i / 10) for i, t in enumerate(times)))
    _, meta = read_table(write("results.csv", text), kind="tensile", strict=False)
    assert any("2 columns could be the time" in warning for warning in meta.warnings)


def test_of_several_columns_for_one_role_none_is_taken_when_not_strict(write):
    # a results block left of the reading: the first was shown as the force, and drafted
    text = "Max force (N),Min force (N),Force (N),gauge [mm]\n" + rows(
        (3.96, -1.15, 0.01, 1), (3.96, -1.15, 0.5, 2), (3.96, -1.15, 1.0, 3))
    table, meta = read_table(write("pull.csv", text), strict=False)
    assert "force" not in table
    assert [column.role for column in meta.columns][:3] == [None, None, None]
    assert ("column 'Max force': 3 columns could be the force: 'Max force', 'Min force', "
            "'Force' (say which in the run sheet, columns = {force = \"...\"})") in meta.warnings
    assert not any(warning.startswith("no force column") for warning in meta.warnings)


def test_the_columns_listed_for_a_missing_role_leave_out_the_empty_ones(write):
    text = "time [s],load,extra,\n" + "".join(f"{i},{i * 2},,\n" for i in range(5))
    _, meta = read_table(write("log.csv", text), strict=False)
    missing = next(warning for warning in meta.warnings if "no gauge column" in warning)
    assert missing.endswith("the file has: time, load)")


@pytest.mark.parametrize("kind", ["tensile", "wear"])
def test_a_gauge_taken_by_its_unit_alone_is_warned_of(write, kind):
    # a force plate's centre of pressure in metres, a rig's feedback in inches: gauges by
    # their unit, whatever they measure
    text = "time [s],Fz [N],Ax [m],Extension [mm]\n" + rows((0, 1, 0.1, 2), (1, 2, 0.1, 3))
    _, meta = read_table(write("plate.csv", text), kind=kind)
    assert ("column 'Ax' is read as a gauge by its unit 'm' alone, its name not one the "
            "readers know: if it is no length along the specimen (a position, a level, a "
            "feedback), name the gauges in the run sheet, columns = {gauges = [...]}"
            ) in meta.warnings
    assert not any("'Extension' is read as a gauge" in warning for warning in meta.warnings)
    _, named = read_table(write("named.csv", text), kind=kind,
                          columns={"gauges": ["Ax", "Extension"]})
    assert not any("read as a gauge by its unit" in warning for warning in named.warnings)


@pytest.mark.parametrize("kind", ["tensile", "engagement"])
def test_a_force_taken_by_its_unit_alone_is_warned_of(write, kind):
    # a nanoindenter's or a force plate's channel named by a letter code, in µN or N
    text = "time [s],Zzz [µN],Extension [mm]\n" + rows((0, 1, 2), (1, 2, 3))
    _, meta = read_table(write("indent.csv", text), kind=kind)
    assert ("column 'Zzz' is read as the force by its unit 'µN' alone, its name not one the "
            "readers know: if it is not the load on the specimen (a reaction, a second load "
            "cell), name the force in the run sheet, columns = {force = \"...\"}"
            ) in meta.warnings
    _, named = read_table(write("indent.csv", text), kind=kind, columns={"force": "Zzz"})
    assert not any("by its unit" in warning for warning in named.warnings)


def test_a_time_saved_as_a_spreadsheets_date_serials_is_told_as_such(write):
    # a real Bluehill export re-saved through a spreadsheet, its time turned into dates and
    # times (days since 1899): the hint asked for a unit without a word on what it is
    text = "Datum/Uhrzeit;Kraft [kN]\n" + "".join(
        f"{45352.4166666667 + i * 0.02 / 86400:.10f};{0.005 * i:.4f}\n".replace(".", ",")
        for i in range(20))
    with pytest.raises(UnitError, match="no unit for the time column") as caught:
        read_table(write("zack.csv", text), kind="engagement")
    assert 'days since 1899: units = {time = "d"}' in caught.value.hint
    table, _ = read_table(write("zack.csv", text), kind="engagement", units={"time": "d"})
    # to the 8.6 µs of the serials' tenth decimal of a day
    np.testing.assert_allclose(np.diff(table["time"]), 0.02, atol=1e-5)
