"""The main screen's barrel panel: the barrel being raised, the closing-stave question, the
cooper's card.

Shown while the selected recipe makes barrels (round or oval). Without a barrel it offers to
start one; with one it draws the staves placed so far (``widgets.barrel_drawing``), says how
many are done, the gap left and about how many staves still close it, and - once a single
stave can close the gap - asks what the next board becomes: the closing stave now, or one more
normal stave (the machine's ``ChooseBoard``; without an answer it decides by the board's
width). Everything shown comes from the snapshot; the card is read from the database.
"""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

from PySide6.QtWidgets import QFrame, QHBoxLayout, QVBoxLayout, QWidget

from app.data.barrel_card import export_barrel_card
from app.data.errors import DataError
from app.machine.barrel_set import BoardChoice
from app.machine.barrel_view import BarrelView
from app.machine.commands import ChooseBoard, StartBarrel
from app.machine.snapshot import MachineSnapshot
from app.screens.barrel_overlay import BarrelOverlay
from app.screens.base import ScreenContext, refusal
from app.screens.formatting import format_number
from app.screens.widgets.barrel_drawing import BarrelDrawing
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.file_chooser import FileChooser, default_exchange_dir
from app.screens.widgets.readouts import ElidedLinesLabel, set_text, styled_label


class BarrelPanel(QFrame):
    def __init__(self, context: ScreenContext, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("panel")
        self.context = context
        self.view: BarrelView | None = None
        self.drawing = BarrelDrawing()
        self.drawing.tapped.connect(self.open_big_drawing)
        self.big_drawing: BarrelOverlay | None = None
        self.staves_label = styled_label("", "figure", "barrelStaves")
        self.gap_label = styled_label("", "caption", "barrelGap")
        self.left_label = styled_label("", "caption", "barrelLeft")
        # Two lines kept, wrapped to the column's width and never widening it.
        self.question_label = ElidedLinesLabel("message", "closingQuestion", lines=2)
        self.question_label.never_widen()
        # Narrow padding: the two answers share the panel's width (half the main screen's).
        self.close_now_button = touch_button("closeNowButton", "step")
        self.one_more_button = touch_button("oneMoreButton", "step")
        for button, choice in (
            (self.close_now_button, BoardChoice.CLOSE_NOW),
            (self.one_more_button, BoardChoice.CUT_ORDINARY),
        ):
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, c=choice: self.context.send(ChooseBoard(c)))
        self.start_button = touch_button("startBarrelButton")
        self.start_button.clicked.connect(lambda: self.context.send(StartBarrel()))
        self.card_button = touch_button("barrelCardButton")
        self.card_button.clicked.connect(self.export_card)

        column = QVBoxLayout()  # beside the drawing: the drawing keeps the panel's height
        column.setSpacing(4)
        column.addWidget(self.staves_label)
        column.addWidget(self.gap_label)
        column.addWidget(self.left_label)
        column.addWidget(self.question_label)
        column.addStretch(1)
        top = QHBoxLayout()
        top.setSpacing(6)
        top.addWidget(self.drawing, 2)
        top.addLayout(column, 3)
        # One row of buttons: the closing question's answers take the place of Start a barrel
        # and the card while it is asked, so the panel never grows (the main screen's height).
        buttons = QHBoxLayout()
        buttons.setSpacing(6)
        for button in (
            self.start_button,
            self.card_button,
            self.close_now_button,
            self.one_more_button,
        ):
            buttons.addWidget(button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(8, 4, 8, 6)
        layout.setSpacing(4)
        layout.addLayout(top, 1)
        layout.addLayout(buttons)
        self.retranslate()
        self.show_barrel(None, None)

    def retranslate(self) -> None:
        self.close_now_button.setText(self.tr("Closing stave"))
        self.one_more_button.setText(self.tr("One more stave"))
        self.card_button.setText(self.tr("Cooper's card"))
        self._texts()

    def open_big_drawing(self) -> BarrelOverlay | None:
        """The barrel drawn over the whole screen, following the machine while open."""
        if self.view is None:
            return None
        overlay = BarrelOverlay(self.view)
        self.big_drawing = overlay
        overlay.finished.connect(lambda _ok: self._big_drawing_closed(overlay))
        self.context.open(overlay)
        return overlay

    def _big_drawing_closed(self, overlay: BarrelOverlay) -> None:
        if self.big_drawing is overlay:
            self.big_drawing = None

    def show_barrel(self, view: BarrelView | None, snapshot: MachineSnapshot | None) -> None:
        self.view = view
        self.drawing.set_view(view)
        if self.big_drawing is not None:
            if view is None:
                self.big_drawing.reject()
            else:
                self.big_drawing.show_view(view)
        reason = refusal(snapshot, "StartBarrel")
        self.start_button.setEnabled(not reason)
        self.start_button.setToolTip(reason)
        choose_reason = refusal(snapshot, "ChooseBoard")
        asking = view is not None and view.ask_closing
        for button, choice in (
            (self.close_now_button, BoardChoice.CLOSE_NOW),
            (self.one_more_button, BoardChoice.CUT_ORDINARY),
        ):
            button.setEnabled(not choose_reason)
            button.setChecked(view is not None and view.choice is choice)
        shown = {
            self.close_now_button: asking,
            self.one_more_button: asking,
            self.question_label: asking,
            self.gap_label: view is not None and not asking,
            self.left_label: view is not None and not asking,
            self.drawing: view is not None,
            self.start_button: not asking,
            self.card_button: view is not None and not asking,
        }
        # What goes away first, then what comes: never both at once, not even for one
        # layout pass (the panel would grow the main screen past the panel's height).
        for widget, visible in sorted(shown.items(), key=lambda item: item[1]):
            if widget.isVisibleTo(self) != visible:
                widget.setVisible(visible)
        self._texts()

    def _texts(self) -> None:
        view = self.view
        if view is None:
            set_text(self.staves_label, self.tr("No barrel is being raised"))
            for label in (self.gap_label, self.left_label, self.question_label):
                set_text(label, "")
            set_text(self.start_button, self.tr("Start a barrel"))
            return
        set_text(self.start_button, self.tr("New barrel"))
        # One line for the barrel and its staves: the panel's height is the main screen's.
        barrel = self.tr("Barrel %1").replace("%1", str(view.number))
        staves = self.tr("Staves: %1").replace("%1", str(view.staves_done))
        set_text(self.staves_label, f"{barrel} · {staves}")
        if view.closed:
            set_text(self.gap_label, self.tr("Closed"))
            set_text(self.left_label, self.tr("The next board starts a new barrel."))
        elif view.gap_mm is None:
            set_text(self.gap_label, "")
            set_text(self.left_label, self.tr("The next board is stave 1."))
        else:
            left_mm = f"{format_number(view.perimeter_left_mm, 0)} mm"
            gap = f"{format_number(view.gap_mm, 1)} mm"
            set_text(
                self.gap_label,
                self.tr("Left %1 · gap %2").replace("%1", left_mm).replace("%2", gap),
            )
            left = "—" if view.staves_left is None else str(view.staves_left)
            set_text(
                self.left_label,
                self.tr("About %1 more staves").replace("%1", left),
            )
        if view.closing_width_mm is not None:
            width = f"{format_number(view.closing_width_mm, 1)} mm"
            set_text(
                self.question_label,
                self.tr("A stave of %1 closes it. Next board:").replace("%1", width),
            )

    def export_card(self, directory: Path | None = None) -> None:
        """The newest barrel's cooper's card, written where the operator chooses (a USB stick)."""
        view = self.view
        if view is None:
            return
        name = f"barrel-{view.number}-{datetime.now().strftime('%Y%m%d-%H%M')}.csv"
        chooser = FileChooser(
            self.tr("Cooper's card"),
            directory or default_exchange_dir(),
            save_name=name,
            keyboard_layout=self.context.keyboard_layout(),
            suffixes=(".csv",),
        )
        chooser.fileChosen.connect(lambda path: self.write_card(Path(path), view.number))
        self.context.open(chooser)

    def write_card(self, path: Path, number: int) -> None:
        try:
            export_barrel_card(self.context.database, path, number)
        except (DataError, OSError, ValueError) as exc:
            self.context.notify(self.tr("Card not written: %1").replace("%1", str(exc)))
            return
        self.context.notify(self.tr("Cooper's card written to %1.").replace("%1", str(path)))
