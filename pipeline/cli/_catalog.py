"""Chain data for the CLI: catalogue entries with command-line overrides."""

from __future__ import annotations

from collections.abc import Mapping

import typer

from pipeline import catalog
from pipeline.units import to_si


def chain_inputs(
    name: str | None,
    kind: str,
    given: Mapping[str, float | None],
    options: Mapping[str, tuple[str, str]],
) -> dict[str, float]:
    """The chain quantities a command needs [SI]: the options given, else the catalogue's.

    Parameters
    ----------
    name : str or None
        Catalogue chain (``--chain``), or None when every quantity is given.
    kind : str
        The catalogue kind the chain must be (``"roller"``, ``"round_link"``).
    given : mapping
        Quantity -> value given on the command line (in the option's unit) or None.
    options : mapping
        Quantity -> (option flag, unit of the option).

    Raises
    ------
    typer.BadParameter
        For an unknown chain, a chain of another kind, or a quantity neither
        given nor in the catalogue (the message names the option to give).
    """
    spec = catalogue_chain(name, kind) if name is not None else None
    values = {}
    for quantity, (flag, unit) in options.items():
        if given[quantity] is not None:
            values[quantity] = to_si(given[quantity], unit)
        elif spec is not None and spec.get(quantity) is not None:
            values[quantity] = spec[quantity]
        else:
            source = f"the catalogue has no {quantity} for chain {name}" if spec else "no --chain"
            raise typer.BadParameter(f"{source}: give {flag} [{unit}]", param_hint=flag)
    return values


def catalogue_chain(name: str, kind: str) -> catalog.ChainSpec:
    """The catalogue entry `name`, which must be of `kind`."""
    try:
        spec = catalog.chain(name)
    except KeyError as error:
        raise typer.BadParameter(error.args[0], param_hint="--chain") from None
    if spec.kind != kind:
        known = ", ".join(catalog.chain_names(kind))
        raise typer.BadParameter(
            f"{name} is not a {kind} chain; use one of: {known}", param_hint="--chain"
        )
    return spec
