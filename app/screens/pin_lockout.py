"""The PIN lockout on the System screen: while PIN entry is locked (alarm W104), a line saying
until when, and the service level's button that lifts it.

Why on the panel: the lockout is shared by the panel, the command line and every other
program on the database, so wrong PINs typed elsewhere lock the panel too; a service engineer
who is logged in must be able to lift it where they stand, not only with
``stave db unlock-pins`` at a terminal. The unlock is the database's own service-level
action: role-checked, and logged with the user in the alarm history (W104 back to normal).
"""

from __future__ import annotations

from datetime import UTC, datetime

from PySide6.QtWidgets import QFrame, QHBoxLayout, QWidget

from app.data.errors import DataError
from app.data.users import Role
from app.screens.base import ScreenContext
from app.screens.formatting import format_clock
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.readouts import set_text, styled_label

UNLOCK_ROLE = Role.SERVICE


class PinLockoutBar(QFrame):
    """Hidden while PIN entry is open; :meth:`refresh` reads the lockout from the database."""

    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("pinLockoutBar")
        self.context = context
        self.text_label = styled_label("", "caption", "pinLockoutText")
        self.text_label.setWordWrap(True)
        self.unlock_button = touch_button("unlockPinEntry", "danger")
        self.unlock_button.clicked.connect(self.request_unlock)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(10, 4, 10, 4)
        layout.addWidget(self.text_label, 1)
        layout.addWidget(self.unlock_button)
        self.locked_until: datetime | None = None
        self.setVisible(False)

    def refresh(self) -> None:
        """Show the bar while a lockout lasts (the database's clock is the judge)."""
        until = self.context.database.pin_guard_state().locked_until
        self.locked_until = until if until is not None and until > datetime.now(UTC) else None
        self.retranslate()
        self.setVisible(self.locked_until is not None)

    def retranslate(self) -> None:
        self.unlock_button.setText(self.tr("Unlock PIN entry"))
        if self.locked_until is not None:
            set_text(
                self.text_label,
                self.tr(
                    "PIN entry is locked after repeated wrong PINs until %1. "
                    "A service user can unlock it now."
                ).replace("%1", format_clock(self.locked_until)),
            )
        self.unlock_button.setEnabled(self.context.session.can(UNLOCK_ROLE))

    def request_unlock(self) -> None:
        self.context.require(UNLOCK_ROLE, self.unlock)

    def unlock(self) -> None:
        user = self.context.session.user
        if user is None:
            return
        try:
            self.context.database.unlock_pin_entry(user)
        except DataError as exc:
            self.context.notify(str(exc))
            return
        self.refresh()
        self.context.notify(self.tr("PIN entry unlocked by %1 (logged).").replace("%1", user.name))
