"""Paper 002 (Berezhnoy, Voina, Kurapov): impact of roller chains on involute sprockets.

The paper's printed constants are read from the packaged ``paper_002.csv``
(through ``compare_published()``); other expectations are typed here from the
paper and from docs/published-values.md (section 002), or worked by hand in the
test; never copied from the code's output.
"""

from __future__ import annotations

import doctest
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from pipeline.theory import roller_impact as ri
from pipeline.theory._published import within_tolerance
from pipeline.units import from_si, to_si

# The example of docs/published-values.md, Paper 002: q = 3.8 kg/m, xi = 0.8, n = 500 rpm,
# t = 31.75 mm.
Q, XI, N_RPM, T_MM = 3.8, 0.8, 500.0, 31.75
OMEGA = 2 * math.pi * N_RPM / 60  # rad/s
T = T_MM / 1000  # m

#: The published numbers of paper_002.csv beside the model's.
PUBLISHED = ri.compare_published()


def test_energy_constant_is_the_derived_one():
    # (1/2)(2 pi/60)^2 1e-9 = 5.4831e-12, given to 5 digits in the docs: 1e-4 relative.
    assert ri.ENERGY_CONSTANT == pytest.approx(5.4831e-12, rel=1e-4)
    # The paper prints 5.48e-12 (paper_002.csv): the derived constant rounds to it (3 digits).
    published = PUBLISHED.set_index("quantity").at["energy_constant", "published"]
    assert round(ri.ENERGY_CONSTANT, 14) == published


def test_example_energy_is_half_m_v_squared():
    m = Q * T  # one link [kg]
    v = OMEGA * T * XI  # impact velocity [m/s]
    by_hand = 0.5 * m * v**2
    # Same physics, same arithmetic up to rounding: 1e-12 relative.
    assert ri.impact_energy(Q, OMEGA, T, XI) == pytest.approx(by_hand, rel=1e-12)
    assert ri.impact_energy_paper(Q, XI, N_RPM, T_MM) == pytest.approx(by_hand, rel=1e-12)


def test_example_energy_matches_the_spec_value():
    # The example's 0.1066 J is what the paper's rounded 5.48e-12 gives (0.10664 J); the
    # derived constant gives 0.10670 J. Half a unit of the 4th digit separates them ...
    assert ri.impact_energy_paper(Q, XI, N_RPM, T_MM) == pytest.approx(0.1067, abs=5e-5)
    assert 5.48e-12 * Q * XI**2 * N_RPM**2 * T_MM**3 == pytest.approx(0.1066, abs=5e-5)
    # ... and the example's 0.1 % covers both.
    assert ri.impact_energy_paper(Q, XI, N_RPM, T_MM) == pytest.approx(0.1066, rel=1e-3)


def test_impact_velocity_is_omega_t_xi():
    # eq. (5); exact arithmetic.
    assert ri.impact_velocity(OMEGA, T, XI) == pytest.approx(52.35988 * 0.03175 * 0.8, rel=1e-6)


# Roller chain 20B-like data (mm) for the speed limit; any positive values would do.
D_MM, B_MM = 19.05, 19.56


def test_n_max_reproduces_the_papers_7400_form():
    omega_max = ri.max_angular_velocity(
        Q, T, XI, to_si(D_MM, "mm"), to_si(B_MM, "mm"), g_lim=to_si(3e-4, "J/mm^2")
    )
    paper = 7400 / (XI * T_MM) * math.sqrt(D_MM * B_MM / (Q * T_MM))  # eq. (8) [rpm]
    # 7400 is the paper's rounding of sqrt(3e-4 / 5.4831e-12) = 7397: within 0.1 %.
    assert from_si(omega_max, "rpm") == pytest.approx(paper, rel=1e-3)
    # ... and with the unrounded 7397 the two agree to 1e-4 (the 4 digits of 7397).
    assert from_si(omega_max, "rpm") == pytest.approx(paper * 7397 / 7400, rel=1e-4)


def test_default_limit_is_3e_4_j_per_mm2():
    assert ri.G_LIM == pytest.approx((to_si(3e-4, "J/mm^2"), to_si(4e-4, "J/mm^2")))
    D, B = to_si(D_MM, "mm"), to_si(B_MM, "mm")
    assert ri.max_angular_velocity(Q, T, XI, D, B) == pytest.approx(
        ri.max_angular_velocity(Q, T, XI, D, B, g_lim=300.0), rel=1e-15
    )


