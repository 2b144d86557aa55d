"""Property-based tests of read_table: odd input gives a typed error or the right numbers.

* random bytes, random "CSV-ish" text and random edits of a valid file: only
  :class:`~pipeline.errors.IngestError` subclasses may escape;
* random valid tables (delimiter, decimal mark, encoding, header style, units,
  NaN runs, a truncated last line): every value comes back in SI units, to
  float precision.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pipeline.errors import IngestError
from pipeline.ingest import read_table
from pipeline.units import to_si

FAST = settings(max_examples=150, deadline=None,
                suppress_health_check=[HealthCheck.too_slow])

VALID = (
    b'Machine : Amsler\r\n\r\nTime,Extension,Load,Total Cycle Count\r\n(sec),(mm),(N),\r\n'
    b"0.0,-2.04,-4.31,0\r\n0.02,-2.05,-4.37,0\r\n0.04,-2.06,-4.49,1\r\n0.06,-2.07,-4.52,1\r\n"
)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("properties")


def read_or_typed_error(path, **options):
    """Read `path`; a typed ingest error is an acceptable outcome, anything else fails."""
    try:
        return read_table(path, **options)
    except IngestError as error:
        assert error.file == str(path)
        return None


@FAST
@given(content=st.binary(max_size=3000), suffix=st.sampled_from([".csv", ".xlsx", ".tdms"]))
def test_random_bytes(folder, content, suffix):
    path = folder / f"random{suffix}"
    path.write_bytes(content)
    read_or_typed_error(path)


@FAST
@given(text=st.text(alphabet="0123456789.,;\t\n\r-+eE\" abN[]()kmsµ:", max_size=400),
       encoding=st.sampled_from(["utf-8", "utf-16", "cp1250"]))
def test_random_csv_like_text(folder, text, encoding):
    path = folder / "random.csv"
    path.write_bytes(text.encode(encoding))
    read_or_typed_error(path)


@FAST
@given(edits=st.lists(st.tuples(st.integers(0, len(VALID)), st.sampled_from(["put", "drop"]),
                                st.binary(min_size=1, max_size=3)), min_size=1, max_size=6))
def test_edited_valid_file(folder, edits):
    content = bytearray(VALID)
    for position, action, data in edits:
        position = min(position, len(content))
        if action == "put":
            content[position:position] = data
        else:
            del content[position : position + len(data)]
    path = folder / "edited.csv"
    path.write_bytes(bytes(content))
    read_or_typed_error(path)


NAMES = {
    "time": {"ascii": ["time", "Time", "Zeit"], "cp1250": ["czas"], "latin-1": ["Prüfzeit",
                                                                                 "Tiempo"]},
    "force": {"ascii": ["force", "Load", "Kraft", "Standardkraft"],
              "cp1250": ["siła", "obciążenie"], "latin-1": ["Fuerza"]},
    "gauge": {"ascii": ["gauge", "Extension", "Weg"], "cp1250": ["wydłużenie", "przemieszczenie"],
              "latin-1": ["Verlängerung", "Desplazamiento"]},
}
UNITS = {
    "time": ["s", "ms", "min", "sec"],
    "force": ["N", "kN", "daN", "kgf", "kG", "tf", "lbf"],
    "gauge": ["mm", "µm", "um", "m", "in"],
}
ENCODINGS = {"utf-8": ("ascii", "cp1250", "latin-1"), "utf-8-sig": ("ascii", "cp1250"),
             "utf-16": ("ascii", "latin-1"), "cp1250": ("ascii", "cp1250"),
             "latin-1": ("ascii", "latin-1")}
VALUES = st.floats(-1e5, 1e5, allow_nan=False, allow_infinity=False)


@st.composite
def tables(draw):
    """A valid odd table: its bytes, and the roles with their raw values and units."""
    encoding = draw(st.sampled_from(sorted(ENCODINGS)))
    pools = ENCODINGS[encoding]
    delimiter = draw(st.sampled_from([",", ";", "\t"]))
    decimal = draw(st.sampled_from([".", ","]))
    rows = draw(st.integers(1, 25))
    roles = (["time"] if draw(st.booleans()) else []) + ["force"] + ["gauge"] * draw(
        st.integers(1, 2))
    columns = []
    for number, role in enumerate(roles):
        name = draw(st.sampled_from([n for pool in pools for n in NAMES[role].get(pool, [])]))
        if role == "gauge":
            name = f"{name} {number}"
        values = draw(st.lists(VALUES, min_size=rows, max_size=rows))
        missing = draw(st.lists(st.booleans(), min_size=rows, max_size=rows))
        for kept in draw(st.lists(st.integers(0, rows - 1), min_size=min(rows, 2),
                                  max_size=min(rows, 2), unique=True)):
            missing[kept] = False  # two values at least: one alone is no channel
        values = [np.nan if gone else value for value, gone in zip(values, missing, strict=True)]
        columns.append((role, name, draw(st.sampled_from(UNITS[role])), values))
    style = draw(st.sampled_from(["[]", "()", "units row", "preamble and units row"]))
    quote = delimiter == decimal == ","

    def cell(value):
        text = draw(st.sampled_from(["", "NaN"])) if np.isnan(value) else repr(value)
        text = text.replace(".", decimal)
        return f'"{text}"' if quote else text

    if style in ("[]", "()"):
        header = [f"{name} {style[0]}{unit}{style[1]}" for _, name, unit, _ in columns]
        lines = [delimiter.join(header)]
    else:
        lines = ["Machine : Amsler 50 t", ""] if style.startswith("preamble") else []
        lines += [delimiter.join(name for _, name, _, _ in columns),
                  delimiter.join(f"({unit})" for _, _, unit, _ in columns)]
    lines += [delimiter.join(cell(values[row]) for _, _, _, values in columns)
              for row in range(rows)]
    newline = draw(st.sampled_from(["\n", "\r\n"]))
    text = newline.join(lines) + newline
    if draw(st.booleans()):  # a half-written last row, no line end
        text += delimiter.join(cell(1.5) for _ in columns[: draw(st.integers(1, len(columns) -
                                                                             1 or 1))])
        if len(columns) == 1:
            text += delimiter
    return text.encode(encoding), columns


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=tables())
def test_valid_tables_round_trip_to_si(folder, case):
    content, columns = case
    path = folder / "valid.csv"
    path.write_bytes(content)
    table, meta = read_table(path)
    gauges = 0
    for role, name, unit, values in columns:
        if role == "gauge":
            gauges += 1
            role = f"gauge_{gauges}"
        expected = np.asarray(values) * to_si(1.0, unit)
        np.testing.assert_allclose(table[role].to_numpy(), expected, rtol=1e-12, atol=0,
                                   err_msg=f"{role} ({name} [{unit}])")
    assert meta.rows == len(columns[0][3])
