"""The one pint unit registry of chainbench, used at the edges only.

Inside the package every quantity is a plain float or numpy array in SI units;
pint converts what comes in (file headers, run sheets, CLI options) and what
goes out (tables in the papers' units).
"""

from __future__ import annotations

import numpy as np
import pint

ureg = pint.UnitRegistry()
# Laboratory spellings pint does not know by default.
# "kp": the kilopond, older European machines' kilogram-force.
ureg.define("@alias kilogram_force = kG = KG = kp")
# "gmf" (gram-force, as Dia-Stron's fibre testers write it).
ureg.define("@alias gram_force = gmf")
# "seg" (Spanish, Portuguese, Italian), "sek" (German, Polish, Scandinavian): seconds.
ureg.define("@alias second = seg = sek")
# "rev": revolutions of a rotary stage (a tribometer's Rotary.Position (rev)).
ureg.define("@alias turn = rev")
# "Ns" (an impact rig's impulse): a newton second, as written; pint alone reads it only in
# lower case, as nanoseconds, which would make an impulse a time.
ureg.define("newton_second = newton * second = Ns")
# Microstrain, as strain-gauge amplifiers and Japanese loggers write it (µε, με with the
# micro sign or the Greek mu; Kyowa's µST), and in plain letters (ue, uE, µe: pint alone
# reads a micro elementary charge): a ratio of 1e-6.
ureg.define("microstrain = 1e-6 = µε = με = µST = μST = ue = uE = µe = μe")
# Gauge and absolute pressures (a burst rig's psig, a hydraulic bench's barg), read as the
# pressure they are of, so that a pressure is never taken for a force; MPa in mixed case.
ureg.define("@alias pound_force_per_square_inch = psig = psia = psid")
ureg.define("@alias bar = barg = bara")
ureg.define("Mpa = megapascal")
# A percent as scripts write it after a name (strain_pct): pint alone reads a picocarat.
ureg.define("@alias percent = pct")
# Keysight data loggers' volts of a direct or alternating voltage (BenchLink's VDC, VAC).
ureg.define("@alias volt = VDC = VAC")
# Russian (Cyrillic) unit symbols, as Russian testing-machine software writes them.
for _definition in ("с = second", "сек = second", "мс = millisecond", "мин = minute",
                    "ч = hour", "Н = newton", "мН = millinewton", "кН = kilonewton",
                    "даН = decanewton", "гс = gram_force", "кгс = kilogram_force",
                    "тс = force_metric_ton",
                    "м = meter", "мм = millimeter", "см = centimeter", "мкм = micrometer"):
    ureg.define(_definition)
# Chinese unit names, as Chinese testing-machine software writes them.
for _definition in ("秒 = second", "毫秒 = millisecond", "分钟 = minute", "小时 = hour",
                    "牛 = newton", "牛顿 = newton", "千牛 = kilonewton", "千牛顿 = kilonewton",
                    "米 = meter", "毫米 = millimeter", "微米 = micrometer", "厘米 = centimeter"):
    ureg.define(_definition)
# Japanese and Korean units of time (a Korean machine's 시간(초): the time in seconds).
for _definition in ("ミリ秒 = millisecond", "分 = minute", "時間 = hour", "초 = second",
                    "밀리초 = millisecond", "분 = minute", "시 = hour"):
    ureg.define(_definition)
Q_ = ureg.Quantity

#: Standard acceleration of gravity [m/s^2] (CGPM 1901); 1 kgf = 9.80665 N.
STANDARD_GRAVITY = float(Q_(1, "gravity").to("m/s^2").magnitude)


def to_si(value, unit: str):
    """Convert `value` given in `unit` to the SI base unit of its dimension.

    Parameters
    ----------
    value : float or array_like
        Magnitude(s) in `unit`.
    unit : str
        A unit pint understands, e.g. ``"kN"``, ``"kgf/cm^2"``, ``"mm"``.

    Returns
    -------
    float or numpy.ndarray
        The magnitude(s) in SI base units.

    Examples
    --------
    >>> to_si(1.0, "kgf")
    9.80665
    """
    quantity = Q_(np.asarray(value, dtype=float), unit).to_base_units()
    magnitude = quantity.magnitude
    return float(magnitude) if np.ndim(magnitude) == 0 else magnitude


def from_si(value, unit: str):
    """Convert `value` in SI base units to `unit` (the inverse of :func:`to_si`)."""
    base = Q_(1.0, unit).to_base_units().units
    quantity = Q_(np.asarray(value, dtype=float), base).to(unit)
    magnitude = quantity.magnitude
    return float(magnitude) if np.ndim(magnitude) == 0 else magnitude
