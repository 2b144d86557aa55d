"""One run, top to bottom: ingest, condition, fit, and its dataset.

Each function takes the validated run sheet and one of its runs and returns
the run's typed result (:mod:`pipeline.results`). They read the raw file and
nothing is written here; :mod:`pipeline.campaign` decides what is run and
stores it.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.condition.segment_load import condition_segment_load
from pipeline.condition.tensile import TensileRun, condition_tensile, cuts_of_channels_used
from pipeline.condition.wear import condition_wear
from pipeline.engagement_log import (
    LogAnalysis,
    LogJob,
    LogSource,
    TableSource,
    analyse_job,
    start_log,
)
from pipeline.errors import FitError, IngestError, RunSheetError, SignalError, UnitError
from pipeline.fit.roller_engagement import RollerBranch, Sprocket, engagement_teeth
from pipeline.fit.segment_load import contact_ratios
from pipeline.fit.stiffness import (
    SpecimenStiffness,
    fit_settings,
    fit_stiffness,
    specimen_stiffness,
)
from pipeline.fit.strength import Strength, specimen_strength
from pipeline.fit.wear import (
    WearFit,
    compare_pin_wear,
    fit_wear,
    pitch_growth_limit,
    predict_life,
)
from pipeline.ingest import TableMetadata, open_log, read_table
from pipeline.ingest.names import tokens
from pipeline.ingest.unitparse import is_counter_unit
from pipeline.results import EngagementResult, TensileResult, WearResult
from pipeline.results.engagement import MAX_STORED_SAMPLES
from pipeline.results.roller_engagement import RollerEngagementResult
from pipeline.results.segment_load import SegmentLoadResult, log_excerpt
from pipeline.results.wear import LimitOutcome
from pipeline.runsheet import RunDef, RunSheet
from pipeline.store.netcdf import provenance_attrs, read_dataset
from pipeline.theory.pin_criterion import SUPPORTS, PinCheck, check_pin
from pipeline.theory.wheel_impact import RYABOV_MASS_SHARE
from pipeline.units import to_si

#: Engagement logs longer than this are read from their file and processed in chunks
#: of :data:`CHUNK_SAMPLES` (with overlap; :mod:`pipeline.engagement_log`): the same
#: events and values, in the memory of a chunk whatever the log's length. Shorter
#: logs are read whole, which is faster.
WHOLE_SAMPLES = 1_000_000

#: A log file up to this size [bytes] whose rows do not read by range is read whole
#: (:func:`open_run_log`): some 10^6 rows of a few columns.
WHOLE_BYTES = 64 * 2**20

#: Samples of a chunk of a long log: half a million keeps a 2e6-sample log's peak
#: memory within 3 times its decoded arrays, at the speed of larger chunks.
CHUNK_SAMPLES = 500_000

#: Kinds whose logs are read as another kind's: a roller-engagement log is an engagement log.
READ_AS = {"roller-engagement": "engagement"}

#: Called as ``progress(run_id, stage)`` while a run is processed.
Progress = Callable[[str, str], None]


def _quiet(run_id: str, stage: str) -> None:
    """The default progress callback: says nothing."""


def existing_run_file(sheet: RunSheet, run: RunDef) -> Path:
    """The run's raw file; an :class:`~pipeline.errors.IngestError` when it is missing."""
    raw = sheet.run_file(run)
    if not raw.is_file():
        raise IngestError("file not found", file=raw,
                          hint="check the run's file name in the run sheet")
    return raw


def _reading(run: RunDef) -> dict:
    """How a run's raw file is read, as its run-sheet entry says."""
    return {"kind": READ_AS.get(run.kind, run.kind), "format": run.format, "sheet": run.sheet,
            "specimen": run.specimen_in_file, "sample_rate_hz": run.sample_rate_hz,
            "columns": run.columns.model_dump(exclude_none=True) if run.columns else None,
            "units": run.units.model_dump(exclude_none=True) if run.units else None}


def read_run(sheet: RunSheet, run: RunDef):
    """Read a run's raw file into the canonical table, as its run-sheet entry says."""
    return read_table(existing_run_file(sheet, run), **_reading(run))


