"""Time columns of clock readings: read as seconds after the first row's, in every reader."""

import datetime

import numpy as np
import openpyxl
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pipeline.errors import ColumnError, LayoutError, ValueParseError
from pipeline.ingest import open_log, parse_table, read_table
from pipeline.ingest.clock import READ_FORMS, ClockColumn, clock_kind

#: 0.25 s steps from 23:59:58.5: the fifth reading is past midnight.
SECONDS = np.arange(12) * 0.25
FORCE_KN = 1.0 + np.sin(np.arange(12))


def time_of_day(seconds: float, start: float = 86_398.5) -> str:
    """The reading ``HH:MM:SS.fff`` `seconds` after `start` [s after midnight]."""
    stamp = datetime.datetime(2024, 3, 5) + datetime.timedelta(seconds=start + seconds)
    return stamp.strftime("%H:%M:%S.%f")[:-3]


def date_and_time(seconds: float, separator: str = " ", date_separator: str = "-") -> str:
    stamp = datetime.datetime(2024, 3, 5, 23, 59, 58, 500_000) + datetime.timedelta(
        seconds=seconds)
    return stamp.isoformat(sep=separator, timespec="milliseconds").replace(
        "-", date_separator)


def log(cells: list[str], header: str = "Time,Load (kN)") -> str:
    rows = [f"{cell},{force:.6f}" for cell, force in zip(cells, FORCE_KN, strict=True)]
    return "\n".join([header, *rows]) + "\n"


@pytest.mark.parametrize("text, kind", [
    ("14:03:27", "time of day"), (" 14:03:27.125 ", "time of day"),
    ("2024-03-05 14:03:27.125", "date and time"), ("2024-03-05T14:03:27", "date and time"),
    ("2018/12/07 17:16:36.882", "date and time"), ("2018/12-07 17:16:36", None),
    ("12/07/2018 17:16:36", "time of day"), ("3/5/2024 2:03:27.5 PM", "time of day"),
    ("3/5/2024 2:03 PM", None), ("2024/3/5 2:03:27 PM", None),
    ("4:03:27", "time of day"), ("14:03:27,125", "time of day"),
    ("2024-03-05 4:03:27,5", "date and time"), ("14:03", None),
    ("114:03:27", "time of day"), ("11403:27:00", None),
    ("2018-11-15-09:30:25.349", "date and time"), ("2018-11-15_09:30:25", "date and time"),
    ("05.03.2024 14:03:27", "date and time"), ("05.03.2024 4:03:27,125", "date and time"),
    ("5.3.2024 14:03:27", None), ("2:03:27 PM", "time of day"), ("13:03:27 PM", None),
    ("14:03:27,", None),
    ("1.5", None), ("", None),
    ("0:00.0", "minutes and seconds"), ("75:12,3", "minutes and seconds"),
    ("1:00:00.5", "time of day"), ("12:3.4", None),
    ("09:39:48:776", "time of day"), ("09:39:48:77", None),
    ("2021-02-26T16:41:09.000+01:00", "date and time"), ("2021-02-26 15:41:09Z", "date and time"),
    ("2021-02-26T16:41:09-0500", "date and time"), ("2021-02-26T16:41:09+1", None),
])
def test_clock_kind(text, kind):
    assert clock_kind(text) == kind


@given(st.lists(st.integers(0, 86_399_999), min_size=1, max_size=20))
def test_a_time_of_day_is_seconds_after_the_first(milliseconds):
    texts = [time_of_day(ms / 1e3, start=0.0) for ms in milliseconds]
    seconds = ClockColumn("time of day", texts[0]).seconds_of_texts(texts)
    expected = (np.array(milliseconds) - milliseconds[0]) / 1e3
    np.testing.assert_allclose(seconds, expected, rtol=0, atol=1e-9)


def elapsed(seconds: float, decimal: str = ".") -> str:
    """``[H:]M:SS.f``, as Measurement Computing's DAQami writes the time since the start."""
    hours, rest = divmod(round(seconds * 10), 36_000)
    minutes, tenths = divmod(rest, 600)
    text = f"{minutes}:{tenths / 10:04.1f}".replace(".", decimal)
    return f"{hours}:{text.zfill(len(text) + 1)}" if hours else text


