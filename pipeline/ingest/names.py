"""Column names of test-machine exports, per language, and the roles they map to.

A header cell such as ``"Standardkraft [kN]"`` is split into a name
(``"Standardkraft"``) and a unit (``"kN"``, see :func:`split_name_unit`); the
name is matched against :data:`COLUMN_NAMES` (see :func:`match_role`).
Matching is case-insensitive and ignores diacritics, so ``"SILA"`` matches
``"siła"``.
"""

from __future__ import annotations

import re
import unicodedata

from pipeline.ingest.unitparse import spellings, unit_fits

#: Names (whole words or word sequences) that give a column its role, per language.
COLUMN_NAMES: dict[str, dict[str, tuple[str, ...]]] = {
    "en": {
        "time": ("time", "elapsed time", "test time", "hours", "operating hours", "timestamp",
                 "time stamp", "seconds", "minutes", "elapsed", "run hours", "running hours"),
        "force": ("force", "load", "tension", "thrust"),
        "gauge": (
            "extension", "displacement", "disp", "gauge", "elongation", "extensometer", "ext",
            "exts", "deflection", "position", "stroke", "crosshead", "lvdt", "dial", "strain",
            "actuator", "piston", "clip gauge", "ave", "video extensometer", "travel",
            "stretch", "chain stretch", "grip to grip separation", "grip separation",
            "grip to grip",
        ),
        "angle": ("angle", "encoder", "rotation"),
        "cycle_count": ("cycle", "cycles", "cycle count", "segment count", "stroke count",
                        "strokes"),
        "length": ("length", "section length", "measured length", "chain length"),
        "speed": ("speed", "velocity", "chain speed"),
        "segment_force_1": ("segment force 1", "segment 1", "f k1", "fk 1"),
        "segment_force_2": ("segment force 2", "segment 2", "f k2", "fk 2"),
        "side_force": ("side force", "f p", "fp"),
    },
    "de": {
        "time": ("zeit", "prüfzeit", "testzeit", "versuchszeit", "laufzeit", "betriebsstunden",
                 "gesamtzeit", "zykluszeit", "zeitstempel", "datum uhrzeit"),
        "force": ("kraft", "standardkraft", "prüfkraft", "last"),
        "gauge": ("weg", "standardweg", "traversenweg", "dehnung", "verlängerung", "längung",
                  "längenänderung", "feindehnung",
                  "wegaufnehmer", "standardwegaufnehmer", "traverse", "kolbenweg",
                  "maschinenweg", "extensometer", "ansetzdehnungsaufnehmer", "maytec"),
        "angle": ("winkel", "drehwinkel"),
        "cycle_count": ("zyklus", "zyklen", "zykluszahl", "zyklenzahl", "gesamtzyklen",
                        "gesamtzyklenzahl", "lastwechsel"),
        "length": ("länge", "messlänge", "kettenlänge", "abschnittslänge"),
        "speed": ("geschwindigkeit", "kettengeschwindigkeit"),
        "segment_force_1": ("segmentkraft 1",),
        "segment_force_2": ("segmentkraft 2",),
        "side_force": ("seitenkraft", "querkraft"),
    },
    "pl": {
        "time": ("czas", "godzina"),
        "force": ("siła", "obciążenie", "naciąg"),
        "gauge": ("wydłużenie", "przemieszczenie", "czujnik", "ugięcie", "odkształcenie",
                  "ekstensometr", "trawersa", "tłok", "droga", "droga standardowa"),
        "angle": ("kąt", "obrót"),
        "cycle_count": ("cykl", "cykle", "liczba cykli"),
        "length": ("długość", "długość odcinka"),
        "speed": ("prędkość",),
        "segment_force_1": ("siła segmentu 1", "segment 1"),
        "segment_force_2": ("siła segmentu 2", "segment 2"),
        "side_force": ("siła boczna",),
    },
    "es": {
        "time": ("tiempo", "fecha hora"),
        "force": ("fuerza", "carga"),
        "gauge": ("desplazamiento", "extensión", "alargamiento", "deformación",
                  "extensómetro", "travesaño", "actuador", "pistón", "carrera"),
        "angle": ("ángulo",),
        "cycle_count": ("ciclo", "ciclos", "recuento"),
        "length": ("longitud",),
        "speed": ("velocidad",),
    },
    "fr": {
        "time": ("temps", "durée", "date heure"),
        "force": ("force", "effort"),  # not "charge": an electric charge in English logs
        "gauge": ("déplacement", "allongement", "déformation", "déform", "extensomètre",
                  "course", "course traverse", "vérin", "écartement entre outils"),
        "cycle_count": ("cycles", "nombre de cycles"),
        "length": ("longueur",),
        "speed": ("vitesse",),
    },
    "pt": {
        "time": ("tempo",),
        "force": ("força", "carga"),
        "gauge": ("deslocamento", "extensão", "alongamento", "deformação", "extensômetro",
                  "travessa", "atuador", "pistão"),
        "cycle_count": ("ciclo", "ciclos"),
        "length": ("comprimento",),
        "speed": ("velocidade",),
    },
    "it": {
        "time": ("tempo",),
        "force": ("forza", "carico"),
        "gauge": ("spostamento", "allungamento", "deformazione", "estensometro", "traversa",
                  "corsa", "attuatore", "pistone"),
        "cycle_count": ("ciclo", "cicli"),
        "length": ("lunghezza",),
        "speed": ("velocità",),
    },
    "nl": {
        "time": ("tijd", "testtijd"),
        "force": ("kracht", "belasting"),
        "gauge": ("verplaatsing", "rek", "verlenging", "extensometer", "traverse",
                  "traversepositie", "zuiger"),
        "cycle_count": ("cyclus", "cycli", "aantal cycli"),
        "length": ("lengte",),
        "speed": ("snelheid",),
    },
    "tr": {
        "time": ("zaman", "süre"),
        "force": ("kuvvet", "yük"),
        "gauge": ("uzama", "deplasman", "ekstansometre", "gerinim"),
        "cycle_count": ("çevrim", "çevrim sayısı"),
    },
    "ru": {
        "time": ("время", "время испытания"),
        "force": ("усилие", "нагрузка", "сила"),
        "gauge": ("перемещение", "удлинение", "абсолютное удлинение", "деформация", "экстензометр",
                  "траверса", "перемещение траверсы", "ход", "ход поршня", "положение"),
        "angle": ("угол", "вращение", "угол поворота"),
        "cycle_count": ("цикл", "циклы", "число циклов", "количество циклов"),
        "length": ("длина",),
        "speed": ("скорость",),
    },
    # Chinese, Japanese and Korean names are whole words: "压缩应力" (compressive stress)
    # is not "力" (force)
    "zh": {
        "time": ("时间", "试验时间"),
        "force": ("载荷", "负荷", "力", "试验力", "拉力", "力值", "荷载"),
        "gauge": ("位移", "变形", "伸长", "引伸计", "横梁位移", "应变", "行程", "横梁",
                  "引伸计变形", "大变形", "小变形"),
        "cycle_count": ("循环计数", "循环次数", "循环"),
    },
    "ja": {
        "time": ("時間", "経過時間", "試験時間", "時刻", "日時", "測定日時"),
        "force": ("試験力", "荷重"),
        "gauge": ("変位", "伸び", "ストローク", "伸び計", "クロスヘッド変位", "ひずみ", "歪み"),
        "cycle_count": ("サイクル数", "繰返し数"),
    },
    "ko": {
        "time": ("시간", "시험 시간"),
        "force": ("하중", "시험력", "힘"),
        "gauge": ("변위", "변형", "변형량", "변형률", "신율", "신장계", "크로스헤드", "스트로크"),
        "cycle_count": ("사이클", "사이클 수"),
    },
}

