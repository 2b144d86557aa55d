"""open_log and LogReader: any partition of the rows, read by range, is read_table's table."""

import pickle
import random
from functools import partial

import numpy as np
import pandas as pd
import pytest

from pipeline.errors import IngestError, LayoutError, ValueParseError
from pipeline.ingest import open_log, read_table, rowindex, stream

#: Real exports and the options they need (see tests/ingest/test_realdata.py).
REALDATA_OPTIONS = {"EPFL-ENAC__CCFatiguePlatform__TST_2021-10_FA_22.csv":
                    {"units": {"force": "kN", "gauges": "mm"}}}
#: Metadata fields the reader knows at open exactly as read_table gives them.
SAME_METADATA = ("file", "layout", "encoding", "delimiter", "decimal", "rows", "columns",
                 "preamble", "sheet", "header_line", "first_data_line")


@pytest.fixture(params=["default index", "an index every 3 rows"])
def index_step(request, monkeypatch):
    """The text index as shipped, or indexing every 3rd row and scanning 8 bytes at a time
    (so that small files cross many indexed rows and blocks)."""
    if request.param != "default index":
        monkeypatch.setattr(stream, "index_rows", partial(rowindex.index_rows, every=3, block=8))
        monkeypatch.setattr(rowindex, "BLOCK", 8)


EMPTY = "empty column(s) dropped: "


def empty_columns(warnings: list[str]) -> set[str]:
    """The columns the note of empty columns lists."""
    return {column for warning in warnings if EMPTY in warning
            for column in warning.split(EMPTY)[1].split(", ")}


def partitions(rows: int, seed: int) -> list[list[tuple[int, int]]]:
    """Partitions of ``[0, rows)`` as ``(start, stop)`` ranges: whole; 1, 3 and 6 random
    cuts; single rows (every row of a short file, random ones among longer ranges in a
    long file)."""
    rng = random.Random(seed)
    cuts = [set(rng.sample(range(1, rows), min(count, rows - 1))) for count in (1, 3, 6)]
    if rows <= 100:
        cuts.append(set(range(1, rows)))
    else:
        singles = rng.sample(range(1, rows - 1), 12)
        cuts.append({*singles, *(row + 1 for row in singles)})
    return [[(0, rows)]] + [list(zip([0, *sorted(found)], [*sorted(found), rows], strict=True))
                            for found in cuts]


def assert_reads_as_whole(reader, whole, name):
    """Every partition concatenates to `whole`; overlapping ranges are its slices."""
    assert reader.n_rows == len(whole), name
    for parts in partitions(reader.n_rows, seed=len(name)):
        got = pd.concat([reader.read(start, stop)[0] for start, stop in parts])
        pd.testing.assert_frame_equal(got, whole, check_exact=True, obj=f"{name} {parts[:3]}")
    rng = random.Random(1)
    for _ in range(8):
        start = rng.randrange(reader.n_rows)
        stop = rng.randrange(start + 1, reader.n_rows + 1)
        pd.testing.assert_frame_equal(reader.read(start, stop)[0], whole.iloc[start:stop],
                                      check_exact=True, obj=f"{name} [{start}, {stop})")


def assert_opens_as_read(path, **options):
    """The reader's rows and metadata are read_table's."""
    whole, meta = read_table(path, **options)
    reader = open_log(path, **options)
    for name in SAME_METADATA:
        assert getattr(reader.metadata, name) == getattr(meta, name), (path.name, name)
    notes = [warning for warning in reader.metadata.warnings if EMPTY not in warning]
    assert set(notes) <= set(meta.warnings), path.name
    # columns that take no role are not scanned for values at open
    assert empty_columns(reader.metadata.warnings) <= empty_columns(meta.warnings), path.name
    assert_reads_as_whole(reader, whole, path.name)
    return reader, meta


def test_every_layout(corpus, index_step):
    for path, options in corpus.items():
        assert_opens_as_read(path, **options)


def test_whole_file_warnings_are_known_at_open(corpus):
    files = {path.name: path for path in corpus}
    expected = {
        "truncated.csv": ["line 39 is truncated (a half-written last row): dropped"],
        "european_truncated.csv": ["line 39 is truncated (a half-written last row): dropped"],
        "comma_pairs.csv": ["the decimal comma is also the delimiter: values were rejoined "
                            "in pairs"],
        "plain_crlf.csv": [],
        "comment_lines.csv": ["7 comment line(s) among the data rows passed over, the first "
                              "at line 8: '# Skipped 1 cycles'"],
    }
    for name, warnings in expected.items():
        assert open_log(files[name]).metadata.warnings == warnings, name


def test_all_rows_warn_as_the_whole_file(corpus):
    """All but the note of empty columns that take no role, which only a whole read finds."""
    for path, options in corpus.items():
        _, meta = read_table(path, **options)
        reader = open_log(path, **options)
        rest = [warning for warning in meta.warnings if warning not in reader.metadata.warnings
                and warning != "1 empty column(s) dropped: column 4"]
        assert reader.read(0, reader.n_rows)[1] == rest, path.name


