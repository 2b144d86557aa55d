"""Segment-load campaigns of the virtual bench: logs, run sheet and ``truth.json``.

:func:`write_segment_table` writes one log of
:func:`pipeline.simulate.segment_load.simulate_segment_load` in a layout the
readers take (``docs/file-formats.md``); :func:`write_segment_campaign` writes
a campaign of runs (:class:`SegmentRunSpec`) on one drum (:class:`DrumSpec`),
each run one operating point (a chain-force level), with the drum's true
geometry and the true ratios in ``truth.json``. The run sheet declares the
drum's geometry with the fitted parameter at a stated value, not the truth.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.simulate.campaign import (
    CampaignSpec,
    campaign_folder,
    chain_key,
    check_run,
    run_sheet_text,
    toml_table,
    write_sheet_and_truth,
)
from pipeline.simulate.export import FORCE_UNITS, WEAR_LAYOUTS, WEAR_SUFFIXES, write_log
from pipeline.simulate.segment_load import SegmentLoadTruth, simulate_segment_load
from pipeline.units import from_si

#: File layouts of segment-load logs (those of wear logs: the delimited ones, xlsx, TDMS).
SEGMENT_LAYOUTS = WEAR_LAYOUTS
#: File name suffix of each layout.
SEGMENT_SUFFIXES = WEAR_SUFFIXES

#: Column names per naming scheme: plain (also the workbook's and the TDMS channels'),
#: European Polish and German, the rig's own short names.
SEGMENT_NAMES = {
    "plain": {"time": "time", "F": "chain force", "F_K1": "segment force 1",
              "F_K2": "segment force 2", "F_P": "side force"},
    "pl": {"time": "Czas", "F": "Siła w łańcuchu", "F_K1": "Siła segmentu 1",
           "F_K2": "Siła segmentu 2", "F_P": "Siła boczna"},
    "de": {"time": "Zeit", "F": "Kettenkraft", "F_K1": "Segmentkraft 1",
           "F_K2": "Segmentkraft 2", "F_P": "Seitenkraft"},
    "machine": {"time": "Time", "F": "Force", "F_K1": "F_K1", "F_K2": "F_K2", "F_P": "F_P"},
}


def write_segment_table(table: pd.DataFrame, path: str | Path, *, layout: str = "plain",
                        force_unit: str = "kN", language: str = "pl") -> Path:
    """Write a segment-load log (SI, :func:`simulate_segment_load`) as a raw file.

    Parameters
    ----------
    table : pandas.DataFrame
        ``time`` [s], ``F``, ``F_K1``, ``F_K2`` and optionally ``F_P`` [N].
    path : str or Path
        File to write (replaced atomically if it exists).
    layout : str
        One of :data:`SEGMENT_LAYOUTS`, with the names of :data:`SEGMENT_NAMES`.
    force_unit : str
        Unit of every force (:data:`~pipeline.simulate.export.FORCE_UNITS`);
        time in s.
    language : str
        Column names of the European layout: ``"pl"`` or ``"de"``.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        On an unknown layout, unit or language.
    """
    if force_unit not in FORCE_UNITS:
        raise ValueError(f"force_unit must be one of {', '.join(FORCE_UNITS)}")
    units = {role: "s" if role == "time" else force_unit for role in SEGMENT_NAMES["plain"]}
    return write_log(table, path, units, SEGMENT_NAMES, layout=layout, language=language)


@dataclass(frozen=True)
class DrumSpec:
    """The drum of a segment-load campaign as its run sheet declares it.

    Parameters
    ----------
    key : str
        Run-sheet key ``[drums.<key>]``.
    fitted : {"s", "beta"}
        The parameter fitted to the measured ratios.
    declared : float
        The run sheet's value of the fitted parameter [m for s, rad for beta];
        the other is written at its true value.
    """

    key: str
    fitted: str = "s"
    declared: float = 55e-3

    def entry(self, truth: SegmentLoadTruth) -> dict[str, float | str]:
        """The ``[drums.<key>]`` table for the true geometry `truth`."""
        geometry = {"s": truth.s, "beta": truth.beta, self.fitted: self.declared}
        return {"groove_width_mm": from_si(truth.groove_width, "mm"),
                "contact_distance_mm": from_si(geometry["s"], "mm"),
                "flank_inclination_deg": math.degrees(geometry["beta"]),
                "link_inclination_deg": math.degrees(truth.eps_n), "fitted": self.fitted}


@dataclass(frozen=True)
class SegmentRunSpec:
    """One segment-load run (one operating point) to simulate and write.

    Parameters
    ----------
    id : str
        Run id in the run sheet.
    chain : str
        Catalogue chain with a torus radius (``"34x126"``); `truth` should carry
        its ``r_outer`` and ``d``.
    truth : SegmentLoadTruth
        Geometry, load (one chain-force level) and measurement.
    seed : int
        Seed of the log's noise.
    file : str
        File name in the campaign folder.
    layout, force_unit, language
        How the log is written (:func:`write_segment_table`).
    """

    id: str
    chain: str
    truth: SegmentLoadTruth
    seed: int
    file: str
    layout: str = "plain"
    force_unit: str = "kN"
    language: str = "pl"

    def __post_init__(self) -> None:
        check_run(self.id, self.file)

    def entry(self, drum: str) -> dict[str, str]:
        """The run's ``[[runs]]`` entry of the run sheet."""
        return {"id": self.id, "kind": "segment-load", "file": self.file,
                "chain": chain_key(self.chain), "drum": drum}


