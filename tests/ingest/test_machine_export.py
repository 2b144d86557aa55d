"""Machine export: preamble, names row, units row (Instron Bluehill style)."""

import re

import numpy as np
import pytest

from pipeline.errors import ColumnError, LayoutError, UnitError, ValueParseError
from pipeline.ingest import open_log, read_table
from pipeline.ingest.preamble import parse_preamble
from pipeline.ingest.sniff import OUT_OF_RANGE_HINT
from pipeline.units import STANDARD_GRAVITY

BLUEHILL = (
    'Text Inputs : Specimen label,"22L.3"\r\n'
    "General : Start Date,13/11/2018 5:14 PM\r\n"
    "\r\n"
    "Time,Extension,Load,Segment ID,Total Cycle Count\r\n"
    "(sec),(mm),(N),,\r\n"
    "0.00000,-2.04726,-4.31900,22476,0\r\n"
    "0.02000,-2.04730,-4.37385,22476,0\r\n"
    "0.04000,-2.04800,-4.49085,22476,1\r\n"
)


def test_bluehill_layout(write):
    table, meta = read_table(write("b.csv", BLUEHILL))
    assert meta.layout == "machine_export"
    assert list(table.columns) == ["time", "force", "gauge_1", "cycle_count"]
    np.testing.assert_allclose(table["gauge_1"], [-2.04726e-3, -2.0473e-3, -2.048e-3])
    np.testing.assert_allclose(table["cycle_count"], [0, 0, 1])
    assert meta.preamble == {"Specimen label": "22L.3", "Start Date": "13/11/2018 5:14 PM"}
    assert (meta.header_line, meta.first_data_line) == (4, 6)
    units = {c.name: (c.role, c.unit) for c in meta.columns}
    assert units["Segment ID"] == (None, None) and units["Time"] == ("time", "sec")


def test_units_row_in_brackets_and_kn(write):
    text = "Machine: Amsler 50 t\nZeit;Kraft;Weg\n[s];[kN];[mm]\n0,0;1,0;0,1\n1,0;2,0;0,2\n"
    table, meta = read_table(write("a.csv", text))
    assert meta.layout == "machine_export" and meta.preamble == {"Machine": "Amsler 50 t"}
    np.testing.assert_allclose(table["force"], [1000.0, 2000.0])


def test_notes_beside_the_header_do_not_hide_the_units_row(write):
    # a real Bluehill export: the operator's notes right of the names and units rows,
    # over columns the data leave empty; they were taken for the names row before
    text = ("Time,Extension,Load,,10 mm/min\n(s),(mm),(N),,20 N preload\n"
            "0,0.55782,20.00323,,\n0.1,0.58688,20.18529,,\n")
    table, meta = read_table(write("taco.csv", text))
    assert (meta.header_line, meta.first_data_line) == (1, 3)
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["gauge_1"], [0.55782e-3, 0.58688e-3])
    assert "2 empty column(s) dropped" in meta.warnings[0]


def test_a_strain_computed_from_the_crosshead_is_not_an_extensometer(write):
    # real Bluehill exports name the channel a strain was computed from in brackets:
    # "(Extension)" is the crosshead's travel, "(Strain 1)" the extensometer's
    text = ('Time,Extension,Load,Flexure stress,Flexure strain (Extension),'
            'Tensile strain (Strain 1)\n(s),(mm),(N),(MPa),(mm/mm),(%)\n'
            '"0.00000","0.20005","10.03282","8.33135","0.00032","0.01"\n'
            '"0.10000","0.20612","10.4","8.6","0.00033","0.02"\n')
    _, meta = read_table(write("flexure.csv", text))
    kinds = {c.name: (c.role, c.unit, c.kind) for c in meta.columns}
    assert kinds["Flexure strain (Extension)"] == ("strain_1", "mm/mm", "gauge")
    assert kinds["Tensile strain (Strain 1)"] == ("strain_2", "%", "extensometer")


def test_units_as_the_last_word_of_every_name_are_read(write):
    # a real Bluehill .is_tens.raw.csv names row; no units row, no brackets
    text = ("Time sec;Extension mm;Strain 1 %;Load N\n0;-0.00012;-4.196304e-005;-16.88363\n"
            "0.1;-0.00012;0.0002235641;-16.85156\n")
    table, meta = read_table(write("raw.csv", text))
    units = {c.name: (c.role, c.unit) for c in meta.columns}
    assert units == {"Time": ("time", "sec"), "Extension": ("gauge_1", "mm"),
                     "Strain 1": ("strain_1", "%"), "Load": ("force", "N")}
    np.testing.assert_allclose(table["gauge_1"], [-0.12e-6, -0.12e-6])


@pytest.mark.parametrize(("header", "names", "units"), [
    # Russian software writes a comma between the name and the unit
    ("Время, с;Нагрузка, кН;Перемещение, мм", ["Время", "Нагрузка", "Перемещение"],
     ["с", "кН", "мм"]),
    ("Time s;Weg 1;Load N", ["Time", "Weg 1", "Load"], ["s", None, "N"]),
    ("Time;Extension mm;Load N", ["Time", "Extension", "Load"], [None, "mm", "N"]),
    # a real Japanese logger: 名前 (the row number) and 測定日時 beside 荷重 kN, 変位 mm
    ("名前;荷重 kN;変位 mm", ["名前", "荷重", "変位"], [None, "kN", "mm"]),
    # a real Rohde & Schwarz oscilloscope export: the unit after "in"
    ("in s;C1 in V;C2 in V", ["column 1", "C1", "C2"], ["s", "V", "V"]),
    # a script's units after an underscore; "gauge_1" ends in no unit of a gauge
    ("time_s;force_kN;gauge_1", ["time", "force", "gauge_1"], ["s", "kN", None]),
])
def test_a_last_word_is_a_unit_of_every_name_or_of_the_role_its_name_gives(
        write, header, names, units):
    # "Weg 1" ends in a word pint reads (1) that is no unit of a gauge
    _, meta = read_table(write("raw.csv", f"{header}\n0;1;2\n1;2;3\n"), strict=False)
    assert [c.name for c in meta.columns] == names
    assert [c.unit for c in meta.columns] == units


SHIMADZU_SPECIMENS = (
    '"CuivreC1",,,"CuivreC1+N",,,"AcierC70",,\n'
    '"Temps","Force","Stroke","Temps","Force","Stroke","Temps","Force","Stroke"\n'
    '"sec","N","mm","sec","N","mm","sec","N","mm"\n'
    '"0","143.954","7.5E-05","0","237.023","6.25E-05","0","81.86976","5E-05"\n'
    '"0.01","143.9857","0.0001625","0.01","237.0262","0.0001375","0.01","81.8952","0.00015"\n'
)


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_specimens_side_by_side_are_refused_not_mixed(write, reader):
    # a real Shimadzu Trapezium export: one group of columns per specimen; before, the
    # first specimen's force was read with every specimen's strokes as its gauges
    with pytest.raises(LayoutError, match="Temps, Force, Stroke repeat 3 times") as error:
        reader(write("shimadzu.csv", SHIMADZU_SPECIMENS), kind="tensile")
    assert error.value.row == 2 and "a file of its own" in error.value.hint


def test_a_results_table_above_the_raw_data_is_named_as_a_second_table(write):
    # a real Bluehill export of several specimens: a results table, then the raw data;
    # the results were read as the data and the raw names row was "not a number"
    text = (",Gauge length,Maximum Force\n,(mm),(N)\n1,9.59,3196.2\n2,9.75,3051.7\n"
            ",,\nResults Table 2,,\n1,Time,Displacement,Force\n,(s),(mm),(N)\n"
            ",0,0.0029,-0.7041\n")
    with pytest.raises(LayoutError, match="second table starts here") as error:
        read_table(write("results.csv", text))
    assert error.value.row == 7 and "'Time', 'Displacement', 'Force'" in str(error.value)
    assert "one table per file" in error.value.hint


def test_a_long_name_of_a_second_table_is_cut_with_an_ellipsis(write):
    text = (",Gauge length,Maximum Force\n,(mm),(N)\n1,9.59,3196.2\n2,9.75,3051.7\n,,\n"
            "1,Time,Tensile strain (Digital Strain 1),Force\n,(s),(%),(N)\n,0,0.01,-0.7\n")
    with pytest.raises(LayoutError, match="second table starts here") as error:
        read_table(write("results.csv", text))
    assert "'Tensile strain (Digital Strai…'" in str(error.value)


def bluehill_batch(raw_rows: int, results_rows: int = 4) -> str:
    """A Bluehill export of a batch's results table (one row per specimen) above one
    specimen's raw data, as a real one lays them out: the raw names row begins with the
    specimen's number, and the raw data rows with an empty cell."""
    results = [f"{n},9.{n},{3000 + n}.5,,50" for n in range(1, results_rows + 1)]
    raw = [f",{0.02 * row:.2f},{0.001 * row:.4f},{10.0 * row:.1f},{0.01 * row:.3f}"
           for row in range(raw_rows)]
    return "\n".join([
        "Results Table 1,,,,", ",Gauge length,Maximum Force,Specimen note 1,Rate 1",
        ",(mm),(N),,(mm/min)", *results, ",,,,", "Results Table 2,,,,", ",,,,",
        "1,Time,Displacement,Force,Tensile strain (Digital Strain 1)",
        ",(s),(mm),(N),(%)", *raw]) + "\n"


