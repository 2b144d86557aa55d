"""Column names per language -> roles; units in header cells."""

import pytest

from pipeline.ingest.names import (
    COLUMN_NAMES,
    fold,
    gauge_kind,
    is_clock_part,
    is_command,
    is_derived,
    is_transverse,
    is_unmeasured,
    match_role,
    repeats,
    split_name_unit,
)


@pytest.mark.parametrize(
    ("name", "role"),
    [
        ("Time", "time"), ("Zeit", "time"), ("czas", "time"), ("Tiempo", "time"),
        ("Load", "force"), ("Standardkraft", "force"), ("siła", "force"),
        ("OBCIĄŻENIE", "force"), ("obciazenie", "force"), ("Channel 1 Force", "force"),
        ("Axial Fuerza", "force"), ("Machine_Load", "force"),
        ("Extension", "gauge"), ("Weg", "gauge"), ("Dehnung", "gauge"),
        ("wydłużenie 2", "gauge"), ("przemieszczenie", "gauge"), ("gauge1", "gauge"),
        ("Ext2", "gauge"), ("Axial Desplazamiento", "gauge"),
        ("Disp", "gauge"),  # a real MTI export: Load, Disp, Stress, Time, Temp, Axial
        ("Winkel", "angle"), ("kąt", "angle"), ("encoder", "angle"),
        ("Total Cycle Count", "cycle_count"), ("Zyklus", "cycle_count"),
        ("cykl", "cycle_count"), ("Channel 1 Recuento", "cycle_count"),
        ("Machine_N_cycles", "cycle_count"), ("Segment Count", "cycle_count"),
        # a bare count may count anything (a DIC rig's camera frames): its unit decides
        ("Count", None), ("1000 kN Count", None),
        # a true strain is worked out (ln(1 + e)); a DAQ table's amplifier gains, a force
        # plate's centre of pressure are no measurements
        ("True Strain", None), ("Engineering Strain", "gauge"), ("gain load", None),
        ("Sensitivity", None), ("FP1_COP_X", None), ("Thrust", "force"),
        ("last_changed", None), ("last_reset_ts", None), ("Last", "force"),
        ("Chain stretch", "gauge"),  # a wear log's elongation
        ("Elapsed", "time"), ("Run hours", "time"), ("Elapsed Cycles", "cycle_count"),
        # a salt-consolidation rig's logger writes its names in camel case
        ("Längung", "gauge"), ("Längenänderung", "gauge"),  # a German wear rig's elongation
        ("SmallLVDT", "gauge"), ("LargeLVDT", "gauge"), ("DilaFBK", None), ("ConfP", None),
        ("PistonTemp", None), ("CrossHead", "gauge"),
        ("Cycle time", "time"), ("Load test/Time", "time"), ("Rig/Branch tension", "force"),
        ("Segment ID", None), ("exx--1", None), ("", None),
        # a real Bluehill export in Chinese: 时间, 位移, 载荷, 压缩应力, 循环计数
        ("时间", "time"), ("位移", "gauge"), ("载荷", "force"), ("循环计数", "cycle_count"),
        ("压缩应力", None),
        ("行程", "gauge"), ("横梁", "gauge"),  # a Chinese machine's stroke, by name not unit
        # real French exports (Shimadzu, Walter+Bai): Temps, Force, Course_Traverse,
        # C_1_Déform1, C_1_Déplacement, C_1_Valeur de consigne; Bluehill's "Charge (kN)"
        # is a force by its unit, not its name, an electric charge in English logs
        ("Temps", "time"), ("C_1_Temps", "time"), ("Charge", None), ("Effort", "force"),
        ("Course_Traverse", "gauge"), ("C_1_Déform1", "gauge"), ("Déplacement", "gauge"),
        ("C_1_Valeur de consigne", None), ("Nombre de cycles", "cycle_count"),
        # real Portuguese exports (MTS TestSuite, Bluehill): Travessa Horizontal, Carga,
        # Tempo; Extensão; the computed Deformação à tracção (a strain, whatever it was
        # worked out from) and Esforço à tracção (a stress)
        ("Travessa Horizontal", "gauge"), ("Carga", "force"), ("Tempo", "time"),
        ("Extensão", "gauge"), ("Deformação à tracção", "gauge"), ("Esforço à tracção", None),
        # a real Turkish rebar tester (PCM304): Test no, Zaman, Kuvvet, Cetvel, Kanal3
        ("Zaman", "time"), ("Kuvvet", "force"), ("Test no", None), ("Kanal3", None),
        ("Forza", "force"), ("Spostamento", "gauge"), ("試験力", "force"),
        ("ストローク", "gauge"),
        # ZwickRoell testXpert's English channel names
        ("Standard travel", "gauge"), ("Standard force", "force"), ("System time", "time"),
        # a real Russian export: Время [с], Перемещение [мм], Усилие [Н]
        ("Время", "time"), ("Перемещение", "gauge"), ("Усилие", "force"),
        ("Нагрузка", "force"), ("Деформация", "gauge"),
        # an Arduino load-cell logger, Campbell Scientific's TOA5
        ("Timestamp", "time"), ("TIMESTAMP", "time"), ("Time stamp", "time"),
        # Dutch and Korean
        ("Tijd", "time"), ("Belasting", "force"), ("Kracht", "force"), ("Rek", "gauge"),
        ("시간", "time"), ("하중", "force"), ("변위", "gauge"), ("변형률", "gauge"),
        ("Положение", "gauge"), ("Вращение", "angle"), ("Крутящий момент", None),
    ],
)
def test_match_role(name, role):
    assert match_role(name) == role


