"""``chainbench theory impact``: Paper 000's impact tensions over a grid of wheels.

Example (Paper 000's case)::

    chainbench theory impact --chain 18x64 --teeth 6 8 10 --apex 20 30 40 50 60 \\
        --omega 20 --branch-length 2 --json
"""

from __future__ import annotations

from typing import Annotated

import typer

from pipeline import catalog
from pipeline.cli._catalog import catalogue_chain
from pipeline.cli._output import emit
from pipeline.theory import wheel_impact as wi

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
    if not wi.is_paper_chain(spec["t"], spec["d"]):
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
        rows = wi.table(
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
        units=wi.TABLE_UNITS,
        notes=[
            "units: psi in deg, v in m/s, N in N, tau in s; "
            f"omega = {omega:g} 1/s, L = {branch_length:g} m, "
            f"E0 = {inputs['E0']:.4g} N, q/g = {inputs['mass_per_length']:g} kg/m, k = {k:g}",
            *wi.published_notes(spec["t"], spec["d"]),
        ],
    )
