"""The broken-file corpus (tests/data/bad/): each file and the error or warning it must give.

Binary corpora (an empty ``.xlsx`` sheet, a TDMS without the named channel) are
written by fixtures in ``test_xlsx.py`` and ``test_tdms.py``.
"""

from pathlib import Path

import pytest

from pipeline.errors import (
    ColumnError,
    EmptyFileError,
    EncodingError,
    IngestError,
    LayoutError,
    UnitError,
    ValueParseError,
)
from pipeline.ingest import read_table

BAD = Path(__file__).parents[1] / "data" / "bad"

#: file -> (error class, line, column, text in the message)
ERRORS = {
    "empty.csv": (EmptyFileError, None, None, "empty"),
    "blank_lines.csv": (EmptyFileError, None, None, "blank"),
    "header_only.csv": (EmptyFileError, 2, None, "no data rows"),
    "header_only_machine_export.csv": (EmptyFileError, 6, None, "no data rows"),
    "non_numeric_cell.csv": (ValueParseError, 4, "force", "'abc' is not a number"),
    "unknown_unit.csv": (UnitError, 1, "force", "unknown unit 'Pfund'"),
    "missing_unit.csv": (UnitError, 1, "force", "no unit"),  # a tensile run needs no time
    "wrong_dimension_unit.csv": (UnitError, 1, "force", "not a unit of force"),
    "missing_force_column.csv": (ColumnError, 1, None, "no force column"),
    "duplicated_column.csv": (ColumnError, 1, "Load", "duplicated"),
    "bom_but_cp1250.csv": (EncodingError, 1, None, "byte-order mark"),
    "binary.csv": (EncodingError, 2, None, "binary"),
    "decimal_comma_delimiter_ambiguous.csv": (LayoutError, 3, None, "5 fields"),
    "decimal_comma_delimiter_unsplittable.csv": (LayoutError, 2, "gauge1", "cannot be split"),
    "mixed_decimal_mark.csv": (ValueParseError, 3, "force", "'0.20' is not a number"),
    "too_many_fields.csv": (LayoutError, 3, None, "4 fields where the data rows have 3"),
    "no_header.csv": (LayoutError, 1, None, "no names row"),
}

#: file -> (rows kept, text in a warning): defects read with a warning, nothing lost silently
WARNINGS = {
    "truncated_last_line.csv": (3, "line 5 is truncated"),
    "european_truncated_last_field.csv": (3, "line 5 is truncated"),
    "european_truncated_missing_field.csv": (3, "line 5 is truncated"),
    "machine_export_european_truncated.csv": (3, "line 9 is truncated"),
    "nan_stretch.csv": (5, "3 missing values kept as NaN; longest run 3 rows from line 3"),
    "time_backwards.csv": (4, "steps back 1 times, first at line 4"),
    "time_gap.csv": (5, "1 gap(s) longer than 10 x the median step"),
    "mts_block_mismatch.dat": (2, "lines 10 to 15: a block of other columns than the first "
                                  "(Time, Axial Displacement, Axial Strain, Axial Count: 2 "
                                  "row(s)"),
}


def test_corpus_is_covered():
    assert {path.name for path in BAD.iterdir()} == set(ERRORS) | set(WARNINGS)


@pytest.mark.parametrize("name", sorted(ERRORS))
def test_broken_file_gives_its_typed_error(name):
    kind, line, column, text = ERRORS[name]
    with pytest.raises(kind, match=text) as caught:
        read_table(BAD / name)
    error = caught.value
    assert isinstance(error, IngestError)
    assert (error.file, error.row, error.column) == (str(BAD / name), line, column)
    assert error.hint


@pytest.mark.parametrize("name", sorted(WARNINGS))
def test_defect_is_reported_as_warning(name):
    rows, text = WARNINGS[name]
    table, meta = read_table(BAD / name)
    assert len(table) == rows
    assert any(text in warning for warning in meta.warnings), meta.warnings