def test_every_listed_name_matches_its_own_role():
    for language in COLUMN_NAMES.values():
        for role, words in language.items():
            for word in words:
                assert match_role(word) == role, (word, role)


@pytest.mark.parametrize(
    ("cell", "expected"),
    [
        ("force [kN]", ("force", "kN")),
        ("Load (N)", ("Load", "N")),
        ("  gauge1 [ mm ] ", ("gauge1", "mm")),
        ("\ufefftime [s]", ("time", "s")),
        ("Time", ("Time", None)),
        ("(sec)", ("(sec)", None)),
        ("wydłużenie [µm]", ("wydłużenie", "µm")),
        ("Kraft / kN", ("Kraft", "kN")),
        ("F/kN", ("F", "kN")),
        ("1/min", ("1/min", None)),  # a unit alone, in a units row read as names: no "1"
        ("Speed/mm/s", ("Speed/mm/s", None)),
        ("Rig/Branch tension", ("Rig/Branch tension", None)),
        ("KRAFT <N>", ("KRAFT", "N")),
        ("DEHNRATE_SOLL <1/s>", ("DEHNRATE_SOLL", "1/s")),
        ("荷重【kN】", ("荷重", "kN")),  # Japanese and Chinese brackets
        ("位移（mm）", ("位移", "mm")),
        # WaveMatrix qualifies a counter by its waveform: no unit, and two such columns
        # would otherwise both be named "Total Cycle Count"
        ("Total Cycle Count(Linear Waveform)", ("Total Cycle Count(Linear Waveform)", None)),
        ("Force(kN)", ("Force", "kN")), ("Temp(deg C)", ("Temp", "deg C")),
        # PASCO Capstone writes the run after the unit
        ("Force (N) Run #1", ("Force Run #1", "N")), ("Time (s) Auto", ("Time Auto", "s")),
        ("Position (m) Run 5", ("Position Run 5", "m")), ("Run 5", ("Run 5", None)),
        # a "/" inside a compound unit after a word (a Dynojet export's rates) is no
        # name-unit separator: "TCP RX kB" in s would be a time
        ("(DWRT CPU) TCP RX kB/s", ("(DWRT CPU) TCP RX kB/s", None)),
        ("Drehzahl U/min", ("Drehzahl U/min", None)), ("Weg 1/mm", ("Weg 1", "mm")),
        # a unit over a unit, its first no quantity's symbol (a rheometer's units row
        # read as the names): "rad" in s would be a time
        ("rad/s", ("rad/s", None)), ("mm/s", ("mm/s", None)), ("t/s", ("t", "s")),
        ("s/mm", ("s", "mm")),
        # a word in parentheses that says how the values were worked is no unit
        ("(DWRT CPU) Power (uncorrected)", ("(DWRT CPU) Power (uncorrected)", None)),
        ("Chain force (filtered)", ("Chain force (filtered)", None)),
        # empty brackets (a TelemetryViewer export's "time ()") give no unit, not ''
        ("time ()", ("time", None)), ("reading []", ("reading", None)),
        # a unit after a comma, one word and no number; a logger's serial number after
        # it stays in the name (HOBOware)
        ("Нагрузка, кН", ("Нагрузка", "кН")), ("RH, %", ("RH", "%")),
        ("Force, N (LGR S/N: 10694967, SEN S/N: 10694967)",
         ("Force (LGR S/N: 10694967, SEN S/N: 10694967)", "N")),
        ("Host Connected (LGR S/N: 10694967)", ("Host Connected (LGR S/N: 10694967)", None)),
        ("Reading (lbf) (88)", ("Reading (88)", "lbf")),  # a Loadstar sensor's number
        ("Displacement (mm).1", ("Displacement.1", "mm")),  # pandas' second copy
        ("Date Time, GMT-06:00", ("Date Time, GMT-06:00", None)),
        ("Force, total", ("Force, total", None)), ("Channel, 1", ("Channel, 1", None)),
        # a fibre tester writes the percent sign first
        ("% Strain", ("Strain", "%")), ("% Elongation", ("Elongation", "%")), ("%", ("%", None)),
        ("%time_s", ("%time_s", None)), ("% time_s", ("% time_s", None)),  # MATLAB's comment
        # a counter in thousands by its name
        ("Cycles x1000", ("Cycles", "x1000")), ("Zyklen in Tsd", ("Zyklen", "x1000")),
        ("Thousand cycles", ("cycles", "x1000")), ("kCycles", ("Cycles", "x1000")),
    ],
)
def test_split_name_unit(cell, expected):
    assert split_name_unit(cell) == expected


