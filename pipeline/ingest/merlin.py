"""Instron Merlin export: a sample's specimens one below the other, in nested blocks.

::

    BeginSample
    <TAB>_SampleName, "15-0291-Pull with PreLoad.mss"
    <TAB>TestSpeed, 12.50,  "mm/min"
    <TAB>BeginSpecimen
    <TAB><TAB>SpecimanName, "311-6",  ""
    <TAB><TAB>PeakLoad, 20613,  "N"
    <TAB><TAB>BeginData
    <TAB><TAB><TAB>_Load, _Time, SlackExt
    <TAB><TAB><TAB>"N", "s", "mm"
    <TAB><TAB><TAB>36.01, 0.200, 0.113
    ...
    <TAB><TAB>EndData
    <TAB>EndSpecimen
    <TAB>BeginSpecimen
    ...
    EndSample

Merlin indents each level by a tab. A file opened in a spreadsheet and saved
again has empty cells in their place (``,,,36.01,0.2,0.113``) and each quoted
text quoted once more, its quotes doubled: both read the same, whatever the
delimiter (``,``, ``;`` or a tab, found in the first names row). The layout is
known by its first line, ``BeginSample``.

Each specimen (``SpecimanName``, as Merlin spells it) is a test of its own. A
file of several is read one specimen at a time: the run sheet's
``specimen_in_file`` names it, by its name or its place from 1 at the top
(:func:`pipeline.ingest.specimens.choose`); without it such a file is refused,
listing them. The preamble holds the sample's settings and the specimen's
own (its peak load, its break), each ``key -> value unit``; a key met twice is
numbered (``"_SampleName (2)"``).

Refused, with a hint: a specimen without a ``BeginData`` block, or whose block
has no names row, units row and data.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field

from pipeline.errors import LayoutError
from pipeline.ingest.delimited import parse_rows, raw_table, text_header
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import Head, TableSpec, detect_dialect, read_head, split_fields
from pipeline.ingest.source import BufferSource
from pipeline.ingest.specimens import choose
from pipeline.ingest.textbody import Region, trim_truncated_tail, truncated_warning

LAYOUT = "merlin"

#: The first line of the file.
FIRST_LINE = "BeginSample"
#: The keys of a specimen's name (Merlin's spelling first).
NAME_KEYS = ("SpecimanName", "SpecimenName")
#: The words that open and close the blocks.
MARKERS = ("BeginSample", "EndSample", "BeginSpecimen", "EndSpecimen", "BeginData",
           "EndData")
#: The delimiters a names row may use, preferred first.
DELIMITERS = (",", ";", "\t")
#: Data rows the dialect is found on.
DIALECT_ROWS = 50


def matches(head: Head, spec: TableSpec | None = None) -> bool:
    """Whether the head is a Merlin export: its first line is ``BeginSample``."""
    return bool(head.lines) and _words(head.lines[0], ",")[:1] == [FIRST_LINE]


def _words(line: str, delimiter: str) -> list[str]:
    """The cells of `line` that hold something, without blanks and quotes around them."""
    cells = (cell.strip().strip('"').strip() for cell in split_fields(line, delimiter))
    return [cell for cell in cells if cell]


@dataclass
class _Specimen:
    """One specimen's block: its settings and where its table lies (indexes of lines)."""

    settings: list[list[str]] = field(default_factory=list)
    names_index: int | None = None
    end_index: int | None = None

    @property
    def label(self) -> str | None:
        return next((words[1] for words in self.settings
                     if words[0] in NAME_KEYS and len(words) > 1), None)


def _structure(lines: list[str]) -> tuple[str, list[list[str]], list[_Specimen]]:
    """The delimiter, the sample's settings and the specimens of a Merlin file's lines."""
    delimiter = _delimiter(lines)
    sample: list[list[str]] = []
    specimens: list[_Specimen] = []
    current: _Specimen | None = None
    index = 0
    while index < len(lines):
        words = _words(lines[index], delimiter)
        key = words[0] if words else ""
        if key == "BeginSpecimen":
            current = _Specimen()
            specimens.append(current)
        elif key == "BeginData":
            if current is None:  # data outside any specimen: the sample's own
                current = _Specimen()
                specimens.append(current)
            current.names_index = next((number for number in range(index + 1, len(lines))
                                        if lines[number].strip(" \t,;")), None)
            current.end_index = next((number for number in range(index + 1, len(lines))
                                      if "EndData" in lines[number]
                                      and _words(lines[number], delimiter)[:1] == ["EndData"]),
                                     len(lines))
            index = current.end_index
        elif key == "EndSpecimen":
            current = None
        elif key and key not in MARKERS:
            (sample if current is None else current.settings).append(words)
        index += 1
    return delimiter, sample, specimens


