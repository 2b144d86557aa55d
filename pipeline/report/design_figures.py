"""Design checks of the report from the other papers, and the published numbers not reproduced.

Which papers a campaign gets
----------------------------
Paper 003 (segmented teeth of a chain drum) needs a round-link chain's outer
torus radius r and the drum's groove width c. A campaign with segment-load
runs has them (its ``[drums.*]`` tables and catalogue chains): its measured
ratios and the geometry fitted to them are the report's segment section
(:mod:`pipeline.report.segment_section`), a campaign result, and
:func:`design_checks` then shows no Paper 003 figure. A campaign without drum
runs gives no r and c (tensile and engagement chains carry d, t, R0, a and
the mass per metre), so the report shows Paper 003's own case instead, chain
34x126 of the catalogue (r, d, c from the paper), labelled as a reference
and not as a result of the campaign.

Papers 002 (impact of roller chains on sprockets: xi, n_max) and 004 (pin
criterion of roller chains) concern roller chains. Tensile and engagement
runs test round-link chains, so :func:`design_checks` returns no item for
them; ``chainbench theory roller-impact`` and ``chainbench theory pin``
compute them for a given chain. A campaign's wear and roller-engagement runs
test roller chains: Paper 004 is set against their measured wear and Paper
002 against their measured xi as campaign results, in the report's wear and
roller sections (:mod:`pipeline.report.wear_section`,
:mod:`pipeline.report.roller_section`), not here.

Published numbers not reproduced
--------------------------------
:func:`published_not_reproduced` lists every number a paper publishes that the
corrected model does not reproduce, the model's value beside it: the rows each
theory module's ``compare_published()`` declares not reproduced (the papers'
numbers are in ``pipeline/data/published/``; see ``docs/published-values.md``).
Some stay within the wider tolerance of their regression test (a reason such as
the paper's uncertain inputs is given); the note of each row says which.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from matplotlib.axes import Axes
from matplotlib.figure import Figure

from pipeline.catalog import chain as catalog_chain
from pipeline.theory import link_stiffness as ls
from pipeline.theory import pin_criterion as pc
from pipeline.theory import roller_impact as ri
from pipeline.theory import tooth_segments as ts
from pipeline.theory import wheel_impact as wi
from pipeline.theory._published import parse_inputs
from pipeline.units import from_si

#: Paper 003's chain, in the catalogue with its torus radius and groove width.
REFERENCE_CHAIN = "34x126"
#: Link inclinations eps_n [degree] of the curves over beta (Paper 003, Figs. 3-5
#: name eps_n = 0 and 6 deg; the steps between show the trend).
EPS_N_DEG = (0.0, 2.0, 4.0, 6.0)
#: Flank inclinations beta [degree] of the curves over s (Paper 003, Figs. 6-9
#: name beta = 50 and 80 deg).
BETA_DEG = (50.0, 60.0, 70.0, 80.0)
#: Range of the flank inclination beta [degree] of the curves over beta.
BETA_RANGE_DEG = (40.0, 90.0)
#: The claims of Paper 003 the model is set against (section 4, Figs. 8-9); the curves
#: over s run up to the largest contact distance of its analysis, ``s_max`` [m]
#: ("from s = 45 mm to s = 70 mm").
CLAIMS = ts.CLAIMS
#: Points of every curve.
GRID_POINTS = 200
#: The theory module of each paper, for its published numbers.
_PAPERS = {"000": wi, "001": ls, "002": ri, "003": ts, "004": pc}

_PUBLISHED_STYLE = {"linestyle": "none", "marker": "o", "markersize": 7,
                    "markerfacecolor": "none", "markeredgecolor": "black"}
_MISSED_STYLE = {"linestyle": "none", "marker": "X", "markersize": 8, "color": "C3"}


def _reference() -> dict[str, float]:
    """r, d, c of :data:`REFERENCE_CHAIN` [m]."""
    spec = catalog_chain(REFERENCE_CHAIN)
    return {"r": spec["r_outer"], "d": spec["d"], "c": spec["groove_width"]}


def _contact_radius(beta_deg: np.ndarray | float, eps_n_deg: float) -> np.ndarray:
    """k [m] of the reference chain (Paper 003, eq. (1))."""
    ref = _reference()
    return np.asarray(ts.contact_radius(ref["r"], ref["d"], np.radians(beta_deg),
                                        np.radians(eps_n_deg)))


def _opening_angle(s: np.ndarray | float, beta_deg: np.ndarray | float,
                   eps_n_deg: float) -> np.ndarray:
    """psi [rad] of the reference chain at contact distance `s` [m] (Paper 003, eq. (2))."""
    return np.asarray(ts.opening_angle(s, _contact_radius(beta_deg, eps_n_deg),
                                       _reference()["c"]))


def _mark_published(ax: Axes, rows: list[dict], x_key: str) -> None:
    """Paper 003's published values of `rows` at x = row[`x_key`], flagged where missed."""
    for reproduced, style, label in (
            (True, _PUBLISHED_STYLE, "Paper 003 published (reproduced)"),
            (False, _MISSED_STYLE, "Paper 003 published, not reproduced")):
        chosen = [row for row in rows if row["reproduced"] is reproduced]
        if not chosen:
            continue
        ax.plot([row[x_key] for row in chosen], [row["published"] for row in chosen],
                label=label, **style)
        for row in chosen if not reproduced else ():
            ax.annotate(f"published {row['published']:g} {row['unit']}, "
                        f"model {row['model']:.5g} {row['unit']}",
                        (row[x_key], row["published"]), xytext=(0.3, 0.1),
                        textcoords="axes fraction", fontsize=8, color="C3",
                        arrowprops={"arrowstyle": "->", "color": "C3"})


