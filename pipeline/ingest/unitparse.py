"""Units of raw columns, read and converted with pint (:data:`pipeline.units.ureg`).

No conversion table lives here: a unit text is handed to pint, which knows
N, kN, daN, kgf, kG, tf, lbf, mm, µm/um, m, in, s, ms, min, deg, rad and the
rest; only the *spelling* is helped (``"Sec"`` -> ``"sec"``, ``"KN"`` -> ``"kN"``).
"""

from __future__ import annotations

import functools
import re

from pipeline.errors import UnitError
from pipeline.units import to_si, ureg

#: The SI unit of each canonical column; ``strain`` is a gauge column whose unit is a
#: ratio (%, mm/mm, µm/m): the machine has already divided by its gauge length.
ROLE_SI_UNIT = {"time": "s", "force": "N", "gauge": "m", "strain": "1", "angle": "rad",
                "cycle_count": "1", "length": "m", "speed": "m/s", "segment_force_1": "N",
                "segment_force_2": "N", "side_force": "N"}

#: The roles a unit alone may give a column (:func:`unit_role`), by dimension: a length
#: unit makes a gauge, never a ``length`` (that role comes from a name or the run sheet).
_ROLE_DIMENSION = {
    "time": ureg.second.dimensionality,
    "force": ureg.newton.dimensionality,
    "gauge": ureg.meter.dimensionality,
}

#: The dimension of every role with one (angles are told by their radians).
_DIMENSION = {**_ROLE_DIMENSION, "length": ureg.meter.dimensionality,
              "speed": (ureg.meter / ureg.second).dimensionality,
              **dict.fromkeys(("segment_force_1", "segment_force_2", "side_force"),
                              ureg.newton.dimensionality)}

#: The range of SI factors a unit of each role may have. Pint reads ``"a"`` as a year,
#: ``"pcs"`` as parsecs, ``"Min"`` as mega-inches and ``"Ms"`` as megaseconds, which no
#: testing machine logs in (a day is the longest time unit read; a length in kilometres is
#: a distance run, an odometer's, no gauge nor chain length):
#: without this, ``"A"`` (amperes, in lower case) would make a current a time.
_SI_FACTOR_RANGE = {
    "time": (1e-9, 1e5), "gauge": (1e-9, 1e2), "length": (1e-9, 1e2), "speed": (1e-9, 1e3),
    **dict.fromkeys(("force", "segment_force_1", "segment_force_2", "side_force"), (1e-6, 1e9)),
}

#: The roles of a force. A unit of mass in such a column is the weight of that mass
#: (``g``: gram-force), as texture analysers and tribometers write it.
FORCE_ROLES = frozenset({"force", "segment_force_1", "segment_force_2", "side_force"})

#: Units that make a column the machine's cycle (or segment) counter whatever its name
#: (pint would read ``cycles`` as an angle, a revolution).
CYCLE_UNITS = frozenset({"cycle", "cycles", "segment", "segments", "zyklen", "cykle", "ciclos"})
#: A unit of :data:`CYCLE_UNITS`, perhaps with a prefix (``kcycles``: scaled, refused later).
_COUNTED_CYCLES = re.compile(r"(?:k|m|kilo|mega)?(?:" + "|".join(sorted(CYCLE_UNITS)) + ")")
#: Units a machine's own counter may carry; the counter is kept as counted.
COUNTER_UNITS = CYCLE_UNITS | {"", "1", "-", "#", "n", "count", "counts"}


def is_counter_unit(text: str | None) -> bool:
    """Whether `text` (bracketed or not) is a unit a counter is kept in as counted
    (:data:`COUNTER_UNITS`); ``kcycles`` or a name's ``x1000`` would scale it.

    >>> is_counter_unit("(cycles)"), is_counter_unit(None), is_counter_unit("x1000")
    (True, True, False)
    """
    return (text or "").strip().strip("()[]").strip().lower() in COUNTER_UNITS


#: Units-row cells that stand for no unit: Siglent oscilloscopes write ``Value`` over each
#: channel beside ``Second`` over the time; a Campbell Scientific TOA5 file ``TS`` over its
#: time stamp and ``RN`` over its record number; a Graphtec logger ``NO.`` over its sample
#: number; a wind-tunnel balance ``/`` over a run number or a Reynolds number.
NO_UNIT_CELLS = frozenset({"value", "ts", "rn", "no.", "/"})

