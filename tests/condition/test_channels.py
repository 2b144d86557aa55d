"""Tests of pipeline.condition.channels: strain columns worked out from a length channel,
length columns that repeat another, the channels E0 is taken from."""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.condition.channels import choose_channels, find_copies, find_duplicates
from pipeline.simulate.pull import PullTruth, simulate_pull

#: The gauge length a Bluehill method divides the crosshead's extension by [m].
METHOD_GAUGE_LENGTH = 0.05


def extension_and_strain(seed: int) -> tuple[np.ndarray, np.ndarray]:
    """A crosshead's extension as Bluehill prints it (5 decimals of a mm) [m], and its
    ``Tensile strain``: that extension over 50 mm, printed to 5 decimals [1]."""
    rng = np.random.default_rng(seed)
    extension_mm = np.round(np.linspace(0.0, 2.0, 400) + rng.normal(0.0, 2e-3, 400), 5)
    return extension_mm * 1e-3, np.round(extension_mm / 50.0, 5)


@pytest.mark.parametrize("seed", range(5))
def test_a_strain_printed_from_a_length_channel_is_found_its_copy(seed):
    extension, strain = extension_and_strain(seed)
    copies = find_copies({"gauge_1": extension, "strain_1": strain})
    assert list(copies) == ["strain_1"]
    source, length, logarithmic = copies["strain_1"]
    assert (source, logarithmic) == ("gauge_1", False)
    assert length == pytest.approx(METHOD_GAUGE_LENGTH, rel=1e-4)


def test_a_copys_own_zero_and_sign_do_not_matter():
    extension, _ = extension_and_strain(0)
    strain = np.round(-(extension - extension[100]) / METHOD_GAUGE_LENGTH, 6)
    source, length, _ = find_copies({"gauge_1": extension, "strain_1": strain})["strain_1"]
    assert (source, length) == ("gauge_1", pytest.approx(METHOD_GAUGE_LENGTH, rel=1e-4))


def test_a_copy_kept_at_full_precision_is_found():
    extension, _ = extension_and_strain(1)
    extension = extension + 1e-9 * np.sqrt(np.arange(extension.size))  # no decimal grid
    copies = find_copies({"gauge_1": extension, "strain_1": extension / 0.08})
    assert copies["strain_1"] == ("gauge_1", pytest.approx(0.08, rel=1e-9), False)


def test_missing_readings_are_left_out_of_the_comparison():
    extension, strain = extension_and_strain(2)
    strain[300:] = np.nan  # taken off
    assert find_copies({"gauge_1": extension, "strain_1": strain})["strain_1"][0] == "gauge_1"


def test_a_strain_off_its_length_channel_by_three_printed_digits_once_is_no_copy():
    extension, strain = extension_and_strain(3)
    strain[200] += 3e-5
    assert find_copies({"gauge_1": extension, "strain_1": strain}) == {}


def test_too_few_samples_in_common_make_no_copy():
    extension, strain = extension_and_strain(4)
    assert find_copies({"gauge_1": extension[:19], "strain_1": strain[:19]}) == {}


@pytest.mark.parametrize("seed", range(5))
def test_an_extensometer_beside_the_crosshead_is_no_copy_of_it(seed):
    # two sensors on one pull: each reads its own noise, quantised to its own division
    truth = PullTruth.for_chain("18x64", strain_channel=True)
    log = simulate_pull(truth, seed)
    assert find_copies({"gauge_1": log["crosshead"].to_numpy(),
                        "strain_1": log["extensometer_strain"].to_numpy()}) == {}


@pytest.mark.parametrize("seed", range(5))
def test_a_true_strain_printed_from_a_length_channel_is_found_its_logarithmic_copy(seed):
    # ln(1 + extension / 50 mm), printed to 6 decimals: off any straight line through the
    # extension by far more than its rounding at 4 % strain
    extension, _ = extension_and_strain(seed)
    true_strain = np.round(np.log1p(extension / METHOD_GAUGE_LENGTH), 6)
    copy = find_copies({"gauge_1": extension, "strain_1": true_strain})["strain_1"]
    assert (copy.source, copy.logarithmic) == ("gauge_1", True)
    assert copy.length == pytest.approx(METHOD_GAUGE_LENGTH, rel=1e-4)


@pytest.mark.parametrize("seed", range(3))
def test_an_extensometers_true_strain_beside_the_crosshead_is_no_copy_of_it(seed):
    log = simulate_pull(PullTruth.for_chain("18x64", strain_channel=True), seed)
    true_strain = np.round(np.log1p(log["extensometer_strain"].to_numpy()), 8)
    assert find_copies({"gauge_1": log["crosshead"].to_numpy(), "strain_1": true_strain}) == {}


