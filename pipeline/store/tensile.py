"""The dataset of one tensile run, built from the stages' outputs.

Layout (``docs/outputs.md``): per sample ``time``, ``force`` [N], ``elongation``
[m] (mean of the gauges), ``gauge_elongation(sample, gauge)`` [m], ``strain``,
``sample_cycle`` and ``sample_branch`` (CF flags; named apart from the
``cycle`` and ``branch`` dimensions of the fits); per fit on ``(cycle, branch)`` the stiffness
``E0`` [N] with its standard error, interval, window and quality figures; per
cycle ``hysteresis_energy`` [J] and ``permanent_set`` [m]; the specimen's E0
(mean loading stiffness of cycles 2..n) as scalars.
"""

from __future__ import annotations

import re
from collections.abc import Mapping

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.condition.segmentation import BRANCHES
from pipeline.condition.tensile import TensileRun
from pipeline.fit.stiffness import SpecimenStiffness
from pipeline.fit.strength import Strength

#: units and long names of the per-fit columns of :func:`~pipeline.fit.stiffness.fit_stiffness`
FIT_VARIABLES = {
    "E0": ("N", "stiffness: slope of force over strain"),
    "E0_stderr": ("N", "standard error of E0 (autocorrelation and window corrected)"),
    "E0_stderr_ols": ("N", "ordinary least-squares standard error of E0"),
    "E0_ci_low": ("N", "lower limit of the 95 % interval of E0"),
    "E0_ci_high": ("N", "upper limit of the 95 % interval of E0"),
    "intercept": ("N", "force at zero strain of the fitted line"),
    "window_low": ("N", "lower force limit of the fit window"),
    "window_high": ("N", "upper force limit of the fit window"),
    "n_points": ("1", "samples in the fit window"),
    "n_eff": ("1", "effective number of independent samples in the window"),
    "dof": ("1", "degrees of freedom of the interval of E0"),
    "r2": ("1", "coefficient of determination of the fit"),
    "residual_rms": ("N", "root-mean-square residual of the fit"),
}

#: units and long names of the specimen scalars (:class:`SpecimenStiffness`)
SPECIMEN_VARIABLES = {
    "E0": ("N", "specimen stiffness: mean loading stiffness of cycles 2..n"),
    "E0_stderr": ("N", "standard error of the specimen stiffness"),
    "E0_ci_low": ("N", "lower limit of the 95 % interval of the specimen stiffness"),
    "E0_ci_high": ("N", "upper limit of the 95 % interval of the specimen stiffness"),
    "E0_first": ("N", "loading stiffness of the first (seating) cycle"),
    "E0_first_stderr": ("N", "standard error of the first-cycle stiffness"),
    "E0_unloading": ("N", "mean unloading stiffness of cycles 2..n"),
    "birge_ratio": ("1", "scatter of the counted cycles over their standard errors"),
    "dof": ("1", "degrees of freedom of the specimen's interval"),
}

#: units and long names of the specimen's strength figures (:class:`Strength`)
STRENGTH_VARIABLES = {
    "max_force": ("N", "maximum (breaking) force"),
    "strain_at_max_force": ("1", "strain at maximum force"),
    "elongation_at_max_force": ("m", "elongation at maximum force"),
    "fracture_force": ("N", "force at fracture (last sample before the sudden drop)"),
    "strain_at_fracture": ("1", "strain at fracture (total, under load)"),
    "elongation_at_fracture": ("m", "elongation at fracture (total, under load)"),
    "yield_force": ("N", "yield-like force: the first loading leaves its line by the offset"),
    "yield_offset": ("1", "strain offset of the yield-like force (offset method)"),
    "proof_force": ("N", "proof force of a proof-load test"),
    "strain_at_proof": ("1", "strain at the proof force on the first loading"),
    "elongation_at_proof": ("m", "elongation at the proof force on the first loading"),
    "permanent_strain_after_proof": ("1", "permanent strain after the proof-load cycle"),
    "permanent_set_after_proof": ("m", "permanent set after the proof-load cycle"),
}


