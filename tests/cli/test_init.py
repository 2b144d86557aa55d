"""``chainbench init``: a draft run sheet from the exports in a folder."""

from __future__ import annotations

import json
import shutil
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.cli import app
from pipeline.cli.init import natural_key, safe_name, toml_string, unique_name
from pipeline.runsheet import load_run_sheet

runner = CliRunner()

ASCHEN = "AschenPhoenix__Simulation_mit_Python__Specimen_RawData_1"
CCFATIGUE = "EPFL-ENAC__CCFatiguePlatform__TST_2021-10_FA_22"
YADBOR = "yadbor__bluer__Specimen_RawData_6"

LOAD = [min(i % 10, 10 - i % 10) for i in range(60)]  # 6 load/unload cycles, 0 -> 5 -> 0 kN
PLAIN = "time [s],force [kN],gauge1 [mm],gauge2 [mm]\n" + "".join(
    f"{i / 10},{load},{load / 100},{load / 90}\n" for i, load in enumerate(LOAD)
)
#: Names with a quote, a backslash and non-ASCII letters (European CSV, quoted header cell).
ODD_NAMES = ("Zeit", 'Siła "A"', "Odkształcenie 1", "Weg\\2")
ODD = 'Zeit [s];"Siła ""A"" [kN]";Odkształcenie 1 [%];Weg\\2 [mm]\n' + "".join(
    f"{i / 10:.1f};{load};{load / 100:.3f};{load / 90:.4f}\n".replace(".", ",")
    for i, load in enumerate(LOAD)
)


@pytest.fixture
def realdata_campaign(realdata, tmp_path) -> Path:
    """A campaign folder in `tmp_path` holding copies of every real export (never the
    repository: the exports are not ours to commit)."""
    folder = tmp_path / "realdata"
    folder.mkdir()
    for path in realdata.iterdir():
        if path.is_file() and path.name != "README.md":
            shutil.copy2(path, folder / path.name)
    return folder


def init(*arguments: str):
    return runner.invoke(app, ["init", *arguments])


def fill_in(sheet: Path) -> None:
    """Replace the placeholders of a realdata draft as a technician would."""
    text = sheet.read_text(encoding="utf-8")
    # 18x64's geometry without its catalogue preload (1000 kgf): the real specimens are
    # coupons loaded to a few kN, below any chain preload
    for key, value in (("d_mm", 18), ("t_mm", 64), ("R0_mm", 20), ("a_mm", 42)):
        text = text.replace(f"\n# {key} = ...\n", f"\n{key} = {value}\n")
    text = text.replace("# gauge_length_mm = ...  # TODO: the length the gauges measure over",
                        "gauge_length_mm = 50")
    text = text.replace('units = {force = "TODO", gauges = "TODO"}',
                        'units = {force = "kN", gauges = "mm"}')
    sheet.write_text(text, encoding="utf-8")


@pytest.mark.realdata
def test_realdata_draft_has_one_run_per_file(realdata_campaign):
    result = init(str(realdata_campaign))
    assert result.exit_code == 0, result.output
    assert "chainbench validate" in result.stdout
    sheet = load_run_sheet(realdata_campaign)
    assert sheet.invalid_runs == []
    assert sheet.campaign.id == "realdata"
    assert sorted(run.file for run in sheet.runs) == sorted(
        path.name for path in realdata_campaign.iterdir() if path.name != "campaign.toml")
    runs = {run.id: run for run in sheet.runs}
    aschen = runs[ASCHEN]
    assert (aschen.kind, aschen.chain, aschen.specimen, aschen.cycles) == (
        "tensile", "chain1", ASCHEN, 1)
    assert aschen.columns.force == "Last" and aschen.columns.time == "Zeit"
    assert {"Traversenweg", "Dehnung 1"} <= set(aschen.columns.gauges)
    assert aschen.units.gauges is None  # mm and %: the file's own units are used
    assert runs[YADBOR].cycles == 3 and runs[YADBOR].columns.force == "Load"
    assert (runs[CCFATIGUE].units.force, runs[CCFATIGUE].units.gauges) == ("TODO", "TODO")
    assert all(run.gauge_length_mm is None for run in sheet.runs)


