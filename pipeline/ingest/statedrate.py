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

#: Keys (folded, unit set apart) that name a sample rate [Hz] when no unit is written.
_RATE_KEYS = re.compile(
    r"sampl(?:e|ing)s?[ _-]?(?:rate|freq(?:uency)?)|sampling[ _-]?rate|"
    r"abtast(?:rate|frequenz)|サンプリング(?:周波数|レート)|采样(?:频率|率)|"
    r"(?:frecuencia|tasa) de muestreo|czestotliwosc probkowania|"
    r"frequence d'echantillonnage|frequenza di campionamento")
#: Keys that name a sample interval [s] when no unit is written.
_INTERVAL_KEYS = re.compile(
    r"sampl(?:e|ing)[ _-]?(?:interval|period)|abtast(?:intervall|periode)|"
    r"サンプリング(?:間隔|周期)|采样(?:间隔|周期)|intervalo de muestreo|okres probkowania|"
    r"periode d'echantillonnage")
#: Keys that state a sample rate or interval only with a unit.
_UNIT_KEYS = re.compile(
    r"(?:scan|acquisition|data|logging|log|recording|measuring|measurement|mess)[ _-]?"
    r"(?:rate|interval|period)|messtakt|dt|delta[ _-]?t|time[ _-]?step|x[ _-]?increment")
#: A stated value: a number and, perhaps, its unit.
_VALUE = re.compile(r"(?P<number>\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?)\s*(?P<unit>\S.*)?")
#: Samples per second as data-acquisition software writes it (pint reads S as a siemens).
_PER_SECOND = re.compile(r"(?:s|sa|samples?|scans?)?\s*/\s*s(?:ec)?|sps", re.IGNORECASE)
_FREQUENCY = ureg.hertz.dimensionality
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
        return (f"the file has no time column: time is built from the header's {self.said} "
                f"(one row each {self.interval:g} s, 0 at the first row)")


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


def _interval(key: str, value: str, decimal: str | None) -> float | None:
    """The interval [s] a key and its value state, or None if they state none."""
    name, key_unit = split_name_unit(key)
    name = name.strip().rstrip(":").strip()
    names = (fold(name), name.casefold())  # folded, and as written (fold parts a kana's marks)
    number = _VALUE.fullmatch(value.strip())
    if number is None or ("," in number["number"] and decimal != ","):
        return None
    magnitude = float(number["number"].replace(",", "."))
    unit = number["unit"] or key_unit
    if any(_RATE_KEYS.fullmatch(form) for form in names):
        default = "Hz"
    elif any(_INTERVAL_KEYS.fullmatch(form) for form in names):
        default = "s"
    elif unit and _UNIT_KEYS.fullmatch(names[0]):
        default = None
    else:
        return None
    return _as_interval(magnitude, unit or default)


def _as_interval(magnitude: float, unit: str) -> float | None:
    """The interval [s] of `magnitude` in `unit` (a frequency or a time), or None."""
    if _PER_SECOND.fullmatch(unit.strip()):
        unit = "Hz"
    for spelling in spellings(unit):
        dimensionality = ureg.parse_units(spelling).dimensionality
        if dimensionality == _FREQUENCY and magnitude > 0:
            return 1.0 / ureg.Quantity(magnitude, spelling).to("Hz").magnitude
        if dimensionality == _TIME and magnitude > 0:
            return float(ureg.Quantity(magnitude, spelling).to("s").magnitude)
    return None
