"""A fingerprint of the code that computes results.

A stored result is reused only when it was made from the same inputs by the
same code. The version string alone does not say that: a changed algorithm
installed at the same version (an editable install, a patched copy on a lab
PC) would be served from cache. The fingerprint hashes the package's own files
(sources, templates, data tables), so any change to them makes every stored
result stale.
"""

from __future__ import annotations

import hashlib
from functools import cache
from pathlib import Path

#: The package folder whose files make the fingerprint.
PACKAGE = Path(__file__).resolve().parents[1]
#: Files that do not change what the code computes.
IGNORED_SUFFIXES = frozenset({".pyc", ".pyo"})


def _package_files(root: Path) -> list[Path]:
    return sorted(
        path for path in root.rglob("*")
        if path.is_file() and path.suffix not in IGNORED_SUFFIXES
        and "__pycache__" not in path.parts
    )


@cache
def code_fingerprint(root: Path = PACKAGE) -> str:
    """SHA-256 over the relative paths and bytes of every file of the package.

    Computed once per process (the package does not change while it runs).

    Parameters
    ----------
    root : Path
        The package folder (default: the installed ``pipeline`` package).

    Returns
    -------
    str
        Hex digest; equal for byte-identical packages on any operating system.
    """
    digest = hashlib.sha256()
    for path in _package_files(root):
        digest.update(path.relative_to(root).as_posix().encode())
        digest.update(b"\0")
        digest.update(path.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()
