"""The ``wear_run`` table of a campaign summary: per wear run, measured, model and checks.

One row per wear run (labels: run ids), built from its result
(:class:`~pipeline.results.wear.WearResult`, read back from its run file):

measured
    ``wear_readings``, the running time (or cycles) of the last reading
    ``wear_log_end``, the pitch growth by wear over the log
    ``wear_growth_measured`` [m] and the last reading's elongation over the
    pitch ``wear_elongation_last`` [1];
model
    the wear model (``wear_model``), its steady wear rate ``wear_rate`` with
    its standard error and interval, ``wear_offset`` and ``wear_run_in`` [m],
    and per limit (``eq3``: Paper 004's eq. (3) for the sprocket; ``lab``: the
    lab's own) the limit ``limit_<limit>`` [m] and the life to it
    ``life_<limit>`` with its interval; Paper 004's allowed pitch growth and
    pin wear, critical and required pin diameters (``pin_*`` [m]) and the pin
    wear the measured growth implies;
checks
    ``wear_significant`` (the wear rate's interval above 0), ``pin_passes``
    (eq. (1)), ``pin_within_<limit>`` (the pin wear at the limit within the
    allowed delta_d) and ``lab_limit_within_eq3`` (the lab's limit below the
    jump-off limit of eq. (3)): 1 yes, 0 no, -1 not evaluated.

A value counted over the running coordinate (lives, rates, the log's end, the
run-in time constant) is named as above for a log over time [s, m/s], and with
``_cycles`` after its stem for a log over cycles [1, m per cycle]
(``life_eq3_cycles_ci_low``): the units of one variable never mix.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import xarray as xr

from pipeline.results.wear import LIMITS, RUNNING_UNITS, WearResult
from pipeline.summary_rows import table_dataset

#: Suffix of the stem of a value counted over the running coordinate, by abscissa.
RUNNING_SUFFIX = {"time": "", "cycles": "_cycles"}

#: The texts of a row.
TEXTS = {
    "wear_chain": "chain of the wear run (run-sheet key)",
    "wear_abscissa": "running coordinate of the log: time or cycles",
    "wear_reference": "what the elongation is counted from: nominal pitch or first reading",
    "wear_model": "wear model fitted: run-in or linear",
}

#: The numbers of a row not counted over the running coordinate: units and long names.
NUMBERS = {
    "wear_teeth": ("1", "teeth z of the driven sprocket"),
    "wear_pitch": ("m", "nominal pitch t of the chain"),
    "wear_section_pitches": ("1", "pitches N of the measured section"),
    "wear_readings": ("1", "readings of the log"),
    "wear_growth_measured": ("m", "pitch growth by wear over the log (fitted, less delta_t0)"),
    "wear_elongation_last": ("1", "measured delta_t / t of the last reading"),
    "wear_offset": ("m", "fitted elongation per pitch at the start, delta_t0"),
    "wear_run_in": ("m", "run-in elongation per pitch A (NaN: linear model)"),
    **{f"limit_{limit}": ("m", f"limit of delta_t: {text}") for limit, text in
       (("eq3", "Paper 004, eq. (3), for the sprocket"), ("lab", "the lab's own"))},
    **{f"limit_{limit}_relative": ("1", f"limit of delta_t over the pitch ({limit})")
       for limit in LIMITS},
    "pin_allowed_growth": ("m", "allowed pitch growth delta_t1, Paper 004 eq. (3)"),
    "pin_allowed_wear": ("m", "allowed pin wear delta_d, Paper 004 eq. (2)"),
    "pin_critical_diameter": ("m", "critical pin diameter d_k, Paper 004 eq. (5)"),
    "pin_required_diameter": ("m", "required pin diameter d_k + delta_d, eq. (1)"),
    "pin_diameter": ("m", "nominal pin diameter d"),
    "pin_wear_coefficient": ("1", "pin wear coefficient K_e"),
    "pin_wear_measured": ("m", "pin wear the pitch growth over the log implies, eq. (2)"),
    "pin_wear_share": ("1", "pin wear over the log over the allowed pin wear delta_d"),
}

#: The checks of a row: 1 yes, 0 no, -1 not evaluated.
CHECKS = {
    "wear_significant": "the interval of the wear rate lies above 0",
    "pin_passes": "the pin satisfies d >= d_k + delta_d (Paper 004, eq. (1))",
    **{f"pin_within_{limit}": f"the pin wear at the {limit} limit is within delta_d"
       for limit in LIMITS},
    "lab_limit_within_eq3": "the lab's limit lies at or below the limit of eq. (3)",
}

#: Stems counted over the running coordinate: the key of their units in
#: :data:`~pipeline.results.wear.RUNNING_UNITS`, their long name, and their statistics.
RUNNING = {
    "wear_log_end": ("tau", "running time (or cycles) of the last reading", ("",)),
    "wear_rate": ("rate", "steady wear rate per pitch",
                  ("", "_stderr", "_ci_low", "_ci_high")),
    "wear_run_in_time": ("tau", "run-in time constant tau0 (NaN: linear model)", ("",)),
    **{f"life_{limit}": ("tau", f"life to the {limit} limit", ("", "_ci_low", "_ci_high"))
       for limit in LIMITS},
}

#: What a statistic's suffix adds to the long name.
_STATISTICS = {"": "", "_stderr": ", standard error",
               "_ci_low": ", lower limit of the {level} interval",
               "_ci_high": ", upper limit of the {level} interval"}


def running_name(stem: str, abscissa: str, statistic: str = "") -> str:
    """The summary name of `stem` (a key of :data:`RUNNING`) for a log over `abscissa`.

    Examples
    --------
    >>> running_name("life_eq3", "time", "_ci_low"), running_name("wear_rate", "cycles")
    ('life_eq3_ci_low', 'wear_rate_cycles')
    """
    return f"{stem}{RUNNING_SUFFIX[abscissa]}{statistic}"


def variables() -> dict[str, tuple[str, str]]:
    """Every numeric variable of the ``wear_run`` table: units and long name."""
    found = dict(NUMBERS)
    found.update({name: ("1", text) for name, text in CHECKS.items()})
    for abscissa, units in RUNNING_UNITS.items():
        for stem, (unit, text, statistics) in RUNNING.items():
            for statistic in statistics:
                found[running_name(stem, abscissa, statistic)] = (
                    units[unit], f"{text} ({abscissa}){_STATISTICS[statistic]}")
    return found


def wear_row(result: WearResult) -> dict[str, Any]:
    """A wear run's row of the ``wear_run`` table (SI; module docstring)."""
    fit, pin, limits, attrs = result.fit, result.pin, result.limits, result.attrs
    abscissa = result.abscissa
    row: dict[str, Any] = {
        "wear_chain": str(attrs["chain"]), "wear_abscissa": abscissa,
        "wear_reference": str(attrs["reference"]), "wear_model": str(attrs["model"]),
        "wear_teeth": float(attrs["sprocket_teeth"]), "wear_pitch": float(attrs["pitch"]),
        "wear_section_pitches": float(attrs["section_pitches"]),
        "wear_readings": float(len(result.readings)),
        "wear_growth_measured": fit["growth_measured"],
        "wear_elongation_last": float(result.readings["relative_elongation"].iloc[-1]),
        "wear_offset": fit["offset"], "wear_run_in": fit["run_in"],
        "wear_significant": float(fit["wear_rate_ci_low"] > 0),
        "pin_passes": pin["pin_passes"],
        **{name: pin[name] for name in NUMBERS if name.startswith("pin_")},
        running_name("wear_log_end", abscissa): fit["tau_end"],
        running_name("wear_run_in_time", abscissa): fit["run_in_time"],
    }
    for statistic in RUNNING["wear_rate"][2]:
        row[running_name("wear_rate", abscissa, statistic)] = fit[f"wear_rate{statistic}"]
    for limit in LIMITS:
        found = limit in limits.index
        values = limits.loc[limit] if found else {}
        row[f"limit_{limit}"] = float(values["limit_elongation"]) if found else math.nan
        row[f"limit_{limit}_relative"] = float(values["limit_relative"]) if found else math.nan
        row[f"pin_within_{limit}"] = float(values["limit_pin_within"]) if found else -1.0
        for statistic in RUNNING[f"life_{limit}"][2]:
            row[running_name(f"life_{limit}", abscissa, statistic)] = (
                float(values[f"life{statistic}"]) if found else math.nan)
    lab, eq3 = row["limit_lab"], row["limit_eq3"]
    row["lab_limit_within_eq3"] = -1.0 if math.isnan(lab) else float(lab <= eq3)
    return row


def wear_summary(rows: Mapping[str, Mapping[str, Any]], confidence: float) -> xr.Dataset:
    """The ``wear_run`` table of a campaign summary.

    Parameters
    ----------
    rows : mapping
        Run id -> its row (:func:`wear_row`).
    confidence : float
        Level of the intervals [1] (recorded on every interval limit).

    Returns
    -------
    xarray.Dataset
        On dimension ``wear_run`` (labels: run ids): the texts of :data:`TEXTS`,
        then every variable of :func:`variables` some row has (NaN where a row
        lacks it: a log over cycles has no life in seconds); checks as int8.
    """
    numbers = {name: value for name, value in variables().items()
               if any(name in row for row in rows.values())}
    return table_dataset("wear_run", rows, TEXTS, numbers, CHECKS, confidence)