@pytest.mark.parametrize("rows", [60, 3000])  # within the lines first looked at, and past
@pytest.mark.parametrize("reader", [read_table, open_log])
def test_a_batchs_results_table_above_the_raw_data_is_passed_over(write, reader, rows):
    found = reader(write("batch.csv", bluehill_batch(rows)), kind="tensile")
    table, meta = found if reader is read_table else (found.read(0, rows)[0], found.metadata)
    np.testing.assert_allclose(table["force"], 10.0 * np.arange(rows))
    np.testing.assert_allclose(table["gauge_1"], 1e-6 * np.arange(rows), atol=1e-12)
    assert meta.first_data_line == 13
    assert "lines 2-10: a table above the data (of results or settings) was passed over; " \
           "the data are the table from line 13" in meta.warnings
    assert meta.preamble == {"Results Table 1": ""}  # the results are no preamble


def test_a_results_table_is_passed_over_only_above_a_longer_table(write):
    # a table of three rows over one of two is no batch's results over the raw data
    with pytest.raises(LayoutError, match="second table starts here"):
        read_table(write("batch.csv", bluehill_batch(2, results_rows=3)))


def test_a_data_row_with_one_bad_cell_is_still_named_as_such(write):
    text = "time [s],force [kN],gauge [mm]\n0,1,2\n1,x,3\n"
    with pytest.raises(ValueParseError, match="'x' is not a number") as error:
        read_table(write("bad.csv", text))
    assert error.value.row == 3


def test_key_equals_value_preamble_units_in_angle_brackets_and_a_width_change(write):
    # a real Salzgitter flow-curve export; before, every unit was "not given" and, with
    # the crosshead alone, the width change (a gauge by its unit) would have won over it
    text = ("MATERIALNAME                           = HC340LA\n"
            "WERKSTOFFNUMMER_NORM                   =\n"
            "MESSLAENGE_IST <mm>                    = 80.0\n"
            "DATEN                                  =\n"
            "ZEIT <s>; KRAFT <kN>; Traverse <mm>; BREITENAENDERUNG <mm>\n"
            "1.2372;0.192181;-0.0235;0.0012\n1.2772;0.198325;-0.0231;0.0013\n")
    table, meta = read_table(write("ut_flat.txt", text), kind="tensile")
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["force"], [192.181, 198.325])
    np.testing.assert_allclose(table["gauge_1"], [-0.0235e-3, -0.0231e-3])
    assert meta.preamble["MATERIALNAME"] == "HC340LA"
    assert meta.preamble["WERKSTOFFNUMMER_NORM"] == ""
    assert meta.preamble["MESSLAENGE_IST <mm>"] == "80.0"
    roles = {column.name: column.role for column in meta.columns}
    assert roles["BREITENAENDERUNG"] is None


def test_run_sheet_columns_pick_among_candidates(write):
    text = BLUEHILL.replace("Segment ID", "Load 2").replace("(N),,", "(N),(N),")
    with pytest.raises(ColumnError, match="could be the force"):
        read_table(write("b.csv", text))
    table, meta = read_table(write("b.csv", text), columns={"force": "load"})
    np.testing.assert_allclose(table["force"], [-4.319, -4.37385, -4.49085])
    assert meta.columns[3].role is None


@pytest.mark.parametrize(
    ("lines", "expected"),
    [
        (["Text Inputs : Specimen label,\"22L.3\""], {"Specimen label": "22L.3"}),
        (['"Operator","J. Kowalski"'], {"Operator": "J. Kowalski"}),
        (["Rate: 5 mm/min"], {"Rate": "5 mm/min"}),
        (["Points: \t51"], {"Points": "51"}),
        (["Title only", "Title only"], {"Title only": "", "Title only (2)": ""}),
        # a real Deben Microtest preamble: each line quoted whole, decimal commas inside
        (['"Span : 10,0"', '""', '"Test duration : 2938,19999999842s"'],
         {"Span": "10,0", "Test duration": "2938,19999999842s"}),
        # a real CETR tribometer: colons inside a clock time and after a drive letter
        (["Created by CETR Data Viewer ver.2.19.106 05/12/22 14:43:46",
          "C:\\Documents and Settings\\user\\HT-2n-6-4 2_001.tst", "Started at: 12:21:58.029"],
         {"Created by CETR Data Viewer ver.2.19.106 05/12/22 14:43:46": "",
          "C:\\Documents and Settings\\user\\HT-2n-6-4 2_001.tst": "",
          "Started at": "12:21:58.029"}),
        # a real Scopy (ADALM2000) export: settings after a comment mark
        ([";Scopy version,48fb6a9", ";Sample rate,1e+06"],
         {"Scopy version": "48fb6a9", "Sample rate": "1e+06"}),
        # a real syringe-pump rig: rows of names over rows of values
        (["Value (V)", "0", "Stop buffer (mm), Syringe diameter (mm)", "5,20.5"],
         {"Value (V)": "0", "Stop buffer (mm)": "5", "Syringe diameter (mm)": "20.5"}),
        # a real Rtec tribometer: names over values, some of them text
        (["Recipe,UpperSample,LowerSample,Averaging,LogFrequency,Type,Radius,",
          "Rotary_3N_Rx,,,100,1000,Rotary,1,"],
         {"Recipe": "Rotary_3N_Rx", "UpperSample": "", "LowerSample": "", "Averaging": "100",
          "LogFrequency": "1000", "Type": "Rotary", "Radius": "1"}),
        # a real Bluehill Universal results table: names over units over values, the
        # specimen's number unnamed
        (["Results Table 1", ";Width;Thickness", ";(mm);(mm)", "2;9,910;4,04", "Raw Data"],
         {"Results Table 1": "", "Width": "9,910 mm", "Thickness": "4,04 mm", "Raw Data": ""}),
        # key,value lines stay so, whatever their values
        (["Operator,John", "Speed,10", "Material,Steel"],
         {"Operator": "John", "Speed": "10", "Material": "Steel"}),
        # a real Bluehill results preamble: key, value, unit
        (['"Modulus","242,370.29658","MPa"', '"Length","26.00000","mm"'],
         {"Modulus": "242,370.29658 MPa", "Length": "26.00000 mm"}),
        # a real Spanish Bluehill preamble: a result not measured, its unit only
        (["Deformación : Hora de retirada,,s", "Deformación : Longitud,26.0,mm"],
         {"Hora de retirada": "", "Longitud": "26.0 mm"}),
        # a real LabVIEW header: one key per line, over as many channels
        (["X_Dimension\tTime\tTime\tTime", "X0\t0.0E+0\t0.0E+0\t0.0E+0"],
         {"X_Dimension": "Time Time Time", "X0": "0.0E+0 0.0E+0 0.0E+0"}),
        # a real MTS 793 export's first line: its signature, ':' among its signs
        (["MTS793|MPT|ESR|1|2|.|/|:|51|1|1|A\t\t", "Fecha:       01-09-2025"],
         {"MTS793|MPT|ESR|1|2|.|/|:|51|1|1|A": "", "Fecha": "01-09-2025"}),
        # a real load-cell logger's: a comment mark before every line, a lone one between
        (["# Test Name: Test 1", "# Peak Force: 3.379 kN", "#"],
         {"Test Name": "Test 1", "Peak Force": "3.379 kN"}),
        (["# of cycles: 5"], {"# of cycles": "5"}),  # alone, the mark may be the key's
        # a rigging dynamometer's settings without blanks; a Chinese machine's full-width colon
        (["Unit=kN", "Speed=1280"], {"Unit": "kN", "Speed": "1280"}),
        (["试样编号：A12"], {"试样编号": "A12"}),
        # a real force-sensor logger's: a blank row padded with delimiters is no key
        (["Data Collection Duration (s):,1,,,,,,", "Force Sensor Sample rate (Hz):,1000,,,,,,",
          ",,,,,,,"],
         {"Data Collection Duration (s)": "1", "Force Sensor Sample rate (Hz)": "1000"}),
        # a real tribometer's settings side by side, each key before its value
        (["Sampling fequency [Hz]:\t100\tx-velocity [mm/s]: \t100\tCycles:\t3000"],
         {"Sampling fequency [Hz]": "100", "x-velocity [mm/s]": "100", "Cycles": "3000"}),
        # a real vibration logger's: several 'key: value' fields in a line
        (["# Time: 2024-04-21 15:54:46.333682, Device: D4E9", "# Duration: 5.0 s"],
         {"Time": "2024-04-21 15:54:46.333682", "Device": "D4E9", "Duration": "5.0 s"}),
        # a real testXpert ASCII export: each value in a column of its own after its key
        (["Pre-load                                50 N", "Test speed    4 mm/min"],
         {"Pre-load": "50 N", "Test speed": "4 mm/min"}),
    ],
)
def test_parse_preamble(lines, expected):
    # a tab, or a semicolon between fields (not Scopy's comment mark before its lines)
    delimiter = next((mark for mark in "\t;" if any(mark in line[1:] for line in lines)), ",")
    assert parse_preamble(lines, delimiter) == expected


# a real Instron WaveMatrix trends export: one row per cycle, its peaks and valleys
TRENDS = (
    '"Gesamtzyklen";"PC:Zyklusstartzeit (s)";"Position des Aktuators:Maximum (mm)";'
    '"Position des Aktuators:Minimum (mm)";"Kraft:Maximum (N)";"Kraft:Minimum (N)";\r\n'
    "1;0,001;17,3591376954666;17,240651615169;-6,79378541467538;-16,7622730238039;\r\n"
    "2;5,599;17,2344483349125;17,1766469408867;-5,11263522669864;-19,9729208551079;\r\n"
)


def test_a_table_of_each_cycles_peaks_is_not_read_as_a_log(write):
    with pytest.raises(LayoutError, match="'Kraft:Maximum' and 'Kraft:Minimum' are a cycle's "
                                          "extremes") as caught:
        read_table(write("trends.csv", TRENDS))
    assert "raw data" in caught.value.hint


