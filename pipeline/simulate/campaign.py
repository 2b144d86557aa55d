"""Write synthetic campaigns: logs from the virtual benches, a run sheet and the truth.

A campaign folder written here is what a lab would hand over: the logs, one a
run, in the layouts and units each run asks for, and the run sheet
``campaign.toml`` (marked ``synthetic = true``, with a note saying where the
data come from). Beside them ``truth.json`` keeps the true values each log was
made from; the run sheet never refers to it, so the folder processes like any
other.

:func:`write_tensile_campaign` writes cyclic tensile runs (:class:`TensileRunSpec`),
:func:`write_pull_campaign` single pulls and proof-load tests (:class:`PullRunSpec`),
:func:`write_engagement_campaign` engagement runs (:class:`EngagementRunSpec`),
:func:`write_wear_campaign` wear tests (:class:`WearRunSpec`);
``chainbench simulate`` and :mod:`pipeline.simulate.demo` both go through them.
Run sheets are written as TOML text by a small writer: strings are quoted with
:func:`json.dumps`, whose escapes TOML basic strings accept.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from pipeline.catalog import chain as catalog_chain
from pipeline.fit.wear import pitch_growth_limit
from pipeline.runsheet import RUN_SHEET_NAME, SAFE_ID
from pipeline.simulate.engagement import (
    EngagementSettings,
    simulate_engagement,
    write_engagement_csv,
    write_engagement_tdms,
)
from pipeline.simulate.export import (
    EUROPEAN_ENCODINGS,
    FORCE_UNITS,
    LAYOUTS,
    LENGTH_UNITS,
    PULL_LANGUAGES,
    TIME_UNITS,
    WEAR_LAYOUTS,
    write_pull_table,
    write_table,
    write_wear_table,
)
from pipeline.simulate.pull import PullTruth, simulate_pull
from pipeline.simulate.tensile import TensileTruth, simulate_tensile
from pipeline.simulate.wear import WearTruth, simulate_wear
from pipeline.store.netcdf import write_text_atomic
from pipeline.units import from_si

#: Name of the file holding the true values beside the run sheet.
TRUTH_NAME = "truth.json"

#: File formats of engagement logs, and their writers.
ENGAGEMENT_WRITERS = {"csv": write_engagement_csv, "tdms": write_engagement_tdms}

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")


@dataclass(frozen=True)
class CampaignSpec:
    """The ``[campaign]`` table of a synthetic campaign.

    Parameters
    ----------
    id : str
        Campaign id (letters, digits, ``.``, ``_`` and ``-``: it names folders).
    title, lab, machine : str
        As in the run sheet.
    note : str
        Where the data come from; the run sheet also gets ``synthetic = true``.
    """

    id: str
    title: str = ""
    lab: str = ""
    machine: str = ""
    note: str = "Synthetic data from the chainbench virtual test bench."

    def __post_init__(self) -> None:
        if not re.fullmatch(SAFE_ID, self.id):
            raise ValueError(
                f"campaign id {self.id!r}: use letters, digits, '.', '_' and '-' only"
            )


@dataclass(frozen=True)
class TensileRunSpec:
    """One tensile run to simulate and write.

    Parameters
    ----------
    id : str
        Run id in the run sheet.
    chain : str
        Catalogue chain (e.g. ``"18x64"``); its run-sheet key is :func:`chain_key`.
    specimen : str
        Specimen label.
    truth : TensileTruth
        The run's settings and true properties.
    seed : int
        Seed of the log's noise.
    file : str
        File name in the campaign folder.
    layout, force_unit, length_unit, encoding, preamble, language
        How the log is written (:func:`pipeline.simulate.export.write_table`).
    """

    id: str
    chain: str
    specimen: str
    truth: TensileTruth
    seed: int
    file: str
    layout: str = "plain"
    force_unit: str = "kN"
    length_unit: str = "mm"
    encoding: str | None = None
    preamble: tuple[tuple[str, str], ...] = ()
    language: str = "pl"

    def __post_init__(self) -> None:
        check_run(self.id, self.file)
        for name, value, allowed in (("layout", self.layout, LAYOUTS),
                                     ("force_unit", self.force_unit, FORCE_UNITS),
                                     ("length_unit", self.length_unit, LENGTH_UNITS),
                                     ("language", self.language, self._languages())):
            if value not in allowed:
                raise ValueError(f"run {self.id}: {name} must be one of "
                                 f"{', '.join(map(str, allowed))}, got {value!r}")

    def _languages(self) -> tuple[str | None, ...]:
        return tuple(EUROPEAN_ENCODINGS)


@dataclass(frozen=True)
class PullRunSpec(TensileRunSpec):
    """One single pull (or proof-load test) to simulate and write.

    Parameters
    ----------
    id, chain, specimen, seed, file
        As in :class:`TensileRunSpec`.
    truth : PullTruth
        The test's settings and true properties.
    layout, force_unit, length_unit, encoding, preamble, language, quote
        How the log is written (:func:`pipeline.simulate.export.write_pull_table`;
        `language` None: the layout's default).
    crosshead : bool
        Write the crosshead channel.
    """

    truth: PullTruth
    language: str | None = None
    quote: bool = False
    crosshead: bool = True

    def _languages(self) -> tuple[str | None, ...]:
        return (None, *PULL_LANGUAGES[self.layout]) if self.layout in LAYOUTS else ()


@dataclass(frozen=True)
class EngagementRunSpec:
    """One engagement run to simulate and write.

    Parameters
    ----------
    id : str
        Run id in the run sheet.
    chain : str
        Catalogue chain (e.g. ``"18x64"``); `settings` should carry its geometry
        (see :func:`engagement_settings`).
    settings : EngagementSettings
        Operating point, branch and measurement.
    seed : int
        Seed of the log's randomness.
    file : str
        File name in the campaign folder.
    format : str
        ``"csv"`` or ``"tdms"`` (:data:`ENGAGEMENT_WRITERS`).
    """

    id: str
    chain: str
    settings: EngagementSettings
    seed: int
    file: str
    format: str = "tdms"

    def __post_init__(self) -> None:
        check_run(self.id, self.file)
        if self.format not in ENGAGEMENT_WRITERS:
            raise ValueError(f"run {self.id}: format must be one of "
                             f"{', '.join(ENGAGEMENT_WRITERS)}, got {self.format!r}")

    @property
    def wheel(self) -> str:
        """Run-sheet key of the wheel: ``w<teeth>_<apex angle in deg>``."""
        return wheel_key(self.settings.z, math.degrees(self.settings.psi))


#: Running coordinates a wear log may be written with: time, cycles, or both.
WEAR_ABSCISSAE = ("time", "cycles", "both")


@dataclass(frozen=True)
class WearRunSpec:
    """One wear test to simulate and write.

    Parameters
    ----------
    id : str
        Run id in the run sheet.
    chain : str
        Catalogue roller chain (e.g. ``"16B"``); `truth` should carry its pitch.
    truth : WearTruth
        The test's settings and true wear.
    seed : int
        Seed of the log's noise.
    file : str
        File name in the campaign folder.
    teeth : int
        Teeth z of the driven sprocket (``sprocket_teeth``, Paper 004, eq. (3)).
    reference : {"nominal", "first"}
        ``elongation_reference`` of the run sheet.
    limit_pct : float, optional
        The lab's limit ``wear_limit_pct`` [% of the pitch].
    abscissa : {"time", "cycles", "both"}
        The running columns written; with both, the run sheet says
        ``wear_abscissa = "time"``.
    layout, time_unit, length_unit, force_unit, language
        How the log is written (:func:`pipeline.simulate.export.write_wear_table`).
    pin : mapping, optional
        The run-sheet keys of Paper 004's pin criterion (``max_link_force_kN``,
        ``pin_allowable_stress_MPa``, ``pin_wear_coefficient``, ``pin_support``).
    """

    id: str
    chain: str
    truth: WearTruth
    seed: int
    file: str
    teeth: int
    reference: str = "nominal"
    limit_pct: float | None = None
    abscissa: str = "time"
    layout: str = "plain"
    time_unit: str = "h"
    length_unit: str = "mm"
    force_unit: str = "kN"
    language: str = "pl"
    pin: Mapping[str, float | str] | None = None

    def __post_init__(self) -> None:
        check_run(self.id, self.file)
        for name, value, allowed in (("layout", self.layout, WEAR_LAYOUTS),
                                     ("abscissa", self.abscissa, WEAR_ABSCISSAE),
                                     ("time_unit", self.time_unit, TIME_UNITS),
                                     ("length_unit", self.length_unit, LENGTH_UNITS),
                                     ("force_unit", self.force_unit, FORCE_UNITS),
                                     ("language", self.language, tuple(EUROPEAN_ENCODINGS))):
            if value not in allowed:
                raise ValueError(f"run {self.id}: {name} must be one of "
                                 f"{', '.join(map(str, allowed))}, got {value!r}")

    def entry(self) -> dict[str, str | bool | int | float]:
        """The run's ``[[runs]]`` entry of the run sheet."""
        entry = {"id": self.id, "kind": "wear", "file": self.file,
                 "chain": chain_key(self.chain), "section_pitches": self.truth.pitches,
                 "elongation_reference": self.reference, "sprocket_teeth": self.teeth}
        if self.limit_pct is not None:
            entry["wear_limit_pct"] = float(self.limit_pct)
        if self.abscissa == "both":
            entry["wear_abscissa"] = "time"
        return {**entry, **(self.pin or {})}

    def true_lives(self) -> dict[str, float]:
        """The true limits and lives of the run (``limit_<limit>_m``, ``life_<limit>_s``,
        ``life_<limit>_cycles``).

        The limits are Paper 004's eq. (3) and the lab's
        (:func:`pipeline.fit.wear.pitch_growth_limit`), counted as the log counts
        delta_t: from the nominal pitch, or from the first reading (whose true
        elongation, at tau = 0, is added back to find the true life).
        """
        origin = float(self.truth.elongation(0.0)) if self.reference == "first" else 0.0
        limits: dict[str, dict[str, float]] = {"eq3": {"teeth": self.teeth}}
        if self.limit_pct is not None:
            limits["lab"] = {"limit_percent": self.limit_pct}
        lives = {}
        for name, limit in limits.items():
            value, _ = pitch_growth_limit(self.truth.pitch, self.reference, **limit)
            time = self.truth.time_to(value + origin)
            lives |= {f"limit_{name}_m": value, f"life_{name}_s": time,
                      f"life_{name}_cycles": self.truth.cycle_rate * time}
        return lives


