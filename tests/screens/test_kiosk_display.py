"""``--kiosk`` covers the screen on an X server without a window manager (a kiosk panel's
usual set-up), judged by the X server itself: Xvfb at 1920x1080 and xwininfo, not Qt."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterator

import pytest

SHOW = """
import sys
from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import QApplication, QMainWindow
from app.screens.application import show_full_screen

app = QApplication([])
window = QMainWindow()
window.setWindowTitle("kiosk-under-test")
window.setWindowFlags(window.windowFlags() | Qt.WindowType.FramelessWindowHint)
window.resize(1024, 768)
show_full_screen(window)
QTimer.singleShot(500, lambda: print("shown", flush=True))
app.exec()
"""


def _tools() -> tuple[str, str]:
    xvfb, xwininfo = shutil.which("Xvfb"), shutil.which("xwininfo")
    if xvfb is None or xwininfo is None:
        if os.environ.get("CI"):
            pytest.fail("Xvfb and xwininfo are needed (scripts/ensure-env.sh dev installs them)")
        pytest.skip("Xvfb or xwininfo missing: apt-get install xvfb x11-utils")
    return xvfb, xwininfo


@pytest.fixture
def display() -> Iterator[str]:
    """A 1920x1080 X server of its own (a free display number chosen by Xvfb), no WM."""
    xvfb, _ = _tools()
    read, write = os.pipe()
    server = subprocess.Popen(
        [xvfb, "-displayfd", str(write), "-screen", "0", "1920x1080x24", "-nolisten", "tcp"],
        pass_fds=(write,),
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    os.close(write)
    with os.fdopen(read) as pipe:
        number = pipe.readline().strip()
    try:
        assert number, "Xvfb did not report its display"
        yield f":{number}"
    finally:
        server.terminate()
        server.wait(timeout=10)


def _window_size(xwininfo: str, env: dict[str, str]) -> str:
    tree = subprocess.run(
        [xwininfo, "-root", "-tree"], env=env, capture_output=True, text=True, check=True
    ).stdout
    for line in tree.splitlines():
        if '"kiosk-under-test"' in line and "x" in line:
            size = line.split(")")[-1].split()[0]
            if size != "1x1+0+0":
                return size.split("+")[0]
    return ""


def test_kiosk_window_covers_a_screen_without_window_manager(display: str) -> None:
    _, xwininfo = _tools()
    env = {**os.environ, "DISPLAY": display, "QT_QPA_PLATFORM": "xcb"}
    with subprocess.Popen(
        [sys.executable, "-c", SHOW], env=env, stdout=subprocess.PIPE, text=True
    ) as shown:
        try:
            assert shown.stdout is not None
            assert shown.stdout.readline().strip() == "shown"
            size = ""
            end = time.monotonic() + 10
            while time.monotonic() < end and size != "1920x1080":
                size = _window_size(xwininfo, env)
                time.sleep(0.05)
            assert size == "1920x1080"
        finally:
            shown.terminate()