#: Names that say what a displacement channel measures: the travel of the machine's
#: crosshead or actuator (it includes the machine's own compliance; "Machine
#: Displacement"), or the specimen itself (an extensometer, a strain; "AVE" is
#: Instron's video extensometer). Other gauge names ("Extension", "Weg 1",
#: "Wydłużenie") say neither and are of kind ``"gauge"``. testXpert's ASCII export cuts
#: names to 14 or 20 characters (``Grip to grip s``).
GAUGE_KINDS: dict[str, tuple[str, ...]] = {
    "crosshead": (
        "crosshead", "cross head", "stroke", "position", "actuator", "piston", "machine",
        "standard travel", "grip to grip separation", "grip separation", "grip to grip",
        "écartement entre outils",
        "traverse", "traversenweg", "standardweg", "standardwegaufnehmer", "kolbenweg",
        "maschinenweg", "trawersa", "trawersy", "tłok", "droga standardowa", "travesaño",
        "actuador", "pistón", "carrera", "course", "vérin", "travessa", "atuador", "pistão",
        "traversa", "corsa", "attuatore", "pistone", "траверса", "перемещение траверсы",
        "ход поршня", "положение", "横梁位移", "横梁", "行程", "位移", "ストローク",
        "クロスヘッド変位",
        "traversepositie", "zuiger", "크로스헤드", "스트로크",
    ),
    "extensometer": (
        "extensometer", "ext", "clip gauge", "strain", "ave", "dehnung", "feindehnung",
        "ansetzdehnungsaufnehmer", "maytec", "ekstensometr", "odkształcenie", "extensómetro",
        "deformación", "dial", "czujnik", "extensomètre", "déformation", "déform",
        "extensômetro", "estensometro", "deformazione", "ekstansometre", "экстензометр",
        "引伸计", "应变", "变形", "引伸计变形", "大变形", "小变形", "伸び計", "rek", "gerinim",
        "ひずみ", "歪み", "변형률", "신장계",
        "optical", "exts",
    ),
}

#: Names of channels that measure across the specimen (a width or thickness change, a
#: transverse strain, a DIC field's minor strain): never its extension, whatever their unit
#: says.
TRANSVERSE_NAMES = (
    "width", "width change", "transverse", "transverse strain", "lateral", "lateral strain",
    "hoop", "hoop strain", "circumferential strain",
    "thickness", "thickness change", "thickness strain", "width strain", "minor strain",
    "breite", "breitenänderung", "breitenaenderung", "breitendehnung", "dicke",
    "dickenänderung", "dickenaenderung", "dickendehnung", "querdehnung", "szerokość", "grubość",
    "anchura", "espesor", "横", "横 ひずみ", "横ひずみ", "横歪み",
)
#: Words of a channel that holds what the controller asked for (a setpoint, a command),
#: not what a sensor measured: ``"Ch 1 Kraft Sollwert"``, ``"Load Command"``,
#: ``"Valeur de consigne"``, a controller's ``"a1 torque cmd"``; or a setting of the
#: amplifier (a DAQ table's ``"gain load"``, a sensitivity, a calibration factor); or what a
#: model or a script expects (a calibration log's ``expected_force_mN``). Such a
#: column takes no role, wherever the word stands.
COMMAND_NAMES = ("sollwert", "soll", "setpoint", "set point", "command", "cmd", "demand",
                 "target", "consigne", "commande", "consigna", "zadana", "gain",
                 "sensitivity", "calibration", "verstärkung", "empfindlichkeit",
                 "expected", "predicted", "theoretical", "simulated", "erwartet")
#: Words of a channel the machine's software worked out from others, not one a sensor
#: measured: WaveMatrix's ``"Elastic Strain(Static Plastic & Elastic Strain
#: Calculation)"``, a strain split into its elastic part (the stress over an assumed
#: modulus) and its plastic rest; a true (logarithmic) strain, ln(1 + e), 30 % below the
#: engineering strain at 100 %. Such a column takes no role: a stiffness fitted to it
#: returns the modulus it was computed with.
DERIVED_NAMES = ("calculation", "berechnung", "calcul", "cálculo", "calcolo", "obliczenia",
                 "elastic strain", "plastic strain", "elastische dehnung",
                 "plastische dehnung", "déformation élastique", "déformation plastique",
                 "true strain", "log strain", "logarithmic strain", "hencky strain",
                 "wahre dehnung", "logarithmische dehnung", "déformation vraie")
