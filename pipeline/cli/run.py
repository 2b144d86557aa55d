"""``chainbench run`` and ``chainbench validate``: process or check campaigns."""

from __future__ import annotations

import json
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import numpy as np
import typer
from rich.markup import escape
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from pipeline.cli._output import console
from pipeline.errors import ChainbenchError
from pipeline.runsheet import RUN_SHEET_NAME, load_run_sheet

if TYPE_CHECKING:
    from pipeline.campaign import CampaignResult

# The stages (pipeline.campaign, pipeline.runs) are imported inside the commands that
# run them, so that every other command starts without loading them.

RAW = Path("raw")
PROCESSED = Path("processed")

CampaignArgs = Annotated[
    list[Path] | None,
    typer.Argument(help="Campaign folders (default: every campaign under raw/).",
                   show_default=False),
]


def campaign_folders(given: list[Path] | None) -> list[Path]:
    """The folders to process: those given, else every ``raw/*`` with a run sheet."""
    if given:
        return list(given)
    folders = sorted(path.parent for path in RAW.glob(f"*/{RUN_SHEET_NAME}"))
    if not folders:
        raise ChainbenchError(
            "no campaign found", file=RAW,
            hint=f"run from the project folder, or name a folder holding a {RUN_SHEET_NAME}",
        )
    return folders


@contextmanager
def _progress_reporter(total_runs: int):
    """A ``progress(run_id, stage)`` callback: a rich bar on a terminal, plain lines otherwise."""
    if not console.is_terminal:
        yield lambda run_id, stage: print(f"  {run_id}: {stage}", flush=True)
        return
    columns = (TextColumn("{task.description}"), BarColumn(), TextColumn("{task.completed}/"
               "{task.total} runs"), TimeElapsedColumn())
    with Progress(*columns, console=console, transient=True) as bar:
        task = bar.add_task("processing", total=total_runs)
        seen: set[str] = set()

        def step(run_id: str, stage: str) -> None:
            if run_id not in seen and seen:
                bar.advance(task)
            seen.add(run_id)
            bar.update(task, description=f"{run_id}: {stage}")

        yield step


def _fmt(value: float, scale: float = 1.0, digits: int = 4) -> str:
    return "-" if not np.isfinite(value) else f"{value / scale:.{digits}g}"


def _chain_table(summary) -> Table:
    low, high = (100 * float(value) for value in summary.attrs["band"].split())
    table = Table(title=f"chain stiffness E0 (lab band {low:g} to {high:g} %)")
    for column in ("chain", "n", "E0_exp [kN]", "95 % interval", "E0_theory [kN]",
                   "d [%]", "in band"):
        table.add_column(escape(column), justify="right")
    for chain in summary["chain"].values:
        row = summary.sel(chain=chain)
        interval = (f"{_fmt(float(row['E0_exp_ci_low']), 1e3, 5)}.."
                    f"{_fmt(float(row['E0_exp_ci_high']), 1e3, 5)}")
        table.add_row(
            str(chain), str(int(row["n_specimens"])), _fmt(float(row["E0_exp"]), 1e3, 5),
            interval, _fmt(float(row["E0_theory"]), 1e3, 5),
            _fmt(100 * float(row["discrepancy"]), 1, 3),
            {1: "yes", 0: "NO", -1: "-"}[int(row["in_band"])],
        )
    return table


def _impact_table(summary) -> Table:
    table = Table(title="impact tensions: measured (median) vs Paper 000 eq. (16), k = 2")
    for column in ("run", "z", "psi [deg]", "omega [1/s]", "N_u1 meas [N]", "N_u1 theory [N]",
                   "N_u2 meas [N]", "N_u2 theory [N]"):
        table.add_column(escape(column), justify="right")
    for point in summary["operating_point"].values:
        row = summary.sel(operating_point=point)
        table.add_row(str(point), *(_fmt(float(row[name])) for name in (
            "teeth", "apex_angle", "omega", "N_u1_meas", "N_u1_theory", "N_u2_meas",
            "N_u2_theory")))
    return table


_VERDICT_TEXT = {1: "pass", 0: "FAIL", -1: "not measured"}


#: Short names of the acceptance checks in the acceptance table.
_CHECK_SHORT = {"proof_force": "proof", "breaking_force": "F_break",
                "elongation_at_proof": "A_proof", "elongation_at_fracture": "A_frac"}


