"""The figures a lab reports for a tensile specimen, beside its stiffness.

From a conditioned run (:class:`~pipeline.condition.tensile.TensileRun`) and the
fit of its first loading (:func:`~pipeline.fit.stiffness.fit_stiffness`):

* the maximum (breaking) force, and the elongation and strain there;
* the force, elongation and strain at fracture (the last sample before the
  sudden drop, :func:`~pipeline.condition.breaks.find_fracture`), total
  elongation under load;
* the yield-like force by the offset method: where the first loading leaves
  the fitted line by a strain offset (0.2 % by default, as for Rp0.2),
  interpolated between samples;
* for a proof-load test, the elongation at the proof force on the first
  loading, and the permanent set after the cycle that reached it.

Elongations are measured on the channels that gave E0, from the zero the lab
set during the test (a gauge zeroed at the preload), else from their reading
where the first loading starts, as an extensometer zeroed there reads them: a
crosshead position or a gauge that did not start at zero counts no length the
specimen did not gain. Where those channels stop before the point (an extensometer taken off
before fracture), the next usable channel in the order of
:data:`~pipeline.condition.channels.PREFERENCE` is read instead, and the
figure says which.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field

import numpy as np
import pandas as pd

from pipeline.condition.channels import PREFERENCE
from pipeline.condition.tensile import TensileRun

#: Default strain offset of the yield-like force [1] (0.2 %, as for Rp0.2).
YIELD_OFFSET = 0.002


@dataclass(frozen=True)
class Strength:
    """Figures of one tensile specimen (SI units; NaN where not reached or not measured)."""

    max_force: float  #: largest force before fracture [N]
    strain_at_max_force: float  #: [1]
    elongation_at_max_force: float  #: [m]
    fracture_force: float  #: force at the last sample before fracture [N]
    strain_at_fracture: float  #: [1]
    elongation_at_fracture: float  #: [m]
    yield_force: float  #: where the first loading leaves the line by `yield_offset` [N]
    yield_offset: float  #: strain offset of the yield-like force [1]
    proof_force: float  #: proof force of a proof-load test [N]
    strain_at_proof: float  #: [1]
    elongation_at_proof: float  #: [m]
    permanent_strain_after_proof: float  #: [1]
    permanent_set_after_proof: float  #: [m]
    #: the file's column(s) each elongation was read on, when not the E0 channels
    sources: dict[str, str] = field(default_factory=dict)

    def as_dict(self) -> dict:
        """The figures as a plain dict."""
        return asdict(self)


def _fallback_strains(run: TensileRun) -> list[tuple[str, str]]:
    """(channel, column) of the usable channels not used for E0, preferred first."""
    found = []
    for kind in PREFERENCE:
        for name, channel in run.channels.iterrows():
            if channel["used"] or channel["kind"] != kind or name not in run.channel_strains:
                continue
            found.append((str(name), str(channel["column"])))
    return found


def _strain_at(run: TensileRun, position: int, figure: str,
               sources: dict[str, str]) -> float:
    """Strain at a sample from the start of the test (:func:`_start`), on the E0 channels
    or the next usable one."""
    used = run.channels.index[run.channels["used"]]
    value = float(run.samples["strain"].iloc[position]) - float(
        np.mean([_start(run, name) for name in used]))
    if np.isfinite(value):
        return value
    for name, column in _fallback_strains(run):
        value = float(run.channel_strains[name].iloc[position]) - _start(run, name)
        if np.isfinite(value):
            sources[figure] = column
            return value
    return np.nan


def _start(run: TensileRun, channel: str) -> float:
    """Where a channel's strain counts from [1]: its zero when the lab zeroed it during the
    record (at a preload, say), else its first reading from where the first loading
    starts (a position read from the machine's own zero, a gauge not zeroed)."""
    if run.channels.loc[channel, "zeroed"]:
        return 0.0
    strain = run.channel_strains[channel].to_numpy()
    first = int(run.segmentation.turns[0][0]) if run.segmentation.n_cycles else 0
    finite = np.flatnonzero(np.isfinite(strain[first:]))
    return float(strain[first + finite[0]]) if finite.size else np.nan


def _crossing(force: np.ndarray, level: float) -> int | None:
    """First position where `force` reaches `level`, or None."""
    above = np.flatnonzero(force >= level)
    return int(above[0]) if above.size else None


def _interpolate(position: int, before: float, after: float, values: np.ndarray) -> float:
    """The value at the fraction where a quantity crosses zero between two samples."""
    if position == 0 or after == before:
        return float(values[position])
    share = -before / (after - before)
    return float(values[position - 1] + share * (values[position] - values[position - 1]))


def _yield_force(run: TensileRun, fit: pd.Series | None, offset: float) -> float:
    """Offset method on the first loading: force where strain - line strain reaches `offset`."""
    if fit is None or not fit["E0"] > 0:
        return np.nan
    first = run.segmentation.turns[0]
    span = slice(int(first[0]), int(first[1]) + 1)
    force = run.sign * run.samples["force"].to_numpy()[span]
    strain = run.sign * run.samples["strain"].to_numpy()[span]
    excess = strain - (force - fit["intercept"]) / fit["E0"] - offset
    beyond = np.flatnonzero((force > fit["window_high"]) & np.isfinite(excess))
    crossed = beyond[excess[beyond] >= 0]
    if not crossed.size:
        return np.nan
    position = int(crossed[0])
    return _interpolate(position, excess[position - 1], excess[position], force)


def specimen_strength(
    run: TensileRun,
    fits: pd.DataFrame,
    *,
    yield_offset: float = YIELD_OFFSET,
    proof_force: float | None = None,
) -> Strength:
    """The figures a lab reports for a tensile specimen (module docstring).

    Parameters
    ----------
    run : TensileRun
        The conditioned run.
    fits : pandas.DataFrame
        Its stiffness fits; the ``(1, "loading")`` fit gives the line of the
        offset method.
    yield_offset : float
        Strain offset of the yield-like force [1] (0.002 = 0.2 %).
    proof_force : float, optional
        Proof force of a proof-load test [N], magnitude in the direction of the load.

    Returns
    -------
    Strength
        Forces as magnitudes in the direction of the load, elongations and
        strains likewise (positive when the specimen lengthens under tension).
    """
    sources: dict[str, str] = {}
    force = run.sign * run.samples["force"].to_numpy()
    end = force.size if run.fracture is None else run.fracture + 1
    peak = int(np.argmax(force[:end]))
    length = run.gauge_length

    def strain(position: int, figure: str) -> float:
        return run.sign * _strain_at(run, position, figure, sources)

    at_max = strain(peak, "at maximum force")
    at_fracture = np.nan if run.fracture is None else strain(run.fracture, "at fracture")
    fit = fits.loc[(1, "loading")] if (1, "loading") in fits.index else None
    proof = np.nan if proof_force is None else float(proof_force)
    at_proof = permanent = np.nan
    if proof_force is not None:
        first = run.segmentation.turns[0]  # the loading and its hold: a proof force is held
        reached = _crossing(force[int(first[0]) : int(first[2]) + 1],
                            proof_force - run.segmentation.tolerance)
        if reached is not None:
            position = int(first[0]) + reached
            at_proof = strain(position, "at proof force")
            cycles = run.cycles
            permanent = float(cycles["permanent_strain"].iloc[0]) if len(cycles) else np.nan
    return Strength(
        max_force=float(force[peak]),
        strain_at_max_force=at_max,
        elongation_at_max_force=at_max * length,
        fracture_force=np.nan if run.fracture is None else float(force[run.fracture]),
        strain_at_fracture=at_fracture,
        elongation_at_fracture=at_fracture * length,
        yield_force=_yield_force(run, fit, yield_offset),
        yield_offset=float(yield_offset),
        proof_force=proof,
        strain_at_proof=at_proof,
        elongation_at_proof=at_proof * length,
        permanent_strain_after_proof=permanent,
        permanent_set_after_proof=permanent * length,
        sources=sources,
    )
