"""The campaign report: ``report.html`` and ``report-runs/<run id>.html`` from the processed files.

:func:`build_report` reads ``summary.nc`` and the run files of a processed
campaign folder (never ``raw/``), builds the figures (matplotlib, rendered
as deterministic inline SVG by :func:`pipeline.report.render.svg`) and fills
the jinja2 templates of ``templates/``. Every page is a self-contained HTML
file: CSS inline, no script, no network.

The campaign page ``report.html`` has the campaign-level figures and tables:
summary (what was tested, every check with its verdict), the run table (one
row per run, linking its page), stiffness (Paper 001), impact (Paper 000),
wear and life of roller chains measured against Paper 004
(:mod:`pipeline.report.wear_section`), design checks of Papers 002-004 where
the campaign's chains fit them,
published values not reproduced, provenance. Its size grows with the runs by
table rows only: the per-run figures are on the runs' own pages
(:mod:`pipeline.report.run_pages`), written one run at a time before it.

Safety: the template autoescapes everything; only the SVG of our own renderer
is inserted verbatim (``|safe`` on ``svg`` fields), and matplotlib escapes
the text it draws, so a string from an input (run id, specimen, chain key,
title, note, error message) is always shown as text.

Reproducible: the same processed folder and the same `created` give the same
bytes; the creation time appears on one line of each page.

The report only formats: every number, verdict, sentence about a fit and
setting it shows is read from the processed files (the settings through
:mod:`pipeline.report.recorded`); none is computed here.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from contextlib import suppress
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import xarray as xr

from pipeline import __version__
from pipeline.acceptance import CHECKS
from pipeline.errors import ChainbenchError
from pipeline.report import design_figures, impact_figures, stiffness_figures, wear_figures
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
    timestamp,
    verdict_class,
)
from pipeline.report.recorded import level, recorded
from pipeline.report.render import report_style, svg
from pipeline.report.roller_figures import amplitude_vs_speed
from pipeline.report.roller_section import roller_checks, roller_section
from pipeline.report.roller_section import tested as roller_tested
from pipeline.report.run_pages import (
    RunFile,
    RunStatus,
    campaign_runs,
    plausibility_flags,
    remove_stale_pages,
    run_rows,
    run_statuses,
    specimen_row,
    write_run_pages,
)
from pipeline.report.segment_figures import contact_ratios_vs_s
from pipeline.report.segment_section import segment_checks, segment_section
from pipeline.report.segment_section import tested as segment_tested
from pipeline.report.wear_section import tested as wear_tested
from pipeline.report.wear_section import wear_checks, wear_level, wear_section, wear_settings
from pipeline.results.notes import lines
from pipeline.results.tensile import STRENGTH_VARIABLES
from pipeline.store import layout
from pipeline.store.netcdf import read_dataset, write_text_atomic
from pipeline.tasks import Mapped
from pipeline.units import from_si

if TYPE_CHECKING:
    from distributed import Client

#: The jinja2 template of the campaign page (``pipeline/report/templates``).
TEMPLATE_NAME = "report.html.j2"

#: How each acceptance check reads in the report.
ACCEPTANCE_LABELS = {
    "proof_force": "carries the proof force",
    "breaking_force": "breaking force at least the minimum",
    "elongation_at_proof": "elongation at proof force at most the maximum",
    "elongation_at_fracture": "elongation at fracture at least the minimum",
}


def _band(summary: xr.Dataset) -> tuple[float, float]:
    low, high = (float(value) for value in summary.attrs["band"].split())
    return low, high


def _has(summary: xr.Dataset, dim: str) -> bool:
    return summary.sizes.get(dim, 0) > 0


def _tested(summary: xr.Dataset) -> str:
    """One phrase saying what the campaign tested."""
    parts = []
    if _has(summary, "chain"):
        specimens = int(summary["n_specimens"].sum())
        parts.append(f"tensile tests of {specimens} specimen(s) of {summary.sizes['chain']} "
                     "chain(s) for their static stiffness E0")
    if _has(summary, "operating_point"):
        parts.append(f"engagement logs of a chain on chain wheels at "
                     f"{summary.sizes['operating_point']} operating point(s) for the impact "
                     "tensions N_u1 and N_u2")
    if _has(summary, "wear_run"):
        parts.append(wear_tested(summary))
    if _has(summary, "sprocket_point"):
        parts.append(roller_tested(summary))
    if _has(summary, "segment_point"):
        parts.append(segment_tested(summary))
    return "; ".join(parts) or "no run could be processed"


def _campaign(summary: xr.Dataset, created: datetime) -> dict[str, Any]:
    attrs = summary.attrs
    return {
        "id": str(attrs.get("campaign", "")),
        "title": str(attrs.get("title", "")),
        "lab": str(attrs.get("lab", "")),
        "machine": str(attrs.get("source", "")),
        "note": str(attrs.get("campaign_note", "")),
        "synthetic": bool(int(attrs.get("synthetic", 0))),
        "tested": _tested(summary),
        "created": timestamp(created),
        "version": __version__,
    }


def _band_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    low, high = _band(summary)
    for chain in summary["chain"].values:
        row = summary.sel(chain=chain)
        verdict = float(row["in_band"])
        passed = None if not math.isfinite(verdict) else bool(verdict)
        result = {None: "not checked", True: "in band", False: "out of band"}[passed]
        spread = interval(row["discrepancy_ci_low"], row["discrepancy_ci_high"], percent)
        detail = (f"d = (E0_exp − E0_theory) / E0_theory = {percent(row['discrepancy'])} "
                  f"({level(row['discrepancy_ci_low'].attrs)} interval {spread})"
                  if passed is not None else "no experimental or no theoretical E0")
        yield {"check": f"E0 of chain {chain} within {100 * low:g} to {100 * high:g} % "
                        "above theory", "result": result, "status": verdict_class(passed),
               "detail": detail}


def _impact_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    k, low, high = (float(summary[name]) for name in ("k_fit", "k_fit_ci_low", "k_fit_ci_high"))
    fitted = math.isfinite(k)
    k_level = level(summary["k_fit_ci_low"].attrs)
    yield {"check": "impact model (Paper 000, eq. (16)) fitted to the measured N_u1, N_u2",
           "result": "fitted" if fitted else "not fitted", "status": verdict_class(fitted),
           "detail": (f"k = {number(k)} ({k_level} interval {interval(low, high)})" if fitted
                      else "see the notes")}
    if fitted:
        inside = int(summary["k_fit_covers_theory"]) == 1
        yield {"check": f"Ryabov's k = {float(recorded(summary.attrs, 'k_theory')):g} inside "
                        f"the {k_level} interval of the fitted k",
               "result": "yes" if inside else "no",
               "status": verdict_class(inside), "detail": f"interval {interval(low, high)}"}


_VERDICT = {1: ("pass", "pass"), 0: ("fail", "fail"), -1: ("not measured", "info")}


def _acceptance_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    """The acceptance limits each chain declares, with its verdict and the failing specimens."""
    for chain in summary["chain"].values:
        for check in CHECKS:
            code = int(summary[f"accept_{check}"].sel(chain=chain))
            if code not in _VERDICT:
                continue
            mine = summary["specimen_chain"].values == chain
            verdicts = summary[f"specimen_accept_{check}"].values[mine]
            failing = [str(run) for run, code in zip(summary["specimen"].values[mine], verdicts,
                                                     strict=True) if code == 0]
            result, status = _VERDICT[code]
            yield {"check": f"chain {chain}: {ACCEPTANCE_LABELS[check]}", "result": result,
                   "status": status,
                   "detail": (f"failed by {', '.join(failing)}; " if failing else "")
                   + f"{int(np.sum(verdicts >= 0))} specimen(s) measured"}


def _run_warnings(runs: Sequence[RunFile]) -> Iterable[dict[str, str]]:
    """One row per tensile run whose stages decided or repaired something."""
    for run in runs:
        found = lines(run.attrs.get("warnings", ""))
        if run.kind == "tensile" and found:
            yield {"check": f"run {run.run_id}: channels, fracture and time",
                   "result": "warning", "status": "info", "detail": "; ".join(found)}


def _plausibility_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    """One row per plausibility flag: a value far from what is known, and the slip it
    suggests; an accepted flag is information, an open one a failure."""
    if not _has(summary, "flag"):
        yield {"check": "values plausible (against theory, breaking force, machine capacity, "
                        "strain limit, the other specimens)", "result": "yes",
               "status": "pass", "detail": "no value far from what is known"}
        return
    for flag in plausibility_flags(summary):
        yield {"check": f"run {flag['run']}: {flag['quantity']} plausible",
               "result": flag["result"], "status": flag["status"], "detail": flag["message"]}


def _checks(summary: xr.Dataset, runs: Sequence[RunFile]) -> list[dict[str, str]]:
    """Every check of the campaign as rows: check, result, status, detail."""
    failures = _failures(summary)
    total = len(runs) + len(failures)
    rows = [{"check": "runs processed", "result": f"{len(runs)} of {total}",
             "status": verdict_class(not failures),
             "detail": "" if not failures else f"{len(failures)} failed, listed below"}]
    if _has(summary, "chain"):
        rows.extend(_band_checks(summary))
        if _has(summary, "specimen"):
            rows.extend(_acceptance_checks(summary))
        rows.extend(_run_warnings(runs))
    if _has(summary, "operating_point"):
        rows.extend(_impact_checks(summary))
    if _has(summary, "wear_run"):
        rows.extend(wear_checks(summary))
    if _has(summary, "sprocket_point"):
        rows.extend(roller_checks(summary))
    if _has(summary, "segment_point"):
        rows.extend(segment_checks(summary))
    rows.extend(_plausibility_checks(summary))
    rows.extend({"check": f"run {run_id}", "result": "failed", "status": "fail",
                 "detail": error} for run_id, error in failures)
    return rows


def _failures(summary: xr.Dataset) -> list[tuple[str, str]]:
    if not _has(summary, "failed_run"):
        return []
    return [(str(run), str(error)) for run, error in
            zip(summary["failed_run"].values, summary["error"].values, strict=True)]


def _kgf(value: float) -> str:
    return f"{number(from_si(float(value), 'kgf') / 1e6, 3)}·10⁶ kgf" \
        if math.isfinite(float(value)) else ""


def _chain_rows(summary: xr.Dataset) -> list[dict[str, str]]:
    rows = []
    for chain in summary["chain"].values:
        row = summary.sel(chain=chain)
        published_exp, published_theory = (float(row[name]) for name in
                                           ("E0_exp_published", "E0_theory_published"))
        verdict = float(row["in_band"])
        rows.append({
            "chain": str(chain),
            "specimens": str(int(row["n_specimens"])),
            "E0_exp": kilonewtons(row["E0_exp"]),
            "E0_exp_interval": kilonewton_interval(row["E0_exp_ci_low"], row["E0_exp_ci_high"]),
            "E0_theory": kilonewtons(row["E0_theory"]),
            "E0_theory_exact": kilonewtons(row["E0_theory_exact"]),
            "published_exp": kilonewtons(published_exp),
            "published_exp_kgf": _kgf(published_exp),
            "published_theory": kilonewtons(published_theory),
            "published_theory_kgf": _kgf(published_theory),
            "discrepancy": percent(row["discrepancy"]),
            "discrepancy_interval": interval(row["discrepancy_ci_low"],
                                             row["discrepancy_ci_high"], percent),
            "discrepancy_vs_exp": percent(row["discrepancy_vs_exp"]),
            "published_discrepancy": percent(row["discrepancy_published"]),
            "verdict": ("not checked" if not math.isfinite(verdict)
                        else "in band" if verdict else "out of band"),
            "status": verdict_class(None if not math.isfinite(verdict) else bool(verdict)),
        })
    return rows


def _percent_of_length(value: float) -> str:
    return percent(value, 2)


def _strength_rows(summary: xr.Dataset) -> list[dict[str, str]]:
    """The figures a lab reports per specimen, with its acceptance verdicts."""
    rows = []
    for run_id in summary["specimen"].values if _has(summary, "specimen") else []:
        row = summary.sel(specimen=run_id)
        value = {name: float(row[f"specimen_{name}"]) for name in STRENGTH_VARIABLES}
        verdicts = [f"{ACCEPTANCE_LABELS[check]}: {_VERDICT[code][0]}" for check in CHECKS
                    if (code := int(row[f"specimen_accept_{check}"])) in _VERDICT]
        rows.append({
            "run": str(run_id), "specimen": str(row["specimen_name"].values),
            "kind": ("single pull" if int(row["specimen_single_pull"]) else "cyclic")
            + (", E0 from the crosshead" if int(row["specimen_from_crosshead"]) else ""),
            "max_force": kilonewtons(value["max_force"]),
            "at_max": _percent_of_length(value["strain_at_max_force"]),
            "fracture_force": kilonewtons(value["fracture_force"]),
            "at_fracture": _percent_of_length(value["strain_at_fracture"]),
            "yield_force": kilonewtons(value["yield_force"]),
            "offset": percent(value["yield_offset"], 2),
            "at_proof": _percent_of_length(value["strain_at_proof"]),
            "set": _percent_of_length(value["permanent_strain_after_proof"]),
            "verdicts": "; ".join(verdicts) or MISSING,
            "status": ("fail" if any(v.endswith("fail") for v in verdicts) else
                       "pass" if verdicts else "info"),
        })
    return rows


def _tensile_results(summary: xr.Dataset, runs: Sequence[RunFile]
                     ) -> tuple[list[dict[str, str]], list[xr.Dataset]]:
    """The specimen table's rows and the fits the stiffness overview draws, read from the
    tensile runs' results one at a time (in the order of the summary's chains)."""
    order = {str(chain): index for index, chain in enumerate(summary["chain"].values)}
    tensile = sorted((run for run in runs if run.kind == "tensile"),
                     key=lambda run: (order.get(run.attrs.get("chain"), len(order)),
                                      natural_key(run.run_id)))
    specimens, drawn = [], []
    for run in tensile:
        results = run.results()
        specimens.append(specimen_row(results))
        drawn.append(results[[name for name in stiffness_figures.OVERVIEW_VARIABLES
                              if name in results]])
    return specimens, drawn


def _stiffness(summary: xr.Dataset, specimens: list[dict[str, str]], overview: str
               ) -> dict[str, Any]:
    """Figures and tables of the stiffness section."""
    low, high = _band(summary)
    return {
        "band": f"{100 * low:g} to {100 * high:g} %",
        "level": level(summary["E0_exp_ci_low"].attrs),
        "overview_svg": overview,
        "chains": _chain_rows(summary),
        "specimens": specimens,
        "strength": _strength_rows(summary),
    }


def _point_rows(summary: xr.Dataset) -> list[dict[str, str]]:
    rows = []
    for point in summary["operating_point"].values:
        row = summary.sel(operating_point=point)
        cells = {"run": str(point), "z": plain_number(row["teeth"]),
                 "psi": plain_number(row["apex_angle"]), "omega": plain_number(row["omega"])}
        for impact in ("N_u1", "N_u2"):
            cells[f"{impact}_meas"] = number(row[f"{impact}_meas"])
            cells[f"{impact}_stderr"] = number(row[f"{impact}_stderr"], 2)
            cells[f"{impact}_count"] = plain_number(row[f"{impact}_count"])
            cells[f"{impact}_theory"] = number(row[f"{impact}_theory"])
            cells[f"{impact}_fit"] = number(row[f"{impact}_fit"])
        rows.append(cells)
    return rows


def _impact(summary: xr.Dataset, runs: Sequence[RunFile], by_omega: str, by_apex: str
            ) -> dict[str, Any]:
    """Figures and tables of the impact section (the figures rendered)."""
    k_theory = f"{float(recorded(summary.attrs, 'k_theory')):g}"
    figures = [{"caption": "Measured impact tensions against wheel speed, with the model "
                           f"for k = {k_theory} and for the fitted k.", "svg": by_omega},
               {"caption": "Impact tensions against the tooth apex angle, per number of "
                           "teeth (as Paper 000, figures 3 and 4).", "svg": by_apex}]
    k = {name: float(summary[name]) for name in
         ("k_fit", "k_fit_stderr", "k_fit_ci_low", "k_fit_ci_high", "k_fit_chi2_reduced")}
    comparison = sorted({str(run.attrs.get("comparison", "")) for run in runs
                         if run.kind == "engagement"} - {""})
    return {
        "figures": figures,
        "points": _point_rows(summary),
        "k_fitted": math.isfinite(k["k_fit"]),
        "k": number(k["k_fit"]),
        "k_stderr": number(k["k_fit_stderr"], 2),
        "k_interval": interval(k["k_fit_ci_low"], k["k_fit_ci_high"]),
        "k_chi2": number(k["k_fit_chi2_reduced"], 3),
        "k_level": level(summary["k_fit_ci_low"].attrs),
        "k_ryabov": k_theory,
        "linearity": str(recorded(summary.attrs, "linearity")),
        "comparison": ", ".join(comparison),
    }


def _design(summary: xr.Dataset) -> list[dict[str, str]]:
    return [{"title": title, "svg": svg(figure)}
            for title, figure in design_figures.design_checks(summary)]


def _overview(summary: xr.Dataset, drawn: list[xr.Dataset]) -> str:
    return svg(stiffness_figures.stiffness_by_specimen(summary, drawn))


def _impact_vs_omega(summary: xr.Dataset) -> str:
    return svg(impact_figures.impact_vs_omega(summary))


def _impact_vs_apex(summary: xr.Dataset) -> str:
    return svg(impact_figures.impact_vs_apex(summary))


def _wear_overview(summary: xr.Dataset, drawn: list[xr.Dataset]) -> str:
    return svg(wear_figures.wear_overview(drawn))


def _wear_runs(summary: xr.Dataset, runs: Sequence[RunFile]) -> list[xr.Dataset]:
    """What the wear overview draws of each wear run, in the order of the summary's table."""
    order = {str(run): index for index, run in enumerate(summary["wear_run"].values)}
    wear = sorted((run for run in runs if run.kind == "wear"),
                  key=lambda run: order.get(run.run_id, len(order)))
    return [run.results()[list(wear_figures.OVERVIEW_VARIABLES)] for run in wear]


