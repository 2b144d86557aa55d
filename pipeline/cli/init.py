"""``chainbench init FOLDER``: a draft run sheet from the machine exports in a folder.

Every file directly in FOLDER is read as ``chainbench inspect`` reads it (the
readers' auto-detection, nothing processed); the run sheet itself, hidden
files, ``truth.json`` and sub-folders are passed over, and files the readers
cannot read are listed as skipped with the reason. The draft
``FOLDER/campaign.toml`` holds the ``[campaign]`` table, one ``[chains.chain1]``
placeholder and one ``[[runs]]`` entry per readable file, in natural order of
the file names, with what was detected written out (columns, units, cycles)
and every value a person must give marked ``TODO``.

A file is drafted as a segment-load run when it logs two segment forces beside
the chain force (a drum rig's tooth segments); as a wear run when it looks like
a wear log: a section length, or a length or elongation with the running time
or cycles and no force (a tensile log has a force); as an engagement run when it looks like an
engagement log: a time and a force column, no gauge column, sampled at
:data:`ENGAGEMENT_RATE_HZ` or faster; every other file as a tensile run.

An existing run sheet is never overwritten; the draft is written to a
temporary file and renamed into place (UTF-8).
"""

from __future__ import annotations

import json
import re
import stat
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.markup import escape
from rich.table import Table

from pipeline.cli._output import console, json_ready
from pipeline.cli.inspect import sample_rate, summary
from pipeline.errors import ChainbenchError, ColumnError, SpecimensError
from pipeline.runsheet import RUN_SHEET_NAME, resolve_inside

if TYPE_CHECKING:
    import pandas as pd

    from pipeline.condition.channels import Copy
    from pipeline.ingest.table import ColumnInfo, TableMetadata

# The readers are imported inside the functions that use them, so that every other
# command starts without loading them.

#: Files of a campaign folder that are no machine exports.
NOT_EXPORTS = (RUN_SHEET_NAME, "truth.json")

#: Key of the placeholder chain every drafted run refers to.
CHAIN_KEY = "chain1"

#: Key of the placeholder wheel the drafted engagement runs are told to name.
WHEEL_KEY = "wheel1"

#: Key of the placeholder drum the drafted segment-load runs are told to name.
DRUM_KEY = "drum1"

#: Sampling rate [Hz] from which a log with time and force but no gauge is an engagement log.
ENGAGEMENT_RATE_HZ = 1000.0

#: Unit written for a role whose unit the file does not give (validation refuses it).
UNIT_PLACEHOLDER = "TODO"

#: Longest comment line written into the draft (longer text is shortened).
COMMENT_WIDTH = 120

#: Roles of the run sheet's ``columns`` / ``units`` tables other than ``gauges``, by the
#: kind of run drafted (a cycle counter takes no unit).
SINGLE_ROLES = {"tensile": ("time", "force", "angle"), "engagement": ("time", "force", "angle"),
                "wear": ("time", "cycle_count", "length", "force", "speed"),
                "segment-load": ("time", "force", "segment_force_1", "segment_force_2",
                                 "side_force")}

_ID_UNSAFE = re.compile(r"[^A-Za-z0-9._-]+")
_CONTROL = re.compile(r"[\x00-\x1f\x7f]")
_TOML_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n",
                 "\f": "\\f", "\r": "\\r"}
_DELIMITER_NAMES = {"\t": "tab", " ": "space"}


