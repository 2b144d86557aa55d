"""Processing a campaign: what is (re)done, in what order, and where it is stored.

``raw/<campaign>/campaign.toml`` + machine exports
-> per run (:mod:`pipeline.runs`): ingest -> condition -> fit -> its typed result
   (:mod:`pipeline.results`) -> one netCDF file
-> compare (:mod:`pipeline.compare`, :mod:`pipeline.wear_summary`) -> ``summary.nc``,
   CSV tables (``summary.csv`` per chain, ``specimens.csv`` per tensile specimen,
   ``impact_summary.csv``, ``wear_summary.csv`` per wear run)
-> report (:mod:`pipeline.report`) -> ``report.html`` and a page per run in
   ``report-runs/``,
all in ``<project>/processed/<campaign id>/`` (``raw/`` is only read).

* One bad run does not stop a campaign: its error is recorded, the other runs
  are processed, and the summary lists the failures.
* Incremental: a run is redone only when its input key changes: the raw file's
  SHA-256, its run-sheet entry, its chain and wheel definitions, the stiffness
  it uses, the campaign fields its dataset records, and the fingerprint of the
  code (:mod:`pipeline.store.fingerprint`). The summary, tables and report are
  rebuilt when the key of all their inputs differs from the one in the
  folder's manifest. ``force=True`` redoes everything. Run files the run sheet
  no longer yields (renamed, removed or now failing runs) are deleted.
* Safe: every output is written to a temporary file and renamed; one process
  at a time writes a campaign's outputs (:mod:`pipeline.store.lock`); the
  manifest is removed before the campaign outputs are rewritten and written
  after the last, so a run interrupted at any point is completed by the next.
* One summary for fresh and reused runs: the summary is built from the results
  read back from the run files (``from_dataset``), one run at a time, whether
  they were processed now or before.
* Scale-out: with a dask.distributed ``client``, each run is a task that hashes
  its raw file (when no stored result needs the hash first), processes the run,
  writes its run file and reads back what the summary needs; the reused runs'
  read-back and the report's run pages are tasks too (:mod:`pipeline.tasks`).
  A long engagement log (cut into chunks) comes back from its first task
  opened; when the other runs left would not keep the other workers busy as
  long as it takes, this process submits its chunks' scans and fits, the
  merges and the run's storing as tasks ahead of the runs still queued
  (:func:`pipeline.engagement_log.submit_analysis`), else one task finishes it:
  the tasks never wait on one another inside a worker.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pandas as pd
import xarray as xr

from pipeline.acceptance import limits_si
from pipeline.catalog import chain as catalog_chain
from pipeline.compare import ChainInput, impact_summary, specimen_summary, stiffness_summary
from pipeline.engagement_log import LogAnalysis, analyse_job, submit_analysis
from pipeline.errors import ChainbenchError, FitError, OutputError
from pipeline.fit.impact_model import ImpactModelFit, fit_impact_model
from pipeline.fit.stiffness import SpecimenStiffness
from pipeline.fit.wear import CONFIDENCE as WEAR_CONFIDENCE
from pipeline.ingest.continuation import numbered_after
from pipeline.plausibility import check_operating_points, check_specimens, excluded, flags_dataset
from pipeline.report.build import build_report, remove_report
from pipeline.results import (
    EngagementResult,
    RollerEngagementResult,
    RunResult,
    SegmentLoadResult,
    TensileResult,
    WearResult,
    result_from_dataset,
)
from pipeline.results.notes import run_notes
from pipeline.results.tensile import STRENGTH_VARIABLES
from pipeline.roller_summary import roller_row, roller_summary
from pipeline.runs import (
    ENGAGEMENT_KINDS,
    OpenedLog,
    Progress,
    chain_stiffness_for,
    engagement_run_result,
    existing_run_file,
    open_engagement_run,
    operating_point,
    process_engagement_run,
    process_segment_load_run,
    process_tensile_run,
    process_wear_run,
)
from pipeline.runsheet import ChainDef, RunDef, RunSheet, load_run_sheet
from pipeline.segment_summary import segment_row, segment_summary
from pipeline.store import layout
from pipeline.store.fingerprint import code_fingerprint
from pipeline.store.freshness import HashCache, HashedFile, forget_rerun, hash_file
from pipeline.store.layout import PROCESSED_FOLDER, RAW_FOLDER, project_root
from pipeline.store.lock import campaign_lock, remove_stale_temporaries
from pipeline.store.netcdf import (
    provenance_attrs,
    read_attrs,
    read_dataset,
    write_atomic,
    write_text_atomic,
)
from pipeline.tasks import Mapped, submit
from pipeline.units import to_si
from pipeline.wear_summary import wear_row, wear_summary

if TYPE_CHECKING:
    from distributed import Client

#: Name of the attribute holding the key of the inputs a file was made from.
INPUT_KEY = "input_key"
#: The ``[campaign]`` fields a run's dataset records (its provenance): the only ones in
#: a run's input key, so that editing the title or the band redoes no run.
RUN_CAMPAIGN_FIELDS = {"id", "machine", "synthetic"}
#: How a text cell that a spreadsheet would run as a formula begins.
FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


@dataclass(frozen=True)
class RunFailure:
    """A run that could not be processed, and why."""

    run_id: str
    error: Exception

    @property
    def message(self) -> str:
        if isinstance(self.error, ChainbenchError):
            return str(self.error)
        return f"internal error ({type(self.error).__name__}): {self.error}"


@dataclass
class CampaignResult:
    """What processing a campaign produced."""

    campaign_id: str
    output: Path
    summary: xr.Dataset
    run_files: dict[str, Path] = field(default_factory=dict)
    failures: list[RunFailure] = field(default_factory=list)
    report: Path | None = None  #: the report written, None when it could not be built
    report_error: str | None = None  #: why the report could not be built
    redone: list[str] = field(default_factory=list)  #: runs processed this time
    reused: list[str] = field(default_factory=list)  #: runs whose stored result was current
    removed: list[str] = field(default_factory=list)  #: stale run files deleted
    warnings: dict[str, list[str]] = field(default_factory=dict)  #: per run
    #: the files the outputs were made from (and those that must stay absent)
    inputs: list[Path] = field(default_factory=list)

    @property
    def implausible(self) -> list[str]:
        """The messages of the plausibility flags no run sheet entry accepts."""
        if "flag_message" not in self.summary:
            return []
        open_flags = self.summary["flag_accepted"].values == 0
        return [str(message) for message in self.summary["flag_message"].values[open_flags]]

    @property
    def ok(self) -> bool:
        return not self.failures and self.report_error is None and not self.implausible


@dataclass(frozen=True)
class _Plan:
    """One run to do (or reuse): its inputs and their key.

    The raw file's SHA-256 is needed before the run only to compare with a stored
    result; a run with none (or forced) hashes its file in its own task.
    """

    run: RunDef
    raw: Path
    E0: float | None  #: chain stiffness of an engagement run [N]
    inputs: dict[str, Any]  #: the inputs of the key but the raw file's SHA-256
    raw_bytes: int  #: size of the raw file [bytes]: on a cluster, the largest start first
    raw_sha256: str | None  #: None: not hashed yet

    def key(self, raw_sha256: str) -> str:
        """The key of the run's inputs, its raw file's SHA-256 being `raw_sha256`."""
        return _digest({**self.inputs, "raw_sha256": raw_sha256})


def default_output(campaign: RunSheet | str | Path) -> Path:
    """``<project>/processed/<campaign id>``, however the campaign is named.

    Parameters
    ----------
    campaign : RunSheet, str or Path
        The run sheet, or the campaign folder or run-sheet file (read for its id).

    Examples
    --------
    The folder ``.`` inside ``raw/c18``, the folder ``raw/c18`` and the file
    ``raw/c18/campaign.toml`` all give ``processed/<id>`` beside ``raw/``, where
    ``<id>`` is ``[campaign] id`` of the run sheet.
    """
    sheet = campaign if isinstance(campaign, RunSheet) else load_run_sheet(campaign)
    return project_root(sheet.folder) / PROCESSED_FOLDER / sheet.campaign.id


def _digest(document) -> str:
    text = json.dumps(document, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()


def _plan(sheet: RunSheet, run: RunDef, output: Path, hashes: HashCache, hash_now: bool
          ) -> _Plan:
    """The plan of `run`; its raw file hashed now when `hash_now` (else only when cached)."""
    raw = existing_run_file(sheet, run)
    E0 = chain_stiffness_for(sheet, run, output) if run.kind in ENGAGEMENT_KINDS else None
    inputs = {
        "entry": sheet.entries[run.id], "E0": E0,
        "chain": sheet.chains[run.chain].model_dump(mode="json"),
        "wheel": sheet.wheels[run.wheel].model_dump(mode="json") if run.wheel else None,
        **({"sprocket": sheet.sprockets[run.sprocket].model_dump(mode="json")}
           if run.sprocket else {}),
        "campaign": sheet.campaign.model_dump(mode="json", include=RUN_CAMPAIGN_FIELDS),
        "code": code_fingerprint(),
        # the files the test may go on in (read when their time runs on from the raw file's)
        "parts": {part.name: hashes.sha256(part) for part in numbered_after(raw)},
    }
    raw_sha256 = hashes.sha256(raw) if hash_now else hashes.cached(raw)
    return _Plan(run, raw, E0, inputs, raw.stat().st_size, raw_sha256)


def _stored(path: Path) -> dict[str, Any] | None:
    """The global attributes of a stored result, or None when absent or unreadable."""
    if not path.is_file():
        return None
    try:
        return read_attrs(path)
    except OSError:  # unreadable: redo it
        return None


def _run_result(sheet: RunSheet, run: RunDef, raw_sha256: str, E0: float | None,
                progress: Progress | None) -> RunResult:
    """The result of one run, processed by the stages of its kind (nothing written)."""
    progress = progress or (lambda run_id, stage: None)
    if run.kind == "tensile":
        return process_tensile_run(sheet, run, raw_sha256, progress)
    if run.kind == "wear":
        return process_wear_run(sheet, run, raw_sha256, progress)
    if run.kind == "segment-load":
        return process_segment_load_run(sheet, run, raw_sha256, progress)
    return process_engagement_run(sheet, run, raw_sha256, E0, progress)


@dataclass(frozen=True)
class _Done:
    """A run processed now: its file, the file's global attributes, what the summary
    needs of the result read back from the file (as of a run reused), and its key."""

    path: Path
    attrs: dict[str, Any]
    summary: _RunSummary
    key: str
    hashed: HashedFile | None  #: the raw file, when the run hashed it


@dataclass(frozen=True)
class _LongLog:
    """An engagement run whose log is cut into chunks, opened by its first task: the main
    process submits the steps of its chunks as tasks (:func:`_execute`)."""

    plan: _Plan
    opened: OpenedLog
    raw_sha256: str
    hashed: HashedFile | None


def _process(plan: _Plan, *, sheet: RunSheet, output: Path, progress: Progress | None = None,
             split: bool = False) -> _Done | _LongLog:
    """Hash the raw file (unless known), process one run, store its result and read it back.

    A dask task when a client is given (`split`): the worker reads the raw file and
    writes the run file; only `_Done` comes back. An engagement log cut into chunks
    comes back opened instead (:class:`_LongLog`), its chunks' steps to be tasks too.
    """
    hashed = None if plan.raw_sha256 is not None else hash_file(plan.raw)
    raw_sha256 = plan.raw_sha256 or hashed.sha256
    if split and plan.run.kind in ENGAGEMENT_KINDS:
        opened = open_engagement_run(sheet, plan.run, raw_sha256, plan.E0)
        if len(opened.job.chunks) > 1:
            return _LongLog(plan, opened, raw_sha256, hashed)
        result = engagement_run_result(opened, analyse_job(opened.job))
    else:
        result = _run_result(sheet, plan.run, raw_sha256, plan.E0, progress)
    return _store(result, plan, raw_sha256, hashed, sheet=sheet, output=output)


def _finish_long_log(analysis: LogAnalysis | None, long: _LongLog, *, sheet: RunSheet,
                     output: Path) -> _Done:
    """The last task of a long log: its result from the log's analysis (None: analysed
    here, in one task), stored and read back."""
    analysis = analysis if analysis is not None else analyse_job(long.opened.job)
    return _store(engagement_run_result(long.opened, analysis), long.plan, long.raw_sha256,
                  long.hashed, sheet=sheet, output=output)


def _worth_splitting(long: _LongLog, others: list[_Plan], slots: int) -> bool:
    """Whether a long log's chunks should be tasks of their own: when the other runs
    left (their raw bytes) would keep the other `slots` - 1 busy for less time than this
    log takes in one task, so that it would finish last, alone. Otherwise each task is
    a run, with no data passed between workers."""
    return long.plan.raw_bytes * max(1, slots - 1) > sum(plan.raw_bytes for plan in others)


def _store(result: RunResult, plan: _Plan, raw_sha256: str, hashed: HashedFile | None, *,
           sheet: RunSheet, output: Path) -> _Done:
    """Write a run's result under its key and read back what the summary needs."""
    dataset = result.to_dataset()
    key = dataset.attrs[INPUT_KEY] = plan.key(raw_sha256)
    path = write_atomic(dataset, layout.run_output(output, plan.run.id))
    del dataset, result
    return _Done(path, read_attrs(path), _read_back((plan.run, path, plan.E0), sheet=sheet),
                 key, hashed)


