"""``chainbench run`` and ``chainbench validate``: process or check campaigns.

``run`` first asks :func:`pipeline.store.freshness.current_rerun` whether
anything a campaign's outputs depend on changed since its last run; when
nothing did, it prints what that run recorded, having loaded neither the
stages nor the numerical libraries. Only a campaign with something to compute
loads them.
"""

from __future__ import annotations

import dataclasses
import io
import json
import math
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer
from rich.console import Console
from rich.markup import escape
from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table
from rich.text import Text

from pipeline.cli._cluster import dask_client, drive_on_cluster
from pipeline.cli._output import console, say
from pipeline.cli._stages import load_stages
from pipeline.errors import ChainbenchError
from pipeline.store.freshness import Rerun, current_rerun, write_rerun
from pipeline.store.layout import RUN_SHEET_NAME

if TYPE_CHECKING:
    import xarray as xr

    from pipeline.campaign import CampaignResult
    from pipeline.runsheet import RunSheet

# The stages (pipeline.campaign, pipeline.runs) are imported inside the commands that
# run them, so that every other command starts without loading them.

RAW = Path("raw")
#: Where a project keeps its campaigns, as said in messages.
EXPECTED = f"{RAW}/<campaign>/{RUN_SHEET_NAME}"
#: Where the summary tables and ``--json`` keep their numbers, as said in messages.
SI_NOTE = ("numbers in SI units as in summary.csv (forces in N, lengths in m, ratios as "
           "fractions): the unit of every column and scalar is under \"units\"; the console "
           "tables show forces in kN")

CampaignArgs = Annotated[
    list[Path] | None,
    typer.Argument(help=f"Campaign folders or their {RUN_SHEET_NAME} (default: every "
                        f"{EXPECTED}).", show_default=False),
]
OutputRoot = Annotated[Path | None, typer.Option(
    "--output", help="Root of the outputs: a campaign goes to OUTPUT/<campaign id> "
                     "(default: processed/<campaign id> beside raw/).", show_default=False)]


def campaign_folders(given: list[Path] | None) -> list[Path]:
    """The campaigns to process: those given, else every ``raw/*`` with a run sheet.

    Parameters
    ----------
    given : list of Path or None
        Campaign folders, or run sheets (files named ``campaign.toml``).

    Returns
    -------
    list of Path
        The campaigns given, as given; else every ``raw/<campaign>`` folder of
        the current folder that holds a run sheet, sorted.

    Raises
    ------
    ChainbenchError
        When a path given is not a campaign, or none was given and the current
        folder has no campaign; the message names the absolute path looked at.
    """
    if given:
        return [_campaign(path) for path in given]
    raw = RAW.resolve()
    if not raw.is_dir():
        raise ChainbenchError(
            f"no campaign found: {raw} does not exist",
            hint=f"run from a project folder holding {EXPECTED}, name a campaign folder, "
                 "or draft a run sheet with chainbench init FOLDER")
    folders = sorted(path.parent for path in RAW.glob(f"*/{RUN_SHEET_NAME}"))
    if not folders:
        raise ChainbenchError(
            f"no campaign found: no {EXPECTED} in {raw}",
            hint=f"draft a run sheet with chainbench init {RAW}/<campaign>")
    return folders


def _campaign(path: Path) -> Path:
    """`path` when it is a campaign folder or its run sheet, else a ChainbenchError."""
    if (path / RUN_SHEET_NAME).is_file() or (path.name == RUN_SHEET_NAME and path.is_file()):
        return path
    if not path.exists():
        problem = "it does not exist"
    elif path.is_dir():
        problem = f"it holds no {RUN_SHEET_NAME}"
    else:
        problem = f"it is neither a campaign folder nor a {RUN_SHEET_NAME}"
    draft = path if path.is_dir() else "FOLDER"
    raise ChainbenchError(
        f"no campaign at {path.resolve()}: {problem}",
        hint=f"expected a folder holding a {RUN_SHEET_NAME} ({EXPECTED}), or that file; "
             f"draft one with chainbench init {draft}")


def _campaigns_or_exit(given: list[Path] | None, debug: bool, stderr: bool) -> list[Path]:
    """The campaigns to work on; a one-line error and exit status 1 when there are none."""
    try:
        return campaign_folders(given)
    except ChainbenchError as error:
        if debug:
            raise
        say("error", "red", str(error), stderr=stderr)
        raise typer.Exit(1) from None


