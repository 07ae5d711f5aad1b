"""What every screen shares: its context (link, database, session, overlays) and its hooks.

Why a context object: each screen needs the same few things (post a command, open a keypad
over the window, ask who is logged in); passing one object keeps the constructors short and
makes a screen testable on its own with the real link and database.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QWidget

from app.data.users import Role
from app.machine.commands import Command
from app.machine.link import MachineLink
from app.machine.snapshot import MachineSnapshot
from app.screens.i18n import LanguageManager
from app.screens.session import Session
from app.screens.texts import machine_text
from app.screens.widgets.overlay import Overlay

if TYPE_CHECKING:
    from app.data.database import Database


@dataclass
class ScreenContext:
    link: MachineLink
    database: Database
    session: Session
    languages: LanguageManager
    host: QWidget  # the window's central widget: overlays open over it
    notify: Callable[[str], None]  # a line for the status bar
    navigate: Callable[[str], None]  # switch to the screen with this key
    # run the action now if the user has the role, else after a PIN of that role was entered
    require: Callable[[Role, Callable[[], None]], None]
    # New shift: count from 0 and ask the operator of the new shift for his name
    new_shift: Callable[[], object]

    def send(self, command: Command) -> None:
        self.link.send(command)

    def open(self, overlay: Overlay) -> Overlay:
        self.session.touch()  # the panel is in use: keep a technician logged in
        overlay.open_on(self.host)
        return overlay

    def keyboard_layout(self) -> str:
        return "qwertz" if self.languages.language == "sl" else "qwerty"


def refusal(snapshot: MachineSnapshot | None, command: str) -> str:
    """Why the machine would refuse ``command`` now ("" when allowed), in the user's language."""
    if snapshot is None:
        return machine_text("no connection to the machine")
    return machine_text(snapshot.allowed.get(command))


class Screen(QWidget):
    """A page of the application. Subclasses set their texts in ``retranslate`` (called again
    on every language switch) and draw the machine in ``update_snapshot``."""

    key = ""

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("screen")
        self.context = context
        self.snapshot: MachineSnapshot | None = None

    def title(self) -> str:
        return ""

    def retranslate(self) -> None:
        """Set every visible text again (language switch)."""

    def update_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        """Show the machine as in ``snapshot``; ``force`` redraws texts that did not change."""
        self.snapshot = snapshot

    def activated(self) -> None:
        """The screen became the visible one."""

    def deactivated(self) -> None:
        """Another screen became the visible one."""

    def user_changed(self) -> None:
        """The logged-in user changed (locks and unlocks)."""

    def apply_scale(self, scale: float) -> None:
        """The theme was scaled (fixed sizes set in code follow it here)."""

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
            if self.snapshot is not None:
                self.update_snapshot(self.snapshot, force=True)
        super().changeEvent(event)
