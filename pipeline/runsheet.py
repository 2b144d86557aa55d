"""The run sheet (``campaign.toml``) validated into typed objects.

A campaign folder holds the machine exports and one run sheet; see
``docs/run-sheet.md``. Validation follows three rules that matter to a lab:

* every error names the file, the key path (``runs[3].gauge_length_mm``) and
  what was expected, as a :class:`~pipeline.errors.RunSheetError`;
* values are taken as written, never converted: ``gauge_length_mm = "900"`` (a
  string) or ``synthetic = "yes"`` is an error, not a number or a boolean, and a
  number is no string (a TOML integer is a number: ``gauge_length_mm = 900``);
* one bad entry does not stop the campaign: a bad run lands in
  :attr:`RunSheet.invalid_runs`; a bad chain or wheel lands in
  :attr:`RunSheet.invalid_chains` or :attr:`RunSheet.invalid_wheels`, and every
  run that uses it in :attr:`RunSheet.invalid_runs`. The other runs are processed.

Sheet-level faults (TOML syntax, unknown top-level keys, the ``[campaign]``
table, no runs) make the whole sheet invalid, since no run could be trusted.

Nothing from the sheet is executed: it is read with :mod:`tomllib`, and every
run file must resolve inside the campaign folder.
"""

from __future__ import annotations

import hashlib
import math
import tomllib
from collections.abc import Callable, Collection
from pathlib import Path
from typing import Annotated, Any, Literal, TypeVar

from pydantic import (
    AfterValidator,
    BaseModel,
    ConfigDict,
    Field,
    StrictFloat,
    ValidationError,
    model_validator,
)

from pipeline.catalog import chain as catalog_chain
from pipeline.errors import RunSheetError
from pipeline.store.layout import RUN_SHEET_NAME, reserved_id_reason, unportable_name_reason
from pipeline.theory.tooth_segments import contact_radius
from pipeline.units import to_si

#: Ids become file and folder names: letters, digits, '.', '_', '-' (and not only dots).
SAFE_ID = r"^[A-Za-z0-9._-]+$"
#: ``stiffness_from``: ``<campaign>/<chain>``, both safe names (it names a processed folder).
SAFE_REFERENCE = r"^[A-Za-z0-9._-]+/[A-Za-z0-9._-]+$"
#: Largest |t - (a + 2 R0 - d)| of a chain, as a fraction of t [-], before its link
#: is taken not to close. Published tables round (the 22x86 row is off by 2 mm, 2.3 %,
#: which the theory only warns about); 10 % is a wrong value, such as a slipped unit.
GEOMETRY_MISMATCH_LIMIT = 0.10


def _no_dot_names(value: str | None) -> str | None:
    if value is not None and any(set(part) == {"."} for part in value.split("/")):
        raise ValueError("'.' and '..' are not names: they would point to another folder")
    return value


PositiveFloat = Annotated[float, Field(gt=0, allow_inf_nan=False)]
def _portable_name(value: str) -> str:
    reason = unportable_name_reason(value)
    if reason:
        raise ValueError(reason + ": it names the campaign's output folder")
    return value


SafeId = Annotated[str, Field(pattern=SAFE_ID, max_length=100), AfterValidator(_no_dot_names)]
#: A campaign id: a safe id that also names a folder on every system.
CampaignId = Annotated[SafeId, AfterValidator(_portable_name)]


