"""The campaign report: sections, figures, run pages, escaping, provenance, determinism, CLI."""

from __future__ import annotations

import hashlib
import html
import json
import re
import shutil
from datetime import UTC, datetime
from pathlib import Path

import pytest
from typer.testing import CliRunner

from pipeline.campaign import process_campaign
from pipeline.cli import app
from pipeline.errors import ChainbenchError
from pipeline.report.build import build_report
from pipeline.report.design_figures import design_checks, published_not_reproduced
from pipeline.report.run_pages import page_href
from pipeline.store.netcdf import read_dataset, write_atomic
from pipeline.theory.link_stiffness import table_1
from pipeline.units import to_si

ROOT = Path(__file__).parents[2]
SCRIPT = "<script>alert(1)</script>"
CREATED = datetime(2024, 5, 6, 7, 8, 9, tzinfo=UTC)
SECTIONS = ("summary", "runs", "stiffness", "impact", "wear", "design", "not-reproduced",
            "provenance")
#: Figures on a run's page, by kind: force-strain and residuals; the log with its impacts.
RUN_FIGURES = {"tensile": 2, "engagement": 1}

#: Two of Table 1's chains, two specimens each, and a run whose file is empty.
TENSILE_RUNS = ("T13-A", "T13-B", "T18-A", "T18-B")
#: One wheel at three speeds and a second wheel: enough to fit k and check linearity.
ENGAGEMENT_RUNS = ("E8-40-10", "E8-40-20", "E8-40-30", "E10-20-20")
BROKEN_RUN = """
[[runs]]
id = "T18-empty"
kind = "tensile"
file = "empty.csv"
chain = "c18x64"
specimen = "18x64-E"
gauge_length_mm = 900
"""

runner = CliRunner()


def _subset(demo: str, target: Path, runs: tuple[str, ...]) -> Path:
    """A copy of a demo campaign with only `runs` (header tables kept; files copied)."""
    source = ROOT / "raw" / demo
    if not source.is_dir():
        pytest.skip(f"demo campaign {source} is absent")
    header, *blocks = (source / "campaign.toml").read_text().split("\n[[runs]]\n")
    kept = [block for block in blocks if re.search(r'^id = "([^"]+)"', block, re.M)[1] in runs]
    target.mkdir(parents=True)
    for block in kept:
        name = re.search(r'^file = "([^"]+)"', block, re.M)[1]
        shutil.copy(source / name, target / name)
    (target / "campaign.toml").write_text("\n[[runs]]\n".join([header, *kept]))
    return target


@pytest.fixture(scope="module")
def lab(tmp_path_factory) -> Path:
    """``raw/`` with a small tensile and a small engagement campaign, processed."""
    root = tmp_path_factory.mktemp("lab")
    tensile = _subset("stiffness-demo", root / "raw" / "mini-stiffness", TENSILE_RUNS)
    sheet = tensile / "campaign.toml"
    text = sheet.read_text().replace('id = "stiffness-demo"', 'id = "mini-stiffness"')
    text = text.replace('specimen = "13x50-A"', f'specimen = "{SCRIPT}"')
    sheet.write_text(text + BROKEN_RUN)
    (tensile / "empty.csv").write_text("")
    engagement = _subset("engagement-demo", root / "raw" / "mini-engagement", ENGAGEMENT_RUNS)
    sheet = engagement / "campaign.toml"
    sheet.write_text(sheet.read_text().replace('id = "engagement-demo"', 'id = "mini-engagement"'))
    for folder in (tensile, engagement):
        result = process_campaign(folder, root / "processed" / folder.name)
        assert result.report == root / "processed" / folder.name / "report.html"
        assert result.report_error is None
    return root


def _report(lab: Path, campaign: str) -> str:
    return (lab / "processed" / campaign / "report.html").read_text(encoding="utf-8")


def _run_pages(folder: Path) -> dict[str, str]:
    """Run id -> the text of its page, for every page in ``report-runs/``."""
    return {path.stem: path.read_text(encoding="utf-8")
            for path in sorted((folder / "report-runs").glob("*.html"))}


def _links(text: str) -> list[str]:
    """The targets of a page's links (not the SVG's references to its own ids)."""
    return re.findall(r'<a href="([^"]*)"', text)


def _svgs(text: str) -> list[str]:
    return re.findall(r"<svg.*?</svg>", text, re.S)


