"""Static stiffness E0 of round-link chains (Paper 001, Rynik).

The chain stiffness is the tensile force over the relative elastic elongation,
E0 = P / eps = P t / delta (eqs. (2), (5)), a force. The link elongation delta
follows from the Maxwell-Mohr method applied to a quarter of the link: a
straight half-bar of length a/2 and a quarter circle of centre-line radius R0,
with the bending moment at the symmetry plane statically indeterminate
(eqs. (9)-(17)). Integrated, it gives eq. (19) for delta and eq. (20) for E0.

Link geometry: ``d`` bar diameter, ``t`` pitch (inner length), ``R0``
centre-line radius of the curved ends, ``a`` length of the straight parts;
consistent links have t = a + 2 R0 - d.

All functions take SI values (lengths in m, E in Pa, forces in N) and return
SI values; E0 is a force [N].

References
----------
Paper 001: J. Rynik, "Analityczno-empiryczne okreslenie statycznej sztywnosci
lancuchow ogniwowych", Zeszyty Naukowe Politechniki Slaskiej, seria Gornictwo,
nr 36, 1969 (as cited in Paper 000, ref. [3]); no DOI found. Corrected formulas
in ``docs/models/paper-001-link-stiffness.md``.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from typing import NamedTuple

import numpy as np
import pandas as pd
from scipy.integrate import quad

from pipeline.theory._checks import non_negative, positive, scalar_or_array
from pipeline.theory._published import compare, read_published, within_tolerance
from pipeline.units import from_si, to_si

#: Young's modulus of the chain steel used for Table 1 [kgf/cm^2]
#: (Paper 001, text below eq. (20): "E = 2,2 * 10^6 kg/cm^2").
PAPER_E_KGF_PER_CM2 = 2.2e6

#: The same modulus in SI [Pa]: the default E of this module.
E_STEEL = to_si(PAPER_E_KGF_PER_CM2, "kgf/cm^2")

#: Poisson's ratio of steel assumed by Paper 001 (text above eq. (19)).
NU_STEEL = 0.3

#: Shear-stress distribution factor alpha of a circular section (Paper 001, below eq. (18)).
SHEAR_FACTOR = 32 / 27

#: Largest |t - (a + 2 R0 - d)| accepted without a GeometryWarning [m]: half a
#: millimetre, the rounding of the link dimensions tabulated in whole mm.
GEOMETRY_TOLERANCE = 0.5e-3

#: The lab's band for the discrepancy (E0_exp - E0_theory) / E0_theory: the paper's
#: "experimental values are somewhat higher, by 3 to 6 %" (Paper 001, section 3).
LAB_BAND = (0.03, 0.06)


class StiffnessCoefficients(NamedTuple):
    """The five numerical coefficients of eqs. (19)-(20) (dimensionless)."""

    c1: float  #: of R0^2 in the bending term
    c2: float  #: of a^2 in the bending term
    c3: float  #: of a R0 in the bending term
    c4: float  #: of d^2 a (normal force)
    c5: float  #: of d^2 R0 (normal and shear force in the curved part)


#: The coefficients printed in eqs. (19)-(20), with which the paper computed Table 1.
#: They equal the exact ones (:func:`exact_coefficients`) evaluated with pi = 3.14.
PRINTED = StiffnessCoefficients(1.46, 0.355, 1.58, 0.03, 0.2)


class PublishedStiffness(NamedTuple):
    """One chain of Paper 001, Table 1, in the paper's units (E = 2.2e6 kgf/cm^2)."""

    E0_exp_kgf: float  #: measured stiffness [kgf]
    E0_theor_kgf: float  #: stiffness from eq. (20) as published [kgf]
    E0_theor_tolerance: float  #: relative tolerance of E0_theor, its printed rounding [-]


class GeometryWarning(UserWarning):
    """The link dimensions do not close: t differs from a + 2 R0 - d."""


