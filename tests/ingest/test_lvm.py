"""LabVIEW measurement files: dialect, units and time from their headers."""

import re

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from pipeline.errors import EmptyFileError, LayoutError
from pipeline.ingest import lvm as lvm_reader
from pipeline.ingest import open_log, read_table
from pipeline.ingest.sniff import TableSpec, read_head
from pipeline.ingest.source import BufferSource

TIME = np.arange(40) * 0.01
FORCE_N = 500.0 * np.abs(np.sin(2 * np.pi * TIME))
EXTENSION_MM = FORCE_N / 2e4


def lvm(*, x_columns="One", decimal=".", separator="Tab", units=("N", "mm"), x0="0.5",
        rows=None, segment_again=False, multi=False) -> str:
    """A LabVIEW measurement file of force and extension (`units` None: no Y_Unit_Label)."""
    d = "\t" if separator == "Tab" else ","

    def line(*fields):
        return d.join(fields)

    def num(value, digits=6):
        return f"{value:.{digits}f}".replace(".", decimal)

    segment = [line("Channels", "2", ""), line("Samples", "40", "40", ""),
               line("Date", "2024/03/05", "2024/03/05", ""),
               line("X_Dimension", "Time", "Time", ""),
               line("X0", x0.replace(".", decimal), x0.replace(".", decimal), ""),
               line("Delta_X", num(0.01), num(0.01), ""), "***End_of_Header***"]
    if units is not None:
        segment.insert(3, line("Y_Unit_Label", *units, ""))
    head = ["LabVIEW Measurement", line("Writer_Version", "2"), line("Separator", separator),
            line("Decimal_Separator", decimal), line("Multi_Headings", "No"),
            line("X_Columns", "Multi" if multi else x_columns), line("Operator", "lab"),
            "***End_of_Header***", "", *segment,
            line("X_Value", "Force", *(["X_Value"] if multi else []), "Extension", "Comment")]
    first = (lambda t: [num(t)]) if x_columns == "One" else (lambda t: [""])
    body = rows if rows is not None else [
        line(*first(t), num(f), *([num(t)] if multi else []), num(e))
        for t, f, e in zip(TIME, FORCE_N, EXTENSION_MM, strict=True)]
    tail = ["", *segment, line("X_Value", "Force", "Extension", "Comment"), *body] \
        if segment_again else []
    return "\r\n".join([*head, *body, *tail]) + "\r\n"


def test_x_column_units_and_preamble_from_the_headers(write):
    table, meta = read_table(write("log.lvm", lvm()), kind="engagement")
    assert (meta.layout, meta.delimiter, meta.decimal) == ("lvm", "\t", ".")
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["force"], np.round(FORCE_N, 6))
    np.testing.assert_allclose(table["gauge_1"], np.round(EXTENSION_MM, 6) * 1e-3)
    assert [(c.name, c.unit) for c in meta.columns] == [
        ("Time", "s"), ("Force", "N"), ("Extension", "mm")]
    assert (meta.preamble["Operator"], meta.preamble["X_Columns"]) == ("lab", "One")
    assert meta.warnings == []


@pytest.mark.parametrize("separator", ["Tab", "Comma"])
def test_no_x_column_time_from_x0_and_delta_x_with_a_decimal_comma(write, separator):
    decimal = "," if separator == "Tab" else "."
    text = lvm(x_columns="No", decimal=decimal, separator=separator)
    table, meta = read_table(write("log.lvm", text), kind="engagement")
    assert meta.decimal == decimal
    np.testing.assert_allclose(table["time"], 0.5 + TIME, rtol=0, atol=1e-12)
    np.testing.assert_allclose(table["force"], np.round(FORCE_N, 6))
    reader = open_log(write("long.lvm", text), kind="engagement")
    np.testing.assert_allclose(reader.read(30, 40)[0]["time"], 0.5 + TIME[30:], atol=1e-12)


def test_an_x0_that_is_a_clock_reading_is_the_times_origin(write):
    # LabVIEW's absolute X0, seconds since 1904: added to each sample's time, its digits
    # rounded a 25.6 kHz step of 39.0625 µs to 39.1006 µs, the rate 0.04 % off
    table, meta = read_table(write("log.lvm", lvm(x_columns="No", x0="3592621801.0")),
                             kind="engagement")
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-12)
    assert meta.warnings == ["X0 = 3592621801 s is a clock reading (LabVIEW counts from "
                             "1904): the time is counted from it"]


@pytest.mark.parametrize("samples, warned", [("400", True), ("40", False), ("10", False)])
def test_fewer_rows_than_the_stated_samples_are_warned_of(write, samples, warned):
    # a real LVM states Samples 51200 over 3 rows; more rows are many writes of the VI
    text = lvm().replace("Samples\t40\t40", f"Samples\t{samples}\t{samples}")
    _, meta = read_table(write("log.lvm", text), kind="engagement")
    said = (f"the header says Samples = {samples}, the file holds 40 rows: it may be cut short "
            "(copy it again from the machine)")
    assert (said in meta.warnings) is warned


