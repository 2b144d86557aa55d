"""Wear logs to pitch elongation: hand-computed elongations, and every unfit log refused."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.condition.wear import condition_wear, wear_from_elongation, wear_from_length
from pipeline.errors import ChainbenchError, SignalError, UnitError

#: A 19.05 mm chain, a section of 10 pitches (190.5 mm nominal).
PITCH, PITCHES = 0.01905, 10
HOUR = 3600.0
TIME = np.array([0.0, 50.0, 100.0, 150.0]) * HOUR
#: Elongation per pitch of each reading [m]: 0.02, 0.05, 0.09, 0.12 mm.
GROWTH = np.array([0.02, 0.05, 0.09, 0.12]) * 1e-3
LENGTH = PITCHES * (PITCH + GROWTH)


def from_length(time=TIME, length=LENGTH, **options):
    return wear_from_length(time, length, **{"pitches": PITCHES, "pitch": PITCH,
                                             "reference": "nominal", **options})


def test_length_against_nominal_pitch():
    log = from_length()
    assert list(log.table.columns) == ["time", "elongation", "relative_elongation"]
    assert log.abscissa == "time" and log.reference == "nominal" and log.pitch == PITCH
    np.testing.assert_allclose(log.tau, TIME)
    np.testing.assert_allclose(log.elongation, GROWTH, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(log.table["relative_elongation"], GROWTH / PITCH, rtol=1e-9)


def test_length_against_first_reading():
    log = from_length(reference="first")
    assert log.reference == "first"
    np.testing.assert_allclose(log.elongation, GROWTH - GROWTH[0], rtol=1e-9, atol=1e-15)


def test_elongation_given_directly_over_cycles():
    cycles = pd.Series([0, 2e5, 4e5, 6e5], index=[10, 11, 12, 13])
    section = pd.Series(PITCHES * GROWTH, index=cycles.index)
    nominal = wear_from_elongation(cycles, section, pitches=PITCHES, pitch=PITCH,
                                   reference="nominal", abscissa="cycles")
    assert list(nominal.table.columns) == ["cycles", "elongation", "relative_elongation"]
    np.testing.assert_allclose(nominal.tau, cycles.to_numpy())
    np.testing.assert_allclose(nominal.elongation, GROWTH, rtol=1e-12)
    first = wear_from_elongation(cycles, section, pitches=PITCHES, pitch=PITCH,
                                 reference="first", abscissa="cycles")
    np.testing.assert_allclose(first.elongation, GROWTH - GROWTH[0], rtol=1e-12, atol=1e-18)


def test_a_gauge_read_from_its_first_reading_may_stand_anywhere():
    # a real rig's stage position read as the gauge, -114.6 mm at the start: read from its
    # first reading the elongation is the steps from there; it was refused as making the
    # section 0.55 times its nominal length, the check made on the readings as they stand
    stage = -0.1146 + PITCHES * GROWTH
    log = wear_from_elongation(TIME, stage, pitches=PITCHES, pitch=PITCH, reference="first")
    np.testing.assert_allclose(log.elongation, GROWTH - GROWTH[0], rtol=1e-9, atol=1e-15)
    # against the nominal section the stand is an elongation: that is refused
    raises(UnitError, wear_from_elongation, TIME, stage, pitches=PITCHES, pitch=PITCH,
           reference="nominal")


def test_one_pitch_elongation():
    log = wear_from_elongation(TIME, GROWTH, pitches=1, pitch=PITCH, reference="nominal")
    np.testing.assert_allclose(log.elongation, GROWTH)


def test_a_worn_chain_up_to_the_jump_off_of_a_small_sprocket_is_accepted():
    # Paper 004, eq. (3) for z = 9: t (2/9 - 0.004) = 0.218 t
    growth = np.array([0.0, 0.1, 0.218]) * PITCH
    log = from_length(TIME[:3], PITCHES * (PITCH + growth))
    np.testing.assert_allclose(log.table["relative_elongation"], [0.0, 0.1, 0.218], atol=1e-12)


def raises(error: type[ChainbenchError], call, *args, **kwargs) -> ChainbenchError:
    with pytest.raises(error) as caught:
        call(*args, **kwargs)
    assert caught.value.hint, "every refusal says what to do"
    return caught.value


def test_time_going_backwards_is_refused():
    error = raises(SignalError, from_length, TIME[[0, 2, 1, 3]])
    assert error.column == "time" and "reading 2 to 3" in error.message and "sort" in error.hint


def test_repeated_time_is_refused():
    error = raises(SignalError, from_length, TIME[[0, 1, 1, 3]])
    assert error.column == "time" and "does not increase" in error.message


def test_time_before_the_start_is_refused():
    error = raises(SignalError, from_length, TIME - HOUR)
    assert error.column == "time" and "start" in error.hint


def test_too_few_readings_are_refused():
    error = raises(SignalError, from_length, TIME[:2], LENGTH[:2])
    assert "2 readings" in error.message and "3" in error.hint


@pytest.mark.parametrize("column", ["time", "length"])
@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_missing_readings_are_refused(column, bad):
    arrays = {"time": TIME.copy(), "length": LENGTH.copy()}
    arrays[column][2] = bad
    error = raises(SignalError, from_length, arrays["time"], arrays["length"])
    assert error.column == column and "reading 3 of 4" in error.message


def test_negative_length_is_refused():
    error = raises(UnitError, from_length, TIME, -LENGTH)
    assert error.column == "length" and "positive" in error.hint


@pytest.mark.parametrize(("unit", "factor"), [("mm", 1e3), ("um", 1e6), ("in", 1 / 0.0254)])
def test_length_in_another_unit_is_refused_naming_it(unit, factor):
    error = raises(UnitError, from_length, TIME, LENGTH * factor)
    assert f"{unit} given as m" in error.hint


def test_length_of_another_section_is_refused():
    # 15 pitches measured, 10 declared: 1.5 times N t
    error = raises(UnitError, from_length, TIME, LENGTH * 1.5)
    assert "number of pitches" in error.hint and "1.5" in error.message


def test_elongation_in_mm_is_refused():
    error = raises(UnitError, wear_from_elongation, TIME, PITCHES * GROWTH * 1e3,
                   pitches=PITCHES, pitch=PITCH, reference="nominal")
    assert error.column == "elongation"


@pytest.mark.parametrize("options", [
    {"reference": "start"}, {"pitches": 0}, {"pitches": 2.5}, {"pitch": -PITCH},
    {"pitch": np.nan}, {"abscissa": "hours"},
])
def test_bad_parameters_raise_value_error(options):
    with pytest.raises(ValueError):
        from_length(**options)


def test_readings_of_different_lengths_raise_value_error():
    with pytest.raises(ValueError, match="one length"):
        from_length(TIME, LENGTH[:3])


def canonical(**columns) -> pd.DataFrame:
    """A canonical wear table (the readers' names) of the readings above."""
    return pd.DataFrame({"time": TIME, "cycle_count": 0.5 * TIME, **columns})


def test_condition_wear_reads_the_length_over_the_running_time():
    log, notes = condition_wear(canonical(length=LENGTH), pitches=PITCHES, pitch=PITCH,
                                reference="nominal")
    assert log.abscissa == "time"
    np.testing.assert_allclose(log.elongation, GROWTH, rtol=1e-9, atol=1e-15)
    assert len(notes) == 1 and "both running time and cycles" in notes[0]


def test_condition_wear_over_cycles_when_asked():
    log, notes = condition_wear(canonical(length=LENGTH), pitches=PITCHES, pitch=PITCH,
                                reference="nominal", abscissa="cycles")
    assert log.abscissa == "cycles" and not notes
    np.testing.assert_allclose(log.tau, 0.5 * TIME)


def test_condition_wear_strain_is_a_share_of_the_nominal_section():
    # an elongation of 0.1 % of N t is N t / 1000, i.e. t / 1000 per pitch
    strain = np.array([0.0, 0.001, 0.002, 0.003])
    log, _ = condition_wear(pd.DataFrame({"time": TIME, "strain_1": strain}), pitches=PITCHES,
                            pitch=PITCH, reference="nominal")
    np.testing.assert_allclose(log.elongation, strain * PITCH, rtol=1e-12)


@pytest.mark.parametrize("columns, options, words", [
    ({"length": LENGTH, "gauge_1": PITCHES * GROWTH}, {}, "2 columns that could be"),
    ({"gauge_1": PITCHES * GROWTH, "gauge_2": PITCHES * GROWTH}, {}, "2 columns that could"),
    ({"length": LENGTH}, {"channel": "elongation"}, "no elongation column"),
    ({"length": LENGTH}, {"abscissa": "cycles"}, "no cycles column"),
])
def test_condition_wear_refuses_what_it_cannot_tell(columns, options, words):
    with pytest.raises(SignalError, match=words) as raised:
        condition_wear(pd.DataFrame({"time": TIME, **columns}), pitches=PITCHES, pitch=PITCH,
                       reference="nominal", **options)
    assert "run sheet" in raised.value.hint


def test_the_channels_that_could_be_the_readings_are_named_as_the_file_names_them():
    table = pd.DataFrame({"time": TIME, "gauge_1": PITCHES * GROWTH,
                          "gauge_2": PITCHES * GROWTH})
    with pytest.raises(SignalError) as raised:
        condition_wear(table, pitches=PITCHES, pitch=PITCH, reference="nominal",
                       columns={"gauge_1": "Piezo position", "gauge_2": "MEMS displ."})
    assert raised.value.message == ("the log holds 2 columns that could be the readings: "
                                    "'Piezo position', 'MEMS displ.'")
    assert raised.value.column == "Piezo position"


def test_condition_wear_takes_the_channel_named():
    table = pd.DataFrame({"time": TIME, "length": LENGTH, "gauge_1": 2 * PITCHES * GROWTH})
    log, _ = condition_wear(table, pitches=PITCHES, pitch=PITCH, reference="nominal",
                            channel="length")
    np.testing.assert_allclose(log.elongation, GROWTH, rtol=1e-9, atol=1e-15)
    log, _ = condition_wear(table, pitches=PITCHES, pitch=PITCH, reference="nominal",
                            channel="elongation")
    np.testing.assert_allclose(log.elongation, 2 * GROWTH, rtol=1e-12)


def test_a_length_read_as_an_elongation_is_refused_with_the_hint_to_name_it():
    with pytest.raises(UnitError) as raised:
        condition_wear(pd.DataFrame({"time": TIME, "gauge_1": LENGTH}), pitches=PITCHES,
                       pitch=PITCH, reference="nominal")
    assert "section's length" in raised.value.hint
