"""``chainbench theory roller-impact``: roller chain on an involute sprocket (Paper 002).

Per number of teeth and sprocket speed: the bounds of the impact-velocity
coefficient xi, xi of the involute sprocket, the impact velocity, the impact
energy, the specific impact energy and the speed limit n_max.

Example::

    chainbench theory roller-impact --chain 20B --teeth 10 15 20 25 --rpm 500 1000 --json
"""

from __future__ import annotations

import math
from typing import Annotated

import typer

from pipeline.cli._catalog import chain_inputs
from pipeline.cli._output import emit
from pipeline.theory import roller_impact as ri
from pipeline.units import from_si, to_si

DEFAULT_TEETH = [10, 15, 20, 25, 30]
DEFAULT_RPM = [500.0]

#: Chain quantities: the option overriding the catalogue, and its unit.
_CHAIN_OPTIONS = {
    "t": ("--pitch-mm", "mm"),
    "mass_per_length": ("--mass-per-m", "kg/m"),
    "roller_diameter": ("--roller-diameter-mm", "mm"),
    "inner_width": ("--inner-width-mm", "mm"),
}


def command(
    chain: Annotated[
        str | None,
        typer.Option("--chain", help="Roller chain of the catalogue (08B..24B), e.g. 16B."),
    ] = None,
    teeth: Annotated[
        list[int] | None,
        typer.Option(
            "--teeth",
            help="Numbers of sprocket teeth z, e.g. 10 15 20 (default).",
            show_default=False,
        ),
    ] = None,
    rpm: Annotated[
        list[float] | None,
        typer.Option("--rpm", help="Sprocket speeds n [rpm], e.g. 500 1000; default 500."),
    ] = None,
    xi: Annotated[
        float | None,
        typer.Option(
            "--xi", help="Impact-velocity coefficient [-] to use instead of the involute's."
        ),
    ] = None,
    module_mm: Annotated[
        float | None,
        typer.Option(
            "--module-mm",
            help="Module m of the involute sprocket [mm]; default t/pi "
            "(circular pitch equal to the chain pitch; Paper 002 does not state m).",
        ),
    ] = None,
    profile_angle_deg: Annotated[
        float,
        typer.Option("--profile-angle-deg", help="Tool profile angle alpha [deg] (ISO 53: 20)."),
    ] = 20.0,
    g_lim: Annotated[
        float,
        typer.Option(
            "--g-lim-j-per-mm2",
            help="Limit of the specific impact energy [J/mm^2]; Paper 002: 3e-4...4e-4.",
        ),
    ] = 3e-4,
    pitch_mm: Annotated[
        float | None,
        typer.Option("--pitch-mm", help="Chain pitch t [mm]; default the catalogue's."),
    ] = None,
    mass_per_m: Annotated[
        float | None,
        typer.Option(
            "--mass-per-m", help="Chain mass per metre q [kg/m]; default the catalogue's."
        ),
    ] = None,
    roller_diameter_mm: Annotated[
        float | None,
        typer.Option(
            "--roller-diameter-mm", help="Roller diameter D [mm]; default the catalogue's."
        ),
    ] = None,
    inner_width_mm: Annotated[
        float | None,
        typer.Option(
            "--inner-width-mm",
            help="Inner width B, taken as roller length L [mm]; default the catalogue's.",
        ),
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a table.")] = False,
) -> None:
    """Paper 002: impact velocity, impact energy and speed limit of a roller chain.

    Give a catalogue chain with --chain, or every chain quantity with its option.
    """
    given = {
        "t": pitch_mm,
        "mass_per_length": mass_per_m,
        "roller_diameter": roller_diameter_mm,
        "inner_width": inner_width_mm,
    }
    inputs = chain_inputs(chain, "roller", given, _CHAIN_OPTIONS)
    module = to_si(module_mm, "mm") if module_mm is not None else inputs["t"] / math.pi
    try:
        rows = ri.table(
            inputs, teeth or DEFAULT_TEETH, rpm or DEFAULT_RPM, xi, module,
            math.radians(profile_angle_deg), to_si(g_lim, "J/mm^2"),
        )  # fmt: skip
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    emit(
        rows,
        title=f"Paper 002: roller-chain impact, chain {chain or 'as given'}",
        as_json=as_json,
        extra={
            "inputs": {
                "chain": chain,
                "pitch_mm": from_si(inputs["t"], "mm"),
                "mass_per_m_kg": inputs["mass_per_length"],
                "roller_diameter_mm": from_si(inputs["roller_diameter"], "mm"),
                "inner_width_mm": from_si(inputs["inner_width"], "mm"),
                "module_mm": from_si(module, "mm"),
                "profile_angle_deg": profile_angle_deg,
                "g_lim_J_per_mm2": g_lim,
                "xi": xi,
            },
            "published": ri.compare_published().to_dict("records"),
        },
        notes=ri.table_notes(xi, module, math.radians(profile_angle_deg)),
    )
