"""The packaged chain catalogue: round-link mining chains and ISO 606 roller chains.

The data live in ``pipeline/data/chains.csv``, one value a row, each with its
unit and its source. Values are returned in SI units (converted with pint).

Quantities
----------
round-link chains: ``d`` bar diameter, ``t`` pitch, ``R0`` centre-line radius of
the curved ends, ``a`` length of the straight parts, ``r_outer`` outer torus
radius, ``groove_width`` (Paper 003's c), ``mass_per_length``, ``preload`` and
``upper_load`` of Paper 001's tensile tests (forces).
roller chains: ``t`` pitch, ``roller_diameter``, ``inner_width``,
``pin_diameter``, ``bush_length``, ``plate_span``, ``mass_per_length``,
``breaking_force``.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass, field
from functools import cache
from importlib.resources import files

from pipeline.units import to_si


@dataclass(frozen=True)
class ChainSpec:
    """One catalogue chain: values in SI units with the source of each."""

    name: str
    kind: str  #: ``"round_link"`` or ``"roller"``
    values: dict[str, float] = field(default_factory=dict)
    sources: dict[str, str] = field(default_factory=dict)

    def __getitem__(self, quantity: str) -> float:
        try:
            return self.values[quantity]
        except KeyError:
            raise KeyError(
                f"the catalogue has no {quantity!r} for chain {self.name}; "
                f"known: {', '.join(sorted(self.values))}"
            ) from None

    def get(self, quantity: str, default: float | None = None) -> float | None:
        return self.values.get(quantity, default)


@cache
def _load() -> dict[str, ChainSpec]:
    text = files("pipeline.data").joinpath("chains.csv").read_text(encoding="utf-8")
    chains: dict[str, ChainSpec] = {}
    for row in csv.DictReader(text.splitlines()):
        spec = chains.setdefault(row["chain"], ChainSpec(row["chain"], row["kind"]))
        spec.values[row["quantity"]] = to_si(float(row["value"]), row["unit"])
        spec.sources[row["quantity"]] = row["source"]
    return chains


def chain_names(kind: str | None = None) -> list[str]:
    """Names of the catalogue chains, optionally of one `kind` only."""
    return [name for name, spec in _load().items() if kind in (None, spec.kind)]


def chain(name: str) -> ChainSpec:
    """The catalogue entry `name` (e.g. ``"18x64"``, ``"16B"``).

    Raises
    ------
    KeyError
        When the catalogue has no such chain; the message lists the known ones.
    """
    try:
        return _load()[name]
    except KeyError:
        raise KeyError(
            f"unknown chain {name!r}; the catalogue has: {', '.join(chain_names())}"
        ) from None
