"""Write a canonical table as a raw log in any layout the readers accept.

Layouts (``docs/file-formats.md``):

``plain``
    CSV, ``,`` delimiter, UTF-8, one header row with units in brackets:
    ``time [s],force [kN],gauge1 [mm],gauge2 [mm]``.
``european``
    ``;`` delimiter, decimal comma, cp1250 (Polish) or latin-1 (German) by
    default; Polish ``Czas [s];Siła [kN];Wydłużenie 1 [mm]`` or German
    ``Zeit [s];Kraft [kN];Weg 1 [mm]`` column names. ``encoding="utf-8-sig"``
    writes UTF-8 with a byte-order mark.
``machine``
    An Instron Bluehill style export: ``key : value`` preamble lines, a blank
    line, a names row ``Time,Extension 1,Extension 2,Load`` and a units row
    ``(sec),(mm),(mm),(kN)``; CRLF line ends.
``xlsx``
    The plain header and the values (as numbers) on the first sheet. The
    workbook's dates (document properties, zip entries) are :data:`XLSX_DATE`,
    so the same table always gives the same bytes.

:func:`write_table` writes the cyclic tensile logs (``force``, ``gauge_<n>``),
:func:`write_pull_table` single pulls (``force``, ``extensometer`` or
``extensometer_strain``, ``crosshead``; :data:`PULL_NAMES`), :func:`write_wear_table`
wear logs (``time``, ``cycles``, ``length`` or ``elongation``, ``load``, ``speed``;
:data:`WEAR_NAMES`, also as NI TDMS); all go through :func:`write_columns`.

Units are converted with pint (:func:`pipeline.units.from_si`). Numbers are
written in fixed-point notation with :data:`SIGNIFICANT_DIGITS` significant
digits of the column's largest magnitude (trailing zeros trimmed), so a
gauge reading of 0.01 mm stays ``0.01`` and no exponent ever appears.
"""

from __future__ import annotations

import io
import os
from collections.abc import Mapping, Sequence
from datetime import datetime
from pathlib import Path
from zipfile import ZIP_DEFLATED, ZipFile, ZipInfo

import numpy as np
import pandas as pd
from openpyxl import Workbook
from openpyxl.xml.constants import ARC_CORE
from openpyxl.xml.functions import tostring

from pipeline.units import from_si

#: Layouts :func:`write_table` can write.
LAYOUTS = ("plain", "european", "machine", "xlsx")

#: File name suffix of each layout.
SUFFIXES = {"plain": ".csv", "european": ".csv", "machine": ".csv", "xlsx": ".xlsx"}

#: Force and length units the readers accept (docs/file-formats.md).
FORCE_UNITS = ("N", "kN", "daN", "kgf", "tf", "lbf")
LENGTH_UNITS = ("mm", "um", "m", "in")

#: Significant digits written, relative to a column's largest magnitude.
SIGNIFICANT_DIGITS = 9

#: Column names per naming scheme: time, force, and gauge ``{n}`` (1-based).
NAMES = {
    "plain": ("time", "force", "gauge{n}"),
    "pl": ("Czas", "Siła", "Wydłużenie {n}"),
    "de": ("Zeit", "Kraft", "Weg {n}"),
    "machine": ("Time", "Load", "Extension {n}"),
}

#: Column names of single-pull logs (:func:`write_pull_table`) per naming scheme:
#: plain, European Polish and German, Bluehill English and German.
PULL_NAMES = {
    "plain": {"time": "time", "force": "force", "extensometer": "extensometer",
              "extensometer_strain": "strain", "crosshead": "crosshead"},
    "pl": {"time": "Czas", "force": "Siła", "extensometer": "Ekstensometr",
           "extensometer_strain": "Odkształcenie", "crosshead": "Trawersa"},
    "de": {"time": "Zeit", "force": "Standardkraft", "extensometer": "Feindehnung",
           "extensometer_strain": "Dehnung", "crosshead": "Traversenweg"},
    "machine-en": {"time": "Time", "force": "Load", "extensometer": "Strain 1",
                   "extensometer_strain": "Strain 1", "crosshead": "Extension"},
    "machine-de": {"time": "Zeit", "force": "Last", "extensometer": "Dehnung 1",
                   "extensometer_strain": "Dehnung 1", "crosshead": "Traversenweg"},
}

