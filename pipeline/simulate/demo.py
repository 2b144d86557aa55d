"""The demo campaigns of ``raw/``: synthetic, deterministic, with known truth.

``chainbench simulate demo`` writes them with :func:`write_stiffness_demo`,
:func:`write_engagement_demo`, :func:`write_pull_demo` and :func:`write_wear_demo`
(:data:`DEMOS`); fixed
seeds make every byte reproducible (a test regenerates them and compares with the
committed files).

``stiffness-demo``
    Paper 001, section 3, re-created on the virtual tensile bench: chains
    13x50, 14x50, 18x64 and 22x86, four specimens each (A to D) on segments of
    about 0.9 m (896 to 904 mm as measured), three cycles between the paper's
    preload and upper force (500/3500 kgf, 1000/10000 kgf, 2000/20000 kgf).
    The true E0 of each chain is Table 1's experimental value, with a
    specimen-to-specimen scatter of at most 0.4 %. The logs are spread over
    the layouts and units a lab meets (:data:`STIFFNESS_FORMATS`).
``engagement-demo``
    Paper 000's rig: chain 18x64 on a 2 m branch, E0 = 2.26e7 N, wheels of
    z = 6, 8, 10 teeth with apex angles 20, 40, 60 deg, each at omega = 10, 20,
    30 1/s (27 runs): TDMS and CSV alternately, some with the wheel-angle
    channel, noise at SNR 20, 1.2 s at 5 kHz (at least 11 seating periods a run).

``pull-demo``
    Single pulls of chain 18x64 with the acceptance limits of its standard
    declared (:data:`PULL_LIMITS`): four pulls to fracture in the layouts a
    tensile lab meets (a German Bluehill export with the extensometer as a
    strain in % taken off near the maximum force, a Polish European CSV with
    extensometer and crosshead in mm, an English Bluehill export with every
    field quoted and the first time stamp repeated, a plain CSV) and one
    proof-load test (load to the proof force, hold, unload). Specimen D breaks
    at 404 kN, below the minimum breaking force of 410 kN: the one failed check.

``wear-demo``
    Wear tests of roller chain 16B (the virtual wear bench of ``chainbench
    simulate wear``): a 10-pitch section read every 5 h for 300 h, with run-in
    then 0.7 to 0.9 um/h of wear per pitch (:data:`WEAR_RUNS`), in four layouts
    (a plain CSV of section lengths with load and speed, a workbook of
    elongations counted from the first reading, a Polish CSV over cycles
    without run-in, a TDMS file with both time and cycles); sprockets of 25,
    40 and 60 teeth, the lab's limits of 1.5 and 3 %, and Paper 004's pin
    criterion for the hand-worked load (12 kN, 800 MPa, K_e = 1) with pinned
    and clamped pins: the pinned pin fails eq. (1), the clamped one passes.

``segment-load-demo``
    Segment-load tests of chain 34x126 on a segmented drum tooth (Paper 003;
    :func:`pipeline.simulate.segment_campaign.write_segment_load_demo`): five
    operating points of 50 to 150 kN in five layouts, true s = 60 mm, the run
    sheet declaring 55 mm and fitting s.

``roller-demo``
    Roller chain 16B on a 1 m branch (E0 = 1e7 N) on two sprockets
    (:data:`~pipeline.simulate.roller_campaign.ROLLER_DEMO`): an involute
    sprocket of z = 18 (m = 8 mm, alpha = 20 deg; true xi the involute's,
    0.535) at 100, 200 and 300 rpm as CSV, and a sprocket of z = 12 without
    involute geometry (true xi 0.6) at 150, 250 and 350 rpm as TDMS, whose
    lab's G_lim = 3e-5 J/mm^2 puts n_max at 305 rpm: the 350 rpm run is flagged.

Every run sheet says ``synthetic = true``; ``truth.json`` beside them keeps the
true values, and the run sheets do not depend on it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import NamedTuple

import numpy as np

from pipeline.catalog import chain as catalog_chain
from pipeline.simulate.campaign import (
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
from pipeline.simulate.export import SUFFIXES, WEAR_SUFFIXES
from pipeline.simulate.pull import YIELD_RATIO, PullTruth
from pipeline.simulate.roller_campaign import write_roller_demo
from pipeline.simulate.segment_campaign import write_segment_load_demo
from pipeline.simulate.tensile import TensileTruth
from pipeline.simulate.wear import HOUR, WearTruth
from pipeline.units import to_si

#: Seeds of the demos.
STIFFNESS_SEED = 1969
ENGAGEMENT_SEED = 2000
PULL_SEED = 2024
WEAR_SEED = 2025

#: Acceptance limits of the pull demo's chain 18x64 (run-sheet keys of ``[chains.*]``):
#: proof force, minimum breaking force, largest elongation at the proof force and
#: smallest elongation at fracture, plausible values for a mining chain of its size.
PULL_LIMITS = {"18x64": {"proof_force_kN": 320.0, "min_breaking_force_kN": 410.0,
                         "max_elongation_at_proof_pct": 1.6,
                         "min_elongation_at_fracture_pct": 12.0}}


class LogFormat(NamedTuple):
    """How one tensile log is written (:func:`pipeline.simulate.export.write_table`)."""

    layout: str
    force_unit: str
    length_unit: str
    language: str = "pl"
    encoding: str | None = None


#: Format of the logs of specimens A to D of each chain: a Polish lab PC (European
#: CSV, kgf, cp1250), a plain CSV logger in kN (one specimen logged on a German PC:
#: European CSV with BOM, daN), an Instron-style export in N (one in lbf and inches)
#: and spreadsheets in kN and micrometres.
STIFFNESS_FORMATS = {
    "13x50": 4 * [LogFormat("european", "kgf", "mm", "pl")],
    "14x50": 3 * [LogFormat("plain", "kN", "mm")]
    + [LogFormat("european", "daN", "mm", "de", "utf-8-sig")],
    "18x64": 3 * [LogFormat("machine", "N", "mm")] + [LogFormat("machine", "lbf", "in")],
    "22x86": 4 * [LogFormat("xlsx", "kN", "um")],
}

#: Loading and unloading rate per chain [kgf/s]: some 45 to 60 s a ramp.
LOADING_RATES_KGF_PER_S = {"13x50": 50.0, "14x50": 50.0, "18x64": 200.0, "22x86": 400.0}

#: Largest relative deviation of a specimen's E0 from Table 1's value.
E0_SCATTER = 0.004


def write_stiffness_demo(folder: str | Path) -> Path:
    """Write the ``stiffness-demo`` campaign (Paper 001's tensile tests) into `folder`.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    rng = np.random.default_rng(STIFFNESS_SEED)
    runs = []
    for chain, formats in STIFFNESS_FORMATS.items():
        base = TensileTruth.for_chain(
            chain, sample_rate=10.0,
            loading_rate=to_si(LOADING_RATES_KGF_PER_S[chain], "kgf/s"))
        for letter, log in zip("ABCD", formats, strict=True):
            truth = base.with_(
                E0=base.E0 * (1.0 + rng.uniform(-E0_SCATTER, E0_SCATTER)),
                gauge_length=to_si(float(rng.integers(896, 905)), "mm"),
                slack=to_si(rng.uniform(0.2, 0.4), "mm"),
                set_first=to_si(rng.uniform(0.05, 0.15), "mm"),
                bending=rng.uniform(0.02, 0.08),
            )
            run_id = f"T{chain.split('x')[0]}-{letter}"
            specimen = f"{chain}-{letter}"
            runs.append(TensileRunSpec(
                id=run_id, chain=chain, specimen=specimen, truth=truth,
                seed=int(rng.integers(2**31)), file=run_id + SUFFIXES[log.layout],
                layout=log.layout, force_unit=log.force_unit, length_unit=log.length_unit,
                language=log.language, encoding=log.encoding,
                preamble=(("Test Method", "Chain stiffness, 3 cycles"),
                          ("Specimen label", specimen),
                          ("Machine", "Amsler 50 t (virtual)")),
            ))
    campaign = CampaignSpec(
        id="stiffness-demo",
        title="Static stiffness of round-link mining chains (Paper 001, re-created)",
        lab="Strength testing laboratory (virtual)",
        machine="Amsler 50 t (virtual)",
        note="Synthetic data made with `chainbench simulate demo`: Paper 001's tensile "
             "tests re-created on the virtual test bench, with Table 1's experimental E0 "
             "as the true stiffness. Not measurements.",
    )
    return write_tensile_campaign(folder, runs, campaign)


def write_engagement_demo(folder: str | Path) -> Path:
    """Write the ``engagement-demo`` campaign (Paper 000's chain wheel) into `folder`.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    rng = np.random.default_rng(ENGAGEMENT_SEED)
    runs = []
    points = [(z, apex, omega) for z in (6, 8, 10) for apex in (20, 40, 60)
              for omega in (10, 20, 30)]
    for index, (z, apex, omega) in enumerate(points):
        settings = engagement_settings(
            "18x64", z=z, psi=math.radians(apex), omega=float(omega), E0=2.26e7,
            branch_length=2.0, sample_rate=5000.0, duration=1.2, snr=20.0,
            amplitude_scatter=0.02, with_angle=index % 3 != 2)
        run_id = f"E{z}-{apex}-{omega}"
        file_format = "tdms" if index % 2 == 0 else "csv"
        runs.append(EngagementRunSpec(
            id=run_id, chain="18x64", settings=settings, seed=int(rng.integers(2**31)),
            file=f"{run_id}.{file_format}", format=file_format))
    campaign = CampaignSpec(
        id="engagement-demo",
        title="Impact tensions of an 18x64 chain on pocket wheels (Paper 000, re-created)",
        lab="Chain drive laboratory (virtual)",
        machine="Chain-wheel rig (virtual)",
        note="Synthetic data made with `chainbench simulate demo`: branch-tension logs "
             "of Paper 000's rig from the virtual engagement bench (k = 2). "
             "Not measurements.",
    )
    return write_engagement_campaign(folder, runs, campaign)


def write_pull_demo(folder: str | Path) -> Path:
    """Write the ``pull-demo`` campaign (single pulls of chain 18x64) into `folder`.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    rng = np.random.default_rng(PULL_SEED)
    kN, mm = to_si(1.0, "kN"), to_si(1.0, "mm")
    base = PullTruth.for_chain("18x64")
    machine = "Instron 600 kN (virtual)"
    german = (("Texteingaben", 'Probenbezeichnung,"18x64-A"'),
              ("Allgemein", f'Prüfmaschine,"{machine}"'))
    english = (("Text Inputs", 'Specimen label,"18x64-C"'), ("General", f'Machine,"{machine}"'))
    specimens = [
        # letter, truth settings (yield force 0.65 of the maximum unless given), log format
        ("A", dict(E0=base.E0 * 1.012, max_force=457 * kN, fracture_strain=0.146,
                   slack=0.25 * mm, strain_channel=True, extensometer_removed_at=0.99,
                   removal_mode="freeze"),
         dict(layout="machine", language="de", preamble=german)),
        ("B", dict(E0=base.E0 * 0.991, max_force=449 * kN, fracture_strain=0.138,
                   slack=0.18 * mm),
         dict(layout="european", language="pl")),
        ("C", dict(E0=base.E0 * 1.004, max_force=462 * kN, fracture_strain=0.152,
                   slack=0.22 * mm, strain_channel=True, repeated_first_time=True),
         dict(layout="machine", language="en", quote=True, preamble=english)),
        ("D", dict(E0=base.E0 * 0.996, max_force=404 * kN, yield_force=293 * kN,
                   fracture_strain=0.131, slack=0.30 * mm),
         dict(layout="plain")),
        ("P", dict(E0=base.E0 * 1.007, max_force=455 * kN, slack=0.2 * mm,
                   proof_force=320 * kN, to_fracture=False),
         dict(layout="european", language="de")),
    ]
    runs = []
    for letter, settings, log in specimens:
        truth = base.with_(**{"yield_force": YIELD_RATIO * settings["max_force"], **settings})
        run_id = f"P18-{letter}"
        runs.append(PullRunSpec(
            id=run_id, chain="18x64", specimen=f"18x64-{letter}", truth=truth,
            seed=int(rng.integers(2**31)), file=run_id + SUFFIXES[log["layout"]], **log))
    campaign = CampaignSpec(
        id="pull-demo",
        title="Single pulls to fracture and a proof-load test of an 18x64 chain",
        lab="Tensile testing laboratory (virtual)",
        machine=machine,
        note="Synthetic data made with `chainbench simulate demo`: single pulls of "
             "chain 18x64 on the virtual tensile bench, with known stiffness, maximum "
             "force and elongations. Not measurements.",
    )
    return write_pull_campaign(folder, runs, campaign, limits=PULL_LIMITS)


#: Paper 004's pin criterion for the wear demo: the hand-worked load of
#: ``docs/models/paper-004-pin-criterion.md`` (run-sheet keys), pinned or clamped.
WEAR_PIN = {"max_link_force_kN": 12.0, "pin_allowable_stress_MPa": 800.0,
            "pin_wear_coefficient": 1.0}

#: The wear demo's runs: letter, true wear (changes of :class:`WearTruth`), the run's
#: settings (:class:`~pipeline.simulate.campaign.WearRunSpec`) and pin support.
WEAR_RUNS = (
    ("A", {"wear_rate": 0.75e-6 / HOUR, "load": 10e3, "speed": 1.5},
     {"teeth": 40, "limit_pct": 3.0, "layout": "plain"}, "pinned"),
    ("B", {"wear_rate": 0.70e-6 / HOUR, "channel": "elongation"},
     {"teeth": 40, "limit_pct": 1.5, "layout": "xlsx", "reference": "first"}, "clamped"),
    ("C", {"wear_rate": 0.80e-6 / HOUR, "run_in": 0.0},
     {"teeth": 60, "limit_pct": 3.0, "layout": "european", "abscissa": "cycles"}, "clamped"),
    ("D", {"wear_rate": 0.90e-6 / HOUR},
     {"teeth": 25, "layout": "tdms", "abscissa": "both", "length_unit": "um"}, "pinned"),
)


def write_wear_demo(folder: str | Path) -> Path:
    """Write the ``wear-demo`` campaign (wear tests of roller chain 16B) into `folder`.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    rng = np.random.default_rng(WEAR_SEED)
    pitch = float(catalog_chain("16B")["t"])
    base = WearTruth(pitch=pitch, initial_error=0.001 * pitch)
    runs = []
    for letter, truth, settings, support in WEAR_RUNS:
        run_id = f"W16-{letter}"
        pin = WEAR_PIN if support == "pinned" else {**WEAR_PIN, "pin_support": support}
        runs.append(WearRunSpec(
            id=run_id, chain="16B", truth=base.with_(**truth), seed=int(rng.integers(2**31)),
            file=run_id + WEAR_SUFFIXES[settings["layout"]], pin=pin, **settings))
    campaign = CampaignSpec(
        id="wear-demo",
        title="Wear and life of a 16B roller chain (Paper 004's pin criterion beside)",
        lab="Chain drive laboratory (virtual)",
        machine="Chain wear rig (virtual)",
        note="Synthetic data made with `chainbench simulate demo`: wear logs of roller "
             "chain 16B from the virtual wear bench of `chainbench simulate wear`, with "
             "known wear rate and life. Not measurements.",
    )
    return write_wear_campaign(folder, runs, campaign)


#: The demo campaigns by folder name, and their writers.
DEMOS: dict[str, Callable[[str | Path], Path]] = {
    "stiffness-demo": write_stiffness_demo,
    "engagement-demo": write_engagement_demo,
    "pull-demo": write_pull_demo,
    "wear-demo": write_wear_demo,
    "segment-load-demo": write_segment_load_demo,
    "roller-demo": write_roller_demo,
}