@dataclass
class DraftRun:
    """One readable file and what its ``[[runs]]`` entry says."""

    file: str  #: path relative to the campaign folder, forward slashes
    id: str
    kind: str
    kind_reason: str
    report: dict  #: what ``chainbench inspect`` shows for the file
    metadata: TableMetadata  #: columns and warnings as the drafted entry reads the file
    columns: dict = field(default_factory=dict)  #: the run sheet's ``columns``
    units: dict = field(default_factory=dict)  #: the run sheet's ``units``
    notes: list[str] = field(default_factory=list)  #: remarks on the columns and the cycles
    #: of several specimens side by side in the file, the one read (its label or place)
    specimen_in_file: str | None = None

    @property
    def copies(self) -> dict[str, Copy]:
        """Strain column -> how it was worked out from a length column, by their names in
        the file (``inspect``'s ``copies``)."""
        from pipeline.condition.channels import Copy

        return {name: Copy(*copy) for name, copy in self.report["copies"].items()}

    @property
    def duplicates(self) -> dict[str, str]:
        """Length column -> the length column whose readings it repeats, by their names in
        the file (``inspect``'s ``duplicates``)."""
        return dict(self.report["duplicates"])

    @property
    def gauges(self) -> list[ColumnInfo]:
        """The gauge and strain columns, in file order."""
        return [column for column in self.metadata.columns if _is_gauge(column)]


# -- names ---------------------------------------------------------------------------------

def safe_name(text: str, fallback: str) -> str:
    """`text` as a run-sheet id: letters, digits, ``.``, ``_``, ``-``, at most 100 characters.

    Examples
    --------
    >>> safe_name("TST 2021/10 (FA) #22", "run")
    'TST_2021_10_FA_22'
    >>> safe_name("..", "run")
    'run'
    """
    name = _ID_UNSAFE.sub("_", text).strip("_")[:100]
    return name if name.strip(".") else fallback


def unique_name(name: str, taken: set[str]) -> str:
    """`name`, or `name` with the first free ``-2``, ``-3``... suffix; added to `taken`."""
    candidate, number = name, 1
    while candidate in taken:
        number += 1
        suffix = f"-{number}"
        candidate = name[: 100 - len(suffix)] + suffix
    taken.add(candidate)
    return candidate


def natural_key(name: str) -> tuple:
    """Sort key putting ``run2`` before ``run10`` (digits compared as numbers)."""
    parts = re.split(r"(\d+)", name)  # the digit runs are at the odd places
    return tuple(int(part) if index % 2 else part.casefold()
                 for index, part in enumerate(parts)), name


# -- TOML text -----------------------------------------------------------------------------

def toml_string(text: str) -> str:
    """`text` as a TOML basic string (quotes, backslashes and control characters escaped).

    Examples
    --------
    >>> print(toml_string('Siła "1" \\\\ kN'))
    "Siła \\"1\\" \\\\ kN"
    """
    return '"' + "".join(
        _TOML_ESCAPES.get(char) or (f"\\u{ord(char):04X}" if _CONTROL.match(char) else char)
        for char in text
    ) + '"'


def toml_value(value: str | list[str]) -> str:
    """A string or a list of strings as a TOML value."""
    if isinstance(value, str):
        return toml_string(value)
    return "[" + ", ".join(toml_string(item) for item in value) + "]"


def inline_table(mapping: dict) -> str:
    """`mapping` (role -> string or list of strings) as a TOML inline table."""
    return "{" + ", ".join(f"{key} = {toml_value(value)}" for key, value in mapping.items()) + "}"


def quoted(text: str) -> str:
    """`text` in double quotes, as names are shown in comments (nothing escaped)."""
    return f'"{text}"'


def comment(text: str) -> str:
    """`text` as one comment line: control characters and runs of blanks made one space,
    shortened to :data:`COMMENT_WIDTH`."""
    flat = " ".join(_CONTROL.sub(" ", text).split())
    line = f"# {flat}"
    return line if len(line) <= COMMENT_WIDTH else line[: COMMENT_WIDTH - 3] + "..."


# -- finding and reading the exports -------------------------------------------------------

def _hidden(path: Path) -> bool:
    attributes = getattr(path.lstat(), "st_file_attributes", 0)
    return path.name.startswith(".") or bool(attributes & stat.FILE_ATTRIBUTE_HIDDEN)


