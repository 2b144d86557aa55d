"""Run-sheet validation: typed errors naming file and key path; bad entries isolated."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from pipeline.errors import RunSheetError
from pipeline.runsheet import RunSheet, load_run_sheet, resolve_inside

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


@pytest.mark.posix_only  # making a link needs rights Windows users seldom have
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


def test_unknown_catalogue_invalidates_the_runs_of_its_chain(tmp_path):
    bad_catalog = HEAD.replace('catalog = "18x64"', 'catalog = "99x99"')
    sheet = load_run_sheet(write_sheet(tmp_path, bad_catalog + tensile()))
    assert sheet.runs == [] and sheet.chains == {}
    assert sheet.invalid_chains["c18"].column == "chains.c18"
    assert "unknown chain '99x99'" in sheet.invalid_chains["c18"].message
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].chain"
    assert error.message.startswith("run 'T1' uses chain 'c18', which is invalid: chains.c18: ")


TWO_CHAINS = HEAD + """
[chains.c22]
catalog = "22x86"
"""


def two_chain_sheet(tmp_path: Path, lines: str) -> RunSheet:
    """Runs T1 on chain c18 (with `lines` added to it) and T2 on chain c22."""
    text = TWO_CHAINS.replace('catalog = "18x64"', 'catalog = "18x64"\n' + lines)
    return load_run_sheet(write_sheet(tmp_path, text + tensile() + tensile("T2", chain="c22")))


@pytest.mark.parametrize(
    ("lines", "key", "words"),
    [
        # 18x64: d = 18, t = 64, R0 = 20, a = 42 mm (t = a + 2 R0 - d exactly)
        ("t_mm = 1e-9", "t_mm", "inner length t = 1e-09 mm is not above 2 d = 36 mm"),
        ("t_mm = 36", "t_mm", "inner length t = 36 mm is not above 2 d = 36 mm"),
        ("d_mm = 40", "d_mm", "inner length t = 64 mm is not above 2 d = 80 mm"),
        ("R0_mm = 9", "R0_mm", "inner width 2 R0 - d = 0 mm is not above d = 18 mm"),
        ("R0_mm = 18", "R0_mm", "inner width 2 R0 - d = 18 mm is not above d = 18 mm"),
        # a + 2 R0 - d = 31 + 40 - 18 = 53 mm against t = 64: 11 / 64 = 17.2 % of t
        ("a_mm = 31", "a_mm", "t = 64 mm but a + 2 R0 - d = 53 mm, 17.2% of t apart"),
        # 42 + 40 - 18 = 64 mm against t = 72: 11.1 % of t
        ("t_mm = 72", "t_mm", "t = 72 mm but a + 2 R0 - d = 64 mm, 11.1% of t apart"),
    ],
)
def test_chain_that_cannot_exist_invalidates_its_runs_only(tmp_path, lines, key, words):
    sheet = two_chain_sheet(tmp_path, lines)
    assert [run.id for run in sheet.runs] == ["T2"]
    assert list(sheet.chains) == ["c22"]
    fault = sheet.invalid_chains["c18"]
    assert fault.column == f"chains.c18.{key}"
    assert words in fault.message
    assert str(sheet.path) in str(fault)
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].chain"  # the campaign labels the failure runs[0]
    assert error.message.startswith(
        f"run 'T1' uses chain 'c18', which is invalid: chains.c18.{key}: the link cannot exist")
    assert words in error.message
    assert error.hint.startswith("fix [chains.c18]: check ")


@pytest.mark.parametrize(
    "lines",
    [
        "",  # the catalogue row is consistent
        "t_mm = 70",  # 64 mm against 70: 8.6 % of t, within 10 %
        "R0_mm = 18.01",  # inner width 18.02 mm, just above d
    ],
)
def test_chain_geometry_within_limits_is_valid(tmp_path, lines):
    sheet = two_chain_sheet(tmp_path, lines)
    assert [run.id for run in sheet.runs] == ["T1", "T2"]
    assert sheet.invalid_runs == [] and sheet.invalid_chains == {}


def test_published_22x86_row_is_valid(tmp_path):
    """Its t = 86 mm against a + 2 R0 - d = 84 mm (2.3 % of t) is a warning of the theory."""
    sheet = two_chain_sheet(tmp_path, "")
    assert sheet.invalid_chains == {}
    assert [run.id for run in sheet.runs] == ["T1", "T2"]
    values = sheet.chains["c22"].si()
    assert values["t"] == pytest.approx(0.086)
    assert values["a"] + 2 * values["R0"] - values["d"] == pytest.approx(0.084)


def test_only_known_geometry_is_checked(tmp_path):
    chain = """
[chains.bare]
d_mm = 18
t_mm = 64

