"""Plausibility checks: hand-computed unit slips are flagged and named, genuine values pass."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from hypothesis import given
from hypothesis import strategies as st

from pipeline.plausibility import (
    Flag,
    check_operating_points,
    check_specimens,
    consensus,
    excluded,
    flags_dataset,
    probable_slip,
)

KGF = 9.80665
NAN = float("nan")
THEORY = 1.0e7  # E0 of the chain [N]
BREAKING = 4.1e5  # minimum breaking force of the chain [N]
CAPACITY = 5.0e5  # the machine's capacity [N]


def specimen(E0=THEORY, max_force=1.2e5, at_max=0.004, at_fracture=NAN, chain="c18"):
    """A row as the campaign gives it: a stiffness test up to 30 % of the breaking force."""
    return {"chain": chain, "E0": E0, "max_force": max_force, "strain_at_max_force": at_max,
            "strain_at_fracture": at_fracture}


def check(rows, *, theory=THEORY, breaking=BREAKING, capacity=CAPACITY, accepted=()):
    return check_specimens(rows, E0_theory={"c18": theory}, breaking_force={"c18": breaking},
                           capacity=capacity, accepted=set(accepted))


def only(flags, against=None) -> Flag:
    found = [flag for flag in flags if against is None or flag.against == against]
    assert len(found) == 1, [flag.message for flag in flags]
    return found[0]


# --- probable_slip -------------------------------------------------------------------------

@pytest.mark.parametrize(("ratio", "quantity", "cause", "factor"), [
    (1000, "max_force", "a force in N labelled kN", "1000"),
    (1 / 1000, "max_force", "a force in kN labelled N", "1/1000"),
    (1050, "E0", "a force in N labelled kN", "1000"),  # 1000 on a genuine 5 % discrepancy
    (1000 * 0.95, "E0", "a force in N labelled kN", "1000"),
    (1 / 1000, "E0", "an elongation in mm labelled m", "1/1000"),
    (9.81, "max_force", "a force in N labelled kgf", "9.81"),
    (KGF, "E0", "a force in N labelled kgf", "9.81"),
    (1 / 9.81, "N_u1", "a force in kgf labelled N", "1/9.81"),
    (1 / KGF, "E0", "a force in kgf labelled N", "1/9.81"),
    (25.4, "E0", "an elongation in inches labelled mm", "25.4"),
    (1 / 25.4, "E0", "an elongation in mm labelled inches", "1/25.4"),
    (25.4, "strain_at_fracture", "an elongation in mm labelled inches", "25.4"),
    (100, "strain_at_max_force", "a strain in % read as a fraction", "100"),
    (1 / 100, "E0", "a strain in % read as a fraction", "1/100"),
    (1000 / KGF, "max_force", "a force in kgf labelled kN", "102"),
    (100, "max_force", "a force in kgf labelled kN", "102"),  # percent never applies to forces
    (1e6, "N_u2", "a force in N labelled MN", "1e+06"),
    (1e-6, "E0", "a strain in µm/m read as a fraction", "1/1e+06"),
])
def test_probable_slip_names_the_known_factor(ratio, quantity, cause, factor):
    slip = probable_slip(ratio, quantity)
    assert slip is not None and cause in slip, slip
    assert slip.endswith(f"(factor {factor})")


@pytest.mark.parametrize(("ratio", "quantity"), [
    (3.5, "E0"),  # no known factor near it
    (1.0, "E0"),
    (1.0, "max_force"),
    (4.5, "N_u1"),
    (25.4, "max_force"),  # inches never apply to forces
    (9.81, "strain_at_fracture"),  # nor kgf to strains
    (2.0, "max_force"),
    (-1000, "E0"),
    (0.0, "E0"),
    (NAN, "E0"),
    (math.inf, "E0"),
])
def test_probable_slip_names_nothing_where_no_known_factor_fits(ratio, quantity):
    assert probable_slip(ratio, quantity) is None


def test_the_windows_of_9_81_and_25_4_do_not_overlap():
    # The geometric middle between them, 15.8, is outside both windows (x/÷ 1.5).
    middle = math.sqrt(KGF * 25.4)
    assert probable_slip(middle, "E0") is None
    assert "kgf" in probable_slip(KGF * 1.45, "E0")
    assert "inches" in probable_slip(25.4 / 1.45, "E0")


def test_probable_slip_rejects_an_unknown_quantity():
    with pytest.raises(ValueError, match="unknown quantity 'torque'"):
        probable_slip(1000, "torque")


def test_a_wide_spread_names_the_commonest_slip_that_fits():
    # 500 x the breaking force: N read as kN on a proof test stopping at half of it.
    assert probable_slip(500, "max_force", spread=(0.1, 1.5)).endswith("(factor 1000)")
    assert probable_slip(500, "max_force") is None  # the default spread is too tight for it


# --- E0 against the theory -----------------------------------------------------------------

def test_E0_in_N_labelled_kN_is_flagged_against_theory():
    flag = only(check({"T1": specimen(E0=1.05e10)}))
    assert (flag.run_id, flag.quantity, flag.against) == ("T1", "E0", "theory")
    assert flag.value == 1.05e10 and flag.reference == THEORY
    assert flag.ratio == pytest.approx(1050)
    assert flag.slip.startswith("a force in N labelled kN")
    assert not flag.accepted
    assert flag.message == (
        "T1: E0 = 1.05e+07 kN is 1050 x the theory (10000 kN): probably a force in N labelled "
        "kN, or an elongation in mm labelled µm (or m labelled mm) (factor 1000). Check the "
        "units of the run's columns, or set accept_implausible = true on the run if the value "
        "is right.")


def test_E0_with_force_in_kgf_labelled_N_is_flagged_against_theory():
    flag = only(check({"T1": specimen(E0=1.02e7 / KGF, max_force=1.2e5 / KGF)}))
    assert flag.ratio == pytest.approx(0.10401, rel=1e-4)
    assert "a force in kgf labelled N" in flag.slip
    assert "is 1/9.61 of the theory (10000 kN)" in flag.message


def test_E0_with_elongation_in_mm_labelled_inches_is_flagged_against_theory():
    flag = only(check({"T1": specimen(E0=THEORY / 25.4, at_max=0.004 * 25.4)}))
    assert flag.ratio == pytest.approx(1 / 25.4)
    assert flag.slip.startswith("an elongation in mm labelled inches")


@pytest.mark.parametrize("ratio", [1.05, 0.95, 1 / 3, 3.0, 2.9, 0.4])
def test_E0_within_a_factor_3_of_theory_is_not_flagged(ratio):
    assert check({"T1": specimen(E0=THEORY * ratio)}) == []


def test_E0_3_5_times_theory_is_flagged_without_a_slip():
    flag = only(check({"T1": specimen(E0=3.5 * THEORY)}))
    assert flag.slip is None
    assert "no known unit slip explains the factor" in flag.message


def test_no_theory_means_no_check_against_it():
    rows = {"T1": specimen(E0=1.0e10)}
    assert check(rows, theory=None) == []
    assert check(rows, theory=NAN) == []


@given(st.floats(min_value=1 / 3, max_value=3.0))
def test_nothing_within_the_band_is_flagged_against_theory(ratio):
    assert check({"T1": specimen(E0=THEORY * ratio)}) == []
    points = pd.DataFrame({"N_u1_meas": [2.0e3 * ratio], "N_u1_theory": [2.0e3],
                           "N_u2_meas": [1.0e3 / ratio], "N_u2_theory": [1.0e3]}, index=["E1"])
    assert check_operating_points(points, accepted=()) == []


@given(st.sampled_from([100.0, 1000.0, KGF, 25.4, 1e6]), st.booleans(),
       st.floats(min_value=1 / 1.45, max_value=1.45))
def test_a_slip_on_a_genuine_discrepancy_is_named(factor, up, discrepancy):
    ratio = (factor if up else 1 / factor) * discrepancy
    flag = only(check({"T1": specimen(E0=THEORY * ratio, max_force=NAN)}))
    shown = f"{float(f'{factor:.3g}'):g}"
    assert flag.slip.endswith(f"(factor {shown if up else '1/' + shown})")


# --- max force against the breaking force and the machine ----------------------------------

@pytest.mark.parametrize("fraction", [1.3, 1.0, 0.5, 0.1, 0.02])
def test_a_genuine_max_force_is_not_flagged(fraction):
    # fracture 30 % above the minimum, proof test, stiffness tests up to 10 % and 2 %
    assert check({"T1": specimen(max_force=BREAKING * fraction)}, capacity=None) == []


def test_max_force_in_N_labelled_kN_on_a_proof_test_is_flagged():
    # A proof test to half the breaking force, 205 kN, read as 205 000 kN.
    flags = check({"T1": specimen(max_force=2.05e8)}, capacity=None)
    flag = only(flags, "breaking force")
    assert (flag.quantity, flag.value, flag.reference) == ("max_force", 2.05e8, BREAKING)
    assert flag.ratio == pytest.approx(500)
    assert flag.slip == "a force in N labelled kN (factor 1000)"
    assert "max force = 205000 kN is 500 x the chain's breaking force (410 kN)" in flag.message


def test_max_force_in_kN_labelled_N_is_flagged_below_the_breaking_force():
    flag = only(check({"T1": specimen(max_force=533.0)}), "breaking force")
    assert flag.ratio == pytest.approx(533 / 4.1e5)
    # a test may stop anywhere from 10 % of the breaking force: both slips fit, 1000 first
    assert flag.slip == ("a force in kN labelled N (factor 1/1000), or a force in kN labelled "
                         "kgf (factor 1/102)")
    assert "is 1/769 of the chain's breaking force" in flag.message


def test_max_force_in_N_labelled_kgf_is_flagged_above_the_breaking_force():
    flag = only(check({"T1": specimen(max_force=4.5e5 * KGF)}, capacity=None))
    assert flag.ratio == pytest.approx(4.5 * KGF / 4.1)
    assert flag.slip.startswith("a force in N labelled kgf (or kN labelled tf) (factor 9.81)")


def test_max_force_above_the_machines_capacity_is_flagged():
    flag = only(check({"T1": specimen(max_force=4.9e8)}, breaking=None))
    assert (flag.against, flag.reference) == ("machine capacity", CAPACITY)
    assert flag.ratio == pytest.approx(980)
    assert flag.slip == "a force in N labelled kN (factor 1000)"
    assert "is 980 x the machine's capacity (500 kN)" in flag.message


def test_an_overload_within_5_percent_of_capacity_is_not_flagged():
    assert check({"T1": specimen(max_force=1.04 * CAPACITY)}, breaking=None) == []
    assert only(check({"T1": specimen(max_force=1.06 * CAPACITY)}, breaking=None))


# --- strains -------------------------------------------------------------------------------

@pytest.mark.parametrize(("at_max", "at_fracture"), [(0.004, NAN), (0.22, 0.25), (0.5, 0.5)])
def test_genuine_strains_are_not_flagged(at_max, at_fracture):
    assert check({"T1": specimen(at_max=at_max, at_fracture=at_fracture)}) == []


def test_a_strain_in_percent_read_as_a_fraction_is_flagged():
    flag = only(check({"T1": specimen(at_max=0.21, at_fracture=24.0)}))
    assert (flag.quantity, flag.against, flag.value, flag.reference) == (
        "strain_at_fracture", "strain limit", 24.0, 0.5)
    assert flag.ratio == pytest.approx(48)
    # a genuine strain may lie anywhere from 0.05 to 50 %: both 100 and 1000 fit 2400 %
    assert flag.slip == ("a strain in % read as a fraction (factor 100), or an elongation in mm "
                         "labelled m (or µm labelled mm), or a gauge length in m written as mm "
                         "(factor 1000)")
    assert flag.message.startswith(
        "T1: strain at fracture = 2400 % is 48 x the strain limit (50 %): probably a strain "
        "in % read as a fraction (factor 100), or an elongation")


def test_a_strain_from_an_elongation_in_mm_labelled_m_is_flagged():
    flag = only(check({"T1": specimen(at_max=180.0)}))
    assert flag.quantity == "strain_at_max_force"
    assert flag.slip.startswith("an elongation in mm labelled m")
    assert flag.slip.endswith("(factor 1000)")


# --- E0 against the chain's other specimens ------------------------------------------------

def chain(*E0s, theory=None):
    rows = {f"T{i}": specimen(E0=E0) for i, E0 in enumerate(E0s, start=1)}
    return check(rows, theory=theory)


def test_a_realistic_specimen_scatter_is_not_flagged():
    assert chain(1.00e7, 1.03e7, 0.97e7, 1.05e7) == []
    assert chain(1.00e7, 1.6e7, 0.9e7) == []  # even 60 % apart stays inside [1/2, 2]


def test_a_specimen_1000_times_the_others_is_flagged():
    flag = only(chain(1.00e7, 1.03e7, 0.97e7, 1.01e10))
    assert (flag.run_id, flag.against) == ("T4", "the chain's other specimens")
    assert flag.reference == pytest.approx(1.00e7)  # median of 0.97, 1.00, 1.03 e7
    assert flag.ratio == pytest.approx(1010)
    assert flag.slip.startswith("a force in N labelled kN")
    assert "the median of the chain's other specimens (10000 kN)" in flag.message


def test_of_three_specimens_only_the_slipped_one_is_flagged():
    # The plain median of the two others of a good specimen would be their mean, 5e9.
    flag = only(chain(1.0e7, 1.02e7, 1.0e10))
    assert flag.run_id == "T3"
    assert flag.reference == pytest.approx(1.01e7)
    assert flag.ratio == pytest.approx(1.0e10 / 1.01e7)


def test_a_specimen_off_by_a_factor_2_5_is_flagged_without_a_slip():
    flag = only(chain(1.0e7, 1.0e7, 1.0e7, 2.5e7))
    assert flag.ratio == pytest.approx(2.5) and flag.slip is None


def test_two_specimens_are_not_judged_against_each_other():
    assert chain(1.0e7, 1.0e10) == []


def test_a_two_against_two_split_is_not_judged():
    assert consensus([1.0e7, 1.0e7, 1.0e10, 1.0e10]) is None
    assert chain(1.0e7, 1.0e7, 1.0e10, 1.0e10) == []


def test_a_slipped_majority_is_caught_by_theory_and_spares_the_good_specimen():
    flags = chain(1.0e7, 1.0e10, 1.02e10, theory=1.0e7)
    assert {(flag.run_id, flag.against) for flag in flags} == {("T2", "theory"),
                                                               ("T3", "theory")}
    assert excluded(flags) == {"T2", "T3"}


def test_specimens_of_other_chains_are_not_peers():
    rows = {"A1": specimen(E0=1.0e7, chain="a"), "A2": specimen(E0=1.0e7, chain="a"),
            "B1": specimen(E0=5.0e7, chain="b"), "A3": specimen(E0=1.0e7, chain="a")}
    assert check_specimens(rows, E0_theory={}, breaking_force={}, capacity=None,
                           accepted=()) == []


# --- accepted runs -------------------------------------------------------------------------

def test_an_accepted_run_is_flagged_but_not_excluded():
    flags = check({"T1": specimen(E0=1.05e10), "T2": specimen(max_force=2.05e8)},
                  accepted={"T1"})
    by_run = {flag.run_id: flag for flag in flags if flag.quantity in ("E0", "max_force")}
    assert by_run["T1"].accepted and not by_run["T2"].accepted
    assert by_run["T1"].message.endswith("Accepted: accept_implausible = true on the run.")
    assert "set accept_implausible = true" in by_run["T2"].message
    assert excluded(flags) == {"T2"}


def test_an_accepted_specimen_still_counts_as_a_peer():
    flags = check({"T1": specimen(E0=1.0e10), "T2": specimen(E0=1.01e10),
                   "T3": specimen(E0=1.0e7)}, accepted={"T1", "T2"})
    assert excluded(flags) == {"T3"}
    assert only(flags, "the chain's other specimens").run_id == "T3"


def test_nan_is_nothing_to_check():
    row = {"chain": "c18", "E0": NAN, "max_force": NAN, "strain_at_max_force": NAN,
           "strain_at_fracture": NAN}
    assert check({"T1": row, "T2": {"chain": "c18"}}) == []


# --- impact tensions -----------------------------------------------------------------------

def test_impact_tensions_against_the_model():
    points = pd.DataFrame(
        {"N_u1_meas": [2.3e3, 2.3e6, 2.3e3 / KGF, NAN],
         "N_u1_theory": [2.0e3, 2.0e3, 2.0e3, 2.0e3],
         "N_u2_meas": [1.1e3, 1.1e6, 1.1e3, 1.0e3],
         "N_u2_theory": [1.0e3, 1.0e3, 1.0e3, NAN]},
        index=["E-ok", "E-kN", "E-kgf", "E-nan"])
    flags = check_operating_points(points, accepted={"E-kgf"})
    assert [(flag.run_id, flag.quantity) for flag in flags] == [
        ("E-kN", "N_u1"), ("E-kN", "N_u2"), ("E-kgf", "N_u1")]
    kN, _, kgf = flags
    assert (kN.value, kN.reference, kN.against) == (2.3e6, 2.0e3, "impact model")
    assert kN.ratio == pytest.approx(1150)
    assert kN.slip == "a force in N labelled kN (factor 1000)"
    assert kN.message.startswith(
        "E-kN: N_u1 = 2300 kN is 1150 x the impact model with k = 2 (2 kN): probably a force "
        "in N labelled kN (factor 1000).")
    assert kgf.ratio == pytest.approx(1.15 / KGF)
    assert kgf.slip == "a force in kgf labelled N (or tf labelled kN) (factor 1/9.81)"
    assert excluded(flags) == {"E-kN"}


# --- the dataset ---------------------------------------------------------------------------

def sample_flags() -> list[Flag]:
    flags = check({"T1": specimen(E0=1.05e10, at_fracture=24.0)}, accepted={"T1"})
    return flags + check_operating_points(
        pd.DataFrame({"N_u1_meas": [3.5e3], "N_u1_theory": [1.0e3], "N_u2_meas": [NAN],
                      "N_u2_theory": [1.0e3]}, index=["E1"]), accepted=())


def test_flags_dataset_holds_the_flags():
    flags = sample_flags()
    assert [flag.slip is None for flag in flags] == [False, False, True]
    dataset = flags_dataset(flags)
    assert dataset.sizes["flag"] == 3
    assert list(dataset["flag_run"].values) == ["T1", "T1", "E1"]
    assert list(dataset["flag_quantity"].values) == ["E0", "strain_at_fracture", "N_u1"]
    np.testing.assert_array_equal(dataset["flag_value"], [1.05e10, 24.0, 3.5e3])
    np.testing.assert_array_equal(dataset["flag_reference"], [THEORY, 0.5, 1.0e3])
    assert list(dataset["flag_units"].values) == ["N", "1", "N"]
    assert list(dataset["flag_against"].values) == ["theory", "strain limit", "impact model"]
    np.testing.assert_allclose(dataset["flag_ratio"], [1050, 48, 3.5])
    assert list(dataset["flag_slip"].values) == [flags[0].slip, flags[1].slip, ""]
    assert list(dataset["flag_accepted"].values) == [1, 1, 0]
    assert list(dataset["flag_message"].values) == [flag.message for flag in flags]
    assert dataset["flag_ratio"].attrs["units"] == "1"


def test_flags_dataset_survives_netcdf(tmp_path):
    dataset = flags_dataset(sample_flags())
    dataset.to_netcdf(tmp_path / "flags.nc")
    back = xr.load_dataset(tmp_path / "flags.nc")
    for name in dataset.data_vars:
        assert list(back[name].values) == list(dataset[name].values), name


def test_flags_dataset_without_flags_is_empty(tmp_path):
    dataset = flags_dataset([])
    assert dataset.sizes["flag"] == 0
    assert set(dataset.data_vars) == set(flags_dataset(sample_flags()).data_vars)
    assert dataset["flag_value"].dtype == float
    dataset.to_netcdf(tmp_path / "empty.nc")
    assert xr.load_dataset(tmp_path / "empty.nc").sizes["flag"] == 0


def test_the_bands_applied_are_the_flags_attributes():
    # README, "Run sheet rules that catch slips", and docs/run-sheet.md: E0 and impact
    # tensions within 1/3 to 3 times the theory, E0 within 1/2 to 2 times its chain's
    # others (from three specimens), max force within 1/100 to 3 times the breaking force
    # and at most the capacity (5 % let through, the module docstring), strains at most 50 %
    attrs = flags_dataset([]).attrs
    assert attrs["plausibility_theory_band"].tolist() == pytest.approx([1 / 3, 3])
    assert attrs["plausibility_peer_band"].tolist() == pytest.approx([1 / 2, 2])
    assert attrs["plausibility_breaking_band"].tolist() == pytest.approx([1 / 100, 3])
    assert attrs["plausibility_capacity_tolerance"] == pytest.approx(1.05)
    assert attrs["plausibility_strain_limit"] == 0.5
    assert attrs["plausibility_min_specimens"] == 3
