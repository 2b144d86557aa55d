"""The result of one tensile run, and its dataset: the run file ``<run id>.nc``.

Layout (``docs/outputs.md``): per sample ``time``, ``force`` [N], ``elongation``
[m] (mean of the gauges), ``gauge_elongation(sample, gauge)`` [m], ``strain``,
``sample_cycle`` and ``sample_branch`` (CF flags; named apart from the
``cycle`` and ``branch`` dimensions of the fits); per fit on ``(cycle, branch)`` the stiffness
``E0`` [N] with its standard error, interval, window and quality figures; per
cycle ``hysteresis_energy`` [J] and ``permanent_set`` [m]; the specimen's E0
(mean loading stiffness of cycles 2..n) and strength figures as scalars.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass
from typing import Any

import numpy as np
import pandas as pd
import xarray as xr

from pipeline.condition.segmentation import BRANCHES
from pipeline.condition.tensile import TensileRun
from pipeline.fit.stiffness import SpecimenStiffness
from pipeline.fit.strength import Strength
from pipeline.results.notes import joined, lines

#: units and long names of the per-fit columns of :func:`~pipeline.fit.stiffness.fit_stiffness`
FIT_VARIABLES = {
    "E0": ("N", "stiffness: slope of force over strain"),
    "E0_stderr": ("N", "standard error of E0 (autocorrelation and window corrected)"),
    "E0_stderr_ols": ("N", "ordinary least-squares standard error of E0"),
    "E0_ci_low": ("N", "lower limit of the {level} interval of E0"),
    "E0_ci_high": ("N", "upper limit of the {level} interval of E0"),
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
    "E0_ci_low": ("N", "lower limit of the {level} interval of the specimen stiffness"),
    "E0_ci_high": ("N", "upper limit of the {level} interval of the specimen stiffness"),
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

#: Per-cycle columns of :attr:`TensileRun.cycles` that are stored: units and long names.
CYCLE_VARIABLES = {
    "hysteresis_energy": ("J", "energy dissipated in the cycle"),
    "permanent_set": ("m", "permanent elongation after the cycle"),
    "permanent_strain": ("1", "permanent strain after the cycle"),
    "peak_force": ("N", "peak force of the cycle: the median from the loading's end to the "
                   "unloading's start (its hold at the top)"),
}

#: Columns of :attr:`TensileRun.channels` that are stored, in order.
CHANNEL_COLUMNS = ("column", "kind", "used", "slope", "removed_at", "removal")

#: Global attributes written from the result's fields (the others are its :attr:`attrs`).
DERIVED_ATTRS = ("ingest_warnings", "warnings", "elongation_sources")


def _sample_columns(columns) -> list[str]:
    """The stored per-sample columns among `columns`, in the order of the run file."""
    gauges = [name for name in columns if re.fullmatch(r"gauge_\d+", name)]
    strains = [name for name in columns if re.fullmatch(r"strain_\d+", name)]
    head = ["time"] if "time" in columns else []
    return [*head, "force", "elongation", *gauges, *strains, "strain", "cycle", "branch"]


@dataclass(frozen=True, eq=False)
class TensileResult:
    """What one tensile run gave, as its run file holds it (SI units).

    Attributes
    ----------
    attrs : dict
        Global attributes: provenance (:func:`pipeline.store.netcdf.provenance_attrs`),
        the run's identity (``campaign``, ``run_id``, ``kind``, ``chain``,
        ``specimen``, ``layout``) and the fit's settings
        (:func:`pipeline.fit.stiffness.fit_settings`: ``confidence_level``,
        ``fit_window``).
    samples : pandas.DataFrame
        Per sample: ``time`` [s] (when the log has one), ``force`` [N],
        ``elongation`` [m], ``gauge_<n>`` [m], ``strain_<n>`` [1], ``strain``
        [1], ``cycle`` and ``branch`` (categorical, :data:`BRANCHES`).
    fits : pandas.DataFrame
        Per ``(cycle, branch)``: the columns of :data:`FIT_VARIABLES`.
    cycles : pandas.DataFrame
        Per cycle: the columns of :data:`CYCLE_VARIABLES`.
    channels : pandas.DataFrame
        Per displacement channel: the columns of :data:`CHANNEL_COLUMNS`.
    specimen : SpecimenStiffness
        The specimen's E0.
    strength : Strength
        The specimen's strength figures, with the channel each elongation was
        read on where not those of E0 (``sources``).
    single_pull : bool
        E0 comes from the one loading of a single pull.
    fracture : int or None
        Last sample before fracture (None: no fracture).
    gauge_length : float
        Gauge length [m].
    gauge_disagreement : float
        Gauge spread per unit mean elongation [1] (bending).
    warnings : tuple of str
        What conditioning decided or repaired, and where an elongation was read.
    ingest_warnings : tuple of str
        What the reader decided or repaired.
    """

    attrs: dict[str, Any]
    samples: pd.DataFrame
    fits: pd.DataFrame
    cycles: pd.DataFrame
    channels: pd.DataFrame
    specimen: SpecimenStiffness
    strength: Strength
    single_pull: bool
    fracture: int | None
    gauge_length: float
    gauge_disagreement: float
    warnings: tuple[str, ...] = ()
    ingest_warnings: tuple[str, ...] = ()

    @classmethod
    def of(cls, run: TensileRun, fits: pd.DataFrame, specimen: SpecimenStiffness,
           strength: Strength, attrs: dict[str, Any], ingest_warnings: list[str]
           ) -> TensileResult:
        """The result of the stages' outputs (the parts a run file stores).

        Parameters
        ----------
        run : TensileRun
            The conditioned run.
        fits : pandas.DataFrame
            Per (cycle, branch) fits from :func:`~pipeline.fit.stiffness.fit_stiffness`.
        specimen : SpecimenStiffness
            From :func:`~pipeline.fit.stiffness.specimen_stiffness`.
        strength : Strength
            From :func:`~pipeline.fit.strength.specimen_strength`.
        attrs : dict
            Provenance, identity and settings (see :attr:`attrs`).
        ingest_warnings : list of str
            The reader's warnings.
        """
        samples = run.samples[_sample_columns(run.samples.columns)].reset_index(drop=True)
        samples["branch"] = pd.Categorical(samples["branch"].astype(str), categories=BRANCHES)
        sources = [f"elongation {figure} read on {column!r} (the channels of E0 no longer "
                   "read there)" for figure, column in strength.sources.items()]
        return cls(
            attrs=dict(attrs), samples=samples, fits=fits[list(FIT_VARIABLES)],
            cycles=run.cycles[list(CYCLE_VARIABLES)].rename_axis("cycle"),
            channels=run.channels[list(CHANNEL_COLUMNS)].rename_axis("channel"),
            specimen=specimen, strength=strength, single_pull=bool(run.single_pull),
            fracture=run.fracture, gauge_length=float(run.gauge_length),
            gauge_disagreement=float(run.gauge_disagreement),
            warnings=(*run.warnings, *sources), ingest_warnings=tuple(ingest_warnings))

    @property
    def from_crosshead(self) -> bool:
        """E0 comes from the crosshead travel (every channel used is a crosshead's), which
        includes the machine's own compliance."""
        used = self.channels.loc[self.channels["used"], "kind"]
        return bool(len(used)) and bool((used == "crosshead").all())

    def global_attrs(self) -> dict[str, Any]:
        """The run file's global attributes: :attr:`attrs` and those of the fields."""
        return {**self.attrs, "ingest_warnings": joined(self.ingest_warnings),
                "warnings": joined(self.warnings),
                "elongation_sources": json.dumps(self.strength.sources, sort_keys=True)}

    def to_dataset(self) -> xr.Dataset:
        """The run file (layout in the module docstring and ``docs/outputs.md``)."""
        level = self.attrs["confidence_level"]
        # A cycle whose branches were too short to fit has no fits: outer join, NaN there.
        dataset = xr.merge([_samples(self.samples), _fits(self.fits, level),
                            _cycles(self.cycles), _channels(self.channels)],
                           join="outer", combine_attrs="override")
        for name, (units, long_name) in SPECIMEN_VARIABLES.items():
            dataset[f"specimen_{name}"] = ((), getattr(self.specimen, name),
                                           variable_attrs(units, long_name, name, level))
        for name, (units, long_name) in STRENGTH_VARIABLES.items():
            dataset[name] = ((), getattr(self.strength, name),
                             {"units": units, "long_name": long_name})
        dataset["single_pull"] = ((), np.int8(self.single_pull), {
            "long_name": "1 for a single pull (E0 from its one loading), 0 for a cyclic test"})
        dataset["fracture_sample"] = ((), np.int32(-1 if self.fracture is None
                                                   else self.fracture), {
            "units": "1", "long_name": "last sample before fracture (-1: no fracture)"})
        dataset["gauge_length"] = ((), self.gauge_length,
                                   {"units": "m", "long_name": "gauge length"})
        dataset["gauge_disagreement"] = ((), self.gauge_disagreement, {
            "units": "1", "long_name": "gauge spread per unit mean elongation (bending)"})
        dataset["specimen_n_cycles"] = ((), self.specimen.n_cycles, {
            "units": "1", "long_name": "loading branches counted in the specimen stiffness"})
        dataset.attrs.update(self.global_attrs())
        return dataset

    @classmethod
    def from_dataset(cls, dataset: xr.Dataset) -> TensileResult:
        """The result a run file holds (the inverse of :meth:`to_dataset`).

        Parameters
        ----------
        dataset : xarray.Dataset
            A tensile run file, loaded (:func:`pipeline.store.netcdf.read_dataset`).
        """
        attrs = {key: value for key, value in dataset.attrs.items() if key not in DERIVED_ATTRS}
        sources = json.loads(dataset.attrs["elongation_sources"])
        specimen = SpecimenStiffness(n_cycles=int(dataset["specimen_n_cycles"]), **{
            name: float(dataset[f"specimen_{name}"]) for name in SPECIMEN_VARIABLES})
        strength = Strength(**{name: float(dataset[name]) for name in STRENGTH_VARIABLES},
                            sources=sources)
        fracture = int(dataset["fracture_sample"])
        return cls(
            attrs=attrs, samples=_samples_of(dataset), fits=_fits_of(dataset),
            cycles=dataset[list(CYCLE_VARIABLES)].to_dataframe().dropna(how="all"),
            channels=_channels_of(dataset), specimen=specimen, strength=strength,
            single_pull=bool(int(dataset["single_pull"])),
            fracture=None if fracture < 0 else fracture,
            gauge_length=float(dataset["gauge_length"]),
            gauge_disagreement=float(dataset["gauge_disagreement"]),
            warnings=lines(dataset.attrs["warnings"]),
            ingest_warnings=lines(dataset.attrs["ingest_warnings"]))


def variable_attrs(units: str, long_name: str, name: str, level: float) -> dict[str, Any]:
    """A variable's attributes; an interval limit also carries its ``confidence_level``.

    Parameters
    ----------
    units : str
        UDUNITS spelling (``"N"``, ``"1"``).
    long_name : str
        What the variable is; ``{level}`` in it becomes the level (``"95 %"``).
    name : str
        The variable's name: one ending in ``_ci_low`` or ``_ci_high`` is an
        interval limit.
    level : float
        Confidence level of the interval [1].

    Examples
    --------
    >>> variable_attrs("N", "lower limit of the {level} interval of E0", "E0_ci_low", 0.95)
    {'units': 'N', 'long_name': 'lower limit of the 95 % interval of E0', 'confidence_level': 0.95}
    """
    if not name.endswith(("_ci_low", "_ci_high")):
        return {"units": units, "long_name": long_name}
    return {"units": units, "long_name": long_name.format(level=f"{100 * level:g} %"),
            "confidence_level": level}


def _samples(samples: pd.DataFrame) -> xr.Dataset:
    gauges = [name for name in samples.columns if re.fullmatch(r"gauge_\d+", name)]
    strains = [name for name in samples.columns if re.fullmatch(r"strain_\d+", name)]
    branch = samples["branch"].cat.codes.to_numpy().astype("int8")
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
        "sample_branch": ("sample", branch, {
            "flag_values": np.arange(len(BRANCHES), dtype="int8"),
            "flag_meanings": " ".join(BRANCHES), "long_name": "branch of the load cycle"}),
    }
    if "time" in samples:
        variables["time"] = ("sample", samples["time"].to_numpy(),
                             {"units": "s", "long_name": "time since the start of the log"})
    return xr.Dataset(variables, coords={"gauge": gauges, "strain_gauge": strains})


