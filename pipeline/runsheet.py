"""The run sheet (``campaign.toml``) validated into typed objects.

A campaign folder holds the machine exports and one run sheet; see
``formats.md``. Validation follows two rules that matter to a lab:

* every error names the file, the key path (``runs[3].gauge_length_mm``) and
  what was expected, as a :class:`~pipeline.errors.RunSheetError`;
* one bad run entry does not stop the campaign: it lands in
  :attr:`RunSheet.invalid_runs` and the other runs are processed.

Campaign-level faults (TOML syntax, the ``[campaign]`` table, a chain or wheel
definition) make the whole sheet invalid, since no run could be trusted.

Nothing from the sheet is executed: it is read with :mod:`tomllib`, and every
run file must resolve inside the campaign folder.
"""

from __future__ import annotations

import hashlib
import tomllib
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    ValidationError,
    model_validator,
)

from pipeline.catalog import chain as catalog_chain
from pipeline.errors import RunSheetError
from pipeline.units import to_si

RUN_SHEET_NAME = "campaign.toml"
#: Ids become file and folder names: letters, digits, '.', '_', '-' (and not only dots).
SAFE_ID = r"^[A-Za-z0-9._-]+$"
#: ``stiffness_from``: ``<campaign>/<chain>``, both safe names (it names a processed folder).
SAFE_REFERENCE = r"^[A-Za-z0-9._-]+/[A-Za-z0-9._-]+$"


def _no_dot_names(value: str | None) -> str | None:
    if value is not None and any(set(part) == {"."} for part in value.split("/")):
        raise ValueError("'.' and '..' are not names: they would point to another folder")
    return value


PositiveFloat = Annotated[float, Field(gt=0, allow_inf_nan=False)]
SafeId = Annotated[str, Field(pattern=SAFE_ID, max_length=100), AfterValidator(_no_dot_names)]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class CampaignInfo(_Strict):
    """The ``[campaign]`` table."""

    id: SafeId
    title: str = ""
    lab: str = ""
    machine: str = ""
    synthetic: bool = False  #: data made by the virtual test bench, not a machine
    note: str = ""
    #: the lab's band for (E0_exp - E0_theory) / E0_theory [%] (Paper 001: 3 to 6 %)
    discrepancy_band_pct: tuple[float, float] = (3.0, 6.0)

    @model_validator(mode="after")
    def _ordered_band(self) -> CampaignInfo:
        low, high = self.discrepancy_band_pct
        if not low < high:
            raise ValueError("discrepancy_band_pct must be [low, high] with low < high")
        return self


class ChainDef(_Strict):
    """A ``[chains.<key>]`` table; missing values come from the catalogue entry."""

    catalog: str | None = None
    d_mm: PositiveFloat | None = None
    t_mm: PositiveFloat | None = None
    R0_mm: PositiveFloat | None = None
    a_mm: PositiveFloat | None = None
    mass_kg_per_m: PositiveFloat | None = None
    E_steel_kgf_per_cm2: PositiveFloat = 2.2e6
    preload_kgf: PositiveFloat | None = None
    upper_load_kgf: PositiveFloat | None = None
    # acceptance limits of the standard the lab tests to (checked only when declared)
    proof_force_kN: PositiveFloat | None = None  #: proof (manufacturing test) force
    min_breaking_force_kN: PositiveFloat | None = None  #: smallest breaking force allowed
    max_elongation_at_proof_pct: PositiveFloat | None = None  #: largest elongation at proof force
    min_elongation_at_fracture_pct: PositiveFloat | None = None  #: smallest elongation at fracture

    @model_validator(mode="after")
    def _known_catalog(self) -> ChainDef:
        if self.catalog is not None:
            try:
                catalog_chain(self.catalog)
            except KeyError as error:
                raise ValueError(str(error.args[0])) from None
        return self

    def si(self) -> dict[str, float | None]:
        """Geometry and mass in SI units, the run sheet's values over the catalogue's."""
        spec = catalog_chain(self.catalog) if self.catalog else None
        from_catalog = (lambda key: spec.get(key)) if spec else (lambda key: None)
        values = {
            "d": self.d_mm, "t": self.t_mm, "R0": self.R0_mm, "a": self.a_mm,
        }
        result: dict[str, float | None] = {
            key: to_si(value, "mm") if value is not None else from_catalog(key)
            for key, value in values.items()
        }
        result["mass_per_length"] = (
            self.mass_kg_per_m if self.mass_kg_per_m is not None
            else from_catalog("mass_per_length")
        )
        result["E_steel"] = to_si(self.E_steel_kgf_per_cm2, "kgf/cm^2")
        for key, value in (("preload", self.preload_kgf), ("upper_load", self.upper_load_kgf)):
            result[key] = to_si(value, "kgf") if value is not None else from_catalog(key)
        return result


