"""Who is at the panel: the user level that unlocks settings, and the name for the records.

Why an operator by default and a timeout: at power-on the machine must be usable for
production without typing anything, so the panel starts at operator level; a technician or
service engineer logs in with a PIN for settings and is logged out again after ten minutes
in which nobody changed screens or opened a keypad, so a panel left unlocked does not stay
unlocked.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, QTimer, Signal

from app.data.users import Role, User

IDLE_LOGOUT_S = 600.0

DefaultUser = Callable[[], "User | None"]


class Session(QObject):
    """The logged-in user (None: the anonymous operator level); ``userChanged`` on change."""

    userChanged = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(
        self,
        default_user: DefaultUser,
        idle_logout_s: float = IDLE_LOGOUT_S,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._default_user = default_user
        self.user: User | None = None
        self.operator_name = ""  # the operator who named himself for the shift
        self._idle = QTimer(self)
        self._idle.setSingleShot(True)
        self._idle.setInterval(round(idle_logout_s * 1000))
        self._idle.timeout.connect(self.logout)

    @property
    def role(self) -> Role:
        return self.user.role if self.user is not None else Role.OPERATOR

    @property
    def name(self) -> str:
        """Who the records and the machine log name: the logged-in user, else the operator
        who named himself, else the operator level's account."""
        if self.user is not None:
            return self.user.name
        return self.operator_name or "operator"

    def name_operator(self, name: str) -> None:
        """At operator level (no PIN): the operator of this shift says who he is; the name
        stays until another operator names himself (a technician's login and logout keep
        it)."""
        self.operator_name = name.strip()
        self.userChanged.emit()

    def acting_user(self) -> User | None:
        """Who the records name: the logged-in user, else the database's operator account."""
        return self.user if self.user is not None else self._default_user()

    def can(self, role: Role) -> bool:
        """True if the current level is at least ``role``."""
        return self.role >= role

    def set_user(self, user: User) -> None:
        """Make ``user`` (already authenticated) the logged-in one."""
        self.user = user
        self.touch()
        self.userChanged.emit()

    def logout(self) -> None:
        self._idle.stop()
        if self.user is not None:
            self.user = None
            self.userChanged.emit()

    def touch(self) -> None:
        """The panel was used: restart the idle timer of a logged-in user."""
        if self.user is not None and self.user.role > Role.OPERATOR:
            self._idle.start()