def _segment_ratios(summary: xr.Dataset) -> str:
    return svg(contact_ratios_vs_s(summary))


def _roller_amplitudes(summary: xr.Dataset) -> str:
    return svg(amplitude_vs_speed(summary))


def _rendered(figure: tuple[Callable, tuple], *, summary: xr.Dataset) -> Any:
    """A figure of the campaign page, rendered: ``figure`` is its function of the summary
    and the function's further arguments."""
    function, arguments = figure
    with report_style():
        return function(summary, *arguments)


@dataclass(frozen=True)
class CampaignFigures:
    """The campaign page's figures being rendered (as tasks on a cluster, or here when
    asked for), and the specimen rows read from the tensile runs on the way."""

    names: list[str]
    rendering: Mapped
    specimens: list[dict[str, str]]

    def svgs(self) -> dict[str, Any]:
        """Figure name -> its SVG (the design checks: a list of titled SVGs)."""
        return dict(zip(self.names, self.rendering.results(), strict=True))


def campaign_figures(summary: xr.Dataset, runs: Sequence[RunFile],
                     client: Client | None = None) -> CampaignFigures:
    """Start rendering the campaign page's figures (as tasks on `client`, at once)."""
    specimens, drawn = _tensile_results(summary, runs) if _has(summary, "chain") else ([], [])
    figures = {"design": (_design, ())}
    if _has(summary, "chain"):
        figures["overview"] = (_overview, (drawn,))
    if _has(summary, "operating_point"):
        figures.update(by_omega=(_impact_vs_omega, ()), by_apex=(_impact_vs_apex, ()))
    if _has(summary, "wear_run"):
        figures["wear"] = (_wear_overview, (_wear_runs(summary, runs),))
    if _has(summary, "sprocket_point"):
        figures["roller"] = (_roller_amplitudes, ())
    if _has(summary, "segment_point"):
        figures["segment"] = (_segment_ratios, ())
    rendering = Mapped(_rendered, list(figures.values()), client, summary=summary)
    return CampaignFigures(list(figures), rendering, specimens)


