"""Run-sheet values are taken as written: no string for a number or a boolean, no
number for a string; the error names the key, what was expected and what was given."""

from __future__ import annotations

from pathlib import Path

import pytest

from pipeline.errors import RunSheetError
from pipeline.runsheet import load_run_sheet

HEAD = """
[campaign]
id = "c-1"

[chains.c18]
catalog = "18x64"

[chains.c22]
catalog = "22x86"

[wheels.w8]
teeth = 8
apex_angle_deg = 40
"""

GOOD_RUN = """
[[runs]]
id = "T1"
kind = "tensile"
file = "T1.csv"
chain = "c18"
gauge_length_mm = 900
"""

ENGAGEMENT = """
[[runs]]
id = "E1"
kind = "engagement"
file = "E1.csv"
chain = "c18"
wheel = "w8"
branch_length_m = 2
"""


def load(folder: Path, text: str):
    sheet = folder / "campaign.toml"
    sheet.write_text(text, encoding="utf-8")
    return load_run_sheet(sheet)


def second_run(*lines: str) -> str:
    """A tensile run ``T2`` on chain c22, without a gauge length, with `lines` added."""
    run = GOOD_RUN.replace('"T1"', '"T2"').replace('"c18"', '"c22"')
    return run.replace("gauge_length_mm = 900\n", "") + "\n".join(lines) + "\n"


@pytest.mark.parametrize(
    ("line", "key", "message", "hint"),
    [
        ('gauge_length_mm = "900"', "gauge_length_mm",
         "expected a number, got the string '900'", "write gauge_length_mm = 900 without quotes"),
        ('gauge_length_mm = "nine hundred"', "gauge_length_mm",
         "expected a number, got the string 'nine hundred'",
         "write gauge_length_mm as a number, without quotes"),
        ("gauge_length_mm = true", "gauge_length_mm",
         "expected a number, got the boolean true", "write gauge_length_mm as a number"),
        ('cycles = "5"', "cycles",
         "expected a whole number, got the string '5'", "write cycles = 5 without quotes"),
        ("cycles = 5.0", "cycles",
         "expected a whole number, got the number 5.0", "write cycles = 5 without a decimal point"),
        ('average_gauges = "yes"', "average_gauges",
         "expected true or false, got the string 'yes'",
         "write average_gauges = true or average_gauges = false, without quotes"),
        ("average_gauges = 1", "average_gauges", "expected true or false, got the number 1",
         "without quotes"),
        ('accept_implausible = "true"', "accept_implausible",
         "expected true or false, got the string 'true'", "accept_implausible = true"),
        ('proof_force_kN = "100"', "proof_force_kN", "expected a number, got the string '100'",
         "write proof_force_kN = 100 without quotes"),
        ("note = 5", "note", "expected a string, got the number 5", 'write note = "5" in quotes'),
        ("specimen = 2024-03-01", "specimen", "expected a string, got the value 2024-03-01",
         'write specimen = "2024-03-01" in quotes'),
        ('fit_window = { force_low_kN = "1", force_high_kN = 10 }',
         "fit_window.force_low_kN", "expected a number, got the string '1'",
         "write fit_window.force_low_kN = 1 without quotes"),
        ("units = { gauges = 5 }", "units.gauges",
         "expected a string or a list, got the number 5", 'write units.gauges = "5" in quotes'),
        ('units = { gauges = ["mV/V", 2] }', "units.gauges[1]",
         "expected a string, got the number 2", 'write units.gauges[1] = "2" in quotes'),
        ('columns = { force = 3 }', "columns.force",
         "expected a string, got the number 3", 'write columns.force = "3" in quotes'),
    ],
)
def test_run_value_of_wrong_type_is_refused(tmp_path, line, key, message, hint):
    sheet = load(tmp_path, HEAD + GOOD_RUN + second_run(line))
    assert [run.id for run in sheet.runs] == ["T1"]  # the good run survives
    (error,) = sheet.invalid_runs
    assert error.column == f"runs[1].{key}"
    assert error.message == message
    assert hint in error.hint


def test_chain_given_as_number_is_refused(tmp_path):
    sheet = load(tmp_path, HEAD + GOOD_RUN.replace('chain = "c18"', "chain = 18"))
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].chain"
    assert error.message == "expected a string, got the number 18"
    assert error.hint == 'write chain = "18" in quotes'