class _Strict(BaseModel):
    """A run sheet table: unknown keys refused, values of the declared type only."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


class CampaignInfo(_Strict):
    """The ``[campaign]`` table."""

    id: CampaignId
    title: str = ""
    lab: str = ""
    machine: str = ""
    synthetic: bool = False  #: data made by the virtual test bench, not a machine
    note: str = ""
    #: the lab's band for (E0_exp - E0_theory) / E0_theory [%] (Paper 001: 3 to 6 %);
    #: a TOML array is a list, so the tuple takes one, but its items must be numbers
    discrepancy_band_pct: tuple[StrictFloat, StrictFloat] = Field((3.0, 6.0), strict=False)
    #: the testing machine's stated force capacity; forces above it are flagged [kN]
    machine_capacity_kN: PositiveFloat | None = None

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
    # roller chains: the pin of Paper 004's criterion (wear runs)
    pin_diameter_mm: PositiveFloat | None = None  #: nominal pin diameter d
    bush_length_mm: PositiveFloat | None = None  #: bush length l
    plate_span_mm: PositiveFloat | None = None  #: span l1 between the outer-plate mid-planes
    # roller chains: the roller of Paper 002's specific impact energy (roller-engagement runs)
    roller_diameter_mm: PositiveFloat | None = None  #: roller diameter D
    inner_width_mm: PositiveFloat | None = None  #: inner width B between the inner plates
    # round-link chains: the horizontal link on a segmented drum tooth (segment-load runs)
    torus_radius_mm: PositiveFloat | None = None  #: outer torus radius r of the link

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
            "r_outer": self.torus_radius_mm,
            "d": self.d_mm, "t": self.t_mm, "R0": self.R0_mm, "a": self.a_mm,
            "pin_diameter": self.pin_diameter_mm, "bush_length": self.bush_length_mm,
            "plate_span": self.plate_span_mm, "roller_diameter": self.roller_diameter_mm,
            "inner_width": self.inner_width_mm,
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


class SprocketDef(_Strict):
    """A ``[sprockets.<key>]`` table: the sprocket of roller-engagement runs (Paper 002).

    The involute geometry (``module_mm`` with ``profile_angle_deg``, or
    ``base_radius_mm``) gives the model's xi; without it xi is only measured.
    """

    teeth: int = Field(ge=6, lt=500)
    module_mm: PositiveFloat | None = None  #: module m of the cutting tool
    profile_angle_deg: float | None = Field(default=None, gt=0, lt=90)  #: its profile angle
    base_radius_mm: PositiveFloat | None = None  #: base-circle radius r_b, instead
    #: the lab's limit of the specific impact energy G_lim (Paper 002, eq. (8))
    g_lim_J_per_mm2: PositiveFloat = 3e-4

    @model_validator(mode="after")
    def _geometry(self) -> SprocketDef:
        if self.teeth % 2:
            raise ValueError(
                f"teeth = {self.teeth}: chainbench reads a roller log by pairing two successive "
                "strikes into one seating, which needs an even number of teeth; a sprocket of "
                "odd z cannot be processed yet")
        if (self.module_mm is None) != (self.profile_angle_deg is None):
            raise ValueError("give module_mm and profile_angle_deg together")
        if self.module_mm is not None and self.base_radius_mm is not None:
            raise ValueError("give module_mm and profile_angle_deg, or base_radius_mm, not both")
        return self


class DrumDef(_Strict):
    """A ``[drums.<key>]`` table: the segmented chain drum of segment-load runs (Paper 003).

    Which of s and beta the campaign's load ratios are fitted for is stated, never
    guessed; the other is held at its value here.
    """

    groove_width_mm: PositiveFloat  #: width c of the groove between a tooth's segments
    contact_distance_mm: PositiveFloat  #: distance s between the contact points K
    flank_inclination_deg: float = Field(gt=0, lt=180)  #: flank inclination beta at K
    link_inclination_deg: float = Field(default=0.0, gt=-90, lt=90)  #: eps_n
    #: the parameter fitted to the measured ratios: the contact distance s, or beta
    fitted: Literal["s", "beta"]

    def si(self) -> dict[str, float]:
        """``groove_width``, ``s`` [m], ``beta`` and ``eps_n`` [rad]."""
        return {"groove_width": to_si(self.groove_width_mm, "mm"),
                "s": to_si(self.contact_distance_mm, "mm"),
                "beta": to_si(self.flank_inclination_deg, "deg"),
                "eps_n": to_si(self.link_inclination_deg, "deg")}


class ColumnMap(_Strict):
    """Roles -> the file's column names (or TDMS ``Channel`` / ``Group/Channel``;
    ``gauges``: one name, or a list)."""

    time: str | None = None
    force: str | None = None
    gauges: str | list[str] | None = None
    angle: str | None = None
    cycle_count: str | None = None
    length: str | None = None
    speed: str | None = None
    segment_force_1: str | None = None
    segment_force_2: str | None = None
    side_force: str | None = None


class UnitMap(_Strict):
    """Roles -> units, for files whose header carries none (``gauges``: one for all, or
    one per gauge column)."""

    time: str | None = None
    force: str | None = None
    gauges: str | list[str] | None = None
    angle: str | None = None
    length: str | None = None
    speed: str | None = None
    segment_force_1: str | None = None
    segment_force_2: str | None = None
    side_force: str | None = None


class FitWindow(_Strict):
    """An explicit stiffness fit window, as forces in kN (default: chosen automatically)."""

    force_low_kN: float = Field(ge=0)
    force_high_kN: PositiveFloat

    @model_validator(mode="after")
    def _ordered(self) -> FitWindow:
        if self.force_high_kN <= self.force_low_kN:
            raise ValueError("force_high_kN must be above force_low_kN")
        return self


#: Keys a wear run must give.
WEAR_KEYS = ("section_pitches", "elongation_reference", "sprocket_teeth")
#: Keys of Paper 004's pin criterion, given all together (or none) on a wear run.
PIN_KEYS = ("max_link_force_kN", "pin_allowable_stress_MPa", "pin_wear_coefficient")
#: Chain quantities the pin criterion needs: the pin, the bush and the plates.
PIN_GEOMETRY = ("pin_diameter", "bush_length", "plate_span")
#: Chain quantities a roller-engagement run needs: pitch, mass per metre and the roller.
ROLLER_GEOMETRY = ("t", "mass_per_length", "roller_diameter", "inner_width")


class RunDef(_Strict):
    """One ``[[runs]]`` entry."""

    id: SafeId
    kind: Literal["tensile", "engagement", "wear", "roller-engagement",
                   "segment-load"]
    file: str = Field(min_length=1)
    chain: str
    format: Literal["auto", "csv", "xlsx", "ods", "xls", "tdms"] = "auto"
    sheet: str | None = None
    #: of several specimens side by side in the file, the one read: its label, or its
    #: place from 1 at the left
    specimen_in_file: str | int | None = None
    columns: ColumnMap | None = None
    units: UnitMap | None = None
    #: the rate the rows were sampled at, for a file with no time column [Hz]
    sample_rate_hz: PositiveFloat | None = None
    note: str = ""
    #: the run's values were checked by hand: plausibility flags (a probable unit slip)
    #: are shown but do not exclude the run
    accept_implausible: bool = False
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
    #: roller-engagement runs: the sprocket (``[sprockets.<key>]``) the roller chain runs on
    sprocket: str | None = None
    #: segment-load runs: the drum (``[drums.<key>]``) whose tooth segments are gauged
    drum: str | None = None
    #: relative disagreement of the two segments beyond which a seating is flagged [%]
    imbalance_tolerance_pct: PositiveFloat = 5.0
    # wear runs
    #: pitches N of the measured section (1: the log gives one pitch's elongation)
    section_pitches: int | None = Field(default=None, ge=1)
    #: what the elongation is counted from: the nominal pitch, or the first reading
    elongation_reference: Literal["nominal", "first"] | None = None
    #: teeth z of the driven sprocket: the allowed pitch growth of Paper 004, eq. (3)
    sprocket_teeth: int | None = Field(default=None, ge=3, lt=500)
    #: the lab's own limit of the pitch growth [% of the pitch], beside eq. (3)'s
    wear_limit_pct: PositiveFloat | None = None
    #: the wear model: chosen by the data ("auto"), or forced
    wear_model: Literal["auto", "run-in", "linear"] = "auto"
    #: the running coordinate of a log that has both time and cycles (default: time)
    wear_abscissa: Literal["time", "cycles"] | None = None
    #: largest force on a chain link F_max of Paper 004, eqs. (4)-(5)
    max_link_force_kN: PositiveFloat | None = None
    #: allowable bending stress of the pin [sigma_T] (Paper 004, eq. (5))
    pin_allowable_stress_MPa: PositiveFloat | None = None
    #: pin wear coefficient K_e of Paper 004, eq. (2) (the paper gives no value)
    pin_wear_coefficient: PositiveFloat | None = None
    #: support of the pin in the outer plates (Paper 004, eq. (4)): K = 1 or K = 3
    pin_support: Literal["pinned", "clamped"] = "pinned"

    @model_validator(mode="after")
    def _kind_fields(self) -> RunDef:
        if self.kind == "engagement":
            missing = [key for key in ("wheel", "branch_length_m") if getattr(self, key) is None]
            if missing:
                raise ValueError(f"an engagement run needs {', '.join(missing)}")
            if (self.omega_per_s is None) == (self.rpm is None):
                raise ValueError("an engagement run needs exactly one of omega_per_s or rpm")
        if self.kind == "roller-engagement":
            missing = [key for key in ("sprocket", "branch_length_m") if getattr(self, key) is None]
            if missing:
                raise ValueError(f"a roller-engagement run needs {', '.join(missing)}")
            if (self.omega_per_s is None) == (self.rpm is None):
                raise ValueError("a roller-engagement run needs exactly one of omega_per_s or rpm")
        if self.kind == "segment-load" and self.drum is None:
            raise ValueError("a segment-load run needs drum")
        if self.kind == "wear":
            missing = [key for key in WEAR_KEYS if getattr(self, key) is None]
            if missing:
                raise ValueError(f"a wear run needs {', '.join(missing)}")
            given = [key for key in PIN_KEYS if getattr(self, key) is not None]
            if given and len(given) < len(PIN_KEYS):
                raise ValueError(
                    "the pin criterion needs all of " + ", ".join(PIN_KEYS) + "; only "
                    + ", ".join(given) + " given (leave them all out to skip it)")
        return self

    @property
    def pin_criterion(self) -> bool:
        """Whether the run sheet asks for Paper 004's pin criterion (a wear run)."""
        return self.kind == "wear" and self.max_link_force_kN is not None

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
    chains: dict[str, ChainDef]  #: the valid chain definitions, by key
    wheels: dict[str, WheelDef]  #: the valid wheel definitions, by key
    runs: list[RunDef]
    invalid_runs: list[RunSheetError]
    #: the error of each invalid chain definition, by key, whether a run uses it or not
    invalid_chains: dict[str, RunSheetError]
    #: the error of each invalid wheel definition, by key, whether a run uses it or not
    invalid_wheels: dict[str, RunSheetError]
    entries: dict[str, dict[str, Any]]  #: the raw TOML table of each valid run, by id
    sprockets: dict[str, SprocketDef] = {}  #: the valid sprocket definitions, by key
    #: the error of each invalid sprocket definition, by key, whether a run uses it or not
    invalid_sprockets: dict[str, RunSheetError] = {}
    drums: dict[str, DrumDef] = {}  #: the valid drum definitions, by key
    #: the error of each invalid drum definition, by key, whether a run uses it or not
    invalid_drums: dict[str, RunSheetError] = {}

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


