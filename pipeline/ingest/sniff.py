"""Sniffing a text export from a small head sample: encoding, dialect, table.

Only the first :data:`HEAD_BYTES` of a file are decoded in Python; the body is
left to :mod:`pipeline.ingest.textbody` (pyarrow). The sniffers find:

* the encoding: a BOM (UTF-8, UTF-16), UTF-16 without BOM (NUL bytes), UTF-8,
  else cp1250 or latin-1, whichever decodes more non-ASCII bytes as letters
  (Polish exports are cp1250, Spanish and German ones latin-1; Turkish cp1254
  where latin-1 would read Icelandic letters), unless the header reads as words
  of another script (words without a Latin letter, or a known column name):
  Russian cp1251, Chinese GBK, Korean cp949, or Japanese Windows' Shift-JIS;
* the dialect: the delimiter (tab, ``;``, ``,``, ``|``) and decimal mark that
  make the most rows all-numeric with one field count;
* the table: the first data row, the names row above it, an optional units
  row between them and the free-text preamble above the names row; a cell
  holding a clock reading (:mod:`pipeline.ingest.clock`) counts as a number, so
  that a time column in a form that is not read is refused as such.
"""

from __future__ import annotations

import codecs
import csv
import re
import unicodedata
from collections import Counter
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from itertools import groupby, pairwise
from pathlib import PureWindowsPath

import pyarrow.csv as pacsv

from pipeline.errors import EmptyFileError, EncodingError, LayoutError
from pipeline.ingest.clock import (
    ClockColumn,
    carried_order,
    clock_kind,
    date_column,
    fraction_column,
    fraction_columns,
    looks_like_clock,
    unpadded_milliseconds,
    unread_clock_hint,
)
from pipeline.ingest.names import (
    COLUMN_NAMES,
    match_role,
    repeats,
    says_result,
    split_name_unit,
    tokens,
)
from pipeline.ingest.source import Source
from pipeline.ingest.unitparse import (
    NO_UNIT_CELLS,
    is_measure_unit,
    is_sample_interval,
    looks_like_unit,
    spellings,
    unit_role,
)

#: Bytes read to sniff a file.
HEAD_BYTES = 1 << 16
#: The delimiter of columns aligned by runs of blanks (spaces or tabs; tried last).
BLANKS = " "
#: Delimiters tried, in order of preference when several fit.
DELIMITERS = ("\t", ";", ",", "|", BLANKS)
#: A number with thousands separators, by decimal mark: ``1,004.80328`` (Bluehill's quoted
#: forces), ``1'017.11`` (a Swiss locale's); with decimal commas, grouped by points before
#: its decimals (``1.017,11``: a spreadsheet's in a German locale) or by blanks (``1 017,11``,
#: a French one's, with a no-break space), and a whole number grouped by points (``1.056``
#: ms), read so only in a column where a cell shows the points to group
#: (:func:`~pipeline.ingest.textbody.parse_body`). Python's and RE2's regular expressions alike.
_BLANKS_GROUPING = "[ \u00a0\u202f]"
THOUSANDS = {
    ".": re.compile(r"[+-]?\d{1,3}(?:(?:,\d{3})+|(?:'\d{3})+)(?:\.\d*)?(?:[eE][+-]?\d+)?"),
    ",": re.compile(r"[+-]?\d{1,3}(?:(?:\.\d{3})+|(?:" + _BLANKS_GROUPING + r"\d{3})+)(?:,\d*)?"),
}
#: What separates the names of a table aligned by blanks when a name holds a blank.
_WIDE_BLANKS = re.compile(r"[ \t]*\t[ \t]*| {2,}")
#: A setting written ``KEY = value`` (an Imada force recorder's ``UNIT = gf,mm``,
#: ``2ND PEAK FORCE = ---,---``).
_SETTING = re.compile(r"\s*[^=,;\t]+? = ")
#: Non-blank lines at the end of the head that the dialect is chosen on.
DIALECT_LINES = 128
#: Lines of the head first classified to find the table (more when they do not tell).
FIND_LINES = 256
#: The most rows a table above the data may have to be passed over as a table of results
#: (one row per specimen of a batch) rather than read as the data.
RESULTS_ROWS = 20
#: First cells of the rows of a results table's statistics (Bluehill: Mean, SD, Min, Max).
STATISTICS_LABELS = frozenset({"mean", "average", "sd", "s.d.", "std", "std dev",
                               "standard deviation", "min", "max", "minimum", "maximum",
                               "median", "cv", "range", "mittelwert", "standardabweichung"})
#: How a Campbell Scientific logger worked a column's values over its output interval, as
#: its TOA5 files say in the row under the units, folded: a sample, an average, an extreme,
#: a total, a standard deviation, a median, a vector average, the time of an extreme.
PROCESSING_WORDS = frozenset({"smp", "avg", "max", "min", "tot", "std", "med", "mom", "wvc",
                              "tmx", "tmn"})
#: Data rows of the head looked at to tell a column of text labels (a step's name, a
#: status) from a column of numbers with a bad cell.
TEXT_ROWS = 32
#: Cell texts read as missing values: pyarrow's defaults (among them a spreadsheet's
#: ``#N/A``), "none" (a data logger's empty channel; Python's None written as text), a lone
#: "." (SAS's missing number, as in a fatigue table's first half cycle) and the other error
#: values of a spreadsheet's formulas (``#VALUE!``, ``#DIV/0!``); each also after the blank
#: of a ", " delimiter (``0.50, , 0.113``).
SPREADSHEET_ERRORS = frozenset({"#VALUE!", "#DIV/0!", "#REF!", "#NUM!", "#NAME?", "#NULL!"})
_NULL_TEXTS = (frozenset(pacsv.ConvertOptions().null_values) | {"None", "none", "."}
               | SPREADSHEET_ERRORS)
NULL_VALUES = _NULL_TEXTS | {" " + text for text in _NULL_TEXTS}
#: Single-byte encodings tried when a file is not UTF-8, in order of preference on a tie.
SINGLE_BYTE_ENCODINGS = ("latin-1", "cp1250")
#: Japanese Windows text (Shift-JIS), chosen when the single-byte encodings give control
#: characters and every non-ASCII character it gives is Japanese (:data:`_JAPANESE_SCRIPTS`).
SHIFT_JIS = "cp932"
#: Unicode name prefixes of the characters of Japanese text (with Greek letters, such as the
#: μ of microstrain, and the degree sign).
_JAPANESE_SCRIPTS = ("CJK", "HIRAGANA", "KATAKANA", "HALFWIDTH KATAKANA", "FULLWIDTH",
                     "GREEK", "IDEOGRAPHIC", "DEGREE", "KATAKANA-HIRAGANA")
#: Turkish Windows text: latin-1 but for six letters (ğ ı ş Ğ İ Ş), which latin-1 reads
#: as Icelandic ones no lab writes (ð ý þ Ð Ý Þ: ``Sýnýfý`` for ``Sınıfı``).
TURKISH = "cp1254"
_TURKISH_BYTES = frozenset(b"\xd0\xdd\xde\xf0\xfd\xfe")
#: Encodings of Windows text in other scripts, tried when latin-1 reads words without a
#: Latin letter (:func:`_in_other_script`), with the Unicode name prefixes of the letters
#: each writes: Russian (cp1251), simplified Chinese (GBK), Korean (cp949), the last two
#: with Greek letters (the µ of a microstrain, ``με``).
OTHER_SCRIPTS = {"cp1251": ("CYRILLIC",), "gbk": ("CJK", "GREEK"), "cp949": ("HANGUL", "GREEK")}
#: Of those, the alphabets, whose text has no symbol within a run of letters (as Chinese
#: or Korean text read in cp1251 has, from bytes that are symbols there: ``ЅГ°Ј``) but
#: for one of these before it (``°С``, ``№``).
ALPHABETS = ("cp1251",)
_LEADING_SYMBOLS = "°µ№±"
#: Words of the column names known in any language (:data:`~pipeline.ingest.names.
#: COLUMN_NAMES`): of two encodings that read another script's letters, the one that reads
#: more of these.
_KNOWN_WORDS = frozenset(tokens(word) for language in COLUMN_NAMES.values()
                         for words in language.values() for word in words)
#: A word of letters.
_WORD = re.compile(r"[^\W\d_]+")
_NON_ASCII_RUN = re.compile(r"[^\x00-\x7f]+")
#: First bytes of the Shift-JIS symbols Japanese text also holds: punctuation, brackets
#: (【kN】), signs (±, ×, ℃, ※), Greek and Cyrillic letters, box drawing (rows 1 to 8 of JIS
#: X 0208), and NEC's circled numbers and unit squares (㎜).
_JIS_SYMBOL_LEADS = frozenset((0x81, 0x82, 0x83, 0x84, 0x87))

_LINE = re.compile(r"([^\r\n]*)(\r\n|\r|\n|$)")
_NON_ASCII = re.compile(r"[^\x00-\x7f]")
#: Row kinds that belong to the table body (see :func:`row_kind`).
_DATA_KINDS = ("numeric", "partial", "missing")
#: The first character of a logger's comment line among its rows (``# missing reply``,
#: ``# Skipped 1 cycles``).
COMMENT_MARK = "#"
_SPECIALS = r"|[+-]?inf(?:inity)?"  # NaN is a missing value (NULL_VALUES), not a number
_NUMBER = {
    mark: re.compile(
        rf" *(?:[+-]?(?:\d+(?:{re.escape(mark)}\d*)?|{re.escape(mark)}\d+)(?:[eE][+-]?\d+)?"
        rf"{_SPECIALS}) *",
        re.IGNORECASE,
    )
    for mark in ".,"
}