@pytest.mark.parametrize("campaign", ["mini-stiffness", "mini-engagement"])
def test_sections_and_figures(lab, campaign):
    text = _report(lab, campaign)
    for section in SECTIONS:
        assert f'<section id="{section}">' in text
    summary = read_dataset(lab / "processed" / campaign / "summary.nc")
    expected = len(design_checks(summary))
    if campaign == "mini-stiffness":
        expected += 1  # the overview; the runs' figures are on their pages
    else:
        expected += 2  # N_u against omega, N_u against apex angle
    assert text.count("<svg") == expected
    assert "<script" not in text.lower()
    assert "SYNTHETIC DATA" in text  # the demos are synthetic
    runs = TENSILE_RUNS if campaign == "mini-stiffness" else ENGAGEMENT_RUNS
    kind = "tensile" if campaign == "mini-stiffness" else "engagement"
    pages = _run_pages(lab / "processed" / campaign)
    assert sorted(pages) == sorted(runs)
    for page in pages.values():
        assert page.count("<svg") == RUN_FIGURES[kind]
        assert "SYNTHETIC DATA" in page


@pytest.mark.parametrize("campaign", ["mini-stiffness", "mini-engagement"])
def test_campaign_page_links_every_run_page_and_holds_no_run_figure(lab, campaign):
    folder = lab / "processed" / campaign
    text = _report(lab, campaign)
    runs = TENSILE_RUNS if campaign == "mini-stiffness" else ENGAGEMENT_RUNS
    linked = [link for link in _links(text) if link.startswith("report-runs/")]
    assert sorted(linked) == sorted(f"report-runs/{run}.html" for run in runs)
    assert all((folder / link).is_file() for link in linked)
    for page in _run_pages(folder).values():
        for figure in _svgs(page):
            assert figure not in text
    if campaign == "mini-stiffness":  # the failed run has a row, and no page
        assert re.search(r'<tr id="run-T18-empty"><td>T18-empty</td>', text)
        assert not (folder / "report-runs" / "T18-empty.html").exists()


@pytest.mark.parametrize("campaign", ["mini-stiffness", "mini-engagement"])
def test_run_pages_are_self_contained_and_link_back(lab, campaign):
    folder = lab / "processed" / campaign
    text = _report(lab, campaign)
    pages = _run_pages(folder)
    order = sorted(pages, key=lambda run: [int(part) if part.isdigit() else part
                                           for part in re.split(r"(\d+)", run)])
    for index, (run, page) in enumerate((run, pages[run]) for run in order):
        lowered = page.lower()
        assert "<script" not in lowered and "<link" not in lowered and "<img" not in lowered
        assert 'src="http' not in lowered and 'href="http' not in lowered
        assert not re.search(r"url\((?!#)", lowered)  # SVG refers to its own ids alone
        links = _links(page)
        assert f"../report.html#run-{run}" in links
        assert f'<tr id="run-{run}">' in text  # the anchor the link goes back to
        neighbours = [order[i] for i in (index - 1, index + 1) if 0 <= i < len(order)]
        assert [link for link in links if not link.startswith("../")] == [
            f"{neighbour}.html" for neighbour in neighbours]
        assert hashlib.sha256(next((lab / "raw" / campaign).glob(f"{run}.*")).read_bytes()
                              ).hexdigest() in page


def test_run_page_links_quote_the_run_id():
    assert page_href("T13-A") == "report-runs/T13-A.html"
    assert page_href("a#b?c d") == "report-runs/a%23b%3Fc%20d.html"


def test_input_strings_are_escaped(lab):
    text = _report(lab, "mini-stiffness")
    assert html.escape(SCRIPT, quote=False) in text
    assert SCRIPT not in text
    page = _run_pages(lab / "processed" / "mini-stiffness")["T13-A"]
    assert html.escape(SCRIPT, quote=False) in page
    assert SCRIPT not in page
    # the failed run and its error are listed
    assert "run T18-empty" in text
    assert "empty.csv" in text


def test_table_1_published_values_beside_the_paper_chains(lab):
    text = _report(lab, "mini-stiffness")
    for chain in ("13x50", "18x64"):
        row = table_1()[chain]
        for kgf in (row.E0_exp_kgf, row.E0_theor_kgf):
            kilonewtons = f"{to_si(kgf, 'kgf') / 1e3:,.0f}".replace(",", "\u2009")
            assert kilonewtons in text
            assert f"{kgf / 1e6:.3g}·10⁶ kgf" in text
    assert "out of band" in text  # 13x50 and 18x64 lie above the band in the demo


