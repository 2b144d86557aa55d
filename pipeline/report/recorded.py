"""The settings the processed files record, as the report reads them.

The code that applies a setting (a confidence level, a window rule, a band, a
threshold) writes it into the attributes of the outputs it makes
(``docs/outputs.md``); the report only reads and formats it, never recomputes it.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pipeline.errors import ChainbenchError


def recorded(attrs: Mapping[str, Any], name: str) -> Any:
    """The setting `name` of a processed file's (or variable's) attributes `attrs`.

    Raises
    ------
    ChainbenchError
        When the attributes do not record it: the files were processed by an
        older chainbench, whose report the files cannot give.
    """
    if name not in attrs:
        raise ChainbenchError(
            f"the processed results do not record {name!r}: an older chainbench made them",
            hint="process the campaign again: chainbench run --force raw/<campaign>")
    return attrs[name]


def level(attrs: Mapping[str, Any]) -> str:
    """The ``confidence_level`` an interval's attributes record, as text (``"95 %"``)."""
    return f"{100 * float(recorded(attrs, 'confidence_level')):g} %"