def _published(quantity: str, **where: float) -> list[dict]:
    """Paper 003's published values of `quantity`, selected by their inputs.

    The rows of :func:`pipeline.theory.tooth_segments.compare_published` whose
    quantity id begins with `quantity` (``"opening_angle"``), each with its
    inputs ``beta_deg``, ``eps_n_deg`` and ``s_mm`` (None without s); `where`
    keeps the rows whose inputs are close to the values given.
    """
    rows = []
    for row in ts.compare_published().to_dict("records"):
        inputs = parse_inputs(row["inputs"])
        row |= {"beta_deg": from_si(inputs["beta"], "deg"),
                "eps_n_deg": from_si(inputs["eps_n"], "deg"),
                "s_mm": from_si(inputs["s"], "mm") if "s" in inputs else None}
        if row["quantity"].startswith(f"{quantity}_") and all(
                row[key] is not None and math.isclose(row[key], value, abs_tol=1e-9)
                for key, value in where.items()):
            rows.append(row)
    return rows


def _reference_text(summary: xr.Dataset) -> str:
    """Caption sentence saying why the reference chain is shown, naming the campaign's chains."""
    ref = {key: value * 1e3 for key, value in _reference().items()}
    chains = (", ".join(str(name) for name in summary["chain"].values)
              if "chain" in summary.coords else "")
    return (f"Reference case of Paper 003: chain {REFERENCE_CHAIN} of the catalogue "
            f"(r = {ref['r']:g} mm, d = {ref['d']:g} mm, groove width c = {ref['c']:g} mm), "
            "not a chain of this campaign: the run sheet gives no torus radius r and groove "
            f"width c for {('its chains ' + chains) if chains else 'its chains'}. "
            "Curves: the model (Paper 003, eqs. (1)-(4)); markers: the values the paper prints.")


def _figure(columns: int, title: str) -> tuple[Figure, list[Axes]]:
    figure = Figure(figsize=(max(7.0, 4.3 * columns), 4.4), layout="constrained")
    axes = list(figure.subplots(1, columns, squeeze=False).ravel())
    figure.suptitle(f"Reference case, not a campaign result: {title}")
    return figure, axes


def _legend(figure: Figure, axes: list[Axes]) -> None:
    """One legend for the figure, each label once."""
    handles: dict[str, object] = {}
    for ax in axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            handles.setdefault(label, handle)
    figure.legend(list(handles.values()), list(handles), loc="outside lower center", ncols=3)


def _contact_radius_figure() -> Figure:
    """Paper 003, Fig. 3: contact radius k over the flank inclination beta, per eps_n.

    Returns
    -------
    matplotlib.figure.Figure
        k [mm] of chain :data:`REFERENCE_CHAIN` for beta in :data:`BETA_RANGE_DEG`
        and each eps_n of :data:`EPS_N_DEG`, with the published k.
    """
    beta = np.linspace(*BETA_RANGE_DEG, GRID_POINTS)
    figure, (ax,) = _figure(1, f"contact radius of the link torus,\nchain {REFERENCE_CHAIN} "
                               "(Paper 003, Fig. 3)")
    for eps_n in EPS_N_DEG:
        ax.plot(beta, _contact_radius(beta, eps_n) * 1e3, label=f"model, ε_n = {eps_n:g}°")
    _mark_published(ax, _published("contact_radius"), "beta_deg")
    ax.set_xlabel("flank inclination β [°]")
    ax.set_ylabel("contact radius k [mm]")
    _legend(figure, [ax])
    return figure