def _delimiter(lines: list[str]) -> str:
    """The delimiter of the first names row (the line after the first ``BeginData``)."""
    opened = next((index for index, line in enumerate(lines) if "BeginData" in line), None)
    names = lines[opened + 1].lstrip(" \t") if opened is not None and opened + 1 < len(lines) \
        else ""
    return next((delimiter for delimiter in DELIMITERS if delimiter in names), ",")


def _preamble(settings: list[list[str]]) -> dict[str, str]:
    """``key -> value unit`` of settings rows; a key met again is numbered."""
    preamble: dict[str, str] = {}
    for key, *values in settings:
        unique, number = key, 1
        while unique in preamble:
            number += 1
            unique = f"{key} ({number})"
        preamble[unique] = " ".join(values)
    return preamble


def read(head: Head, columns: Mapping | None = None,
         specimen: str | int | None = None) -> RawTable:
    """Read the specimen `specimen` of a Merlin export whose head is `head`.

    Parameters
    ----------
    head : Head
        The file's sniffed head (the whole file is read).
    columns : mapping, optional
        Run-sheet ``columns``.
    specimen : str or int, optional
        Run-sheet ``specimen_in_file``: the specimen's name or its place from 1.

    Raises
    ------
    SpecimensError
        When the file holds several specimens and `specimen` does not say which.
    LayoutError
        When `specimen` names none of them, or the specimen holds no table.
    """
    whole = head if head.complete else read_head(head.source, head.size)
    delimiter, sample, specimens = _structure(whole.lines)
    labels = [found.label for found in specimens]
    labelled = [label for label in labels if label is not None]
    unique = labelled if len(set(labelled)) == len(labels) else []
    first = next((found.names_index for found in specimens), None)
    said = (f"the file holds {len(specimens)} specimens one below the other"
            + (f" ({', '.join(unique)})" if unique else ""))
    if not specimens:
        raise LayoutError("the Merlin export holds no specimen's data (no BeginData block)",
                          file=head.name, hint="export the sample again with its raw data")
    chosen = specimens[choose(unique, len(specimens), specimen, said, "from the top",
                              file=head.name, row=None if first is None else first + 1)]
    spec, table_head = _table_spec(whole, delimiter, chosen)
    header = text_header(table_head, spec, LAYOUT, _preamble(sample + chosen.settings),
                         columns)
    if len(specimens) > 1:
        header.metadata.specimens = unique
        header.metadata.specimen = (unique[specimens.index(chosen)] if unique
                                    else str(specimens.index(chosen) + 1))
    data = ("\n".join(table_head.lines[spec.data_index: chosen.end_index]) + "\n").encode()
    whole_region = Region(BufferSource(data, head.name), 0, len(data), spec.data_index + 1,
                          "utf-8")
    region, truncated = trim_truncated_tail(whole_region, spec.width, spec.delimiter,
                                            spec.decimal)
    parsed, _ = parse_rows(region, spec, header)
    if truncated:
        header.metadata.warnings.append(truncated_warning(whole_region.line_of(parsed[1])))
    return raw_table(parsed, region, header)


def _table_spec(whole: Head, delimiter: str, chosen: _Specimen) -> tuple[TableSpec, Head]:
    """The table of specimen `chosen`, and the file's lines with the block's indent taken
    off the table's rows (the TableSpec's indexes point into them)."""
    names_index, end = chosen.names_index, chosen.end_index
    if names_index is None or end is None or end - names_index < 3:
        raise LayoutError(
            "a specimen's data block has no names row, units row and data",
            file=whole.name, row=None if names_index is None else names_index + 1,
            hint="export the sample again with its raw data")
    cells = split_fields(whole.lines[names_index], delimiter)
    indent = next((index for index, cell in enumerate(cells) if cell.strip()), 0)
    strip = re.compile(r"^[ \t]*" + rf"(?:{re.escape(delimiter)}[ \t]*)" + f"{{{indent}}}")
    lines = list(whole.lines)
    for number in range(names_index, end):
        lines[number] = strip.sub("", lines[number], count=1)
    data = names_index + 2
    _, decimal, width = detect_dialect(lines[data: min(end, data + DIALECT_ROWS)],
                                       whole.name, (delimiter,))
    names = [cell.strip() for cell in split_fields(lines[names_index], delimiter)]
    units = [cell.strip().strip('"').strip() or None
             for cell in split_fields(lines[names_index + 1], delimiter)]
    spec = TableSpec(delimiter=delimiter, decimal=decimal, names=names[:width] + [""] * (
        width - len(names)), header_index=names_index, units_index=names_index + 1,
        data_index=data, width=width, units=(units + [None] * width)[:width])
    return spec, Head(whole.source, whole.encoding, whole.codec, lines, whole.offsets, True)
