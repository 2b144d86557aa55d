"""``chainbench theory tooth-segments``: loads on segmented teeth of a chain drum (Paper 003).

Per flank inclination beta, link inclination eps_n and contact distance s: the
contact radius k, the segment opening angle psi, F_K/F, F_P/F and the friction
increase. The defaults are Paper 003's cases (chain 34x126); the published
values the model does not reproduce are noted under the table.

Example::

    chainbench theory tooth-segments --chain 34x126 --beta 50 80 --eps-n 0 6 --s 45 70 --json
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Annotated

import numpy as np
import pandas as pd
import typer

from pipeline.cli._catalog import chain_inputs
from pipeline.cli._output import emit
from pipeline.theory import tooth_segments as ts
from pipeline.theory._published import parse_inputs
from pipeline.units import from_si, to_si

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


def segment_rows(
    chain: Mapping[str, float], beta_deg: list[float], eps_n_deg: list[float], s_mm: list[float]
) -> list[dict]:
    """One row per (beta, eps_n, s), beta varying slowest, in the units the keys name.

    `chain` holds r_outer, d and groove_width [m]; s below the groove width or
    at least 2 k raises ``ValueError``.
    """
    grids = np.meshgrid(beta_deg, eps_n_deg, s_mm, indexing="ij")
    beta, eps_n, s = (grid.ravel() for grid in grids)
    k = ts.contact_radius(chain["r_outer"], chain["d"], np.radians(beta), np.radians(eps_n))
    psi = ts.opening_angle(to_si(s, "mm"), k, chain["groove_width"])
    columns = {
        "beta_deg": beta,
        "eps_n_deg": eps_n,
        "s_mm": s,
        "k_mm": from_si(k, "mm"),
        "psi_deg": np.degrees(psi),
        "F_K/F": ts.contact_force_ratio(psi),
        "F_P/F": ts.side_force_ratio(psi),
        "friction_increase_pct": 100.0 * ts.friction_increase(psi),
    }
    return [dict(zip(columns, row, strict=True)) for row in zip(*columns.values(), strict=True)]


def _published_notes(chain: Mapping[str, float], published: pd.DataFrame) -> list[str]:
    """Paper 003's values not reproduced, when the chain has the paper's r and d.

    `published` is :func:`pipeline.theory.tooth_segments.compare_published`.
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
    return [summary, *(_flag(row) for row in flagged.itertuples())]


def _flag(row) -> str:
    """One line for a published value the model does not reproduce (a row of the comparison)."""
    return (
        f"{row.source}: {row.quantity} ({row.inputs}): published {row.published:g} {row.unit}, "
        f"model {row.model:.5g} ({100 * row.rel_diff:+.2f} %): NOT reproduced "
        f"within {100 * row.tolerance:g} %"
    )


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
        rows = segment_rows(
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
        notes=_published_notes(inputs, published),
    )