def _failure(sheet: RunSheet, run: RunDef, error: Exception, debug: bool) -> RunFailure:
    """`error` of `run` as a recorded failure; an output that cannot be written is no fault
    of the run: it stops the campaign, before anything stored is touched."""
    if isinstance(error, OutputError) or (debug and not isinstance(error, ChainbenchError)):
        raise error
    return run_failure(sheet, run, error)


def run_failure(sheet: RunSheet, run: RunDef | None, error: Exception) -> RunFailure:
    """`error` of `run` (None: of the run sheet) as the campaign lists it: with the file
    it concerns (the run's file when the error names none), named inside the campaign
    folder, so that no home path reaches the outputs."""
    if isinstance(error, ChainbenchError):
        if error.file is None and run is not None:
            error.file = str(sheet.run_file(run))  # stages after ingest know no file
        path, folder = Path(error.file or ""), sheet.folder.resolve()
        if path.is_absolute() and path.is_relative_to(folder):
            error.file = path.relative_to(folder).as_posix()
    label = run.id if run is not None else _invalid_run_id(error)
    return RunFailure(label, error)


def _execute(sheet: RunSheet, plans: list[_Plan], output: Path, progress: Progress | None,
             debug: bool, client: Client | None) -> tuple[dict[str, _Done], list[RunFailure]]:
    """Process `plans` serially, or as dask tasks on `client`, the largest raw files first
    (the short runs fill in at the end, so that the workers finish together). On a
    cluster, a long engagement log's chunks are tasks, ahead of the runs queued, when
    it would otherwise finish last, alone (:func:`_worth_splitting`)."""
    done, failures = {}, []
    if client is None:
        for plan in plans:
            try:
                done[plan.run.id] = _process(plan, sheet=sheet, output=output, progress=progress)
            except Exception as error:  # one bad run must not stop the campaign
                failures.append(_failure(sheet, plan.run, error, debug))
        return done, failures
    from distributed import as_completed

    shared = client.scatter(sheet, broadcast=True, hash=False) if plans else None
    task = partial(submit, client, sheet=shared, output=output)
    futures = {task(_process, plan, split=True): plan
               for plan in sorted(plans, key=lambda plan: plan.raw_bytes, reverse=True)}
    queue = as_completed(futures, loop=client.loop)  # the client need not be the default
    for future in queue:
        plan = futures.pop(future)
        try:
            outcome = future.result()
            if isinstance(outcome, _LongLog):  # its steps go before the runs still queued
                split = _worth_splitting(outcome, list(futures.values()),
                                         sum(client.nthreads().values()))
                analysis = (submit_analysis(outcome.opened.job, client, priority=1)
                            if split else None)
                finish = task(_finish_long_log, analysis, outcome, priority=1)
                futures[finish] = plan
                queue.add(finish)
                continue
            done[plan.run.id] = outcome
        except Exception as error:
            failures.append(_failure(sheet, plan.run, error, debug))
        if progress:
            progress(plan.run.id, "done")
    return done, failures


