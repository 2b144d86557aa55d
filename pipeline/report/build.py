"""The campaign report: ``processed/<campaign>/report.html`` from the processed files alone.

:func:`build_report` reads ``summary.nc`` and the run files of a processed
campaign folder (never ``raw/``), builds the figures (matplotlib, rendered
as deterministic inline SVG by :func:`pipeline.report.render.svg`) and fills
the jinja2 template ``templates/report.html.j2``. The result is one
self-contained HTML file: CSS inline, no script, no network.

Sections: summary (what was tested, every check with its verdict), stiffness
(Paper 001), impact (Paper 000), design checks of Papers 002-004 where the
campaign's chains fit them, published values not reproduced, provenance.

Safety: the template autoescapes everything; only the SVG of our own renderer
is inserted verbatim (``|safe`` on ``svg`` fields), and matplotlib escapes
the text it draws, so a string from an input (run id, specimen, chain key,
title, note, error message) is always shown as text.

Reproducible: the same processed folder and the same `created` give the same
bytes; the creation time appears on one line of the report.

The report only formats: every number, verdict, sentence about a fit and
setting it shows is read from the processed files (the settings through
:mod:`pipeline.report.recorded`); none is computed here.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import jinja2
import numpy as np
import xarray as xr

from pipeline import __version__
from pipeline.acceptance import CHECKS
from pipeline.errors import ChainbenchError
from pipeline.report import design_figures, impact_figures, stiffness_figures
from pipeline.report.recorded import level, recorded
from pipeline.report.render import report_style, svg
from pipeline.results.notes import lines
from pipeline.results.tensile import STRENGTH_VARIABLES
from pipeline.store import layout
from pipeline.store.netcdf import read_dataset, write_text_atomic
from pipeline.units import from_si

#: The jinja2 template (``pipeline/report/templates``).
TEMPLATE_NAME = "report.html.j2"

#: Shown where a value is missing (NaN).
MISSING = "–"

#: How each acceptance check reads in the report.
ACCEPTANCE_LABELS = {
    "proof_force": "carries the proof force",
    "breaking_force": "breaking force at least the minimum",
    "elongation_at_proof": "elongation at proof force at most the maximum",
    "elongation_at_fracture": "elongation at fracture at least the minimum",
}


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


def number(value: float, digits: int = 4) -> str:
    """`value` to `digits` significant digits, thin-space thousands; :data:`MISSING` for NaN."""
    value = float(value)
    if not math.isfinite(value):
        return MISSING
    if value == 0:
        return "0"
    decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
    return f"{value:,.{decimals}f}".replace(",", "\u2009")


def plain_number(value: float) -> str:
    """`value` in the shortest form (``6``, ``20``, ``2.54``); :data:`MISSING` for NaN."""
    value = float(value)
    return f"{value:.6g}" if math.isfinite(value) else MISSING


def percent(value: float, decimals: int = 2) -> str:
    """A ratio as a percentage with `decimals` decimals (``0.0586`` -> ``"5.86 %"``)."""
    value = float(value)
    return f"{100 * value:.{decimals}f} %" if math.isfinite(value) else MISSING


def interval(low: float, high: float, format_value=number) -> str:
    """``low … high`` (or :data:`MISSING`)."""
    if not (math.isfinite(float(low)) and math.isfinite(float(high))):
        return MISSING
    return f"{format_value(low)} … {format_value(high)}"


def kilonewtons(value: float) -> str:
    """A force [N] in kN, 5 significant digits."""
    return number(float(value) / 1e3, 5)


def timestamp(created: datetime) -> str:
    """ISO 8601 UTC stamp of `created` (a naive time is taken as UTC)."""
    if created.tzinfo is None:
        created = created.replace(tzinfo=UTC)
    return created.astimezone(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")


def natural_key(text: str) -> list[int | str]:
    """Sort key putting ``E8-20`` before ``E10-20``: digit runs compare as numbers."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def campaign_runs(output_dir: Path, summary: xr.Dataset) -> list[RunFile]:
    """The run files the summary was made from (its ``run`` labels), in natural order of ids.

    Files of runs since removed from the run sheet, or of earlier attempts of
    runs that failed this time, are not results of this summary and are not shown.
    """
    runs = []
    for run_id in summary["run"].values if "run" in summary.coords else []:
        path = output_dir / f"{run_id}.nc"
        with xr.open_dataset(path, engine="netcdf4") as dataset:
            runs.append(RunFile(path, dict(dataset.attrs)))
    return sorted(runs, key=lambda run: natural_key(run.run_id))


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


