"""``chainbench report CAMPAIGN``: rebuild a campaign's report from ``processed/`` alone."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from pipeline.cli._output import say
from pipeline.errors import ChainbenchError
from pipeline.store.lock import campaign_lock

# The report builder and the campaign module are imported inside the functions that
# use them, so that every other command starts without loading them.


def processed_folder(target: Path) -> Path:
    """The processed campaign folder `target` names.

    Parameters
    ----------
    target : Path
        A processed folder (``processed/<campaign>``, holding ``summary.nc``),
        a raw campaign folder (``raw/<campaign>``, mapped to
        ``processed/<campaign>``) or a campaign id.

    Raises
    ------
    ChainbenchError
        When neither `target` nor its processed folder holds a summary.
    """
    from pipeline.campaign import PROCESSED_FOLDER, default_output
    from pipeline.runsheet import RUN_SHEET_NAME
    from pipeline.store.layout import SUMMARY

    if (target / SUMMARY).is_file():
        return target
    is_campaign = (target / RUN_SHEET_NAME).is_file() or target.name == RUN_SHEET_NAME
    processed = default_output(target) if is_campaign else Path(PROCESSED_FOLDER) / target.name
    if (processed / SUMMARY).is_file():
        return processed
    raise ChainbenchError(
        f"no processed results for {target}", file=processed / SUMMARY,
        hint=f"process the campaign first (chainbench run raw/{target.name}), or name a "
             "processed/<campaign> folder")


def command(
    campaign: Annotated[Path, typer.Argument(
        help="A processed folder (processed/<campaign>), or a raw campaign folder "
             "(raw/<campaign>) whose processed folder is rebuilt.", show_default=False)],
    debug: Annotated[bool, typer.Option("--debug", help="Show tracebacks.")] = False,
) -> None:
    """Rebuild the report of a processed campaign, from processed/ alone; print its path."""
    from pipeline.report.build import build_report

    try:
        folder = processed_folder(campaign)
        with campaign_lock(folder):  # not while a run writes the same outputs
            report = build_report(folder).page
    except ChainbenchError as error:
        if debug:
            raise
        say("error", "red", str(error))
        raise typer.Exit(1) from None
    print(report)