def _impact_fit(points: pd.DataFrame) -> tuple[ImpactModelFit | None, list[str]]:
    if len(points) < 2:
        return None, ["the impact model is fitted over two or more operating points"]
    try:
        return fit_impact_model(points), []
    except FitError as error:
        return None, [f"impact model not fitted: {error}"]


def _chain_inputs(sheet: RunSheet, keys: list[str]) -> list[ChainInput]:
    inputs = []
    for key in keys:
        values = sheet.chains[key].si()
        inputs.append(ChainInput(key=key, catalog=sheet.chains[key].catalog, d=values["d"],
                                 t=values["t"], R0=values["R0"], a=values["a"],
                                 E_steel=values["E_steel"]))
    return inputs


def _failures_dataset(failures: list[RunFailure]) -> xr.Dataset:
    return xr.Dataset(
        {"error": ("failed_run", [failure.message for failure in failures],
                   {"long_name": "why the run could not be processed"})},
        coords={"failed_run": [failure.run_id for failure in failures]},
    )


def summary_table(summary: xr.Dataset, dim: str) -> pd.DataFrame:
    """The variables of `summary` on dimension `dim` as a flat table."""
    columns = [name for name in summary.data_vars if summary[name].dims == (dim,)]
    return summary[columns].to_dataframe()