#: Words of a test's results, one value a specimen (``Yield (N)``, ``Break Elong [mm]``,
#: ``Tensile Str. (MPa)``, ``Modulus of Elasticity``, ``Bruchdehnung``; a chain
#: catalogue's ``Breaking load``, ``Mindestbruchkraft``, ``MBL``): such a column takes no
#: role, and under such names rows each labelled their own are specimens
#: (:func:`says_result`).
RESULT_WORDS = frozenset({"yield", "break", "breaking", "modulus", "strength", "str",
                          "toughness", "rupture", "ruptura", "rotura", "modul", "bruch",
                          "bruchdehnung", "bruchkraft", "mindestbruchkraft", "bruchlast", "mbl",
                          "streckgrenze", "zugfestigkeit", "festigkeit"})
#: Names of an air's humidity, logged in % beside the channels (a climate chamber's ``RH``):
#: no strain, whatever its unit says.
HUMIDITY_NAMES = ("rh", "humidity", "relative humidity", "feuchte", "luftfeuchte",
                  "luftfeuchtigkeit", "humidité", "humedad", "wilgotność", "umidità", "umidade")
#: Names of one part of a clock reading split into columns (``Hour [h]``, ``Minute [m]``,
#: ``Second [sec]``, as a LabVIEW logger writes them; the date, as MTS 793 writes
#: ``Datum [d]``, the spreadsheet's day number): no elapsed time, and no length whatever
#: their unit says (``m`` is a minute there).
CLOCK_PART_NAMES = ("hour", "minute", "second", "stunde", "sekunde", "heure", "seconde",
                    "hora", "minuto", "segundo", "ora", "secondo",
                    "date", "datum", "fecha", "дата", "日付", "日期", "tarih")
#: Words a logger appends to a channel's name for the statistic of each interval it writes
#: (PicoLog's ``Force Ave. (kN)``, ``LVDT Last (mm)``, ``Differential 13 - 14 Last (V)``):
#: after other words, a qualifier, not the German load (``Last``) or Instron's video
#: extensometer (``AVE``).
STATISTIC_WORDS = ("last", "ave", "avg", "mean", "min", "max")
#: Words in parentheses after a name that say how its values were worked, not their unit
#: (a dyno's ``Power (uncorrected)``, ``Ashcroft (Relative)``, a rig's ``Force (filtered)``).
QUALIFIER_WORDS = frozenset({"uncorrected", "corrected", "filtered", "unfiltered", "raw",
                             "relative", "absolute", "smoothed", "averaged", "calculated",
                             "computed", "measured", "nominal", "gefiltert", "ungefiltert",
                             "korrigiert", "unkorrigiert", "roh"})
#: First words of the name of a channel a second instrument recorded beside the testing
#: machine's own: a video extensometer's or camera's clock (MTS TestSuite's ``Video
#: Time`` beside the controller's ``Time``).
AUXILIARY_WORDS = frozenset({"video", "camera", "dic"})
#: The CCFatigue layout's columns of a "measuring device" (a camera, a logger) at its
#: points: ``MD_Load--1``, ``MD_N_cycles--#`` beside ``Machine_Load``, ``Machine_N_cycles``.
_MEASURING_DEVICE = re.compile(r"md_.*--", re.IGNORECASE)
#: Words of a time or a counter that runs over the whole test (WaveMatrix's ``Total Cycles``
#: beside the step's ``Elapsed Cycles``; a rig's ``CYCLES TOTAL`` beside ``CYCLES RESET``).
TOTAL_WORDS = frozenset({"total", "totale", "totales"})
#: First words of a time that starts again with a part of the test (MTS TestStar's ``Scan
#: Time``, each block's, beside its ``Elapsed Time``; a step's, a segment's, a cycle's).
PART_WORDS = frozenset({"scan", "step", "segment", "stage", "block", "loop", "cycle"})
#: Words of a fracture test's crack record: its length, its opening, and the machine's
#: readings copied where it was measured (the CCFatigue layout's ``Crack_length``,
#: ``Crack_Displacement``, ``Crack_Load``): no chain's length, no gauge along the specimen.
CRACK_WORDS = frozenset({"crack", "cracks"})
#: First words of a load a machine's software works out in the sign of one kind of test
#: beside the load it measured (Bluehill's ``Compressive load``: ``Load`` with its sign
#: turned, for a compression test's plots).
SIGN_CONVENTION_WORDS = frozenset({"compressive", "tensile"})
#: Names of other quantities than a test's: a count that is no cycle count (a load-cell
#: rig's ``sample_count``, the readings it averaged; Bluehill's ``PIP count``, the marks an
#: operator's button set), a temperature (``Temp(°)``, whose degrees are no angle), an
#: acceleration (a drop tower's ``Deformation Acceleration (m/s^2)``, no deformation), a
#: strain of a DIC field other than along the specimen (``mises_strain``, an equivalent
#: strain; a shear strain) and a
#: torque (a drive rig's ``torque (nm)``, newton metres in lower case, no nanometres), a
#: logger's stamps of a state's last change (``last_changed``, no German load), a rate or
#: a pace of a quantity (a rowing machine's ``Stroke Rate (SPM)``, ``Pace``; a
#: ``Load rate``, no load), a stress in Spanish (Bluehill's ``Tensión de tracción``: no
#: chain's tension), a meter's setting of its display (a Keithley's ``Disp
#: Digits``, no displacement), a logger's external input or trigger (a force plate's
#: ``ExtIn1``, no extensometer). Such a column takes no role, not even from its unit.
OTHER_QUANTITY_NAMES = ("sample count", "samples count", "point count", "points count",
                        "reading count", "readings count", "scan count", "pip count", "temp",
                        "temperature", "temperatur", "température", "temperatura", "温度",
                        "acceleration", "accel", "beschleunigung", "accélération",
                        "aceleración", "aceleração", "accelerazione", "mises strain",
                        "von mises strain", "equivalent strain", "effective strain",
                        "shear strain", "vergleichsdehnung", "cop", "center of pressure",
                        "centre of pressure", "last changed", "last updated", "last reset",
                        "last seen", "torque", "drehmoment", "stroke rate", "load rate",
                        "loading rate", "force rate", "strain rate", "stress rate",
                        "displacement rate", "extension rate", "cycle rate", "pace", "digits",
                        "tensión de tracción", "tensión de compresión", "tensión de flexión",
                        "moment obrotowy", "momento torsor", "couple moteur", "扭矩", "トルク",
                        "토크", "крутящий момент", "ext in", "ext trig", "external input",
                        "external trigger")
