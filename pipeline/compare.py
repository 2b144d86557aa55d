"""Experiment against theory: the campaign's tables per chain and per operating point.

For each chain of the run sheet: the experimental E0 (mean over its specimens
with an interval at :data:`~pipeline.fit.stiffness.CONFIDENCE`), the theoretical
E0 of Paper 001, eq. (20) (printed and exact coefficients), the discrepancy
(E0_exp - E0_theory) / E0_theory with the interval carried over from E0_exp,
the other common definition referred to E0_exp, and the lab's band check. Where
the chain is one of Table 1's, the published values stand beside, with their
own discrepancy.

The check reports what the data say: the verdict is the point estimate's, and
the interval shows how sure it is.

Per tensile specimen: its E0, the figures a lab reports (maximum force,
elongations, yield-like force, proof) and the verdicts of the acceptance
limits its chain declares (:mod:`pipeline.acceptance`).

For engagement runs, per operating point: the measured impact tensions
against Paper 000's eq. (16) with Ryabov's k = 2 and with the fitted k; per
wheel and impact, the line of N_u in omega, and in words how straight those
lines are.

Every setting applied is written beside the values it gave: the level of each
interval (``confidence_level`` of every ``*_ci_low``, ``*_ci_high``), the band
(``band``), the k of the theory (``k_theory``), how k is fitted (``k_fit_method``).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.acceptance import (
    CHECKS,
    NOT_MEASURED,
    VERDICTS,
    chain_verdict,
    specimen_verdicts,
)
from pipeline.fit import impact_model
from pipeline.fit.impact_model import ImpactModelFit, linearity, linearity_note, model_tensions
from pipeline.fit.stiffness import CONFIDENCE, SpecimenStiffness, combine_specimens
from pipeline.results.tensile import STRENGTH_VARIABLES, variable_attrs
from pipeline.theory import link_stiffness as ls
from pipeline.theory.wheel_impact import RYABOV_MASS_SHARE
from pipeline.units import to_si


@dataclass(frozen=True)
class ChainInput:
    """What the comparison needs of one run-sheet chain (SI units)."""

    key: str  #: the run sheet's chain key
    catalog: str | None  #: catalogue name, used to find Table 1's published row
    d: float | None
    t: float | None
    R0: float | None
    a: float | None
    E_steel: float  #: Young's modulus of the steel [Pa]


_VARIABLES = {
    "E0_exp": ("N", "experimental stiffness: mean over specimens"),
    "E0_exp_ci_low": ("N", "lower limit of the {level} interval of E0_exp"),
    "E0_exp_ci_high": ("N", "upper limit of the {level} interval of E0_exp"),
    "E0_exp_stderr": ("N", "standard error of E0_exp"),
    "n_specimens": ("1", "specimens counted in E0_exp"),
    "E0_theory": ("N", "theoretical stiffness, Paper 001 eq. (20), printed coefficients"),
    "E0_theory_exact": ("N", "theoretical stiffness, Paper 001 eq. (20), exact coefficients"),
    "discrepancy": ("1", "(E0_exp - E0_theory) / E0_theory"),
    "discrepancy_ci_low": ("1", "discrepancy at the lower limit of E0_exp's interval"),
    "discrepancy_ci_high": ("1", "discrepancy at the upper limit of E0_exp's interval"),
    "discrepancy_vs_exp": ("1", "(E0_exp - E0_theory) / E0_exp"),
    "in_band": ("1", "1 when the discrepancy lies in the lab's band, else 0"),
    "geometry_mismatch": ("m", "t - (a + 2 R0 - d): 0 for a link whose dimensions close"),
    "E0_exp_published": ("N", "experimental E0 published in Paper 001, Table 1"),
    "E0_theory_published": ("N", "theoretical E0 published in Paper 001, Table 1"),
    "discrepancy_published": ("1", "(E0_exp_published - E0_theory_published) / "
                                   "E0_theory_published"),
}


def _theory(chain: ChainInput) -> tuple[float, float, float, list[str]]:
    if None in (chain.d, chain.t, chain.R0, chain.a):
        return np.nan, np.nan, np.nan, [
            f"{chain.key}: no theoretical E0 (eq. (20) needs d, t, R0 and a)"]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", ls.GeometryWarning)
        printed = ls.chain_stiffness(chain.d, chain.t, chain.R0, chain.a, E=chain.E_steel)
        exact = ls.chain_stiffness(chain.d, chain.t, chain.R0, chain.a, E=chain.E_steel,
                                   coefficients=ls.exact_coefficients())
    mismatch = ls.geometry_mismatch(chain.d, chain.t, chain.R0, chain.a)
    notes = sorted({f"{chain.key}: {warning.message}" for warning in caught})
    return printed, exact, mismatch, notes


def _published(chain: ChainInput) -> tuple[float, float]:
    row = ls.table_1().get(chain.catalog or "")
    if row is None:
        return np.nan, np.nan
    return to_si(row.E0_exp_kgf, "kgf"), to_si(row.E0_theor_kgf, "kgf")


def _row(chain: ChainInput, specimens: Sequence[SpecimenStiffness], band) -> tuple[dict, list]:
    theory, exact, mismatch, notes = _theory(chain)
    row = dict.fromkeys(_VARIABLES, np.nan)
    row.update(E0_theory=theory, E0_theory_exact=exact, geometry_mismatch=mismatch)
    published = row["E0_exp_published"], row["E0_theory_published"] = _published(chain)
    if np.isfinite(published[1]):  # a chain of Table 1
        row["discrepancy_published"] = ls.discrepancy(*published)
    row["n_specimens"] = len(specimens)
    if specimens:
        combined = combine_specimens(specimens)
        row.update(E0_exp=combined.E0, E0_exp_ci_low=combined.E0_ci_low,
                   E0_exp_ci_high=combined.E0_ci_high, E0_exp_stderr=combined.E0_stderr)
    if specimens and np.isfinite(theory):
        row["discrepancy"] = ls.discrepancy(row["E0_exp"], theory)
        row["discrepancy_vs_exp"] = ls.discrepancy_vs_experiment(row["E0_exp"], theory)
        row["discrepancy_ci_low"] = (row["E0_exp_ci_low"] - theory) / theory
        row["discrepancy_ci_high"] = (row["E0_exp_ci_high"] - theory) / theory
        row["in_band"] = float(ls.in_band(row["discrepancy"], band))
    return row, notes


def stiffness_summary(
    chains: Sequence[ChainInput],
    specimens: Mapping[str, Sequence[SpecimenStiffness]],
    band: tuple[float, float] = ls.LAB_BAND,
) -> xr.Dataset:
    """The per-chain table of experimental against theoretical E0.

    Parameters
    ----------
    chains : sequence of ChainInput
        The run sheet's chains that have tensile runs.
    specimens : mapping
        Chain key -> the stiffness of each of its successfully processed specimens.
    band : (float, float)
        The lab's band for the discrepancy [-]; default (0.03, 0.06).

    Returns
    -------
    xarray.Dataset
        Variables of :data:`_VARIABLES` on dimension ``chain`` (labels = chain
        keys), the interval limits with their ``confidence_level``; attributes
        ``band`` (``"0.03 0.06"``) and ``notes``.

    References
    ----------
    Paper 001, eq. (20) and Table 1; discrepancy check in
    ``docs/models/paper-001-link-stiffness.md``.
    """
    rows, notes = [], []
    for chain in chains:
        row, chain_notes = _row(chain, specimens.get(chain.key, ()), band)
        rows.append(row)
        notes.extend(chain_notes)
    data = {
        name: ("chain", np.array([row[name] for row in rows], dtype=float),
               variable_attrs(units, long_name, name, CONFIDENCE))
        for name, (units, long_name) in _VARIABLES.items()
    }
    summary = xr.Dataset(data, coords={"chain": [chain.key for chain in chains]})
    summary["in_band"] = summary["in_band"].fillna(-1).astype("int8")
    summary["in_band"].attrs.update(
        units="1", long_name=_VARIABLES["in_band"][1], _FillValue=np.int8(-1),
        flag_values=np.array([0, 1], dtype="int8"), flag_meanings="out_of_band in_band")
    summary["n_specimens"] = summary["n_specimens"].astype("int32")
    summary.attrs.update(band=f"{band[0]:g} {band[1]:g}", notes="\n".join(notes))
    return summary


_POINT_VARIABLES = {
    "teeth": ("1", "number of teeth (pockets) of the wheel"),
    "apex_angle": ("degree", "tooth apex angle psi"),
    "omega": ("s-1", "wheel angular velocity stated in the run sheet"),
    "omega_measured": ("s-1", "wheel angular velocity measured in the log"),
    "N_u1_meas": ("N", "measured impact tension 1: median over the run's events"),
    "N_u1_iqr": ("N", "interquartile range of N_u1 over the run's events"),
    "N_u1_stderr": ("N", "standard error of the median N_u1"),
    "N_u1_count": ("1", "events counted in N_u1_meas"),
    "N_u2_meas": ("N", "measured impact tension 2: median over the run's events"),
    "N_u2_iqr": ("N", "interquartile range of N_u2 over the run's events"),
    "N_u2_stderr": ("N", "standard error of the median N_u2"),
    "N_u2_count": ("1", "events counted in N_u2_meas"),
    "N_u1_theory": ("N", "impact tension 1, Paper 000 eq. (16) with k = 2 (Ryabov)"),
    "N_u2_theory": ("N", "impact tension 2, Paper 000 eq. (16) with k = 2 (Ryabov)"),
    "N_u1_fit": ("N", "impact tension 1 of the model with the fitted k"),
    "N_u2_fit": ("N", "impact tension 2 of the model with the fitted k"),
    "E0": ("N", "chain stiffness used by the model"),
    "branch_length": ("m", "length of the active chain branch"),
    "t": ("m", "chain pitch"),
    "d": ("m", "bar diameter of the chain links"),
    "mass_per_length": ("kg m-1", "chain mass per metre (q/g)"),
}


def impact_summary(points: pd.DataFrame, fit: ImpactModelFit | None) -> xr.Dataset:
    """The per-operating-point table of measured against theoretical impact tensions.

    Parameters
    ----------
    points : pandas.DataFrame
        One row per engagement run (index: run id) with the
        :data:`~pipeline.fit.impact_model.POINT_COLUMNS` (SI) and the measured
        ``N_u1_meas``, ``N_u2_meas`` with their spread.
    fit : ImpactModelFit or None
        The campaign fit of k (None when it could not be made).

    Returns
    -------
    xarray.Dataset
        Variables on dimension ``operating_point`` (labels = run ids); the
        scalars ``k_fit``, ``k_fit_stderr``, ``k_fit_ci_low``, ``k_fit_ci_high``
        (with their ``confidence_level``), ``k_fit_chi2_reduced`` (NaN without a
        fit) and ``k_fit_covers_theory`` (1 when the interval holds the theory's
        k, 0 when not, -1 without a fit); the lines of N_u in omega on
        ``speed_line`` (``line_*``); attributes ``k_theory`` (the k of the
        ``_theory`` tensions), ``k_fit_method`` and ``linearity`` (how straight
        the lines are, in words: :func:`~pipeline.fit.impact_model.linearity_note`).

    References
    ----------
    Paper 000, eqs. (1)-(2) and (16); ``docs/models/paper-000-wheel-impact.md``.
    """
    table = points.copy()
    table["N_u1_theory"], table["N_u2_theory"] = model_tensions(table, k=RYABOV_MASS_SHARE)
    if fit is not None:
        table["N_u1_fit"], table["N_u2_fit"] = model_tensions(table, k=fit.k)
    else:
        table["N_u1_fit"] = table["N_u2_fit"] = np.nan
    table["apex_angle"] = np.degrees(table["apex_angle"])
    data = {
        name: ("operating_point", table[name].to_numpy(dtype=float),
               {"units": units, "long_name": long_name})
        for name, (units, long_name) in _POINT_VARIABLES.items()
    }
    summary = xr.Dataset(data, coords={"operating_point": table.index.astype(str).to_numpy()})
    values = (fit.value, fit.stderr, fit.ci_low, fit.ci_high, fit.chi2_reduced) if fit else (
        (np.nan,) * 5)
    level = fit.confidence if fit else impact_model.CONFIDENCE
    for (name, long_name), value in zip(_K_VARIABLES.items(), values, strict=True):
        summary[name] = ((), float(value), variable_attrs("1", long_name, name, level))
    summary["k_fit_covers_theory"] = ((), np.int8(fit.covers(RYABOV_MASS_SHARE) if fit else -1), {
        "long_name": "1 when the interval of k_fit holds k_theory, 0 when not, -1 without a fit",
        "flag_values": np.array([-1, 0, 1], dtype="int8"),
        "flag_meanings": "not_fitted outside inside"})
    lines = linearity(points)
    summary = xr.merge([summary, _speed_lines(lines)])
    summary.attrs.update(k_theory=RYABOV_MASS_SHARE, k_fit_method=impact_model.FIT_METHOD,
                         linearity=linearity_note(lines))
    return summary


_K_VARIABLES = {
    "k_fit": "share k of link masses in the impact, fitted",
    "k_fit_stderr": "standard error of k_fit",
    "k_fit_ci_low": "lower limit of the {level} interval of k_fit",
    "k_fit_ci_high": "upper limit of the {level} interval of k_fit",
    "k_fit_chi2_reduced": "reduced chi-square of the fit of k (weighted by the standard errors)",
}


_LINE_VARIABLES = {
    "teeth": ("1", "number of teeth of the wheel of the line"),
    "apex_angle": ("degree", "tooth apex angle of the wheel of the line"),
    "impact": ("1", "impact of the line: 1 (N_u1) or 2 (N_u2)"),
    "n_speeds": ("1", "wheel speeds on the line"),
    "slope": ("N s", "slope of the straight line of measured N_u against omega"),
    "intercept": ("N", "intercept of that line (0 for N_u proportional to omega)"),
    "r2": ("1", "R^2 of that line (NaN below 3 speeds)"),
    "largest": ("N", "largest measured N_u on the line"),
}


def _speed_lines(lines: pd.DataFrame) -> xr.Dataset:
    """The lines of :func:`~pipeline.fit.impact_model.linearity` (per wheel and impact, the
    straight line of measured N_u against omega: eq. (16) makes N_u proportional to
    omega) on dimension ``speed_line``, variables ``line_*``."""
    lines = lines.assign(apex_angle=np.degrees(lines["apex_angle"]))
    return xr.Dataset({
        f"line_{name}": ("speed_line", lines[name].to_numpy(dtype=float),
                         {"units": units, "long_name": long_name})
        for name, (units, long_name) in _LINE_VARIABLES.items()})


_SPECIMEN_VARIABLES = {
    "E0": ("N", "specimen stiffness E0"),
    "E0_ci_low": ("N", "lower limit of the {level} interval of E0"),
    "E0_ci_high": ("N", "upper limit of the {level} interval of E0"),
    "single_pull": ("1", "1 for a single pull (E0 from its one loading), 0 for a cyclic test"),
    "from_crosshead": ("1", "1 when E0 comes from the crosshead travel, which includes the "
                       "machine's own compliance (E0 too low), 0 otherwise"),
    **{name: (units, long_name) for name, (units, long_name) in STRENGTH_VARIABLES.items()},
}


def _verdict_attrs(long_name: str) -> dict:
    return {"long_name": long_name, "flag_values": np.arange(-2, 2, dtype="int8"),
            "flag_meanings": " ".join(VERDICTS)}


def specimen_summary(rows: Mapping[str, Mapping], limits: Mapping[str, Mapping[str, float]]
                     ) -> xr.Dataset:
    """The per-specimen table of a tensile campaign, with its acceptance verdicts.

    Parameters
    ----------
    rows : mapping
        Run id -> ``chain``, ``specimen`` and the figures of :data:`_SPECIMEN_VARIABLES` [SI].
    limits : mapping
        Chain key -> its declared limits [SI] (:func:`pipeline.acceptance.limits_si`).

    Returns
    -------
    xarray.Dataset
        On dimension ``specimen`` (labels = run ids): ``specimen_chain``,
        ``specimen_name``, the figures, and ``accept_<check>`` per check of
        :data:`pipeline.acceptance.CHECKS`; on dimension ``chain``, the chains'
        ``accept_<check>`` (:func:`pipeline.acceptance.chain_verdict`).
    """
    ids = list(rows)
    data = {
        "specimen_chain": ("specimen", [str(rows[i]["chain"]) for i in ids],
                           {"long_name": "chain of the specimen (run-sheet key)"}),
        "specimen_name": ("specimen", [str(rows[i]["specimen"]) for i in ids],
                          {"long_name": "specimen as named in the run sheet"}),
    }
    for name, (units, long_name) in _SPECIMEN_VARIABLES.items():
        data[f"specimen_{name}"] = ("specimen", np.array([rows[i][name] for i in ids],
                                                         dtype=float),
                                    variable_attrs(units, long_name, name, CONFIDENCE))
    verdicts = {i: specimen_verdicts(rows[i], limits.get(rows[i]["chain"], {})) for i in ids}
    chains = sorted(limits)
    for check in CHECKS:
        data[f"specimen_accept_{check}"] = (
            "specimen", np.array([verdicts[i][check] for i in ids], dtype="int8"),
            _verdict_attrs(f"acceptance check {check.replace('_', ' ')} of the specimen"))
        data[f"accept_{check}"] = (
            "chain", np.array([chain_verdict([verdicts[i][check] for i in ids
                                              if rows[i]["chain"] == chain] or
                                             ([NOT_MEASURED] if check in limits[chain] else []))
                               for chain in chains], dtype="int8"),
            _verdict_attrs(f"acceptance check {check.replace('_', ' ')} of the chain"))
    return xr.Dataset(data, coords={"specimen": ids, "chain": chains})
