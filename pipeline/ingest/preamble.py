"""The free-text preamble machines write above their table (Instron Bluehill, MTS, Zwick).

Lines of ``key : value``, ``key: value``, ``key = value``, ``"key","value"``,
``key<TAB>value`` or a key and its value set apart by blanks (testXpert's
``Pre-load                                50 N``) before the names row become ``key -> value`` in
:attr:`~pipeline.ingest.table.TableMetadata.preamble`; so do a row of names
over a row of their values (a rig's settings: ``Stop buffer (mm),Syringe
diameter (mm)`` over ``5,20.5``), and so does each of several settings written in
a line (``Sampling frequency [Hz]:<TAB>100<TAB>Cycles:<TAB>3000``).
"""

from __future__ import annotations

import re

from pipeline.ingest.names import split_name_unit
from pipeline.ingest.sniff import is_number, split_fields

#: A colon that separates a key from its value (a full-width one, as Chinese software writes
#: it: ``试样编号：A12``): not one between digits (a clock time,
#: ``14:43:46``) nor a drive letter's (``C:\``).
_KEY_COLON = re.compile(r"(?<!\d):|(?<=\d):(?!\d)|：")
_DRIVE = re.compile(r"[A-Za-z]:[\\/]")
#: A file's signature of fields between bars, as MTS 793 opens its exports with
#: (``MTS793|MPT|ESR|1|2|.|/|:|51|1|1|A``: its decimal, date and time signs among them):
#: kept whole as a key.
_SIGNATURE = re.compile(r"[^|\s]+(?:\|[^|\s]*){3,}")
#: Blanks that set a value in a column of its own after its key (testXpert's ASCII export:
#: ``Pre-load                                50 N``).
_COLUMN_GAP = re.compile(r" {3,}")
#: Comment marks some loggers set before each settings line (Scopy: ``;Device,M2K``).
_COMMENT_MARKS = ";#"
#: A unit in brackets, as a units row writes it (``(mm)``, ``[N]``, ``(%)``).
_BRACKETED_UNIT = re.compile(r"[(\[][^()\[\]]{1,12}[)\]]")


def parse_preamble(lines: list[str], delimiter: str) -> dict[str, str]:
    """``key -> value`` from free-text preamble lines.

    ``Category : Name,Value`` (Bluehill) gives ``Name -> Value``; ``key: a b``
    and ``key<delimiter>a<delimiter>b`` give ``key -> "a b"``; a line that is
    only text is kept as a key with an empty value. A row of names over a row
    of as many values (:func:`_names_over_values`) gives each name its value. A
    repeated key is kept once per occurrence, numbered (``"key (2)"``).
    """
    preamble: dict[str, str] = {}
    pairs: list[tuple[str, str]] = []
    lines = _without_common_mark(lines)
    index = 0
    while index < len(lines):
        paired, used = _names_over_values(lines[index: index + 3], delimiter)
        if paired:
            pairs += paired
            index += used
            continue
        pairs += _settings_in_a_row(lines[index], delimiter) or [
            _key_and_value(lines[index], delimiter)]
        index += 1
    for key, value in pairs:
        if key is None:
            continue
        unique, number = key, 1
        while unique in preamble:
            number += 1
            unique = f"{key} ({number})"
        preamble[unique] = value
    return preamble


def _without_common_mark(lines: list[str]) -> list[str]:
    """`lines` without the comment mark that opens every one of them, two at least (a
    logger's ``# Test Name: Test 1``, ``# Peak Force: 3.379 kN``, ``#``): a mark
    opening one line only may be part of its key (``# of cycles``)."""
    filled = [line.lstrip() for line in lines if line.strip()]
    marks = {line[0] for line in filled}
    if len(filled) < 2 or len(marks) != 1 or not marks <= set(_COMMENT_MARKS):
        return lines
    return [line.lstrip()[1:] for line in lines]


def _settings_in_a_row(line: str, delimiter: str) -> list[tuple[str, str]]:
    """The settings of a line that writes several side by side, each ``key:`` then its
    value in the next field (a tribometer's ``Sampling frequency [Hz]:<TAB>100<TAB>Track
    length [mm]:<TAB>5``), or each ``key: value`` in a field of its own (``Time: 15:54:46,
    Device: D4E9``); [] for any other line."""
    fields = [field.strip() for field in split_fields(line, delimiter) if field.strip()]
    if len(fields) < 2 or " : " in line:
        return []
    keys, values = fields[::2], fields[1::2]
    if (len(fields) % 2 == 0 and all(key.endswith(":") for key in keys)
            and not any(value.endswith(":") for value in values)):
        return [(key.rstrip(":").strip(), value) for key, value in zip(keys, values,
                                                                        strict=True)]
    split = [(field[:at], field[at + 1:]) for field in fields
             if 0 < (at := _key_colon(field)) < len(field) - 1]
    if len(split) == len(fields) and all(key.strip() and value.strip() for key, value in split):
        return [(key.strip(), value.strip()) for key, value in split]
    return []