#: Languages of the column names of single-pull logs per layout (the first is the default).
PULL_LANGUAGES = {"plain": ("en",), "european": ("pl", "de"), "machine": ("en", "de"),
                  "xlsx": ("en",)}

#: Column order of single-pull logs: the machine layout puts the crosshead first.
PULL_ORDER = {"machine": ("time", "crosshead", "force", "extensometer", "extensometer_strain")}

#: Column names of wear logs (:func:`write_wear_table`) per naming scheme: plain (also
#: the workbook's and the TDMS channels'), European Polish and German, Bluehill English.
WEAR_NAMES = {
    "plain": {"time": "running time", "cycles": "cycles", "length": "section length",
              "elongation": "section elongation", "load": "load", "speed": "chain speed"},
    "pl": {"time": "Czas pracy", "cycles": "Liczba cykli", "length": "Długość odcinka",
           "elongation": "Wydłużenie odcinka", "load": "Obciążenie", "speed": "Prędkość"},
    "de": {"time": "Laufzeit", "cycles": "Lastwechsel", "length": "Messlänge",
           "elongation": "Verlängerung", "load": "Kraft", "speed": "Kettengeschwindigkeit"},
    "machine": {"time": "Time", "cycles": "Cycles", "length": "Length",
                "elongation": "Elongation", "load": "Load", "speed": "Speed"},
}

#: File layouts of wear logs: those of :data:`LAYOUTS`, and NI TDMS.
WEAR_LAYOUTS = (*LAYOUTS, "tdms")

#: File name suffix of each wear-log layout.
WEAR_SUFFIXES = {**SUFFIXES, "tdms": ".tdms"}

#: Time units a wear log may be written in.
TIME_UNITS = ("s", "min", "h")

#: The TDMS group of a wear log's channels.
WEAR_TDMS_GROUP = "Wear test"

#: Default encoding of the European layout per language.
EUROPEAN_ENCODINGS = {"pl": "cp1250", "de": "latin-1"}

#: Creation and modification date written into workbooks, in place of the clock.
XLSX_DATE = datetime(2000, 1, 1)


def _check_units(force_unit: str, length_unit: str) -> None:
    if force_unit not in FORCE_UNITS:
        raise ValueError(f"force_unit must be one of {', '.join(FORCE_UNITS)}, got {force_unit!r}")
    if length_unit not in LENGTH_UNITS:
        raise ValueError(
            f"length_unit must be one of {', '.join(LENGTH_UNITS)}, got {length_unit!r}"
        )


def _converted(table: pd.DataFrame, force_unit: str, length_unit: str):
    """Names by role and values converted from SI: [(role, unit, values)]."""
    _check_units(force_unit, length_unit)
    gauges = [name for name in table.columns if str(name).startswith("gauge_")]
    if "force" not in table.columns or not gauges:
        raise ValueError("the table needs a force column and at least one gauge_<n> column")
    columns = []
    if "time" in table.columns:
        columns.append(("time", "s", table["time"].to_numpy(dtype=float)))
    columns.append(("force", force_unit, from_si(table["force"].to_numpy(dtype=float), force_unit)))
    for name in gauges:
        columns.append((name, length_unit, from_si(table[name].to_numpy(dtype=float), length_unit)))
    return columns


def _name(role: str, scheme: str, gauges: int) -> str:
    time, force, gauge = NAMES[scheme]
    if role == "time":
        return time
    if role == "force":
        return force
    if scheme == "machine" and gauges == 1:
        return gauge.replace(" {n}", "")
    return gauge.format(n=role.removeprefix("gauge_"))


