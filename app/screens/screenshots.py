"""Render every screen to PNG, with the real machine driven into realistic states.

Why through the link: the pictures in the README must show what an operator sees, so the
machine is homed, a recipe is selected, a cycle is started and a board is cut through the same
commands the buttons send; then a fault is injected (simulated machine) for the alarm
pictures. Nothing is faked in the window. Works offscreen (``QT_QPA_PLATFORM=offscreen``).
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from datetime import UTC, datetime, timedelta
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QtMsgType, qInstallMessageHandler
from PySide6.QtWidgets import QApplication

from app.data.production_stats import StatsRange, range_window
from app.data.recipe import BarrelType
from app.data.records import AlarmEvent, AlarmState, PieceResult
from app.data.shifts import ShiftPlan
from app.data.users import Role
from app.machine.alarms import AlarmCode
from app.machine.commands import (
    Acknowledge,
    ClearFaults,
    Command,
    EnterManual,
    Home,
    InjectFault,
    LeaveManual,
    LoadBoard,
    Reset,
    Resume,
    SelectHandwheel,
    SelectRecipe,
    SetClamps,
    Start,
    StartBarrel,
)
from app.machine.link import MachineLink
from app.machine.snapshot import MachineSnapshot
from app.machine.states import CycleStep, MachineState
from app.resources import resources_dir
from app.screens.application import create_main_window, ensure_application
from app.screens.main_window import MainWindow
from app.screens.recipe_chooser import RecipeChooser
from app.screens.recipe_filter import RecipeFilter

if TYPE_CHECKING:
    from app.data.database import Database

# Messages of the offscreen platform that say nothing about the application.
OFFSCREEN_NOISE = ("propagateSizeHints",)
STEP_TIMEOUT_S = 120.0
CLOSING_BOARDS_MAX = 60  # the smallest sample barrel takes about 15 boards


@contextmanager
def quiet_offscreen_noise() -> Iterator[None]:
    """Drop the offscreen platform's harmless warnings; everything else is printed."""

    def handler(kind: QtMsgType, _context: object, message: str) -> None:
        if any(noise in message for noise in OFFSCREEN_NOISE):
            return
        print(f"Qt {kind.name}: {message}")

    previous = qInstallMessageHandler(handler)
    try:
        yield
    finally:
        qInstallMessageHandler(previous)


class Driver:
    """Polls the window's link until a condition holds (machine time runs while polling)."""

    def __init__(self, app: QApplication, window: MainWindow) -> None:
        self.app = app
        self.window = window

    def snapshot(self) -> MachineSnapshot | None:
        return self.window.poller.snapshot

    def until(
        self, done: Callable[[MachineSnapshot], bool], what: str, timeout_s: float = STEP_TIMEOUT_S
    ) -> MachineSnapshot:
        deadline = time.monotonic() + timeout_s
        while True:
            before = self.snapshot()
            seq = before.seq if before is not None else -1
            self.window.poller.poll()
            self.app.processEvents()
            snapshot = self.snapshot()
            if snapshot is not None and done(snapshot):
                return snapshot
            if time.monotonic() > deadline:
                state = snapshot.state.value if snapshot else "no snapshot"
                message = snapshot.message if snapshot else ""
                raise TimeoutError(
                    f"screenshots: machine did not reach '{what}' within "
                    f"{timeout_s:.0f} s (state {state}; {message})"
                )
            if snapshot is None or snapshot.seq == seq:
                time.sleep(0.01)  # a machine in its own process: give it time

    def send_and_wait(
        self, command: Command, done: Callable[[MachineSnapshot], bool], what: str
    ) -> MachineSnapshot:
        self.window.link.send(command)
        return self.until(done, what)

    def settle(self, polls: int = 5) -> None:
        for _ in range(polls):
            self.window.poller.poll()
            self.app.processEvents()


SAMPLE_DRAWING = resources_dir() / "profiles" / "sample_side_profile.dxf"
"""The shipped DXF drawing the recipe screenshot imports (a house-style bilge)."""


def _homed_and_ready(driver: Driver) -> None:
    snapshot = driver.until(lambda s: s.state is not MachineState.POWER_UP, "started")
    if snapshot.state in (MachineState.ERROR, MachineState.EMERGENCY_STOP):
        driver.window.link.send(Acknowledge(0))
        snapshot = driver.send_and_wait(
            Reset(),
            lambda s: s.state not in (MachineState.ERROR, MachineState.EMERGENCY_STOP),
            "reset",
        )
    if snapshot.state is MachineState.MANUAL:
        snapshot = driver.send_and_wait(
            LeaveManual(), lambda s: s.state is not MachineState.MANUAL, "automatic mode"
        )
    if not snapshot.all_homed or snapshot.state is MachineState.NOT_HOMED:
        driver.send_and_wait(
            Home(), lambda s: s.state is MachineState.READY and s.all_homed, "homed"
        )