def open_run_log(sheet: RunSheet, run: RunDef) -> tuple[LogSource, list[str], str]:
    """An engagement run's log as a source, the reader's warnings and the file's layout.

    A log of up to :data:`WHOLE_SAMPLES` samples is read whole into memory; a
    longer one is left in its file and read a chunk at a time
    (:func:`pipeline.ingest.open_log`), so its memory is that of a chunk.

    A log of up to :data:`WHOLE_BYTES` whose rows do not read by range is
    read as :func:`~pipeline.ingest.read_table` reads it, which also leaves
    out the event lines a rig writes among its readings (as ``chainbench
    inspect`` does); a larger one refuses them at their line.
    """
    path = existing_run_file(sheet, run)
    try:
        reader = open_log(path, **_reading(run))
        said = list(reader.metadata.warnings)
        if reader.n_rows > WHOLE_SAMPLES:
            return reader, said, reader.metadata.layout
        table, more = reader.read(0, reader.n_rows)
    except IngestError:
        if path.stat().st_size > WHOLE_BYTES:
            raise
        table, metadata = read_table(path, **_reading(run))
        return TableSource(table), metadata.warnings, metadata.layout
    return TableSource(table), list(dict.fromkeys([*said, *more])), reader.metadata.layout


def _attrs(sheet: RunSheet, run: RunDef, title: str, raw_sha256: str) -> dict[str, str]:
    attrs = provenance_attrs(
        title=title,
        source=("chainbench virtual test bench (synthetic)" if sheet.campaign.synthetic
                else sheet.campaign.machine or "testing machine"),
        run_sheet_sha256=sheet.sha256,
        raw_file=run.file,
        raw_sha256=raw_sha256,
        run_entry=sheet.entries[run.id],
    )
    attrs.update(campaign=sheet.campaign.id, run_id=run.id, kind=run.kind, chain=run.chain)
    return attrs


def _read_attrs(metadata: TableMetadata) -> dict[str, str]:
    """What the reader found that a result keeps: the layout, and the parts of a test
    written in several files (``raw_parts``, their names after the raw file's)."""
    parts = {"raw_parts": ", ".join(metadata.continued_in)} if metadata.continued_in else {}
    return {"layout": metadata.layout, **parts}


@dataclass(frozen=True)
class TensileAnalysis:
    """Everything one tensile run gives, before it is stored."""

    metadata: TableMetadata
    conditioned: TensileRun
    fits: pd.DataFrame
    specimen: SpecimenStiffness
    strength: Strength
    settings: dict[str, float | str]  #: what the fit applied (:func:`fit_settings`)

    @property
    def warnings(self) -> list[str]:
        """What the reader and the stages decided or repaired, in that order."""
        return [*self.metadata.warnings, *self.conditioned.warnings]


def analyse_tensile_run(sheet: RunSheet, run: RunDef,
                        progress: Progress = _quiet) -> TensileAnalysis:
    """Ingest, condition and fit one tensile run (nothing is written).

    Raises the typed error of the first stage that refuses the run, so that
    ``chainbench validate`` finds what ``chainbench run`` would refuse.
    """
    progress(run.id, "ingest")
    table, metadata = read_run(sheet, run)
    progress(run.id, "condition")
    conditioned = condition_tensile_run(sheet, run, table, metadata)
    progress(run.id, "fit")
    options = {"force_window": None}
    if run.fit_window is not None:
        options["force_window"] = (to_si(run.fit_window.force_low_kN, "kN"),
                                   to_si(run.fit_window.force_high_kN, "kN"))
    try:
        fits = fit_stiffness(conditioned, **options)
    except FitError as error:  # too few samples where a channel was cut: say where
        error.message += cuts_of_channels_used(conditioned)
        raise
    specimen = specimen_stiffness(fits, single_pull=conditioned.single_pull)
    strength = specimen_strength(conditioned, fits, yield_offset=run.yield_offset_pct / 100,
                                 proof_force=proof_force(sheet, run))
    return TensileAnalysis(metadata, conditioned, fits, specimen, strength,
                           fit_settings(**options))


