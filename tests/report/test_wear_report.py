"""The wear section of the report: the wear demo's measured results against Paper 004."""

from __future__ import annotations

import re

import pytest

from pipeline.report.design_figures import design_checks
from pipeline.store.netcdf import read_dataset


@pytest.fixture(scope="module")
def wear_demo(processed_demos):
    return processed_demos / "wear-demo"


def test_campaign_page_shows_the_wear_runs_as_results(wear_demo):
    text = (wear_demo / "report.html").read_text(encoding="utf-8")
    summary = read_dataset(wear_demo / "summary.nc")
    section = text[text.index('<section id="wear">'):text.index('<section id="design">')]
    assert "No wear runs" not in section and "Reference case" not in section
    # one overview figure in the section; the runs' figures are on their pages
    assert section.count("<svg") == 1
    assert text.count("<svg") == 1 + len(design_checks(summary))
    for run in summary["wear_run"].values:
        assert f"<td rowspan=\"2\">{run}</td>" in section or f"<td rowspan=\"1\">{run}</td>" \
            in section
    # the life table shows each run's wear rate as the summary holds it, in um/h
    rate = float(summary["wear_rate"].sel(wear_run="W16-A")) * 3600 * 1e6
    assert f"{rate:.3f} µm/h" in section
    # the pin criterion: the pinned pin of W16-A fails eq. (1)
    rows = re.findall(r"<tr><td>c16B</td><td>(W16-[A-D])</td>.*?class=\"(pass|fail)\">", section,
                      re.S)
    assert dict(rows)["W16-A"] == "fail" and dict(rows)["W16-B"] == "pass"


def test_checks_name_the_wear_verdicts(wear_demo):
    text = (wear_demo / "report.html").read_text(encoding="utf-8")
    assert "run W16-A: pin criterion d ≥ d_k + Δd (Paper 004, eq. (1))" in text
    assert "run W16-B: the lab&#39;s limit below the jump-off growth of eq. (3)" in text


def test_wear_run_page_has_its_figure_limits_and_pin(wear_demo):
    page = (wear_demo / "report-runs" / "W16-C.html").read_text(encoding="utf-8")
    assert page.count("<svg") == 1
    assert "·10⁶ cycles" in page  # a log over cycles counts its life in cycles
    assert "jump-off, eq. (3)" in page and "lab&#39;s limit" in page
    assert "Pin criterion of Paper 004" in page


def test_a_campaign_without_wear_runs_says_so(processed_demos):
    text = (processed_demos / "stiffness-demo" / "report.html").read_text(encoding="utf-8")
    section = text[text.index('<section id="wear">'):text.index('<section id="design">')]
    assert "No wear runs in this campaign." in section and "<svg" not in section
