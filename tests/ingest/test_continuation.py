"""A test written in parts: the files a test goes on in are named, with a warning."""

import numpy as np
import pytest

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


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_the_parts_a_test_goes_on_in_are_named_with_a_warning(write, reader):
    first, *rest = write_parts(write, [0.1, 4.2, 8.3])
    metadata = (open_log(first, kind="tensile").metadata if reader is open_log
                else read_table(first)[1])
    assert metadata.continued_in == [path.name for path in rest]
    said = [w for w in metadata.warnings if w.startswith("the test goes on in")]
    assert len(said) == 1
    # the first file's last time (0.1 + 39 x 0.1 s) and the next part's first
    assert "this file's last (4 s) to 4.2 s there" in said[0]
    assert f"'{rest[0].name}', '{rest[1].name}'" in said[0]


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
    assert read_table(first)[1].continued_in == []


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