def process_tensile_run(
    sheet: RunSheet, run: RunDef, raw_sha256: str, progress: Progress = _quiet
) -> TensileResult:
    """Ingest, condition and fit one tensile run; its result holds the specimen's E0."""
    analysis = analyse_tensile_run(sheet, run, progress)
    attrs = _attrs(sheet, run, f"Tensile test {run.id} of campaign {sheet.campaign.id}",
                   raw_sha256)
    attrs.update(specimen=run.specimen or "", **_read_attrs(analysis.metadata),
                 **analysis.settings)
    return TensileResult.of(analysis.conditioned, analysis.fits, analysis.specimen,
                            analysis.strength, attrs, analysis.metadata.warnings)


def proof_force(sheet: RunSheet, run: RunDef) -> float | None:
    """Proof force [N] of a run: its own ``proof_force_kN``, else its chain's, else None."""
    value = run.proof_force_kN or sheet.chains[run.chain].proof_force_kN
    return to_si(value, "kN") if value is not None else None


def condition_tensile_run(sheet: RunSheet, run: RunDef, table: pd.DataFrame,
                          metadata: TableMetadata) -> TensileRun:
    """Condition a tensile run's table as its run-sheet entry says (channels, cycles)."""
    channels = {column.role: column for column in metadata.columns
                if column.kind is not None}
    gauge_length = to_si(run.gauge_length_mm, "mm") if run.gauge_length_mm else None
    preload, note = _preload(sheet, run, table)
    try:
        conditioned = condition_tensile(
            table, gauge_length, preload=preload,
            n_cycles=run.cycles, kinds={name: info.kind for name, info in channels.items()},
            columns={name: info.name for name, info in channels.items()},
            average=run.average_gauges)
    except SignalError as error:
        if "gauge length" in error.message:
            error.file, error.column = str(sheet.path), f"{run.id}.gauge_length_mm"
        raise
    conditioned.warnings.extend(note)
    return conditioned


def _preload(sheet: RunSheet, run: RunDef, table: pd.DataFrame) -> tuple[float | None, list]:
    """The preload [N] a cyclic run is segmented with, and a warning when one is set aside.

    A single pull has none. The run sheet's ``preload_kgf`` always holds; the
    catalogue's (the lower force of Paper 001's cyclic programme for that chain)
    only where the log rises above it: a log that never does was not run to that
    programme, and is said so.
    """
    chain = sheet.chains[run.chain]
    preload = chain.si()["preload"]
    if run.cycles == 1 or preload is None:
        return None, []
    peak = float(np.nanmax(np.abs(table["force"].to_numpy()))) if "force" in table else 0.0
    if chain.preload_kgf is not None or peak > preload:
        return preload, []
    return None, [f"the catalogue's preload of chain {chain.catalog} ({preload / 1e3:.4g} kN) "
                  f"is above this log's largest force ({peak / 1e3:.4g} kN): not used; set "
                  "preload_kgf for the chain if the test had one"]


def chain_stiffness_for(sheet: RunSheet, run: RunDef, output: Path) -> float:
    """E0 [N] of an engagement run: ``E0_N`` of the run sheet, or ``stiffness_from``.

    ``stiffness_from = "<campaign>/<chain>"`` takes ``E0_exp`` of that chain from
    the processed ``summary.nc`` of another campaign (beside `output`).
    """
    if run.E0_N is not None:
        return run.E0_N
    if run.stiffness_from is None:
        raise RunSheetError(
            f"run {run.id} needs the chain stiffness", file=sheet.path, column="E0_N",
            hint='give E0_N = ... [N] or stiffness_from = "<campaign>/<chain>"')
    campaign, _, chain = run.stiffness_from.partition("/")
    source = output.parent / campaign / "summary.nc"
    if not source.is_file():
        raise RunSheetError(
            f"no processed stiffness campaign at {source}", file=sheet.path,
            column="stiffness_from", hint=f"process campaign {campaign!r} first")
    summary = read_dataset(source)
    if chain not in summary.get("chain", []):
        raise RunSheetError(
            f"campaign {campaign!r} has no chain {chain!r}", file=sheet.path,
            column="stiffness_from", hint=f"its chains: {list(summary.get('chain', []).values)}")
    value = float(summary["E0_exp"].sel(chain=chain))
    if not math.isfinite(value):
        raise RunSheetError(f"chain {chain!r} of {campaign!r} has no measured E0",
                            file=sheet.path, column="stiffness_from")
    return value