def exact_coefficients(nu: float = NU_STEEL) -> StiffnessCoefficients:
    """The exact coefficients of eqs. (19)-(20) from the Maxwell-Mohr integration.

    Parameters
    ----------
    nu : float
        Poisson's ratio [-], in (-1, 0.5); default 0.3 as in Paper 001.

    Returns
    -------
    StiffnessCoefficients
        ``((pi^3 - 8 pi)/4, (3 pi - 8)/4, (4 pi^2 - 8 pi - 8)/4, 1/32,
        pi/64 + pi (1 + nu)/27)``; the last uses the shear factor alpha = 32/27.

    Notes
    -----
    The seed prints ``(1 + nu)/27`` in the last term: a factor pi was lost in the
    OCR (only with it do the printed coefficients follow).

    References
    ----------
    Paper 001, eq. (18) and the line after it.

    Examples
    --------
    >>> [round(c, 4) for c in exact_coefficients()]
    [1.4684, 0.3562, 1.5864, 0.0312, 0.2003]
    """
    nu = _poisson_ratio(nu)
    pi = np.pi
    return StiffnessCoefficients(
        (pi**3 - 8 * pi) / 4,
        (3 * pi - 8) / 4,
        (4 * pi**2 - 8 * pi - 8) / 4,
        1 / 32,
        pi / 64 + pi * (1 + nu) / 27,
    )


def chain_stiffness(
    d,
    t,
    R0,
    a,
    E=E_STEEL,
    coefficients: StiffnessCoefficients = PRINTED,
):
    """Static stiffness E0 of a round-link chain, eq. (20).

    E0 = E J t / (R0^3 (c1 R0^2 + c2 a^2 + c3 a R0) / (a + pi R0)^2
    + d^2 (c4 a + c5 R0)), J = pi d^4 / 64.

    Parameters
    ----------
    d : float or array_like
        Bar diameter [m].
    t : float or array_like
        Pitch (inner length of a link) [m].
    R0 : float or array_like
        Centre-line radius of the curved ends [m]; must exceed d/2.
    a : float or array_like
        Length of the straight parts [m]; 0 gives a circular ring.
    E : float or array_like
        Young's modulus [Pa]; default 2.2e6 kgf/cm^2 = 2.157e11 Pa (Paper 001).
    coefficients : StiffnessCoefficients
        :data:`PRINTED` (default, as the paper computed Table 1) or
        :func:`exact_coefficients`.

    Returns
    -------
    float or numpy.ndarray
        E0 [N], the force per unit relative elongation of the chain.

    Warns
    -----
    GeometryWarning
        When |t - (a + 2 R0 - d)| exceeds 0.5 mm (see :func:`check_geometry`).

    References
    ----------
    Paper 001, eqs. (5), (19), (20).

    Examples
    --------
    Chain 18x64 of Table 1 (published 2.09e6 kgf, with E rounded there):

    >>> from pipeline.units import from_si, to_si
    >>> d, t, R0, a = to_si([18, 64, 20, 42], "mm")
    >>> round(from_si(chain_stiffness(d, t, R0, a), "kgf") / 1e6, 4)
    2.043
    """
    d, R0, a = _link(d, R0, a)
    t, E = positive("t", t), positive("E", E)
    check_geometry(d, t, R0, a, stacklevel=3)
    return scalar_or_array(E * _second_moment(d) * t / _compliance(d, R0, a, coefficients))


def link_elongation(
    force,
    d,
    R0,
    a,
    E=E_STEEL,
    coefficients: StiffnessCoefficients = PRINTED,
):
    """Elastic elongation delta of one link under a tensile force, eq. (19).

    delta = P / (E J) (R0^3 (c1 R0^2 + c2 a^2 + c3 a R0) / (a + pi R0)^2
    + d^2 (c4 a + c5 R0)).

    Parameters
    ----------
    force : float or array_like
        Tensile force P on the chain [N], >= 0.
    d : float or array_like
        Bar diameter [m].
    R0 : float or array_like
        Centre-line radius of the curved ends [m]; must exceed d/2.
    a : float or array_like
        Length of the straight parts [m].
    E : float or array_like
        Young's modulus [Pa]; default 2.2e6 kgf/cm^2 (Paper 001).
    coefficients : StiffnessCoefficients
        :data:`PRINTED` (default) or ``exact_coefficients(nu)`` for a given
        Poisson's ratio.

    Returns
    -------
    float or numpy.ndarray
        delta [m], the change of the inner length of the whole link.

    References
    ----------
    Paper 001, eqs. (18), (19).

    Examples
    --------
    >>> from pipeline.units import to_si
    >>> d, R0, a = to_si([18, 20, 42], "mm")
    >>> round(link_elongation(to_si(1000, "kgf"), d, R0, a) * 1e3, 5)  # [mm]
    0.03133
    """
    force, E = non_negative("force", force), positive("E", E)
    d, R0, a = _link(d, R0, a)
    return scalar_or_array(force * _compliance(d, R0, a, coefficients) / (E * _second_moment(d)))


