"""Sniffing: encoding, dialect and the table's place in the head."""

import codecs

import numpy as np
import pytest

from pipeline.errors import EmptyFileError, EncodingError, LayoutError, ValueParseError
from pipeline.ingest import read_table
from pipeline.ingest.sniff import (
    HEAD_BYTES,
    detect_dialect,
    find_table,
    is_number,
    read_head,
    row_kind,
)
from pipeline.ingest.source import BufferSource


def head_of(path):
    """The sniffed head of a file, read as a buffer."""
    return read_head(BufferSource(path.read_bytes(), str(path)))

POLISH = "czas [s];siła [kN];wydłużenie [mm]\r\n0,0;1,5;0,01\r\n0,1;1,6;0,02\r\n"
SPANISH = "Tiempo\tFuerza\tDesplazamiento\r\nSec\tkgf\tmm\r\n0,0\t1,5\t0,01\r\n0,1\t1,6\t0,02\r\n"
# a real Japanese data logger's header, written in Shift-JIS by Japanese Windows
JAPANESE = ("H300-CP-No.1\r\n名前,測定日時 ,荷重 kN,変位 mm,表-縦 μ\r\n"
            "1,2019/11/01 17:06:57,0.064,-0.004,-0.947867\r\n"
            "2,2019/11/01 17:06:59,0.104,0,0.947867\r\n")
GERMAN = "Zeit [s];Temperatur [°C];Kraft [kN];Länge [mm]\r\n0,1;20,5;1,2;3\r\n0,2;20,5;1,3;3\r\n"
# as Russian, Chinese and Korean Windows write them: latin-1 reads their names as words of
# accented letters alone (Âðåìÿ), cp1250 likewise
RUSSIAN = ("Время\tНагрузка\tПеремещение\tТемпература\r\nс\tкН\tмм\t°С\r\n"
           "0,1\t5,024\t0,000\t20,5\r\n0,2\t5,379\t0,001\t20,5\r\n")
CHINESE = "时间(s),负荷(kN),位移(mm),应变(με)\r\n0.1,5.024,0.000,1\r\n0.2,5.379,0.001,2\r\n"
KOREAN = "시간(s),하중(kN),변위(mm)\r\n0.1,5.024,0.000\r\n0.2,5.379,0.001\r\n"


@pytest.mark.parametrize(
    ("text", "encoding", "expected"),
    [
        (POLISH, "cp1250", "cp1250"),
        (SPANISH.replace("Fuerza", "Fuerza señal"), "latin-1", "latin-1"),
        (JAPANESE, "cp932", "cp932"),
        # a real Japanese logger's channel table: ranges in ±, units in 【】 brackets
        (JAPANESE.replace("荷重 kN", "荷重【kN】") + "入力レンジ,±10V\r\n", "cp932", "cp932"),
        (GERMAN, "latin-1", "latin-1"),  # °C and ä decode in Shift-JIS too, as nonsense
        (RUSSIAN, "cp1251", "cp1251"),
        (CHINESE, "gbk", "gbk"),
        (KOREAN, "cp949", "cp949"),
        # a few names only, of four characters, beside English ones or Greek units
        ("试验时间(s),横梁位移(mm),循环次数\r\n1,2,3\r\n", "gbk", "gbk"),
        ("Time(s),Force(kN),位移(mm)\r\n1,2,3\r\n", "gbk", "gbk"),
        ("试验力(kN),变形(μm)\r\n1,2\r\n", "gbk", "gbk"),
        ("하중(N),변위(mm)\r\n1,2\r\n", "cp949", "cp949"),
        ("힘(N),변형량(mm)\r\n1,2\r\n", "cp949", "cp949"),
        # a Turkish machine's export: latin-1 read its ı and ş as Icelandic letters
        ("Süre;Yük;Uzama;Çevrim sayısı;Sınıfı\r\n1;2;3;4;5\r\n", "cp1254", "cp1254"),
        # words of accented letters alone, Latin all the same
        ("Länge;Größe;Höhe;Öffnung;Ärger\r\n1;2;3;4;5\r\n", "latin-1", "latin-1"),
        ("Siła;Wydłużenie;Czas;Ścieżka\r\n1;2;3;4\r\n", "cp1250", "cp1250"),
        (POLISH, "utf-8", "utf-8"),
        (POLISH, "utf-8-sig", "utf-8-sig"),
        (POLISH, "utf-16", "utf-16"),
        (POLISH, "utf-16-le", "utf-16-le"),
    ],
)
def test_encoding(write, text, encoding, expected):
    head = head_of(write("f.csv", text, encoding))
    assert head.encoding == expected
    assert head.lines[0] == text.splitlines()[0]


