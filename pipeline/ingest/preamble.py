"""The free-text preamble machines write above their table (Instron Bluehill, MTS, Zwick).

Lines of ``key : value``, ``key: value``, ``key = value``, ``"key","value"``
or ``key<TAB>value`` before the names row become ``key -> value`` in
:attr:`~pipeline.ingest.table.TableMetadata.preamble`.
"""

from __future__ import annotations

from pipeline.ingest.sniff import split_fields


def parse_preamble(lines: list[str], delimiter: str) -> dict[str, str]:
    """``key -> value`` from free-text preamble lines.

    ``Category : Name,Value`` (Bluehill) gives ``Name -> Value``; ``key: a b``
    and ``key<delimiter>a<delimiter>b`` give ``key -> "a b"``; a line that is
    only text is kept as a key with an empty value. A repeated key is kept
    once per occurrence, numbered (``"key (2)"``).
    """
    preamble: dict[str, str] = {}
    for line in lines:
        whole = split_fields(line, delimiter) if line.lstrip().startswith('"') else []
        if len(whole) == 1:  # quoted whole (Deben: "Span : 10,0"): one key and one value
            line = whole[0]
            if not line.strip():
                continue
        if " : " in line:
            category, rest = (part.strip() for part in line.split(" : ", 1))
            fields = split_fields(rest, delimiter) if len(whole) != 1 else [rest]
            key, values = (fields[0], fields[1:]) if len(fields) > 1 else (category, [rest])
        else:
            fields = [field.strip() for field in split_fields(line, delimiter) if field.strip()]
            first = fields[0] if fields else line.strip()
            separators = [index for index in (first.find(":"), first.find(" =")) if index >= 0]
            if separators:
                at = min(separators)
                key, tail = first[:at], first[at:].lstrip(" ")[1:]
                values = [tail, *fields[1:]]
            else:
                key, values = first, fields[1:]
        key = key.strip().rstrip(":").strip() or line.strip()
        value = " ".join(value.strip() for value in values if value.strip())
        unique, number = key, 1
        while unique in preamble:
            number += 1
            unique = f"{key} ({number})"
        preamble[unique] = value
    return preamble