def _not_reproduced() -> list[dict[str, str]]:
    """Published numbers the models do not give: published as printed, model to 4 digits."""
    rows = []
    for row in design_figures.published_not_reproduced():
        cells = {key: str(row.get(key, "")) for key in
                 ("paper", "quantity", "inputs", "unit", "note")}
        published = number(row["published"], 6)
        cells["published"] = published.rstrip("0").rstrip(".") if "." in published \
            else published
        cells["model"] = number(row["model"], 4)
        cells["difference"] = percent(row["difference"], 1)
        rows.append(cells)
    return rows


def _grouped(texts: dict[str, str]) -> str:
    """Run id -> a setting as one text: the setting when all runs share it, else each
    setting followed by its runs."""
    runs: dict[str, list[str]] = {}
    for run_id, text in texts.items():
        runs.setdefault(text, []).append(run_id)
    if len(runs) == 1:
        return next(iter(runs))
    return "; ".join(f"{text} (runs {', '.join(ids)})" for text, ids in runs.items()) or MISSING


def _extraction(attrs: dict[str, Any]) -> str:
    """The impact extraction's settings an engagement run file records, in words."""
    return (f"each event's window from {float(recorded(attrs, 'event_window_pre')):g} tau "
            f"before impact 1 to {float(recorded(attrs, 'event_window_guard')):g} tau before "
            "the next seating (tau: half the seating period); an event's fit failed when an "
            f"onset moves by more than {float(recorded(attrs, 'max_onset_shift')):g} ringing "
            f"periods or its residual exceeds {float(recorded(attrs, 'residual_outlier')):g} "
            "times the run's median and "
            f"{100 * float(recorded(attrs, 'residual_floor')):g} % of the typical strike; "
            "omega_n and zeta fitted on up to "
            f"{int(recorded(attrs, 'ringing_events_max'))} events")