@pytest.mark.realdata
def test_realdata_draft_comments(realdata_campaign):
    text = init("--print", str(realdata_campaign)).stdout
    assert '# TODO: fill in the chain (catalog = "18x64", or d_mm, t_mm, R0_mm, a_mm)' in text
    assert ('# gauge channels: "Traversenweg" crosshead (length); "Dehnung 1" extensometer '
            "(strain)") in text
    assert '# chainbench prefers "Dehnung 1" (extensometer;' in text
    assert "# detected: layout mts, encoding latin-1, delimiter tab" in text
    assert "# TODO: the file gives no unit for force, gauges" in text
    assert all(len(line) <= 120 for line in text.splitlines()
               if line.startswith("#") and "chainbench validate" not in line)


@pytest.mark.realdata
def test_realdata_draft_validates_once_filled_in(realdata_campaign):
    assert init(str(realdata_campaign)).exit_code == 0
    assert runner.invoke(app, ["validate", str(realdata_campaign)]).exit_code == 1
    sheet = realdata_campaign / "campaign.toml"
    fill_in(sheet)
    # coupons of a few kN are no 18x64 chain: each E0 is flagged against the chain's theory
    flagged = runner.invoke(app, ["validate", str(realdata_campaign)], env={"COLUMNS": "300"})
    assert flagged.exit_code == 1
    lines = [line for line in flagged.output.splitlines() if line.startswith("implausible ")]
    assert len(lines) == 5 and all("of the theory" in line for line in lines), flagged.output
    sheet.write_text(sheet.read_text(encoding="utf-8").replace(
        '[[runs]]\n', '[[runs]]\naccept_implausible = true\n'), encoding="utf-8")
    result = runner.invoke(app, ["validate", str(realdata_campaign)])
    assert result.exit_code == 0, result.output
    assert "5 runs, 0 problems" in " ".join(result.output.split())


def test_never_overwrites(tmp_path):
    (tmp_path / "t.csv").write_text(PLAIN)
    (tmp_path / "campaign.toml").write_text("# mine\n")
    result = init(str(tmp_path))
    assert result.exit_code == 1
    assert "exists" in result.stderr and "never overwrites" in result.stderr
    assert (tmp_path / "campaign.toml").read_text() == "# mine\n"


def test_print_writes_nothing_and_is_allowed_over_a_sheet(tmp_path):
    (tmp_path / "t.csv").write_text(PLAIN)
    (tmp_path / "campaign.toml").write_text("# mine\n")
    result = init("--print", str(tmp_path))
    assert result.exit_code == 0, result.output
    draft = tomllib.loads(result.stdout)
    assert draft["runs"] == [{
        "id": "t", "kind": "tensile", "file": "t.csv", "chain": "chain1", "specimen": "t",
        "cycles": 6, "columns": {"time": "time", "force": "force", "gauges": ["gauge1", "gauge2"]},
        "units": {"time": "s", "force": "kN", "gauges": "mm"},
    }]
    assert draft["chains"] == {"chain1": {}}
    assert (tmp_path / "campaign.toml").read_text() == "# mine\n"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["campaign.toml", "t.csv"]


def test_a_tensile_draft_leaves_out_a_time_without_unit_the_run_does_without(tmp_path):
    # a microtester's export names its columns but gives no unit: a tensile run needs the
    # force's and the gauge's, and goes on without the time's
    (tmp_path / "data_1.csv").write_text("Elongation,Force,Time\n" + "".join(
        f"{0.01 * i:.2f},{load},{0.00055 * i:.5f}\n" for i, load in enumerate(LOAD)))
    result = init("--print", str(tmp_path))
    assert result.exit_code == 0, result.output
    run = tomllib.loads(result.stdout)["runs"][0]
    assert (run["columns"], run["units"]) == (
        {"force": "Force", "gauges": ["Elongation"]}, {"force": "TODO", "gauges": "TODO"})