#: Words of another quantity only as written, with their accent: Spanish ``Tensión``, a
#: stress (or a voltage), which without it is the English tension, a force.
ACCENTED_OTHER_WORDS = frozenset({"tensión"})
#: The labels of :data:`TRANSVERSE_NAMES` and :data:`OTHER_QUANTITY_NAMES` among the role
#: keywords: each wins as a role would.
_TRANSVERSE = "transverse"
_OTHER_QUANTITY = "other quantity"
_NO_ROLE_LABELS = (_TRANSVERSE, _OTHER_QUANTITY)

_BRACKETED = re.compile(r"^(?P<name>.*?)\s*(?:\[(?P<sq>[^\[\]]*)\]|\((?P<par>[^()]*)\)"
                        r"|<(?P<ang>[^<>]*)>|【(?P<jis>[^【】]*)】|（(?P<wide>[^（）]*)）)\s*$")
#: A sensor's serial number (or number alone) in brackets after a name and its unit
#: (HOBOware's ``Temp, °C (LGR S/N: 10694967)``, a Loadstar logger's ``Reading (lbf)
#: (88)``): no unit.
_SERIAL = re.compile(r"\b(?:S/N|SN|serial)\b|^\s*\d+\s*$", re.IGNORECASE)
#: The suffix pandas gives a repeated name, after a unit in brackets (``Force (N).1``).
_PANDAS_COPY = re.compile(r"(?P<head>.*\S\s*[\])>])(?P<suffix>\.\d+)")
#: A count in thousands said by its name (``Cycles x1000``, ``Zyklen in Tsd``, ``Thousand
#: cycles``, ``kCycles``): its unit, ``x1000``, which no counter is read in.
_THOUSANDS_COUNT = re.compile(
    r"(?P<name>.*?\S)\s*(?:[x×*]\s*1[ ,.']?000|/\s*1[ ,.']?000|\(\s*[x×*]\s*1[ ,.']?000\s*\)"
    r"|in\s+(?:thousands?|tsd\.?))|(?:thousands?\s+(?:of\s+)?|tsd\.?\s+|k)(?P<counted>"
    r"cycles?|zyklen|lastwechsel)", re.IGNORECASE)
#: A percent sign and a blank before a gauge's name (a fibre tester's ``% Strain``,
#: ``% Elongation``): its unit.
_PERCENT_FIRST = re.compile(r"%\s+(?P<name>[^\W\d_][^_]*)")
#: A unit after a comma (``Temp, °C``, ``Нагрузка, кН``): one word, no number.
_COMMA_UNIT = re.compile(r"(?P<name>.*\S),\s+(?P<unit>[^\s\d]\S*)")
#: The run label PASCO Capstone writes after a column's unit (``Force (N) Run #1``,
#: ``Time (s) Auto``).
_RUN_LABEL = re.compile(r"\s+(?:Run\s*#?\s*\d+|Auto)$")
#: The channel a computed one was derived from, in trailing brackets.
_SOURCE = re.compile(r"\((?P<source>[^()]+)\)\s*$")
#: A displacement of an MTS controller's channel (``Ch 1 Weg``, ``Ch 1 Displacement``,
#: ``Ch 1 LVDT``, TestWare's ``Channel 1 Displacement``) or station (793's ``Axial
#: Displacement``, ``Universal Displacement``): the channel's own transducer on its
#: actuator, so the machine's travel; the sensors on the specimen are named by the lab
#: (``Extensometer``, a serial number) or by the station as a strain (``Axial Strain``).
_CONTROLLER_TRAVEL = re.compile(r"(?:ch\.? ?\d+|channel ?\d+|axial|universal) "
                                r"(?:weg|displacement|position|lvdt|stroke)", re.IGNORECASE)
_TOKEN = re.compile(r"[^\W\d_]+|\d+")


def fold(text: str) -> str:
    """`text` in lower case without diacritics (``"Siła"`` -> ``"sila"``)."""
    decomposed = unicodedata.normalize("NFKD", text.casefold().replace("ł", "l"))
    return "".join(char for char in decomposed if not unicodedata.combining(char))


def tokens(text: str) -> tuple[str, ...]:
    """The words and numbers of `text`, folded (``"Machine_N_cycles"`` -> machine, n, cycles)."""
    return tuple(_TOKEN.findall(fold(text)))


_KEYWORDS: tuple[tuple[tuple[str, ...], str], ...] = tuple(
    (tokens(word), role)
    for language in COLUMN_NAMES.values()
    for role, words in language.items()
    for word in words
) + tuple((tokens(word), _TRANSVERSE) for word in TRANSVERSE_NAMES
          ) + tuple((tokens(word), _OTHER_QUANTITY) for word in OTHER_QUANTITY_NAMES)


def header_text(header: str) -> str:
    """A header cell without surrounding blanks or a byte-order mark."""
    return header.strip().lstrip("\ufeff").strip()


