"""Loads on the segmented teeth of a chain drum (Paper 003).

Dolipski, Remiorz, Sobota and Osadnik replace the flank reaction F, assumed
in the symmetry plane of the tooth groove, by the two forces F_K that the rear
torus of the horizontal link exerts on the two tooth segments either side of
the groove, at the contact points K a distance s apart.

Units: lengths in m and angles in rad at the interface (SI), except where a
name ends in ``_mm`` or ``_deg``.

Notes
-----
The seed's eq. (3) is OCR-garbled (it prints k where s belongs and would
always give 0.577); :func:`contact_force_ratio` uses the corrected form of
``docs/models/paper-003-tooth-segments.md``,
F_K / F = 1 / (2 sin(psi / 2)), which reproduces every published ratio.

Against the paper's claims the model gives (chain 34x126):

* F_P / F exceeds 0.5 only for s above about 67.9 mm (beta = 50 deg,
  eps_n = 0), not "in the analysed range" of s as the paper says of Fig. 8.
* The friction increase 2 F_K / F - 1 at s = 70 mm, beta = 50 deg is 46.0 %
  with eps_n = 0 and 50.6 % with eps_n = 6 deg: the paper's "over 50 %"
  (Fig. 9) holds for eps_n >= 5.3 deg.
* psi at s = 45 mm, beta = 80 deg is 128.45 deg, not the published 128.7 deg.

References
----------
Paper 003: Dolipski M., Remiorz E., Sobota P., Osadnik J., "Wyznaczenie
obciazenia segmentow zebow bebna lancuchowego" (determination of the load on
the tooth segments of a chain drum); journal and year not printed in the OCR'd
copy (its references run to 2011); no DOI found.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike
from scipy.optimize import brentq

from pipeline.theory._checks import arccos, non_negative, positive, scalar_or_array
from pipeline.theory._published import compare, parse_inputs
from pipeline.theory._tables import rows
from pipeline.units import from_si, to_si

#: Paper 003, section 4 (Figs. 8-9): the side force F_P exceeds ``side_force_ratio`` of F
#: "in the analysed range" of s (from the groove width to ``s_max`` [m]), and the
#: friction increase exceeds ``friction_increase`` [-] at ``s`` [m], ``beta`` [rad].
CLAIMS = {"side_force_ratio": 0.5, "friction_increase": 0.5, "s_max": 70e-3, "s": 70e-3,
          "beta": math.radians(50.0)}


def contact_radius(
    r_outer: ArrayLike, d: ArrayLike, beta: ArrayLike, eps_n: ArrayLike = 0.0
) -> float | np.ndarray:
    """Contact radius k of the link's rear torus on the tooth segment.

    Parameters
    ----------
    r_outer : float or array_like
        Outer radius r of the horizontal link's torus [m].
    d : float or array_like
        Link bar thickness [m].
    beta : float or array_like
        Inclination of the segment flank at the contact point [rad].
    eps_n : float or array_like, optional
        Inclination of the link to the pocket floor [rad]; 0 for a link lying
        on the pocket floor.

    Returns
    -------
    float or numpy.ndarray
        k = r - (d/2) [1 - cos(pi/2 - beta + eps_n)] [m].

    References
    ----------
    Paper 003, eq. (1).
    """
    r = positive("r_outer", r_outer)
    thickness = positive("d", d)
    angle = np.pi / 2.0 - np.asarray(beta, dtype=float) + np.asarray(eps_n, dtype=float)
    k = r - thickness / 2.0 * (1.0 - np.cos(angle))
    return scalar_or_array(positive("r_outer and d (contact radius k)", k))


def opening_angle(
    s: ArrayLike, k: ArrayLike, groove_width: ArrayLike | None = None
) -> float | np.ndarray:
    """Opening angle psi of the tooth segments at the contact points.

    Parameters
    ----------
    s : float or array_like
        Distance between the contact points on the two segments [m]; at
        least the groove width c (edge contact at s = c) and below 2 k.
    k : float or array_like
        Contact radius [m] (:func:`contact_radius`).
    groove_width : float or array_like, optional
        Width c of the groove for the vertical links [m]; when given, `s`
        is checked against it.

    Returns
    -------
    float or numpy.ndarray
        psi = 2 acos(s / (2 k)) [rad].

    Raises
    ------
    ValueError
        If ``s < groove_width`` or ``s >= 2 k``.

    References
    ----------
    Paper 003, eq. (2).
    """
    distance = positive("s", s)
    radius = positive("k", k)
    if groove_width is not None and np.any(distance < non_negative("groove_width", groove_width)):
        raise ValueError(
            f"s must be at least the groove width c (Paper 003, eq. (2)); "
            f"got s={s!r}, groove_width={groove_width!r}"
        )
    if np.any(distance >= 2.0 * radius):
        raise ValueError(
            f"s must be below 2 k, the contact diameter (Paper 003, eq. (2)); got s={s!r}, k={k!r}"
        )
    return scalar_or_array(2.0 * arccos("s", distance / (2.0 * radius)))


def contact_force_ratio(psi: ArrayLike) -> float | np.ndarray:
    """Force on each segment over the symmetric-plane force, F_K / F.

    Parameters
    ----------
    psi : float or array_like
        Segment opening angle [rad] (:func:`opening_angle`).

    Returns
    -------
    float or numpy.ndarray
        F_K / F = 1 / (2 sin(psi / 2)) [-].

    References
    ----------
    Paper 003, eq. (3) (corrected form, ``docs/models/paper-003-tooth-segments.md``).
    """
    return scalar_or_array(1.0 / (2.0 * np.sin(_half_angle(psi))))


def side_force_ratio(psi: ArrayLike) -> float | np.ndarray:
    """Side component of the segment force over the symmetric-plane force, F_P / F.

    Parameters
    ----------
    psi : float or array_like
        Segment opening angle [rad] (:func:`opening_angle`).

    Returns
    -------
    float or numpy.ndarray
        F_P / F = 1 / (2 tan(psi / 2)) [-].

    References
    ----------
    Paper 003, eq. (4).
    """
    return scalar_or_array(1.0 / (2.0 * np.tan(_half_angle(psi))))


def friction_increase(psi: ArrayLike) -> float | np.ndarray:
    """Relative increase of the flank friction force at equal friction coefficient.

    Parameters
    ----------
    psi : float or array_like
        Segment opening angle [rad] (:func:`opening_angle`).

    Returns
    -------
    float or numpy.ndarray
        2 F_K / F - 1 [-]: the friction from the two segment forces F_K over
        that from F, minus one.

    References
    ----------
    Paper 003, section 4 and Fig. 9.
    """
    return scalar_or_array(2.0 * np.asarray(contact_force_ratio(psi)) - 1.0)


def _half_angle(psi: ArrayLike) -> np.ndarray:
    """psi / 2, raising unless 0 < psi < pi (an opening angle of eq. (2))."""
    angle = positive("psi", psi)
    if np.any(angle >= np.pi):
        raise ValueError(f"psi must be below pi rad (Paper 003, eq. (2)); got psi={psi!r}")
    return angle / 2.0


def table(
    chain: Mapping[str, float],
    beta_deg: Sequence[float],
    eps_n_deg: Sequence[float],
    s_mm: Sequence[float],
) -> list[dict]:
    """The segment loads per flank inclination, link inclination and contact distance.

    Parameters
    ----------
    chain : mapping
        The chain's outer torus radius ``r_outer``, link thickness ``d`` and
        the drum's ``groove_width`` c [m].
    beta_deg : sequence of float
        Flank inclinations beta [deg] (varying slowest).
    eps_n_deg : sequence of float
        Link inclinations to the pocket floor eps_n [deg].
    s_mm : sequence of float
        Distances s between the contact points [mm].

    Returns
    -------
    list of dict
        One row per (beta, eps_n, s) in the units its keys name: ``beta_deg``,
        ``eps_n_deg``, ``s_mm``, ``k_mm`` (eq. (1)), ``psi_deg`` (eq. (2)),
        ``F_K/F`` (eq. (3)), ``F_P/F`` and ``friction_increase_pct``.

    Raises
    ------
    ValueError
        When an s is below the groove width or at least 2 k.

    References
    ----------
    Paper 003, eqs. (1)-(4).
    """
    grids = np.meshgrid(beta_deg, eps_n_deg, s_mm, indexing="ij")
    beta, eps_n, s = (grid.ravel() for grid in grids)
    k = contact_radius(chain["r_outer"], chain["d"], np.radians(beta), np.radians(eps_n))
    psi = opening_angle(to_si(s, "mm"), k, chain["groove_width"])
    columns = {
        "beta_deg": beta,
        "eps_n_deg": eps_n,
        "s_mm": s,
        "k_mm": from_si(k, "mm"),
        "psi_deg": np.degrees(psi),
        "F_K/F": contact_force_ratio(psi),
        "F_P/F": side_force_ratio(psi),
        "friction_increase_pct": 100.0 * friction_increase(psi),
    }
    return rows(columns)


def published_notes(chain: Mapping[str, float], published: pd.DataFrame) -> list[str]:
    """How many of Paper 003's values the model reproduces, and each it does not.

    Parameters
    ----------
    chain : mapping
        The chain's ``r_outer`` and ``d`` [m]: notes only for the paper's chain.
    published : pandas.DataFrame
        :func:`compare_published`.

    Returns
    -------
    list of str
        None for another chain; else a count, then one line per value not
        reproduced (published, model, difference and tolerance).
    """
    paper = [parse_inputs(inputs) for inputs in published["inputs"]]
    if not all(
        math.isclose(chain["r_outer"], inputs["r_outer"]) and math.isclose(chain["d"], inputs["d"])
        for inputs in paper
    ):
        return []
    flagged = published[~published["reproduced"]]
    summary = (
        f"Paper 003 (r = {from_si(paper[0]['r_outer'], 'mm'):g} mm, "
        f"d = {from_si(paper[0]['d'], 'mm'):g} mm): {len(published) - len(flagged)} of "
        f"{len(published)} published values reproduced"
    )
    return [summary, *(_not_reproduced(row) for row in flagged.itertuples())]


def _not_reproduced(row) -> str:
    """One line for a published value the model does not reproduce (a row of the comparison)."""
    return (
        f"{row.source}: {row.quantity} ({row.inputs}): published {row.published:g} {row.unit}, "
        f"model {row.model:.5g} ({100 * row.rel_diff:+.2f} %): NOT reproduced "
        f"within {100 * row.tolerance:g} %"
    )


def side_force_threshold(chain: Mapping[str, float], beta: float) -> float:
    """Where F_P / F reaches the share Paper 003 claims exceeded (:data:`CLAIMS`), eps_n = 0.

    Parameters
    ----------
    chain : mapping
        The chain's ``r_outer``, ``d`` and the drum's ``groove_width`` [m].
    beta : float
        Flank inclination [rad].

    Returns
    -------
    float
        The contact distance s [m] between the groove width and the claims'
        ``s_max``; NaN when F_P / F does not reach the share there.
    """
    radius = contact_radius(chain["r_outer"], chain["d"], beta, 0.0)

    def excess(s: float) -> float:
        psi = opening_angle(s, radius, chain["groove_width"])
        return float(side_force_ratio(psi)) - CLAIMS["side_force_ratio"]

    low, high = chain["groove_width"], CLAIMS["s_max"]
    if excess(low) * excess(high) > 0:
        return math.nan
    return float(brentq(excess, low, high))


def claims_note(chain: Mapping[str, float], beta: Sequence[float], eps_n: Sequence[float]
                ) -> str:
    """What the model gives against Paper 003's claims (:data:`CLAIMS`), in words.

    Parameters
    ----------
    chain : mapping
        The chain's ``r_outer``, ``d`` and the drum's ``groove_width`` [m].
    beta : sequence of float
        Flank inclinations [rad] to find where F_P / F reaches the claimed share
        (:func:`side_force_threshold`).
    eps_n : sequence of float
        Link inclinations [rad] to give the friction increase for, at the
        claims' s and beta.

    Returns
    -------
    str
        Two sentences: each claim, and the model's values against it.
    """
    found = {math.degrees(angle): side_force_threshold(chain, angle) for angle in beta}
    thresholds = [f"{1e3 * s:.1f} mm at β = {angle:g}°" for angle, s in found.items()
                  if math.isfinite(s)]
    increases = []
    for angle in eps_n:
        radius = contact_radius(chain["r_outer"], chain["d"], CLAIMS["beta"], angle)
        psi = opening_angle(CLAIMS["s"], radius, chain["groove_width"])
        increases.append(f"{100 * float(friction_increase(psi)):.1f} % with "
                         f"ε_n = {math.degrees(angle):g}°")
    return (f"The paper says F_P exceeds 50 % of F over its whole range of s; with ε_n = 0 "
            f"the model's F_P/F passes 0.5 only above s = {', '.join(thresholds) or 'none'} "
            f"(never below {1e3 * CLAIMS['s_max']:g} mm for the other β). The paper says the "
            f"friction increase exceeds 50 % at s = {1e3 * CLAIMS['s']:g} mm, "
            f"β = {math.degrees(CLAIMS['beta']):g}°; the model gives {' and '.join(increases)}.")


def compare_published() -> pd.DataFrame:
    """Paper 003's published values for chain 34x126 beside the model's.

    Returns
    -------
    pandas.DataFrame
        One row per number of ``pipeline/data/published/paper_003.csv``: the
        contact radius k [mm] (eq. (1)), the opening angle psi [deg] (eq. (2))
        and F_K / F [-] (eq. (3)), each with the row's r_outer, d, beta, eps_n
        and s; columns as :func:`pipeline.theory._published.compare`.

    Examples
    --------
    >>> table = compare_published().set_index("quantity")
    >>> round(float(table.at["opening_angle_s45_beta80_eps0", "model"]), 2)
    128.45
    """
    return compare(
        "003",
        {
            "contact_radius": lambda inputs: from_si(_contact_radius_of(inputs), "mm"),
            "opening_angle": lambda inputs: np.degrees(_opening_angle_of(inputs)),
            "contact_force_ratio": lambda inputs: contact_force_ratio(_opening_angle_of(inputs)),
        },
    )


def _contact_radius_of(inputs: dict) -> float:
    """k [m] for a row's r_outer, d, beta, eps_n (eq. (1))."""
    return contact_radius(inputs["r_outer"], inputs["d"], inputs["beta"], inputs["eps_n"])


def _opening_angle_of(inputs: dict) -> float:
    """psi [rad] for a row's r_outer, d, beta, eps_n and s (eqs. (1)-(2))."""
    return opening_angle(inputs["s"], _contact_radius_of(inputs))
