"""The System screen's simulation page works the simulated handwheel and joystick, through
the real widgets and the real machine on its simulated clock: a turn from the page moves the
selected axis by exactly the count times the multiplier, and a held stick push moves it until
let go."""

from __future__ import annotations

from collections.abc import Callable

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QPushButton

from app.machine.snapshot import JogSource, MachineSnapshot
from app.machine.states import MachineState
from tests.screens.helpers import enter_pin, find_button, open_pin_pad, wait_for


def x_axis(snapshot: MachineSnapshot) -> tuple[float, float]:
    """X's commanded and actual position."""
    axis = next(a for a in snapshot.axes if a.name == "X")
    return axis.command, axis.position


def at_rest(snapshot: MachineSnapshot) -> bool:
    return snapshot.pendant.jog_source is None


def test_the_wheel_turned_on_the_page_moves_x_by_count_times_multiplier(
    qtbot, window, machine, tap: Callable[[QPushButton], None]
) -> None:
    # The wheel owns the jog for about half a second of machine time: small steps of machine
    # time per poll, so the screen sees it however fast this computer runs the machine.
    machine.advance_per_poll_s = 0.02

    def press(name: str) -> None:
        """Scroll the page to the button, as a finger would, and tap it."""
        button = find_button(window, name)
        window.page("system").sim_scroll.ensureWidgetVisible(button)
        tap(button)

    open_pin_pad(qtbot, window, tap)
    enter_pin(qtbot, window, tap, "1234")  # a technician
    tap(find_button(window, "nav_system"))
    tap(find_button(window, "group_simulation"))
    manual_button = find_button(window, "simManualButton")
    wait_for(qtbot, window, lambda s: manual_button.isEnabled())
    assert (
        manual_button.height() >= 60 and find_button(window, "simWheelTurn_plus100").width() >= 60
    )
    press("simManualButton")
    snapshot = wait_for(qtbot, window, lambda s: s.state is MachineState.MANUAL)
    press("simWheelAxis_X")
    press("simWheelX10")
    snapshot = wait_for(
        qtbot, window, lambda s: (s.pendant.wheel_axis, s.pendant.wheel_multiplier) == ("X", 10)
    )
    assert find_button(window, "simWheelAxis_X").isChecked()
    x0_command, _ = x_axis(snapshot)

    press("simWheelTurn_plus100")  # not enabled: nothing moves
    snapshot = wait_for(qtbot, window, lambda s: s.machine_time_s > snapshot.machine_time_s + 1)
    assert x_axis(snapshot)[0] == x0_command

    press("simJogEnable")
    press("simWheelTurn_plus100")
    wait_for(qtbot, window, lambda s: s.pendant.jog_source is JogSource.HANDWHEEL)
    snapshot = wait_for(qtbot, window, at_rest)
    command, actual = x_axis(snapshot)
    assert command == pytest.approx(x0_command + 1.0, abs=1e-9)  # 100 counts x10 x 0.001 mm
    assert actual == pytest.approx(x0_command + 1.0, abs=0.005)
    press("simWheelAxis_off")

    stick = find_button(window, "simStick_Xminus")
    window.page("system").sim_scroll.ensureWidgetVisible(stick)
    qtbot.mousePress(stick, Qt.MouseButton.LeftButton)
    wait_for(qtbot, window, lambda s: x_axis(s)[0] < command - 0.5)
    qtbot.mouseRelease(stick, Qt.MouseButton.LeftButton)
    snapshot = wait_for(qtbot, window, at_rest)
    stopped = x_axis(snapshot)[0]
    assert stopped < command - 0.5
    later = wait_for(qtbot, window, lambda s: s.machine_time_s > snapshot.machine_time_s + 1)
    assert x_axis(later)[0] == stopped  # let go: it stays