def _status(passed: bool | None) -> str:
    return {True: "pass", False: "fail", None: "info"}[passed]


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
                        "above theory", "result": result, "status": _status(passed),
               "detail": detail}


def _impact_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    k, low, high = (float(summary[name]) for name in ("k_fit", "k_fit_ci_low", "k_fit_ci_high"))
    fitted = math.isfinite(k)
    k_level = level(summary["k_fit_ci_low"].attrs)
    yield {"check": "impact model (Paper 000, eq. (16)) fitted to the measured N_u1, N_u2",
           "result": "fitted" if fitted else "not fitted", "status": _status(fitted),
           "detail": (f"k = {number(k)} ({k_level} interval {interval(low, high)})" if fitted
                      else "see the notes")}
    if fitted:
        inside = int(summary["k_fit_covers_theory"]) == 1
        yield {"check": f"Ryabov's k = {float(recorded(summary.attrs, 'k_theory')):g} inside "
                        f"the {k_level} interval of the fitted k",
               "result": "yes" if inside else "no",
               "status": _status(inside), "detail": f"interval {interval(low, high)}"}


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
    for run, quantity, accepted, message in zip(
            summary["flag_run"].values, summary["flag_quantity"].values,
            summary["flag_accepted"].values, summary["flag_message"].values, strict=True):
        yield {"check": f"run {run}: {quantity} plausible",
               "result": "accepted in the run sheet" if accepted else "implausible",
               "status": "info" if accepted else "fail", "detail": str(message)}


def _checks(summary: xr.Dataset, runs: Sequence[RunFile]) -> list[dict[str, str]]:
    """Every check of the campaign as rows: check, result, status, detail."""
    failures = _failures(summary)
    total = len(runs) + len(failures)
    rows = [{"check": "runs processed", "result": f"{len(runs)} of {total}",
             "status": _status(not failures),
             "detail": "" if not failures else f"{len(failures)} failed, listed below"}]
    if _has(summary, "chain"):
        rows.extend(_band_checks(summary))
        if _has(summary, "specimen"):
            rows.extend(_acceptance_checks(summary))
        rows.extend(_run_warnings(runs))
    if _has(summary, "operating_point"):
        rows.extend(_impact_checks(summary))
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
            "E0_exp_interval": interval(row["E0_exp_ci_low"] / 1e3, row["E0_exp_ci_high"] / 1e3,
                                        lambda v: number(v, 5)),
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
            "status": _status(None if not math.isfinite(verdict) else bool(verdict)),
        })
    return rows


def _specimen_row(run: xr.Dataset) -> dict[str, str]:
    return {
        "run": str(run.attrs.get("run_id", "")),
        "specimen": str(run.attrs.get("specimen", "")),
        "chain": str(run.attrs.get("chain", "")),
        "E0": kilonewtons(run["specimen_E0"]),
        "E0_interval": interval(run["specimen_E0_ci_low"] / 1e3, run["specimen_E0_ci_high"] / 1e3,
                                lambda v: number(v, 5)),
        "cycles": plain_number(run["specimen_n_cycles"]),
        "E0_first": kilonewtons(run["specimen_E0_first"]),
        "E0_unloading": kilonewtons(run["specimen_E0_unloading"]),
        "birge": number(run["specimen_birge_ratio"], 3),
        "bending": percent(run["gauge_disagreement"], 1),
    }


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
            "kind": "single pull" if int(row["specimen_single_pull"]) else "cyclic",
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
                "interval": interval(fit["fit_E0_ci_low"] / 1e3, fit["fit_E0_ci_high"] / 1e3,
                                     lambda v: number(v, 5)),
                "window": interval(fit["fit_window_low"] / 1e3, fit["fit_window_high"] / 1e3,
                                   lambda v: number(v, 3)),
                "points": plain_number(fit["fit_n_points"]),
                "r2": f"{float(fit['fit_r2']):.6f}" if math.isfinite(float(fit["fit_r2"]))
                else MISSING,
                "rms": number(fit["fit_residual_rms"], 3),
            })
    return rows