def operating_point(sheet: RunSheet, run: RunDef, E0: float) -> dict[str, float]:
    """The model's inputs of an engagement run [SI]: Paper 000's operating point."""
    chain, wheel = sheet.chains[run.chain].si(), sheet.wheels[run.wheel]
    return {"teeth": wheel.teeth, "apex_angle": math.radians(wheel.apex_angle_deg),
            "omega": run.omega, "t": chain["t"], "d": chain["d"],
            "mass_per_length": chain["mass_per_length"], "E0": E0,
            "branch_length": run.branch_length_m}


@dataclass(frozen=True)
class OpenedLog:
    """An engagement run's log, opened and set up, and what its result needs besides
    the log's analysis (:func:`engagement_run_result`).

    Attributes
    ----------
    job : LogJob
        The log set up and cut into chunks (:func:`pipeline.engagement_log.start_log`);
        more than one chunk for a log longer than :data:`WHOLE_SAMPLES`.
    result_type : type
        :class:`~pipeline.results.EngagementResult` or
        :class:`~pipeline.results.roller_engagement.RollerEngagementResult`.
    attrs : dict
        The result's global attributes.
    read_warnings : tuple of str
        What opening the file said.
    """

    job: LogJob
    result_type: type[EngagementResult] | type[RollerEngagementResult]
    attrs: dict[str, Any]
    read_warnings: tuple[str, ...]


def open_engagement_run(sheet: RunSheet, run: RunDef, raw_sha256: str, E0: float,
                        progress: Progress = _quiet) -> OpenedLog:
    """Open an engagement or roller-engagement run's log and set it up for the one
    engagement pipeline (:mod:`pipeline.engagement_log`).

    The log is read with the wheel's teeth (a roller chain: half the sprocket's,
    :func:`pipeline.fit.roller_engagement.engagement_teeth`) and the branch's
    natural frequency sqrt(E0 / (m L^2)) [rad/s]; a log of over
    :data:`WHOLE_SAMPLES` samples is cut into chunks of :data:`CHUNK_SAMPLES`.

    Parameters
    ----------
    raw_sha256 : str
        SHA-256 of the raw file, for the result's provenance.
    E0 : float
        Chain stiffness [N] (:func:`chain_stiffness_for`).

    Raises
    ------
    RunSheetError
        When a roller-engagement run's sprocket cannot engage its chain.
    """
    teeth, natural, attrs, result_type = _OPENINGS[run.kind](sheet, run, raw_sha256, E0)
    progress(run.id, "ingest")
    source, read_warnings, attrs["layout"] = open_run_log(sheet, run)
    clip = to_si(run.clip_level_kN, "kN") if run.clip_level_kN is not None else None
    job = start_log(source, z=teeth, omega=run.omega,
                    chunk_samples=CHUNK_SAMPLES if source.n_rows > WHOLE_SAMPLES else None,
                    natural_frequency=natural, clip_level=clip,
                    preview_samples=MAX_STORED_SAMPLES, warn_speed=False,
                    file=sheet.run_file(run))
    return OpenedLog(job, result_type, attrs, tuple(read_warnings))


def engagement_run_result(opened: OpenedLog, analysis: LogAnalysis
                          ) -> EngagementResult | RollerEngagementResult:
    """The result of an engagement run from its opened log and the log's analysis."""
    warned = list(dict.fromkeys([*opened.read_warnings, *analysis.warnings]))
    preview = (analysis.preview_time, analysis.preview_force, analysis.preview_stride)
    return opened.result_type.of(analysis.events, analysis.impacts, preview, opened.attrs,
                                 warned)


def process_engagement_run(
    sheet: RunSheet, run: RunDef, raw_sha256: str, E0: float, progress: Progress = _quiet
) -> EngagementResult | RollerEngagementResult:
    """Ingest one engagement log, detect its events and extract the impact tensions.

    A roller-engagement run's log is read as a wheel of half the sprocket's
    teeth (:func:`pipeline.fit.roller_engagement.engagement_teeth`): two
    successive roller strikes make one seating. xi is fitted across the runs
    of a sprocket in the summary (:mod:`pipeline.roller_summary`).

    Parameters
    ----------
    E0 : float
        Chain stiffness [N] (:func:`chain_stiffness_for`): it sets the expected
        natural frequency of the branch, sqrt(E0 / (m L^2)).

    Raises
    ------
    RunSheetError
        When a roller-engagement run's sprocket cannot engage its chain (Paper
        002, eq. (3)).
    """
    opened = open_engagement_run(sheet, run, raw_sha256, E0, progress)
    progress(run.id, "detect and extract impacts")
    return engagement_run_result(opened, analyse_job(opened.job))