#: A units-row cell over a sample counter that gives the interval between two samples
#: (a Shimadzu export's ``X 200msec`` over ``Number``): the counter's step, not its unit.
_SAMPLE_INTERVAL = re.compile(r"[xX×]\s*\d+(?:[.,]\d+)?\s*(?P<unit>[^\W\d_]+)")


def is_sample_interval(text: str) -> bool:
    """Whether a units-row cell gives the interval of a sample counter (``X 200msec``).

    >>> is_sample_interval("X 200msec"), is_sample_interval("x 0.5 s"), is_sample_interval("mm")
    (True, True, False)
    """
    found = _SAMPLE_INTERVAL.fullmatch(text.strip())
    return found is not None and unit_role(found["unit"]) == "time"


#: A micro sign alone: pint's micrometre (micron), but a Japanese logger's microstrain
#: (``表-縦 μ`` beside ``変位 mm``). No unit is read from it, rather than a strain of 1e-6
#: taken for a micrometre.
AMBIGUOUS_MICRO = frozenset({"µ", "μ"})

#: What is said of a micro sign alone.
MICRO_ALONE = "a micro sign alone, micrometres (µm) or microstrain (µε)"


def is_micro_alone(text: str | None) -> bool:
    """Whether `text` is a micro sign alone (:data:`AMBIGUOUS_MICRO`), bracketed or not."""
    return (text or "").strip().strip("()[]{}").strip() in AMBIGUOUS_MICRO


#: Units read as no unit, for what they may mean, folded: a micro sign alone
#: (:data:`MICRO_ALONE`); a ton, pint's US short ton (2000 lb) where a Spanish, Korean or
#: Brazilian machine's ``Carga (ton)`` means the metric tonne-force, 10 % more.
AMBIGUOUS_UNITS = {**dict.fromkeys(AMBIGUOUS_MICRO, MICRO_ALONE),
                   **dict.fromkeys(("ton", "tons", "tonf"),
                                   "a ton, the metric tonne (write t or tf), the US short ton "
                                   "of 2000 lb or the UK long ton of 2240 lb")}


def ambiguity(text: str | None) -> str | None:
    """What `text` may mean, if it is a unit of :data:`AMBIGUOUS_UNITS`, else None.

    >>> ambiguity("(TON)").split(",")[0], ambiguity("tf")
    ('a ton', None)
    """
    return AMBIGUOUS_UNITS.get((text or "").strip().strip("()[]{}").strip().casefold())


#: What to tell a user whose unit is not understood.
ACCEPTED_UNITS = ("N, kN, daN, mN, µN (uN), kgf (kG), tf, lbf, gf, g (in a force column); "
                  "mm, µm (um), nm, m, in; %, mm/mm, µε (microstrain) for a strain; s, ms, "
                  "min, h; deg, rad; m/s")


def spellings(text: str) -> list[str]:
    """The spellings of `text` that pint understands, best first.

    Tries the text as written, then, where its case says nothing (all capitals,
    ``"KN"``; a capitalised word, ``"Sec"``; or text pint does not read as
    written), in lower case and with its first letter in lower case (``"KN"`` ->
    ``"kn"`` (knot), ``"kN"``): the caller keeps the first of the right
    dimension. A unit written in mixed case means its case: ``"Pa"`` is a
    pascal and ``"Nm"`` a newton metre, never a peta-year or a nanometre.
    Pint's parser evaluates nothing.

    Examples
    --------
    >>> spellings("KN"), spellings("Pa")
    (['kn', 'kN'], ['Pa'])
    """
    if ambiguity(text):
        return []
    text = text.strip().strip("()[]{}").strip()
    if _CHANNEL_NUMBER.search(text):  # Bluehill's "(Strain 1)": a channel, no strain x 1
        return []
    since = _SINCE.fullmatch(text)  # a clock's count from an epoch: its unit
    text = since["unit"] if since else "microstrain" if _MILLIONTHS.fullmatch(text) else text
    if not _parses(text):  # a weight's force written out (gram-force, pound force), a
        # product written with hyphens (a rheometer's Pa-s, N-m), a square without its caret
        # (kg/cm2), a gauge or absolute pressure's mark (bar(g))
        text = _FORCE_OF_WEIGHT.sub(r"\1_force", text)
        text = _PRESSURE_MARK.sub("", _SQUARE.sub(r"\1^\2", _HYPHEN.sub("*", text)))
    candidates = [text]
    if not _parses(text) or _case_says_nothing(text):
        candidates += [text.lower(), text[:1].lower() + text[1:]]
    return [spelling for spelling in dict.fromkeys(candidates) if spelling and _parses(spelling)]


