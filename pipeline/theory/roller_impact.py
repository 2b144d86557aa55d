"""Impact of a roller chain on an involute sprocket (Paper 002).

Berezhnoy, Voina and Kurapov compare involute sprockets with the standard
GOST 591 / GOST 592 profiles by the impact velocity of the chain joint on the
tooth, its kinetic energy and the speed limit that follows from a limit on the
specific impact energy.

Units
-----
SI at the interface unless a name says otherwise: pitch, radii, roller
diameter and length in m, angular velocity in rad/s, mass per length in kg/m,
energy in J, specific energy in J/m^2. The one exception is
:func:`impact_energy_paper`, the paper's eq. (6) in the paper's units, whose
argument names carry them (``q_kg_per_m``, ``n_rpm``, ``t_mm``).

What the paper does not let us derive
-------------------------------------
* xi for the GOST 591-69 (convex-concave) and GOST 592-81 (straight) profiles,
  curves 1 and 2 of Figs. 2 and 6: the paper takes them from its refs. [1, 2]
  and gives no formula.
* The toothed-chain construction, eqs. (12)-(17): the involute angle theta at
  the contact point, the distance u of the joint centre from the working face
  and the centre distance OO1 are not given, so xi of a toothed chain on an
  involute sprocket (Fig. 6, curves 3-5) cannot be computed.
* The module m and tool profile angle alpha behind the involute curves of
  Figs. 2-4 are not stated, nor the worn pitch of Fig. 4, so none of the
  plotted xi or n_max values can be reproduced. Only the constants of eqs. (6)
  and (8) are checkable (see :func:`compare_published`).

Corrections to the printed text (see ``docs/models/paper-002-roller-impact.md``): eq. (6) prints
``5,48 10^12`` for 5.48e-12; eq. (7) prints ``1,8 10^12`` and "J/mm" where
(6) and (8) require 1.82e11 and J/mm^2, and calls n a speed in 1/s where the
constants require rpm.

References
----------
Paper 002: Berezhnoy S.B., Voina A.A., Kurapov G.V. (Kuban State Technological
University), "Analysis of impact resistance of chain according to sprocket lug
profile" (Russian: "Analiz udarnoi stoikosti tsepi v zavisimosti ot profilya
zuba zvezdochki"); journal and year not printed in the OCR'd copy; no DOI found.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.theory._checks import non_negative, positive, scalar_or_array
from pipeline.theory._checks import teeth as whole_teeth
from pipeline.theory._published import compare
from pipeline.theory._tables import rows
from pipeline.units import from_si, to_si

#: Constant of eq. (6) [J per (kg/m * rpm^2 * mm^3)]: (1/2) (2 pi / 60)^2 * 1e-9,
#: i.e. E = (1/2) (q t) (omega t xi)^2 with omega = 2 pi n / 60 and t in mm.
#: Paper 002 prints it rounded as 5.48e-12.
ENERGY_CONSTANT = 0.5 * (2.0 * np.pi / 60.0) ** 2 * 1e-9

#: Limit of the specific impact energy [J/m^2]: the paper's (3...4)e-4 J/mm^2,
#: after GOST 13568-97 (Paper 002, eq. (7) and its ref. [4]). The lower value
#: gives eq. (8)'s constant 7400.
G_LIM = (300.0, 400.0)

#: Relative rounding tolerated at the admissible limit of the base radius.
_ROUNDING = 1e-12

def base_radius(
    module: ArrayLike, teeth: ArrayLike, profile_angle: ArrayLike
) -> float | np.ndarray:
    """Base-circle radius of an involute sprocket.

    Parameters
    ----------
    module : float or array_like
        Module m of the cutting tool [m].
    teeth : int or array_like
        Number of sprocket teeth z [-].
    profile_angle : float or array_like
        Profile angle alpha of the cutting tool [rad].

    Returns
    -------
    float or numpy.ndarray
        Base radius r_b = m z cos(alpha) / 2 [m].

    References
    ----------
    Paper 002, eq. (4).
    """
    m = positive("module", module)
    z = whole_teeth("teeth", teeth)
    return scalar_or_array(m * z * np.cos(profile_angle) / 2.0)


def impact_angle(teeth: ArrayLike, base_radius: ArrayLike, pitch: ArrayLike) -> float | np.ndarray:
    """Pressure angle Theta of the chain joint on an involute tooth.

    Parameters
    ----------
    teeth : int or array_like
        Number of sprocket teeth z [-].
    base_radius : float or array_like
        Base-circle radius r_b of the involute [m]; at most
        ``pitch / (2 sin(pi / z))``.
    pitch : float or array_like
        Current chain pitch t_K [m].

    Returns
    -------
    float or numpy.ndarray
        Theta = pi / z + delta_K with delta_K = acos(2 r_b sin(pi/z) / t_K) [rad].

    Raises
    ------
    ValueError
        If `base_radius` exceeds ``pitch / (2 sin(pi / z))`` (the acos has no
        real value) or an input is out of its domain.

    References
    ----------
    Paper 002, eq. (3).
    """
    z = whole_teeth("teeth", teeth)
    r_b = non_negative("base_radius", base_radius)
    t = positive("pitch", pitch)
    ratio = 2.0 * r_b * np.sin(np.pi / z) / t
    if np.any(ratio > 1.0 + _ROUNDING):
        raise ValueError(
            "base_radius must not exceed pitch / (2 sin(pi / teeth)) "
            f"(Paper 002, eq. (3)); got base_radius={base_radius!r}, pitch={pitch!r}, "
            f"teeth={teeth!r}"
        )
    return scalar_or_array(np.pi / z + np.arccos(np.minimum(ratio, 1.0)))


def impact_velocity_coefficient(
    teeth: ArrayLike, base_radius: ArrayLike, pitch: ArrayLike
) -> float | np.ndarray:
    """Impact-velocity coefficient xi of a roller chain on an involute sprocket.

    Parameters
    ----------
    teeth : int or array_like
        Number of sprocket teeth z [-].
    base_radius : float or array_like
        Base-circle radius r_b of the involute [m] (see :func:`base_radius`).
    pitch : float or array_like
        Current chain pitch t_K [m].

    Returns
    -------
    float or numpy.ndarray
        xi = sin(Theta) [-].

    Notes
    -----
    xi lies within :func:`impact_velocity_coefficient_bounds` when
    ``pitch cos(pi/z) <= base_radius <= pitch / (2 sin(pi/z))`` and z >= 4;
    below that base radius Theta passes pi/2 and xi rises towards 1 (reached
    at r_b = t_K / 2).

    References
    ----------
    Paper 002, eqs. (3) and (5).
    """
    return scalar_or_array(np.sin(impact_angle(teeth, base_radius, pitch)))


def impact_velocity_coefficient_bounds(
    teeth: ArrayLike,
) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Bounds of xi for a sprocket of z teeth: sin(pi/z) and cos(pi/z).

    Parameters
    ----------
    teeth : int or array_like
        Number of sprocket teeth z [-], at least 4.

    Returns
    -------
    tuple of float or numpy.ndarray
        ``(sin(pi/z), cos(pi/z))`` [-]: xi at the largest admissible base
        radius (delta_K = 0) and at r_b = t_K cos(pi/z) (Theta = pi/2 - pi/z).

    References
    ----------
    Paper 002, eq. (3); ``docs/models/paper-002-roller-impact.md``.
    """
    z = whole_teeth("teeth", teeth, minimum=4)
    return scalar_or_array(np.sin(np.pi / z)), scalar_or_array(np.cos(np.pi / z))


