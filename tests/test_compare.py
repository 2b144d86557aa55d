"""The stiffness and impact tables: experiment against theory, by hand-computed numbers."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from pipeline.compare import ChainInput, impact_summary, stiffness_summary
from pipeline.fit.impact_model import fit_impact_model, model_tensions
from pipeline.fit.stiffness import SpecimenStiffness
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si

KGF = 9.80665


def table1_chain(key: str, d, t, R0, a) -> ChainInput:
    return ChainInput(key=key, catalog=key, d=d / 1e3, t=t / 1e3, R0=R0 / 1e3, a=a / 1e3,
                      E_steel=to_si(2.2e6, "kgf/cm^2"))


def specimen(E0: float, stderr: float = 0.0) -> SpecimenStiffness:
    return SpecimenStiffness(E0=E0, E0_stderr=stderr, E0_ci_low=E0, E0_ci_high=E0, dof=10,
                             birge_ratio=1.0, n_cycles=2, E0_first=E0, E0_first_stderr=0.0,
                             E0_unloading=E0)


def test_table_1_as_measured_gives_the_papers_rows():
    # Specimens measuring exactly Table 1's experimental E0 (kgf) of each chain, as packaged.
    published = table_1()
    exp = np.array([published[name].E0_exp_kgf for name in ("13x50", "18x64")])
    chains = [table1_chain("13x50", 13, 50, 15, 33), table1_chain("18x64", 18, 64, 20, 42)]
    measured = {"13x50": [specimen(exp[0] * KGF)] * 2, "18x64": [specimen(exp[1] * KGF)] * 3}
    summary = stiffness_summary(chains, measured)
    # docs/published-values.md: eq. (20), printed coefficients: 1.0553e6 and 2.0430e6 kgf.
    theory = np.array([1.0553e6, 2.0430e6])
    assert summary["E0_theory"].values / KGF == pytest.approx(theory, rel=1e-4)
    assert summary["discrepancy"].values == pytest.approx(exp / theory - 1, rel=1e-3)
    assert summary["discrepancy_vs_exp"].values == pytest.approx(1 - theory / exp, rel=1e-3)
    # 6.13 % and 10.6 %: both out of the 3-6 % band against this model's E0.
    assert summary["in_band"].values.tolist() == [0, 0]
    assert summary["E0_exp_published"].values / KGF == pytest.approx(exp)
    assert summary["E0_theory_published"].values / KGF == pytest.approx(
        [published[name].E0_theor_kgf for name in ("13x50", "18x64")])
    assert summary["n_specimens"].values.tolist() == [2, 3]
    assert summary.attrs["band"] == "0.03 0.06"


def test_band_is_configurable_and_interval_is_carried():
    chain = table1_chain("14x50", 14, 50, 16, 32)
    values = [1.22e6 * KGF, 1.24e6 * KGF, 1.26e6 * KGF]
    summary = stiffness_summary([chain], {"14x50": [specimen(v) for v in values]}, band=(0.0, 0.1))
    theory = float(summary["E0_theory"][0])
    mean = np.mean(values)
    half = 4.302652729911275 * np.std(values, ddof=1) / math.sqrt(3)  # t(0.975, 2)
    assert float(summary["E0_exp"][0]) == pytest.approx(mean)
    assert float(summary["discrepancy_ci_low"][0]) == pytest.approx((mean - half) / theory - 1)
    assert float(summary["discrepancy_ci_high"][0]) == pytest.approx((mean + half) / theory - 1)
    assert int(summary["in_band"][0]) == 1  # 4.7 % lies in 0-10 %


def test_chain_without_specimens_or_geometry_is_reported_not_hidden():
    unknown = ChainInput(key="cX", catalog=None, d=0.02, t=0.08, R0=None, a=None, E_steel=2e11)
    summary = stiffness_summary([unknown], {})
    assert np.isnan(float(summary["E0_theory"][0]))
    assert int(summary["in_band"][0]) == -1
    assert "needs d, t, R0 and a" in summary.attrs["notes"]


def test_geometry_warning_lands_in_notes():
    summary = stiffness_summary([table1_chain("22x86", 22, 86, 24, 58)], {})
    assert float(summary["geometry_mismatch"][0]) == pytest.approx(0.002)
    assert "84 mm" in summary.attrs["notes"]


def test_impact_summary_theory_is_papers_grid():
    # docs/published-values.md, Paper 000 grid: N_u1 = 972 N (psi 40), N_u2 = 3423 N (z = 8).
    points = pd.DataFrame(
        {"teeth": [8], "apex_angle": [math.radians(40)], "omega": [20.0], "t": [0.064],
         "d": [0.018], "mass_per_length": [6.6], "E0": [2.26e7], "branch_length": [2.0],
         "omega_measured": [20.0], "N_u1_meas": [980.0], "N_u1_iqr": [5.0],
         "N_u1_stderr": [1.0], "N_u1_count": [30], "N_u2_meas": [3400.0], "N_u2_iqr": [9.0],
         "N_u2_stderr": [2.0], "N_u2_count": [30]},
        index=["E8"],
    )
    summary = impact_summary(points, fit=None)
    assert float(summary["N_u1_theory"][0]) == pytest.approx(972, abs=0.5)
    assert float(summary["N_u2_theory"][0]) == pytest.approx(3423, abs=0.5)
    assert float(summary["apex_angle"][0]) == pytest.approx(40)
    assert np.isnan(float(summary["k_fit"]))


def test_impact_summary_lines_in_omega_are_fitted_per_wheel_and_impact():
    # N_u1 = 50 omega + 100 (exactly straight, intercept 100 N); N_u2 = 3 omega^2 (curved)
    omega = np.array([10.0, 20.0, 30.0])
    points = pd.DataFrame(
        {"teeth": 8, "apex_angle": math.radians(40), "omega": omega, "t": 0.064, "d": 0.018,
         "mass_per_length": 6.6, "E0": 2.26e7, "branch_length": 2.0, "omega_measured": omega,
         "N_u1_meas": 50 * omega + 100, "N_u1_iqr": 1.0, "N_u1_stderr": 1.0, "N_u1_count": 9,
         "N_u2_meas": 3 * omega**2, "N_u2_iqr": 1.0, "N_u2_stderr": 1.0, "N_u2_count": 9},
        index=["a", "b", "c"])
    summary = impact_summary(points, fit=None)
    assert summary.sizes["speed_line"] == 2
    first, second = (summary.isel(speed_line=i) for i in (0, 1))
    assert (int(first["line_impact"]), int(first["line_n_speeds"])) == (1, 3)
    assert float(first["line_slope"]) == pytest.approx(50)
    assert float(first["line_intercept"]) == pytest.approx(100)
    assert float(first["line_r2"]) == pytest.approx(1)
    assert float(first["line_largest"]) == pytest.approx(1600)
    # y = 300, 1200, 2700 on x = 10, 20, 30: slope 120, fitted 200, 1400, 2600, so
    # residuals 100, -200, 100 and R^2 = 1 - 6e4 / 2.94e6
    assert float(second["line_slope"]) == pytest.approx(120)
    assert float(second["line_r2"]) == pytest.approx(1 - 6e4 / 2.94e6, rel=1e-9)
    assert float(first["line_apex_angle"]) == pytest.approx(40)


def test_table_1_chains_carry_the_papers_own_discrepancy():
    # docs/published-values.md, Paper 001: on Table 1 alone d = 3.70 % (13x50), 8.13 % (18x64)
    chains = [table1_chain("13x50", 13, 50, 15, 33), table1_chain("18x64", 18, 64, 20, 42),
              ChainInput(key="cX", catalog=None, d=0.02, t=0.08, R0=0.022, a=0.056,
                         E_steel=2e11)]
    summary = stiffness_summary(chains, {})
    assert summary["discrepancy_published"].values[:2] == pytest.approx([0.0370, 0.0813],
                                                                        abs=5e-5)
    assert np.isnan(float(summary["discrepancy_published"][2]))  # not a chain of Table 1


def test_intervals_record_their_confidence_level():
    summary = stiffness_summary([table1_chain("14x50", 14, 50, 16, 32)],
                                {"14x50": [specimen(1.22e7), specimen(1.26e7)]})
    for name in ("E0_exp_ci_low", "E0_exp_ci_high", "discrepancy_ci_low", "discrepancy_ci_high"):
        assert summary[name].attrs["confidence_level"] == 0.95
    assert summary["E0_exp_ci_low"].attrs["long_name"] == (
        "lower limit of the 95 % interval of E0_exp")
    assert "confidence_level" not in summary["E0_exp"].attrs


def exact_points(k: float) -> pd.DataFrame:
    """Four operating points of one wheel measuring the model with mass share `k` exactly."""
    points = pd.DataFrame(
        {"teeth": 8, "apex_angle": math.radians(40), "omega": [10.0, 20.0, 30.0, 40.0],
         "t": 0.064, "d": 0.018, "mass_per_length": 6.6, "E0": 2.26e7, "branch_length": 2.0},
        index=["a", "b", "c", "d"])
    n_u1, n_u2 = model_tensions(points, k=k)
    return points.assign(omega_measured=points["omega"], N_u1_meas=n_u1, N_u2_meas=n_u2,
                         N_u1_iqr=1.0, N_u2_iqr=1.0, N_u1_stderr=0.01 * n_u1,
                         N_u2_stderr=0.01 * n_u2, N_u1_count=30, N_u2_count=30)


@pytest.mark.parametrize(("k", "covers"), [(2.0, 1), (1.5, 0)])
def test_impact_summary_records_the_theory_the_fit_and_the_lines(k, covers):
    points = exact_points(k)
    summary = impact_summary(points, fit_impact_model(points))
    assert float(summary["k_fit"]) == pytest.approx(k, rel=1e-6)
    # Ryabov's k = 2 (Paper 000, eq. (11)) is what the _theory tensions use
    assert summary.attrs["k_theory"] == 2.0
    assert int(summary["k_fit_covers_theory"]) == covers
    assert summary["k_fit_ci_low"].attrs["confidence_level"] == 0.95
    assert "weighted least squares" in summary.attrs["k_fit_method"]
    # exactly proportional to omega: R^2 = 1 and no intercept on both lines
    assert "(2 lines: wheels × impacts) give R² ≥ 1.0000" in summary.attrs["linearity"]
    assert "at most 0.0 % of N_u" in summary.attrs["linearity"]


def test_impact_summary_without_a_fit():
    summary = impact_summary(exact_points(2.0), fit=None)
    assert int(summary["k_fit_covers_theory"]) == -1
    assert summary["k_fit_ci_high"].attrs["confidence_level"] == 0.95