def test_values_not_reproduced_are_listed(lab):
    text = _report(lab, "mini-stiffness")
    section = text[text.index('<section id="not-reproduced">'):
                   text.index('<section id="provenance">')]
    rows = published_not_reproduced()
    assert rows
    for row in rows:
        assert html.escape(row["quantity"], quote=False) in section
    ratio = next(row for row in rows if row["quantity"] == "N_u2_over_N_u1_z8_psi40")
    assert f"{ratio['published']:g}" in section and "3.521" in section  # published and model


@pytest.mark.parametrize("campaign", ["mini-stiffness", "mini-engagement"])
def test_provenance_lists_raw_hashes(lab, campaign):
    text = _report(lab, campaign)
    raw = lab / "raw" / campaign
    runs = TENSILE_RUNS if campaign == "mini-stiffness" else ENGAGEMENT_RUNS
    for run in runs:
        (data,) = [path for path in raw.iterdir() if path.stem == run]
        assert hashlib.sha256(data.read_bytes()).hexdigest() in text
    assert hashlib.sha256((raw / "campaign.toml").read_bytes()).hexdigest() in text


def test_same_inputs_same_bytes(lab, tmp_path):
    output = shutil.copytree(lab / "processed" / "mini-stiffness", tmp_path / "mini-stiffness")
    built_now = (output / "report.html").read_bytes()  # by process_campaign, created now
    first = build_report(output, created=CREATED).page.read_bytes()
    pages = _run_pages(output)
    second = build_report(output, created=CREATED).page.read_bytes()
    assert first == second
    assert _run_pages(output) == pages
    changed = [pair for pair in zip(first.splitlines(), built_now.splitlines(), strict=True)
               if pair[0] != pair[1]]
    assert len(changed) == 1 and b"2024-05-06T07:08:09Z" in changed[0][0]


def test_the_report_shows_the_settings_the_files_record(lab, tmp_path):
    # The report formats what the processed files say; it recomputes nothing: change the
    # recorded settings and the report follows them.
    output = shutil.copytree(lab / "processed" / "mini-stiffness", tmp_path / "stiffness")
    run = read_dataset(output / "T13-B.nc")
    write_atomic(run.assign_attrs(fit_window="fixed force window 1 to 2 kN for every branch"),
                 output / "T13-B.nc")
    summary = read_dataset(output / "summary.nc")
    summary["E0_exp_ci_low"].attrs["confidence_level"] = 0.9
    write_atomic(summary.assign_attrs(plausibility_strain_limit=0.4), output / "summary.nc")
    text = build_report(output, created=CREATED).page.read_text(encoding="utf-8")
    assert "fixed force window 1 to 2 kN for every branch (runs T13-B)" in text
    assert "automatic per branch" in text  # the other runs' rule
    assert "with its 90 % interval (blue band)" in text
    assert "strains at most 0.4" in text

    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "engagement")
    summary = read_dataset(output / "summary.nc")
    write_atomic(summary.assign_attrs(linearity="Straight as recorded.", k_fit_method="By hand."),
                 output / "summary.nc")
    text = build_report(output, created=CREATED).page.read_text(encoding="utf-8")
    assert "<p>Straight as recorded.</p>" in text and "<td>By hand.</td>" in text
    run = read_dataset(output / "E8-40-10.nc")
    assert f"up to {run.attrs['ringing_events_max']} events" in text


def test_files_that_do_not_record_a_setting_are_refused(lab, tmp_path):
    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "old")
    summary = read_dataset(output / "summary.nc")
    del summary.attrs["k_theory"]
    write_atomic(summary, output / "summary.nc")
    with pytest.raises(ChainbenchError, match="do not record 'k_theory'"):
        build_report(output, created=CREATED)


def test_cli_report_from_processed_alone(lab, tmp_path):
    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "elsewhere")
    (output / "report.html").unlink()
    shutil.rmtree(output / "report-runs")
    result = runner.invoke(app, ["report", str(output)])
    assert result.exit_code == 0, result.output
    assert result.stdout.strip() == str(output / "report.html")
    assert "<svg" in (output / "report.html").read_text(encoding="utf-8")
    assert sorted(_run_pages(output)) == sorted(ENGAGEMENT_RUNS)


