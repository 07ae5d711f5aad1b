"""``stave simulate``: complete automatic cycles on the simulated machine, faster than real time.

What it is for: preparing and checking recipes in the office, and proving the machine's
behaviour under faults. It drives the real machine layer (state machine, cycle, planner,
executor) on the simulation backend, exactly as the operator would: home, select the recipe,
put a board in, press Start, wait for the cycle to end; with ``--inject`` a fault is injected
when the cycle reaches a step, and the run watches that nothing moves again by itself, and
says so when the fault had no effect in that step.

A simulation never writes into production: without ``--db`` it runs on a new database of its
own; ``--db`` naming a file that does not exist creates one marked as a simulation's
(:attr:`app.data.database.Database.for_simulation`), which later runs write into; any other
database (the panel's) is only read: the run works on a private copy and says so. A
``--recipe-file`` is used as given: it never replaces a stored recipe of the same name.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, TextIO

import numpy as np

from app.cli.profile_args import ProfileOptionError, add_profile_arguments, profile_from_args
from app.cli.recipe_args import add_recipe_source
from app.cli.simulate_jog import (
    JogOptionError,
    add_jog_arguments,
    describe_jog,
    hand_jogs,
    run_hand_jogs,
)
from app.config import ConfigError, MachineConfig, load_config
from app.data.recipe import Recipe
from app.drivers.contracts import FAULT_KINDS, FaultInjector
from app.drivers.sim.world import SimWorld
from app.geometry.barrel_section import next_joint_t
from app.machine import commands as cmd
from app.machine.barrel_job import TOO_NARROW_ALARM
from app.machine.controller import MachineController
from app.machine.cycle_plan import PlannedStave
from app.machine.process_params import motion_limits
from app.machine.runtime import MachineRuntime
from app.machine.states import LATCHED_STATES, CycleStep, MachineState

STEP_NAMES = {step.name.lower(): step for step in CycleStep if step is not CycleStep.WAIT_FOR_PART}
"""Steps a fault can be injected at. Not waiting for a board: the board is put in before
Start, so the cycle leaves that step in its first period, and a fault "injected" there would
pass silently."""
MAX_CYCLES = 100_000
SETTLE_AFTER_ALARM_S = 3.0
RESET_TIMEOUT_S = 5.0  # how long the run watches for motion after an alarm
HOMING_TIMEOUT_S = 300.0
CYCLE_TIMEOUT_S = 600.0


class UsageError(Exception):
    """Bad command-line input: one line, exit code 2."""


MAX_INJECT_DELAY_S = 600.0  # longer than any step of a cycle
OPERATOR_STOP = "stop"  # not a fault: the operator's Stop (screen or push button)
INJECT_KINDS = (*FAULT_KINDS, OPERATOR_STOP)


@dataclass(frozen=True)
class Injection:
    kind: str
    target: str
    step: CycleStep
    # How long into the step: 0 is as it begins; a few seconds into cutting_a puts the
    # fault in the middle of side A, the cutter in the board.
    after_s: float = 0.0

    @classmethod
    def parse(cls, text: str) -> Injection:
        if not text.strip():
            raise UsageError(
                "--inject '': empty is not allowed: KIND[:TARGET]@STEP[+SECONDS] "
                "(or leave --inject out)"
            )
        what, _, when = text.partition("@")
        step_name, plus, delay = when.partition("+")
        kind, _, target = what.partition(":")
        if kind not in INJECT_KINDS:
            raise UsageError(
                f"--inject {text!r}: kind {kind!r} is not allowed: one of "
                + ", ".join(INJECT_KINDS)
            )
        if step_name not in STEP_NAMES:
            raise UsageError(
                f"--inject {text!r}: step {step_name!r} is not allowed: one of "
                + ", ".join(STEP_NAMES)
            )
        after_s = 0.0
        if plus:
            try:
                after_s = float(delay) if len(delay) <= 20 else math.nan
            except ValueError:
                after_s = math.nan
            if not 0.0 <= after_s <= MAX_INJECT_DELAY_S:
                raise UsageError(
                    f"--inject {text!r}: seconds into the step {delay!r} is not allowed: "
                    f"a number from 0 to {MAX_INJECT_DELAY_S:.0f}"
                )
        return cls(kind, target, STEP_NAMES[step_name], after_s)


@dataclass
class Watch:
    """Per-period observation: contour error while cutting, and motion after an alarm."""

    max_contour_error_mm: float = 0.0
    latched_at_s: float | None = None
    still_positions: tuple[float, float, float] | None = None
    restarted: bool = False
    trace: Any = None
    operator_acted: bool = False
    _settled_periods: int = 0
    _cut_xy: list[tuple[float, float]] = field(default_factory=list)
    _plan: Any = None

    def flush_contour_error(self) -> None:
        """Distances of the actual positions from the exact tool path while the cutter is
        over the board (machine X from P0x to P0x + L: what shapes the stave; the leads cut
        air), computed in one vectorised call when the cut is over."""
        if self._cut_xy and self._plan is not None:
            xy = np.asarray(self._cut_xy)
            params = self._plan.toolpath.params
            x0 = params.start_x_mm
            x1 = x0 + self._plan.toolpath.profile.length_mm
            on_board = xy[(xy[:, 0] >= x0) & (xy[:, 0] <= x1)]
            if len(on_board):
                errors = self._plan.distances_to_path(on_board[:, 0], on_board[:, 1])
                self.max_contour_error_mm = max(self.max_contour_error_mm, float(errors.max()))
        self._cut_xy.clear()

    def observe(self, runtime: MachineRuntime) -> None:
        c = runtime.controller
        if c.cycle is not None and c.cycle.executor is not None and c.cycle.planned is not None:
            last = c.cycle.last_output
            if last is not None and last.cutting:
                x, y, _z = c.axes.positions()
                self._cut_xy.append((x, y))
                self._plan = c.cycle.planned.plan
        elif self._cut_xy:
            self.flush_contour_error()
        if c.state in LATCHED_STATES and not self.operator_acted:
            self._watch_latched(c)
        if self.trace is not None:
            cmd_pos = c.axes.command
            x, y, z = c.axes.positions()
            self.trace.writerow(
                [
                    f"{runtime.time_s:.4f}",
                    c.state.value,
                    f"{cmd_pos['X']:.4f}",
                    f"{cmd_pos['Y']:.4f}",
                    f"{cmd_pos['Z']:.4f}",
                    f"{x:.4f}",
                    f"{y:.4f}",
                    f"{z:.4f}",
                    int(c.outputs.spindle_on),
                    c.cycle.step.name.lower() if c.cycle is not None else "",
                ]
            )

    def _watch_latched(self, c: MachineController) -> None:
        positions = c.axes.positions()
        if self.latched_at_s is None:
            self.latched_at_s = c.now_s
        if self.still_positions is None:
            # The axes stop on their ramps first; once still for 50 periods, any later motion
            # before an operator acts is a restart.
            if c.axes.standing_still(tolerance=1e-3):
                self._settled_periods += 1
                if self._settled_periods >= 50:
                    self.still_positions = positions
            else:
                self._settled_periods = 0
            return
        if max(abs(a - b) for a, b in zip(positions, self.still_positions, strict=True)) > 0.01:
            self.restarted = True


@dataclass
class CycleReport:
    width_mm: float
    measured_width_mm: float | None = None  # what the gauge read, the width the profile is cut for
    result: str = "ok"
    alarms: list[str] = field(default_factory=list)
    D_mm: float | None = None
    R_mm: float | None = None
    cycle_time_s: float | None = None
    cut_time_s: dict[str, float] = field(default_factory=dict)
    cut_length_mm: dict[str, float] = field(default_factory=dict)
    step_times_s: dict[str, float] = field(default_factory=dict)
    max_contour_error_mm: float = 0.0
    injection: str = ""  # what the injected fault did, in words ("" without --inject)
    barrel_stave_number: int | None = None  # with --barrel: the stave's place in the barrel
    tilt_a_deg: float | None = None
    tilt_b_deg: float | None = None
    target_width_mm: float | None = None  # the width it was cut to when narrower than the board
    passes: int | None = None
    resume: str = ""  # with --resume: what became of the interrupted board, in words


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_recipe_source(parser)
    parser.add_argument("--width", type=float, metavar="MM", help="width of every board put in")
    parser.add_argument(
        "--barrel",
        action="store_true",
        help="raise a barrel of the recipe (round or oval) until it closes",
    )
    parser.add_argument(
        "--widths",
        metavar="W1,W2,...",
        help="with --barrel: the boards' widths in order (default: the simulation's boards)",
    )
    parser.add_argument("--cycles", type=int, default=1, metavar="N")
    parser.add_argument(
        "--inject",
        metavar="KIND[:TARGET]@STEP[+SECONDS]",
        help="inject a fault when the cycle reaches STEP (or SECONDS into it), or press "
        "Stop then (KIND stop); KIND is one of "
        + ", ".join(INJECT_KINDS)
        + "; TARGET an axis (X, Y, Z) or the "
        "simulation's target (e.g. clamp_sensor:open); STEP one of " + ", ".join(STEP_NAMES),
    )
    parser.add_argument(
        "--trace",
        type=Path,
        metavar="FILE.csv",
        help="write commanded and actual positions at every period",
    )
    parser.add_argument(
        "--resume",
        action="store_true",
        help="with --inject: after the alarm clear the fault, Reset, then Resume the "
        "interrupted board (as an operator would)",
    )
    add_jog_arguments(parser)
    parser.add_argument("--json", action="store_true", help="one JSON object on stdout")
    parser.add_argument("--realtime", action="store_true", help="run at real-time speed")
    parser.add_argument("--config", type=Path, help="machine configuration (TOML)")
    parser.add_argument("--db", type=Path, help="database with the recipes (default: a new one)")
    add_profile_arguments(parser)


def _recipe_from_args(args: argparse.Namespace, controller: MachineController) -> Recipe:
    if args.recipe_file is not None:
        from app.data.errors import DataError
        from app.data.recipe_files import load_recipe_file

        try:
            recipes = load_recipe_file(args.recipe_file)
        except (DataError, ValueError) as exc:
            raise UsageError(f"--recipe-file: {exc}") from exc
        if not recipes:
            raise UsageError(f"--recipe-file {args.recipe_file}: no recipe in the file")
        given = _unused_name(recipes[0], controller)
        try:
            return controller.store.save_recipe(given)
        except ValueError as exc:
            raise UsageError(f"--recipe-file: {exc}") from exc
    recipe = controller.store.recipe_by_name(args.recipe)
    if recipe is None:
        names = ", ".join(r.name for r in controller.store.recipes())
        raise UsageError(f"--recipe {args.recipe!r} is not in the database; it has: {names}")
    return recipe


def _unused_name(recipe: Recipe, controller: MachineController) -> Recipe:
    """The file's recipe as given: if a stored recipe has its name and differs, the file's is
    stored beside it under "<name> (simulation N)" instead of replacing it."""
    from dataclasses import replace

    stored = controller.store.recipe_by_name(recipe.name)
    if stored is None or replace(stored, id=None) == replace(recipe, id=None):
        return recipe
    for number in range(1, 1000):
        name = f"{recipe.name[:26]} (simulation {number})"
        if controller.store.recipe_by_name(name) is None:
            return replace(recipe, id=None, name=name)
    raise UsageError(f"--recipe-file: no free name for {recipe.name!r}")


def _sim_world(runtime: MachineRuntime) -> SimWorld:
    world = runtime.backend.extras.get("world")
    if not isinstance(world, SimWorld):
        raise UsageError("stave simulate needs the simulation backend (backend.name = 'sim')")
    return world


def _home(runtime: MachineRuntime) -> None:
    c = runtime.controller
    if c.state is MachineState.READY:
        return
    c.post(cmd.Home())
    if not runtime.run_until(
        lambda m: m.state is not MachineState.HOMING and m.state is not MachineState.NOT_HOMED,
        HOMING_TIMEOUT_S,
    ):
        raise RuntimeError("homing did not finish")
    state: MachineState = c.state  # changed by run_until
    if state is not MachineState.READY:
        raise RuntimeError(f"homing ended in {state.value}: {c.state_text()}")


@contextmanager
def _tick_pacing(runtime: MachineRuntime, realtime: bool) -> Iterator[None]:
    if not realtime:
        yield
        return
    start_wall = time.monotonic()

    def pace(rt: MachineRuntime) -> None:
        ahead = rt.time_s - (time.monotonic() - start_wall)
        if ahead > 0:
            time.sleep(ahead)

    runtime.on_tick.append(pace)
    try:
        yield
    finally:
        runtime.on_tick.remove(pace)


def _reset_and_resume(
    runtime: MachineRuntime, report: CycleReport, watch: Watch, *, reset: bool = True
) -> None:
    """The operator's gestures after an interruption: the cause removed, Reset (after an
    alarm; a Stop latches nothing), Resume."""
    c = runtime.controller
    faults = runtime.backend.extras.get("faults")
    if isinstance(faults, FaultInjector):
        faults.clear_injections()
    watch.operator_acted = True
    runtime.run_for(0.5)
    if reset:
        c.post(cmd.Reset())
        if not runtime.run_until(lambda m: m.state not in LATCHED_STATES, RESET_TIMEOUT_S):
            report.resume = f"reset refused: {c.message}"
            return
    if c.partly_cut.board is None:
        report.resume = "nothing to resume: the cut had not begun"
        return
    runtime.run_for(1.0)  # the operator reads the screen; the axes have stopped
    c.post(cmd.Resume())
    runtime.run_for(2 * runtime.period_s)
    if c.cycle is None:
        report.resume = f"resume refused: {c.message}"
        return
    if not runtime.run_until(
        lambda m: m.state is not MachineState.AUTOMATIC or m.cycle is None, CYCLE_TIMEOUT_S
    ):
        raise RuntimeError(f"resumed cycle did not end within {CYCLE_TIMEOUT_S:.0f} s")
    piece = c.finished_cycles[-1][0] if c.finished_cycles else None
    if c.state is MachineState.READY and piece is not None and piece.resumed:
        report.result = "resumed"
        report.resume = "resumed and finished"
    else:
        report.resume = f"resumed cycle ended in {c.state.value}: {c.message}"


def _run_cycle(
    runtime: MachineRuntime,
    width_mm: float | None,
    injection: Injection | None,
    watch: Watch,
    resume: bool = False,
) -> CycleReport:
    """One board through the machine (``width_mm`` None: drawn from the simulation's)."""
    c = runtime.controller
    world = _sim_world(runtime)
    world.remove_board()
    runtime.run_for(0.1)  # the part sensor must see the finished board gone
    report = CycleReport(world.load_board(width_mm).true_width_mm)
    runtime.run_for(0.1)
    alarms_before = {a.alarm_id for a in c.alarms.views()}
    c.post(cmd.Start())
    injected = False
    step_began_s: float | None = None

    def finished(m: MachineController) -> bool:
        nonlocal injected, step_began_s
        in_step = injection is not None and m.cycle is not None and m.cycle.step is injection.step
        if in_step and step_began_s is None:
            step_began_s = m.now_s
        if (
            injection is not None
            and not injected
            and in_step
            and step_began_s is not None
            and m.now_s - step_began_s >= injection.after_s
        ):
            faults = runtime.backend.extras.get("faults")
            if injection.kind == OPERATOR_STOP:
                m.post(cmd.Stop())
            elif isinstance(faults, FaultInjector):
                try:
                    faults.inject(injection.kind, injection.target)
                except ValueError as exc:
                    raise UsageError(f"--inject: {exc}") from exc
            injected = True
        return m.state in LATCHED_STATES or (
            m.state is MachineState.READY and m.cycle is None and runtime.periods > 2
        )

    runtime.run_for(2 * runtime.period_s)
    if not runtime.run_until(finished, CYCLE_TIMEOUT_S):
        raise RuntimeError(f"cycle did not end within {CYCLE_TIMEOUT_S:.0f} s")
    stopped = injection is not None and injection.kind == OPERATOR_STOP and injected
    if c.state in LATCHED_STATES:
        runtime.run_for(SETTLE_AFTER_ALARM_S)
        report.result = "alarm"
    elif stopped and c.partly_cut.board is not None:
        report.result = "stopped"  # the board lies partly cut: Resume or Abandon it
    report.alarms = sorted({a.code for a in c.alarms.views() if a.alarm_id not in alarms_before})
    if resume and report.result in ("alarm", "stopped"):
        _reset_and_resume(runtime, report, watch, reset=report.result == "alarm")
    if c.finished_cycles:
        piece, cycle = c.finished_cycles[-1]
        o = cycle.outcome
        report.D_mm, report.R_mm = o.d_mm, o.r_mm
        report.measured_width_mm = o.width_mm
        report.cycle_time_s = piece.cycle_time_s
        report.step_times_s = dict(piece.step_times_s)
        if report.result == "ok":
            report.cut_time_s = {"A": o.cut_time_a_s, "B": o.cut_time_b_s}
            report.cut_length_mm = {"A": o.cut_length_a_mm, "B": o.cut_length_b_mm}
    if injection is not None:
        delay = f"+{injection.after_s:g}" if injection.after_s else ""
        if not injected:
            effect = "never reached that step (or left it before that time)"
        elif stopped and report.result != "ok":
            effect = "stopped the cycle, the board partly cut"
        elif report.result != "ok":
            effect = "raised " + (", ".join(report.alarms) or "no alarm")
        else:
            effect = "had no effect in that step (the cycle ended normally)"
        report.injection = f"{injection.kind}@{injection.step.name.lower()}{delay}: {effect}"
    watch.flush_contour_error()
    report.max_contour_error_mm = watch.max_contour_error_mm
    watch.max_contour_error_mm = 0.0
    return report


def _with_profile_options(
    args: argparse.Namespace, recipe: Recipe, runtime: MachineRuntime
) -> Recipe:
    """The recipe with the side profile the options ask for (stored under a new name, so the
    database's recipe is not changed), or the recipe itself without profile options."""
    try:
        profile = profile_from_args(args)
    except ProfileOptionError as exc:
        raise UsageError(str(exc)) from exc
    if profile is None:
        return recipe
    variant = replace(
        recipe, id=None, name=f"{recipe.name[:28]} ({profile.kind.value[:8]})", profile=profile
    )
    try:
        return runtime.controller.store.save_recipe(variant)
    except ValueError as exc:
        raise UsageError(f"--profile: {exc}") from exc


def simulate(
    args: argparse.Namespace, config: MachineConfig, db_path: Path, out: TextIO
) -> dict[str, Any]:
    injection = Injection.parse(args.inject) if args.inject is not None else None
    if args.resume and injection is None:
        raise UsageError("--resume is not allowed without --inject: there is nothing to resume")
    widths = _barrel_widths(args)
    stick = config.pendant.joystick
    if args.joystick and not stick.fitted:
        raise UsageError("--joystick is not allowed: the configuration has no joystick fitted")
    if args.handwheel and not config.pendant.handwheel.fitted:
        raise UsageError("--handwheel is not allowed: the configuration has no handwheel fitted")
    try:
        jogs = hand_jogs(args, ("X", "Y", "Z") if stick.z_fitted else ("X", "Y"))
    except JogOptionError as exc:
        raise UsageError(str(exc)) from exc
    if args.width is None and not args.barrel and not jogs:
        raise UsageError(
            "--width is missing: the width of every board in mm (or --barrel, or only "
            "--handwheel / --joystick)"
        )
    if args.width is not None and (not math.isfinite(args.width) or args.width <= 0):
        raise UsageError(f"--width {args.width:g} is not allowed: a finite number of mm > 0")
    if not 1 <= args.cycles <= MAX_CYCLES:
        raise UsageError(f"--cycles {args.cycles} is not allowed: 1 to {MAX_CYCLES}")
    try:
        trace_file = args.trace.open("w", newline="", encoding="utf-8") if args.trace else None
    except OSError as exc:
        raise UsageError(f"--trace {args.trace}: cannot be written ({exc.strerror})") from None
    try:
        runtime = MachineRuntime.create(config.with_backend("sim", "sim"), db_path)
    except BaseException:
        if trace_file is not None:
            trace_file.close()
        raise
    watch = Watch()
    try:
        if trace_file is not None:
            watch.trace = csv.writer(trace_file)
            watch.trace.writerow(
                [
                    "t_s",
                    "state",
                    "x_cmd",
                    "y_cmd",
                    "z_cmd",
                    "x_act",
                    "y_act",
                    "z_act",
                    "spindle",
                    "step",
                ]
            )
        runtime.on_tick.append(watch.observe)
        runtime.start()
        recipe = _with_profile_options(args, _recipe_from_args(args, runtime.controller), runtime)
        assert recipe.id is not None
        runtime.controller.post(cmd.SelectRecipe(recipe.id))
        if args.barrel:
            runtime.controller.post(cmd.StartBarrel())
            runtime.run_for(2 * runtime.period_s)
            if runtime.controller.barrel is None:
                raise UsageError(f"--barrel: {runtime.controller.message}")
        with _tick_pacing(runtime, args.realtime):
            _home(runtime)
            jogged = run_hand_jogs(runtime, jogs) if jogs else []
            if not args.json:
                for entry in jogged:
                    print(describe_jog(entry), file=out)
            reports = []
            if args.barrel:
                reports = _raise_barrel(runtime, args.width, widths, watch, out, args.json)
            boards = args.cycles if args.width is not None and not args.barrel else 0
            for _ in range(boards):
                report = _run_cycle(runtime, args.width, injection, watch, args.resume)
                reports.append(report)
                if not args.json:
                    print(_describe(report), file=out)
                    if report.injection:
                        print(f"injected {report.injection}", file=out)
                    if report.resume:
                        print(f"resume: {report.resume}", file=out)
                if report.result not in ("ok", "resumed"):
                    break
        c = runtime.controller
        params = c.params
        limits = motion_limits(c.config, params)
        tilt = c.finished_cycles[-1][1].outcome.tilt_deg if c.finished_cycles else recipe.tilt_deg
        result = {
            "pieces": c.pieces_total,
            "final_state": c.state.value,
            "restarted": watch.restarted,
            "params": {
                "P0": [params["start_x_mm"], params["start_y_mm"]],
                "tool_radius_mm": params["tool_radius_mm"],
                "machine_height_mm": params["machine_height_mm"],
                "tilt_deg": tilt,
                "length_mm": recipe.length_mm,
                "length_ratio": recipe.length_ratio.value,
                "width_ratio": recipe.width_ratio.value,
                "feed_mm_s": params["xy_speed_mm_s"],
                "accel_mm_s2": min(limits.x.acceleration, limits.y.acceleration),
            },
            "cycles": [_cycle_json(r) for r in reports],
        }
        if jogs:
            result["jogs"] = jogged
        if args.barrel:
            result.update(_barrel_result(c, reports))
        return result
    finally:
        runtime.shutdown()
        if trace_file is not None:
            trace_file.close()


MAX_BARREL_BOARDS = 200
"""More boards than any barrel takes: a simulated barrel that has not closed by then stops."""


def _barrel_widths(args: argparse.Namespace) -> list[float] | None:
    """The --widths list (None: boards drawn from the simulation's distribution)."""
    if args.widths is None:
        return None
    if not args.barrel:
        raise UsageError("--widths is only for --barrel: use --width for single staves")
    widths: list[float] = []
    for text in args.widths.split(","):
        try:
            width = float(text)
        except ValueError:
            width = math.nan
        if not (math.isfinite(width) and width > 0):
            raise UsageError(
                f"--widths: {text.strip()!r} is not allowed: a finite number of mm > 0"
            )
        widths.append(width)
    return widths


def _raise_barrel(
    runtime: MachineRuntime,
    width_mm: float | None,
    widths: list[float] | None,
    watch: Watch,
    out: TextIO,
    quiet: bool,
) -> list[CycleReport]:
    """Boards in until the barrel closes (or the given widths run out). A board too narrow
    to close it (E034) is taken off, as an operator choosing a wider board would; the next
    board comes in after the operator's reset."""
    c = runtime.controller
    queue = list(widths) if widths is not None else None
    reports: list[CycleReport] = []
    while len(reports) < MAX_BARREL_BOARDS:
        barrel = c.barrel
        if barrel is not None and barrel.closed:
            break
        if queue is not None and not queue:
            break
        board = queue.pop(0) if queue is not None else width_mm
        report = _run_cycle(runtime, board, None, watch)
        if c.finished_cycles and report.result == "ok":
            planned = c.finished_cycles[-1][1].planned
            if planned is not None:
                _barrel_fields(report, planned)
        reports.append(report)
        if not quiet:
            print(_describe(report), file=out)
        if report.result != "ok":
            if TOO_NARROW_ALARM not in {a.code for a in c.alarms.views()}:
                break
            c.post(cmd.Reset())
            runtime.run_for(1.0)
            _home(runtime)
    return reports


def _barrel_fields(report: CycleReport, planned: PlannedStave) -> None:
    placed = planned.barrel_stave
    report.barrel_stave_number = None if placed is None else placed.number
    report.tilt_a_deg = planned.cut.tilts.a_deg
    report.tilt_b_deg = planned.cut.tilts.b_deg
    report.target_width_mm = None if placed is None else placed.target_width_mm
    report.passes = planned.cut.passes


def _barrel_result(c: MachineController, reports: list[CycleReport]) -> dict[str, Any]:
    """Whether the barrel closed, and the gap the cut staves leave: the last stave's second
    joint, placed at the width it was cut to, against the first stave's first joint."""
    barrel = c.barrel
    closed = barrel is not None and barrel.closed
    gap: float | None = None
    if closed and barrel is not None and c.finished_cycles:
        planned = c.finished_cycles[-1][1].planned
        if planned is not None and planned.barrel_stave is not None:
            start = planned.barrel_stave.stave.start_t_rad
            end = next_joint_t(barrel.section, start, planned.cut.width_mm)
            gap = math.dist(barrel.section.point(end), barrel.section.point(0.0))
    return {
        "barrel_closed": closed,
        "barrel_staves": 0 if barrel is None else len(barrel.staves),
        "closing_gap_mm": gap,
    }


def _cycle_json(r: CycleReport) -> dict[str, Any]:
    return {
        "width_mm": r.width_mm,
        "measured_width_mm": r.measured_width_mm,
        "D_mm": r.D_mm,
        "R_mm": r.R_mm,
        "cycle_time_s": r.cycle_time_s,
        "cut_time_s": r.cut_time_s,
        "cut_length_mm": r.cut_length_mm,
        "step_times_s": r.step_times_s,
        "max_contour_error_mm": r.max_contour_error_mm,
        "result": r.result,
        "alarms": r.alarms,
        "injection": r.injection or None,
        "resume": r.resume or None,
        **(
            {}
            if r.passes is None
            else {
                "barrel_stave_number": r.barrel_stave_number,
                "tilt_a_deg": r.tilt_a_deg,
                "tilt_b_deg": r.tilt_b_deg,
                "target_width_mm": r.target_width_mm,
                "passes": r.passes,
            }
        ),
    }


def _describe(r: CycleReport) -> str:
    interrupted = f"ALARM {', '.join(r.alarms)}" if r.alarms else "STOPPED"
    if r.result == "resumed":
        return f"width {r.width_mm:.2f} mm: {interrupted}, then resumed"
    if r.result == "stopped":
        return f"width {r.width_mm:.2f} mm: STOPPED by the operator, the board partly cut"
    if r.result != "ok":
        return f"width {r.width_mm:.2f} mm: ALARM {', '.join(r.alarms) or '(none)'}"
    # A curved side (a family, a drawing) has no single rise D and radius R.
    shape = (
        "a fitted curve (no D, R)"
        if r.D_mm is None or r.R_mm is None
        else f"D {r.D_mm:.4f} mm, R {r.R_mm:.2f} mm"
    )
    return (
        f"width {r.width_mm:.2f} mm: {shape}, "
        f"cycle {r.cycle_time_s:.2f} s (cut A {r.cut_time_s['A']:.2f} s, "
        f"B {r.cut_time_s['B']:.2f} s), max contour error {r.max_contour_error_mm:.4f} mm"
    )


def simulation_database(requested: Path | None, tmp: Path, out: TextIO) -> Path:
    """The database the run writes into: never one the panel uses (see the module text)."""
    from app.data.backup import backup_database
    from app.data.database import Database

    if requested is None:
        path = tmp / "simulate.db"
    elif not requested.exists():
        path = requested
    else:
        with Database.open(requested) as existing:
            if existing.for_simulation:
                return requested
        copy = tmp / "simulate.db"
        backup_database(requested, copy)
        print(
            f"stave simulate: {requested} is not a simulation's database: the run reads its "
            "recipes and parameters from a copy and writes nothing into it",
            file=out,
        )
        return copy  # a private copy, deleted with the run
    with Database.open(path) as created:
        created.mark_for_simulation()
    return path


def run(args: argparse.Namespace) -> int:
    from app.data.errors import DataError

    try:
        config = load_config(args.config)
        with tempfile.TemporaryDirectory() as tmp:
            db_path = simulation_database(args.db, Path(tmp), sys.stderr)
            result = simulate(args, config, db_path, sys.stdout)
    except (ConfigError, UsageError, DataError) as exc:
        print(f"stave simulate: {exc}", file=sys.stderr)
        return 2
    except RuntimeError as exc:  # the simulated machine did not do what it should
        print(f"stave simulate: {exc}", file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        print(
            f"pieces {result['pieces']}, final state {result['final_state']}, "
            f"restarted {str(result['restarted']).lower()}"
        )
    return 0
