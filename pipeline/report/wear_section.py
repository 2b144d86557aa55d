"""The report's wear section: the campaign page's tables and checks, and a wear run's page.

Wear runs are the campaign's measured results against Paper 004: the measured
pitch growth and its fitted wear rate (with its interval) beside the model's
allowed growth (eq. (3), for the run's sprocket) and the lab's own limit, the
predicted life to each with its interval, and the pin criterion (eqs.
(1)-(5)) with the pin wear the measured growth implies (eq. (2)). Every
number is read from ``summary.nc`` (its ``wear_run`` table,
:mod:`pipeline.wear_summary`) or from the run file
(:mod:`pipeline.results.wear`); only units change here: elongations in mm and
in % of the pitch, running times in hours, cycles in millions.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

import xarray as xr

from pipeline.report import wear_figures
from pipeline.report.formatting import (
    MISSING,
    interval,
    natural_key,
    number,
    percent,
    plain_number,
    verdict_class,
)
from pipeline.report.recorded import level, recorded
from pipeline.report.render import svg
from pipeline.wear_summary import LIMITS, running_name

#: How values counted over the running coordinate are shown, by abscissa: SI per unit
#: shown and the unit, for a life and for a rate.
SHOWN = {"time": {"life": (3600.0, "h"), "rate": (1e-6 / 3600.0, "µm/h")},
         "cycles": {"life": (1e6, "·10⁶ cycles"), "rate": (1e-12, "µm per 10⁶ cycles")}}

#: What each limit is called in the tables.
LIMIT_NAMES = {"eq3": "jump-off, eq. (3)", "lab": "lab's limit"}

#: A check's value (1, 0, -1) as result and CSS class.
_CHECK = {1: ("yes", "pass"), 0: ("no", "fail"), -1: ("not evaluated", "info")}


def _shown(value: float, abscissa: str, what: str, digits: int = 4) -> str:
    """A life or a rate [SI] in the units it is shown in, with its unit."""
    scale, unit = SHOWN[abscissa][what]
    shown = number(float(value) / scale, digits)
    return shown if shown == MISSING else f"{shown} {unit}"


def _shown_interval(low: float, high: float, abscissa: str, what: str, digits: int = 4) -> str:
    scale, unit = SHOWN[abscissa][what]
    text = interval(float(low) / scale, float(high) / scale, lambda v: number(v, digits))
    return text if text == MISSING else f"{text} {unit}"


def _mm(value: float, digits: int = 4) -> str:
    """A length [m] in mm."""
    shown = number(float(value) * 1e3, digits)
    return shown if shown == MISSING else f"{shown} mm"


def _um(value: float) -> str:
    """A length [m] in µm."""
    shown = number(float(value) * 1e6, 3)
    return shown if shown == MISSING else f"{shown} µm"


def _check(value: float) -> tuple[str, str]:
    return _CHECK[int(value)]


def _runs(summary: xr.Dataset) -> list[str]:
    """The wear runs of the summary, by chain, then in natural order of ids."""
    runs = [str(run) for run in summary["wear_run"].values]
    chains = dict(zip(runs, summary["wear_chain"].values.astype(str), strict=True))
    return sorted(runs, key=lambda run: (chains[run], natural_key(run)))


def _life_cells(row: xr.Dataset, abscissa: str, limit: str) -> dict[str, str]:
    name = running_name(f"life_{limit}", abscissa)
    return {"limit": f"{_mm(row[f'limit_{limit}'])} ({percent(row[f'limit_{limit}_relative'])})",
            "life": _shown(row[name], abscissa, "life"),
            "interval": _shown_interval(row[f"{name}_ci_low"], row[f"{name}_ci_high"],
                                        abscissa, "life")}


def life_rows(summary: xr.Dataset) -> list[dict[str, Any]]:
    """The life table per chain: one row per wear run, measured against model."""
    rows = []
    for run in _runs(summary):
        row = summary.sel(wear_run=run)
        abscissa = str(row["wear_abscissa"].values)
        rate = running_name("wear_rate", abscissa)
        rows.append({
            "chain": str(row["wear_chain"].values), "run": run,
            "z": plain_number(row["wear_teeth"]), "model": str(row["wear_model"].values),
            "reference": str(row["wear_reference"].values),
            "readings": plain_number(row["wear_readings"]),
            "log_end": _shown(row[running_name("wear_log_end", abscissa)], abscissa, "life"),
            "growth": f"{_mm(row['wear_growth_measured'], 3)} "
                      f"({percent(float(row['wear_growth_measured']) / float(row['wear_pitch']))})",
            "rate": _shown(row[rate], abscissa, "rate", 3),
            "rate_interval": _shown_interval(row[f"{rate}_ci_low"], row[f"{rate}_ci_high"],
                                             abscissa, "rate", 3),
            "limits": [{"name": LIMIT_NAMES[limit], **_life_cells(row, abscissa, limit)}
                       for limit in LIMITS if math.isfinite(float(row[f"limit_{limit}"]))],
        })
    return rows


def pin_rows(summary: xr.Dataset) -> list[dict[str, str]]:
    """The pin criterion per wear run that asks for it: the terms, the verdict, the wear."""
    rows = []
    for run in _runs(summary):
        row = summary.sel(wear_run=run)
        if int(row["pin_passes"]) < 0:
            continue
        verdict, status = ("passes", "pass") if int(row["pin_passes"]) else ("fails", "fail")
        within = {limit: _check(row[f"pin_within_{limit}"])[0] for limit in LIMITS}
        rows.append({
            "chain": str(row["wear_chain"].values), "run": run,
            "z": plain_number(row["wear_teeth"]),
            "k_e": plain_number(row["pin_wear_coefficient"]),
            "d": _mm(row["pin_diameter"]), "d_k": _mm(row["pin_critical_diameter"]),
            "allowed_growth": _mm(row["pin_allowed_growth"]),
            "allowed_wear": _mm(row["pin_allowed_wear"]),
            "required": _mm(row["pin_required_diameter"]), "verdict": verdict,
            "status": status, "measured": _um(row["pin_wear_measured"]),
            "share": percent(row["pin_wear_share"], 1),
            "within": "; ".join(f"{LIMIT_NAMES[limit]}: {within[limit]}" for limit in LIMITS
                                if math.isfinite(float(row[f"limit_{limit}"]))),
        })
    return rows


def wear_checks(summary: xr.Dataset) -> Iterable[dict[str, str]]:
    """The checks of the wear runs, for the campaign page's table of checks."""
    for run in _runs(summary):
        row = summary.sel(wear_run=run)
        abscissa = str(row["wear_abscissa"].values)
        rate = running_name("wear_rate", abscissa)
        result, status = _check(row["wear_significant"])
        spread = _shown_interval(row[f"{rate}_ci_low"], row[f"{rate}_ci_high"], abscissa,
                                 "rate", 3)
        yield {"check": f"run {run}: wear measured (interval of the wear rate above 0)",
               "result": result, "status": status,
               "detail": f"w = {_shown(row[rate], abscissa, 'rate', 3)} ({spread})"}
        if int(row["pin_passes"]) >= 0:
            passed = bool(int(row["pin_passes"]))
            yield {"check": f"run {run}: pin criterion d ≥ d_k + Δd (Paper 004, eq. (1))",
                   "result": "pass" if passed else "fail", "status": verdict_class(passed),
                   "detail": f"d = {_mm(row['pin_diameter'])}, d_k + Δd = "
                             f"{_mm(row['pin_required_diameter'])}"}
        if int(row["lab_limit_within_eq3"]) >= 0:
            result, status = _check(row["lab_limit_within_eq3"])
            yield {"check": f"run {run}: the lab's limit below the jump-off growth of eq. (3)",
                   "result": result, "status": status,
                   "detail": f"{percent(row['limit_lab_relative'])} against "
                             f"{percent(row['limit_eq3_relative'])} of the pitch"}


