"""What ``chainbench run`` and ``validate`` print: inputs verbatim, units, counts, where."""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd
import pytest
from typer.testing import CliRunner

from pipeline.cli import app

runner = CliRunner()
WIDE = {"COLUMNS": "200"}  # table rows on one line each

#: Texts rich would read as markup if they were not escaped.
FOLDER = "[red]lab"
KEY = "[/bold]"
#: The line naming the campaign folder in the output of each command.
CAMPAIGN_LINE = {"run": f"campaign raw/{FOLDER}", "validate": f"raw/{FOLDER}: 2 runs, 1 problems"}
UNKNOWN_CHAIN_RUN = """
[[runs]]
id = "T99-1"
kind = "tensile"
file = "T22-1.csv"
chain = "c99"
gauge_length_mm = 900
"""


def simulate_tensile(folder: Path, campaign: str, specimens: int = 2,
                     chain: str = "18x64") -> Path:
    """A cyclic tensile campaign from the virtual bench, written to `folder`."""
    result = runner.invoke(app, ["simulate", "tensile", "--out", str(folder), "--chain", chain,
                                 "--specimens", str(specimens), "--campaign", campaign,
                                 "--seed", "5"])
    assert result.exit_code == 0, result.output
    return folder


def simulate_engagement(folder: Path, campaign: str, *omega: str) -> Path:
    """An engagement campaign (wheel z = 8, 1 s CSV logs, one run per speed)."""
    result = runner.invoke(app, ["simulate", "engagement", "--out", str(folder), "--format", "csv",
                                 "--teeth", "8", "--omega", *omega, "--duration", "1",
                                 "--campaign", campaign])
    assert result.exit_code == 0, result.output
    return folder


def bracketed_campaign(project: Path) -> Path:
    """A tensile campaign whose folder, chain key, note and one error hold brackets.

    The folder is ``raw/[red]lab``; the chain key ``[/bold]`` (catalogue
    chain 22x86, whose geometry note names the key); a third run names the
    undefined chain c99, whose error hint reads ``define [chains.c99] or use
    one of: [/bold]``.
    """
    folder = simulate_tensile(project / "raw" / FOLDER, "brackets", chain="22x86")
    sheet = folder / "campaign.toml"
    text = sheet.read_text(encoding="utf-8").replace("[chains.c22x86]", f'[chains."{KEY}"]')
    text = text.replace('chain = "c22x86"', f'chain = "{KEY}"')
    sheet.write_text(text + UNKNOWN_CHAIN_RUN, encoding="utf-8")
    return folder


def line_after(output: str, prefix: str) -> str:
    """The rest of the one output line that starts with `prefix`."""
    (line,) = [line for line in output.splitlines() if line.startswith(prefix)]
    return line.removeprefix(prefix)


def cells(output: str, first: str) -> list[str]:
    """The cells of the table row whose first cell is `first`."""
    row = next(line for line in output.splitlines() if line.startswith(f"│ {first} "))
    return [cell.strip() for cell in row.split("│")[1:-1]]


# -- inputs holding brackets --------------------------------------------------------------

@pytest.mark.parametrize("command", ["run", "validate"])
def test_bracketed_inputs_are_printed_verbatim(tmp_path, monkeypatch, command):
    bracketed_campaign(tmp_path)
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, [command], env=WIDE)
    assert isinstance(result.exception, SystemExit), result.exception  # no traceback
    assert result.exit_code == 1  # the run of chain c99 is refused
    assert "unknown chain 'c99' (hint: define [chains.c99] or use one of: [/bold])" in (
        result.output)
    assert CAMPAIGN_LINE[command] in result.output.splitlines()


def test_run_prints_a_bracketed_chain_key_in_its_table_and_notes(tmp_path, monkeypatch):
    bracketed_campaign(tmp_path)
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["run"], env=WIDE)
    assert result.exit_code == 1, result.output
    assert cells(result.output, KEY)[1] == "2"  # two specimens
    assert line_after(result.output, "note ").startswith(
        f"{KEY}: link geometry does not close")


# -- units ----------------------------------------------------------------------------------

