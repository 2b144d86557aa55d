"""LabChart text exports: Key=<TAB>values header lines (channel titles, units, interval),
then the samples, the time first or not at all."""

import numpy as np
import pytest

from pipeline.ingest import open_log, read_table

#: A pull on a chain link logged by a PowerLab at 1 kHz [N, mm] (our numbers).
FORCE_N = np.array([0.0, 12.5, 180.0, 950.0, 2400.0, 1800.0, 300.0, 20.0])
TRAVEL_MM = np.array([0.0, 0.01, 0.05, 0.12, 0.25, 0.21, 0.08, 0.02])


def export(timed: bool = True, units: str = "N\tmm", time_format: str = "StartOfBlock") -> str:
    """A LabChart text export, in the layout of a real one."""
    header = ("Interval=\t0.001 s\nExcelDateTime=\t4.5855649139942347e+04\t07/17/25 "
              f"15:34:45.691019\nTimeFormat=\t{time_format}\nDateFormat=\n"
              "ChannelTitle=\tForce\tDisplacement\nRange=\t10.000 V\t5.000 V\n"
              f"UnitName=\t{units}\nTopValue=\t*\t*\nBottomValue=\t*\t*\n")
    rows = "".join((f"{0.001 * i:g}\t" if timed else "") + f"{force:g}\t{travel:g}\n"
                   for i, (force, travel) in enumerate(zip(FORCE_N, TRAVEL_MM, strict=True)))
    return header + rows


def test_the_channels_take_the_titles_and_units_and_the_first_column_is_the_time(write):
    path = write("pull.txt", export())
    table, meta = read_table(path, kind="tensile")
    assert meta.layout == "labchart" and meta.rows == len(FORCE_N)
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("Time", "time", "s"), ("Force", "force", "N"), ("Displacement", "gauge_1", "mm")]
    np.testing.assert_allclose(table["time"], 0.001 * np.arange(len(FORCE_N)), atol=1e-12)
    np.testing.assert_allclose(table["force"], FORCE_N)
    np.testing.assert_allclose(table["gauge_1"], TRAVEL_MM / 1e3)
    assert meta.preamble["ChannelTitle"] == "Force Displacement"
    rows, _ = open_log(path, kind="tensile").read(2, 6)  # by row ranges too
    np.testing.assert_allclose(rows["force"], FORCE_N[2:6])


def test_without_the_time_column_the_interval_makes_the_time(write):
    table, meta = read_table(write("pull.txt", export(timed=False)), kind="engagement")
    np.testing.assert_allclose(table["time"], 0.001 * np.arange(len(FORCE_N)), rtol=1e-12)
    assert ("the file has no time column: time is built from the header's 'Interval' = "
            "0.001 s (one row each 0.001 s, 0 at the first row)") in meta.warnings


def test_a_channel_without_a_unit_asks_for_one(write):
    # LabChart writes '*' for a channel it has no unit for
    _, meta = read_table(write("pull.txt", export(units="*\tmm")), kind="tensile",
                         strict=False)
    assert [column.unit for column in meta.columns] == ["s", None, "mm"]
    assert any("no unit for the force column" in warning for warning in meta.warnings)


@pytest.mark.parametrize("time_format, unit", [("StartOfBlock", "s"), ("", "s"),
                                               ("TimeOfDay", None)])
def test_the_time_is_in_seconds_from_the_blocks_start_only(write, time_format, unit):
    # a time of day is no count of seconds: left to the clock readers, or to the run sheet
    _, meta = read_table(write("pull.txt", export(time_format=time_format)), kind="tensile",
                         strict=False)
    assert meta.columns[0].unit == unit
