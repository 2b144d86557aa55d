"""Whether a campaign's outputs are current, decided with the standard library alone.

A re-run with nothing changed should cost almost nothing: reading the run
sheet, looking at the raw files and printing what the last run printed. This
module does that without importing pandas, xarray, lmfit or matplotlib, so
``chainbench run`` answers in a fraction of a second when nothing changed, and
loads the stages only when something must be computed.

Two records in a campaign's output folder (``docs/outputs.md``):

* ``.hashes.json`` (:data:`~pipeline.store.layout.HASHES`), the raw files'
  SHA-256 (kept for provenance), each with the file's size, modification time
  and inode it was computed at: a file whose three are unchanged is not read
  again (:class:`HashCache`; ``--rehash`` reads every file).
* ``.rerun.json`` (:data:`~pipeline.store.layout.RERUN`, :func:`write_rerun`),
  written by ``chainbench run`` after the campaign's outputs: the run sheet's
  SHA-256, the identity of every input (raw files, the summaries of the
  campaigns a stiffness is taken from) and of every output, the code
  fingerprint, the manifest's key, and what a re-run with nothing changed
  prints. :func:`current_rerun` gives it back only when every one of them
  still holds; anything else (a changed byte, a touched or replaced file, a
  deleted output, other code) sends the run down the full path.
"""

from __future__ import annotations

import hashlib
import json
import os
import tomllib
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from pipeline.store import layout
from pipeline.store.fingerprint import code_fingerprint
from pipeline.store.layout import PROCESSED_FOLDER, RUN_SHEET_NAME, project_root


def identity(path: Path) -> list[int]:
    """Size [bytes], modification time [ns] and inode of a file: what changes when it does."""
    stat = os.stat(path)
    return [stat.st_size, stat.st_mtime_ns, stat.st_ino]


def _identity_if_any(path: Path) -> list[int] | None:
    """:func:`identity` of a file, None when there is none."""
    try:
        return identity(path)
    except FileNotFoundError:
        return None