#: What a value had to be, by the pydantic error type that refused it.
_EXPECTED = {
    "float_type": "a number",
    "int_type": "a whole number",
    "bool_type": "true or false",
    "string_type": "a string",
    "list_type": "a list",
    "tuple_type": "a list",
    "model_type": "a table",
    "dict_type": "a table",
}


def _key_path(prefix: str, location: tuple) -> str:
    path = prefix
    for part in location:
        path += f"[{part}]" if isinstance(part, int) else (f".{part}" if path else str(part))
    return path


def _located(data: Any, error: dict) -> tuple:
    """Where `error` lies in `data`, without the names pydantic gives the members of a
    union (the ``str`` and ``list[str]`` of ``gauges.str``, ``gauges.list[str]``)."""
    kept: list[str | int] = []
    node = data
    for part in error["loc"]:
        if isinstance(node, dict) and (part in node or error["type"] == "missing"):
            kept.append(part)
            node = node.get(part)
        elif isinstance(node, list) and isinstance(part, int):
            kept.append(part)
            node = node[part]
    return tuple(kept)


def _first_problem(errors: list[dict], data: Any) -> tuple[tuple, list[dict]]:
    """The location of the first error in `data` and the errors found there.

    A value refused by every member of a union gives one error per member; the
    deepest of them (an item of a list, say) is the one that got furthest.
    """
    located = [(_located(data, error), error) for error in errors]
    first = located[0][0]
    inside = [(where, error) for where, error in located if where[: len(first)] == first]
    deepest = max(inside, key=lambda item: len(item[0]))[0]
    return deepest, [error for where, error in inside if where == deepest]


