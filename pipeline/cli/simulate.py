"""``chainbench simulate ...``: synthetic campaigns from the virtual test benches.

``chainbench simulate tensile`` (cyclic runs, or with ``--single-pull`` single
pulls to fracture and proof-load tests), ``chainbench simulate engagement`` and
``chainbench simulate wear`` (wear tests of a roller chain), ``chainbench
simulate segment-load`` (the segments of a chain-drum tooth) and ``chainbench
simulate roller-engagement`` (a roller chain on a sprocket) write the logs of a
campaign (one file per run, in any layout and units the readers
accept), its run sheet ``campaign.toml`` and ``truth.json``, the true values each
log was made from (:mod:`pipeline.simulate.campaign`). ``chainbench simulate
demo`` (re)writes the demo campaigns of ``raw/`` (:mod:`pipeline.simulate.demo`).
The commands only parse options.
"""

from __future__ import annotations

import math
from enum import StrEnum
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from pipeline.catalog import chain as catalog_chain
from pipeline.cli._options import MultiValueCommand
from pipeline.cli._output import emit
from pipeline.condition.wear import REFERENCES
from pipeline.fit.roller_engagement import Sprocket
from pipeline.simulate.campaign import (
    WEAR_ABSCISSAE,
    CampaignSpec,
    EngagementRunSpec,
    PullRunSpec,
    TensileRunSpec,
    WearRunSpec,
    engagement_settings,
    write_engagement_campaign,
    write_pull_campaign,
    write_tensile_campaign,
    write_wear_campaign,
)
from pipeline.simulate.demo import DEMOS
from pipeline.simulate.export import (
    FORCE_UNITS,
    LENGTH_UNITS,
    SUFFIXES,
    TIME_UNITS,
    WEAR_LAYOUTS,
    WEAR_SUFFIXES,
)
from pipeline.simulate.pull import REMOVAL_MODES, PullTruth
from pipeline.simulate.roller_campaign import RollerRunSpec, SprocketSpec, write_roller_campaign
from pipeline.simulate.roller_engagement import CHAIN_16B, RollerEngagementTruth
from pipeline.simulate.segment_campaign import (
    SEGMENT_LAYOUTS,
    DrumSpec,
    SegmentRunSpec,
    demo_runs,
    write_segment_campaign,
)
from pipeline.simulate.segment_load import SegmentLoadTruth
from pipeline.simulate.tensile import TensileTruth
from pipeline.simulate.wear import CHANNELS as WEAR_CHANNELS
from pipeline.simulate.wear import HOUR, WearTruth
from pipeline.units import from_si, to_si

simulate_app = typer.Typer(
    help="Write synthetic campaigns from the virtual test benches (known truth).",
    no_args_is_help=True,
)


class Layout(StrEnum):
    """File layouts of the written logs (docs/file-formats.md)."""

    plain = "plain"
    european = "european"
    machine = "machine"
    xlsx = "xlsx"


class Language(StrEnum):
    """Column names of the European layout."""

    pl = "pl"
    de = "de"


#: How a removed extensometer misbehaves (:data:`pipeline.simulate.pull.REMOVAL_MODES`).
RemovalMode = StrEnum("RemovalMode", {mode: mode for mode in REMOVAL_MODES})


def _choice(value: str, allowed: tuple[str, ...], option: str) -> str:
    if value not in allowed:
        raise typer.BadParameter(f"choose one of {', '.join(allowed)}", param_hint=option)
    return value


def _campaign(campaign: str, title: str, command: str, seed: int) -> CampaignSpec:
    """The ``[campaign]`` table of a simulated campaign, or a bad ``--campaign``."""
    try:
        return CampaignSpec(
            id=campaign, title=title, machine=f"chainbench virtual {command} bench",
            note=f"Synthetic data written by `chainbench simulate {command} --seed {seed}`: "
                 "the virtual test bench, not a testing machine.")
    except ValueError:
        raise typer.BadParameter(
            "use letters, digits, '.', '_' and '-' only", param_hint="--campaign"
        ) from None