@dataclass(frozen=True)
class _RunSummary:
    """What the campaign summary needs of one run's result: a tensile run's specimen
    stiffness and its row of the specimen table, an engagement run's operating point, or
    a wear run's row of the wear table."""

    specimen: SpecimenStiffness | None = None
    row: dict | None = None
    point: dict[str, float] | None = None
    wear: dict | None = None
    roller: dict | None = None
    segment: dict | None = None


def _run_summary(sheet: RunSheet, run: RunDef, result: RunResult, E0: float | None
                 ) -> _RunSummary:
    """What the summary needs of `run`'s result (E0 [N]: of an engagement run)."""
    if isinstance(result, TensileResult):
        return _RunSummary(specimen=result.specimen, row=_specimen_row(run, result))
    if isinstance(result, WearResult):
        return _RunSummary(wear=wear_row(result))
    if isinstance(result, RollerEngagementResult):
        return _RunSummary(roller=roller_row(run, result, E0))
    if isinstance(result, SegmentLoadResult):
        return _RunSummary(segment=segment_row(result))
    return _RunSummary(point={**operating_point(sheet, run, E0), **_measured(result)})


def _read_back(stored: tuple[RunDef, Path, float | None], *, sheet: RunSheet) -> _RunSummary:
    """What the summary needs of a run, read back from its file (`stored`: the run, its
    file and its E0 [N]); a dask task when a client is given."""
    run, path, E0 = stored
    return _run_summary(sheet, run, result_from_dataset(read_dataset(path)), E0)


@dataclass
class _SummaryInputs:
    """What the campaign summary is built from, in run-sheet order: per tensile run its
    specimen stiffness and its row of the specimen table, per engagement run its
    operating point, per wear run its row of the wear table."""

    specimens: dict[str, SpecimenStiffness] = field(default_factory=dict)
    rows: dict[str, dict] = field(default_factory=dict)
    points: dict[str, dict[str, float]] = field(default_factory=dict)
    wear: dict[str, dict] = field(default_factory=dict)
    roller: dict[str, dict] = field(default_factory=dict)
    segment: dict[str, dict] = field(default_factory=dict)

    @classmethod
    def of(cls, sheet: RunSheet, runs: dict[str, _RunSummary]) -> _SummaryInputs:
        """The inputs of the runs in `runs` (run id -> what the summary needs of it)."""
        inputs = cls()
        for run in sheet.runs:
            found = runs.get(run.id)
            if found is None:
                continue
            if found.point is not None:
                inputs.points[run.id] = found.point
            elif found.wear is not None:
                inputs.wear[run.id] = found.wear
            elif found.roller is not None:
                inputs.roller[run.id] = found.roller
            elif found.segment is not None:
                inputs.segment[run.id] = found.segment
            else:
                inputs.specimens[run.id], inputs.rows[run.id] = found.specimen, found.row
        return inputs


