"""HBM catman ASCII export: the channel names and units above the channels' settings."""

import numpy as np
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest import open_log, read_table
from pipeline.ingest.sniff import HEAD_BYTES

#: The head of a real catman AP export of an MGCplus (three of its channels), as it
#: writes it: the settings, the names with their channel numbers, the units, then one
#: row per setting of every channel, a blank line and the data.
HEAD = ("HBM_CATMAN_DATAFILE_40\n\n2017-11-13\n11:24\nCHANNELS: 3\nSEPARATOR: 9\n"
        "MAXLINES: 38730              \n\n"
        "Time DEVICE_1 (Sample rate 1) CH=1\tLoad CH=2\tStroke CH=3\n"
        "s\tkN\tmm\n")
SETTINGS = ("2017-11-10-17:06\t2017-11-10-17:06\t2017-11-10-17:06\n"
            "\t\t\n"
            "T0 =10.11.17 16:53:58\tT0 =10.11.17 16:53:58\tT0 =10.11.17 16:53:58\n"
            "dt =20 ms\tdt =20 ms\tdt =20 ms\n"
            "CH 0\tCH 1 - 1\tCH 1 - 2\n"
            "Not available ID=0\tDC 10V (AP801) ID=5506\tDC 10V (AP801) ID=5506\n"
            "x1=0 y1=0;x2=0 y2=0\tx1=0 y1=0;x2=10 y2=100\tx1=0 y1=0;x2=10 y2=100\n"
            "0  Zero\t0 V-in Zero\t0 V-in Zero\n"
            "Gage factor = 0\tGage factor = 0\tGage factor = 0\n"
            "Cable length correction Not available\tCable length correction Not available"
            "\tCable length correction Not available\n\n")
TIME = 0.02 * np.arange(40)
LOAD_KN = 50 * np.sin(np.pi * TIME / TIME[-1])
STROKE_MM = LOAD_KN / 25


def export(settings: str = SETTINGS, decimal: str = ".", newline: str = "\n") -> str:
    rows = "".join(f"{t:.6f}\t{f:.3f}\t{s:.4f}\n" for t, f, s in zip(TIME, LOAD_KN, STROKE_MM,
                                                                     strict=True))
    return (HEAD + settings + rows.replace(".", decimal)).replace("\n", newline)


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_names_and_units_above_the_settings(write, reader):
    found = reader(write("test_2.asc", export()), kind="tensile")
    table, meta = found if reader is read_table else (found.read(0, 40)[0], found.metadata)
    assert meta.layout == "catman" and meta.first_data_line == 22
    assert [(c.name, c.role, c.unit) for c in meta.columns] == [
        ("Time DEVICE_1 (Sample rate 1)", "time", "s"), ("Load", "force", "kN"),
        ("Stroke", "gauge_1", "mm")]
    np.testing.assert_allclose(table["time"], TIME)
    np.testing.assert_allclose(table["force"], 1e3 * LOAD_KN, atol=0.5)
    np.testing.assert_allclose(table["gauge_1"], 1e-3 * STROKE_MM, atol=5e-8)
    assert (meta.preamble["CHANNELS"], meta.preamble["SEPARATOR"]) == ("3", "9")


@pytest.mark.parametrize("settings", [SETTINGS, "\n", ""], ids=["settings", "blank", "none"])
def test_the_data_start_after_any_number_of_settings(write, settings):
    table, meta = read_table(write("test.asc", export(settings)), kind="tensile")
    assert len(table) == len(TIME)
    assert meta.first_data_line == HEAD.count("\n") + settings.count("\n") + 1
    np.testing.assert_allclose(table["force"], 1e3 * LOAD_KN, atol=0.5)


def test_a_german_export_with_decimal_commas_and_crlf(write):
    table, meta = read_table(write("test.asc", export(decimal=",", newline="\r\n")),
                             kind="tensile")
    assert meta.layout == "catman" and meta.decimal == ","
    np.testing.assert_allclose(table["gauge_1"], 1e-3 * STROKE_MM, atol=5e-8)


def test_the_separator_setting_is_the_delimiter(write):
    text = export().replace("SEPARATOR: 9", "SEPARATOR: 59").replace("\t", ";")
    table, meta = read_table(write("test.asc", text), kind="tensile")
    assert meta.delimiter == ";"
    np.testing.assert_allclose(table["force"], 1e3 * LOAD_KN, atol=0.5)


def test_settings_that_fill_the_head_are_refused(write):
    many = SETTINGS.splitlines(keepends=True)[0] * (HEAD_BYTES // 40)
    with pytest.raises(LayoutError, match="no row of numbers") as caught:
        read_table(write("test.asc", export(many)), kind="tensile")
    assert caught.value.row == 10 and "without the channel information" in caught.value.hint
