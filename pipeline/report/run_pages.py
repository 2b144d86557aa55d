"""The report's per-run pages (``report-runs/<run id>.html``) and the run table linking them.

The campaign page (``report.html``, :mod:`pipeline.report.build`) keeps the
campaign-level figures and tables and a run table: one row per run with its
key values and its status, linking the run's own page. A run's page shows what
belongs to that run alone: a tensile run's force-strain curve, fit residuals,
displacement channels and fits; an engagement run's log with the detected
impacts, its statistics, events and ringing fit; a wear run's elongation against
running time with the fit, its limits and lives, and its pin criterion
(:mod:`pipeline.report.wear_section`); and for every run its
warnings, plausibility flags and raw file. Every page links back to its row of
the run table and on to the previous and next run, so the campaign page stays
the same size whatever the number of per-run figures.

A page is self-contained like the campaign page (inline SVG and CSS, no
script, no network). Pages are built one run at a time, so that the memory is
one run's whatever the campaign's size, and each is written atomically; the
pages of runs the summary no longer holds are deleted first. Run ids are
portable file names (``<run id>.nc`` is one); links quote them all the same.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any
from urllib.parse import quote

import numpy as np
import xarray as xr

from pipeline.acceptance import CHECKS
from pipeline.report import impact_figures, stiffness_figures
from pipeline.report.formatting import (
    MISSING,
    environment,
    interval,
    kilonewton_interval,
    kilonewtons,
    natural_key,
    number,
    percent,
    plain_number,
)
from pipeline.report.recorded import level, recorded
from pipeline.report.render import report_style, svg
from pipeline.report.roller_section import roller_numbers
from pipeline.report.segment_section import segment_numbers, segment_run_page
from pipeline.report.wear_section import run_numbers, wear_run_page
from pipeline.results.notes import run_notes
from pipeline.store import layout
from pipeline.store.lock import remove_stale_temporaries
from pipeline.store.netcdf import read_attrs, read_dataset, write_text_atomic
from pipeline.tasks import Mapped

if TYPE_CHECKING:
    from distributed import Client

#: The jinja2 template of a run's page (``pipeline/report/templates``).
TEMPLATE_NAME = "run.html.j2"

#: The dimension of a run file's signals, left out where only its results are read.
SAMPLE_DIM = "sample"

#: The statistics of an engagement run its page shows: variable prefix, what it is, unit.
ENGAGEMENT_QUANTITIES = (
    ("N_u1", "impact tension N_u1 (idle flank): strike amplitude", "N"),
    ("N_u2", "impact tension N_u2 (working flank): strike amplitude", "N"),
    ("peak1", "first-peak height of strike 1", "N"),
    ("peak2", "first-peak height of strike 2", "N"),
    ("baseline", "slow branch tension at impact 1", "N"),
    ("tau", "time from impact 1 to impact 2", "s"),
)

#: Why an engagement event can be excluded (``excluded_<reason>`` of the run file).
EXCLUSION_REASONS = ("clipped", "fit_failed", "gap", "overlap", "truncated")


@dataclass(frozen=True)
class RunFile:
    """A processed run file of the campaign and its global attributes."""

    path: Path
    attrs: dict[str, Any]

    @property
    def run_id(self) -> str:
        return str(self.attrs.get("run_id", self.path.stem))

    @property
    def kind(self) -> str:
        return str(self.attrs.get("kind", ""))

    def load(self) -> xr.Dataset:
        """The whole dataset, in memory."""
        return read_dataset(self.path)

    def results(self) -> xr.Dataset:
        """The dataset without its signals (the variables on ``sample``), in memory."""
        with xr.open_dataset(self.path, engine="netcdf4") as dataset:
            return dataset.drop_dims(SAMPLE_DIM, errors="ignore").load()


@dataclass(frozen=True)
class RunStatus:
    """What the run table and a run's page say of one run."""

    status: str  #: CSS class: ``pass``, ``fail`` or ``info``
    text: str  #: the status in words ("ok", "implausible: E0; warnings"...)
    flags: tuple[dict[str, str], ...]  #: its plausibility flags (:func:`plausibility_flags`)


