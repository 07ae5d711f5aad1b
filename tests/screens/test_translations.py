"""Slovenian is complete: every text of the screens and of the catalogues they show is
translated in the .ts source, the compiled .qm is loadable, and switching the language at
runtime retranslates the visible screen."""

from __future__ import annotations

import ast
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from PySide6.QtCore import QCoreApplication, QTranslator

from app.resources import resource_path
from app.screens.catalogue_text import catalogue_texts
from app.screens.i18n import LanguageManager

TS_SL = resource_path("translations", "stave_sl.ts")
SCREENS = Path(__file__).resolve().parents[2] / "app" / "screens"
PLACEHOLDER = re.compile(r"%\d")


def messages(path: Path) -> dict[tuple[str, str], ET.Element]:
    tree = ET.parse(path)
    found: dict[tuple[str, str], ET.Element] = {}
    for context in tree.getroot().iter("context"):
        name = context.findtext("name", "")
        for message in context.iter("message"):
            found[(name, message.findtext("source", ""))] = message
    return found


def test_every_slovenian_message_is_translated() -> None:
    found = messages(TS_SL)
    assert len(found) > 250
    problems: list[str] = []
    for (context, source), message in found.items():
        translation = message.find("translation")
        text = "" if translation is None else (translation.text or "")
        if translation is None or translation.get("type") in ("unfinished", "vanished", "obsolete"):
            problems.append(f"{context}: {source!r} is not finished")
        elif not text.strip():
            problems.append(f"{context}: {source!r} has no translation")
        elif sorted(PLACEHOLDER.findall(text)) != sorted(PLACEHOLDER.findall(source)):
            problems.append(f"{context}: {source!r} -> {text!r} changes the placeholders")
    assert problems == []


def test_every_catalogue_text_is_in_the_translation_source() -> None:
    """Alarm titles, refusal reasons and parameter descriptions come from other layers:
    if one is added or reworded there, run resources/translations/update.py and translate."""
    found = messages(TS_SL)
    missing = [
        f"{context}: {text!r}"
        for context, texts in catalogue_texts().items()
        for text in texts
        if (context, text) not in found
    ]
    assert missing == []


def screen_texts() -> list[tuple[str, str]]:
    """(file, text) of every literal passed to tr(), translate() or QT_TRANSLATE_NOOP() in
    app/screens (found on the syntax tree, so concatenated literals count as one)."""
    found: list[tuple[str, str]] = []
    for path in SCREENS.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if not isinstance(node, ast.Call):
                continue
            func = node.func
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            index = {"tr": 0, "translate": 1, "QT_TRANSLATE_NOOP": 1}.get(name)
            if index is None or len(node.args) <= index:
                continue
            argument = node.args[index]
            if isinstance(argument, ast.Constant) and isinstance(argument.value, str):
                found.append((path.name, argument.value))
    return found


def test_every_screen_text_is_in_the_translation_source() -> None:
    """The .ts was refreshed after the last change of the screens' texts (run
    resources/translations/update.py): every literal of app/screens is in it."""
    texts = screen_texts()
    assert len(texts) > 200
    sources = {source for _context, source in messages(TS_SL)}
    missing = [f"{name}: {text!r}" for name, text in texts if text not in sources]
    assert missing == []


@pytest.mark.parametrize("language", ["en", "sl"])
def test_compiled_translations_load(qapp, language: str) -> None:
    translator = QTranslator()
    assert translator.load(str(resource_path("translations", f"stave_{language}.qm")))
    if language == "sl":
        QCoreApplication.installTranslator(translator)
        try:
            assert QCoreApplication.translate("MainWindow", "Recipes") == "Recepti"
            assert QCoreApplication.translate("States", "READY") == "PRIPRAVLJEN"
        finally:
            QCoreApplication.removeTranslator(translator)


def test_unknown_language_is_refused_with_the_allowed_ones(qapp) -> None:
    manager = LanguageManager()
    with pytest.raises(ValueError, match=r"'de'.*en, sl"):
        manager.set_language("de")
