"""``chainbench inspect``: what the readers detect, and one clean line on error."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from pipeline.cli import app

runner = CliRunner()

LOAD = [min(i % 10, 10 - i % 10) for i in range(60)]  # 6 load/unload cycles, 0 -> 5 -> 0 kN
PLAIN = "time [s],force [kN],gauge1 [mm],gauge2 [mm]\n" + "".join(
    f"{i / 10},{load},{load / 100},{load / 90}\n" for i, load in enumerate(LOAD)
)


def inspect_json(*arguments: str) -> dict:
    result = runner.invoke(app, ["inspect", "--json", *arguments])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_json_document(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text(PLAIN)
    report = inspect_json(str(path))
    assert {"layout", "encoding", "delimiter", "decimal", "rows", "columns", "cycles",
            "warnings"} <= set(report)
    assert (report["layout"], report["delimiter"], report["decimal"], report["rows"]) == (
        "plain_csv", ",", ".", 60)
    assert report["columns"][1] == {"name": "force", "role": "force", "unit": "kN",
                                    "si_unit": "N", "kind": None}
    assert report["cycles"] == 6 and report["machine_cycles"] is None
    assert report["warnings"] == []


def test_the_sampling_rate_is_shown_and_an_engagement_log_too_slow_for_impacts_warned_of(
        tmp_path):
    path = tmp_path / "t.csv"
    path.write_text(PLAIN)  # a sample every 0.1 s
    tensile = inspect_json(str(path))
    assert tensile["sample_rate_hz"] == pytest.approx(10.0)
    assert tensile["warnings"] == []
    engagement = inspect_json("--kind", "engagement", str(path))
    assert engagement["warnings"] == [
        "sampled at 10 Hz: an engagement run needs the ringing of the chain branch after each "
        "strike, 5 kHz or more; processed at this rate it is likely refused"]
    fast = tmp_path / "fast.csv"
    fast.write_text("time [s],force [kN]\n" + "".join(f"{i / 1e4},{load}\n"
                                                      for i, load in enumerate(LOAD)))
    assert inspect_json("--kind", "engagement", str(fast))["warnings"] == []


def test_a_file_without_time_is_shown_at_the_rate_given(tmp_path):
    path = tmp_path / "logger.csv"
    path.write_text("force [kN],gauge [mm]\n" + "".join(f"{load},{load / 100}\n"
                                                      for load in LOAD))
    assert inspect_json("--sample-rate-hz", "5000", str(path))["sample_rate_hz"] == (
        pytest.approx(5000.0))
    refused = runner.invoke(app, ["inspect", "--sample-rate-hz", "0", str(path)])
    assert refused.exit_code == 2 and "give a rate above 0" in refused.output


def test_rows_sent_in_bursts_give_the_mean_steps_rate_told_beside_the_median_steps(tmp_path):
    # a logger sending three readings 1 ms apart every 10 ms: 300 Hz, not the median's 1 kHz
    times = [10e-3 * (i // 3) + 1e-3 * (i % 3) for i in range(60)]
    path = tmp_path / "bursts.csv"
    path.write_text("time [s],force [kN]\n" + "".join(
        f"{time:.4f},{load}\n" for time, load in zip(times, LOAD, strict=True)))
    report = inspect_json("--kind", "engagement", str(path))
    mean_step = (times[-1] - times[0]) / (len(times) - 1)
    assert report["sample_rate_hz"] == pytest.approx(1 / mean_step)
    assert (f"the time steps are uneven: the median step gives 1000 Hz, their mean "
            f"{1 / mean_step:.4g} Hz") in report["warnings"][0]


def test_stamps_rounded_coarser_than_the_steps_give_the_rows_rate(tmp_path):
    # a real Arduino log: samples every 1.18 ms stamped in whole milliseconds (millis()),
    # one and two apart; the median step's 1 kHz overstated the rate by 18 %
    times = [int(i * 1.18e-3 * 1e3) / 1e3 for i in range(60)]
    path = tmp_path / "millis.csv"
    path.write_text("time [s],force [kN]\n" + "".join(
        f"{time},{load}\n" for time, load in zip(times, LOAD, strict=True)))
    report = inspect_json("--kind", "engagement", str(path))
    assert report["sample_rate_hz"] == pytest.approx(59 / (times[-1] - times[0]))
    assert report["sample_rate_hz"] == pytest.approx(1 / 1.18e-3, rel=0.02)
    assert not any("uneven" in warning for warning in report["warnings"])


def test_stamps_coarser_than_the_samples_give_the_rows_rate(tmp_path):
    # a logger sampling at 10 kHz prints its stamps to the millisecond: ten rows a stamp;
    # the steps between stamps gave 1 kHz, and "likely refused" for an engagement run
    times = [1e-3 * (i // 10) for i in range(60)]
    path = tmp_path / "coarse.csv"
    path.write_text("time [s],force [kN]\n" + "".join(
        f"{time:.3f},{load}\n" for time, load in zip(times, LOAD, strict=True)))
    report = inspect_json("--kind", "engagement", str(path))
    assert report["sample_rate_hz"] == pytest.approx(1e4)
    assert not any("sampled at" in warning for warning in report["warnings"])
    # a texture analyser writing each sample thrice: the samples' rate, not the rows'
    thrice = tmp_path / "thrice.csv"
    thrice.write_text("time [s],force [kN]\n" + "".join(
        f"{row // 3 * 0.013:.3f},{LOAD[row // 3]}\n" for row in range(60)))
    assert inspect_json(str(thrice))["sample_rate_hz"] == pytest.approx(1 / 0.013)
    # a real Hopkinson bar's scope export: stamps to three digits, ten rows a stamp, and
    # a coarse reading that rests on a value for rows on end (two rows in three alike):
    # taken for rows written thrice, the rate shown was the stamps', ten times too low
    coarse = tmp_path / "raw_voltage.csv"
    coarse.write_text("Time/s,force [kN]\n" + "".join(
        f"{-1.98e-4 + 1e-6 * (row // 10):.2e},{0.01 * (row // 3)}\n" for row in range(60)))
    assert inspect_json(str(coarse))["sample_rate_hz"] == pytest.approx(1e7)


def test_a_clock_to_the_second_gives_the_rows_rate_whole_seconds_counted(tmp_path):
    # a real bending rig's log: a clock to the second, about two rows a second (stamps
    # repeated in under half the rows), starting and ending within a second: 1 Hz was shown
    seconds = [0, 1, 1, 2, 2, 3, 4, 4, 5, 5, 6, 6, 7, 8, 8, 9, 9, 10, 10, 11, 12, 12]
    path = tmp_path / "1A_FLEX.csv"
    path.write_text("time,deflection[mm],force[N]\n" + "".join(
        f"15:03:{26 + second:02d},{row / 10},{load}\n"
        for row, (second, load) in enumerate(zip(seconds, LOAD, strict=False))))
    report = inspect_json(str(path))
    # rows from the first change of stamp (second 1) to the last (second 12), over 11 s
    assert report["sample_rate_hz"] == pytest.approx((seconds.index(12) - 1) / 11)


@pytest.mark.parametrize("header", ["Cycles (kcycles)", "Cycles x1000"])
def test_a_counter_in_a_unit_that_scales_it_is_told_as_a_run_would_refuse_it(tmp_path,
                                                                            header):
    path = tmp_path / "wear.csv"
    path.write_text(f"Time (h),{header},Length (mm)\n0,0,500\n1,1,500.1\n2,2,500.2\n")
    unit = "kcycles" if "kcycles" in header else "x1000"
    assert (f"the cycle counter 'Cycles' has the unit {unit!r}, which chainbench cannot "
            "scale: a run refuses it (log the cycles as a plain count)"
            ) in inspect_json("--kind", "wear", str(path))["warnings"]


def test_a_counter_that_skips_cycles_is_named(tmp_path):
    # a real fatigue log's counter: cycles 0 to 3 logged, then 110
    path = tmp_path / "fatigue.csv"
    path.write_text("N_cycles,Load [kN],Weg [mm]\n" + "".join(
        f"{cycle},{load},{load / 100}\n" for cycle in (0, 1, 2, 3, 110) for load in (0, 5, 0)))
    report = inspect_json(str(path))
    assert report["machine_cycles"] == 5
    assert any("counter runs from 0 to 110, and the file holds 5" in warning
               for warning in report["warnings"])
    dense = tmp_path / "dense.csv"
    dense.write_text(path.read_text().replace("\n110,", "\n4,"))
    assert not any("counter runs" in warning for warning in inspect_json(str(dense))["warnings"])


def test_table_output(tmp_path):
    path = tmp_path / "t.csv"
    path.write_text(PLAIN)
    result = runner.invoke(app, ["inspect", str(path)])
    assert result.exit_code == 0
    assert "plain_csv" in result.stdout and "gauge_2" in result.stdout


def test_error_is_one_clean_line(tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("time [s],force [kN],gauge [mm]\n0,1,2\n0.1,x,2\n")
    result = runner.invoke(app, ["inspect", str(path)])
    assert result.exit_code == 1
    lines = result.stderr.strip().splitlines()
    assert lines == [f"error: {path}, line 3, column 'force': 'x' is not a number "
                     "(hint: fix or delete the cell (missing values may be left empty or "
                     "written NaN))"]
    assert "Traceback" not in result.output


def test_debug_shows_the_traceback(tmp_path):
    path = tmp_path / "empty.csv"
    path.write_bytes(b"")
    result = runner.invoke(app, ["inspect", "--debug", str(path)])
    assert result.exit_code != 0
    assert type(result.exception).__name__ == "EmptyFileError"


def test_missing_units_show_as_null_with_a_warning(tmp_path):
    path = tmp_path / "u.csv"
    path.write_text("time,force,gauge\n0,1,2\n1,2,3\n")
    report = inspect_json(str(path))
    assert [column["unit"] for column in report["columns"]] == [None, None, None]
    assert [column["role"] for column in report["columns"]] == ["time", "force", "gauge_1"]
    assert sum("no unit" in warning for warning in report["warnings"]) == 3
    assert report["cycles"] is None


@pytest.mark.realdata
def test_bluehill_has_three_cycles(realdata):
    report = inspect_json(str(realdata / "yadbor__bluer__Specimen_RawData_6.csv"))
    assert (report["layout"], report["rows"], report["cycles"], report["machine_cycles"]) == (
        "machine_export", 18_011, 3, 3)
    assert {c["name"]: c["role"] for c in report["columns"]}["Extension"] == "gauge_1"


@pytest.mark.realdata
def test_ccfatigue_without_units(realdata):
    report = inspect_json(str(realdata / "EPFL-ENAC__CCFatiguePlatform__TST_2021-10_FA_22.csv"))
    load = next(c for c in report["columns"] if c["name"] == "Machine_Load")
    assert load == {"name": "Machine_Load", "role": "force", "unit": None, "si_unit": None,
                    "kind": None}
    assert any("Machine_Load" in w and "run sheet" in w for w in report["warnings"])
    assert report["machine_cycles"] == 373


@pytest.mark.realdata
@pytest.mark.parametrize("number", [1, 2])
def test_mts(realdata, number):
    report = inspect_json(
        str(realdata / f"ramonbotella__MTS_data_process_Python__sampledatafiletype{number}.dat"))
    assert (report["layout"], report["delimiter"], report["decimal"]) == ("mts", "\t", ",")
    assert report["machine_cycles"] == 10


@pytest.mark.parametrize("kind, header, roles", [
    ("segment-load", "Czas [s];Siła w łańcuchu [kN];Siła segmentu 1 [kN];Siła segmentu 2 [kN]",
     ["time", "force", "segment_force_1", "segment_force_2"]),
    # read as the engagement log chainbench run reads it: time and the branch tension
    ("roller-engagement", "time [s];force [kN]", ["time", "force"]),
])
def test_the_new_kinds_are_checked_as_run_reads_them(tmp_path, kind, header, roles):
    path = tmp_path / "log.csv"
    width = header.count(";") + 1
    rows = "".join(";".join(str(i + column) for column in range(width)) + "\n"
                   for i in range(20))
    path.write_text(header + "\n" + rows, encoding="cp1250")
    report = inspect_json(str(path), "--kind", kind)
    assert [column["role"] for column in report["columns"]] == roles
    assert report["columns"][1]["si_unit"] == "N"


def test_a_strain_worked_out_from_the_crosshead_shows_as_the_crosshead(tmp_path):
    # Bluehill's 'Tensile strain' is named like an extensometer's strain; its readings are
    # the crosshead's 'Extension' over the method's 50 mm, to the last digit
    rows = [(i / 10, load / 100 + i * 3e-4, load * 1000) for i, load in enumerate(LOAD)]
    path = tmp_path / "bluehill.csv"
    path.write_text("Time,Crosshead,Load,Tensile strain\n(s),(mm),(N),(mm/mm)\n" + "".join(
        f"{time:.1f},{extension:.4f},{force},{extension / 50:.6f}\n"
        for time, extension, force in rows))
    report = inspect_json(str(path))
    assert [column["kind"] for column in report["columns"]] == [
        None, "crosshead", None, "crosshead"]
    assert report["copies"] == {
        "Tensile strain": ["Crosshead", pytest.approx(0.05, rel=1e-4), False]}
    shown = runner.invoke(app, ["inspect", str(path)], env={"COLUMNS": "200"})
    assert ("note: 'Tensile strain' is 'Crosshead' over 50 mm to the last digit: a strain "
            "worked out from it, counted as its kind") in shown.stdout


def test_a_length_column_repeating_the_crosshead_shows_as_the_crosshead(tmp_path):
    # MTS TestSuite's 'Extension' beside 'Crosshead', the same readings when no
    # extensometer is fitted
    rows = [(i / 10, load / 100 + i * 3e-4, load * 1000) for i, load in enumerate(LOAD)]
    path = tmp_path / "testsuite.txt"
    path.write_text("Time\tLoad\tCrosshead\tExtension\nsec\tN\tmm\tmm\n" + "".join(
        f"{time:.2f}\t{force}\t{travel:.6f}\t{travel:.6f}\n" for time, travel, force in rows))
    report = inspect_json(str(path))
    assert [column["kind"] for column in report["columns"]] == [
        None, None, "crosshead", "crosshead"]
    assert report["duplicates"] == {"Extension": "Crosshead"}
    shown = runner.invoke(app, ["inspect", str(path)], env={"COLUMNS": "200"})
    assert ("note: 'Extension' moves with 'Crosshead' to the last digit, its zero and sign "
            "aside: one transducer written twice, counted as its kind") in shown.stdout


def test_a_unit_between_colons_is_printed_as_written_not_as_an_emoji(tmp_path):
    # a wind-tunnel balance's units row writes H:M:S over its clock: rich made it HⓂS
    path = tmp_path / "raw_test.txt"
    path.write_text("time [H:M:S],force [kN]\n0,1\n1,2\n2,3\n")
    result = runner.invoke(app, ["inspect", str(path)], env={"COLUMNS": "200"})
    assert "unit 'H:M:S' is not a unit of time" in result.output
    assert "Ⓜ" not in result.output