def test_a_time_built_from_channels_of_other_rates_is_questioned(write):
    text = lvm(x_columns="No").replace("Delta_X\t0.010000\t0.010000", "Delta_X\t0.010000\t0.000606")
    table, meta = read_table(write("log.lvm", text), kind="engagement")
    np.testing.assert_allclose(table["time"], 0.5 + TIME, rtol=0, atol=1e-12)  # the first's
    assert ("the time is built from the first channel's Delta_X (0.010000), but the channels' "
            "differ (0.010000, 0.000606): they were not sampled at one rate (name the time "
            "column in the run sheet if a channel holds the time)") in meta.warnings
    _, same = read_table(write("same.lvm", lvm(x_columns="No")), kind="engagement")
    assert not any("Delta_X" in warning for warning in same.warnings)


def test_no_time_is_built_beside_a_channel_that_holds_the_time(write):
    # a rig's LabVIEW log: a channel "time" of its own, the channels' Delta_X unlike
    # (the "time" channel's 1.0 would make a 1 Hz time of the rows)
    text = "\n".join([
        "LabVIEW Measurement,", "Writer_Version,2", "Reader_Version,2", "Separator,Comma",
        "Decimal_Separator,.", "Multi_Headings,No", "X_Columns,No", "Time_Pref,Relative",
        "***End_of_Header***,", ",", "Channels,2,,", "Samples,5,5,",
        "Y_Unit_Label,s,N,", "X_Dimension,Time,Time,", "X0,0,0,", "Delta_X,1.000000,0.000606,",
        "***End_of_Header***,,,", "X_Value,time,Force,Comment",
        *(f",{0.000606 * i:.6f},{10.0 * i:.1f}" for i in range(5))]) + "\n"
    table, meta = read_table(write("impact.lvm", text), kind="engagement")
    np.testing.assert_allclose(table["time"], 0.000606 * np.arange(5), atol=1e-9)
    assert ("no time is built from the channels' Delta_X: they differ (1.000000, 0.000606), "
            "and channel 'time' holds a time") in meta.warnings


def test_without_unit_labels_the_run_sheet_gives_the_units(write):
    path = write("log.lvm", lvm(units=None))
    with pytest.raises(Exception, match="no unit for the force column"):
        read_table(path)
    table, _ = read_table(path, units={"force": "kN", "gauges": "mm"})
    np.testing.assert_allclose(table["force"], np.round(FORCE_N, 6) * 1e3)


def test_an_x_column_for_every_channel_of_one_x_axis_is_read_by_the_first(write):
    # a real LabVIEW file (X_Columns Multi): each channel's X column repeats the first's
    table, meta = read_table(write("log.lvm", lvm(multi=True)), kind="tensile")
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["gauge_1"], np.round(EXTENSION_MM, 6) * 1e-3)
    assert [(c.name, c.role, c.unit) for c in meta.columns] == [
        ("Time", "time", "s"), ("Force", "force", "N"), ("X_Value 2", None, None),
        ("Extension", "gauge_1", "mm")]


@pytest.mark.parametrize("text, message", [
    (lvm(multi=True).replace("Delta_X\t0.010000\t0.010000", "Delta_X\t0.010000\t0.020000"),
     "X_Columns Multi"),
    (lvm(segment_again=True), "several segments"),
])
def test_what_is_not_read_is_refused_with_a_hint(write, text, message):
    with pytest.raises(LayoutError, match=message) as caught:
        read_table(write("log.lvm", text))
    assert caught.value.hint


def test_one_channel_with_its_x_column_and_the_separator_written_as_itself(write):
    # a real LabVIEW 2017 file: "Separator<TAB>" (the tab itself as the value),
    # X_Columns Multi with one channel, and the names row padded after "Comment"
    text = ("LabVIEW Measurement\t\nWriter_Version\t2\nSeparator\t\nDecimal_Separator\t.\n"
            "X_Columns\tMulti\n***End_of_Header***\t\n\t\nChannels\t1\t\t\t\n"
            "Samples\t3\t\t\t\nY_Unit_Label\tN\t\t\t\nX_Dimension\tTime\t\t\t\n"
            "***End_of_Header***\t\t\t\t\nX_Value\tChan 0\tComment\t\t\t\n"
            "-0.1997486759\t0.23167\n-0.1993486759\t0.24167\n-0.1989486759\t0.25167\n")
    table, meta = read_table(write("Test1.lvm", text), kind="engagement",
                             columns={"force": "Chan 0"})
    assert (meta.delimiter, [c.name for c in meta.columns]) == ("\t", ["Time", "Chan 0"])
    np.testing.assert_allclose(table["time"], [-0.1997486759, -0.1993486759, -0.1989486759])
    np.testing.assert_allclose(table["force"], [0.23167, 0.24167, 0.25167])