def test_engagement_speed_as_string_is_refused(tmp_path):
    sheet = load(tmp_path, HEAD + ENGAGEMENT + 'rpm = "60"\n')
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].rpm"
    assert error.message == "expected a number, got the string '60'"


@pytest.mark.parametrize(
    ("line", "key", "message"),
    [
        ('synthetic = "yes"', "campaign.synthetic", "expected true or false, got the string 'yes'"),
        ("title = 5", "campaign.title", "expected a string, got the number 5"),
        ('discrepancy_band_pct = ["3", 6]', "campaign.discrepancy_band_pct[0]",
         "expected a number, got the string '3'"),
        ('discrepancy_band_pct = "3-6"', "campaign.discrepancy_band_pct",
         "expected a list, got the string '3-6'"),
        ('machine_capacity_kN = "500"', "campaign.machine_capacity_kN",
         "expected a number, got the string '500'"),
    ],
)
def test_campaign_value_of_wrong_type_makes_the_sheet_invalid(tmp_path, line, key, message):
    text = HEAD.replace('id = "c-1"', f'id = "c-1"\n{line}') + GOOD_RUN
    with pytest.raises(RunSheetError) as caught:
        load(tmp_path, text)
    assert (caught.value.column, caught.value.message) == (key, message)


def test_chain_value_of_wrong_type_invalidates_its_runs_only(tmp_path):
    text = HEAD.replace('catalog = "18x64"', 'catalog = "18x64"\nt_mm = "64"')
    sheet = load(tmp_path, text + GOOD_RUN + second_run())
    assert [run.id for run in sheet.runs] == ["T2"]  # on chain c22
    assert list(sheet.chains) == ["c22"]
    fault = sheet.invalid_chains["c18"]
    assert (fault.column, fault.message) == (
        "chains.c18.t_mm", "expected a number, got the string '64'")
    assert fault.hint == "write t_mm = 64 without quotes"
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].chain"
    assert error.message == ("run 'T1' uses chain 'c18', which is invalid: "
                             "chains.c18.t_mm: expected a number, got the string '64'")
    assert error.hint == "fix [chains.c18]: write t_mm = 64 without quotes"


def test_wheel_value_of_wrong_type_invalidates_its_runs_only(tmp_path):
    text = HEAD.replace("teeth = 8", 'teeth = "7"')
    sheet = load(tmp_path, text + GOOD_RUN + ENGAGEMENT + "rpm = 60\n")
    assert [run.id for run in sheet.runs] == ["T1"]
    assert sheet.invalid_wheels["w8"].column == "wheels.w8.teeth"
    assert sheet.invalid_wheels["w8"].message == "expected a whole number, got the string '7'"
    (error,) = sheet.invalid_runs
    assert error.column == "runs[1].wheel"
    assert error.message.startswith("run 'E1' uses wheel 'w8', which is invalid: wheels.w8.teeth")


def test_values_of_the_right_type_still_load(tmp_path):
    campaign = 'id = "c-1"\ndiscrepancy_band_pct = [2, 5]\nmachine_capacity_kN = 500'
    run = second_run(
        'format = "csv"', "cycles = 3", "accept_implausible = true",
        'columns = { force = "F", gauges = ["g1", "g2"] }', 'units = { gauges = "mV/V" }',
        "fit_window = { force_low_kN = 1, force_high_kN = 10.5 }",
    )
    sheet = load(tmp_path, HEAD.replace('id = "c-1"', campaign) + GOOD_RUN + run)
    assert sheet.invalid_runs == []
    assert sheet.campaign.discrepancy_band_pct == (2.0, 5.0)
    assert sheet.campaign.machine_capacity_kN == 500.0
    first, second = sheet.runs
    assert first.gauge_length_mm == 900.0 and isinstance(first.gauge_length_mm, float)
    assert (first.accept_implausible, second.accept_implausible) == (False, True)
    assert second.columns.gauges == ["g1", "g2"]
    assert second.units.gauges == "mV/V"
    assert (second.fit_window.force_low_kN, second.fit_window.force_high_kN) == (1.0, 10.5)
    assert (second.format, second.cycles) == ("csv", 3)


def test_one_gauge_column_may_be_named_without_a_list(tmp_path):
    run = second_run('columns = { force = "F", gauges = "eyy" }')
    sheet = load(tmp_path, HEAD + GOOD_RUN + run)
    assert sheet.invalid_runs == []
    assert sheet.runs[1].columns.gauges == "eyy"
