"""The language switch: English (the source language) and Slovenian, at runtime.

Why runtime switching: the panel is shared by people who prefer different languages; a switch
must not need a restart (which would stop the machine's GUI). Installing a QTranslator makes
Qt send every widget a LanguageChange event; each screen re-sets its texts in ``retranslate``.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QTranslator, Signal

from app.resources import resource_path

SOURCE_LANGUAGE = "en"
LANGUAGES: tuple[tuple[str, str], ...] = (("en", "English"), ("sl", "Slovenščina"))
LANGUAGE_CODES = tuple(code for code, _ in LANGUAGES)


def translation_file(code: str) -> str:
    return str(resource_path("translations", f"stave_{code}.qm"))


class LanguageManager(QObject):
    """Holds the installed translator; ``languageChanged(str)`` after a switch."""

    languageChanged = Signal(str)  # noqa: N815 (Qt signal naming)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.language = SOURCE_LANGUAGE
        self._translator: QTranslator | None = None

    def set_language(self, code: str) -> None:
        """Switch to ``code`` ("en" or "sl"); ValueError names the allowed codes."""
        if code not in LANGUAGE_CODES:
            raise ValueError(
                f"language {code!r} is not available; allowed: {', '.join(LANGUAGE_CODES)}"
            )
        app = QCoreApplication.instance()
        if app is None:
            raise RuntimeError("set_language needs a QApplication")
        if self._translator is not None:
            QCoreApplication.removeTranslator(self._translator)
            self._translator = None
        if code != SOURCE_LANGUAGE:
            translator = QTranslator(self)
            path = translation_file(code)
            if not translator.load(path):
                raise FileNotFoundError(f"translation file {path} could not be loaded")
            QCoreApplication.installTranslator(translator)
            self._translator = translator
        self.language = code
        # Qt posts the LanguageChange; deliver it now, so the switch is complete on return.
        QCoreApplication.sendPostedEvents(None, QEvent.Type.LanguageChange)
        self.languageChanged.emit(code)

    def next_language(self) -> str:
        index = LANGUAGE_CODES.index(self.language)
        return LANGUAGE_CODES[(index + 1) % len(LANGUAGE_CODES)]

    def uninstall(self) -> None:
        if self._translator is not None:
            QCoreApplication.removeTranslator(self._translator)
            self._translator = None
            self.language = SOURCE_LANGUAGE