class WheelDef(_Strict):
    """A ``[wheels.<key>]`` table."""

    teeth: int = Field(ge=3)
    apex_angle_deg: float = Field(gt=0, lt=180)


class ColumnMap(_Strict):
    """Roles -> the file's column names (or TDMS ``Channel`` / ``Group/Channel``)."""

    time: str | None = None
    force: str | None = None
    gauges: list[str] | None = None
    angle: str | None = None


class UnitMap(_Strict):
    """Roles -> units, for files whose header carries none (``gauges``: one for all, or
    one per gauge column)."""

    time: str | None = None
    force: str | None = None
    gauges: str | list[str] | None = None
    angle: str | None = None


class FitWindow(_Strict):
    """An explicit stiffness fit window, as forces in kN (default: chosen automatically)."""

    force_low_kN: float = Field(ge=0)
    force_high_kN: PositiveFloat

    @model_validator(mode="after")
    def _ordered(self) -> FitWindow:
        if self.force_high_kN <= self.force_low_kN:
            raise ValueError("force_high_kN must be above force_low_kN")
        return self


class RunDef(_Strict):
    """One ``[[runs]]`` entry."""

    id: SafeId
    kind: Literal["tensile", "engagement"]
    file: str = Field(min_length=1)
    chain: str
    format: Literal["auto", "csv", "xlsx", "tdms"] = "auto"
    sheet: str | None = None
    columns: ColumnMap | None = None
    units: UnitMap | None = None
    note: str = ""
    # tensile runs
    specimen: str | None = None
    #: length the gauges measure over; not needed when every channel used is a strain
    gauge_length_mm: PositiveFloat | None = None
    #: load cycles of the test; 1 is a single pull (E0 from the first loading)
    cycles: int | None = Field(default=None, ge=1)
    fit_window: FitWindow | None = None
    #: True: the gauge channels measure the same thing, average them; False: never average
    average_gauges: bool | None = None
    #: proof force of a proof-load test (default: the chain's ``proof_force_kN``)
    proof_force_kN: PositiveFloat | None = None
    #: strain offset of the yield-like force (offset method, like Rp0.2) [%]
    yield_offset_pct: PositiveFloat = 0.2
    # engagement runs
    wheel: str | None = None
    branch_length_m: PositiveFloat | None = None
    omega_per_s: PositiveFloat | None = None
    rpm: PositiveFloat | None = None
    E0_N: PositiveFloat | None = None
    stiffness_from: Annotated[str | None, Field(pattern=SAFE_REFERENCE),
                              AfterValidator(_no_dot_names)] = None
    clip_level_kN: PositiveFloat | None = None

    @model_validator(mode="after")
    def _kind_fields(self) -> RunDef:
        if self.kind == "engagement":
            missing = [key for key in ("wheel", "branch_length_m") if getattr(self, key) is None]
            if missing:
                raise ValueError(f"an engagement run needs {', '.join(missing)}")
            if (self.omega_per_s is None) == (self.rpm is None):
                raise ValueError("an engagement run needs exactly one of omega_per_s or rpm")
        return self

    @property
    def omega(self) -> float | None:
        """Wheel angular velocity [1/s] from ``omega_per_s`` or ``rpm``."""
        if self.omega_per_s is not None:
            return self.omega_per_s
        return to_si(self.rpm, "rpm") if self.rpm is not None else None


class RunSheet(BaseModel):
    """A validated run sheet and where it came from."""

    model_config = ConfigDict(arbitrary_types_allowed=True, frozen=True)

    path: Path
    sha256: str
    campaign: CampaignInfo
    chains: dict[str, ChainDef]
    wheels: dict[str, WheelDef]
    runs: list[RunDef]
    invalid_runs: list[RunSheetError]
    entries: dict[str, dict[str, Any]]  #: the raw TOML table of each valid run, by id

    @property
    def folder(self) -> Path:
        return self.path.parent

    def run_file(self, run: RunDef) -> Path:
        """The run's raw file, resolved inside the campaign folder."""
        return resolve_inside(self.folder, run.file)


def resolve_inside(folder: Path, relative: str) -> Path:
    """`relative` resolved against `folder`, refusing anything that leaves it.

    Raises
    ------
    ValueError
        For absolute paths and paths that resolve outside `folder` (``../``,
        links pointing out).
    """
    if Path(relative).is_absolute():
        raise ValueError(f"{relative!r} is an absolute path; give it relative to the campaign")
    base = folder.resolve()
    target = (base / relative).resolve()
    if not target.is_relative_to(base):
        raise ValueError(f"{relative!r} leaves the campaign folder")
    return target


