"""NI TDMS: channels by name or Group/Channel, time from waveform properties."""

import numpy as np
import pytest
from nptdms import ChannelObject, GroupObject, TdmsWriter

from pipeline.errors import ColumnError, EmptyFileError, LayoutError
from pipeline.ingest import read_table


@pytest.fixture
def tdms(tmp_path):
    """Write channels (group -> {channel: (data, properties)}) to a TDMS file."""

    def _tdms(groups: dict, name="e.tdms"):
        path = tmp_path / name
        with TdmsWriter(path) as writer:
            for group, channels in groups.items():
                writer.write_segment([GroupObject(group)] + [
                    ChannelObject(group, channel, np.asarray(data), properties=properties)
                    for channel, (data, properties) in channels.items()
                ])
        return path

    return _tdms


WAVE = {"wf_increment": 1e-4, "wf_start_offset": 0.5, "unit_string": "kN"}


def test_time_from_waveform(tdms):
    force = np.linspace(0.0, 1.0, 50)
    path = tdms({"Rig": {"Branch tension": (force, WAVE),
                         "Wheel angle": (np.zeros(50), {"unit_string": "deg"}),
                         "Spare": (np.array([], dtype=float), {})}})
    table, meta = read_table(path, kind="engagement")
    assert list(table.columns) == ["time", "force", "angle"]
    np.testing.assert_allclose(table["time"], 0.5 + 1e-4 * np.arange(50))
    np.testing.assert_allclose(table["force"], force * 1e3)
    assert meta.layout == "tdms" and meta.rows == 50
    assert meta.columns[-1].name == "time (waveform of Rig/Branch tension)"


def test_channels_named_in_the_run_sheet(tdms):
    path = tdms({"A": {"ch0": (np.arange(5.0), WAVE), "ch1": (np.arange(5.0) * 2, WAVE)},
                 "B": {"ch0": (np.arange(5.0) * 3, WAVE)}})
    table, _ = read_table(path, kind="engagement", columns={"force": "B/ch0"})
    np.testing.assert_allclose(table["force"], np.arange(5.0) * 3e3)
    table, _ = read_table(path, kind="engagement", columns={"force": "ch1"},
                          units={"force": "N"})
    np.testing.assert_allclose(table["force"], np.arange(5.0) * 2)


def test_missing_channel_lists_channels(tdms):
    path = tdms({"Rig": {"Force": (np.arange(3.0), WAVE), "Angle": (np.arange(3.0), {})}})
    with pytest.raises(ColumnError, match="no column 'Tension'") as caught:
        read_table(path, kind="engagement", columns={"force": "Tension"})
    assert "Rig/Force, Rig/Angle" in caught.value.hint


def test_duplicated_channel_name(tdms):
    path = tdms({"A": {"F": (np.arange(3.0), WAVE)}, "B": {"F": (np.arange(3.0), WAVE)}})
    with pytest.raises(ColumnError, match="appears 2 times"):
        read_table(path, kind="engagement", columns={"force": "F"})


def test_unequal_lengths_are_cut(tdms):
    path = tdms({"Rig": {"Time": (np.arange(6.0), {"unit_string": "s"}),
                         "Force": (np.arange(5.0), {"unit_string": "N"})}})
    table, meta = read_table(path, kind="engagement")
    assert len(table) == 5 and "unequal length" in meta.warnings[0]


def test_no_samples(tdms):
    with pytest.raises(EmptyFileError):
        read_table(tdms({"Rig": {"Force": (np.array([], dtype=float), WAVE)}}))


def test_not_tdms(write):
    for content in (b"TDSm\x00", b"TDSm" + bytes(range(60))):
        with pytest.raises(LayoutError, match="TDMS"):
            read_table(write("x.tdms", content))
