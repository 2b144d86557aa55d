"""The names of the files a campaign's output folder holds.

``processed/<campaign id>/`` holds one netCDF file per run (``<run id>.nc``)
beside the campaign outputs below. A run id therefore must not name a campaign
output (in any letter case: Windows and macOS file systems ignore case), nor a
device name that Windows refuses as a file name (``CON``, ``NUL``, ``COM1``...).
"""

from __future__ import annotations

from pathlib import Path

#: The run sheet's file name in a campaign folder.
RUN_SHEET_NAME = "campaign.toml"
#: Folders of a project: the campaigns' raw files, and their outputs.
RAW_FOLDER, PROCESSED_FOLDER = "raw", "processed"

SUMMARY = "summary.nc"  #: the campaign summary dataset
CHAIN_TABLE = "summary.csv"  #: one row per chain
SPECIMEN_TABLE = "specimens.csv"  #: one row per tensile specimen
IMPACT_TABLE = "impact_summary.csv"  #: one row per engagement operating point
WEAR_TABLE = "wear_summary.csv"  #: one row per wear run
ROLLER_TABLE = "roller_summary.csv"  #: one row per roller-engagement run (sprocket point)
SEGMENT_TABLE = "segment_summary.csv"  #: one row per segment-load run (segment point)
REPORT = "report.html"  #: the campaign report
#: The folder of the report's per-run pages (``<run id>.html``), beside ``report.html``.
RUN_PAGES = "report-runs"
LOCK = ".lock"  #: held while a process writes the folder
#: The input key the campaign outputs were built from; written after the last of them.
MANIFEST = ".outputs.json"
#: The raw files' SHA-256, keyed by their size, modification time and inode.
HASHES = ".hashes.json"
#: What a re-run with nothing changed checks and prints (:mod:`pipeline.store.freshness`).
RERUN = ".rerun.json"

#: Every campaign-level output of a processed folder.
CAMPAIGN_OUTPUTS = (SUMMARY, CHAIN_TABLE, SPECIMEN_TABLE, IMPACT_TABLE, WEAR_TABLE, ROLLER_TABLE,
                    SEGMENT_TABLE, REPORT)

#: File names Windows reserves for devices, with or without an extension.
WINDOWS_DEVICE_NAMES = frozenset(
    {"con", "prn", "aux", "nul"}
    | {f"com{digit}" for digit in range(10)}
    | {f"lpt{digit}" for digit in range(10)}
)


def project_root(campaign_folder: Path) -> Path:
    """The project folder of a campaign: the parent of the ``raw/`` folder holding it.

    A campaign outside any ``raw/`` folder belongs to the current folder's
    project (the current folder, or the parent of the ``raw/`` folder it lies in).
    """
    for folder in (Path(campaign_folder).resolve(), Path.cwd().resolve()):
        for parent in (folder, *folder.parents):
            if parent.name.casefold() == RAW_FOLDER:
                return parent.parent
    return Path.cwd().resolve()


def run_output(output: Path, run_id: str) -> Path:
    """The netCDF file of run `run_id` in the output folder `output`."""
    return Path(output) / f"{run_id}.nc"


def unportable_name_reason(name: str) -> str | None:
    """Why `name` cannot name a file or folder on Windows, or None when it can.

    >>> unportable_name_reason("CON")
    "'CON' is a device name Windows refuses as a file name"
    >>> unportable_name_reason("c18") is None
    True
    """
    if name.split(".")[0].casefold() in WINDOWS_DEVICE_NAMES:
        return f"{name!r} is a device name Windows refuses as a file name"
    if name.endswith("."):
        return f"{name!r} ends in '.', which Windows drops from file names"
    return None


def reserved_id_reason(run_id: str) -> str | None:
    """Why `run_id` cannot name a run's output file, or None when it can.

    >>> reserved_id_reason("Summary")
    "'Summary' names a campaign output (summary.nc, summary.csv)"
    >>> reserved_id_reason("pull-01") is None
    True
    """
    taken = [name for name in CAMPAIGN_OUTPUTS if name.split(".")[0] == run_id.casefold()]
    if taken:
        return f"{run_id!r} names a campaign output ({', '.join(taken)})"
    return unportable_name_reason(run_id)
