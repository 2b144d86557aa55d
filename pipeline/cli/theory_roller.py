"""``chainbench theory roller-impact``: roller chain on an involute sprocket (Paper 002).

Per number of teeth and sprocket speed: the bounds of the impact-velocity
coefficient xi, xi of the involute sprocket, the impact velocity, the impact
energy, the specific impact energy and the speed limit n_max.

Example::

    chainbench theory roller-impact --chain 20B --teeth 10 15 20 25 --rpm 500 1000 --json
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Annotated

import numpy as np
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


def roller_rows(
    chain: Mapping[str, float],
    teeth: list[int],
    rpm: list[float],
    xi: float | None,
    module: float,
    profile_angle: float,
    g_lim: float,
) -> list[dict]:
    """One row per number of teeth and speed, teeth varying slowest.

    `chain` holds t, mass_per_length, roller_diameter and inner_width [SI];
    `module` [m], `profile_angle` [rad], `g_lim` [J/m^2]. `xi` None means xi of
    the involute sprocket (eqs. (3)-(5)). Rows are in the units their keys name.
    """
    z, n_rpm = (grid.ravel() for grid in np.meshgrid(teeth, rpm, indexing="ij"))
    t, q = chain["t"], chain["mass_per_length"]
    diameter, width = chain["roller_diameter"], chain["inner_width"]
    if xi is None:
        xi_z = ri.impact_velocity_coefficient(z, ri.base_radius(module, z, profile_angle), t)
    else:
        xi_z = np.full(z.shape, xi)
    low, high = ri.impact_velocity_coefficient_bounds(z)
    omega = to_si(n_rpm, "rpm")
    energy = ri.impact_energy(q, omega, t, xi_z)
    n_max = from_si(ri.max_angular_velocity(q, t, xi_z, diameter, width, g_lim), "rpm")
    columns = {
        "z": z.astype(int).tolist(),
        "n_rpm": n_rpm,
        "xi_min": low,
        "xi_max": high,
        "xi": xi_z,
        "v_y_m_per_s": ri.impact_velocity(omega, t, xi_z),
        "energy_J": energy,
        "G_J_per_mm2": from_si(ri.specific_impact_energy(energy, diameter, width), "J/mm^2"),
        "n_max_rpm": n_max,
        "below_n_max": n_rpm <= n_max,
    }
    return [dict(zip(columns, row, strict=True)) for row in zip(*columns.values(), strict=True)]


def _notes(xi: float | None, module_mm: float, profile_angle_deg: float) -> list[str]:
    """How xi was obtained, and Paper 002's printed constants beside the derived ones."""
    how = (
        f"xi given ({xi:g}), not computed"
        if xi is not None
        else f"xi of an involute sprocket, m = {module_mm:.4g} mm, alpha = "
        f"{profile_angle_deg:g} deg (eqs. (3)-(5)); xi for the GOST 591/592 profiles "
        "cannot be derived from Paper 002: read it off its Fig. 2 and give --xi"
    )
    constants = [
        f"{row.source}: {row.quantity} published {row.published:.4g}, "
        f"derived {row.model:.5g} {row.unit}" + ("" if row.reproduced else f"; {row.note}")
        for row in ri.compare_published().itertuples()
    ]
    return [how, *constants]


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
        rows = roller_rows(
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
        notes=_notes(xi, from_si(module, "mm"), profile_angle_deg),
    )
