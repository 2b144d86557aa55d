"""``chainbench theory stiffness``: static stiffness E0 of round-link chains (Paper 001).

Eq. (20) per chain, beside the published Table 1 values where the chain is one
of the paper's, with the discrepancy of the measured E0 and the band verdict.
"""

from __future__ import annotations

import warnings
from enum import StrEnum
from typing import Annotated

import typer

from pipeline.catalog import chain
from pipeline.cli._output import emit
from pipeline.theory._published import within_tolerance
from pipeline.theory.link_stiffness import (
    LAB_BAND,
    PAPER_E_KGF_PER_CM2,
    PRINTED,
    PublishedStiffness,
    chain_stiffness,
    discrepancy,
    exact_coefficients,
    in_band,
    table_1,
)
from pipeline.units import from_si, to_si

_DIMENSIONS = ("d", "t", "R0", "a")

_LEGEND = (
    "discrepancy = (E0_exp - E0_theory) / E0_theory with Table 1's E0_exp; "
    "discrepancy_pct refers it to this model's E0, discrepancy_paper_pct to the "
    "paper's E0_theor; in_band: inside the band, signed"
)


class CoefficientSet(StrEnum):
    """Which coefficients of eq. (20) to use."""

    printed = "printed"
    exact = "exact"


def command(
    chains: Annotated[
        list[str] | None,
        typer.Option(
            "--chain",
            help="Catalogue chain, e.g. 18x64 (repeatable). "
            "Default: the four chains of Paper 001, Table 1.",
        ),
    ] = None,
    d_mm: Annotated[
        float | None,
        typer.Option("--d-mm", help="Bar diameter d in mm, for a chain given by its dimensions."),
    ] = None,
    t_mm: Annotated[float | None, typer.Option("--t-mm", help="Pitch t in mm.")] = None,
    R0_mm: Annotated[
        float | None, typer.Option("--R0-mm", help="Centre-line radius R0 of the ends in mm.")
    ] = None,
    a_mm: Annotated[
        float | None, typer.Option("--a-mm", help="Length a of the straight parts in mm.")
    ] = None,
    E_kgf_per_cm2: Annotated[
        float, typer.Option("--E-kgf-per-cm2", help="Young's modulus in kgf/cm^2 (Paper 001).")
    ] = PAPER_E_KGF_PER_CM2,
    coefficients: Annotated[
        CoefficientSet,
        typer.Option(help="printed: as in eq. (20); exact: Maxwell-Mohr values, nu = 0.3."),
    ] = CoefficientSet.printed,
    band_pct: Annotated[
        tuple[float, float],
        typer.Option("--band-pct", help="Discrepancy band, lower and upper, in %."),
    ] = (100 * LAB_BAND[0], 100 * LAB_BAND[1]),
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a table.")] = False,
) -> None:
    """Static stiffness E0 of round-link chains, eq. (20) of Paper 001, beside Table 1."""
    explicit = _explicit_link(d_mm=d_mm, t_mm=t_mm, R0_mm=R0_mm, a_mm=a_mm)
    published = table_1()
    names = chains or ([] if explicit else list(published))
    links = [_catalogue_link(name) for name in names] + explicit
    band = (band_pct[0] / 100, band_pct[1] / 100)
    settings = dict(
        E=to_si(E_kgf_per_cm2, "kgf/cm^2"),
        coefficients=PRINTED if coefficients is CoefficientSet.printed else exact_coefficients(),
        band=band,
    )
    rows, notes = [], []
    for name, lengths in links:
        row, row_notes = _row(name, lengths, published.get(name), **settings)
        rows.append(row)
        notes += row_notes
    if any(name in published for name, _ in links):
        notes.append(_LEGEND)
    extra = {
        "E_kgf_per_cm2": E_kgf_per_cm2,
        "coefficients": coefficients.value,
        "band_pct": list(band_pct),
    }
    title = "Static stiffness E0 of round-link chains (Paper 001, eq. (20))"
    emit(rows, title=title, as_json=as_json, extra=extra, notes=notes)


def _catalogue_link(name: str) -> tuple[str, tuple[float, ...]]:
    """(name, (d, t, R0, a) [m]) of a catalogue chain."""
    try:
        spec = chain(name)
        return name, tuple(spec[quantity] for quantity in _DIMENSIONS)
    except KeyError as error:
        raise typer.BadParameter(error.args[0], param_hint="--chain") from None


def _explicit_link(**dimensions_mm: float | None) -> list[tuple[str, tuple[float, ...]]]:
    """The chain given by --d-mm, --t-mm, --R0-mm, --a-mm as a one-element list (or none)."""
    given = {key: value for key, value in dimensions_mm.items() if value is not None}
    if not given:
        return []
    missing = [f"--{key.replace('_', '-')}" for key in dimensions_mm if key not in given]
    if missing:
        raise typer.BadParameter(
            f"a chain given by its dimensions needs all four; missing {', '.join(missing)}"
        )
    d, t, R0, a = (given[f"{key}_mm"] for key in _DIMENSIONS)
    return [(f"{d:g}x{t:g} (given)", tuple(to_si([d, t, R0, a], "mm")))]


def _row(
    name: str, lengths, published: PublishedStiffness | None, *, E, coefficients, band
) -> tuple[dict, list[str]]:
    """One table row and its notes (geometry warnings, published values not reproduced).

    `published` is the chain's Table 1 row (:func:`~pipeline.theory.link_stiffness.table_1`),
    None for other chains.
    """
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            E0 = chain_stiffness(*lengths, E=E, coefficients=coefficients)
    except ValueError as error:
        raise typer.BadParameter(f"{name}: {error}") from None
    notes = [f"{name}: {warning.message}" for warning in caught]
    row = {"chain": name}
    dimensions = zip(_DIMENSIONS, lengths, strict=True)
    row |= {f"{key}_mm": from_si(value, "mm") for key, value in dimensions}
    row |= {"E0_kgf": from_si(E0, "kgf"), "E0_kN": from_si(E0, "kN")}
    row |= _comparison(row["E0_kgf"], published, band)
    if published is not None:
        notes += _reproduction_notes(name, row["E0_kgf"], published)
    return row, notes


def _comparison(E0_kgf: float, published: PublishedStiffness | None, band) -> dict:
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