def _flags(values: np.ndarray, meanings: tuple[str, ...]) -> tuple[np.ndarray, dict]:
    codes = pd.Categorical(values, categories=meanings).codes.astype("int8")
    attrs = {
        "flag_values": np.arange(len(meanings), dtype="int8"),
        "flag_meanings": " ".join(meanings),
        "long_name": "branch of the load cycle",
    }
    return codes, attrs


def _channels(run: TensileRun) -> xr.Dataset:
    channels = run.channels
    return xr.Dataset(
        {
            "channel_column": ("channel", channels["column"].astype(str).to_numpy(),
                               {"long_name": "the channel's column in the raw file"}),
            "channel_kind": ("channel", channels["kind"].astype(str).to_numpy(), {
                "long_name": "what the channel measures: extensometer, gauge or crosshead"}),
            "channel_used": ("channel", channels["used"].to_numpy().astype("int8"), {
                "long_name": "1 when the channel gives the specimen's strain",
                "flag_values": np.array([0, 1], dtype="int8"),
                "flag_meanings": "not_used used"}),
            "channel_stiffness": ("channel", channels["slope"].to_numpy(dtype=float), {
                "units": "N", "long_name": "slope of force over the channel's strain on the "
                "first loading between 10 and 40 % of its force range"}),
            "channel_removed_at": ("channel", channels["removed_at"].to_numpy().astype("int32"),
                                   {"units": "1", "long_name": "first sample where the channel "
                                    "stopped following the specimen (-1: never)"}),
            "channel_removal": ("channel", channels["removal"].astype(str).to_numpy(), {
                "long_name": "how the channel stopped following the specimen"}),
        },
        coords={"channel": channels.index.to_numpy().astype(str)},
    )


def _samples(run: TensileRun) -> xr.Dataset:
    samples = run.samples
    gauges = [name for name in samples.columns if re.fullmatch(r"gauge_\d+", name)]
    strains = [name for name in samples.columns if re.fullmatch(r"strain_\d+", name)]
    branch, branch_attrs = _flags(samples["branch"].astype(str).to_numpy(), BRANCHES)
    variables = {
        "force": ("sample", samples["force"].to_numpy(), {"units": "N", "long_name": "force"}),
        "elongation": ("sample", samples["elongation"].to_numpy(),
                       {"units": "m", "long_name": "mean elongation of the gauges"}),
        "gauge_elongation": (("sample", "gauge"), samples[gauges].to_numpy().reshape(
            len(samples), len(gauges)), {"units": "m",
                                         "long_name": "elongation read by each gauge"}),
        "gauge_strain": (("sample", "strain_gauge"), samples[strains].to_numpy().reshape(
            len(samples), len(strains)), {"units": "1",
                                          "long_name": "strain read by each strain channel"}),
        "strain": ("sample", samples["strain"].to_numpy(), {
            "units": "1", "long_name": "strain of the specimen: mean of the channels used"}),
        "sample_cycle": ("sample", samples["cycle"].to_numpy().astype("int16"),
                  {"units": "1", "long_name": "load cycle (0 before the first loading)"}),
        "sample_branch": ("sample", branch, branch_attrs),
    }
    if "time" in samples:
        variables["time"] = ("sample", samples["time"].to_numpy(),
                             {"units": "s", "long_name": "time since the start of the log"})
    return xr.Dataset(variables, coords={"gauge": gauges, "strain_gauge": strains})


def _fits(fits: pd.DataFrame) -> xr.Dataset:
    table = fits[list(FIT_VARIABLES)].to_xarray()
    for name, (units, long_name) in FIT_VARIABLES.items():
        table[name].attrs.update(units=units, long_name=long_name)
    return table.rename({name: f"fit_{name}" for name in FIT_VARIABLES})


