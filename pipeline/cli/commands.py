"""The ``chainbench`` command tree (:data:`app`): every command, wired to its module."""

from __future__ import annotations

import typer

from pipeline import __version__
from pipeline.cli import init, inspect, report, run
from pipeline.cli.simulate import simulate_app
from pipeline.cli.theory import theory_app

app = typer.Typer(
    help="chainbench: test-bench data analysis for chain-drive laboratories.",
    pretty_exceptions_enable=False,
)
app.add_typer(theory_app, name="theory")
app.command("init")(init.command)
app.command("inspect")(inspect.command)
app.command("run")(run.run_command)
app.command("validate")(run.validate_command)
app.command("report")(report.command)
app.add_typer(simulate_app, name="simulate")


@app.callback(invoke_without_command=True)
def _main(
    context: typer.Context,
    version: bool = typer.Option(False, "--version", help="Print the version and exit."),
) -> None:
    if version:
        typer.echo(__version__)
        raise typer.Exit()
    if context.invoked_subcommand is None:
        typer.echo(context.get_help())
        raise typer.Exit()