@simulate_app.command("tensile")
def tensile(
    out: Annotated[Path, typer.Option("--out", help="Campaign folder to write (created).")],
    chain: Annotated[
        str, typer.Option("--chain", help="Catalogue round-link chain, e.g. 18x64.")
    ] = "18x64",
    e0_kn: Annotated[
        float | None,
        typer.Option("--e0-kn", help="True stiffness E0 in kN. Default: Paper 001, Table 1."),
    ] = None,
    specimens: Annotated[
        int, typer.Option("--specimens", min=1, help="Number of specimens (Paper 001: 4).")
    ] = 4,
    specimen_scatter: Annotated[
        float,
        typer.Option(
            "--specimen-scatter",
            min=0.0,
            help="Relative standard deviation of E0 between specimens.",
        ),
    ] = 0.01,
    cycles: Annotated[int, typer.Option("--cycles", min=1, help="Load cycles per run.")] = 3,
    gauge_length_mm: Annotated[
        float | None,
        typer.Option("--gauge-length-mm",
                     help="Gauge length in mm. Default: 900 (Paper 001); single pull: 5 pitches."),
    ] = None,
    sample_rate: Annotated[
        float | None,
        typer.Option("--sample-rate", help="Logging rate in Hz. Default: 10; single pull: 20."),
    ] = None,
    loading_rate_kn_per_s: Annotated[
        float, typer.Option("--loading-rate-kn-per-s", help="Loading and unloading rate in kN/s.")
    ] = 1.0,
    dwell: Annotated[float, typer.Option("--dwell", help="Hold at each peak in s.")] = 0.0,
    layout: Annotated[Layout, typer.Option("--layout", help="File layout.")] = Layout.plain,
    language: Annotated[
        Language, typer.Option("--language", help="Column names of the European layout.")
    ] = Language.pl,
    force_unit: Annotated[
        str, typer.Option("--force-unit", help=f"Force unit: {', '.join(FORCE_UNITS)}.")
    ] = "kN",
    length_unit: Annotated[
        str, typer.Option("--length-unit", help=f"Gauge unit: {', '.join(LENGTH_UNITS)}.")
    ] = "mm",
    encoding: Annotated[
        str | None,
        typer.Option(
            "--encoding", help="Text encoding (utf-8-sig adds a BOM). Default: per layout."
        ),
    ] = None,
    campaign: Annotated[
        str, typer.Option("--campaign", help="Campaign id written to the run sheet.")
    ] = "simulated-tensile",
    single_pull: Annotated[
        bool,
        typer.Option("--single-pull",
                     help="Single pulls to fracture (or proof-load tests) instead of cycles: "
                          "extensometer and crosshead channels."),
    ] = False,
    max_force_kn: Annotated[
        float | None,
        typer.Option("--max-force-kn",
                     help="Single pull: true maximum force in kN. Default: 1.1 x the "
                          "minimum breaking force."),
    ] = None,
    proof_force_kn: Annotated[
        float | None,
        typer.Option("--proof-force-kn",
                     help="Single pull: load to this force, hold, unload, then pull."),
    ] = None,
    proof_only: Annotated[
        bool,
        typer.Option("--proof-only",
                     help="Single pull: end after the proof unloading (a proof-load test)."),
    ] = False,
    extensometer_removed_at: Annotated[
        float | None,
        typer.Option("--extensometer-removed-at",
                     help="Single pull: take the extensometer off at this fraction of the "
                          "maximum force."),
    ] = None,
    removal_mode: Annotated[
        RemovalMode,
        typer.Option("--removal-mode", help="How the removed extensometer misbehaves."),
    ] = RemovalMode.jump,
    crosshead: Annotated[
        bool, typer.Option("--crosshead/--no-crosshead", help="Single pull: write the crosshead.")
    ] = True,
    strain_channel: Annotated[
        bool,
        typer.Option("--strain-channel", help="Single pull: write the extensometer as a strain "
                                              "in % (the run sheet then has no gauge length)."),
    ] = False,
    repeated_first_time: Annotated[
        bool,
        typer.Option("--repeated-first-time",
                     help="Single pull: two first rows at time 0, as Bluehill writes."),
    ] = False,
    quote: Annotated[
        bool, typer.Option("--quote", help="Single pull, machine layout: quote every field.")
    ] = False,
    seed: Annotated[int, typer.Option("--seed", help="Seed of all the randomness.")] = 1,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Write the logs of a simulated tensile campaign with known truth.

    Cyclic runs by default; with --single-pull, single pulls to fracture or
    proof-load tests (--language de also names the machine layout's columns in
    German).
    """
    _choice(force_unit, FORCE_UNITS, "--force-unit")
    _choice(length_unit, LENGTH_UNITS, "--length-unit")
    spec = _campaign(campaign, f"Virtual tensile bench, chain {chain}", "tensile", seed)
    rng = np.random.default_rng(seed)
    E0 = None if e0_kn is None else to_si(e0_kn, "kN")
    lengths = {} if gauge_length_mm is None else {"gauge_length": to_si(gauge_length_mm, "mm")}
    rates = {} if sample_rate is None else {"sample_rate": sample_rate}
    try:
        if single_pull:
            forces = {name: to_si(value, "kN") for name, value in
                      (("max_force", max_force_kn), ("proof_force", proof_force_kn))
                      if value is not None}
            base = PullTruth.for_chain(
                chain, E0=E0, **lengths, **rates, **forces, to_fracture=not proof_only,
                extensometer_removed_at=extensometer_removed_at,
                removal_mode=str(removal_mode), strain_channel=strain_channel,
                repeated_first_time=repeated_first_time)
        else:
            base = TensileTruth.for_chain(
                chain, E0=E0, n_cycles=cycles, gauge_length=lengths.get("gauge_length", 0.9),
                sample_rate=rates.get("sample_rate", 10.0),
                loading_rate=to_si(loading_rate_kn_per_s, "kN/s"), dwell=dwell)
    except (KeyError, ValueError) as error:
        raise typer.BadParameter(str(error).strip("'\"")) from None
    runs = []
    prefix = ("P" if single_pull else "T") + chain.split("x")[0]
    for number in range(1, specimens + 1):
        truth = base.with_(E0=base.E0 * (1.0 + specimen_scatter * rng.standard_normal()))
        run_id = f"{prefix}-{number}"
        common = dict(
            id=run_id, chain=chain, specimen=f"{chain}-{number}", truth=truth,
            seed=int(rng.integers(2**31)), file=run_id + SUFFIXES[layout], layout=str(layout),
            force_unit=force_unit, length_unit=length_unit, encoding=encoding,
            preamble=(("Text Inputs", f'Specimen label,"{run_id}"'),
                      ("General", f'Machine,"{spec.machine}"')))
        if single_pull:
            runs.append(PullRunSpec(**common, language=_pull_language(layout, language),
                                    quote=quote, crosshead=crosshead))
        else:
            runs.append(TensileRunSpec(**common, language=str(language)))
    if single_pull:
        sheet = write_pull_campaign(out, runs, spec)
        rows = [{"id": run.id, "file": run.file, "E0_kN": from_si(run.truth.E0, "kN"),
                 "max_force_kN": from_si(run.truth.max_force, "kN")} for run in runs]
    else:
        sheet = write_tensile_campaign(out, runs, spec)
        rows = [{"id": run.id, "file": run.file, "E0_kN": from_si(run.truth.E0, "kN")}
                for run in runs]
    emit(
        rows,
        title=f"Simulated tensile campaign in {out}",
        as_json=as_json,
        extra={"out": str(out), "run_sheet": str(sheet), "truth": str(out / "truth.json")},
        digits=6,
    )


def _pull_language(layout: Layout, language: Language) -> str | None:
    """Column names of a single-pull log: the European language, or a German machine export."""
    if layout == Layout.european:
        return str(language)
    if layout == Layout.machine and language == Language.de:
        return "de"
    return None


#: Units of the simulated engagement table's columns whose names do not say them.
TENSION_UNITS = {"N_u1": "N", "N_u2": "N"}


class EngagementFormat(StrEnum):
    """File formats of the simulated engagement logs."""

    csv = "csv"
    tdms = "tdms"


@simulate_app.command("engagement", cls=MultiValueCommand)
def engagement(
    out: Annotated[Path, typer.Option("--out", help="Campaign folder to write (created).")],
    chain: Annotated[
        str, typer.Option("--chain", help="Catalogue round-link chain, e.g. 18x64.")
    ] = "18x64",
    teeth: Annotated[
        list[int] | None, typer.Option("--teeth", help="Teeth of the wheels, e.g. 6 8 10.")
    ] = None,
    apex_deg: Annotated[
        list[float] | None,
        typer.Option("--apex-deg", help="Tooth apex angles in deg (a wheel per teeth x apex)."),
    ] = None,
    omega: Annotated[
        list[float] | None, typer.Option("--omega", help="Wheel speeds in 1/s, one run each.")
    ] = None,
    e0_kn: Annotated[
        float, typer.Option("--e0-kn", help="Chain stiffness E0 in kN (Paper 000: 22600).")
    ] = 22600.0,
    branch_length: Annotated[
        float, typer.Option("--branch-length", help="Active branch length in m.")
    ] = 2.0,
    k: Annotated[float, typer.Option("--k", help="Share of link masses in the impact.")] = 2.0,
    pretension_kn: Annotated[
        float, typer.Option("--pretension-kn", help="Mean branch tension in kN.")
    ] = 20.0,
    polygon_kn: Annotated[
        float, typer.Option("--polygon-kn", help="Polygon-effect amplitude in kN.")
    ] = 0.5,
    damping: Annotated[
        float, typer.Option("--damping", help="Damping ratio of the branch.")
    ] = 0.03,
    natural_frequency_hz: Annotated[
        float | None,
        typer.Option("--natural-frequency-hz",
                     help="Natural frequency in Hz. Default: sqrt(E0 / (L m_branch)) / 2 pi."),
    ] = None,
    sample_rate: Annotated[
        float, typer.Option("--sample-rate", help="Logging rate in Hz.")
    ] = 20000.0,
    duration: Annotated[float, typer.Option("--duration", help="Log length in s.")] = 2.0,
    snr: Annotated[
        float, typer.Option("--snr", help="N_u1 over the noise's standard deviation.")
    ] = 20.0,
    jitter_ms: Annotated[
        float, typer.Option("--jitter-ms", help="Standard deviation of the seating times in ms.")
    ] = 0.1,
    amplitude_scatter: Annotated[
        float, typer.Option("--amplitude-scatter", help="Relative scatter of strike amplitudes.")
    ] = 0.0,
    angle: Annotated[
        bool, typer.Option("--angle/--no-angle", help="Write a wheel-angle channel.")
    ] = True,
    clip_kn: Annotated[
        float | None, typer.Option("--clip-kn", help="Clip the force channel at this level in kN.")
    ] = None,
    file_format: Annotated[
        EngagementFormat, typer.Option("--format", help="File format of the logs.")
    ] = EngagementFormat.tdms,
    campaign: Annotated[
        str, typer.Option("--campaign", help="Campaign id written to the run sheet.")
    ] = "simulated-engagement",
    seed: Annotated[int, typer.Option("--seed", help="Seed of all the randomness.")] = 1,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Write the logs of a simulated engagement campaign with known truth (Paper 000)."""
    spec = _campaign(campaign, f"Virtual engagement bench, chain {chain}", "engagement", seed)
    rng = np.random.default_rng(seed)
    runs = []
    for z in dict.fromkeys(teeth or [8]):
        for apex in dict.fromkeys(apex_deg or [40.0]):
            for speed in dict.fromkeys(omega or [20.0]):
                try:
                    settings = engagement_settings(
                        chain, z=z, psi=math.radians(apex), omega=speed, E0=to_si(e0_kn, "kN"),
                        branch_length=branch_length, k=k, pretension=to_si(pretension_kn, "kN"),
                        polygon_amplitude=to_si(polygon_kn, "kN"), damping_ratio=damping,
                        natural_frequency=(None if natural_frequency_hz is None
                                           else 2 * math.pi * natural_frequency_hz),
                        sample_rate=sample_rate, duration=duration, snr=snr,
                        jitter=jitter_ms / 1000, amplitude_scatter=amplitude_scatter,
                        with_angle=angle,
                        clip_level=None if clip_kn is None else to_si(clip_kn, "kN"))
                except KeyError as error:
                    raise typer.BadParameter(str(error).strip("'\""),
                                             param_hint="--chain") from None
                except ValueError as error:
                    raise typer.BadParameter(str(error)) from None
                run_id = f"E{z}-{apex:g}-{speed:g}".replace(".", "p")
                runs.append(EngagementRunSpec(
                    id=run_id, chain=chain, settings=settings, seed=int(rng.integers(2**31)),
                    file=f"{run_id}.{file_format}", format=str(file_format)))
    sheet = write_engagement_campaign(out, runs, spec)
    rows = []
    for run in runs:
        n_u1, n_u2 = run.settings.impact_tensions()
        rows.append({"id": run.id, "file": run.file, "omega_per_s": run.settings.omega,
                     "N_u1": n_u1, "N_u2": n_u2})
    emit(
        rows,
        title=f"Simulated engagement campaign in {out}",
        as_json=as_json,
        extra={"out": str(out), "run_sheet": str(sheet), "truth": str(out / "truth.json")},
        digits=6,
        units=TENSION_UNITS,
    )


#: Wear-log layouts, running columns, channels and references (the simulator's own lists).
WearLayout = StrEnum("WearLayout", {name: name for name in WEAR_LAYOUTS})
WearAbscissa = StrEnum("WearAbscissa", {name: name for name in WEAR_ABSCISSAE})
WearChannel = StrEnum("WearChannel", {name: name for name in WEAR_CHANNELS})
Reference = StrEnum("Reference", {name: name for name in REFERENCES})


@simulate_app.command("wear", cls=MultiValueCommand)
def wear(
    out: Annotated[Path, typer.Option("--out", help="Campaign folder to write (created).")],
    chain: Annotated[
        str, typer.Option("--chain", help="Catalogue roller chain, e.g. 16B.")
    ] = "16B",
    layout: Annotated[
        list[WearLayout] | None,
        typer.Option("--layout", help="File layouts, one run each (default: plain)."),
    ] = None,
    runs: Annotated[int, typer.Option("--runs", min=1, help="Runs per layout.")] = 1,
    teeth: Annotated[
        int, typer.Option("--teeth", min=3, max=499, help="Teeth z of the driven sprocket.")
    ] = 40,
    limit_pct: Annotated[
        float | None,
        typer.Option("--limit-pct", help="The lab's limit of the pitch growth in % of the "
                                         "pitch (e.g. 1.5 or 3)."),
    ] = None,
    reference: Annotated[
        Reference, typer.Option("--reference", help="Elongation counted from the nominal "
                                                     "pitch or the first reading.")
    ] = Reference.nominal,
    pitches: Annotated[
        int, typer.Option("--pitches", min=1, help="Pitches N of the measured section.")
    ] = 10,
    wear_rate_um_per_h: Annotated[
        float, typer.Option("--wear-rate-um-per-h", help="True steady wear rate per pitch "
                                                          "in um/h.")
    ] = 0.75,
    run_in_um: Annotated[
        float, typer.Option("--run-in-um", help="True run-in elongation per pitch in um "
                                                 "(0: no run-in).")
    ] = 30.0,
    run_in_h: Annotated[
        float, typer.Option("--run-in-h", help="True run-in time constant in h.")
    ] = 10.0,
    noise_um: Annotated[
        float, typer.Option("--noise-um", help="Standard deviation of a reading of the "
                                                "section in um.")
    ] = 10.0,
    duration_h: Annotated[float, typer.Option("--duration-h", help="Test length in h.")] = 300.0,
    interval_h: Annotated[
        float, typer.Option("--interval-h", help="Time between readings in h.")
    ] = 5.0,
    cycle_rate: Annotated[
        float, typer.Option("--cycle-rate", help="Cycles counted per second.")
    ] = 0.5,
    abscissa: Annotated[
        WearAbscissa, typer.Option("--abscissa", help="Running columns written.")
    ] = WearAbscissa.time,
    channel: Annotated[
        WearChannel, typer.Option("--channel", help="Section length or its elongation.")
    ] = WearChannel.length,
    time_unit: Annotated[
        str, typer.Option("--time-unit", help=f"Time unit: {', '.join(TIME_UNITS)}.")
    ] = "h",
    length_unit: Annotated[
        str, typer.Option("--length-unit", help=f"Length unit: {', '.join(LENGTH_UNITS)}.")
    ] = "mm",
    language: Annotated[
        Language, typer.Option("--language", help="Column names of the European layout.")
    ] = Language.pl,
    load_kn: Annotated[
        float | None, typer.Option("--load-kn", help="Chain tension logged, in kN.")
    ] = None,
    speed: Annotated[
        float | None, typer.Option("--speed", help="Chain speed logged, in m/s.")
    ] = None,
    f_max_kn: Annotated[
        float | None,
        typer.Option("--f-max-kn", help="Pin criterion: largest force on a link F_max in kN "
                                        "(with --sigma-t-mpa and --wear-coefficient)."),
    ] = None,
    sigma_t_mpa: Annotated[
        float | None,
        typer.Option("--sigma-t-mpa", help="Pin criterion: allowable bending stress in MPa."),
    ] = None,
    wear_coefficient: Annotated[
        float | None,
        typer.Option("--wear-coefficient", help="Pin criterion: pin wear coefficient K_e."),
    ] = None,
    campaign: Annotated[
        str, typer.Option("--campaign", help="Campaign id written to the run sheet.")
    ] = "simulated-wear",
    seed: Annotated[int, typer.Option("--seed", help="Seed of all the randomness.")] = 1,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Write the logs of simulated wear tests of a roller chain with known truth (Paper 004)."""
    spec = _campaign(campaign, f"Virtual wear bench, chain {chain}", "wear", seed)
    _choice(time_unit, TIME_UNITS, "--time-unit")
    _choice(length_unit, LENGTH_UNITS, "--length-unit")
    pin_options = {"max_link_force_kN": f_max_kn, "pin_allowable_stress_MPa": sigma_t_mpa,
                   "pin_wear_coefficient": wear_coefficient}
    if None in pin_options.values() and any(v is not None for v in pin_options.values()):
        raise typer.BadParameter("give all of --f-max-kn, --sigma-t-mpa and "
                                 "--wear-coefficient, or none", param_hint="--f-max-kn")
    try:
        pitch = float(catalog_chain(chain)["t"])
        base = WearTruth(
            pitch=pitch, pitches=pitches, initial_error=0.001 * pitch,
            run_in=run_in_um * 1e-6, run_in_time=run_in_h * HOUR,
            wear_rate=wear_rate_um_per_h * 1e-6 / HOUR, noise=noise_um * 1e-6,
            duration=duration_h * HOUR, interval=interval_h * HOUR, cycle_rate=cycle_rate,
            channel=str(channel), load=None if load_kn is None else to_si(load_kn, "kN"),
            speed=speed)
    except KeyError as error:
        raise typer.BadParameter(str(error).strip("'\""), param_hint="--chain") from None
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    rng = np.random.default_rng(seed)
    specs = []
    for kind in dict.fromkeys(layout or [WearLayout.plain]):
        for number in range(1, runs + 1):
            run_id = f"W{chain}-{kind}-{number}"
            specs.append(WearRunSpec(
                id=run_id, chain=chain, truth=base, seed=int(rng.integers(2**31)),
                file=run_id + WEAR_SUFFIXES[kind], teeth=teeth, reference=str(reference),
                limit_pct=limit_pct, abscissa=str(abscissa), layout=str(kind),
                time_unit=time_unit, length_unit=length_unit, language=str(language),
                pin=None if f_max_kn is None else pin_options))
    sheet = write_wear_campaign(out, specs, spec)
    rows = [{"id": run.id, "file": run.file, "wear_rate_um_per_h": wear_rate_um_per_h,
             **{f"life_{name}_h": run.true_lives()[f"life_{name}_s"] / HOUR
                for name in ("eq3", "lab") if f"life_{name}_s" in run.true_lives()}}
            for run in specs]
    emit(rows, title=f"Simulated wear campaign in {out}", as_json=as_json,
         extra={"out": str(out), "run_sheet": str(sheet), "truth": str(out / "truth.json")},
         digits=6)


class RollerFormat(StrEnum):
    """File formats of roller-engagement logs (the engagement writers)."""

    csv = "csv"
    tdms = "tdms"


@simulate_app.command("roller-engagement", cls=MultiValueCommand)
def roller_engagement(
    out: Annotated[Path, typer.Option("--out", help="Campaign folder to write (created).")],
    teeth: Annotated[
        int, typer.Option("--teeth", min=6, max=498, help="Teeth z of the sprocket (even).")
    ] = 18,
    module_mm: Annotated[
        float | None, typer.Option("--module-mm", help="Module of the involute's cutting tool "
                                                        "in mm (0: none, xi only measured).")
    ] = 8.0,
    profile_angle_deg: Annotated[
        float, typer.Option("--profile-angle-deg", help="Profile angle of the tool in deg.")
    ] = 20.0,
    xi: Annotated[
        float | None, typer.Option("--xi", help="True xi (default: the involute's).")
    ] = None,
    rpm: Annotated[
        list[float] | None, typer.Option("--rpm", help="Sprocket speeds in rpm, one run each "
                                                       "(default: 100 200 300).")
    ] = None,
    file_format: Annotated[
        RollerFormat, typer.Option("--format", help="File format of the logs.")
    ] = RollerFormat.csv,
    g_lim: Annotated[
        float, typer.Option("--g-lim", help="The lab's G_lim in J/mm^2 (Paper 002, eq. (8)).")
    ] = 3e-4,
    campaign: Annotated[
        str, typer.Option("--campaign", help="Campaign id written to the run sheet.")
    ] = "simulated-roller",
    seed: Annotated[int, typer.Option("--seed", help="Seed of all the randomness.")] = 1,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Write engagement logs of roller chain 16B on a sprocket with known xi (Paper 002)."""
    spec = _campaign(campaign, f"Virtual roller bench, z = {teeth}", "roller-engagement", seed)
    try:
        involute = bool(module_mm)
        sprocket = SprocketSpec(f"z{teeth}", teeth, module_mm=module_mm if involute else None,
                                profile_angle_deg=profile_angle_deg if involute else None,
                                g_lim_J_per_mm2=g_lim)
        if xi is None and not involute:
            raise ValueError("give --xi when the sprocket has no involute (--module-mm)")
        true_xi = xi if xi is not None else Sprocket(
            teeth, module=to_si(module_mm, "mm"),
            profile_angle=math.radians(profile_angle_deg)).involute_xi(CHAIN_16B.pitch)[0]
        truth = RollerEngagementTruth(teeth=teeth, xi=true_xi)
        rng = np.random.default_rng(seed)
        specs = [RollerRunSpec(id=f"R{teeth}-{n:g}", chain="16B", sprocket=sprocket, truth=truth,
                               omega=float(to_si(n, "rpm")), seed=int(rng.integers(2**31)),
                               file=f"R{teeth}-{n:g}.{file_format}", format=str(file_format))
                 for n in dict.fromkeys(rpm or [100.0, 200.0, 300.0])]
        sheet = write_roller_campaign(out, specs, spec)
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    rows = [{"id": run.id, "file": run.file, "rpm": float(from_si(run.omega, "rpm")),
             "xi": true_xi, "amplitude_N": truth.amplitude(run.omega)} for run in specs]
    emit(rows, title=f"Simulated roller-engagement campaign in {out}", as_json=as_json,
         extra={"out": str(out), "run_sheet": str(sheet), "truth": str(out / "truth.json")},
         digits=6)


SegmentLayout = StrEnum("SegmentLayout", {name: name for name in SEGMENT_LAYOUTS})


class FittedGeometry(StrEnum):
    """The drum parameter fitted to the measured ratios (Paper 003)."""

    s = "s"
    beta = "beta"


@simulate_app.command("segment-load", cls=MultiValueCommand)
def segment_load(
    out: Annotated[Path, typer.Option("--out", help="Campaign folder to write (created).")],
    chain: Annotated[
        str, typer.Option("--chain", help="Catalogue round-link chain with a torus radius.")
    ] = "34x126",
    groove_width_mm: Annotated[
        float, typer.Option("--groove-width-mm", help="Groove width c between the segments "
                                                      "in mm.")
    ] = 45.0,
    s_mm: Annotated[
        float, typer.Option("--s-mm", help="True contact distance s in mm.")
    ] = 60.0,
    beta_deg: Annotated[
        float, typer.Option("--beta-deg", help="True flank inclination beta in deg.")
    ] = 50.0,
    eps_n_deg: Annotated[
        float, typer.Option("--eps-n-deg", help="Link inclination eps_n in deg.")
    ] = 0.0,
    fit: Annotated[
        FittedGeometry, typer.Option("--fit", help="Parameter the drum fits (Paper 003).")
    ] = FittedGeometry.s,
    declared_mm: Annotated[
        float | None, typer.Option("--declared-mm", help="The run sheet's s in mm (with "
                                                         "--fit s; default 55).")
    ] = None,
    declared_deg: Annotated[
        float | None, typer.Option("--declared-deg", help="The run sheet's beta in deg (with "
                                                          "--fit beta; default 45).")
    ] = None,
    levels_kn: Annotated[
        list[float] | None, typer.Option("--levels-kn", help="Chain-force levels in kN, one "
                                                             "run each (default: 50 100 150).")
    ] = None,
    seatings: Annotated[
        int, typer.Option("--seatings", min=1, help="Seatings per run.")
    ] = 30,
    layout: Annotated[
        list[SegmentLayout] | None,
        typer.Option("--layout", help="File layouts, taken in turn by the runs (default: plain).")
    ] = None,
    gain_imbalance: Annotated[
        float, typer.Option("--gain-imbalance", help="Relative gain difference of the two "
                                                     "segments.")
    ] = 0.0,
    side_force: Annotated[
        bool, typer.Option("--side-force/--no-side-force", help="Log the side force F_P.")
    ] = True,
    campaign: Annotated[
        str, typer.Option("--campaign", help="Campaign id written to the run sheet.")
    ] = "simulated-segment-load",
    seed: Annotated[int, typer.Option("--seed", help="Seed of all the randomness.")] = 1,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """Write segment-load logs of a chain-drum tooth with known contact geometry (Paper 003)."""
    spec = _campaign(campaign, f"Virtual drum rig, chain {chain}", "segment-load", seed)
    wrong = {FittedGeometry.s: ("--declared-deg", declared_deg),
             FittedGeometry.beta: ("--declared-mm", declared_mm)}[fit]
    if wrong[1] is not None:
        raise typer.BadParameter(f"{wrong[0]} goes with the other --fit; with --fit {fit} "
                                 "give " + ("--declared-mm" if fit == "s" else "--declared-deg"),
                                 param_hint=wrong[0])
    try:
        catalogue = catalog_chain(chain)
    except KeyError as error:
        raise typer.BadParameter(str(error).strip("'\""), param_hint="--chain") from None
    if not catalogue.get("r_outer"):
        raise typer.BadParameter(f"the catalogue gives chain {chain} no torus radius r_outer "
                                 "(Paper 003 needs it)", param_hint="--chain")
    layouts = [str(kind) for kind in dict.fromkeys(layout or [SegmentLayout.plain])]
    levels = [to_si(level, "kN") for level in dict.fromkeys(levels_kn or [50.0, 100.0, 150.0])]
    if len(layouts) > len(levels):
        raise typer.BadParameter(f"{len(layouts)} layouts for {len(levels)} runs: the runs take "
                                 "the layouts in turn, give as many --levels-kn at least",
                                 param_hint="--layout")
    declared = (to_si(55.0 if declared_mm is None else declared_mm, "mm") if fit == "s"
                else math.radians(45.0 if declared_deg is None else declared_deg))
    try:
        truth = SegmentLoadTruth(
            r_outer=float(catalogue["r_outer"]), d=float(catalogue["d"]),
            groove_width=to_si(groove_width_mm, "mm"), beta=math.radians(beta_deg),
            eps_n=math.radians(eps_n_deg), s=to_si(s_mm, "mm"), seatings=seatings,
            seating_rate=1.0, plateau=0.4, transition=0.1, sample_rate=200.0,
            gain_imbalance=gain_imbalance, with_side_force=side_force)
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    try:
        truth.with_(**{str(fit): declared})
    except ValueError as error:
        raise typer.BadParameter(f"the run sheet's {fit} cannot hold: {error}", param_hint=(
            "--declared-mm" if fit == "s" else "--declared-deg")) from None
    try:
        runs = demo_runs(chain, truth, levels, layouts, seed, f"S{chain}")
        sheet = write_segment_campaign(out, runs, DrumSpec("drum", str(fit), declared), spec)
    except ValueError as error:
        raise typer.BadParameter(str(error)) from None
    rows = [_segment_row(run) for run in runs]
    emit(rows, title=f"Simulated segment-load campaign in {out}", as_json=as_json,
         extra={"out": str(out), "run_sheet": str(sheet), "truth": str(out / "truth.json")},
         digits=6)


def _segment_row(run: SegmentRunSpec) -> dict[str, str | float]:
    """What the command prints of a simulated segment-load run: its file and truth."""
    truth = run.truth
    return {"id": run.id, "file": run.file, "F_kN": from_si(truth.chain_force[0], "kN"),
            "F_K/F": truth.contact_force_ratio, "F_P/F": truth.side_force_ratio,
            "s_mm": from_si(truth.s, "mm"), "beta_deg": math.degrees(truth.beta)}


@simulate_app.command("demo")
def demo(
    out: Annotated[
        Path, typer.Option("--out", help="Folder of the campaigns (raw/ of the project).")
    ] = Path("raw"),
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
) -> None:
    """(Re)write the demo campaigns: stiffness-demo, engagement-demo, pull-demo and wear-demo."""
    rows = []
    for name, write in DEMOS.items():
        folder = out / name
        write(folder)
        files = sorted(path for path in folder.iterdir() if path.is_file())
        rows.append({"campaign": name, "folder": str(folder), "files": len(files),
                     "size_kB": sum(path.stat().st_size for path in files) / 1e3})
    emit(rows, title=f"Demo campaigns in {out}", as_json=as_json, extra={"out": str(out)},
         digits=4)
