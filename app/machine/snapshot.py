"""The immutable picture of the machine that the screens sample.

Why a snapshot and not signals from the machine: the machine runs in its own process at the
setpoint period; the GUI samples the latest snapshot at 20-50 Hz and draws only what changed
(after QtPyVCP's status plugin). A slow screen can drop snapshots, never delay the machine.
Everything here is plain data that pickles small; the tool path preview, which is large, is
sent once per plan as a :class:`PlanPreview` and referred to by ``plan_id``.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from app.drivers.contracts import InputImage, OutputImage
from app.machine.barrel_view import BarrelView
from app.machine.refusals import Refusal
from app.machine.states import CycleStep, MachineState, Mode


class AlarmState(enum.Enum):
    """ISA-18.2 alarm states."""

    NORMAL = "normal"
    ACTIVE_UNACKED = "active, unacknowledged"
    ACTIVE_ACKED = "active, acknowledged"
    RTN_UNACKED = "returned to normal, unacknowledged"


@dataclass(frozen=True)
class AxisView:
    name: str
    unit: str
    position: float
    command: float
    following_error: float
    homed: bool
    enabled: bool
    faulted: bool
    fault_code: int
    homing: bool
    limit_negative: bool
    limit_positive: bool
    power_state: str


@dataclass(frozen=True)
class AlarmArgument:
    """One value an alarm is about (the axis, the value measured, its limit), kept as data
    beside the text so that a plant system can read it without parsing words."""

    name: str
    value: float | int | str
    unit: str = ""


@dataclass(frozen=True)
class AlarmView:
    alarm_id: int
    code: str
    text: str
    source: str
    state: AlarmState
    raised_at: float  # epoch seconds
    severity: str  # "fault" (stops the machine) or "warning"
    arguments: tuple[AlarmArgument, ...] = ()
    detail: Refusal | None = None  # what was found, for the screens to translate
    technical: str = ""  # a device's own words (English), for the alarm's details


@dataclass(frozen=True)
class CycleView:
    step: CycleStep | None
    elapsed_s: float  # since Start
    remaining_s: float
    width_mm: float | None  # the board's, as soon as the gauge has measured it
    d_mm: float | None
    r_mm: float | None
    tilt_deg: float | None
    finished_board_on_table: bool = False  # waiting for a board while the last one lies there
    waited_s: float = 0.0  # of elapsed_s, the wait for the board (so far, while waiting)
    working_s: float = 0.0  # of elapsed_s, the time since the board was there
    # 0 .. 1 along the planned path; None while the step has no known length (a wait for a
    # board, a sensor, the gauge or the spindle) or while stopping: no progress bar then.
    progress: float | None = None
    # While the axes follow the path: the X-Y path left in this move and in this phase (a
    # side's cut with all its passes), and the speed along the path; None otherwise.
    move_to_go_mm: float | None = None
    phase_to_go_mm: float | None = None
    path_velocity_mm_s: float | None = None


@dataclass(frozen=True)
class HomingView:
    """Where a homing run is, for the screens: the axes it homes in their order, those done,
    the one homing now ("" once done), whether it first moves clear of a board, and how long
    it has run (machine seconds)."""

    axes: tuple[str, ...]
    done: tuple[str, ...]
    current: str
    clearing: bool
    elapsed_s: float


@dataclass(frozen=True)
class IoPoint:
    """One digital input or output of the machine and where it is wired on the configured
    backend, for the technicians' I/O page (its state is in ``inputs`` / ``outputs``)."""

    signal: str  # the field of InputImage or OutputImage
    output: bool
    address: str  # e.g. "unit 3, discrete input 10004"; "" when the signal is not wired


@dataclass(frozen=True)
class PlanPreview:
    """What the plan view draws: the stave outline and the tool path, in machine X/Y."""

    plan_id: int
    outline_xy: tuple[tuple[float, float], ...]
    toolpath_xy: tuple[tuple[float, float], ...]
    cutting_mask: tuple[bool, ...]


class JogSource(enum.Enum):
    """Who jogs in manual mode: one of them at a time."""

    SCREEN = "screen"
    HANDWHEEL = "handwheel"
    JOYSTICK = "joystick"
    PENDANT = "pendant"  # a USB pendant or gamepad


@dataclass(frozen=True)
class PendantView:
    """The machine's own jog controls as the Manual screen shows them: who jogs now, the
    handwheel's selected axis ("" off) and multiplier, and what is fitted."""

    jog_source: JogSource | None = None
    wheel_axis: str = ""
    wheel_multiplier: int = 1
    handwheel_fitted: bool = False
    joystick_fitted: bool = False
    pendant_connected: bool = False


@dataclass(frozen=True)
class MachineSnapshot:
    seq: int
    machine_time_s: float
    wall_time: float  # epoch seconds
    state: MachineState
    mode: Mode
    state_text: str
    backend: str
    axes: tuple[AxisView, ...]
    inputs: InputImage
    outputs: OutputImage
    alarms: tuple[AlarmView, ...]  # every alarm not NORMAL, newest first
    recipe_id: int | None
    recipe_name: str
    pieces_shift: int
    plan_shifts_begun: int  # counts up when the shift plan's next shift begins
    pieces_total: int
    last_width_mm: float | None
    last_cycle_time_s: float | None  # from Start to the clamps open, the wait included
    cycle: CycleView
    feed_override_pct: float
    plan_id: int  # 0: no plan
    jog_xy: tuple[float, float]  # velocity, acceleration of manual X-Y jog
    jog_z: tuple[float, float]
    # command name (the class name in app.machine.commands) -> None if allowed now, or why not
    allowed: dict[str, Refusal | None] = field(default_factory=dict)
    message: Refusal | None = None  # the last refusal or notice for the operator
    io_points: tuple[IoPoint, ...] = ()  # every input, then every output, in image order
    pendant: PendantView = field(default_factory=PendantView)
    barrel: BarrelView | None = None  # the barrel being raised (None: single staves)
    # Where the last finished cycle's seconds went: (timed step name, seconds), in order.
    last_step_times_s: tuple[tuple[str, float], ...] = ()
    message_serial: int = 0  # counts every message given, so a repeated one is seen as new
    last_wait_s: float | None = None  # of last_cycle_time_s, the wait for the board
    homing: HomingView | None = None  # a homing run, in automatic or manual mode

    def axis(self, name: str) -> AxisView:
        for axis in self.axes:
            if axis.name == name:
                return axis
        raise KeyError(name)

    @property
    def last_work_time_s(self) -> float | None:
        """The last cycle's time without its wait for the board (from the board's arrival to
        the clamps open)."""
        if self.last_cycle_time_s is None:
            return None
        return max(self.last_cycle_time_s - (self.last_wait_s or 0.0), 0.0)

    @property
    def all_homed(self) -> bool:
        return all(a.homed for a in self.axes)

    @property
    def unacknowledged_alarms(self) -> int:
        return sum(
            1 for a in self.alarms if a.state in (AlarmState.ACTIVE_UNACKED, AlarmState.RTN_UNACKED)
        )