def check_run(run_id: str, file: str) -> None:
    """Refuse a run id or file name a synthetic run sheet cannot hold.

    Parameters
    ----------
    run_id : str
        Run id [-]: letters, digits, ``.``, ``_`` and ``-`` only.
    file : str
        File name of the run's log [-]: a plain name in the campaign folder,
        neither the run sheet's nor ``truth.json``.

    Raises
    ------
    ValueError
        For an id or a file name that breaks these rules; the message says why.
    """
    if not re.fullmatch(SAFE_ID, run_id):
        raise ValueError(f"run id {run_id!r}: use letters, digits, '.', '_' and '-' only")
    if Path(file).name != file or file in (RUN_SHEET_NAME, TRUTH_NAME):
        raise ValueError(f"run {run_id}: file {file!r} must be a plain file name "
                         f"other than {RUN_SHEET_NAME} and {TRUTH_NAME}")


def chain_key(chain: str) -> str:
    """Run-sheet key of catalogue chain `chain`.

    Examples
    --------
    >>> chain_key("18x64")
    'c18x64'
    """
    return "c" + chain.replace(".", "_")


def wheel_key(teeth: int, apex_deg: float) -> str:
    """Run-sheet key of a wheel of `teeth` teeth and apex angle `apex_deg` [deg].

    Examples
    --------
    >>> wheel_key(8, 40.0), wheel_key(6, 22.5)
    ('w8_40', 'w6_22p5')
    """
    return f"w{teeth}_{round(apex_deg, 6):g}".replace(".", "p")


