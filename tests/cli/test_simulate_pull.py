"""``chainbench simulate tensile --single-pull``: single pulls with their truth and run sheet."""

from __future__ import annotations

import json
import tomllib

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.ingest import read_table

runner = CliRunner()


def simulate(tmp_path, *arguments: str) -> dict:
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(tmp_path), "--single-pull",
                                 *arguments, "--json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_writes_single_pulls_run_sheet_and_truth(tmp_path):
    printed = simulate(tmp_path, "--specimens", "2", "--layout", "european", "--seed", "5")
    assert [row["file"] for row in printed["rows"]] == ["P18-1.csv", "P18-2.csv"]
    sheet = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert all(run["cycles"] == 1 and run["gauge_length_mm"] == pytest.approx(320)
               and "proof_force_kN" not in run for run in sheet["runs"])
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]["P18-1"]
    for key in ("E0_N", "max_force_N", "strain_at_max_force", "elongation_at_fracture_m",
                "offset_yield_force_N", "fracture_index", "removal_index",
                "elongation_at_proof_m", "permanent_set_m"):
        assert key in truth
    table, _ = read_table(tmp_path / "P18-1.csv")
    assert len(table) == truth["n_samples"]
    assert table["force"].max() == pytest.approx(truth["max_force_N"], rel=2e-3)
    assert (tmp_path / "P18-1.csv").read_text(encoding="cp1250").startswith(
        "Czas [s];Siła [kN];Ekstensometr [mm];Trawersa [mm]\n")
    again = tmp_path / "again"
    simulate(again, "--specimens", "2", "--layout", "european", "--seed", "5")
    assert (again / "P18-2.csv").read_bytes() == (tmp_path / "P18-2.csv").read_bytes()


def test_strain_channel_removal_and_bluehill_options(tmp_path):
    simulate(tmp_path, "--specimens", "1", "--layout", "machine", "--language", "de",
             "--strain-channel", "--extensometer-removed-at", "0.95", "--removal-mode",
             "reverse", "--repeated-first-time", "--quote")
    sheet = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert "gauge_length_mm" not in sheet["runs"][0]
    lines = (tmp_path / "P18-1.csv").read_bytes().decode("latin-1").split("\r\n")
    assert lines[3:5] == ['"Zeit";"Traversenweg";"Last";"Dehnung 1"',
                          '"(sec)";"(mm)";"(kN)";"(%)"']
    assert lines[5].startswith('"0";') and lines[6].startswith('"0";')
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]["P18-1"]
    assert truth["removal_index"] < truth["fracture_index"]
    assert truth["truth"]["removal_mode"] == "reverse"


def test_proof_only_without_crosshead(tmp_path):
    simulate(tmp_path, "--specimens", "1", "--proof-force-kn", "320", "--proof-only",
             "--no-crosshead")
    sheet = tomllib.loads((tmp_path / "campaign.toml").read_text(encoding="utf-8"))
    assert sheet["runs"][0]["proof_force_kN"] == 320
    assert (tmp_path / "P18-1.csv").read_text().splitlines()[0] == (
        "time [s],force [kN],extensometer [mm]")
    truth = json.loads((tmp_path / "truth.json").read_text(encoding="utf-8"))["runs"]["P18-1"]
    assert truth["fracture_index"] is None and truth["permanent_set_m"] > 0


@pytest.mark.parametrize(
    ("arguments", "words"),
    [(["--proof-only"], "proof_force"), (["--extensometer-removed-at", "1.5"], "removed_at"),
     (["--chain", "13x50"], "give max_force"), (["--removal-mode", "fly"], "fly")],
)
def test_bad_options_exit_non_zero(tmp_path, arguments, words):
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(tmp_path), "--single-pull",
                                 *arguments])
    assert result.exit_code != 0
    assert words in result.output