def _output_folder(sheet: RunSheet, output_root: Path | None) -> Path | None:
    """``output_root/<campaign id>``, or None (the campaign's default) without a root."""
    return None if output_root is None else Path(output_root) / sheet.campaign.id


class _Progress:
    """Where a campaign's progress goes: a rich bar on a terminal, plain lines otherwise.

    The processing calls :meth:`runs` once, then :meth:`step` at each stage of each
    run; on a cluster, the driver's calls arrive here as dask events
    (:func:`pipeline.cli._cluster.drive_on_cluster`).
    """

    def __init__(self, bar: Progress | None) -> None:
        self._bar, self._seen = bar, set()
        self._task = bar.add_task("processing", total=None) if bar is not None else None

    def runs(self, total: int) -> None:
        """The campaign has `total` runs."""
        if self._bar is not None:
            self._bar.update(self._task, total=total)

    def step(self, run_id: str, stage: str) -> None:
        """Run `run_id` reached `stage`."""
        if self._bar is None:
            print(f"  {run_id}: {stage}", flush=True)
            return
        if run_id not in self._seen and self._seen:
            self._bar.advance(self._task)
        self._seen.add(run_id)
        self._bar.update(self._task, description=escape(f"{run_id}: {stage}"))


class _Silent:
    """No progress shown (``--json``)."""

    def runs(self, total: int) -> None:
        """Nothing to show."""

    def step(self, run_id: str, stage: str) -> None:
        """Nothing to show."""


@contextmanager
def _progress_reporter(shown: bool = True):
    """A :class:`_Progress` for this console (or :class:`_Silent` when not `shown`)."""
    if not shown:
        yield _Silent()
    elif not console.is_terminal:
        yield _Progress(None)
    else:
        columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                   TextColumn("runs"), TimeElapsedColumn())
        with Progress(*columns, console=console, transient=True) as bar:
            yield _Progress(bar)


def _fmt(value: float, scale: float = 1.0, digits: int = 4) -> str:
    return "-" if not math.isfinite(value) else f"{value / scale:.{digits}g}"


def _table(title: str, columns: tuple[str, ...]) -> Table:
    """An empty console table titled `title`, with right-aligned `columns` (escaped)."""
    table = Table(title=title)
    for column in columns:
        table.add_column(escape(column), justify="right")
    return table


def _chain_table(summary) -> Table:
    low, high = (100 * float(value) for value in summary.attrs["band"].split())
    table = _table(f"chain stiffness E0 (forces in kN; lab band {low:g} to {high:g} %)",
                   ("chain", "n", "E0_exp [kN]", "95 % interval [kN]", "E0_theory [kN]",
                    "d [%]", "in band"))
    for chain in summary["chain"].values:
        row = summary.sel(chain=chain)
        interval = (f"{_fmt(float(row['E0_exp_ci_low']), 1e3, 5)}.."
                    f"{_fmt(float(row['E0_exp_ci_high']), 1e3, 5)}")
        table.add_row(
            escape(str(chain)), str(int(row["n_specimens"])), _fmt(float(row["E0_exp"]), 1e3, 5),
            interval, _fmt(float(row["E0_theory"]), 1e3, 5),
            _fmt(100 * float(row["discrepancy"]), 1, 3),
            # -1 when computed, NaN (its fill value) when read back: not checked
            {1.0: "yes", 0.0: "NO"}.get(float(row["in_band"]), "-"),
        )
    return table


def _impact_table(summary) -> Table:
    table = _table("impact tensions (forces in N): measured (median) vs Paper 000 "
                   "eq. (16), k = 2",
                   ("run", "z", "psi [deg]", "omega [1/s]", "N_u1 meas [N]", "N_u1 theory [N]",
                    "N_u2 meas [N]", "N_u2 theory [N]"))
    for point in summary["operating_point"].values:
        row = summary.sel(operating_point=point)
        table.add_row(escape(str(point)), *(_fmt(float(row[name])) for name in (
            "teeth", "apex_angle", "omega", "N_u1_meas", "N_u1_theory", "N_u2_meas",
            "N_u2_theory")))
    return table


#: How a wear run's rate and lives are printed, by its abscissa: names' suffix, units and
#: scale (SI over the printed unit) of the rate and of a life.
_WEAR_UNITS = {"time": ("", "um/h", 1e-6 / 3600, "h", 3600.0),
               "cycles": ("_cycles", "um/Mcycle", 1e-12, "cycles", 1.0)}