def sentinel(column):
    return (f"column {column!r}: 1 sentinel values (-1e+06, MTS / Instron unused-channel "
            "marker) set to NaN")


def missing(count, line):
    return f"force: {count} missing values kept as NaN; longest run {count} rows from {line}"


# the corpus's pause of 0.5 s after row 20, and the step of 0.005 s
GAP = ("time: 1 gap(s) longer than 10 x the median step (0.005 s), the longest 0.505 s, first "
       "before line ")


@pytest.mark.parametrize(
    ("name", "start", "stop", "expected"),
    [
        ("plain_lf.csv", 10, 12, [sentinel("force"), missing(1, "line 13")]),
        ("plain_lf.csv", 0, 10, [missing(3, "line 7")]),
        ("plain_lf.csv", 18, 25, [GAP + "23"]),
        ("plain_lf.csv", 25, 37, []),
        ("blank_lines.csv", 10, 12, [sentinel("force"), missing(1, "line 15")]),
        ("blank_lines.csv", 4, 9, [missing(3, "line 8")]),
        ("blank_lines.csv", 18, 25, [GAP + "28"]),
        ("rig.tdms", 10, 20, [sentinel("Rig/Branch tension"), missing(1, "sample 18")]),
        ("rig.tdms", 18, 1000, []),
    ],
)
def test_a_read_warns_of_its_own_rows(corpus, index_step, name, start, stop, expected):
    reader = open_log(next(path for path in corpus if path.name == name))
    assert reader.read(start, stop)[1] == expected


def test_a_pickled_reader_reads_the_same_rows(corpus):
    path = next(path for path in corpus if path.name == "european.csv")
    reader = open_log(path)
    copy = pickle.loads(pickle.dumps(reader))
    assert copy.metadata == reader.metadata
    for start, stop in ((0, 5), (5, 37), (20, 21)):
        pd.testing.assert_frame_equal(copy.read(start, stop)[0], reader.read(start, stop)[0],
                                      check_exact=True)


@pytest.mark.parametrize(("start", "stop"), [(0, 0), (5, 5), (6, 5), (-1, 3), (0, 38),
                                             (37, 38)])
def test_empty_or_outside_ranges_are_refused(corpus, start, stop):
    reader = open_log(next(path for path in corpus if path.name == "plain_lf.csv"))
    with pytest.raises(ValueError, match=r"\[0, 37\)"):
        reader.read(start, stop)


def test_a_bad_cell_is_met_by_the_read_of_its_rows(write, index_step, monkeypatch):
    lines = ["time [s],force [kN]"] + [f"{row * 0.1:.1f},{row}" for row in range(30)]
    lines[18] = "1.7,x"  # line 19, data row 17
    path = write("bad.csv", "\r\n".join(lines) + "\r\n")
    with pytest.raises(ValueParseError) as whole:
        read_table(path, kind="engagement")
    with pytest.raises(ValueParseError) as caught:
        open_log(path)  # the rows read at open include it
    assert caught.value.row == 19
    monkeypatch.setattr(stream, "EVERY", 4)  # the rows read at open do not
    reader = open_log(path)
    for start, stop in ((10, 20), (17, 18), (0, 30)):
        with pytest.raises(ValueParseError) as caught:
            reader.read(start, stop)
        assert (caught.value.row, caught.value.column, caught.value.message) == (
            whole.value.row, whole.value.column, whole.value.message) == (19, "force",
                                                                          "'x' is not a number")
    table, _ = reader.read(18, 30)
    np.testing.assert_array_equal(table["force"], np.arange(18, 30) * 1e3)
    assert list(table.index) == list(range(18, 30))


def test_a_changed_file_is_not_read_with_an_old_index(write):
    path = write("log.csv", "time [s],force [N]\n" + "".join(f"{i},{i}\n" for i in range(9)))
    reader = open_log(path)
    path.write_bytes(path.read_bytes() + b"9,9\n")
    with pytest.raises(IngestError, match="changed since it was opened"):
        reader.read(0, 3)


def test_a_column_empty_in_the_whole_file_is_dropped(write, monkeypatch):
    monkeypatch.setattr(stream, "EVERY", 4)
    monkeypatch.setattr(stream, "SCAN_ROWS", 5)
    rows = [f"{row * 0.1:.1f},{row},-1000000" for row in range(30)]
    late = rows.copy()
    late[23], late[28] = "2.3,23,45", "2.8,28,46"  # the angle's values, found by later scans
    lone = rows.copy()
    lone[0] = "0.0,0,12.5"  # a setting written beside the first sample, no channel
    for name, lines, columns in (("empty.csv", rows, ["time", "force"]),
                                 ("late.csv", late, ["time", "force", "angle"]),
                                 ("lone.csv", lone, ["time", "force"])):
        path = write(name, "time [s],force [N],angle [deg]\n" + "\n".join(lines) + "\n")
        reader, meta = assert_opens_as_read(path, kind="engagement")
        assert list(reader.read(0, 30)[0].columns) == columns
        assert ("1 empty column(s) dropped: angle" in reader.metadata.warnings) == (
            name == "empty.csv")
        assert ("column 'angle' holds one value (12.5, line 2) over 30 rows: a specimen's "
                "dimension or a setting, no channel: not used" in reader.metadata.warnings
                ) == (name == "lone.csv")


