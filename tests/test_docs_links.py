"""The documentation in docs/ is whole, and nothing cites notes outside the repository.

* every relative Markdown link in ``docs/`` and ``README.md`` resolves to a file
  or folder of the repository (anchors stripped, ``http(s)`` links ignored);
* every ``docs/...`` path cited in the package, tests, notebooks, benchmarks and
  the README exists;
* no file cites the planning notes kept outside the repository, nor an issue
  number: such references are dead links for a newcomer.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
README = ROOT / "README.md"
#: Folders whose files may cite docs/ paths (and must not cite outside notes).
SOURCE_FOLDERS = ("pipeline", "tests", "notebooks", "bench")
#: Text files worth scanning; binary data and generated files are skipped.
TEXT_SUFFIXES = {".py", ".md", ".toml", ".csv", ".txt", ".html", ".j2", ".cfg", ".ini"}

#: The documentation pages other code and engineers cite by name.
REQUIRED_PAGES = (
    "docs/index.md",
    "docs/published-values.md",
    "docs/run-sheet.md",
    "docs/file-formats.md",
    "docs/outputs.md",
    "docs/quality.md",
    "docs/models/paper-000-wheel-impact.md",
    "docs/models/paper-001-link-stiffness.md",
    "docs/models/paper-002-roller-impact.md",
    "docs/models/paper-003-tooth-segments.md",
    "docs/models/paper-004-pin-criterion.md",
)

#: ``[text](target)`` and ``![alt](target "title")``; the target up to a space or ``)``.
MARKDOWN_LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
#: A ``docs/...`` path as cited in code and prose (not part of a longer path).
DOCS_PATH = re.compile(r"(?<![\w./-])docs/[\w./-]*[\w/]")

# The forbidden citations, built from pieces so that this file does not cite them.
_MD = r"\.md\b"
_NOTE_NAMES = "|".join(("models", "formats", "reference-values", "quality", "style"))
#: A planning note named bare (its name and ``.md`` alone), not as part of a longer
#: name or a path (``docs/file-formats.md`` is a page of this repository).
BARE_NOTE = re.compile(r"(?<![\w/.-])(?:" + _NOTE_NAMES + ")" + _MD)
#: The folder of the planning notes, by itself or under ``shared/``.
NOTES_FOLDER = re.compile(r"(?<![\w.-])" + "sp" + r"ec/|shared/" + "sp" + r"ec\b")
#: The notes cited by their collective name (not "the specimen", "the specified").
THE_NOTES = re.compile(r"\bthe " + "sp" + r"ec(?:'s)?\b", re.IGNORECASE)
#: An issue number, with or without "#", in any letter case.
ISSUE_NUMBER = re.compile(r"\b" + "iss" + r"ues?\s*#?\s*\d+", re.IGNORECASE)
FORBIDDEN = {
    "a planning note": BARE_NOTE,
    "the planning-notes folder": NOTES_FOLDER,
    "the planning notes": THE_NOTES,
    "an issue number": ISSUE_NUMBER,
}


def _markdown_files() -> list[Path]:
    return sorted(DOCS.rglob("*.md")) + [README]


def _source_files() -> list[Path]:
    files = [README]
    for folder in SOURCE_FOLDERS:
        files += sorted(
            path for path in (ROOT / folder).rglob("*")
            if path.is_file() and path.suffix in TEXT_SUFFIXES
            and "__pycache__" not in path.parts
        )
    return files


def _relative(path: Path) -> str:
    return path.relative_to(ROOT).as_posix()


def _links(page: Path) -> list[tuple[int, str]]:
    """(line, target) of every relative link of `page` outside fenced code blocks."""
    links, fenced = [], False
    for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for match in MARKDOWN_LINK.finditer(line):
            target = match.group(1)
            if re.match(r"^[a-z][a-z0-9+.-]*:", target, re.IGNORECASE) or target.startswith("#"):
                continue  # http(s), mailto: ... and anchors within the page
            links.append((number, target))
    return links


def test_the_documentation_pages_exist():
    missing = [page for page in REQUIRED_PAGES if not (ROOT / page).is_file()]
    assert not missing, f"docs/ lacks {missing}"


@pytest.mark.parametrize("page", _markdown_files(), ids=_relative)
def test_relative_links_resolve(page):
    broken = []
    for number, target in _links(page):
        path = target.split("#", 1)[0].split("?", 1)[0]
        if not path:
            continue
        resolved = (page.parent / path).resolve()
        if not resolved.exists():
            broken.append(f"{_relative(page)}:{number}: {target}")
    assert not broken, "broken links:\n" + "\n".join(broken)


def test_cited_docs_paths_exist():
    missing = []
    for path in _source_files():
        for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace")
                                      .splitlines(), 1):
            for match in DOCS_PATH.finditer(line):
                cited = match.group(0).split("#", 1)[0]
                if not (ROOT / cited).exists():
                    missing.append(f"{_relative(path)}:{number}: {cited}")
    assert not missing, "cited docs/ paths that do not exist:\n" + "\n".join(missing)


def _forbidden_citations(path: Path) -> list[str]:
    """Lines of `path` citing a planning note or an issue number."""
    found = []
    in_docs = path.is_relative_to(DOCS)
    for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace")
                                  .splitlines(), 1):
        for what, pattern in FORBIDDEN.items():
            for match in pattern.finditer(line):
                if in_docs and pattern is BARE_NOTE and (path.parent / match.group(0)).is_file():
                    continue  # a page of docs/ named relative to its neighbour
                found.append(f"{_relative(path)}:{number}: {what}: {match.group(0)!r}")
    return found


@pytest.mark.parametrize("folder", [*SOURCE_FOLDERS, "docs"])
def test_nothing_cites_notes_outside_the_repository_or_issue_numbers(folder):
    files = sorted(path for path in (ROOT / folder).rglob("*")
                   if path.is_file() and path.suffix in TEXT_SUFFIXES
                   and "__pycache__" not in path.parts)
    found = [line for path in files for line in _forbidden_citations(path)]
    assert not found, "\n".join(found)


def test_readme_cites_no_notes_outside_the_repository_and_points_to_the_docs():
    assert not _forbidden_citations(README)
    assert "docs/index.md" in README.read_text(encoding="utf-8")


_MD_TEXT = "." + "md"


@pytest.mark.parametrize("text", [
    "see models" + _MD_TEXT + ", section 001", "(``formats" + _MD_TEXT + "``)",
    "sp" + "ec/models" + _MD_TEXT, "../shared/" + "sp" + "ec",
    "reference-values" + _MD_TEXT + ", 004", "quality" + _MD_TEXT + "'s table",
    "style" + _MD_TEXT, "Done-when of " + "iss" + "ue 3", "(" + "iss" + "ue #12)",
    "the " + "sp" + "ec's example",
])
def test_the_patterns_catch_citations(text):
    assert any(pattern.search(text) for pattern in FORBIDDEN.values())


@pytest.mark.parametrize("text", [
    "docs/quality.md", "docs/file-formats.md", "docs/models/paper-001-link-stiffness.md",
    "the specimen table", "spec = catalog_chain(name)", "../shared/realdata",
    "safe_name('TST 2021/10 (FA) #22')", "color: #1f77b4", "# 1 kgf = 9.80665 N",
])
def test_the_patterns_leave_legitimate_text_alone(text):
    assert not any(pattern.search(text) for pattern in FORBIDDEN.values())