def _verdicts(row, prefix: str) -> str:
    """The declared checks of a chain row, as ``name: verdict`` text."""
    from pipeline.acceptance import CHECKS

    found = [f"{check.replace('_', ' ')}: {_VERDICT_TEXT[int(row[prefix + check])]}"
             for check in CHECKS if int(row[prefix + check]) in _VERDICT_TEXT]
    return "; ".join(found) or "-"


def _specimen_table(summary) -> Table:
    table = Table(title="tensile specimens (forces in kN, elongations A in % of the gauge "
                  "length)")
    for column in ("run", "E0 [kN]", "F_max [kN]", "A at F_max [%]", "A at fracture [%]",
                   "F_yield [kN]", "A at proof [%]", "set [%]"):
        table.add_column(escape(column), justify="right")
    for run_id in summary["specimen"].values:
        row = summary.sel(specimen=run_id)
        table.add_row(
            escape(str(run_id)) + ("*" if int(row["specimen_single_pull"]) else ""),
            _fmt(float(row["specimen_E0"]), 1e3, 5),
            _fmt(float(row["specimen_max_force"]), 1e3, 4),
            *(_fmt(100 * float(row[f"specimen_{name}"]), 1, 3)
              for name in ("strain_at_max_force", "strain_at_fracture")),
            _fmt(float(row["specimen_yield_force"]), 1e3, 4),
            *(_fmt(100 * float(row[f"specimen_{name}"]), 1, 3)
              for name in ("strain_at_proof", "permanent_strain_after_proof")),
        )
    table.caption = "* single pull: E0 from its one loading; - not reached or not measured"
    return table


def _acceptance_table(summary) -> Table | None:
    """Verdict of every declared check per specimen, or None when no chain declares one."""
    from pipeline.acceptance import CHECKS

    declared = [check for check in CHECKS
                if any(int(value) in _VERDICT_TEXT for value in summary[f"accept_{check}"].values)]
    if not declared:
        return None
    table = Table(title="acceptance checks the chains declare")
    for column in ("run", *(_CHECK_SHORT[check] for check in declared)):
        table.add_column(column, justify="right")
    for run_id in summary["specimen"].values:
        row = summary.sel(specimen=run_id)
        table.add_row(escape(str(run_id)), *(
            _VERDICT_TEXT.get(int(row[f"specimen_accept_{check}"]), "-") for check in declared))
    return table


def _shows_specimens(summary) -> bool:
    """Single pulls or declared acceptance limits make the specimen table worth printing."""
    if not summary.sizes.get("specimen", 0):
        return False
    declared = any(int(value) != -2 for name in summary.data_vars
                   if name.startswith("accept_") for value in summary[name].values)
    return declared or bool(summary["specimen_single_pull"].any())


def _print_result(result: CampaignResult) -> None:
    summary = result.summary
    if summary.sizes.get("chain", 0):
        console.print(_chain_table(summary))
    if _shows_specimens(summary):
        console.print(_specimen_table(summary))
        acceptance = _acceptance_table(summary)
        if acceptance is not None:
            console.print(acceptance)
        for chain in summary["chain"].values:
            verdicts = _verdicts(summary.sel(chain=chain), "accept_")
            if verdicts != "-":
                console.print(f"chain {escape(str(chain))} acceptance: {escape(verdicts)}",
                              highlight=False)
    if summary.sizes.get("operating_point", 0):
        console.print(_impact_table(summary))
        if np.isfinite(float(summary["k_fit"])):
            console.print(
                f"fitted mass share k = {float(summary['k_fit']):.4g} "
                f"(95 % interval {float(summary['k_fit_ci_low']):.4g} .. "
                f"{float(summary['k_fit_ci_high']):.4g}; Ryabov: k = 2)", highlight=False)
    for note in filter(None, summary.attrs.get("notes", "").split("\n")):
        console.print(f"[yellow]note[/yellow] {escape(note)}", highlight=False)
    for run_id, found in result.warnings.items():
        for warning in found:
            console.print(f"[yellow]warning[/yellow] {escape(run_id)}: {escape(warning)}",
                          highlight=False)
    for failure in result.failures:
        console.print(f"[red]failed[/red] {escape(failure.run_id)}: {escape(failure.message)}",
                      highlight=False)
    console.print(f"{len(result.redone)} run(s) processed, {len(result.reused)} unchanged; "
                  f"results in {result.output}", highlight=False)
    if result.report is not None:
        console.print(f"report: {result.report}", highlight=False)
    else:
        console.print(f"[red]report not written[/red]: {result.report_error}", highlight=False)


