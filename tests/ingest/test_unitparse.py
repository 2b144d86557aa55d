"""Units found in files, converted with pint."""

import pytest

from pipeline.errors import UnitError
from pipeline.ingest.unitparse import looks_like_unit, si_factor, unit_role
from pipeline.units import STANDARD_GRAVITY


def factor(text, role):
    return si_factor(text, role, file="f.csv", row=1, column="c", source="the file")


@pytest.mark.parametrize(
    ("unit", "role", "expected"),
    [
        ("N", "force", 1.0), ("kN", "force", 1e3), ("daN", "force", 10.0),
        ("kgf", "force", STANDARD_GRAVITY), ("kG", "force", STANDARD_GRAVITY),
        ("tf", "force", 1e3 * STANDARD_GRAVITY), ("lbf", "force", 4.4482216152605),
        ("KN", "force", 1e3),
        ("mm", "gauge", 1e-3), ("µm", "gauge", 1e-6), ("μm", "gauge", 1e-6),
        ("um", "gauge", 1e-6), ("m", "gauge", 1.0), ("in", "gauge", 0.0254),
        ("s", "time", 1.0), ("sec", "time", 1.0), ("Sec", "time", 1.0),
        ("(sec)", "time", 1.0), ("ms", "time", 1e-3), ("min", "time", 60.0),
        ("deg", "angle", 0.017453292519943295), ("rad", "angle", 1.0),
        ("Min", "time", 60.0), ("MM", "gauge", 1e-3), ("SEC", "time", 1.0),
        ("seg", "time", 1.0), ("sek", "time", 1.0),  # Portuguese and Spanish; German, Polish
        # Russian (Cyrillic) symbols
        ("с", "time", 1.0), ("мс", "time", 1e-3), ("мин", "time", 60.0), ("ч", "time", 3600.0),
        ("Н", "force", 1.0), ("кН", "force", 1e3), ("кгс", "force", STANDARD_GRAVITY),
        ("мм", "gauge", 1e-3), ("мкм", "gauge", 1e-6), ("см", "gauge", 1e-2), ("м", "gauge", 1.0),
    ],
)
def test_si_factor(unit, role, expected):
    assert factor(unit, role) == pytest.approx(expected, rel=1e-12)


def test_unknown_unit_names_column_and_lists_units():
    with pytest.raises(UnitError, match="unknown unit 'Pfund'") as caught:
        factor("Pfund", "force")
    assert caught.value.column == "c" and "kN" in caught.value.hint


def test_wrong_dimension():
    with pytest.raises(UnitError, match="not a unit of force"):
        factor("mm", "force")


@pytest.mark.parametrize(
    ("unit", "role"),
    [("kN", "force"), ("mm", "gauge"), ("s", "time"), ("deg", "angle"), ("%", None),
     ("mm/s", None), ("", None), (None, None), ("hello world", None)],
)
def test_unit_role(unit, role):
    assert unit_role(unit) == role


@pytest.mark.parametrize(
    "unit",
    [
        "A", "mA", "Ah",  # pint reads "a" as a year: a current is not a time
        "Pa", "kPa",  # nor is a stress ("pa" would be a pico-year)
        "Nm",  # a torque is not a gauge ("nm" would be)
        "Nm/deg", "Nm/rad",  # nor is a torsional stiffness (a flex tester's, "nm/deg")
        "Ns", "kNs",  # nor is an impulse ("ns" would be a time)
        "pcs", "PC", "AU",  # parsecs and astronomical units: no machine measures in them
        "rpm", "lx",  # a rotation speed or an illuminance is not an angle
        "Mm", "Ms",  # megametres and megaseconds: refused rather than read a million-fold
    ],
)
def test_units_a_lab_means_otherwise_give_no_role(unit):
    assert unit_role(unit) is None


def test_a_current_in_amperes_is_not_a_time_candidate():
    from pipeline.ingest.roles import find_candidates

    # a thrust stand's export: "Time (s)", ..., "Thrust (kgf)", "Current (A)"
    found = find_candidates(["Time", "Thrust", "Current"], ["s", "kgf", "A"], None,
                            file="f.csv", header_line=1)
    assert found.roles == {"time": [0], "force": [1]}


@pytest.mark.parametrize("cell", ["(sec)", "[mm]", "Sec", "kgf", "cycles", "segments", "", "seg"])
def test_units_row_cells(cell):
    assert looks_like_unit(cell)


@pytest.mark.parametrize("cell", ["Extension", "Segment ID", "Total Cycle Count"])
def test_names_are_not_units(cell):
    assert not looks_like_unit(cell)
