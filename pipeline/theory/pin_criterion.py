"""Pin criterion for roller chains of open drives (Paper 004).

Kravchenko and Bogdanovych choose the chain of an open drive so that the
worn pin does not yield in bending before the pitch has grown to the limit at
which the chain jumps off the sprocket: the nominal pin diameter must cover
the critical (bending) diameter plus the wear allowed until jump-off, eq. (1).

Units: SI at the interface (lengths in m, forces in N, stresses in Pa,
moments in N m). The paper works in mm, N and MPa; being homogeneous, its
formulas hold in either system.

The paper publishes no numbers: the tests use the identity
M_max / W(d_k) = [sigma_T] and a hand-worked example
(``docs/models/paper-004-pin-criterion.md``).

References
----------
Paper 004: Kravchenko M.I., Bogdanovych S.A. (State Biotechnological
University), "Kryterii vyboru i dovhovichnist pryvidnykh vtulochno-rolykovykh
lantsiuhiv vidkrytykh peredach" (criterion of choice and durability of drive
bush-roller chains of open drives); journal and year not printed in the OCR'd
copy; no DOI found.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.theory._checks import positive, scalar_or_array
from pipeline.theory._checks import teeth as whole_teeth
from pipeline.theory._published import compare
from pipeline.theory._tables import rows
from pipeline.units import from_si

#: Safety factor psi of the allowed pitch growth (Paper 004, eq. (3), after
#: Vorobiev [1]).
PITCH_GROWTH_SAFETY = 0.8

#: Mean positive pitch error of a new chain as a fraction of the pitch,
#: delta_t_n = 0.004 t (Paper 004, eq. (3)).
PITCH_ERROR_FRACTION = 0.004

#: Support factor K of the pin in the outer plates: hinged supports
#: (Paper 004, eq. (4)); the conservative scheme of Gotovtsev [2].
K_PINNED = 1.0

#: Support factor K of a pin clamped rigidly on both sides (Paper 004, eq. (4)).
K_CLAMPED = 3.0

#: Pin supports of eq. (4) a table is made for: name and K.
SUPPORTS = {"pinned": K_PINNED, "clamped": K_CLAMPED}


def allowed_pitch_growth(
    pitch: ArrayLike,
    teeth: ArrayLike,
    safety: ArrayLike = PITCH_GROWTH_SAFETY,
    pitch_error_fraction: ArrayLike = PITCH_ERROR_FRACTION,
) -> float | np.ndarray:
    """Pitch growth at which the chain would jump off the sprocket.

    Parameters
    ----------
    pitch : float or array_like
        Chain pitch t [m].
    teeth : int or array_like
        Number of teeth z of the (driven) sprocket [-].
    safety : float or array_like, optional
        Safety factor psi [-]; default :data:`PITCH_GROWTH_SAFETY` (0.8,
        Paper 004, eq. (3)).
    pitch_error_fraction : float or array_like, optional
        Mean positive pitch error over the pitch, delta_t_n / t [-]; default
        :data:`PITCH_ERROR_FRACTION` (0.004, Paper 004, eq. (3)).

    Returns
    -------
    float or numpy.ndarray
        delta_t1 = 2.5 psi t / z - delta_t_n [m]; with the defaults
        t (2 / z - 0.004).

    References
    ----------
    Paper 004, eq. (3).
    """
    t = positive("pitch", pitch)
    z = whole_teeth("teeth", teeth)
    psi = positive("safety", safety)
    error = np.asarray(pitch_error_fraction, dtype=float) * t
    growth = 2.5 * psi * t / z - error
    return scalar_or_array(positive("teeth (allowed pitch growth delta_t1)", growth))


def pin_wear_allowance(pitch_growth: ArrayLike, wear_coefficient: ArrayLike) -> float | np.ndarray:
    """Allowed decrease of the pin diameter by wear.

    Parameters
    ----------
    pitch_growth : float or array_like
        Allowed pitch growth delta_t1 [m] (:func:`allowed_pitch_growth`).
    wear_coefficient : float or array_like
        Pin wear coefficient K_e [-] (no value in Paper 004).

    Returns
    -------
    float or numpy.ndarray
        delta_d = (delta_t1 / 2) K_e [m].

    References
    ----------
    Paper 004, eq. (2).
    """
    growth = positive("pitch_growth", pitch_growth)
    k_e = positive("wear_coefficient", wear_coefficient)
    return scalar_or_array(growth / 2.0 * k_e)


def max_bending_moment(
    force: ArrayLike,
    plate_span: ArrayLike,
    bush_length: ArrayLike,
    support_factor: ArrayLike = K_PINNED,
) -> float | np.ndarray:
    """Largest bending moment in the pin under a load spread along the bush.

    Parameters
    ----------
    force : float or array_like
        Largest force on the chain link F_max [N].
    plate_span : float or array_like
        Span l1 between the mid-planes of the outer plates [m].
    bush_length : float or array_like
        Bush length l [m]; below 2 l1.
    support_factor : float or array_like, optional
        K: :data:`K_PINNED` (1, hinged, the default and conservative case) or
        :data:`K_CLAMPED` (3).

    Returns
    -------
    float or numpy.ndarray
        M_max = (2 l1 - l) F_max / (8 K) [N m].

    References
    ----------
    Paper 004, eq. (4).
    """
    f = positive("force", force)
    k = positive("support_factor", support_factor)
    return scalar_or_array(_lever(plate_span, bush_length) * f / (8.0 * k))


def critical_pin_diameter(
    force: ArrayLike,
    plate_span: ArrayLike,
    bush_length: ArrayLike,
    allowable_stress: ArrayLike,
    support_factor: ArrayLike = K_PINNED,
) -> float | np.ndarray:
    """Pin diameter at which the bending stress reaches the allowable stress.

    Parameters
    ----------
    force : float or array_like
        Largest force on the chain link F_max [N].
    plate_span : float or array_like
        Span l1 between the mid-planes of the outer plates [m].
    bush_length : float or array_like
        Bush length l [m]; below 2 l1.
    allowable_stress : float or array_like
        Allowable bending stress [sigma_T] from the yield strength [Pa].
    support_factor : float or array_like, optional
        K: :data:`K_PINNED` (default) or :data:`K_CLAMPED`.

    Returns
    -------
    float or numpy.ndarray
        d_k = cbrt(4 F_max (2 l1 - l) / (K pi [sigma_T])) [m], the diameter
        with M_max / (pi d_k^3 / 32) = [sigma_T].

    References
    ----------
    Paper 004, eq. (5).
    """
    f = positive("force", force)
    k = positive("support_factor", support_factor)
    stress = positive("allowable_stress", allowable_stress)
    lever = _lever(plate_span, bush_length)
    return scalar_or_array(np.cbrt(4.0 * f * lever / (k * np.pi * stress)))


@dataclass(frozen=True)
class PinCheck:
    """Result of the pin criterion, eq. (1); lengths in m.

    Attributes
    ----------
    pitch_growth : float or numpy.ndarray
        Allowed pitch growth delta_t1 [m], eq. (3).
    wear_allowance : float or numpy.ndarray
        Allowed pin wear delta_d [m], eq. (2).
    critical_diameter : float or numpy.ndarray
        Critical pin diameter d_k [m], eq. (5).
    required_diameter : float or numpy.ndarray
        d_k + delta_d [m], eq. (1).
    pin_diameter : float or numpy.ndarray
        The nominal pin diameter checked [m].
    passes : bool or numpy.ndarray
        Whether ``pin_diameter >= required_diameter``.
    """

    pitch_growth: float | np.ndarray
    wear_allowance: float | np.ndarray
    critical_diameter: float | np.ndarray
    required_diameter: float | np.ndarray
    pin_diameter: float | np.ndarray
    passes: bool | np.ndarray


def check_pin(
    pin_diameter: ArrayLike,
    pitch: ArrayLike,
    teeth: ArrayLike,
    force: ArrayLike,
    plate_span: ArrayLike,
    bush_length: ArrayLike,
    allowable_stress: ArrayLike,
    wear_coefficient: ArrayLike,
    support_factor: ArrayLike = K_PINNED,
) -> PinCheck:
    """Check a nominal pin diameter against the criterion d >= d_k + delta_d.

    Parameters
    ----------
    pin_diameter : float or array_like
        Nominal pin diameter d [m].
    pitch, teeth
        As in :func:`allowed_pitch_growth` (default psi and delta_t_n).
    force, plate_span, bush_length, allowable_stress, support_factor
        As in :func:`critical_pin_diameter`.
    wear_coefficient : float or array_like
        Pin wear coefficient K_e [-], as in :func:`pin_wear_allowance`.

    Returns
    -------
    PinCheck
        The terms of the criterion and the verdict.

    References
    ----------
    Paper 004, eqs. (1)-(5).
    """
    d = positive("pin_diameter", pin_diameter)
    growth = allowed_pitch_growth(pitch, teeth)
    wear = pin_wear_allowance(growth, wear_coefficient)
    critical = critical_pin_diameter(
        force, plate_span, bush_length, allowable_stress, support_factor
    )
    required = critical + wear
    passes = d >= required
    return PinCheck(
        pitch_growth=growth,
        wear_allowance=wear,
        critical_diameter=critical,
        required_diameter=scalar_or_array(np.asarray(required)),
        pin_diameter=scalar_or_array(d),
        passes=bool(passes) if np.ndim(passes) == 0 else passes,
    )


def table(
    chain: Mapping[str, float],
    teeth: Sequence[int],
    force: float,
    allowable_stress: float,
    wear_coefficient: float,
) -> list[dict]:
    """The criterion per number of teeth and pin support (:data:`SUPPORTS`), teeth slowest.

    Parameters
    ----------
    chain : mapping
        The chain's pitch ``t``, ``pin_diameter``, ``bush_length`` and
        ``plate_span`` [m].
    teeth : sequence of int
        Teeth z of the driven sprocket [-].
    force : float
        Largest force on a chain link F_max [N].
    allowable_stress : float
        Allowable bending stress of the pin [sigma_T] [Pa].
    wear_coefficient : float
        Pin wear coefficient K_e [-].

    Returns
    -------
    list of dict
        One row per (z, support) in the units its keys name: ``z``,
        ``support``, ``K``, ``delta_t1_mm``, ``delta_d_mm``, ``d_k_mm``,
        ``required_mm`` (d_k + delta_d), ``pin_mm`` and ``passes``.

    References
    ----------
    Paper 004, eqs. (1)-(5).
    """
    z, support = (grid.ravel() for grid in np.meshgrid(teeth, list(SUPPORTS), indexing="ij"))
    check = check_pin(
        chain["pin_diameter"], chain["t"], z, force, chain["plate_span"], chain["bush_length"],
        allowable_stress, wear_coefficient, [SUPPORTS[name] for name in support],
    )  # fmt: skip
    columns = {
        "z": z.astype(int).tolist(),
        "support": support.tolist(),
        "K": [SUPPORTS[name] for name in support],
        "delta_t1_mm": from_si(check.pitch_growth, "mm"),
        "delta_d_mm": from_si(check.wear_allowance, "mm"),
        "d_k_mm": from_si(check.critical_diameter, "mm"),
        "required_mm": from_si(check.required_diameter, "mm"),
        "pin_mm": np.broadcast_to(from_si(check.pin_diameter, "mm"), z.shape),
        "passes": check.passes,
    }
    return rows(columns)


def compare_published() -> pd.DataFrame:
    """Paper 004's published numbers beside the model's: none, the paper prints none.

    Returns
    -------
    pandas.DataFrame
        The rows of ``pipeline/data/published/paper_004.csv`` (none) with the
        columns of :func:`pipeline.theory._published.compare`.
    """
    return compare("004", {})


def _lever(plate_span: ArrayLike, bush_length: ArrayLike) -> np.ndarray:
    """2 l1 - l [m], raising unless 0 < l < 2 l1 (Paper 004, eq. (4))."""
    span = positive("plate_span", plate_span)
    length = positive("bush_length", bush_length)
    if np.any(length >= 2.0 * span):
        raise ValueError(
            "bush_length must be below 2 * plate_span (Paper 004, eq. (4)); "
            f"got bush_length={bush_length!r}, plate_span={plate_span!r}"
        )
    return 2.0 * span - length
