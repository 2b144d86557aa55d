"""Text lines after the table (a results block, an end-of-test line): left out, with a warning."""

import numpy as np
import pytest

from pipeline.errors import LayoutError, ValueParseError
from pipeline.ingest import open_log, read_table

HEADER = "Time (s),Load (kN),Extension (mm)"
DATA = [f"{row * 0.1:.1f},{row * 0.5:.3f},{row * 0.01:.3f}" for row in range(40)]


def text(trailer: list[str], end: str = "\n") -> str:
    return end.join([HEADER, *DATA, *trailer]) + end


@pytest.mark.parametrize("trailer, shown", [
    (["", "Results", "Maximum Load,19.5", "Elongation at break,0.39"], 3),
    (["Test ended by the operator"], 1),
    (["", "", "Statistik", "Mittelwert: 12,5 kN"], 2),
])
@pytest.mark.parametrize("end, encoding", [("\n", "utf-8"), ("\r\n", "utf-16"), ("\r", "latin-1")])
def test_a_trailer_is_left_out_with_a_warning(write, trailer, shown, end, encoding):
    path = write("log.csv", text(trailer, end), encoding)
    table, meta = read_table(path)
    assert len(table) == len(DATA)
    np.testing.assert_allclose(table["force"], np.arange(40) * 500.0)
    first = next(line for line in trailer if line.strip())
    assert f"{shown} line(s) after the last data row left out, from {first!r}: not data rows" \
        in meta.warnings


def test_a_long_log_read_by_ranges_leaves_the_trailer_out_too(write):
    path = write("log.csv", text(["", "Results", "Maximum Load,19.5"]))
    reader = open_log(path, kind="engagement")
    assert reader.n_rows == len(DATA)
    assert any("after the last data row left out" in w for w in reader.metadata.warnings)
    np.testing.assert_allclose(reader.read(30, 40)[0]["force"], np.arange(30, 40) * 500.0)


@pytest.mark.parametrize("trailer, error", [
    (["4.1,abc,0.41"], ValueParseError),  # a data row with a bad cell
    (["4.0,20.0"], LayoutError),  # a data row short of a field
    (["0.123"], LayoutError),  # a lone number: a row cut short, not text
    (["", "Second test", *DATA[:5]], LayoutError),  # a second table: not left out
])
def test_what_is_not_a_trailer_is_still_refused(write, trailer, error):
    with pytest.raises(error):
        read_table(write("log.csv", text(trailer)))