def format_numbers(values: np.ndarray, decimal: str = ".") -> np.ndarray:
    """Fixed-point text of `values`, :data:`SIGNIFICANT_DIGITS` of the largest magnitude.

    Examples
    --------
    >>> format_numbers(np.array([0.01, 1.5, -20.0])).tolist()
    ['0.01', '1.5', '-20']
    """
    finite = np.abs(values[np.isfinite(values)])
    largest = finite.max() if finite.size and finite.max() > 0 else 1.0
    decimals = int(np.clip(SIGNIFICANT_DIGITS - 1 - np.floor(np.log10(largest)), 0, 15))
    text = np.char.mod(f"%.{decimals}f", values)
    if decimals:
        text = np.char.rstrip(np.char.rstrip(text, "0"), ".")
    text = np.where(text == "-0", "0", text)
    text = np.where(np.isfinite(values), text, "")
    return np.char.replace(text, ".", decimal) if decimal != "." else text


def _lines(
    header: Sequence[Sequence[str]],
    columns: Sequence[np.ndarray],
    delimiter: str,
    decimal: str,
    quote: bool = False,
) -> list[str]:
    """The header rows, then one line per row of `columns`; ``quote`` wraps every field in ``"``."""

    def cells(text: np.ndarray) -> np.ndarray:
        return np.char.add(np.char.add('"', text), '"') if quote else text

    rows = cells(format_numbers(columns[0], decimal))
    for values in columns[1:]:
        rows = np.char.add(np.char.add(rows, delimiter), cells(format_numbers(values, decimal)))
    head = [delimiter.join(cells(np.array(row, dtype=str)).tolist()) for row in header]
    return [*head, *rows.tolist()]


def _xlsx_bytes(workbook: Workbook) -> bytes:
    """The saved `workbook` with :data:`XLSX_DATE` in place of every clock reading.

    openpyxl stamps the time of saving into ``docProps/core.xml`` and into
    every zip entry; both are replaced, so equal content gives equal bytes.
    """
    saved = io.BytesIO()
    workbook.save(saved)
    workbook.properties.created = workbook.properties.modified = XLSX_DATE
    core = tostring(workbook.properties.to_tree())
    fixed = io.BytesIO()
    with ZipFile(saved) as source, ZipFile(fixed, "w", ZIP_DEFLATED) as target:
        for info in source.infolist():
            entry = ZipInfo(info.filename, date_time=XLSX_DATE.timetuple()[:6])
            entry.external_attr = 0o644 << 16
            data = core if info.filename == ARC_CORE else source.read(info)
            target.writestr(entry, data, compress_type=ZIP_DEFLATED)
    return fixed.getvalue()


def _write_atomic(path: Path, data: bytes) -> None:
    temporary = path.with_name(f".{path.name}.tmp")
    temporary.write_bytes(data)
    os.replace(temporary, path)


def write_table(
    table: pd.DataFrame,
    path: str | Path,
    *,
    layout: str = "plain",
    force_unit: str = "kN",
    length_unit: str = "mm",
    language: str = "pl",
    encoding: str | None = None,
    preamble: Sequence[tuple[str, str]] = (),
) -> Path:
    """Write a canonical table (SI) as a raw log file.

    Parameters
    ----------
    table : pandas.DataFrame
        Canonical table: ``force`` [N], ``gauge_1``... [m], optionally ``time`` [s].
    path : str or Path
        File to write (replaced atomically if it exists).
    layout : str
        One of :data:`LAYOUTS`.
    force_unit : str
        Unit of the force column, one of :data:`FORCE_UNITS`.
    length_unit : str
        Unit of the gauge columns, one of :data:`LENGTH_UNITS`.
    language : str
        Column names of the European layout: ``"pl"`` or ``"de"``.
    encoding : str, optional
        Text encoding; default UTF-8 (plain), :data:`EUROPEAN_ENCODINGS`
        (European), ASCII (machine). ``"utf-8-sig"`` adds a byte-order mark.
    preamble : sequence of (str, str)
        ``key : value`` lines of the machine layout.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        On an unknown layout, language or unit, or a table without force or gauges.
    """
    path = Path(path)
    if layout not in LAYOUTS:
        raise ValueError(f"layout must be one of {', '.join(LAYOUTS)}, got {layout!r}")
    if layout == "european" and language not in EUROPEAN_ENCODINGS:
        raise ValueError(f"language must be one of {', '.join(EUROPEAN_ENCODINGS)}")
    columns = _converted(table, force_unit, length_unit)
    gauges = len(columns) - 1 - ("time" in table.columns)
    if layout == "machine":
        columns = [column for column in columns if column[0] != "force"] + [
            column for column in columns if column[0] == "force"
        ]
    scheme = {"european": language, "machine": "machine"}.get(layout, "plain")
    return write_columns(
        path,
        [_name(role, scheme, gauges) for role, _, _ in columns],
        [unit for _, unit, _ in columns],
        [values for _, _, values in columns],
        layout=layout,
        encoding=encoding or (EUROPEAN_ENCODINGS[language] if layout == "european" else None),
        preamble=preamble,
        xlsx_names=[_name(role, "plain", gauges) for role, _, _ in columns],
    )


