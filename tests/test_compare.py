"""The stiffness and impact tables: experiment against theory, by hand-computed numbers."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from pipeline.compare import ChainInput, impact_summary, stiffness_summary
from pipeline.fit.stiffness import SpecimenStiffness
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
    # Specimens measuring exactly Table 1's experimental E0 (kgf) of each chain.
    chains = [table1_chain("13x50", 13, 50, 15, 33), table1_chain("18x64", 18, 64, 20, 42)]
    measured = {"13x50": [specimen(1.12e6 * KGF)] * 2, "18x64": [specimen(2.26e6 * KGF)] * 3}
    summary = stiffness_summary(chains, measured)
    # reference-values.md: eq. (20), printed coefficients: 1.0553e6 and 2.0430e6 kgf.
    assert summary["E0_theory"].values / KGF == pytest.approx([1.0553e6, 2.0430e6], rel=1e-4)
    expected = np.array([1.12e6 / 1.0553e6 - 1, 2.26e6 / 2.0430e6 - 1])
    assert summary["discrepancy"].values == pytest.approx(expected, rel=1e-3)
    assert summary["discrepancy_vs_exp"].values == pytest.approx(
        [1 - 1.0553e6 / 1.12e6, 1 - 2.0430e6 / 2.26e6], rel=1e-3)
    # 6.13 % and 10.6 %: both out of the 3-6 % band against this model's E0.
    assert summary["in_band"].values.tolist() == [0, 0]
    assert summary["E0_theory_published"].values / KGF == pytest.approx([1.08e6, 2.09e6])
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
    # reference-values.md, 000 grid: N_u1 = 972 N (psi 40), N_u2 = 3423 N (z = 8, psi 40).
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