def engagement_settings(chain: str, **settings) -> EngagementSettings:
    """Engagement settings for catalogue chain `chain`: its pitch, bar and mass per metre.

    Parameters
    ----------
    chain : str
        Catalogue round-link chain with a mass per metre, e.g. ``"18x64"``.
    **settings
        Any other field of :class:`~pipeline.simulate.engagement.EngagementSettings`.

    Raises
    ------
    KeyError
        For a chain the catalogue does not have, or has no mass per metre for.
    ValueError
        For settings :class:`EngagementSettings` rejects.
    """
    spec = catalog_chain(chain)
    geometry = {"t": spec["t"], "d": spec["d"], "mass_per_length": spec["mass_per_length"]}
    return EngagementSettings(**geometry, **settings)


def _toml_value(value: str | bool | int | float) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if not math.isfinite(value):
            raise ValueError(f"a run sheet value must be finite, got {value!r}")
        return f"{value:.10g}"
    if isinstance(value, str):
        # JSON string escapes are TOML basic-string escapes; TOML also wants DEL escaped.
        return json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")
    raise TypeError(f"cannot write {type(value).__name__} {value!r} to a run sheet")


def toml_key(key: str) -> str:
    """`key` as a TOML key: bare when it can be, else quoted.

    Examples
    --------
    >>> toml_key("D34"), toml_key("z 18")
    ('D34', '"z 18"')
    """
    return key if _BARE_KEY.fullmatch(key) else _toml_value(key)