def write_columns(
    path: Path,
    names: Sequence[str],
    units: Sequence[str],
    columns: Sequence[np.ndarray],
    *,
    layout: str,
    encoding: str | None = None,
    preamble: Sequence[tuple[str, str]] = (),
    delimiter: str | None = None,
    decimal: str | None = None,
    quote: bool = False,
    xlsx_names: Sequence[str] | None = None,
) -> Path:
    """Write named columns, already in their units, as a raw log in `layout`.

    Parameters
    ----------
    path : Path
        File to write (replaced atomically if it exists).
    names, units : sequence of str
        Column names and units as written (``"s"`` is written ``(sec)`` in the
        units row of the machine layout).
    columns : sequence of numpy.ndarray
        Values in those units (:func:`format_numbers`).
    layout : str
        One of :data:`LAYOUTS`: ``plain`` and ``european`` write ``name [unit]``
        headers with LF line ends; ``machine`` writes the preamble, a blank
        line, a names row and a units row with CRLF line ends; ``xlsx`` a
        workbook.
    encoding : str, optional
        Text encoding; default UTF-8 (plain) or ASCII (machine).
    preamble : sequence of (str, str)
        ``key : value`` lines of the machine layout.
    delimiter, decimal : str, optional
        Default ``;`` and ``,`` for the European layout, else ``,`` and ``.``.
    quote : bool
        Wrap every field of the table (not the preamble) in ``"``.
    xlsx_names : sequence of str, optional
        Names of the workbook's header (default `names`).

    Returns
    -------
    Path
        The file written.
    """
    if layout == "xlsx":
        workbook = Workbook(write_only=True)
        sheet = workbook.create_sheet("Data")
        sheet.append([f"{name} [{unit}]"
                      for name, unit in zip(xlsx_names or names, units, strict=True)])
        for row in np.column_stack(columns).tolist():
            sheet.append(row)
        _write_atomic(path, _xlsx_bytes(workbook))
        return path
    european = layout == "european"
    delimiter = delimiter or (";" if european else ",")
    decimal = decimal or ("," if european else ".")
    if layout == "machine":
        unit_row = [f"({'sec' if unit == 's' else unit})" for unit in units]
        lines = [f"{key} : {value}" for key, value in preamble] + ([""] if preamble else [])
        body = _lines([names, unit_row], columns, delimiter, decimal, quote)
        text = "\r\n".join([*lines, *body]) + "\r\n"
        _write_atomic(path, text.encode(encoding or "ascii"))
        return path
    header = [f"{name} [{unit}]" for name, unit in zip(names, units, strict=True)]
    body = _lines([header], columns, delimiter, decimal, quote)
    _write_atomic(path, ("\n".join(body) + "\n").encode(encoding or "utf-8"))
    return path


