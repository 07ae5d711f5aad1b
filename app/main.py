"""``python -m app``: start the operator application.

Start-up order and why: the configuration is checked first (a bad file is one line and exit
code 2, before anything opens a port); then logging; then the display is checked (no display
is one line that says how to run it, not a Qt abort); then the machine process is started
with its backends, and only then the screens, which talk to it through a MachineLink.
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from collections.abc import Sequence
from pathlib import Path

from app import __version__
from app.config import BACKENDS_KNOWN, GAUGES_KNOWN, ConfigError, MachineConfig, load_config

log = logging.getLogger("app")

_HEADLESS_PLATFORMS = ("offscreen", "minimal", "eglfs", "linuxfb", "vnc", "vkkhrdisplay")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m app", description="Stave jointer operator application"
    )
    parser.add_argument("--version", action="version", version=f"stave-jointer {__version__}")
    parser.add_argument("--config", type=Path, help="machine configuration file (TOML)")
    parser.add_argument("--backend", choices=BACKENDS_KNOWN, help="motion and I/O backend")
    parser.add_argument("--gauge", choices=GAUGES_KNOWN, help="width gauge backend")
    parser.add_argument("--db", type=Path, help="database file (default: user data directory)")
    parser.add_argument("--kiosk", action="store_true", help="full screen, no window frame")
    parser.add_argument("--lang", choices=("en", "sl"), help="language of the screens")
    parser.add_argument(
        "--screenshots",
        type=Path,
        metavar="DIR",
        help="render every screen to PNG files in DIR and exit",
    )
    parser.add_argument(
        "--size",
        default="1024x768",
        metavar="WxH",
        help="window size for --screenshots (default 1024x768)",
    )
    return parser


def parse_size(text: str) -> tuple[int, int]:
    try:
        width_text, height_text = text.lower().split("x")
        width, height = int(width_text), int(height_text)
    except ValueError:
        raise ConfigError("--size", text, "WIDTHxHEIGHT in pixels, e.g. 1024x768") from None
    if not (320 <= width <= 7680 and 240 <= height <= 4320):
        raise ConfigError("--size", text, "320x240 to 7680x4320")
    return width, height


def display_problem() -> str:
    """Why Qt could not open a window here, or "" when it can."""
    if sys.platform != "linux":
        return ""
    platform = os.environ.get("QT_QPA_PLATFORM", "")
    if platform.split(":")[0] in _HEADLESS_PLATFORMS:
        return ""
    if os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"):
        return ""
    return (
        "no display: the operator application needs a screen; run it on the panel's "
        "desktop, or here with `xvfb-run -a ./run.sh`, or render the screens with "
        "`./run.sh --screenshots DIR`"
    )


def resolve_config(args: argparse.Namespace) -> MachineConfig:
    config = load_config(args.config)
    return config.with_backend(args.backend, args.gauge)


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        config = resolve_config(args)
        size = parse_size(args.size)
        if args.screenshots is None:
            from app.drivers.settings_check import check_settings

            check_settings(config)  # here, before the machine process starts
    except ConfigError as exc:
        print(f"stave: configuration error: {exc}", file=sys.stderr)
        return 2
    if args.screenshots is not None:
        os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    problem = display_problem()
    if problem:
        print(f"stave: {problem}", file=sys.stderr)
        return 2
    from app.logging_setup import setup_logging

    log_file = setup_logging(config.log_dir, config.log_level)
    log.info(
        "stave-jointer %s starting (backend %s, gauge %s), log %s",
        __version__,
        config.backend,
        config.gauge,
        log_file,
    )

    from app.data.database import Database, default_database_path

    db_path = args.db or (
        Path(config.database_path) if config.database_path else default_database_path()
    )
    language = args.lang or config.language
    if args.screenshots is not None:
        return _screenshots(config, db_path, args.screenshots, size, language)

    if config.backend != "sim":
        with Database.open(db_path) as database:
            defaults = database.users_with_default_pins()
        if defaults:
            print(
                f"stave: users {', '.join(defaults)} still have their default PINs: change them "
                "(`stave db set-pin NAME`) before the real machine runs",
                file=sys.stderr,
            )
            return 2

    from app.machine.link import MachineLink
    from app.machine.process_link import ProcessMachineLink
    from app.machine.process_params import stave_limits
    from app.screens.application import run_gui

    link: MachineLink = ProcessMachineLink.start(config, db_path)
    if config.opcua.enabled:
        from app.plant.process import PlantFeedLink, PlantProcess

        for warning in config.opcua.insecure_choices():
            log.warning("OPC UA: %s is on ([opcua] configuration): commissioning only", warning)
        link = PlantFeedLink(link, PlantProcess.start(config.opcua, db_path, config.log_dir))
    try:
        # The machine's travel: what the screens check recipes against and show as enforced.
        with Database.open(db_path, limits=stave_limits(config)) as database:
            _quit_on_sigterm()
            return run_gui(link, database, language=language, kiosk=args.kiosk)
    finally:
        link.close()


def _quit_on_sigterm() -> None:
    """systemd stops the kiosk with SIGTERM: end the event loop, so that the link is closed
    and the machine stops safely, instead of dying in the middle of it. A timer lets the
    Python interpreter run the handler while Qt's event loop waits."""
    import signal

    from PySide6.QtCore import QTimer

    from app.screens.application import ensure_application

    app = ensure_application()

    def terminate(_signum: int, _frame: object) -> None:
        # The window's own safe shutdown, without asking: in the kiosk a plain quit would
        # ask the window to close, which the kiosk answers with the "Shut down?" dialog,
        # and systemd's stop would wait for ever.
        from app.screens.main_window import MainWindow

        windows = [w for w in app.topLevelWidgets() if isinstance(w, MainWindow)]
        for window in windows:
            window.shutdown()
        if not windows:
            app.quit()

    signal.signal(signal.SIGTERM, terminate)
    timer = QTimer(app)
    timer.timeout.connect(lambda: None)
    timer.start(200)


def _screenshots(
    config: MachineConfig, db_path: Path, out_dir: Path, size: tuple[int, int], language: str
) -> int:
    """Screenshots run the real machine in-process on a simulated clock, so that the states
    they show (a cycle running, an alarm active) are reached quickly and reproducibly, on a
    copy of the database (the user's recipes, nothing written back)."""
    import tempfile

    from app.data.backup import backup_database
    from app.data.database import Database
    from app.machine.local_link import LocalMachineLink
    from app.machine.process_params import stave_limits
    from app.screens.screenshots import render_screenshots

    with tempfile.TemporaryDirectory() as tmp:
        shot_db = Path(tmp) / "screenshots.db"
        if db_path.exists():
            backup_database(db_path, shot_db)
        link = LocalMachineLink.create(config.with_backend("sim", "sim"), shot_db)
        try:
            with Database.open(shot_db, limits=stave_limits(config)) as database:
                paths = render_screenshots(out_dir, size, link, database, language=language)
        finally:
            link.close()
    for path in paths:
        print(path)
    return 0