def tested(summary: xr.Dataset) -> str:
    """What the wear runs tested, as a phrase."""
    chains = sorted(set(summary["wear_chain"].values.astype(str)))
    return (f"wear tests of {summary.sizes['wear_run']} run(s) of {len(chains)} roller "
            "chain(s) for their wear rate and life (Paper 004)")


def wear_level(summary: xr.Dataset) -> str:
    """The confidence level of the wear table's intervals, as text (``"95 %"``)."""
    name = next(name for name in summary.data_vars
                if name.startswith("wear_rate") and name.endswith("_ci_low"))
    return level(summary[name].attrs)


def wear_section(summary: xr.Dataset, overview: str) -> dict[str, Any]:
    """What the campaign page's wear section shows (the overview figure rendered)."""
    return {"overview_svg": overview, "runs": life_rows(summary), "pins": pin_rows(summary),
            "level": wear_level(summary)}


def wear_settings(runs: Iterable[Any]) -> list[tuple[str, str]]:
    """The settings the wear run files record, for the provenance table."""
    choices = {run.run_id: f"{recorded(run.attrs, 'model')} model "
                           f"({recorded(run.attrs, 'model_choice')})" for run in runs}
    return [("wear model", "; ".join(f"{run}: {text}" for run, text in choices.items())
             or MISSING),
            ("wear limits", "Paper 004, eq. (3): ψ = 0.8, Δt_n = 0.004 t (a log counted "
                            "from its first reading), or the jump-off pitch error 2.5 ψ t / z "
                            "(a log counted from the nominal pitch); the lab's limit as "
                            "declared")]