def _chain_opening(sheet: RunSheet, run: RunDef, raw_sha256: str, E0: float
                   ) -> tuple[int, float, dict[str, Any], type[EngagementResult]]:
    """A round-link chain on a wheel: teeth [-], natural frequency [rad/s], attributes."""
    point = operating_point(sheet, run, E0)
    natural = math.sqrt(E0 / (point["mass_per_length"] * run.branch_length_m ** 2))
    attrs = _attrs(sheet, run, f"Engagement log {run.id} of campaign {sheet.campaign.id}",
                   raw_sha256)
    attrs.update(wheel=run.wheel)
    return point["teeth"], natural, attrs, EngagementResult


def roller_engagement_inputs(sheet: RunSheet, run: RunDef, E0: float
                             ) -> tuple[Sprocket, RollerBranch, float]:
    """The sprocket, the branch and G_lim [J/m^2] of a roller-engagement run (SI).

    The branch is the run's roller chain (pitch, mass per metre, roller diameter
    D and inner width B) on ``branch_length_m``, with stiffness `E0` [N] and
    Paper 000's share of link masses k = 2.
    """
    definition, chain = sheet.sprockets[run.sprocket], sheet.chains[run.chain].si()
    involute = definition.module_mm is not None
    sprocket = Sprocket(
        definition.teeth, module=to_si(definition.module_mm, "mm") if involute else None,
        profile_angle=math.radians(definition.profile_angle_deg) if involute else None,
        base_radius=(to_si(definition.base_radius_mm, "mm")
                     if definition.base_radius_mm is not None else None))
    branch = RollerBranch(pitch=chain["t"], mass_per_length=chain["mass_per_length"], E0=E0,
                          branch_length=run.branch_length_m, k=RYABOV_MASS_SHARE,
                          roller_diameter=chain["roller_diameter"],
                          roller_length=chain["inner_width"])
    return sprocket, branch, to_si(definition.g_lim_J_per_mm2, "J/mm^2")


def _roller_opening(sheet: RunSheet, run: RunDef, raw_sha256: str, E0: float
                    ) -> tuple[int, float, dict[str, Any], type[RollerEngagementResult]]:
    """A roller chain on a sprocket: the teeth it is read with [-], the natural frequency
    sqrt(E0 / (q L^2)) [rad/s] and the attributes; refused when the sprocket's involute
    cannot engage the chain (Paper 002, eq. (3))."""
    sprocket, branch, _ = roller_engagement_inputs(sheet, run, E0)
    xi_model, reason = sprocket.involute_xi(branch.pitch)
    if math.isnan(xi_model) and (sprocket.module is not None or sprocket.base_radius is not None):
        raise RunSheetError(f"sprocket {run.sprocket!r} cannot hold chain {run.chain!r}: {reason}",
                            file=sheet.path, column=f"sprockets.{run.sprocket}",
                            hint="check module_mm and profile_angle_deg (or base_radius_mm) "
                                 "against the chain's pitch t_mm")
    natural = math.sqrt(E0 / (branch.mass_per_length * branch.branch_length ** 2))
    attrs = _attrs(sheet, run, f"Roller-chain engagement log {run.id} of campaign "
                               f"{sheet.campaign.id}", raw_sha256)
    attrs.update(sprocket=run.sprocket, sprocket_teeth=sprocket.teeth,
                 engagement_teeth=engagement_teeth(sprocket.teeth))
    return engagement_teeth(sprocket.teeth), natural, attrs, RollerEngagementResult


#: How each engagement kind's log is read and its result labelled.
_OPENINGS = {"engagement": _chain_opening, "roller-engagement": _roller_opening}
#: The kinds whose log goes through the one engagement pipeline (and that need the chain
#: stiffness E0 for the branch's natural frequency, :func:`chain_stiffness_for`).
ENGAGEMENT_KINDS = frozenset(_OPENINGS)