def _samples_of(dataset: xr.Dataset) -> pd.DataFrame:
    columns = {"force": dataset["force"].values, "elongation": dataset["elongation"].values}
    if "time" in dataset:
        columns = {"time": dataset["time"].values, **columns}
    for variable, dim in (("gauge_elongation", "gauge"), ("gauge_strain", "strain_gauge")):
        for position, name in enumerate(dataset[dim].values):
            columns[str(name)] = dataset[variable].values[:, position]
    meanings = dataset["sample_branch"].attrs["flag_meanings"].split()
    columns.update(strain=dataset["strain"].values,
                   cycle=dataset["sample_cycle"].values.astype("int64"),
                   branch=pd.Categorical.from_codes(dataset["sample_branch"].values,
                                                    categories=meanings))
    return pd.DataFrame(columns)


def _fits(fits: pd.DataFrame, level: float) -> xr.Dataset:
    table = fits[list(FIT_VARIABLES)].to_xarray()
    for name, (units, long_name) in FIT_VARIABLES.items():
        table[name].attrs.update(variable_attrs(units, long_name, name, level))
    return table.rename({name: f"fit_{name}" for name in FIT_VARIABLES})


def _fits_of(dataset: xr.Dataset) -> pd.DataFrame:
    table = dataset[[f"fit_{name}" for name in FIT_VARIABLES]].to_dataframe()
    table.columns = list(FIT_VARIABLES)
    table = table[table["E0"].notna()]  # the outer join's cycles without fits
    return table.astype({"n_points": "int64"})


def _cycles(cycles: pd.DataFrame) -> xr.Dataset:
    return xr.Dataset(
        {name: ("cycle", cycles[name].to_numpy(), {"units": units, "long_name": long_name})
         for name, (units, long_name) in CYCLE_VARIABLES.items()},
        coords={"cycle": cycles.index.to_numpy()},
    )


def _channels(channels: pd.DataFrame) -> xr.Dataset:
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


def _channels_of(dataset: xr.Dataset) -> pd.DataFrame:
    return pd.DataFrame({
        "column": dataset["channel_column"].values.astype(str),
        "kind": dataset["channel_kind"].values.astype(str),
        "used": dataset["channel_used"].values.astype(bool),
        "slope": dataset["channel_stiffness"].values.astype(float),
        "removed_at": dataset["channel_removed_at"].values.astype("int64"),
        "removal": dataset["channel_removal"].values.astype(str),
    }, index=pd.Index(dataset["channel"].values.astype(str), name="channel"))