def campaign_runs(output_dir: Path, summary: xr.Dataset,
                  attrs: Mapping[str, dict[str, Any]] | None = None) -> list[RunFile]:
    """The run files the summary was made from (its ``run`` labels), in natural order of ids.

    Files of runs since removed from the run sheet, or of earlier attempts of
    runs that failed this time, are not results of this summary and are not shown.
    Only their global attributes are read, unless `attrs` (run id -> the global
    attributes of its file, as just read by the caller) holds them.
    """
    labels = [str(run_id) for run_id in summary["run"].values] if "run" in summary.coords else []
    known = attrs or {}
    runs = []
    for run_id in labels:
        path = layout.run_output(output_dir, run_id)
        runs.append(RunFile(path, known[run_id] if run_id in known else read_attrs(path)))
    return sorted(runs, key=lambda run: natural_key(run.run_id))


def page_name(run_id: str) -> str:
    """The file name of run `run_id`'s page in :data:`pipeline.store.layout.RUN_PAGES`."""
    return f"{run_id}.html"


def page_href(run_id: str) -> str:
    """The link from the campaign page to run `run_id`'s page (the id URL-quoted)."""
    return f"{layout.RUN_PAGES}/{quote(page_name(run_id), safe='')}"


def row_anchor(run_id: str) -> str:
    """The id of run `run_id`'s row in the run table."""
    return f"run-{run_id}"


def _by_label(summary: xr.Dataset, dim: str, name: str) -> dict[str, Any]:
    """Label of `dim` -> value of `name` (nothing when `dim` is empty)."""
    if not summary.sizes.get(dim, 0):
        return {}
    return dict(zip(summary[dim].values.astype(str), summary[name].values, strict=True))


def plausibility_flags(summary: xr.Dataset) -> list[dict[str, str]]:
    """The summary's plausibility flags: run, quantity, result, status (CSS class), message.

    An accepted flag is information, an open one a failure.
    """
    if not summary.sizes.get("flag", 0):
        return []
    return [{"run": str(run), "quantity": str(quantity), "message": str(message),
             "result": "accepted in the run sheet" if accepted else "implausible",
             "status": "info" if accepted else "fail"}
            for run, quantity, accepted, message in zip(
                summary["flag_run"].values, summary["flag_quantity"].values,
                summary["flag_accepted"].values, summary["flag_message"].values, strict=True)]


def _flags_by_run(summary: xr.Dataset) -> dict[str, list[dict[str, str]]]:
    """Run id -> its plausibility flags (:func:`plausibility_flags`)."""
    found: dict[str, list[dict[str, str]]] = {}
    for flag in plausibility_flags(summary):
        found.setdefault(flag["run"], []).append(flag)
    return found


def _failing_acceptance(summary: xr.Dataset) -> set[str]:
    """The tensile runs that fail an acceptance limit their chain declares."""
    if not summary.sizes.get("specimen", 0):
        return set()
    failed = np.zeros(summary.sizes["specimen"], dtype=bool)
    for check in CHECKS:
        failed |= summary[f"specimen_accept_{check}"].values == 0
    return {str(run) for run in summary["specimen"].values[failed]}


def _status(run: RunFile, flags: list[dict[str, str]], fails_acceptance: bool) -> RunStatus:
    """The status of one run from its flags, acceptance and warnings."""
    implausible = [flag["quantity"] for flag in flags if flag["status"] == "fail"]
    accepted = [flag["quantity"] for flag in flags if flag["status"] == "info"]
    parts = []
    if implausible:
        parts.append(f"implausible: {', '.join(implausible)}")
    if fails_acceptance:
        parts.append("fails acceptance")
    if accepted:
        parts.append(f"accepted in the run sheet: {', '.join(accepted)}")
    if run_notes(run.attrs):
        parts.append("warnings")
    css = "fail" if implausible or fails_acceptance else "info" if parts else "pass"
    return RunStatus(css, "; ".join(parts) or "ok", tuple(flags))


def run_statuses(summary: xr.Dataset, runs: Sequence[RunFile]) -> dict[str, RunStatus]:
    """Run id -> its status: plausibility flags, acceptance verdicts and warnings."""
    flags, failing = _flags_by_run(summary), _failing_acceptance(summary)
    return {run.run_id: _status(run, flags.get(run.run_id, []), run.run_id in failing)
            for run in runs}