#: The force of a weight written out, its words apart (``gram-force``, ``pound force``).
_FORCE_OF_WEIGHT = re.compile(r"\b(gram|kilogram|pound)[-\s]force\b", re.IGNORECASE)

#: A word and a number apart at the end of a text: a channel's name and number.
_CHANNEL_NUMBER = re.compile(r"[^\W\d_]\s+\d+$")

#: A millionth written as a power of ten, as Japanese strain loggers write microstrain
#: (Kyowa's and Tokyo Sokki's ``×10^-6``; ``x10-6``, ``1e-6``).
_MILLIONTHS = re.compile(r"[x×*]\s*10\s*\^?\s*[-−⁻]\s*[6⁶]|10\s*(?:\^\s*[-−]|⁻)\s*[6⁶]"
                         r"|1[eE]-0?6")

#: A hyphen between letters: a product of units (``Pa-s``, ``N-m``, ``lbf-in``).
_HYPHEN = re.compile(r"(?<=[^\W\d_])-(?=[^\W\d_])")

#: A 2 or 3 right after a unit of length or the second: its power (``kg/cm2``, ``N/mm2``,
#: ``m/s2``; not ``a2``, a label).
_SQUARE = re.compile(r"(?<![^\W\d_])((?:[kcmµu]?m|in|ft|s))([23])\b")
#: A pressure's mark of gauge or absolute after its unit (``bar(g)``, ``psi (a)``).
_PRESSURE_MARK = re.compile(r"\s*\((?:g|a|gauge|abs)\)?$", re.IGNORECASE)  # ")" stripped

#: A time counted from an epoch, as a logger writes its stamps' unit (TelemetryViewer's
#: ``Milliseconds since 1970-01-01``).
_SINCE = re.compile(r"(?P<unit>[^\W\d_]+)\s+since\s+\S.*", re.IGNORECASE)


def _parses(spelling: str) -> bool:
    try:
        ureg.parse_units(spelling)
    except Exception:  # pint raises many kinds of error on odd text
        return False
    return True


def _case_says_nothing(text: str) -> bool:
    """All capitals (``"KN"``, ``"A"``) or a capitalised word (``"Sec"``, ``"Min"``); not a
    compound unit whose capital is a symbol (``"Nm/deg"``: newton metres per degree, never
    nanometres)."""
    letters = "".join(char for char in text if char.isalpha())
    return letters.isupper() or (len(letters) >= 3 and text.isalpha() and letters[0].isupper()
                                 and letters[1:].islower())


def _plausible(spelling: str, role: str) -> bool:
    """Whether a testing machine could log `role` in `spelling`: see :data:`_SI_FACTOR_RANGE`."""
    low, high = _SI_FACTOR_RANGE.get(role, (0.0, float("inf")))
    return low <= abs(float(to_si(1.0, spelling))) <= high


def _role_of(spelling: str) -> str | None:
    dimensionality = ureg.parse_units(spelling).dimensionality
    for role, dimension in _ROLE_DIMENSION.items():
        if dimensionality == dimension:
            return role if _plausible(spelling, role) else None
    return "angle" if ureg.get_root_units(spelling)[1] == ureg.radian else None


def _fits(spelling: str, role: str) -> bool:
    """Whether the unit `spelling` (one pint parses) is of `role`'s dimension and scale."""
    if role == "angle":
        return _role_of(spelling) == "angle"
    spelling = _as_weight(spelling) if role in FORCE_ROLES else spelling
    return (ureg.parse_units(spelling).dimensionality == _DIMENSION.get(role)
            and _plausible(spelling, role))


def _as_weight(spelling: str) -> str:
    """A unit of mass as the weight of that mass (``"g"`` -> gram-force); others as given."""
    if ureg.parse_units(spelling).dimensionality == ureg.gram.dimensionality:
        return f"{spelling} * gravity"
    return spelling


