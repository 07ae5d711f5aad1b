"""The repository's text points only at documents it holds.

Why: a reference to a document outside the tree (a specification section, a note) is a dead end
for the next reader; "docs/MACHINE.md section N" must name a section that exists.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
MACHINE_DOC = REPO / "docs" / "MACHINE.md"

_SECTION_REFERENCE = re.compile(r"docs/MACHINE\.md\s+sections?\s+(\d+)(?:\s+and\s+(\d+))?")
# "lead", "lead-in" and "lead-out" are machine words (the lead's length); a person is "reported
# to the lead", "asked by the lead".
_OUTSIDE_REFERENCE = re.compile(
    r"\bspec section\b|\bthe guide\b|\bthe brief\b|\bthe issue asks\b"
    r"|\b(?:to|by|tell|ask|asked) the lead\b(?![-'])",
    re.I,
)
_ABSOLUTE_WORK_PATH = re.compile(r"(?<![\w.])/work/")


def _tracked_text_files() -> list[Path]:
    listed = subprocess.run(
        ["git", "ls-files", "-z"], cwd=REPO, capture_output=True, check=True
    ).stdout.decode()
    suffixes = {".py", ".md", ".toml", ".sh", ".txt", ".in", ".cfg"}
    return [REPO / name for name in listed.split("\0") if name and Path(name).suffix in suffixes]


def _machine_sections() -> set[int]:
    headings = re.findall(r"^## (\d+)\. ", MACHINE_DOC.read_text(encoding="utf-8"), re.M)
    return {int(number) for number in headings}


def test_machine_doc_has_its_seven_sections() -> None:
    assert _machine_sections() == set(range(1, 8))


def test_every_section_reference_names_an_existing_section() -> None:
    sections = _machine_sections()
    dangling = []
    for path in _tracked_text_files():
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in _SECTION_REFERENCE.finditer(" ".join(text.split())):
            for number in filter(None, match.groups()):
                if int(number) not in sections:
                    dangling.append(f"{path.relative_to(REPO)}: section {number}")
    assert dangling == []


def test_no_reference_to_documents_outside_the_repository() -> None:
    found = []
    for path in _tracked_text_files():
        if path == Path(__file__).resolve():
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if _OUTSIDE_REFERENCE.search(line) or _ABSOLUTE_WORK_PATH.search(line):
                found.append(f"{path.relative_to(REPO)}:{number}: {line.strip()}")
    assert found == []