def test_two_length_channels_are_not_compared():
    extension, _ = extension_and_strain(5)
    assert find_copies({"gauge_1": extension, "gauge_2": 2 * extension}) == {}


def mts_testsuite_pull(seed: int) -> dict[str, np.ndarray]:
    """A simulated pull's crosshead and extensometer as MTS TestSuite prints them (to 1e-6
    mm) [m]."""
    log = simulate_pull(PullTruth.for_chain("18x64"), seed)
    return {name: np.round(log[name].to_numpy() * 1e3, 6) * 1e-3
            for name in ("crosshead", "extensometer")}


@pytest.mark.parametrize("seed", range(5))
def test_a_length_column_repeating_the_crosshead_is_the_crosshead_whatever_its_name(seed):
    crosshead = mts_testsuite_pull(seed)["crosshead"]
    readings = {"gauge_1": crosshead - 2e-5, "gauge_2": crosshead}  # 'Extension' zeroed later
    kinds = {"gauge_1": "gauge", "gauge_2": "crosshead"}
    assert find_duplicates(readings, kinds) == {"gauge_1": "gauge_2"}
    kinds = {"gauge_1": "extensometer", "gauge_2": "crosshead"}
    assert find_duplicates(readings, kinds) == {"gauge_1": "gauge_2"}


def test_a_repeat_with_the_other_sign_is_found_and_of_one_kind_the_first_is_the_source():
    crosshead = mts_testsuite_pull(0)["crosshead"]
    readings = {"gauge_1": crosshead, "gauge_2": -crosshead, "gauge_3": crosshead + 1e-6}
    assert find_duplicates(readings, {}) == {"gauge_2": "gauge_1", "gauge_3": "gauge_1"}


@pytest.mark.parametrize("seed", range(5))
def test_an_extensometer_beside_the_crosshead_repeats_nothing(seed):
    readings = mts_testsuite_pull(seed)
    pair = {"gauge_1": readings["crosshead"], "gauge_2": readings["extensometer"]}
    assert find_duplicates(pair, {"gauge_1": "crosshead", "gauge_2": "extensometer"}) == {}


def test_a_length_column_on_a_line_of_another_slope_is_no_repeat():
    # two LVDTs of one lever, or a unit slip: not the same readings
    crosshead = mts_testsuite_pull(1)["crosshead"]
    assert find_duplicates({"gauge_1": crosshead, "gauge_2": np.round(1.01 * crosshead, 9)},
                           {}) == {}


def test_strain_columns_are_not_compared_as_repeats():
    extension, _ = extension_and_strain(6)
    assert find_duplicates({"gauge_1": extension, "strain_1": extension.copy()}, {}) == {}


def test_of_three_transducers_the_two_that_agree_are_averaged():
    # a real MTS 793 modulus test's three transducers around a specimen (stiffnesses 1,
    # 0.991 and 0.762 of the stiffest): the stiffest alone was used, 12.6 % above the mean
    slopes = {"gauge_1": 1.0e8, "gauge_2": 0.991e8, "gauge_3": 0.762e8}
    kinds = dict.fromkeys(slopes, "gauge")
    columns = {"gauge_1": "1281068", "gauge_2": "1944 B", "gauge_3": "2157"}
    choice = choose_channels(slopes, kinds, columns)
    assert choice.used == ["gauge_1", "gauge_2"]
    assert choice.warnings == [
        "E0 from '1281068' (gauge) + '1944 B' (gauge), '2157' (gauge) not used (the gauge "
        f"channels' stiffnesses disagree beyond 20 %): its stiffness is {0.762 / 0.9955:.3g} x "
        "the mean of those used"]
    # two that disagree: the stiffer; all that agree: all of them
    assert choose_channels({"gauge_1": 1e8, "gauge_3": 0.7e8}, kinds, columns).used == ["gauge_1"]
    agreeing = {"gauge_1": 1e8, "gauge_2": 0.9e8, "gauge_3": 0.85e8}
    assert choose_channels(agreeing, kinds, columns).used == ["gauge_1", "gauge_2", "gauge_3"]
    # of two pairs that agree within themselves, the stiffer pair
    pairs = {"gauge_1": 1e8, "gauge_2": 0.9e8, "gauge_3": 0.6e8, "gauge_4": 0.55e8}
    kinds["gauge_4"], columns["gauge_4"] = "gauge", "Weg"
    assert choose_channels(pairs, kinds, columns).used == ["gauge_1", "gauge_2"]