def is_mass_unit(text: str | None) -> bool:
    """True if a force column reads `text` as a unit of mass (``"g"``, ``"kg"``, ``"lb"``),
    that is as the weight of that mass.

    Examples
    --------
    >>> is_mass_unit("g"), is_mass_unit("gf"), is_mass_unit("KG")  # KG: kilogram-force
    (True, False, False)
    """
    for spelling in spellings(text or ""):
        if _fits(spelling, "force"):
            return ureg.parse_units(spelling).dimensionality == ureg.gram.dimensionality
    return False


def unit_fits(text: str | None, role: str) -> bool:
    """Whether some spelling of `text` is a unit of `role` (``"KN"``, force: ``"kN"`` is).

    Examples
    --------
    >>> unit_fits("mm", "length"), unit_fits("m/s", "speed"), unit_fits("kN", "length")
    (True, True, False)
    """
    return any(_fits(spelling, role) for spelling in spellings(text or ""))


def is_quantity_unit(text: str | None) -> bool:
    """Whether some spelling of `text` is a unit of a quantity a test rig logs (a time,
    length, speed, force, mass, pressure, frequency, torque, power, temperature, voltage or
    current): not a byte's, a mole's or a bare ratio.

    Examples
    --------
    >>> is_quantity_unit("psi"), is_quantity_unit("RPM"), is_quantity_unit("kB")
    (True, True, False)
    """
    return any(ureg.parse_units(spelling).dimensionality in _QUANTITIES
               for spelling in spellings(text or ""))


#: The dimensions of :func:`is_quantity_unit`.
_QUANTITIES = tuple(ureg.parse_units(unit).dimensionality for unit in (
    "s", "m", "m/s", "N", "kg", "Pa", "kg/m^2", "Hz", "J", "W", "K", "V", "A"))


@functools.lru_cache(maxsize=256)
def is_measure_unit(text: str) -> bool:
    """Whether `text` is a unit of force or length (``"gf"``, ``"mm"``), as a force gauge
    writes beside each value."""
    return unit_fits(text, "force") or unit_fits(text, "length")


def is_temperature_unit(text: str | None) -> bool:
    """Whether some spelling of `text` is a unit of temperature (``"°C"``, ``"K"``).

    >>> is_temperature_unit("°C"), is_temperature_unit("degF"), is_temperature_unit("s")
    (True, True, False)
    """
    return _of_dimension(text, _TEMPERATURE)


def is_voltage_unit(text: str | None) -> bool:
    """Whether some spelling of `text` is a unit of electric potential (``"V"``, ``"mV"``),
    or a bridge's output over its excitation (``"mV/V"``): a sensor's signal, before its
    calibration.

    >>> is_voltage_unit("V"), is_voltage_unit("mV/V"), is_voltage_unit("N")
    (True, True, False)
    """
    return _of_dimension(text, _VOLTAGE) or _BRIDGE.fullmatch((text or "").strip()) is not None


#: A bridge's output over its excitation (a strain-gauge load cell's ``mV/V``), which pint
#: reads as a plain ratio.
_BRIDGE = re.compile(r"[mµμu]?V\s*/\s*V", re.IGNORECASE)


def _of_dimension(text: str | None, dimensionality: object) -> bool:
    """Whether some spelling of `text` is a unit of `dimensionality` (pint's)."""
    return any(ureg.parse_units(spelling).dimensionality == dimensionality
               for spelling in spellings(text or ""))


_TEMPERATURE, _VOLTAGE = (ureg.parse_units(unit).dimensionality for unit in ("K", "V"))


def unit_misfits(text: str | None, role: str) -> bool:
    """Whether `text` is a unit, and not one a column of `role` could be logged in.

    A ratio fits a gauge (a strain); a cycle count fits no unit of a dimension but its
    cycles (``"cycles"``, an angle to pint) or none.

    Examples
    --------
    >>> unit_misfits("MPa", "force"), unit_misfits("J", "cycle_count"), unit_misfits("%", "gauge")
    (True, True, False)
    >>> unit_misfits("", "force"), unit_misfits("cycles", "cycle_count")
    (False, False)
    """
    found = spellings(text or "")
    if not found or (role == "gauge" and is_strain_unit(text)):
        return False
    if role == "cycle_count":
        return not any(ureg.parse_units(spelling).dimensionless or _role_of(spelling) == "angle"
                       for spelling in found)
    return not unit_fits(text, role)