def toml_table(header: str, values: dict[str, str | bool | int | float]) -> list[str]:
    """Lines of a TOML table: a blank line, `header`, then one ``key = value`` each.

    Parameters
    ----------
    header : str
        The table's header line, e.g. ``"[drums.D34]"`` or ``"[[runs]]"``.
    values : dict
        Keys and values (strings, booleans, integers, finite floats).

    Returns
    -------
    list of str
        The lines, without line ends.

    Raises
    ------
    ValueError
        For a value that is not finite.

    Examples
    --------
    >>> toml_table("[drums.D34]", {"fitted": "s", "groove_width_mm": 45.0})
    ['', '[drums.D34]', 'fitted = "s"', 'groove_width_mm = 45']
    """
    return ["", header, *(f"{toml_key(key)} = {_toml_value(value)}"
                          for key, value in values.items())]


def run_sheet_text(
    campaign: CampaignSpec,
    chains: Iterable[str],
    runs: Sequence[dict[str, str | bool | int | float]],
    wheels: dict[str, tuple[int, float]] | None = None,
    chain_settings: Mapping[str, Mapping[str, float]] | None = None,
) -> str:
    """Text of the ``campaign.toml`` of a synthetic campaign.

    Parameters
    ----------
    campaign : CampaignSpec
        The ``[campaign]`` table (written with ``synthetic = true``).
    chains : iterable of str
        Catalogue chains, each written as ``[chains.<chain_key>]`` with ``catalog``.
    runs : sequence of dict
        The ``[[runs]]`` entries, in order.
    wheels : dict, optional
        Wheel key -> (teeth, apex angle [deg]), written as ``[wheels.<key>]``.
    chain_settings : mapping, optional
        Catalogue chain -> more keys of its table (acceptance limits such as
        ``min_breaking_force_kN``).

    Returns
    -------
    str
        TOML text (UTF-8 when written).

    Examples
    --------
    >>> text = run_sheet_text(CampaignSpec("demo"), ["18x64"], [{"id": "T1"}])
    >>> import tomllib; tomllib.loads(text)["campaign"]["synthetic"]
    True
    """
    info = {"id": campaign.id, "title": campaign.title, "lab": campaign.lab,
            "machine": campaign.machine, "synthetic": True, "note": campaign.note}
    lines = ["# Synthetic campaign written by chainbench's virtual test bench.",
             "[campaign]", *(f"{key} = {_toml_value(value)}" for key, value in info.items())]
    for chain in dict.fromkeys(chains):
        settings = {"catalog": chain, **(chain_settings or {}).get(chain, {})}
        lines += toml_table(f"[chains.{toml_key(chain_key(chain))}]", settings)
    for key, (teeth, apex_deg) in (wheels or {}).items():
        lines += toml_table(f"[wheels.{toml_key(key)}]",
                             {"teeth": teeth, "apex_angle_deg": float(apex_deg)})
    for run in runs:
        lines += toml_table("[[runs]]", run)
    return "\n".join(lines) + "\n"


def _check_unique(runs: Sequence[Any]) -> None:
    if not runs:
        raise ValueError("a campaign needs at least one run")
    for attribute in ("id", "file"):
        values = [getattr(run, attribute) for run in runs]
        duplicates = sorted({value for value in values if values.count(value) > 1})
        if duplicates:
            raise ValueError(f"duplicate run {attribute}(s): {', '.join(duplicates)}")


def _plain(value):
    """`value` with numpy arrays and scalars turned into JSON-ready Python values."""
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    if isinstance(value, np.ndarray | np.generic):
        return value.tolist()
    return value


def campaign_folder(out: str | Path, runs: Sequence[Any]) -> Path:
    """The campaign folder of a synthetic campaign, created, after checking its run list.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created with its parents when missing).
    runs : sequence
        Run specs of any kind, each with an ``id`` and a ``file``.

    Returns
    -------
    Path
        The folder.

    Raises
    ------
    ValueError
        For an empty run list, or run ids or files given twice.
    """
    _check_unique(runs)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    return out