def _stiffness(summary: xr.Dataset, runs: Sequence[RunFile]) -> dict[str, Any]:
    """Figures and tables of the stiffness section."""
    chains = [str(chain) for chain in summary["chain"].values]
    tensile = [run.load() for run in runs if run.kind == "tensile"]
    tensile.sort(key=lambda run: (chains.index(run.attrs["chain"])
                                  if run.attrs.get("chain") in chains else len(chains),
                                  natural_key(str(run.attrs.get("run_id")))))
    low, high = _band(summary)
    return {
        "band": f"{100 * low:g} to {100 * high:g} %",
        "level": level(summary["E0_exp_ci_low"].attrs),
        "overview_svg": svg(stiffness_figures.stiffness_by_specimen(summary, tensile)),
        "chains": _chain_rows(summary),
        "specimens": [_specimen_row(run) for run in tensile],
        "strength": _strength_rows(summary),
        "runs": [{
            **_specimen_row(run),
            "single_pull": bool(int(run["single_pull"])) if "single_pull" in run else False,
            "level": level(run["fit_E0_ci_low"].attrs),
            "channels": _channel_rows(run),
            "warnings": "; ".join([*lines(run.attrs.get("warnings", "")),
                                   *lines(run.attrs.get("ingest_warnings", ""))]),
            "curve_svg": svg(stiffness_figures.force_strain(run)),
            "residual_svg": svg(stiffness_figures.fit_residuals(run)),
            "fits": _fit_rows(run),
        } for run in tensile],
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


def _impact(summary: xr.Dataset, runs: Sequence[RunFile]) -> dict[str, Any]:
    """Figures and tables of the impact section."""
    by_id = {run.run_id: run for run in runs if run.kind == "engagement"}
    zoomed = next((by_id[str(point)] for point in summary["operating_point"].values
                   if str(point) in by_id), None)
    figures, k_theory = [], f"{float(recorded(summary.attrs, 'k_theory')):g}"
    with report_style():
        if zoomed is not None:
            figures.append({"caption": f"Run {zoomed.run_id}: a stretch of the branch-tension "
                                       "log with the detected impacts marked.",
                            "svg": svg(impact_figures.impact_zoom(zoomed.load()))})
        figures.append({"caption": "Measured impact tensions against wheel speed, with the "
                                   f"model for k = {k_theory} and for the fitted k.",
                        "svg": svg(impact_figures.impact_vs_omega(summary))})
        figures.append({"caption": "Impact tensions against the tooth apex angle, per number "
                                   "of teeth (as Paper 000, figures 3 and 4).",
                        "svg": svg(impact_figures.impact_vs_apex(summary))})
    k = {name: float(summary[name]) for name in
         ("k_fit", "k_fit_stderr", "k_fit_ci_low", "k_fit_ci_high", "k_fit_chi2_reduced")}
    comparison = sorted({str(run.attrs.get("comparison", "")) for run in by_id.values()} - {""})
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
    with report_style():
        return [{"title": title, "svg": svg(figure)}
                for title, figure in design_figures.design_checks(summary)]


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


def report_context(summary: xr.Dataset, runs: Sequence[RunFile], created: datetime
                   ) -> dict[str, Any]:
    """Everything the template shows, as strings, lists and dicts (figures as SVG).

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign's ``summary.nc``.
    runs : sequence of RunFile
        Its run files (:func:`campaign_runs`).
    created : datetime
        Creation time of the report.

    Returns
    -------
    dict
        ``campaign``, ``checks``, ``notes``, ``stiffness`` (or None),
        ``impact`` (or None), ``design``, ``not_reproduced``, ``provenance``.
    """
    notes = [line for line in str(summary.attrs.get("notes", "")).split("\n") if line]
    return {
        "campaign": _campaign(summary, created),
        "checks": _checks(summary, runs),
        "notes": notes,
        "stiffness": _stiffness(summary, runs) if _has(summary, "chain") else None,
        "impact": _impact(summary, runs) if _has(summary, "operating_point") else None,
        "design": _design(summary),
        "not_reproduced": _not_reproduced(),
        "provenance": _provenance(summary, runs),
    }


def environment() -> jinja2.Environment:
    """The jinja2 environment of the report: package templates, autoescape on."""
    return jinja2.Environment(
        loader=jinja2.PackageLoader("pipeline.report", "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
    )


def build_report(output_dir: str | Path, created: datetime | None = None) -> Path:
    """Build ``report.html`` of a processed campaign from its processed files alone.

    Parameters
    ----------
    output_dir : str or Path
        The processed campaign folder (``processed/<campaign>``) holding
        ``summary.nc`` and the run files.
    created : datetime, optional
        Creation time written in the report (default: now, UTC); with the same
        folder and the same `created` the report is the same, byte for byte.

    Returns
    -------
    Path
        The report written (atomically) into `output_dir`.

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
    runs = campaign_runs(output_dir, summary)
    context = report_context(summary, runs, created or datetime.now(UTC))
    html = environment().get_template(TEMPLATE_NAME).render(**context)
    return write_text_atomic(html, output_dir / layout.REPORT)