def _plausibility(summary: xr.Dataset) -> str:
    """The bands of the plausibility checks the summary records, in words."""
    def band(name: str) -> str:
        low, high = (float(value) for value in recorded(summary.attrs, name))
        return f"{low:.3g} to {high:.3g}"

    attrs = summary.attrs
    return (f"value / theory (E0, N_u1, N_u2) within {band('plausibility_theory_band')}; E0 / "
            f"the chain's other specimens within {band('plausibility_peer_band')} (from "
            f"{int(recorded(attrs, 'plausibility_min_specimens'))} specimens); max force / "
            f"breaking force within {band('plausibility_breaking_band')}; max force at most "
            f"{float(recorded(attrs, 'plausibility_capacity_tolerance')):g} x the machine's "
            f"capacity; strains at most {float(recorded(attrs, 'plausibility_strain_limit')):g}")


def _provenance(summary: xr.Dataset, runs: Sequence[RunFile]) -> dict[str, Any]:
    settings, levels = [], []
    if _has(summary, "chain"):
        low, high = _band(summary)
        windows = {run.run_id: str(recorded(run.attrs, "fit_window")) for run in runs
                   if run.kind == "tensile"}
        settings += [
            ("stiffness fit window", _grouped(windows)),
            ("specimen E0", "mean of the loading slopes of cycles 2..n; cycle 1 (seating) and "
                            "the unloading branches reported beside it"),
            ("discrepancy band", f"{100 * low:g} to {100 * high:g} % for "
                                 "d = (E0_exp − E0_theory) / E0_theory"),
            ("theoretical E0", "Paper 001 eq. (20) with the printed coefficients (exact "
                               "Maxwell-Mohr coefficients beside)"),
        ]
        levels.append(f"{level(summary['E0_exp_ci_low'].attrs)} for E0 (Student's t)")
    if _has(summary, "operating_point"):
        extraction = {run.run_id: _extraction(run.attrs) for run in runs
                      if run.kind == "engagement"}
        settings += [("impact model fit", str(recorded(summary.attrs, "k_fit_method"))),
                     ("impact extraction", _grouped(extraction))]
        levels.append(f"{level(summary['k_fit_ci_low'].attrs)} for k")
    if _has(summary, "wear_run"):
        settings += wear_settings(run for run in runs if run.kind == "wear")
        levels.append(f"{wear_level(summary)} for wear rates and lives (Student's t)")
    settings += [("confidence level", "; ".join(levels) or MISSING),
                 ("plausibility bands", _plausibility(summary))]
    return {
        "processed_with": str(summary.attrs.get("chainbench_version", "")),
        "run_sheet_sha256": str(summary.attrs.get("run_sheet_sha256", "")),
        "files": [{"run": run.run_id, "kind": run.kind,
                   "file": str(run.attrs.get("raw_file", "")),
                   "sha256": str(run.attrs.get("raw_sha256", "")),
                   "layout": str(run.attrs.get("layout", ""))} for run in runs],
        "settings": settings,
    }