@pytest.mark.parametrize("decimal", [".", ","])
def test_elapsed_minutes_and_seconds_read_on_past_the_hour(write, decimal):
    start = 3598.0  # the fifth reading is past the hour: 0:59:59.9 -> 1:00:00.0
    cells = [elapsed(start + s, decimal) for s in SECONDS]
    assert cells[:2] == [f"59:58{decimal}0", f"59:58{decimal}2"] and cells[-1].startswith("1:00:")
    delimiter = ";" if decimal == "," else ","
    text = f"Time (s){delimiter}Load (kN)\n" + "".join(
        f"{cell}{delimiter}{force:.6f}\n".replace(".", decimal)
        for cell, force in zip(cells, FORCE_KN, strict=True))
    table, meta = read_table(write("daqami.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], np.round(SECONDS * 10) / 10, rtol=0, atol=1e-9)
    assert any("clock readings (minutes and seconds" in warning for warning in meta.warnings)


@pytest.mark.parametrize("cell", ["x", "0:00:03", "1.5"])
def test_a_cell_that_is_no_elapsed_time_is_named(write, cell):
    cells = [elapsed(s) for s in SECONDS]
    cells[6] = cell
    with pytest.raises(ValueParseError) as caught:
        read_table(write("daqami.csv", log(cells)), kind="engagement")
    assert (caught.value.row, caught.value.column) == (8, "Time")
    assert caught.value.message == f"{cell!r} is not a clock reading like the first row's '0:00.0'"


@pytest.mark.parametrize("separator, date_separator", [(" ", "-"), ("T", "-"), (" ", "/"),
                                                      ("-", "-")])
def test_a_date_and_time_log_counts_on_past_midnight(write, separator, date_separator):
    # the year first, the date's parts joined by "-" (ISO 8601) or by "/" (a force logger);
    # a load-cell logger joins the date to the time by "-" too
    path = write("log.csv", log([date_and_time(s, separator, date_separator)
                                 for s in SECONDS]))
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["force"], np.round(FORCE_KN, 6) * 1e3)
    assert meta.time_monotonic
    (column,) = [c for c in meta.columns if c.role == "time"]
    assert (column.unit, column.si_unit) == ("s", "s")
    assert any("holds clock readings (date and time" in w for w in meta.warnings)


def test_a_time_of_day_past_midnight_is_reported_as_a_step_back(write):
    path = write("log.csv", log([time_of_day(s) for s in SECONDS]))
    table, meta = read_table(path, kind="engagement")
    expected = np.where(SECONDS < 1.5, SECONDS, SECONDS - 86_400.0)
    np.testing.assert_allclose(table["time"], expected, rtol=0, atol=1e-9)
    assert meta.time_monotonic is False
    assert ("time: steps back 1 times, first at line 8 (the time of day passes midnight; "
            "a date in the column before or after it is joined only when it can be read one "
            "way: year first, dotted, or of slashes whose dates follow one another day by day "
            "read day first or month first; export the date and time in one column, year "
            "first, or the time in seconds)") in meta.warnings


@pytest.mark.parametrize("step_ms", [1, 7, 37])
def test_milliseconds_without_zero_padding_are_read_as_milliseconds(write, step_ms):
    # an ESP32 logger prints millis() % 1000 with %d: "21.99" then "21.100"; and "22.5"
    # is 5 ms into the next second
    stamps = np.arange(0, 2500, step_ms)
    cells = [f"03:15:{21 + ms // 1000}.{ms % 1000}" for ms in stamps]
    text = "time,force\n" + "".join(f"{cell},{i}\n" for i, cell in enumerate(cells))
    table, meta = read_table(write("kite.csv", text), kind="engagement", units={"force": "N"})
    np.testing.assert_allclose(table["time"], stamps / 1e3, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert any("milliseconds without zero padding" in warning for warning in meta.warnings)


@pytest.mark.parametrize("fractions", [
    ["5", "75", "8"],  # decimals with their trailing zeros left out: 0.5, 0.75, 0.8
    ["1", "2", "25", "5"],  # 0.1, 0.2, 0.25, 0.5 s: a fraction grows, its value too
])
def test_decimals_without_trailing_zeros_stay_decimals(write, fractions):
    cells = [f"10:00:00.{fraction}" for fraction in fractions] + ["10:00:01.0"]
    text = "time,force\n" + "".join(f"{cell},{i}\n" for i, cell in enumerate(cells))
    table, meta = read_table(write("log.csv", text), kind="engagement", units={"force": "N"})
    expected = [float(f"0.{fraction}") for fraction in fractions] + [1.0]
    np.testing.assert_allclose(table["time"], np.subtract(expected, expected[0]), atol=1e-9)
    assert not any("zero padding" in warning for warning in meta.warnings)


def test_a_preamble_units_row_and_decimal_comma_around_clock_readings(write):
    rows = [time_of_day(s, 3600.0) + ";" + f"{force:.3f}".replace(".", ",")
            for s, force in zip(SECONDS, FORCE_KN, strict=True)]
    text = "Versuch;12\n\nZeit;Kraft\n;kN\n" + "\n".join(rows) + "\n"
    table, meta = read_table(write("log.csv", text), kind="engagement")
    assert (meta.delimiter, meta.decimal) == (";", ",")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["force"], np.round(FORCE_KN, 3) * 1e3)


def test_one_digit_hours_and_a_decimal_comma_in_the_seconds(write):
    # a logger set to a German locale: "9:59:59,750" with ";" between the fields
    cells = [time_of_day(s, 9 * 3600 + 3598.5).lstrip("0").replace(".", ",")
             for s in SECONDS]
    assert cells[0] == "9:59:58,500" and cells[-1] == "10:00:01,250"
    rows = [f"{cell};{force:.3f}".replace(".", ",") for cell, force in zip(
        cells, FORCE_KN, strict=True)]
    table, meta = read_table(write("log.csv", "Zeit;Kraft [kN]\n" + "\n".join(rows) + "\n"),
                             kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["force"], np.round(FORCE_KN, 3) * 1e3)
    assert any("holds clock readings (time of day, first '9:59:58,500')" in warning
               for warning in meta.warnings)


def test_a_clock_counting_from_zero_is_told_as_a_time_elapsed(write):
    # a real PicoLog export: its elapsed "00:00:00" past 24 hours was called a time of day
    text = "Time,Force (N)\n00:00:00,1.0\n00:00:01,1.5\n00:00:02,2.0\n"
    table, meta = read_table(write("pico.csv", text), kind="engagement", strict=False)
    np.testing.assert_allclose(table["time"], [0.0, 1.0, 2.0])
    assert any("holds clock readings (a time elapsed, from zero, first '00:00:00')" in warning
               for warning in meta.warnings)


def test_milliseconds_after_a_colon(write):
    # a press's software: "09:39:48:776", a colon before the milliseconds
    cells = [time_of_day(s, 9 * 3600 + 3598.5) for s in SECONDS]
    cells = [cell[:-4] + ":" + cell[-3:] for cell in cells]
    assert cells[0] == "09:59:58:500" and cells[-1] == "10:00:01:250"
    path = write("press.csv", log(cells))
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    rows, _ = open_log(path, kind="engagement").read(4, 12)  # by row ranges too
    np.testing.assert_allclose(rows["time"], SECONDS[4:], rtol=0, atol=1e-9)
    assert "first '09:59:58:500'" in meta.warnings[0]


def test_date_times_at_their_offset_from_utc_count_on_as_utc(write):
    # a logger's ISO 8601 stamps with their offset, over the night summer time begins:
    # 01:59:59.5+01:00 is followed by 03:00:00+02:00, half a second later
    cells = ["2021-03-28T01:59:59.000+01:00", "2021-03-28T01:59:59.500+01:00",
             "2021-03-28T03:00:00.000+02:00", "2021-03-28T03:00:00.500+02:00"]
    text = "Time,Load (kN)\n" + "".join(f"{cell},{i}\n" for i, cell in enumerate(cells))
    path = write("tz.csv", text)
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], [0, 0.5, 1.0, 1.5], rtol=0, atol=1e-9)
    assert meta.warnings[0].endswith("each at its offset from UTC")
    rows, _ = open_log(path, kind="engagement").read(2, 4)
    np.testing.assert_allclose(rows["time"], [1.0, 1.5], rtol=0, atol=1e-9)


