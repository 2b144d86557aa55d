"""Wear runs in the run sheet: the keys a wear run needs, named in clear errors."""

from __future__ import annotations

from pathlib import Path

import pytest

from pipeline.runsheet import load_run_sheet
from pipeline.units import to_si

HEAD = """
[campaign]
id = "wear-sheet"

[chains.c16B]
catalog = "16B"

[chains.c12B]
catalog = "12B"

[chains.plain]
t_mm = 19.05
"""

WEAR = """
[[runs]]
id = "W1"
kind = "wear"
file = "W1.csv"
chain = "c16B"
section_pitches = 10
elongation_reference = "nominal"
sprocket_teeth = 40
"""

PIN = """max_link_force_kN = 12
pin_allowable_stress_MPa = 800
pin_wear_coefficient = 1
"""


def errors(folder: Path, text: str) -> list[str]:
    (folder / "campaign.toml").write_text(HEAD + text, encoding="utf-8")
    return [str(error) for error in load_run_sheet(folder).invalid_runs]


def test_a_full_wear_run_is_valid_with_the_catalogue_pin(tmp_path):
    (tmp_path / "campaign.toml").write_text(HEAD + WEAR + PIN + 'pin_support = "clamped"\n'
                                            "wear_limit_pct = 1.5\n", encoding="utf-8")
    sheet = load_run_sheet(tmp_path)
    assert not sheet.invalid_runs
    run = sheet.runs[0]
    assert run.pin_criterion and run.pin_support == "clamped" and run.wear_model == "auto"
    chain = sheet.chains["c16B"].si()
    # 16B of the catalogue: ISO 606 pitch and pin, bush and plates of the hand-worked example
    assert chain["t"] == pytest.approx(to_si(25.4, "mm"))
    assert chain["pin_diameter"] == pytest.approx(to_si(8.28, "mm"))
    assert chain["bush_length"] == pytest.approx(to_si(25.45, "mm"))
    assert chain["plate_span"] == pytest.approx(to_si(29.78, "mm"))


@pytest.mark.parametrize("key", ["section_pitches", "elongation_reference", "sprocket_teeth"])
def test_a_wear_run_without_a_required_key_is_refused_by_name(tmp_path, key):
    text = "\n".join(line for line in WEAR.splitlines() if not line.startswith(key))
    found = errors(tmp_path, text + "\n")
    assert len(found) == 1 and f"a wear run needs {key}" in found[0]
    assert "runs[0]" in found[0]


@pytest.mark.parametrize("line, words", [
    ('elongation_reference = "last"', "elongation_reference"),
    ("sprocket_teeth = 500", "sprocket_teeth"),
    ('section_pitches = "10"', "without quotes"),
    ("wear_limit_pct = -3", "wear_limit_pct"),
    ('wear_model = "cubic"', "wear_model"),
    ("gauge_length = 3", "gauge_length"),  # an unknown key
])
def test_bad_wear_keys_are_named(tmp_path, line, words):
    key = line.split(" = ")[0]
    text = "\n".join(each for each in WEAR.splitlines() if not each.startswith(key))
    found = errors(tmp_path, text + "\n" + line + "\n")
    assert len(found) == 1 and words in found[0], found


def test_the_pin_criterion_takes_all_its_keys_or_none(tmp_path):
    found = errors(tmp_path, WEAR + "max_link_force_kN = 12\n")
    assert len(found) == 1
    assert "pin_allowable_stress_MPa" in found[0] and "pin_wear_coefficient" in found[0]


def test_the_pin_criterion_needs_the_chains_pin(tmp_path):
    # 12B of the catalogue has a pin diameter but no bush length and plate span
    found = errors(tmp_path, WEAR.replace('"c16B"', '"c12B"') + PIN)
    assert len(found) == 1
    assert "bush_length_mm, plate_span_mm" in found[0] and "runs[0].chain" in found[0]
    # without the pin criterion the pitch is enough
    assert not errors(tmp_path, WEAR.replace('"c16B"', '"c12B"'))


def test_a_wear_run_needs_the_chains_pitch(tmp_path):
    text = HEAD.replace("t_mm = 19.05", "mass_kg_per_m = 1.25") + WEAR.replace('"c16B"',
                                                                               '"plain"')
    (tmp_path / "campaign.toml").write_text(text, encoding="utf-8")
    found = [str(error) for error in load_run_sheet(tmp_path).invalid_runs]
    assert len(found) == 1 and "gives no t_mm" in found[0]


def test_a_bush_longer_than_twice_the_plate_span_is_refused(tmp_path):
    text = HEAD + "\n[chains.odd]\ncatalog = \"16B\"\nplate_span_mm = 12\n" + \
        WEAR.replace('"c16B"', '"odd"') + PIN
    (tmp_path / "campaign.toml").write_text(text, encoding="utf-8")
    found = [str(error) for error in load_run_sheet(tmp_path).invalid_runs]
    assert len(found) == 1 and "chains.odd.bush_length_mm" in found[0]