def candidate_files(folder: Path) -> tuple[list[Path], list[tuple[str, str]]]:
    """The files of `folder` to read, in natural order, and the sub-folders passed over."""
    files, skipped = [], []
    for path in sorted(folder.iterdir(), key=lambda item: natural_key(item.name)):
        if _hidden(path) or path.name in NOT_EXPORTS:
            continue
        try:
            resolve_inside(folder, path.name)
        except ValueError:
            skipped.append((path.name, "a link leading out of the campaign folder"))
            continue
        if path.is_dir():
            skipped.append((path.name, "a folder: only the files directly in the campaign "
                            "folder are read"))
        else:
            files.append(path)
    return files, skipped


def _is_gauge(column: ColumnInfo) -> bool:
    return (column.role or "").startswith(("gauge_", "strain_"))


def run_kind(table: pd.DataFrame, metadata: TableMetadata) -> tuple[str, str]:
    """``"segment-load"``, ``"wear"`` or ``"engagement"`` for a log that looks like one,
    else ``"tensile"``; and why.

    A segment-load log has two segment forces. A wear log has a section length, or a
    length or elongation (a gauge) with the running time or cycles and no force. An
    engagement log has a time and a force column and no gauge column, sampled at
    :data:`ENGAGEMENT_RATE_HZ` or faster.
    """
    roles = {column.role for column in metadata.columns}
    has_gauge = any(_is_gauge(column) for column in metadata.columns)
    if {"segment_force_1", "segment_force_2"} <= roles:
        return "segment-load", ("guessed: two segment forces beside the chain force, like a "
                                "drum rig's log")
    if "length" in roles or ("force" not in roles and has_gauge
                             and roles & {"time", "cycle_count"}):
        return "wear", ("guessed: a section's length or elongation against the running "
                        "time or cycles, like a wear log")
    rate = sample_rate(table)
    if "force" in table and not has_gauge and rate is not None and rate >= ENGAGEMENT_RATE_HZ:
        return "engagement", (f"guessed: time and force at {rate:.4g} Hz and no gauge "
                              "column, like an engagement log")
    return "tensile", "a force and gauge log" if has_gauge else "no gauge column found"


def column_map(metadata: TableMetadata, kind: str = "tensile") -> dict:
    """The run sheet's ``columns`` of a run of `kind`: each role found -> the file's column
    name (but a column the kind does without that has no unit: the run goes on without it)."""
    found = {role: next((c.name for c in _drafted(metadata, kind) if c.role == role), None)
             for role in SINGLE_ROLES[kind]}
    mapping: dict = {role: name for role, name in found.items() if name is not None}
    gauges = [column.name for column in metadata.columns if _is_gauge(column)]
    if gauges:
        mapping["gauges"] = gauges
    return mapping


def unit_map(metadata: TableMetadata, kind: str = "tensile") -> dict:
    """The run sheet's ``units`` of a run of `kind`: the units found,
    :data:`UNIT_PLACEHOLDER` where the file gives none; ``gauges`` only when every gauge
    column has one unit (the run sheet takes one unit for all gauges)."""
    units: dict = {}
    for role in SINGLE_ROLES[kind]:
        if role == "cycle_count":  # kept as counted
            continue
        column = next((c for c in _drafted(metadata, kind) if c.role == role), None)
        if column is not None:
            units[role] = column.unit or UNIT_PLACEHOLDER
    found = {column.unit for column in metadata.columns if _is_gauge(column)}
    if len(found) == 1:
        units["gauges"] = found.pop() or UNIT_PLACEHOLDER
    return units


def _drafted(metadata: TableMetadata, kind: str) -> list[ColumnInfo]:
    """The columns a run of `kind` is drafted with: all but those of a role it does without
    that have no unit (the reader leaves them out of such a run, with a warning)."""
    from pipeline.ingest.canonical import DISPENSABLE

    return [column for column in metadata.columns
            if column.unit or column.role not in DISPENSABLE.get(kind, ())]