def _edge_contact_figure() -> Figure:
    """Paper 003, Figs. 4-5: psi and F_K/F over beta at edge contact (s = c), per eps_n.

    Returns
    -------
    matplotlib.figure.Figure
        Segment opening angle psi [°] and force ratio F_K/F [-] of chain
        :data:`REFERENCE_CHAIN` with s equal to the groove width c, against
        beta, for each eps_n of :data:`EPS_N_DEG`, with the published values at s = c.
    """
    c = _reference()["c"]
    beta = np.linspace(*BETA_RANGE_DEG, GRID_POINTS)
    figure, axes = _figure(2, f"edge contact (s = c = {c * 1e3:g} mm),\nchain {REFERENCE_CHAIN} "
                              "(Paper 003, Figs. 4-5)")
    for eps_n in EPS_N_DEG:
        psi = _opening_angle(c, beta, eps_n)
        axes[0].plot(beta, np.degrees(psi), label=f"model, ε_n = {eps_n:g}°")
        axes[1].plot(beta, ts.contact_force_ratio(psi), label=f"model, ε_n = {eps_n:g}°")
    _mark_published(axes[0], _published("opening_angle", s_mm=c * 1e3), "beta_deg")
    _mark_published(axes[1], _published("contact_force_ratio", s_mm=c * 1e3), "beta_deg")
    axes[0].set_ylabel("segment opening angle ψ [°]")
    axes[1].set_ylabel("segment force over flank force F_K/F [-]")
    for ax in axes:
        ax.set_xlabel("flank inclination β [°]")
    _legend(figure, axes)
    return figure


def _s_grid() -> np.ndarray:
    """Contact distances s from the groove width c to the claims' ``s_max`` [m]."""
    return np.linspace(_reference()["c"], CLAIMS["s_max"], GRID_POINTS)


def _contact_distance_figure() -> Figure:
    """Paper 003, Figs. 6-7: psi and F_K/F over the contact distance s, per beta (eps_n = 0).

    Returns
    -------
    matplotlib.figure.Figure
        Segment opening angle psi [°] and force ratio F_K/F [-] of chain
        :data:`REFERENCE_CHAIN` for s from c to 70 mm, for each beta
        of :data:`BETA_DEG`, with the published values for eps_n = 0.
    """
    s = _s_grid()
    figure, axes = _figure(2, f"segment loads against contact distance,\nchain {REFERENCE_CHAIN}, "
                              "ε_n = 0 (Paper 003, Figs. 6-7)")
    for beta in BETA_DEG:
        psi = _opening_angle(s, beta, 0.0)
        axes[0].plot(s * 1e3, np.degrees(psi), label=f"model, β = {beta:g}°")
        axes[1].plot(s * 1e3, ts.contact_force_ratio(psi), label=f"model, β = {beta:g}°")
    _mark_published(axes[0], _published("opening_angle", eps_n_deg=0.0), "s_mm")
    _mark_published(axes[1], _published("contact_force_ratio", eps_n_deg=0.0), "s_mm")
    axes[0].set_ylabel("segment opening angle ψ [°]")
    axes[1].set_ylabel("segment force over flank force F_K/F [-]")
    for ax in axes:
        ax.set_xlabel("distance of the contact points s [mm]")
    _legend(figure, axes)
    return figure