def _cycles(run: TensileRun) -> xr.Dataset:
    cycles = run.cycles
    return xr.Dataset(
        {
            "hysteresis_energy": ("cycle", cycles["hysteresis_energy"].to_numpy(),
                                  {"units": "J", "long_name": "energy dissipated in the cycle"}),
            "permanent_set": ("cycle", cycles["permanent_set"].to_numpy(),
                              {"units": "m", "long_name": "permanent elongation after the cycle"}),
            "permanent_strain": ("cycle", cycles["permanent_strain"].to_numpy(),
                                 {"units": "1", "long_name": "permanent strain after the cycle"}),
            "peak_force": ("cycle", cycles["peak_force"].to_numpy(),
                           {"units": "N", "long_name": "peak force of the cycle"}),
        },
        coords={"cycle": cycles.index.to_numpy()},
    )


def tensile_dataset(
    run: TensileRun,
    fits: pd.DataFrame,
    specimen: SpecimenStiffness,
    strength: Strength,
    attrs: Mapping[str, str],
) -> xr.Dataset:
    """Assemble the dataset of one tensile run.

    Parameters
    ----------
    run : TensileRun
        The conditioned run.
    fits : pandas.DataFrame
        Per (cycle, branch) fits from :func:`~pipeline.fit.stiffness.fit_stiffness`.
    specimen : SpecimenStiffness
        The specimen's stiffness from :func:`~pipeline.fit.stiffness.specimen_stiffness`.
    strength : Strength
        The specimen's figures from :func:`~pipeline.fit.strength.specimen_strength`.
    attrs : mapping
        Global attributes (provenance, run identity).

    Returns
    -------
    xarray.Dataset
        Samples on ``sample``/``gauge``, fits on ``(cycle, branch)`` as
        ``fit_<name>``, per-cycle results, the specimen's scalars as
        ``specimen_<name>``.
    """
    # A cycle whose branches were too short to fit has no fits: outer join, NaN there.
    dataset = xr.merge([_samples(run), _fits(fits), _cycles(run), _channels(run)],
                       join="outer", combine_attrs="override")
    for name, (units, long_name) in SPECIMEN_VARIABLES.items():
        dataset[f"specimen_{name}"] = ((), getattr(specimen, name),
                                       {"units": units, "long_name": long_name})
    for name, (units, long_name) in STRENGTH_VARIABLES.items():
        dataset[name] = ((), getattr(strength, name), {"units": units, "long_name": long_name})
    dataset["single_pull"] = ((), np.int8(run.single_pull), {
        "long_name": "1 for a single pull (E0 from its one loading), 0 for a cyclic test"})
    dataset["fracture_sample"] = ((), np.int32(-1 if run.fracture is None else run.fracture), {
        "units": "1", "long_name": "last sample before fracture (-1: no fracture)"})
    dataset["gauge_length"] = ((), run.gauge_length, {"units": "m", "long_name": "gauge length"})
    dataset["gauge_disagreement"] = ((), run.gauge_disagreement, {
        "units": "1", "long_name": "gauge spread per unit mean elongation (bending)"})
    dataset.attrs.update(attrs)
    dataset["specimen_n_cycles"] = ((), specimen.n_cycles, {
        "units": "1", "long_name": "loading branches counted in the specimen stiffness"})
    dataset.attrs["warnings"] = "; ".join(run.warnings + [
        f"elongation {figure} read on {column!r} (the channels of E0 no longer read there)"
        for figure, column in strength.sources.items()])
    return dataset


def strength_from(dataset: Mapping) -> dict[str, float]:
    """The specimen's strength figures as stored by :func:`tensile_dataset` [SI]."""
    return {name: float(dataset[name]) for name in STRENGTH_VARIABLES}


def specimen_from(dataset: Mapping) -> SpecimenStiffness:
    """The specimen's stiffness as stored by :func:`tensile_dataset` (the inverse).

    `dataset` is the run's dataset or any mapping of its scalar variables
    (:func:`pipeline.store.netcdf.read_scalars`).
    """
    values = {name: float(dataset[f"specimen_{name}"]) for name in SPECIMEN_VARIABLES}
    return SpecimenStiffness(n_cycles=int(dataset["specimen_n_cycles"]), **values)