def _specimen_row(run: RunDef, result: TensileResult) -> dict:
    """A tensile run's row of the specimen table (:func:`pipeline.compare.specimen_summary`)."""
    stiffness = result.specimen
    return {"chain": run.chain, "specimen": run.specimen or run.id, "E0": stiffness.E0,
            "E0_ci_low": stiffness.E0_ci_low, "E0_ci_high": stiffness.E0_ci_high,
            "single_pull": float(result.single_pull),
            "from_crosshead": float(result.from_crosshead),
            **{name: getattr(result.strength, name) for name in STRENGTH_VARIABLES}}


def _measured(result: EngagementResult) -> dict[str, float]:
    """An engagement run's measured values in its operating point: ``N_u1_meas`` (the
    median over its events), ``N_u1_iqr``, ``N_u1_stderr``, ``N_u1_count``, the same
    for ``N_u2``, and ``omega_measured``."""
    row = {"omega_measured": result.omega_measured}
    for impact in ("N_u1", "N_u2"):
        statistics = result.impact.statistics[impact]
        row.update({f"{impact}_meas": statistics.median, f"{impact}_iqr": statistics.iqr,
                    f"{impact}_stderr": statistics.stderr,
                    f"{impact}_count": float(statistics.count)})
    return row


def _warnings(attrs: dict[str, dict[str, Any]]) -> dict[str, list[str]]:
    """Per run with any, its warnings (:func:`pipeline.results.notes.run_notes`)."""
    notes = {run_id: run_notes(found) for run_id, found in attrs.items()}
    return {run_id: found for run_id, found in notes.items() if found}


def _by_chain(sheet: RunSheet, specimens: dict[str, SpecimenStiffness], leave_out: set[str]
              ) -> dict[str, list[SpecimenStiffness]]:
    chains: dict[str, list[SpecimenStiffness]] = {}
    for run in sheet.runs:
        if run.id in specimens and run.id not in leave_out:
            chains.setdefault(run.chain, []).append(specimens[run.id])
    return chains


def _breaking_force(chain: ChainDef) -> float | None:
    """The chain's declared minimum breaking force, else its catalogue value [N]."""
    declared = limits_si(chain.model_dump()).get("breaking_force")
    if declared is None and chain.catalog:
        return catalog_chain(chain.catalog).get("breaking_force")
    return declared


def _stiffness_parts(sheet: RunSheet, specimens, rows, accepted: set[str]):
    """The chain and specimen tables, and the plausibility flags of the specimens.

    A flagged specimen (not accepted in the run sheet) keeps its row in the
    specimen table but is left out of its chain's E0.
    """
    chain_keys = sorted({run.chain for run in sheet.runs if run.kind == "tensile"})
    chains = _chain_inputs(sheet, chain_keys)
    band = tuple(value / 100 for value in sheet.campaign.discrepancy_band_pct)
    stiffness = stiffness_summary(chains, _by_chain(sheet, specimens, set()), band)
    capacity = sheet.campaign.machine_capacity_kN
    flags = check_specimens(
        rows, E0_theory={key: float(stiffness["E0_theory"].sel(chain=key)) for key in chain_keys},
        breaking_force={key: _breaking_force(sheet.chains[key]) for key in chain_keys},
        capacity=to_si(capacity, "kN") if capacity is not None else None, accepted=accepted)
    if excluded(flags):
        stiffness = stiffness_summary(chains, _by_chain(sheet, specimens, excluded(flags)), band)
    limits = {key: limits_si(sheet.chains[key].model_dump()) for key in chain_keys}
    return [stiffness, specimen_summary(rows, limits)], flags


def _impact_parts(points: dict[str, dict], accepted: set[str]):
    """The operating-point table and the plausibility flags of its runs, with notes.

    A flagged run (not accepted) keeps its row but is left out of the fit of k.
    """
    table = pd.DataFrame.from_dict(points, orient="index")
    fit, notes = _impact_fit(table)
    impact = impact_summary(table, fit)
    flags = check_operating_points(summary_table(impact, "operating_point"), accepted=accepted)
    if excluded(flags):
        fit, notes = _impact_fit(table.drop(index=sorted(excluded(flags))))
        impact = impact_summary(table, fit)
    return impact, flags, notes


def _runs_dataset(sheet: RunSheet, stored: list[str]) -> xr.Dataset:
    kinds = {run.id: run.kind for run in sheet.runs}
    return xr.Dataset(
        {"run_kind": ("run", [kinds[run_id] for run_id in stored],
                      {"long_name": "kind of the run (tensile, engagement or wear)"})},
        coords={"run": list(stored)},
    )


