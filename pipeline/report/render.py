"""Deterministic rendering of matplotlib figures for the self-contained report.

The same data must give the same report, byte for byte (``docs/quality.md``): SVG
ids come from a fixed hash salt and no date is embedded.
"""

from __future__ import annotations

import io
from contextlib import AbstractContextManager

import matplotlib
from matplotlib.figure import Figure

# Figures are built as bare matplotlib Figure objects, never through pyplot: no
# backend is chosen and a user's interactive session (a notebook) is left as it is.

#: Fixed salt of the SVG element ids, so that equal figures give equal files.
SVG_HASH_SALT = "chainbench"

#: Style of every report figure: readable when printed, units on every axis.
STYLE = {
    "figure.figsize": (7.0, 4.2),
    "figure.dpi": 100,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "axes.titlesize": 11,
    "axes.labelsize": 10,
    "legend.fontsize": 8,
    "font.family": "DejaVu Sans",
    "svg.fonttype": "none",  # text stays text: smaller files, selectable, searchable
    "svg.hashsalt": SVG_HASH_SALT,
}


def report_style() -> AbstractContextManager:
    """Context in which figures are built and rendered in the report's style (:data:`STYLE`)."""
    return matplotlib.rc_context(STYLE)


def svg(figure: Figure) -> str:
    """The figure as an inline ``<svg>`` element (no XML prolog, no date)."""
    buffer = io.StringIO()
    with report_style():
        figure.savefig(buffer, format="svg", metadata={"Date": None, "Creator": None},
                       bbox_inches="tight")
    text = buffer.getvalue()
    return text[text.index("<svg"):]