def report_context(summary: xr.Dataset, runs: Sequence[RunFile],
                   statuses: dict[str, RunStatus], created: datetime,
                   figures: CampaignFigures) -> dict[str, Any]:
    """Everything the campaign page shows, as strings, lists and dicts (figures as SVG).

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign's ``summary.nc``.
    runs : sequence of RunFile
        Its run files (:func:`~pipeline.report.run_pages.campaign_runs`).
    statuses : dict
        Run id -> its status (:func:`~pipeline.report.run_pages.run_statuses`).
    created : datetime
        Creation time of the report.
    figures : CampaignFigures
        Its figures, rendering (:func:`campaign_figures`): waited for last.

    Returns
    -------
    dict
        ``campaign``, ``checks``, ``notes``, ``runs`` (the run table),
        ``stiffness`` (or None), ``impact`` (or None), ``wear`` (or None), ``design``,
        ``not_reproduced``, ``provenance``.
    """
    notes = [line for line in str(summary.attrs.get("notes", "")).split("\n") if line]
    context = {
        "campaign": _campaign(summary, created),
        "checks": _checks(summary, runs),
        "notes": notes,
        "runs": run_rows(summary, runs, statuses),
        "not_reproduced": _not_reproduced(),
        "provenance": _provenance(summary, runs),
    }
    svgs = figures.svgs()
    return {
        **context,
        "stiffness": (_stiffness(summary, figures.specimens, svgs["overview"])
                      if _has(summary, "chain") else None),
        "impact": (_impact(summary, runs, svgs["by_omega"], svgs["by_apex"])
                   if _has(summary, "operating_point") else None),
        "wear": wear_section(summary, svgs["wear"]) if _has(summary, "wear_run") else None,
        "roller": (roller_section(summary, svgs["roller"])
                   if _has(summary, "sprocket_point") else None),
        "segment": (segment_section(summary, svgs["segment"])
                    if _has(summary, "segment_point") else None),
        "design": svgs["design"],
    }


