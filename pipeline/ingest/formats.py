"""Which reader reads a file or buffer: its format, then its text layout.

The format comes from the first bytes (zip magic: ``.xlsx``, or OpenDocument
``.ods`` when the zip's first entry names that type, as the format requires;
OLE2 magic: old binary Excel, ``.xls``; ``TDSm``: TDMS), then from the name's
suffix (a ``.xls`` name on bytes of text is text: some machines write their
tab-separated export so); anything else is delimited text, whose
layout is recognised from its sniffed head (:data:`TEXT_LAYOUTS`, tried in
order; a LabVIEW measurement file by its first line).
:func:`~pipeline.ingest.read_table`, :func:`~pipeline.ingest.parse_table` and
:func:`~pipeline.ingest.open_log` all choose their reader here.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import PurePath

from pipeline.ingest import (
    canonical,
    catman,
    delimited,
    gwinstek,
    isomme,
    keyence,
    labchart,
    linescale,
    lvm,
    merlin,
    mts,
    rigol,
    tdms,
    tektronix,
    xlsx,
)
from pipeline.ingest.raw import RawTable
from pipeline.ingest.sniff import (
    Head,
    TableSpec,
    detect_dialect,
    find_table,
    read_head,
    refuse_document,
)
from pipeline.ingest.source import Source

#: Text layouts, in the order they are tried on a file (an Instron Merlin export, a LabVIEW
#: measurement file, an HBM catman export, a Rigol, Tektronix or GW Instek oscilloscope's
#: export, an ISO-MME channel file, a LineScale log, a LabChart export and a KEYENCE
#: logger's are known by their first lines, before a table is looked for).
TEXT_LAYOUTS = {lvm.LAYOUT: lvm, catman.LAYOUT: catman.TEXT, rigol.LAYOUT: rigol,
                tektronix.LAYOUT: tektronix.TEXT, gwinstek.LAYOUT: gwinstek.TEXT,
                isomme.LAYOUT: isomme, linescale.LAYOUT: linescale, labchart.LAYOUT: labchart.TEXT,
                keyence.LAYOUT: keyence.TEXT,
                merlin.LAYOUT: merlin, mts.LAYOUT: mts,
                **{layout.name: layout for layout in delimited.LAYOUTS}}

#: Values of ``format``: auto-detection, a file format, or one text layout.
FORMATS = ("auto", "csv", *xlsx.LAYOUTS, "tdms", *TEXT_LAYOUTS)

_MAGIC = {b"PK\x03\x04": "xlsx", b"\xd0\xcf\x11\xe0": "xls", b"TDSm": "tdms"}
_SUFFIXES = {".xlsx": "xlsx", ".xlsm": "xlsx", ".ods": "ods", ".tdms": "tdms"}
#: An OpenDocument file's first zip entry: its uncompressed ``mimetype`` (the local
#: header is 30 bytes), here of a spreadsheet.
_ODS_MIMETYPE = b"mimetype" + b"application/vnd.oasis.opendocument.spreadsheet"


def check_options(kind: str, format: str) -> None:
    """Raise ValueError for a run kind or format the readers do not know."""
    if format not in FORMATS:
        raise ValueError(f"format must be one of {FORMATS}, not {format!r}")
    if kind not in canonical.REQUIRED:
        raise ValueError(f"kind must be one of {tuple(canonical.REQUIRED)}, not {kind!r}")


def format_of(source: Source) -> str:
    """``"xlsx"``, ``"ods"``, ``"xls"``, ``"tdms"`` or ``"csv"`` from the first bytes, then
    the name's suffix."""
    by_name = _SUFFIXES.get(PurePath(source.name).suffix.lower(), "csv")
    by_magic = _MAGIC.get(source.read(0, 4))
    if by_magic == "xlsx" and (by_name == "ods"
                               or source.read(30, 30 + len(_ODS_MIMETYPE)) == _ODS_MIMETYPE):
        return "ods"
    return by_magic or by_name


@dataclass(frozen=True)
class Sniffed:
    """The reader chosen for a file: a workbook's (``"xlsx"``, ``"ods"``, ``"xls"``),
    ``"tdms"`` or a text layout.

    Attributes
    ----------
    layout : str
        A name of :data:`FORMATS` other than ``"auto"`` and ``"csv"``.
    head, spec : Head and TableSpec, or None
        The sniffed head and table of a text file.
    """

    layout: str
    head: Head | None = None
    spec: TableSpec | None = None


def sniff(source: Source, format: str = "auto") -> Sniffed:
    """Choose the reader of `source`, forced by `format` (a value of :data:`FORMATS`).

    Raises
    ------
    IngestError
        If the file is empty, binary text, or holds no table.
    """
    layout = format_of(source) if format == "auto" else format
    if layout in (*xlsx.LAYOUTS, "tdms"):
        return Sniffed(layout)
    head = read_head(source)
    if layout == merlin.LAYOUT or (layout == "csv" and merlin.matches(head)):
        return Sniffed(merlin.LAYOUT, head)  # its table is found per specimen when read
    # known by their headers
    for known in (lvm, catman, rigol, tektronix, gwinstek, isomme, linescale, labchart,
                  keyence):
        if layout == known.LAYOUT or (layout == "csv" and known.matches(head)):
            return Sniffed(known.LAYOUT, head, known.table_spec(head))
    refuse_document(head.lines, source.name)
    delimiter, decimal, width = detect_dialect(head.lines, source.name)
    spec = find_table(head.lines, source.name, delimiter, decimal, width)
    if layout == "csv":
        layout = next(name for name, reader in TEXT_LAYOUTS.items()
                      if reader.matches(head, spec))
    return Sniffed(layout, head, spec)


def read_raw(
    source: Source, sniffed: Sniffed, columns: Mapping | None, sheet: str | int | None,
    specimen: str | int | None = None,
) -> RawTable:
    """Read the whole of `source` with the reader `sniffed` chose.

    Parameters
    ----------
    source : Source
        The file or buffer.
    sniffed : Sniffed
        Its :func:`sniff`.
    columns : mapping, optional
        Run-sheet ``columns``.
    sheet : str or int, optional
        Sheet of a workbook.
    specimen : str or int, optional
        Of the specimens one below the other in an Instron Merlin export or of the tests
        in an MTS-like export of blocks, the one read (its name or place from 1); the
        other layouts leave the choice of a specimen
        to :func:`~pipeline.ingest.canonical.build`.
    """
    if sniffed.layout in xlsx.LAYOUTS:
        return xlsx.parse(source, sheet, columns, layout=sniffed.layout)
    if sniffed.layout == "tdms":
        return tdms.parse(source, columns)
    if sniffed.layout == merlin.LAYOUT:
        return merlin.read(sniffed.head, columns, specimen)
    if sniffed.layout == mts.LAYOUT:
        return mts.read(sniffed.head, sniffed.spec, columns, specimen)
    return TEXT_LAYOUTS[sniffed.layout].read(sniffed.head, sniffed.spec, columns)
