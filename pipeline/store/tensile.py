"""The dataset of one tensile run, built from the stages' outputs.

Layout (``formats.md``): per sample ``time``, ``force`` [N], ``elongation``
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


def _flags(values: np.ndarray, meanings: tuple[str, ...]) -> tuple[np.ndarray, dict]:
    codes = pd.Categorical(values, categories=meanings).codes.astype("int8")
    attrs = {
        "flag_values": np.arange(len(meanings), dtype="int8"),
        "flag_meanings": " ".join(meanings),
        "long_name": "branch of the load cycle",
    }
    return codes, attrs


def _samples(run: TensileRun) -> xr.Dataset:
    samples = run.samples
    gauges = [name for name in samples.columns if re.fullmatch(r"gauge_\d+", name)]
    branch, branch_attrs = _flags(samples["branch"].astype(str).to_numpy(), BRANCHES)
    variables = {
        "force": ("sample", samples["force"].to_numpy(), {"units": "N", "long_name": "force"}),
        "elongation": ("sample", samples["elongation"].to_numpy(),
                       {"units": "m", "long_name": "mean elongation of the gauges"}),
        "gauge_elongation": (("sample", "gauge"), samples[gauges].to_numpy(),
                             {"units": "m", "long_name": "elongation read by each gauge"}),
        "strain": ("sample", samples["strain"].to_numpy(),
                   {"units": "1", "long_name": "relative elongation over the gauge length"}),
        "sample_cycle": ("sample", samples["cycle"].to_numpy().astype("int16"),
                  {"units": "1", "long_name": "load cycle (0 before the first loading)"}),
        "sample_branch": ("sample", branch, branch_attrs),
    }
    if "time" in samples:
        variables["time"] = ("sample", samples["time"].to_numpy(),
                             {"units": "s", "long_name": "time since the start of the log"})
    return xr.Dataset(variables, coords={"gauge": gauges})


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
            "peak_force": ("cycle", cycles["peak_force"].to_numpy(),
                           {"units": "N", "long_name": "peak force of the cycle"}),
        },
        coords={"cycle": cycles.index.to_numpy()},
    )


def tensile_dataset(
    run: TensileRun,
    fits: pd.DataFrame,
    specimen: SpecimenStiffness,
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
    dataset = xr.merge([_samples(run), _fits(fits), _cycles(run)], join="outer",
                       combine_attrs="override")
    for name, (units, long_name) in SPECIMEN_VARIABLES.items():
        dataset[f"specimen_{name}"] = ((), getattr(specimen, name),
                                       {"units": units, "long_name": long_name})
    dataset["gauge_length"] = ((), run.gauge_length, {"units": "m", "long_name": "gauge length"})
    dataset["gauge_disagreement"] = ((), run.gauge_disagreement, {
        "units": "1", "long_name": "gauge spread per unit mean elongation (bending)"})
    dataset.attrs.update(attrs)
    dataset["specimen_n_cycles"] = ((), specimen.n_cycles, {
        "units": "1", "long_name": "loading branches counted in the specimen stiffness"})
    dataset.attrs["warnings"] = "; ".join(run.warnings)
    return dataset


def specimen_from(dataset: Mapping) -> SpecimenStiffness:
    """The specimen's stiffness as stored by :func:`tensile_dataset` (the inverse).

    `dataset` is the run's dataset or any mapping of its scalar variables
    (:func:`pipeline.store.netcdf.read_scalars`).
    """
    values = {name: float(dataset[f"specimen_{name}"]) for name in SPECIMEN_VARIABLES}
    return SpecimenStiffness(n_cycles=int(dataset["specimen_n_cycles"]), **values)
