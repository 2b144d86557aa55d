"""A unit slip in one run is flagged, named and kept out of the chain's E0 and the fit of k.

The virtual bench writes the logs with the right units; the tests then relabel
a column as a technician might (gauges in mm headed ``[m]``, a force in N
headed ``[kN]``) and check what the campaign makes of it.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app

runner = CliRunner()


@pytest.fixture(scope="module")
def tensile_source(simulated) -> Path:
    return simulated("tensile", "--specimens", "3", "--seed", "5", "--campaign", "c")


@pytest.fixture(scope="module")
def engagement_source(simulated) -> Path:
    return simulated("engagement", "--format", "csv", "--seed", "2", "--campaign", "c")


def copy(source: Path, tmp_path: Path) -> Path:
    folder = tmp_path / "raw" / "c"
    shutil.copytree(source, folder)
    return folder


def relabel(path: Path, old: str, new: str) -> None:
    """Change the header of a log, leaving its numbers as they are."""
    header, rest = path.read_text(encoding="utf-8").split("\n", 1)
    assert old in header
    path.write_text(header.replace(old, new) + "\n" + rest, encoding="utf-8")


def accept(sheet: Path, run_id: str) -> None:
    text = sheet.read_text(encoding="utf-8")
    marker = f'id = "{run_id}"\n'
    sheet.write_text(text.replace(marker, marker + "accept_implausible = true\n"),
                     encoding="utf-8")


def flags_of(summary, run_id: str) -> dict[str, str]:
    """Quantity -> slip named, of the flags on `run_id`."""
    chosen = summary["flag_run"].values == run_id
    return dict(zip(summary["flag_quantity"].values[chosen], summary["flag_slip"].values[chosen],
                    strict=True))


def test_gauges_in_mm_headed_m_are_flagged_named_and_left_out_of_the_chain(tensile_source,
                                                                           tmp_path):
    good = process_campaign(copy(tensile_source, tmp_path / "good"), tmp_path / "good-out")
    campaign = copy(tensile_source, tmp_path / "slip")
    relabel(campaign / "T18-2.csv", "gauge1 [mm],gauge2 [mm]", "gauge1 [m],gauge2 [m]")
    result = process_campaign(campaign, tmp_path / "out")
    summary = result.summary
    flags = flags_of(summary, "T18-2")
    assert "1000" in flags["E0"] and "mm labelled m" in flags["E0"]
    assert set(summary["flag_run"].values) == {"T18-2"}
    assert int(summary["n_specimens"].item()) == 2
    others = good.summary["specimen_E0"].sel(specimen=["T18-1", "T18-3"]).values
    np.testing.assert_allclose(float(summary["E0_exp"].item()), others.mean(), rtol=1e-12)
    ratio = float(summary["specimen_E0"].sel(specimen="T18-2")
                  / good.summary["specimen_E0"].sel(specimen="T18-2"))
    assert ratio == pytest.approx(1e-3, rel=1e-9)  # the row is kept, as measured


def test_an_accepted_slip_is_shown_and_counted(tensile_source, tmp_path):
    campaign = copy(tensile_source, tmp_path)
    relabel(campaign / "T18-2.csv", "gauge1 [mm],gauge2 [mm]", "gauge1 [m],gauge2 [m]")
    accept(campaign / "campaign.toml", "T18-2")
    summary = process_campaign(campaign, tmp_path / "out").summary
    assert "E0" in flags_of(summary, "T18-2")
    assert summary["flag_accepted"].values.all()
    assert int(summary["n_specimens"].item()) == 3


def test_a_campaign_without_slips_has_no_flags(tensile_source, tmp_path):
    summary = process_campaign(copy(tensile_source, tmp_path), tmp_path / "out").summary
    assert summary.sizes["flag"] == 0
    assert int(summary["n_specimens"].item()) == 3


def test_forces_in_N_headed_kN_give_impact_tensions_flagged_against_the_model(
        engagement_source, tmp_path):
    campaign = copy(engagement_source, tmp_path)
    (log,) = campaign.glob("*.csv")
    relabel(log, "force [N]", "force [kN]")
    summary = process_campaign(campaign, tmp_path / "out").summary
    flags = flags_of(summary, log.stem)
    assert set(flags) == {"N_u1", "N_u2"}
    assert all("1000" in slip for slip in flags.values())


def test_the_cli_shows_the_flag_and_the_report_lists_it(tensile_source, tmp_path,
                                                        monkeypatch):
    campaign = copy(tensile_source, tmp_path)
    relabel(campaign / "T18-2.csv", "gauge1 [mm],gauge2 [mm]", "gauge1 [m],gauge2 [m]")
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["run", "raw/c"], env={"COLUMNS": "200"})
    assert "implausible" in result.output and "T18-2" in result.output
    assert "mm labelled m" in result.output
    assert result.exit_code == 1  # a flagged run needs a person's decision
    report = (tmp_path / "processed" / "c" / "report.html").read_text(encoding="utf-8")
    assert "mm labelled m" in report
