"""Write a generated large campaign for the benchmarks (virtual test benches, known truth).

Two campaign folders under ``--out``:

``bench-tensile``
    16 tensile runs: chains 13x50, 14x50, 18x64 and 22x86, four specimens each,
    three cycles between Paper 001's preload and upper force (as the
    ``stiffness-demo``), logged at ``tensile_rate``, written as plain CSV,
    European CSV (kgf, cp1250) and machine exports in turn.
``bench-engagement``
    Many engagement runs of an 18x64 chain on a 2 m branch (z = 6, 8, 10; apex
    angles 20 to 60 deg; omega 10 to 30 1/s) at 20 kHz, TDMS and CSV in turn,
    three in four with the wheel-angle channel: ``runs`` logs of ``samples``
    samples and ``large_runs`` logs of ``large_samples`` samples.

Sizes (:data:`SIZES`): ``quick`` (a minute or so to write and to process) and
``full`` (several 10^7-sample logs: the real figures)::

    .venv/bin/python bench/large_campaign.py --out /tmp/large           # full
    .venv/bin/python bench/large_campaign.py --out /tmp/large --quick

:func:`write_many_small` writes instead one campaign of many small runs of both
kinds (the growth benchmark, ``bench/bench_growth.py``)::

    .venv/bin/python bench/large_campaign.py --out /tmp/many --many 100

:func:`write_one_long` writes instead ``bench-one-long``, a campaign dominated
by one long log (one CSV log of ``large_samples``, four of ``samples``), where
only the log's chunks as tasks let two workers share the work::

    .venv/bin/python bench/large_campaign.py --out /tmp/large --one-long
"""

from __future__ import annotations

import argparse
import json
import math
import time
import tomllib
from pathlib import Path
from typing import NamedTuple

import numpy as np

from pipeline.runsheet import RUN_SHEET_NAME
from pipeline.simulate.campaign import (
    TRUTH_NAME,
    CampaignSpec,
    EngagementRunSpec,
    TensileRunSpec,
    engagement_settings,
    run_sheet_text,
    write_engagement_campaign,
    write_tensile_campaign,
)
from pipeline.simulate.demo import LOADING_RATES_KGF_PER_S
from pipeline.simulate.tensile import TensileTruth
from pipeline.units import to_si

#: Seed of the generated campaign.
SEED = 4242

#: Sampling rate of the engagement logs [Hz].
ENGAGEMENT_RATE = 20e3

#: Tensile log layouts, in turn: (layout, force unit); European logs in Polish (cp1250).
TENSILE_FORMATS = (("plain", "kN"), ("european", "kgf"), ("machine", "N"))


class CampaignSize(NamedTuple):
    """How big the generated campaign is."""

    tensile_rate: float  #: logging rate of the tensile runs [Hz]
    runs: int  #: engagement runs of `samples` samples
    samples: int
    large_runs: int  #: engagement runs of `large_samples` samples
    large_samples: int


SIZES = {
    "quick": CampaignSize(tensile_rate=10.0, runs=16, samples=200_000,
                          large_runs=2, large_samples=2_000_000),
    "full": CampaignSize(tensile_rate=100.0, runs=48, samples=1_000_000,
                         large_runs=4, large_samples=10_000_000),
}


class Campaigns(NamedTuple):
    """The folders of the generated campaign."""

    tensile: Path
    engagement: Path


def write_tensile(folder: Path, rate: float, rng: np.random.Generator) -> Path:
    """Write the 16-run tensile campaign into `folder`; return the run sheet."""
    runs = []
    for chain, loading_rate in LOADING_RATES_KGF_PER_S.items():
        base = TensileTruth.for_chain(chain, sample_rate=rate,
                                      loading_rate=to_si(loading_rate, "kgf/s"))
        for letter in "ABCD":
            layout, force_unit = TENSILE_FORMATS[len(runs) % len(TENSILE_FORMATS)]
            run_id = f"T{chain.replace('x', '-')}-{letter}"
            runs.append(TensileRunSpec(
                id=run_id, chain=chain, specimen=f"{chain}-{letter}",
                truth=base.with_(E0=base.E0 * (1.0 + rng.uniform(-0.004, 0.004)),
                                 gauge_length=to_si(float(rng.integers(896, 905)), "mm")),
                seed=int(rng.integers(2**31)), file=f"{run_id}.csv", layout=layout,
                force_unit=force_unit))
    campaign = CampaignSpec(id="bench-tensile", title="Benchmark: 16 tensile runs",
                            note="Synthetic benchmark campaign (bench/large_campaign.py).")
    return write_tensile_campaign(folder, runs, campaign)