def split_name_unit(header: str) -> tuple[str, str | None]:
    """Split a header cell into the column name and the unit in brackets.

    Parameters
    ----------
    header : str
        A names-row cell, e.g. ``"force [kN]"``, ``"Load (N)"``, ``"KRAFT <N>"``,
        ``"Kraft / kN"`` (ISO 80000 quantity / unit), ``"Нагрузка, кН"`` (after a comma),
        ``"荷重【kN】"``, ``"Force (N) Run #1"`` (the run label kept in the name),
        ``"Temp, °C (LGR S/N: 1069)"`` (a serial number kept in the name), ``"% Strain"``,
        pandas' ``"Force (N).1"`` (its suffix kept in the name) or ``"Time"``.

    Returns
    -------
    name : str
        The name without the unit, stripped.
    unit : str or None
        The text inside trailing ``[...]``, ``(...)``, ``<...>``, ``【...】`` or full-width
        parentheses ``（...）``, or after `` / `` (or a single ``/``) or a comma when pint
        reads it as a unit, or a percent sign before the name; None when there is none.
    """
    text = header_text(header)
    copy = _PANDAS_COPY.fullmatch(text)
    if copy is not None:  # pandas' "Displacement (mm).1": the unit before its suffix
        name, unit = split_name_unit(copy["head"])
        return name + copy["suffix"], unit
    label = _RUN_LABEL.search(text)
    if label is not None and label.start() > 0:  # PASCO Capstone: "Force (N) Run #1"
        name, unit = split_name_unit(text[: label.start()])
        if unit is not None:
            return name + label.group(), unit
    match = _BRACKETED.match(text)
    if match is not None and match["par"] is not None and _SERIAL.search(match["par"]):
        name, unit = split_name_unit(match["name"])
        return f"{name} ({match['par'].strip()})", unit
    if match is not None and match["name"] and not _qualifier(match):
        unit = next(match[group] for group in ("sq", "par", "ang", "jis", "wide")
                    if match[group] is not None)
        return match["name"].strip(), unit.strip() or None  # "time ()": no unit
    separator = " / " if " / " in text else "/" if text.count("/") == 1 else None
    if separator:
        name, _, unit = text.rpartition(separator)
        if name.strip() and spellings(unit) and not (separator == "/" and (
                _ends_in_unit_over(name, unit) or re.fullmatch(r"\s*\d+\s*", name))):
            return name.strip(), unit.strip()
    match = _COMMA_UNIT.fullmatch(text)
    if match is not None and spellings(match["unit"]):
        return match["name"], match["unit"]
    match = _THOUSANDS_COUNT.fullmatch(text)
    if match is not None:
        return match["name"] or match["counted"], "x1000"
    match = _PERCENT_FIRST.fullmatch(text)
    if match is not None and match_role(match["name"]) == "gauge":  # not MATLAB's "% time_s"
        return match["name"], "%"
    return text, None


def _ends_in_unit_over(name: str, unit: str) -> bool:
    """Whether `name` ends in a word that makes a unit over `unit`: the ``/`` is then inside
    a compound unit (a dyno's ``TCP RX kB/s``, ``Drehzahl U/min``), not after a name; or
    is a unit of length, or of three letters or more, that names no role (a rheometer's
    ``rad/s`` taken for the names: no ``rad`` in seconds, a time; ``mm/s``; a quantity's
    symbol is shorter and no length, ``t/s``, ``F/kN``)."""
    words = name.split()
    if len(words) == 1 and not ((len(words[0]) >= 3 or unit_fits(words[0], "length"))
                                and spellings(words[0]) and match_role(words[0]) is None):
        return False
    return (bool(words) and words[-1][0].isalpha()
            and bool(spellings(f"{words[-1]}/{unit.strip()}")))


def _qualifier(match: re.Match) -> bool:
    """Whether the parentheses of `match` qualify the name rather than give its unit: set
    against it without a blank, words that are no unit (WaveMatrix's ``Total Cycle
    Count(Linear Waveform)`` beside ``Total Cycle Count(Rotary Waveform)``); or one of
    :data:`QUALIFIER_WORDS` (a dyno's ``Power (uncorrected)`` beside ``Power``)."""
    inside = match["par"]
    if inside is not None and fold(inside.strip()) in QUALIFIER_WORDS:
        return True
    return (inside is not None and not match.string[match.start("par") - 2].isspace()
            and " " in inside.strip() and not spellings(inside))


def _best_match(name: str, keywords: tuple[tuple[tuple[str, ...], str], ...]) -> str | None:
    """The label of the keyword ending last in `name` (then the longest), or None; a last
    word of :data:`STATISTIC_WORDS` after others never counts (PicoLog's ``Differential
    13 - 14 Last``: the last reading of a channel not named, not a load)."""
    words = tokens(name)
    if len(words) > 1 and words[-1] in STATISTIC_WORDS:
        words = words[:-1]
    return _best_of(words, keywords)


def _best_of(words: tuple[str, ...], keywords: tuple[tuple[tuple[str, ...], str], ...]
             ) -> str | None:
    """The label of the keyword ending last among `words` (then the longest), or None."""
    best: tuple[int, int, str] | None = None
    for keyword, label in keywords:
        size = len(keyword)
        for start in range(len(words) - size + 1):
            if words[start : start + size] == keyword:
                rank = (start + size, size, label)
                if best is None or rank[:2] > best[:2]:
                    best = rank
    return best[2] if best else None


_KIND_KEYWORDS = tuple(
    (tokens(word), kind) for kind, words in GAUGE_KINDS.items() for word in words
)


def gauge_kind(name: str) -> str:
    """What a displacement channel measures, from its name: see :data:`GAUGE_KINDS`.

    A channel computed from another names it in trailing brackets and measures
    what that one does: Bluehill's ``"Tensile strain (Extension)"`` is the
    crosshead's extension over the gauge length, not an extensometer's strain.

    Examples
    --------
    >>> gauge_kind("Traversenweg"), gauge_kind("Dehnung 1"), gauge_kind("Extension")
    ('crosshead', 'extensometer', 'gauge')
    >>> gauge_kind("Tensile strain (Extension)"), gauge_kind("Tensile strain (AVE 2)")
    ('gauge', 'extensometer')
    >>> gauge_kind("Ch 1 Weg"), gauge_kind("Ch 1 LVDT"), gauge_kind("1470533")
    ('crosshead', 'crosshead', 'gauge')
    """
    source = _SOURCE.search(name)
    if source is not None:
        return gauge_kind(source["source"])
    if _CONTROLLER_TRAVEL.fullmatch(name.strip()):
        return "crosshead"
    return _best_match(name, _KIND_KEYWORDS) or "gauge"


