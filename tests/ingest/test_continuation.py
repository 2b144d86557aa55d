"""A test written in parts: the files a test goes on in are named, with a warning."""

import numpy as np

from pipeline.ingest import open_log, read_table
from pipeline.ingest.continuation import HEAD_BYTES

#: An MTS TestSuite export's head, as it writes every part of a long test.
PREAMBLE = ("File Path: C:\\Data\\Test Run 5\\DAQ- Crosshead, … - (Timed){part}.txt   \n"
            "Test: Compression and Relaxation\nTest Run: Test Run 5\n"
            "Date: 10/23/2023 3:06:55 PM\n\n\nCrosshead \tLoad \tTime \nmm\tN\tsec\n")
BASE = "DAQ- Crosshead, … - (Timed)"


def part(number: str, times: np.ndarray, names: str = "Crosshead \tLoad \tTime ") -> str:
    rows = "".join(f"{-3 + t / 100:.6f}\t{0.01 * t:.6f}\t{t:.4f}\n" for t in times)
    return PREAMBLE.format(part=number).replace("Crosshead \tLoad \tTime ", names) + rows


def write_parts(write, starts: list[float], rows: int = 40, step: float = 0.1) -> list:
    """Parts of one test whose times start at `starts` [s] and run `rows` samples each."""
    return [write(f"{BASE}{number}.txt",
                  part(number, start + step * np.arange(rows)).replace("\n", "\r\n"))
            for number, start in zip(["", *map(str, range(1, len(starts)))], starts,
                                     strict=True)]


def test_a_test_written_in_parts_is_read_whole(write):
    first, *rest = write_parts(write, [0.1, 4.2, 8.3])
    table, metadata = read_table(first)
    times = np.concatenate([start + 0.1 * np.arange(40) for start in (0.1, 4.2, 8.3)])
    np.testing.assert_allclose(table["time"], times)
    np.testing.assert_allclose(table["force"], 0.01 * times)  # each part's own rows, in N
    assert metadata.rows == 120 and metadata.time_monotonic and metadata.time_gaps == 0
    assert metadata.continued_in == [path.name for path in rest]
    # the first file's last time (0.1 + 39 x 0.1 s) and the next part's first
    assert metadata.warnings[0] == (
        f"read with the parts the test goes on in, '{rest[0].name}', '{rest[1].name}': the "
        "time runs on from this file's last (4 s) to 4.2 s in the next, as a machine writes "
        "a long test in parts")


def test_a_long_log_opened_by_row_ranges_says_its_parts_are_not_read(write):
    first, *rest = write_parts(write, [0.1, 4.2, 8.3])
    reader = open_log(first, kind="tensile")
    assert reader.n_rows == 40
    assert reader.metadata.continued_in == [path.name for path in rest]
    said = [w for w in reader.metadata.warnings if w.startswith("the test goes on in")]
    assert len(said) == 1 and "only this file is read" in said[0]


def test_a_pause_between_two_parts_is_a_time_gap(write):
    first, second = write_parts(write, [0.1, 60.0])
    table, metadata = read_table(first)
    assert len(table) == 80 and metadata.time_gaps == 1
    assert f"time: a gap of 56 s before the part '{second.name}'" in metadata.warnings


def test_the_warnings_of_a_part_name_it(write):
    first, second = write_parts(write, [0.1, 4.2])
    rows = second.read_text(encoding="utf-8").splitlines(keepends=True)
    rows[10] = rows[10].replace(rows[10].split("\t")[1], "-1000000")  # a sentinel
    second.write_text("".join(rows), encoding="utf-8", newline="")
    metadata = read_table(first)[1]
    assert any(warning.startswith(f"in '{second.name}': ") and "sentinel" in warning
               for warning in metadata.warnings)


def test_a_part_in_other_units_ends_the_test_with_a_warning(write):
    first, second, third = write_parts(write, [0.1, 4.2, 8.3])
    third.write_bytes(third.read_bytes().replace(b"mm\tN\tsec", b"mm\tkN\tsec"))
    table, metadata = read_table(first)
    assert len(table) == 80 and metadata.continued_in == [second.name]
    assert (f"'{third.name}' is not read as a further part of the test: its columns or its "
            "time do not run on from the file before") in metadata.warnings


def test_the_last_part_goes_on_in_none(write):
    *_, last = write_parts(write, [0.1, 4.2, 8.3])
    assert read_table(last)[1].continued_in == []


def test_specimens_one_to_a_file_are_no_parts(write):
    """Bluehill writes a specimen per file, ``_1`` beside ``_11``: each starts its time
    again."""
    first, *_ = [write(f"Specimen_RawData_{number}.csv",
                       "Time (s),Load (N),Extension (mm)\n"
                       + "".join(f"{t / 10:.1f},{t},{t / 50}\n" for t in range(30)))
                 for number in ("1", "11", "12")]
    metadata = read_table(first)[1]
    assert metadata.continued_in == []
    assert not any("goes on" in warning for warning in metadata.warnings)


def test_a_file_of_other_columns_is_no_part(write):
    first, _ = write_parts(write, [0.1, 4.2])
    write(f"{BASE}1.txt", part("1", 4.2 + 0.1 * np.arange(40), "Crosshead \tLoad \tTime 2"))
    table, metadata = read_table(first)
    assert metadata.continued_in == [] and len(table) == 40


def test_the_parts_stop_at_the_first_missing_number(write):
    first, second, third = write_parts(write, [0.1, 4.2, 8.3])
    third.rename(third.with_name(f"{BASE}3.txt"))
    assert read_table(first)[1].continued_in == [second.name]


def test_a_part_longer_than_the_head_read_is_found(write):
    """Only the head of a part is read, cut after its last whole line."""
    rows = HEAD_BYTES // 20 + 100  # more than the head holds
    first, second = write_parts(write, [0.1, 0.1 + 0.1 * rows], rows=rows)
    assert second.stat().st_size > HEAD_BYTES
    assert read_table(first)[1].continued_in == [second.name]


def test_without_time_no_part_is_looked_for(write):
    first, _ = [write(f"pull{number}.csv", "Load (N),Extension (mm)\n" + "".join(
        f"{f},{f / 50}\n" for f in range(30))) for number in ("", "1")]
    assert read_table(first)[1].continued_in == []