def link_elongation_numerical(force, d, R0, a, E=E_STEEL, nu: float = NU_STEEL):
    """Elongation of one link by direct numerical Maxwell-Mohr integration.

    Independent of eq. (19): the statically indeterminate moment x1 at the
    symmetry plane (eqs. (10)-(13)) and the elongation (eq. (9)) are both found
    by quadrature (``scipy.integrate.quad``) over the quarter link, from the
    internal forces of eqs. (14), (16), (17), with EJ, EF = 16 EJ / d^2,
    GF = EF / (2 (1 + nu)) and alpha = 32/27.

    Parameters
    ----------
    force : float or array_like
        Tensile force P on the chain [N], >= 0.
    d : float or array_like
        Bar diameter [m].
    R0 : float or array_like
        Centre-line radius of the curved ends [m]; must exceed d/2.
    a : float or array_like
        Length of the straight parts [m].
    E : float or array_like
        Young's modulus [Pa]; default 2.2e6 kgf/cm^2 (Paper 001).
    nu : float
        Poisson's ratio [-], in (-1, 0.5); default 0.3.

    Returns
    -------
    float or numpy.ndarray
        delta [m]; equals ``link_elongation(..., coefficients=exact_coefficients(nu))``.

    References
    ----------
    Paper 001, eqs. (9)-(17).
    """
    force, E = non_negative("force", force), positive("E", E)
    d, R0, a = _link(d, R0, a)
    nu = _poisson_ratio(nu)
    quarter = np.vectorize(_quarter_elongation, otypes=[float])
    return scalar_or_array(4 * quarter(force, d, R0, a, E, nu))


def geometry_mismatch(d, t, R0, a):
    """How far the pitch misses the link's closure, t - (a + 2 R0 - d) [m].

    Parameters
    ----------
    d, t, R0, a : float or array_like
        Bar diameter, pitch, centre-line radius of the ends, straight length [m].

    Returns
    -------
    float or numpy.ndarray
        The mismatch [m]; 0 for a consistent link.

    Examples
    --------
    Table 1's 22x86 link closes at 84 mm:

    >>> round(geometry_mismatch(0.022, 0.086, 0.024, 0.058) * 1e3, 6)
    2.0
    """
    d, t, R0, a = (np.asarray(value, dtype=float) for value in (d, t, R0, a))
    return scalar_or_array(t - (a + 2 * R0 - d))


def check_geometry(d, t, R0, a, tolerance: float = GEOMETRY_TOLERANCE, stacklevel: int = 2):
    """Warn when the link dimensions do not close; never raise.

    Parameters
    ----------
    d, t, R0, a : float or array_like
        Bar diameter, pitch, centre-line radius of the ends, straight length [m].
    tolerance : float
        Largest accepted |t - (a + 2 R0 - d)| [m]; default 0.5 mm.
    stacklevel : int
        Passed to :func:`warnings.warn` (2: the caller of this function).

    Returns
    -------
    float or numpy.ndarray
        The mismatch t - (a + 2 R0 - d) [m].

    Warns
    -----
    GeometryWarning
        Naming t and a + 2 R0 - d [mm] of every link beyond `tolerance`.
    """
    mismatch = np.asarray(geometry_mismatch(d, t, R0, a))
    bad = np.atleast_1d(np.abs(mismatch) > tolerance)
    if np.any(bad):
        pitch = np.atleast_1d(np.broadcast_to(t, mismatch.shape))[bad]
        closure = pitch - np.atleast_1d(mismatch)[bad]
        pairs = "; ".join(
            f"t = {1e3 * p:.4g} mm but a + 2 R0 - d = {1e3 * c:.4g} mm"
            for p, c in zip(pitch, closure, strict=True)
        )
        warnings.warn(
            f"link geometry does not close within {1e3 * tolerance:g} mm: {pairs} "
            "(check the dimensions; E0 is computed with t as given)",
            GeometryWarning,
            stacklevel=stacklevel,
        )
    return scalar_or_array(mismatch)


def discrepancy(E0_exp, E0_theory):
    """Relative discrepancy referred to theory, (E0_exp - E0_theory) / E0_theory.

    Parameters
    ----------
    E0_exp : float or array_like
        Measured stiffness [N] (any force unit, the same for both).
    E0_theory : float or array_like
        Theoretical stiffness [N].

    Returns
    -------
    float or numpy.ndarray
        The discrepancy [-]; positive when the chain is stiffer than the model.

    References
    ----------
    Paper 001, section 3 and Table 1; ``docs/models/paper-001-link-stiffness.md``.

    Examples
    --------
    >>> round(discrepancy(2.26e6, 2.09e6), 4)
    0.0813
    """
    E0_exp = positive("E0_exp", E0_exp)
    E0_theory = positive("E0_theory", E0_theory)
    return scalar_or_array((E0_exp - E0_theory) / E0_theory)