def test_offsets_are_bytes_of_line_starts(write):
    path = write("f.csv", POLISH, "utf-16")
    head = head_of(path)
    raw = path.read_bytes()
    assert raw[head.offsets[1] : head.offsets[2]].decode("utf-16-le") == "0,0;1,5;0,01\r\n"


def test_long_file_head_drops_the_cut_line(write):
    line = "1.5,2.5,3.5\n"
    header = "a [s],b [kN],c [mm]\n"
    head = head_of(write("f.csv", header + line * (HEAD_BYTES // len(line) + 50)))
    assert not head.complete
    assert all(text in ("1.5,2.5,3.5",) for text in head.lines[1:])
    assert head.offsets[-1] % len(line) == len(header) % len(line)


def test_binary_file(write):
    with pytest.raises(EncodingError, match="binary"):
        head_of(write("f.csv", b"\x00\x01\x02\x03" * 100))


def test_bom_contradicted(write):
    with pytest.raises(EncodingError, match="byte-order mark") as caught:
        head_of(write("f.csv", codecs.BOM_UTF8 + POLISH.encode("cp1250")))
    assert caught.value.row == 1


@pytest.mark.parametrize(("content", "message"), [(b"", "empty"), (b"\r\n \n", "blank")])
def test_empty(write, content, message):
    with pytest.raises(EmptyFileError, match=message):
        head_of(write("f.csv", content))


@pytest.mark.parametrize(
    ("lines", "dialect"),
    [
        (["t,f", "0.5,1.5", "1.5,2.5"], (",", ".", 2)),
        (["t;f", "0,5;1,5", "1,5;2,5"], (";", ",", 2)),
        (["t\tf", "0,5\t1,5"], ("\t", ",", 2)),
        (["t\tf", "0.5\t1.5"], ("\t", ".", 2)),
        (['"t","f"', '"0,5","1,5"'], (",", ",", 2)),
        (["t|f|g", "1|2|3"], ("|", ".", 3)),
        (["date,f,g", "2021-01-01,1.5,2.5", "2021-01-02,1.5,2.5"], (",", ".", 3)),
        (["t,f", "0,5,1,5", "1,5,2,5"], (",", ".", 4)),
        # a fatigue rig's log ending in its raw serial frame: split at the semicolons, the
        # rows hold more numbers, but the names row is split at the commas only
        (["t,f1,f2,state,frame", "0.5,1.5,2.5,OK,DTA;1;15;25;4;5;!",
          "1.5,1.6,2.6,OK,DTA;2;16;26;4;5;!"], (",", ".", 5)),
        # a home-built rig's log under a settings line: split at its commas, a row's first
        # field still holds a clock reading, but among semicolons
        (["L0 = 81,2;d = 2,25;Polymer PVC", "38354132;11:02:46;2,8;0,0",
          "57745416;11:02:47;1,4;0,0", "54460604;11:02:48;0,4;0,0"], (";", ",", 4)),
        # a GOM ARAMIS section: aligned by blanks, with decimal commas (split at them,
        # a row would leave "133656  -0" in a cell)
        (["Sectionlength deltaL", "0,000000  -0,004665", "0,133656  -0,004617",
          "2,398251  0,000270"], (" ", ",", 2)),
        # a spreadsheet's semicolons and decimal commas, a force grouped in thousands once:
        # split at the commas, every row would read "0;97" in a cell
        (["Ecrasement (mm);Forcestandard (N)", "0,0;97,52", "-0,0000378;96,24",
          "1,35376588733876;1.017,11"], (";", ",", 2)),
    ],
)
def test_dialect(lines, dialect, tmp_path):
    assert detect_dialect(lines, tmp_path) == dialect


@pytest.mark.parametrize(("text", "kind"), [
    ('{"format":"channel","nr":1,"tightening steps":[{"graph":{"time values":[0.0,0.001]}}]}',
     "JSON"),
    ('[\n  {\n    "time": 0.0,\n    "torque": 1.5\n  },\n  {"time": 0.001}\n]\n', "JSON"),
    ('<?xml version="1.0"?>\n<test><point t="0.0" f="1,5"/></test>\n', "XML"),
    # a catman UFF58 dataset: its records were read as a table, broken at the sixth
    ("    -1\n    58\n1x : m/s²\nUFF58 file created by HBM catman\n30-Apr-20 19:12:52\n"
     "NONE\nNONE\n    1         0    0         0 NONE               0   0 NONE   0   0\n"
     "         2        13         1 0.00000E+000 5.00000E-005 0.00000E+000\n"
     " -3.81956E+00 -3.56616E+00 -2.98987E+00 -2.62207E+00 -3.22879E+00 -3.63712E+00\n"
     "    -1\n", r"Universal File Format \(UFF\)"),
])
def test_a_structured_document_is_refused_as_such(write, text, kind):
    # a screwdriver's curve export: its braces and commas are no table's rows
    with pytest.raises(LayoutError, match=f"the file is a {kind} document, not a table"):
        read_table(write("curve.txt", text))


@pytest.mark.parametrize("cell", ["1.017,11", "1 017,11", "1\u00a0017,11", "1\u202f017,11",
                                  "1.001,5"])
def test_a_force_grouped_in_thousands_before_its_decimal_comma_is_read(write, cell):
    # a spreadsheet in a German or French locale formats the loads from 1,000 N on so
    text = f"Weg (mm);Kraft (N)\n0,0;97,52\n0,1;485,27\n0,2;{cell}\n"
    table, _ = read_table(write("excel.csv", text), kind="tensile")
    expected = float(cell.replace(".", "").replace(",", ".").replace("\u00a0", "")
                     .replace("\u202f", "").replace(" ", ""))
    np.testing.assert_allclose(table["force"], [97.52, 485.27, expected])


def test_a_swiss_apostrophe_grouping_thousands_is_read(write):
    text = "Weg (mm);Kraft (N)\n0.0;97.52\n0.1;485.27\n0.2;1'017.11\n"
    table, _ = read_table(write("excel.csv", text), kind="tensile")
    np.testing.assert_allclose(table["force"], [97.52, 485.27, 1017.11])


def test_a_grouping_no_break_space_not_in_utf8_is_named_with_its_cause(write):
    text = "Weg (mm);Kraft (N)\n0,0;97,52\n0,1;485,27\n0,2;1\u00a0017,11\n"
    with pytest.raises(ValueParseError, match="is not a number") as caught:
        read_table(write("excel.csv", text, encoding="cp1252"), kind="tensile")
    assert caught.value.row == 4 and caught.value.hint.startswith(
        "the number is grouped in thousands in a form not read here")


@pytest.mark.parametrize(("rows", "shown"), [
    (["1,1.8%,0.4%", "2,2.5%,0.7%", "3,3.8%,1.1%"], "'1.8%', '2.5%', '3.8%'"),
    (["0 mm;97,52 N", "0,1 mm;98,3 N", "0,2 mm;99,1 N"], "'0 mm', '0,1 mm', '0,2 mm'"),
])
def test_numbers_with_their_unit_in_each_cell_are_refused_as_such(write, rows, shown):
    # a webbing maker's stretch chart saved with its percent format; a spreadsheet's units
    with pytest.raises(LayoutError) as caught:
        read_table(write("chart.csv", "Force,Elongation A,Elongation B\n" + "\n".join(rows)))
    assert caught.value.message == (f"the cells hold numbers with a unit or percent sign in "
                                    f"them ({shown}): the readers read bare numbers")


def test_complex_numbers_are_refused_as_such(write):
    # a MATLAB script wrote its force through a complex intermediate
    text = "time_s,force_N\n" + "".join(f"{i}+0i,{839.9 + i:.3f}+0i\n" for i in range(5))
    with pytest.raises(LayoutError) as caught:
        read_table(write("rig.csv", text))
    assert caught.value.message == ("the cells hold complex numbers ('0+0i', '1+0i', '2+0i'): "
                                    "the readers read real numbers")


def test_header_only_is_empty(tmp_path):
    with pytest.raises(EmptyFileError, match="no data rows"):
        detect_dialect(["Machine : Amsler", "", "time [s],force [kN]"], tmp_path)
    with pytest.raises(EmptyFileError, match="no data rows"):
        detect_dialect(["Points: 51", "Cycles: 3 5", "end"], tmp_path)


def test_a_summary_of_results_is_told_as_such_not_as_text_lines(tmp_path):
    # a real finger-strength app's export: one row of results, one number among its texts
    lines = ["date,tag,comment,unit,type,max weight,body weight,force/BW",
             "2026-29-07 09:31:55,max force test ,,SI,single,10.3841515,,"]
    with pytest.raises(EmptyFileError) as caught:
        detect_dialect(lines, tmp_path)
    assert caught.value.message == (
        "no data rows: no line holds two numbers side by side, as a log's rows do (a summary "
        "of a test's results?)")
    assert caught.value.hint.startswith("export the test's raw data")


def test_a_text_with_a_year_in_its_sentences_holds_only_text_lines(tmp_path):
    lines = ["MIT License", "", "Copyright (c) 2021 The authors", "", "Permission is granted"]
    with pytest.raises(EmptyFileError, match="the file holds only text lines"):
        detect_dialect(lines, tmp_path)


def test_a_header_file_naming_its_data_file_points_to_it(tmp_path):
    # a real HBM catman .TSX: the test's settings, and the file its measurements went to
    lines = ["CATMAN TEST FILE", "Messwertdatei=DD11_7_3.ASC", "Standardmessrate=50 Hz",
             r"DATAFILE=C:\Users\Ch\Desktop\2007_HTT\DD11_7_3.ASC"]
    with pytest.raises(EmptyFileError, match="no data rows") as caught:
        detect_dialect(lines, tmp_path / "DD11_7_3.TSX")
    assert caught.value.hint.startswith("the file names 'DD11_7_3.ASC': the measurements")
    assert caught.value.row == 5  # where the data would have begun
    with pytest.raises(EmptyFileError) as own:  # a file naming itself names no other
        detect_dialect(lines[:3], tmp_path / "dd11_7_3.asc")
    assert own.value.hint == "the machine wrote no measurements: export the test again"


def test_a_log_of_states_beside_its_readings_is_a_table(tmp_path):
    # a real hip-wear rig's log: six columns of text, four of numbers and clock readings
    names = ("wall_time_iso,elapsed_s,elapsed_hhmmss,mode,run_state,temp_s1_c,temp_s2_c,"
             "side_motor,top_motor_s1,top_motor_s2,message")
    lines = [names] + [f"2026-03-09T00:19:4{row},{row + 0.19:.2f},00:00:0{row},S1,RUNNING,"
                       f"25.{row}20,24.819,RUN,RUN,SLEEP,Test started (S1)." for row in range(5)]
    assert detect_dialect(lines, tmp_path) == (",", ".", 11)
    spec = find_table(lines, tmp_path, ",", ".", 11)
    assert (spec.header_index, spec.data_index) == (0, 1)
    assert spec.texts == frozenset({3, 4, 7, 8, 9, 10})


def test_no_numbers_is_layout_error(tmp_path):
    with pytest.raises(LayoutError, match="no table of numbers"):
        detect_dialect(["a,b,c,1,2", "d,e,f,3,4"], tmp_path)


def test_find_machine_export(tmp_path):
    lines = ["Text Inputs : Specimen label,\"22L.3\"", "General : Start Date,13/11/2018", "",
             "Time,Extension,Load,Segment ID,Total Cycle Count", "(sec),(mm),(N),,",
             "0.0,-2.0,-4.3,22476,0", "0.1,-2.1,-4.4,22476,0"]
    spec = find_table(lines, tmp_path, ",", ".", 5)
    assert (spec.header_index, spec.units_index, spec.data_index) == (3, 4, 5)
    assert spec.units == ["sec", "mm", "N", None, None]
    assert spec.preamble == lines[:2]


def test_find_plain_table_with_bad_first_row(tmp_path):
    spec = find_table(["t [s],f [kN]", "0.0,abc", "0.1,2.0", "0.2,3.0"], tmp_path, ",", ".", 2)
    assert (spec.header_index, spec.data_index) == (0, 1)


def test_trailing_delimiter_pads_names(tmp_path):
    spec = find_table(["t [s],f [kN]", "0.0,1.0,", "0.1,2.0,"], tmp_path, ",", ".", 3)
    assert spec.names == ["t [s]", "f [kN]", ""]
    assert not spec.notes  # the column on the right is empty


@pytest.mark.parametrize("lines", [
    ["time [s],force [N],0,angle [rad]", "0.000,1.0,0,0.1", "0.001,1.1,0,0.2"],
    ["# Test started", "time [s],force [N],0,angle [rad]", "0.000,1.0,0,0.1", "0.001,1.1,0,0.2"],
])
def test_a_number_among_the_names_leaves_them_the_names_row(tmp_path, lines):
    # a rig's logger named one column "0": its names row is no data row with a bad cell
    spec = find_table(lines, tmp_path, ",", ".", 4)
    assert spec.names == ["time [s]", "force [N]", "0", "angle [rad]"]
    assert spec.data_index == len(lines) - 2
    assert (f"line {len(lines) - 2}: the names row holds numbers among its names ('0'): "
            "read as names") in spec.notes


def test_a_row_of_channel_numbers_over_columns_of_text_is_the_names_row(write):
    # an endurance rig's log names its channels by number; its rows hold flags F and T
    text = "1;7;8;2\n" + "".join(f"{1657711476152 + 100 * i};30.19;{i}.5;{'FT'[i % 2]}\n"
                                  for i in range(6))
    table, meta = read_table(write("Log_ecos.csv", text), kind="tensile", strict=False,
                             columns={"force": "8", "gauges": "7"}, units={"force": "N",
                                                                       "gauges": "mm"})
    assert meta.rows == 6 and meta.header_line == 1
    np.testing.assert_allclose(table["force"], np.arange(6) + 0.5)
    assert ("line 1: a row of channel numbers over columns of text is read as the names row"
            in meta.warnings)


def test_data_wider_than_its_names_is_told(tmp_path):
    # a rig's log whose names row lost a delimiter: names and data may not line up
    spec = find_table(["t [s],f [N],angle [rad]", "0.0,1.0,10.0,0.1", "0.1,1.1,10.1,0.2"],
                      tmp_path, ",", ".", 4)
    assert spec.names == ["t [s]", "f [N]", "angle [rad]", ""]
    assert any("has 3 names over data rows of 4 fields" in note and "1 column(s) on the "
               "right go without one" in note for note in spec.notes)


def test_names_row_too_wide(tmp_path):
    with pytest.raises(LayoutError, match="names row has 3 fields") as caught:
        find_table(["a,b,c", "1.0,2.0", "1.0,2.0"], tmp_path, ",", ".", 2)
    assert caught.value.row == 1


@pytest.mark.parametrize(
    ("text", "decimal", "expected"),
    [("1.5", ".", True), ("-1,5e-3", ",", True), (" 2 ", ".", True), (".5", ".", True),
     ("1,5", ".", False), ("1.5", ",", False), ("abc", ".", False), ("inf", ".", True),
     ("1.0.0", ".", False), ("", ".", False)],
)
def test_is_number(text, decimal, expected):
    assert is_number(text, decimal) is expected


@pytest.mark.parametrize("preamble", [0, 255, 256, 700])
def test_a_table_below_a_preamble_of_any_length_is_found(tmp_path, preamble):
    lines = [f"Comment {i} : value {i}" for i in range(preamble)]
    lines += ["t [s],f [kN]", "(s),(kN)"] + [f"{i / 10:.1f},{i:.1f}" for i in range(300)]
    spec = find_table(lines, tmp_path, ",", ".", 2)
    assert (spec.header_index, spec.units_index, spec.data_index) == (
        preamble, preamble + 1, preamble + 2)
    assert len(spec.preamble) == preamble


@pytest.mark.parametrize(("line", "kind"), [
    ("1,0.0,gf,0.000,mm,OK,--,10:30:52 AM", "numeric"),  # a unit after each value
    ("1,0.0,0.000,OK,--,10:30:52 AM", "numeric"),
    ("1,0.0,xx,0.000,yy,OK,--,10:30:52 AM", "partial"),  # words, not units
    (",Sec,mm,N,,-0.081,-5.86", "partial"),  # a units row with numbers typed beside it
    ("Points,51,mm", "partial"),  # a setting: its unit does not make it data
    ("gf,0.0,mm,0.000,OK", "partial"),  # a unit before the first value is text
])
def test_a_unit_right_after_a_number_counts_for_neither(line, kind):
    assert row_kind(line.split(","), line, ".") == kind