def test_fold_drops_case_and_diacritics():
    assert fold("SIŁA Ąę Straße") == "sila ae strasse"


@pytest.mark.parametrize("name", ["Hoop Strain", "Breitenänderung", "BREITENAENDERUNG",
                                  "Width change",
                                  "Transverse strain", "Transverse", "Querdehnung",
                                  "表-横 ひずみ", "横-平均",  # a Japanese logger's
                                  # a DIC export's (GOM Correlate's thickness_strain)
                                  "thickness_strain", "Width strain", "Minor strain"])
def test_a_channel_across_the_specimen_takes_no_role(name):
    assert match_role(name) is None and is_transverse(name)


@pytest.mark.parametrize("name", ["sample_count", "Sample count", "PIP count", "Temp",
                                  "Temperature", "Temperatur Probe",
                                  "Deformation Acceleration", "Accel X", "torque",
                                  "Drehmoment", "mises_strain", "von Mises strain",
                                  "Equivalent strain", "Shear strain"])
def test_a_count_of_samples_a_temperature_or_an_acceleration_takes_no_role(name):
    # a load-cell rig's calibration table counts the readings it averaged in sample_count,
    # Bluehill the marks of an operator's button in PIP count; an accelerometer logs its
    # temperature in degrees, no angle; a drop tower's 'Deformation Acceleration (m/s^2)'
    # was a gauge by its first word; a DIC field's equivalent (von Mises) strain is about
    # 0.87 of the axial strain in the elastic range, and a shear strain none of it
    assert match_role(name) is None and is_unmeasured(name)


@pytest.mark.parametrize("name", ["Stroke Rate", "StrokeRate", "Load rate", "Strain rate",
                                  "Pace", "Disp Digits", "Tensión de tracción"])
def test_a_rate_a_setting_or_a_stress_takes_no_role(name):
    # a rowing machine's 'Stroke Rate (SPM)' was a gauge by its first word, in a unit the
    # run sheet could have set to millimetres; a load rate is no load, a strain rate no strain
    assert match_role(name) is None and is_unmeasured(name)


def test_the_spanish_tension_a_stress_is_no_force_but_the_english_one_is():
    # 'Tensión' over MPa was a force refused for its unit ("correct the unit"); over no
    # unit, the run sheet's force unit would have read a stress as a load
    assert [match_role(name) for name in ("Tensión", "Tensión real (MPa)", "Tension",
                                          "Chain tension")] == [None, None, "force", "force"]


@pytest.mark.parametrize("name", ["Breaking load", "Break load", "Bruchkraft", "MBL",
                                  "Mindestbruchkraft", "Yield", "Load at Break"])
def test_a_result_of_a_test_takes_no_role(name):
    # a chain catalogue's breaking loads beside its pitches was read as a tensile curve
    # through its chain sizes, the load by its name or by its unit alone
    assert match_role(name) is None and is_unmeasured(name)


@pytest.mark.parametrize("name", ["MX840B_CH 1", "MX1615B_CH 1"])
def test_an_amplifiers_channel_takes_no_role_by_its_name(name):
    # HBM QuantumX amplifiers: their channels take a role by their unit alone
    assert match_role(name) is None and not is_unmeasured(name)


@pytest.mark.parametrize("name", ["Stroke Count", "StrokeCount", "Strokes"])
def test_a_count_of_strokes_is_a_cycle_count(name):
    # a fatigue rig's or a rowing machine's strokes: no crosshead travel
    assert match_role(name) == "cycle_count"


