"""The Manual screen's line on the machine's own jog controls: who jogs, the handwheel's
axis and multiplier; hidden on a machine without them."""

from __future__ import annotations

from pytestqt.qtbot import QtBot

from app.machine.snapshot import JogSource, PendantView
from app.screens.widgets.pendant_status import PendantStatus


def test_the_line_names_the_source_and_the_wheels_axis_and_multiplier(qtbot: QtBot) -> None:
    status = PendantStatus()
    qtbot.addWidget(status)
    status.show()
    status.show_view(PendantView(JogSource.HANDWHEEL, "X", 10, handwheel_fitted=True))
    assert "the handwheel" in status.text() and "X ×10" in status.text()
    status.show_view(PendantView(None, "", 1, handwheel_fitted=True, joystick_fitted=True))
    assert "nobody" in status.text() and "Handwheel: off" in status.text()
    assert status.isVisible()
    status.show_view(PendantView())
    assert not status.isVisible()