def test_the_gauge_lengths_the_header_states_are_shown_not_filled_in(tmp_path):
    # a Bluehill export in Polish states the extensometer's gauge length and the one its
    # strain from the crosshead travel was computed over: which one the run's gauges
    # measure over is the lab's to say
    preamble = ("Odkształcenie : Odkształcenie 1 długość pomiarowa;\"10,00000\";mm\n"
                "Odkształcenie : Odkształcenie przy rozciąganiu (Przemieszczenie) długość "
                "pomiarowa;\"25,00000\";mm\nWłaściwości próbki : Szerokość;\"6,66000\";mm\n\n")
    body = "Godzina;Przemieszczenie;Obciążenie\n(s);(mm);(N)\n" + "".join(
        f"{i / 10:.1f};{load / 100:.3f};{load * 100}\n".replace(".", ",")
        for i, load in enumerate(LOAD))
    (tmp_path / "pl.csv").write_bytes((preamble + body).encode("cp1250"))
    result = init("--print", str(tmp_path))
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    todo = lines.index("# gauge_length_mm = ...  # TODO: the length the gauges measure over")
    assert lines[todo + 1 : todo + 3] == [
        '# the file\'s header says "Odkształcenie 1 długość pomiarowa" = 10,00000 mm',
        '# the file\'s header says "Odkształcenie przy rozciąganiu (Przemieszczenie) długość '
        'pomiarowa" = 25,00000 mm']
    assert "Szerokość" not in result.stdout
    assert "gauge_length_mm" not in tomllib.loads(result.stdout)["runs"][0]


def test_odd_column_names_round_trip(tmp_path):
    (tmp_path / "odd.csv").write_text(ODD, encoding="utf-8")
    assert init(str(tmp_path)).exit_code == 0
    raw = (tmp_path / "campaign.toml").read_bytes()
    run = tomllib.loads(raw.decode("utf-8"))["runs"][0]
    assert [run["columns"]["time"], run["columns"]["force"], *run["columns"]["gauges"]] == list(
        ODD_NAMES)
    text = raw.decode("utf-8")
    text = text.replace("# gauge_length_mm = ...  # TODO: the length the gauges measure over",
                        "gauge_length_mm = 500").replace('# catalog = "..."', 'catalog = "13x50"')
    (tmp_path / "campaign.toml").write_text(text, encoding="utf-8")
    sheet = load_run_sheet(tmp_path)
    from pipeline.runs import read_run

    _, metadata = read_run(sheet, sheet.runs[0])
    assert {column.name: column.role for column in metadata.columns} == {
        "Zeit": "time", 'Siła "A"': "force", "Odkształcenie 1": "strain_1", "Weg\\2": "gauge_1"}


@pytest.mark.parametrize("text", ['Siła "A"', "back\\slash", "tab\there", "line\nbreak",
                                  "bell\x07 del\x7f", "Odkształcenie 1", "µm/m ≥ 0 🙂"])
def test_toml_string_reads_back_exactly(text):
    assert tomllib.loads(f"name = {toml_string(text)}\n")["name"] == text


def test_skips_what_is_no_export(tmp_path):
    (tmp_path / "run2.csv").write_text(PLAIN)
    (tmp_path / "run10.csv").write_text(PLAIN)
    (tmp_path / "run 2.csv").write_text(PLAIN)
    (tmp_path / "notes.txt").write_text("nothing to read here\n")
    (tmp_path / "empty.csv").write_bytes(b"")
    (tmp_path / ".hidden.csv").write_text(PLAIN)
    (tmp_path / "truth.json").write_text("{}")
    (tmp_path / "photos").mkdir()
    result = init("--json", str(tmp_path))
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert [(run["file"], run["id"]) for run in document["runs"]] == [
        ("run2.csv", "run2"), ("run10.csv", "run10"), ("run 2.csv", "run_2")]
    assert sorted(item["file"] for item in document["skipped"]) == [
        "empty.csv", "notes.txt", "photos"]
    sheet = load_run_sheet(tmp_path)
    assert [run.id for run in sheet.runs] == ["run2", "run10", "run_2"]
    text = (tmp_path / "campaign.toml").read_text(encoding="utf-8")
    assert "# skipped empty.csv: " in text and "# skipped notes.txt: " in text


