"""The impact figures of the report: built from small datasets made here.

The expected model values are typed from docs/published-values.md (paper 000's
grid) or computed with the closed forms of docs/models/paper-000-wheel-impact.md,
never read back from the code under test.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pandas as pd
import pytest
import xarray as xr
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure

from pipeline.fit.impact_model import model_tensions
from pipeline.report import impact_figures as figs
from pipeline.report.render import report_style, svg
from pipeline.theory.wheel_impact import compare_published

# Paper 000's example: chain 18x64, 6.6 kg/m, E0 = 2.26e7 N, L = 2 m (SI).
T, D, Q, E0, L = 0.064, 0.018, 6.6, 2.26e7, 2.0
UNIT = re.compile(r"\[[^\]]+\]$")


def closed_form(z: float, psi_deg: float, omega: float, k: float) -> tuple[float, float]:
    """N_u1, N_u2 [N] from Paper 000's closed forms of v_u1, v_u2 and eq. (16)."""
    psi = math.radians(psi_deg)
    scale = math.sqrt(k * Q * T * E0 / L)
    return (omega * (T - D) * math.sin(psi / 2) * scale,
            omega * (T + D) * math.sin(math.pi / z + psi / 2) * scale)


def engagement_run(samples_per_second: float = 5000.0, duration: float = 0.5) -> xr.Dataset:
    """A run dataset of an 8-pocket wheel at 20 1/s: strikes of 1 kN and 3 kN on 20 kN."""
    omega, z, omega_n, zeta = 20.0, 8, 900.0, 0.03
    period = 2 * math.pi / (z * omega)
    time = np.arange(0.0, duration, 1 / samples_per_second)
    onsets = 0.01 + period * np.arange(int((duration - 0.01) / period))
    force = np.full_like(time, 20e3)
    for onset in onsets:
        for start, amplitude in ((onset, 1e3), (onset + period / 2, 3e3)):
            s = np.clip(time - start, 0, None)
            force += amplitude * np.exp(-zeta * omega_n * s) * np.sin(omega_n * s) * (s > 0)
    status = np.array(["ok"] * onsets.size, dtype=object)
    status[[0, 2]] = ["truncated", "clipped"]
    n = onsets.size
    return xr.Dataset(
        {"time": ("sample", time), "force": ("sample", force),
         "event_time": ("event", onsets), "impact2_time": ("event", onsets + period / 2),
         "baseline": ("event", 20e3 + np.arange(n)), "N_u1": ("event", 1e3 + np.arange(n)),
         "N_u2": ("event", 3e3 - np.arange(n)), "status": ("event", status.astype(str)),
         "seating_period": period, "omega_n": omega_n, "zeta": zeta, "omega_measured": omega},
        attrs={"run_id": "R1"})


def impact_summary(k_fit: float = 1.9) -> xr.Dataset:
    """A campaign summary over z in {6, 10}, psi in {20, 40} deg, omega in {10, 20} 1/s."""
    rows = [{"teeth": z, "apex_angle": math.radians(psi), "omega": omega, "t": T, "d": D,
             "mass_per_length": Q, "E0": E0, "branch_length": L}
            for z in (6, 10) for psi in (20, 40) for omega in (10, 20)]
    points = pd.DataFrame(rows, index=[f"P{i}" for i in range(len(rows))])
    theory = model_tensions(points, k=2.0)
    fit = model_tensions(points, k=k_fit) if np.isfinite(k_fit) else (np.nan * theory[0],) * 2
    data = {name: ("operating_point", points[name].to_numpy(dtype=float)) for name in points}
    data["apex_angle"] = ("operating_point", np.degrees(points["apex_angle"].to_numpy()))
    offsets = 1 + 0.01 * np.arange(len(rows))
    for number, impact in enumerate(("N_u1", "N_u2")):
        data[f"{impact}_meas"] = ("operating_point", theory[number] * offsets)
        data[f"{impact}_stderr"] = ("operating_point", 5.0 + np.arange(len(rows)))
        data[f"{impact}_iqr"] = ("operating_point", 40.0 + np.arange(len(rows)))
        data[f"{impact}_theory"] = ("operating_point", theory[number])
        data[f"{impact}_fit"] = ("operating_point", fit[number])
    data.update(k_fit=k_fit, k_fit_stderr=0.01)
    return xr.Dataset(data, coords={"operating_point": points.index.to_numpy()},
                      attrs={"k_theory": 2.0})  # the k of the theory, as compare records it


def build(function, data) -> Figure:
    with report_style():
        return function(data)


def assert_labelled(figure: Figure) -> None:
    """Every axis label names its unit in brackets; some x and y label exists."""
    labels = [(ax.get_xlabel(), ax.get_ylabel()) for ax in figure.axes]
    assert any(x for x, _ in labels) and any(y for _, y in labels)
    for label in (text for pair in labels for text in pair if text):
        assert UNIT.search(label), label
    assert figure.legends or any(ax.get_legend() for ax in figure.axes)
    legend = (figure.legends or [ax.get_legend() for ax in figure.axes if ax.get_legend()])[0]
    assert len(legend.get_texts()) > 1