def write_segment_campaign(out: str | Path, runs: Sequence[SegmentRunSpec], drum: DrumSpec,
                           campaign: CampaignSpec) -> Path:
    """Simulate and write a segment-load campaign: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of SegmentRunSpec
        The runs, in run-sheet order, all of the drum's true geometry.
    drum : DrumSpec
        The drum as the run sheet declares it.
    campaign : CampaignSpec
        The ``[campaign]`` table.

    Returns
    -------
    Path
        The run sheet written. ``truth.json`` holds per run its file, chain,
        layout, seed, ``truth`` (the :class:`SegmentLoadTruth` fields, SI) and
        the true ``contact_force_ratio``, ``side_force_ratio``,
        ``friction_increase`` [1], ``s`` [m] and ``beta`` [rad].

    Raises
    ------
    ValueError
        For an empty or duplicated run list, or runs of different geometries.
    """
    out = campaign_folder(out, runs)
    geometry = {(run.truth.r_outer, run.truth.d, run.truth.groove_width, run.truth.s,
                 run.truth.beta, run.truth.eps_n) for run in runs}
    if len(geometry) > 1:
        raise ValueError("the runs of one drum must share its geometry")
    truths = {}
    for run in runs:
        write_segment_table(simulate_segment_load(run.truth, run.seed), out / run.file,
                            layout=run.layout, force_unit=run.force_unit,
                            language=run.language)
        truth = run.truth
        truths[run.id] = {"file": run.file, "chain": run.chain, "layout": run.layout,
                          "seed": run.seed, "truth": asdict(truth),
                          "contact_force_ratio": truth.contact_force_ratio,
                          "side_force_ratio": truth.side_force_ratio,
                          "friction_increase": truth.friction_increase,
                          "s": truth.s, "beta": truth.beta}
    text = run_sheet_text(campaign, [run.chain for run in runs],
                          [run.entry(drum.key) for run in runs])
    text += "\n".join(toml_table(f"[drums.{drum.key}]", drum.entry(runs[0].truth))) + "\n"
    return write_sheet_and_truth(out, campaign, text, truths)


def demo_runs(chain: str, truth: SegmentLoadTruth, levels: Sequence[float],
              layouts: Sequence[str], seed: int, prefix: str) -> list[SegmentRunSpec]:
    """One run per chain-force level [N], in the layouts in turn, with seeds from `seed`.

    Parameters
    ----------
    chain : str
        Catalogue chain.
    truth : SegmentLoadTruth
        The runs' truth but their chain-force level.
    levels : sequence of float
        Chain-force level of each run [N].
    layouts : sequence of str
        Layouts of :data:`SEGMENT_LAYOUTS`, used in turn.
    seed : int
        Seed of the runs' seeds.
    prefix : str
        Run ids are ``<prefix>-<n>`` (n from 1).
    """
    rng = np.random.default_rng(seed)
    runs = []
    for number, level in enumerate(levels, start=1):
        layout = layouts[(number - 1) % len(layouts)]
        run_id = f"{prefix}-{number}"
        runs.append(SegmentRunSpec(
            id=run_id, chain=chain, truth=truth.with_(chain_force=(float(level),)),
            seed=int(rng.integers(2**31)), file=run_id + SEGMENT_SUFFIXES[layout],
            layout=layout))
    return runs


#: Seed of the segment-load demo.
DEMO_SEED = 2011
#: The demo's chain-force levels, one run each [N]: 50 to 150 kN.
DEMO_LEVELS = (50e3, 75e3, 100e3, 125e3, 150e3)
#: The demo's layouts, in turn.
DEMO_LAYOUTS = ("plain", "european", "xlsx", "tdms", "machine")


def write_segment_load_demo(folder: str | Path) -> Path:
    """Write the ``segment-load-demo`` campaign into `folder`.

    Chain 34x126 on a drum with a groove of 45 mm, true s = 60 mm at
    beta = 50 deg, eps_n = 0 (Paper 003, section 3); five runs of 30 seatings
    (one a second, logged at 200 Hz) at 50 to 150 kN in five layouts, the last
    one without the side force. The run sheet declares s = 55 mm and fits s.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    truth = SegmentLoadTruth(seating_rate=1.0, plateau=0.4, transition=0.1, sample_rate=200.0)
    runs = demo_runs("34x126", truth, DEMO_LEVELS, DEMO_LAYOUTS, DEMO_SEED, "S34")
    runs[-1] = SegmentRunSpec(**{**asdict(runs[-1]),
                                 "truth": runs[-1].truth.with_(with_side_force=False)})
    campaign = CampaignSpec(
        id="segment-load-demo",
        title="Loads on the segments of a chain-drum tooth, chain 34x126 (Paper 003)",
        lab="Mining chain laboratory (virtual)",
        machine="Drum rig with strain-gauged tooth segments (virtual)",
        note="Synthetic data made with `chainbench simulate demo`: segment-load logs from "
             "the virtual bench of `chainbench simulate segment-load`, with known contact "
             "geometry (s = 60 mm) and load ratios. Not measurements.")
    return write_segment_campaign(folder, runs, DrumSpec("D34"), campaign)