def test_a_file_of_several_force_columns_is_skipped_saying_so_not_drafted_with_one(tmp_path):
    # a results block left of the reading: 'Max force' was drafted as the run's force
    (tmp_path / "run1.csv").write_text(PLAIN)
    # with no force, a log of a gauge against time drafts a wear run: no guess either
    (tmp_path / "pull.csv").write_text(
        "Time (s),Max force (N),Min force (N),Force (N),gauge [mm]\n"
        + "".join(f"{i},{3.96 + i},{i - 1.15},{i / 10},{i}\n" for i in range(20)))
    result = init("--json", str(tmp_path))
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert [run["file"] for run in document["runs"]] == ["run1.csv"]
    assert document["skipped"] == [{
        "file": "pull.csv",
        "reason": "column 'Max force': 3 columns could be the force: 'Max force', 'Min "
                  "force', 'Force' (hint: write this run by hand, naming its force, columns = "
                  "{force = \"...\"})"}]


def test_no_readable_file_exits_1(tmp_path):
    (tmp_path / "notes.txt").write_text("nothing to read here\n")
    result = init(str(tmp_path))
    assert result.exit_code == 1
    assert "no file" in result.stderr and "skipped notes.txt" in result.stderr
    assert not (tmp_path / "campaign.toml").exists()


def test_engagement_log_is_guessed(tmp_path):
    rows = "".join(f"{i / 5000},{20000 + (i % 50) * 100},{i / 1000}\n" for i in range(2000))
    (tmp_path / "E6.csv").write_text("time [s],force [N],angle [rad]\n" + rows)
    text = init("--print", str(tmp_path)).stdout
    assert 'kind = "engagement"  # guessed: time and force at 5000 Hz and no gauge' in text
    assert "# [wheels.wheel1]" in text and '# wheel = "wheel1"' in text
    draft = tomllib.loads(text)
    assert draft["runs"][0]["columns"] == {"time": "time", "force": "force", "angle": "angle"}
    assert "cycles" not in draft["runs"][0]


DEMOS = Path(__file__).parents[2] / "raw"


def drafted_copy(demo: str, logs: str, folder: Path) -> tuple[str, dict]:
    """The draft of a folder holding demo campaign `demo`'s logs `logs` (a glob) without
    its run sheet, and that run sheet, as a technician would compare them."""
    if not (DEMOS / demo).is_dir():
        pytest.skip(f"raw/{demo} is absent")
    folder.mkdir()
    for path in (DEMOS / demo).glob(logs):
        shutil.copy2(path, folder / path.name)
    result = init(str(folder))
    assert result.exit_code == 0, result.output
    return ((folder / "campaign.toml").read_text(encoding="utf-8"),
            tomllib.loads((DEMOS / demo / "campaign.toml").read_text(encoding="utf-8")))


def validates(folder: Path, text: str, runs: int) -> None:
    """The filled-in draft `text`, written over `folder`'s, validates with no problem."""
    (folder / "campaign.toml").write_text(text, encoding="utf-8")
    validated = runner.invoke(app, ["validate", str(folder)], env={"COLUMNS": "200"})
    assert validated.exit_code == 0, validated.output
    assert f"{runs} runs, 0 problems" in " ".join(validated.output.split())