def impact_velocity(omega: ArrayLike, pitch: ArrayLike, xi: ArrayLike) -> float | np.ndarray:
    """Normal impact velocity of the chain joint on the sprocket tooth.

    Parameters
    ----------
    omega : float or array_like
        Sprocket angular velocity [rad/s].
    pitch : float or array_like
        Current chain pitch t_K [m].
    xi : float or array_like
        Impact-velocity coefficient [-].

    Returns
    -------
    float or numpy.ndarray
        V_y = omega t_K xi [m/s].

    References
    ----------
    Paper 002, eqs. (2) and (5).
    """
    w = non_negative("omega", omega)
    t = positive("pitch", pitch)
    x = non_negative("xi", xi)
    return scalar_or_array(w * t * x)


def impact_energy(
    mass_per_length: ArrayLike, omega: ArrayLike, pitch: ArrayLike, xi: ArrayLike
) -> float | np.ndarray:
    """Kinetic energy of the impact of one chain link on the sprocket tooth.

    Parameters
    ----------
    mass_per_length : float or array_like
        Chain mass per metre q [kg/m].
    omega : float or array_like
        Sprocket angular velocity [rad/s].
    pitch : float or array_like
        Chain pitch t [m].
    xi : float or array_like
        Impact-velocity coefficient [-].

    Returns
    -------
    float or numpy.ndarray
        E = (1/2) (q t) (omega t xi)^2 [J]: one link of mass q t striking with
        the velocity V_y.

    See Also
    --------
    impact_energy_paper : the same in the paper's form and units.

    References
    ----------
    Paper 002, eq. (6) (corrected exponent, ``docs/models/paper-002-roller-impact.md``).
    """
    q = positive("mass_per_length", mass_per_length)
    t = positive("pitch", pitch)
    velocity = impact_velocity(omega, t, xi)
    return scalar_or_array(0.5 * q * t * np.square(velocity))