def test_cli_report_maps_raw_to_processed(lab, monkeypatch):
    monkeypatch.chdir(lab)
    result = runner.invoke(app, ["report", "raw/mini-engagement"])
    assert result.exit_code == 0, result.output
    assert Path(result.stdout.strip()) == lab / "processed" / "mini-engagement" / "report.html"
    missing = runner.invoke(app, ["report", "raw/no-such-campaign"])
    assert missing.exit_code == 1
    assert "no processed results for raw/no-such-campaign" in " ".join(missing.output.split())


def test_failed_report_keeps_the_results(lab, tmp_path, monkeypatch):
    def broken(output_dir, created=None, client=None, run_attrs=None):
        raise RuntimeError("no figures today")

    monkeypatch.setattr("pipeline.campaign.build_report", broken)
    raw = lab / "raw" / "mini-engagement"
    result = process_campaign(raw, tmp_path / "out")
    assert result.report is None and "no figures today" in result.report_error
    assert not result.ok
    assert (tmp_path / "out" / "summary.nc").is_file()
    assert (tmp_path / "out" / "impact_summary.csv").is_file()
    assert not (tmp_path / "out" / "report.html").exists()


def test_a_failed_rebuild_removes_the_old_report_and_its_pages(lab, tmp_path, monkeypatch):
    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "out")
    (output / ".outputs.json").unlink()  # the outputs are rebuilt

    def broken(output_dir, created=None, client=None, run_attrs=None):
        raise RuntimeError("no figures today")

    monkeypatch.setattr("pipeline.campaign.build_report", broken)
    result = process_campaign(lab / "raw" / "mini-engagement", output)
    assert "no figures today" in result.report_error
    assert not (output / "report.html").exists() and not (output / "report-runs").exists()


def _manifest(folder: Path) -> list[str]:
    return json.loads((folder / ".outputs.json").read_text(encoding="utf-8"))["outputs"]


def test_the_manifest_lists_every_page_and_a_missing_page_is_rebuilt(lab, tmp_path):
    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "out")
    pages = sorted(f"report-runs/{run}.html" for run in ENGAGEMENT_RUNS)
    assert sorted(name for name in _manifest(output) if name.startswith("report")) == sorted(
        ["report.html", *pages])
    (output / pages[0]).unlink()  # as a run killed while writing the report leaves it
    result = process_campaign(lab / "raw" / "mini-engagement", output)
    assert result.report_error is None and result.redone == []
    assert (output / pages[0]).is_file()


def test_pages_of_runs_no_longer_in_the_campaign_are_removed(lab, tmp_path):
    raw = shutil.copytree(lab / "raw" / "mini-engagement", tmp_path / "raw" / "mini-engagement")
    output = shutil.copytree(lab / "processed" / "mini-engagement", tmp_path / "out")
    header, *blocks = (raw / "campaign.toml").read_text().split("\n[[runs]]\n")
    kept = [block for block in blocks if 'id = "E8-40-30"' not in block]
    assert len(kept) == len(blocks) - 1
    (raw / "campaign.toml").write_text("\n[[runs]]\n".join([header, *kept]))
    (output / "report-runs" / "left-by-hand.html").write_text("stale")
    (output / "report-runs" / ".E8-40-10.html.killed.tmp").write_text("half a page")
    result = process_campaign(raw, output)
    assert result.report_error is None and result.removed == ["E8-40-30"]
    remaining = sorted(set(ENGAGEMENT_RUNS) - {"E8-40-30"})
    assert sorted(path.name for path in (output / "report-runs").iterdir()) == [
        f"{run}.html" for run in remaining]
    text = (output / "report.html").read_text(encoding="utf-8")
    assert "report-runs/E8-40-30.html" not in text
    assert sorted(name for name in _manifest(output) if name.startswith("report-runs/")) == [
        f"report-runs/{run}.html" for run in remaining]


def _campaign_page_growth(tmp_path: Path, runs: tuple[str, ...]) -> tuple[int, list[int]]:
    """Size [bytes] of the campaign page of a subset of the engagement demo, and the sizes
    of the figures on its runs' pages."""
    raw = _subset("engagement-demo", tmp_path / "raw" / f"growth-{len(runs)}", runs)
    sheet = raw / "campaign.toml"
    sheet.write_text(sheet.read_text().replace('id = "engagement-demo"',
                                               f'id = "growth-{len(runs)}"'))
    result = process_campaign(raw, tmp_path / "processed" / f"growth-{len(runs)}")
    assert result.report_error is None and not result.failures
    pages = _run_pages(result.output)
    return result.report.stat().st_size, [len(figure) for page in pages.values()
                                          for figure in _svgs(page)]