def _described(value: Any) -> str:
    """A TOML value as a technician wrote it: ``the string '900'``, ``the number 5``."""
    if isinstance(value, str):
        return f"the string {value!r}"
    if isinstance(value, bool):
        return f"the boolean {_toml_text(value)}"
    if isinstance(value, int | float):
        return f"the number {value!r}"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a table"
    return f"the value {value}"  # TOML dates and times


def _toml_text(value: Any) -> str:
    """A scalar TOML value as written in a sheet (``true``, not ``True``)."""
    return str(value).lower() if isinstance(value, bool) else str(value)


def _is_number(text: str) -> bool:
    """Whether `text` would be a number without its quotes."""
    try:
        float(text)
    except ValueError:
        return False
    return True


def _type_hint(name: str, expected: str, value: Any) -> str:
    """How to write `value` at key `name` as `expected` (a word of :data:`_EXPECTED`)."""
    if expected in ("a number", "a whole number"):
        if isinstance(value, str) and _is_number(value):
            return f"write {name} = {value.strip()} without quotes"
        if isinstance(value, float) and value.is_integer():
            return f"write {name} = {int(value)} without a decimal point"
        return f"write {name} as a number, without quotes"
    if expected == "true or false":
        return f"write {name} = true or {name} = false, without quotes"
    if expected == "a string" and not isinstance(value, list | dict):
        return f'write {name} = "{_toml_text(value)}" in quotes'
    if expected == "a string":
        return f"write {name} as a string in quotes"
    if expected == "a list":
        return f"write {name} as a list in brackets: {name} = [..., ...]"
    return "write it as a table of keys and values"