@pytest.mark.parametrize("g_lim_j_per_mm2", [3e-4, 4e-4])
def test_specific_energy_at_n_max_equals_the_limit(g_lim_j_per_mm2):
    D, B = to_si(D_MM, "mm"), to_si(B_MM, "mm")
    g_lim = to_si(g_lim_j_per_mm2, "J/mm^2")
    omega_max = ri.max_angular_velocity(Q, T, XI, D, B, g_lim=g_lim)
    energy = ri.impact_energy(Q, omega_max, T, XI)
    # An identity (eq. (7) solved for n): rounding only.
    assert ri.specific_impact_energy(energy, D, B) == pytest.approx(g_lim, rel=1e-12)


def test_specific_energy_is_energy_over_projected_area():
    # eq. (7) corrected: 1 J on a 10 mm x 20 mm roller = 1 / 200 J/mm^2 = 5000 J/m^2.
    assert ri.specific_impact_energy(1.0, 0.010, 0.020) == pytest.approx(5000.0, rel=1e-12)


def test_base_radius_eq_4():
    # m = 10 mm, z = 20, alpha = 20 deg: r_b = 100 mm * cos(20 deg) = 93.969 mm.
    assert ri.base_radius(0.010, 20, math.radians(20)) == pytest.approx(0.0939693, rel=1e-6)


def test_xi_at_the_largest_base_radius_is_sin_pi_over_z():
    # r_b = t / (2 sin(pi/z)): delta_K = 0, Theta = pi/z (eq. (3)).
    z, t = 12, 0.0254
    r_b = t / (2 * math.sin(math.pi / z))
    assert ri.impact_velocity_coefficient(z, r_b, t) == pytest.approx(math.sin(math.pi / 12))


def test_xi_reaches_one_at_half_the_pitch():
    # r_b = t/2: cos(delta_K) = sin(pi/z), Theta = pi/2, so xi = 1 outside [sin, cos](pi/z).
    assert ri.impact_velocity_coefficient(10, 0.0127, 0.0254) == pytest.approx(1.0, abs=1e-12)


@given(
    z=st.integers(min_value=4, max_value=200),
    pitch=st.floats(min_value=5e-3, max_value=0.2),
    fraction=st.floats(min_value=0.0, max_value=1.0),
)
def test_xi_within_bounds_for_base_radii_above_t_cos_pi_over_z(z, pitch, fraction):
    # For t cos(pi/z) <= r_b <= t / (2 sin(pi/z)), Theta runs from pi/2 - pi/z to pi/z.
    low, high = pitch * math.cos(math.pi / z), pitch / (2 * math.sin(math.pi / z))
    r_b = min(low + fraction * (high - low), high)
    xi = ri.impact_velocity_coefficient(z, r_b, pitch)
    lower, upper = ri.impact_velocity_coefficient_bounds(z)
    assert lower == pytest.approx(math.sin(math.pi / z))
    assert upper == pytest.approx(math.cos(math.pi / z))
    # At r_b = t cos(pi/z) with z = 4 the ratio under arccos is 1 up to rounding (1e-16),
    # and arccos turns a rounding of eps into sqrt(2 eps) = 1.5e-8: the bound holds to that.
    conditioning = math.sqrt(2 * np.finfo(float).eps)
    assert lower - conditioning <= xi <= upper + conditioning


@given(
    z=st.integers(min_value=6, max_value=150),
    pitch=st.floats(min_value=5e-3, max_value=0.2),
    alpha_deg=st.floats(min_value=15.0, max_value=20.0),
)
def test_xi_of_an_involute_sprocket_falls_as_z_grows(z, pitch, alpha_deg):
    # An involute sprocket whose circular pitch equals the chain pitch: m = t / pi.
    # For z >= 6 and alpha <= 20 deg its base radius is above t cos(pi/z).
    alpha = math.radians(alpha_deg)
    xi = [
        ri.impact_velocity_coefficient(n, ri.base_radius(pitch / math.pi, n, alpha), pitch)
        for n in (z, z + 1)
    ]
    assert xi[1] < xi[0]
    for n, value in zip((z, z + 1), xi, strict=True):
        assert math.sin(math.pi / n) <= value <= math.cos(math.pi / n)


def test_vectorised_over_teeth():
    z = np.array([10, 20, 40])
    pitch = 0.03175
    xi = ri.impact_velocity_coefficient(z, ri.base_radius(pitch / math.pi, z, 0.349), pitch)
    assert xi.shape == (3,)
    assert np.all(np.diff(xi) < 0)


@pytest.mark.parametrize(
    "row", PUBLISHED.to_dict("records"), ids=PUBLISHED["quantity"].tolist()
)
def test_published_number_reproduced_as_declared(row):
    # A row declared reproduced is within its tolerance; one declared not is not (a
    # finding: the model's value is pinned in test_published_constants_model_values).
    assert row["within_tolerance"] is row["reproduced"], row["note"]