def test_campaign_page_grows_by_table_rows_not_by_figures(tmp_path):
    """3 against 12 runs: each run adds its table rows to the campaign page, far less than
    the figure on its own page."""
    speeds = ("10", "20", "30")
    few = tuple(f"E8-40-{omega}" for omega in speeds)
    many = tuple(f"E{z}-{psi}-{omega}" for z in (6, 8) for psi in (20, 40) for omega in speeds)
    small, _ = _campaign_page_growth(tmp_path, few)
    large, figures = _campaign_page_growth(tmp_path, many)
    assert len(figures) == len(many)  # one figure a run, on its page
    per_run = (large - small) / (len(many) - len(few))
    assert 0 < per_run < min(figures) / 4, (per_run, min(figures))


# --- in a real browser: headless Chromium (Debian's), driven by Playwright ---------------------

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
#: Flags for a headless Chromium on a machine with no network (see the env docs).
CHROMIUM_ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--no-first-run"]
SCREENSHOTS = ROOT / "processed" / "screenshots"
#: Longest a page may take to load, and a link to be followed [ms] (Playwright's default);
#: ``bench/bench_growth.py`` opens a 1,000-run campaign page within it.
OPEN_TIMEOUT_MS = 30_000


@pytest.fixture(scope="module")
def browser():
    """A headless Chromium; the test is skipped (never installs anything) when it is absent."""
    sync_api = pytest.importorskip("playwright.sync_api")
    if CHROMIUM is None:
        pytest.skip("chromium is not installed (.ci/run installs Debian's chromium)")
    with sync_api.sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield launched
        launched.close()


def _open(browser, report: Path):
    """The report loaded in a page, with every dialog (e.g. an alert) recorded."""
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.set_default_timeout(OPEN_TIMEOUT_MS)
    page.dialogs = []
    page.on("dialog", lambda dialog: (page.dialogs.append(dialog.message), dialog.dismiss()))
    page.goto(report.as_uri(), timeout=OPEN_TIMEOUT_MS)
    return page


def _rendered_figures(page) -> list[tuple[float, float]]:
    return page.eval_on_selector_all(
        "svg", "svgs => svgs.map(s => [s.getBoundingClientRect().width,"
               " s.getBoundingClientRect().height])")


def test_every_figure_renders_in_chromium_and_first_screen_is_saved(browser, processed_demos):
    for campaign, run in (("stiffness-demo", "T13-A"), ("engagement-demo", "E8-40-10")):
        for name, report in (("report", processed_demos / campaign / "report.html"),
                             (run, processed_demos / campaign / "report-runs" / f"{run}.html")):
            page = _open(browser, report)
            sizes = _rendered_figures(page)
            assert len(sizes) == report.read_text(encoding="utf-8").count("<svg") > 0
            assert all(width > 100 and height > 100 for width, height in sizes), sizes
            assert page.dialogs == []
            SCREENSHOTS.mkdir(parents=True, exist_ok=True)
            shot = SCREENSHOTS / f"{campaign}-{name}-first-screen.png"
            page.screenshot(path=str(shot))
            assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
            page.close()


def test_run_table_links_open_in_chromium_and_lead_back(browser, processed_demos):
    report = processed_demos / "engagement-demo" / "report.html"
    page = _open(browser, report)
    page.click('#run-E8-40-10 a')
    page.wait_for_load_state()
    assert page.url == (report.parent / "report-runs" / "E8-40-10.html").as_uri()
    assert page.inner_text("h1") == "Run E8-40-10"
    page.click("text=next run: E8-40-20")
    page.wait_for_load_state()
    assert page.inner_text("h1") == "Run E8-40-20"
    page.click("text=Campaign report engagement-demo: run table")
    page.wait_for_load_state()
    assert page.url == report.as_uri() + "#run-E8-40-20"
    assert page.evaluate("document.querySelectorAll('script').length") == 0
    assert page.dialogs == []
    page.close()


def test_input_strings_stay_text_in_chromium(browser, lab):
    page = _open(browser, lab / "processed" / "mini-stiffness" / "report.html")
    assert page.evaluate("document.querySelectorAll('script').length") == 0
    assert SCRIPT in page.inner_text("body")  # shown as text, not run
    assert page.dialogs == []  # alert(1) never ran
    page.close()