def _key_and_value(line: str, delimiter: str) -> tuple[str | None, str]:
    """One preamble line's key and value; no key for a line of empty fields."""
    whole = split_fields(line, delimiter) if line.lstrip().startswith('"') else []
    if len(whole) == 1:  # quoted whole (Deben: "Span : 10,0"): one key and one value
        line = whole[0]
        if not line.strip():
            return None, ""
    if " : " in line:
        category, rest = (part.strip() for part in line.split(" : ", 1))
        fields = split_fields(rest, delimiter) if len(whole) != 1 else [rest]
        key, values = (fields[0], fields[1:]) if len(fields) > 1 else (category, [rest])
        if len(values) > 1 and not values[0].strip():  # "Name,,s": no value, its unit only
            values = []
    else:
        fields = [field.strip() for field in split_fields(line, delimiter) if field.strip()]
        if not fields:  # a blank row padded with delimiters (a spreadsheet's ",,,,")
            return None, ""
        first = fields[0]
        separators = [at for at in (_key_colon(first), first.find("=")) if at >= 0]
        if _SIGNATURE.fullmatch(first):  # its ':' is one of the signs it lists
            key, values = first, fields[1:]
        elif separators:
            at = min(separators)
            key, tail = first[:at], first[at:].lstrip(" ")[1:]
            values = [tail, *fields[1:]]
        elif len(fields) == 1 and (gap := _COLUMN_GAP.search(first)):
            key, values = first[: gap.start()], [first[gap.end():]]
        else:
            key, values = first, fields[1:]
    key = _without_comment_mark(key.strip().rstrip(":").strip()) or line.strip()
    return key, " ".join(value.strip() for value in values if value.strip())


def _key_colon(text: str) -> int:
    """Where the colon ending `text`'s key is (-1: none), passing over those of clock times
    and drive letters."""
    for match in _KEY_COLON.finditer(text):
        if not _DRIVE.match(text, match.start() - 1):
            return match.start()
    return -1


def _without_comment_mark(key: str) -> str:
    """`key` without a comment mark set directly before it (``;Device``, ``#EndHeader``);
    ``# of cycles`` keeps its ``#``."""
    if len(key) > 1 and key[0] in _COMMENT_MARKS and key[1].isalnum():
        return key[1:]
    return key


def _names_over_values(lines: list[str], delimiter: str) -> tuple[list[tuple[str, str]], int]:
    """Each name of `lines`' first row with the value under it, and the rows read (2, or 3
    with a units row between, whose units join the values); ([], 0) unless the rows are
    names over values.

    The names are distinct texts, three at least or each with its unit (``Value
    (V)``, or a units row); a column without a name (a results table's specimen
    number) is passed over. The values are as many fields, more of them numbers than
    texts. So ``Operator,John`` over ``Speed,10``, ``Length,26.0,mm`` over
    ``Width,4.1,mm`` and LabVIEW's ``X_Dimension,Time,Time`` over ``X0,0,0`` stay
    ``key,value`` lines; a Bluehill results table, ``;Width;Thickness`` over
    ``;(mm);(mm)`` over ``2;9,910;4,04``, gives ``Width -> 9,910 mm``.
    """
    if len(lines) < 2:
        return [], 0
    rows = [_fields(line, delimiter) for line in lines]
    names = rows[0]
    units = rows[1] if len(rows) == 3 and _is_units_row(rows[1], len(names)) else None
    values = rows[2] if units else rows[1]
    named = [name for name in names if name]
    if (not named or len(names) != len(values) or len(set(named)) < len(named)
            or any(":" in name or _is_number(name.replace(",", "").replace(".", ""))
                   for name in named)):  # a number, grouped or not, names nothing
        return [], 0
    numbers = sum(map(_is_number, values))
    texts = sum(bool(value) and not _is_number(value) for value in values)
    if numbers <= texts or (len(named) < 3 and units is None
                            and not all(split_name_unit(name)[1] for name in named)):
        return [], 0
    units = units or [""] * len(names)
    return ([(name, f"{value} {unit.strip('()[]')}".strip())
             for name, unit, value in zip(names, units, values, strict=True) if name],
            3 if any(units) else 2)


def _is_units_row(fields: list[str], width: int) -> bool:
    """Whether `fields` are a units row under `width` names: as many, each a unit in
    brackets (``(mm)``, ``[N]``) or empty, one at least."""
    return (len(fields) == width and any(fields)
            and all(not field or _BRACKETED_UNIT.fullmatch(field) for field in fields))


def _is_number(text: str) -> bool:
    return is_number(text, ".") or is_number(text, ",")


def _fields(line: str, delimiter: str) -> list[str]:
    """The fields of `line`, stripped, without the empty ones a trailing delimiter adds."""
    fields = [field.strip() for field in split_fields(line, delimiter)]
    while fields and not fields[-1]:
        fields.pop()
    return fields