def unit_role(text: str | None) -> str | None:
    """The role a unit alone suggests (``"kN"`` -> ``"force"``, ``"cycles"`` ->
    ``"cycle_count"``), or None."""
    if _COUNTED_CYCLES.fullmatch((text or "").strip().casefold()):
        return "cycle_count"
    for spelling in spellings(text or ""):
        role = _role_of(spelling)
        if role is not None:
            return role
    return None


def is_strain_unit(text: str | None) -> bool:
    """True if `text` is a ratio unit a strain channel carries (``"%"``, ``"mm/mm"``, ``"µm/m"``).

    Examples
    --------
    >>> is_strain_unit("(%)"), is_strain_unit("µm/m"), is_strain_unit("mm"), is_strain_unit("dB")
    (True, True, False, False)
    >>> is_strain_unit("mV/V")  # a bridge's output: a strain only through its gauge factor
    False
    """
    found = spellings(text or "")
    if not found:
        return False
    unit = ureg.parse_units(found[0])
    return (unit.dimensionless and _role_of(found[0]) != "angle"
            and _NO_RATIO_UNITS.isdisjoint(re.findall(r"[a-z]+", str(unit)))
            and not _BRIDGE_OUTPUT.search(found[0]))


#: Units pint counts as dimensionless that no strain channel logs in: levels (an acoustic
#: emission sensor's ``dB``), counts, solid angles and bits (pint reads ``B`` as a byte).
_NO_RATIO_UNITS = frozenset({"bel", "decibel", "neper", "octave", "decade", "count",
                             "steradian", "byte", "bit"})


#: A bridge's output over its excitation (``mV/V``, ``µV/V``, ``V/V``): a strain gauge
#: amplifier's raw signal, which is a strain only through the gauge factor and the bridge.
_BRIDGE_OUTPUT = re.compile(r"V\s*/\s*V")


def looks_like_unit(text: str) -> bool:
    """True if `text` reads as a unit cell of a units row (``"(mm)"``, ``"Sec"``, ``""``)."""
    stripped = text.strip()
    if not stripped or stripped.lower() in COUNTER_UNITS | NO_UNIT_CELLS or ambiguity(stripped):
        return True  # an ambiguous unit (ton) is one, refused later with its meanings
    if is_sample_interval(stripped):
        return True
    if stripped[0] + stripped[-1] in ("()", "[]"):
        return True
    return bool(spellings(stripped))


def si_factor(
    text: str, role: str, *, file: str, row: int | None, column: str, source: str
) -> float:
    """The factor taking values in unit `text` to the SI unit of `role`.

    Parameters
    ----------
    text : str
        The unit as found (``"kN"``, ``"(sec)"``).
    role : str
        ``"time"``, ``"force"``, ``"gauge"``, ``"strain"`` (a ratio), ``"angle"``,
        ``"length"`` or ``"speed"``.
    file, row, column : str, int or None, str
        Where the unit was found, for the error message.
    source : str
        Where the unit came from, e.g. ``"the header"`` or ``"the run sheet"``.

    Returns
    -------
    float
        Multiply raw values by this to get SI values.

    Raises
    ------
    UnitError
        If pint does not know the unit or it is not of the role's dimension.
    """
    found = spellings(text)
    if not found:
        raise UnitError(
            f"unknown unit {text!r} in {source}"
            + (f": {said}" if (said := ambiguity(text)) else ""),
            file=file, row=row, column=column,
            hint=f"write a unit pint understands ({ACCEPTED_UNITS})",
        )
    for spelling in found:
        if role == "strain" and is_strain_unit(spelling):
            return float(to_si(1.0, spelling))
        if role != "strain" and _fits(spelling, role):
            return float(to_si(1.0, _as_weight(spelling) if role in FORCE_ROLES else spelling))
    signal = (f"{text!r} is a sensor's signal: convert the column to a {role} with the "
              "sensor's calibration first (the readers apply none), or, if its amplifier was "
              f"scaled to give a unit of {role}, give that unit in the run sheet (units = "
              "{...}); else " if is_voltage_unit(text) else "")
    raise UnitError(
        f"unit {text!r} in {source} is not a unit of {role} ({ROLE_SI_UNIT[role]})",
        file=file, row=row, column=column,
        hint=f"{signal}check the column roles (columns = {{...}}) and units in the run sheet",
    )