def discrepancy_vs_experiment(E0_exp, E0_theory):
    """Relative discrepancy referred to experiment, (E0_exp - E0_theory) / E0_exp.

    Parameters and return as :func:`discrepancy`.

    Examples
    --------
    >>> round(discrepancy_vs_experiment(2.26e6, 2.09e6), 4)
    0.0752
    """
    E0_exp = positive("E0_exp", E0_exp)
    E0_theory = positive("E0_theory", E0_theory)
    return scalar_or_array((E0_exp - E0_theory) / E0_exp)


def in_band(discrepancy, band: tuple[float, float] = LAB_BAND) -> np.ndarray:
    """Whether each discrepancy lies in the closed interval `band` (signed).

    Parameters
    ----------
    discrepancy : float or array_like
        Relative discrepancies [-] (fractions, not percent).
    band : (float, float)
        Lower and upper bound [-]; default (0.03, 0.06), the lab's 3-6 %.

    Returns
    -------
    numpy.ndarray of bool
        ``lower <= discrepancy <= upper`` element-wise.

    Notes
    -----
    The test is signed, without ``abs()``: the paper's claim is that the
    experimental values are *higher* than the theoretical ones by 3 to 6 %, so a
    chain 4 % softer than the model does not agree with it. For a two-sided
    tolerance pass a symmetric band, e.g. ``(-0.06, 0.06)``.

    Examples
    --------
    >>> in_band([0.0370, 0.0333, 0.0813, 0.0636, -0.04])
    array([ True,  True, False, False, False])
    """
    lower, upper = band
    if not lower <= upper:
        raise ValueError(f"band must be (lower, upper) with lower <= upper, got {band!r}")
    values = np.asarray(discrepancy, dtype=float)
    return (values >= lower) & (values <= upper)


def table_1() -> dict[str, PublishedStiffness]:
    """Paper 001, Table 1: the published E0 of each chain, from ``paper_001.csv``.

    Returns
    -------
    dict
        Catalogue name of the chain (d x t in mm) -> :class:`PublishedStiffness`
        [kgf], in the paper's order; the link geometry (d, t, R0, a) of these
        chains is in the chain catalogue.
    """
    table = read_published("001").set_index("quantity")
    chains = [name.removeprefix("E0_theory_") for name in table.index
              if name.startswith("E0_theory_")]  # fmt: skip
    return {
        chain: PublishedStiffness(
            float(table.at[f"E0_exp_{chain}", "published"]),
            float(table.at[f"E0_theory_{chain}", "published"]),
            float(table.at[f"E0_theory_{chain}", "tolerance"]),
        )
        for chain in chains
    }


#: The dimensions of a link in a :func:`table` row, in their order.
TABLE_DIMENSIONS = ("d", "t", "R0", "a")

#: What the discrepancy columns of :func:`table` mean (a note under a table with Table 1's
#: chains).
TABLE_LEGEND = (
    "discrepancy = (E0_exp - E0_theory) / E0_theory with Table 1's E0_exp; "
    "discrepancy_pct refers it to this model's E0, discrepancy_paper_pct to the "
    "paper's E0_theor; in_band: inside the band, signed"
)