def unit_notes(run: DraftRun) -> list[str]:
    """Remarks on the drafted ``units``: the placeholders, gauges of several units."""
    notes = []
    if run.units and run.gauges and "gauges" not in run.units:
        listed = ", ".join(f"{quoted(c.name)} {c.unit or 'no unit (TODO)'}" for c in run.gauges)
        notes.append(f"gauge units differ ({listed}): units takes one for all gauges, so the "
                     "file's own are used")
    missing = [role for role, unit in run.units.items() if unit == UNIT_PLACEHOLDER]
    if missing:
        notes.append(f"TODO: the file gives no unit for {', '.join(missing)}: replace "
                     f"{quoted(UNIT_PLACEHOLDER)} by the unit (s, N, kN, kgf, mm, um, %...)")
    return notes


def _read(path: Path, kind: str, columns: dict | None = None, units: dict | None = None,
          specimen: str | None = None) -> tuple[pd.DataFrame, TableMetadata]:
    from pipeline.ingest import read_table

    return read_table(path, kind=kind, columns=columns, units=units, specimen=specimen,
                      strict=False)


def _roles(metadata: TableMetadata) -> dict[str, str]:
    return {column.name: column.role for column in metadata.columns if column.role}


def _as_drafted(run: DraftRun, path: Path, detected: TableMetadata) -> None:
    """Read `path` again as the drafted entry says, keeping that read's metadata.

    When the file's names cannot be given back to the reader (a TDMS time made
    from the waveform, a blank name) or give other roles, ``columns`` and
    ``units`` are left out of the entry (auto-detection), with a note.
    """
    known = {role: unit for role, unit in run.units.items() if unit != UNIT_PLACEHOLDER}
    try:
        _, metadata = _read(path, run.kind, run.columns, known, run.specimen_in_file)
        problem = None if _roles(metadata) == _roles(detected) else "they give other roles"
    except ChainbenchError as error:
        problem = _reason(error)
    if problem is None:
        run.metadata = metadata
        return
    run.columns, run.units = {}, {}
    run.notes.insert(0, f"columns and units left to auto-detection: naming them failed "
                        f"({problem})")
    run.metadata = _read(path, run.kind, specimen=run.specimen_in_file)[1]


def _countable(path: Path, table: pd.DataFrame, specimen: str | None) -> pd.DataFrame:
    """`table`, or, when its force has no usable unit, the file read with the force taken
    as N: the number of cycles does not depend on the force's unit."""
    return table if "force" in table else _read(path, "tensile", units={"force": "N"},
                                                specimen=specimen)[0]


def draft_run(path: Path, folder: Path, taken: set[str], specimen: str | None = None
              ) -> DraftRun:
    """Read one export (or `specimen` of the several side by side in it) and draft its
    ``[[runs]]`` entry; its id is added to `taken`.

    Raises
    ------
    ChainbenchError
        When the readers cannot read the file (:class:`~pipeline.errors.ColumnError`
        when they find no force column in it, and it is no wear log).
    """
    table, metadata = _read(path, "tensile", specimen=specimen)
    several = next((warning for warning in metadata.warnings
                    if "columns could be the force" in warning), None)
    if several is not None:  # drafting one of them, or no force at all, would be a guess
        raise ColumnError(several.split(" (say which")[0], file=path,
                          hint="write this run by hand, naming its force, columns = "
                               "{force = \"...\"}")
    kind, reason = run_kind(table, metadata)
    if kind != "wear" and not any(column.role == "force" for column in metadata.columns):
        raise ColumnError("no force column found", file=path,
                          hint="a run needs a force (a wear log, a section length or "
                          "elongation against time or cycles); name it in the run sheet if "
                          "the file has one")
    report = summary(_countable(path, table, specimen), metadata)
    name = path.stem if specimen is None else f"{path.stem}-{specimen}"
    run = DraftRun(
        file=path.relative_to(folder).as_posix(),
        id=unique_name(safe_name(name, "run"), taken),
        kind=kind, kind_reason=reason, report=report, metadata=metadata,
        columns=column_map(metadata, kind), units=unit_map(metadata, kind),
        # the cycle counts disagreeing (a wear log's counter logs a few cycles: no news)
        notes=report["warnings"][len(metadata.warnings):] if kind != "wear" else [],
        specimen_in_file=specimen,
    )
    _as_drafted(run, path, metadata)
    return run