#: English temperatures named by their sensors' tags (a test stand's ``temps.T1``,
#: ``temps_TC2``), which the French time, ``temps``, would otherwise claim.
_TEMPERATURES = re.compile(r"temps\W*[a-z]{1,3}\W*\d+")


def match_role(name: str) -> str | None:
    """The role a column name suggests, or None.

    When several names match (``"Cycle time"``), the one ending last in the
    name wins (the head noun in English and German compounds), then the longest. A
    name ending in ``id`` names an identifier (a logger's ``actuator_a_id``), no
    measurement.

    Examples
    --------
    >>> match_role("Total Cycle Count"), match_role("Machine_Load"), match_role("Siła")
    ('cycle_count', 'force', 'force')
    >>> match_role("actuator_a_id") is None, match_role("Tensión") is None  # a stress
    (True, True)
    >>> match_role("SmallLVDT"), match_role("LoadCell")  # camel case, set apart
    ('gauge', 'force')
    >>> match_role("Temps"), match_role("temps.T1"), match_role("ExtIn1")
    ('time', None, None)
    """
    if (tokens(name)[-1:] == ("id",) or _TEMPERATURES.fullmatch(fold(name).strip())
            or not ACCENTED_OTHER_WORDS.isdisjoint(
                re.findall(r"\w+", unicodedata.normalize("NFC", name.casefold())))):
        return None
    role = _keyword(name)
    return (None if role in _NO_ROLE_LABELS or is_command(name) or is_derived(name)
            or is_crack(name) or says_result(name) else role)


#: Where a name written in camel case (``SmallLVDT``, ``LoadCell``) is set apart into words.
_CAMEL = re.compile(r"(?<=[a-z])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])")


def _keyword(name: str) -> str | None:
    """The label of :data:`COLUMN_NAMES` (or of the no-role names) `name` matches: as
    written, else with its camel-case words set apart (``SmallLVDT`` -> ``Small LVDT``;
    ``CrossHead`` matches as written)."""
    return _best_match(name, _KEYWORDS) or _best_match(_CAMEL.sub(" ", name), _KEYWORDS)


_COMMAND_KEYWORDS = tuple((tokens(word), "command") for word in COMMAND_NAMES)
_DERIVED_KEYWORDS = tuple((tokens(word), "derived") for word in DERIVED_NAMES)


def is_command(name: str) -> bool:
    """Whether a column name says it holds a setpoint or a command (:data:`COMMAND_NAMES`):
    such a column takes no role, not even from its unit.

    >>> [is_command(name) for name in ("Ch 1 Kraft Sollwert", "Load Command", "Ch 1 Kraft")]
    [True, True, False]
    """
    return _best_match(name, _COMMAND_KEYWORDS) is not None


def is_derived(name: str) -> bool:
    """Whether a column name says the software worked it out from other channels
    (:data:`DERIVED_NAMES`): such a column takes no role, not even from its unit.

    >>> [is_derived(name) for name in (
    ...     "Elastic Strain(Static Plastic & Elastic Strain Calculation)",
    ...     "Total Energy(Energy Calculation)", "Strain(8801MTB12548:SGE-57)")]
    [True, True, False]
    """
    return _best_of(tokens(name), _DERIVED_KEYWORDS) is not None


def says_result(name: str) -> bool:
    """Whether a column name holds a word of a test's results (:data:`RESULT_WORDS`).

    >>> [says_result(name) for name in ("Yield (N)", "Tensile Str. (MPa)", "Load (N)")]
    [True, True, False]
    """
    return not RESULT_WORDS.isdisjoint(tokens(name))


def is_unmeasured(name: str) -> bool:
    """Whether a column name says it holds no measurement along the specimen: a transverse
    channel (:data:`TRANSVERSE_NAMES`), another quantity (:data:`OTHER_QUANTITY_NAMES`), a
    setpoint or command, a value worked out from others, one part of a clock reading, a
    crack's record (:data:`CRACK_WORDS`), or a test's result (:data:`RESULT_WORDS`). Such
    a column takes no role, not even from its unit.

    >>> [is_unmeasured(name) for name in ("Querdehnung", "Load Command", "Minute",
    ...                                   "Crack_length", "sample_count", "Temp", "Load")]
    [True, True, True, True, True, True, False]
    """
    return (_keyword(name) in _NO_ROLE_LABELS or is_command(name) or is_derived(name)
            or is_clock_part(name) or is_crack(name) or says_result(name))


def is_crack(name: str) -> bool:
    """Whether a column name is of a crack's record (:data:`CRACK_WORDS`): such a column
    takes no role, not even from its unit.

    >>> [is_crack(name) for name in ("Crack_length", "Crack_Load  ", "Load")]
    [True, True, False]
    """
    return not CRACK_WORDS.isdisjoint(tokens(name))


def is_auxiliary(name: str) -> bool:
    """Whether a column name says a second instrument recorded it beside the testing
    machine (:data:`AUXILIARY_WORDS` first, or the CCFatigue layout's ``MD_...--#``): of
    several columns that could take one role, such a one gives way to the machine's.

    >>> [is_auxiliary(name) for name in ("Video Time", "MD_Load--1", "Time", "Load MD")]
    [True, True, False, False]
    """
    return (_opens_with(name, AUXILIARY_WORDS)
            or _MEASURING_DEVICE.match(name.strip()) is not None)


