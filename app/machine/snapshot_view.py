"""The controller's state as the immutable snapshot the screens sample (see
:mod:`app.machine.snapshot`), and the state in words for the status line."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from app.config import MachineConfig
from app.data.recipe import Recipe
from app.drivers.contracts import InputImage, MachineBackend, OutputImage
from app.machine.alarms import AlarmManager
from app.machine.axes import AxisGroup
from app.machine.barrel_set import BarrelSet, BoardChoice
from app.machine.barrel_view import barrel_view
from app.machine.cycle import AutomaticCycle
from app.machine.homing import HomingSequence
from app.machine.manual import ManualControl
from app.machine.pendant.jog_sources import PendantJog
from app.machine.permissions import Facts, allowed_commands
from app.machine.refusals import Refusal
from app.machine.snapshot import AxisView, CycleView, IoPoint, MachineSnapshot
from app.machine.states import LATCHED_STATES, CycleStep, MachineState, Mode


class MachineController(Protocol):
    """What the snapshot reads of the controller (``app.machine.controller``); a protocol,
    so that this module does not import the controller that imports it."""

    config: MachineConfig
    backend: MachineBackend
    alarms: AlarmManager
    axes: AxisGroup
    manual: ManualControl
    state: MachineState
    mode: Mode
    now_s: float
    wall_clock: Callable[[], float]
    inputs: InputImage
    outputs: OutputImage
    recipe: Recipe | None
    cycle: AutomaticCycle | None
    homing: HomingSequence | None
    feed_override_pct: float
    message: Refusal | None
    io_points: tuple[IoPoint, ...]
    pendant_jog: PendantJog
    barrel: BarrelSet | None
    message_serial: int
    board_choice: BoardChoice | None

    @property
    def pieces_shift(self) -> int: ...

    @property
    def plan_shifts_begun(self) -> int: ...

    @property
    def pieces_total(self) -> int: ...

    @property
    def last_width_mm(self) -> float | None: ...

    @property
    def last_cycle_time_s(self) -> float | None: ...

    @property
    def last_wait_s(self) -> float | None: ...

    @property
    def last_step_times_s(self) -> dict[str, float]: ...

    @property
    def plan_id(self) -> int: ...

    def facts(self) -> Facts: ...


def state_text(c: MachineController) -> str:
    if c.state is MachineState.AUTOMATIC and c.cycle is not None:
        return f"automatic: {c.cycle.step.value}"
    if c.state in LATCHED_STATES:
        faults = c.alarms.active_faults()
        return f"{c.state.value}: {faults[0].text}" if faults else c.state.value
    if c.state is MachineState.MANUAL and c.homing is not None:
        return f"manual: homing {c.homing.current_axis}"
    if c.state is MachineState.HOMING and c.homing is not None:
        return f"homing {c.homing.current_axis}"
    return c.state.value


def build_snapshot(c: MachineController, seq: int) -> MachineSnapshot:
    axes = tuple(
        AxisView(
            n,
            c.config.axes[n].unit,
            fb.position,
            c.axes.command.get(n, 0.0),
            fb.following_error,
            fb.homed,
            fb.enabled,
            fb.faulted,
            fb.fault_code,
            fb.homing_active,
            fb.limit_negative,
            fb.limit_positive,
            fb.power_state.value,
        )
        for n, fb in c.axes.feedback.items()
    )
    cycle = c.cycle
    planned = cycle.planned if cycle is not None else None
    following = cycle.following_executor if cycle is not None else None
    cycle_view = CycleView(
        step=cycle.step if cycle is not None else None,
        elapsed_s=c.now_s - cycle.started_s if cycle is not None else 0.0,
        remaining_s=cycle.remaining_s() if cycle is not None else 0.0,
        width_mm=cycle.outcome.width_mm if cycle is not None else None,
        d_mm=planned.profile.D if planned else None,
        r_mm=planned.profile.R if planned else None,
        tilt_deg=planned.tilt_deg if planned else None,
        finished_board_on_table=cycle is not None
        and cycle.step is CycleStep.WAIT_FOR_PART
        and cycle.board_already_cut
        and c.inputs.part_present,
        waited_s=cycle.waited_s(c.now_s) if cycle is not None else 0.0,
        working_s=cycle.working_s(c.now_s) if cycle is not None else 0.0,
        progress=cycle.path_progress() if cycle is not None else None,
        move_to_go_mm=following.distance_to_go_mm if following is not None else None,
        phase_to_go_mm=following.phase_distance_to_go_mm if following is not None else None,
        path_velocity_mm_s=following.path_velocity_mm_s if following is not None else None,
    )
    recipe = c.recipe
    return MachineSnapshot(
        seq=seq,
        machine_time_s=c.now_s,
        wall_time=c.wall_clock(),
        state=c.state,
        mode=c.mode,
        state_text=state_text(c),
        backend=c.backend.name,
        axes=axes,
        inputs=c.inputs,
        outputs=c.outputs,
        alarms=c.alarms.views(),
        recipe_id=recipe.id if recipe else None,
        recipe_name=recipe.name if recipe else "",
        pieces_shift=c.pieces_shift,
        plan_shifts_begun=c.plan_shifts_begun,
        pieces_total=c.pieces_total,
        last_width_mm=c.last_width_mm,
        last_cycle_time_s=c.last_cycle_time_s,
        cycle=cycle_view,
        feed_override_pct=c.feed_override_pct,
        plan_id=c.plan_id,
        jog_xy=c.manual.speed("XY"),
        jog_z=c.manual.speed("Z"),
        pendant=c.pendant_jog.view(),
        allowed=allowed_commands(c.facts()),
        message=c.message,
        io_points=c.io_points,
        message_serial=c.message_serial,
        barrel=None
        if c.barrel is None
        else barrel_view(c.barrel, planned.barrel_stave if planned else None, c.board_choice),
        last_step_times_s=tuple(c.last_step_times_s.items()),
        last_wait_s=c.last_wait_s,
        homing=c.homing.view(c.now_s) if c.homing is not None else None,
    )