def write_pull_table(
    table: pd.DataFrame,
    path: str | Path,
    *,
    layout: str = "plain",
    force_unit: str = "kN",
    length_unit: str = "mm",
    language: str | None = None,
    encoding: str | None = None,
    preamble: Sequence[tuple[str, str]] = (),
    quote: bool = False,
) -> Path:
    """Write a single-pull log (SI, :func:`pipeline.simulate.pull.simulate_pull`) as a raw file.

    Parameters
    ----------
    table : pandas.DataFrame
        ``time`` [s], ``force`` [N], and any of ``extensometer`` [m],
        ``extensometer_strain`` [1] and ``crosshead`` [m].
    path : str or Path
        File to write (replaced atomically if it exists).
    layout : str
        One of :data:`LAYOUTS`. The column names are :data:`PULL_NAMES`:
        ``time [s],force [kN],extensometer [mm],crosshead [mm]`` (plain, xlsx);
        ``Czas [s];Siła [kN];Ekstensometr [mm];Trawersa [mm]`` or
        ``Zeit [s];Standardkraft [kN];Feindehnung [mm];Traversenweg [mm]``
        (European); ``Time,Extension,Load,Strain 1`` over ``(sec),(mm),(kN),(%)``
        or, German with ``;`` and decimal comma, ``Zeit;Traversenweg;Last;Dehnung 1``
        (machine: ``Extension`` is the crosshead, ``Strain 1`` the extensometer).
        A strain column is written in %.
    force_unit, length_unit : str
        Units of force and of the length columns (:data:`FORCE_UNITS`,
        :data:`LENGTH_UNITS`).
    language : str, optional
        Column names: ``"pl"`` (default) or ``"de"`` for the European layout,
        ``"en"`` (default) or ``"de"`` for the machine layout.
    encoding : str, optional
        Text encoding; default UTF-8 (plain), :data:`EUROPEAN_ENCODINGS`
        (European, German machine), ASCII (English machine).
    preamble : sequence of (str, str)
        ``key : value`` lines of the machine layout.
    quote : bool
        Wrap every field of the table in ``"`` (as some Bluehill versions write).

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        On an unknown layout, language or unit, or a table without time or force.
    """
    if layout not in LAYOUTS:
        raise ValueError(f"layout must be one of {', '.join(LAYOUTS)}, got {layout!r}")
    languages = PULL_LANGUAGES[layout]
    language = language or languages[0]
    if language not in languages:
        raise ValueError(f"language of the {layout} layout must be one of "
                         f"{', '.join(languages)}, got {language!r}")
    _check_units(force_unit, length_unit)
    if not {"time", "force"} <= set(table.columns):
        raise ValueError("a pull log needs time and force columns")
    units = {"time": "s", "force": force_unit, "extensometer": length_unit,
             "extensometer_strain": "%", "crosshead": length_unit}
    scheme = {"european": language, "machine": f"machine-{language}"}.get(layout, "plain")
    roles = [role for role in PULL_ORDER.get(layout, tuple(units)) if role in table.columns]
    german_machine = layout == "machine" and language == "de"
    return write_columns(
        Path(path),
        [PULL_NAMES[scheme][role] for role in roles],
        [units[role] for role in roles],
        [from_si(table[role].to_numpy(dtype=float), units[role]) for role in roles],
        layout=layout,
        encoding=encoding or EUROPEAN_ENCODINGS.get(language),
        preamble=preamble,
        delimiter=";" if german_machine else None,
        decimal="," if german_machine else None,
        quote=quote,
    )


def write_wear_table(
    table: pd.DataFrame,
    path: str | Path,
    *,
    layout: str = "plain",
    time_unit: str = "h",
    length_unit: str = "mm",
    force_unit: str = "kN",
    language: str = "pl",
    encoding: str | None = None,
    preamble: Sequence[tuple[str, str]] = (),
) -> Path:
    """Write a wear log (SI, :func:`pipeline.simulate.wear.simulate_wear`) as a raw file.

    Parameters
    ----------
    table : pandas.DataFrame
        Any of ``time`` [s], ``cycles`` [-], ``length`` or ``elongation`` [m]
        of the section, ``load`` [N] and ``speed`` [m/s], written in that order.
    path : str or Path
        File to write (replaced atomically if it exists).
    layout : str
        One of :data:`WEAR_LAYOUTS`, with the column names of
        :data:`WEAR_NAMES`: ``running time [h],cycles [1],section length [mm]``
        (plain, xlsx), Polish or German names (European), ``Time,Cycles,Length``
        over a units row (machine), or TDMS channels of the plain names in the
        group :data:`WEAR_TDMS_GROUP`, each with its ``unit_string``.
    time_unit, length_unit, force_unit : str
        Units of the running time (:data:`TIME_UNITS`), of the section's length
        or elongation (:data:`LENGTH_UNITS`) and of the load
        (:data:`FORCE_UNITS`); cycles are written as counted (unit ``1``),
        speeds in m/s.
    language : str
        Column names of the European layout: ``"pl"`` or ``"de"``.
    encoding, preamble
        As for :func:`write_table`.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        On an unknown layout, language or unit.
    """
    if time_unit not in TIME_UNITS:
        raise ValueError(f"time_unit must be one of {', '.join(TIME_UNITS)}, got {time_unit!r}")
    _check_units(force_unit, length_unit)
    units = {"time": time_unit, "cycles": "1", "length": length_unit,
             "elongation": length_unit, "load": force_unit, "speed": "m/s"}
    return write_log(table, path, units, WEAR_NAMES, layout=layout, language=language,
                     encoding=encoding, preamble=preamble)


