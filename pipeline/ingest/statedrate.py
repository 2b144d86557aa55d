"""A sample rate or interval stated in a file's header, for rows that have no time column.

A force plate's export (``サンプリング周波数,1000``), a data logger's
(``Sampling frequency (Hz): 1000``, ``Sample interval: 2 ms``) writes one row a
sample and no time beside it. The time of row ``i`` is then ``i / rate``
[s], counted from the first data row. Only keys that name the sampling say
so: a bare ``Frequency`` or ``Rate`` in a test machine's header is the
loading frequency or the crosshead rate, and is never read as one. Keys
that may name other rates (``Scan rate``, ``Logging interval``, ``dt``) count
only with a unit of time or frequency. Two stated values that disagree give
no time, and say why.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

from pipeline.ingest.names import fold, split_name_unit
from pipeline.ingest.unitparse import spellings
from pipeline.units import ureg

#: Keys (folded, unit set apart) that name a sample rate [Hz] when no unit is written, perhaps
#: after the instrument's name (``Force Sensor Sample rate``).
_RATE_KEYS = re.compile(
    r"(?:\S.* )?(?:sampl(?:e|ing)s?[ _-]?(?:rate|freq(?:uency)?|fequency)|sampling[ _-]?rate|"
    r"samples? ?(?:per ?|/ ?)s(?:ec(?:ond)?)?|"
    r"abtast(?:rate|frequenz)|サンプリング(?:周波数|レート)|采样(?:频率|率)|"
    r"(?:frecuencia|tasa) de muestreo|czestotliwosc probkowania|"
    r"frequence d'echantillonnage|frequenza di campionamento)")
#: Keys that name a sample interval [s] when no unit is written.
_INTERVAL_KEYS = re.compile(
    r"(?:\S.* )?(?:sampl(?:e|ing)[ _-]?(?:interval|period)|abtast(?:intervall|periode)|"
    r"サンプリング(?:間隔|周期)|采样(?:间隔|周期)|intervalo de muestreo|okres probkowania|"
    r"periode d'echantillonnage)")
#: Words of a key that names another rate than the one used (a device's largest).
_NOT_USED = re.compile(r"\b(?:max|maximum|min|minimum|limit|default|nominal|max\.|min\.)\b")
#: Keys that state a sample rate or interval only with a unit.
_UNIT_KEYS = re.compile(
    r"(?:scan|acquisition|data|logging|log|recording|measuring|measurement|mess)[ _-]?"
    r"(?:rate|interval|period)|messtakt|messfrequenz|interval|dt|delta[ _-]?t|time[ _-]?step|"
    r"x[ _-]?increment")
#: A stated value: a number and, perhaps, its unit.
_VALUE = re.compile(r"(?P<number>\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?)\s*(?P<unit>\S.*)?")
#: What may follow a rate or an interval: of each channel, each sample.
_EACH = re.compile(r"\s*(?:per|/)\s*(?:ch(?:an(?:nel)?)?|samples?)\s*$", re.IGNORECASE)
#: A frequency: hertz, or samples per second as data-acquisition software writes them (pint
#: reads S as a siemens), with a prefix (``2 kS/s``); never another unit of 1/s (a baud, a
#: percent per second).
_FREQUENCY = re.compile(
    r"(?P<prefix>[kKMm]?)(?:hz|(?:s|sa|samples?|scans?)?\s*/\s*s(?:ec(?:ond)?)?|sps)",
    re.IGNORECASE)
_TIME = ureg.second.dimensionality


@dataclass(frozen=True)
class StatedRate:
    """What the header states of its sampling.

    Attributes
    ----------
    interval : float or None
        Time between rows [s]; None when the header states none, or values that
        disagree.
    said : str
        The stated keys and values (``"'Sampling frequency (Hz)' = 1000"``), for notes.
    """

    interval: float | None
    said: str

    def note(self) -> str:
        """The note of a time built from :attr:`interval`."""
        return built_note(f"the header's {self.said}", self.interval)


def built_note(source: str, interval: float) -> str:
    """The note of a time built a row each `interval` [s] from what `source` states."""
    return (f"the file has no time column: time is built from {source} (one row each "
            f"{interval:g} s, 0 at the first row)")


def stated_rate(preamble: Mapping[str, str], decimal: str | None = None) -> StatedRate | None:
    """The sampling the header states, or None when it states none.

    Parameters
    ----------
    preamble : mapping
        The header's keys and values as written.
    decimal : str, optional
        The file's decimal mark; a comma in a value is read as one only when it is.

    Examples
    --------
    >>> stated_rate({"Sampling frequency (Hz)": "1000"}).interval
    0.001
    >>> stated_rate({"Frequency": "5 Hz"}) is None
    True
    """
    found = [(key, value, interval) for key, value in preamble.items()
             if (interval := _interval(key, value, decimal)) is not None]
    if not found:
        return None
    said = " and ".join(f"{key!r} = {value}" for key, value, _ in found)
    first = found[0][2]
    if any(not math.isclose(interval, first, rel_tol=1e-6) for _, _, interval in found):
        return StatedRate(None, said)
    return StatedRate(first, said)


#: Words of a header's key or value that may state the sampling.
_SAMPLING_WORDS = re.compile(r"rate|freq|interval|hz\b|abtast|サンプリング|采样",
                             re.IGNORECASE)


def unread_rate(preamble: Mapping[str, str]) -> str:
    """What the hint of a missing time says of a header's setting that may state the
    sampling but is not read as such (``'Config' = 'data_rate = 2000.0 Hz ...'``), or ""."""
    found = next(((key, value) for key, value in preamble.items()
                  if _SAMPLING_WORDS.search(f"{key} {value}")), None)
    if found is None:
        return ""
    key, value = found
    value = value if len(value) <= 40 else value[:40] + "..."
    return (f"the header's {key!r} = {value!r} is not read as a sample rate (a key that "
            "names the sampling, a value in Hz or s); ")


def _interval(key: str, value: str, decimal: str | None) -> float | None:
    """The interval [s] a key and its value state, or None if they state none."""
    named = _named(key)
    number = _VALUE.fullmatch(value.strip())
    if named is None or number is None:
        return None
    digits = number["number"]
    if ("," in digits and decimal != ",") or ("." in digits and decimal == ","):
        return None  # 1,000 in a file of decimal points, 1.000 in one of commas: a thousand?
    default, key_unit = named
    unit = number["unit"] or key_unit or default
    return None if unit is None else _as_interval(float(digits.replace(",", ".")), unit)


def _named(key: str) -> tuple[str | None, str | None] | None:
    """What a key names: the unit a value without one is in (Hz for a rate, s for an
    interval, None for a key that needs a unit), and the unit in the key; None for a key
    that names no sampling."""
    key = key.strip().rstrip(":").strip()
    default = _default_unit(key)  # the whole key first: "Samples/sec"
    if default is not False:
        return default, None
    name, unit = split_name_unit(key)
    if unit is not None and _EACH.fullmatch(unit):  # "Sample rate (per channel)"
        unit = None
    elif unit is not None and _as_interval(1.0, unit) is None:  # "Sample rate (max)"
        return None
    default = _default_unit(name)
    return None if default is False else (default, unit)


def _default_unit(name: str) -> str | None | bool:
    """The unit of a value stated under `name` without one: Hz, s or None (a unit is
    needed); False when the name names no sampling."""
    name = _EACH.sub("", name.strip().rstrip(":").strip())
    forms = (fold(name), name.casefold())  # folded, and as written (fold parts a kana's marks)
    if _NOT_USED.search(forms[0]):
        return False
    if any(_RATE_KEYS.fullmatch(form) for form in forms):
        return "Hz"
    if any(_INTERVAL_KEYS.fullmatch(form) for form in forms):
        return "s"
    return None if _UNIT_KEYS.fullmatch(forms[0]) else False


def _as_interval(magnitude: float, unit: str) -> float | None:
    """The interval [s] of `magnitude` in `unit` (a frequency or a time, perhaps of each
    channel or sample), or None."""
    unit = _EACH.sub("", unit.strip().strip("()[]"))
    if magnitude <= 0:
        return None
    frequency = _FREQUENCY.fullmatch(unit)
    if frequency is not None:
        prefix = frequency["prefix"].replace("K", "k")
        return 1.0 / ureg.Quantity(magnitude, prefix + "Hz").to("Hz").magnitude
    for spelling in spellings(unit):
        if ureg.parse_units(spelling).dimensionality == _TIME:
            return float(ureg.Quantity(magnitude, spelling).to("s").magnitude)
    return None