def draft_runs(folder: Path, *, debug: bool = False) -> tuple[list[DraftRun], list[tuple]]:
    """The drafted runs of `folder`'s exports (one per specimen of a file that holds
    several side by side), and the ``(name, reason)`` of those skipped."""
    files, skipped = candidate_files(folder)
    runs: list[DraftRun] = []
    taken: set[str] = set()
    for path in files:
        pending: list[str | None] = [None]
        while pending:
            specimen = pending.pop(0)
            name = path.name if specimen is None else f"{path.name} ({specimen})"
            try:
                runs.append(draft_run(path, folder, taken, specimen))
            except SpecimensError as error:  # asked only of the whole file: one per specimen
                pending = list(error.specimens)
            except ChainbenchError as error:
                if debug:
                    raise
                skipped.append((name, _reason(error)))
            except Exception as error:
                if debug:
                    raise
                skipped.append((name, f"unexpected failure ({type(error).__name__}: "
                                f"{' '.join(str(error).split())}); rerun with --debug and "
                                "report it"))
    return _without_parts(runs, skipped)


def _without_parts(runs: list[DraftRun], skipped: list[tuple]
                   ) -> tuple[list[DraftRun], list[tuple]]:
    """`runs` but those of files another run's test goes on in, which join `skipped`."""
    parts = {part: run.file for run in runs for part in run.metadata.continued_in}
    skipped += [(run.file, f"the rest of the test of {parts[run.file]} (its time runs on "
                 "from there): join the parts into one file")
                for run in runs if run.file in parts]
    return [run for run in runs if run.file not in parts], skipped


def _reason(error: ChainbenchError) -> str:
    """The error on one line, without the file name (the draft names the file)."""
    text = " ".join(str(error).split())
    return text.removeprefix(f"{error.file}, ").removeprefix(f"{error.file}: ")


# -- the draft -----------------------------------------------------------------------------

def _header(folder: Path, skipped: list[tuple]) -> list[str]:
    lines = [
        "# Draft run sheet written by `chainbench init` from the exports in this folder.",
        "# Fill in every TODO, then check it with: chainbench validate "
        + folder.as_posix(),
    ]
    lines += [comment(f"skipped {name}: {reason}") for name, reason in skipped]
    return lines


def _campaign(folder: Path) -> list[str]:
    campaign_id = safe_name(folder.resolve().name, "campaign")
    return [
        "",
        "[campaign]",
        f"id = {toml_string(campaign_id)}  # from the folder name",
        'title = ""    # TODO: what the campaign tests',
        'lab = ""      # TODO: the laboratory',
        'machine = ""  # TODO: the testing machine',
    ]