def test_a_wear_run_reads_a_table_of_each_cycles_peaks_once_the_elongation_is_named(write):
    # a wear run needs no force: the force's extremes were refused, with the hint to export
    # every sample, though one row per cycle is what a wear log is
    with pytest.raises(LayoutError, match="'Position des Aktuators:Maximum' and 'Position des "
                                          "Aktuators:Minimum' are a cycle's extremes: the file "
                                          "is a table of one row per cycle") as caught:
        read_table(write("trends.csv", TRENDS), kind="wear")
    assert caught.value.hint.startswith("a wear run reads one row per cycle: name the column "
                                        "that is the elongation")
    table, _ = read_table(write("trends.csv", TRENDS), kind="wear",
                          columns={"gauges": ["Position des Aktuators:Maximum"]})
    np.testing.assert_allclose(table["gauge_1"], [17.3591376954666e-3, 17.2344483349125e-3])
    np.testing.assert_allclose(table["cycle_count"], [1, 2])


def test_a_table_of_each_cycles_gauge_extremes_is_not_read_as_a_log(write):
    # a real Instron 8800 low-cycle fatigue table without its load channel: the position's
    # and the strain's extremes, and the strain's amplitude, one row per cycle
    text = ('Total Cycles,"Position:Maximum (mm)","Position:Minimum (mm)",'
            '"Strain:Maximum (%)","Strain:Minimum (%)","Strain:Amplitude (%)"\n'
            "1,37.938,35.867,0.522,-1.196,0.859\n2,38.797,35.877,1.219,-1.196,1.207\n")
    with pytest.raises(LayoutError, match="the gauge columns 'Position:Maximum' and "
                                          "'Position:Minimum' are a cycle's extremes") as caught:
        read_table(write("10-13.csv", text), kind="wear")
    assert 'columns = {gauges = "..."}' in caught.value.hint


@pytest.mark.parametrize(("names", "said"), [
    # the real E3000 table with a third statistic of the force, as it writes one of its
    # temperature: the force was only "ambiguous", the positions' extremes read as gauges
    ('"Kraft:Maximum (N)";"Kraft:Minimum (N)";"Kraft:Mittel der Spitzenwerte (N)"',
     "the force columns 'Kraft:Maximum' and 'Kraft:Minimum' are a cycle's extremes"),
    ('"Fmax (N)";"Fmin (N)"', "the force columns 'Fmax' and 'Fmin'"),
    ('"Oberlast (N)";"Unterlast (N)";"Load (N)"', "the gauge columns 'Position des "
                                                   "Aktuators:Maximum' and"),
])
def test_a_table_of_peaks_is_refused_whatever_else_its_force_columns_hold(write, names, said):
    header = TRENDS.split("\r\n")[0].replace('"Kraft:Maximum (N)";"Kraft:Minimum (N)"', names)
    rows = "".join(row.rstrip(";") + ";1,5;\r\n" for row in TRENDS.split("\r\n")[1:] if row)
    with pytest.raises(LayoutError, match=re.escape(said)):
        read_table(write("trends.csv", header + "\r\n" + rows))


@pytest.mark.parametrize("text", [
    # a real Instron 8800 table's first rows with its minima left out, and as a DION or
    # testXpert table names them: each cycle's maximum was read as a force signal
    "Cycles,Max Load (kN),Max Position (mm)\n1,0.655,37.938\n2,1.461,38.797\n3,1.5,38.8\n",
    "Zyklen;Fmax [kN];Weg max [mm]\n1;0,655;37,938\n2;1,461;38,797\n3;1,5;38,8\n",
])
def test_each_cycles_maximum_beside_a_cycle_count_is_a_table_of_peaks(write, text):
    with pytest.raises(LayoutError, match="hold a maximum, beside a count of cycles: the file "
                                          "is a table of one row per cycle"):
        read_table(write("peaks.csv", text), kind="tensile")
    # a logger's peak held beside no count is read, as its only force
    held = text.replace("Cycles", "Time (s)").replace("Zyklen", "Zeit [s]")
    table, _ = read_table(write("held.csv", held), kind="tensile")
    assert len(table) == 3


def test_a_named_force_is_read_and_a_raw_force_beside_its_extremes_is_a_choice(write):
    table, _ = read_table(write("trends.csv", TRENDS), columns={"force": "Kraft:Maximum"})
    np.testing.assert_allclose(table["force"], [-6.79378541467538, -5.11263522669864])
    text = "Time (s),Load (N),Load max (N),Load min (N),Extension (mm)\n0,1,2,0,0.1\n1,2,2,0,0.2\n"
    with pytest.raises(ColumnError, match="3 columns could be the force"):
        read_table(write("log.csv", text))


# the header of a real Instron WaveMatrix time series (German), and its English wording
WAVEMATRIX_HEADERS = {
    "de": '"Gesamtzeit (s)";"Verstrichene Zykluszeit (s)";"Gesamtzyklen";"Verstrichene '
          'Zyklen";"Schritt";"Position des Aktuators (mm)";"Kraft (N)"',
    "en": '"Total Time (s)";"Elapsed Cycle Time (s)";"Total Cycles";"Elapsed Cycles";'
          '"Step";"Position of the Actuator (mm)";"Load (N)"',
}


def wavematrix_rows() -> str:
    """Nine rows of the WaveMatrix header's columns: the total time and cycles run on, the
    step's start from 0, the force is -1 - row/10 N."""
    return "".join(f"{500 + row / 1000:.3f};{row / 1000:.3f};{992 + row // 3};{row // 3};2;"
                   f"{17 + row / 100:.4f};{-1 - row / 10:.3f}\r\n".replace(".", ",")
                   for row in range(9))