def _summary(sheet: RunSheet, stored: list[str], inputs: _SummaryInputs,
             failures: list[RunFailure]) -> xr.Dataset:
    parts, notes, flags = [_runs_dataset(sheet, stored), _failures_dataset(failures)], [], []
    accepted = {run.id for run in sheet.runs if run.accept_implausible}
    if any(run.kind == "tensile" for run in sheet.runs):
        tables, flags = _stiffness_parts(sheet, inputs.specimens, inputs.rows, accepted)
        parts += tables
    if inputs.points:
        impact, impact_flags, notes = _impact_parts(inputs.points, accepted)
        parts.append(impact)
        flags += impact_flags
    if inputs.wear:
        parts.append(wear_summary(inputs.wear, WEAR_CONFIDENCE))
    if inputs.roller:
        roller, roller_notes = roller_summary(sheet, inputs.roller)
        parts.append(roller)
        notes = [*notes, *roller_notes]
    if inputs.segment:
        segment, segment_notes = segment_summary(inputs.segment)
        parts.append(segment)
        notes = [*notes, *segment_notes]
    parts.append(flags_dataset(flags))
    summary = xr.merge(parts, combine_attrs="drop_conflicts")
    summary.attrs["notes"] = "\n".join(filter(None, [summary.attrs.get("notes", ""), *notes]))
    summary.attrs.update(provenance_attrs(
        title=sheet.campaign.title or f"Campaign {sheet.campaign.id}",
        source=sheet.campaign.machine, run_sheet_sha256=sheet.sha256))
    summary.attrs.update(campaign=sheet.campaign.id, synthetic=int(sheet.campaign.synthetic),
                         lab=sheet.campaign.lab, campaign_note=sheet.campaign.note)
    return summary


def _write_summary(summary: xr.Dataset, output: Path) -> list[str]:
    """Write ``summary.nc`` and its CSV tables; return the names written."""
    write_atomic(summary, output / layout.SUMMARY)
    written = [layout.SUMMARY]
    for dim, name in (("chain", layout.CHAIN_TABLE), ("specimen", layout.SPECIMEN_TABLE),
                      ("operating_point", layout.IMPACT_TABLE),
                      ("wear_run", layout.WEAR_TABLE),
                      ("sprocket_point", layout.ROLLER_TABLE),
                      ("segment_point", layout.SEGMENT_TABLE)):
        if summary.sizes.get(dim, 0):
            write_text_atomic(csv_table(summary, dim), output / name)
            written.append(name)
        else:
            (output / name).unlink(missing_ok=True)  # from an earlier sheet: not current
    return written


def csv_table(summary: xr.Dataset, dim: str) -> str:
    """The variables of `summary` on `dim` as CSV: headings with units, text made inert.

    A text cell that begins like a spreadsheet formula (``=``, ``+``, ``-``,
    ``@``, a tab or a carriage return) is written with a leading apostrophe, so
    that a spreadsheet shows it instead of running it.
    """
    table = summary_table(summary, dim)
    table.columns = [_with_unit(column, summary[column].attrs.get("units"))
                     for column in table.columns]
    table.index = table.index.map(_inert)
    for column in table.columns:
        if table[column].dtype == object:
            table[column] = table[column].map(_inert)
    return table.to_csv(float_format="%.6g", lineterminator="\n")


def _inert(value):
    """`value`, with a leading apostrophe when it is text that a spreadsheet would run."""
    if isinstance(value, str) and value.startswith(FORMULA_STARTS):
        return "'" + value
    return value


def _with_unit(name: str, units: str | None) -> str:
    """A CSV column heading: the variable's name and its unit (``E0_exp [N]``)."""
    return f"{name} [{units}]" if units else name