[chains.roller]
catalog = "16B"
"""
    text = HEAD + chain + tensile(chain="bare") + tensile("T2", chain="roller")
    sheet = load_run_sheet(write_sheet(tmp_path, text))
    assert [run.id for run in sheet.runs] == ["T1", "T2"]
    assert sheet.invalid_chains == {}
    assert sheet.chains["bare"].si()["R0"] is None
    assert sheet.chains["roller"].si()["d"] is None


def test_unused_invalid_chain_is_listed(tmp_path):
    text = TWO_CHAINS.replace('catalog = "22x86"', 'catalog = "22x86"\nt_mm = 30')
    sheet = load_run_sheet(write_sheet(tmp_path, text + tensile()))
    assert [run.id for run in sheet.runs] == ["T1"]
    assert sheet.invalid_runs == []
    assert list(sheet.invalid_chains) == ["c22"]
    assert sheet.invalid_chains["c22"].column == "chains.c22.t_mm"


ENGAGEMENT = """
[[runs]]
id = "{id}"
kind = "engagement"
file = "{id}.csv"
chain = "c18"
wheel = "{wheel}"
branch_length_m = 2
rpm = 60
"""


def test_invalid_wheel_invalidates_its_runs_only(tmp_path):
    wheels = HEAD + "\n[wheels.w2]\nteeth = 2\napex_angle_deg = 40\n"
    text = (wheels + ENGAGEMENT.format(id="E1", wheel="w2") + ENGAGEMENT.format(id="E2", wheel="w8")
            + tensile())
    sheet = load_run_sheet(write_sheet(tmp_path, text))
    assert [run.id for run in sheet.runs] == ["E2", "T1"]
    assert list(sheet.wheels) == ["w8"]
    assert sheet.invalid_wheels["w2"].column == "wheels.w2.teeth"
    (error,) = sheet.invalid_runs
    assert error.column == "runs[0].wheel"
    assert error.message == ("run 'E1' uses wheel 'w2', which is invalid: wheels.w2.teeth: "
                             "Input should be greater than or equal to 3")


@pytest.mark.parametrize("name", ["chains", "wheels"])
def test_definitions_must_be_tables(tmp_path, name):
    text = f'{name} = 5\n[campaign]\nid = "c-1"\n' + tensile()
    with pytest.raises(RunSheetError) as caught:
        load_run_sheet(write_sheet(tmp_path, text))
    assert caught.value.column == name
    assert caught.value.message == f"expected a table of [{name}.<key>] tables, got the number 5"


@pytest.mark.parametrize(
    ("run_id", "message"),
    [
        ("summary", "'summary' names a campaign output (summary.nc, summary.csv)"),
        ("Report", "'Report' names a campaign output (report.html)"),
        ("specimens", "'specimens' names a campaign output (specimens.csv)"),
        ("impact_summary", "'impact_summary' names a campaign output (impact_summary.csv)"),
        ("CON", "'CON' is a device name Windows refuses as a file name"),
        ("nul.1", "'nul.1' is a device name Windows refuses as a file name"),
        ("pull.", "'pull.' ends in '.', which Windows drops from file names"),
    ],
)
def test_reserved_run_id_is_refused(tmp_path, run_id, message):
    sheet = load_run_sheet(write_sheet(tmp_path, HEAD + tensile() + tensile(run_id)))
    assert [run.id for run in sheet.runs] == ["T1"]
    (error,) = sheet.invalid_runs
    assert error.column == "runs[1].id"
    assert error.message == message
    assert error.hint.startswith("choose another id")


def test_run_ids_differing_only_in_case_are_duplicates(tmp_path):
    text = HEAD + tensile("Pull1") + tensile("pull1") + tensile("pull2")
    sheet = load_run_sheet(write_sheet(tmp_path, text))
    assert [run.id for run in sheet.runs] == ["Pull1", "pull2"]
    (error,) = sheet.invalid_runs
    assert error.column == "runs[1].id"
    assert error.message == ("duplicate run id 'pull1': it differs from 'Pull1' only in letter "
                             "case, which Windows and macOS file systems ignore")
    assert error.hint == "every run needs its own id: it names the output file"


def test_accept_implausible_and_machine_capacity(tmp_path):
    sheet = load_run_sheet(write_sheet(tmp_path, HEAD + tensile()))
    assert sheet.campaign.machine_capacity_kN is None
    assert sheet.runs[0].accept_implausible is False
    text = (HEAD.replace('title = "test campaign"', "machine_capacity_kN = 250")
            + tensile() + "accept_implausible = true\n")
    sheet = load_run_sheet(write_sheet(tmp_path, text))
    assert sheet.campaign.machine_capacity_kN == 250.0
    assert sheet.runs[0].accept_implausible is True


def test_machine_capacity_must_be_positive(tmp_path):
    text = HEAD.replace('title = "test campaign"', "machine_capacity_kN = 0") + tensile()
    with pytest.raises(RunSheetError, match="greater than 0") as caught:
        load_run_sheet(write_sheet(tmp_path, text))
    assert caught.value.column == "campaign.machine_capacity_kN"


@pytest.mark.parametrize("campaign_id", ["CON", "aux", "lpt1", "demo."])
def test_campaign_id_that_cannot_name_a_folder_on_windows_is_refused(tmp_path, campaign_id):
    text = HEAD.replace('id = "c-1"', f'id = "{campaign_id}"', 1) + tensile()
    with pytest.raises(RunSheetError, match="names the campaign's output folder") as caught:
        load_run_sheet(write_sheet(tmp_path, text))
    assert caught.value.column == "campaign.id"