def test_a_header_that_does_not_end_is_refused(write):
    text = lvm().split("***End_of_Header***")[0]
    with pytest.raises(LayoutError, match="does not end"):
        read_table(write("log.lvm", text))


def test_a_file_header_alone_is_an_empty_file(write):
    # a real bioreactor logger's file: the acquisition stopped before its first segment
    text = lvm().split("***End_of_Header***")[0] + "***End_of_Header***\t\r\n\t\r\n"
    with pytest.raises(EmptyFileError, match="file header only") as caught:
        read_table(write("test_1.lvm", text))
    assert caught.value.row == 8 and "no measurements" in caught.value.hint


def test_a_csv_that_mentions_labview_later_is_not_an_lvm(write):
    text = "time [s],force [kN],gauge [mm]\n0,1,0.1\n1,2,0.2\nLabVIEW Measurement,,\n"
    _, meta = read_table(write("log.csv", text))
    assert meta.layout == "plain_csv"


def test_a_second_segment_past_the_sniffed_head_is_refused_too(write):
    rows = [f"{i * 0.01:.6f}\t{i % 7:.6f}\t{i % 5:.6f}" for i in range(6000)]  # ~150 KB
    with pytest.raises(LayoutError, match="several segments"):
        read_table(write("log.lvm", lvm(rows=rows, segment_again=True)))


@pytest.mark.parametrize("commented", [0, 1, 17])
def test_rows_with_a_comment_keep_every_sample_and_the_comments_are_named(write, commented):
    # a real LabVIEW file: a comment ("Standby") as one more field on the rows it was
    # given for; before, the other rows were refused as one field short
    rows = [f"{t:.6f}\t{f:.6f}\t{e:.6f}" for t, f, e in zip(TIME, FORCE_N, EXTENSION_MM,
                                                            strict=True)]
    for index in (0, commented):
        rows[index] += "\tStandby" if commented else ""
    table, meta = read_table(write("log.lvm", lvm(rows=rows)), kind="engagement")
    np.testing.assert_allclose(table["time"], TIME, rtol=0, atol=1e-9)
    np.testing.assert_allclose(table["force"], np.round(FORCE_N, 6))
    assert [column.name for column in meta.columns] == ["Time", "Force", "Extension"]
    expected = (2 if commented > 0 else 0)
    if expected:
        assert meta.warnings == [f"{expected} row comment(s) left out of the data, the first "
                                 "'Standby' on line 19"]
    else:
        assert meta.warnings == []


@pytest.mark.parametrize(("rows", "x_columns", "by_range"), [
    (None, "One", True), (None, "No", False), ("commented", "One", False)])
def test_a_long_log_is_read_by_row_range_unless_its_rows_need_the_whole_file(
        write, monkeypatch, rows, x_columns, by_range):
    # its X column and no comment: the rows below the headers are delimited text
    body = None
    if rows == "commented":
        body = [f"{t:.6f}\t{f:.6f}\t{e:.6f}" for t, f, e in zip(TIME, FORCE_N, EXTENSION_MM,
                                                                strict=True)]
        body[30] += "\tStandby"
    path = write("log.lvm", lvm(x_columns=x_columns, rows=body))
    whole, _ = read_table(path, kind="engagement")
    reader = open_log(path, kind="engagement")
    if by_range:
        monkeypatch.setattr(lvm_reader, "read", None)  # the file is no longer read whole
    parts = [reader.read(start, stop)[0] for start, stop in ((0, 7), (7, 31), (31, 40))]
    pd.testing.assert_frame_equal(pd.concat(parts), whole, check_exact=True)


def _lines_with_more_fields(text: str, width: int) -> bool:
    return any(line.count("\t") > width - 1 for line in re.split(r"\r\n|\r|\n", text))


@settings(max_examples=60, deadline=None)
@given(rows=st.lists(st.tuples(st.integers(1, 4), st.sampled_from(["\n", "\r\n", "\r"])),
                     min_size=1, max_size=30),
       block=st.integers(1, 40))
def test_a_row_with_a_field_more_is_found_across_blocks(rows, block):
    # the count of delimiters per line runs over blocks of bytes: a small block cuts
    # rows anywhere, a line end (CR LF too) included
    body = "".join("\t".join(["1.5"] * fields) + end for fields, end in rows)
    text = "names\tof\tthree\n" + body
    head = read_head(BufferSource(text.encode(), "log.lvm"))
    spec = TableSpec(delimiter="\t", decimal=".", names=["a", "b", "c"], header_index=0,
                     units_index=None, data_index=1, width=3, units=[None] * 3, preamble=[])
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(lvm_reader, "BLOCK", block)
        assert lvm_reader._field_more(head, spec) == _lines_with_more_fields(body, 3)