def _with_interval(row, name: str, scale: float, unit: str, digits: int = 4) -> str:
    """A summary value and its interval, in `unit` (`scale`: SI per unit)."""
    low, high = (_fmt(float(row[name + end]), scale, digits) for end in ("_ci_low", "_ci_high"))
    return f"{_fmt(float(row[name]), scale, digits)} ({low}..{high}) {unit}"


def _wear_table(summary) -> Table:
    table = _table("wear runs: steady wear rate and life to the limits (95 % intervals; "
                   "eq. (3): Paper 004's jump-off growth)",
                   ("run", "chain", "z", "model", "wear rate", "life eq. (3)", "life lab limit",
                    "pin eq. (1)"))
    for run in summary["wear_run"].values:
        row = summary.sel(wear_run=run)
        suffix, rate_unit, rate_scale, life_unit, life_scale = _WEAR_UNITS[
            str(row["wear_abscissa"].values)]
        lab = math.isfinite(float(row["limit_lab"]))
        table.add_row(
            escape(str(run)), escape(str(row["wear_chain"].values)),
            _fmt(float(row["wear_teeth"])), str(row["wear_model"].values),
            _with_interval(row, f"wear_rate{suffix}", rate_scale, rate_unit, 3),
            _with_interval(row, f"life_eq3{suffix}", life_scale, life_unit),
            _with_interval(row, f"life_lab{suffix}", life_scale, life_unit) if lab else "-",
            {1: "pass", 0: "FAIL", -1: "-"}[int(row["pin_passes"])])
    return table


#: How a drum's fitted parameter is printed: scale (SI per printed unit) and unit.
_GEOMETRY_UNITS = {"s": (1e-3, "mm", "segment_contact_distance"),
                   "beta": (math.pi / 180, "deg", "segment_flank_inclination")}


def _segment_table(summary) -> Table:
    """Per drum: the fitted s or beta against the run sheet's, F_K/F measured against model."""
    from pipeline.report.formatting import first_rows
    from pipeline.segment_summary import AGREEMENT

    table = _table("segment-load drums: contact geometry fitted to the measured F_K/F, "
                   "F_P/F (95 % intervals; Paper 003, eqs. (1)-(4))",
                   ("drum", "runs", "fitted", "sheet", "F_K/F meas.", "model sheet",
                    "model fit", "agree"))
    drums = summary["segment_drum"].values.astype(str)
    for row in first_rows(summary, "segment_point", "segment_drum"):
        drum = str(row["segment_drum"].values)
        runs = summary.isel(segment_point=drums == drum)
        name = str(row["segment_fitted"].values)
        scale, unit, declared = _GEOMETRY_UNITS[name]
        measured = runs["segment_contact_ratio"].values
        table.add_row(
            escape(drum), str(runs.sizes["segment_point"]),
            f"{name} {_with_interval(row, f'segment_fit_{name}', scale, unit)}",
            f"{_fmt(float(row[declared]), scale)} {unit}",
            f"{_fmt(float(measured.min()))}..{_fmt(float(measured.max()))}",
            _fmt(float(row["segment_model_contact_ratio"])),
            _fmt(float(row["segment_fitted_contact_ratio"])),
            f"{int(runs['segment_model_agrees'].sum())}/{runs.sizes['segment_point']}")
    table.caption = (f"F_K/F meas.: the runs' medians; model: eqs. (1)-(3) at the run sheet's "
                     f"and at the fitted geometry; agree: runs within {AGREEMENT:g} standard "
                     "errors of the run sheet's model")
    return table