def table(
    links: Sequence[tuple[str, Sequence[float]]],
    *,
    E: float = E_STEEL,
    coefficients: StiffnessCoefficients = PRINTED,
    band: tuple[float, float] = LAB_BAND,
) -> tuple[list[dict], list[str]]:
    """Eq. (20) per chain, beside Table 1's published values where it is one of its chains.

    Parameters
    ----------
    links : sequence of (str, (d, t, R0, a))
        The chains: a name (a Table 1 chain by its catalogue name, ``13x50``)
        and the link's dimensions [m].
    E : float
        Young's modulus of the steel [Pa].
    coefficients : StiffnessCoefficients
        Those of eq. (20): :data:`PRINTED` or :func:`exact_coefficients`.
    band : (float, float)
        The lab's band of the discrepancy [1].

    Returns
    -------
    rows : list of dict
        One per chain, in the units its keys name: ``chain``, ``d_mm``,
        ``t_mm``, ``R0_mm``, ``a_mm``, ``E0_kgf``, ``E0_kN``, and for a Table 1
        chain (None otherwise) ``E0_theor_paper_kgf``, ``E0_exp_paper_kgf``,
        ``discrepancy_pct`` and ``in_band`` (Table 1's E0_exp against this
        E0), ``discrepancy_paper_pct`` and ``in_band_paper`` (against Table
        1's E0_theor).
    notes : list of str
        Geometry warnings, Table 1 values eq. (20) does not reproduce beyond
        their rounding, and :data:`TABLE_LEGEND` when a Table 1 chain is shown.

    Raises
    ------
    ValueError
        Naming the chain whose dimensions are outside the model's domain.

    References
    ----------
    Paper 001, eq. (20) and Table 1; ``docs/models/paper-001-link-stiffness.md``.
    """
    published = table_1()
    rows, notes = [], []
    for name, lengths in links:
        row, row_notes = _table_row(name, lengths, published.get(name), E, coefficients, band)
        rows.append(row)
        notes += row_notes
    if any(name in published for name, _ in links):
        notes.append(TABLE_LEGEND)
    return rows, notes


def _table_row(name: str, lengths: Sequence[float], published: PublishedStiffness | None,
               E: float, coefficients: StiffnessCoefficients, band: tuple[float, float]
               ) -> tuple[dict, list[str]]:
    """One row of :func:`table` and its notes (`published`: the chain's Table 1 row)."""
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            E0 = chain_stiffness(*lengths, E=E, coefficients=coefficients)
    except ValueError as error:
        raise ValueError(f"{name}: {error}") from None
    notes = [f"{name}: {warning.message}" for warning in caught]
    row = {"chain": name}
    dimensions = zip(TABLE_DIMENSIONS, lengths, strict=True)
    row |= {f"{key}_mm": from_si(value, "mm") for key, value in dimensions}
    row |= {"E0_kgf": from_si(E0, "kgf"), "E0_kN": from_si(E0, "kN")}
    row |= _published_comparison(row["E0_kgf"], published, band)
    if published is not None:
        notes += _reproduction_notes(name, row["E0_kgf"], published)
    return row, notes


def _published_comparison(E0_kgf: float, published: PublishedStiffness | None,
                          band: tuple[float, float]) -> dict:
    """Table 1's values and the discrepancies of its E0_exp (None for other chains)."""
    keys = ("E0_theor_paper_kgf", "E0_exp_paper_kgf", "discrepancy_pct", "in_band")
    keys += ("discrepancy_paper_pct", "in_band_paper")
    if published is None:
        return dict.fromkeys(keys)
    to_model = discrepancy(published.E0_exp_kgf, E0_kgf)
    to_paper = discrepancy(published.E0_exp_kgf, published.E0_theor_kgf)
    values = (published.E0_theor_kgf, published.E0_exp_kgf, 100 * to_model)
    values += (bool(in_band(to_model, band)), 100 * to_paper, bool(in_band(to_paper, band)))
    return dict(zip(keys, values, strict=True))


def _reproduction_notes(name: str, E0_kgf: float, published: PublishedStiffness) -> list[str]:
    """A note when eq. (20) misses Table 1's E0_theor by more than its rounding."""
    if within_tolerance(E0_kgf, published.E0_theor_kgf, published.E0_theor_tolerance):
        return []
    gap = E0_kgf / published.E0_theor_kgf - 1
    return [
        f"{name}: eq. (20) gives {E0_kgf:.5g} kgf, {100 * gap:+.1f} % from Table 1's "
        f"E0_theor = {published.E0_theor_kgf:.3g} kgf (not reproduced beyond its rounding)"
    ]


def compare_published() -> pd.DataFrame:
    """Paper 001's published numbers (Table 1) beside eq. (20).

    Returns
    -------
    pandas.DataFrame
        One row per number of ``pipeline/data/published/paper_001.csv``: the
        theoretical and the experimental E0 of each chain [kgf], each beside
        :func:`chain_stiffness` with the printed coefficients and the row's
        d, t, R0, a and E; and the elongation per kgf eps of each [1/kgf],
        beside 1 / E0 of the row's E0 (E0 = P / eps, eqs. (2), (5): Table 1's
        own consistency); columns as :func:`pipeline.theory._published.compare`.

    Notes
    -----
    The 22x86 link does not close (t = 86 mm, a + 2 R0 - d = 84 mm); its
    GeometryWarning is not raised here, the rows' notes say it.

    Examples
    --------
    >>> table = compare_published().set_index("quantity")
    >>> round(float(table.at["E0_theory_18x64", "model"]) / 1e6, 4)
    2.043
    """
    return compare("001", {"E0_theory": _stiffness_kgf, "E0_exp": _stiffness_kgf,
                           "eps": lambda inputs: 1.0 / from_si(inputs["E0"], "kgf")})


