"""Units found in files, converted with pint."""

import numpy as np
import pytest

from pipeline.errors import UnitError
from pipeline.ingest.unitparse import looks_like_unit, si_factor, spellings, unit_role
from pipeline.units import STANDARD_GRAVITY, ureg


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
        ("rev", "angle", 2 * 3.141592653589793),  # a rotary stage's revolutions
        ("Min", "time", 60.0), ("MM", "gauge", 1e-3), ("SEC", "time", 1.0),
        ("seg", "time", 1.0), ("sek", "time", 1.0),  # Portuguese and Spanish; German, Polish
        ("Milliseconds since 1970-01-01", "time", 1e-3),  # a logger's stamps from an epoch
        # a mass in a force column is its weight (texture analysers, tribometers: "g")
        ("g", "force", 1e-3 * STANDARD_GRAVITY), ("kg", "force", STANDARD_GRAVITY),
        ("lb", "force", 4.4482216152605), ("oz", "force", 4.4482216152605 / 16),
        # Russian (Cyrillic) symbols
        ("с", "time", 1.0), ("мс", "time", 1e-3), ("мин", "time", 60.0), ("ч", "time", 3600.0),
        ("Н", "force", 1.0), ("кН", "force", 1e3), ("кгс", "force", STANDARD_GRAVITY),
        ("сек", "time", 1.0), ("мН", "force", 1e-3), ("даН", "force", 10.0),
        ("гс", "force", 1e-3 * STANDARD_GRAVITY), ("тс", "force", 1e3 * STANDARD_GRAVITY),
        ("мм", "gauge", 1e-3), ("мкм", "gauge", 1e-6), ("см", "gauge", 1e-2), ("м", "gauge", 1.0),
        # Chinese unit names
        ("秒", "time", 1.0), ("毫秒", "time", 1e-3), ("千牛", "force", 1e3), ("牛", "force", 1.0),
        ("毫米", "gauge", 1e-3), ("微米", "gauge", 1e-6),
        # Japanese and Korean units of time
        ("ミリ秒", "time", 1e-3), ("分", "time", 60.0), ("초", "time", 1.0),
        ("밀리초", "time", 1e-3), ("분", "time", 60.0),
        # a fibre tester's gram-force
        ("gmf", "force", 1e-3 * STANDARD_GRAVITY), ("gf", "force", 1e-3 * STANDARD_GRAVITY),
        # the force of a weight written out (a switch tester's gram-force)
        ("gram-force", "force", 1e-3 * STANDARD_GRAVITY), ("pound force", "force", 4.4482216152605),
        ("kilogram-force", "force", STANDARD_GRAVITY),
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
     ("mm/s", None), ("", None), (None, None), ("hello world", None),
     # a counter's cycles, not revolutions as pint reads them; an MTS station's segments
     ("cycles", "cycle_count"), ("Cycles", "cycle_count"), ("segments", "cycle_count"),
     ("rev", "angle"), ("counts", None)],
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
        "g", "kg", "lb",  # a mass makes a force only in a column named as one
        "km", "mi",  # a distance run (a wear rig's odometer) is no gauge
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


@pytest.mark.parametrize("cell", ["(sec)", "[mm]", "Sec", "kgf", "cycles", "segments", "", "seg",
                                  "VDC", "VAC"])  # a Keysight logger's volts
def test_units_row_cells(cell):
    assert looks_like_unit(cell)


@pytest.mark.parametrize("cell", ["Extension", "Segment ID", "Total Cycle Count"])
def test_names_are_not_units(cell):
    assert not looks_like_unit(cell)


def test_a_texture_analysers_force_in_grams_is_read_as_gram_force_with_a_warning():
    from pipeline.ingest import parse_table

    # Stable Micro Systems Exponent's export: a label row, names, units, a blank line
    text = ("gel_1\tgel_1\tgel_1\t\nForce\tDistance\tTime\t\ng\tmm\tsec\t\n\n"
            "0.0862526\t0\t0\t\n0.0988749\t0\t0.005\t\n12.5\t0.01\t0.010\t\n")
    table, metadata = parse_table(text.encode(), name="gel.tab")
    assert table["force"].tolist() == pytest.approx(
        [v * 1e-3 * STANDARD_GRAVITY for v in (0.0862526, 0.0988749, 12.5)], rel=1e-12)
    assert any("unit 'g' is a mass" in warning for warning in metadata.warnings)


@pytest.mark.parametrize("unit", ["deg", "°", "rad", "rev"])
def test_an_angle_is_no_strain(unit):
    from pipeline.ingest.unitparse import is_strain_unit

    # pint's angles are dimensionless, as ratios are: a rotary position is not a strain
    assert not is_strain_unit(unit) and is_strain_unit("%")


@pytest.mark.parametrize(("unit", "newton_metres"), [("N-m", 1.0), ("lbf-in", 0.112984829)])
def test_a_product_of_units_written_with_a_hyphen_is_read(unit, newton_metres):
    # a rheometer's units row (Pa-s, N-m) was taken for the names, pint reading none of it
    assert ureg.Quantity(1, spellings(unit)[0]).to("N*m").magnitude == pytest.approx(
        newton_metres)
    assert spellings("Load-cell") == []


