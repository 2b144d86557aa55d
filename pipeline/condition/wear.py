"""Conditioning of a wear log: section lengths or elongations to pitch elongation.

A wear test of a roller chain logs, against the running time (or the cycles),
either the length ``L`` of a measured section of ``N`` pitches or the
elongation of that section directly. Both become the elongation per pitch
``delta_t`` [m] and its share of the pitch ``delta_t / t`` [-]: the quantity
whose growth Paper 004 limits, eq. (3) (the chain jumps off the sprocket when
the pitch has grown too much).

The reference
-------------
``delta_t`` is counted from a reference the caller states, never guessed:

``reference="nominal"``
    the nominal pitch: ``delta_t = (L - N t) / N``, or ``e / N`` for a section
    elongation ``e`` given against the nominal length ``N t``;
``reference="first"``
    the first reading (a lab that declares its log relative, e.g. a gauge
    zeroed on the new chain): ``delta_t = (L - L_0) / N``, or
    ``(e - e_0) / N``.

Checks
------
A log that cannot be a wear log raises a :class:`~pipeline.errors.ChainbenchError`
with a hint: fewer than :data:`MIN_READINGS` readings, a missing (NaN or
infinite) reading, a running time or cycle count that does not increase or
starts below zero (:class:`~pipeline.errors.SignalError`), and a section length
or elongation that is not within :data:`MAX_RELATIVE_ELONGATION` of the
nominal length (:class:`~pipeline.errors.UnitError`: a length in mm read as m
is 1000 times too long, and the hint says so).

From a read log
---------------
:func:`condition_wear` takes the canonical table of a wear log
(:mod:`pipeline.ingest`: ``time`` [s] and/or ``cycle_count``; ``length`` [m],
or one elongation ``gauge_1`` [m] or ``strain_1`` [-]) and picks the running
coordinate and the channel. It refuses a table that holds both a section
length and an elongation, or several elongations, unless told which: two
channels may disagree, and neither is preferred silently.

References
----------
Paper 004, eq. (3) (allowed pitch growth); ``docs/models/paper-004-pin-criterion.md``.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd
from numpy.typing import ArrayLike

from pipeline.errors import SignalError, UnitError
from pipeline.units import to_si

#: Fewest readings of a wear log: a straight line and its scatter need three.
MIN_READINGS = 3

#: Largest |delta_t / t| [-] a reading may show. Above the jump-off pitch
#: growth of Paper 004, eq. (3), of any sprocket of nine or more teeth
#: (t (2/9 - 0.004) = 0.218 t), and far below the factor of a wrong length unit.
MAX_RELATIVE_ELONGATION = 0.25

#: References ``delta_t`` may be counted from.
REFERENCES = ("nominal", "first")

#: Running coordinates of a log: time [s] or cycles [-].
ABSCISSAE = ("time", "cycles")

#: The canonical column (:mod:`pipeline.ingest`) of each running coordinate.
RUNNING_COLUMNS = {"time": "time", "cycles": "cycle_count"}

#: Channels a wear log gives its readings by: the section's length, or its elongation.
CHANNELS = ("length", "elongation")

#: Length units a lab may have logged in place of m, named in the hint of a
#: length that is that unit's factor too long.
_LIKELY_UNITS = ("mm", "um", "cm", "in")


@dataclass(frozen=True)
class WearLog:
    """A conditioned wear log, from :func:`wear_from_length` or :func:`wear_from_elongation`.

    Attributes
    ----------
    table : pandas.DataFrame
        One row per reading: the running coordinate ``time`` [s] or
        ``cycles`` [-] (increasing, from 0 or later), ``elongation`` delta_t
        [m] (per pitch) and ``relative_elongation`` delta_t / t [-].
    pitch : float
        Nominal pitch t [m].
    reference : str
        What delta_t is counted from: ``"nominal"`` (the nominal pitch) or
        ``"first"`` (the first reading).
    """

    table: pd.DataFrame
    pitch: float
    reference: str

    @property
    def abscissa(self) -> str:
        """Name of the running coordinate: ``"time"`` [s] or ``"cycles"`` [-]."""
        return str(self.table.columns[0])

    @property
    def tau(self) -> np.ndarray:
        """Running time [s] (or cycles [-]) of each reading."""
        return self.table[self.abscissa].to_numpy(dtype=float)

    @property
    def elongation(self) -> np.ndarray:
        """Elongation per pitch delta_t [m] of each reading."""
        return self.table["elongation"].to_numpy(dtype=float)


def wear_from_length(
    tau: ArrayLike,
    length: ArrayLike,
    *,
    pitches: int,
    pitch: float,
    reference: str,
    abscissa: str = "time",
) -> WearLog:
    """Elongation per pitch from the logged length of a section of `pitches` pitches.

    Parameters
    ----------
    tau : array_like
        Running time [s] (or cycles [-], with ``abscissa="cycles"``) of each
        reading, increasing, from 0 or later.
    length : array_like
        Measured length L of the section [m].
    pitches : int
        Number of pitches N of the section [-].
    pitch : float
        Nominal pitch t [m].
    reference : {"nominal", "first"}
        ``"nominal"``: delta_t = (L - N t) / N; ``"first"``: delta_t =
        (L - L_0) / N, L_0 the first reading (a log the lab declares relative).
    abscissa : {"time", "cycles"}, optional
        What `tau` counts.

    Returns
    -------
    WearLog

    Raises
    ------
    SignalError
        Too few readings, a missing reading, or a `tau` that does not increase
        or starts below 0.
    UnitError
        A length not within :data:`MAX_RELATIVE_ELONGATION` of N t (zero,
        negative, or in another unit than m).
    ValueError
        On an unknown `reference` or `abscissa`, or a `pitch` or `pitches` that
        is not positive.

    References
    ----------
    Paper 004, eq. (3): delta_t is the pitch growth it limits.

    Examples
    --------
    Ten pitches of 19.05 mm measured 190.5 mm, then 190.8 mm, then 191.1 mm:

    >>> log = wear_from_length([0.0, 3600.0, 7200.0], [0.1905, 0.1908, 0.1911],
    ...                        pitches=10, pitch=0.01905, reference="nominal")
    >>> log.elongation.round(9).tolist()
    [0.0, 3e-05, 6e-05]
    """
    return _wear(tau, length, "length", pitches=pitches, pitch=pitch, reference=reference,
                 abscissa=abscissa)


def wear_from_elongation(
    tau: ArrayLike,
    elongation: ArrayLike,
    *,
    pitches: int,
    pitch: float,
    reference: str,
    abscissa: str = "time",
) -> WearLog:
    """Elongation per pitch from the logged elongation of a section of `pitches` pitches.

    Parameters
    ----------
    tau, pitches, pitch, abscissa
        As in :func:`wear_from_length`.
    elongation : array_like
        Measured elongation e of the section [m]; ``pitches=1`` for the
        elongation of one pitch.
    reference : {"nominal", "first"}
        ``"nominal"``: e is counted from the nominal length N t, delta_t = e / N;
        ``"first"``: from the first reading, delta_t = (e - e_0) / N.

    Returns
    -------
    WearLog

    Raises
    ------
    SignalError, ValueError
        As in :func:`wear_from_length`.
    UnitError
        A |delta_t / t| above :data:`MAX_RELATIVE_ELONGATION` (an elongation in
        another unit than m).

    References
    ----------
    Paper 004, eq. (3): delta_t is the pitch growth it limits.
    """
    return _wear(tau, elongation, "elongation", pitches=pitches, pitch=pitch,
                 reference=reference, abscissa=abscissa)


def _wear(tau: ArrayLike, values: ArrayLike, column: str, *, pitches: int, pitch: float,
          reference: str, abscissa: str) -> WearLog:
    """The checked :class:`WearLog` of section lengths or elongations (as `column` names)."""
    nominal = _section_length(pitches, pitch, reference)
    tau, values = _readings(tau, values, abscissa=abscissa, column=column)
    elongation = values - nominal if column == "length" else values
    origin = elongation[0] if reference == "first" else 0.0
    # a gauge read from its first reading may stand anywhere (a stage at -114.6 mm): the
    # readings from there are checked; a length is the section's, whatever the reference
    _check_length(nominal + elongation - (origin if column == "elongation" else 0.0),
                  nominal, column)
    table = pd.DataFrame({abscissa: tau, "elongation": (elongation - origin) / pitches})
    table["relative_elongation"] = table["elongation"] / pitch
    return WearLog(table=table, pitch=float(pitch), reference=reference)


def _section_length(pitches: int, pitch: float, reference: str) -> float:
    """Nominal length N t [m]; raises unless N >= 1 is whole, t > 0 and `reference` is known."""
    if reference not in REFERENCES:
        raise ValueError(f"reference must be one of {', '.join(REFERENCES)}, got {reference!r}")
    if not (isinstance(pitches, int | np.integer) and pitches >= 1):
        raise ValueError(f"pitches must be a whole number >= 1, got {pitches!r}")
    if not (np.isfinite(pitch) and pitch > 0):
        raise ValueError(f"pitch must be a finite positive length [m], got {pitch!r}")
    return float(pitches * pitch)


def _readings(
    tau: ArrayLike, values: ArrayLike, *, abscissa: str, column: str
) -> tuple[np.ndarray, np.ndarray]:
    """`tau` and `values` as float arrays, checked: count, completeness, increasing `tau`."""
    if abscissa not in ABSCISSAE:
        raise ValueError(f"abscissa must be one of {', '.join(ABSCISSAE)}, got {abscissa!r}")
    tau, values = np.asarray(tau, dtype=float), np.asarray(values, dtype=float)
    if tau.ndim != 1 or tau.shape != values.shape:
        raise ValueError(f"{abscissa} and {column} must be 1-D and of one length, "
                         f"got shapes {tau.shape} and {values.shape}")
    if tau.size < MIN_READINGS:
        raise SignalError(f"the wear log holds {tau.size} readings", column=column,
                          hint=f"a wear rate needs at least {MIN_READINGS} readings")
    for name, array in ((abscissa, tau), (column, values)):
        missing = np.flatnonzero(~np.isfinite(array))
        if missing.size:
            raise SignalError(
                f"reading {missing[0] + 1} of {array.size} is missing (NaN or infinite)",
                column=name, hint="drop the incomplete readings from the log, or fill them in")
    _check_increasing(tau, abscissa)
    return tau, values


def _check_increasing(tau: np.ndarray, abscissa: str) -> None:
    """Raise unless `tau` starts at 0 or later and increases strictly."""
    if tau[0] < 0:
        raise SignalError(f"the {abscissa} starts at {tau[0]:.6g}, before the start of the test",
                          column=abscissa,
                          hint=f"count the {abscissa} from the start of the wear test (0)")
    stalls = np.flatnonzero(np.diff(tau) <= 0)
    if stalls.size:
        raise SignalError(
            f"the {abscissa} does not increase from reading {stalls[0] + 1} to {stalls[0] + 2}",
            column=abscissa,
            hint="sort the readings in running order and remove repeated ones; a counter "
                 "restarted during the test must be continued in the log")


def _check_length(length: np.ndarray, nominal: float, column: str) -> None:
    """Raise a :class:`UnitError` unless every L / (N t) is within 1 +- MAX_RELATIVE_ELONGATION."""
    ratio = length / nominal
    worst = float(ratio[np.argmax(np.abs(ratio - 1))])
    if abs(worst - 1) <= MAX_RELATIVE_ELONGATION:
        return
    raise UnitError(
        f"a reading makes the section {worst:.4g} times its nominal length N t = {nominal:.6g} m",
        column=column, hint=_scale_hint(worst, column))


def _scale_hint(ratio: float, column: str) -> str:
    """What a section length of `ratio` times N t suggests: a unit, or the run sheet."""
    if column == "elongation" and abs(ratio - 2) <= MAX_RELATIVE_ELONGATION:
        return ("the readings look like the section's length, not its elongation: name the "
                'column in the run sheet, columns = {length = "..."}')
    if ratio <= 0:
        return "lengths must be positive: check that the column holds the section length [m]"
    for unit in _LIKELY_UNITS:
        if abs(ratio * to_si(1.0, unit) - 1) <= MAX_RELATIVE_ELONGATION:
            return f"the readings look like {unit} given as m: state the column's unit"
    return ("check the unit of the column, the pitch t and the number of pitches N of the "
            "measured section")


def condition_wear(
    table: pd.DataFrame,
    *,
    pitches: int,
    pitch: float,
    reference: str,
    abscissa: str | None = None,
    channel: str | None = None,
    columns: Mapping[str, str] | None = None,
) -> tuple[WearLog, list[str]]:
    """The :class:`WearLog` of a canonical wear table, and the choices made on the way.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table (:mod:`pipeline.ingest`): ``time`` [s] and/or
        ``cycle_count`` [-]; ``length`` [m] of the section, or its elongation
        ``gauge_<n>`` [m] or ``strain_<n>`` [-] (a ratio of the nominal
        length N t: e = strain N t).
    pitches, pitch, reference
        As in :func:`wear_from_length`.
    abscissa : {"time", "cycles"}, optional
        The running coordinate; default the running time, else the cycles.
    channel : {"length", "elongation"}, optional
        The channel to read; default the one the table holds.
    columns : mapping, optional
        Canonical column -> the file's column name, for messages; default the
        canonical name.

    Returns
    -------
    log : WearLog
    notes : list of str
        The choices a reader of the results should know of (the running
        coordinate taken when the log holds both).

    Raises
    ------
    SignalError
        When the coordinate or channel asked for is absent, the table holds
        both a length and an elongation or several elongations (and `channel`
        does not settle it), or as :func:`wear_from_length`.
    UnitError
        As :func:`wear_from_length`.
    """
    abscissa, notes = _running(table, abscissa)
    name = _channel(table, channel, columns or {})
    values = table[name].to_numpy(dtype=float)
    if name.startswith("strain_"):
        values = values * _section_length(pitches, pitch, reference)
    convert = wear_from_length if name == "length" else wear_from_elongation
    log = convert(table[RUNNING_COLUMNS[abscissa]].to_numpy(dtype=float), values,
                  pitches=pitches, pitch=pitch, reference=reference, abscissa=abscissa)
    return log, notes


def _running(table: pd.DataFrame, abscissa: str | None) -> tuple[str, list[str]]:
    """The running coordinate of `table` (`abscissa`, or the default) and a note on it."""
    present = [name for name, column in RUNNING_COLUMNS.items() if column in table]
    if abscissa is not None and abscissa not in present:
        raise SignalError(f"the log has no {abscissa} column", column=RUNNING_COLUMNS[abscissa],
                          hint=f"name it in the run sheet (columns = "
                               f"{{{RUNNING_COLUMNS[abscissa]} = \"...\"}}), or choose the "
                               "log's running coordinate with wear_abscissa")
    if abscissa is not None or len(present) < 2:
        return abscissa or present[0], []
    return "time", ["the log counts both running time and cycles: the wear is fitted over "
                    "the running time (wear_abscissa = \"cycles\" in the run sheet fits it "
                    "over the cycles)"]


def _channel(table: pd.DataFrame, channel: str | None, columns: Mapping[str, str]) -> str:
    """The column of `table` holding the readings: ``length``, or its one elongation
    (`columns` the file's name of each, for messages)."""
    if channel not in (None, *CHANNELS):
        raise ValueError(f"channel must be one of {', '.join(CHANNELS)}, got {channel!r}")
    elongations = [name for name in table.columns if re.fullmatch(r"(gauge|strain)_\d+", name)]
    lengths = ["length"] if "length" in table else []
    chosen = {"length": lengths, "elongation": elongations, None: lengths + elongations}[channel]
    if len(chosen) == 1:
        return chosen[0]
    hint = ('name the column to use in the run sheet: columns = {length = "..."} for the '
            'section length, or columns = {gauges = ["..."]} for its elongation')
    if not chosen:
        wanted = channel or " or ".join(CHANNELS)
        raise SignalError(f"the log has no {wanted} column", column=wanted, hint=hint)
    shown = [columns.get(name, name) for name in chosen]
    raise SignalError(f"the log holds {len(chosen)} columns that could be the readings: "
                      + ", ".join(map(repr, shown)), column=shown[0], hint=hint)
