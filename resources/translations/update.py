"""Refresh the translation sources from the code and compile them.

    .venv/bin/python resources/translations/update.py

1. writes ``catalogue_strings.py`` here: the alarm titles, refusal reasons and parameter
   descriptions of the other layers (see ``app.screens.catalogue_text``), for lupdate;
2. runs ``pyside6-lupdate`` over ``app/screens`` and that file into ``stave_en.ts`` (English,
   the source language: every translation is the source text) and ``stave_sl.ts``
   (Slovenian: new texts arrive unfinished; translate them with ``pyside6-linguist``);
3. runs ``pyside6-lrelease`` to make the ``.qm`` files the application loads;
4. prints how many Slovenian texts are still unfinished (the tests fail while any is).
"""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
BIN = Path(sys.executable).parent
LANGUAGES = ("en", "sl")


def sources() -> list[str]:
    files = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "app" / "screens").rglob("*.py"))
    return [*files, str((HERE / "catalogue_strings.py").relative_to(ROOT))]


def fill_english(path: Path) -> None:
    """English is the source language: its translation of every text is the text itself."""
    tree = ET.parse(path)
    for message in tree.getroot().iter("message"):
        source = message.find("source")
        translation = message.find("translation")
        if source is None or translation is None:
            continue
        translation.text = source.text
        translation.attrib.pop("type", None)
    body = ET.tostring(tree.getroot(), encoding="unicode")
    path.write_text(
        f'<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n{body}\n', encoding="utf-8"
    )


def unfinished(path: Path) -> list[str]:
    tree = ET.parse(path)
    missing: list[str] = []
    for context in tree.getroot().iter("context"):
        name = context.findtext("name", "")
        for message in context.iter("message"):
            translation = message.find("translation")
            if (
                translation is None
                or translation.get("type") in ("unfinished",)
                or not (translation.text or "").strip()
            ):
                missing.append(f"{name}: {message.findtext('source', '')}")
    return missing


def main() -> int:
    sys.path.insert(0, str(ROOT))
    from app.screens.catalogue_text import as_python_source

    generated = HERE / "catalogue_strings.py"
    generated.write_text(as_python_source(), encoding="utf-8")
    ruff = BIN / "ruff"
    if ruff.exists():  # keep the generated file as the linters want it
        subprocess.run([str(ruff), "format", "--quiet", str(generated)], check=False)
    for language in LANGUAGES:
        ts = HERE / f"stave_{language}.ts"
        subprocess.run(
            [
                str(BIN / "pyside6-lupdate"),
                "-no-obsolete",
                "-locations",
                "relative",
                "-source-language",
                "en",
                "-target-language",
                language,
                *sources(),
                "-ts",
                str(ts),
            ],
            cwd=ROOT,
            check=True,
        )
        if language == "en":
            fill_english(ts)
        subprocess.run(
            [str(BIN / "pyside6-lrelease"), str(ts), "-qm", str(ts.with_suffix(".qm"))],
            cwd=ROOT,
            check=True,
        )
    missing = unfinished(HERE / "stave_sl.ts")
    for line in missing:
        print(f"untranslated: {line}")
    print(f"{len(missing)} Slovenian texts unfinished")
    return 1 if missing else 0


if __name__ == "__main__":
    raise SystemExit(main())