def write_sheet_and_truth(out: Path, campaign: CampaignSpec, sheet_text: str,
                          truths: dict[str, dict]) -> Path:
    """Write a synthetic campaign's run sheet and its ``truth.json`` (both atomically).

    Parameters
    ----------
    out : Path
        Campaign folder.
    campaign : CampaignSpec
        The campaign; its id heads ``truth.json``.
    sheet_text : str
        Text of the run sheet (:func:`run_sheet_text` and more tables).
    truths : dict
        Run id -> what the run's truth is (SI; numpy values are made plain).

    Returns
    -------
    Path
        The run sheet written.
    """
    sheet = write_text_atomic(sheet_text, out / RUN_SHEET_NAME)
    document = {"campaign": campaign.id, "runs": truths}
    write_text_atomic(json.dumps(_plain(document), indent=2) + "\n", out / TRUTH_NAME)
    return sheet


def _log_truth(run: TensileRunSpec) -> dict:
    """What ``truth.json`` says of a tensile log: its file, how it is written, its truth."""
    return {"file": run.file, "chain": run.chain, "specimen": run.specimen,
            "layout": run.layout, "force_unit": run.force_unit,
            "length_unit": run.length_unit, "language": run.language,
            "encoding": run.encoding, "seed": run.seed, "truth": asdict(run.truth)}


def write_tensile_campaign(
    out: str | Path, runs: Sequence[TensileRunSpec], campaign: CampaignSpec
) -> Path:
    """Simulate and write a tensile campaign: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of TensileRunSpec
        The runs, in run-sheet order (unique ids and file names).
    campaign : CampaignSpec
        The ``[campaign]`` table.

    Returns
    -------
    Path
        The run sheet written. ``truth.json`` holds per run its file, chain,
        layout and units, seed, ``truth`` (the :class:`TensileTruth` fields, SI),
        ``permanent_set_m`` and ``hysteresis_energy_J`` per cycle.

    Raises
    ------
    ValueError
        For an empty or duplicated run list.
    """
    out = campaign_folder(out, runs)
    entries, truths = [], {}
    for run in runs:
        write_table(simulate_tensile(run.truth, run.seed), out / run.file, layout=run.layout,
                    force_unit=run.force_unit, length_unit=run.length_unit,
                    language=run.language, encoding=run.encoding, preamble=run.preamble)
        cycles = range(1, run.truth.n_cycles + 1)
        entries.append({
            "id": run.id, "kind": "tensile", "file": run.file, "chain": chain_key(run.chain),
            "specimen": run.specimen,
            "gauge_length_mm": float(from_si(run.truth.gauge_length, "mm")),
            "cycles": run.truth.n_cycles,
        })
        truths[run.id] = {
            **_log_truth(run),
            "permanent_set_m": [run.truth.permanent_set(k) for k in cycles],
            "hysteresis_energy_J": [run.truth.hysteresis_energy(k) for k in cycles],
        }
    text = run_sheet_text(campaign, [run.chain for run in runs], entries)
    return write_sheet_and_truth(out, campaign, text, truths)


def write_pull_campaign(
    out: str | Path,
    runs: Sequence[PullRunSpec],
    campaign: CampaignSpec,
    limits: Mapping[str, Mapping[str, float]] | None = None,
) -> Path:
    """Simulate and write single pulls and proof-load tests: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of PullRunSpec
        The runs, in run-sheet order (unique ids and file names).
    campaign : CampaignSpec
        The ``[campaign]`` table.
    limits : mapping, optional
        Catalogue chain -> acceptance limits written into its ``[chains.*]``
        table: ``proof_force_kN``, ``min_breaking_force_kN``,
        ``max_elongation_at_proof_pct``, ``min_elongation_at_fracture_pct``.

    Returns
    -------
    Path
        The run sheet written: per run ``cycles = 1``, ``gauge_length_mm``
        (unless the extensometer is written as a strain) and ``proof_force_kN``
        (with a proof load). ``truth.json`` holds per run its file, chain, how
        it is written, seed, ``truth`` (the :class:`PullTruth` fields, SI),
        ``crosshead``, ``quote`` and the true values of
        :meth:`PullTruth.summary` (``E0_N``, ``max_force_N``,
        ``offset_yield_force_N``, ``fracture_index``...).

    Raises
    ------
    ValueError
        For an empty or duplicated run list.
    """
    out = campaign_folder(out, runs)
    entries, truths = [], {}
    for run in runs:
        table = simulate_pull(run.truth, run.seed)
        write_pull_table(table if run.crosshead else table.drop(columns="crosshead"),
                         out / run.file, layout=run.layout, force_unit=run.force_unit,
                         length_unit=run.length_unit, language=run.language,
                         encoding=run.encoding, preamble=run.preamble, quote=run.quote)
        entry = {"id": run.id, "kind": "tensile", "file": run.file,
                 "chain": chain_key(run.chain), "specimen": run.specimen, "cycles": 1}
        if not run.truth.strain_channel:
            entry["gauge_length_mm"] = float(from_si(run.truth.gauge_length, "mm"))
        if run.truth.proof_force is not None:
            entry["proof_force_kN"] = float(from_si(run.truth.proof_force, "kN"))
        entries.append(entry)
        truths[run.id] = {**_log_truth(run), "crosshead": run.crosshead, "quote": run.quote,
                          **run.truth.summary()}
    text = run_sheet_text(campaign, [run.chain for run in runs], entries,
                          chain_settings=limits)
    return write_sheet_and_truth(out, campaign, text, truths)