def _outputs_current(output: Path, key: str) -> bool:
    """Whether the campaign outputs were all written, completely, from inputs of `key`.

    The manifest (:data:`pipeline.store.layout.MANIFEST`) is removed before any
    campaign output is rewritten and written after the last one, so a run
    killed in between leaves no manifest, and the next run rebuilds them all.
    """
    try:
        manifest = json.loads((output / layout.MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return (manifest.get(INPUT_KEY) == key
            and all((output / name).is_file() for name in manifest.get("outputs", [])))


def _write_manifest(output: Path, key: str, written: list[str]) -> None:
    text = json.dumps({INPUT_KEY: key, "outputs": written}, indent=1)
    write_text_atomic(text, output / layout.MANIFEST)


def _remove_stale_runs(output: Path, campaign_id: str, current: set[str]) -> list[str]:
    """Delete run files of this campaign that the run sheet no longer yields (call under
    the lock): runs renamed, removed, or failing now. Returns their run ids."""
    removed = []
    for path in sorted(output.glob("*.nc")):
        if path.name == layout.SUMMARY or path.stem in current:
            continue
        found = _stored(path)
        if found is None or found.get("campaign") != campaign_id or "run_id" not in found:
            continue  # not a run file chainbench wrote for this campaign: leave it
        path.unlink()
        removed.append(path.stem)
    return removed


def process_campaign(
    path: str | Path,
    output: str | Path | None = None,
    progress: Progress | None = None,
    debug: bool = False,
    force: bool = False,
    client: Client | None = None,
    rehash: bool = False,
) -> CampaignResult:
    """Process the runs of a campaign whose inputs changed, and write its results.

    Parameters
    ----------
    path : str or Path
        The campaign folder (holding ``campaign.toml``) or the run sheet.
    output : str or Path, optional
        Output folder; default ``<project>/processed/<campaign id>`` (see
        :func:`default_output`).
    progress : callable, optional
        Called as ``progress(run_id, stage)`` at each stage.
    debug : bool
        Re-raise unexpected (non-chainbench) errors instead of recording them.
    force : bool
        Redo every run, the summary and the report, changed or not.
    client : distributed.Client, optional
        Process the runs as tasks on this dask cluster (default: in this process).
    rehash : bool
        Read every raw file for its SHA-256, however unchanged its size,
        modification time and inode (:class:`~pipeline.store.freshness.HashCache`).

    Returns
    -------
    CampaignResult
        The summary dataset, the run files, the failures, the report (a report
        that cannot be built is recorded in ``report_error``; the results
        written before it are kept), and which runs were redone, reused or
        removed.

    Raises
    ------
    RunSheetError
        When the run sheet as a whole is unusable.
    CampaignBusyError
        When another process is writing the same outputs.
    OutputError
        When the outputs cannot be written (the outputs already there are kept).
    """
    sheet = load_run_sheet(path)
    output = Path(output) if output is not None else default_output(sheet)
    _check_output_folder(output, sheet)
    with campaign_lock(output):
        remove_stale_temporaries(output)
        forget_rerun(output)  # whatever happens next, the last run's record may not hold
        failures = sheet_failures(sheet)
        plans: dict[str, _Plan] = {}
        current: dict[str, dict[str, Any]] = {}  # run id -> attributes of its stored result
        hashes = HashCache(output, rehash)
        for run in sheet.runs:
            found = None if force else _stored(layout.run_output(output, run.id))
            try:  # a stored result is compared by key: its raw file is hashed now
                plan = plans[run.id] = _plan(sheet, run, output, hashes, found is not None)
            except Exception as error:
                failures.append(_failure(sheet, run, error, debug))
                continue
            if found is not None and found.get(INPUT_KEY) == plan.key(plan.raw_sha256):
                current[run.id] = found
                if progress:
                    progress(run.id, "unchanged")
        todo = [plan for run_id, plan in plans.items() if run_id not in current]
        done, failed = _execute(sheet, todo, output, progress, debug, client)
        failures += failed
        for run_id, found in done.items():
            if found.hashed is not None:
                hashes.remember(plans[run_id].raw, found.hashed)
        hashes.save()
        current.update({run_id: found.attrs for run_id, found in done.items()})
        files = {run.id: layout.run_output(output, run.id) for run in sheet.runs
                 if run.id in current}
        removed = _remove_stale_runs(output, sheet.campaign.id, set(files))
        key = _digest({"runs": {run_id: current[run_id][INPUT_KEY] for run_id in sorted(files)},
                       "failures": [failure.message for failure in failures],
                       "sheet": sheet.sha256, "code": code_fingerprint()})
        result = CampaignResult(
            sheet.campaign.id, output, xr.Dataset(), files, failures,
            redone=[plan.run.id for plan in todo if plan.run.id in done],
            reused=[run_id for run_id in plans if run_id in current and run_id not in done],
            removed=removed, warnings=_warnings({run_id: current[run_id] for run_id in files}),
            inputs=_input_files(sheet, output))
        if not force and _outputs_current(output, key):
            result.summary = read_dataset(output / layout.SUMMARY)
            result.report = output / layout.REPORT
            return result
        (output / layout.MANIFEST).unlink(missing_ok=True)  # outputs being rewritten
        reused = [(run, files[run.id], plans[run.id].E0) for run in sheet.runs
                  if run.id in files and run.id not in done]  # read back one at a time
        summaries = {run.id: found for (run, _, _), found in zip(
            reused, Mapped(_read_back, reused, client, sheet=sheet).results(), strict=True)}
        summaries.update({run_id: found.summary for run_id, found in done.items()})
        inputs = _SummaryInputs.of(sheet, summaries)
        result.summary = _summary(sheet, list(files), inputs, failures)
        result.summary.attrs[INPUT_KEY] = key
        written = _write_summary(result.summary, output)
        try:  # the results are written: a failing report loses nothing but itself
            report = build_report(output, client=client,
                                  run_attrs={run_id: current[run_id] for run_id in files})
            result.report = report.page
            written += report.outputs  # the campaign page and every run's page
        except OutputError:
            raise
        except Exception as error:
            if debug and not isinstance(error, ChainbenchError):
                raise
            result.report_error = RunFailure("report", error).message
            remove_report(output)  # an old report is not current
        _write_manifest(output, key, written)
    return result


def _input_files(sheet: RunSheet, output: Path) -> list[Path]:
    """The files a campaign's outputs are computed from, besides its run sheet: the raw
    files there are, the parts a raw file's test may go on in (:func:`numbered_after`),
    the name each one's next part would have (absent: a re-run is no longer one with
    nothing changed once it appears), and the summaries of the campaigns a stiffness is
    taken from."""
    files, absent = [], set()
    for raw in (sheet.run_file(run) for run in sheet.runs):
        parts = list(numbered_after(raw))
        files += [raw, *parts]
        absent.add(raw.with_name(f"{raw.stem}{len(parts) + 1}{raw.suffix}"))
    files += [output.parent / run.stiffness_from.partition("/")[0] / layout.SUMMARY
              for run in sheet.runs if run.stiffness_from]
    existing = sorted({path for path in files if path.is_file()})
    return existing + sorted(absent - set(existing))


def check_campaign(path: str | Path, output: str | Path | None = None,
                   progress: Progress | None = None) -> CampaignResult:
    """Everything :func:`process_campaign` does, in memory, writing nothing.

    Every run is read, conditioned and fitted, and the campaign summary with its
    plausibility flags is built, so that what ``chainbench run`` would refuse or
    flag is found before anything is written (``chainbench validate``).

    Parameters
    ----------
    path : str or Path
        The campaign folder or its run sheet.
    output : str or Path, optional
        Where ``run`` would write (read only: for ``stiffness_from``); default
        ``<project>/processed/<campaign id>``.
    progress : callable, optional
        Called as ``progress(run_id, stage)`` at each stage.

    Returns
    -------
    CampaignResult
        The summary, the failures and the warnings; no run file, no report.
    """
    sheet = load_run_sheet(path)
    output = Path(output) if output is not None else default_output(sheet)
    failures, summaries, attrs = sheet_failures(sheet), {}, {}
    for run, E0, result in _checked_results(sheet, output, progress, failures):
        summaries[run.id] = _run_summary(sheet, run, result, E0)
        attrs[run.id] = result.global_attrs()
    summary = _summary(sheet, list(attrs), _SummaryInputs.of(sheet, summaries), failures)
    return CampaignResult(sheet.campaign.id, output, summary, failures=failures,
                          warnings=_warnings(attrs))


def _checked_results(sheet: RunSheet, output: Path, progress: Progress | None,
                     failures: list[RunFailure]
                     ) -> Iterator[tuple[RunDef, float | None, RunResult]]:
    """Each run processed in memory with its chain stiffness E0 [N] (engagement runs), one
    at a time; the runs that fail are appended to `failures` (as process_campaign: every
    run is checked)."""
    for run in sheet.runs:
        try:
            E0 = chain_stiffness_for(sheet, run, output) if run.kind in ENGAGEMENT_KINDS else None
            result = _run_result(sheet, run, "", E0, progress)
        except Exception as error:
            failures.append(run_failure(sheet, run, error))
            continue
        yield run, E0, result


def _check_output_folder(output: Path, sheet: RunSheet) -> None:
    """Refuse an output folder inside ``raw/`` or one that is a file, before writing."""
    resolved = output.resolve()
    if any(resolved.is_relative_to(folder) for folder in (
            sheet.folder.resolve(), project_root(sheet.folder) / RAW_FOLDER)):
        raise OutputError(
            "outputs are never written inside raw/", file=output,
            hint="leave out --output, or give a folder outside raw/")
    in_the_way = next((path for path in (resolved, *resolved.parents)
                       if path.exists() and not path.is_dir()), None)
    if in_the_way is not None:
        raise OutputError("the output folder is a file" if in_the_way == resolved
                          else f"the output folder lies under a file ({in_the_way})",
                          file=output, hint="move the file away or give another --output")
    try:
        resolved.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise OutputError(f"cannot create the output folder ({error.strerror})", file=output,
                          hint="check that its parent folder is writable") from None


def _invalid_run_id(error: ChainbenchError) -> str:
    """A label for a run-sheet entry that failed validation (``runs[3]``)."""
    return (error.column or "runs").split(".")[0]


def sheet_failures(sheet: RunSheet) -> list[RunFailure]:
    """The run-sheet entries that failed validation: runs, and chain and wheel tables
    (listed even when no run uses them)."""
    failures = [run_failure(sheet, None, error) for error in sheet.invalid_runs]
    for table, invalid in (("chains", sheet.invalid_chains), ("wheels", sheet.invalid_wheels),
                           ("sprockets", sheet.invalid_sprockets)):
        failures += [RunFailure(f"{table}.{key}", run_failure(sheet, None, error).error)
                     for key, error in invalid.items()]
    return failures


def run_campaign(path: str | Path, output: str | Path | None = None, *, force: bool = False,
                 client: Client | None = None) -> xr.Dataset:
    """Process a campaign and return its summary (the Python API of ``chainbench run``).

    For example, ``run_campaign("raw/stiffness-demo")["E0_exp"].sel(chain="c18x64")``
    is the measured stiffness of chain 18x64 [N], with ``E0_theory`` beside it.
    """
    return process_campaign(path, output, force=force, client=client).summary