def test_console_shows_kN_and_json_says_its_SI_units(tmp_path, monkeypatch):
    simulate_tensile(tmp_path / "raw" / "c18", "c18", specimens=3)
    monkeypatch.chdir(tmp_path)
    shown = runner.invoke(app, ["run"], env=WIDE)
    assert shown.exit_code == 0, shown.output
    document = json.loads(runner.invoke(app, ["run", "--json"]).stdout)[0]
    csv = pd.read_csv(tmp_path / "processed" / "c18" / "summary.csv").iloc[0]

    assert "forces in kN" in shown.output
    assert "E0_exp [kN]" in shown.output and "95 % interval [kN]" in shown.output
    row = cells(shown.output, "c18x64")
    assert float(row[2]) == pytest.approx(csv["E0_exp [N]"] / 1e3, rel=1e-4)
    low, high = (float(value) for value in row[3].split(".."))
    assert low == pytest.approx(csv["E0_exp_ci_low [N]"] / 1e3, rel=1e-4)
    assert high == pytest.approx(csv["E0_exp_ci_high [N]"] / 1e3, rel=1e-4)

    (chain,) = document["chains"]
    assert chain["E0_exp"] == pytest.approx(csv["E0_exp [N]"], rel=1e-5)
    units = document["units"]
    assert (units["E0_exp"], units["E0_theory"], units["discrepancy"]) == ("N", "N", "1")
    assert set(chain) - {"chain"} <= set(units)
    assert "SI units" in document["note"] and "forces in N" in document["note"]


def test_impact_table_states_its_units(tmp_path, monkeypatch):
    simulate_engagement(tmp_path / "raw" / "eng", "eng", "20", "30")
    monkeypatch.chdir(tmp_path)
    shown = runner.invoke(app, ["run"], env=WIDE)
    assert shown.exit_code == 0, shown.output
    assert "forces in N" in shown.output and "N_u1 meas [N]" in shown.output
    document = json.loads(runner.invoke(app, ["run", "--json"]).stdout)[0]
    units = document["units"]
    assert (units["N_u1_meas"], units["omega"], units["branch_length"]) == ("N", "s-1", "m")
    assert units["k_fit"] == "1"
    assert set(document["operating_points"][0]) - {"operating_point"} <= set(units)


# -- outside a project ------------------------------------------------------------------------

@pytest.mark.parametrize("command", ["run", "validate"])
@pytest.mark.parametrize(("folders", "arguments", "looked_at"), [
    ((), [], "raw"),  # no raw/ folder
    (("raw", "raw/empty"), [], "raw"),  # raw/ without a run sheet
    ((), ["nowhere"], "nowhere"),  # a folder that does not exist
    (("exports",), ["exports"], "exports"),  # a folder without a run sheet
])
def test_no_campaign_gives_one_line_saying_where_it_looked(
        tmp_path, monkeypatch, command, folders, arguments, looked_at):
    for folder in folders:
        (tmp_path / folder).mkdir()
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, [command, *arguments])
    assert isinstance(result.exception, SystemExit), result.exception
    assert result.exit_code == 1
    (line,) = result.output.strip().splitlines()
    assert line.startswith("error ")
    assert str(tmp_path.resolve() / looked_at) in line
    assert "raw/<campaign>/campaign.toml" in line and "chainbench init" in line


def test_no_campaign_with_json_keeps_stdout_for_json(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["run", "--json"])
    assert result.exit_code == 1
    assert result.stdout == ""
    assert str(tmp_path.resolve() / "raw") in result.stderr


# -- where the outputs go ---------------------------------------------------------------------

def test_outputs_are_named_by_the_campaign_id(tmp_path, monkeypatch):
    folder = simulate_tensile(tmp_path / "raw" / "folder-name", "the-id")
    monkeypatch.chdir(folder)
    given = [["run", str(folder / "campaign.toml"), "--output", str(tmp_path / "by-sheet")],
             ["run", ".", "--output", str(tmp_path / "here")],
             ["run", "."]]
    for arguments in given:
        result = runner.invoke(app, arguments)
        assert result.exit_code == 0, result.output
    for root in ("by-sheet", "here", "processed"):
        assert [path.name for path in (tmp_path / root).iterdir()] == ["the-id"]
        assert (tmp_path / root / "the-id" / "summary.csv").is_file()
    assert not list(folder.glob("*.nc"))


# -- bookkeeping ------------------------------------------------------------------------------

def test_counts_say_what_became_of_every_run(tmp_path):
    folder = simulate_tensile(tmp_path / "raw" / "mixed", "mixed", specimens=2)
    (folder / "garbage.csv").write_bytes(bytes(range(256)) * 8)
    sheet = folder / "campaign.toml"
    broken = "".join(
        f'\n[[runs]]\nid = "{run_id}"\nkind = "tensile"\nfile = "{file}"\nchain = "c18x64"\n'
        "gauge_length_mm = 900\n"
        for run_id, file in (("T-missing", "missing.csv"), ("T-garbage", "garbage.csv")))
    sheet.write_text(sheet.read_text(encoding="utf-8") + broken, encoding="utf-8")
    out = ["--output", str(tmp_path / "out")]

    first = runner.invoke(app, ["run", str(folder), *out, "--json"])
    assert first.exit_code == 1
    (document,) = json.loads(first.stdout)
    assert (document["processed"], document["unchanged"], document["failed"]) == (2, 0, 2)
    assert {failure["run"] for failure in document["failed_runs"]} == {"T-missing", "T-garbage"}

    second = runner.invoke(app, ["run", str(folder), *out], env=WIDE)
    assert second.exit_code == 1
    assert "0 run(s) processed, 2 unchanged, 2 failed; results in " in second.output