def _clear_the_alarm(driver: Driver) -> None:
    """Acknowledge the alarm the pictures before raised, clear the simulated fault, Reset."""
    driver.window.link.send(Acknowledge(0))
    driver.window.link.send(ClearFaults())
    _homed_and_ready(driver)
    driver.window.clear_notice()


def _board_done_after(pieces_before: int) -> Callable[[MachineSnapshot], bool]:
    """The machine is ready again with one more piece counted than ``pieces_before``."""
    return lambda s: s.pieces_total > pieces_before and s.state is MachineState.READY


def _cut_until_the_closing_question(driver: Driver) -> None:
    """Cut boards of the barrel already started, Start and a board each, as an operator
    would, until the panel asks about the closing stave."""
    _homed_and_ready(driver)
    for _ in range(CLOSING_BOARDS_MAX):
        snapshot = driver.until(lambda s: s.state is MachineState.READY, "ready for a board")
        if snapshot.barrel is not None and snapshot.barrel.ask_closing:
            return
        total = snapshot.pieces_total
        if "Resume" in snapshot.allowed and snapshot.allowed["Resume"] is None:
            # The board the fault interrupted: its cut is finished, as the operator would.
            driver.send_and_wait(
                Resume(), lambda s: s.state is MachineState.AUTOMATIC, "cut resumed"
            )
        else:
            driver.send_and_wait(
                Start(), lambda s: s.state is MachineState.AUTOMATIC, "barrel cycle started"
            )
            driver.window.link.send(LoadBoard())
        driver.until(_board_done_after(total), "barrel board finished")
    raise TimeoutError(
        f"screenshots: the barrel did not ask for its closing stave in {CLOSING_BOARDS_MAX} boards"
    )


HISTORY_SEED = 21
"""The simulated shift before this one is the same in every run."""


def simulate_last_shift(database: Database, now: datetime) -> int:
    """Fill the shift before the running one with simulated production for the Production
    screen's picture: boards fed at an operator's pace (the waits and the breaks vary), each
    with the step times of the board the machine really cut in this run, some refused for
    their width (E032), a few aborted by a clamp sensor (E040); returns how many records.

    The screenshot database is a copy that is thrown away; nothing here reaches the panel's."""
    cut = [r for r in database.list_production(now - timedelta(hours=1), now) if r.step_times_s]
    if not cut:
        raise ValueError("screenshots: no board was cut, no step times to simulate with")
    model = cut[-1]
    start, end = range_window(
        StatsRange.LAST_SHIFT, now, ShiftPlan.from_parameters(database.get_parameters())
    )
    rng = random.Random(HISTORY_SEED)
    moment, written = start + timedelta(minutes=5), 0
    while moment < end - timedelta(minutes=5):
        if rng.random() < 0.004:  # a break
            moment += timedelta(minutes=rng.uniform(10, 30))
        wait_s = rng.choice((0.4, 0.6, 0.9, 1.5, 3.0, 6.0))
        steps = {**model.step_times_s, "waiting": wait_s}
        width_mm = round(rng.gauss(150.0, 14.0), 2)
        result, alarm = PieceResult.OK, None
        if rng.random() < 0.015:
            result, alarm, width_mm = PieceResult.REJECTED, AlarmCode.WIDTH_NOT_ALLOWED, 62.4
            steps = {"waiting": wait_s, "centering": 0.8, "clamping": 0.6, "measuring": 0.3}
        elif rng.random() < 0.005:
            result, alarm = PieceResult.ABORTED, AlarmCode.CLAMPS_SENSOR
            steps = {"waiting": wait_s, "centering": 0.8, "clamping": 3.6}
        cycle_s = sum(steps.values())
        moment += timedelta(seconds=cycle_s)
        database.record_piece(
            replace(
                model,
                id=None,
                time=moment,
                width_mm=width_mm,
                cycle_time_s=cycle_s,
                result=result,
                alarm_code=alarm,
                step_times_s=steps,
                resumed=False,
                barrel_number=None,
                stave_number=None,
            )
        )
        if alarm is not None:
            database.record_alarm_event(
                AlarmEvent(
                    moment,
                    alarm,
                    "simulated history",
                    "machine",
                    AlarmState.NORMAL,
                    AlarmState.ACTIVE_UNACKED,
                )
            )
        written += 1
    return written