def write_log(table: pd.DataFrame, path: str | Path, units: Mapping[str, str],
              names: Mapping[str, Mapping[str, str]], *, layout: str, language: str,
              encoding: str | None = None, preamble: Sequence[tuple[str, str]] = ()) -> Path:
    """Write the columns of a log (SI) in their units, named and laid out as a machine would.

    The writer of the wear and segment-load logs: one column (or TDMS
    channel) per role of `units` that `table` has, in the order of `units`.

    Parameters
    ----------
    table : pandas.DataFrame
        The log: one column per role, in SI units [s, m, N, m/s, ...].
    path : str or Path
        File to write (replaced atomically if it exists).
    units : mapping of str to str
        Role -> the unit its column is written in.
    names : mapping
        Naming scheme (``"plain"``, ``"machine"`` and each language of
        :data:`EUROPEAN_ENCODINGS`) -> role -> column name.
    layout : str
        One of :data:`WEAR_LAYOUTS`: the plain scheme's names but for the
        European layout (the `language`'s) and the machine export (the
        ``"machine"`` scheme's).
    language : str
        Column names and encoding of the European layout: a key of
        :data:`EUROPEAN_ENCODINGS`.
    encoding, preamble
        As for :func:`write_columns` (`encoding` default: the language's for
        the European layout).

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    ValueError
        On an unknown layout or language.
    """
    if layout not in WEAR_LAYOUTS:
        raise ValueError(f"layout must be one of {', '.join(WEAR_LAYOUTS)}, got {layout!r}")
    if layout == "european" and language not in EUROPEAN_ENCODINGS:
        raise ValueError(f"language must be one of {', '.join(EUROPEAN_ENCODINGS)}")
    roles = [role for role in units if role in table.columns]
    values = [from_si(table[role].to_numpy(dtype=float), units[role]) for role in roles]
    scheme = {"european": language, "machine": "machine"}.get(layout, "plain")
    columns = [names[scheme][role] for role in roles]
    if layout == "tdms":
        return write_tdms(Path(path), columns, [units[role] for role in roles], values)
    return write_columns(Path(path), columns, [units[role] for role in roles], values,
                         layout=layout, preamble=preamble,
                         encoding=encoding or (EUROPEAN_ENCODINGS[language]
                                               if layout == "european" else None))


def write_tdms(path: Path, names: Sequence[str], units: Sequence[str],
               columns: Sequence[np.ndarray]) -> Path:
    """Write named columns as the channels of a TDMS file, each with its unit.

    Parameters
    ----------
    path : Path
        File to write (replaced atomically if it exists).
    names : sequence of str
        Channel names, in group :data:`WEAR_TDMS_GROUP`.
    units : sequence of str
        Each channel's ``unit_string`` (the unit its values are in).
    columns : sequence of numpy.ndarray
        Each channel's values [its unit].

    Returns
    -------
    Path
        The file written.
    """
    from nptdms import ChannelObject, GroupObject, RootObject, TdmsWriter

    channels = [ChannelObject(WEAR_TDMS_GROUP, name, np.asarray(values, dtype=float),
                              properties={"unit_string": unit})
                for name, unit, values in zip(names, units, columns, strict=True)]
    temporary = path.with_name(f".{path.name}.tmp")
    with TdmsWriter(temporary) as writer:
        writer.write_segment([RootObject({"title": "chainbench virtual wear bench"}),
                              GroupObject(WEAR_TDMS_GROUP), *channels])
    os.replace(temporary, path)
    return path