def test_date_times_marked_utc_are_read(write):
    # ThingSpeak's created_at: "2021-03-04 10:15:02 UTC"
    cells = ["2021-03-04 10:15:02 UTC", "2021-03-04 10:15:17 UTC", "2021-03-04 10:15:32 UTC"]
    text = "Time,Load (kN)\n" + "".join(f"{cell},{i}\n" for i, cell in enumerate(cells))
    table, meta = read_table(write("feed.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], [0.0, 15.0, 30.0])
    assert meta.warnings[0].endswith("each at its offset from UTC")


def test_a_reading_not_in_the_first_rows_arrow_form_is_named(write):
    # the first reading in pyarrow's own form: the column is parsed as such, and a
    # reading written otherwise further down is named, not misread
    cells = [date_and_time(s) for s in SECONDS]
    cells[5] = cells[5].replace(".", ",")
    rows = [f"{cell};{force:.6f}" for cell, force in zip(cells, FORCE_KN, strict=True)]
    with pytest.raises(ValueParseError) as caught:
        read_table(write("log.csv", "Time;Load (kN)\n" + "\n".join(rows) + "\n"),
                   kind="engagement")
    assert (caught.value.row, caught.value.column) == (7, "Time")
    assert caught.value.message == (
        f"{cells[5]!r} is not a clock reading like the first row's {cells[0]!r}")


def test_a_cell_that_is_no_clock_reading_is_named(write):
    cells = [time_of_day(s, 3600.0) for s in SECONDS]
    cells[6] = "1.5"
    with pytest.raises(ValueParseError) as caught:
        read_table(write("log.csv", log(cells)), kind="engagement")
    assert (caught.value.row, caught.value.column) == (8, "Time")
    assert caught.value.message == (
        "'1.5' is not a clock reading like the first row's '01:00:00.000'")


def test_a_run_sheet_unit_does_not_rescale_clock_readings(write):
    path = write("log.csv", log([time_of_day(s, 3600.0) for s in SECONDS]))
    table, meta = read_table(path, kind="engagement", units={"time": "ms"})
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert any("unit 'ms' from the run sheet not used" in w for w in meta.warnings)
    _, meta = read_table(path, kind="engagement", units={"time": "s"})  # as init writes it
    assert not any("from the run sheet" in w for w in meta.warnings)


def test_a_clock_column_that_is_not_the_time_is_left_alone(write):
    cells = [f"{time_of_day(s, 3600.0)},{s:.2f}" for s in SECONDS]
    text = "Clock,Time [s],Load [kN]\n" + "\n".join(
        f"{cell},{force:.6f}" for cell, force in zip(cells, FORCE_KN, strict=True)) + "\n"
    table, meta = read_table(write("log.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert not any("clock readings" in w for w in meta.warnings)


@pytest.mark.parametrize("cell, kind", [
    (lambda stamp: stamp, "date and time"), (lambda stamp: stamp.time(), "time of day")])
def test_spreadsheet_time_cells(tmp_path, cell, kind):
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["Time", "Load [kN]"])
    start = datetime.datetime(2024, 3, 5, 10, 59, 58, 500_000)
    for s, force in zip(SECONDS, FORCE_KN, strict=True):
        sheet.append([cell(start + datetime.timedelta(seconds=float(s))), float(force)])
    path = tmp_path / "log.xlsx"
    book.save(path)
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-6)
    assert any(f"holds clock readings ({kind}" in w for w in meta.warnings)


@pytest.mark.parametrize("cell", ["5.3.2024 14:03:27", "2024-3-5 14:03:27"])
def test_a_clock_form_not_read_is_set_aside_and_a_run_needing_time_refused(write, cell):
    # two columns: found as a table all the same
    with pytest.raises(ColumnError) as caught:
        read_table(write("log.csv", log([cell] * len(SECONDS))), kind="engagement")
    assert caught.value.message.startswith("no time column found")
    assert (f"column 'Time' holds clock readings in a form the reader does not guess "
            f"({cell!r}...; it reads {READ_FORMS}), to be exported as seconds;"
            ) in caught.value.hint


@pytest.mark.parametrize("cell", ["3/5/2024 2:03 PM", "3/5/2024 14:03", "05.03.2024 14:03",
                                  "14:03"])
def test_clock_readings_to_the_minute_are_refused_as_the_time_and_say_why(write, cell):
    """A spreadsheet saves a date and time as it shows them, often without the seconds:
    a minute's samples then share one reading, which no order of the rows can time."""
    with pytest.raises(ColumnError) as caught:
        read_table(write("log.csv", log([cell] * len(SECONDS))), kind="engagement")
    assert (f"column 'Time' holds clock readings to the minute ({cell!r}...): the samples "
            "of a minute share one reading, so they cannot time the log (a spreadsheet "
            "saves a date and time as it shows them: show the seconds, h:mm:ss, before "
            "saving, or export from the machine);") in caught.value.hint


@pytest.mark.parametrize("suffix", [".csv", ".xlsx"])
def test_a_tensile_log_with_a_clock_form_not_read_is_read_without_it(tmp_path, suffix):
    """A spreadsheet's date and time to the minute beside the force and the gauge: a
    stiffness needs no time, so the column is set aside with a warning and the rest read."""
    rows = [[f"3/5/2024 {11 + (i >= 4)}:5{i % 4} {'PM' if i >= 4 else 'AM'}",
             f"{force:.6f}", f"{0.01 * i:.4f}"] for i, force in enumerate(FORCE_KN)]
    header = ["Date Time", "Load (kN)", "Extension (mm)"]
    path = tmp_path / f"log{suffix}"
    if suffix == ".csv":
        path.write_text("\n".join(",".join(row) for row in [header, *rows]) + "\n")
    else:
        book = openpyxl.Workbook()
        for row in [header, *rows]:
            book.active.append([row[0], *(float(cell) for cell in row[1:])]
                               if row is not header else row)
        book.save(path)
    table, meta = read_table(path, kind="tensile")
    assert list(table.columns) == ["force", "gauge_1"]
    np.testing.assert_allclose(table["force"], np.round(FORCE_KN, 6) * 1e3)
    np.testing.assert_allclose(table["gauge_1"], np.arange(len(FORCE_KN)) * 1e-5, atol=1e-12)
    assert ("column 'Date Time' holds clock readings to the minute ('3/5/2024 11:50 AM'"
            "...): the samples of a minute share one reading") in "\n".join(meta.warnings)
    assert meta.warnings[-1].endswith("export from the machine): not used as the time")


def spreadsheet_stamp(stamp: datetime.datetime, order: str, twelve: bool,
                      year: str = "%Y") -> str:
    """``3/5/2024 11:59:58.500 PM`` (a US spreadsheet) or ``05/03/2024 23:59:58.500``;
    `year` ``"%y"``: two digits (``3/5/24``)."""
    date = (f"{stamp.month}/{stamp.day}/" if order == "mdy" else f"{stamp:%d/%m/}"
            ) + stamp.strftime(year)
    clock = (f"{int(stamp.strftime('%I'))}:{stamp:%M:%S}.{stamp.microsecond // 1000:03d} "
             f"{stamp:%p}" if twelve else f"{stamp:%H:%M:%S}.{stamp.microsecond // 1000:03d}")
    return f"{date} {clock}"


@pytest.mark.parametrize("suffix", [".csv", ".xlsx"])
@pytest.mark.parametrize(("order", "twelve"), [("mdy", True), ("dmy", False), ("mdy", False)])
def test_a_spreadsheets_date_and_time_counts_on_past_midnight(tmp_path, suffix, order,
                                                               twelve):
    """A date of slashes and a time in one cell, as a spreadsheet saves them (12-hour clock
    or not): the 5th of March read either way, the change of day at midnight says which
    part is the day; 12 AM is midnight."""
    start = datetime.datetime(2024, 3, 5, 23, 59, 58, 500_000)
    cells = [spreadsheet_stamp(start + datetime.timedelta(seconds=float(s)), order, twelve)
             for s in SECONDS]
    path = tmp_path / f"log{suffix}"
    if suffix == ".csv":
        path.write_text("Date Time,Load (kN)\n" + "".join(
            f"{cell},{force:.6f}\n" for cell, force in zip(cells, FORCE_KN, strict=True)))
    else:
        book = openpyxl.Workbook()
        book.active.append(["Date Time", "Load (kN)"])
        for cell, force in zip(cells, FORCE_KN, strict=True):
            book.active.append([cell, float(force)])  # text cells, as a CSV opened in Excel
        book.save(path)
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert any("holds clock readings (date and time, first" in w and "on the date each "
               "reading carries (day or month first, whichever" in w for w in meta.warnings)


@pytest.mark.parametrize(("order", "twelve"), [("mdy", True), ("dmy", False)])
def test_a_loggers_two_digit_year_counts_on_past_midnight(write, order, twelve):
    """A logger's date of slashes with a two-digit year (HOBOware's ``11/17/18 12:37:17
    PM``): the change of day at midnight says which part is the day, though the 17th
    says it too (a two-digit year might come first)."""
    start = datetime.datetime(2018, 11, 17, 23, 59, 58, 500_000)
    cells = [spreadsheet_stamp(start + datetime.timedelta(seconds=float(s)), order, twelve,
                               "%y") for s in SECONDS]
    assert cells[0] in ("11/17/18 11:59:58.500 PM", "17/11/18 23:59:58.500")
    text = '"#","Date Time, GMT-06:00","Force, N"\n' + "".join(
        f"{row},{cell},{force:.3f}\n" for row, (cell, force) in enumerate(
            zip(cells, FORCE_KN, strict=True), start=1))
    table, meta = read_table(write("hobo.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert "whichever makes the dates follow one another day by day" in meta.warnings[0]


def test_a_two_digit_year_first_is_not_read_as_the_day(write):
    # "18/11/17" (year, month, day) then "18/11/18": read day first, a step of a year;
    # so the dates are not joined, and the time's step back past midnight is told
    cells = ["18/11/17 23:59:59", "18/11/17 23:59:59.5", "18/11/18 00:00:00",
             "18/11/18 00:00:00.5"]
    text = "Date Time,Load (kN)\n" + "".join(f"{cell},{i}\n" for i, cell in enumerate(cells))
    table, meta = read_table(write("ymd.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], [0, 0.5, 0.5 - 86_399.5, 1 - 86_399.5])
    assert any(warning.startswith("time: steps back 1 times") for warning in meta.warnings)


def test_a_twelve_hour_clock_with_an_hour_past_12_is_refused(write):
    cells = ["11:59:59 AM", "12:00:00 PM", "13:00:00 PM"] + ["1:00:00 PM"] * 9
    with pytest.raises(ValueParseError, match="'13:00:00 PM'"):
        read_table(write("log.csv", log(cells)), kind="engagement")


@pytest.mark.parametrize("decimal", [".", ","])
def test_a_dotted_date_day_first_counts_on_past_midnight(write, decimal):
    """German software's ``05.03.2024 23:59:58,500``: a dotted date is day, month, year."""
    cells = [date_and_time(s).replace(".", decimal) for s in SECONDS]  # ISO, then dotted
    cells = [f"{c[8:10]}.{c[5:7]}.{c[:4]}{c[10:]}" for c in cells]
    assert cells[0] == f"05.03.2024 23:59:58{decimal}500" and cells[-1].startswith("06.03.2024")
    delimiter = ";" if decimal == "," else ","
    text = f"Zeit{delimiter}Kraft (kN)\n" + "".join(
        f"{cell}{delimiter}{f'{force:.6f}'.replace('.', decimal)}\n"
        for cell, force in zip(cells, FORCE_KN, strict=True))
    table, meta = read_table(write("log.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert any("holds clock readings (date and time, first '05.03.2024" in w
               for w in meta.warnings)


@pytest.mark.parametrize("first, other", [("/", "-"), ("-", "/")])
def test_a_column_of_dates_joined_by_slashes_reads_iso_dates_and_names_other_cells(
        write, first, other):
    cells = [date_and_time(s, date_separator=first) for s in SECONDS]
    cells[4] = cells[4].replace(first, other)  # 2024-03-06 00:00:00.500 either way
    if first == "/":  # a date of the same order, joined as in ISO 8601: read alike
        table, _ = read_table(write("log.csv", log(cells)), kind="engagement")
        np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
        cells[7] = "14:03:27"
    with pytest.raises(ValueParseError) as caught:
        read_table(write("log.csv", log(cells)), kind="engagement")
    bad = 7 if first == "/" else 4
    assert (caught.value.row, caught.value.column) == (bad + 2, "Time")
    assert caught.value.message == (
        f"{cells[bad]!r} is not a clock reading like the first row's {cells[0]!r}")


def test_year_month_day_with_slashes_as_spreadsheet_text(tmp_path):
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["Time", "Load [kN]"])
    for s, force in zip(SECONDS, FORCE_KN, strict=True):
        sheet.append([date_and_time(float(s), date_separator="/"), float(force)])
    path = tmp_path / "log.xlsx"
    book.save(path)
    table, _ = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)


def graphtec_rows(stamps_ms: list[int], columns: str, step: str = ",") -> list[str]:
    """Rows of a logger that stamps to the whole second and counts the fraction beside it:
    ``No.``, the clock (``date and time`` or ``date, time``), the count (``ms`` or ``us``
    per `columns`), a force [kN] (row number / 8); from 2026/03/05 10:59:58."""
    start = datetime.datetime(2026, 3, 5, 10, 59, 58)
    rows = []
    for row, ms in enumerate(stamps_ms):
        stamp = start + datetime.timedelta(milliseconds=ms)
        force = f"+{row / 8:.3f}".replace(".", "," if step == ";" else ".")
        if columns == "date&time,ms":
            cells = [f"{stamp:%Y/%m/%d %H:%M:%S}", str(ms % 1000)]
        else:  # date and time of day apart, microseconds
            cells = [f"{stamp:%d/%m/%Y}", f"{stamp:%H:%M:%S}", str(ms % 1000 * 1000)]
        rows.append(step.join([str(row + 1), *cells, force]))
    return rows


def test_a_graphtec_log_adds_the_milliseconds_counted_beside_the_whole_seconds(
        write, graphtec_export):
    text = graphtec_export(step_ms=250)
    table, meta = read_table(write("GL840.csv", text), kind="engagement",
                             columns={"force": "CH1", "angle": "CH2"})
    # 250 ms steps over midnight (the stamps carry their date), from the first row's
    assert "\r\n9,2026/03/06 00:00:00,0," in text
    assert len(table) == text.count("LLLLLLLLLL")
    np.testing.assert_allclose(table["time"], np.arange(len(table)) * 0.25, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    units = {column.name: column.unit for column in meta.columns}
    assert units["CH1"] == "kN" and units["CH2"] == "deg"  # the units row under the names
    assert table["force"].iloc[0] == 1500.0
    assert ("column 'Date&Time' holds clock readings (date and time, first '2026/03/05 "
            "23:59:58'): read as seconds after the first row's, plus the milliseconds "
            "within the second that column 'ms' counts") in meta.warnings
    assert not any("repeated time stamp" in warning for warning in meta.warnings)


@given(st.lists(st.integers(1, 2500), min_size=1, max_size=30))
def test_whole_seconds_and_the_milliseconds_beside_them_give_the_time(steps):
    stamps = np.cumsum([0, *steps])
    text = "No.,Date&Time,ms,Load [kN]\n" + "\n".join(
        graphtec_rows([int(ms) for ms in stamps], "date&time,ms")) + "\n"
    table, _ = parse_table(text.encode(), kind="engagement")
    np.testing.assert_allclose(table["time"], stamps / 1e3, rtol=0, atol=1e-9)


def test_a_date_a_time_of_day_and_microseconds_apart(write):
    # a GL980's "Number;Date;Time;us" with a decimal comma
    stamps = list(range(0, 3000, 100))
    text = ("Number;Date;Time;us;Load [kN]\n"
            + "\n".join(graphtec_rows(stamps, "date;time;us", step=";")) + "\n")
    table, meta = read_table(write("GL980.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], np.array(stamps) / 1e3, rtol=0, atol=1e-9)
    assert meta.decimal == ","
    assert any("plus the microseconds within the second that column 'us' counts" in warning
               for warning in meta.warnings)


@pytest.mark.parametrize("clock, counts", [
    ("10:00:00.{}", ["0", "250", "500", "750"]),  # the clock has a fraction of its own
    ("10:00:0{}", ["0", "1000", "2000", "3000"]),  # counts of a second or more
])
def test_a_count_that_is_no_fraction_of_the_second_is_not_added(write, clock, counts):
    cells = [clock.format(row) for row in range(4)]
    text = "Time,ms,Load [kN]\n" + "".join(
        f"{cell},{count},{row}\n" for row, (cell, count) in enumerate(zip(cells, counts,
                                                                         strict=True)))
    table, meta = read_table(write("log.csv", text), kind="engagement",
                             columns={"time": "Time"})
    expected = ClockColumn(clock_kind(cells[0]), cells[0]).seconds_of_texts(cells)
    np.testing.assert_allclose(table["time"], expected, rtol=0, atol=1e-9)
    assert not any("within the second" in warning for warning in meta.warnings)


def test_a_graphtec_log_saved_as_a_workbook(tmp_path):
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["No.", "Date&Time", "ms", "Load [kN]"])
    start = datetime.datetime(2026, 3, 5, 10, 59, 58)
    stamps = range(0, 2500, 250)
    for row, ms in enumerate(stamps):
        stamp = start + datetime.timedelta(milliseconds=ms)
        sheet.append([row + 1, stamp.replace(microsecond=0), stamp.microsecond // 1000, 1.0])
    path = tmp_path / "GL840.xlsx"
    book.save(path)
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], np.array(stamps) / 1e3, rtol=0, atol=1e-9)
    assert any("plus the milliseconds within the second" in w for w in meta.warnings)


def test_a_time_of_day_set_back_by_an_hour_is_no_midnight(write):
    # a logger's clock put back for the end of summer time: a step back, not midnight
    seconds = np.where(SECONDS < 1.5, SECONDS, SECONDS - 3600.0)
    path = write("log.csv", log([time_of_day(s, start=7200.0) for s in seconds]))
    _, meta = read_table(path, kind="engagement")
    assert "time: steps back 1 times, first at line 8" in meta.warnings


@pytest.mark.parametrize("written, order", [
    ("%d/%m/%Y", "day first"), ("%m/%d/%Y", "month first"), ("%Y-%m-%d", "year first"),
    ("%d.%m.%Y", "day first"), ("%Y/%m/%d", "year first")])
def test_a_date_in_the_column_before_a_time_of_day_is_joined_past_midnight(
        write, written, order):
    # the 13th: a day past the 12th says the order of a date of slashes
    start = datetime.datetime(2026, 3, 13, 23, 59, 58, 500_000)
    stamps = [start + datetime.timedelta(seconds=float(s)) for s in SECONDS]
    text = "Date,Time,Load (kN)\n" + "".join(
        f"{stamp:{written}},{stamp:%H:%M:%S.%f}"[:-3] + f",{force:.6f}\n"
        for stamp, force in zip(stamps, FORCE_KN, strict=True))
    table, meta = read_table(write("log.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert any(f"on the dates of column 'Date' (first '{start:{written}}', {order})" in w
               for w in meta.warnings)


def test_a_date_in_the_column_after_a_time_of_day_is_joined_past_midnight(write):
    # IMADA's Force Recorder writes Time,Date: the date after the time of day
    start = datetime.datetime(2024, 12, 26, 23, 59, 58, 500_000)
    stamps = [start + datetime.timedelta(seconds=float(s)) for s in SECONDS]
    text = "Load (kN),Time,Date\n" + "".join(
        f"{force:.6f},{stamp:%H:%M:%S.%f}"[:-3] + f",{stamp:%m/%d/%Y}\n"
        for stamp, force in zip(stamps, FORCE_KN, strict=True))
    table, meta = read_table(write("log.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert any("on the dates of column 'Date' (first '12/26/2024', month first)" in w
               for w in meta.warnings)


def slashed_log(start: datetime.datetime, written: str, seconds=SECONDS) -> str:
    """A ``Date,Time,Load (kN)`` log from `start`, its date written as `written`."""
    return "Date,Time,Load (kN)\n" + "".join(
        f"{start + datetime.timedelta(seconds=float(s)):{written},%H:%M:%S.%f}"[:-3]
        + f",{force:.6f}\n" for s, force in zip(seconds, FORCE_KN, strict=True))


@pytest.mark.parametrize("written", ["%d/%m/%Y", "%m/%d/%Y"])
def test_a_date_of_slashes_the_first_rows_do_not_decide_is_read_by_its_days(write, written):
    """05/03 or 03/05, the day not past the 12th: only the true order reads the change of
    date at midnight as one day (the other reads a month)."""
    start = datetime.datetime(2026, 3, 5, 23, 59, 58, 500_000)
    table, meta = read_table(write("log.csv", slashed_log(start, written)), kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert any(f"on the dates of column 'Date' (first '{start:{written}}', day or month "
               "first, whichever makes the dates follow one another day by day)" in w
               for w in meta.warnings)


def test_a_date_of_slashes_that_skips_days_is_not_joined(write):
    # the logger paused from the 5th to the 7th: neither order steps a day at a time
    start = datetime.datetime(2026, 3, 5, 23, 59, 58, 500_000)
    seconds = np.where(SECONDS < 1.5, SECONDS, SECONDS + 86_400.0)
    table, meta = read_table(write("log.csv", slashed_log(start, "%d/%m/%Y", seconds)),
                             kind="engagement")
    assert meta.time_monotonic is False
    assert any("time: steps back 1 times" in w and "a date in the column before or after it" in w
               for w in meta.warnings)


def test_rows_of_a_long_log_on_one_later_date_are_refused_not_guessed(write):
    """A row range on the 6th alone, after a first row on the 5th: a day (05/03, 06/03)
    or a month (03/05, 03/06) later; the whole file shows the day."""
    start = datetime.datetime(2026, 3, 5, 23, 59, 58, 500_000)
    path = write("log.csv", slashed_log(start, "%d/%m/%Y"))
    reader = open_log(path)
    whole, _ = reader.read(0, reader.n_rows)
    np.testing.assert_allclose(whole["time"], SECONDS, rtol=0, atol=1e-9)
    with pytest.raises(LayoutError, match="read as whole days both day first and month first"):
        reader.read(reader.n_rows - 3, reader.n_rows)


def test_a_graphtec_log_with_its_date_apart_counts_on_past_midnight(write, graphtec_export):
    text = graphtec_export(step_ms=250, split_date=True)
    assert "\r\n9,14/03/2026,00:00:00,0," in text
    table, meta = read_table(write("GL980.csv", text), kind="engagement",
                             columns={"force": "CH1", "angle": "CH2"})
    np.testing.assert_allclose(table["time"], np.arange(len(table)) * 0.25, rtol=0, atol=1e-9)
    assert meta.time_monotonic


def test_a_workbook_date_beside_its_time_of_day(tmp_path):
    book = openpyxl.Workbook()
    book.active.append(["Date", "Time", "Load [kN]"])
    start = datetime.datetime(2026, 3, 5, 23, 59, 58, 500_000)
    for s, force in zip(SECONDS, FORCE_KN, strict=True):
        stamp = start + datetime.timedelta(seconds=float(s))
        book.active.append([stamp.date(), stamp.time(), float(force)])  # cells of dates
    book.save(tmp_path / "log.xlsx")
    table, meta = read_table(tmp_path / "log.xlsx", kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-6)
    assert meta.time_monotonic


def hours_minutes_seconds(seconds: float) -> str:
    """``H:MM:SS.fff`` of a time elapsed, the hours past 24 as a rig's test clock counts."""
    hours, rest = divmod(round(seconds * 1000), 3_600_000)
    minutes, milliseconds = divmod(rest, 60_000)
    return f"{hours}:{minutes:02d}:{milliseconds / 1000:06.3f}"


def test_a_clock_of_the_time_elapsed_counts_on_past_24_hours(write):
    cells = [hours_minutes_seconds(86_398.5 + s) for s in SECONDS]
    assert cells[0] == "23:59:58.500" and cells[-1] == "24:00:01.250"
    table, meta = read_table(write("wear.csv", log(cells, "Test time,Load (kN)")),
                             kind="engagement")
    np.testing.assert_allclose(table["time"], SECONDS, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    hours = ClockColumn("time of day", "99:59:59").seconds_of_texts(
        ["99:59:59", "100:00:00", "1000:00:00,5"])
    np.testing.assert_allclose(hours, [0.0, 1.0, 900 * 3600 + 1.5], rtol=0, atol=1e-9)


def test_a_twelve_hour_clock_passes_noon_and_midnight():
    """12 PM is noon, 12 AM midnight: hand-counted seconds after the first reading."""
    cells = ["11:59:59.5 AM", "12:00:00.5 PM", "12:59:59 PM", "1:00:00 PM", "11:59:59 PM",
             "12:00:00 AM"]
    expected = [0.0, 1.0, 3599.5, 3600.5, 43199.5, -43199.5]  # the time of day steps back
    np.testing.assert_allclose(ClockColumn(clock_kind(cells[0]), cells[0]).seconds_of_texts(
        cells), expected, rtol=0, atol=1e-9)
