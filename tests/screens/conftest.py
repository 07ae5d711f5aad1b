"""Fixtures for the screen tests: offscreen Qt, a real database, the real machine in-process.

The machine is the real machine layer (state machine, cycle, planner, simulated drives)
behind ``LocalMachineLink`` on a simulated clock: each poll of the screens advances it. No
fake machine: what the tests see is what the panel does.
"""

from __future__ import annotations

import os

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QApplication, QPushButton, QWidget

from app.data.database import Database
from app.machine.link import MachineLink
from app.machine.states import MachineState
from app.screens.i18n import LanguageManager
from app.screens.main_window import MainWindow
from tests.screens.helpers import click, wait_for

HERE = Path(__file__).resolve().parent
# The offscreen platform warns that it cannot propagate size hints whenever a top-level
# window is shown or restyled; that says nothing about the application.
OFFSCREEN_NOISE = "This plugin does not support propagateSizeHints"


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if HERE in Path(str(item.fspath)).resolve().parents:
            item.add_marker(pytest.mark.qt_log_ignore(OFFSCREEN_NOISE))


def _uninstall_left_translators() -> None:
    """A window an earlier test closed is only scheduled for deletion (deleteLater, and no
    event loop runs between tests): its translator stays installed and would translate the
    texts of the next test, whichever test file ran before on this worker."""
    if QApplication.instance() is None:
        return
    # Delete now what earlier tests closed (pytest-qt's deleteLater): a closed window left
    # alive would still receive the next test's language change and read its closed database.
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    for widget in QApplication.topLevelWidgets():
        for manager in widget.findChildren(LanguageManager):
            manager.uninstall()


@pytest.fixture(autouse=True)
def source_language() -> Iterator[None]:
    """Every screen test starts, and leaves the application, in the source language."""
    _uninstall_left_translators()
    yield
    _uninstall_left_translators()


@pytest.fixture(scope="session")
def template_db(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """One brand-new database per session (hashing the default PINs takes a moment)."""
    path = tmp_path_factory.mktemp("screens-template") / "template.db"
    Database.open(path).close()
    return path


@pytest.fixture
def db_path(template_db: Path, tmp_path: Path) -> Path:
    path = tmp_path / "stave.db"
    shutil.copyfile(template_db, path)
    return path


@pytest.fixture
def database(db_path: Path) -> Iterator[Database]:
    """The panel's database, with the machine's travel limits (as the application opens it)."""
    from app.config import load_config
    from app.machine.process_params import stave_limits

    db = Database.open(db_path, limits=stave_limits(load_config()))
    yield db
    db.close()


@pytest.fixture
def host(qtbot) -> QWidget:
    """A window-sized widget, themed, to open overlays on."""
    from app.screens.theme import stylesheet

    widget = QWidget()
    widget.setObjectName("centralHost")
    widget.setStyleSheet(stylesheet(1.0))
    widget.resize(1024, 768)
    qtbot.addWidget(widget)
    widget.show()
    return widget


@pytest.fixture
def tap(qtbot) -> Callable[[QPushButton], None]:
    """Tap a button as a finger would."""
    return lambda button: click(qtbot, button)


@pytest.fixture
def machine(db_path: Path) -> Iterator[MachineLink]:
    """The real machine layer in-process on a simulated clock (advanced by each poll)."""
    from app.config import load_config
    from app.machine.local_link import LocalMachineLink

    link = LocalMachineLink.create(load_config(), db_path, advance_per_poll_s=0.25)
    yield link
    link.close()


@pytest.fixture
def window(qtbot, machine: MachineLink, database: Database) -> MainWindow:
    """The application window on that machine, 1024x768, polling as fast as it can."""
    from app.screens.application import create_main_window

    created = create_main_window(machine, database)
    assert isinstance(created, MainWindow)
    qtbot.addWidget(created)
    created.resize(1024, 768)
    created.show()
    created.poller.set_interval_ms(0)  # run the simulated machine as fast as it goes
    wait_for(qtbot, created, lambda s: s.state is not MachineState.POWER_UP)
    return created