@pytest.mark.parametrize("kind", ["wear", "tensile"])
@pytest.mark.parametrize("language", ["de", "en"])
def test_wavematrix_total_time_and_cycles_are_taken_over_the_steps(write, language, kind):
    # the step's time and cycles start again at every step: the whole test's are used, and
    # the step's are named in a warning
    path = write("stop.csv", WAVEMATRIX_HEADERS[language] + "\r\n" + wavematrix_rows())
    names = [cell.strip('"').rsplit(" (", 1)[0]
             for cell in WAVEMATRIX_HEADERS[language].split(";")]
    table, meta = read_table(path, kind=kind)
    np.testing.assert_allclose(table["time"], 500 + np.arange(9) / 1000)
    np.testing.assert_array_equal(table["cycle_count"], 992 + np.arange(9) // 3)
    np.testing.assert_allclose(table["force"], -1 - np.arange(9) / 10)
    assert [warning.split(" is named as")[0] for warning in meta.warnings
            if "beside the whole test's" in warning] == [f"column {names[1]!r}",
                                                         f"column {names[3]!r}"]
    table, _ = read_table(path, kind=kind, columns={"time": names[1], "cycle_count": names[3]})
    np.testing.assert_array_equal(table["cycle_count"], np.arange(9) // 3)


# the CCFatigue layout of a quasi-static test with its crack record: the crack's length,
# and the machine's readings copied where it was measured, on the first rows only
CRACKS = ("Machine_Time,Machine_Displacement,Machine_Load,Crack_length,Crack_Displacement,"
          "Crack_Load\n"
          + "".join(f"18:10:{row // 2:02d},{0.2 * row:.1f},{0.05 * row:.2f},"
                    + (f"{30 + row},{0.2 * row:.1f},{0.05 * row:.2f}" if row < 3 else ",,")
                    + "\n" for row in range(8)))


def test_a_load_turned_to_compressions_sign_gives_way_to_the_measured_load(write):
    # a real Bluehill cyclic compression export writes its load twice, the second turned
    # to the compression's sign for its plots: the measured one is used
    text = ("Time,Extension,Load,Compressive extension,Compressive load,Total Cycle Count\n"
            "(sec),(mm),(N),(mm),(N),\n"
            + "".join(f"{0.1 * row:.1f},{-0.025 - 0.01 * row:.3f},{-2.0 * row:.1f},"
                      f"{0.01 * row:.3f},{2.0 * row:.1f},0\n" for row in range(6)))
    table, meta = read_table(write("Specimen_RawData_3.csv", text), kind="tensile")
    np.testing.assert_allclose(table["force"], -2.0 * np.arange(6))
    assert ("column 'Compressive load' is named as the load in one kind of test's sign, "
            "worked out from the measured one ('Load'): not used") in meta.warnings[0]


def test_a_cracks_record_takes_no_role(write):
    table, meta = read_table(write("TST_2020-12_QS_001.csv", CRACKS), kind="tensile",
                             units={"force": "kN", "gauges": "mm"})
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["gauge_1"], 0.2e-3 * np.arange(8))
    assert {column.name: column.role for column in meta.columns}["Crack_length"] is None


def test_a_time_without_unit_is_left_out_of_a_tensile_run_not_of_an_engagement_run(write):
    text = "Time,Load (N),Extension (mm)\n0,1,0.1\n1,2,0.2\n2,3,0.3\n"
    table, meta = read_table(write("log.csv", text), kind="tensile")
    assert list(table.columns) == ["force", "gauge_1"]
    assert ("column 'Time': no unit for the time column, which tensile runs do without: not "
            "used") in meta.warnings[0]
    with pytest.raises(UnitError, match="no unit for the time column"):
        read_table(write("log.csv", text), kind="engagement")
    table, _ = read_table(write("log.csv", text), kind="tensile", units={"time": "s"})
    np.testing.assert_allclose(table["time"], [0.0, 1.0, 2.0])


def test_two_times_neither_preferred_are_left_out_of_a_tensile_run_with_a_warning(write):
    # a tensile run needs no time: the ambiguity is no reason to refuse its force and gauge
    text = "Time (s),Testzeit (s),Load (N),Extension (mm)\n0,5,1,0.1\n1,6,2,0.2\n2,7,3,0.3\n"
    table, meta = read_table(write("log.csv", text), kind="tensile")
    assert list(table.columns) == ["force", "gauge_1"]
    assert sum("which tensile runs do without" in warning for warning in meta.warnings) == 1
    with pytest.raises(ColumnError, match="2 columns could be the time"):
        read_table(write("log.csv", text), kind="engagement")


def test_a_column_named_as_the_time_is_preferred_to_one_of_a_time_unit_only(write):
    # a thrust stand's export: the ESC's pulse width in µs is a command, not a clock
    text = ("Time (s),ESC signal (µs),Thrust (kgf)\n0,1000,0.01\n0.25,1585,0.52\n"
            "0.5,1650,0.61\n0.75,1065,0.05\n")
    table, meta = read_table(write("rcb.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], [0.0, 0.25, 0.5, 0.75])
    assert any(warning.startswith("column 'ESC signal' has a unit of time but no name of "
                                  "one") for warning in meta.warnings)


def test_a_column_named_t_in_a_unit_of_time_is_the_time_over_a_pcs_clock(write):
    # a real rig's log: the PC's Timestamp, when lines arrived (in bursts, repeated, gaps),
    # and its controller's clock t [ms], a row each 100 ms; the PC's stretched 15.4 s to 19
    text = "Timestamp,t [ms],Load [N]\n" + "".join(
        f"16:01:{51 + (i + i // 3) // 10:02d}.{(i + i // 3) % 10}000,{6634078 + 100 * i},"
        f"{0.5 * i:.1f}\n" for i in range(40))
    table, meta = read_table(write("ignition.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], 6634.078 + 0.1 * np.arange(40))
    assert any(warning.startswith("column 'Timestamp' holds clock readings beside")
               for warning in meta.warnings)


def test_a_time_counted_in_seconds_is_preferred_to_clock_readings(write):
    # PASCO Capstone: a date and time to the second beside the time of a 40 Hz run
    text = '"Date and Time Run 5","Time (s) Run 5","Force (N) Run 5"\n' + "".join(
        f"01/09/2024 11:12:5{6 + i // 40} am,{i / 40:.3f},{0.1 * i:.2f}\n" for i in range(60))
    table, meta = read_table(write("spring.csv", text), kind="engagement")
    np.testing.assert_allclose(table["time"], np.arange(60) / 40)
    assert ("column 'Date and Time Run 5' holds clock readings beside a time counted in "
            "seconds ('Time Run 5'): not used") in " ".join(meta.warnings)


# the names of a real Instron WaveMatrix tracking export: derived channels are named
# after the channel they come from ("Stress(...:Load)") or a count ("Cycle Energy")
TRACKING = ('"Total Time (s)","Total Cycles","Load(8801:Load) (kN)","Stress(8801:Load) (MPa)",'
            '"Cycle Energy (J)","Position(8801:Position) (mm)"\n'
            "5.08,1,4.3857,108.77,0,8.0699\n5.12,1,4.6882,116.27,0.0332,8.0772\n")


def test_a_candidate_whose_unit_is_not_of_its_role_makes_no_ambiguity(write):
    # a stress (MPa) is no force and an energy (J) no cycle count: each is left out with a
    # warning, instead of refusing the file for two candidates
    table, meta = read_table(write("tracking.csv", TRACKING), kind="wear")
    np.testing.assert_allclose(table["force"], [4385.7, 4688.2])
    np.testing.assert_array_equal(table["cycle_count"], [1, 1])
    assert "column 'Stress(8801:Load)': unit 'MPa' is not a unit of force (N): column not used" \
        in meta.warnings
    assert ("column 'Cycle Energy': unit 'J' is not a unit of "
            "cycle_count: column not used") in meta.warnings


def test_candidates_none_of_which_fits_are_still_an_ambiguity(write):
    text = TRACKING.replace("Load(8801:Load) (kN)", "Load(8801:Load) (MPa)")
    with pytest.raises(ColumnError, match="2 columns could be the force"):
        read_table(write("tracking.csv", text), kind="engagement")


def test_speeds_none_of_which_fits_a_role_the_run_does_without_are_left_out(write):
    # a drive bench's motor speeds in rpm: no chain speed, and no speed to choose among
    text = ("Time (s),Thrust (N),Motor Electrical Speed (RPM),Motor Optical Speed (RPM)\n"
            "0,1,1000,1010\n0.25,2,1500,1490\n0.5,3,1600,1610\n")
    _, meta = read_table(write("bench.csv", text), kind="engagement")
    assert ("column 'Motor Optical Speed': unit 'RPM' is not a unit of speed (m/s): column not "
            "used") in meta.warnings
    assert not any("could be the speed" in warning for warning in meta.warnings)


# a real transient recorder's export (Hopkinson bar strain gauges): every header row ends
# with the delimiter, the data rows do not
RECORDER = ("Starttime;16.08.2016 15:46:25\nSamplerate;10000000 Hz\n\n"
            "Kanal;DMS1A (0.A1);DMS1B (0.A2);\nZeit;Signal;Signal;\ns;V;V;\n\n\n"
            "2,24130000e-03;-4,37500e-03;-3,12500e-03\n"
            "2,24140000e-03;-5,00000e-03;-5,62500e-03\n")


def test_a_units_row_ending_with_the_delimiter_is_still_the_units_row(write):
    table, meta = read_table(write("recorder.asd", RECORDER), kind="wear", strict=False)
    np.testing.assert_allclose(table["time"], [2.2413e-3, 2.2414e-3])
    # the channels' names are in the row over the one that names each of them "Signal"
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Zeit", "s"), ("DMS1A (0.A1)", "V"), ("DMS1B (0.A2)", "V")]


# a real Siglent SDS1204X-E export: 'Value' over each channel in the units row
SIGLENT = ("Record Length,Analog:14000,\nVertical Units,CH1:V, CH2:V,,\nSource,CH1,CH2\n"
           "Second,Value,Value\n-1.400000E-05,-4.400000E+01,-2.800000E+00\n"
           "-1.399800E-05,-4.600000E+01,-2.800000E+00\n")


def test_value_in_a_units_row_stands_for_no_unit(write):
    table, meta = read_table(write("SDS00368.csv", SIGLENT), kind="engagement",
                             columns={"force": "CH1"}, units={"force": "kN"})
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Source", "Second"), ("CH1", "kN"), ("CH2", None)]
    np.testing.assert_allclose(table["time"], [-1.4e-05, -1.3998e-05])
    np.testing.assert_allclose(table["force"], [-44e3, -46e3])


# a real Shimadzu export (a Spanish-locale lab): the sample counter's interval over it
SHIMADZU = ("Specimen\t 1 \nOriginalGL\t 89,394 \tmm\tExtenso.GL\t 0 mm\n"
            "Number\tLoad\tStroke\tElong\tWidth\nX 200msec\ttf\tmm\tmm\tmm\n"
            " 1 \t ,075 \t 0 \t 0 \t 0 \n 2 \t ,08 \t ,032 \t 0 \t 0 \n")


def test_a_sample_counters_interval_in_the_units_row_is_no_unit(write):
    table, meta = read_table(write("KENNETH2.TXT", SHIMADZU), kind="tensile")
    assert [(column.name, column.role, column.unit) for column in meta.columns] == [
        ("Number", None, None), ("Load", "force", "tf"), ("Stroke", "gauge_1", "mm"),
        ("Elong", "gauge_2", "mm"), ("Width", None, "mm")]
    np.testing.assert_allclose(table["force"], [0.075 * 9806.65, 0.08 * 9806.65])
    np.testing.assert_allclose(table["gauge_1"], [0.0, 0.032e-3])


# a real MaCh3D export: a row of channel states between the names and the units
MACH3D = ("+----+\n|  DATA  |\n+----+\n\nTIME;DISP;LOAD;TMP1;TMP2\n-;-;ON;ON;OFF\n"
          "(ms);(mm);(N);(deg_C);(deg_C)\n\n0;7.430;2.94;nan;0\n200;7.443;4.23;nan;0\n")


def test_a_row_of_channel_states_between_names_and_units_is_passed_over(write):
    table, meta = read_table(write("example.dat", MACH3D), kind="tensile")
    assert [(column.name, column.unit) for column in meta.columns][:3] == [
        ("TIME", "ms"), ("DISP", "mm"), ("LOAD", "N")]
    np.testing.assert_allclose(table["time"], [0.0, 0.2])
    np.testing.assert_allclose(table["force"], [2.94, 4.23])
    assert "ON" not in str(meta.preamble)



# a real Campbell Scientific CR1000 TOA5 file: file line, names, units, then how each value
# was worked over the interval (sample, average, extreme), then the data
TOA5 = (
    '"TOA5","RF407_CR1000","CR1000","69096","CR1000.Std.27.04","CPU:SkiSF_Met_Apr2024.CR1",'
    '"46595","SkiSF_Met"\n'
    '"TIMESTAMP","RECORD","AirTF_Max","AirTF_Min","AirTF_Avg","WC_F_Avg","WS_mph_Max",'
    '"WS_mph_Min","WS_mph_Avg","WindDir","RH","DP_F_Avg","BP_inHg_Avg","BattV","PanelTemp_F"\n'
    '"TS","RN","°F","°F","°F","°F","miles/hour","miles/hour","miles/hour","Degrees","%","°F",'
    '"inHg","Volts","°F"\n'
    '"","","Max","Min","Avg","Avg","Max","Min","Avg","Smp","Smp","Avg","Avg","Smp","Smp"\n'
    '"2024-04-06 13:30:00",0,10.87,10.74,10.78,0.553,12.09,0,7.875,302.5,88.1,7.958,28.69,'
    '14.15,-10.47\n'
    '"2024-04-06 13:45:00",0,10.01,9.76,9.86,-7.825,29.08,0,20.19,287.7,87.4,6.911,29.26,'
    '14.15,-10.42\n'
)


def test_a_campbell_row_of_processing_words_under_the_units_is_passed_over(write):
    table, meta = read_table(write("SkiSF_MetData.dat", TOA5.encode()), kind="engagement",
                             strict=False)  # a weather station's: no force
    named = {column.name: (column.role, column.unit) for column in meta.columns}
    assert named["TIMESTAMP"] == ("time", "s") and named["RECORD"] == (None, None)
    assert named["AirTF_Max"] == (None, "°F") and named["WindDir"] == ("angle", "Degrees")
    np.testing.assert_allclose(table["time"], [0.0, 900.0])
    np.testing.assert_allclose(table["angle"], np.radians([302.5, 287.7]))


# a real GRIMM EDM80 dust-monitor log (three of its 42 columns, and its last): the header
# closed by a line of its own under the names
EDM80 = (
    "***begin of header***\n"
    "date&time [local time];serial-no;PM10 [ug/m3];last calibration [local time]\n"
    "***end of header***\n\n"
    "2019-07-07 00:00:48;SN19011;0,82;2019-06-11 14:16:04\n"
    "2019-07-07 00:01:48;SN19011;1,70;2019-06-11 14:16:04\n"
)


def test_a_line_closing_the_header_under_the_names_is_passed_over(write):
    table, meta = read_table(write("SN19011-measure.dat", EDM80), kind="engagement",
                             strict=False)  # a dust monitor's: no force
    assert [column.name for column in meta.columns] == [
        "date&time", "serial-no", "PM10", "last calibration"]
    np.testing.assert_allclose(table["time"], [0.0, 60.0])
    # a date of calibration, no force (German "Last") though it holds clock readings
    assert not any("'last calibration'" in warning for warning in meta.warnings)
    assert not meta.columns[3].role


# a real PASCO Capstone export (Norwegian locale): the run label after each unit
PASCO = "Time (s) Auto;Force (N) Run #1\n0,000;-7,10E-15\n0,050;1,25E+00\n0,100;2,50E+00\n"


def test_a_run_label_after_the_unit_keeps_the_unit(write):
    table, meta = read_table(write("rakettdata.csv", PASCO), kind="engagement")
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Time Auto", "s"), ("Force Run #1", "N")]
    np.testing.assert_allclose(table["force"], [-7.1e-15, 1.25, 2.5])


def test_runs_side_by_side_are_refused_unless_the_run_sheet_says_which(write):
    names = ",".join(f"{name} Run {run}" for run in (5, 6)
                     for name in ("Time (s)", "Force (N)", "Position (m)"))
    text = names + "\n" + "0.0,0.1,0.0,0.0,0.2,0.0\n0.1,0.2,0.01,0.1,0.3,0.02\n"
    path = write("spring.csv", text)
    with pytest.raises(LayoutError, match="repeat 2 times side by side") as caught:
        read_table(path, kind="tensile")
    assert ('specimen_in_file = "Run 5": the file\'s labels Run 5, Run 6, or the places 1 to '
            '2 from the left') in caught.value.hint
    for chosen in (2, "Run 6"):  # by place, or by the run's label
        table, meta = read_table(path, kind="tensile", specimen=chosen)
        np.testing.assert_allclose(table["force"], [0.2, 0.3])
        np.testing.assert_allclose(table["gauge_1"], [0.0, 0.02])
        assert meta.specimen == "Run 6"
        assert [column.name for column in meta.columns] == [
            "Time Run 6", "Force Run 6", "Position Run 6"]


def test_vernier_runs_side_by_side_with_the_newest_unnumbered_are_refused(write):
    # a real Vernier Graphical Analysis export: the newest run 'Latest', then 'Run 1'...;
    # read as one test, a force named in the run sheet paired with every run's position
    names = ",".join(f'"{run}: {name}"' for run in ("Latest", "Run 1", "Run 2")
                     for name in ("Time (s)", "Force (N)", "Position (m)"))
    rows = ["0.01,-0.05,,0.01,-0.05,,0.01,-0.02,", "0.02,0.4,0.001,0.02,0.6,0.002,0.02,0.8,0.003"]
    path = write("dr_lee.csv", names + "\n" + "\n".join(rows) + "\n")
    with pytest.raises(LayoutError, match="repeat 3 times side by side"):
        read_table(path, kind="tensile")
    table, meta = read_table(path, kind="tensile", specimen=2)
    np.testing.assert_allclose(table["force"], [-0.05, 0.6])
    assert [column.name for column in meta.columns] == [
        "Run 1: Time", "Run 1: Force", "Run 1: Position"]


def test_pandas_copies_of_names_ending_in_a_number_are_specimens_side_by_side(write):
    # Bluehill's columns written side by side by pandas: "Corrected displacement 1" of the
    # first specimen is no first specimen's number; read as one, the force of one specimen
    # was paired with another's gauges
    group = ["Time (s)", "Force (N)", "Corrected displacement 1 (mm)"]
    names = group + [f"{name}.{copy}" for copy in (1, 2) for name in group]
    rows = [",".join(f"{t},{10 * s * t},{0.01 * s * t}" for s in (1, 2, 3)) for t in range(4)]
    path = write("wide.csv", ",".join(names) + "\n" + "\n".join(rows) + "\n")
    with pytest.raises(LayoutError, match="repeat 3 times side by side"):
        read_table(path, kind="tensile")
    table, _ = read_table(path, kind="tensile", specimen=3)
    np.testing.assert_allclose(table["force"], 30.0 * np.arange(4))
    np.testing.assert_allclose(table["gauge_1"], 3e-5 * np.arange(4))


def test_specimens_numbered_in_the_names_are_read_one_a_run(write):
    """``Force 1 [kN], Disp 1 [mm], Force 2 [kN], Disp 2 [mm]``: read as one specimen, the
    first force would pair with both displacements."""
    text = ("Force 1 [kN],Disp 1 [mm],Force 2 [kN],Disp 2 [mm]\n"
            "0.0,0.00,0.0,0.00\n1.0,0.01,2.0,0.03\n2.0,0.02,4.0,0.06\n")
    path = write("two.csv", text)
    with pytest.raises(LayoutError, match="repeat 2 times side by side"):
        read_table(path)
    table, meta = read_table(path, specimen=2)
    np.testing.assert_allclose(table["force"], [0.0, 2000.0, 4000.0])
    np.testing.assert_allclose(table["gauge_1"], [0.0, 3e-5, 6e-5])
    assert list(table.columns) == ["force", "gauge_1"] and meta.specimen == "2"


# a real Mecmesin Emperor export: names, units, then a label over each specimen's columns
EMPEROR = (
    "Force,Distance,Time,Event,,,,\n"
    "N,mm,min,,,,,\n"
    "Sample 1,,,,Sample 2,,,\n"
    "\n"
    "0.1202,0,0,0,0.0601,0,0,0\n"
    "0.1202,0,0.00002,0,0.1202,0.0025,0.00002,0\n"
    "0.1502,0,0.00005,0,0.1202,0.0025,0.00005,0\n"
)


def test_specimens_side_by_side_under_a_row_of_labels_are_read_one_a_run(write):
    """Emperor writes the names and units over the first specimen's columns only: each
    specimen's columns take them; the run sheet says which specimen a run reads."""
    path = write("emperor.csv", EMPEROR)
    with pytest.raises(LayoutError, match="repeat 2 times side by side") as caught:
        read_table(path)
    assert caught.value.hint.startswith(
        'say which one a run reads in the run sheet (specimen_in_file = "Sample 1": the '
        "file's labels Sample 1, Sample 2, or the places 1 to 2 from the left")
    for specimen in ("Sample 2", 2):
        table, meta = read_table(path, specimen=specimen)
        np.testing.assert_allclose(table["force"], [0.0601, 0.1202, 0.1202])
        np.testing.assert_allclose(table["gauge_1"], [0, 2.5e-6, 2.5e-6])
        np.testing.assert_allclose(table["time"], [0, 0.0012, 0.003])  # minutes, in seconds
        assert (meta.specimens, meta.specimen) == (["Sample 1", "Sample 2"], "Sample 2")
        assert [(column.name, column.unit) for column in meta.columns] == [
            ("Force", "N"), ("Distance", "mm"), ("Time", "min"), ("Event", None)]
    with pytest.raises(LayoutError, match='none of them "Sample 3"'):
        read_table(path, specimen="Sample 3")


# a real Shimadzu Trapezium export of a batch: a label over each specimen's columns, the
# shorter specimen's columns left empty below its last row
TRAPEZIUM = (
    '"CuivreC1",,,"AcierC70",,\n'
    '"Temps","Force","Stroke","Temps","Force","Stroke"\n'
    '"sec","N","mm","sec","N","mm"\n'
    '"0","143.954","7.5E-05","0","81.86976","5E-05"\n'
    '"0.01","143.9857","0.0001625","0.01","81.8952","0.00015"\n'
    '"","","","0.02","81.93652","0.000525"\n'
)


def test_specimens_side_by_side_under_their_labels_and_a_shorter_one(write):
    path = write("tract.csv", TRAPEZIUM)
    table, meta = read_table(path, specimen="CuivreC1")
    np.testing.assert_allclose(table["force"], [143.954, 143.9857])
    assert meta.rows == 2 and meta.preamble == {}
    assert ("specimen 'CuivreC1' ends at line 5: the 1 row(s) below, empty in its columns, "
            "were left out") in meta.warnings
    table, meta = read_table(path, specimen="AcierC70")
    np.testing.assert_allclose(table["time"], [0, 0.01, 0.02])
    assert meta.rows == 3 and not meta.warnings


def test_a_specimen_whose_columns_are_empty_is_refused_as_such(write):
    # a force tester's batch export with slots left empty: the empty specimen was shown
    # as read, its rows counted, "no force column found ... the file has: " and no name
    empty = TRAPEZIUM.replace('"AcierC70",,', '"AcierC70",,,"Vide",,').replace(
        '"Stroke"\n', '"Stroke","Temps","Force","Stroke"\n').replace(
        '"mm"\n', '"mm","sec","N","mm"\n')
    empty = "\n".join(line + (",,," if line.startswith('"0') or line.startswith('""') else "")
                      for line in empty.splitlines()) + "\n"
    path = write("tract.csv", empty)
    with pytest.raises(LayoutError, match=r"specimen 'Vide' holds no readings: its columns "
                                          r"\(Temps, Force, Stroke\) are empty"):
        read_table(path, specimen="Vide")
    table, _ = read_table(path, specimen="AcierC70")
    np.testing.assert_allclose(table["force"], [81.86976, 81.8952, 81.93652])


def test_specimens_labelled_over_each_of_their_columns_are_told_apart(write):
    # a Stable Micro Systems Exponent layout: each test's name over each of its columns; a
    # name the readers do not know (Distance) was then named by that row, two tests read
    # as one with the first's force beside the second's distance
    text = ("gel2\tgel2\tgel2\tframe\tframe\tframe\t\nForce\tDistance\tTime\tForce\t"
            "Distance\tTime\t\ng\tmm\tsec\tg\tmm\tsec\t\n\n0.023\t0\t0\t-0.054\t0\t0\t\n"
            "0.039\t0.01\t0.005\t-0.021\t0.02\t0.005\t\n")
    with pytest.raises(LayoutError, match="repeat 2 times side by side") as caught:
        read_table(write("gels.tab", text), kind="engagement")
    assert "the file's labels gel2, frame" in caught.value.hint
    table, meta = read_table(write("gels.tab", text), kind="engagement", specimen="frame")
    np.testing.assert_allclose(table["force"] / STANDARD_GRAVITY, [-0.054e-3, -0.021e-3])


def test_a_specimen_asked_of_a_file_of_one_is_refused(write):
    one = "".join(line.rsplit(",", 4)[0] + "\n" if line else "\n"
                  for line in EMPEROR.splitlines())
    with pytest.raises(LayoutError, match="but the file holds one specimen"):
        read_table(write("emperor.csv", one), specimen="Sample 1")


def test_one_specimens_label_between_the_header_and_the_data_is_passed_over(write):
    one = "".join(line.rsplit(",", 4)[0] + "\n" if line else "\n"
                  for line in EMPEROR.splitlines())
    table, meta = read_table(write("emperor.csv", one))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["time"], [0, 0.0012, 0.003])  # minutes, in seconds
    assert [column.unit for column in meta.columns] == ["N", "mm", "min", None]


# a real MTS TestSuite export in Portuguese: names with trailing blanks, "seg" for seconds
TESTSUITE_PT = (
    "Teste: MTS EM ASTM A370 Tração de Metais\n"
    "Execução de Teste: Execução de Teste 1\n"
    "\n"
    "Travessa Horizontal \tCarga \tTempo \n"
    "mm\tkN\tseg\n"
    "0,00101365412774612\t0,034461555480957\t0,104999996721745\n"
    "0,0013785695500701\t0,0473601341247559\t0,125\n"
)


def test_a_portuguese_testsuite_export(write):
    table, meta = read_table(write("1045.txt", TESTSUITE_PT))
    np.testing.assert_allclose(table["time"], [0.104999996721745, 0.125])
    np.testing.assert_allclose(table["force"], [34.461555480957, 47.3601341247559])
    np.testing.assert_allclose(table["gauge_1"], [1.01365412774612e-6, 1.3785695500701e-6])
    assert meta.columns[0].kind == "crosshead"


# a real MTS TestSuite export in German: every cell quoted, sensors named by their serial
# numbers, and the force's setpoint beside the force
TESTSUITE_DE = (
    '"Test: E_Modul_Beton_Zylinder 2"\n'
    '""\n'
    '"Zeit ";"Ch 1 Kraft Sollwert ";"Ch 1 Kraft ";"Ch 1 Weg ";"1470533 ";"1281068 "\n'
    '"sec";"kN";"kN";"mm";"mm";"mm"\n'
    '"159,8212890625";"-40,39783984375";"-40,41028125";"-0,0075727703";"-0,0005323";"-0,11404"\n'
    '"160,021484375";"-40,39783984375";"-40,45183984375";"-0,0079900028";"-0,0005865";"-0,11411"\n'
)


def test_names_row_with_serial_numbers_and_a_setpoint_that_is_no_force(write):
    table, meta = read_table(write("zeitgetaktet.csv", TESTSUITE_DE))
    assert [column.name for column in meta.columns] == [
        "Zeit", "Ch 1 Kraft Sollwert", "Ch 1 Kraft", "Ch 1 Weg", "1470533", "1281068"]
    assert meta.columns[1].role is None
    np.testing.assert_allclose(table["force"], [-40410.28125, -40451.83984375])
    assert list(table.columns) == ["time", "force", "gauge_1", "gauge_2", "gauge_3"]


# a real Keysight InfiniiVision export: channels named by number, over a units row
INFINIIVISION = (
    "x-axis,1,2\n"
    "second,Volt,Volt\n"
    "-1.00000E-06,-402.01005E-06,-201.00502E-06\n"
    "-999.00E-09,-402.01005E-06,+0.0E+00\n"
)


def test_an_oscilloscopes_numbered_channels_over_a_units_row(write):
    table, meta = read_table(write("scope_0.csv", INFINIIVISION), kind="engagement",
                             columns={"force": "1"}, units={"force": "kN"})
    assert [column.name for column in meta.columns] == ["x-axis", "1", "2"]
    np.testing.assert_allclose(table["time"], [-1e-6, -999e-9])
    np.testing.assert_allclose(table["force"], [-0.40201005, -0.40201005])
    # a sensor's signal read as a force only as the amplifier's scale allows
    assert ("column '1': the file gives it in 'Volt', a sensor's signal, no force; read in "
            "'kN' as the run sheet says: right only if its amplifier was scaled to give 'kN' "
            "(1 Volt = 1 kN); else convert it with the sensor's calibration first (the readers "
            "apply none)") in meta.warnings


def bluehill_quoted(rows: int) -> str:
    """A Bluehill export with every number quoted, as a real one: loads from 1,000 N on
    written with a thousands separator (``"1,004.80328"``)."""
    lines = ['"Specimen number","1"', "", '"Time","Extension","Load"', '"(s)","(mm)","(N)"']
    lines += [f'"{0.1 * row:.5f}","{0.002 * row:.5f}","{25.0 * row:,.5f}"' for row in range(rows)]
    return "\r\n".join(lines) + "\r\n"


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_quoted_numbers_with_thousands_separators(write, reader):
    found = reader(write("Specimen_RawData_1.csv", bluehill_quoted(80)), kind="tensile")
    table = found[0] if reader is read_table else found.read(0, 80)[0]
    np.testing.assert_allclose(table["force"], 25.0 * np.arange(80))  # 40: "1,000.00000"
    np.testing.assert_allclose(table["gauge_1"], 2e-6 * np.arange(80), atol=1e-12)


@pytest.mark.parametrize("reader", [read_table, open_log])
def test_loads_grouped_in_thousands_from_the_first_row_are_the_force(write, reader):
    # a preloaded specimen's export: every load in the first rows over 1,000 N; the column
    # was taken for text, its unit dropped, and the run found no force
    lines = bluehill_quoted(120).split("\r\n")
    text = "\r\n".join(lines[:4] + lines[44:])
    found = reader(write("Specimen_RawData_1.csv", text), kind="tensile")
    table = found[0] if reader is read_table else found.read(0, 80)[0]
    np.testing.assert_allclose(table["force"][:80], 25.0 * np.arange(40, 120))


@pytest.mark.parametrize("cell", ["1,2", "10,00.5", "1,0045.2"])
def test_a_comma_that_is_no_thousands_separator_is_still_refused(write, cell):
    text = bluehill_quoted(80).replace('"1,500.00000"', f'"{cell}"')  # past 20 grouped loads
    with pytest.raises(ValueParseError, match=f"'{cell}' is not a number") as error:
        read_table(write("Specimen_RawData_1.csv", text))
    assert error.value.row == 65


# a real DTS SLICE export (a headform impact): each channel's unit in a settings row
DTS_SLICE = ("Headers,,,,\nTest ID,c-front-hard1,c-front-hard1,c-front-hard1,\n"
             "Sample Rate (Hz),20000,20000,20000,\nEngineering Unit,deg/sec ,g ,kN ,\n"
             "Data Starts Here,,,,\nTime,Chan 0:AV1,Chan 1:AC1,Chan 2:LC1,\n"
             "-0.040050,-12.880515,0.072539,1.5\n-0.040000,-1.951593,0.090674,1.7\n")


# the settings block of a Kyowa PCD-400A strain-gauge recorder (its layout; our numbers):
# calibration factors and offsets above the units row make a table of settings
KYOWA = ('"ID番号","PCD-400A"\n"試験日時","2026/02/26","16:41:09"\n"測定CH数",2\n'
         '"サンプリング周波数(Hz)",50\n"CH名称"\n"レンジ","5kμε","2kμε"\n'
         '"ローパス(デジタル)","***","***"\n"校正係数",2.5,0.3\n"オフセット",0,0\n'
         '"単位","kN","N"\n"Time(sec)","CH1","CH2"\n0.00,1.25,3.5\n0.02,1.5,3.75\n'
         '0.04,1.75,4.0\n')


# the settings of a Rohde & Schwarz RTH1004 export (its layout; our numbers), its load
# cell's channel set to kN
RTH = ("Model,RTH1004\nSerialNumber,100001\nFirmware Version,'1.70.3.2'\n\n"
       "Acquisition Time Stamp,2026-01-05 10:00:00.0,2026-01-05 10:00:00.0\n"
       "Waveform Type,ANALOG,\nAcquisition Mode,SAMPLE,\nHorizontal Unit,s,\n"
       "Horizontal Scale,0.2,\nHorizontal Position,0.8,\nReference Point,50 %,\n"
       "Sample Interval,1e-05,\nRecord Length,100000,\nProbe Setting,'10:1','10:1'\n"
       "Vertical Unit,kN,V\nVertical Scale,2,2\nVertical Position,-3,0\n"
       "Vertical Offset,0,0\nHistory Index,0,0\n"
       "History Time Stamp,0.000000000000,0.000000000000\n,,\nTIME,CH1,CH2\n"
       + "".join(f"{-0.2 + 1e-5 * i:.5f},{-0.085 - 0.005 * i:.3f},0.15\n" for i in range(30)))


@pytest.mark.parametrize("text, options, units, forces, key", [
    (RTH, {"columns": {"force": "CH1"}}, [("TIME", "s"), ("CH1", "kN"), ("CH2", "V")],
     -85.0 - 5.0 * np.arange(30), "'CH1', 'CH2' from the preamble's 'Vertical Unit' row"),
    (DTS_SLICE, {"units": {"time": "s"}},
     [("Time", "s"), ("Chan 0:AV1", "deg/sec"), ("Chan 1:AC1", "g"), ("Chan 2:LC1", "kN")],
     [1.5e3, 1.7e3], "'Chan 0:AV1', 'Chan 1:AC1', 'Chan 2:LC1' from the preamble's "
     "'Engineering Unit' row"),
    # the units row among a logger's settings, passed over as a table above the data
    (KYOWA, {"columns": {"force": "CH1"}}, [("Time", "sec"), ("CH1", "kN"), ("CH2", "N")],
     [1.25e3, 1.5e3, 1.75e3], "'CH1', 'CH2' from the preamble's '単位' row"),
])
def test_a_preamble_row_of_units_gives_each_channel_its_unit(write, text, options, units,
                                                             forces, key):
    table, meta = read_table(write("log.csv", text), kind="engagement", **options)
    assert [(c.name, c.unit) for c in meta.columns] == units
    np.testing.assert_allclose(table["force"], forces)
    assert f"units of {key}" in meta.warnings


def test_a_single_units_setting_names_no_column(write):
    text = "Units,mm\nTime,Load,Travel\n0.0,1.5,0.1\n0.1,1.7,0.2\n"
    _, meta = read_table(write("t.csv", text), kind="tensile",
                         units={"time": "s", "force": "kN", "gauges": "mm"})
    assert meta.preamble == {"Units": "mm"}
    assert not any("preamble's 'Units' row" in warning for warning in meta.warnings)


# a real ElectroForce WinTest export re-saved through a spreadsheet: two numbers typed
# beside the units row, and in the first data row
WINTEST_RESAVED = ("Axial Counts\t0\t\t\t\t\t\n"
                   "Points\tElapsed Time \tDisp 1\tLoad 1 \t\t\t\n"
                   "      \tSec          \tmm    \tN      \t\t-0.081\t-5.86\n"
                   "1\t0\t0\t-0.55\t\t-0.056\t-12.11\n2\t0.005\t0\t-0.55\t\t\t\n"
                   "3\t0.01\t0.002\t-0.56\t\t\t\n")


def test_numbers_typed_beside_the_units_row_are_passed_over(write):
    table, meta = read_table(write("1.TXT", WINTEST_RESAVED), kind="tensile")
    assert [(c.name, c.role, c.unit) for c in meta.columns][1:4] == [
        ("Elapsed Time", "time", "Sec"), ("Disp 1", "gauge_1", "mm"), ("Load 1", "force", "N")]
    np.testing.assert_allclose(table["force"], [-0.55, -0.55, -0.56])
    assert meta.first_data_line == 4
    assert "line 3: the numbers beside the units (-0.081, -5.86) were passed over" in (
        meta.warnings)


@pytest.mark.parametrize("mark", ["+++++++", "-------", "OL", "-OL", "Overflow", "BURNOUT"])
def test_an_out_of_range_mark_is_refused_with_what_it_means(write, graphtec_export, mark):
    text = graphtec_export().replace("\r\n3,2026/03/05 23:59:58,500,+2.00,",
                                     f"\r\n3,2026/03/05 23:59:58,500,{mark},")
    assert mark in text
    with pytest.raises(ValueParseError) as caught:
        read_table(write("GL840.csv", text), kind="engagement",
                   columns={"force": "CH1", "angle": "CH2"})
    assert (caught.value.row, caught.value.column) == (14, "CH1")
    assert caught.value.message == f"{mark!r} is not a number"
    assert caught.value.hint == OUT_OF_RANGE_HINT


def test_a_row_of_dashes_is_told_as_no_reading_not_a_second_table(write):
    # a real rowing monitor's export: '---' where a stroke gave no reading; five dashes
    # and two numbers read as a names row opening a second table
    text = ("Interval,Distance,Elapsed,Total Strokes,Force Avg,Force Max\n"
            ",(m),(s),(Strokes),(N),(N)\n1,0.4,1.7,1,0.0,26.0\n1,0.7,3.2,2,111.0,271.0\n"
            "1,---,---,5,---,---\n1,57.9,44.8,6,5.0,31.0\n")
    with pytest.raises(ValueParseError) as caught:
        read_table(write("nk.csv", text), columns={"force": "Force Max", "gauges": ["Distance"]})
    assert (caught.value.row, caught.value.message) == (5, "'---' is not a number")
    assert caught.value.hint == OUT_OF_RANGE_HINT


def imada_list(force_units: list[str]) -> str:
    """An Imada Force Recorder list export: its statistics, then each value with its unit
    beside it, a judgement, an unused position and a time of day before the date."""
    head = ("Maximum,193.9,@,No.3,,,,,,\r\nMinimum,-0.5,@,No.1,,,,,,\r\nAverage,56.18,,,,,,,,\r\n"
            "Data Quantity,6,,,,,,,,\r\nNumber of NG,0,,,,,,,,\r\n"
            "No.,Force,Unit,Displacement,Unit,Judge,Position,Time,Date,\r\n")
    return head + "".join(
        f"{i + 1},{10.0 * i:.1f},{unit},{0.005 * i:.3f},mm,OK,--,10:30:5{i} AM,12/26/2024,\r\n"
        for i, unit in enumerate(force_units))


def test_a_force_gauges_unit_beside_each_value_is_the_columns_unit(write):
    table, meta = read_table(write("imada.csv", imada_list(["gf"] * 6)))
    assert list(table.columns) == ["time", "force", "gauge_1"]
    np.testing.assert_allclose(table["force"], 10.0 * np.arange(6) * 9.80665e-3)  # gf in N
    np.testing.assert_allclose(table["gauge_1"], 0.005e-3 * np.arange(6))
    np.testing.assert_allclose(table["time"], np.arange(6.0))
    assert {(c.name, c.unit) for c in meta.columns if c.role} == {
        ("Force", "gf"), ("Displacement", "mm"), ("Time", "s")}
    assert "unit of 'Force' (gf) from the column 'Unit' beside it" in meta.warnings
    assert meta.preamble["Maximum"].startswith("193.9")


def test_a_unit_column_of_two_units_gives_none(write):
    """A column whose unit changes is not one column's unit: the run sheet must say."""
    path = write("imada.csv", imada_list(["gf"] * 3 + ["N"] * 3))
    with pytest.raises(UnitError, match="no unit for the force column"):
        read_table(path)
    said = read_table(path, strict=False)[1].warnings
    assert "the column 'Unit' beside 'Force' holds several units (N, gf): none is taken as " \
        "its unit" in said


def test_components_named_alike_are_named_by_a_row_higher_up(write):
    # a Visual3D export: the signals' names, their types, then a components row "X X X"
    text = ("\tC:\\F02.txt\tC:\\F02.txt\tC:\\F02.txt\n\tFZsum\tFZsum_1Hz\tFZsum_2Hz\n"
            "\tDERIVED\tDERIVED\tDERIVED\n\tPROCESSED\tFILTER\tFILTER\nITEM\tX\tX\tX\n"
            "1\t723.38\t723.42\t722.12\n2\t724.60\t723.42\t722.12\n")
    _, meta = read_table(write("F02_CTRL2.txt", text), kind="tensile", strict=False)
    assert [column.name for column in meta.columns] == [
        "ITEM", "FZsum", "FZsum_1Hz", "FZsum_2Hz"]
    assert ("the columns named 'X' alike are named by a row higher up: 'FZsum', 'FZsum_1Hz', "
            "'FZsum_2Hz'" in meta.warnings)


def test_columns_named_alike_are_named_by_the_row_over_them(write):
    # they could not be told apart: naming one in the run sheet was refused
    table, meta = read_table(write("shot.asd", RECORDER), kind="engagement",
                             columns={"force": "DMS1B (0.A2)"}, units={"force": "kN"})
    np.testing.assert_allclose(table["force"], [-3.125, -5.625])
    assert ("the columns named 'Signal' alike are named by the row over them: 'DMS1A (0.A1)', "
            "'DMS1B (0.A2)'") in meta.warnings


def test_columns_named_alike_by_a_role_keep_their_names(write):
    # two load cells written 'Force': the row over them is not asked
    text = "Test;A;B;C\nTime;Force;Force;Disp\ns;kN;kN;mm\n0;1;2;3\n1;2;3;4\n"
    with pytest.raises(ColumnError, match="column .Force. is duplicated"):
        read_table(write("two.csv", text))


def test_settings_beside_the_first_rows_of_the_data_are_questioned(write):
    # a Hopkinson bar lab's export (its layout; our numbers): settings in the first two
    # columns beside the waveforms, whose first two numbers are their start and step
    settings = [("Test Time", "11:48:55 AM"), ("System ID", "HE"), ("Test Loading", "Compression"),
                ("Sample", "Cu")]
    lines = ["Test Date\t12/1/2006\tIncident\tTransmitted",
             *(f"{key}\t{value}\t{number}\t{number}" for (key, value), number
               in zip(settings, ["-5.00E-05", "1.00E-07", "-0.0113", "-0.0122"], strict=True)),
             *(f"\t\t{-0.01 * i:.4f}\t{-0.02 * i:.4f}" for i in range(10))]
    _, meta = read_table(write("shot.raw", "\n".join(lines) + "\n"), kind="engagement",
                         columns={"time": "Incident", "force": "Transmitted"},
                         units={"time": "s", "force": "kN"}, strict=False)
    assert ("lines 2 to 5: text beside the numbers in column(s) 1, 2, and none below: settings "
            "written beside the data? The numbers of those lines may be settings too (a "
            "waveform's start and step), not samples: check them") in meta.warnings


def test_a_comment_column_filled_to_the_end_of_the_head_is_no_setting(write):
    lines = ["time [s],force [kN],note", *(f"{i},{i * 2},ok" for i in range(12))]
    _, meta = read_table(write("log.csv", "\n".join(lines) + "\n"), kind="engagement")
    assert not any("settings written beside" in warning for warning in meta.warnings)
    # a lab's remarks on its first rows only ('broke near neck') are no settings either
    lines = ["time [s],force [kN],Comments", "0,0,broke near neck", "1,2,near neck",
             "2,4,neck", *(f"{i},{i * 2}," for i in range(3, 12))]
    _, meta = read_table(write("log.csv", "\n".join(lines) + "\n"), kind="engagement")
    assert not any("settings written beside" in warning for warning in meta.warnings)
    _, meta = read_table(write("log.csv", "\n".join(lines).replace("Comments", "Setting")
                               + "\n"), kind="engagement")
    assert any("settings written beside" in warning for warning in meta.warnings)
    # a material written on the first rows and N/A below: the column goes on
    lines = ["time [s],force [kN],material_type", *(f"{i},{i * 2},PLA" for i in range(3)),
             *(f"{i},{i * 2},N/A" for i in range(3, 12))]
    _, meta = read_table(write("log.csv", "\n".join(lines) + "\n"), kind="engagement")
    assert not any("settings written beside" in warning for warning in meta.warnings)


def test_a_units_row_repeating_a_name_gives_that_column_no_unit(write):
    # Instron WaveMatrix's peak-valley export writes the counter's name where its unit goes
    text = ("CycleCount,Axial Displacement ,Axial Force \nCycleCount,mm,N\n"
            "1,-0.9897321,-1043.830078\n1,-2.194233239,-2446.410645\n2,-1.0,-1100.5\n")
    table, meta = read_table(write("pv.csv", text), kind="tensile")
    np.testing.assert_allclose(table["force"], [-1043.830078, -2446.410645, -1100.5])
    np.testing.assert_allclose(table["gauge_1"], [-0.9897321e-3, -2.194233239e-3, -1.0e-3])
    np.testing.assert_allclose(table["cycle_count"], [1, 1, 2])
    assert {column.name: column.unit for column in meta.columns}["CycleCount"] is None
    assert meta.header_line == 1


def test_a_unit_alone_in_the_names_row_takes_the_name_over_it(write):
    # a Mitsubishi MR Configurator export: 'ms' under 'Time', the channels' names under
    # their slots
    text = ("Axis1\nNumber of sampling data,3\nSampling time interval(ms),0.667\n"
            "Time,Analog 1,Analog 2\nms,Servo motor speed,Torque\n"
            "0.000000,0.0,-1.0\n0.666666,0.0,-1.0\n1.333332,0.0,-0.8\n")
    table, meta = read_table(write("mr.csv", text), kind="engagement",
                             columns={"force": "Torque"}, units={"force": "N"})
    np.testing.assert_allclose(table["time"], [0, 0.666666e-3, 1.333332e-3])
    assert {column.name: column.unit for column in meta.columns}["Time"] == "ms"
    assert "a unit alone in the names row is taken with the name over it: 'Time [ms]'" in (
        meta.warnings)


def test_a_units_row_with_marks_and_words_the_reader_does_not_know_stays_one(write):
    # a real wind-tunnel balance's export: '/' for no unit, 'degr._C', 'steps' beside Pa,
    # 1/min and N; read as the names row, its '1/min' became a time in minutes
    names = ["Run_nr", "Time", "Alpha", "Delta_Pb", "T", "B1", "B2", "Fx", "Fy", "rpm", "Re"]
    units = ["/", "H:M:S", "degrees", "Pa", "degr._C", "steps", "steps", "N", "N", "1/min", "/"]
    rows = [f"{run}\t16:{31 + run}:28\t{run - 3}\t401.4\t15.3\t120.6\t-2057.6\t{run}.5\t"
            f"{run}.1\t471.9\t660951\n" for run in range(1, 6)]
    text = "\t".join(names) + "\n" + "\t".join(units) + "\n" + "".join(rows)
    table, meta = read_table(write("raw_test.txt", text), kind="engagement",
                             columns={"force": "Fx"})
    assert meta.header_line == 1 and meta.first_data_line == 3
    assert [(column.name, column.role, column.unit) for column in meta.columns
            if column.role] == [("Time", "time", "s"), ("Alpha", "angle", "degrees"),
                                ("Fx", "force", "N")]
    np.testing.assert_allclose(table["time"], [0.0, 60.0, 120.0, 180.0, 240.0])
    np.testing.assert_allclose(table["force"], [1.5, 2.5, 3.5, 4.5, 5.5])


def test_channels_labelled_by_letters_in_turn_are_no_units_row(write):
    # a real pressure rig's log: channels A to D under a one-word title; read as a units
    # row (amperes, bytes, coulombs, days), D made the sensor's counts the time
    text = ("log\nt (s) | A | B | C | D\n"
            + "".join(f"{0.05 * (i + 1):.2f} | {33852 + i} | {35304 - i} | {70 + i} | 45244\n"
                      for i in range(4)))
    table, meta = read_table(write("trial1_raw.csv", text), kind="tensile", strict=False)
    assert meta.header_line == 2
    assert [(column.name, column.role, column.unit) for column in meta.columns][0] == (
        "t", "time", "s")
    assert all(column.role is None for column in meta.columns[1:])
    np.testing.assert_allclose(table["time"], [0.05, 0.1, 0.15, 0.2])


def test_a_settings_table_passed_over_tells_the_rows_stated(write):
    # a real Kistler BioWare export, cut short: its settings, one value over each channel,
    # stand as a table above the names; they state 59118 samples, the file holds 4
    settings = "".join(f"{key}:\t" + "\t".join([value] * 3) + "\n" for key, value in [
        ("Device", "9260AA6"), ("Samples (#)", "59118"), ("Rate (Hz)", "1000.000000"),
        ("First sample time (s)", "0.000000")])
    text = ("BioWare Version 5.3.0.7 Export\n" + settings + "File Information\n"
            "abs time (s)\tFx\tFy\tFz\n\tN\tN\tN\n"
            + "".join(f"{i / 1000:.6f}\t0.1\t-0.2\t{i * 3.5}\n" for i in range(4)))
    _, meta = read_table(write("KistlerCSV_example.txt", text), kind="engagement",
                         columns={"force": "Fz"})
    assert meta.preamble["Rate (Hz)"] == "1000.000000 1000.000000 1000.000000"
    assert ("the header says Samples (#) = 59118, the file holds 4 rows: it may be cut short "
            "(copy it again from the machine)") in meta.warnings


@pytest.mark.parametrize(("unit", "newtons"), [("kp", STANDARD_GRAVITY), ("ton", None)])
def test_a_units_row_with_a_kilopond_or_a_ton_stays_the_units_row(write, unit, newtons):
    # an MTS Criterion export under a DAQ preamble, its load in kp (a kilopond, kgf) or in
    # ton: not read as a unit, the units row became the names row ('ton' named the load)
    text = ("Test: Tension Test\nTest Run: Test Run 3\n\nCrosshead\tLoad\tTime\n"
            f"mm\t{unit}\tsec\n" + "".join(f"{i * 0.1:.3f}\t{i * 0.5:.3f}\t{i}\n"
                                          for i in range(5)))
    path = write("DAQ- Crosshead, Load - (Timed).txt", text)
    if newtons is None:
        with pytest.raises(UnitError, match="a ton, the metric tonne") as caught:
            read_table(path)
        assert caught.value.column == "Load"
        return
    table, meta = read_table(path)
    assert [(column.name, column.unit) for column in meta.columns] == [
        ("Crosshead", "mm"), ("Load", unit), ("Time", "sec")]
    np.testing.assert_allclose(table["force"], 0.5 * np.arange(5) * newtons)
