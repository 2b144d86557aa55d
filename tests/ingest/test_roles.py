"""Role candidates from the run sheet, names and units."""

import pytest

from pipeline.errors import ColumnError
from pipeline.ingest.roles import find_candidates


def candidates(names, units=None, columns=None):
    units = units or [None] * len(names)
    return find_candidates(names, units, columns, file="f.csv", header_line=1)


def test_automatic_roles_in_file_order():
    found = candidates(["Zeit", "Weg 2", "Kraft", "Weg 1", "Status"])
    assert found.roles == {"time": [0], "gauge": [1, 3], "force": [2]}
    assert found.explicit == frozenset() and found.indexes() == {0, 1, 2, 3}


def test_unit_gives_the_role_of_an_unknown_name():
    assert candidates(["A", "B"], ["s", "kN"]).roles == {"time": [0], "force": [1]}


def test_a_count_is_the_cycle_counter_only_by_its_unit():
    # a DIC rig's frame index "Count" beside the load; an MTS station's counter in segments
    found = candidates(["Count", "Load", "Extension", "1000 kN Count", "Count"],
                       [None, "N", "mm", "segments", "cycles"])
    assert found.roles == {"force": [1], "gauge": [2], "cycle_count": [3, 4]}


def test_the_parts_of_a_clock_reading_take_no_role_from_their_units():
    # a LabVIEW logger's columns: "Minute" in m is minutes, no displacement
    found = candidates(["Time", "Voltage", "Hour", "Minute", "Second"], ["s", "V", "h", "m", "sec"])
    assert found.roles == {"time": [0]}


def test_explicit_roles_exclude_their_columns_from_automatic_matching():
    found = candidates(["Load", "Load 2", "Time"], columns={"force": "load 2"})
    assert found.roles == {"force": [1], "time": [2]}
    assert found.explicit == frozenset({"force"})


def test_group_channel_names():
    found = candidates(["Rig/Force", "Rig/Time"], columns={"force": "Force"})
    assert found.roles == {"force": [0], "time": [1]}


def test_a_name_given_is_the_whole_name_before_a_channel_after_a_slash():
    # a real VIC-3D extensometer export: 'ΔL/L0' ends in the name of the column 'L0'
    found = candidates(["Index", "ΔL/L0", "ΔL", "L1", "L0"], columns={"gauges": ["L0"]})
    assert found.roles["gauge"] == [4]


def test_a_column_without_a_name_is_given_by_what_the_messages_call_it():
    # "the file has: Time, column 2, column 3": the hint's names work in the run sheet
    with pytest.raises(ColumnError) as caught:
        candidates(["Time", "", ""], columns={"force": "Kraft"})
    assert caught.value.hint == "the file has: Time, column 2, column 3"
    found = candidates(["Time", "", ""], columns={"force": "Column 3"})
    assert found.roles == {"force": [2], "time": [0]}
    with pytest.raises(ColumnError, match="no column 'column 4'"):
        candidates(["Time", "", ""], columns={"force": "column 4"})


def test_a_column_is_given_by_its_place_when_its_name_is_duplicated():
    names = ["Channel name", "Force", "Channel name", "Input 1"]
    with pytest.raises(ColumnError) as caught:
        candidates(names, columns={"time": "Channel name"})
    assert 'as "column 1"' in caught.value.hint
    found = candidates(names, columns={"time": "column 3", "force": "Force"})
    assert found.roles["time"] == [2] and found.roles["force"] == [1]
    # a column named so is the one meant, not the place
    assert candidates(["column 2", "Load"], columns={"force": "column 2"}).roles["force"] == [0]


@pytest.mark.parametrize(
    ("columns", "message"),
    [({"force": "Kraft"}, "no column 'Kraft'"), ({"force": "Load"}, "appears 2 times"),
     ({"strain": "Load"}, "unknown role")],
)
def test_run_sheet_errors(columns, message):
    with pytest.raises(ColumnError, match=message):
        candidates(["Load", "Load", "Time"], columns=columns)