def _error(sheet: Path, prefix: str, error: ValidationError, data: Any) -> RunSheetError:
    where, found = _first_problem(error.errors(), data)
    column = _key_path(prefix, where)
    first = found[0]
    if first["type"] not in _EXPECTED:
        return RunSheetError(
            first["msg"].removeprefix("Value error, "), file=sheet, column=column,
            hint=f"got {first.get('input')!r}" if "input" in first else None,
        )
    expected = " or ".join(dict.fromkeys(
        _EXPECTED[each["type"]] for each in found if each["type"] in _EXPECTED))
    return RunSheetError(
        f"expected {expected}, got {_described(first['input'])}", file=sheet, column=column,
        hint=_type_hint(_key_path("", where), _EXPECTED[first["type"]], first["input"]),
    )


ModelT = TypeVar("ModelT", bound=BaseModel)


def _validate(model: type[ModelT], data: Any, sheet: Path, prefix: str) -> ModelT:
    try:
        return model.model_validate(data)
    except ValidationError as error:
        raise _error(sheet, prefix, error, data) from None


def _mm(value: float) -> str:
    """A length [m] as millimetres, for messages."""
    return f"{value * 1e3:.4g} mm"


def _geometry_fault(values: dict[str, float | None]) -> tuple[tuple[str, ...], str] | None:
    """Why a link of geometry `values` [m] (``ChainDef.si()``) cannot exist, or None.

    Only the known values are checked. A link must hold the bars of its two
    neighbours in its inner length (t > 2 d), let a neighbour's bar pass through its
    inner width (2 R0 - d > d), and close: t = a + 2 R0 - d within
    :data:`GEOMETRY_MISMATCH_LIMIT` of t.

    Returns
    -------
    tuple or None
        The quantities involved (``"t"``, ``"d"``...), the one most likely wrong
        first, and the reason.
    """
    d, t, R0, a = (values[key] for key in ("d", "t", "R0", "a"))
    if d is not None and t is not None and t <= 2 * d:
        return ("t", "d"), (f"its inner length t = {_mm(t)} is not above 2 d = {_mm(2 * d)}: "
                            "it cannot hold the bars of its two neighbours")
    if d is not None and R0 is not None and 2 * R0 - d <= d:
        return ("R0", "d"), (f"its inner width 2 R0 - d = {_mm(2 * R0 - d)} is not above "
                             f"d = {_mm(d)}: the bar of its neighbour cannot pass through")
    if None in (d, t, R0, a):
        return None
    closing = a + 2 * R0 - d
    if abs(t - closing) > GEOMETRY_MISMATCH_LIMIT * t:
        return ("t", "a", "R0", "d"), (
            f"it does not close: t = {_mm(t)} but a + 2 R0 - d = {_mm(closing)}, "
            f"{abs(t - closing) / t:.1%} of t apart "
            f"(at most {GEOMETRY_MISMATCH_LIMIT:.0%} is taken as rounding)")
    return None