def _chain(kinds: set[str]) -> list[str]:
    """The chain placeholder, and the drum's and wheel's of the `kinds` of runs drafted."""
    lines = [
        "",
        '# TODO: fill in the chain (catalog = "18x64", or d_mm, t_mm, R0_mm, a_mm)',
        *(['# (a wear run needs the pitch t_mm, or a catalogue roller chain: catalog = "16B")']
          if "wear" in kinds else []),
        *(["# (a segment-load run needs d_mm and torus_radius_mm, or a catalogue chain: "
           'catalog = "34x126")'] if "segment-load" in kinds else []),
        f"[chains.{CHAIN_KEY}]",
        '# catalog = "..."',
        *(f"# {key} = ..." for key in ("d_mm", "t_mm", "R0_mm", "a_mm")),
    ]
    if "segment-load" in kinds:
        lines += [
            "",
            "# TODO: the drum of the segment-load runs (uncomment and fill in); fitted: which",
            "# of s and beta the campaign fits, never guessed",
            f"# [drums.{DRUM_KEY}]",
            *(f"# {key} = ..." for key in ("groove_width_mm", "contact_distance_mm",
                                           "flank_inclination_deg")),
            '# fitted = "..."',
        ]
    if "engagement" in kinds:
        lines += [
            "",
            "# TODO: the wheel of the engagement runs (uncomment and fill in)",
            f"# [wheels.{WHEEL_KEY}]",
            "# teeth = ...",
            "# apex_angle_deg = ...",
            "# (a roller chain's sprocket instead: [sprockets.<key>] with teeth, module_mm, "
            "profile_angle_deg)",
        ]
    return lines


def _detected(run: DraftRun) -> list[str]:
    """What the reader detected, and its warnings, one comment line each."""
    meta = run.metadata
    found = {
        "layout": meta.layout, "encoding": meta.encoding,
        "sheet": meta.sheet and quoted(meta.sheet),
        "delimiter": meta.delimiter and _DELIMITER_NAMES.get(meta.delimiter,
                                                             quoted(meta.delimiter)),
        "decimal": meta.decimal and quoted(meta.decimal),
    }
    text = ", ".join(f"{key} {value}" for key, value in found.items() if value)
    return [comment(f"detected: {text}, {meta.rows} rows"),
            *(comment(f"reader: {warning}") for warning in meta.warnings)]


def _cycles(run: DraftRun) -> str:
    cycles = run.report["cycles"]
    if cycles:
        return (f"cycles = {cycles}  # detected: {cycles} loading(s) in the force signal "
                "(1 = a single pull)")
    return "# cycles = ...  # TODO: load cycles of the test (none found in the force signal)"


def _is_strain(column: ColumnInfo) -> bool:
    return column.role.startswith("strain_")


def _reads(column: ColumnInfo, run: DraftRun) -> str:
    """What a gauge column reads: a length, a strain, a strain worked out from another, or
    another's readings."""
    if column.name in run.copies:
        return f"strain worked out from {quoted(run.copies[column.name].source)}"
    if column.name in run.duplicates:
        return f"repeats {quoted(run.duplicates[column.name])}"
    return "strain" if _is_strain(column) else "length"


def _gauge_lines(run: DraftRun) -> list[str]:
    """The gauge channels' kinds, the one chainbench prefers, and the gauge length."""
    from pipeline.condition.channels import PREFERENCE

    gauges = run.gauges
    if not gauges:
        return ['# TODO: no gauge column found: name it, columns = {gauges = ["..."]}']
    kind_of = {column["name"]: column["kind"] for column in run.report["columns"]}
    kinds = [(column, kind_of[column.name] or "gauge") for column in gauges]
    preferred = next(kind for kind in PREFERENCE if any(k == kind for _, k in kinds))
    chosen = [column.name for column, kind in kinds  # a copy is its source
              if kind == preferred and column.name not in run.copies | run.duplicates]
    together = " (averaged when their stiffnesses agree)" if len(chosen) > 1 else ""
    lines = [
        comment("gauge channels: " + "; ".join(
            f"{quoted(column.name)} {kind} ({_reads(column, run)})"
            for column, kind in kinds)),
        comment(f"chainbench prefers {', '.join(map(quoted, chosen))}{together} "
                f"({preferred}; extensometer over plain gauge over crosshead)"),
    ]
    strains = [column.name for column in gauges if _is_strain(column)]
    if len(strains) == len(gauges):
        return [*lines, "# no gauge_length_mm needed: every gauge channel reads a strain"]
    lines.append("# gauge_length_mm = ...  # TODO: the length the gauges measure over")
    lines += [comment(f"the file's header says {quoted(key)} = {value}")
              for key, value in _stated_gauge_lengths(run.metadata.preamble)]
    lines += [comment(f"the file's {quoted(strain)} is {copy.formula(quoted(copy.source))}: "
                      f"{copy.length * 1e3:.4g} mm is the gauge length its software used")
              for strain, copy in run.copies.items()]
    if strains:
        lines.append(comment(f"(without it only the strain channel(s) "
                             f"{', '.join(map(quoted, strains))} are used)"))
    return lines