def _result_json(result: CampaignResult) -> dict:
    from pipeline.campaign import summary_table

    summary = result.summary
    tables = {
        dim: json.loads(summary_table(summary, dim).reset_index().to_json(orient="records"))
        for dim in ("chain", "operating_point") if summary.sizes.get(dim, 0)
    }
    scalars = {name: float(summary[name]) for name in summary.data_vars
               if summary[name].ndim == 0}
    return {
        "campaign": result.campaign_id,
        "output": str(result.output),
        "chains": tables.get("chain", []),
        "operating_points": tables.get("operating_point", []),
        **scalars,
        "failed_runs": [{"run": f.run_id, "error": f.message} for f in result.failures],
        "warnings": result.warnings,
        "redone": result.redone,
        "reused": result.reused,
        "report": str(result.report) if result.report else None,
    }


@contextmanager
def _dask_client(workers: int | None, scheduler: str | None):
    """A dask.distributed client: a local cluster of `workers` processes, or `scheduler`'s."""
    if workers is None and scheduler is None:
        yield None
        return
    if workers is not None and scheduler is not None:
        raise typer.BadParameter("give --workers or --scheduler, not both")
    from distributed import Client, LocalCluster

    if scheduler is not None:
        with Client(scheduler) as client:
            yield client
        return
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        yield client


def run_command(
    campaigns: CampaignArgs = None,
    output_root: Annotated[Path, typer.Option("--output", help="Root of the outputs.")] = PROCESSED,
    force: Annotated[bool, typer.Option("--force", help="Redo every run, changed or not.")] = False,
    workers: Annotated[int | None, typer.Option(
        "--workers", min=1, help="Process runs on a local dask cluster of N workers.")] = None,
    scheduler: Annotated[str | None, typer.Option(
        "--scheduler", help="Process runs on an existing dask scheduler (ADDRESS).")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
    debug: Annotated[bool, typer.Option("--debug", help="Show tracebacks.")] = False,
) -> None:
    """Process campaigns: ingest, condition, fit, store, compare and report.

    Runs whose inputs did not change since the last run are not redone.
    """
    from pipeline.campaign import process_campaign

    all_ok, documents = True, []
    with _dask_client(workers, scheduler) as client:
        for folder in campaign_folders(campaigns):
            if not as_json:
                console.print(f"[bold]campaign {folder}[/bold]", highlight=False)
            try:
                total = len(load_run_sheet(folder).runs)
                with _progress_reporter(total) as progress:
                    result = process_campaign(
                        folder, output_root / folder.name, progress=None if as_json else progress,
                        debug=debug, force=force, client=client)
            except ChainbenchError as error:
                if debug:
                    raise
                all_ok = False
                console.print(f"[red]error[/red] {error}", highlight=False)
                documents.append({"campaign": str(folder), "error": str(error)})
                continue
            all_ok &= result.ok
            if as_json:
                documents.append(_result_json(result))
            else:
                _print_result(result)
    if as_json:
        print(json.dumps(documents, indent=2))
    raise typer.Exit(0 if all_ok else 1)


def validate_command(
    campaigns: CampaignArgs = None,
) -> None:
    """Check run sheets and their files as `run` would, writing nothing.

    Every file is read; a tensile run is also conditioned and fitted, so that what
    `run` would refuse (cycles found against asked, channels, gauge length) is found
    here, and what it would decide (channels used, fracture) is shown as warnings.
    """
    from pipeline.runs import analyse_tensile_run, read_run

    all_ok = True
    for folder in campaign_folders(campaigns):
        try:
            sheet = load_run_sheet(folder)
        except ChainbenchError as error:
            console.print(f"[red]error[/red] {error}", highlight=False)
            all_ok = False
            continue
        problems = [str(error) for error in sheet.invalid_runs]
        for run in sheet.runs:
            try:
                if run.kind == "tensile":
                    found = analyse_tensile_run(sheet, run).warnings
                else:
                    found = read_run(sheet, run)[1].warnings
            except ChainbenchError as error:
                problems.append(f"run {run.id}: {error}")
                continue
            for warning in found:
                console.print(f"[yellow]warning[/yellow] {run.id}: {escape(warning)}",
                              highlight=False)
        for problem in problems:
            console.print(f"[red]error[/red] {escape(problem)}", highlight=False)
        all_ok &= not problems
        summary = f"{folder}: {len(sheet.runs)} runs, {len(problems)} problems"
        console.print(summary, highlight=False)
    raise typer.Exit(0 if all_ok else 1)
