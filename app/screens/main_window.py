"""The application window: the frame, the screens, the poller and the overlays.

Why one poller for the whole window: the snapshot is sampled once per tick and handed to the
frame and to the visible screen only; hidden screens catch up when they are shown. That keeps
a tick cheap (the benchmark measures it) whatever the number of screens.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QTimer, Signal
from PySide6.QtGui import QCloseEvent, QResizeEvent
from PySide6.QtWidgets import QMainWindow, QStackedWidget, QVBoxLayout, QWidget

from app.data.records import OPERATOR_NAME_MAX_CHARS
from app.data.users import Role, User
from app.machine.commands import ResetShiftCounter, SetUser
from app.machine.link import MachineLink
from app.machine.snapshot import MachineSnapshot
from app.screens.alarms_screen import AlarmsScreen
from app.screens.base import Screen, ScreenContext
from app.screens.chrome import AlarmBanner, NavBar, TopBar
from app.screens.i18n import LANGUAGES, LanguageManager
from app.screens.io_screen import IoScreen
from app.screens.main_screen import MainScreen
from app.screens.manual_screen import ManualScreen
from app.screens.pin_check import PinChecker
from app.screens.poller import SnapshotPoller
from app.screens.production_screen import ProductionScreen
from app.screens.recipes_screen import RecipesScreen
from app.screens.session import Session
from app.screens.system_screen import SystemScreen
from app.screens.texts import machine_text, role_text
from app.screens.theme import scale_for_size, stylesheet
from app.screens.top_bar_message import ExpiringMessage
from app.screens.widgets.dialogs import ChoiceOverlay, ConfirmOverlay
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.keypad import Keypad
from app.screens.widgets.overlay import Overlay, top_overlay

if TYPE_CHECKING:
    from app.data.database import Database

SCREEN_KEYS = ("main", "recipes", "system", "manual", "alarms", "production")
NOTICE_S = 6.0
EXIT_LEAVE_KIOSK = 64  # packaging/: the kiosk service stays down on this exit status


class MainWindow(QMainWindow):
    """``shutdownRequested`` is emitted after the operator confirmed Shut down and the link
    was closed."""

    shutdownRequested = Signal()  # noqa: N815 (Qt signal naming)

    def __init__(
        self,
        link: MachineLink,
        database: Database,
        languages: LanguageManager,
        *,
        kiosk: bool = False,
    ) -> None:
        super().__init__()
        self.setObjectName("mainWindow")
        self.link = link
        self.database = database
        self.languages = languages
        self.kiosk = kiosk
        self.scale = 0.0
        self._shutting_down = False
        self.exit_code = 0
        self._notice = ""
        self._logged_in = False
        self._plan_shifts_seen: int | None = None  # the machine's count at the last snapshot
        self._name_keyboard: TextKeyboard | None = None  # the operator's name being asked
        self.machine_message = ExpiringMessage()
        self.session = Session(self._default_user, parent=self)
        self.pin_checker = PinChecker(database.path, parent=self)

        self.host = QWidget()
        self.host.setObjectName("centralHost")
        self.setCentralWidget(self.host)
        self.top_bar = TopBar()
        self.banner = AlarmBanner()
        self.stack = QStackedWidget()
        self.nav = NavBar(SCREEN_KEYS)
        layout = QVBoxLayout(self.host)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addWidget(self.top_bar)
        # The banner's place is kept while no alarm is shown: its appearing never moves a
        # button on the screen below (START, STOP, Home and Reset stay under the finger).
        self.banner_slot = QWidget()
        self.banner_slot.setObjectName("bannerSlot")
        slot_layout = QVBoxLayout(self.banner_slot)
        slot_layout.setContentsMargins(0, 0, 0, 0)
        slot_layout.addWidget(self.banner)
        layout.addWidget(self.banner_slot)
        layout.addWidget(self.stack, 1)
        layout.addWidget(self.nav)

        self.context = ScreenContext(
            link=link,
            database=database,
            session=self.session,
            languages=languages,
            host=self.host,
            notify=self.notify,
            navigate=self.show_screen,
            require=self.require,
            new_shift=self.start_new_shift,
        )
        self.screens: dict[str, Screen] = {}
        for screen_class in (
            MainScreen,
            RecipesScreen,
            SystemScreen,
            ManualScreen,
            AlarmsScreen,
            IoScreen,
            ProductionScreen,
        ):
            screen = screen_class(self.context)
            self.screens[screen.key] = screen
            self.stack.addWidget(screen)
        self.current_key = "main"

        self.poller = SnapshotPoller(link, parent=self)
        self.poller.snapshotChanged.connect(self.on_snapshot)
        self.poller.linkLost.connect(self.on_link_lost)
        self._notice_timer = QTimer(self)
        self._notice_timer.setSingleShot(True)
        self._notice_timer.timeout.connect(self.clear_notice)
        self._clock_timer = QTimer(self)
        self._clock_timer.setInterval(1000)
        self._clock_timer.timeout.connect(self._tick)

        self.nav.navigate.connect(self.show_screen)
        self.nav.shutdownClicked.connect(self.request_shutdown)
        self.banner.clicked.connect(lambda: self.show_screen("alarms"))
        self.top_bar.userClicked.connect(self.user_menu)
        self.top_bar.languageClicked.connect(self.language_menu)
        self.session.userChanged.connect(self.on_user_changed)
        self.languages.languageChanged.connect(self._language_changed)
        self.retranslate()
        self.nav.set_current("main")
        self.apply_scale(1.0)
        self.resize(1024, 768)
        self.poller.start()
        self._clock_timer.start()
        # the records name someone from the start
        self.link.send(SetUser(self.session.name, self.session.operator_name))

    # -- screens -----------------------------------------------------------------------------

    def page(self, key: str) -> Screen:
        return self.screens[key]

    @property
    def current_screen(self) -> Screen:
        return self.screens[self.current_key]

    def show_screen(self, key: str) -> None:
        """Make the screen with this key the visible one (ValueError for an unknown key)."""
        if key not in self.screens:
            raise ValueError(f"screen {key!r} is unknown; allowed: {', '.join(self.screens)}")
        self.session.touch()
        if key != self.current_key:
            self.current_screen.deactivated()
            self.machine_message.dismiss()
            self.current_key = key
            self.stack.setCurrentWidget(self.screens[key])
            screen = self.screens[key]
            if self.poller.snapshot is not None:
                screen.update_snapshot(self.poller.snapshot, force=True)
            screen.activated()
        self.nav.set_current(key)

    def overlay(self) -> Overlay | None:
        """The overlay open over the window (keypad, keyboard, confirmation), if any."""
        return top_overlay(self.host)

    # -- machine -----------------------------------------------------------------------------

    def on_snapshot(self, snapshot: MachineSnapshot, force: bool = False) -> None:
        self._follow_plan_shifts(snapshot)
        self.top_bar.show_snapshot(snapshot, self._notice or self._machine_text(snapshot))
        self.banner.show_alarms(snapshot, self.tr("(+%1 more)"), force)
        count = len(snapshot.alarms)
        alarms_text = self.tr("Alarms") + (f" ({count})" if count else "")
        button = self.nav.buttons["alarms"]
        if button.text() != alarms_text:
            button.setText(alarms_text)
        self.current_screen.update_snapshot(snapshot, force)

    def on_link_lost(self) -> None:
        self.top_bar.show_snapshot(None, self.tr("The machine is not running."))

    def notify(self, text: str) -> None:
        """Show a line in the status bar for a few seconds (saved, refused, logged in...)."""
        self._notice = text
        self._notice_timer.start(round(NOTICE_S * 1000))
        self.top_bar.show_snapshot(self.poller.snapshot, text)

    def clear_notice(self) -> None:
        self._notice = ""
        snapshot = self.poller.snapshot
        self.top_bar.show_snapshot(snapshot, self._machine_text(snapshot) if snapshot else "")

    def _tick(self) -> None:
        """Every second: the clock, and the machine's message expires even while nothing
        else changes."""
        self.top_bar.tick_clock()
        snapshot = self.poller.snapshot
        if not self._notice and snapshot is not None:
            self.top_bar.show_snapshot(snapshot, self._machine_text(snapshot))

    def _machine_text(self, snapshot: MachineSnapshot) -> str:
        return machine_text(self.machine_message.current(snapshot.message, snapshot.message_serial))

    # -- users and language ---------------------------------------------------------------------

    def user_menu(self) -> None:
        if self.kiosk and self.session.user is not None and self.session.role >= Role.SERVICE:
            choice = ChoiceOverlay(
                self.tr("Service"),
                [(self.tr("Log out"), "logout"), (self.tr("Leave the kiosk"), "leave")],
            )
            choice.chosen.connect(self._service_choice)
            self.context.open(choice)
            return
        if self.session.user is not None and self.session.role > Role.OPERATOR:
            overlay = ConfirmOverlay(
                self.tr("Log out"),
                self.tr("Log out %1 and go back to the operator level?").replace(
                    "%1", self.session.name
                ),
                self.tr("Log out"),
            )
            overlay.finished.connect(lambda ok: self.session.logout() if ok else None)
            self.context.open(overlay)
            return
        choice = ChoiceOverlay(
            self.tr("User"),
            [
                (self.tr("Log in with a PIN"), "pin"),
                (self.tr("Name the operator of this shift"), "name"),
            ],
        )
        choice.chosen.connect(self._operator_choice)
        self.context.open(choice)

    def _operator_choice(self, choice: object) -> None:
        if choice == "pin":
            self.ask_pin(self.tr("Log in: enter your PIN"))
        elif choice == "name":
            self.ask_operator_name()

    def _follow_plan_shifts(self, snapshot: MachineSnapshot) -> None:
        """The shift plan's next shift began while the panel ran: the last shift's operator
        is forgotten and the new one is asked his name, as at New shift (the machine already
        records the new shift's boards without the old name)."""
        seen = self._plan_shifts_seen
        self._plan_shifts_seen = snapshot.plan_shifts_begun
        if seen is None or snapshot.plan_shifts_begun == seen:
            return
        if self.session.operator_name:
            self.session.name_operator("")
        if self._name_keyboard is None:
            self.ask_operator_name()

    def start_new_shift(self) -> TextKeyboard:
        """New shift: the shift's counter starts from 0 and its operator names himself. The
        last shift's name is cleared first, so no record of the new shift carries it (if
        nobody types a name, the records name the panel's user)."""
        self.link.send(ResetShiftCounter())
        if self.session.operator_name:
            self.session.name_operator("")
        return self.ask_operator_name()

    def ask_operator_name(self) -> TextKeyboard:
        """The operator names himself (no PIN at operator level): every acknowledgement,
        reset and manual action, and each board's production record, then carries his
        name."""
        keyboard = TextKeyboard(
            self.tr("Operator of this shift: your name"),
            self.session.operator_name,
            max_length=OPERATOR_NAME_MAX_CHARS,
            layout=self.context.keyboard_layout(),
        )
        keyboard.textAccepted.connect(self.session.name_operator)
        self._name_keyboard = keyboard
        keyboard.finished.connect(lambda _ok: self._name_asked(keyboard))
        self.context.open(keyboard)
        return keyboard

    def _name_asked(self, keyboard: TextKeyboard) -> None:
        if self._name_keyboard is keyboard:
            self._name_keyboard = None

    def ask_pin(self, title: str, required: Role = Role.OPERATOR) -> Keypad:
        """Open the PIN pad; a PIN below ``required`` is refused with a message."""
        pad = Keypad.for_pin(title)

        def checked(user: User | None, error: str) -> None:
            pad.set_busy(False)
            if error:
                pad.show_error(error)
            elif user is None:
                pad.show_error(self.tr("Wrong PIN."))
            elif user.role < required:
                pad.show_error(
                    self.tr("This needs the %1 level; %2 is %3.")
                    .replace("%1", role_text(required))
                    .replace("%2", user.name)
                    .replace("%3", role_text(user.role))
                )
            else:
                self.session.set_user(user)
                pad.accept()

        def entered(pin: str) -> None:
            pad.set_busy(True, self.tr("Checking…"))
            self.pin_checker.check(pin, checked)

        pad.pinEntered.connect(entered)
        self.context.open(pad)
        return pad

    def require(self, role: Role, action: Callable[[], None]) -> None:
        """Run ``action`` if the logged-in level is at least ``role``; otherwise ask for a PIN
        of that level first (and run it once one was entered)."""
        if self.session.can(role):
            action()
            return
        pad = self.ask_pin(
            self.tr("This needs the %1 level: enter a PIN").replace("%1", role_text(role)),
            required=role,
        )
        pad.finished.connect(lambda ok: action() if ok else None)

    def _default_user(self) -> User | None:
        for user in self.database.list_users():
            if user.role is Role.OPERATOR:
                return user
        return None

    def on_user_changed(self) -> None:
        self._show_user()
        self.link.send(SetUser(self.session.name, self.session.operator_name))
        was_logged_in, self._logged_in = self._logged_in, self.session.user is not None
        if self.session.user is None and not was_logged_in:
            self.notify(self.tr("Operator of this shift: %1").replace("%1", self.session.name))
        elif self.session.user is None:
            self.notify(self.tr("Logged out."))
        else:
            self.notify(
                self.tr("Logged in: %1 (%2)")
                .replace("%1", self.session.name)
                .replace("%2", role_text(self.session.role))
            )
        for screen in self.screens.values():
            screen.user_changed()

    def _show_user(self) -> None:
        if self.session.user is None:
            name = self.session.operator_name
            role = role_text(Role.OPERATOR)
            self.top_bar.show_user(f"{name} · {role}" if name else role)
        else:
            role = role_text(self.session.role)
            name = self.session.name
            same = name.casefold() in (role.casefold(), self.session.role.label)
            self.top_bar.show_user(role if same else f"{name} · {role}")

    def language_menu(self) -> None:
        overlay = ChoiceOverlay(
            self.tr("Language"),
            [(name, code) for code, name in LANGUAGES],
            current=self.languages.language,
        )
        overlay.chosen.connect(self.languages.set_language)
        self.context.open(overlay)

    def _language_changed(self, code: str) -> None:
        self.top_bar.show_language(code)

    def retranslate(self) -> None:
        titles = {
            "main": self.tr("Main"),
            "recipes": self.tr("Recipes"),
            "system": self.tr("System"),
            "manual": self.tr("Manual"),
            "alarms": self.tr("Alarms"),
            "production": self.tr("Production"),
        }
        for key, button in self.nav.buttons.items():
            button.setText(titles[key])
        self.nav.shutdown_button.setText(self.tr("Shut down"))
        self.top_bar.user_button.setToolTip(self.tr("Log in or out"))
        self.top_bar.language_button.setToolTip(self.tr("Language"))
        self.top_bar.show_language(self.languages.language)
        self.setWindowTitle(self.tr("Stave jointer"))
        self._show_user()
        snapshot = self.poller.snapshot if hasattr(self, "poller") else None
        if snapshot is not None:
            self.on_snapshot(snapshot, force=True)

    def changeEvent(self, event: QEvent) -> None:
        if event.type() == QEvent.Type.LanguageChange:
            self.retranslate()
        super().changeEvent(event)

    # -- size ----------------------------------------------------------------------------------

    def apply_scale(self, scale: float) -> None:
        """Re-style for a new scale (only when it changed: a restyle is not free)."""
        if abs(scale - self.scale) < 0.01:
            return
        self.scale = scale
        self.setStyleSheet(stylesheet(scale))
        self.top_bar.lamp.set_diameter(round(40 * scale))
        self.banner.ensurePolished()
        self.banner_slot.setFixedHeight(self.banner.sizeHint().height())
        for screen in self.screens.values():
            screen.apply_scale(scale)

    def resizeEvent(self, event: QResizeEvent) -> None:
        size = event.size()
        self.apply_scale(scale_for_size(size.width(), size.height()))
        super().resizeEvent(event)

    # -- shut down ----------------------------------------------------------------------------

    def _service_choice(self, value: object) -> None:
        if value == "logout":
            self.session.logout()
        elif value == "leave":
            overlay = ConfirmOverlay(
                self.tr("Leave the kiosk"),
                self.tr("Stop the machine safely and leave the operator screen for the console?"),
                self.tr("Leave the kiosk"),
                danger=True,
            )
            overlay.finished.connect(lambda ok: self.leave_kiosk() if ok else None)
            self.context.open(overlay)

    def leave_kiosk(self) -> None:
        """Service level: end with EXIT_LEAVE_KIOSK, which the panel's kiosk service takes as
        "stay down" (RestartPreventExitStatus), leaving a console login on the panel."""
        self.exit_code = EXIT_LEAVE_KIOSK
        self.shutdown()

    def request_shutdown(self) -> None:
        overlay = ConfirmOverlay(
            self.tr("Shut down"),
            self.tr("Stop the machine safely and close the program?"),
            self.tr("Shut down"),
            danger=True,
        )
        overlay.finished.connect(lambda ok: self.shutdown() if ok else None)
        self.context.open(overlay)

    def shutdown(self) -> None:
        """Stop polling, close the link (the machine stops safely), close the window."""
        if self._shutting_down:
            return
        self._shutting_down = True
        self.poller.stop()
        self._clock_timer.stop()
        self.link.close()
        self.shutdownRequested.emit()
        self.close()

    def closeEvent(self, event: QCloseEvent) -> None:
        if self.kiosk and not self._shutting_down:
            # In the kiosk only Shut down (with its confirmation) ends the program.
            event.ignore()
            self.request_shutdown()
            return
        self.poller.stop()
        self._clock_timer.stop()
        self.pin_checker.wait()
        super().closeEvent(event)