@pytest.mark.parametrize("name", ["Ch 1 Kraft Sollwert", "Sollwert Kraft", "Load Command",
                                  "Force setpoint", "Valeur de consigne", "Siła zadana",
                                  "a1 position cmd", "force_cmd",  # a motor controller's
                                  "C_1_Valeur de commande",  # a French controller's
                                  "expected_force_mN"])  # a calibration script's reference
def test_a_setpoint_or_command_channel_takes_no_role(name):
    assert match_role(name) is None and is_command(name)


@pytest.mark.parametrize("name", [
    # Instron WaveMatrix: a strain split at an assumed modulus into its elastic and
    # plastic parts; fitting the elastic part returns that modulus
    "Elastic Strain(Static Plastic & Elastic Strain Calculation)",
    "Plastic Strain(Static Plastic & Elastic Strain Calculation)",
    "Plastische Dehnung", "Déformation élastique", "Kraft (Berechnung)"])
def test_a_channel_worked_out_from_others_takes_no_role(name):
    assert match_role(name) is None and is_derived(name)


def test_a_measured_channel_is_not_derived():
    assert not is_derived("Strain(8801MTB12548:SGE-57)")
    assert match_role("Strain(8801MTB12548:SGE-57)") is not None


@pytest.mark.parametrize("name", ["actuator_a_id", "Load cell ID", "Specimen id"])
def test_an_identifier_named_after_a_channel_takes_no_role(name):
    # a torque-rig logger's last column: the actuator's number, not its travel
    assert match_role(name) is None


@pytest.mark.parametrize("name", ["Dehnung", "Strain 1", "Extension", "Weg", "Major strain"])
def test_a_channel_along_the_specimen_is_not_transverse(name):
    assert match_role(name) == "gauge" and not is_transverse(name)


@pytest.mark.parametrize("name", ["Grip to grip s", "Grip to grip separat"])
def test_a_testxpert_name_cut_to_its_column_width_keeps_its_role_and_kind(name):
    # real testXpert II and III ASCII exports cut names to 14 and 20 characters: the
    # crosshead's travel took no role, and a strain column equal to it passed for an
    # extensometer's
    assert match_role(name) == "gauge" and gauge_kind(name) == "crosshead"


@pytest.mark.parametrize(("name", "kind"), [
    ("Course_Traverse", "crosshead"), ("Position vérin", "crosshead"),
    # ZwickRoell testXpert's crosshead gauge, in English and French
    ("Grip to grip separation", "crosshead"), ("Ecartement entre outils", "crosshead"),
    ("C_1_Déform1", "extensometer"), ("Extensomètre", "extensometer"),
    ("Déplacement", "gauge"), ("Allongement", "gauge"),
])
def test_what_a_french_displacement_channel_measures(name, kind):
    assert gauge_kind(name) == kind


@pytest.mark.parametrize(("name", "kind"), [
    ("Travessa Horizontal", "crosshead"), ("Extensão", "gauge"), ("Extensômetro", "extensometer"),
    ("Corsa traversa", "crosshead"), ("Estensometro", "extensometer"), ("Spostamento", "gauge"),
    ("ストローク", "crosshead"), ("伸び計", "extensometer"), ("変位", "gauge"),
    ("Standard travel", "crosshead"), ("Crosshead travel", "crosshead"),
    ("Standard extensometer", "extensometer"),
    # a Polish Zwick testXpert header: the standard travel; an Italian strain
    ("Droga standardowa", "crosshead"), ("Deformazione", "extensometer"),
    # a strain, as Bluehill's "Strain 1", in Dutch, Turkish, Japanese and Korean (the
    # Portuguese and Russian words name a displacement too)
    ("Rek 1", "extensometer"), ("Gerinim 1", "extensometer"), ("ひずみ 1", "extensometer"),
    ("변형률 1", "extensometer"), ("Deformação 1", "gauge"), ("Деформация 1", "gauge"),
    ("Verplaatsing", "gauge"), ("변위", "gauge"), ("크로스헤드", "crosshead"),
    # an Instron 8800's actuator in a Russian WaveMatrix export
    ("Положение(8800 (0,1):Положение)", "crosshead"),
    # a Chinese testing machine's export: the crosshead's displacement, the extensometer's
    # deformation (a large-deformation extensometer's too)
    ("位移", "crosshead"), ("变形", "extensometer"), ("引伸计变形", "extensometer"),
    ("大变形", "extensometer"),
])
def test_what_a_displacement_channel_measures_in_more_languages(name, kind):
    assert gauge_kind(name) == kind


