"""The top-level command: version and help."""

from typer.testing import CliRunner

from pipeline import __version__
from pipeline.cli import app


def test_version():
    result = CliRunner().invoke(app, ["--version"])
    assert result.exit_code == 0
    assert result.stdout.strip() == __version__


def test_no_command_prints_help():
    result = CliRunner().invoke(app, [])
    assert result.exit_code == 0
    for command in ("run", "validate", "report", "inspect", "theory", "simulate"):
        assert command in result.stdout