def run_rows(summary: xr.Dataset, runs: Sequence[RunFile],
             statuses: dict[str, RunStatus]) -> list[dict[str, str]]:
    """The run table: one row per processed run (linking its page), then the failed runs."""
    e0 = _by_label(summary, "specimen", "specimen_E0")
    crosshead = _by_label(summary, "specimen", "specimen_from_crosshead")
    impacts = {name: _by_label(summary, "operating_point", f"{name}_meas")
               for name in ("N_u1", "N_u2")}
    rows = []
    for run in runs:
        run_id, attrs = run.run_id, run.attrs
        if run.kind == "tensile":
            what = f"chain {attrs.get('chain', '')}, specimen {attrs.get('specimen', '')}"
            numbers = f"E0 = {kilonewtons(e0.get(run_id, math.nan))} kN" + (
                " (from the crosshead: too low)" if crosshead.get(run_id, 0) else "")
        elif run.kind == "roller-engagement":
            what = f"chain {attrs.get('chain', '')}, sprocket {attrs.get('sprocket', '')}"
            numbers = roller_numbers(summary, run_id)
        elif run.kind == "wear":
            what = f"chain {attrs.get('chain', '')}, sprocket z = {attrs.get('sprocket_teeth', '')}"
            numbers = run_numbers(summary, run_id)
        elif run.kind == "segment-load":
            what = f"chain {attrs.get('chain', '')}, drum {attrs.get('drum', '')}"
            numbers = segment_numbers(summary, run_id)
        else:
            what = f"chain {attrs.get('chain', '')}, wheel {attrs.get('wheel', '')}"
            numbers = ", ".join(f"{name} = {number(impacts[name].get(run_id, math.nan))} N"
                               for name in impacts)
        rows.append({"run": run_id, "anchor": row_anchor(run_id), "href": page_href(run_id),
                     "kind": run.kind, "what": what, "numbers": numbers,
                     "status": statuses[run_id].status, "result": statuses[run_id].text})
    failed = summary["failed_run"].values if summary.sizes.get("failed_run", 0) else []
    rows += [{"run": str(run_id), "anchor": row_anchor(str(run_id)), "href": "",
              "kind": MISSING, "what": MISSING, "numbers": MISSING, "status": "fail",
              "result": "failed: no results (its error is in the checks)"}
             for run_id in failed]
    return rows


def specimen_row(run: xr.Dataset) -> dict[str, str]:
    """A tensile run's E0 and how it was found, as text (E0 in kN)."""
    return {
        "run": str(run.attrs.get("run_id", "")),
        "specimen": str(run.attrs.get("specimen", "")),
        "chain": str(run.attrs.get("chain", "")),
        "E0": kilonewtons(run["specimen_E0"]),
        "E0_interval": kilonewton_interval(run["specimen_E0_ci_low"],
                                           run["specimen_E0_ci_high"]),
        "cycles": plain_number(run["specimen_n_cycles"]),
        "E0_first": kilonewtons(run["specimen_E0_first"]),
        "E0_unloading": kilonewtons(run["specimen_E0_unloading"]),
        "birge": number(run["specimen_birge_ratio"], 3),
        "bending": percent(run["gauge_disagreement"], 1),
    }


def _channel_rows(run: xr.Dataset) -> list[dict[str, str]]:
    rows = []
    for channel in run["channel"].values if "channel" in run.dims else []:
        row = run.sel(channel=channel)
        removed = int(row["channel_removed_at"])
        rows.append({
            "channel": str(channel), "column": str(row["channel_column"].values),
            "kind": str(row["channel_kind"].values),
            "stiffness": kilonewtons(row["channel_stiffness"]),
            "used": "yes" if int(row["channel_used"]) else "no",
            "removed": (f"{row['channel_removal'].values} at sample {removed}" if removed >= 0
                        else MISSING),
        })
    return rows


def _fit_rows(run: xr.Dataset) -> list[dict[str, str]]:
    rows = []
    for cycle in run["cycle"].values:
        for branch in run["branch"].values:
            fit = run.sel(cycle=cycle, branch=branch)
            rows.append({
                "cycle": str(int(cycle)), "branch": str(branch),
                "E0": kilonewtons(fit["fit_E0"]),
                "interval": kilonewton_interval(fit["fit_E0_ci_low"], fit["fit_E0_ci_high"]),
                "window": interval(fit["fit_window_low"] / 1e3, fit["fit_window_high"] / 1e3,
                                   lambda v: number(v, 3)),
                "points": plain_number(fit["fit_n_points"]),
                "r2": f"{float(fit['fit_r2']):.6f}" if math.isfinite(float(fit["fit_r2"]))
                else MISSING,
                "rms": number(fit["fit_residual_rms"], 3),
            })
    return rows


