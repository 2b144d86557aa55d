"""NI TDMS: channels by name or Group/Channel, time from waveform properties, truncation."""

import numpy as np
import pandas as pd
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


SEGMENTS = 3
POINTS = 100  # per channel and segment


@pytest.fixture
def segmented(tmp_path):
    """A 3-segment engagement log, its table as read whole and its segments' (start, end)."""
    path = tmp_path / "whole.tdms"
    with TdmsWriter(path) as writer:
        for segment in range(SEGMENTS):
            samples = np.arange(segment * POINTS, (segment + 1) * POINTS, dtype=float)
            writer.write_segment([
                ChannelObject("Rig", "Force", samples, properties=WAVE if segment == 0 else {}),
                ChannelObject("Rig", "Angle", -samples,
                              properties={"unit_string": "rad"} if segment == 0 else {}),
            ])
    content = path.read_bytes()
    starts = [index for index in range(len(content)) if content.startswith(b"TDSm", index)]
    bounds = list(zip(starts, [*starts[1:], len(content)], strict=True))
    table, meta = read_table(path, kind="engagement")
    assert len(table) == SEGMENTS * POINTS and meta.warnings == []
    return content, table, bounds


def cut_file(tmp_path, content: bytes, end: int):
    path = tmp_path / "cut.tdms"
    path.write_bytes(content[:end])
    return path


def assert_nothing_printed(capfd, caplog):
    assert capfd.readouterr().err == ""
    assert not [record for record in caplog.records if record.name.startswith("nptdms")]


@pytest.mark.parametrize(
    ("segment", "offset"),
    [(0, -1), (1, 40), (1, 700), (1, -1), (2, 1000), (2, -1)],
)
def test_truncated_file_is_read_up_to_the_cut(segmented, tmp_path, capfd, caplog, segment,
                                              offset):
    content, whole, bounds = segmented
    start, end = bounds[segment]
    cut = (start if offset >= 0 else end) + offset
    table, meta = read_table(cut_file(tmp_path, content, cut), kind="engagement")
    assert 0 < len(table) < len(whole)
    pd.testing.assert_frame_equal(table, whole.iloc[: len(table)])
    assert (f"the file is truncated ({cut} of {end} bytes, segment {segment + 1} incomplete): "
            f"the {len(table)} samples before the cut were read") in meta.warnings
    assert any(warning.startswith("npTDMS: ") for warning in meta.warnings)
    assert_nothing_printed(capfd, caplog)


@pytest.mark.parametrize("cut", [3, 20, 28, 100, 1000])
def test_truncated_file_with_nothing_before_the_cut(segmented, tmp_path, capfd, caplog, cut):
    content, _, bounds = segmented
    with pytest.raises(LayoutError, match=r"the TDMS file is truncated \(") as caught:
        read_table(cut_file(tmp_path, content, cut), kind="engagement")
    end = 28 if cut < 28 else bounds[0][1]
    assert f"({cut} of {end} bytes, segment 1 incomplete)" in caught.value.message
    assert "copy the file again" in caught.value.hint
    assert_nothing_printed(capfd, caplog)


def test_segment_whose_length_was_never_written(segmented, tmp_path):
    content, whole, bounds = segmented
    start = bounds[-1][0]
    broken = content[: start + 12] + b"\xff" * 8 + content[start + 20 :]
    table, meta = read_table(cut_file(tmp_path, broken, len(broken)), kind="engagement")
    pd.testing.assert_frame_equal(table, whole)
    assert any("truncated (segment 3 incomplete, its length never written)" in warning
               for warning in meta.warnings)


def test_a_time_channel_of_timestamps_becomes_seconds_after_its_first(tdms):
    start = np.datetime64("2024-03-05T23:59:59.990", "us")
    steps = np.arange(40) * 2_500  # 400 Hz, across midnight
    path = tdms({"Rig": {"Time": (start + steps.astype("timedelta64[us]"), {}),
                         "Branch tension": (np.linspace(1.0, 2.0, 40), {"unit_string": "kN"})}})
    table, meta = read_table(path, kind="engagement")
    np.testing.assert_allclose(table["time"], steps * 1e-6, rtol=0, atol=1e-9)
    assert meta.time_monotonic
    assert ("column 'Rig/Time' holds clock readings (date and time, first "
            "'2024-03-05T23:59:59.990000'): read as seconds after the first row's") in meta.warnings
    text = tdms({"Rig": {"Time": (np.array(["a", "b"]), {}),
                         "Branch tension": (np.ones(2), {"unit_string": "kN"})}}, "text.tdms")
    with pytest.raises(ColumnError, match="not numbers"):
        read_table(text, kind="engagement")