def line(ax, label: str):
    (found,) = [item for item in ax.get_lines() if item.get_label() == label]
    return found


def errorbar(ax, label: str):
    (found,) = [item for item in ax.containers if item.get_label() == label]
    data = found.lines[0]
    (bars,) = found.lines[2]
    half = np.array([abs(seg[1, 1] - seg[0, 1]) / 2 for seg in bars.get_segments()])
    return data.get_xdata(), data.get_ydata(), half


def panel(figure: Figure, title: str):
    (found,) = [ax for ax in figure.axes if ax.get_title().splitlines()[0] == title]
    return found


# --- impact_zoom -----------------------------------------------------------------


def test_zoom_is_labelled_and_titled():
    figure = build(figs.impact_zoom, engagement_run())
    assert isinstance(figure, Figure)
    assert_labelled(figure)
    (ax,) = figure.axes
    assert "R1" in ax.get_title() and "[kN]" in ax.get_ylabel() and "[ms]" in ax.get_xlabel()
    assert svg(figure).startswith("<svg")


def test_zoom_plots_the_logged_signal_from_just_before_the_first_valid_impact():
    run = engagement_run()
    figure = build(figs.impact_zoom, run)
    signal = line(figure.axes[0], "branch tension (measured)")
    period = float(run["seating_period"])
    start = float(run["event_time"][1]) - figs.ZOOM_LEAD * period  # event 0 is truncated
    shown = (run["time"] >= start) & (run["time"] <= start + figs.ZOOM_PERIODS * period)
    np.testing.assert_allclose(signal.get_xdata(), (run["time"][shown] - start) * 1e3)
    np.testing.assert_allclose(signal.get_ydata(), run["force"][shown] / 1e3)


def test_zoom_marks_onsets_baselines_and_amplitudes_of_valid_events():
    run = engagement_run()
    ax = build(figs.impact_zoom, run).axes[0]
    period = float(run["seating_period"])
    start = float(run["event_time"][1]) - figs.ZOOM_LEAD * period
    end = start + figs.ZOOM_PERIODS * period
    events = run[["event_time", "impact2_time", "baseline", "N_u1", "N_u2", "status"]]
    events = events.to_dataframe()
    inside = events[events["event_time"].between(start, end)]
    valid = inside[inside["status"] == "ok"]
    assert list(inside["status"]) == ["ok", "clipped", "ok"]

    onsets = sorted(item.get_xdata()[0] for item in ax.get_lines()
                    if item.get_linestyle() == "--")
    np.testing.assert_allclose(onsets, (valid["event_time"] - start) * 1e3)
    collections = {item.get_label(): item for item in ax.collections}
    for impact in ("N_u1", "N_u2"):
        arrows = collections[f"{impact}: strike amplitude above the baseline"]
        bottoms = [segment[0, 1] for segment in arrows.get_segments()]
        tops = [segment[1, 1] for segment in arrows.get_segments()]
        np.testing.assert_allclose(bottoms, valid["baseline"] / 1e3)
        np.testing.assert_allclose(tops, (valid["baseline"] + valid[impact]) / 1e3)
    excluded = [item for item in ax.get_lines() if item.get_label() == "excluded event"]
    assert len(excluded) == 1
    np.testing.assert_allclose(excluded[0].get_xdata()[0],
                               (inside["event_time"].iloc[1] - start) * 1e3)
    assert isinstance(collections["baseline (slow tension)"], LineCollection)


def test_zoom_of_a_long_window_is_an_envelope_keeping_the_peaks():
    run = engagement_run(samples_per_second=400_000.0, duration=0.2)
    figure = build(figs.impact_zoom, run)
    y = line(figure.axes[0], "branch tension (measured)").get_ydata()
    period = float(run["seating_period"])
    start = float(run["event_time"][1]) - figs.ZOOM_LEAD * period
    shown = (run["time"] >= start) & (run["time"] <= start + figs.ZOOM_PERIODS * period)
    assert int(shown.sum()) > 10 * figs.MAX_LINE_POINTS
    assert y.size <= figs.MAX_LINE_POINTS
    assert y.max() == pytest.approx(float(run["force"][shown].max()) / 1e3)
    assert y.min() == pytest.approx(float(run["force"][shown].min()) / 1e3)


# --- impact_vs_omega --------------------------------------------------------------


def test_omega_figure_has_one_labelled_panel_per_wheel():
    figure = build(figs.impact_vs_omega, impact_summary())
    assert_labelled(figure)
    titles = sorted(ax.get_title() for ax in figure.axes)
    assert titles == ["z = 10, ψ = 20°", "z = 10, ψ = 40°", "z = 6, ψ = 20°", "z = 6, ψ = 40°"]
    assert "18x64" in figure.get_suptitle()