def sha256_file(path: Path) -> str:
    """SHA-256 hex digest of a file's bytes, read in blocks of 1 MiB."""
    digest = hashlib.sha256()
    with open(path, "rb") as stream:
        for block in iter(lambda: stream.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


@dataclass(frozen=True)
class HashedFile:
    """A file's SHA-256 and its identity (size, modification time, inode) when read."""

    identity: list[int]
    sha256: str


def hash_file(path: Path) -> HashedFile:
    """Read `path` for its SHA-256, with its identity taken before the read."""
    now = identity(path)
    return HashedFile(now, sha256_file(path))


def _read_json(path: Path) -> dict:
    """The JSON object in `path`, or an empty dict when it is missing or unreadable."""
    try:
        found = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return found if isinstance(found, dict) else {}


def _write_json(document: dict, path: Path) -> None:
    """Write `document` to `path` through a temporary file and a rename.

    Raises
    ------
    OSError
        When it cannot be written (the temporary file is removed).
    """
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        temporary.write_text(json.dumps(document, indent=1, sort_keys=True), encoding="utf-8")
        os.replace(temporary, path)
    except OSError:
        temporary.unlink(missing_ok=True)
        raise


class HashCache:
    """The raw files' SHA-256 of one output folder, keyed by the files' identities.

    Parameters
    ----------
    folder : Path
        The campaign's output folder (the cache is :data:`~pipeline.store.layout.HASHES` in it).
    rehash : bool
        Read every file again, whatever the cache holds.
    """

    def __init__(self, folder: Path, rehash: bool = False) -> None:
        self.path = Path(folder) / layout.HASHES
        self.rehash = rehash
        self.entries: dict[str, dict] = {} if rehash else _read_json(self.path)
        self.changed = False

    def cached(self, file: Path) -> str | None:
        """SHA-256 of `file` when the cache holds it for its size, time and inode, else None."""
        entry = self.entries.get(str(Path(file).resolve()))
        if entry is not None and entry.get("identity") == identity(file):
            return entry["sha256"]
        return None

    def remember(self, file: Path, hashed: HashedFile) -> None:
        """Keep the SHA-256 of `file` (computed elsewhere, e.g. in a run's task)."""
        self.entries[str(Path(file).resolve())] = {"identity": hashed.identity,
                                                   "sha256": hashed.sha256}
        self.changed = True

    def sha256(self, file: Path) -> str:
        """SHA-256 of `file`: from the cache when its size, time and inode are unchanged."""
        digest = self.cached(file)
        if digest is None:
            hashed = hash_file(file)
            self.remember(file, hashed)
            digest = hashed.sha256
        return digest

    def save(self) -> None:
        """Write the cache when it learnt something (call while holding the folder's lock).

        A cache that cannot be written costs only reading the files again next
        time: the failure is left to the outputs, whose writes report it.
        """
        if self.changed and self.path.parent.is_dir():
            try:
                _write_json(self.entries, self.path)
            except OSError:
                return
            self.changed = False


def run_sheet_path(campaign: Path) -> Path:
    """The run sheet of a campaign folder, or `campaign` itself when it is the run sheet."""
    campaign = Path(campaign)
    return campaign if campaign.name == RUN_SHEET_NAME and campaign.is_file() else (
        campaign / RUN_SHEET_NAME)


@dataclass(frozen=True)
class Rerun:
    """What a re-run with nothing changed prints (:func:`current_rerun`).

    Attributes
    ----------
    text : str
        The console output.
    document : dict
        The ``--json`` document.
    exit_code : int
        The exit status the run had.
    output : Path
        The campaign's output folder.
    """

    text: str
    document: dict
    exit_code: int
    output: Path


def _identities(paths: Iterable[Path]) -> dict[str, list[int] | None]:
    return {str(Path(path).resolve()): _identity_if_any(path) for path in paths}


def write_rerun(output: Path, sheet_file: Path, inputs: Iterable[Path], text: str,
                document: dict, exit_code: int) -> None:
    """Record what a re-run of the campaign with nothing changed checks and prints.

    Parameters
    ----------
    output : Path
        The campaign's output folder, its outputs and manifest just written.
    sheet_file : Path
        The run sheet.
    inputs : iterable of Path
        Every file the outputs were computed from besides the run sheet (raw
        files, summaries of other campaigns), and those that must stay absent
        (recorded as such).
    text : str
        The console output of a run that found nothing to do.
    document : dict
        The ``--json`` document of such a run.
    exit_code : int
        Its exit status.
    """
    output = Path(output)
    manifest = _read_json(output / layout.MANIFEST)
    outputs = [output / name for name in manifest.get("outputs", [])]
    outputs += sorted(path for path in output.glob("*.nc") if path.name != layout.SUMMARY)
    _write_json({
        "run_sheet": {"path": str(Path(sheet_file).resolve()),
                      "sha256": sha256_file(sheet_file)},
        "inputs": _identities(inputs), "outputs": _identities(outputs),
        "manifest": manifest.get("input_key"), "code": code_fingerprint(),
        "text": text, "document": document, "exit_code": exit_code,
    }, output / layout.RERUN)


def forget_rerun(output: Path) -> None:
    """Remove the re-run record (before anything in the folder is rewritten)."""
    (Path(output) / layout.RERUN).unlink(missing_ok=True)


def _unchanged(recorded: dict) -> bool:
    """Whether every file of `recorded` (path -> identity, None: absent) still has that
    identity."""
    try:
        return all(_identity_if_any(Path(path)) == value for path, value in recorded.items())
    except OSError:
        return False


def campaign_output(campaign: Path, output_root: Path | None = None) -> Path | None:
    """The output folder of a campaign, from its run sheet's ``[campaign] id``.

    None when the run sheet cannot be read or has no id (the full path then
    says what is wrong with it).
    """
    try:
        with open(run_sheet_path(campaign), "rb") as stream:
            campaign_id = tomllib.load(stream)["campaign"]["id"]
    except (OSError, tomllib.TOMLDecodeError, KeyError, TypeError):
        return None
    if not isinstance(campaign_id, str):
        return None
    root = Path(output_root) if output_root is not None else (
        project_root(Path(campaign)) / PROCESSED_FOLDER)
    return root / campaign_id


def current_rerun(campaign: Path, output_root: Path | None = None) -> Rerun | None:
    """What a re-run prints, when nothing the campaign's outputs depend on changed.

    Parameters
    ----------
    campaign : Path
        The campaign folder or its run sheet.
    output_root : Path, optional
        The root of the outputs (``--output``); by default ``processed/``
        beside the project's ``raw/``.

    Returns
    -------
    Rerun or None
        None when anything differs from the record: the run sheet's bytes, the
        identity of an input or output file, the code, the manifest; or when
        there is no record.
    """
    output = campaign_output(campaign, output_root)
    if output is None:
        return None
    record = _read_json(output / layout.RERUN)
    sheet = run_sheet_path(campaign)
    try:
        same_sheet = (record.get("run_sheet", {}).get("path") == str(sheet.resolve())
                      and sha256_file(sheet) == record["run_sheet"]["sha256"])
    except (OSError, KeyError):
        return None
    manifest = _read_json(output / layout.MANIFEST).get("input_key")
    if not (same_sheet and manifest is not None and manifest == record.get("manifest")
            and _unchanged(record.get("inputs", {})) and _unchanged(record.get("outputs", {}))
            and record.get("code") == code_fingerprint()):
        return None
    return Rerun(record["text"], record["document"], int(record["exit_code"]), output)
