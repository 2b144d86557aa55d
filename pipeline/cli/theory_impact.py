"""``chainbench theory impact``: Paper 000's impact tensions over a grid of wheels.

Example (Paper 000's case)::

    chainbench theory impact --chain 18x64 --teeth 6 8 10 --apex 20 30 40 50 60 \\
        --omega 20 --branch-length 2 --json
"""

from __future__ import annotations

import math
from typing import Annotated

import numpy as np
import typer

from pipeline import catalog
from pipeline.cli._catalog import catalogue_chain
from pipeline.cli._output import emit
from pipeline.theory import wheel_impact as wi

#: Units of the row members.
UNITS = {
    "z": "1",
    "psi_deg": "deg",
    "v_u1": "m/s",
    "v_u2": "m/s",
    "N_u1": "N",
    "N_u2": "N",
    "N_u2/N_u1": "1",
    "tau": "s",
}

#: The command-line option of each model parameter, to point errors at it.
_OPTION_OF = {
    "z": "--teeth",
    "psi": "--apex",
    "omega": "--omega",
    "branch_length": "--branch-length",
    "E0": "--E0",
    "k": "--k",
    "mass_per_length": "--mass-per-m",
}


def impact_rows(
    t: float,
    d: float,
    teeth: list[int],
    apex_deg: list[float],
    omega: float,
    mass_per_length: float,
    E0: float,
    branch_length: float,
    k: float,
) -> list[dict]:
    """One row per wheel (z) and apex angle (psi), z varying slowest.

    Arguments are SI (see :mod:`pipeline.theory.wheel_impact`) except `apex_deg`
    [deg]; each row holds z, psi_deg, v_u1, v_u2, N_u1, N_u2, N_u2/N_u1 and tau
    in the units of :data:`UNITS`.
    """
    z, psi_deg = (grid.ravel() for grid in np.meshgrid(teeth, apex_deg, indexing="ij"))
    tau = wi.time_between_impacts(z, omega)  # first: it also rejects omega = 0
    v_u1, v_u2 = wi.impact_velocities(t, d, z, np.radians(psi_deg), omega)
    n_u1, n_u2 = (
        wi.impact_tension(v, mass_per_length, t, E0, branch_length, k) for v in (v_u1, v_u2)
    )
    columns = zip(z, psi_deg, v_u1, v_u2, n_u1, n_u2, n_u2 / n_u1, tau, strict=True)
    return [dict(zip(UNITS, (int(row[0]), *map(float, row[1:])), strict=True)) for row in columns]


def _is_paper_chain(spec: catalog.ChainSpec) -> bool:
    """Whether `spec` has the pitch and bar diameter of Paper 000's example chain."""
    example = wi.paper_example()
    return all(math.isclose(spec[name], example[name]) for name in ("t", "d"))


def _published_notes(spec: catalog.ChainSpec) -> list[str]:
    """Paper 000's published numbers and whether the model reproduces them (its chain only)."""
    if not _is_paper_chain(spec):
        return []
    case = wi.paper_example()
    notes = [
        f"Paper 000 (section 3) publishes, for q = {case['mass_per_length']:g} kg/m * g, "
        f"E0 = {case['E0']:g} N, L = {case['branch_length']:g} m, "
        f"omega = {case['omega']:g} 1/s, k = {case['k']:g}:"
    ]
    for row in wi.compare_published().itertuples():
        unit = "" if row.unit == "-" else f" {row.unit}"
        status = "reproduced" if row.reproduced else "NOT REPRODUCED by the model"
        notes.append(
            f"  {row.quantity} = {row.published:g}{unit}, model {row.model:.4g}{unit}: {status} "
            f"(tolerance {100 * row.tolerance:g} %)"
        )
    return notes


def _mass_per_length(spec: catalog.ChainSpec, given: float | None) -> float:
    """The mass per metre [kg/m]: `given`, else the catalogue's."""
    mass = given if given is not None else spec.get("mass_per_length")
    if mass is None:
        raise typer.BadParameter(
            f"the catalogue has no mass per metre for chain {spec.name}: give it in kg/m",
            param_hint="--mass-per-m",
        )
    return mass


def _stiffness(spec: catalog.ChainSpec, given: float | None) -> float:
    """E0 [N]: `given`, else Paper 000's value for its own chain."""
    if given is not None:
        return given
    example = wi.paper_example()
    if not _is_paper_chain(spec):
        raise typer.BadParameter(
            f"Paper 000 gives E0 for its example chain only (t = {1e3 * example['t']:g} mm, "
            f"d = {1e3 * example['d']:g} mm): give the stiffness of {spec.name} in N "
            "(e.g. from a tensile test)",
            param_hint="--E0",
        )
    return example["E0"]


def command(
    chain: Annotated[
        str, typer.Option("--chain", help="Round-link chain of the catalogue, e.g. 18x64.")
    ],
    teeth: Annotated[
        list[int], typer.Option("--teeth", help="Numbers of teeth z, e.g. 6 8 10 (or 6,8,10).")
    ],
    apex: Annotated[
        list[float],
        typer.Option(
            "--apex", help="Tooth apex angles psi in degrees, e.g. 20 30 40 (or 20,30,40)."
        ),
    ],
    omega: Annotated[float, typer.Option("--omega", help="Wheel angular velocity omega in 1/s.")],
    branch_length: Annotated[
        float, typer.Option("--branch-length", help="Length L of the active chain branch in m.")
    ],
    e0: Annotated[
        float | None,
        typer.Option(
            "--E0", help="Chain stiffness in N; default Paper 000's 2.26e7 N (18x64 only)."
        ),
    ] = None,
    k: Annotated[
        float, typer.Option("--k", help="Share of link masses in the impact; Ryabov's 2.")
    ] = wi.RYABOV_MASS_SHARE,
    mass_per_m: Annotated[
        float | None,
        typer.Option("--mass-per-m", help="Chain mass per metre in kg/m; default the catalogue's."),
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a table.")] = False,
) -> None:
    """Paper 000: impact velocities and impact tensions N_u1, N_u2 of a link chain on pocket wheels.

    N_u1 is the strike on the idle tooth flank, N_u2 the one on the working
    flank a time tau later; both are peak tensions of an undamped branch.
    """
    spec = catalogue_chain(chain, "round_link")
    inputs = {
        "chain": chain,
        "t": spec["t"],
        "d": spec["d"],
        "mass_per_length": _mass_per_length(spec, mass_per_m),
        "E0": _stiffness(spec, e0),
        "branch_length": branch_length,
        "omega": omega,
        "k": k,
    }
    try:
        rows = impact_rows(
            inputs["t"], inputs["d"], teeth, apex, omega, inputs["mass_per_length"],
            inputs["E0"], branch_length, k,
        )  # fmt: skip
    except ValueError as error:
        message = str(error)
        raise typer.BadParameter(message, param_hint=_OPTION_OF.get(message.split()[0])) from None
    emit(
        rows,
        title=f"Paper 000: impact tensions, chain {chain}",
        as_json=as_json,
        extra={"inputs": inputs},
        units=UNITS,
        notes=[
            "units: psi in deg, v in m/s, N in N, tau in s; "
            f"omega = {omega:g} 1/s, L = {branch_length:g} m, "
            f"E0 = {inputs['E0']:.4g} N, q/g = {inputs['mass_per_length']:g} kg/m, k = {k:g}",
            *_published_notes(spec),
        ],
    )
