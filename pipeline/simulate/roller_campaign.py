"""Write synthetic roller-engagement campaigns: a roller chain on sprockets, with known xi.

:func:`write_roller_campaign` simulates each run (:class:`RollerRunSpec`: one
speed of one sprocket) on the virtual roller bench
(:func:`pipeline.simulate.roller_engagement.simulate_roller_engagement`),
writes its log as CSV or TDMS (the engagement writers, :data:`ENGAGEMENT_WRITERS`),
the run sheet with its ``[sprockets.*]`` tables (:class:`SprocketSpec`) and
``truth.json``, as :mod:`pipeline.simulate.campaign` does for the other kinds;
:func:`write_roller_demo` writes the ``roller-demo`` campaign of ``raw/``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from pipeline.fit.roller_engagement import Sprocket
from pipeline.simulate.campaign import (
    ENGAGEMENT_WRITERS,
    CampaignSpec,
    campaign_folder,
    chain_key,
    check_run,
    run_sheet_text,
    toml_key,
    toml_table,
    write_sheet_and_truth,
)
from pipeline.simulate.roller_engagement import (
    CHAIN_16B,
    RollerEngagementTruth,
    simulate_roller_engagement,
)
from pipeline.units import from_si, to_si


@dataclass(frozen=True)
class SprocketSpec:
    """A ``[sprockets.<key>]`` table of a synthetic campaign.

    Parameters
    ----------
    key : str
        Its run-sheet key.
    teeth : int
        Number of teeth z [-].
    module_mm : float, optional
        Module m of the cutting tool [mm] (with `profile_angle_deg`; None: no
        involute geometry, xi only measured).
    profile_angle_deg : float, optional
        Profile angle alpha of the cutting tool [deg].
    g_lim_J_per_mm2 : float
        The lab's limit of the specific impact energy [J/mm^2].
    """

    key: str
    teeth: int
    module_mm: float | None = None
    profile_angle_deg: float | None = None
    g_lim_J_per_mm2: float = 3e-4

    def table(self) -> dict[str, int | float]:
        """The keys of its run-sheet table."""
        values = {"teeth": self.teeth, "module_mm": self.module_mm,
                  "profile_angle_deg": self.profile_angle_deg,
                  "g_lim_J_per_mm2": self.g_lim_J_per_mm2}
        return {key: value for key, value in values.items() if value is not None}


@dataclass(frozen=True)
class RollerRunSpec:
    """One roller-engagement run (one speed of one sprocket) to simulate and write.

    Parameters
    ----------
    id : str
        Run id in the run sheet.
    chain : str
        Catalogue roller chain (e.g. ``"16B"``); ``truth.branch`` should carry
        its pitch, mass per metre and roller.
    sprocket : SprocketSpec
        The sprocket (``truth.teeth`` its teeth).
    truth : RollerEngagementTruth
        Branch, true xi and measurement.
    omega : float
        Sprocket angular velocity of the run [rad/s].
    seed : int
        Seed of the log's randomness.
    file : str
        File name in the campaign folder.
    format : str
        ``"csv"`` or ``"tdms"`` (:data:`ENGAGEMENT_WRITERS`).
    """

    id: str
    chain: str
    sprocket: SprocketSpec
    truth: RollerEngagementTruth
    omega: float
    seed: int
    file: str
    format: str = "csv"

    def __post_init__(self) -> None:
        check_run(self.id, self.file)
        if self.format not in ENGAGEMENT_WRITERS:
            raise ValueError(f"run {self.id}: format must be one of "
                             f"{', '.join(ENGAGEMENT_WRITERS)}, got {self.format!r}")
        if self.sprocket.teeth != self.truth.teeth:
            raise ValueError(f"run {self.id}: the sprocket has {self.sprocket.teeth} teeth, "
                             f"the truth {self.truth.teeth}")

    def entry(self) -> dict[str, str | float]:
        """The run's ``[[runs]]`` entry of the run sheet (speed in rpm)."""
        return {"id": self.id, "kind": "roller-engagement", "file": self.file,
                "chain": chain_key(self.chain), "sprocket": self.sprocket.key,
                "branch_length_m": float(self.truth.branch.branch_length),
                "rpm": round(float(from_si(self.omega, "rpm")), 9),
                "E0_N": float(self.truth.branch.E0)}


