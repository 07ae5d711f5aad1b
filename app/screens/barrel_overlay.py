"""The barrel being raised, drawn big: a tap on the main screen's small drawing opens it.

Why: on a 1024x768 panel the main screen's barrel drawing is a few centimetres across, too
small to read the staves' numbers; the cooper checks the order of the staves and the gap
here. It follows the machine while it is open (the barrel panel hands it each new view).
"""

from __future__ import annotations

from PySide6.QtWidgets import QHBoxLayout, QWidget

from app.machine.barrel_view import BarrelView
from app.screens.formatting import format_number
from app.screens.theme import scale_for_size
from app.screens.widgets.barrel_drawing import BarrelDrawing
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.overlay import Overlay
from app.screens.widgets.readouts import set_text, styled_label

BIG_DRAWING_SIZE_PX = (900, 620)  # at 1024x768; scaled with the panel
BIG_LABEL_FONT_PX = 20


class BarrelOverlay(Overlay):
    def __init__(self, view: BarrelView, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("barrelOverlay")
        self.title_label = styled_label("", "title", "barrelOverlayTitle")
        self.drawing = BarrelDrawing(label_font_px=BIG_LABEL_FONT_PX)
        self.drawing.tapped.connect(self.reject)
        self.close_button = touch_button("barrelCloseButton", text=self.tr("Close"))
        self.close_button.clicked.connect(self.reject)
        self.panel_layout.addWidget(self.title_label)
        self.panel_layout.addWidget(self.drawing, 1)
        buttons = QHBoxLayout()
        buttons.addStretch(1)
        buttons.addWidget(self.close_button)
        self.panel_layout.addLayout(buttons)
        self.show_view(view)

    def show_view(self, view: BarrelView) -> None:
        self.drawing.set_view(view)
        barrel = self.tr("Barrel %1").replace("%1", str(view.number))
        staves = self.tr("Staves: %1").replace("%1", str(view.staves_done))
        if view.closed:
            state = self.tr("Closed")
        elif view.gap_mm is None:
            state = self.tr("The next board is stave 1.")
        else:
            gap = f"{format_number(view.gap_mm, 1)} mm"
            state = self.tr("Gap %1").replace("%1", gap)
        set_text(self.title_label, f"{barrel} · {staves} · {state}")

    def open_on(self, host: QWidget) -> None:
        """A fixed size in the panel's scale, never larger than the window."""
        window = host.window()
        scale = scale_for_size(window.width(), window.height())
        width, height = (round(px * scale) for px in BIG_DRAWING_SIZE_PX)
        self.panel.setFixedSize(min(width, host.width()), min(height, host.height()))
        super().open_on(host)
