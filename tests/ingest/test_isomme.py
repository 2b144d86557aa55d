"""ISO-MME channel files: one channel's header, then its samples one a line, the time built
from the header's sampling interval and the time of the first sample."""

import numpy as np
import pytest

from pipeline.ingest import open_log, read_table

#: A drop tower's force channel, pre-trigger samples first (the layout of ISO/TS 13499; our
#: numbers).
FORCE_KN = np.array([0.0, 0.0, 0.5, 2.0, 4.5, 3.0, 1.0, 0.0])


def channel(unit: str = "kN", name: str = "Chain Force Z", values=FORCE_KN) -> str:
    header = {
        "Data format edition number": "1.6", "Channel code": "00CHAI0000FOZP",
        "Name of the channel": name, "Sampling interval": "1.000000E-4",
        "Unit": unit, "Time of first sample": "-2.000000E-4",
        "Number of samples": str(len(values)), "Data status": "ok",
    }
    return "".join(f"{key:<28}:{value}\n" for key, value in header.items()) + "".join(
        f"{value:.6E}\n" for value in values)


def test_the_time_is_built_from_the_first_sample_and_the_interval(write):
    path = write("TEST.001", channel())
    table, meta = read_table(path, kind="engagement")
    assert meta.layout == "isomme" and meta.rows == len(FORCE_KN)
    np.testing.assert_allclose(table["time"], -2e-4 + 1e-4 * np.arange(len(FORCE_KN)),
                               atol=1e-12)
    np.testing.assert_allclose(table["force"], 1e3 * FORCE_KN)
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Time", "s"), ("Chain Force Z", "kN")]
    assert meta.preamble["Number of samples"] == str(len(FORCE_KN))
    rows, _ = open_log(path, kind="engagement").read(3, 6)  # by row ranges too
    np.testing.assert_allclose(rows["force"], 1e3 * FORCE_KN[3:6])
    np.testing.assert_allclose(rows["time"], 1e-4 * np.arange(1, 4), atol=1e-12)


def test_a_channel_without_a_unit_asks_for_one(write):
    from pipeline.errors import UnitError

    path = write("TEST.002", channel(unit="NOVALUE"))
    with pytest.raises(UnitError, match="no unit for the force column"):
        read_table(path, kind="engagement")
    table, _ = read_table(path, kind="engagement", units={"force": "kN"})
    np.testing.assert_allclose(table["force"], 1e3 * FORCE_KN)


def test_a_preamble_of_settings_over_a_table_is_no_channel_file(write):
    text = "Sampling interval: 0.001\nTime of first sample: 0\nTime [s],Force [N]\n0,1\n1,2\n"
    _, meta = read_table(write("log.csv", text), kind="engagement")
    assert meta.layout != "isomme"