def impact_energy_paper(
    q_kg_per_m: ArrayLike, xi: ArrayLike, n_rpm: ArrayLike, t_mm: ArrayLike
) -> float | np.ndarray:
    """Impact energy in the paper's form and units, E = C q xi^2 n^2 t^3.

    Parameters
    ----------
    q_kg_per_m : float or array_like
        Chain mass per metre [kg/m].
    xi : float or array_like
        Impact-velocity coefficient [-].
    n_rpm : float or array_like
        Sprocket speed [rpm].
    t_mm : float or array_like
        Chain pitch [mm].

    Returns
    -------
    float or numpy.ndarray
        Impact energy [J], with C = :data:`ENERGY_CONSTANT`.

    References
    ----------
    Paper 002, eq. (6) (printed constant 5.48e-12; corrected exponent).

    Examples
    --------
    >>> round(impact_energy_paper(3.8, 0.8, 500.0, 31.75), 4)
    0.1067
    """
    q = positive("q_kg_per_m", q_kg_per_m)
    x = non_negative("xi", xi)
    n = non_negative("n_rpm", n_rpm)
    t = positive("t_mm", t_mm)
    return scalar_or_array(ENERGY_CONSTANT * q * x**2 * n**2 * t**3)


def specific_impact_energy(
    energy: ArrayLike, roller_diameter: ArrayLike, roller_length: ArrayLike
) -> float | np.ndarray:
    """Impact energy per unit projected roller area, G = E / (D L).

    Parameters
    ----------
    energy : float or array_like
        Impact energy E [J].
    roller_diameter : float or array_like
        Roller diameter D [m].
    roller_length : float or array_like
        Roller length L [m] (the paper's eq. (8) uses the inner width B).

    Returns
    -------
    float or numpy.ndarray
        G [J/m^2]; the paper's limit is :data:`G_LIM`.

    References
    ----------
    Paper 002, eq. (7) (corrected constant and unit,
    ``docs/models/paper-002-roller-impact.md``).
    """
    e = non_negative("energy", energy)
    diameter = positive("roller_diameter", roller_diameter)
    length = positive("roller_length", roller_length)
    return scalar_or_array(e / (diameter * length))


def max_angular_velocity(
    mass_per_length: ArrayLike,
    pitch: ArrayLike,
    xi: ArrayLike,
    roller_diameter: ArrayLike,
    roller_length: ArrayLike,
    g_lim: ArrayLike = G_LIM[0],
) -> float | np.ndarray:
    """Sprocket speed at which the specific impact energy reaches `g_lim`.

    Parameters
    ----------
    mass_per_length : float or array_like
        Chain mass per metre q [kg/m].
    pitch : float or array_like
        Chain pitch t [m].
    xi : float or array_like
        Impact-velocity coefficient [-].
    roller_diameter : float or array_like
        Roller diameter D [m].
    roller_length : float or array_like
        Roller length L [m]; eq. (8) uses the inner width B between the inner
        plates.
    g_lim : float or array_like, optional
        Limit of the specific impact energy [J/m^2]. Default: the lower end
        of :data:`G_LIM` (3e-4 J/mm^2), with which the result is eq. (8).

    Returns
    -------
    float or numpy.ndarray
        omega_max = sqrt(2 g_lim D L / (q t)) / (xi t) [rad/s]; in rpm with
        g_lim = 3e-4 J/mm^2 and lengths in mm this is
        n_max = 7400 / (xi t) sqrt(D B / (q t)).

    References
    ----------
    Paper 002, eqs. (6)-(8).
    """
    q = positive("mass_per_length", mass_per_length)
    t = positive("pitch", pitch)
    x = positive("xi", xi)
    area = positive("roller_diameter", roller_diameter) * positive("roller_length", roller_length)
    limit = positive("g_lim", g_lim)
    return scalar_or_array(np.sqrt(2.0 * limit * area / (q * t)) / (x * t))


