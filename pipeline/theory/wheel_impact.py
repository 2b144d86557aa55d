"""Impact tension of a round-link chain on a pocket wheel (Paper 000).

Rynik J., Dolipski M.: *Napięcia udarowe łańcucha ogniwowego współpracującego
z kołem gniazdowym* (impact tension of a link chain engaging a pocket wheel).
Journal, year and pages are not printed in the OCR'd copy (its references run
to 1978); no DOI found. Formulas as corrected in
``docs/models/paper-000-wheel-impact.md``.

A horizontal link seating in its pocket strikes the wheel twice: first the idle
flank of one tooth (point C, velocity ``v_u1``), then, a time ``tau = pi/(z
omega)`` later, the working flank of the next tooth (point G, ``v_u2``). The
impact energy of ``k`` link masses, eqs. (10)-(11), turns into elastic energy of
the active branch, eq. (14); the balance, eq. (15), gives the impact tension
``N_u``, eq. (16): the peak tension of an undamped branch.

Symbols and units (SI at the interface): ``t`` chain pitch [m], ``d`` bar
diameter [m], ``z`` number of teeth (pockets) [-], ``psi`` tooth apex angle
[rad], ``omega`` wheel angular velocity [1/s], ``mass_per_length`` chain mass
per metre q/g [kg/m], ``E0`` chain stiffness [N], ``branch_length`` length L of
the active branch [m], ``k`` share of link masses in the impact [-].

Every function broadcasts its array arguments against each other (e.g. ``z`` as
a column and ``psi`` as a row give the whole grid) and raises ``ValueError``
naming the parameter when an input is outside the model's domain.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Final, NamedTuple, TypeAlias

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.theory import _checks
from pipeline.theory._published import compare, parse_inputs, read_published

#: Share of link masses taking part in the impact, k [-]: the reduced mass of the
#: branch equals twice the mass of one link. Ryabov G.K., Vestnik
#: Mashinostroeniya 8/1968 (Paper 000, ref. [1]); used in Paper 000, eq. (11).
RYABOV_MASS_SHARE: Final = 2.0

#: A float or an array of floats (0-d results come back as float).
ScalarOrArray: TypeAlias = float | np.ndarray

#: The columns of :func:`table` and their units.
TABLE_UNITS = {
    "z": "1",
    "psi_deg": "deg",
    "v_u1": "m/s",
    "v_u2": "m/s",
    "N_u1": "N",
    "N_u2": "N",
    "N_u2/N_u1": "1",
    "tau": "s",
}


class _Engagement(NamedTuple):
    """Geometry of one seating link: R, delta1, delta2, R_C, alpha1, alpha2 [m, rad]."""

    radius: np.ndarray
    delta1: np.ndarray
    delta2: np.ndarray
    impact_radius: np.ndarray
    alpha1: np.ndarray
    alpha2: np.ndarray


def _chain_and_wheel(
    t: ArrayLike, d: ArrayLike, z: ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Validated pitch, bar diameter and number of teeth as float arrays."""
    t = _checks.positive("t", t)
    d = _checks.positive("d", d)
    if np.any(d >= t):
        raise ValueError(f"d (bar diameter) must be smaller than t (pitch), got d={d!r}, t={t!r}")
    z = _checks.teeth("z", z)
    return t, d, z


def _apex_angle(psi: ArrayLike) -> np.ndarray:
    """Validated tooth apex angle psi in (0, pi) [rad]."""
    psi = _checks.positive("psi", psi)
    if np.any(psi >= np.pi):
        raise ValueError(f"psi (tooth apex angle) must be below pi rad (180 deg), got {psi!r}")
    return psi


def _pitch_radius(t: np.ndarray, d: np.ndarray, z: np.ndarray) -> np.ndarray:
    """Eq. (3) on validated inputs."""
    half_pitch_angle = np.pi / (2 * z)
    return 0.5 * np.hypot(t / np.sin(half_pitch_angle), d / np.cos(half_pitch_angle))


