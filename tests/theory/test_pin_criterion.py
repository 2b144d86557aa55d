"""Paper 004 (Kravchenko & Bogdanovych): pin criterion for roller chains of open drives.

The paper publishes no numbers: expectations are the identities and the hand-worked
16B example of docs/models/paper-004-pin-criterion.md, typed here.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pipeline.theory import pin_criterion as pc

# ISO 606 16B worked example (docs/models/paper-004-pin-criterion.md), SI.
T, PIN, L, L1 = 25.4e-3, 8.28e-3, 25.45e-3, 29.78e-3  # m
F_MAX, SIGMA_T, K_E, Z = 12e3, 800e6, 1.0, 40  # N, Pa, -, -
HAND_MM = 5e-6  # the hand values are rounded to 0.01 mm: half a unit, in m
HAND_UM = 5e-7  # ... or to 0.001 mm


def test_no_published_numbers():
    # Paper 004 prints no numbers: its paper_004.csv has no rows.
    table = pc.compare_published()
    assert table.empty
    assert "within_tolerance" in table.columns


def test_named_defaults():
    assert pc.PITCH_GROWTH_SAFETY == 0.8  # psi, eq. (3)
    assert pc.PITCH_ERROR_FRACTION == 0.004  # delta_t_n / t, eq. (3)
    assert (pc.K_PINNED, pc.K_CLAMPED) == (1.0, 3.0)  # eq. (4)


@given(
    pitch=st.floats(min_value=5e-3, max_value=0.1),
    z=st.integers(min_value=9, max_value=400),
)
def test_pitch_growth_with_psi_0_8_is_t_times_2_over_z_minus_0_004(pitch, z):
    # 2.5 * 0.8 = 2: an identity, rounding only.
    expected = pitch * (2 / z - 0.004)
    assert pc.allowed_pitch_growth(pitch, z) == pytest.approx(expected, rel=1e-12)


def test_hand_example_pitch_growth_and_wear():
    growth = pc.allowed_pitch_growth(T, Z)
    assert growth == pytest.approx(1.168e-3, abs=HAND_UM)  # 25.4 (2/40 - 0.004) mm
    assert pc.pin_wear_allowance(growth, K_E) == pytest.approx(0.584e-3, abs=HAND_UM)


@pytest.mark.parametrize(
    ("support", "d_k_mm", "required_mm", "passes"),
    [(pc.K_PINNED, 8.67, 9.25, False), (pc.K_CLAMPED, 6.01, 6.60, True)],
)
def test_hand_example_16b(support, d_k_mm, required_mm, passes):
    assert pc.critical_pin_diameter(F_MAX, L1, L, SIGMA_T, support) == pytest.approx(
        d_k_mm * 1e-3, abs=HAND_MM
    )
    check = pc.check_pin(PIN, T, Z, F_MAX, L1, L, SIGMA_T, K_E, support)
    assert check.critical_diameter == pytest.approx(d_k_mm * 1e-3, abs=HAND_MM)
    assert check.wear_allowance == pytest.approx(0.584e-3, abs=HAND_UM)
    # The example's required diameters add rounded terms (6.01 + 0.584 -> 6.60; exact 6.595):
    # 0.01 mm covers the two roundings. The sum itself is exact.
    assert check.required_diameter == pytest.approx(required_mm * 1e-3, abs=1e-5)
    assert check.required_diameter == check.critical_diameter + check.wear_allowance
    assert check.pin_diameter == PIN
    assert check.passes is passes


def test_max_bending_moment_hand_value():
    # (2 * 29.78 - 25.45) mm * 12 kN / 8 = 34.11 mm * 1.5 kN = 51.165 N m (K = 1).
    assert pc.max_bending_moment(F_MAX, L1, L) == pytest.approx(51.165, rel=1e-9)
    assert pc.max_bending_moment(F_MAX, L1, L, pc.K_CLAMPED) == pytest.approx(17.055, rel=1e-9)


@given(
    force=st.floats(min_value=100.0, max_value=1e6),
    span=st.floats(min_value=5e-3, max_value=0.2),
    bush_fraction=st.floats(min_value=0.05, max_value=1.95),
    stress=st.floats(min_value=50e6, max_value=2e9),
    support=st.sampled_from([1.0, 3.0]),
)
def test_bending_stress_at_critical_diameter_is_the_allowable_stress(
    force, span, bush_fraction, stress, support
):
    # sigma = M_max / W with W = pi d^3 / 32 (Paper 004, eq. (5)): an identity.
    bush = bush_fraction * span
    d_k = pc.critical_pin_diameter(force, span, bush, stress, support)
    moment = pc.max_bending_moment(force, span, bush, support)
    assert moment / (math.pi * d_k**3 / 32) == pytest.approx(stress, rel=1e-9)


def test_vectorised_over_teeth():
    check = pc.check_pin(PIN, T, np.array([20, 40, 80]), F_MAX, L1, L, SIGMA_T, K_E, pc.K_CLAMPED)
    assert check.required_diameter.shape == (3,)
    # More teeth, less allowed pitch growth, smaller wear allowance.
    assert np.all(np.diff(check.required_diameter) < 0)
    assert check.passes.tolist() == [True, True, True]


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: pc.allowed_pitch_growth(0.0, 40), "pitch"),
        (lambda: pc.allowed_pitch_growth(T, 2), "teeth"),
        (lambda: pc.allowed_pitch_growth(T, 600), "teeth"),  # 2/z < 0.004: no growth left
        (lambda: pc.pin_wear_allowance(1e-3, -1.0), "wear_coefficient"),
        (lambda: pc.max_bending_moment(-1.0, L1, L), "force"),
        (lambda: pc.max_bending_moment(F_MAX, L1, 2 * L1), "bush_length"),
        (lambda: pc.critical_pin_diameter(F_MAX, L1, L, 0.0), "allowable_stress"),
        (lambda: pc.critical_pin_diameter(F_MAX, L1, L, SIGMA_T, 0.0), "support_factor"),
        (lambda: pc.check_pin(0.0, T, Z, F_MAX, L1, L, SIGMA_T, K_E), "pin_diameter"),
    ],
)
def test_domain_errors_name_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_table_of_the_hand_example_per_support():
    # the hand-worked example, both supports, in the table's mm (no published numbers)
    chain = {"t": T, "pin_diameter": PIN, "bush_length": L, "plate_span": L1}
    rows = pc.table(chain, [Z, 20], F_MAX, SIGMA_T, K_E)
    assert [(row["z"], row["support"], row["K"]) for row in rows] == [
        (40, "pinned", 1.0), (40, "clamped", 3.0), (20, "pinned", 1.0), (20, "clamped", 3.0)]
    pinned, clamped = rows[:2]
    for row in (pinned, clamped):
        assert row["delta_t1_mm"] == pytest.approx(1.168, abs=1e3 * HAND_UM)
        assert row["delta_d_mm"] == pytest.approx(0.584, abs=1e3 * HAND_UM)
        assert row["pin_mm"] == pytest.approx(8.28, rel=1e-12)
    assert (pinned["d_k_mm"], pinned["passes"]) == (pytest.approx(8.67, abs=5e-3), False)
    assert (clamped["d_k_mm"], clamped["passes"]) == (pytest.approx(6.01, abs=5e-3), True)
    assert pinned["required_mm"] == pytest.approx(pinned["d_k_mm"] + pinned["delta_d_mm"])
    # z = 20: the allowed growth 25.4 (2/20 - 0.004) mm, twice the wear allowance
    assert rows[2]["delta_t1_mm"] == pytest.approx(25.4 * (2 / 20 - 0.004), rel=1e-12)
