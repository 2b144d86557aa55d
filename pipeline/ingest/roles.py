"""Which column of a file plays which role, from its name, its unit or the run sheet.

Runs before the body is parsed, so that only the candidate columns are read as
numbers; :mod:`pipeline.ingest.canonical` settles the final roles once it knows
which candidates are empty.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from pipeline.errors import ColumnError
from pipeline.ingest.names import fold, is_unmeasured, match_role
from pipeline.ingest.unitparse import is_temperature_unit, unit_role

#: Keys accepted in the run sheet's ``columns`` and ``units``, and the role each names.
ROLE_KEYS = {
    "time": "time",
    "force": "force",
    "gauge": "gauge",
    "gauges": "gauge",
    "angle": "angle",
    "cycle": "cycle_count",
    "cycles": "cycle_count",
    "cycle_count": "cycle_count",
    "length": "length",
    "speed": "speed",
    "segment_force_1": "segment_force_1",
    "segment_force_2": "segment_force_2",
    "side_force": "side_force",
}

#: The run-sheet key shown in hints for each role.
SHEET_KEY = {"time": "time", "force": "force", "gauge": "gauges", "angle": "angle",
             "cycle_count": "cycle_count", "length": "length", "speed": "speed",
             "segment_force_1": "segment_force_1", "segment_force_2": "segment_force_2",
             "side_force": "side_force"}


@dataclass(frozen=True)
class Candidates:
    """Columns that may take each role.

    Attributes
    ----------
    roles : dict
        Role -> column indexes, in file order (run-sheet order when explicit).
    explicit : frozenset of str
        Roles named in the run sheet's ``columns``.
    """

    roles: dict[str, list[int]]
    explicit: frozenset[str]

    def indexes(self) -> set[int]:
        """Every candidate column."""
        return {index for indexes in self.roles.values() for index in indexes}

    def without(self, columns: frozenset[int], but: str | None = None
                ) -> tuple[Candidates, dict[int, str]]:
        """These candidates but `columns`, where the run sheet does not name them nor are
        they candidates for role `but`; and the role each column left out was a candidate
        for."""
        left_out = {index: role for role, indexes in self.roles.items()
                    if role not in self.explicit and role != but
                    for index in indexes if index in columns}
        roles = {role: kept for role, indexes in self.roles.items()
                 if (kept := [index for index in indexes if index not in left_out])}
        return Candidates(roles, self.explicit), left_out


def role_of_key(key: str, *, file: Path | str, what: str) -> str:
    """The role a run-sheet key names (``"gauges"`` -> ``"gauge"``)."""
    role = ROLE_KEYS.get(str(key).strip().lower())
    if role is None:
        raise ColumnError(
            f"unknown role {key!r} in the run sheet's {what}",
            file=file, column=str(key),
            hint="roles are " + ", ".join(sorted(SHEET_KEY.values())),
        )
    return role


def display_name(names: list[str], index: int) -> str:
    """A column's name, or ``"column N"`` (1-based) when the file leaves it blank."""
    return names[index] or f"column {index + 1}"


#: A run sheet's column given by its place, from 1 (``"column 3"``), folded.
_PLACE = re.compile(r"column\s*(\d+)")


def _lookup(wanted: str, names: list[str], role: str, file: Path | str, line: int | None) -> int:
    target = fold(str(wanted).strip())
    hits = ([index for index, name in enumerate(names) if target == fold(name.strip())]
            or [index for index, name in enumerate(names)  # a channel after its group's
                if target == fold(name.rsplit("/", 1)[-1].strip())])  # name: not L0 of ΔL/L0
    place = _PLACE.fullmatch(target)
    if not hits and place and 1 <= int(place.group(1)) <= len(names):
        hits = [int(place.group(1)) - 1]  # "column N": the Nth field, as the messages call it
    if not hits:
        raise ColumnError(
            f"no column {wanted!r} (given for {role} in the run sheet)",
            file=file, row=line, column=str(wanted),
            hint="the file has: " + ", ".join(display_name(names, i) for i in range(len(names))),
        )
    if len(hits) > 1:
        raise ColumnError(
            f"column {wanted!r} appears {len(hits)} times (fields "
            + ", ".join(str(index + 1) for index in hits) + ")",
            file=file, row=line, column=str(wanted),
            hint=f"name it by its place, as \"column {hits[0] + 1}\", or rename the "
                 "duplicated columns in the export so that each name is unique",
        )
    return hits[0]


def find_candidates(
    names: list[str],
    units: list[str | None],
    columns: Mapping | None,
    *,
    file: Path | str,
    header_line: int | None,
) -> Candidates:
    """Give each column a role, from the run sheet or from its name and unit.

    Parameters
    ----------
    names : list of str
        The file's column names, without units.
    units : list of str or None
        The unit of each column as found in the file.
    columns : mapping, optional
        Run-sheet ``columns``: role -> column name (a list for ``gauges``).
        Names are matched case-insensitively; ``"Channel"`` also matches
        ``"Group/Channel"``. Roles not given are matched automatically among
        the other columns, by name or unit.
    file : Path or str
        The file, for messages.
    header_line : int or None
        The line of the names row, for messages.

    Returns
    -------
    Candidates

    Raises
    ------
    ColumnError
        If a named column is missing or duplicated, or a key is not a role.
    """
    roles: dict[str, list[int]] = {}
    for key, wanted in (columns or {}).items():
        role = role_of_key(key, file=file, what="columns")
        wanted_list = [wanted] if isinstance(wanted, str) else list(wanted)
        roles[role] = [_lookup(name, names, role, file, header_line) for name in wanted_list]
    explicit = frozenset(roles)
    claimed = {index for indexes in roles.values() for index in indexes}
    for index, name in enumerate(names):
        if index in claimed:
            continue
        role = match_role(name) or (None if is_unmeasured(name) else unit_role(units[index]))
        if is_temperature_unit(units[index]):
            role = None  # a temperature, whatever its name (English temps, French time)
        if role == "gauge" and unit_role(units[index]) == "angle":
            role = "angle"  # a position in degrees is a rotary one (an encoder's)
        if role is not None and role not in explicit:
            roles.setdefault(role, []).append(index)
    return Candidates(roles, explicit)