def _roller_table(summary) -> Table:
    """Per sprocket: the fitted xi against the involute's, and the speeds above n_max."""
    from pipeline.report.formatting import first_rows

    table = _table("roller-chain sprockets: impact-velocity coefficient xi fitted to the "
                   "strike amplitudes (95 % intervals; Paper 002)",
                   ("sprocket", "z", "xi fitted", "xi model", "bounds", "n_max [rpm]",
                    "above n_max [rpm]"))
    keys = summary["roller_sprocket"].values.astype(str)
    for row in first_rows(summary, "sprocket_point", "roller_sprocket"):
        runs = summary.isel(sprocket_point=keys == str(row["roller_sprocket"].values))
        above = runs["roller_n"].values[runs["above_n_max"].values == 1]
        table.add_row(
            escape(str(row["roller_sprocket"].values)), _fmt(float(row["roller_teeth"])),
            _with_interval(row, "xi_fit", 1.0, "").strip(),
            _fmt(float(row["xi_model"])),
            {1: "yes", 0: "NO", -1: "-"}[int(row["xi_within_bounds"])],
            _fmt(float(row["n_max"])), " ".join(_fmt(float(n)) for n in above) or "none")
    table.caption = ("xi model: the involute's (eqs. (3)-(5)); bounds: sin(pi/z) <= xi <= "
                     "cos(pi/z), eq. (3); n_max: eq. (8) with the fitted xi")
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
    table = _table("tensile specimens (forces in kN, elongations A in % of the gauge "
                   "length)",
                   ("run", "E0 [kN]", "F_max [kN]", "A at F_max [%]", "A at fracture [%]",
                    "F_yield [kN]", "A at proof [%]", "set [%]"))
    for run_id in summary["specimen"].values:
        row = summary.sel(specimen=run_id)
        table.add_row(
            escape(str(run_id)) + ("*" if int(row["specimen_single_pull"]) else "")
            + ("^" if int(row["specimen_from_crosshead"]) else ""),
            _fmt(float(row["specimen_E0"]), 1e3, 5),
            _fmt(float(row["specimen_max_force"]), 1e3, 4),
            *(_fmt(100 * float(row[f"specimen_{name}"]), 1, 3)
              for name in ("strain_at_max_force", "strain_at_fracture")),
            _fmt(float(row["specimen_yield_force"]), 1e3, 4),
            *(_fmt(100 * float(row[f"specimen_{name}"]), 1, 3)
              for name in ("strain_at_proof", "permanent_strain_after_proof")),
        )
    table.caption = "* single pull: E0 from its one loading; - not reached or not measured"
    if summary["specimen_from_crosshead"].any():
        table.caption += ("; ^ E0 from the crosshead travel, which includes the machine's "
                          "compliance: too low")
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


def _print_result(result: CampaignResult, out: Console = console) -> None:
    """Print a processed campaign's tables, findings and where its results are, to `out`."""
    summary = result.summary
    if summary.sizes.get("chain", 0):
        out.print(_chain_table(summary))
    if _shows_specimens(summary):
        out.print(_specimen_table(summary))
        acceptance = _acceptance_table(summary)
        if acceptance is not None:
            out.print(acceptance)
        for chain in summary["chain"].values:
            verdicts = _verdicts(summary.sel(chain=chain), "accept_")
            if verdicts != "-":
                out.print(f"chain {escape(str(chain))} acceptance: {escape(verdicts)}",
                              highlight=False)
    if summary.sizes.get("operating_point", 0):
        out.print(_impact_table(summary))
        if math.isfinite(float(summary["k_fit"])):
            out.print(
                f"fitted mass share k = {float(summary['k_fit']):.4g} "
                f"(95 % interval {float(summary['k_fit_ci_low']):.4g} .. "
                f"{float(summary['k_fit_ci_high']):.4g}; Ryabov: k = 2)", highlight=False)
    if summary.sizes.get("wear_run", 0):
        out.print(_wear_table(summary))
    if summary.sizes.get("segment_point", 0):
        out.print(_segment_table(summary))
    if summary.sizes.get("sprocket_point", 0):
        out.print(_roller_table(summary))
    for note in filter(None, summary.attrs.get("notes", "").split("\n")):
        say("note", "yellow", note, to=out)
    _print_findings(result, failure_tag="failed", out=out)
    out.print(f"{_counts(result)}; results in {result.output} (summary tables in SI "
                  "units: forces in N)", markup=False, highlight=False, soft_wrap=True)
    if result.report is not None:
        out.print(f"report: {result.report}", markup=False, highlight=False)
    else:
        say("report not written:", "red", str(result.report_error), to=out)


def _counts(result: CampaignResult) -> str:
    """What became of the runs: ``3 run(s) processed, 1 unchanged, 2 failed``."""
    return (f"{len(result.redone)} run(s) processed, {len(result.reused)} unchanged, "
            f"{len(result.failures)} failed")


def _units(summary: xr.Dataset, names) -> dict[str, str | None]:
    """The unit of each variable of `names` (its ``units`` attribute; None for text and
    verdict codes)."""
    return {name: summary[name].attrs.get("units") for name in names}


