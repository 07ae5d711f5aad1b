"""The simulated machine's physical world: three drives, the I/O devices, the board, the
E-stop chain and guard, the links, and simulated time.

Why one owner of everything physical: the adapters in :mod:`app.drivers.sim.backend` and the
gauge are thin views onto one world, so that a fault injected here shows on every view the
way the real machine would show it, and so that time advances in exactly one place.

Time: there is no wall clock. :meth:`SimWorld.advance` integrates by a fixed substep of at
most 1 ms (the machine period divided into whole substeps, counted in integer nanoseconds), so
the result does not depend on how a caller chops time: 4 ms chunks and 1 ms chunks give
identical states. The fieldbus SYNC falls on the first substep of every period: the master
(the motion adapter's hook) sends controlwords, modes and targets then, as a cyclic PDO
exchange would, and the simulated operator and the I/O watchdog are evaluated then too.

Operator actions: :meth:`press_start`, :meth:`press_stop`, :meth:`press_reset` (momentary,
100 ms of simulated time), :meth:`set_estop` (latching), :meth:`set_guard`,
:meth:`load_board` / :meth:`remove_board` and :meth:`queue_board_widths`. With ``auto_load``
a simulated operator takes each finished board away and puts in the next.
"""

from __future__ import annotations

import enum
import math
import random
from collections import deque
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, replace

from app.config import MachineConfig
from app.drivers.contracts import AXIS_NAMES, InputImage, OutputImage
from app.drivers.sim.drive import DriveParams, SimDrive
from app.drivers.sim.io import MachineIO
from app.drivers.sim.pendant import SimHandwheel, SimJoystick
from app.drivers.sim.settings import SimSettings, parse_sim_settings

MAX_SUBSTEP_S = 0.001
LINKS: tuple[str, ...] = ("drives", "io", "gauge")


@dataclass(frozen=True)
class Board:
    """The board on the table; ``number`` counts boards put in since power-up."""

    true_width_mm: float
    number: int


@dataclass(frozen=True)
class EmcyRecord:
    """An emergency message a drive sent (only while its link was up)."""

    time_s: float
    device: str
    code: int
    text: str


@dataclass(frozen=True)
class LinkChange:
    time_s: float
    link: str
    ok: bool


class GaugeMode(enum.Enum):
    """How the gauge answers (fault injection)."""

    NORMAL = "normal"
    NO_REPLY = "no reply"
    GARBAGE = "garbage"
    OUT_OF_RANGE = "out of range"


@dataclass
class GaugeLine:
    """The gauge's condition: how it answers, and whether its cable is plugged in."""

    mode: GaugeMode = GaugeMode.NORMAL
    plugged: bool = True