def process_wear_run(sheet: RunSheet, run: RunDef, raw_sha256: str,
                     progress: Progress = _quiet) -> WearResult:
    """Ingest, condition and fit one wear log; its life to the limits and the pin criterion.

    The log's elongation per pitch is fitted with the run-in or the linear
    wear model (:func:`pipeline.fit.wear.fit_wear`, as ``wear_model`` says);
    the life is predicted to the jump-off growth of Paper 004, eq. (3), for
    the run's sprocket and to the lab's ``wear_limit_pct`` when declared. A
    life that cannot be given (no significant wear, or the chain at the limit
    from the start) is NaN, with the reason in the run's warnings.
    """
    progress(run.id, "ingest")
    table, metadata = read_run(sheet, run)
    _check_counter(sheet, run, metadata)
    progress(run.id, "condition")
    chain = sheet.chains[run.chain].si()
    explicit = run.columns.model_dump(exclude_none=True) if run.columns else {}
    channel = ("length" if "length" in explicit else "elongation" if "gauges" in explicit
               else None)
    log, notes = condition_wear(table, pitches=run.section_pitches, pitch=chain["t"],
                                reference=run.elongation_reference,
                                abscissa=run.wear_abscissa, channel=channel,
                                columns={column.role: column.name
                                         for column in metadata.columns if column.role})
    progress(run.id, "fit")
    fit = fit_wear(log, model=run.wear_model)
    pin = _pin_criterion(run, chain)
    limits = {"eq3": _limit(fit, pin, run, teeth=run.sprocket_teeth)}
    if run.wear_limit_pct is not None:
        limits["lab"] = _limit(fit, pin, run, limit_percent=run.wear_limit_pct)
    notes += [f"no life to the {name} limit: {outcome.note}" for name, outcome in limits.items()
              if outcome.note]
    notes += _load_notes(run, table)
    attrs = _attrs(sheet, run, f"Wear test {run.id} of campaign {sheet.campaign.id}",
                   raw_sha256)
    attrs.update(**_read_attrs(metadata), abscissa=log.abscissa, reference=log.reference,
                 channel=channel or ("length" if "length" in table else "elongation"),
                 section_pitches=run.section_pitches, pitch=log.pitch,
                 sprocket_teeth=run.sprocket_teeth,
                 pin_criterion="evaluated" if pin else "not evaluated: the run sheet gives "
                 "no max_link_force_kN, pin_allowable_stress_MPa and pin_wear_coefficient")
    logged = table.loc[:, [name for name in ("force", "speed") if name in table]]
    return WearResult.of(fit, limits, pin, logged.rename(columns={"force": "load"}), attrs,
                         metadata.warnings, notes)


def _check_counter(sheet: RunSheet, run: RunDef, metadata: TableMetadata) -> None:
    """Refuse a cycle counter whose unit scales it (``kcycles``), or that counts segments
    by its unit or name (MTS's ``Axial Segment Count``: two a cycle of a sine, more of
    other waveforms): it is kept as counted, as cycles."""
    for column in metadata.columns:
        unit = (column.unit or "").strip().strip("()[]").strip()
        if column.role != "cycle_count":
            continue
        if not is_counter_unit(column.unit):
            raise UnitError(
                f"the cycle counter has the unit {column.unit!r}, which chainbench cannot "
                "scale: counts are kept as counted", file=sheet.run_file(run),
                column=column.name,
                hint="log the cycles as a plain count (unit 1, cycles, or none)")
        if "segment" in (*tokens(column.name), unit.lower().rstrip("s")):
            raise UnitError(
                f"the cycle counter {column.name!r} counts segments (two a cycle of a sine, "
                "more of other waveforms), and chainbench counts cycles",
                file=sheet.run_file(run), column=column.name,
                hint="log the machine's cycle count, or name another counter in the run "
                     "sheet, columns = {cycle_count = \"...\"}")


