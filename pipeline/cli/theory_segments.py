"""``chainbench theory tooth-segments``: loads on segmented teeth of a chain drum (Paper 003).

Per flank inclination beta, link inclination eps_n and contact distance s: the
contact radius k, the segment opening angle psi, F_K/F, F_P/F and the friction
increase. The defaults are Paper 003's cases (chain 34x126); the published
values the model does not reproduce are noted under the table.

Example::

    chainbench theory tooth-segments --chain 34x126 --beta 50 80 --eps-n 0 6 --s 45 70 --json
"""

from __future__ import annotations

from typing import Annotated

import typer

from pipeline.cli._catalog import chain_inputs
from pipeline.cli._output import emit
from pipeline.theory import tooth_segments as ts
from pipeline.units import from_si

DEFAULT_CHAIN = "34x126"
DEFAULT_BETA_DEG = [50.0, 80.0]
DEFAULT_EPS_N_DEG = [0.0, 6.0]
DEFAULT_S_MM = [45.0, 70.0]

#: Chain quantities: the option overriding the catalogue, and its unit.
_CHAIN_OPTIONS = {
    "r_outer": ("--r-outer-mm", "mm"),
    "d": ("--d-mm", "mm"),
    "groove_width": ("--groove-width-mm", "mm"),
}


def command(
    chain: Annotated[
        str,
        typer.Option(
            "--chain", help="Round-link chain of the catalogue; default 34x126 (Paper 003)."
        ),
    ] = DEFAULT_CHAIN,
    beta: Annotated[
        list[float] | None,
        typer.Option("--beta", help="Flank inclinations beta [deg]; default 50 80."),
    ] = None,
    eps_n: Annotated[
        list[float] | None,
        typer.Option(
            "--eps-n", help="Link inclinations to the pocket floor eps_n [deg]; default 0 6."
        ),
    ] = None,
    s: Annotated[
        list[float] | None,
        typer.Option("--s", help="Distances s between the contact points [mm]; default 45 70."),
    ] = None,
    r_outer_mm: Annotated[
        float | None,
        typer.Option("--r-outer-mm", help="Outer torus radius r [mm]; default the catalogue's."),
    ] = None,
    d_mm: Annotated[
        float | None, typer.Option("--d-mm", help="Link thickness d [mm]; default the catalogue's.")
    ] = None,
    groove_width_mm: Annotated[
        float | None,
        typer.Option("--groove-width-mm", help="Groove width c [mm]; default the catalogue's."),
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a table.")] = False,
) -> None:
    """Paper 003: contact radius, segment opening angle and segment forces of a chain drum.

    The options --r-outer-mm, --d-mm and --groove-width-mm override the catalogue.
    """
    given = {"r_outer": r_outer_mm, "d": d_mm, "groove_width": groove_width_mm}
    inputs = chain_inputs(chain, "round_link", given, _CHAIN_OPTIONS)
    try:
        rows = ts.table(
            inputs, beta or DEFAULT_BETA_DEG, eps_n or DEFAULT_EPS_N_DEG, s or DEFAULT_S_MM
        )
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    published = ts.compare_published()
    emit(
        rows,
        title=f"Paper 003: segmented tooth loads, chain {chain}",
        as_json=as_json,
        extra={
            "inputs": {"chain": chain, **{f"{q}_mm": from_si(v, "mm") for q, v in inputs.items()}},
            "published": published.to_dict("records"),
        },
        notes=ts.published_notes(inputs, published),
    )
