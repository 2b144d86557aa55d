"""``chainbench simulate roller-engagement``: logs with known xi that the campaign reads back."""

from __future__ import annotations

import io
import json
import re

import pytest
from rich.console import Console
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.cli.run import _print_result


def test_simulated_campaign_processes_to_its_truth(tmp_path):
    out = tmp_path / "raw" / "sim"
    result = CliRunner().invoke(app, ["simulate", "roller-engagement", "--out", str(out),
                                      "--xi", "0.5", "--module-mm", "0", "--rpm", "100", "250",
                                      "--format", "tdms", "--seed", "3"])
    assert result.exit_code == 0, result.output
    truth = json.loads((out / "truth.json").read_text())["runs"]
    assert sorted(truth) == ["R18-100", "R18-250"] and truth["R18-100"]["xi"] == 0.5
    result = process_campaign(out, tmp_path / "processed")
    summary = result.summary
    assert float(summary["xi_fit"][0]) == pytest.approx(0.5, rel=0.03)
    # the console's sprocket table: xi and its interval around 0.5, no involute model, and
    # the speeds above n_max of eq. (8) as the summary flags them
    console = Console(file=io.StringIO(), width=200, color_system=None)
    _print_result(result, out=console)
    printed = console.file.getvalue()
    found = re.search(r"│ +z18 │ +18 │ +([\d.]+) \(([\d.]+)\.\.([\d.]+)\) │ +- │ +yes │ "
                      r"+[\d.]+ │ +([\d. ]+|none) │", printed)
    assert found, printed
    xi, low, high = map(float, found.groups()[:3])
    assert xi == pytest.approx(0.5, rel=0.03) and low <= 0.5 <= high
    speeds, flags = summary["roller_n"].values, summary["above_n_max"].values
    above = [f"{n:g}" for n, flag in zip(speeds, flags, strict=True) if flag == 1]
    assert found.group(4) == (" ".join(above) or "none")


def test_odd_teeth_without_xi_or_geometry_is_refused(tmp_path):
    result = CliRunner().invoke(app, ["simulate", "roller-engagement", "--out",
                                      str(tmp_path / "x"), "--module-mm", "0"])
    assert result.exit_code != 0 and "--xi" in result.output
