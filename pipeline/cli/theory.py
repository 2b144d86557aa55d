"""``chainbench theory ...``: the papers' calculators as tables."""

from __future__ import annotations

import typer

theory_app = typer.Typer(
    help="The published models as tables (papers 000-004).", no_args_is_help=True
)