def _pin_criterion(run: RunDef, chain: dict[str, float | None]
                   ) -> tuple[PinCheck, dict[str, float]] | None:
    """Paper 004's pin criterion, eqs. (1)-(5), for the run's chain, sprocket and loads."""
    if not run.pin_criterion:
        return None
    inputs = {"pin_wear_coefficient": run.pin_wear_coefficient,
              "pin_force": to_si(run.max_link_force_kN, "kN"),
              "pin_allowable_stress": to_si(run.pin_allowable_stress_MPa, "MPa"),
              "pin_support_factor": SUPPORTS[run.pin_support]}
    check = check_pin(chain["pin_diameter"], chain["t"], run.sprocket_teeth,
                      inputs["pin_force"], chain["plate_span"], chain["bush_length"],
                      inputs["pin_allowable_stress"], inputs["pin_wear_coefficient"],
                      inputs["pin_support_factor"])
    return check, inputs


def _limit(fit: WearFit, pin: tuple[PinCheck, dict[str, float]] | None, run: RunDef,
           **limit: float) -> LimitOutcome:
    """The limit (``teeth=`` or ``limit_percent=``), the life to it and the pin wear there."""
    value, source = pitch_growth_limit(fit.log.pitch, fit.log.reference, **limit)
    try:
        life = predict_life(fit, **limit)
    except FitError as error:
        return LimitOutcome(value, source, note=error.message)
    worn = (compare_pin_wear(life, teeth=run.sprocket_teeth,
                             wear_coefficient=pin[1]["pin_wear_coefficient"])
            if pin and life.growth > 0 else None)
    return LimitOutcome(value, source, life, worn)


def _load_notes(run: RunDef, table: pd.DataFrame) -> list[str]:
    """A note when the logged load exceeds the force the pin criterion is evaluated at."""
    if not run.pin_criterion or "force" not in table:
        return []
    peak = float(np.nanmax(table["force"].to_numpy())) if table["force"].notna().any() else 0.0
    declared = to_si(run.max_link_force_kN, "kN")
    if peak <= declared:
        return []
    return [f"the log's largest load, {peak / 1e3:.4g} kN, is above max_link_force_kN = "
            f"{run.max_link_force_kN:g} kN: the pin criterion is evaluated at a smaller force "
            "than the chain carried; set max_link_force_kN to the largest force on a link"]


def segment_geometry(sheet: RunSheet, run: RunDef) -> dict[str, float]:
    """The chain's ``r_outer``, ``d`` and the drum's ``groove_width`` [m], ``s`` [m],
    ``beta``, ``eps_n`` [rad] of a segment-load run (Paper 003, eqs. (1)-(4))."""
    chain = sheet.chains[run.chain].si()
    return {"r_outer": chain["r_outer"], "d": chain["d"], **sheet.drums[run.drum].si()}


def process_segment_load_run(sheet: RunSheet, run: RunDef, raw_sha256: str,
                             progress: Progress = _quiet) -> SegmentLoadResult:
    """Ingest and condition one segment-load log: one operating point of the drum's tooth.

    The seatings are found on the segment-force sum and their plateau ratios
    F_K / F and F_P / F taken (:func:`pipeline.condition.segment_load.condition_segment_load`);
    the model's ratios at the run sheet's geometry (Paper 003, eqs. (1)-(4)) are
    kept beside them. The contact geometry is fitted across the drum's runs at
    the summary stage (:mod:`pipeline.segment_summary`).
    """
    progress(run.id, "ingest")
    table, metadata = read_run(sheet, run)
    progress(run.id, "condition")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the imbalance warning is kept in the result
        events = condition_segment_load(
            table["time"], table["force"], table["segment_force_1"], table["segment_force_2"],
            table.get("side_force"), imbalance_tolerance=run.imbalance_tolerance_pct / 100)
    geometry = segment_geometry(sheet, run)
    declared = contact_ratios(geometry, beta=geometry["beta"], s=geometry["s"],
                              eps_n=geometry["eps_n"])
    attrs = _attrs(sheet, run, f"Segment-load run {run.id} of campaign {sheet.campaign.id}",
                   raw_sha256)
    attrs.update(drum=run.drum, fitted=sheet.drums[run.drum].fitted, **_read_attrs(metadata))
    return SegmentLoadResult.of(events, declared, geometry, attrs, metadata.warnings,
                                log_excerpt(table, events.events))