def table(
    chain: Mapping[str, float],
    teeth: Sequence[int],
    rpm: Sequence[float],
    xi: float | None,
    module: float,
    profile_angle: float,
    g_lim: float,
) -> list[dict]:
    """Impact velocity, impact energy and speed limit per number of teeth and speed.

    Parameters
    ----------
    chain : mapping
        The chain's pitch ``t`` [m], ``mass_per_length`` [kg/m],
        ``roller_diameter`` and ``inner_width`` [m].
    teeth : sequence of int
        Numbers of sprocket teeth z [-] (varying slowest).
    rpm : sequence of float
        Sprocket speeds n [rpm].
    xi : float or None
        Impact-velocity coefficient [-]; None: xi of the involute sprocket
        (eqs. (3)-(5)).
    module : float
        Module m of the involute sprocket [m].
    profile_angle : float
        Tool profile angle alpha [rad].
    g_lim : float
        Limit of the specific impact energy [J/m^2].

    Returns
    -------
    list of dict
        One row per (z, n) in the units its keys name: ``z``, ``n_rpm``,
        ``xi_min``, ``xi_max`` (eq. (5)), ``xi``, ``v_y_m_per_s``, ``energy_J``
        (eq. (6)), ``G_J_per_mm2`` (eq. (7)), ``n_max_rpm`` (eq. (8)) and
        ``below_n_max``.

    References
    ----------
    Paper 002, eqs. (3)-(8).
    """
    z, n_rpm = (grid.ravel() for grid in np.meshgrid(teeth, rpm, indexing="ij"))
    t, q = chain["t"], chain["mass_per_length"]
    diameter, width = chain["roller_diameter"], chain["inner_width"]
    if xi is None:
        xi_z = impact_velocity_coefficient(z, base_radius(module, z, profile_angle), t)
    else:
        xi_z = np.full(z.shape, xi)
    low, high = impact_velocity_coefficient_bounds(z)
    omega = to_si(n_rpm, "rpm")
    energy = impact_energy(q, omega, t, xi_z)
    n_max = from_si(max_angular_velocity(q, t, xi_z, diameter, width, g_lim), "rpm")
    columns = {
        "z": z.astype(int).tolist(),
        "n_rpm": n_rpm,
        "xi_min": low,
        "xi_max": high,
        "xi": xi_z,
        "v_y_m_per_s": impact_velocity(omega, t, xi_z),
        "energy_J": energy,
        "G_J_per_mm2": from_si(specific_impact_energy(energy, diameter, width), "J/mm^2"),
        "n_max_rpm": n_max,
        "below_n_max": n_rpm <= n_max,
    }
    return rows(columns)


def table_notes(xi: float | None, module: float, profile_angle: float) -> list[str]:
    """How :func:`table` got xi, and Paper 002's printed constants beside the derived ones.

    Parameters
    ----------
    xi : float or None
        As given to :func:`table`.
    module : float
        Module of the involute sprocket [m].
    profile_angle : float
        Tool profile angle [rad].
    """
    how = (
        f"xi given ({xi:g}), not computed"
        if xi is not None
        else f"xi of an involute sprocket, m = {from_si(module, 'mm'):.4g} mm, alpha = "
        f"{math.degrees(profile_angle):g} deg (eqs. (3)-(5)); xi for the GOST 591/592 profiles "
        "cannot be derived from Paper 002: read it off its Fig. 2 and give --xi"
    )
    constants = [
        f"{row.source}: {row.quantity} published {row.published:.4g}, "
        f"derived {row.model:.5g} {row.unit}" + ("" if row.reproduced else f"; {row.note}")
        for row in compare_published().itertuples()
    ]
    return [how, *constants]


def compare_published() -> pd.DataFrame:
    """Paper 002's printed constants beside the model's.

    Returns
    -------
    pandas.DataFrame
        One row per number of ``pipeline/data/published/paper_002.csv``: the
        constant of eq. (6) (:func:`impact_energy` for unit inputs), its
        reciprocal printed in eq. (7), and the constant of eq. (8)
        (:func:`max_angular_velocity` for unit inputs, in rpm); columns as
        :func:`pipeline.theory._published.compare`.

    Examples
    --------
    >>> table = compare_published().set_index("quantity")
    >>> round(float(table.at["speed_limit_constant", "model"]))
    7397
    """
    return compare(
        "002",
        {
            "energy_constant": lambda inputs: impact_energy(**inputs),
            "specific_energy_denominator": lambda inputs: 1.0 / impact_energy(**inputs),
            "speed_limit_constant": lambda inputs: from_si(max_angular_velocity(**inputs), "rpm"),
        },
    )