def _side_force_friction_figure() -> tuple[Figure, str]:
    """Paper 003, Figs. 8-9: F_P/F and the friction increase over s, per beta.

    Returns
    -------
    figure : matplotlib.figure.Figure
        F_P/F [-] and the friction increase 2 F_K/F - 1 [%] of chain
        :data:`REFERENCE_CHAIN` for s from c to 70 mm, for each beta
        of :data:`BETA_DEG` with eps_n = 0, the friction also for beta = 50 deg,
        eps_n = 6 deg; the paper's claimed 50 % level as a line.
    text : str
        What the model gives against the paper's claims
        (:func:`pipeline.theory.tooth_segments.claims_note`).
    """
    s = _s_grid()
    figure, axes = _figure(2, f"side force and friction on the segments,\nchain {REFERENCE_CHAIN} "
                              "(Paper 003, Figs. 8-9)")
    for beta in BETA_DEG:
        psi = _opening_angle(s, beta, 0.0)
        axes[0].plot(s * 1e3, ts.side_force_ratio(psi), label=f"model, β = {beta:g}°")
        axes[1].plot(s * 1e3, 100 * np.asarray(ts.friction_increase(psi)),
                     label=f"model, β = {beta:g}°")
    inclined, claimed_beta = max(EPS_N_DEG), math.degrees(CLAIMS["beta"])
    axes[1].plot(s * 1e3, 100 * np.asarray(ts.friction_increase(
        _opening_angle(s, claimed_beta, inclined))), color="C0", linestyle="--",
        label=f"model, β = {claimed_beta:g}°, ε_n = {inclined:g}°")
    axes[0].axhline(CLAIMS["side_force_ratio"], color="0.3", linestyle=":",
                    label="level the paper claims exceeded (50 %)")
    axes[1].axhline(100 * CLAIMS["friction_increase"], color="0.3", linestyle=":",
                    label="level the paper claims exceeded (50 %)")
    axes[0].set_ylabel("side force over flank force F_P/F [-]")
    axes[1].set_ylabel("friction increase 2 F_K/F - 1 [%]")
    for ax in axes:
        ax.set_xlabel("distance of the contact points s [mm]")
    _legend(figure, axes)

    reference = _reference()
    chain = {"r_outer": reference["r"], "d": reference["d"], "groove_width": reference["c"]}
    text = ts.claims_note(chain, np.radians(BETA_DEG), np.radians([0.0, inclined]))
    return figure, text


def design_checks(summary: xr.Dataset) -> list[tuple[str, Figure]]:
    """The design-check figures of a campaign's report, each with its caption.

    Parameters
    ----------
    summary : xarray.Dataset
        The campaign summary; its ``chain`` labels (if any) are named in the captions.

    Returns
    -------
    list of (str, matplotlib.figure.Figure)
        Paper 003's curves (Figs. 3-9) for its reference chain
        :data:`REFERENCE_CHAIN`, labelled as a reference (a campaign's chains
        lack r and c), with the published values marked; nothing when the
        campaign has segment-load runs (``segment_point``): their measured
        section stands for Paper 003. Nothing for Papers 002 and 004: they
        concern roller chains; roller-engagement and wear runs set them
        against their measurements in their own sections (module docstring).
    """
    if summary.sizes.get("segment_point", 0):
        return []
    reference = _reference_text(summary)
    side_friction, claims = _side_force_friction_figure()
    return [
        ("Tooth-segment loads (Paper 003, Fig. 3): contact radius k of the link torus on "
         "the segment flank against the flank inclination β, for link inclinations ε_n. "
         + reference, _contact_radius_figure()),
        ("Tooth-segment loads (Paper 003, Figs. 4-5): at edge contact (contact points on the "
         "groove edges, s = c) the segments open by the angle ψ and each carries F_K, more "
         "than half the flank force F. " + reference, _edge_contact_figure()),
        ("Tooth-segment loads (Paper 003, Figs. 6-7): the further apart the contact points "
         "(s), the narrower the opening ψ and the larger the segment force F_K/F. "
         + reference, _contact_distance_figure()),
        ("Tooth-segment loads (Paper 003, Figs. 8-9): side component F_P/F of the segment "
         "force and the increase of the flank friction (2 F_K/F - 1) against s. "
         + claims + " " + reference, side_friction),
    ]


def published_not_reproduced() -> list[dict]:
    """Every published number the corrected models do not reproduce.

    Returns
    -------
    list of dict
        The rows each theory module's ``compare_published()`` declares not
        reproduced, in paper order: ``paper`` ("000" ... "004"), ``quantity``
        (the stable id), ``inputs`` (text), ``published`` and ``model`` (in
        ``unit``: the paper's), ``difference`` (model / published - 1) and
        ``note`` (source, why, and whether the number stays within the wider
        tolerance of its regression test).

    Notes
    -----
    Paper 003's claims about F_P/F and the friction increase (statements, not
    numbers) are discussed in the caption of its Figs. 8-9.
    """
    rows = []
    for paper, module in _PAPERS.items():
        table = module.compare_published()
        rows += [{"paper": paper, "quantity": row.quantity, "inputs": row.inputs,
                  "published": row.published, "model": row.model, "unit": row.unit,
                  "difference": row.rel_diff, "note": f"{row.source}: {row.note}"}
                 for row in table[~table["reproduced"]].itertuples()]
    return rows
