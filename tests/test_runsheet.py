"""Run-sheet validation: typed errors naming file and key path; bad entries isolated."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from pipeline.errors import RunSheetError
from pipeline.runsheet import load_run_sheet, resolve_inside

HEAD = """
[campaign]
id = "c-1"
title = "test campaign"

[chains.c18]
catalog = "18x64"

[wheels.w8]
teeth = 8
apex_angle_deg = 40
"""

TENSILE = """
[[runs]]
id = "{id}"
kind = "tensile"
file = "{file}"
chain = "{chain}"
gauge_length_mm = {gauge}
"""


def write_sheet(folder: Path, text: str) -> Path:
    sheet = folder / "campaign.toml"
    sheet.write_text(text, encoding="utf-8")
    return sheet


def tensile(id="T1", file="T1.csv", chain="c18", gauge="900") -> str:
    return TENSILE.format(id=id, file=file, chain=chain, gauge=gauge)


def test_valid_sheet_takes_catalogue_defaults(tmp_path):
    sheet = load_run_sheet(write_sheet(tmp_path, HEAD + tensile()))
    assert [run.id for run in sheet.runs] == ["T1"]
    assert sheet.invalid_runs == []
    geometry = sheet.chains["c18"].si()
    # Paper 001 Table 1: 18x64 has d = 18, t = 64, R0 = 20, a = 42 mm.
    assert geometry["d"] == pytest.approx(0.018)
    assert geometry["R0"] == pytest.approx(0.020)
    assert geometry["mass_per_length"] == 6.6
    # 2.2e6 kgf/cm^2 = 2.2e6 * 9.80665 / 1e-4 Pa
    assert geometry["E_steel"] == pytest.approx(2.2e6 * 9.80665e4)


def test_run_sheet_values_override_catalogue(tmp_path):
    text = HEAD.replace('catalog = "18x64"', 'catalog = "18x64"\nmass_kg_per_m = 6.54')
    sheet = load_run_sheet(write_sheet(tmp_path, text + tensile()))
    assert sheet.chains["c18"].si()["mass_per_length"] == 6.54


@pytest.mark.parametrize(
    ("entry", "key", "words"),
    [
        (tensile(chain="c99"), "runs[1].chain", "unknown chain"),
        (tensile(id="T/2"), "runs[1].id", "pattern"),
        (tensile(id="T1"), "runs[1].id", "duplicate run id"),
        (tensile(file="../outside.csv"), "runs[1].file", "leaves the campaign"),
        (tensile(file="/etc/passwd"), "runs[1].file", "absolute path"),
        (tensile(id="T3", gauge="-1"), "runs[1].gauge_length_mm", "greater than 0"),
        (tensile(id="T3", gauge="0"), "runs[1].gauge_length_mm", "greater than 0"),
    ],
)
def test_bad_entry_is_isolated_and_named(tmp_path, entry, key, words):
    sheet = load_run_sheet(write_sheet(tmp_path, HEAD + tensile() + entry))
    assert [run.id for run in sheet.runs] == ["T1"]  # the good run survives
    (error,) = sheet.invalid_runs
    assert error.column == key
    assert words in str(error)
    assert str(sheet.path) in str(error)


def test_engagement_run_needs_one_speed(tmp_path):
    entry = """
[[runs]]
id = "E1"
kind = "engagement"
file = "e.csv"
chain = "c18"
wheel = "w8"
branch_length_m = 2
"""
    sheet = load_run_sheet(write_sheet(tmp_path, HEAD + entry))
    (error,) = sheet.invalid_runs
    assert "exactly one of omega_per_s or rpm" in str(error)
    ok = load_run_sheet(write_sheet(tmp_path, HEAD + entry + "rpm = 60\n"))
    assert ok.runs[0].omega == pytest.approx(2 * math.pi)  # 60 rpm = 2 pi rad/s


def test_unknown_wheel_and_catalogue(tmp_path):
    bad_catalog = HEAD.replace('catalog = "18x64"', 'catalog = "99x99"')
    with pytest.raises(RunSheetError, match=r"chains\.c18.*unknown chain '99x99'"):
        load_run_sheet(write_sheet(tmp_path, bad_catalog + tensile()))


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("[campaign\nid = 1", "not a valid TOML"),
        (HEAD.replace('id = "c-1"', 'id = "../evil"') + tensile(), "campaign.id"),
        (HEAD, "lists no runs"),
        (HEAD + tensile() + "[extra]\nx = 1\n", "unknown top-level"),
    ],
)
def test_sheet_level_faults_raise(tmp_path, text, words):
    with pytest.raises(RunSheetError, match=words.replace(".", r"\.")):
        load_run_sheet(write_sheet(tmp_path, text))


def test_missing_sheet(tmp_path):
    with pytest.raises(RunSheetError, match="campaign.toml"):
        load_run_sheet(tmp_path)


def test_resolve_inside_refuses_links_out(tmp_path):
    campaign = tmp_path / "campaign"
    campaign.mkdir()
    (campaign / "link.csv").symlink_to(tmp_path / "elsewhere.csv")
    with pytest.raises(ValueError, match="leaves"):
        resolve_inside(campaign, "link.csv")
    assert resolve_inside(campaign, "sub/../a.csv") == (campaign / "a.csv").resolve()


def test_sha256_is_of_the_bytes(tmp_path):
    import hashlib

    path = write_sheet(tmp_path, HEAD + tensile())
    assert load_run_sheet(path).sha256 == hashlib.sha256(path.read_bytes()).hexdigest()