def write_engagement_campaign(
    out: str | Path, runs: Sequence[EngagementRunSpec], campaign: CampaignSpec
) -> Path:
    """Simulate and write an engagement campaign: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of EngagementRunSpec
        The runs, in run-sheet order (unique ids and file names). Their wheels
        become ``[wheels.*]`` tables (:func:`wheel_key`).
    campaign : CampaignSpec
        The ``[campaign]`` table.

    Returns
    -------
    Path
        The run sheet written. ``truth.json`` holds per run its file, format,
        chain, seed and the truth of
        :func:`~pipeline.simulate.engagement.simulate_engagement` (``N_u1``,
        ``N_u2``, the events...).

    Raises
    ------
    ValueError
        For an empty or duplicated run list.
    """
    out = campaign_folder(out, runs)
    entries, truths, wheels = [], {}, {}
    for run in runs:
        s = run.settings
        table, truth = simulate_engagement(s, run.seed)
        ENGAGEMENT_WRITERS[run.format](table, out / run.file)
        wheels[run.wheel] = (s.z, math.degrees(s.psi))
        entry = {"id": run.id, "kind": "engagement", "file": run.file,
                 "chain": chain_key(run.chain), "wheel": run.wheel,
                 "branch_length_m": float(s.branch_length), "omega_per_s": float(s.omega),
                 "E0_N": float(s.E0)}
        if s.clip_level is not None:
            entry["clip_level_kN"] = float(from_si(s.clip_level, "kN"))
        entries.append(entry)
        truths[run.id] = {"file": run.file, "format": run.format, "chain": run.chain,
                          "seed": run.seed, **truth}
    text = run_sheet_text(campaign, [run.chain for run in runs], entries, wheels)
    return write_sheet_and_truth(out, campaign, text, truths)


def write_wear_campaign(
    out: str | Path, runs: Sequence[WearRunSpec], campaign: CampaignSpec
) -> Path:
    """Simulate and write a wear campaign: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of WearRunSpec
        The runs, in run-sheet order (unique ids and file names).
    campaign : CampaignSpec
        The ``[campaign]`` table.

    Returns
    -------
    Path
        The run sheet written. ``truth.json`` holds per run its file, chain,
        how it is written, seed, ``truth`` (the :class:`WearTruth` fields, SI)
        and the true limits and lives (:meth:`WearRunSpec.true_lives`).

    Raises
    ------
    ValueError
        For an empty or duplicated run list.
    """
    out = campaign_folder(out, runs)
    truths = {}
    for run in runs:
        table = simulate_wear(run.truth, run.seed)
        dropped = {"time": ["cycles"], "cycles": ["time"], "both": []}[run.abscissa]
        write_wear_table(table.drop(columns=dropped), out / run.file, layout=run.layout,
                         time_unit=run.time_unit, length_unit=run.length_unit,
                         force_unit=run.force_unit, language=run.language)
        truths[run.id] = {"file": run.file, "chain": run.chain, "layout": run.layout,
                          "abscissa": run.abscissa, "time_unit": run.time_unit,
                          "length_unit": run.length_unit, "seed": run.seed,
                          "truth": asdict(run.truth), **run.true_lives()}
    text = run_sheet_text(campaign, [run.chain for run in runs], [run.entry() for run in runs])
    return write_sheet_and_truth(out, campaign, text, truths)