def says_total(name: str) -> bool:
    """Whether a time's or a counter's name says it runs over the whole test
    (:data:`TOTAL_WORDS`, or a German compound of ``Gesamt``), not from a step's or a
    cycle's start or a counter's reset.

    >>> [says_total(name) for name in ("Total Time", "Gesamtzyklen", "CYCLES TOTAL",
    ...                                "Elapsed Cycles", "Cycle Elapsed Time")]
    [True, True, True, False, False]
    """
    words = tokens(name)
    return not TOTAL_WORDS.isdisjoint(words) or any(word.startswith("gesamt") for word in words)


#: Words of a column's name that call it a weight or a mass (a hanging-scale or a
#: load-cell logger's ``weight``): no role, but perhaps the load.
WEIGHT_WORDS = frozenset({"weight", "mass", "gewicht", "masse", "peso", "masa", "waga",
                          "poids", "massa", "重量", "質量", "质量"})


def says_weight(name: str) -> bool:
    """Whether a column's name calls it a weight or a mass (:data:`WEIGHT_WORDS`).

    >>> [says_weight(name) for name in ("weight", "Weight_g", "Load")]
    [True, True, False]
    """
    return not WEIGHT_WORDS.isdisjoint(tokens(name))


def says_part(name: str) -> bool:
    """Whether a column name opens with :data:`PART_WORDS`: a time (or count) of a part of
    the test, which starts again with each.

    >>> [says_part(name) for name in ("Scan Time", "Elapsed Time", "Step time")]
    [True, False, True]
    """
    return _opens_with(name, PART_WORDS)


def says_sign_convention(name: str) -> bool:
    """Whether a column name opens with :data:`SIGN_CONVENTION_WORDS`: a load worked out in
    one kind of test's sign, beside the measured one.

    >>> [says_sign_convention(name) for name in ("Compressive load", "Load", "Tensile load")]
    [True, False, True]
    """
    return _opens_with(name, SIGN_CONVENTION_WORDS)


def _opens_with(name: str, words: frozenset[str]) -> bool:
    """Whether the first word of a column name is one of `words`."""
    first = tokens(name)[:1]
    return bool(first) and first[0] in words


def is_humidity(name: str) -> bool:
    """Whether a column name is an air's humidity (:data:`HUMIDITY_NAMES`).

    >>> [is_humidity(name) for name in ("RH", "Rel. Luftfeuchte", "Strain 1")]
    [True, True, False]
    """
    return _best_of(tokens(name), _HUMIDITY_KEYWORDS) is not None


_HUMIDITY_KEYWORDS = tuple((tokens(word), "humidity") for word in HUMIDITY_NAMES)


def is_clock_part(name: str) -> bool:
    """Whether a column name is one part of a clock reading (:data:`CLOCK_PART_NAMES`): such
    a column takes no role, not even from its unit.

    >>> [is_clock_part(name) for name in ("Minute", "Stunde", "Minutes", "Time")]
    [True, True, False, False]
    """
    return tokens(name) in _CLOCK_PARTS


_CLOCK_PARTS = {tokens(word) for word in CLOCK_PART_NAMES}


def is_transverse(name: str) -> bool:
    """Whether a column name says it measures across the specimen (:data:`TRANSVERSE_NAMES`):
    such a column takes no role, not even from its unit.

    >>> [is_transverse(name) for name in ("Breitenänderung", "Transverse strain", "Strain")]
    [True, True, False]
    """
    return _keyword(name) == _TRANSVERSE