@dataclass(frozen=True)
class Head:
    """The decoded head of a text file.

    Attributes
    ----------
    source : Source
        The file or buffer (its name is the one messages give).
    encoding : str
        The encoding as reported (``"utf-8-sig"`` when a BOM was found).
    codec : str
        The Python codec of the text after the BOM.
    lines : list of str
        The complete lines of the sample, without line ends.
    offsets : list of int
        Byte offset of each line's start, plus the offset after the last line.
    complete : bool
        True if the sample is the whole file.
    """

    source: Source
    encoding: str
    codec: str
    lines: list[str]
    offsets: list[int]
    complete: bool

    @property
    def name(self) -> str:
        """The source's name, for messages."""
        return self.source.name

    @property
    def size(self) -> int:
        """The source's length [bytes]."""
        return self.source.size

    @property
    def ascii_compatible(self) -> bool:
        """True if digits and delimiters are single ASCII bytes (all but UTF-16)."""
        return not self.codec.startswith("utf-16")


@dataclass(frozen=True)
class TableSpec:
    """Where the table sits in a text file's head, and its dialect.

    Attributes
    ----------
    delimiter, decimal : str
        The field delimiter and the decimal mark.
    names : list of str
        The names-row cells (units included), one per data field; blank when the
        file has no names row.
    header_index : int or None
        Index in :attr:`Head.lines` of the names row; None when the file begins
        with its data (:func:`require_names`).
    units_index : int or None
        Index of the separate units row, if any.
    data_index : int
        Index of the first data row.
    width : int
        Fields per data row (twice the columns when ``pairs``).
    units : list of str or None
        The units-row cells, one per column.
    preamble : list of str
        The non-blank lines above the names row.
    pairs : bool
        True if a decimal comma is also the delimiter (``0,5,1,25``): each
        value is two fields.
    clocks : dict of int -> ClockColumn
        The columns whose first data cell is a clock reading (``14:03:27.125``).
    results : tuple of (int, int) or None
        The lines (first, past the last; indexes in :attr:`Head.lines`) of the
        results tables passed over above the data (:func:`find_table`).
    passed : list of str
        The non-blank lines of those tables (a logger's settings among them).
    texts : frozenset of int
        The columns whose every cell in the head's first data rows is text (a label of
        the step, a status): they hold no numbers to read.
    notes : tuple of str
        What the reader should say of how the header was read.
    specimens : tuple of str
        The labels of the specimens whose groups of columns stand side by side, as
        the file writes them over the columns (none: one specimen, or unlabelled).
    """

    delimiter: str
    decimal: str
    names: list[str]
    header_index: int | None
    units_index: int | None
    data_index: int
    width: int
    units: list[str | None] = field(default_factory=list)
    preamble: list[str] = field(default_factory=list)
    pairs: bool = False
    clocks: dict[int, ClockColumn] = field(default_factory=dict)
    results: tuple[int, int] | None = None
    passed: list[str] = field(default_factory=list)
    texts: frozenset[int] = frozenset()
    notes: tuple[str, ...] = ()
    specimens: tuple[str, ...] = ()

    @property
    def fractions(self) -> frozenset[int]:
        """The columns counting the fraction of a second of a clock column (:attr:`clocks`):
        part of the time, not a quantity of their own."""
        return fraction_columns(self.clocks)

    def results_warning(self) -> list[str]:
        """The warnings of the header's reading: the results tables passed over, the
        :attr:`notes`."""
        if self.results is None:
            return list(self.notes)
        first, stop = self.results
        return [f"lines {first + 1}-{stop}: a table above the data (of results or settings) "
                f"was passed over; the data are the table from line {self.data_index + 1}",
                *self.notes]


def split_fields(line: str, delimiter: str) -> list[str]:
    """The fields of one line (``"`` quotes honoured, blanks before a quote passed over:
    VIC-3D writes `` "X",  "Y"``); with :data:`BLANKS`, each run of blanks is one delimiter
    and blanks around the line are none."""
    if delimiter == BLANKS:
        line = line.replace("\t", " ").strip()
        if '"' not in line:
            return line.split()
        return next(csv.reader([line], delimiter=" ", skipinitialspace=True), [])
    if '"' not in line:
        return line.split(delimiter)
    try:
        return next(csv.reader([line], delimiter=delimiter, skipinitialspace=True), [])
    except csv.Error:
        return [line]


def is_number(text: str, decimal: str) -> bool:
    """True if `text` is a number written with `decimal` as decimal mark."""
    return _NUMBER[decimal].fullmatch(text) is not None


def is_missing(text: str) -> bool:
    """True if `text` denotes a missing value (empty, ``NaN``, ``N/A``...)."""
    return text.strip() in NULL_VALUES


#: Cells a logger writes for a reading outside the channel's range: Graphtec's
#: ``+++++++`` and ``-------``, a meter's ``OL``, ``OVER``, ``Overflow``, ``BURNOUT``
#: (an open thermocouple); dashes stand for no reading too (a rowing monitor's ``---``).
_OUT_OF_RANGE = re.compile(r"\+{3,}|-{3,}|[+-]?(?:OL|OVER(?:RANGE|FLOW)?|BURNOUT)", re.IGNORECASE)
#: The hint for such a cell.
OUT_OF_RANGE_HINT = (
    "the logger writes this for a reading outside the channel's range, or for no reading: "
    "the signal there is not known, so the reader does not guess it. Record again with a "
    "wider range, or delete the rows if they lie outside the test (or, if the logger "
    "read nothing there, leave the cells empty: missing values are read and told)")


def is_out_of_range(text: str) -> bool:
    """Whether `text` is a logger's mark of a reading out of range (:data:`_OUT_OF_RANGE`)."""
    return _OUT_OF_RANGE.fullmatch(text.strip()) is not None


def cell_hint(text: str, default: str) -> str:
    """The hint for a cell `text` of a numeric column that is not a number: an
    out-of-range mark or a clock reading explained, else `default`."""
    if is_out_of_range(text):
        return OUT_OF_RANGE_HINT
    return unread_clock_hint(text) if looks_like_clock(text) else default


def _line_of(raw: bytes, position: int) -> int:
    return raw.count(b"\n", 0, position) + 1