def _stiffness_kgf(inputs: dict) -> float:
    """eq. (20) with the printed coefficients for a row's d, t, R0, a, E [kgf]."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", GeometryWarning)
        return from_si(chain_stiffness(**inputs), "kgf")


def _link(d, R0, a):
    """The link dimensions (d, R0, a) as validated arrays."""
    d, R0 = positive("d", d), positive("R0", R0)
    if np.any(R0 <= d / 2):
        raise ValueError(
            f"R0 must exceed d/2 (the link needs an eye), got R0={R0.tolist()} m, d={d.tolist()} m"
        )
    return d, R0, non_negative("a", a)


def _poisson_ratio(nu) -> float:
    nu = float(nu)
    if not -1 < nu < 0.5:
        raise ValueError(f"nu (Poisson's ratio) must lie in (-1, 0.5), got {nu!r}")
    return nu


def _second_moment(d):
    """J = pi d^4 / 64 of the circular bar section [m^4]."""
    return np.pi * d**4 / 64


def _compliance(d, R0, a, coefficients: StiffnessCoefficients):
    """The bracket of eqs. (19)-(20) [m^3]: delta = P / (E J) * bracket."""
    c1, c2, c3, c4, c5 = coefficients
    bending = R0**3 * (c1 * R0**2 + c2 * a**2 + c3 * a * R0) / (a + np.pi * R0) ** 2
    return bending + d**2 * (c4 * a + c5 * R0)


def _along_quarter(straight, curved, R0: float, a: float) -> float:
    """Integral over the quarter link: straight half-bar 0 <= x <= a/2, then arc ds = R0 dphi."""
    options = {"epsabs": 0.0, "epsrel": 1e-12}
    along_bar = quad(straight, 0.0, a / 2, **options)[0]
    along_arc = quad(lambda phi: curved(phi) * R0, 0.0, np.pi / 2, **options)[0]
    return along_bar + along_arc


def _released_moment(load: float, R0: float, phi: float) -> float:
    """M_p of the released quarter (x1 = 0) on the arc, Fig. 5: -(P/2) R0 (1 - cos phi)."""
    return -load / 2 * R0 * (1 - np.cos(phi))


def _redundant_moment(load: float, R0: float, a: float) -> float:
    """x1 of eq. (10), x1 delta_11 + delta_10 = 0, with eqs. (11)-(12) by quadrature.

    The unit moment M0 = 1 acts along the whole quarter; EJ cancels.
    """
    delta_11 = _along_quarter(lambda x: 1.0, lambda phi: 1.0, R0, a)
    delta_10 = _along_quarter(lambda x: 0.0, lambda phi: _released_moment(load, R0, phi), R0, a)
    return -delta_10 / delta_11


def _forces_on_bar(load: float, x1: float) -> tuple[float, float, float]:
    """(M, N, T) on the straight half-bar, eqs. (14), (16): x1, P/2, 0."""
    return x1, load / 2, 0.0


def _forces_on_arc(load: float, x1: float, R0: float, phi: float) -> tuple[float, float, float]:
    """(M, N, T) on the arc, eqs. (14), (17) and Figs. 5-7."""
    return x1 + _released_moment(load, R0, phi), load / 2 * np.cos(phi), -load / 2 * np.sin(phi)


def _quarter_elongation(force: float, d: float, R0: float, a: float, E: float, nu: float) -> float:
    """delta / 4 from eq. (9) over the quarter link, for the load `force` [m]."""
    EF = E * np.pi * d**2 / 4
    EJ = E * _second_moment(d)
    GF = EF / (2 * (1 + nu))
    x1 = _redundant_moment(force, R0, a)
    x1_unit = _redundant_moment(1.0, R0, a)

    def work(actual, unit) -> float:
        (M, N, T), (M0, N0, T0) = actual, unit
        return M * M0 / EJ + N * N0 / EF + SHEAR_FACTOR * T * T0 / GF

    return _along_quarter(
        lambda x: work(_forces_on_bar(force, x1), _forces_on_bar(1.0, x1_unit)),
        lambda phi: work(_forces_on_arc(force, x1, R0, phi), _forces_on_arc(1.0, x1_unit, R0, phi)),
        R0,
        a,
    )