def repeats(names: list[str]) -> int:
    """How many times the columns repeat one group of names side by side (1: they do not).

    Trailing unnamed columns are left out; a group needs two names or more, one
    of which is not empty. Several specimens of one test exported into one
    file (Shimadzu Trapezium) repeat their columns so.

    Examples
    --------
    >>> repeats(["Temps", "Force", "Stroke", "Temps", "Force", "Stroke", ""])
    2
    >>> repeats(["time", "force", "gauge", "gauge"])
    1
    >>> repeats(["Time Run 5", "Force Run 5", "Time Run 6", "Force Run 6"])  # PASCO
    2
    >>> repeats(["Latest: Time", "Latest: Force", "Run 1: Time", "Run 1: Force"])  # Vernier
    2
    >>> repeats(["Force", "Disp 1", "Force.1", "Disp 1.1"])  # pandas, a name ending in 1
    2
    """
    folded = [fold(_RUN_LABEL.sub("", name.strip())) for name in names]
    while folded and not folded[-1]:
        folded.pop()
    for size in range(2, len(folded) // 2 + 1):
        if len(folded) % size == 0 and any(folded[:size]) and all(
                name == folded[index % size] for index, name in enumerate(folded)):
            return len(folded) // size
        if len(folded) % size == 0 and any(folded[:size]) and all(  # pandas: "Force.1"
                name == f"{folded[index % size]}.{index // size}"
                for index, name in enumerate(folded[size:], start=size)):
            return len(folded) // size
    return _numbered_repeats(folded)


#: A specimen's number in a column name: after it (``Force 1``, ``Force_2``, ``Load (S1)``,
#: ``Kraft (Probe 3)``, pandas' ``Kraft.1`` for a repeated name) or before it
#: (``Probe 1 Kraft``, ``Sample 2 Force``, Vernier's ``Run 1: Force``, whose newest run is
#: ``Latest: Force``, unnumbered).
_NUMBER_AFTER = re.compile(
    r"(?P<base>.*?[^\W\d_].*?)(?:\s*[#_.\-]\s*|\s+|\s*\(\s*(?:s|sample|specimen|probe|"
    r"probek|run)?\s*#?\s*)(?P<number>\d+)\s*\)?")
_NUMBER_BEFORE = re.compile(
    r"(?:(?:sample|specimen|probe|probek|run)\s*#?\s*(?P<number>\d+)|latest)\s*[:_\-]?\s+"
    r"(?P<base>.+)")


#: A run's label in a name (PASCO Capstone's ``Time (s) Run 5`` after it, Vernier's
#: ``Run 1: Force (N)`` before it).
_RUN_IN_NAME = re.compile(r"(?:^|\s)(Run\s*#?\s*\d+)(?::|\s*$)", re.IGNORECASE)


def run_labels(names: list[str], count: int) -> list[str]:
    """The labels of `count` groups of columns side by side (`names`, the groups' columns
    in order), as the runs of a logger name them (``Run 5``, ``Run 6``): the label in the
    first name of each group, when every group's has one of its own; else none.

    >>> run_labels(["Time Run 5", "Force Run 5", "Time Run 6", "Force Run 6"], 2)
    ['Run 5', 'Run 6']
    """
    size = len(names) // count
    found = [_RUN_IN_NAME.search(names[group * size]) for group in range(count)]
    labels = [" ".join(match.group(1).split()) for match in found if match]
    return labels if len(set(labels)) == count else []


def _numbered(name: str) -> tuple[str, str | None]:
    """A folded name without its specimen's number, and that number (None: no number)."""
    for pattern in (_NUMBER_AFTER, _NUMBER_BEFORE):
        if found := pattern.fullmatch(name):
            return found["base"].strip(), found["number"]
    return name, None


def _numbered_repeats(folded: list[str]) -> int:
    """How many times the folded names repeat one group of names side by side, each group
    numbered by its specimen (``Force 1, Disp 1, Force 2, Disp 2``; the first group may
    be unnumbered, as pandas writes ``Kraft, Weg, Kraft.1, Weg.1``); 1 if they do not.

    Every name of a group carries the same number and the groups different ones, so
    that two gauges of one specimen (``time, force, gauge 1, gauge 2``) are no groups.

    Examples
    --------
    >>> _numbered_repeats(["force 1", "disp 1", "force 2", "disp 2"])
    2
    >>> _numbered_repeats(["time", "force", "gauge 1", "gauge 2"])
    1
    """
    parsed = [_numbered(name) for name in folded]
    for size in range(2, len(parsed) // 2 + 1):
        if len(parsed) % size:
            continue
        groups = [parsed[start:start + size] for start in range(0, len(parsed), size)]
        numbers = [{number for _, number in group} for group in groups]
        if (all(len(found) == 1 for found in numbers)
                and len({next(iter(found)) for found in numbers}) == len(groups)
                and None not in set().union(*numbers[1:])
                and all([base for base, _ in group] == [base for base, _ in groups[0]]
                        for group in groups)):
            return len(groups)
    return 1


#: Words that make a column one statistic of each cycle, in a table of one row per
#: cycle (Instron WaveMatrix's trends: ``"Kraft:Maximum"``, ``"Kraft:Minimum"``).
_PEAK_WORDS = {"maximum": "max", "max": "max", "peak": "max", "höchstwert": "max",
               "fmax": "max", "oberlast": "max",
               "minimum": "min", "min": "min", "valley": "min", "tiefstwert": "min",
               "fmin": "min", "unterlast": "min"}
_PEAK_TOKENS = {tokens(word)[0]: side for word, side in _PEAK_WORDS.items()}


def is_held_peak(names: list[str], index: int) -> bool:
    """Whether column `index` is a peak held beside the reading: its name holds a word of a
    maximum (``peak``, ``max``...) and no column is the same channel's minimum (as a
    cycle's extremes are, :func:`peak_partner`).

    >>> names = ["timestamp", "current", "peak", "Load max", "Load min"]
    >>> [is_held_peak(names, index) for index in range(5)]
    [False, False, True, False, False]
    """
    found = _extreme(names[index])
    return found is not None and found[1] == "max" and peak_partner(names, index) is None


def _extreme(name: str) -> tuple[tuple[str, ...], str] | None:
    """The words of `name` but its one extreme word (:data:`_PEAK_WORDS`), and the side of
    that word (``"max"`` or ``"min"``); None without one such word."""
    words = tokens(name)
    found = [(position, _PEAK_TOKENS[word]) for position, word in enumerate(words)
             if word in _PEAK_TOKENS]
    if len(found) != 1:
        return None
    position, side = found[0]
    return words[:position] + words[position + 1:], side


def peak_partner(names: list[str], index: int) -> str | None:
    """The column that is the other extreme of column `index`'s channel, or None.

    A column is one of a cycle's extremes when the names hold its name with a
    maximum word and with a minimum word, and nothing else differs.

    Examples
    --------
    >>> names = ["Zyklen", "Kraft:Maximum (N)", "Kraft:Minimum (N)", "Weg"]
    >>> peak_partner(names, 1), peak_partner(names, 3)
    ('Kraft:Minimum (N)', None)
    """
    mine = _extreme(names[index])
    if mine is None:
        return None
    for other in names:
        theirs = _extreme(other)
        if theirs is not None and theirs[0] == mine[0] and theirs[1] != mine[1]:
            return other
    return None


#: Words of a statistic of each cycle other than its extremes (WaveMatrix's
#: ``Strain:Amplitude``, ``Kraft:Mittel der Spitzenwerte``, a mean, a range), folded.
_CYCLE_STATISTIC_WORDS = frozenset({"amplitude", "mean", "average", "range", "bereich",
                                    "mittel", "mittelwert", "der", "spitzenwerte", "of",
                                    "peaks"})


def is_cycle_statistic(names: list[str], index: int) -> bool:
    """Whether column `index` is one statistic of each cycle: one of a cycle's extremes
    (:func:`peak_partner`), or the amplitude, mean or range of a channel whose extremes
    are there (WaveMatrix's ``Strain:Amplitude`` beside ``Strain:Maximum``,
    ``Strain:Minimum``).

    >>> names = ["Cycles", "Strain:Maximum", "Strain:Minimum", "Strain:Amplitude", "Load"]
    >>> [is_cycle_statistic(names, index) for index in range(5)]
    [False, True, True, True, False]
    """
    if peak_partner(names, index) is not None:
        return True
    words = tokens(names[index])
    if _CYCLE_STATISTIC_WORDS.isdisjoint(words):
        return False
    channel = tuple(word for word in words if word not in _CYCLE_STATISTIC_WORDS)
    return any((found := _extreme(other)) is not None and found[0] == channel
               for other in names)