@pytest.mark.parametrize(("name", "kind"), [
    # real MTS TestSuite exports: the controller's channel travels with its actuator; the
    # lab's displacement transducers on the specimen are named by their serial numbers
    ("Ch 1 Weg", "crosshead"), ("Ch 1 Displacement", "crosshead"), ("Ch2 Position", "crosshead"),
    ("1470533", "gauge"), ("Ch 1 Dehnung", "extensometer"), ("Weg Ch 1", "gauge"),
    # a real MTS 793 single pull: the actuator's own LVDT; an LVDT on the specimen is the lab's
    ("Ch 1 LVDT", "crosshead"), ("Ch 1 Stroke", "crosshead"), ("LVDT 2", "gauge"),
    # a real MTS 793 export's station, and TestWare's channel: the actuator's LVDT, which
    # was ranked above the crosshead and gave E0 without the machine-compliance warning
    ("Universal Displacement", "crosshead"), ("Axial Displacement", "crosshead"),
    ("Channel 1 Displacement", "crosshead"), ("Axial Strain", "extensometer"),
])
def test_an_mts_controller_channels_displacement_is_its_actuators(name, kind):
    assert gauge_kind(name) == kind


@pytest.mark.parametrize(("name", "kind"), [
    # a real Bluehill export's video extensometer beside the crosshead's 'Displacement':
    # both were gauges, so the choice for E0 could not prefer the extensometer
    ("Optical Displacement", "extensometer"), ("Displacement", "gauge"),
    ("EXTS", "extensometer"),  # a MaCh3D tester's clip-on beside its DISP and ENC1
])
def test_an_optical_or_abbreviated_extensometer_is_one(name, kind):
    assert match_role(name) == "gauge" and gauge_kind(name) == kind


@pytest.mark.parametrize(("name", "role", "kind"), [
    # PicoLog writes each channel's statistic after its name: a qualifier
    ("Force Ave.", "force", None), ("Load Ave.", "force", None), ("Force Min.", "force", None),
    ("LVDT Last", "gauge", "gauge"), ("Extension Last", "gauge", "gauge"),
    ("Crosshead Ave.", "gauge", "crosshead"),
    # alone, the word keeps its own meaning
    ("Last", "force", None), ("AVE", "gauge", "extensometer"),
    # after words that name no role (PicoLog's default channel names), it names none
    ("Ch 1 Last", None, None), ("Differential 13 - 14 Last", None, None),
    ("Single-ended 12 Ave.", None, "gauge"),
])
def test_a_statistic_after_a_channels_name_is_a_qualifier(name, role, kind):
    assert match_role(name) == role
    assert kind is None or gauge_kind(name) == kind


@pytest.mark.parametrize("name", ["Date/Heure", "Datum Uhrzeit", "Fecha/Hora", "Date/Time"])
def test_a_date_and_time_named_in_its_language_is_the_time(name):
    # a French recorder's 'Date/Heure' over its stamps took no role: no time, no rate
    assert match_role(name) == "time" and not is_clock_part(name)


@pytest.mark.parametrize("name", ["Hour", "Minute", "Second", "Stunde", "Sekunde", "Heure"])
def test_a_part_of_a_clock_reading_is_no_elapsed_time(name):
    assert match_role(name) is None and is_clock_part(name)


@pytest.mark.parametrize("name", ["Seconds", "Minutes", "Hours"])
def test_elapsed_seconds_minutes_and_hours_are_the_time(name):
    assert match_role(name) == "time" and not is_clock_part(name)


@pytest.mark.parametrize(("names", "count"), [
    (["Force 1", "Disp 1", "Force 2", "Disp 2"], 2),
    (["Zeit_1", "Kraft_1", "Weg_1", "Zeit_2", "Kraft_2", "Weg_2", "Zeit_3", "Kraft_3",
      "Weg_3"], 3),
    (["Load (S1)", "Ext (S1)", "Load (S2)", "Ext (S2)"], 2),
    (["Probe 1 Kraft", "Probe 1 Weg", "Probe 2 Kraft", "Probe 2 Weg"], 2),
    (["Kraft", "Weg", "Kraft.1", "Weg.1"], 2),  # a repeated header as pandas writes it
    (["Force 1", "Disp 1", "Force 2", "Disp 2", ""], 2),  # a trailing delimiter
    # one specimen: gauges or channels numbered, not groups of one number each
    (["time", "force", "gauge 1", "gauge 2"], 1),
    (["CH1", "CH2", "CH3", "CH4"], 1),
    (["Force 1", "Force 2", "Disp 1", "Disp 2"], 1),
    (["Dehnung 1", "Dehnung 2", "Kraft", "Zeit"], 1),
    (["Force 1", "Disp 1", "Force 1", "Disp 2"], 1),  # a number twice: no specimens
])
def test_specimens_numbered_in_their_names_repeat_side_by_side(names, count):
    assert repeats(names) == count
