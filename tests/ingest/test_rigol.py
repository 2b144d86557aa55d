"""Rigol oscilloscope CSV: the time from the start and increment of its units row."""

import numpy as np
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest import open_log, read_table

START, INCREMENT = -1.37e-05, 2e-09


def rigol(rows: int = 40, start: str = "-1.370000e-05") -> str:
    """A Rigol DS1000Z export, as one of a lab's: two channels in volts, rows ending in a
    delimiter."""
    lines = ["X,CH1,CH2,Start,Increment,", f"Sequence,Volt,Volt,{start},2.000000e-09"]
    lines += [f"{x},{0.01 * (x % 7):.2e},{1.8e1:.2e}," for x in range(rows)]
    return "\n".join(lines) + "\n"


def test_the_time_is_start_plus_the_sample_number_times_the_increment(write):
    table, meta = read_table(write("NewFile1.csv", rigol()), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    assert meta.layout == "rigol"
    np.testing.assert_allclose(table["time"], START + INCREMENT * np.arange(40),
                               rtol=0, atol=1e-18)
    np.testing.assert_allclose(table["force"], 10.0 * (np.arange(40) % 7))
    assert [(c.name, c.unit) for c in meta.columns][:3] == [
        ("Time", "s"), ("CH1", "kN"), ("CH2", "Volt")]  # the run sheet's unit replaces Volt
    assert meta.preamble == {"Start": "-1.370000e-05", "Increment": "2.000000e-09"}
    reader = open_log(write("long.csv", rigol()), kind="engagement",
                      columns={"force": "CH1"}, units={"force": "kN"})
    np.testing.assert_allclose(reader.read(30, 40)[0]["time"], table["time"][30:],
                               rtol=0, atol=1e-18)


def test_without_an_x_column_the_time_is_built_from_the_rows_places(write):
    # a real Rigol export of no X column: the time in the empty field the rows end with
    text = rigol().replace("X,CH1", "CH1").replace("Sequence,Volt", "Volt")
    text = "\n".join(line.split(",", 1)[1] if index > 1 else line
                     for index, line in enumerate(text.splitlines())) + "\n"
    table, meta = read_table(write("NewFile1.csv", text), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    assert meta.layout == "rigol"
    assert [(c.name, c.unit) for c in meta.columns][:3] == [
        ("CH1", "kN"), ("CH2", "Volt"), ("Time", "s")]
    np.testing.assert_allclose(table["time"], START + INCREMENT * np.arange(40),
                               rtol=0, atol=1e-18)
    np.testing.assert_allclose(table["force"], 10.0 * (np.arange(40) % 7))
    reader = open_log(write("long.csv", text), kind="engagement",
                      columns={"force": "CH1"}, units={"force": "kN"})
    np.testing.assert_allclose(reader.read(30, 40)[0]["time"], table["time"][30:],
                               rtol=0, atol=1e-18)


def test_volts_are_no_force_until_the_run_sheet_says_so(write):
    with pytest.raises(Exception, match="no force column"):
        read_table(write("NewFile1.csv", rigol()), kind="engagement")


def test_a_time_axis_that_is_not_a_number_is_refused(write):
    with pytest.raises(LayoutError, match="Start and Increment are not numbers"):
        read_table(write("NewFile1.csv", rigol(start="n/a")), kind="engagement")


def test_a_csv_whose_first_column_is_x_is_not_a_rigol_export(write):
    _, meta = read_table(write("x.csv", "X [s],Force [kN]\n0,1\n1,2\n"), kind="engagement")
    assert meta.layout == "plain_csv"