@pytest.mark.parametrize("unit", ["psig", "psia", "psid", "barg", "bar(g)", "[bar (a)]",
                                  "kgf/cm2", "N/mm2", "lb/in2", "Mpa"])
def test_a_pressure_however_written_is_no_force(unit):
    from pipeline.ingest.unitparse import unit_misfits

    # a burst rig's or a hydraulic bench's pressure: pint read none of these, and a
    # unit it cannot read does not misfit, so a 'Load [psig]' became the force
    pressure = ureg.parse_units(spellings(unit)[0]) * (ureg.gravity if "lb" in unit else 1)
    assert pressure.dimensionality == ureg.pascal.dimensionality
    assert unit_misfits(unit, "force")


def test_a_channel_and_its_number_is_no_unit():
    # Bluehill's 'Tensile strain (Strain 1)' names the channel it was worked from; pint read
    # 'strain 1' as a ratio, and a strain in % a hundred times too large
    assert spellings("Strain 1") == [] and spellings("(AVE 2)") == []


def test_a_percent_after_a_scripts_name_is_a_percent():
    # a script's 'strain_pct': pint alone reads a picocarat, a mass
    from pipeline.ingest.unitparse import is_strain_unit

    assert is_strain_unit("pct") and ureg.Quantity(5, "pct").to("").magnitude == 0.05


def test_a_range_of_numbers_is_no_millionth():
    assert spellings("10-6") == [] and spellings("x10^-3") == []


def test_a_unit_squared_without_its_caret_is_read():
    assert ureg.Quantity(1, spellings("kgf/cm2")[0]).to("Pa").magnitude == pytest.approx(
        98066.5)
    assert spellings("CH1") == [] and spellings("Weg 2") == []
    assert spellings("a2") == []  # a label (a tensile specimen's width a2), no are squared


@pytest.mark.parametrize("unit", ["ue", "uE", "µe", "(με)", "µε", "×10^-6", "x10-6", "1e-6",
                                  "10⁻⁶", "(x10^-6)"])
def test_microstrain_in_plain_letters_is_a_strain_of_a_millionth(unit):
    from pipeline.ingest.unitparse import is_strain_unit, si_factor

    # strain-gauge amplifiers write microstrain so; pint alone reads a micro elementary charge
    assert is_strain_unit(unit) and si_factor(
        unit, "strain", file="f.csv", row=1, column="SG1", source="file") == pytest.approx(1e-6)


@pytest.mark.parametrize("unit", ["mV/V", "µV/V", "V/V", "[mV/V]"])
def test_a_bridge_output_is_no_strain(unit):
    from pipeline.ingest.unitparse import is_strain_unit

    # pint reads mV/V as a ratio (1e-3), but it is a strain gauge amplifier's raw signal:
    # about 2000 µm/m per mV/V of a quarter bridge, 500 of a full one
    assert not is_strain_unit(unit) and is_strain_unit("µm/m")


def test_a_strain_channel_in_mv_per_v_is_not_read_as_a_strain():
    from pipeline.ingest import parse_table

    # an HBM catman export of a strain gauge's bridge signal beside the force
    text = b"Time [s]\tForce [kN]\tStrain 1 [mV/V]\n0\t0\t0\n0.1\t1\t-0.00011\n0.2\t2\t-0.0002\n"
    table, metadata = parse_table(text, kind="engagement", name="catman.asc")
    assert "gauge_1" not in table and "strain_1" not in table
    assert any("'mV/V' is not a unit of gauge" in warning for warning in metadata.warnings)


def test_a_position_in_degrees_is_an_angle_not_a_strain():
    from pipeline.ingest import parse_table

    # a chain wheel's encoder beside the crosshead: pint reads both deg and mm/mm as ratios
    text = ("Time (s),Force (N),Encoder Position (deg),Stroke (mm)\n0,1,2,3\n0.1,1,2.5,3.1\n"
            "0.2,1,3,3.2\n")
    table, _ = parse_table(text.encode(), name="rotary.csv", kind="engagement")
    assert "strain_1" not in table and table["gauge_1"].tolist() == pytest.approx(
        [3e-3, 3.1e-3, 3.2e-3])
    assert table["angle"].tolist() == pytest.approx(np.radians([2.0, 2.5, 3.0]).tolist())


def test_a_sensors_signal_named_as_the_force_is_told_as_such():
    # a real catman export's 'Kraft [mV/V]' named as the force: the hint said to correct
    # the unit, and a technician who wrote kN read the bridge's output as kilonewtons
    with pytest.raises(UnitError, match="'mV/V' in the file is not a unit of force") as caught:
        factor("mV/V", "force")
    assert caught.value.hint.startswith("'mV/V' is a sensor's signal: convert the column to a "
                                        "force with the sensor's calibration first")