def test_wear_logs_are_drafted_as_wear_runs_that_validate_once_filled_in(tmp_path):
    """The wear demo's four logs (a length, an elongation without force, cycles, TDMS),
    drafted without their run sheet, then filled in with the demo sheet's values."""
    text, demo = drafted_copy("wear-demo", "W16-*", tmp_path / "wear")
    draft = tomllib.loads(text)
    assert [run["kind"] for run in draft["runs"]] == ["wear"] * 4
    assert draft["runs"][2]["columns"] == {"cycle_count": "Liczba cykli",
                                           "length": "Długość odcinka"}
    assert draft["runs"][2]["units"] == {"length": "mm"}  # a counter takes no unit
    given = {run["id"]: run for run in demo["runs"]}
    for key in ("section_pitches", "elongation_reference", "sprocket_teeth"):
        assert f"# {key} = " in text
    entries = text.split("[[runs]]\n")
    for index, run in enumerate(draft["runs"], start=1):
        values = given[run["id"]]
        entries[index] = entries[index].replace("# section_pitches = ...", "section_pitches = "
                                                f"{values['section_pitches']}").replace(
            '# elongation_reference = "..."',
            f'elongation_reference = "{values["elongation_reference"]}"').replace(
            "# sprocket_teeth = ...", f"sprocket_teeth = {values['sprocket_teeth']}")
    validates(tmp_path / "wear", "[[runs]]\n".join(entries).replace(
        '# catalog = "..."', 'catalog = "16B"'), runs=4)


def test_segment_load_logs_are_drafted_as_such_and_validate_once_filled_in(tmp_path):
    """The segment-load demo's five logs, drafted without their run sheet, then given the
    demo's chain and drum."""
    text, demo = drafted_copy("segment-load-demo", "S34-*", tmp_path / "segments")
    draft = tomllib.loads(text)
    assert [run["kind"] for run in draft["runs"]] == ["segment-load"] * 5
    assert draft["runs"][4]["columns"] == {"time": "Time", "force": "Force",
                                           "segment_force_1": "F_K1",
                                           "segment_force_2": "F_K2"}
    drum = demo["drums"]["D34"]
    text = text.replace('# catalog = "..."', 'catalog = "34x126"').replace(
        "# [drums.drum1]", "[drums.drum1]").replace('# fitted = "..."',
                                                    f'fitted = "{drum["fitted"]}"')
    for key in ("groove_width_mm", "contact_distance_mm", "flank_inclination_deg"):
        text = text.replace(f"# {key} = ...", f"{key} = {drum[key]}")
    validates(tmp_path / "segments", text.replace('# drum = "drum1"', 'drum = "drum1"'), runs=5)


def test_ids_and_order():
    assert safe_name("TST 2021/10 (FA) #22", "run") == "TST_2021_10_FA_22"
    assert safe_name("...", "run") == "run"
    taken: set[str] = set()
    assert [unique_name(name, taken) for name in ("a", "a", "a")] == ["a", "a-2", "a-3"]
    assert sorted(["s10.csv", "s9.csv", "S1.csv"], key=natural_key) == [
        "S1.csv", "s9.csv", "s10.csv"]


def test_tdms_time_from_the_waveform_is_left_to_auto_detection(tmp_path):
    demo = Path(__file__).resolve().parents[2] / "raw" / "engagement-demo" / "E6-20-10.tdms"
    if not demo.is_file():
        pytest.skip("the engagement demo campaign is absent")
    shutil.copy2(demo, tmp_path / demo.name)
    text = init("--print", str(tmp_path)).stdout
    run = tomllib.loads(text)["runs"][0]
    assert (run["kind"], "columns" in run) == ("engagement", False)
    assert "# columns and units left to auto-detection: naming them failed" in text


def test_equal_safe_ids_are_made_unique(tmp_path):
    (tmp_path / "a b.csv").write_text(PLAIN)
    (tmp_path / "a_b.csv").write_text(PLAIN)
    assert init(str(tmp_path)).exit_code == 0
    sheet = load_run_sheet(tmp_path)
    assert [(run.file, run.id) for run in sheet.runs] == [("a b.csv", "a_b"),
                                                          ("a_b.csv", "a_b-2")]


def test_link_leading_out_is_skipped(tmp_path):
    outside = tmp_path / "outside.csv"
    outside.write_text(PLAIN)
    campaign = tmp_path / "campaign"
    campaign.mkdir()
    (campaign / "t.csv").write_text(PLAIN)
    try:
        (campaign / "link.csv").symlink_to(outside)
    except OSError:
        pytest.skip("this system cannot make symbolic links")
    document = json.loads(init("--json", str(campaign)).stdout)
    assert [run["file"] for run in document["runs"]] == ["t.csv"]
    assert document["skipped"] == [
        {"file": "link.csv", "reason": "a link leading out of the campaign folder"}]


