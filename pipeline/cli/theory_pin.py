"""``chainbench theory pin``: pin criterion for roller chains of open drives (Paper 004).

Per number of sprocket teeth and pin support (K = 1 pinned, K = 3 clamped):
the allowed pitch growth delta_t1, the allowed pin wear delta_d, the critical
pin diameter d_k, the required diameter d_k + delta_d and the verdict for the
chain's pin.

Example (the hand-worked example of ``docs/models/paper-004-pin-criterion.md``)::

    chainbench theory pin --chain 16B --f-max-kn 12 --sigma-t-mpa 800 --teeth 40 --json
"""

from __future__ import annotations

from typing import Annotated

import typer

from pipeline.cli._catalog import chain_inputs
from pipeline.cli._output import emit
from pipeline.theory import pin_criterion as pc
from pipeline.units import from_si, to_si

#: Chain quantities: the option overriding the catalogue, and its unit.
_CHAIN_OPTIONS = {
    "t": ("--pitch-mm", "mm"),
    "pin_diameter": ("--pin-diameter-mm", "mm"),
    "bush_length": ("--bush-length-mm", "mm"),
    "plate_span": ("--plate-span-mm", "mm"),
}


def command(
    f_max_kn: Annotated[
        float, typer.Option("--f-max-kn", help="Largest force on a chain link F_max [kN].")
    ],
    sigma_t_mpa: Annotated[
        float,
        typer.Option("--sigma-t-mpa", help="Allowable bending stress of the pin [sigma_T] [MPa]."),
    ],
    teeth: Annotated[
        list[int],
        typer.Option("--teeth", help="Teeth z of the driven sprocket, e.g. 20 40 (or 20,40)."),
    ],
    chain: Annotated[
        str | None,
        typer.Option("--chain", help="Roller chain of the catalogue, e.g. 16B."),
    ] = None,
    wear_coefficient: Annotated[
        float,
        typer.Option(
            "--wear-coefficient",
            help="Pin wear coefficient K_e [-] (Paper 004 gives no value).",
        ),
    ] = 1.0,
    pitch_mm: Annotated[
        float | None,
        typer.Option("--pitch-mm", help="Chain pitch t [mm]; default the catalogue's."),
    ] = None,
    pin_diameter_mm: Annotated[
        float | None,
        typer.Option(
            "--pin-diameter-mm", help="Nominal pin diameter d [mm]; default the catalogue's."
        ),
    ] = None,
    bush_length_mm: Annotated[
        float | None,
        typer.Option("--bush-length-mm", help="Bush length l [mm]; default the catalogue's."),
    ] = None,
    plate_span_mm: Annotated[
        float | None,
        typer.Option(
            "--plate-span-mm",
            help="Span l1 between the outer-plate mid-planes [mm]; default the catalogue's.",
        ),
    ] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON instead of a table.")] = False,
) -> None:
    """Paper 004: does the chain's pin satisfy d >= d_k + delta_d?

    Give a catalogue chain with --chain, or every chain quantity with its option.
    """
    given = {
        "t": pitch_mm,
        "pin_diameter": pin_diameter_mm,
        "bush_length": bush_length_mm,
        "plate_span": plate_span_mm,
    }
    inputs = chain_inputs(chain, "roller", given, _CHAIN_OPTIONS)
    force, stress = to_si(f_max_kn, "kN"), to_si(sigma_t_mpa, "MPa")
    try:
        rows = pc.table(inputs, teeth, force, stress, wear_coefficient)
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    emit(
        rows,
        title=f"Paper 004: pin criterion, chain {chain or 'as given'}",
        as_json=as_json,
        extra={
            "inputs": {
                "chain": chain,
                **{f"{q}_mm": from_si(v, "mm") for q, v in inputs.items()},
                "f_max_kN": f_max_kn,
                "sigma_T_MPa": sigma_t_mpa,
                "wear_coefficient": wear_coefficient,
            }
        },
        notes=[
            f"psi = {pc.PITCH_GROWTH_SAFETY:g}, delta_t_n = {pc.PITCH_ERROR_FRACTION:g} t "
            "(eq. (3)); K = 1 pinned, K = 3 clamped (eq. (4)); passes: d >= d_k + delta_d "
            "(eq. (1))"
        ],
    )
