"""The operator application as the panel runs it: the machine in its own process, the main
window offscreen with live positions, and a clean quit."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from app.config import load_config
from app.machine import commands as cmd
from app.machine.process_link import ProcessMachineLink
from app.screens.application import create_main_window
from app.screens.main_window import MainWindow


def test_starts_shows_live_positions_and_quits_cleanly(qtbot, database, db_path: Path) -> None:
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    link = ProcessMachineLink.start(replace(config, axes=axes), db_path, realtime_priority=False)
    window = create_main_window(link, database)
    assert isinstance(window, MainWindow)
    qtbot.addWidget(window)
    window.resize(1024, 768)
    window.show()
    main = window.page("main")
    try:
        qtbot.waitUntil(lambda: link.latest() is not None, timeout=20_000)
        link.send(cmd.EnterManual())
        qtbot.waitUntil(lambda: link.latest().state.value == "manual", timeout=10_000)
        link.send(cmd.JogStep("X", 25.0))
        target = link.latest().axis("X").position + 25.0
        qtbot.waitUntil(
            lambda: abs(float(main.axis_x.value_label.text()) - target) < 0.02, timeout=15_000
        )
    finally:
        window.shutdown()
    assert not link.alive(), "Shut down stops the machine process"
    assert link.lateness["periods"] > 100