# -- validate = run without writing -----------------------------------------------------------

def test_validate_reports_the_failures_run_reports_and_writes_nothing(tmp_path, monkeypatch):
    folder = simulate_engagement(tmp_path / "raw" / "eng", "eng", "20", "30")
    log = folder / "E8-40-30.csv"  # 10 ms: too short for the events of a wheel
    log.write_text("".join(log.read_text().splitlines(keepends=True)[:200]))
    (folder / "broken.csv").write_bytes(bytes(range(256)) * 8)
    sheet = folder / "campaign.toml"
    text = sheet.read_text(encoding="utf-8")
    copy = text[text.rindex("[[runs]]"):].replace('"E8-40-30', '"E-broken').replace(
        'file = "E-broken.csv"', 'file = "broken.csv"')
    sheet.write_text(text + "\n" + copy, encoding="utf-8")
    monkeypatch.chdir(tmp_path)

    checked = runner.invoke(app, ["validate"], env=WIDE)
    assert checked.exit_code == 1
    assert not (tmp_path / "processed").exists()
    assert "raw/eng: 3 runs, 2 problems" in checked.output
    processed = runner.invoke(app, ["run"], env=WIDE)
    assert processed.exit_code == 1
    assert "1 run(s) processed, 0 unchanged, 2 failed" in processed.output
    for run_id in ("E8-40-30", "E-broken"):
        refused = line_after(processed.output, f"failed {run_id}: ")
        assert line_after(checked.output, f"error {run_id}: ") == refused
    assert "seating periods" in line_after(checked.output, "error E8-40-30: ")
    assert "broken.csv" in line_after(checked.output, "error E-broken: ")


def test_validate_reads_the_stiffness_run_would_use(tmp_path, monkeypatch):
    simulate_tensile(tmp_path / "raw" / "stiff", "stiff")
    folder = simulate_engagement(tmp_path / "raw" / "eng", "eng", "20")
    sheet = folder / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8").replace(
        "E0_N = 22600000", 'stiffness_from = "stiff/c18x64"'), encoding="utf-8")
    monkeypatch.chdir(tmp_path)

    before = runner.invoke(app, ["validate", "raw/eng"], env=WIDE)
    assert before.exit_code == 1
    assert str(tmp_path.resolve() / "processed" / "stiff" / "summary.nc") in before.output
    assert runner.invoke(app, ["run", "raw/stiff"]).exit_code == 0
    after = runner.invoke(app, ["validate", "raw/eng"], env=WIDE)
    assert after.exit_code == 0, after.output
    assert "raw/eng: 1 runs, 0 problems" in after.output


def test_validate_lists_chain_definitions_set_aside(tmp_path):
    folder = simulate_tensile(tmp_path / "c18", "c18")
    sheet = folder / "campaign.toml"
    sheet.write_text(sheet.read_text(encoding="utf-8") + '\n[chains.c5]\ncatalog = "5x5"\n',
                     encoding="utf-8")  # defined, used by no run
    result = runner.invoke(app, ["validate", str(folder)], env=WIDE)
    assert result.exit_code == 1
    assert line_after(result.output, "error chains.c5: ").startswith(
        "campaign.toml, key 'chains.c5': unknown chain '5x5'")


# -- the other commands -----------------------------------------------------------------------

def test_other_commands_print_bracketed_paths_verbatim(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    written = runner.invoke(app, ["simulate", "tensile", "--out", FOLDER, "--specimens", "1"],
                            env=WIDE)
    assert written.exit_code == 0, written.output
    assert FOLDER in written.output  # in the table's title
    log = Path(FOLDER) / "T18-1.csv"
    inspected = runner.invoke(app, ["inspect", str(log)], env=WIDE)
    assert inspected.exit_code == 0, inspected.output
    assert inspected.output.splitlines()[0] == str(log)


def test_theory_tables_carry_units_in_headings_and_json():
    command = ["theory", "impact", "--chain", "18x64", "--teeth", "8", "--apex", "40",
               "--omega", "20", "--branch-length", "2"]
    shown = runner.invoke(app, command, env=WIDE)
    assert shown.exit_code == 0, shown.output
    headings = " ".join(line for line in shown.output.splitlines() if line.startswith("┃"))
    assert [unit for unit in ("[m/s]", "[N]", "[s]") if unit not in headings] == []
    document = json.loads(runner.invoke(app, [*command, "--json"]).stdout)
    assert (document["units"]["N_u1"], document["units"]["tau"]) == ("N", "s")
    assert set(document["rows"][0]) == set(document["units"])