def write_roller_campaign(out: str | Path, runs: Sequence[RollerRunSpec],
                          campaign: CampaignSpec) -> Path:
    """Simulate and write a roller-engagement campaign: logs, run sheet and ``truth.json``.

    Parameters
    ----------
    out : str or Path
        Campaign folder (created; files of the same names are replaced).
    runs : sequence of RollerRunSpec
        The runs, in run-sheet order (unique ids and file names).
    campaign : CampaignSpec
        The ``[campaign]`` table.

    Returns
    -------
    Path
        The run sheet written. ``truth.json`` holds per run its file, format,
        chain, sprocket, seed, ``xi`` and ``teeth``, the speed ``omega``
        [rad/s] and the truth of the virtual bench (``amplitude`` [N],
        ``impact_velocity`` [m/s], the strikes...).

    Raises
    ------
    ValueError
        For an empty or duplicated run list, or two sprockets of one key.
    """
    out = campaign_folder(out, runs)
    sprockets = {run.sprocket.key: run.sprocket for run in runs}
    if len(set(sprockets.values())) != len(sprockets):
        raise ValueError("two different sprockets share a key")
    truths = {}
    for run in runs:
        table, truth = simulate_roller_engagement(run.truth, run.omega, run.seed)
        ENGAGEMENT_WRITERS[run.format](table, out / run.file)
        truths[run.id] = {"file": run.file, "format": run.format, "chain": run.chain,
                          "sprocket": run.sprocket.key, "seed": run.seed, "xi": run.truth.xi,
                          "teeth": run.truth.teeth, "omega": run.omega,
                          "branch": asdict(run.truth.branch), **truth}
    text = run_sheet_text(campaign, [run.chain for run in runs], [])
    for key, sprocket in sprockets.items():
        text += "\n".join(toml_table(f"[sprockets.{toml_key(key)}]", sprocket.table())) + "\n"
    text += "\n".join(line for run in runs for line in toml_table("[[runs]]", run.entry()))
    return write_sheet_and_truth(out, campaign, text + "\n", truths)


#: Seed of the ``roller-demo`` campaign.
ROLLER_SEED = 2026

#: The roller demo's sprockets, their true xi (None: the involute's) and speeds [rpm].
ROLLER_DEMO = (
    (SprocketSpec("z18-involute", 18, module_mm=8.0, profile_angle_deg=20.0), None,
     (100.0, 200.0, 300.0), "csv"),
    (SprocketSpec("z12-gost", 12, g_lim_J_per_mm2=3e-5), 0.6, (150.0, 250.0, 350.0), "tdms"),
)


def write_roller_demo(folder: str | Path) -> Path:
    """Write the ``roller-demo`` campaign (roller chain 16B on two sprockets) into `folder`.

    Parameters
    ----------
    folder : str or Path
        Campaign folder (created; the demo's files are replaced).

    Returns
    -------
    Path
        The run sheet written.
    """
    rng = np.random.default_rng(ROLLER_SEED)
    runs = []
    for sprocket, xi, speeds, file_format in ROLLER_DEMO:
        if xi is None:
            xi = Sprocket(sprocket.teeth, module=to_si(sprocket.module_mm, "mm"),
                          profile_angle=math.radians(sprocket.profile_angle_deg)
                          ).involute_xi(CHAIN_16B.pitch)[0]
        truth = RollerEngagementTruth(teeth=sprocket.teeth, xi=xi)
        for rpm in speeds:
            run_id = f"R{sprocket.teeth}-{rpm:g}"
            runs.append(RollerRunSpec(
                id=run_id, chain="16B", sprocket=sprocket, truth=truth,
                omega=float(to_si(rpm, "rpm")), seed=int(rng.integers(2**31)),
                file=f"{run_id}.{file_format}", format=file_format))
    campaign = CampaignSpec(
        id="roller-demo",
        title="Roller chain 16B on two sprockets: measured xi against Paper 002",
        lab="Chain drive laboratory (virtual)",
        machine="Sprocket rig (virtual)",
        note="Synthetic data made with `chainbench simulate demo`: branch-tension logs of "
             "roller chain 16B from the virtual roller bench of `chainbench simulate "
             "roller-engagement`, with known xi. Not measurements.",
    )
    return write_roller_campaign(folder, runs, campaign)