#: Words of a header entry that gives a gauge length, folded (Bluehill's ``Tensile strain
#: (Extension) gauge length``, ``... distancia inicial``, ``Odkształcenie 1 długość
#: pomiarowa``; Zwick's ``Gage length, standard travel``, ``Messlänge Standardweg``).
GAUGE_LENGTH_WORDS = ("gauge length", "gage length", "messlange", "dlugosc pomiarowa",
                      "distancia inicial", "longitud calibrada", "longueur de jauge",
                      "longueur de reference", "lunghezza calibrata", "lunghezza di misura")


def _stated_gauge_lengths(preamble: dict[str, str]) -> list[tuple[str, str]]:
    """The entries of a file's header that give a gauge length (:data:`GAUGE_LENGTH_WORDS`):
    shown beside the TODO, not filled in, as which channel each belongs to is the lab's to
    say."""
    from pipeline.ingest.names import fold

    return [(key, value) for key, value in preamble.items()
            if any(word in fold(key) for word in GAUGE_LENGTH_WORDS)]


#: What a drafted run of each kind but a tensile one still needs, as TODO comments.
_TODO_LINES = {
    "engagement": [
        "# TODO: an engagement run needs its wheel, branch length, speed and chain stiffness:",
        f'# wheel = "{WHEEL_KEY}"',
        "# branch_length_m = ...",
        "# rpm = ...          # or omega_per_s = ...",
        '# E0_N = ...         # or stiffness_from = "<campaign>/<chain>"',
        '# (a roller chain on a sprocket: kind = "roller-engagement", with sprocket = "..." '
        "in place of the wheel)",
    ],
    "wear": [
        "# TODO: a wear run needs its measured section, what its elongation counts from and "
        "its sprocket:",
        "# section_pitches = ...    # pitches N of the measured section (1: one pitch's "
        "elongation)",
        '# elongation_reference = "..."    # "nominal" (a length, or against N t) or "first" '
        "(a gauge zeroed on the new chain): never guessed",
        "# sprocket_teeth = ...",
        "# wear_limit_pct = ...     # optional: the lab's own limit of the pitch growth [%]",
    ],
    "segment-load": [
        "# TODO: a segment-load run needs its drum:",
        f'# drum = "{DRUM_KEY}"',
    ],
}


def run_lines(run: DraftRun) -> list[str]:
    """The ``[[runs]]`` entry of one drafted run, with its comments."""
    lines = ["", "[[runs]]", *_detected(run)]
    lines += [
        f"id = {toml_string(run.id)}",
        f"kind = {toml_string(run.kind)}  " + comment(run.kind_reason),
        f"file = {toml_string(run.file)}",
        *([f"specimen_in_file = {toml_string(run.specimen_in_file)}"]
          if run.specimen_in_file is not None else []),
        f"chain = {toml_string(CHAIN_KEY)}",
    ]
    if run.kind == "tensile":
        lines += [f"specimen = {toml_string(run.specimen_in_file or Path(run.file).stem)}",
                  _cycles(run)]
    if run.columns:
        lines.append(f"columns = {inline_table(run.columns)}")
        lines.append(f"units = {inline_table(run.units)}")
    lines += [comment(note) for note in [*run.notes, *unit_notes(run)]]
    lines += _gauge_lines(run) if run.kind == "tensile" else _TODO_LINES[run.kind]
    return lines


