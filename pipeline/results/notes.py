"""The warnings a run file carries: lists of texts in global attributes, one a line."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

#: The global attributes of a run file that hold warnings, in the order they arose:
#: the reader's, the stages' (tensile), the detection's and extraction's (engagement).
NOTE_ATTRS = ("ingest_warnings", "warnings", "messages")


def joined(texts: Iterable[str]) -> str:
    """`texts` as one attribute value, one a line (a text may hold ``;``)."""
    return "\n".join(texts)


def lines(value: str) -> tuple[str, ...]:
    """The texts of an attribute value written by :func:`joined` (none when empty)."""
    return tuple(text for text in str(value).split("\n") if text)


def run_notes(attrs: Mapping[str, Any]) -> list[str]:
    """Every warning of a run, from its run file's global attributes (:data:`NOTE_ATTRS`).

    Examples
    --------
    >>> run_notes({"ingest_warnings": "line 4 is truncated", "warnings": "", "kind": "tensile"})
    ['line 4 is truncated']
    """
    return [text for name in NOTE_ATTRS for text in lines(attrs.get(name, ""))]
