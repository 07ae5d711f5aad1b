"""A touch file chooser for recipe import and export and the programs for other controls
(USB stick, network share, home).

Why not QFileDialog: its rows are too small for a finger and it opens as a separate window,
which a frameless kiosk cannot manage. This one shows one directory at a time in big rows,
with shortcuts to mounted USB sticks, and (for export) a file name typed on the keyboard.
"""

from __future__ import annotations

import getpass
import os
from pathlib import Path

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QWidget,
)

from app.screens.widgets.buttons import touch_button
from app.screens.widgets.keyboard import TextKeyboard
from app.screens.widgets.kinetic import kinetic_scroll
from app.screens.widgets.overlay import Overlay

EXCHANGE_DIR_ENV = "STAVE_EXCHANGE_DIR"
SUFFIXES = (".json", ".csv")


def removable_roots() -> list[Path]:
    """Mounted removable media (USB sticks), where a desktop or udisks mounts them."""
    user = getpass.getuser()
    roots: list[Path] = []
    for base in (Path("/media") / user, Path("/run/media") / user, Path("/media"), Path("/mnt")):
        try:
            roots.extend(sorted(p for p in base.iterdir() if p.is_dir() and p.name != user))
        except OSError:
            continue
    return roots


def default_exchange_dir() -> Path:
    """``$STAVE_EXCHANGE_DIR``, else the first USB stick, else the home directory."""
    override = os.environ.get(EXCHANGE_DIR_ENV, "").strip()
    if override:
        return Path(override).expanduser()
    sticks = removable_roots()
    return sticks[0] if sticks else Path.home()


class FileChooser(Overlay):
    """Pick a file (``save_name`` None) or a place and name to write one; ``suffixes`` are
    the file types shown and allowed (recipe files by default).

    ``fileChosen(str)`` carries the full path."""

    fileChosen = Signal(str)  # noqa: N815 (Qt signal naming)

    def __init__(
        self,
        title: str,
        start_dir: Path,
        *,
        save_name: str | None = None,
        keyboard_layout: str = "qwerty",
        suffixes: tuple[str, ...] = SUFFIXES,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("fileChooser")
        self.suffixes = tuple(suffix.lower() for suffix in suffixes)
        self.directory = start_dir if start_dir.is_dir() else Path.home()
        self.save_name = save_name
        self.selected: Path | None = None
        self._layout = keyboard_layout
        title_label = QLabel(title)
        title_label.setProperty("role", "title")
        self.path_label = QLabel()
        self.path_label.setProperty("role", "caption")
        self.path_label.setObjectName("pathLabel")
        self.path_label.setWordWrap(True)
        self.up_button = touch_button("upButton", text=self.tr("▲ Up"))
        self.up_button.clicked.connect(self.go_up)
        places = QHBoxLayout()
        places.addWidget(self.up_button)
        home = touch_button("homeDirButton", text=self.tr("Home"))
        home.clicked.connect(lambda: self.go_to(Path.home()))
        places.addWidget(home)
        for index, root in enumerate(removable_roots()[:3]):
            stick = touch_button(f"stick_{index}", text=root.name)
            stick.clicked.connect(lambda _=False, r=root: self.go_to(r))
            places.addWidget(stick)
        places.addStretch(1)
        self.entries = QListWidget()
        self.entries.setObjectName("fileList")
        self.entries.setMinimumSize(640, 300)
        self.entries.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.entries.itemClicked.connect(self._clicked)
        kinetic_scroll(self.entries)
        self.name_button = touch_button("fileNameButton", "field")
        self.name_button.clicked.connect(self.edit_name)
        self.name_button.setVisible(save_name is not None)
        self.error_label = QLabel()
        self.error_label.setProperty("role", "error")
        self.error_label.setObjectName("errorLabel")
        self.cancel_button = touch_button("cancelButton", text=self.tr("Cancel"))
        self.cancel_button.clicked.connect(self.reject)
        self.ok_button = touch_button(
            "okButton",
            "primary",
            self.tr("Save here") if save_name is not None else self.tr("Open"),
        )
        self.ok_button.clicked.connect(self.confirm)
        buttons = QHBoxLayout()
        buttons.addWidget(self.cancel_button)
        buttons.addWidget(self.ok_button)
        self.panel_layout.addWidget(title_label)
        self.panel_layout.addWidget(self.path_label)
        self.panel_layout.addLayout(places)
        self.panel_layout.addWidget(self.entries)
        self.panel_layout.addWidget(self.name_button)
        self.panel_layout.addWidget(self.error_label)
        self.panel_layout.addLayout(buttons)
        self.refresh()

    def go_to(self, directory: Path) -> None:
        self.directory = directory
        self.selected = None
        self.refresh()

    def go_up(self) -> None:
        self.go_to(self.directory.parent)

    def refresh(self) -> None:
        self.path_label.setText(str(self.directory))
        self.entries.clear()
        try:
            children = sorted(self.directory.iterdir(), key=lambda p: (not p.is_dir(), p.name))
        except OSError as exc:
            self.error_label.setText(str(exc))
            children = []
        for child in children:
            if child.name.startswith("."):
                continue
            if child.is_dir():
                item = QListWidgetItem(f"▸ {child.name}/")
            elif child.suffix.lower() in self.suffixes:
                item = QListWidgetItem(f"   {child.name}")
            else:
                continue
            item.setData(Qt.ItemDataRole.UserRole, str(child))
            self.entries.addItem(item)
        if self.save_name is not None:
            self.name_button.setText(self.save_name)

    def _clicked(self, item: QListWidgetItem) -> None:
        path = Path(item.data(Qt.ItemDataRole.UserRole))
        if path.is_dir():
            self.go_to(path)
            return
        self.selected = path
        self.error_label.setText("")
        if self.save_name is not None:
            self.save_name = path.name
            self.name_button.setText(path.name)

    def edit_name(self) -> None:
        keyboard = TextKeyboard(
            self.tr("File name"),
            self.save_name or "",
            max_length=80,
            layout=self._layout,
            check=self._check_name,
        )

        def accepted(text: str) -> None:
            self.save_name = text
            self.name_button.setText(text)

        keyboard.textAccepted.connect(accepted)
        host = self.parentWidget()
        if host is not None:
            keyboard.open_on(host)

    def _check_name(self, name: str) -> str:
        if "/" in name or name in (".", ".."):
            return self.tr("A file name cannot contain '/'.")
        if Path(name).suffix.lower() not in self.suffixes:
            return self.tr("The file name must end in %1.").replace(
                "%1", self.tr(" or ").join(self.suffixes)
            )
        return ""

    def chosen_path(self) -> Path | None:
        if self.save_name is not None:
            return self.directory / self.save_name
        return self.selected

    def confirm(self) -> None:
        path = self.chosen_path()
        if path is None:
            self.error_label.setText(self.tr("Choose a file first."))
            return
        if self.save_name is not None and (problem := self._check_name(self.save_name)):
            self.error_label.setText(problem)
            return
        self.fileChosen.emit(str(path))
        self.accept()
