"""Processing a campaign: the flow of a run, top to bottom.

``raw/<campaign>/campaign.toml`` + machine exports
-> ingest (:mod:`pipeline.ingest`) -> condition (:mod:`pipeline.condition`)
-> fit (:mod:`pipeline.fit`) -> store (:mod:`pipeline.store`)
-> compare (:mod:`pipeline.compare`) -> ``processed/<campaign>/``.

One bad run does not stop a campaign: its error is recorded, the other runs
are processed, and the summary lists the failures. ``raw/`` is only read.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import pandas as pd
import xarray as xr

from pipeline.compare import ChainInput, impact_summary, stiffness_summary
from pipeline.condition.engagement import SpeedMismatchWarning, detect_events
from pipeline.condition.tensile import condition_tensile
from pipeline.errors import ChainbenchError, FitError, RunSheetError
from pipeline.fit.impact import extract_impacts
from pipeline.fit.impact_model import ImpactModelFit, fit_impact_model
from pipeline.fit.stiffness import SpecimenStiffness, fit_stiffness, specimen_stiffness
from pipeline.ingest import read_table
from pipeline.runsheet import RunDef, RunSheet, load_run_sheet
from pipeline.store.engagement import engagement_dataset, operating_point
from pipeline.store.netcdf import (
    provenance_attrs,
    read_dataset,
    sha256_of,
    write_atomic,
    write_text_atomic,
)
from pipeline.store.tensile import tensile_dataset
from pipeline.units import to_si

#: Called as ``progress(run_id, stage)`` while a campaign is processed.
Progress = Callable[[str, str], None]


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

    @property
    def ok(self) -> bool:
        return not self.failures


def default_output(campaign_folder: Path) -> Path:
    """``processed/<campaign>`` beside the ``raw/`` folder holding the campaign."""
    campaign_folder = Path(campaign_folder).resolve()
    root = campaign_folder.parent.parent if campaign_folder.parent.name == "raw" else Path.cwd()
    return root / "processed" / campaign_folder.name


def read_run(sheet: RunSheet, run: RunDef):
    """Read a run's raw file into the canonical table, as its run-sheet entry says."""
    columns = run.columns.model_dump(exclude_none=True) if run.columns else None
    units = run.units.model_dump(exclude_none=True) if run.units else None
    return read_table(sheet.run_file(run), kind=run.kind, columns=columns, units=units,
                      format=run.format, sheet=run.sheet)


def _attrs(sheet: RunSheet, run: RunDef, title: str) -> dict[str, str]:
    raw = sheet.run_file(run)
    attrs = provenance_attrs(
        title=title,
        source=("chainbench virtual test bench (synthetic)" if sheet.campaign.synthetic
                else sheet.campaign.machine or "testing machine"),
        run_sheet_sha256=sheet.sha256,
        raw_file=run.file,
        raw_sha256=sha256_of(raw),
        run_entry=sheet.entries[run.id],
    )
    attrs.update(campaign=sheet.campaign.id, run_id=run.id, kind=run.kind, chain=run.chain)
    return attrs


def process_tensile_run(
    sheet: RunSheet, run: RunDef, progress: Progress | None = None
) -> tuple[xr.Dataset, SpecimenStiffness]:
    """Ingest, condition and fit one tensile run.

    Returns
    -------
    (xarray.Dataset, SpecimenStiffness)
        The run's dataset (see :mod:`pipeline.store.tensile`) and its stiffness.
    """
    step = progress or (lambda run_id, stage: None)
    step(run.id, "ingest")
    table, metadata = read_run(sheet, run)
    step(run.id, "condition")
    chain = sheet.chains[run.chain].si()
    conditioned = condition_tensile(
        table, to_si(run.gauge_length_mm, "mm"), preload=chain["preload"], n_cycles=run.cycles)
    step(run.id, "fit")
    window = None
    if run.fit_window is not None:
        window = (to_si(run.fit_window.force_low_kN, "kN"),
                  to_si(run.fit_window.force_high_kN, "kN"))
    fits = fit_stiffness(conditioned, force_window=window)
    specimen = specimen_stiffness(fits)
    attrs = _attrs(sheet, run, f"Tensile test {run.id} of campaign {sheet.campaign.id}")
    attrs.update(specimen=run.specimen or "", layout=metadata.layout,
                 ingest_warnings="; ".join(metadata.warnings))
    return tensile_dataset(conditioned, fits, specimen, attrs), specimen


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


