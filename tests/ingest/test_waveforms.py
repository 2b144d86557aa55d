"""NI DAQ CSVs of waveforms side by side: the x column of each named, the first the time."""

import numpy as np
import pytest

from pipeline.errors import LayoutError
from pipeline.ingest import parse_table

NI_DAQ = ("Timestamp,2/7/2024 3:58:30 PM,Timestamp,2/7/2024 3:58:30 PM\n"
          "Interval,0.0005,Interval,0.0005\n"
          'Channel name,"Force",Channel name,"Input 1"\n'
          'Unit,"kN",Unit,"V"\n'
          "0,0.12,0,-3.21\n0.0005,0.13,0.0005,-3.22\n0.001,0.15,0.001,-3.20\n")


def test_the_first_x_column_is_the_time_in_seconds():
    table, metadata = parse_table(NI_DAQ.encode(), kind="engagement", name="daq.csv")
    np.testing.assert_allclose(table["time"], [0, 0.0005, 0.001])
    np.testing.assert_allclose(table["force"], [120, 130, 150])
    roles = {column.name: column.role for column in metadata.columns}
    assert roles == {"Time": "time", "Force": "force", "X_Value 2": None, "Input 1": None}
    assert any("2 waveform(s) side by side" in warning for warning in metadata.warnings)


@pytest.mark.parametrize(("row", "edited", "message"), [
    (1, "Interval,0.0005,Interval,0.001", "sampled at different intervals"),
    (0, "Timestamp,2/7/2024 3:58:30 PM,Timestamp,2/7/2024 3:58:31 PM",
     "started at different times"),
])
def test_waveforms_of_different_time_axes_are_refused(row, edited, message):
    lines = NI_DAQ.splitlines()
    lines[row] = edited
    with pytest.raises(LayoutError, match=message) as caught:
        parse_table("\n".join(lines).encode(), kind="engagement", name="daq.csv")
    assert caught.value.row == row + 1
