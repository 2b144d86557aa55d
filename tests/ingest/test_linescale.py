"""LineScale dynamometer logs: the device's settings as Key=Value, then one force reading a
line, the time built from the log's Speed (its rate in Hz)."""

import numpy as np
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest import open_log, read_table
from pipeline.units import STANDARD_GRAVITY

#: A pull on a chain sling logged by the dynamometer [kN] (our numbers).
FORCE_KN = np.array([0.02, 0.41, 1.56, 3.14, 4.63, 2.72, 0.35, 0.03])


def log(unit: str = "kN", speed: str = "40", values=FORCE_KN) -> str:
    """A LineScale 3 log, in the layout of a real one (its PC software's logfile.csv)."""
    settings = {"LogNo": "002", "Unit": unit, "Mode": "REL", "RelZero": "0.02",
                "Speed": speed, "Trig": "0.70", "Stop": "0.00", "Pre": "3", "Catch": "15",
                "Total": "18"}
    return ("6B:6C:05\r\n15.05.22\r\n16:14:25\r\n"
            + "".join(f"{key}={value}\r\n" for key, value in settings.items())
            + "".join(f"{value:.2f}\r\n" for value in values))


@pytest.mark.parametrize("unit, newtons", [("kN", 1e3), ("kgf", STANDARD_GRAVITY)])
def test_the_force_is_in_the_logs_unit_and_the_time_at_its_speed(write, unit, newtons):
    path = write("logfile0.csv", log(unit=unit, speed="1280"))
    table, meta = read_table(path, kind="engagement")
    assert meta.layout == "linescale" and meta.rows == len(FORCE_KN)
    np.testing.assert_allclose(table["time"], np.arange(len(FORCE_KN)) / 1280, rtol=1e-12)
    np.testing.assert_allclose(table["force"], newtons * FORCE_KN, rtol=1e-12)
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("Time", "time", "s"), ("Force", "force", unit)]
    assert meta.preamble["Unit"] == unit and meta.preamble["Total"] == "18"
    rows, _ = open_log(path).read(2, 5)  # by row ranges too
    np.testing.assert_allclose(rows["time"], np.arange(2, 5) / 1280, rtol=1e-12)
    np.testing.assert_allclose(rows["force"], newtons * FORCE_KN[2:5], rtol=1e-12)


def test_a_speed_that_is_no_rate_is_refused(write):
    with pytest.raises(LayoutError, match="Speed=fast is no sampling rate"):
        read_table(write("logfile0.csv", log(speed="fast")), kind="engagement")


def test_settings_of_another_device_are_no_linescale_log(write):
    # a logger's Key=Value settings without LineScale's own: not this layout
    text = "Unit=N\r\nSpeed=10\r\n" + "".join(f"{value:.2f}\r\n" for value in FORCE_KN)
    with pytest.raises(LayoutError):
        read_table(write("other.csv", text), kind="engagement")