def test_published_constants_model_values():
    model = PUBLISHED.set_index("quantity")["model"]
    # sqrt(3e-4 / 5.4831e-12) = 7397 rpm mm, to the unit.
    assert model["speed_limit_constant"] == pytest.approx(7397, abs=0.5)
    # 1 / 5.4831e-12 = 1.8238e11, given to 5 digits: the paper's 1.8e12 is a misprint.
    assert model["specific_energy_denominator"] == pytest.approx(1.8238e11, rel=1e-4)
    assert model["energy_constant"] == pytest.approx(5.4831e-12, rel=1e-4)


def test_base_radius_too_large_names_the_parameter():
    t, z = 0.0254, 10
    too_large = 1.001 * t / (2 * math.sin(math.pi / z))
    with pytest.raises(ValueError, match="base_radius"):
        ri.impact_velocity_coefficient(z, too_large, t)


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: ri.impact_angle(2, 0.01, 0.0254), "teeth"),
        (lambda: ri.impact_angle(10.5, 0.01, 0.0254), "teeth"),
        (lambda: ri.impact_angle(10, -0.01, 0.0254), "base_radius"),
        (lambda: ri.impact_angle(10, 0.01, 0.0), "pitch"),
        (lambda: ri.impact_velocity_coefficient_bounds(3), "teeth"),
        (lambda: ri.impact_energy(-1.0, 10.0, 0.0254, 0.5), "mass_per_length"),
        (lambda: ri.impact_energy_paper(3.8, 0.8, -500.0, 31.75), "n_rpm"),
        (lambda: ri.specific_impact_energy(1.0, 0.0, 0.01), "roller_diameter"),
        (lambda: ri.max_angular_velocity(3.8, 0.03, 0.0, 0.019, 0.019), "xi"),
        (lambda: ri.max_angular_velocity(3.8, 0.03, 0.5, 0.019, 0.019, g_lim=-1.0), "g_lim"),
    ],
)
def test_domain_errors_name_the_parameter(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_doctests():
    assert doctest.testmod(ri, raise_on_error=True).attempted >= 1


def test_table_of_unit_inputs_gives_the_papers_constants_as_declared():
    # eqs. (6)-(8) for q = 1 kg/m, n = 1 rpm, t = 1 mm, xi = 1, D = L = 1 mm and
    # G_lim = 3e-4 J/mm^2: the energy, its reciprocal per mm^2 and n_max are the constants
    unit = {"t": 1e-3, "mass_per_length": 1.0, "roller_diameter": 1e-3, "inner_width": 1e-3}
    (row,) = ri.table(unit, [20], [1.0], 1.0, 1e-3, math.radians(20), to_si(3e-4, "J/mm^2"))
    found = {"energy_constant": row["energy_J"],
             "specific_energy_denominator": 1 / row["G_J_per_mm2"],
             "speed_limit_constant": row["n_max_rpm"]}
    published = PUBLISHED.set_index("quantity")
    assert set(found) == set(published.index)
    for quantity, value in found.items():
        assert value == pytest.approx(published.at[quantity, "model"], rel=1e-9)
        assert within_tolerance(value, published.at[quantity, "published"],
                                published.at[quantity, "tolerance"]) is bool(
            published.at[quantity, "reproduced"])
    assert row["xi"] == 1.0 and bool(row["below_n_max"])


def test_table_rows_per_teeth_and_speed_with_the_involute_xi():
    chain = {"t": 31.75e-3, "mass_per_length": 3.7, "roller_diameter": 19.05e-3,
             "inner_width": 19.56e-3}
    rows = ri.table(chain, [10, 20], [500.0, 1000.0], None, 31.75e-3 / math.pi,
                    math.radians(20), to_si(3e-4, "J/mm^2"))
    assert [(row["z"], row["n_rpm"]) for row in rows] == [(10, 500), (10, 1000), (20, 500),
                                                         (20, 1000)]
    for row in rows:
        assert row["xi_min"] <= row["xi"] <= row["xi_max"]
        # eq. (6): E = (1/2) q t (omega t xi)^2, omega = 2 pi n / 60
        omega = 2 * math.pi * row["n_rpm"] / 60
        assert row["energy_J"] == pytest.approx(
            0.5 * 3.7 * 31.75e-3 * (omega * 31.75e-3 * row["xi"]) ** 2, rel=1e-12)
    assert rows[0]["xi"] == rows[1]["xi"]  # xi depends on z only
    notes = ri.table_notes(None, 31.75e-3 / math.pi, math.radians(20))
    assert notes[0].startswith("xi of an involute sprocket, m = 10.11 mm, alpha = 20 deg")
    assert len(notes) == 1 + len(PUBLISHED)
    assert ri.table_notes(0.5, 1e-3, 0.3)[0] == "xi given (0.5), not computed"
