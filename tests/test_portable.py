"""The package stays portable to Windows, checked on any system.

chainbench runs on Windows lab PCs, while CI runs on Linux, where a POSIX-only
module or call works and goes unnoticed. These tests read the package's source
and fail on such uses, and import every module with the POSIX-only modules
made unimportable, as on Windows.

A use that is truly needed must stay behind a portable library (as the campaign
lock does with ``filelock``); a platform branch may reach a POSIX-only function
through ``getattr(os, name, None)``, which this check does not flag.
"""

from __future__ import annotations

import ast
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import pipeline

PACKAGE = Path(pipeline.__file__).parent

#: Standard modules that exist on POSIX systems only.
POSIX_MODULES = frozenset({"fcntl", "termios", "tty", "pty", "pwd", "grp", "resource", "posix",
                           "syslog"})

#: Attributes of standard modules that exist on POSIX systems only.
POSIX_ATTRIBUTES = {
    "os": frozenset({
        "fork", "forkpty", "pread", "pwrite", "preadv", "pwritev", "getuid", "geteuid",
        "getgid", "getegid", "getgroups", "setuid", "setgid", "chown", "lchown", "fchown",
        "killpg", "getpgid", "setpgid", "setsid", "getsid", "mkfifo", "mknod", "statvfs",
        "fstatvfs", "sched_getaffinity", "getloadavg", "uname", "sync", "wait3", "wait4",
        "WNOHANG", "posix_fadvise", "posix_fallocate",
    }),
    "signal": frozenset({
        "SIGKILL", "SIGHUP", "SIGQUIT", "SIGUSR1", "SIGUSR2", "SIGALRM", "SIGCHLD",
        "SIGSTOP", "SIGCONT", "SIGPIPE", "alarm", "setitimer", "getitimer", "pause",
        "pthread_kill", "sigwait", "siginterrupt",
    }),
    "time": frozenset({"tzset"}),
}


def posix_only_uses(source: str) -> list[tuple[int, str]]:
    """``(line, what)`` of every POSIX-only import or attribute in `source`."""
    tree = ast.parse(source)
    aliases: dict[str, str] = {}  # local name -> module of POSIX_ATTRIBUTES it names
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                top = alias.name.split(".")[0]
                if top in POSIX_MODULES:
                    found.append((node.lineno, f"import {alias.name}"))
                if alias.name in POSIX_ATTRIBUTES:
                    aliases[alias.asname or alias.name] = alias.name
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            top = node.module.split(".")[0]
            if top in POSIX_MODULES:
                found.append((node.lineno, f"from {node.module} import ..."))
            for alias in node.names:
                if alias.name in POSIX_ATTRIBUTES.get(node.module, ()):
                    found.append((node.lineno, f"{node.module}.{alias.name}"))
    for node in ast.walk(tree):
        if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                and node.value.id in aliases
                and node.attr in POSIX_ATTRIBUTES[aliases[node.value.id]]):
            found.append((node.lineno, f"{aliases[node.value.id]}.{node.attr}"))
    return sorted(found)


def package_sources() -> list[Path]:
    return sorted(PACKAGE.rglob("*.py"))


@pytest.mark.parametrize("source, expected", [
    ("import fcntl", ["import fcntl"]),
    ("import os\nos.pread(3, 1, 0)", ["os.pread"]),
    ("import os as o\no.fork()", ["os.fork"]),
    ("from os import getuid", ["os.getuid"]),
    ("import signal\nprocess.send_signal(signal.SIGKILL)", ["signal.SIGKILL"]),
    ("from resource import getrusage", ["from resource import ..."]),
    ("import os\nos.replace(a, b)\nos.getpid()", []),
    ("import signal\nsignal.signal(signal.SIGINT, handler)\nsignal.SIGTERM", []),
    ("import os\nfork = getattr(os, 'fork', None)", []),
], ids=["import", "call", "aliased module", "from import", "signal", "from module import",
        "portable os", "portable signal", "guarded getattr"])
def test_the_check_finds_posix_only_uses(source, expected):
    assert [what for _, what in posix_only_uses(source)] == expected


def test_package_uses_no_posix_only_module_or_call():
    assert len(package_sources()) > 10  # the walk did find the package
    found = [
        f"{path.relative_to(PACKAGE.parent).as_posix()}:{line}: {what}"
        for path in package_sources()
        for line, what in posix_only_uses(path.read_text(encoding="utf-8"))
    ]
    assert not found, "POSIX-only code (the package must run on Windows):\n" + "\n".join(found)


IMPORT_ALL = textwrap.dedent("""
    import importlib, pkgutil, sys, warnings
    for name in sys.argv[1:]:
        sys.modules[name] = None  # as on Windows: importing it raises ImportError
    warnings.simplefilter("ignore")
    import pipeline
    failed = []
    for module in pkgutil.walk_packages(pipeline.__path__, "pipeline."):
        if module.name.rsplit(".", 1)[-1] == "__main__":
            continue
        try:
            importlib.import_module(module.name)
        except Exception as error:
            failed.append(f"{module.name}: {error!r}")
    print("\\n".join(failed))
""")


def test_every_module_imports_without_posix_only_modules():
    # posix itself stays: the standard library imports it on a POSIX system.
    blocked = sorted(POSIX_MODULES - {"posix"})
    result = subprocess.run([sys.executable, "-c", IMPORT_ALL, *blocked], capture_output=True,
                            text=True, cwd=PACKAGE.parent, timeout=300)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "", "modules that do not import:\n" + result.stdout