def render(folder: Path, runs: list[DraftRun], skipped: list[tuple]) -> str:
    """The draft run sheet of `folder`, as TOML text."""
    lines = [*_header(folder, skipped), *_campaign(folder),
             *_chain({run.kind for run in runs})]
    for run in runs:
        lines += run_lines(run)
    return "\n".join(lines) + "\n"


# -- the command ---------------------------------------------------------------------------

def run_json(run: DraftRun) -> dict:
    """What was detected in one file and drafted for it, JSON-ready."""
    keys = ("layout", "encoding", "delimiter", "decimal", "sheet", "specimen", "rows",
            "cycles", "machine_cycles", "preamble")
    return {
        "file": run.file, "id": run.id, "kind": run.kind, "kind_reason": run.kind_reason,
        **{key: run.report[key] for key in keys},
        "columns": [asdict(column) for column in run.metadata.columns],
        "run_sheet_columns": run.columns, "run_sheet_units": run.units,
        "warnings": [*run.metadata.warnings, *run.notes, *unit_notes(run)],
    }


def _show(runs: list[DraftRun], skipped: list[tuple]) -> None:
    table = Table(title="exports found")
    for heading in ("file", "kind", "layout", "rows", "cycles", "force", "gauges"):
        table.add_column(heading)
    for run in runs:
        table.add_row(*(escape(str(value)) for value in (
            run.file + (f" ({run.specimen_in_file})" if run.specimen_in_file else ""),
            run.kind, run.metadata.layout, run.metadata.rows,
            run.report["cycles"] if run.kind == "tensile" and run.report["cycles"] else "-",
            next((c.name for c in run.metadata.columns if c.role == "force"), "-"),
            ", ".join(f"{c.name} ({c.kind})" for c in run.gauges) or "-")))
    console.print(table)
    for name, reason in skipped:
        console.print(f"[yellow]skipped[/yellow] {escape(name)}: {escape(reason)}",
                      highlight=False)


def _refuse(message: str) -> typer.Exit:
    typer.echo(f"error: {message}", err=True)
    return typer.Exit(1)


def command(
    folder: Annotated[Path, typer.Argument(help="Campaign folder holding the machine exports.")],
    to_stdout: Annotated[bool, typer.Option(
        "--print", help="Print the draft instead of writing FOLDER/campaign.toml.")] = False,
    as_json: Annotated[bool, typer.Option(
        "--json", help="Print what was detected as JSON (for programs).")] = False,
    debug: Annotated[bool, typer.Option("--debug", help="Show the traceback of an error.")] = False,
) -> None:
    """Draft FOLDER/campaign.toml from the exports in FOLDER, for you to complete."""
    if to_stdout and as_json:
        raise typer.BadParameter("give --print or --json, not both")
    if not folder.is_dir():
        raise _refuse(f"{folder} is not a folder")
    target = folder / RUN_SHEET_NAME
    if target.exists() and not to_stdout:
        raise _refuse(f"{target} exists: init never overwrites a run sheet (use --print to "
                      "see the draft, or move the file away)")
    runs, skipped = draft_runs(folder, debug=debug)
    if not runs:
        for name, reason in skipped:
            typer.echo(f"skipped {name}: {reason}", err=True)
        raise _refuse(f"no file in {folder} could be read as a machine export")
    text = render(folder, runs, skipped)
    if to_stdout:
        typer.echo(text, nl=False)
        return
    from pipeline.store.netcdf import write_text_atomic

    write_text_atomic(text, target)
    if as_json:
        document = {"campaign": folder.as_posix(), "run_sheet": target.as_posix(),
                    "runs": [run_json(run) for run in runs],
                    "skipped": [{"file": name, "reason": reason} for name, reason in skipped]}
        print(json.dumps(json_ready(document), indent=2))
        return
    _show(runs, skipped)
    console.print(f"wrote {escape(str(target))}", highlight=False)
    console.print(f"next: fill in the TODOs, then chainbench validate {escape(str(folder))}",
                  highlight=False)
