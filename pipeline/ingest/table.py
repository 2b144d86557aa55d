"""The canonical table every reader returns, and its metadata.

A reader turns one raw file into ``(table, metadata)``:

``table``
    a :class:`pandas.DataFrame` of float64 columns in SI units whose names are
    *roles*, not the file's names:

    ==============  ======  ==================================================
    column          unit    meaning
    ==============  ======  ==================================================
    ``time``        s       sample time (absent when the file has none)
    ``force``       N       tensile force, or the branch tension of an
                            engagement log
    ``gauge_1``...  m       elongation read by each displacement gauge /
                            extensometer / crosshead channel, in file order
    ``strain_1``... 1       strain read by each channel that gives a ratio
                            (%, mm/mm, µm/m), in file order
    ``angle``       rad     wheel angle or encoder channel (engagement logs)
    ``cycle_count`` 1       the machine's own cycle or segment counter
    ``length``      m       a measured length (the section of a wear log)
    ``speed``       m/s     a speed channel (the chain speed of a wear rig)
    ``segment_force_1``, ``segment_force_2``
                    N       forces F_K1, F_K2 on the two segments of a drum tooth
    ``side_force``  N       side component F_P of the segment force
    ==============  ======  ==================================================

    Sentinel values of unused channels become NaN. Rows are in file order.

``metadata``
    a :class:`TableMetadata` saying what was detected, so that ``chainbench
    inspect`` can print it and the store can keep it as provenance.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

#: Roles a column can take; gauges are numbered ``gauge_1``, ``gauge_2``, ... (``strain_1``,
#: ... for gauges whose unit is a ratio).
ROLES = ("time", "force", "gauge", "angle", "cycle_count", "length", "speed",
         "segment_force_1", "segment_force_2", "side_force")

#: A time step longer than this many median steps is reported as a gap.
GAP_FACTOR = 10.0


@dataclass(frozen=True)
class ColumnInfo:
    """One column of a raw file and what it became."""

    name: str  #: the column's name in the file
    role: str | None  #: canonical column name (``"force"``, ``"gauge_2"``) or None if unused
    unit: str | None  #: unit as found in the file or run sheet (``"kN"``), None if none
    si_unit: str | None  #: SI unit of the canonical column (``"N"``), None if unused
    #: for gauge and strain columns, what the name says it measures: ``"extensometer"``
    #: (on the specimen), ``"crosshead"`` (machine travel) or ``"gauge"`` (not said)
    kind: str | None = None


@dataclass
class TableMetadata:
    """What a reader detected in a raw file."""

    file: str
    layout: str  #: ``"plain_csv"``, ``"european_csv"``, ``"machine_export"``, ``"xlsx"``, ...
    encoding: str | None = None
    delimiter: str | None = None
    decimal: str | None = None
    rows: int = 0
    columns: list[ColumnInfo] = field(default_factory=list)
    preamble: dict[str, str] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    sheet: str | None = None  #: the spreadsheet sheet read (``.xlsx``)
    header_line: int | None = None  #: 1-based line (or sheet row) of the names row
    first_data_line: int | None = None  #: 1-based line (or sheet row) of the first data row
    time_monotonic: bool | None = None  #: False if time ever steps back; None without time
    time_gaps: int = 0  #: steps longer than :data:`GAP_FACTOR` x the median time step
    #: the labels of the specimens side by side in the file (none: one, or unlabelled)
    specimens: list[str] = field(default_factory=list)
    specimen: str | None = None  #: the one read of several side by side (its label or place)
    #: the files the test goes on in, in order (a machine writing a long test in parts)
    continued_in: list[str] = field(default_factory=list)

    def as_dict(self) -> dict:
        """A JSON-ready copy (as printed by ``chainbench inspect --json``)."""
        return asdict(self)