@dataclass(frozen=True)
class Report:
    """The files of a campaign's report."""

    page: Path  #: the campaign page, ``report.html``
    run_pages: tuple[Path, ...]  #: the runs' pages, ``report-runs/<run id>.html``

    @property
    def outputs(self) -> list[str]:
        """The files' names relative to the campaign folder (``/``-separated), the
        campaign page first: the entries of the folder's manifest."""
        return [self.page.name, *(f"{layout.RUN_PAGES}/{page.name}" for page in self.run_pages)]


def build_report(output_dir: str | Path, created: datetime | None = None,
                 client: Client | None = None,
                 run_attrs: Mapping[str, dict[str, Any]] | None = None) -> Report:
    """Build the report of a processed campaign from its processed files alone.

    Writes every run's page into ``report-runs/`` (deleting the pages of runs
    no longer in the summary), then the campaign page ``report.html`` linking them.

    Parameters
    ----------
    output_dir : str or Path
        The processed campaign folder (``processed/<campaign>``) holding
        ``summary.nc`` and the run files.
    created : datetime, optional
        Creation time written in the report (default: now, UTC); with the same
        folder and the same `created` the report is the same, byte for byte.
    client : distributed.Client, optional
        Render the campaign page's figures and write the run pages as tasks on
        this dask cluster while this process builds the page's tables (default:
        all in this process).
    run_attrs : mapping, optional
        Run id -> the global attributes of its run file, when the caller has
        just read them (the campaign, from the runs' tasks): those files'
        attributes are not read again (default: read them all).

    Returns
    -------
    Report
        The pages written (each atomically) into `output_dir`.

    Raises
    ------
    ChainbenchError
        When `output_dir` holds no ``summary.nc``.
    """
    output_dir = Path(output_dir)
    summary_path = output_dir / layout.SUMMARY
    if not summary_path.is_file():
        raise ChainbenchError(
            "no processed campaign here (summary.nc is missing)", file=summary_path,
            hint="process the campaign first: chainbench run raw/<campaign>")
    summary = read_dataset(summary_path)
    runs = campaign_runs(output_dir, summary, run_attrs)
    statuses = run_statuses(summary, runs)
    created = created or datetime.now(UTC)
    figures = campaign_figures(summary, runs, client)  # on a cluster: the largest tasks first
    pages = write_run_pages(output_dir, summary, runs, statuses, _campaign(summary, created),
                            client)
    html = environment().get_template(TEMPLATE_NAME).render(
        **report_context(summary, runs, statuses, created, figures))
    written = tuple(pages.results())
    return Report(write_text_atomic(html, output_dir / layout.REPORT), written)


def remove_report(output_dir: str | Path) -> None:
    """Delete the report of a campaign folder: ``report.html`` and every run's page."""
    output_dir = Path(output_dir)
    (output_dir / layout.REPORT).unlink(missing_ok=True)
    remove_stale_pages(output_dir / layout.RUN_PAGES, set())
    with suppress(OSError):  # a folder someone put other files into is left
        (output_dir / layout.RUN_PAGES).rmdir()