@pytest.mark.parametrize(("z", "psi"), [(6, 20), (10, 40)])
def test_omega_figure_plots_the_measured_medians_with_their_standard_errors(z, psi):
    summary = impact_summary()
    ax = panel(build(figs.impact_vs_omega, summary), f"z = {z}, ψ = {psi}°")
    wheel = summary.where((summary["teeth"] == z) & (summary["apex_angle"] == psi), drop=True)
    for impact in ("N_u1", "N_u2"):
        x, y, half = errorbar(ax, f"{impact} measured: median ± standard error")
        np.testing.assert_allclose(x, wheel["omega"])
        np.testing.assert_allclose(y, wheel[f"{impact}_meas"])
        np.testing.assert_allclose(half, wheel[f"{impact}_stderr"])


def test_omega_figure_lines_are_the_model_with_k_2_and_the_fitted_k():
    summary = impact_summary(k_fit=1.9)
    ax = panel(build(figs.impact_vs_omega, summary), "z = 6, ψ = 40°")
    for number, impact in enumerate(("N_u1", "N_u2")):
        ryabov = line(ax, f"{impact} model, k = 2 (Ryabov)")
        fitted = line(ax, f"{impact} model, fitted k = 1.900 ± 0.010")
        assert ryabov.get_xdata().size <= figs.MAX_LINE_POINTS
        assert ryabov.get_xdata()[-1] >= 20
        for omega in (10.0, 15.0, 20.0):
            expected = closed_form(6, 40, omega, 2.0)[number]
            assert np.interp(omega, ryabov.get_xdata(), ryabov.get_ydata()) == pytest.approx(
                expected, rel=1e-6)
            assert np.interp(omega, fitted.get_xdata(), fitted.get_ydata()) == pytest.approx(
                expected * math.sqrt(1.9 / 2), rel=1e-6)


def test_omega_figure_without_a_fit_draws_only_the_k_2_lines():
    ax = build(figs.impact_vs_omega, impact_summary(k_fit=math.nan)).axes[0]
    labels = [item.get_label() for item in ax.get_lines()]
    assert "N_u1 model, k = 2 (Ryabov)" in labels
    assert not any("fitted" in label for label in labels)


def test_a_summary_without_the_chain_geometry_is_refused_by_name():
    with pytest.raises(KeyError, match="mass_per_length"):
        build(figs.impact_vs_omega, impact_summary().drop_vars("mass_per_length"))


# --- impact_vs_apex ---------------------------------------------------------------


def test_apex_figure_has_one_labelled_panel_per_omega():
    figure = build(figs.impact_vs_apex, impact_summary())
    assert_labelled(figure)
    assert sorted(ax.get_title() for ax in figure.axes) == ["ω = 10 1/s", "ω = 20 1/s"]
    assert "[°]" in figure.axes[0].get_xlabel()


def test_apex_figure_curves_are_paper_000_figs_3_and_4():
    ax = panel(build(figs.impact_vs_apex, impact_summary()), "ω = 20 1/s")
    n_u1 = line(ax, "N_u1 model, any z (k = 2)")
    psi = n_u1.get_xdata()
    assert psi[0] <= 20 and psi[-1] >= 60
    # docs/published-values.md, paper 000's grid at omega = 20 1/s [N]
    for psi_deg, expected in ((20, 494), (40, 972), (60, 1421)):
        assert np.interp(psi_deg, psi, n_u1.get_ydata()) == pytest.approx(expected, abs=1)
    for z, grid in ((6, (3257, 3882, 4388)), (10, (2379, 3120, 3766))):
        curve = line(ax, f"N_u2 model, z = {z} (k = 2)")
        for psi_deg, expected in zip((20, 40, 60), grid, strict=True):
            assert np.interp(psi_deg, curve.get_xdata(), curve.get_ydata()) == pytest.approx(
                expected, abs=1)


def test_apex_figure_overlays_the_measured_points_of_its_omega():
    summary = impact_summary()
    ax = panel(build(figs.impact_vs_apex, summary), "ω = 10 1/s")
    for z in (6, 10):
        chosen = summary.where((summary["omega"] == 10) & (summary["teeth"] == z), drop=True)
        for impact in ("N_u1", "N_u2"):
            x, y, half = errorbar(ax, f"{impact} measured, z = {z}")
            np.testing.assert_allclose(x, chosen["apex_angle"])
            np.testing.assert_allclose(y, chosen[f"{impact}_meas"])
            np.testing.assert_allclose(half, chosen[f"{impact}_stderr"])


def test_apex_figure_marks_the_published_smallest_N_u2_only_at_the_papers_conditions():
    figure = build(figs.impact_vs_apex, impact_summary())
    published = compare_published().set_index("quantity").at["N_u2_smallest", "published"]
    label = f"Paper 000 published: smallest N_u2 = {published:g} N (z = 10, ψ = 20°)"
    marked = line(panel(figure, "ω = 20 1/s"), label)
    assert (marked.get_xdata()[0], marked.get_ydata()[0]) == (20.0, published)
    assert label not in [item.get_label() for item in panel(figure, "ω = 10 1/s").get_lines()]
