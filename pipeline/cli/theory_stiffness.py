"""``chainbench theory stiffness``: static stiffness E0 of round-link chains (Paper 001).

Eq. (20) per chain, beside the published Table 1 values where the chain is one
of the paper's, with the discrepancy of the measured E0 and the band verdict.
"""

from __future__ import annotations

from enum import StrEnum
from typing import Annotated

import typer

from pipeline.catalog import chain
from pipeline.cli._output import emit
from pipeline.theory.link_stiffness import (
    LAB_BAND,
    PAPER_E_KGF_PER_CM2,
    PRINTED,
    TABLE_DIMENSIONS,
    exact_coefficients,
    table,
    table_1,
)
from pipeline.units import to_si


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
    names = chains or ([] if explicit else list(table_1()))
    links = [_catalogue_link(name) for name in names] + explicit
    try:
        rows, notes = table(
            links, E=to_si(E_kgf_per_cm2, "kgf/cm^2"),
            coefficients=PRINTED if coefficients is CoefficientSet.printed
            else exact_coefficients(),
            band=(band_pct[0] / 100, band_pct[1] / 100))
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
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
        return name, tuple(spec[quantity] for quantity in TABLE_DIMENSIONS)
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
    d, t, R0, a = (given[f"{key}_mm"] for key in TABLE_DIMENSIONS)
    return [(f"{d:g}x{t:g} (given)", tuple(to_si([d, t, R0, a], "mm")))]