def _key_path(prefix: str, location: tuple) -> str:
    path = prefix
    for part in location:
        path += f"[{part}]" if isinstance(part, int) else (f".{part}" if path else str(part))
    return path


def _error(sheet: Path, prefix: str, error: ValidationError) -> RunSheetError:
    first = error.errors()[0]
    return RunSheetError(
        first["msg"],
        file=sheet,
        column=_key_path(prefix, first["loc"]),
        hint=f"got {first.get('input')!r}" if "input" in first else None,
    )


def _validate(model: type[BaseModel], data: Any, sheet: Path, prefix: str):
    try:
        return model.model_validate(data)
    except ValidationError as error:
        raise _error(sheet, prefix, error) from None


def _cross_check(run: RunDef, position: str, sheet: Path, chains: dict, wheels: dict) -> None:
    if run.chain not in chains:
        raise RunSheetError(
            f"unknown chain {run.chain!r}", file=sheet, column=f"{position}.chain",
            hint=f"define [chains.{run.chain}] or use one of: {', '.join(chains) or 'none'}",
        )
    if run.wheel is not None and run.wheel not in wheels:
        raise RunSheetError(
            f"unknown wheel {run.wheel!r}", file=sheet, column=f"{position}.wheel",
            hint=f"define [wheels.{run.wheel}] or use one of: {', '.join(wheels) or 'none'}",
        )
    try:
        resolve_inside(sheet.parent, run.file)
    except ValueError as error:
        raise RunSheetError(
            str(error), file=sheet, column=f"{position}.file",
            hint="run files must lie in the campaign folder",
        ) from None


def load_run_sheet(path: str | Path) -> RunSheet:
    """Read and validate a run sheet.

    Parameters
    ----------
    path : str or Path
        The ``campaign.toml`` file, or the campaign folder holding it.

    Returns
    -------
    RunSheet
        Valid runs in ``runs``; entries that failed in ``invalid_runs``.

    Raises
    ------
    RunSheetError
        When the sheet as a whole cannot be used (missing, not TOML, bad
        ``[campaign]``, ``[chains]`` or ``[wheels]`` tables).
    """
    path = Path(path)
    sheet = path / RUN_SHEET_NAME if path.is_dir() else path
    try:
        raw_bytes = sheet.read_bytes()
    except OSError as error:
        raise RunSheetError(
            f"cannot read the run sheet ({error.strerror})", file=sheet,
            hint=f"a campaign folder needs a {RUN_SHEET_NAME}",
        ) from None
    try:
        data = tomllib.loads(raw_bytes.decode("utf-8"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise RunSheetError(
            f"not a valid TOML file: {error}", file=sheet, hint="check the line named above"
        ) from None

    unknown = set(data) - {"campaign", "chains", "wheels", "runs"}
    if unknown:
        raise RunSheetError(
            f"unknown top-level key(s) {sorted(unknown)}", file=sheet,
            hint="expected [campaign], [chains.*], [wheels.*] and [[runs]]",
        )
    campaign = _validate(CampaignInfo, data.get("campaign", {}), sheet, "campaign")
    chains = {
        key: _validate(ChainDef, value, sheet, f"chains.{key}")
        for key, value in data.get("chains", {}).items()
    }
    wheels = {
        key: _validate(WheelDef, value, sheet, f"wheels.{key}")
        for key, value in data.get("wheels", {}).items()
    }

    runs: list[RunDef] = []
    invalid: list[RunSheetError] = []
    entries: dict[str, dict[str, Any]] = {}
    raw_runs = data.get("runs", [])
    if not isinstance(raw_runs, list) or not raw_runs:
        raise RunSheetError(
            "the run sheet lists no runs", file=sheet, column="runs",
            hint="add one [[runs]] table per machine export",
        )
    for index, entry in enumerate(raw_runs):
        position = f"runs[{index}]"
        try:
            run = _validate(RunDef, entry, sheet, position)
            _cross_check(run, position, sheet, chains, wheels)
            if run.id in entries:
                raise RunSheetError(
                    f"duplicate run id {run.id!r}", file=sheet, column=f"{position}.id",
                    hint="every run needs its own id: it names the output file",
                )
        except RunSheetError as error:
            invalid.append(error)
            continue
        runs.append(run)
        entries[run.id] = entry

    return RunSheet(
        path=sheet, sha256=hashlib.sha256(raw_bytes).hexdigest(), campaign=campaign,
        chains=chains, wheels=wheels, runs=runs, invalid_runs=invalid, entries=entries,
    )
