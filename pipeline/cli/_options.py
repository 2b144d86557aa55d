"""List options that take several values after one flag: ``--teeth 6 8 10``.

Click, and so Typer, gives a list option one value per flag (``--teeth 6 --teeth
8``) and has no ``nargs=-1`` for options. Register a command with
``cls=MultiValueCommand`` and each of its list options also takes the values
that follow the flag up to the next option, separated by spaces or commas:
``--teeth 6 8 10``, ``--teeth 6,8,10``, ``--teeth "6 8 10"``, ``--teeth=6,8``
and ``--teeth 6 --teeth 8 --teeth 10`` all give ``[6, 8, 10]``. Negative
numbers count as values. A command with such options cannot also take
positional arguments right after them (they would be read as values).

Example::

    theory_app.command("impact", cls=MultiValueCommand)(theory_impact.command)
"""

from __future__ import annotations

import re
from collections.abc import Collection, Sequence

import typer
from typer.core import TyperCommand

_SEPARATORS = re.compile(r"[,\s]+")


def _is_option(token: str) -> bool:
    """True for ``--name``, ``--name=value`` and ``-n``; False for values such as ``-5``."""
    if len(token) < 2 or not token.startswith("-"):
        return False
    try:
        float(token)
    except ValueError:
        return True
    return False


def _values(token: str) -> list[str]:
    """The space- or comma-separated values in `token`."""
    return [value for value in _SEPARATORS.split(token) if value]


def spread_values(args: Sequence[str], flags: Collection[str]) -> list[str]:
    """Rewrite ``--flag a b,c`` as ``--flag a --flag b --flag c`` for every flag in `flags`.

    Parameters
    ----------
    args : sequence of str
        Command-line tokens (without the program and command names).
    flags : collection of str
        Option names that accept several values (e.g. ``{"--teeth", "--apex"}``).

    Returns
    -------
    list of str
        The tokens with one value after each occurrence of a flag; tokens after
        ``--`` and tokens of other options are left as they are.

    Examples
    --------
    >>> spread_values(["--teeth", "6", "8,10", "--json"], {"--teeth"})
    ['--teeth', '6', '--teeth', '8', '--teeth', '10', '--json']
    """
    spread: list[str] = []
    flag: str | None = None  # the multi-value flag whose values are being read
    for position, token in enumerate(args):
        if token == "--":
            return spread + list(args[position:])
        if flag is not None and not _is_option(token):
            for value in _values(token):
                # the first value after a bare flag needs no repeated flag
                spread += [value] if spread[-1] == flag else [flag, value]
            continue
        name, equals, inline = token.partition("=")
        flag = name if name in flags else None
        if flag is not None and equals:
            spread += [part for value in _values(inline) for part in (flag, value)]
        else:
            spread.append(token)
    return spread


class MultiValueCommand(TyperCommand):
    """A Typer command whose list options take several values after one flag."""

    def parse_args(self, ctx: typer.Context, args: list[str]) -> list[str]:
        flags = {
            name
            for param in self.params
            if param.param_type_name == "option" and param.multiple
            for name in param.opts
        }
        return super().parse_args(ctx, spread_values(args, flags))