def process_engagement_run(
    sheet: RunSheet, run: RunDef, output: Path, progress: Progress | None = None
) -> tuple[xr.Dataset, dict[str, float]]:
    """Ingest one engagement log, detect its events and extract the impact tensions.

    Returns
    -------
    (xarray.Dataset, dict)
        The run's dataset (see :mod:`pipeline.store.engagement`) and its
        operating point (the model's inputs in SI and the measured medians).
    """
    step = progress or (lambda run_id, stage: None)
    step(run.id, "ingest")
    raw = sheet.run_file(run)
    table, metadata = read_run(sheet, run)
    chain, wheel = sheet.chains[run.chain].si(), sheet.wheels[run.wheel]
    point = {"teeth": wheel.teeth, "apex_angle": math.radians(wheel.apex_angle_deg),
             "omega": run.omega, "t": chain["t"], "d": chain["d"],
             "mass_per_length": chain["mass_per_length"],
             "E0": chain_stiffness_for(sheet, run, output), "branch_length": run.branch_length_m}
    step(run.id, "detect events")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SpeedMismatchWarning)  # kept in events.messages
        natural = math.sqrt(point["E0"] / (point["mass_per_length"] * run.branch_length_m ** 2))
        events = detect_events(table, z=wheel.teeth, omega=run.omega,
                               natural_frequency=natural, file=raw)
    step(run.id, "extract impacts")
    clip = to_si(run.clip_level_kN, "kN") if run.clip_level_kN is not None else None
    result = extract_impacts(table, events, clip_level=clip, file=raw)
    attrs = _attrs(sheet, run, f"Engagement log {run.id} of campaign {sheet.campaign.id}")
    attrs.update(wheel=run.wheel, layout=metadata.layout,
                 ingest_warnings="; ".join(metadata.warnings))
    point.update(operating_point(events, result))
    return engagement_dataset(table, events, result, attrs), point


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


def process_campaign(
    path: str | Path,
    output: str | Path | None = None,
    progress: Progress | None = None,
    debug: bool = False,
) -> CampaignResult:
    """Process every run of a campaign and write its results.

    Parameters
    ----------
    path : str or Path
        The campaign folder (holding ``campaign.toml``) or the run sheet.
    output : str or Path, optional
        Output folder; default ``processed/<campaign>`` (see :func:`default_output`).
    progress : callable, optional
        Called as ``progress(run_id, stage)`` at each stage.
    debug : bool
        Re-raise unexpected (non-chainbench) errors instead of recording them.

    Returns
    -------
    CampaignResult
        The summary dataset, the written run files and the failures.

    Raises
    ------
    RunSheetError
        When the run sheet as a whole is unusable.
    """
    sheet = load_run_sheet(path)
    output = Path(output) if output is not None else default_output(sheet.folder)
    failures = [RunFailure(_invalid_run_id(error), error) for error in sheet.invalid_runs]
    run_files: dict[str, Path] = {}
    specimens: dict[str, list[SpecimenStiffness]] = {}
    points: dict[str, dict[str, float]] = {}

    for run in sheet.runs:
        try:
            if run.kind == "tensile":
                dataset, specimen = process_tensile_run(sheet, run, progress)
                specimens.setdefault(run.chain, []).append(specimen)
            else:
                dataset, points[run.id] = process_engagement_run(sheet, run, output, progress)
        except Exception as error:  # one bad run must not stop the campaign
            if debug and not isinstance(error, ChainbenchError):
                raise
            if isinstance(error, ChainbenchError) and error.file is None:
                error.file = str(sheet.run_file(run))  # stages after ingest know no file
            failures.append(RunFailure(run.id, error))
            continue
        run_files[run.id] = write_atomic(dataset, output / f"{run.id}.nc")

    parts, notes = [_failures_dataset(failures)], []
    chain_keys = sorted({run.chain for run in sheet.runs if run.kind == "tensile"})
    if chain_keys:
        band = tuple(value / 100 for value in sheet.campaign.discrepancy_band_pct)
        parts.append(stiffness_summary(_chain_inputs(sheet, chain_keys), specimens, band))
    if points:
        table = pd.DataFrame.from_dict(points, orient="index")
        fit, notes = _impact_fit(table)
        parts.append(impact_summary(table, fit))
    summary = xr.merge(parts, combine_attrs="drop_conflicts")
    summary.attrs["notes"] = "\n".join(filter(None, [summary.attrs.get("notes", ""), *notes]))
    summary.attrs.update(provenance_attrs(
        title=sheet.campaign.title or f"Campaign {sheet.campaign.id}",
        source=sheet.campaign.machine, run_sheet_sha256=sheet.sha256))
    summary.attrs.update(campaign=sheet.campaign.id, synthetic=int(sheet.campaign.synthetic))
    write_atomic(summary, output / "summary.nc")
    for dim, name in (("chain", "summary.csv"), ("operating_point", "impact_summary.csv")):
        if summary.sizes.get(dim, 0):
            csv = summary_table(summary, dim).to_csv(float_format="%.6g")
            write_text_atomic(csv, output / name)
    return CampaignResult(sheet.campaign.id, output, summary, run_files, failures)


def _invalid_run_id(error: ChainbenchError) -> str:
    """A label for a run-sheet entry that failed validation (``runs[3]``)."""
    return (error.column or "runs").split(".")[0]


def run_campaign(path: str | Path, output: str | Path | None = None) -> xr.Dataset:
    """Process a campaign and return its summary (the Python API of ``chainbench run``).

    For example, ``run_campaign("raw/stiffness-demo")["E0_exp"].sel(chain="c18x64")``
    is the measured stiffness of chain 18x64 [N], with ``E0_theory`` beside it.
    """
    return process_campaign(path, output).summary