def _result_json(result: CampaignResult) -> dict:
    from pipeline.campaign import summary_table

    summary = result.summary
    tables = {
        dim: json.loads(summary_table(summary, dim).reset_index().to_json(orient="records"))
        for dim in ("chain", "operating_point") if summary.sizes.get(dim, 0)
    }
    scalars = {name: float(summary[name]) for name in summary.data_vars
               if summary[name].ndim == 0}
    columns = [name for dim in tables for name in summary_table(summary, dim).columns]
    return {
        "campaign": result.campaign_id,
        "output": str(result.output),
        "note": SI_NOTE,
        "units": _units(summary, [*columns, *scalars]),
        "chains": tables.get("chain", []),
        "operating_points": tables.get("operating_point", []),
        **scalars,
        "failed_runs": [{"run": f.run_id, "error": f.message} for f in result.failures],
        "implausible": result.implausible,
        "warnings": result.warnings,
        "processed": len(result.redone),
        "unchanged": len(result.reused),
        "failed": len(result.failures),
        "redone": result.redone,
        "reused": result.reused,
        "report": str(result.report) if result.report else None,
    }


def run_command(
    campaigns: CampaignArgs = None,
    output_root: OutputRoot = None,
    force: Annotated[bool, typer.Option("--force", help="Redo every run, changed or not.")] = False,
    rehash: Annotated[bool, typer.Option(
        "--rehash", help="Read every raw file again for its SHA-256, even those whose size, "
                         "modification time and inode are unchanged.")] = False,
    workers: Annotated[int | None, typer.Option(
        "--workers", min=1, help="Process runs on a local dask cluster of N workers.")] = None,
    scheduler: Annotated[str | None, typer.Option(
        "--scheduler", help="Process runs on an existing dask scheduler (ADDRESS).")] = None,
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON.")] = False,
    debug: Annotated[bool, typer.Option("--debug", help="Show tracebacks.")] = False,
) -> None:
    """Process campaigns: ingest, condition, fit, store, compare and report.

    Runs whose inputs did not change since the last run are not redone; when
    nothing a campaign depends on changed (run sheet, raw files, code, outputs),
    what its last run printed is printed again.
    """
    all_ok, documents = True, []
    folders = _campaigns_or_exit(campaigns, debug, stderr=as_json)
    with ExitStack() as stack:
        client, started = None, False
        for folder in folders:
            if not as_json:
                console.print(f"[bold]campaign {escape(str(folder))}[/bold]", highlight=False)
            rerun = None if force or rehash else current_rerun(folder, output_root)
            if rerun is not None:
                all_ok &= rerun.exit_code == 0
                if as_json:
                    documents.append(rerun.document)
                else:
                    _print_rerun(rerun)
                continue
            if not started:  # the cluster starts when a campaign has something to compute
                client, started = stack.enter_context(dask_client(workers, scheduler)), True
            try:
                outcome = _process(folder, output_root, force, rehash, debug, client, as_json)
            except ChainbenchError as error:
                if debug:
                    raise
                all_ok = False
                say("error", "red", str(error), stderr=as_json)
                documents.append({"campaign": str(folder), "error": str(error)})
                continue
            all_ok &= outcome.ok
            if as_json:
                documents.append(outcome.document)
            else:
                console.print(Text.from_ansi(outcome.text), soft_wrap=True, end="")
    if as_json:
        print(json.dumps(documents, indent=2))
    raise typer.Exit(0 if all_ok else 1)


@dataclasses.dataclass(frozen=True)
class _Screen:
    """What the driver of a campaign needs to know of this command's console to render
    the text it prints: its width, its encoding, and whether it shows colours."""

    width: int
    encoding: str
    coloured: bool

    @classmethod
    def of(cls, target: Console) -> _Screen:
        return cls(target.width, target.encoding, target.is_terminal)

    def recorder(self) -> Console:
        """A console that keeps what is printed to it, rendered as for this screen."""
        return Console(file=_Recording(self.encoding), width=self.width,
                       color_system="truecolor" if self.coloured else None,
                       force_terminal=self.coloured, legacy_windows=False, emoji=False)


class _Recording(io.StringIO):
    """Text kept in memory, as if written to a stream of `encoding` (rich draws a
    table's lines in ASCII for a stream that cannot show others)."""

    def __init__(self, encoding: str) -> None:
        super().__init__()
        self._encoding = encoding

    @property
    def encoding(self) -> str:
        return self._encoding


@dataclasses.dataclass(frozen=True)
class _Outcome:
    """A processed campaign, as the command reports it."""

    ok: bool
    text: str  #: what it prints (ANSI colours for a terminal)
    document: dict  #: its ``--json`` document


