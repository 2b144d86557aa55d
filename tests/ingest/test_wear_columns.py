"""Wear logs through the readers: running time or cycles, section length or elongation,
load and speed, recognised by name and converted to SI by their units."""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.errors import ColumnError, UnitError
from pipeline.ingest import parse_table

PLAIN = (b"running time [h],cycles [1],section length [mm],load [kN],chain speed [m/s]\n"
         b"0,0,254.25,10,1.5\n5,9000,254.40,10,1.5\n10,18000,254.52,10,1.5\n")


def test_plain_wear_log_in_si():
    table, meta = parse_table(PLAIN, kind="wear", name="w.csv")
    assert list(table.columns) == ["time", "force", "cycle_count", "length", "speed"]
    np.testing.assert_allclose(table["time"], [0, 18000, 36000])  # h -> s
    np.testing.assert_allclose(table["length"], [0.25425, 0.25440, 0.25452])  # mm -> m
    np.testing.assert_allclose(table["force"], 10e3)
    np.testing.assert_allclose(table["cycle_count"], [0, 9000, 18000])
    np.testing.assert_allclose(table["speed"], 1.5)
    roles = {column.name: (column.role, column.si_unit) for column in meta.columns}
    assert roles["section length"] == ("length", "m")
    assert roles["chain speed"] == ("speed", "m/s")


def test_european_german_names_and_an_elongation_gauge():
    text = ("Laufzeit [min];Verlängerung [µm];Kettengeschwindigkeit [m/s]\n"
            "0;0;2\n30;12,5;2\n60;20;2\n").encode("latin-1")
    table, _ = parse_table(text, kind="wear", name="w.csv")
    np.testing.assert_allclose(table["time"], [0, 1800, 3600])
    np.testing.assert_allclose(table["gauge_1"], [0, 12.5e-6, 20e-6])
    np.testing.assert_allclose(table["speed"], 2.0)


def test_polish_section_length_over_cycles():
    text = "Liczba cykli;Długość odcinka [mm]\n0;190,5\n1000;190,6\n2000;190,7\n".encode(
        "cp1250")
    table, _ = parse_table(text, kind="wear", name="w.csv")
    assert list(table.columns) == ["cycle_count", "length"]
    np.testing.assert_allclose(table["length"], [0.1905, 0.1906, 0.1907])


def test_a_speed_in_a_unit_of_no_speed_is_not_used():
    text = b"time [h],length [mm],speed [rpm]\n0,190.5,60\n1,190.6,60\n2,190.7,60\n"
    table, meta = parse_table(text, kind="wear", name="w.csv")
    assert "speed" not in table
    assert any("not a unit of speed" in warning for warning in meta.warnings)


def test_run_sheet_names_and_units_of_the_wear_columns():
    text = b"t,L,v\n0,190.5,1\n1,190.6,1\n2,190.7,1\n"
    table, _ = parse_table(text, kind="wear", name="w.csv",
                           columns={"time": "t", "length": "L", "speed": "v"},
                           units={"time": "h", "length": "mm", "speed": "m/s"})
    np.testing.assert_allclose(table["time"], [0, 3600, 7200])
    np.testing.assert_allclose(table["length"], [0.1905, 0.1906, 0.1907])


@pytest.mark.parametrize("header, error, words", [
    (b"load [kN],length [mm]", ColumnError, "no time or cycle_count column"),
    (b"time [h],load [kN]", ColumnError, "no length or gauge column"),
    (b"time [h],length [kN]", UnitError, "not a unit of length"),
])
def test_a_wear_log_without_its_channels_is_refused(header, error, words):
    with pytest.raises(error, match=words):
        parse_table(header + b"\n0,1\n1,2\n2,3\n", kind="wear", name="w.csv")


def test_a_wear_run_does_without_a_force_or_speed_it_cannot_settle():
    # a pin-on-disc tribometer's log: two speeds, the load beside two friction forces
    text = (b"Test Time [s],Displacement [um],Sliding Velocity [m/s],Speed [m/s],Load [N],"
            b"Friction Force [N],Friction Force [N]\n0,3969,0.1,60,59.8,5.1,5.2\n"
            b"1,3970,0.1,60,59.8,5.3,5.2\n2,3971,0.1,60,59.9,5.2,5.1\n")
    table, meta = parse_table(text, kind="wear", name="pod.csv")
    assert list(table.columns) == ["time", "gauge_1"]
    np.testing.assert_allclose(table["gauge_1"], [3969e-6, 3970e-6, 3971e-6])
    assert any("could be the force" in warning and "which wear runs do without" in warning
               for warning in meta.warnings)
    with pytest.raises(ColumnError, match="could be the force"):  # an engagement run needs it
        parse_table(text, kind="engagement", name="pod.csv")


def test_an_engagement_run_does_without_a_gauge_of_no_unit():
    # a wave tank's mooring line load cell beside the wave maker's paddle position
    text = b"Time [s],Tension [N],WM_Position\n0,10,0.1\n0.001,11,0.2\n0.002,12,0.3\n"
    table, meta = parse_table(text, kind="engagement", name="tank.csv")
    assert list(table.columns) == ["time", "force"]
    assert any("no unit for the gauge column, which engagement runs do without" in warning
               for warning in meta.warnings)
    with pytest.raises(UnitError, match="no unit for the gauge column"):
        parse_table(text, kind="wear", name="tank.csv")
