"""The feed override on the main screen: touch steps (-10 %, 100 %, +10 %) and a slider,
0 to the machine's highest override.

Why steps beside the slider: a finger on a slider lands a few percent off; the steps give the
usual values in one tap, the slider the rest. The widget only asks (``requested``); the value
shown is the machine's (``show_percent`` from the snapshot), so a refused or not yet applied
change never looks applied. While a finger holds the slider the snapshot does not move it.
"""

from __future__ import annotations

from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import QFrame, QHBoxLayout, QSlider, QVBoxLayout, QWidget

from app.machine.commands import SetFeedOverride
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.readouts import set_text, styled_label

STEP_PCT = 10


class FeedOverride(QFrame):
    """Asks for a feed override in percent (``requested``); shows the machine's."""

    requested = Signal(float)

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("feedOverride")
        self._shown_pct: float | None = None
        self.caption = styled_label("", "caption")
        self.value_label = styled_label("—", "value", "feedOverrideValue")
        self.minus_button = touch_button("feedMinusButton", "step")
        self.plus_button = touch_button("feedPlusButton", "step")
        self.full_button = touch_button("feedFullButton", "step")
        self.minus_button.setText(f"−{STEP_PCT}")
        self.plus_button.setText(f"+{STEP_PCT}")
        self.full_button.setText("100 %")
        self.slider = QSlider(Qt.Orientation.Horizontal)
        self.slider.setObjectName("feedOverrideSlider")
        self.slider.setRange(0, round(SetFeedOverride.MAX_PCT))
        self.slider.setSingleStep(1)
        self.slider.setPageStep(STEP_PCT)
        self.slider.setTracking(False)  # one request when the finger lifts, not one per pixel
        self.slider.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.slider.valueChanged.connect(lambda value: self.requested.emit(float(value)))
        self.slider.sliderMoved.connect(self._show_dragged)
        self.minus_button.clicked.connect(lambda: self.step(-STEP_PCT))
        self.plus_button.clicked.connect(lambda: self.step(+STEP_PCT))
        self.full_button.clicked.connect(lambda: self.requested.emit(100.0))

        head = QHBoxLayout()
        head.setSpacing(6)
        head.addWidget(self.caption)
        head.addStretch(1)
        head.addWidget(self.value_label)
        controls = QHBoxLayout()
        controls.setSpacing(6)
        controls.addWidget(self.minus_button)
        controls.addWidget(self.slider, 1)
        controls.addWidget(self.plus_button)
        controls.addWidget(self.full_button)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(0)
        layout.addLayout(head)
        layout.addLayout(controls)
        self.retranslate()

    def retranslate(self) -> None:
        self.caption.setText(self.tr("Feed override"))
        self.minus_button.setToolTip(self.tr("Slower by 10 %"))
        self.plus_button.setToolTip(self.tr("Faster by 10 %"))
        self.full_button.setToolTip(self.tr("The recipe's feed"))

    @property
    def percent(self) -> float | None:
        """The machine's override as last shown."""
        return self._shown_pct

    def step(self, delta_pct: int) -> None:
        """Ask for the shown override changed by ``delta_pct``, kept within 0 .. the highest."""
        base = 100.0 if self._shown_pct is None else self._shown_pct
        target = min(max(base + delta_pct, 0.0), SetFeedOverride.MAX_PCT)
        if target != base:
            self.requested.emit(target)

    def show_percent(self, percent: float) -> None:
        """The machine's override (from the snapshot); the slider follows unless held."""
        if percent == self._shown_pct:
            return
        self._shown_pct = percent
        set_text(self.value_label, f"{percent:.0f} %")
        if not self.slider.isSliderDown():
            self.slider.blockSignals(True)
            self.slider.setValue(round(percent))
            self.slider.blockSignals(False)
        self.minus_button.setEnabled(percent > 0.0)
        self.plus_button.setEnabled(percent < SetFeedOverride.MAX_PCT)

    def _show_dragged(self, value: int) -> None:
        """While the finger moves the slider: the value it would ask for."""
        set_text(self.value_label, f"{value} %")