def detect_encoding(raw: bytes, complete: bool, file: str) -> tuple[str, str, int]:
    """Find the encoding of a file from its head.

    Parameters
    ----------
    raw : bytes
        The head sample.
    complete : bool
        True if `raw` is the whole file (otherwise its last line may be cut).
    file : str
        The file's or buffer's name, for messages.

    Returns
    -------
    encoding : str
        The name reported to the user.
    codec : str
        The codec decoding the text after the BOM.
    bom : int
        Length of the BOM in bytes.

    Raises
    ------
    EncodingError
        If the file is binary, or its BOM contradicts its content.
    """
    for bom, name, codec, shown in (
        (codecs.BOM_UTF8, "utf-8-sig", "utf-8", "UTF-8"),
        (codecs.BOM_UTF16_LE, "utf-16", "utf-16-le", "UTF-16"),
        (codecs.BOM_UTF16_BE, "utf-16", "utf-16-be", "UTF-16"),
    ):
        if raw.startswith(bom):
            _check_decodes(raw, len(bom), codec, complete, file, bom_name=shown)
            return name, codec, len(bom)
    if b"\x00" in raw:
        half = max(len(raw) // 2, 1)
        odd_zeros, even_zeros = raw[1::2].count(0), raw[0::2].count(0)
        for codec, zeros, others in (("utf-16-le", odd_zeros, even_zeros),
                                     ("utf-16-be", even_zeros, odd_zeros)):
            if zeros > 0.3 * half and others == 0 and _printable(raw, codec):
                return codec, codec, 0
        raise EncodingError(
            "the file is binary, not a text table",
            file=file, row=_line_of(raw, raw.index(b"\x00")),
            hint='check the file; give its format in the run sheet (format = "xlsx" or "tdms") '
            "or export it from the machine as CSV",
        )
    text = raw if complete else raw[: raw.rfind(b"\n") + 1] or raw
    try:
        text.decode("utf-8")
    except UnicodeDecodeError:
        pass
    else:
        return "utf-8", "utf-8", 0
    scores = {codec: _letter_score(text, codec) for codec in SINGLE_BYTE_ENCODINGS}
    best = max(
        (codec for codec, score in scores.items() if score is not None),
        key=lambda codec: (scores[codec], codec == "latin-1"),
    )
    if _has_controls(text, best) and _is_japanese(text):
        return SHIFT_JIS, SHIFT_JIS, 0
    if (best == "latin-1" and not _TURKISH_BYTES.isdisjoint(text)
            and _letter_score(text, TURKISH) is not None):  # it decodes
        best = TURKISH
    other, known = _in_other_script(text)
    if other is not None and (known or _reads_foreign_words(text)):
        return other, other, 0
    return best, best, 0


def _reads_foreign_words(raw: bytes) -> bool:
    """Whether latin-1 reads `raw` as words without a Latin letter (``Âðåìÿ``, cp1251's
    ``Время``): at least two, and more than the words that mix in accented letters
    (``Länge``, ``Siła``), of two letters or more each."""
    words = [word for word in _WORD.findall(raw.decode("latin-1"))
             if len(word) > 1 and _NON_ASCII.search(word)]
    foreign = sum(not re.search(r"[A-Za-z]", word) for word in words)
    return foreign >= 2 and 2 * foreign > len(words)


def _in_other_script(raw: bytes) -> tuple[str | None, int]:
    """The encoding of :data:`OTHER_SCRIPTS` that reads every word of `raw` outside ASCII
    in its script (:func:`_of_script`), of several the one reading most known column names
    (:data:`_KNOWN_WORDS`), then the first; and how many it reads. (None, 0) if there is
    none."""
    readings = {}
    for codec, scripts in OTHER_SCRIPTS.items():
        try:
            text = raw.decode(codec)
        except UnicodeDecodeError:
            continue
        foreign = [word for word in _WORD.findall(text) if _NON_ASCII.search(word)]
        if (foreign and all(_of_script(word, scripts) for word in foreign)
                and (codec not in ALPHABETS or all(
                    run.lstrip(_LEADING_SYMBOLS).isalpha() or run in _LEADING_SYMBOLS
                    for run in _NON_ASCII_RUN.findall(text)))):
            readings[codec] = sum(tokens(word) in _KNOWN_WORDS for word in foreign)
    best = max(readings, key=readings.get, default=None)
    return best, readings.get(best, 0)


def _of_script(word: str, scripts: tuple[str, ...]) -> bool:
    """Whether every letter of `word` outside ASCII is of `scripts`, a word that mixes in
    ASCII letters one of a unit's symbol (``μm``: Greek, then Latin); and a word of more
    than three letters of a script with cases (no unit's symbol, as ``кН`` or ``МПа``) in
    one case throughout but for a capital first letter."""
    letters = [char for char in word if not char.isascii()]
    if not all(unicodedata.name(char, "").startswith(scripts) for char in letters):
        return False
    if len(letters) < len(word):  # Latin letters beside
        return all(unicodedata.name(char, "").startswith("GREEK") for char in letters)
    cased = word.lower() != word.upper()
    return not cased or len(word) <= 3 or word.isupper() or word[1:].islower()


def _has_controls(raw: bytes, codec: str) -> bool:
    """Whether `raw` decoded with `codec` holds control characters other than line ends
    and tabs: no text written in that encoding does."""
    return any(unicodedata.category(char) == "Cc" for char in _NON_ASCII.findall(
        raw.decode(codec)))


def _is_japanese(raw: bytes) -> bool:
    """Whether `raw` decodes as Japanese Windows text (:data:`SHIFT_JIS`), its non-ASCII
    characters all ideographs, kana, full-width forms or Japanese symbols."""
    try:
        text = raw.decode(SHIFT_JIS)
    except UnicodeDecodeError:
        return False
    return all(unicodedata.name(char, "").startswith(_JAPANESE_SCRIPTS)
               or char.encode(SHIFT_JIS)[0] in _JIS_SYMBOL_LEADS
               for char in _NON_ASCII.findall(text))


def _printable(raw: bytes, codec: str) -> bool:
    """True if `raw` decodes in `codec` to mostly printable text."""
    text = raw[: len(raw) // 2 * 2].decode(codec, errors="replace")
    return sum(char.isprintable() or char in "\r\n\t" for char in text) >= 0.95 * len(text)


def _letter_score(raw: bytes, codec: str) -> int | None:
    """How many non-ASCII bytes of `raw` decode to letters, minus control characters.

    None if `raw` does not decode (latin-1 always does).
    """
    try:
        text = raw.decode(codec)
    except UnicodeDecodeError:
        return None
    score = 0
    for char in _NON_ASCII.findall(text):
        score += 1 if char.isalpha() else -2 if unicodedata.category(char) == "Cc" else 0
    return score


def _check_decodes(
    raw: bytes, bom: int, codec: str, complete: bool, file: str, *, bom_name: str
) -> None:
    decoder = codecs.getincrementaldecoder(codec)()
    try:
        decoder.decode(raw[bom:], final=complete)
    except UnicodeDecodeError as error:
        raise EncodingError(
            f"the file starts with a {bom_name} byte-order mark but is not {bom_name} text",
            file=file, row=_line_of(raw, bom + error.start),
            hint="re-save the file as UTF-8 (or without the byte-order mark)",
        ) from error


def read_head(source: Source, size: int = HEAD_BYTES) -> Head:
    """Read and decode the head of a text file or buffer: its first `size` bytes [bytes]
    (the whole file when it is no longer).

    Raises
    ------
    EmptyFileError
        If the file is empty or blank.
    EncodingError
        See :func:`detect_encoding`.
    """
    raw = source.read(0, size)
    complete = len(raw) == source.size
    if not raw.strip():
        raise EmptyFileError(
            "the file is empty" if source.size == 0 else "the file holds only blank lines",
            file=source.name, hint="the machine wrote no data: export the test again",
        )
    encoding, codec, bom = detect_encoding(raw, complete, source.name)
    text = codecs.getincrementaldecoder(codec)(errors="replace").decode(raw[bom:], final=complete)
    lines, offsets, position = [], [bom], bom
    for match in _LINE.finditer(text):
        if not match.group(0):
            break
        lines.append(match.group(1))
        position += len(match.group(0).encode(codec))
        offsets.append(position)
    if not complete and lines:
        lines.pop()
        offsets.pop()
    return Head(source, encoding, codec, lines, offsets, complete)


#: The start of a structured document that is no table: a JSON object or array of
#: records (a screwdriver's curve export), an XML document, a Universal File Format
#: dataset (a modal-test system's or catman's UFF: ``-1`` over its dataset number, 58).
_DOCUMENTS = {"JSON": re.compile(r'\s*(?:\{\s*"|\[\s*[{\["])'),
              "XML": re.compile(r"\s*<\?xml\b"),
              "Universal File Format (UFF)": re.compile(r" *-1 *\n *\d+ *\n")}


def refuse_document(lines: list[str], name: str) -> None:
    """Refuse a text file that is a structured document (:data:`_DOCUMENTS`), not a table,
    before its braces or tags are taken for a table's rows.

    Raises
    ------
    LayoutError
        If the head's `lines` open a JSON or XML document.
    """
    text = "\n".join(lines[:5])
    kind = next((kind for kind, start in _DOCUMENTS.items() if start.match(text)), None)
    if kind is not None:
        raise LayoutError(
            f"the file is a {kind} document, not a table of columns", file=name, row=1,
            hint="export the test's channels as a CSV or text table (time, force, "
                 "displacement side by side)")


def detect_dialect(
    lines: list[str], name: str, delimiters: tuple[str, ...] = DELIMITERS
) -> tuple[str, str, int]:
    """Find the delimiter and decimal mark that make the most rows numeric.

    Blanks are tried only when no other delimiter makes half the rows numeric, and win
    only with more than twice the numeric rows (they drop empty cells): a table apart by
    blanks with decimal commas (``0,74 23,5``) has a row or two that the commas split into
    numbers (``2,21 707,7``: 2, 21 707, 7).
    The dialect with the most numeric rows of one width wins, then the one that
    splits the line above its first numeric row (the names row) as wide, then the
    one reading more cells as numbers than as text, then the first in `delimiters`:
    a comma-separated log whose last column holds a raw frame with semicolons
    (``...,No Error,DTA;1;182;233;0;!``) has as many rows of numbers split at
    the semicolons, but its names row is split at the commas only.

    Parameters
    ----------
    lines : list of str
        The head's lines.
    name : str
        The file's or buffer's name, for messages.
    delimiters : tuple of str
        The delimiters to try, preferred first.

    Returns
    -------
    delimiter, decimal : str
        The best dialect.
    width : int
        The number of fields of its numeric rows.

    Raises
    ------
    EmptyFileError
        If no line holds a number (a header without data).
    LayoutError
        If no dialect gives numeric rows.
    """
    sample = [line for line in lines if line.strip()][-DIALECT_LINES:]
    best: tuple[tuple[int, bool, int], str, str, int] = ((0, False, 0), ",", ".", 0)
    for delimiter in delimiters:
        if delimiter == BLANKS and 2 * best[0][0] >= len(sample):
            break  # blanks only when no delimiter gives a table: they drop empty cells
        beaten = 2 * best[0][0] if delimiter == BLANKS else 0
        rows = [split_fields(line, delimiter) for line in sample]
        if delimiter == ",":
            rows = [row for row in rows if not _split_at_decimal_commas(row)]
        for decimal in ".,":
            numeric = [row for row in rows if _numeric_row(row, decimal, delimiter == BLANKS)]
            if not numeric:
                continue
            width = Counter(len(row) for row in numeric).most_common(1)[0][0]
            fitting = [row for row in numeric if len(row) == width]
            score = (len(fitting), _names_as_wide(lines, delimiter, decimal, width),
                     sum(_balance(row, decimal) for row in fitting))
            if score > best[0] and score[0] > beaten:
                best = (score, delimiter, decimal, width)
    if best[0][0] == 0:
        steady = steady_text_columns(lines, delimiters)
        if steady is not None:
            return steady[:3]
        if _one_column_of_numbers(sample):
            raise LayoutError(
                "the file holds one column of numbers: a run needs its channels side by "
                "side (time and force, or force and gauge)",
                file=name,
                hint="export the test with its time (or its displacement) beside the force",
            )
        complex_cells = _cells_like(sample, _COMPLEX)
        if complex_cells:
            raise LayoutError(
                "the cells hold complex numbers (" + ", ".join(map(repr, complex_cells))
                + "): the readers read real numbers", file=name,
                hint="save the real parts (MATLAB's real(x), numpy's x.real)")
        marked = _numbers_with_units(sample)
        if marked:
            raise LayoutError(
                "the cells hold numbers with a unit or percent sign in them ("
                + ", ".join(map(repr, marked)) + "): the readers read bare numbers",
                file=name,
                hint="save the table with bare numbers (a spreadsheet's number format "
                     "without % or a unit) and the unit in the names row, e.g. "
                     "'Elongation [%]'")
        if _quoted_lines(sample):
            raise LayoutError(
                "each line is one quoted cell (" + repr(sample[-1].strip()[:40]) + "...): "
                "the table was saved as one column of text, its fields inside the quotes",
                file=name,
                hint="export the table again without quoting it, or give the run a copy "
                     "of the file with the quote at the start and at the end of each line "
                     "removed (a text editor's replace), keeping the file as it came")
        if not any(_has_two_numbers(line) for line in sample):
            named = _data_file_named(lines, name)
            lone = any(is_number(cell, decimal) for line in sample for delimiter in DELIMITERS
                       if delimiter != BLANKS  # a sentence's year is no result
                       for cell in split_fields(line, delimiter) for decimal in ".,")
            raise EmptyFileError(
                "no data rows: no line holds two numbers side by side, as a log's rows do (a "
                "summary of a test's results?)" if lone else
                "no data rows: the file holds only text lines",
                file=name, row=len(lines) + 1,
                hint=f"the file names {named!r}: the measurements may be there; give that "
                     "file in the run sheet" if named else
                     "the machine wrote no measurements: export the test again" if not lone
                     else "export the test's raw data (time, force, displacement side by "
                          "side), not its results",
            )
        texts = _text_in_every_row(sample, tuple(d for d in delimiters if d != BLANKS))
        if texts:
            raise LayoutError(
                "every row holds text beside its numbers (" + ", ".join(map(repr, texts))
                + "): the readers read columns of numbers only",
                file=name,
                hint="export the measured channels only, or delete the columns of text in "
                     "a copy of the file",
            )
        raise LayoutError(
            "no table of numbers found at the start of the file",
            file=name,
            hint="the readers expect rows of numbers separated by ',', ';', tabs or spaces; "
            'give the format in the run sheet (format = "xlsx" or "tdms") if it is not text',
        )
    return best[1], best[2], best[3]


def _names_as_wide(lines: list[str], delimiter: str, decimal: str, width: int) -> bool:
    """Whether the last non-blank line above the first numeric row of `lines` splits
    into `width` fields (a names row over the table)."""
    above = None
    for line in lines:
        if _numeric_row(split_fields(line, delimiter), decimal, delimiter == BLANKS):
            break
        if line.strip():
            above = line
    return above is not None and len(split_fields(above, delimiter)) == width


#: A line that is one quoted cell holding a number and fields apart by delimiters (two at
#: least: ``"1,5"`` is one number with a decimal comma).
_QUOTED_LINE = re.compile(r'\s*"(?=[^"]*\d)[^"]*[;,\t][^"]*[;,\t][^"]*"\s*')


def _quoted_lines(sample: list[str]) -> bool:
    """Whether most of `sample`'s lines are each one quoted cell holding a row's fields
    (``"2,1762e-03;-26,875e-03;..."``: a table saved through a spreadsheet as one column)."""
    return sum(bool(_QUOTED_LINE.fullmatch(line)) for line in sample) > len(sample) / 2


def _one_column_of_numbers(sample: list[str]) -> bool:
    """Whether `sample`'s lines are mostly single numbers, or end in three or more (a
    meter's log of readings under its settings)."""
    single = [is_number(line.strip(" \t;,"), ".") for line in sample]
    trailing = len(single) - next((at + 1 for at in range(len(single) - 1, -1, -1)
                                   if not single[at]), 0)
    return sum(single) > len(sample) / 2 or trailing >= 3


#: A file name with the extension of a data file, as a header file names its data file
#: (an HBM catman ``.TSX``'s ``DATAFILE=C:\...\DD11_7_3.ASC``).
_DATA_FILE = re.compile(r"[^\\/:=\s\"',;]+\.(?:asc|csv|txt|dat|tdms|lvm|xlsx?|bin)\b",
                        re.IGNORECASE)


def _data_file_named(lines: list[str], name: str) -> str | None:
    """The last data file `lines` name other than the file `name` itself, or None."""
    own = PureWindowsPath(str(name)).name.casefold()  # either separator
    found = [match for line in lines for match in _DATA_FILE.findall(line)
             if match.casefold() != own]
    return found[-1] if found else None


def steady_text_columns(
    lines: list[str], delimiters: tuple[str, ...] = DELIMITERS
) -> tuple[str, str, int, frozenset[int]] | None:
    """The dialect of a table whose rows hold more texts than numbers, and its columns of
    text: a rig's log of states beside its readings (``...,S1,RUNNING,25.420,24.819,RUN,
    RUN,SLEEP,Test started (S1).``), a database's rows of labels beside the measurements.

    Most of the head's last lines, split at a delimiter, are rows of one width with two
    numbers (or clock readings) at least, whose cells are text or missing in the same
    columns in every row, and numbers outnumber texts in the other columns. None when no
    delimiter gives such rows.

    Returns
    -------
    delimiter, decimal : str
        The dialect.
    width : int
        The number of fields of the rows.
    texts : frozenset of int
        The columns of text, left out when rows are told numeric (:func:`row_kind`).
    """
    sample = [line for line in lines if line.strip()][-DIALECT_LINES:]
    best: tuple[int, tuple[str, str, int, frozenset[int]] | None] = (0, None)
    for delimiter in delimiters:
        if delimiter == BLANKS:
            continue  # a sentence splits at its blanks into words and numbers
        rows = [split_fields(line, delimiter) for line in sample]
        for decimal in ".,":
            numbered = [row for row in rows if sum(
                is_number(cell, decimal) or looks_like_clock(cell) for cell in row) >= 2]
            if not numbered:
                continue
            width = Counter(len(row) for row in numbered).most_common(1)[0][0]
            fitting = [row for row in numbered if len(row) == width]
            if len(fitting) < 3 or 2 * len(fitting) <= len(sample) or len(fitting) <= best[0]:
                continue
            texts = frozenset(index for index in range(width) if all(
                is_missing(row[index]) or not (is_number(row[index], decimal)
                                               or looks_like_clock(row[index]))
                for row in fitting) and not all(is_missing(row[index]) for row in fitting))
            if texts and all(_numeric_row(row, decimal, skip=texts) for row in fitting):
                best = (len(fitting), (delimiter, decimal, width, texts))
    return best[1]


def _text_in_every_row(sample: list[str], delimiters: tuple[str, ...]) -> list[str]:
    """The text cells of the last row, when a delimiter splits every row of `sample`
    into as many fields, with numbers in each (a table with columns of text); else []."""
    for delimiter in delimiters:
        rows = [split_fields(line, delimiter) for line in sample[1:]]
        if (len(rows) >= 2 and len({len(row) for row in rows}) == 1 and len(rows[0]) >= 2
                and all(any(is_number(cell, ".") for cell in row) for row in rows)):
            return [cell.strip() for cell in rows[-1]
                    if not is_number(cell, ".") and not is_missing(cell)][:3]
    return []


#: A number with a unit or percent sign in its cell (a spreadsheet's ``1.8%``, ``97,52 N``).
_NUMBER_AND_UNIT = re.compile(r" *[+-]?\d+(?:[.,]\d+)?(?:[eE][+-]?\d+)? *"
                              r"(?P<unit>%|[^\W\d_][^\s,;\t|]*) *")


#: A complex number, as MATLAB or numpy writes it (``839.890+0i``, ``(1.5-2j)``).
_COMPLEX = re.compile(r" *\(?[-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?[-+]\d+(?:\.\d*)?"
                      r"(?:[eE][-+]?\d+)?[ij]\)? *")


def _numbers_with_units(sample: list[str]) -> list[str]:
    """Up to three cells of numbers with their unit (:data:`_NUMBER_AND_UNIT`, a unit pint
    reads) when most of the `sample` lines, split at any delimiter, hold one; else none."""
    return _cells_like(sample, _NUMBER_AND_UNIT, lambda match: bool(spellings(match["unit"])))


def _cells_like(sample: list[str], form: re.Pattern,
                accept: Callable[[re.Match], bool] = bool) -> list[str]:
    """Up to three cells of `form` (that `accept` accepts) when most of the `sample` lines,
    split at any delimiter, hold one; else none."""
    found = []
    for line in sample:
        cells = [cell.strip() for delimiter in DELIMITERS if delimiter != BLANKS
                 for cell in split_fields(line, delimiter)
                 if (match := form.fullmatch(cell)) and accept(match)]
        if cells:
            found.append(cells[0])
    return list(dict.fromkeys(found))[:3] if 2 * len(found) > len(sample) else []


def _has_two_numbers(line: str) -> bool:
    return any(
        sum(is_number(cell, decimal) for cell in split_fields(line, delimiter)) >= 2
        for delimiter in DELIMITERS if delimiter != BLANKS  # a sentence has blanks too
        for decimal in ".,"
    )


def _balance(row: list[str], decimal: str) -> int:
    """Numbers minus texts among the cells of `row`."""
    return sum(1 if is_number(cell, decimal) else 0 if is_missing(cell) else -1 for cell in row)


def _numeric_row(row: list[str], decimal: str, blanks: bool = False,
                 skip: frozenset[int] = frozenset()) -> bool:
    """At least two fields, and more numbers (or clock readings, read or not) than texts,
    the columns `skip` (of text in every row, :func:`steady_text_columns`) left out.

    A text cell is allowed so that a table with a text column (a date, a
    status) is still found; its text column takes no role. A clock reading counts only
    in a cell without another delimiter in it. A unit of force or
    length right after a number counts for neither: a force gauge writes its
    unit beside each value (``1,0.0,gf,0.000,mm,OK``). In a table aligned
    by blanks (`blanks`), where a line of words and numbers splits into fields
    too (``Cycles: 3 5``), none is.
    """
    numbers = texts = 0
    after_number = False
    for index, cell in enumerate(row):
        if index in skip:
            continue
        if is_number(cell, decimal) or (looks_like_clock(cell) and not _OTHER_FIELDS.search(cell)):
            numbers += 1
            after_number = True
            continue
        if not is_missing(cell) and not (after_number and is_measure_unit(cell.strip())):
            texts += 1
        after_number = False
    return len(row) >= 2 and numbers > texts and not (blanks and texts)


def _split_at_decimal_commas(row: list[str]) -> bool:
    """Whether `row`, split at commas, is a row of a table with decimal commas whose
    delimiter is another: a cell holds two whole numbers apart by blanks, not one grouped
    in thousands (``1 234``), as a table aligned by blanks gives (``0,133656  -0,004617``
    -> ``0``, ``133656  -0``, ``004617``), or joined by a semicolon, tab or bar (a
    spreadsheet's ``0,0;1.017,11`` -> ``0``, ``0;1.017``, ``11``)."""
    return any((match := _NUMBERS_APART.fullmatch(cell)) and (
        match["blanks"] is None or len(match["blanks"]) > 1 or match["sign"]
        or len(match["last"]) != 3) for cell in row)


#: Two whole numbers (the second perhaps with a decimal point) apart by blanks, the second
#: perhaps signed, or joined by another delimiter.
_NUMBERS_APART = re.compile(r" *[-+]?\d+(?:(?P<blanks> +)(?P<sign>[-+]?)(?P<last>\d+)"
                            r"|[;\t|] *[-+]?\d+(?:\.\d+)?) *")

#: A delimiter inside a cell: a clock reading there is part of a row split at the wrong
#: delimiter (``38354132;11:02:46;2`` of ``38354132;11:02:46;2,8;0,0`` split at its commas).
_OTHER_FIELDS = re.compile(r"[;\t|]")


def row_kind(row: list[str], line: str, decimal: str, blanks: bool = False,
             skip: frozenset[int] = frozenset()) -> str:
    """``"blank"``, ``"numeric"``, ``"missing"`` (only missing values), ``"partial"``
    (numbers and text: a data row with a bad cell) or ``"text"``. A line of
    delimiters only (``"\t\t"``) is a row of missing values, not a blank line.
    `blanks`: the row is of a table aligned by blanks (:data:`BLANKS`)."""
    if not line.strip(" "):
        return "blank"
    if _numeric_row(row, decimal, blanks, skip):
        return "numeric"
    if len(row) >= 2 and all(is_missing(cell) for cell in row):
        return "missing"
    if len(row) >= 2 and any(is_number(cell, decimal) for cell in row):
        return "partial"
    return "text"


def is_comment(line: str, delimiter: str, width: int) -> bool:
    """Whether a line is a comment among rows of `width` fields: it starts with
    :data:`COMMENT_MARK` and, without the mark, has another field count (a names row
    written as a comment, ``# time,force`` or numpy's ``# time(s)  force(N)``, has the
    data's)."""
    return line.startswith(COMMENT_MARK) and len(
        split_fields(line[len(COMMENT_MARK):], delimiter)) != width


def find_table(
    lines: list[str], name: str, delimiter: str, decimal: str, width: int
) -> TableSpec:
    """Locate the names row, units row and first data row among a head's lines.

    Rows with numbers just below the header count as data even with a bad
    cell, only missing values or a wrong field count, so that the body parser
    reports or keeps them. Comment lines (:func:`is_comment`) count as blank
    lines: the body parser passes over them too.

    Raises
    ------
    LayoutError
        If the line above the first data row is no names row, or the names row does
        not fit the data rows. A file that begins with its data has no names row
        (:attr:`TableSpec.header_index` None): :func:`require_names` decides.
    """
    # Rows are classified from the top, as far as it takes to find the table (the head
    # holds thousands of lines; the table usually starts within the first few).
    limit, skip = FIND_LINES, frozenset()
    while True:
        rows = [split_fields(line, delimiter) for line in lines[:limit]]
        kinds = ["blank" if is_comment(line, delimiter, width) else
                 row_kind(row, line, decimal, delimiter == BLANKS, skip)
                 for row, line in zip(rows, lines, strict=False)]
        complete = limit >= len(lines)
        data = _first_data_row(rows, kinds, width, complete=complete)
        found = (None if data is None
                 else _past_results(rows, kinds, width, data, complete, decimal))
        if found is not None:
            data, results = found
            break
        steady = None if skip or not complete else steady_text_columns(lines, (delimiter,))
        if steady is not None and steady[1:3] == (decimal, width):
            skip = steady[3]  # more texts than numbers in each row: columns of text
            continue
        if complete:  # the dialect is chosen on rows of numbers: some are of this width
            raise LayoutError("no data rows of the table's width", file=name,
                              hint="check the file's delimiter and decimal mark")
        limit *= 4
    while (data > 0 and kinds[data - 1] in _DATA_KINDS
           and _units_beside_numbers(rows[data - 1], decimal) is None
           and not _names_with_numbers(rows[data - 1], kinds[data - 1], decimal, width)
           and not _leading_record(rows, kinds, data - 1, width)):
        data -= 1
    statistics = _statistics(rows[data:])
    if len(statistics) > 1 and statistics[0][0] <= RESULTS_ROWS:  # under a batch's results
        raise _statistics_error([label for _, label in statistics], name, data)
    numbered = ()
    if _numbers_over_texts(rows[data:], kinds[data:], width, decimal):
        numbered = (f"line {data + 1}: a row of channel numbers over columns of text is read "
                    "as the names row",)
        kinds[data] = "text"
        data += 1
    above = _above(kinds, data)
    labels = _specimen_labels(rows, kinds, above)
    if labels:  # the specimens' labels between the header and the data
        above = _above(kinds, above)
    elif _processing_row(rows, kinds, above):  # a Campbell logger's row under the units
        above = _above(kinds, above)
    elif _section_mark(rows, kinds, above, width):  # "***end of header***" under the names
        above = _above(kinds, above)
    units_index, units_cells, notes = None, [], numbered
    if above >= 1 and kinds[above] == "partial":  # numbers typed beside the units
        units_cells = _units_beside_numbers(rows[above], decimal) or []
    elif above >= 1 and kinds[above] == "text":
        units_cells = rows[above]
    if (
        units_cells
        and any(not (is_number(cell, decimal) or is_missing(cell)) for cell in rows[above - 1])
        and _filled_width(units_cells) <= width  # a trailing delimiter adds a blank field
        and _units_row(units_cells, rows[data], decimal, rows[above - 1])
    ):  # numbers among the names over a units row (sensors named by serial number, an
        # oscilloscope's channels 1 and 2: "x-axis,1,2") do not make the names row data
        if units_cells is not rows[above]:
            typed = [cell.strip() for cell in rows[above] if is_number(cell, decimal)]
            notes = (f"line {above + 1}: the numbers beside the units ({', '.join(typed)}) "
                     "were passed over",)
        units_index, above = above, above - 1
        if above >= 1 and _channel_states(rows[above]) and kinds[above - 1] == "text":
            above -= 1  # a row of channel states between the names and the units (MaCh3D)
    preamble_end = above
    if units_index is None and above >= 1 and all(
            _SETTING.match(lines[index]) for index in (above - 1, above)):
        preamble_end, above = data, -1  # the last of a block of settings: no names row
    if above >= 0 and units_index is None and _leading_record(rows, kinds, above, width):
        notes += (f"line {above + 1}: a record of {_filled_width(rows[above])} numbers opens "
                  f"the file, before rows of {width}: passed over as its preamble",)
        preamble_end, above = data, -1
    if above >= 0 and kinds[above] != "text" and units_index is None:
        if not _names_with_numbers(rows[above], kinds[above], decimal, width):
            raise _no_names_row(name, data, delimiter)
        notes += (f"line {above + 1}: the names row holds numbers among its names ("
                  + ", ".join(repr(cell.strip()) for cell in rows[above]
                              if is_number(cell, decimal)) + "): read as names",)
    names_line = lines[above] if above >= 0 else ""
    if names_line.startswith(COMMENT_MARK):  # a names row written as a comment
        names_line = names_line[len(COMMENT_MARK):]
    names = split_fields(names_line, delimiter) if above >= 0 else [""] * width
    if delimiter == BLANKS:  # a script's names kept apart by a delimiter and blanks
        names = [name.rstrip(",;") for name in names]
    pairs = (delimiter == "," and decimal == "." and 2 * len(names) == width >= 4
             and not _decimal_points(rows[data:data + TEXT_ROWS])
             and not _counts_rows(rows[data:data + TEXT_ROWS], kinds[data:data + TEXT_ROWS]))
    columns = width // 2 if pairs else width
    if len(names) > columns and not any(cell.strip() for cell in names[columns:]):
        names = names[:columns]
    if len(names) > columns and delimiter == BLANKS:  # names with a blank inside them
        names = _WIDE_BLANKS.split(names_line.strip())
        if len(names) < columns and (grouped := _names_by_roles(names_line, columns)):
            names = grouped
            notes += (f"the names row, its names apart by single blanks, was split after "
                      f"each word that names a role: {', '.join(map(repr, names))}",)
        elif len(names) < columns:
            notes += (f"the names row {names_line.strip()[:60]!r} does not split into the "
                      f"{columns} columns (in a table aligned by blanks, names need two "
                      "blanks or a tab between them): the columns are named by their place",)
            names = [""] * columns
    if len(names) > columns:
        if statistics:
            raise _statistics_error([label for _, label in statistics], name, data)
        raise LayoutError(
            f"the names row has {len(names)} fields but the data rows have {width}",
            file=name, row=above + 1,
            hint="the header and the data do not match: check the delimiter and the export"
            + (" (in a table aligned by blanks, separate names that hold a blank by two "
               "blanks or more)" if delimiter == BLANKS else ""),
        )
    if (0 < len(names) < columns and above >= 0 and units_index is None
            and not any((match_role(cell) or split_name_unit(cell)[1])
                        and not looks_like_clock(cell) for cell in names)
            and any(cell.strip() for row in rows[data:data + TEXT_ROWS]
                    for cell in row[len(names):columns])):
        # narrower than the data, naming nothing: a status or settings line, no names row
        # (a logger's stamped message, "2025-01-17 13:06:21 - Load cell tared.", names none)
        preamble_end, above, names = data, -1, []
    if 0 < len(names) < columns and any(
            not is_missing(cell) for row in rows[data:data + TEXT_ROWS]
            for cell in row[len(names):columns]):
        notes += (f"the names row (line {above + 1}) has {len(names)} names over data rows "
                  f"of {columns} fields: the names are set over the columns from the left, "
                  f"and {columns - len(names)} column(s) on the right go without one; check "
                  "that each name stands over its own data (a delimiter missing between two "
                  "names shifts the names after it)",)
    names = names + [""] * (columns - len(names))
    labels_over = -1
    if len(labels) < 2 and above >= 1:  # labels over the names (Shimadzu Trapezium)
        labels = _labels_over(rows[_above(kinds, above)], names)
        labels_over = _above(kinds, above) if len(labels) > 1 else -1
        if labels_over < 0 and kinds[_above(kinds, above)] == "text":
            names, named = _named_over(names, _text_rows_over(rows, kinds, above))
            names, united = _units_under_names(names, rows[_above(kinds, above)])
            notes += named + united
    units: list[str | None] = [None] * columns
    clocks = {} if pairs else {
        index: _clock_column(kind, index, names, rows[data:], data + 1)
        for index, cell in enumerate(rows[data][:columns]) if (kind := clock_kind(cell))}
    if units_index is not None:
        for index, cell in enumerate(units_cells[:columns]):
            unit = cell.strip().strip("()[]<>").strip()
            units[index] = (None if unit.lower() in NO_UNIT_CELLS or is_sample_interval(unit)
                            or _over_text(rows[data], index, decimal)
                            or _repeats_name(cell, names, index) else unit or None)
    specimens = tuple(labels) if len(labels) > 1 else ()
    if specimens:  # names and units written over the first specimen's columns only
        names, units = _each_specimen(names, specimens), _each_specimen(units, specimens)
    notes += _settings_beside(rows[data:], decimal, columns, data, names)
    texts = frozenset() if pairs else _text_columns(rows[data:], kinds[data:], columns, decimal)
    _refuse_interleaved(rows[data:], kinds[data:], texts, names, name, data)
    if not _advancing(clocks, rows[data:data + TEXT_ROWS]) and not any(
            match_role(name) == "time" for name in names):
        labelled = _labelled_rows(rows[data:], kinds[data:], texts, names)
        results_named = [column for column in names if says_result(column)]
        if not labelled and len(results_named) >= 2:  # specimens numbered, not labelled
            labelled = _numbered_rows(rows[data:], kinds[data:], names)
        if labelled and results_named:
            raise _results_error(labelled, results_named, name, data)
        if labelled:
            notes += (f"{labelled}: the rows may be specimens (a table of results or "
                      "settings), not the samples of one test",)
    return TableSpec(
        delimiter=delimiter,
        decimal="," if pairs else decimal,
        names=names,
        header_index=above if above >= 0 else None,
        units_index=units_index,
        data_index=data,
        width=width,
        units=units,
        preamble=[line for index, line in enumerate(lines[:max(preamble_end, 0)])
                  if line.strip() and index != labels_over
                  and not (results and results[0] <= index < results[1])],
        passed=[line for line in lines[slice(*results)] if line.strip()] if results else [],
        pairs=pairs,
        clocks=clocks,
        results=results,
        texts=texts,
        notes=notes,
        specimens=specimens,
    )


def _statistics(rows: list[list[str]]) -> list[tuple[int, str]]:
    """The rows of `rows` labelled as a statistic (:data:`STATISTICS_LABELS`) in their
    first or second cell (the first may number the row), with their place."""
    found = []
    for at, row in enumerate(rows):
        label = next((cell.strip() for cell in row[:2] if not is_missing(cell)), "")
        if label.lower() in STATISTICS_LABELS:
            found.append((at, label))
    return found


def _refuse_interleaved(rows: list[list[str]], kinds: list[str], texts: frozenset[int],
                       names: list[str], name: str, data: int) -> None:
    """Refuse a log whose text column (of `texts`) labels the head's data `rows` in turn,
    the same few labels over and over (``Left``, ``Right``, ``Left``...): each row a
    reading of another sensor (a long-format log), which read as one channel would zigzag
    between them."""
    data_rows = _head_data(rows, kinds)
    for index in sorted(texts):
        cells = [row[index].strip() for row in data_rows]
        labels = list(dict.fromkeys(cells))
        period = len(labels)
        if (2 <= period <= 16 and len(cells) >= max(6, 2 * period)
                and not {label.casefold() for label in labels} <= _FLAGS
                and all(cells[at] == labels[at % period] for at in range(len(cells)))):
            column = names[index].strip() or f"column {index + 1}"
            raise LayoutError(
                f"column {column!r} labels the rows in turn "
                f"({', '.join(map(repr, labels[:4]))}{', ...' if period > 4 else ''}): each "
                f"row is a reading of one of {period} sensors, not a sample of all the "
                "channels; read as one channel they would be mixed",
                file=name, row=data + 1,
                hint=f"write each sensor's readings in a column of its own (or a file of "
                     f"its own, by {column!r}), then read that")


#: A flag's states, folded: a flag toggling every row (a rig's ``F``, ``T``) labels no sensor.
_FLAGS = frozenset({"t", "f", "true", "false", "y", "n", "yes", "no", "on", "off"})


def _counts_rows(rows: list[list[str]], kinds: list[str]) -> bool:
    """Whether the first field of the head's data `rows` counts them (``0``, ``1``, ``2``,
    three rows at least) and the second varies: a sample's number beside a reading, not
    the whole and decimal parts of a value written with a decimal comma (``0,1000``,
    ``1,1007`` are a number and a load, not 0.1 and 1.1007; ``0,0``, ``1,0``, ``2,0`` may
    be a time in whole seconds)."""
    pairs = [(row[0].strip(), row[1].strip()) for row, kind in zip(rows, kinds, strict=False)
             if kind == "numeric" and len(row) > 1]
    firsts = [first for first, _ in pairs]
    return (len(pairs) >= 3 and all(first.isdigit() for first in firsts)
            and all(int(b) - int(a) == 1 for a, b in pairwise(firsts))
            and len({second for _, second in pairs}) > 1)


def _advancing(clocks: Mapping[int, object], rows: list[list[str]]) -> bool:
    """Whether a clock column of `clocks` reads more than one time over the head's `rows`,
    not all at midnight (the date of each specimen's test in a results table,
    ``2019-12-06 00:00:00``, is no time of a test)."""
    for index in clocks:
        cells = {row[index].strip() for row in rows if len(row) > index and row[index].strip()}
        if len(cells) > 1 and not all(_MIDNIGHT.search(cell) for cell in cells):
            return True
    return False


#: A clock reading at midnight: a date written as a date and time.
_MIDNIGHT = re.compile(r"(?:(?<![\d:])0?0:00|12:00(?=(?::00(?:[.,]0*)?)?\s*AM$))"
                       r"(?::00(?:[.,]0*)?)?(?:\s*AM)?$", re.IGNORECASE)


#: The hint of a refused results table.
_RESULTS_HINT = ("export the raw data of each specimen (time, force, extension), not the "
                 "results table")


def _results_error(labelled: str, results: list[str], name: str, data: int) -> LayoutError:
    """The refusal of a table whose rows are labelled each their own (`labelled`, as
    :func:`_labelled_rows` says it) under names of a test's results."""
    shown = ", ".join(repr(result.strip()) for result in results[:3])
    return LayoutError(
        f"{labelled}, under names of results ({shown}): the rows are specimens of a results "
        "table, not a test's raw data", file=name, row=data + 1, hint=_RESULTS_HINT)


def _statistics_error(labels: list[str], name: str, data: int) -> LayoutError:
    """The refusal of a batch's results table, its statistics labelled `labels`."""
    return LayoutError(
        f"the rows under the names are statistics of a batch's results "
        f"({', '.join(labels[:4])}), not a test's raw data",
        file=name, row=data + 1, hint=_RESULTS_HINT)


def _clock_column(kind: str, index: int, names: list[str], rows: list[list[str]],
                  first_line: int) -> ClockColumn:
    """Column `index` of clock readings of `kind`, as the head's data `rows` (from line
    `first_line`) show them: the fraction of a second, and the date beside or in it."""
    carried = carried_order(kind, index, rows)
    return ClockColumn(
        kind, rows[0][index],
        None if kind == "minutes and seconds" else unpadded_milliseconds(
            [row[index] if index < len(row) else "" for row in rows], first_line),
        fraction_column(rows[0][index], index, names, rows),
        None if carried else date_column(kind, index, names, rows),
        carried)


def _units_beside_numbers(row: list[str], decimal: str) -> list[str] | None:
    """A units row with numbers typed after its last unit (an export re-saved through a
    spreadsheet, ``Sec  mm  N  -0.081  -5.86``): the row with those numbers blank; None
    for any other row (two units at least, every text a unit, no number among them)."""
    texts = [index for index, cell in enumerate(row)
             if cell.strip() and not is_number(cell, decimal)]
    numbers = [index for index, cell in enumerate(row) if is_number(cell, decimal)]
    if (len(texts) < 2 or not numbers or min(numbers) < max(texts)
            or not all(looks_like_unit(row[index]) for index in texts)):
        return None
    return [cell if index < min(numbers) else "" for index, cell in enumerate(row)]


def _names_by_roles(line: str, columns: int) -> list[str]:
    """The names of a row whose names are apart by single blanks, as blanks also stand
    within them (MTS TestWare's ``Ch 1 Displacement Ch 1 Force Time``): each ends with
    a word that names a role. Empty unless that gives `columns` names and leaves no
    word over."""
    names, words = [], []
    for word in line.split():
        words.append(word)
        if match_role(word) is not None:
            names.append(" ".join(words))
            words = []
    return names if len(names) == columns and not words else []


def _text_columns(rows: list[list[str]], kinds: list[str], columns: int, decimal: str
                  ) -> frozenset[int]:
    """The columns whose cells are text in each of the first :data:`TEXT_ROWS` data rows
    of `rows`, two at least (neither numbers, clock readings of a form read nor missing
    values: ``3/5/2024 2:03:27 PM`` is text)."""
    texts = set(range(columns))
    data = _head_data(rows, kinds)
    for row in data:
        texts = {index for index in texts if index < len(row) and not (
            is_number(row[index], decimal) or is_missing(row[index])
            or THOUSANDS[decimal].fullmatch(row[index].strip())
            or clock_kind(row[index]) is not None)}
    return frozenset(texts) if len(data) >= 2 else frozenset()  # one bad row is a bad cell


def _numbers_over_texts(rows: list[list[str]], kinds: list[str], width: int, decimal: str
                        ) -> bool:
    """Whether the first of `rows`, a row of small whole numbers, stands over columns the
    rows below hold text in (a rig's logger names its channels by number: ``1;7;8;2`` over
    ``1657711476152;30.19;...;F;T``): no data row, but the names row."""
    if len(rows) < 3 or len(rows[0]) != width or not all(
            _CHANNEL_NUMBER.fullmatch(cell.strip()) for cell in rows[0]):
        return False
    return bool(_text_columns(rows[1:], kinds[1:], width, decimal))


#: A channel's number.
_CHANNEL_NUMBER = re.compile(r"\d{1,4}")


def _names_with_numbers(row: list[str], kind: str, decimal: str, width: int) -> bool:
    """Whether `row`, of `kind` ``"partial"`` (numbers among text), is a names row with
    numbers among its names (a logger's column named ``0``): more names than numbers,
    two names at least, and no wider than the data's `width`."""
    if kind != "partial" or len(row) > width:
        return False
    numbers = sum(is_number(cell, decimal) for cell in row)
    names = sum(not (is_number(cell, decimal) or is_missing(cell)) for cell in row)
    return names >= 2 and names > numbers


#: An image's file name: a DIC export names each frame's image in a column of its own
#: (``S1-00001_0.tif``), one row a frame (a nanoindenter's results name each indent's
#: file, ``0000 LC.hys``, one row a test).
_FILE_NAME = re.compile(r"\.(?:tiff?|png|jpe?g|bmp|raw|dng)$", re.IGNORECASE)


def _head_data(rows: list[list[str]], kinds: list[str]) -> list[list[str]]:
    """The first :data:`TEXT_ROWS` rows of numbers of `rows`."""
    return [row for row, kind in zip(rows, kinds, strict=False) if kind == "numeric"
            ][:TEXT_ROWS]


def _labelled_rows(rows: list[list[str]], kinds: list[str], texts: frozenset[int],
                   names: list[str]) -> str | None:
    """What to say of a text column (of `texts`) that gives each of the head's first data
    `rows`, three at least, a label of its own (not an image's file name, as a DIC
    export's frames have), in a table without a time: such rows are likely specimens (a
    table of results or settings, a DAQ's gains per specimen), not the samples of one
    test; None without one."""
    data = _head_data(rows, kinds)
    for index in sorted(texts):
        cells = [row[index].strip() for row in data]
        if len(cells) >= 3 and len(set(cells)) == len(cells) and not any(
                _FILE_NAME.search(cell) for cell in cells):
            name = names[index].strip() or f"column {index + 1}"
            shown = ", ".join(map(repr, cells[:3]))
            return (f"column {name!r} gives each row a label of its own ({shown}...) and no "
                    "column is a time")
    return None


def _numbered_rows(rows: list[list[str]], kinds: list[str], names: list[str]) -> str | None:
    """What to say of a column that numbers the head's first data `rows`, three at least,
    one by one (a results table's ``no.``: 1, 2, 3...), or None. A log numbers its samples
    so too: only beside names of results does it make the rows specimens."""
    data = _head_data(rows, kinds)
    for index in range(min(map(len, data), default=0)):
        cells = [row[index].strip() for row in data]
        if (len(cells) >= 3 and all(cell.isdigit() for cell in cells)
                and all(int(b) - int(a) == 1 for a, b in pairwise(cells))):
            name = names[index].strip() or f"column {index + 1}"
            return (f"column {name!r} numbers the rows ({', '.join(cells[:3])}...) and no "
                    "column is a time")
    return None


def _past_results(rows: list[list[str]], kinds: list[str], width: int, data: int,
                  complete: bool, decimal: str) -> tuple[int, tuple[int, int] | None] | None:
    """The first data row past any results tables above the data, and the rows (first,
    past the last) of those tables; None when the rows so far do not tell.

    Bluehill exports the results of a batch (one row per specimen) above a
    specimen's raw data. A table is passed over when it has at most
    :data:`RESULTS_ROWS` rows and a table of other names and more rows follows
    it (or runs past the rows looked at); tables of the same names are blocks of
    one log (MTS TestWare), read as such.
    """
    first = None
    while True:
        end = next((index for index in range(data + 1, len(kinds)) if kinds[index] == "text"),
                   None)
        count = sum(kind != "blank" for kind in kinds[data:end])
        if end is None or count > RESULTS_ROWS:
            break
        later = _first_data_row(rows[end:], kinds[end:], width, complete)
        if later is None:
            if not complete:
                return None  # more rows may hold the data's table
            break
        later += end
        stop = next((index for index in range(later + 1, len(kinds)) if kinds[index] == "text"),
                    len(kinds))
        longer = (stop == len(kinds) and not complete
                  or sum(kind != "blank" for kind in kinds[later:stop]) > count)
        if not longer or (rows[_header_top(rows, kinds, later, decimal)]
                          == rows[_header_top(rows, kinds, data, decimal)]):
            break  # a shorter table below (a trailer), or the same names (blocks of one log)
        if first is None:
            first = _header_top(rows, kinds, data, decimal)
        data = later
    return data, (None if first is None else (first, _header_top(rows, kinds, data, decimal)))


def _header_top(rows: list[list[str]], kinds: list[str], data: int, decimal: str) -> int:
    """The first row of the names (and units) rows over the data row `data`."""
    above = _above(kinds, data)
    if (above >= 1 and kinds[above] == "text"
            and _units_row(rows[above], rows[data], decimal, rows[above - 1])):
        above = _above(kinds, above)
    return max(above, 0)


def _leading_record(rows: list[list[str]], kinds: list[str], index: int, width: int) -> bool:
    """Whether row `index` is a record of numbers of another width than the data rows'
    that opens the file (a Chinese controller's count and date over its rows of six):
    the file's preamble, no data row and no names row."""
    return (kinds[index] in _DATA_KINDS and _filled_width(rows[index]) != width
            and all(kind == "blank" for kind in kinds[:index]))


def _above(kinds: list[str], index: int) -> int:
    """The nearest row above row `index` that is not blank (-1: none)."""
    above = index - 1
    while above >= 0 and kinds[above] == "blank":
        above -= 1
    return above


def _specimen_labels(rows: list[list[str]], kinds: list[str], index: int) -> list[str]:
    """The labels of row `index` if it labels the specimens of the columns below it, else [].

    Mecmesin Emperor writes its names and units rows, then a row with a label
    over the first column of each specimen's group (``Sample 1,,,,Sample 2,,,,...``),
    then the data. Such a row is text under another header row, its labels
    name no role and stand alone at the start of groups of equal width (one
    label: over the first column, every other cell empty).
    """
    header = _above(kinds, index)
    if header < 0 or kinds[index] != "text" or kinds[header] != "text":
        return []
    return _group_labels(rows[index])


def _labels_over(row: list[str], names: list[str]) -> list[str]:
    """The labels of `row`, the row over the names row, if it labels the groups of columns
    that repeat one group of names (Shimadzu Trapezium: ``"CuivreC1",,,,"AcierC70",,,``
    over ``"Temps","Force","Stroke","Ext.1","Temps",...``), else []."""
    labels = _group_labels(row)
    count = repeats(names)
    return labels if len(labels) > 1 and len(labels) == count else []


#: Fewest first data rows whose text in a column, empty below them, makes them settings.
SETTINGS_BESIDE_ROWS = 3


def _settings_beside(rows: list[list[str]], decimal: str, columns: int,
                     data: int, names: list[str]) -> tuple[str, ...]:
    """A note when the first data rows hold text in some column that is empty below them
    (a Hopkinson bar's export: its settings, ``Test Time<TAB>11:48:55 AM``, in the first
    columns beside the waveforms, whose first two numbers are their start and step), else
    none; `rows` are the head's data rows, the first on line ``data + 1``. A column named
    for remarks (:data:`_REMARKS`) holds none."""
    beside = []
    for column in range(columns):
        if column < len(names) and not _REMARKS.isdisjoint(tokens(names[column])):
            continue
        cells = [row[column].strip() if column < len(row) else "" for row in rows]
        filled = [cell for cell in cells if not is_missing(cell)]
        reach = max((count + 1 for count, cell in enumerate(cells) if cell), default=0)
        # the rows down to the last one written: an N/A below says the column goes on
        if (len(filled) >= SETTINGS_BESIDE_ROWS and reach + SETTINGS_BESIDE_ROWS <= len(cells)
                and not any(is_number(cell, decimal) for cell in filled)):
            beside.append((column, reach))
    if not beside:
        return ()
    last = max(reach for _, reach in beside)
    return (f"lines {data + 1} to {data + last}: text beside the numbers in column(s) "
            f"{', '.join(str(column + 1) for column, _ in beside)}, and none below: settings "
            "written beside the data? The numbers of those lines may be settings too (a "
            "waveform's start and step), not samples: check them",)


#: Words of a column of remarks (``Comments``), folded.
_REMARKS = frozenset({"comment", "comments", "remark", "remarks", "note", "notes",
                      "bemerkung", "bemerkungen", "kommentar", "commentaire", "commentaires",
                      "observaciones", "observacoes", "uwagi"})


def _text_rows_over(rows: list[list[str]], kinds: list[str], index: int,
                    most: int = 4) -> list[list[str]]:
    """The rows of text over row `index`, nearest first, up to `most` of them."""
    over = []
    while len(over) < most and (index := _above(kinds, index)) >= 0 and kinds[index] == "text":
        over.append(rows[index])
    return over


def _named_over(names: list[str], overs: list[list[str]]) -> tuple[list[str], tuple[str, ...]]:
    """`names` with a word they repeat that names no role (an Elsys recorder's
    ``Zeit;Signal;Signal;Signal`` under ``Kanal;DMS1A (0.A1);DMS1B (0.A2);...``; a Visual3D
    export's components ``X;X;X`` under rows of types, under ``FZsum;FZsum_1Hz;...``)
    replaced by the cells of the nearest row of `overs` (the rows of text over them,
    nearest first) that names each such column apart; and a note saying so (else `names`
    and no note)."""
    counts = Counter(name.strip() for name in names if name.strip())
    repeated = [index for index, name in enumerate(names) if counts[name.strip()] > 1
                and not match_role(name) and split_name_unit(name)[1] is None]
    for nearest, over in enumerate(overs if repeated else ()):
        cells = [over[index].strip() if index < len(over) else "" for index in repeated]
        if all(cells) and len(set(cells)) == len(cells):
            renamed = dict(zip(repeated, cells, strict=True))
            row = "the row over them" if nearest == 0 else "a row higher up"
            return ([renamed.get(index, name) for index, name in enumerate(names)],
                    (f"the columns named {names[repeated[0]].strip()!r} alike are named by "
                     f"{row}: {', '.join(map(repr, cells[:6]))}"
                     + (", ..." if len(cells) > 6 else ""),))
    return names, ()


def _units_under_names(names: list[str], over: list[str]) -> tuple[list[str], tuple[str, ...]]:
    """`names` with a unit alone under a name of the row `over` them that names a role of
    that unit taken as that name in that unit (a Mitsubishi servo export's ``ms`` under
    ``Time``: ``Time [ms]``), and a note saying so (else `names` and no note)."""
    joined = {index: f"{over[index].strip()} [{name.strip()}]"
              for index, name in enumerate(names)
              if index < len(over) and not match_role(name)
              and (role := unit_role(name.strip())) is not None and match_role(over[index]) == role}
    if not joined:
        return names, ()
    return ([joined.get(index, name) for index, name in enumerate(names)],
            ("a unit alone in the names row is taken with the name over it: "
             + ", ".join(map(repr, joined.values())),))


def _group_labels(row: list[str]) -> list[str]:
    """The labels of `row` when they stand alone at the start of groups of columns of equal
    width (one label: over the first column, every other cell empty), or over each column
    of its group (Stable Micro Systems' Exponent: ``gel2,gel2,gel2,frame,frame,frame``),
    and name no role; else []."""
    cells = [cell.strip() for cell in row]
    while cells and not cells[-1]:  # a trailing delimiter
        cells.pop()
    runs = [(label, len(list(group))) for label, group in groupby(cells)]
    if (len(runs) > 1 and all(label for label, _ in runs) and runs[0][1] > 1
            and len({size for _, size in runs}) == 1):
        labels = [label for label, _ in runs]
    else:
        filled = [position for position, cell in enumerate(cells) if cell]
        if not filled or filled[0] != 0 or len(row) < 2:
            return []
        stride = filled[1] if len(filled) > 1 else len(row)
        if stride < 2 or filled != list(range(0, stride * len(filled), stride)):
            return []
        labels = [cells[position] for position in filled]
    return [] if len(set(labels)) < len(labels) or any(map(match_role, labels)) else labels


def _each_specimen(cells: list, specimens: tuple[str, ...]) -> list:
    """`cells` (names or units, one per column) with each blank one of a later specimen's
    group of columns filled from the first group's (Mecmesin Emperor writes them over
    the first specimen only)."""
    stride = len(cells) // len(specimens)
    return [cells[index % stride] if stride <= index < stride * len(specimens)
            and not (cell or "").strip() else cell for index, cell in enumerate(cells)]


def require_names(spec: TableSpec, file: str, columns: Mapping | None) -> None:
    """Refuse a table without a names row unless the run sheet names its columns.

    Such a file's columns are called ``column 1``, ``column 2``... and take the
    roles the run sheet's ``columns`` give them, nothing else: no role is
    guessed from a position.

    Raises
    ------
    LayoutError
        When the file has no names row and `columns` is empty.
    """
    if spec.header_index is None and not columns:
        raise _no_names_row(file, spec.data_index, spec.delimiter)


def _no_names_row(file: str, data: int, delimiter: str) -> LayoutError:
    return LayoutError(
        "no names row above the first data row",
        file=file, row=data + 1,
        hint="add a header row naming the columns, separated as the data are, e.g. "
             + {"\t": "<Tab>", BLANKS: "  "}.get(delimiter, delimiter).join(
                 ("'time [s]", "force [kN]", "gauge1 [mm]'"))
             + ", or name them in the run sheet by position, with their units: columns = "
               '{time = "column 1", force = "column 2"}, units = {time = "s", force = "kN"}'
               ' (for a tensile or wear run, gauges = ["column 3"] too, with its unit; the'
               " units the numbers are in: a logger's raw counts or volts are converted to a "
               "force with the sensor's calibration first, outside chainbench)",
    )


def _decimal_points(rows: list[list[str]]) -> bool:
    """Whether a cell of `rows` holds a decimal point: its numbers are not split at their
    decimal comma."""
    return any("." in cell for row in rows for cell in row)


def _processing_row(rows: list[list[str]], kinds: list[str], index: int) -> bool:
    """Whether row `index` tells how a logger worked each column's values over its interval
    (:data:`PROCESSING_WORDS`, blank over a time stamp or a record number), under a units
    row: a Campbell Scientific TOA5 file's fourth row (``"","","Smp","Avg","Max"``)."""
    if index < 1 or kinds[index] != "text" or kinds[_above(kinds, index)] != "text":
        return False
    cells = {cell.strip().lower() for cell in rows[index]}
    return bool(cells - {""}) and cells <= PROCESSING_WORDS | {""}


def _section_mark(rows: list[list[str]], kinds: list[str], index: int, width: int) -> bool:
    """Whether row `index`, one text field over a table of three columns or more, closes a
    header whose row above names every column (a GRIMM dust monitor's ``***end of
    header***`` under its names)."""
    above = _above(kinds, index)
    return (width >= 3 and above >= 0 and kinds[index] == kinds[above] == "text"
            and _filled_width(rows[index]) == 1 and _filled_width(rows[above]) == width)


def _channel_states(row: list[str]) -> bool:
    """Whether `row` tells each channel's state: ``ON`` or ``OFF`` (``-`` where a channel has
    none), as a MaCh3D machine writes between the names and the units."""
    cells = {cell.strip().lower() for cell in row}
    return bool(cells & {"on", "off"}) and cells <= {"on", "off", "-", ""}


def _filled_width(row: list[str]) -> int:
    """The fields of `row` up to its last one not blank."""
    width = len(row)
    while width and not row[width - 1].strip():
        width -= 1
    return width


#: The share of a units row's cells over numbers that must read as units when some do not.
UNITS_SHARE = 2 / 3


def _units_row(row: list[str], first_data: list[str], decimal: str, names: list[str]) -> bool:
    """Whether `row` is a units row under the names row `names`: a unit (or nothing) over
    every column of numbers.

    Cells over columns the first data row leaves empty are notes beside the
    table (Bluehill: ``"20 N preload"`` under ``"10 mm/min"``), not units; cells
    over text or clock readings are whatever the logger writes there (Graphtec:
    ``Time`` over its date and time, ``A1234567890`` over its alarms' states); a
    cell that repeats the name above it says the column has no unit (Instron
    WaveMatrix: ``CycleCount`` under ``CycleCount``). Letters in turn label channels
    (:func:`_channel_letters`). Of a row of many, more than
    :data:`UNITS_SHARE` of them will do, the others units the reader does not know and no
    numbers (a wind-tunnel balance's ``steps``, ``degr._C`` beside ``Pa``, ``1/min``,
    ``/``). A row over text or clock readings only is none (a logger's stamped message,
    ``2025-01-17 13:06:26 - Testing started...``).
    """
    if _channel_letters(row):
        return False
    over = [looks_like_unit(cell) or _repeats_name(cell, names, index)
            for index, cell in enumerate(row)
            if index >= len(first_data)
            or not (is_missing(first_data[index]) or _over_text(first_data, index, decimal))]
    return (any(not _over_text(first_data, index, decimal) for index in range(len(row)))
            and (all(over) or UNITS_SHARE * len(over) < sum(over) and not any(
                is_number(cell, decimal) for cell in row)))


def _channel_letters(row: list[str]) -> bool:
    """Whether `row` labels channels by letters in turn (``t (s) | A | B | C | D``): no
    units, though pint reads ``A`` as amperes and ``D`` as days."""
    letters = [ord(cell.strip()) for cell in row
               if len(cell.strip()) == 1 and cell.strip().isascii() and cell.strip().isalpha()]
    return len(letters) >= 2 and all(b - a == 1 for a, b in pairwise(letters))


def _repeats_name(cell: str, names: list[str], index: int) -> bool:
    """Whether the units cell `cell` of column `index` repeats its name (not blank)."""
    return bool(cell.strip()) and index < len(names) and cell.strip() == names[index].strip()


def _over_text(first_data: list[str], index: int, decimal: str) -> bool:
    """Whether column `index` of the first data row holds text or a clock reading."""
    cell = first_data[index] if index < len(first_data) else ""
    return not (is_missing(cell) or is_number(cell, decimal)
                or THOUSANDS[decimal].fullmatch(cell.strip()))


def _first_data_row(rows: list[list[str]], kinds: list[str], width: int,
                    complete: bool = True) -> int | None:
    """The first numeric row of `width` fields followed by a data row (or by nothing).

    `rows` and `kinds` are the head's first lines, all of them when `complete`;
    otherwise None when those lines do not tell (more lines are needed).
    """
    candidates = [i for i, kind in enumerate(kinds) if kind == "numeric" and len(rows[i]) == width]
    for i in candidates:
        following = next((j for j in range(i + 1, len(kinds)) if kinds[j] != "blank"), None)
        if following is None and not complete:
            return None
        if following is None or (kinds[following] in _DATA_KINDS and len(rows[following]) == width):
            return i
    return candidates[0] if complete and candidates else None