def _tensile(run: xr.Dataset) -> dict[str, Any]:
    """What a tensile run's page shows besides its status and raw file."""
    return {
        **specimen_row(run),
        "single_pull": bool(int(run["single_pull"])) if "single_pull" in run else False,
        "level": level(run["fit_E0_ci_low"].attrs),
        "channels": _channel_rows(run),
        "curve_svg": svg(stiffness_figures.force_strain(run)),
        "residual_svg": svg(stiffness_figures.fit_residuals(run)),
        "fits": _fit_rows(run),
    }


def _statistics(run: xr.Dataset) -> list[dict[str, str]]:
    """An engagement run's statistics per quantity (:data:`ENGAGEMENT_QUANTITIES`)."""
    return [{"quantity": label, "unit": unit, "median": number(run[f"{name}_median"]),
             "iqr": number(run[f"{name}_iqr"], 3), "stderr": number(run[f"{name}_stderr"], 2),
             "stderr_events": number(run[f"{name}_stderr_events"], 2),
             "stderr_ringing": number(run[f"{name}_stderr_ringing"], 2),
             "count": plain_number(run[f"{name}_count"])}
            for name, label, unit in ENGAGEMENT_QUANTITIES]


def _operating_point(point: xr.Dataset | None, k_theory: str) -> dict[str, str] | None:
    """The run's operating point in the summary, with the model's impact tensions."""
    if point is None:
        return None
    cells = {"z": plain_number(point["teeth"]), "psi": plain_number(point["apex_angle"]),
             "omega": plain_number(point["omega"]), "k_theory": k_theory}
    for name in ("N_u1", "N_u2"):
        for column in ("meas", "theory", "fit"):
            cells[f"{name}_{column}"] = number(point[f"{name}_{column}"])
    return cells


def _engagement(run: xr.Dataset, point: xr.Dataset | None, k_theory: str) -> dict[str, Any]:
    """What an engagement run's page shows besides its status and raw file."""
    with report_style():
        zoom = svg(impact_figures.impact_zoom(run))
    excluded = [f"{reason.replace('_', ' ')}: {int(run[f'excluded_{reason}'])}"
                for reason in EXCLUSION_REASONS if int(run[f"excluded_{reason}"])]
    return {
        "point": _operating_point(point, k_theory),
        "statistics": _statistics(run),
        "events": plain_number(run["events_total"]),
        "excluded": ", ".join(excluded) or "none",
        "omega_n": number(run["omega_n"]), "omega_n_stderr": number(run["omega_n_stderr"], 2),
        "zeta": number(run["zeta"]), "zeta_stderr": number(run["zeta_stderr"], 2),
        "ringing_events": plain_number(run["ringing_events"]),
        "seating_period": number(run["seating_period"]),
        "omega_measured": number(run["omega_measured"]),
        "comparison": str(run.attrs.get("comparison", "")),
        "event_source": str(run.attrs.get("event_source", "")),
        "zoom_svg": zoom,
    }


def _neighbour(run: RunFile | None) -> dict[str, str] | None:
    """A link from one run's page to another's (they share a folder)."""
    return None if run is None else {"run": run.run_id,
                                     "href": quote(page_name(run.run_id), safe="")}


def _point(summary: xr.Dataset, run_id: str) -> xr.Dataset | None:
    """The summary's operating point of engagement run `run_id`, if it has one."""
    if not summary.sizes.get("operating_point", 0):
        return None
    index = summary.indexes["operating_point"]
    return summary.isel(operating_point=index.get_loc(run_id)) if run_id in index else None


