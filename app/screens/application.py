"""Start the operator application: QApplication, theme, translator, the window, the loop.

Why a function that takes the link and the database: the caller (``python -m app``) decides
whether the machine runs in its own process or in-process on a simulated clock, and where the
database is; the screens work the same either way.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QMainWindow

from app.machine.link import MachineLink
from app.screens.i18n import LanguageManager
from app.screens.main_window import MainWindow
from app.screens.theme import apply_palette

if TYPE_CHECKING:
    from app.data.database import Database


def ensure_application() -> QApplication:
    """The running QApplication, created (with the theme's palette and font) if needed."""
    app = QApplication.instance()
    if app is None:
        app = QApplication([])
        app.setApplicationName("Stave jointer")
    assert isinstance(app, QApplication)
    apply_palette(app)
    return app


def create_main_window(
    link: MachineLink, database: Database, *, language: str = "en", kiosk: bool = False
) -> QMainWindow:
    """The application window on ``link`` and ``database`` in ``language`` ("en" or "sl").

    Needs a QApplication (see :func:`ensure_application`). In kiosk mode the window has no
    decorations and only Shut down (with confirmation) closes it."""
    app = ensure_application()
    languages = LanguageManager(app)
    languages.set_language(language)
    window = MainWindow(link, database, languages, kiosk=kiosk)
    languages.setParent(window)
    if kiosk:
        window.setWindowFlags(window.windowFlags() | Qt.WindowType.FramelessWindowHint)
    return window


def show_full_screen(window: QMainWindow) -> None:
    """Cover the whole screen the window is on, with or without a window manager.

    Why the geometry first: full screen is a request to the window manager (the EWMH
    ``_NET_WM_STATE_FULLSCREEN`` on X11); a kiosk X server often runs none, and then the request
    goes unanswered and the window stays at its default size in a corner. A frameless window
    placed over the screen's geometry covers it either way, and a window manager that is
    there makes it full screen as asked."""
    window.setGeometry(window.screen().geometry())
    window.showFullScreen()


def run_gui(
    link: MachineLink, database: Database, *, language: str = "en", kiosk: bool = False
) -> int:
    """Show the window and run the event loop; returns the exit code. Shut down (confirmed)
    closes the link, so the machine stops safely, and ends the loop."""
    app = ensure_application()
    window = create_main_window(link, database, language=language, kiosk=kiosk)
    assert isinstance(window, MainWindow)
    window.shutdownRequested.connect(lambda: app.exit(window.exit_code))
    if kiosk:
        show_full_screen(window)
    else:
        window.show()
    code = app.exec()
    if link.alive():
        link.close()
    return int(code)
