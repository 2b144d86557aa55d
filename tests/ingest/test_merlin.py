"""Instron Merlin export: a sample's specimens one below the other, one read per run."""

import numpy as np
import pytest

from pipeline.errors import LayoutError, SpecimensError, ValueParseError
from pipeline.ingest import open_log, parse_table, read_table

#: Two pulls of a bracket, as Merlin exports a sample: force, time, extension after the
#: slack; a cell of each row says which specimen and row it is (A7: 10x N, A8: 20x N).
ROWS = 12


def merlin(names: tuple[str, ...] = ("A7", "A8"), end: bool = True) -> str:
    """A Merlin export of the specimens `names`, indented by tabs as Merlin writes it."""
    lines = ["BeginSample", '\t_SampleName, "15-0257-Pull with PreLoad.mss"',
             '\tTestSpeed, 12.50,  "mm/min"', '\tSampleID, "15-0257",  ""',
             '\t_SampleName, "15-0257-Pull with PreLoad",  ""']
    for place, name in enumerate(names, start=1):
        lines += ["\tBeginSpecimen", f'\t\tSpecimanName, "{name}",  ""',
                  f'\t\tPeakLoad, {12000 + place},  "N"', "\t\tBeginData",
                  "\t\t\t_Load, _Time, SlackExt", '\t\t\t"N", "s", "mm"']
        lines += [f"\t\t\t{10.0 * place * row:.2f}, {0.1 * row:.3f}, {0.083 * row:.3f}"
                  for row in range(1, ROWS + 1)]
        lines += ["\t\tEndData", "\tEndSpecimen"]
    if end:
        lines.append("EndSample")
    return "\r\n".join(lines) + "\r\n"


def resaved(text: str) -> str:
    """`text` opened in a spreadsheet and saved again as CSV: each tab an empty cell, every
    line as wide as the widest, each quoted text quoted again."""
    rows = []
    for line in text.splitlines():
        depth = len(line) - len(line.lstrip("\t"))
        cells = [""] * depth + [cell.strip() for cell in line.lstrip("\t").split(",")]
        cells = [f'" {cell.replace(chr(34), 2 * chr(34))}"' if '"' in cell else cell
                 for cell in cells]
        rows.append(",".join(cells + [""] * (6 - len(cells))))
    return "\n".join(rows) + "\n"


def test_a_file_of_several_specimens_is_refused_naming_them(write):
    with pytest.raises(SpecimensError, match="2 specimens one below the other") as caught:
        read_table(write("pull.txt", merlin()))
    assert caught.value.specimens == ["A7", "A8"]
    assert 'specimen_in_file = "A7"' in caught.value.hint
    assert "the places 1 to 2 from the top" in caught.value.hint


@pytest.mark.parametrize("specimen", ["A8", 2])
def test_the_specimen_named_is_read_by_its_name_or_place(write, specimen):
    table, meta = read_table(write("pull.txt", merlin()), specimen=specimen)
    rows = np.arange(1, ROWS + 1)
    assert meta.layout == "merlin"
    assert (meta.specimen, meta.specimens) == ("A8", ["A7", "A8"])
    np.testing.assert_allclose(table["force"], 20.0 * rows)
    np.testing.assert_allclose(table["time"], 0.1 * rows)
    np.testing.assert_allclose(table["gauge_1"], 0.083e-3 * rows)
    assert [(c.name, c.role, c.unit) for c in meta.columns] == [
        ("_Load", "force", "N"), ("_Time", "time", "s"), ("SlackExt", "gauge_1", "mm")]
    # the sample's settings and the specimen's own; a key met twice is numbered
    assert meta.preamble == {
        "_SampleName": "15-0257-Pull with PreLoad.mss", "TestSpeed": "12.50 mm/min",
        "SampleID": "15-0257", "_SampleName (2)": "15-0257-Pull with PreLoad",
        "SpecimanName": "A8", "PeakLoad": "12002 N"}
    lines = merlin().split("\r\n")
    names_line = lines.index("\t\t\t_Load, _Time, SlackExt", lines.index("\tEndSpecimen")) + 1
    assert (meta.header_line, meta.first_data_line) == (names_line, names_line + 2)


def test_a_spreadsheets_copy_reads_as_the_export(write):
    native, _ = read_table(write("pull.txt", merlin()), specimen="A7")
    copy, meta = read_table(write("pull.csv", resaved(merlin())), specimen="A7")
    assert meta.layout == "merlin"
    assert meta.preamble["TestSpeed"] == "12.50 mm/min"
    assert not [w for w in meta.warnings if "empty column" in w]
    np.testing.assert_array_equal(copy.to_numpy(), native.to_numpy())


def test_a_bad_cell_is_reported_at_its_line_in_the_file(write):
    text = merlin().replace("\t\t\t40.00, 0.200, 0.166", "\t\t\t40.00, 0.2x0, 0.166")
    line = text.split("\r\n").index("\t\t\t40.00, 0.2x0, 0.166") + 1
    with pytest.raises(ValueParseError, match=f"line {line}"):
        read_table(write("pull.txt", text), specimen=2)
    read_table(write("pull.txt", text), specimen=1)  # the other specimen's rows are not read


def test_a_sample_of_one_specimen_reads_without_saying_which(write):
    table, meta = read_table(write("pull.txt", merlin(("311-6",))))
    assert (len(table), meta.specimen, meta.specimens) == (ROWS, None, [])
    with pytest.raises(LayoutError, match="but the file holds one specimen"):
        read_table(write("pull.txt", merlin(("311-6",))), specimen="311-6")


def test_a_specimen_the_file_does_not_hold_is_refused(write):
    with pytest.raises(LayoutError, match='none of them "A9"') as caught:
        read_table(write("pull.txt", merlin()), specimen="A9")
    assert "A7, A8" in caught.value.hint


def test_a_file_cut_off_in_its_last_specimen_reads_to_its_end(write):
    text = merlin(end=False).rsplit("\t\tEndData", 1)[0]
    table, _ = read_table(write("pull.txt", text), specimen="A8")
    assert len(table) == ROWS


def test_the_log_reader_reads_the_same_rows(write):
    path = write("pull.txt", merlin())
    table, _ = read_table(path, kind="engagement", specimen="A8")
    reader = open_log(path, kind="engagement", specimen="A8")
    assert reader.n_rows == ROWS
    np.testing.assert_array_equal(reader.read(3, 9)[0].to_numpy(), table[3:9].to_numpy())
    buffered, _ = parse_table(merlin().encode(), kind="engagement", specimen="A8",
                              name="pull.txt")
    np.testing.assert_array_equal(buffered.to_numpy(), table.to_numpy())
