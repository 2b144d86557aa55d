"""The ``chainbench`` command line: it only wires the pipeline's stages."""

from __future__ import annotations

import typer

from pipeline import __version__
from pipeline.cli.theory import theory_app

app = typer.Typer(
    help="chainbench: test-bench data analysis for chain-drive laboratories.",
    no_args_is_help=True,
    pretty_exceptions_enable=False,
)
app.add_typer(theory_app, name="theory")


@app.callback()
def _main(
    version: bool = typer.Option(False, "--version", help="Print the version and exit."),
) -> None:
    if version:
        typer.echo(__version__)
        raise typer.Exit()