def write_engagement(folder: Path, size: CampaignSize, rng: np.random.Generator,
                     campaign_id: str = "bench-engagement",
                     formats: tuple[str, str] = ("tdms", "csv")) -> Path:
    """Write the engagement campaign of `size` into `folder`, its files in `formats` in
    turn; return the run sheet."""
    lengths = [size.large_samples] * size.large_runs + [size.samples] * size.runs
    runs = []
    for index, samples in enumerate(lengths):
        z, apex = (6, 8, 10)[index % 3], (20, 40, 60)[index // 3 % 3]
        omega = (10.0, 15.0, 20.0, 25.0, 30.0)[index % 5]
        settings = engagement_settings(
            "18x64", z=z, psi=math.radians(apex), omega=omega, E0=2.26e7, branch_length=2.0,
            sample_rate=ENGAGEMENT_RATE, duration=(samples - 1) / ENGAGEMENT_RATE, snr=20.0,
            amplitude_scatter=0.02, with_angle=index % 4 != 3)
        run_id = f"E{index + 1:03d}"
        file_format = formats[index % 2]
        runs.append(EngagementRunSpec(
            id=run_id, chain="18x64", settings=settings, seed=int(rng.integers(2**31)),
            file=f"{run_id}.{file_format}", format=file_format))
    campaign = CampaignSpec(
        id=campaign_id,
        title=f"Benchmark: {len(runs)} engagement runs, {size.large_runs} of "
              f"{size.large_samples:.0e} samples",
        note="Synthetic benchmark campaign (bench/large_campaign.py).")
    return write_engagement_campaign(folder, runs, campaign)


def write_one_long(folder: Path, size: CampaignSize) -> Path:
    """Write a campaign dominated by one long log into `folder`: one CSV log of
    ``size.large_samples`` samples and four of ``size.samples`` (the scale-out of a long
    log's chunks, ``bench/SCALE_OUT.md``); return the run sheet."""
    return write_engagement(folder, size._replace(runs=4, large_runs=1),
                            np.random.default_rng(SEED), "bench-one-long", ("csv", "tdms"))


def write_campaign(out: Path, size: CampaignSize) -> Campaigns:
    """Write both campaigns of `size` under `out`."""
    rng = np.random.default_rng(SEED)
    campaigns = Campaigns(out / "bench-tensile", out / "bench-engagement")
    write_tensile(campaigns.tensile, size.tensile_rate, rng)
    write_engagement(campaigns.engagement, size, rng)
    return campaigns


#: The small runs of :func:`write_many_small`: tensile logging rate [Hz], engagement
#: sampling rate [Hz] and engagement log length [s] (the engagement demo's: at least
#: 11 seating periods a run).
SMALL_TENSILE_RATE, SMALL_ENGAGEMENT_RATE, SMALL_ENGAGEMENT_SECONDS = 5.0, 5e3, 1.2


def small_tensile_runs(count: int, rng: np.random.Generator) -> list[TensileRunSpec]:
    """`count` short cyclic tensile runs (``T0001``...), the chains of Paper 001 in turn."""
    chains = list(LOADING_RATES_KGF_PER_S)
    runs = []
    for index in range(count):
        chain = chains[index % len(chains)]
        base = TensileTruth.for_chain(chain, sample_rate=SMALL_TENSILE_RATE,
                                      loading_rate=to_si(LOADING_RATES_KGF_PER_S[chain],
                                                         "kgf/s"))
        run_id = f"T{index + 1:04d}"
        runs.append(TensileRunSpec(
            id=run_id, chain=chain, specimen=f"{chain}-{index // len(chains) + 1}",
            truth=base.with_(E0=base.E0 * (1.0 + rng.uniform(-0.004, 0.004)),
                             gauge_length=to_si(float(rng.integers(896, 905)), "mm")),
            seed=int(rng.integers(2**31)), file=f"{run_id}.csv"))
    return runs


def small_engagement_runs(count: int, rng: np.random.Generator) -> list[EngagementRunSpec]:
    """`count` short engagement logs (``E0001``...) of an 18x64 chain, CSV: z = 6, 8, 10,
    apex angles 20 to 60 deg and omega 10 to 30 1/s in turn."""
    runs = []
    for index in range(count):
        z, apex = (6, 8, 10)[index % 3], (20, 40, 60)[index // 3 % 3]
        settings = engagement_settings(
            "18x64", z=z, psi=math.radians(apex), omega=(10.0, 20.0, 30.0)[index // 9 % 3],
            E0=2.26e7, branch_length=2.0, sample_rate=SMALL_ENGAGEMENT_RATE,
            duration=SMALL_ENGAGEMENT_SECONDS, snr=20.0, amplitude_scatter=0.02)
        run_id = f"E{index + 1:04d}"
        runs.append(EngagementRunSpec(id=run_id, chain="18x64", settings=settings,
                                      seed=int(rng.integers(2**31)), file=f"{run_id}.csv",
                                      format="csv"))
    return runs


def _sheet(folder: Path) -> dict:
    with open(folder / RUN_SHEET_NAME, "rb") as stream:
        return tomllib.load(stream)


def write_many_small(folder: Path, runs: int, campaign_id: str) -> Path:
    """Write one campaign of `runs` small runs, half tensile and half engagement.

    Parameters
    ----------
    folder : Path
        Campaign folder (created).
    runs : int
        Number of runs (at least 2): ``runs // 2`` tensile, the others engagement.
    campaign_id : str
        The campaign id.

    Returns
    -------
    Path
        The run sheet written (both kinds of runs; ``truth.json`` of both beside it).
    """
    rng = np.random.default_rng(SEED)
    campaign = CampaignSpec(id=campaign_id, title=f"Benchmark: {runs} small runs",
                            note="Synthetic benchmark campaign (bench/large_campaign.py).")
    write_tensile_campaign(folder, small_tensile_runs(runs // 2, rng), campaign)
    tensile = _sheet(folder), json.loads((folder / TRUTH_NAME).read_text(encoding="utf-8"))
    write_engagement_campaign(folder, small_engagement_runs(runs - runs // 2, rng), campaign)
    engagement = _sheet(folder), json.loads((folder / TRUTH_NAME).read_text(encoding="utf-8"))
    chains = [table["catalog"] for sheet, _ in (tensile, engagement)
              for table in sheet["chains"].values()]
    wheels = {key: (table["teeth"], table["apex_angle_deg"])
              for key, table in engagement[0]["wheels"].items()}
    text = run_sheet_text(campaign, chains, tensile[0]["runs"] + engagement[0]["runs"], wheels)
    (folder / RUN_SHEET_NAME).write_text(text, encoding="utf-8")
    truth = {"campaign": campaign_id, "runs": {**tensile[1]["runs"], **engagement[1]["runs"]}}
    (folder / TRUTH_NAME).write_text(json.dumps(truth, indent=2) + "\n", encoding="utf-8")
    return folder / RUN_SHEET_NAME


def main() -> None:
    """Write the campaign and say where it is."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, required=True, help="folder to write into")
    parser.add_argument("--quick", action="store_true", help="the quick size")
    parser.add_argument("--many", type=int, metavar="N",
                        help="write instead one campaign of N small runs of both kinds")
    parser.add_argument("--one-long", action="store_true",
                        help="write instead one campaign dominated by one long log")
    args = parser.parse_args()
    start = time.perf_counter()
    size = SIZES["quick" if args.quick else "full"]
    if args.one_long:
        sheet = write_one_long(args.out / "bench-one-long", size)
        print(f"{sheet}: one CSV log of {size.large_samples:.0e} samples and four of "
              f"{size.samples:.0e}, written in {time.perf_counter() - start:.0f} s")
        return
    if args.many:
        sheet = write_many_small(args.out / f"bench-many-{args.many}", args.many,
                                 f"bench-many-{args.many}")
        print(f"{sheet}: {args.many} small runs, written in "
              f"{time.perf_counter() - start:.0f} s")
        return
    campaigns = write_campaign(args.out, size)
    print(f"{campaigns.tensile}: 16 tensile runs at {size.tensile_rate:g} Hz")
    print(f"{campaigns.engagement}: {size.runs} engagement logs of {size.samples:.0e} samples "
          f"and {size.large_runs} of {size.large_samples:.0e}")
    print(f"written in {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