def _chain(key: str, data: Any, sheet: Path) -> ChainDef:
    """The chain ``[chains.<key>]``, validated with its effective geometry."""
    chain = _validate(ChainDef, data, sheet, f"chains.{key}")
    fault = _geometry_fault(chain.si())
    if fault is None:
        return chain
    quantities, reason = fault
    given = [name for name in quantities if getattr(chain, f"{name}_mm") is not None]
    raise RunSheetError(
        f"the link cannot exist: {reason}", file=sheet,
        column=f"chains.{key}." + (f"{given[0]}_mm" if given else "catalog"),
        hint=f"check {', '.join(f'{name}_mm' for name in quantities)} [mm]: d is the bar "
             "diameter, t the inner length (pitch), R0 the centre-line radius of the ends, "
             "a the length of the straight parts",
    )


def _wheel(key: str, data: Any, sheet: Path) -> WheelDef:
    """The wheel ``[wheels.<key>]``."""
    return _validate(WheelDef, data, sheet, f"wheels.{key}")


def _sprocket(key: str, data: Any, sheet: Path) -> SprocketDef:
    """The sprocket ``[sprockets.<key>]``."""
    return _validate(SprocketDef, data, sheet, f"sprockets.{key}")


def _drum(key: str, data: Any, sheet: Path) -> DrumDef:
    """The drum ``[drums.<key>]``."""
    return _validate(DrumDef, data, sheet, f"drums.{key}")


def _definitions(data: dict, name: str, sheet: Path,
                 validate: Callable[[str, Any, Path], ModelT]
                 ) -> tuple[dict[str, ModelT], dict[str, RunSheetError]]:
    """The valid and the invalid tables of ``[<name>.<key>]``, by key."""
    tables = data.get(name, {})
    if not isinstance(tables, dict):
        raise RunSheetError(
            f"expected a table of [{name}.<key>] tables, got {_described(tables)}",
            file=sheet, column=name, hint=f"define each as its own [{name}.<key>] table",
        )
    valid: dict[str, ModelT] = {}
    invalid: dict[str, RunSheetError] = {}
    for key, value in tables.items():
        try:
            valid[key] = validate(key, value, sheet)
        except RunSheetError as error:
            invalid[key] = error
    return valid, invalid


def _check_id(run: RunDef, position: str, sheet: Path, taken: dict[str, str]) -> None:
    """Refuse an id that names a campaign output or a run before it (in any letter case).

    `taken` maps the case-folded ids of the runs accepted so far to their ids.
    """
    reason = reserved_id_reason(run.id)
    if reason is not None:
        raise RunSheetError(reason, file=sheet, column=f"{position}.id",
                            hint="choose another id: it names the run's output file")
    other = taken.get(run.id.casefold())
    if other is None:
        return
    message = f"duplicate run id {run.id!r}"
    if other != run.id:
        message += (f": it differs from {other!r} only in letter case, which Windows and "
                    "macOS file systems ignore")
    raise RunSheetError(message, file=sheet, column=f"{position}.id",
                        hint="every run needs its own id: it names the output file")


def _check_uses(run: RunDef, position: str, sheet: Path, kind: str, key: str | None,
                valid: Collection[str], invalid: dict[str, RunSheetError]) -> None:
    """Refuse a run whose chain or wheel (`kind`) `key` is undefined or invalid.

    `valid` holds the keys of the valid definitions, `invalid` the error of each
    invalid one.
    """
    if key is None or key in valid:
        return
    if key in invalid:
        fault = invalid[key]
        raise RunSheetError(
            f"run {run.id!r} uses {kind} {key!r}, which is invalid: "
            f"{fault.column}: {fault.message}",
            file=sheet, column=f"{position}.{kind}",
            hint=f"fix [{kind}s.{key}]" + (f": {fault.hint}" if fault.hint else ""),
        )
    raise RunSheetError(
        f"unknown {kind} {key!r}", file=sheet, column=f"{position}.{kind}",
        hint=f"define [{kind}s.{key}] or use one of: {', '.join(valid) or 'none'}",
    )