def test_roles_and_units_are_settled_at_open(write):
    path = write("log.csv", "time [s],force\n0,1\n1,2\n")
    with pytest.raises(IngestError, match="no unit"):
        open_log(path)
    reader = open_log(path, units={"force": "kN"})
    np.testing.assert_array_equal(reader.read(1, 2)[0]["force"], [2000.0])
    with pytest.raises(LayoutError, match="no names row"):
        open_log(write("noheader.csv", "0,1\n1,2\n"))
    with pytest.raises(ValueError, match="kind"):
        open_log(path, kind="fatigue")


@pytest.mark.realdata
def test_real_exports(realdata, index_step):
    for path in sorted(realdata.glob("*.*")):
        if path.suffix != ".md":
            assert_opens_as_read(path, kind="tensile", **REALDATA_OPTIONS.get(path.name, {}))


def outcome(open_or_read, path):
    """What reading a TDMS file gives: its table and warnings, or its error."""
    try:
        result = open_or_read(path)
    except IngestError as error:
        return type(error), error.message, error.column
    if isinstance(result, stream.LogReader):
        table, warnings = result.read(0, result.n_rows)
        return table, result.metadata.warnings + warnings
    return result[0], result[1].warnings


def test_a_truncated_tdms_file_is_read_up_to_the_cut(corpus, tmp_path):
    content = next(path for path in corpus if path.name == "rig.tdms").read_bytes()
    cut = tmp_path / "cut.tdms"
    read = 0
    for end in range(len(content) - 1, 0, -len(content) // 80):
        cut.write_bytes(content[:end])
        by_range = outcome(open_log, cut)
        whole = outcome(partial(read_table, kind="engagement"), cut)
        if isinstance(whole[0], pd.DataFrame):
            read += 1
            pd.testing.assert_frame_equal(by_range[0], whole[0], check_exact=True, obj=str(end))
            assert sorted(by_range[1]) == sorted(whole[1]), end
        else:
            assert by_range == whole, end
    assert read > 40  # most cuts leave samples to read


def test_tdms_time_channel_and_unequal_channels(tmp_path, tdms_writer):
    path = tdms_writer(tmp_path / "t.tdms", {
        "Time": (np.arange(300) * 1e-3, {"unit_string": "s"}),
        "Force": (np.linspace(0, 2, 290), {"unit_string": "kN"}),
        "Encoder": (np.arange(310) * 0.5, {"unit_string": "deg"}),
        "Spare": (np.array([], dtype=float), {}),
    }, segments=3)
    reader, meta = assert_opens_as_read(path, kind="engagement")
    assert reader.n_rows == 290 and list(reader.read(3, 4)[0].columns) == [
        "time", "force", "angle"]
    assert reader.metadata.warnings == [
        "channels of unequal length cut to the shortest (Rig/Time: 300, Rig/Force: 290, "
        "Rig/Encoder: 310)", "1 empty column(s) dropped: Rig/Spare"]


@pytest.mark.parametrize("joined", ["-", "/"])
def test_clock_readings_count_from_the_file_first_row_in_every_range(write, index_step, joined):
    rows = [f"2024{joined}03{joined}05 23:59:{58 + row * 0.125:06.3f},{row}" if row < 16 else
            f"2024{joined}03{joined}06 00:00:{(row - 16) * 0.125:06.3f},{row}"
            for row in range(30)]
    path = write("clock.csv", "Time,Load [N]\n" + "\n".join(rows) + "\n")
    reader, meta = assert_opens_as_read(path, kind="engagement")
    table, _ = reader.read(20, 30)
    np.testing.assert_allclose(table["time"], np.arange(20, 30) * 0.125, rtol=0, atol=1e-9)


def test_a_tdms_timestamp_channel_counts_from_its_first_sample_in_every_range(tmp_path,
                                                                              tdms_writer):
    stamps = np.datetime64("2024-03-05T10:00:00", "us") + np.arange(30) * np.timedelta64(250, "us")
    path = tdms_writer(tmp_path / "stamps.tdms", {
        "Time": (stamps, {}), "Force": (np.arange(30.0), {"unit_string": "N"})}, segments=3)
    reader, _ = assert_opens_as_read(path, kind="engagement")
    np.testing.assert_allclose(reader.read(20, 30)[0]["time"], np.arange(20, 30) * 250e-6,
                               rtol=0, atol=1e-12)
