"""``python -m app``: version, the no-display message, and bad arguments."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from app import __version__


def run_app(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "app", *args],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        check=False,
    )


def test_version() -> None:
    result = run_app("--version")
    assert result.returncode == 0
    assert __version__ in result.stdout


def test_no_display_is_one_line_that_says_how(tmp_path) -> None:  # type: ignore[no-untyped-def]
    env = {
        k: v
        for k, v in os.environ.items()
        if k not in ("DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM")
    }
    env["HOME"] = str(tmp_path)
    result = run_app("--db", str(tmp_path / "stave.db"), env=env)
    assert result.returncode == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "no display" in lines[0] and "xvfb-run" in lines[0]


def test_bad_size_is_one_line() -> None:
    result = run_app("--screenshots", "/tmp/x", "--size", "big")
    assert result.returncode == 2
    assert "--size" in result.stderr and "WIDTHxHEIGHT" in result.stderr


@pytest.mark.parametrize("mode", [[], ["--kiosk"]], ids=["window", "kiosk"])
def test_sigterm_ends_gui_and_machine_cleanly(tmp_path, mode) -> None:  # type: ignore[no-untyped-def]
    """systemd stops the kiosk with SIGTERM: the window closes, the machine process shuts
    down through its normal path (spindle off, drives disabled) and both end."""
    import signal
    import time

    env = {**os.environ, "HOME": str(tmp_path), "QT_QPA_PLATFORM": "offscreen"}
    env.pop("XDG_STATE_HOME", None)
    app = subprocess.Popen(
        [sys.executable, "-m", "app", "--db", str(tmp_path / "stave.db"), *mode],
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    machine_log = tmp_path / ".local" / "state" / "stave-jointer" / "log" / "machine.log"
    try:
        end = time.monotonic() + 60
        while time.monotonic() < end:
            if machine_log.exists() and "machine process started" in machine_log.read_text():
                break
            time.sleep(0.1)
        else:
            raise AssertionError("the machine process did not start")
        time.sleep(1.0)
        app.send_signal(signal.SIGTERM)
        assert app.wait(20) == 0
        assert "machine loop lateness" in machine_log.read_text()
    finally:
        if app.poll() is None:
            app.kill()