def _check_wear_chain(run: RunDef, position: str, sheet: Path,
                      chains: dict[str, ChainDef]) -> None:
    """Refuse a wear run whose chain lacks the pitch, or the pin its criterion needs."""
    if run.kind != "wear":
        return
    values = chains[run.chain].si()
    needed = ("t", *PIN_GEOMETRY) if run.pin_criterion else ("t",)
    missing = [key for key in needed if values[key] is None]
    if missing:
        raise RunSheetError(
            f"wear run {run.id!r}: chain {run.chain!r} gives no "
            + ", ".join(f"{key}_mm" for key in missing), file=sheet,
            column=f"{position}.chain",
            hint=f"give them in [chains.{run.chain}] [mm], or use a roller chain of the "
                 "catalogue that has them (16B)" + ("" if "t" in missing else
                                                     "; or leave out the pin criterion"))
    if run.pin_criterion and values["bush_length"] >= 2 * values["plate_span"]:
        raise RunSheetError(
            f"chain {run.chain!r}: the bush length {_mm(values['bush_length'])} is not below "
            f"twice the plate span l1 ({_mm(2 * values['plate_span'])})", file=sheet,
            column=f"chains.{run.chain}.bush_length_mm",
            hint="l1 is the span between the mid-planes of the outer plates (Paper 004, "
                 "eq. (4)); check bush_length_mm and plate_span_mm")


def _check_roller_chain(run: RunDef, position: str, sheet: Path,
                        chains: dict[str, ChainDef]) -> None:
    """Refuse a roller-engagement run whose chain lacks the pitch, mass or roller."""
    if run.kind != "roller-engagement":
        return
    values = chains[run.chain].si()
    missing = [key for key in ROLLER_GEOMETRY if values[key] is None]
    if missing:
        raise RunSheetError(
            f"roller-engagement run {run.id!r}: chain {run.chain!r} gives no "
            + ", ".join("mass_kg_per_m" if key == "mass_per_length" else f"{key}_mm"
                        for key in missing), file=sheet, column=f"{position}.chain",
            hint=f"give them in [chains.{run.chain}], or use a roller chain of the catalogue "
                 "(08B, 10B, 16B...)")


def _check_segment_drum(run: RunDef, position: str, sheet: Path,
                        chains: dict[str, ChainDef], drums: dict[str, DrumDef]) -> None:
    """Refuse a segment-load run whose chain and drum cannot hold (Paper 003, eqs. (1)-(2)).

    The chain needs d and the torus radius r; the drum's s must lie in c <= s < 2 k
    and beta in 0 < beta <= pi/2 + eps_n (the branch on which k grows with beta).
    """
    if run.kind != "segment-load":
        return
    values, drum = chains[run.chain].si(), drums[run.drum].si()
    missing = [key for key in ("d", "r_outer") if values[key] is None]
    if missing:
        raise RunSheetError(
            f"segment-load run {run.id!r}: chain {run.chain!r} gives no "
            + ", ".join({"d": "d_mm", "r_outer": "torus_radius_mm"}[key] for key in missing),
            file=sheet, column=f"{position}.chain",
            hint=f"give them in [chains.{run.chain}] [mm], or use a chain of the catalogue "
                 "that has them (34x126)")
    if drum["beta"] > math.pi / 2 + drum["eps_n"]:
        raise RunSheetError(
            f"drum {run.drum!r}: flank_inclination_deg is above 90 deg + link_inclination_deg",
            file=sheet, column=f"drums.{run.drum}.flank_inclination_deg",
            hint="beta is the flank's inclination at the contact (Paper 003, eq. (1)), "
                 "0 < beta <= 90 deg + eps_n")
    k = float(contact_radius(values["r_outer"], values["d"], drum["beta"], drum["eps_n"]))
    if not drum["groove_width"] <= drum["s"] < 2 * k:
        raise RunSheetError(
            f"drum {run.drum!r} with chain {run.chain!r}: s = {_mm(drum['s'])} lies outside "
            f"c <= s < 2 k = [{_mm(drum['groove_width'])}, {_mm(2 * k)}): the link cannot "
            "touch both segments (Paper 003, eq. (2))", file=sheet,
            column=f"drums.{run.drum}.contact_distance_mm",
            hint="check contact_distance_mm, groove_width_mm and flank_inclination_deg, and "
                 "the chain's d_mm and torus_radius_mm")