# a Shimadzu Trapezium batch: a label over each specimen's columns (E0 of 20 and 24 MN
# over 50 mm: about 18x64's)
BATCH = ('"CuivreC1",,,"AcierC70",,\n"Temps","Force","Stroke","Temps","Force","Stroke"\n'
         '"sec","kN","mm","sec","kN","mm"\n'
         + "".join(f'"{0.1 * i:.1f}","{4.0 * i:.1f}","{0.01 * i:.2f}",'
                   f'"{0.1 * i:.1f}","{4.8 * i:.1f}","{0.01 * i:.2f}"\n' for i in range(30)))


# an Instron Merlin sample: two specimens one below the other (about 18x64's E0 over 50 mm)
MERLIN = ("BeginSample\n\tTestSpeed, 12.50,  \"mm/min\"\n" + "".join(
    f'\tBeginSpecimen\n\t\tSpecimanName, "{name}",  ""\n\t\tBeginData\n'
    '\t\t\t_Load, _Time, SlackExt\n\t\t\t"N", "s", "mm"\n'
    + "".join(f"\t\t\t{slope * i:.1f}, {0.1 * i:.1f}, {0.01 * i:.2f}\n" for i in range(30))
    + "\t\tEndData\n\tEndSpecimen\n" for name, slope in (("311-6", 4000.0), ("311-9", 4800.0)))
    + "EndSample\n")


@pytest.mark.parametrize(("name", "content", "drafted"), [
    ("batch.csv", BATCH, [("batch-CuivreC1", "CuivreC1"), ("batch-AcierC70", "AcierC70")]),
    ("sample.txt", MERLIN, [("sample-311-6", "311-6"), ("sample-311-9", "311-9")]),
], ids=["side by side", "one below the other"])
def test_specimens_of_one_file_are_drafted_one_run_each_that_validates(tmp_path, name,
                                                                       content, drafted):
    (tmp_path / name).write_text(content)
    result = init(str(tmp_path))
    assert result.exit_code == 0, result.output
    text = (tmp_path / "campaign.toml").read_text(encoding="utf-8")
    draft = tomllib.loads(text)
    assert [(run["id"], run["specimen_in_file"], run["specimen"]) for run in draft["runs"]] == [
        (run, specimen, specimen) for run, specimen in drafted]
    text = text.replace("# gauge_length_mm = ...  # TODO: the length the gauges measure over",
                        "gauge_length_mm = 50")
    text = text.replace('# catalog = "..."', 'catalog = "18x64"')
    validates(tmp_path, text, runs=2)


def test_roller_logs_drafted_as_engagement_runs_validate_as_roller_runs_the_draft_names(
        tmp_path):
    """A roller chain's engagement log looks like a chain wheel's: drafted as engagement
    runs, turned into roller-engagement runs as the draft's comments say, and given the
    demo sheet's sprockets and values, they validate."""
    text, demo = drafted_copy("roller-demo", "R*", tmp_path / "roller")
    draft = tomllib.loads(text)
    assert [run["kind"] for run in draft["runs"]] == ["engagement"] * 6
    assert 'kind = "roller-engagement", with sprocket = "..." in place of the wheel' in text
    assert "[sprockets.<key>] with teeth, module_mm, profile_angle_deg" in text
    given = {run["id"]: run for run in demo["runs"]}
    entries = text.split("[[runs]]\n")
    for index, run in enumerate(draft["runs"], start=1):
        values = given[run["id"]]
        speed = (f"rpm = {values['rpm']}" if "rpm" in values
                 else f"omega_per_s = {values['omega_per_s']}")
        entries[index] = (entries[index].replace('kind = "engagement"',
                                                 'kind = "roller-engagement"')
                          .replace('# wheel = "wheel1"',
                                   f'sprocket = "{values["sprocket"]}"')
                          .replace("# branch_length_m = ...",
                                   f"branch_length_m = {values['branch_length_m']}")
                          .replace("# rpm = ...", speed)
                          .replace("# E0_N = ...", f"E0_N = {values['E0_N']}"))
    sprockets = "".join(
        f"\n[sprockets.{key}]\n" + "".join(f"{name} = {json.dumps(value)}\n"
                                            for name, value in sprocket.items())
        for key, sprocket in demo["sprockets"].items())
    validates(tmp_path / "roller", "[[runs]]\n".join(entries).replace(
        '# catalog = "..."', 'catalog = "16B"').replace("\n[[runs]]", sprockets + "\n[[runs]]",
                                                        1), runs=6)