def _central_angles(
    t: np.ndarray, d: np.ndarray, radius: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Eqs. (7)-(8) on validated inputs."""
    delta1 = 2 * _checks.arcsin("t, d, z", (t + d) / (2 * radius))
    delta2 = 2 * _checks.arcsin("t, d, z", (t - d) / (2 * radius))
    return delta1, delta2


def _engagement(t: np.ndarray, d: np.ndarray, z: np.ndarray, psi: np.ndarray) -> _Engagement:
    """Eqs. (3)-(8) on validated inputs."""
    radius = _pitch_radius(t, d, z)
    delta1, delta2 = _central_angles(t, d, radius)
    half_angle = (delta2 + psi) / 2
    impact_radius = np.sqrt(radius**2 + d**2 / 4 - radius * d * np.sin(half_angle))
    gamma = _checks.arcsin("t, d, z, psi", d / (2 * impact_radius) * np.cos(half_angle))
    alpha1, alpha2 = delta1 / 2 + gamma, delta2 / 2 - gamma
    return _Engagement(radius, delta1, delta2, impact_radius, alpha1, alpha2)


def pitch_radius(t: ArrayLike, d: ArrayLike, z: ArrayLike) -> ScalarOrArray:
    r"""Pitch-circle radius R of the pocket wheel.

    Parameters
    ----------
    t : float or array_like
        Chain pitch (inner link length) [m].
    d : float or array_like
        Bar diameter of the links [m], below `t`.
    z : int or array_like
        Number of teeth (pockets) [-], a whole number >= 3.

    Returns
    -------
    float or numpy.ndarray
        R [m]: the radius of the circle through the centres of the link joints.

    Notes
    -----
    .. math:: R = \tfrac12 \sqrt{(t / \sin\tfrac{\pi}{2z})^2 + (d / \cos\tfrac{\pi}{2z})^2}

    References
    ----------
    Paper 000, eq. (3).

    Examples
    --------
    Chain 18x64 on a six-pocket wheel:

    >>> round(pitch_radius(0.064, 0.018, 6) * 1000, 2)
    123.99
    """
    return _checks.scalar_or_array(_pitch_radius(*_chain_and_wheel(t, d, z)))


def central_angles(t: ArrayLike, d: ArrayLike, z: ArrayLike) -> tuple[ScalarOrArray, ScalarOrArray]:
    """Central angles of the pitch circle spanned by the horizontal and vertical links.

    Parameters
    ----------
    t, d : float or array_like
        Chain pitch and bar diameter [m], ``0 < d < t``.
    z : int or array_like
        Number of teeth [-], a whole number >= 3.

    Returns
    -------
    delta1, delta2 : float or numpy.ndarray
        delta1 = 2 asin((t + d) / (2R)) of the horizontal link and
        delta2 = 2 asin((t - d) / (2R)) of the vertical link [rad]; their sum
        is the tooth pitch angle 2 pi / z (eq. (9)).

    References
    ----------
    Paper 000, eqs. (7)-(9).

    Examples
    --------
    >>> delta1, delta2 = central_angles(0.064, 0.018, 8)
    >>> round(float(np.degrees(delta1 + delta2)), 12)
    45.0
    """
    t, d, z = _chain_and_wheel(t, d, z)
    delta1, delta2 = _central_angles(t, d, _pitch_radius(t, d, z))
    return _checks.scalar_or_array(delta1), _checks.scalar_or_array(delta2)


def impact_radius(t: ArrayLike, d: ArrayLike, z: ArrayLike, psi: ArrayLike) -> ScalarOrArray:
    r"""Distance R_C = R_G of the impact points C and G from the wheel axis.

    Parameters
    ----------
    t, d : float or array_like
        Chain pitch and bar diameter [m], ``0 < d < t``.
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    psi : float or array_like
        Tooth apex angle [rad], in (0, pi).

    Returns
    -------
    float or numpy.ndarray
        R_C = R_G [m].

    Notes
    -----
    .. math:: R_C = R_G = \sqrt{R^2 + d^2/4 - R d \sin\frac{\delta_2 + \psi}{2}}

    References
    ----------
    Paper 000, eq. (4).

    Examples
    --------
    >>> round(impact_radius(0.064, 0.018, 6, np.radians(40)) * 1000, 2)
    119.65
    """
    geometry = _engagement(*_chain_and_wheel(t, d, z), _apex_angle(psi))
    return _checks.scalar_or_array(geometry.impact_radius)


def contact_angles(
    t: ArrayLike, d: ArrayLike, z: ArrayLike, psi: ArrayLike
) -> tuple[ScalarOrArray, ScalarOrArray]:
    """Angles alpha1, alpha2 locating the impact points G and C.

    Parameters
    ----------
    t, d : float or array_like
        Chain pitch and bar diameter [m], ``0 < d < t``.
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    psi : float or array_like
        Tooth apex angle [rad], in (0, pi).

    Returns
    -------
    alpha1, alpha2 : float or numpy.ndarray
        alpha1 = delta1/2 + gamma and alpha2 = delta2/2 - gamma [rad], with
        gamma = asin(d / (2 R_C) cos((delta2 + psi)/2)).

    References
    ----------
    Paper 000, eqs. (5)-(6) (the seed's kappa is alpha).
    """
    geometry = _engagement(*_chain_and_wheel(t, d, z), _apex_angle(psi))
    return _checks.scalar_or_array(geometry.alpha1), _checks.scalar_or_array(geometry.alpha2)


def impact_velocities(
    t: ArrayLike, d: ArrayLike, z: ArrayLike, psi: ArrayLike, omega: ArrayLike
) -> tuple[ScalarOrArray, ScalarOrArray]:
    r"""Impact velocities of the seating link on the idle and the working tooth flank.

    Parameters
    ----------
    t, d : float or array_like
        Chain pitch and bar diameter [m], ``0 < d < t``.
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    psi : float or array_like
        Tooth apex angle [rad], in (0, pi).
    omega : float or array_like
        Angular velocity of the wheel [1/s], >= 0.

    Returns
    -------
    v_u1, v_u2 : float or numpy.ndarray
        Impact velocity on the idle flank (point C) and on the working flank
        (point G) [m/s].

    Notes
    -----
    Computed in the paper's form, the difference of the projections of the
    circumferential velocities of the wheel and of the joint centre on the
    common normal:

    .. math::

        v_{u1} = \omega [R \cos\tfrac{\psi - \delta_2}{2}
                 - R_C \cos(\tfrac{\psi}{2} + \alpha_2)]

        v_{u2} = \omega [R_G \cos(\tfrac{\pi}{z} + \tfrac{\psi}{2} - \alpha_1)
                 - R \cos(\tfrac{\pi}{z} + \tfrac{\psi}{2} + \tfrac{\delta_1}{2})]

    They reduce to v_u1 = omega (t - d) sin(psi/2), independent of z, and
    v_u2 = omega (t + d) sin(pi/z + psi/2) (``docs/models/paper-000-wheel-impact.md``).

    References
    ----------
    Paper 000, eqs. (1)-(2), with (3)-(8).

    Examples
    --------
    >>> v_u1, v_u2 = impact_velocities(0.064, 0.018, 8, np.radians(40), 20.0)
    >>> round(v_u1, 4), round(v_u2, 4)
    (0.3147, 1.108)
    """
    t, d, z = _chain_and_wheel(t, d, z)
    psi = _apex_angle(psi)
    omega = _checks.non_negative("omega", omega)
    geo = _engagement(t, d, z, psi)
    v_u1 = omega * (
        geo.radius * np.cos((psi - geo.delta2) / 2)
        - geo.impact_radius * np.cos(psi / 2 + geo.alpha2)
    )
    lead = np.pi / z + psi / 2
    v_u2 = omega * (
        geo.impact_radius * np.cos(lead - geo.alpha1) - geo.radius * np.cos(lead + geo.delta1 / 2)
    )
    return _checks.scalar_or_array(v_u1), _checks.scalar_or_array(v_u2)


def link_mass(mass_per_length: ArrayLike, t: ArrayLike) -> ScalarOrArray:
    """Mass m0 of one link [kg]: m0 = q t / g = (mass per metre) t.

    Parameters
    ----------
    mass_per_length : float or array_like
        Chain mass per metre q/g [kg/m].
    t : float or array_like
        Chain pitch [m].

    References
    ----------
    Paper 000, eq. (11).
    """
    mass = _checks.positive("mass_per_length", mass_per_length) * _checks.positive("t", t)
    return _checks.scalar_or_array(mass)


def impact_energy(
    v_u: ArrayLike, mass_per_length: ArrayLike, t: ArrayLike, k: ArrayLike = RYABOV_MASS_SHARE
) -> ScalarOrArray:
    """Kinetic energy E_u released by one impact of the chain on a tooth.

    Parameters
    ----------
    v_u : float or array_like
        Impact velocity [m/s], >= 0.
    mass_per_length : float or array_like
        Chain mass per metre q/g [kg/m].
    t : float or array_like
        Chain pitch [m].
    k : float or array_like, optional
        Share of link masses in the impact [-], > 0. Default
        :data:`RYABOV_MASS_SHARE` = 2 (Ryabov, Paper 000 ref. [1]).

    Returns
    -------
    float or numpy.ndarray
        E_u = k m0 v_u^2 / 2 [J], m0 = (mass per metre) t.

    References
    ----------
    Paper 000, eqs. (10)-(11) (the seed's (12)-(13) lost the square: not used).

    Examples
    --------
    >>> round(impact_energy(1.0, 6.6, 0.064), 4)
    0.4224
    """
    v_u = _checks.non_negative("v_u", v_u)
    k = _checks.positive("k", k)
    return _checks.scalar_or_array(k * link_mass(mass_per_length, t) * v_u**2 / 2)


def elastic_energy(tension: ArrayLike, E0: ArrayLike, branch_length: ArrayLike) -> ScalarOrArray:
    """Elastic energy T stored in the active chain branch under `tension`.

    Parameters
    ----------
    tension : float or array_like
        Chain tension N [N], >= 0.
    E0 : float or array_like
        Chain stiffness (force over relative elongation) [N], > 0.
    branch_length : float or array_like
        Length L of the active branch [m], > 0.

    Returns
    -------
    float or numpy.ndarray
        T = N^2 L / (2 E0) [J].

    References
    ----------
    Paper 000, eq. (14).
    """
    tension = _checks.non_negative("tension", tension)
    E0 = _checks.positive("E0", E0)
    branch_length = _checks.positive("branch_length", branch_length)
    return _checks.scalar_or_array(tension**2 * branch_length / (2 * E0))


def impact_tension(
    v_u: ArrayLike,
    mass_per_length: ArrayLike,
    t: ArrayLike,
    E0: ArrayLike,
    branch_length: ArrayLike,
    k: ArrayLike = RYABOV_MASS_SHARE,
) -> ScalarOrArray:
    """Impact tension N_u of the active branch for an impact at velocity `v_u`.

    Parameters
    ----------
    v_u : float or array_like
        Impact velocity [m/s], >= 0.
    mass_per_length : float or array_like
        Chain mass per metre q/g [kg/m].
    t : float or array_like
        Chain pitch [m].
    E0 : float or array_like
        Chain stiffness [N].
    branch_length : float or array_like
        Length L of the active branch [m].
    k : float or array_like, optional
        Share of link masses in the impact [-]; default 2 (Ryabov).

    Returns
    -------
    float or numpy.ndarray
        N_u = v_u sqrt(k q t E0 / (g L)) [N], from the energy balance
        impact energy (10) = elastic energy (14): the peak tension of an
        undamped branch.

    References
    ----------
    Paper 000, eqs. (15)-(16) (the seed's (17)-(18) print R_C where R belongs).

    Examples
    --------
    Paper 000's example (18x64 chain, 6.6 kg/m, E0 = 2.26e7 N, L = 2 m):

    >>> round(impact_tension(1.0, 6.6, 0.064, 2.26e7, 2.0))
    3090
    """
    v_u = _checks.non_negative("v_u", v_u)
    k = _checks.positive("k", k)
    E0 = _checks.positive("E0", E0)
    branch_length = _checks.positive("branch_length", branch_length)
    tension = v_u * np.sqrt(k * link_mass(mass_per_length, t) * E0 / branch_length)
    return _checks.scalar_or_array(tension)


def impact_tensions(
    t: ArrayLike,
    d: ArrayLike,
    z: ArrayLike,
    psi: ArrayLike,
    omega: ArrayLike,
    mass_per_length: ArrayLike,
    E0: ArrayLike,
    branch_length: ArrayLike,
    k: ArrayLike = RYABOV_MASS_SHARE,
) -> tuple[ScalarOrArray, ScalarOrArray]:
    """Impact tensions N_u1 (idle flank) and N_u2 (working flank) of a wheel.

    Parameters
    ----------
    t, d : float or array_like
        Chain pitch and bar diameter [m], ``0 < d < t``.
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    psi : float or array_like
        Tooth apex angle [rad], in (0, pi).
    omega : float or array_like
        Angular velocity of the wheel [1/s], >= 0.
    mass_per_length : float or array_like
        Chain mass per metre q/g [kg/m].
    E0 : float or array_like
        Chain stiffness [N].
    branch_length : float or array_like
        Length L of the active branch [m].
    k : float or array_like, optional
        Share of link masses in the impact [-]; default 2 (Ryabov).

    Returns
    -------
    N_u1, N_u2 : float or numpy.ndarray
        Impact tensions [N] of the strikes on the idle and the working flank.

    References
    ----------
    Paper 000, eq. (16) with eqs. (1)-(2).

    Examples
    --------
    Paper 000's smallest N_u2 (published 2300 N) at z = 10, psi = 20 deg:

    >>> n_u1, n_u2 = impact_tensions(0.064, 0.018, 10, np.radians(20), 20.0, 6.6, 2.26e7, 2.0)
    >>> round(n_u1), round(n_u2)
    (494, 2379)
    """
    v_u1, v_u2 = impact_velocities(t, d, z, psi, omega)
    return tuple(
        impact_tension(v_u, mass_per_length, t, E0, branch_length, k) for v_u in (v_u1, v_u2)
    )


def time_between_impacts(z: ArrayLike, omega: ArrayLike) -> ScalarOrArray:
    """Time tau between the idle-flank and the working-flank impact [s].

    Parameters
    ----------
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    omega : float or array_like
        Angular velocity of the wheel [1/s], > 0.

    Returns
    -------
    float or numpy.ndarray
        tau = pi / (z omega) [s], half the seating period.

    References
    ----------
    Paper 000, section 2 (tau ~ pi / (z omega)).
    """
    return _checks.scalar_or_array(seating_period(z, omega) / 2)


def seating_period(z: ArrayLike, omega: ArrayLike) -> ScalarOrArray:
    """Time between the seating of two successive horizontal links [s].

    Parameters
    ----------
    z : int or array_like
        Number of teeth [-], a whole number >= 3.
    omega : float or array_like
        Angular velocity of the wheel [1/s], > 0.

    Returns
    -------
    float or numpy.ndarray
        2 pi / (z omega) [s]: one tooth pitch angle at speed omega.

    References
    ----------
    Paper 000, eq. (9) (tooth pitch angle 2 pi / z).
    """
    z = _checks.teeth("z", z)
    omega = _checks.positive("omega", omega)
    return _checks.scalar_or_array(2 * np.pi / (z * omega))


def paper_example() -> dict[str, float]:
    """The conditions of Paper 000's example (section 3), from ``paper_000.csv``.

    Returns
    -------
    dict
        ``t``, ``d`` [m], ``omega`` [1/s], ``mass_per_length`` [kg/m], ``E0``
        [N], ``branch_length`` [m] and ``k`` [-]: the inputs of the published
        smallest N_u2 without the wheel (z, psi). The paper prints neither q
        nor the chain's E0 for it: q = 6.6 kg/m is the DIN 22252 nominal mass
        of chain 18x64, E0 = 2.26e7 N the paper's citation of its ref. [3].
    """
    table = read_published("000").set_index("quantity")
    inputs = parse_inputs(table.at["N_u2_smallest", "inputs"])
    return {name: value for name, value in inputs.items() if name not in ("z", "psi")}


def table(
    t: float,
    d: float,
    teeth: Sequence[int],
    apex_deg: Sequence[float],
    omega: float,
    mass_per_length: float,
    E0: float,
    branch_length: float,
    k: float = RYABOV_MASS_SHARE,
) -> list[dict]:
    """Impact velocities and tensions per wheel (z) and apex angle (psi), z varying slowest.

    Parameters
    ----------
    t, d : float
        Chain pitch and bar diameter [m].
    teeth : sequence of int
        Numbers of teeth z [-].
    apex_deg : sequence of float
        Tooth apex angles psi [deg].
    omega : float
        Wheel angular velocity [1/s].
    mass_per_length : float
        Chain mass per metre q/g [kg/m].
    E0 : float
        Chain stiffness [N].
    branch_length : float
        Length L of the active branch [m].
    k : float
        Share of link masses in the impact [-] (Ryabov's 2).

    Returns
    -------
    list of dict
        One row per (z, psi): ``z``, ``psi_deg``, ``v_u1``, ``v_u2`` (eqs.
        (1)-(2)), ``N_u1``, ``N_u2`` (eq. (16)), ``N_u2/N_u1`` and ``tau``
        (eq. (9)), in the units of :data:`TABLE_UNITS`.

    Raises
    ------
    ValueError
        Naming the parameter outside the model's domain (``omega`` first).
    """
    z, psi_deg = (grid.ravel() for grid in np.meshgrid(teeth, apex_deg, indexing="ij"))
    tau = time_between_impacts(z, omega)  # first: it also rejects omega = 0
    v_u1, v_u2 = impact_velocities(t, d, z, np.radians(psi_deg), omega)
    n_u1, n_u2 = (impact_tension(v, mass_per_length, t, E0, branch_length, k)
                  for v in (v_u1, v_u2))
    columns = zip(z, psi_deg, v_u1, v_u2, n_u1, n_u2, n_u2 / n_u1, tau, strict=True)
    return [dict(zip(TABLE_UNITS, (int(row[0]), *map(float, row[1:])), strict=True))
            for row in columns]


def is_paper_chain(t: float, d: float) -> bool:
    """Whether pitch `t` and bar diameter `d` [m] are those of Paper 000's example chain."""
    example = paper_example()
    return math.isclose(t, example["t"]) and math.isclose(d, example["d"])


def published_notes(t: float, d: float) -> list[str]:
    """Paper 000's published numbers and whether the model reproduces them, for its chain.

    Parameters
    ----------
    t, d : float
        The chain's pitch and bar diameter [m]: notes only for the paper's chain
        (:func:`is_paper_chain`).

    Returns
    -------
    list of str
        The example's conditions, then one line per published number with the
        model's value and the verdict (:func:`compare_published`).
    """
    if not is_paper_chain(t, d):
        return []
    case = paper_example()
    notes = [
        f"Paper 000 (section 3) publishes, for q = {case['mass_per_length']:g} kg/m * g, "
        f"E0 = {case['E0']:g} N, L = {case['branch_length']:g} m, "
        f"omega = {case['omega']:g} 1/s, k = {case['k']:g}:"
    ]
    for row in compare_published().itertuples():
        unit = "" if row.unit == "-" else f" {row.unit}"
        status = "reproduced" if row.reproduced else "NOT REPRODUCED by the model"
        notes.append(
            f"  {row.quantity} = {row.published:g}{unit}, model {row.model:.4g}{unit}: {status} "
            f"(tolerance {100 * row.tolerance:g} %)"
        )
    return notes


def compare_published() -> pd.DataFrame:
    """Paper 000's published numbers beside the model's.

    Returns
    -------
    pandas.DataFrame
        One row per number of ``pipeline/data/published/paper_000.csv`` (the
        smallest N_u2 [N] and where it lies, z [-] and psi [deg], over the
        grid of the row's inputs, and N_u2 / N_u1 [-]), each beside
        :func:`impact_tensions` with the row's inputs; columns as
        :func:`pipeline.theory._published.compare`.

    Examples
    --------
    >>> table = compare_published().set_index("quantity")
    >>> round(float(table.at["N_u2_over_N_u1_z8_psi40", "model"]), 3)
    3.521
    """
    return compare(
        "000",
        {
            "N_u2_smallest": lambda inputs: impact_tensions(**inputs)[1],
            "z_of_smallest_N_u2": lambda inputs: _smallest_N_u2_at(inputs)[0],
            "psi_of_smallest_N_u2": lambda inputs: np.degrees(_smallest_N_u2_at(inputs)[1]),
            "N_u2_over_N_u1": _tension_ratio,
        },
    )


def _tension_ratio(inputs: dict) -> float:
    """N_u2 / N_u1 [-] of one operating point."""
    n_u1, n_u2 = impact_tensions(**inputs)
    return n_u2 / n_u1


def _smallest_N_u2_at(inputs: dict) -> tuple[float, float]:
    """(z [-], psi [rad]) of the smallest N_u2 over the grid of the inputs' z and psi."""
    z, psi = np.atleast_1d(inputs["z"]), np.atleast_1d(inputs["psi"])
    _, n_u2 = impact_tensions(**{**inputs, "z": z[:, None], "psi": psi[None, :]})
    row, column = np.unravel_index(np.argmin(n_u2), n_u2.shape)
    return float(z[row]), float(psi[column])