VARIANT_THICKNESSES_MM = (25.0, 30.0, 36.0, 45.0, 55.0, 70.0)
"""Stave thicknesses a cooperage keeps recipes for, beside each sample recipe's own."""


def add_thickness_variants(database: Database) -> int:
    """Give the screenshot database the recipe list of a working cooperage: each sample
    recipe also in other stave thicknesses, named by them; returns how many were added.

    The screenshot database is a copy that is thrown away; nothing here reaches the panel's."""
    operator = min(database.list_users(), key=lambda user: user.role)
    variants = [
        replace(recipe, id=None, name=f"{recipe.name} {thickness:g} mm", thickness_mm=thickness)
        for recipe in database.list_recipes()
        for thickness in VARIANT_THICKNESSES_MM
        if thickness != recipe.thickness_mm
    ]
    database.save_recipes(variants, operator)
    return len(variants)


def render_screenshots(
    out_dir: Path,
    size: tuple[int, int],
    link: MachineLink,
    database: Database,
    *,
    language: str = "en",
) -> list[Path]:
    """Drive the machine through ``link`` and save one PNG per screen (plus the keypad) in
    ``out_dir``; returns the files written. Raises TimeoutError naming the step the machine
    did not reach, ValueError if the database has no recipe."""
    recipes = database.list_recipes()
    if not recipes:
        raise ValueError("screenshots: the database has no recipe to load")
    out_dir.mkdir(parents=True, exist_ok=True)
    written: list[Path] = []
    with quiet_offscreen_noise():
        app = ensure_application()
        window = create_main_window(link, database, language=language)
        assert isinstance(window, MainWindow)
        window.poller.stop()  # the driver polls, so the pictures follow the machine exactly
        window.resize(*size)
        window.show()
        driver = Driver(app, window)

        def shoot(name: str) -> None:
            driver.settle()
            path = out_dir / f"{len(written) + 1:02d}-{name}.png"
            if not window.grab().save(str(path)):
                raise OSError(f"screenshots: could not write {path}")
            written.append(path)

        try:
            _homed_and_ready(driver)
            recipe = recipes[0]
            assert recipe.id is not None
            driver.send_and_wait(
                SelectRecipe(recipe.id), lambda s: s.recipe_id == recipe.id, "recipe selected"
            )
            if recipe.barrel_section is not None:  # its boards are the staves of a barrel
                driver.send_and_wait(StartBarrel(), lambda s: s.barrel is not None, "barrel")
            driver.send_and_wait(
                Start(), lambda s: s.state is MachineState.AUTOMATIC, "cycle started"
            )
            driver.window.link.send(LoadBoard())
            driver.until(lambda s: s.cycle.step is CycleStep.CUTTING_A, "cutting side A")
            total = driver.snapshot().pieces_total  # type: ignore[union-attr]
            # One whole board, so the counters and the last width are filled in.
            driver.until(
                lambda s: s.pieces_total > total and s.state is MachineState.READY,
                "first board finished",
            )
            # The next board: Start again, and cut until side B.
            driver.send_and_wait(
                Start(), lambda s: s.state is MachineState.AUTOMATIC, "second cycle started"
            )
            driver.window.link.send(LoadBoard())
            driver.until(lambda s: s.cycle.step is CycleStep.CUTTING_B, "cutting side B")
            window.show_screen("main")
            shoot("main-running")

            window.show_screen("recipes")
            screen = window.page("recipes")
            screen.fill_width_ranges()  # type: ignore[attr-defined]
            shoot("recipes")
            screen.edit_field("thickness_mm")  # type: ignore[attr-defined]
            overlay = window.overlay()
            if overlay is not None:
                for key in ("3", "2"):
                    overlay.press(key)  # type: ignore[attr-defined]
            shoot("recipes-keypad")
            if overlay is not None:
                overlay.reject()

            technician = next((u for u in database.list_users() if u.role >= Role.TECHNICIAN), None)
            if technician is not None:
                window.session.set_user(technician)
            window.show_screen("system")
            system = window.page("system")
            system.show_group("motion")  # type: ignore[attr-defined]
            shoot("system")
            window.session.logout()
            window.clear_notice()  # "logged out" is not part of the next pictures

            driver.send_and_wait(
                InjectFault("following_error", "X"), lambda s: bool(s.alarms), "alarm raised"
            )
            window.show_screen("main")
            shoot("main-alarm")
            window.show_screen("alarms")
            shoot("alarms")

            driver.window.link.send(Acknowledge(0))
            driver.window.link.send(ClearFaults())
            driver.send_and_wait(
                Reset(),
                lambda s: s.state not in (MachineState.ERROR, MachineState.EMERGENCY_STOP),
                "reset after the fault",
            )
            driver.send_and_wait(
                EnterManual(), lambda s: s.state is MachineState.MANUAL, "manual mode"
            )
            # The handwheel's switches on X x10: the Manual screen shows them.
            driver.send_and_wait(
                SelectHandwheel("X", 10),
                lambda s: s.pendant.wheel_multiplier == 10,
                "handwheel on X x10",
            )
            window.show_screen("manual")
            shoot("manual")

            # A drawn side profile in the recipe preview: the shipped sample drawing.
            window.show_screen("recipes")
            recipes_screen = window.page("recipes")
            recipes_screen.import_drawing(SAMPLE_DRAWING)  # type: ignore[attr-defined]
            shoot("recipes-drawn-profile")
            recipes_screen.discard()  # type: ignore[attr-defined]

            # The technicians' I/O page, with the clamps closed by hand.
            window.link.send(SetClamps(True))
            driver.until(lambda s: s.inputs.clamps_closed, "clamps closed by hand")
            window.show_screen("io")
            shoot("io")

            # The plant connection's page (the screenshots run without the OPC UA server).
            if technician is not None:
                window.session.set_user(technician)
            window.show_screen("system")
            window.page("system").show_group("opcua")  # type: ignore[attr-defined]
            shoot("system-opcua")
            window.page("system").show_group("limits")  # type: ignore[attr-defined]
            shoot("system-limits")
            window.session.logout()

            # One alarm opened: its whole text, causes, remedy, details and history.
            driver.send_and_wait(
                InjectFault("drive_fault", "Y"), lambda s: bool(s.alarms), "drive fault raised"
            )
            window.show_screen("alarms")
            alarms_screen = window.page("alarms")
            driver.settle()
            alarms_screen.open_active(0)  # type: ignore[attr-defined]
            shoot("alarm-detail")
            detail = window.overlay()
            if detail is not None:
                detail.reject()

            # The simulation page with the handwheel's and the joystick's controls.
            if technician is not None:
                window.session.set_user(technician)
            window.show_screen("system")
            system_page = window.page("system")
            system_page.show_group("simulation")  # type: ignore[attr-defined]
            system_page.sim_scroll.ensureWidgetVisible(system_page.sim_pendant)  # type: ignore[attr-defined]
            shoot("system-simulation")
            window.session.logout()
            _clear_the_alarm(driver)  # the pictures after this one show a working machine

            # Production at a glance: the shift before this one, simulated from this run's
            # board (the screenshot database is a throw-away copy).
            simulate_last_shift(database, datetime.now(UTC))
            window.clear_notice()  # "logged out" is not part of the picture
            window.show_screen("production")
            production = window.page("production")
            production.show_range(StatsRange.LAST_SHIFT)  # type: ignore[attr-defined]
            production.jobs.wait()  # type: ignore[attr-defined]
            driver.settle()
            shoot("production")

            # Finding a recipe: the Recipes list searched and filtered, the main screen's
            # chooser filtered by barrel type, among the many recipes of a working cooperage.
            add_thickness_variants(database)
            window.show_screen("recipes")
            recipes_page = window.page("recipes")
            recipes_page.reload()  # type: ignore[attr-defined]
            recipes_page.filter_bar.set_filter(RecipeFilter("bordeaux", BarrelType.ROUND))  # type: ignore[attr-defined]
            shoot("recipes-search")
            recipes_page.filter_bar.set_filter(RecipeFilter())  # type: ignore[attr-defined]
            window.show_screen("main")
            window.page("main").open_recipe_list()  # type: ignore[attr-defined]
            chooser = window.overlay()
            if isinstance(chooser, RecipeChooser):
                chooser.filter_bar.set_barrel_type(BarrelType.ROUND)
                shoot("main-recipe-chooser")
                chooser.reject()

            # The closing stave: boards are cut until one stave can close the barrel, and
            # the barrel panel asks what the next board becomes.
            if recipe.barrel_section is not None:
                _cut_until_the_closing_question(driver)
                window.show_screen("main")
                shoot("main-closing-question")
                # The barrel drawn big (a tap on the small drawing): the staves' numbers.
                big = window.page("main").barrel_panel.open_big_drawing()  # type: ignore[attr-defined]
                if big is not None:
                    shoot("main-barrel-drawing")
                    big.reject()
        finally:
            window.poller.stop()
            window.close()
            window.deleteLater()
            app.processEvents()
    return written