def _process(folder: Path, output_root: Path | None, force: bool, rehash: bool, debug: bool,
             client, as_json: bool) -> _Outcome:
    """Process one campaign here, or on `client`'s cluster as a task
    (:func:`pipeline.cli._cluster.drive_on_cluster`), showing its progress here."""
    arguments = (folder, output_root, force, rehash, debug, _Screen.of(console))
    with _progress_reporter(shown=not as_json) as progress:
        if client is None:
            return _processed(*arguments, listener=progress)
        return drive_on_cluster(client, _processed, *arguments, listener=progress)


def _processed(folder: Path, output_root: Path | None, force: bool, rehash: bool, debug: bool,
               screen: _Screen, *, listener, client=None) -> _Outcome:
    """Process one campaign, telling `listener` its progress; record what a re-run with
    nothing changed prints; what to report, rendered for `screen`."""
    process_campaign = load_stages().process_campaign  # before the run sheet's imports
    from pipeline.runsheet import load_run_sheet

    sheet = load_run_sheet(folder)
    listener.runs(len(sheet.runs))
    result = process_campaign(folder, _output_folder(sheet, output_root),
                              progress=listener.step, debug=debug, force=force, client=client,
                              rehash=rehash)
    if not result.failures and result.report is not None:
        again = dataclasses.replace(result, redone=[], reused=list(result.run_files),
                                    removed=[])
        recorder = Console(file=io.StringIO(), width=screen.width, color_system=None,
                           force_terminal=False, highlight=False, emoji=False)
        _print_result(again, out=recorder)
        write_rerun(result.output, sheet.path, result.inputs, recorder.file.getvalue(),
                    _result_json(again), 0 if again.ok else 1)
    shown = screen.recorder()
    _print_result(result, out=shown)
    return _Outcome(result.ok, shown.file.getvalue(), _result_json(result))


def _print_rerun(rerun: Rerun) -> None:
    """Say that nothing changed, and print what the campaign's last run printed."""
    say("unchanged", "green", "run sheet, raw files, code and outputs are as the last run "
        f"left them: its results in {rerun.output} are current")
    console.print(rerun.text, markup=False, highlight=False, soft_wrap=True, end="")


def _print_findings(result: CampaignResult, failure_tag: str, out: Console = console) -> None:
    """The runs' warnings, the failures (tagged `failure_tag`) and the open plausibility
    flags of a processed or checked campaign."""
    for run_id, found in result.warnings.items():
        for warning in found:
            say("warning", "yellow", f"{run_id}: {warning}", to=out)
    for failure in result.failures:
        say(failure_tag, "red", f"{failure.run_id}: {failure.message}", to=out)
    for message in result.implausible:
        say("implausible", "red", message, to=out)


def _validate_campaign(folder: Path, output_root: Path | None) -> bool:
    """Check one campaign as `run` would process it, print what is found; True when clean."""
    from pipeline.campaign import check_campaign
    from pipeline.runsheet import load_run_sheet

    try:
        sheet = load_run_sheet(folder)
        with _progress_reporter() as progress:
            progress.runs(len(sheet.runs))
            result = check_campaign(folder, _output_folder(sheet, output_root), progress.step)
    except ChainbenchError as error:
        say("error", "red", str(error))
        return False
    _print_findings(result, failure_tag="error")
    problems = len(result.failures) + len(result.implausible)
    console.print(f"{folder}: {len(sheet.runs)} runs, {problems} problems",
                  markup=False, highlight=False)
    return not problems


def validate_command(
    campaigns: CampaignArgs = None,
    output_root: Annotated[Path | None, typer.Option(
        "--output", help="Root of the outputs `run` writes to, read for stiffness_from "
                         "(default: processed/ beside raw/); nothing is written.",
        show_default=False)] = None,
) -> None:
    """Check run sheets and their files as `run` would, writing nothing.

    Every run goes through the processing of `run` (read, condition and fit a
    tensile run; read, detect the events and extract the impacts of an
    engagement log), so that what `run` would refuse is found here, and what it
    would decide (channels used, fracture) is shown as warnings.
    """
    all_ok = True
    for folder in _campaigns_or_exit(campaigns, debug=False, stderr=False):
        all_ok &= _validate_campaign(folder, output_root)
    raise typer.Exit(0 if all_ok else 1)


#: ``chainbench run`` on its own: what the entry point loads for it (:func:`pipeline.cli.main`).
run_app = typer.Typer(add_completion=False, pretty_exceptions_enable=False)
run_app.command()(run_command)