def _limit_rows(run: xr.Dataset) -> list[dict[str, str]]:
    abscissa = str(recorded(run.attrs, "abscissa"))
    rows = []
    for name in run["limit"].values.astype(str):
        limit = run.sel(limit=name)
        within = int(limit["limit_pin_within"])
        rows.append({
            "name": LIMIT_NAMES[name], "source": str(limit["limit_source"].values),
            "limit": f"{_mm(limit['limit_elongation'])} ({percent(limit['limit_relative'])})",
            "life": _shown(limit["life"], abscissa, "life"),
            "interval": _shown_interval(limit["life_ci_low"], limit["life_ci_high"], abscissa,
                                        "life"),
            "note": str(limit["life_note"].values) or "",
            "growth": _mm(limit["limit_growth"]), "pin_wear": _um(limit["limit_pin_wear"]),
            "within": _CHECK[within][0], "status": _CHECK[within][1]})
    return rows


def wear_run_page(run: xr.Dataset) -> dict[str, Any]:
    """What a wear run's page shows besides its status and raw file."""
    attrs = run.attrs
    abscissa = str(recorded(attrs, "abscissa"))
    pin = {name: run[name] for name in run.data_vars if name.startswith("pin_")}
    logged = {name: number(run[name].mean(), 4) for name in ("load", "speed") if name in run}
    return {
        "figure_svg": svg(wear_figures.wear_run(run)),
        "level": level(run["wear_rate_ci_low"].attrs),
        "abscissa": abscissa, "channel": str(recorded(attrs, "channel")),
        "reference": str(recorded(attrs, "reference")),
        "pitches": str(recorded(attrs, "section_pitches")),
        "pitch": _mm(recorded(attrs, "pitch")), "teeth": str(recorded(attrs, "sprocket_teeth")),
        "readings": str(run.sizes["reading"]),
        "model": str(recorded(attrs, "model")), "choice": str(recorded(attrs, "model_choice")),
        "rate": _shown(run["wear_rate"], abscissa, "rate", 3),
        "rate_interval": _shown_interval(run["wear_rate_ci_low"], run["wear_rate_ci_high"],
                                         abscissa, "rate", 3),
        "rate_stderr": _shown(run["wear_rate_stderr"], abscissa, "rate", 2),
        "offset": _um(run["offset"]), "offset_stderr": _um(run["offset_stderr"]),
        "run_in": _um(run["run_in"]), "run_in_time": _shown(run["run_in_time"], abscissa, "life"),
        "dof": plain_number(run["dof"]), "growth": _mm(run["growth_measured"], 3),
        "load": f"{logged['load']} N (mean)" if "load" in logged else MISSING,
        "speed": f"{logged['speed']} m/s (mean)" if "speed" in logged else MISSING,
        "limits": _limit_rows(run),
        "pin_evaluated": int(pin["pin_passes"]) >= 0,
        "pin_note": str(recorded(attrs, "pin_criterion")),
        "pin": {"force": number(float(pin["pin_force"]) / 1e3, 4) + " kN",
                "stress": number(float(pin["pin_allowable_stress"]) / 1e6, 4) + " MPa",
                "K": plain_number(pin["pin_support_factor"]),
                "K_e": plain_number(pin["pin_wear_coefficient"]),
                "d": _mm(pin["pin_diameter"]), "d_k": _mm(pin["pin_critical_diameter"]),
                "allowed_growth": _mm(pin["pin_allowed_growth"]),
                "allowed_wear": _mm(pin["pin_allowed_wear"]),
                "required": _mm(pin["pin_required_diameter"]),
                "verdict": _CHECK[int(pin["pin_passes"])][0],
                "status": _CHECK[int(pin["pin_passes"])][1],
                "measured": _um(pin["pin_wear_measured"]),
                "share": percent(pin["pin_wear_share"], 1)},
    }


def run_numbers(summary: xr.Dataset, run_id: str) -> str:
    """A wear run's key values for the run table: its wear rate and its life to eq. (3)."""
    if not summary.sizes.get("wear_run", 0) or run_id not in summary.indexes["wear_run"]:
        return MISSING
    row = summary.sel(wear_run=run_id)
    abscissa = str(row["wear_abscissa"].values)
    return (f"w = {_shown(row[running_name('wear_rate', abscissa)], abscissa, 'rate', 3)}, "
            f"life to eq. (3) = "
            f"{_shown(row[running_name('life_eq3', abscissa)], abscissa, 'life')}")
