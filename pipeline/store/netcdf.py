"""Writing and reading result datasets as netCDF4, atomically, with provenance.

Every dataset chainbench writes carries CF-1.10 global attributes and the
provenance of its inputs (``docs/outputs.md``): ``Conventions``, ``title``,
``history``, ``source``, ``chainbench_version``, ``raw_file``, ``raw_sha256``,
``run_sheet_sha256``, ``created`` and the run's run-sheet entry (as JSON).
A file is written to a temporary name in the target folder and renamed into
place, so a crash never leaves a half-written result.
"""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

import netCDF4
import xarray as xr

from pipeline import __version__
from pipeline.errors import OutputError

CONVENTIONS = "CF-1.10"

#: Permissions of written outputs (``mkstemp`` creates its files private: 0600).
FILE_MODE = 0o644


def provenance_attrs(
    *,
    title: str,
    source: str,
    run_sheet_sha256: str,
    raw_file: str = "",
    raw_sha256: str = "",
    run_entry: Mapping[str, Any] | None = None,
    created: datetime | None = None,
) -> dict[str, str]:
    """The global attributes every chainbench dataset carries.

    Parameters
    ----------
    title : str
        What the dataset holds.
    source : str
        Where the data come from (machine, or "chainbench virtual test bench").
    run_sheet_sha256 : str
        SHA-256 of the run sheet the run was processed with.
    raw_file, raw_sha256 : str
        The raw file's name (relative to the campaign) and its SHA-256.
    run_entry : mapping, optional
        The run's run-sheet entry, stored as JSON.
    created : datetime, optional
        Creation time (default: now, UTC).
    """
    created = created or datetime.now(UTC)
    stamp = created.strftime("%Y-%m-%dT%H:%M:%SZ")
    return {
        "Conventions": CONVENTIONS,
        "title": title,
        "history": f"{stamp} created by chainbench {__version__}",
        "source": source,
        "chainbench_version": __version__,
        "raw_file": raw_file,
        "raw_sha256": raw_sha256,
        "run_sheet_sha256": run_sheet_sha256,
        "created": stamp,
        "run_entry": json.dumps(dict(run_entry or {}), sort_keys=True, default=str),
    }


@contextmanager
def _atomic(path: Path) -> Iterator[Path]:
    """A temporary path beside `path`, renamed onto it when the block succeeds.

    The rename is atomic on one file system, so readers see the old file or
    the whole new one, never a part; on failure the temporary file is removed.
    """
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp",
                                             dir=path.parent)
    except OSError as error:
        raise _output_error(path, error) from None
    os.close(handle)
    try:
        yield Path(temporary)
        os.chmod(temporary, FILE_MODE)
        os.replace(temporary, path)
    except BaseException as error:
        Path(temporary).unlink(missing_ok=True)
        if isinstance(error, OSError):
            raise _output_error(path, error) from None
        raise


def _output_error(path: Path, error: OSError) -> OutputError:
    """`error` of writing `path` as the typed error a technician sees."""
    reason = error.strerror or str(error)
    return OutputError(f"cannot write this output ({reason})", file=path,
                       hint="check that the output folder is writable, is a folder, and that "
                            "the disk has space, and close the file in other programs (a "
                            "spreadsheet, a notebook); the previous outputs are unchanged")


def write_atomic(dataset: xr.Dataset, path: str | Path) -> Path:
    """Write `dataset` to `path` as netCDF4 via a temporary file and a rename.

    Returns
    -------
    Path
        The written file.
    """
    path = Path(path)
    with _atomic(path) as temporary:
        dataset.to_netcdf(temporary, format="NETCDF4", engine="netcdf4")
    return path


def write_text_atomic(text: str, path: str | Path) -> Path:
    """Write `text` (UTF-8) to `path` via a temporary file and a rename."""
    path = Path(path)
    with _atomic(path) as temporary:
        temporary.write_text(text, encoding="utf-8", newline="\n")
    return path


def read_dataset(path: str | Path) -> xr.Dataset:
    """Load a chainbench netCDF file fully into memory (the file is closed on return)."""
    with xr.open_dataset(path, engine="netcdf4") as dataset:
        return dataset.load()


def read_attrs(path: str | Path) -> dict[str, Any]:
    """The global attributes of a netCDF file, read cheaply (no variable is read).

    Opens the file with netCDF4 directly (no xarray decoding): what a re-run
    needs to decide whether a stored result is current, and its warnings.
    """
    with netCDF4.Dataset(path) as stored:
        return {name: stored.getncattr(name) for name in stored.ncattrs()}