def run_page_context(summary: xr.Dataset, run: RunFile, dataset: xr.Dataset,
                     status: RunStatus, neighbours: tuple[RunFile | None, RunFile | None]
                     ) -> dict[str, Any]:
    """What a run's page shows, as strings, lists and dicts (figures as SVG).

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign's ``summary.nc``.
    run : RunFile
        The run.
    dataset : xarray.Dataset
        Its whole run file (:meth:`RunFile.load`).
    status : RunStatus
        Its status (:func:`run_statuses`).
    neighbours : tuple of RunFile or None
        The runs before and after it in the run table.

    Returns
    -------
    dict
        ``run`` (id, kind, status, flags, warnings, raw file, link back),
        ``previous`` and ``next`` (or None), ``tensile``, ``engagement``,
        ``wear`` and ``segment`` (the one of its kind; the others None).
    """
    attrs = run.attrs
    engagement = None
    if run.kind == "roller-engagement":
        engagement = _engagement(dataset, None, "")
    if run.kind == "engagement":
        k_theory = f"{float(recorded(summary.attrs, 'k_theory')):g}"
        engagement = _engagement(dataset, _point(summary, run.run_id), k_theory)
    return {
        "run": {"id": run.run_id, "kind": run.kind, "chain": str(attrs.get("chain", "")),
                "status": status.status, "result": status.text, "flags": list(status.flags),
                "warnings": run_notes(attrs), "file": str(attrs.get("raw_file", "")),
                "layout": str(attrs.get("layout", "")),
                "sha256": str(attrs.get("raw_sha256", "")),
                "back": f"../{layout.REPORT}#{quote(row_anchor(run.run_id), safe='')}"},
        "previous": _neighbour(neighbours[0]),
        "next": _neighbour(neighbours[1]),
        "tensile": _tensile(dataset) if run.kind == "tensile" else None,
        "engagement": engagement,
        "wear": wear_run_page(dataset) if run.kind == "wear" else None,
        "segment": segment_run_page(dataset) if run.kind == "segment-load" else None,
    }


def remove_stale_pages(folder: Path, keep: set[str]) -> list[Path]:
    """Delete the pages in `folder` not named in `keep`, and temporaries of a killed build.

    Returns
    -------
    list of Path
        The pages deleted.
    """
    if not folder.is_dir():
        return []
    remove_stale_temporaries(folder)
    stale = sorted(path for path in folder.glob("*.html") if path.name not in keep)
    for path in stale:
        path.unlink()
    return stale


@dataclass(frozen=True)
class RunPage:
    """One run's page to write: the run, its status, and the runs before and after it."""

    run: RunFile
    status: RunStatus
    neighbours: tuple[RunFile | None, RunFile | None]


def write_run_page(page: RunPage, *, output_dir: Path, summary: xr.Dataset,
                   campaign: dict[str, Any]) -> Path:
    """Write one run's page into ``report-runs/`` (atomically) and return its path.

    Parameters
    ----------
    page : RunPage
        The run, its status and its neighbours in the run table.
    output_dir : Path
        The processed campaign folder.
    summary : xarray.Dataset
        Its ``summary.nc``.
    campaign : dict
        The campaign's id, title, creation time and version, as the campaign page shows them.
    """
    context = run_page_context(summary, page.run, page.run.load(), page.status, page.neighbours)
    html = environment().get_template(TEMPLATE_NAME).render(campaign=campaign, **context)
    return write_text_atomic(html, output_dir / layout.RUN_PAGES / page_name(page.run.run_id))


def write_run_pages(output_dir: Path, summary: xr.Dataset, runs: Sequence[RunFile],
                    statuses: dict[str, RunStatus], campaign: dict[str, Any],
                    client: Client | None = None) -> Mapped:
    """Start writing the page of every run into ``report-runs/``, one run in memory at a time.

    Parameters
    ----------
    output_dir : Path
        The processed campaign folder.
    summary : xarray.Dataset
        Its ``summary.nc``.
    runs : sequence of RunFile
        Its runs, in the order of the run table (:func:`campaign_runs`).
    statuses : dict
        Run id -> its status (:func:`run_statuses`).
    campaign : dict
        The campaign's id, title, creation time and version, as the campaign page shows them.
    client : distributed.Client, optional
        Write the pages as tasks on this dask cluster, started at once (default:
        in this process, when the results are asked for).

    Returns
    -------
    Mapped
        Its ``results()`` are the pages written (:func:`write_run_page`), in the
        order of `runs`. The pages of other runs in the folder are deleted first.
    """
    folder = output_dir / layout.RUN_PAGES
    remove_stale_pages(folder, {page_name(run.run_id) for run in runs})
    pages = [RunPage(run, statuses[run.run_id],
                     (runs[index - 1] if index else None,
                      runs[index + 1] if index + 1 < len(runs) else None))
             for index, run in enumerate(runs)]
    return Mapped(write_run_page, pages, client, output_dir=output_dir, summary=summary,
                  campaign=campaign)