def _check_file(run: RunDef, position: str, sheet: Path) -> None:
    """Refuse a run whose file does not lie in the campaign folder."""
    try:
        resolve_inside(sheet.parent, run.file)
    except ValueError as error:
        raise RunSheetError(
            str(error), file=sheet, column=f"{position}.file",
            hint="run files must lie in the campaign folder",
        ) from None


def _read(sheet: Path) -> tuple[bytes, dict[str, Any]]:
    """The bytes of the run sheet and its TOML content."""
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
    unknown = set(data) - {"campaign", "chains", "wheels", "sprockets", "drums", "runs"}
    if unknown:
        raise RunSheetError(
            f"unknown top-level key(s) {sorted(unknown)}", file=sheet,
            hint="expected [campaign], [chains.*], [wheels.*], [sprockets.*], [drums.*] "
                 "and [[runs]]",
        )
    return raw_bytes, data


def load_run_sheet(path: str | Path) -> RunSheet:
    """Read and validate a run sheet.

    Parameters
    ----------
    path : str or Path
        The ``campaign.toml`` file, or the campaign folder holding it.

    Returns
    -------
    RunSheet
        Valid runs in ``runs``; entries that failed in ``invalid_runs`` (with the
        runs of an invalid chain or wheel); invalid chains and wheels in
        ``invalid_chains`` and ``invalid_wheels``.

    Raises
    ------
    RunSheetError
        When the sheet as a whole cannot be used (missing, not TOML, unknown
        top-level keys, bad ``[campaign]`` table, no runs).
    """
    path = Path(path)
    sheet = path / RUN_SHEET_NAME if path.is_dir() else path
    raw_bytes, data = _read(sheet)
    campaign = _validate(CampaignInfo, data.get("campaign", {}), sheet, "campaign")
    chains, invalid_chains = _definitions(data, "chains", sheet, _chain)
    wheels, invalid_wheels = _definitions(data, "wheels", sheet, _wheel)
    sprockets, invalid_sprockets = _definitions(data, "sprockets", sheet, _sprocket)
    drums, invalid_drums = _definitions(data, "drums", sheet, _drum)

    raw_runs = data.get("runs", [])
    if not isinstance(raw_runs, list) or not raw_runs:
        raise RunSheetError(
            "the run sheet lists no runs", file=sheet, column="runs",
            hint="add one [[runs]] table per machine export",
        )
    runs: list[RunDef] = []
    invalid: list[RunSheetError] = []
    entries: dict[str, dict[str, Any]] = {}
    taken: dict[str, str] = {}
    for index, entry in enumerate(raw_runs):
        position = f"runs[{index}]"
        try:
            run = _validate(RunDef, entry, sheet, position)
            _check_uses(run, position, sheet, "chain", run.chain, chains, invalid_chains)
            _check_uses(run, position, sheet, "wheel", run.wheel, wheels, invalid_wheels)
            _check_wear_chain(run, position, sheet, chains)
            _check_uses(run, position, sheet, "sprocket", run.sprocket, sprockets,
                        invalid_sprockets)
            _check_roller_chain(run, position, sheet, chains)
            _check_uses(run, position, sheet, "drum", run.drum, drums, invalid_drums)
            _check_segment_drum(run, position, sheet, chains, drums)
            _check_file(run, position, sheet)
            _check_id(run, position, sheet, taken)
        except RunSheetError as error:
            invalid.append(error)
            continue
        runs.append(run)
        entries[run.id] = entry
        taken[run.id.casefold()] = run.id

    return RunSheet(
        path=sheet, sha256=hashlib.sha256(raw_bytes).hexdigest(), campaign=campaign,
        chains=chains, wheels=wheels, runs=runs, invalid_runs=invalid,
        invalid_chains=invalid_chains, invalid_wheels=invalid_wheels, entries=entries,
        sprockets=sprockets, invalid_sprockets=invalid_sprockets,
        drums=drums, invalid_drums=invalid_drums,
    )