def test_a_strain_worked_out_from_a_length_column_shows_the_length_it_divides_by(tmp_path):
    # a real Portuguese Bluehill export: 'Deformação à tracção' is 'Extensão' over the
    # 190 mm its method was given, the gauge length the lab fills in
    rows = [(i / 10, load / 100 + i * 3e-4, load * 10) for i, load in enumerate(LOAD)]
    text = "Tempo;Extensão;Carga;Deformação à tracção\n(sec);(mm);(N);(mm/mm)\n" + "".join(
        f"{time:.1f};{extension:.4f};{force};{extension / 190:.7f}\n".replace(".", ",")
        for time, extension, force in rows)
    (tmp_path / "pt.csv").write_text(text, encoding="utf-8")
    result = init("--print", str(tmp_path))
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert ('# gauge channels: "Extensão" gauge (length); "Deformação à tracção" gauge (strain '
            'worked out from "Extensão")') in lines
    assert lines[lines.index("# gauge_length_mm = ...  # TODO: the length the gauges measure "
                             "over") + 1] == (
        '# the file\'s "Deformação à tracção" is "Extensão" over 190 mm: 190 mm is the gauge '
        "length its software used")


def test_a_length_column_repeating_the_crosshead_is_drafted_as_the_crosshead(tmp_path):
    # MTS TestSuite's 'Extension' repeats 'Crosshead' when no extensometer is fitted: the
    # draft says so, and that chainbench takes the crosshead
    rows = [(i / 10, load / 100 + i * 3e-4, load * 1000) for i, load in enumerate(LOAD)]
    (tmp_path / "testsuite.txt").write_text(
        "Time\tLoad\tCrosshead\tExtension\nsec\tN\tmm\tmm\n" + "".join(
            f"{time:.2f}\t{force}\t{travel:.6f}\t{travel:.6f}\n"
            for time, travel, force in rows))
    result = init("--print", str(tmp_path))
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert ('# gauge channels: "Crosshead" crosshead (length); "Extension" crosshead (repeats '
            '"Crosshead")') in lines
    assert ('# chainbench prefers "Crosshead" (crosshead; extensometer over plain gauge over '
            'crosshead)') in lines


def test_the_parts_a_test_goes_on_in_are_skipped_as_such(tmp_path):
    # MTS TestSuite writes a long test in parts, the time running on: one run, for the
    # first part, which reads the others; they are no runs of their own
    header = "Crosshead \tLoad \tTime \nmm\tN\tsec\n"
    for number, start in (("", 0), ("1", 60), ("2", 120)):
        (tmp_path / f"DAQ - (Timed){number}.txt").write_text(header + "".join(
            f"{load / 100:.4f}\t{load * 100}\t{start + i / 10:.1f}\n"
            for i, load in enumerate(LOAD)))
    result = init("--json", str(tmp_path))
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert [run["file"] for run in document["runs"]] == ["DAQ - (Timed).txt"]
    assert sorted(item["file"] for item in document["skipped"]) == [
        "DAQ - (Timed)1.txt", "DAQ - (Timed)2.txt"]
    assert all(item["reason"].startswith("the rest of the test of DAQ - (Timed).txt")
               for item in document["skipped"])
    text = (tmp_path / "campaign.toml").read_text(encoding="utf-8")
    assert ("# reader: read with the parts the test goes on in, 'DAQ - (Timed)1.txt', "
            "'DAQ - (Timed)2.txt'") in text
    assert "# detected: layout machine_export, encoding utf-8, delimiter tab, decimal " \
        '".", 180 rows' in text