class SimWorld:
    """Everything physical of the simulated machine."""

    def __init__(self, config: MachineConfig, settings: SimSettings | None = None) -> None:
        self.config = config
        self.settings = settings if settings is not None else SimSettings()
        period_ns = round(config.period_s * 1e9)
        self.substeps_per_period = max(1, math.ceil(period_ns / (MAX_SUBSTEP_S * 1e9) - 1e-9))
        self._substep_ns = period_ns // self.substeps_per_period
        self.substep_s = self._substep_ns / 1e9
        self.period_s = config.period_s
        self._pending_ns = 0
        self._count = 0
        self._phase = 0
        self._sync_hooks: list[Callable[[], None]] = []
        self.emcy_log: list[EmcyRecord] = []
        self.link_log: list[LinkChange] = []
        self._links = dict.fromkeys(LINKS, True)
        self._io_lost_at_s: float | None = None
        self.gauge_line = GaugeLine()

        seed = self.settings.seed
        start_rng = random.Random(f"{seed}/start")
        self._board_rng = random.Random(f"{seed}/boards")
        self.drives: dict[str, SimDrive] = {}
        for name in AXIS_NAMES:
            axis = config.axes[name]
            if name in self.settings.start_position:
                start = self.settings.start_position[name]
            elif axis.absolute_encoder:
                start = axis.home_position
            else:
                start = start_rng.uniform(axis.min_position, axis.max_position)
            params = DriveParams.from_config(
                axis, self.settings, self.period_s, self.substeps_per_period
            )
            self.drives[name] = SimDrive(name, params, start, self._record_emcy)
        self._drive_list = list(self.drives.values())

        io = config.io
        self.io = MachineIO(io.centering_time_s, io.clamp_time_s, io.spindle_runup_s)
        self.board: Board | None = None
        self._boards_loaded = 0
        self._width_queue: deque[float] = deque()
        self._board_clamped = False
        self._unload_at_s: float | None = None
        self._load_at_s: float | None = None
        if self.settings.board_present or self.settings.auto_load:
            self.load_board()
        stick = config.pendant.joystick
        self.handwheel = SimHandwheel()
        self.joystick = SimJoystick(stick.mid_scale_counts, stick.full_scale_counts)

    @classmethod
    def from_config(cls, config: MachineConfig) -> SimWorld:
        """The world the configuration describes; ``[backend.sim]`` is checked here."""
        raw = config.backend_settings.get("sim", {})
        return cls(config, parse_sim_settings(raw, config.axes))

    # -- time ------------------------------------------------------------------------------
    @property
    def time_s(self) -> float:
        """Simulated time since power-up."""
        return self._count * self._substep_ns / 1e9

    def advance(self, dt_s: float) -> None:
        """Integrate everything by ``dt_s`` seconds of simulated time, in fixed substeps;
        a remainder shorter than a substep is carried over to the next call."""
        if (
            isinstance(dt_s, bool)
            or not isinstance(dt_s, int | float)
            or not (math.isfinite(dt_s) and dt_s >= 0.0)
        ):
            raise ValueError(f"dt_s = {dt_s!r} is not allowed: a finite number >= 0")
        self._pending_ns += round(dt_s * 1e9)
        steps, self._pending_ns = divmod(self._pending_ns, self._substep_ns)
        dt = self.substep_s
        drives = self._drive_list
        io_step = self.io.step
        n = self.substeps_per_period
        for _ in range(steps):
            if self._phase == 0:
                self._sync()
            self._phase = (self._phase + 1) % n
            io_step(dt)
            for drive in drives:
                drive.step(dt)
            self._count += 1
        if steps:
            self.handwheel.step(steps * dt)

    def add_sync_hook(self, hook: Callable[[], None]) -> None:
        """``hook`` runs at every SYNC while the drives' link is up (the master's PDOs)."""
        self._sync_hooks.append(hook)

    def _sync(self) -> None:
        if self._links["drives"]:
            for hook in self._sync_hooks:
                hook()
        if (
            self._io_lost_at_s is not None
            and self.time_s - self._io_lost_at_s >= self.settings.heartbeat_timeout_s
        ):
            self.io.switch_outputs_off()
            self._io_lost_at_s = None
        if self.settings.auto_load:
            self._simulated_operator()

    def _record_emcy(self, device: str, code: int, text: str) -> None:
        self.emcy_log.append(EmcyRecord(self.time_s, device, code, text))

    # -- links -----------------------------------------------------------------------------
    def link_ok(self, link: str) -> bool:
        return self._links[_check_link(link)]

    def set_link(self, link: str, ok: bool) -> None:
        """Cut (``ok=False``) or restore one link: "drives", "io" or "gauge"."""
        link = _check_link(link)
        if self._links[link] == ok:
            return
        self._links[link] = ok
        self.link_log.append(LinkChange(self.time_s, link, ok))
        if link == "drives":
            for drive in self._drive_list:
                drive.set_link(ok)
        elif link == "io":
            self._io_lost_at_s = None if ok else self.time_s
        else:
            self.gauge_line.plugged = ok

    # -- I/O -------------------------------------------------------------------------------
    def inputs(self) -> InputImage:
        """What the input terminals read now (the handwheel and the joystick as the
        configuration says they are fitted)."""
        image = self.io.inputs(self.time_s, self.board is not None)
        pendant = self.config.pendant
        if not (pendant.handwheel.fitted or pendant.joystick.fitted):
            return image
        wheel = self.handwheel.inputs()
        stick = self.joystick
        return replace(
            image,
            handwheel_x=wheel.axis == "X",
            handwheel_y=wheel.axis == "Y",
            handwheel_z=wheel.axis == "Z",
            handwheel_x10=wheel.multiplier == 10,
            handwheel_x100=wheel.multiplier == 100,
            jog_enable=wheel.enable,
            handwheel_count=wheel.count if pendant.handwheel.fitted else None,
            joystick_x=stick.counts("X") if pendant.joystick.fitted else None,
            joystick_y=stick.counts("Y") if pendant.joystick.fitted else None,
            joystick_z=stick.counts("Z") if pendant.joystick.z_fitted else None,
        )

    def write_outputs(self, outputs: OutputImage) -> None:
        self.io.apply_outputs(outputs)

    @property
    def outputs(self) -> OutputImage:
        """The outputs as last written (lamps included)."""
        return self.io.outputs

    # -- operator --------------------------------------------------------------------------
    def press_start(self) -> None:
        self.io.start_button.press(self.time_s)

    def press_stop(self) -> None:
        self.io.stop_button.press(self.time_s)

    def press_reset(self) -> None:
        self.io.reset_button.press(self.time_s)

    def set_estop(self, pressed: bool) -> None:
        """Press (latching) or release the E-stop: the chain opens, the spindle contactor
        drops and the drives get safe torque off (stop category 1)."""
        self.io.estop_pressed = pressed
        for drive in self._drive_list:
            drive.set_sto(pressed)

    def set_guard(self, closed: bool) -> None:
        self.io.guard_closed = closed

    def queue_board_widths(self, widths: Iterable[float]) -> None:
        """True widths for the next boards put in without a width, in order."""
        values = [_check_width(w, "width") for w in widths]
        self._width_queue.extend(values)

    def load_board(self, width_mm: float | None = None) -> Board:
        """Put a board on the table: of ``width_mm``, else the next queued width, else one
        drawn from the board width distribution."""
        if width_mm is not None:
            width = _check_width(width_mm, "width_mm")
        elif self._width_queue:
            width = self._width_queue.popleft()
        else:
            width = self.settings.board_widths.draw(self._board_rng)
        self._boards_loaded += 1
        self.board = Board(width, self._boards_loaded)
        self._board_clamped = False
        self._unload_at_s = None
        self._load_at_s = None
        return self.board

    def remove_board(self) -> None:
        """Take the board away; with ``auto_load`` the next one follows after the delay."""
        self.board = None
        self._board_clamped = False
        self._unload_at_s = None
        if self.settings.auto_load:
            self._load_at_s = self.time_s + self.settings.operator_delay_s

    def _simulated_operator(self) -> None:
        now = self.time_s
        if self.board is None:
            if self._load_at_s is None:
                self._load_at_s = now + self.settings.operator_delay_s
            if now >= self._load_at_s:
                self.load_board()
            return
        clamps = self.io.clamps.position
        if clamps >= 1.0:
            self._board_clamped = True
            self._unload_at_s = None
        elif self._board_clamped and clamps <= 0.0 and self._unload_at_s is None:
            self._unload_at_s = now + self.settings.operator_delay_s
        if self._unload_at_s is not None and now >= self._unload_at_s:
            self.remove_board()

    # -- views for tests and displays -----------------------------------------------------
    def axis_positions(self) -> Mapping[str, float]:
        """True positions of the axes (what a ruler on the machine would show)."""
        return {name: drive.true_position for name, drive in self.drives.items()}


def _check_link(link: str) -> str:
    if link not in LINKS:
        raise ValueError(f"link = {link!r} is not allowed: one of {', '.join(LINKS)}")
    return link


def _check_width(value: float, field_name: str) -> float:
    if (
        isinstance(value, bool)
        or not isinstance(value, int | float)
        or not (math.isfinite(value) and value > 0.0)
    ):
        raise ValueError(f"{field_name} = {value!r} is not allowed: a finite number of mm > 0")
    return float(value)
