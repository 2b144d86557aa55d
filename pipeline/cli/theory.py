"""``chainbench theory ...``: the papers' calculators as tables."""

from __future__ import annotations

import typer

from pipeline.cli import (
    theory_impact,
    theory_pin,
    theory_roller,
    theory_segments,
    theory_stiffness,
)
from pipeline.cli._options import MultiValueCommand

theory_app = typer.Typer(
    help="The published models as tables (papers 000-004).", no_args_is_help=True
)
theory_app.command("stiffness")(theory_stiffness.command)
theory_app.command("impact", cls=MultiValueCommand)(theory_impact.command)
theory_app.command("roller-impact", cls=MultiValueCommand)(theory_roller.command)
theory_app.command("tooth-segments", cls=MultiValueCommand)(theory_segments.command)
theory_app.command("pin", cls=MultiValueCommand)(theory_pin.command)
