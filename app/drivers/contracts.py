"""The contracts every backend implements: axes, digital I/O and the width gauge.

Why one contract per device role: the machine layer (state machine, executor) must run
unchanged on the simulation, on Modbus and on CANopen. It therefore talks only to these
abstract classes, and every backend (``app.drivers.sim``, ``app.drivers.modbus``,
``app.drivers.canopen``, ``app.drivers.serial_gauge``) implements them.

Why a lifecycle (configure -> activate -> deactivate -> shutdown, after ros2_control's
hardware_interface): opening a port, mapping PDOs or connecting to a server can fail, and
those failures must surface at a known moment, never half-way through a cut. Motion commands
are refused unless the backend is ACTIVE, and on activation the command position is set to
the measured one so that nothing jumps.

Why cyclic ``read``/``write`` methods and no callbacks: the machine loop owns time. Once per
period it reads every device, decides, then writes every device. A backend that simulates
physics also implements :class:`TimeDriven`, and the loop advances it by exactly one period,
so the simulation behaves the same in real time and on a simulated clock.

Errors are surfaced, never swallowed: a failed exchange raises :class:`DriverError` (or its
subclass :class:`CommunicationError`) from the call that hit it, and asynchronous events
(EMCY messages, a lost heartbeat, a dead receive thread) are queued and returned by
``events()``.
"""

from __future__ import annotations

import enum
from abc import ABC, abstractmethod
from collections.abc import Mapping
from dataclasses import dataclass, field, fields
from typing import Protocol, runtime_checkable

from app.drivers.cia402 import Cia402State, decode_statusword

AXIS_NAMES: tuple[str, ...] = ("X", "Y", "Z")


class DriverError(Exception):
    """A device reported a failure; ``device`` names it, ``code`` is its error code if any."""

    def __init__(self, device: str, message: str, code: int | None = None) -> None:
        super().__init__(f"{device}: {message}")
        self.device = device
        self.code = code


class CommunicationError(DriverError):
    """The device did not answer, answered garbage, or the link is gone."""


class LifecycleError(DriverError):
    """A call was made in a lifecycle state that does not allow it (for example a motion
    command while the backend is not ACTIVE)."""


class LifecycleState(enum.Enum):
    """ros2_control's primary states; ERROR is entered when configure/activate fail."""

    UNCONFIGURED = "unconfigured"
    INACTIVE = "inactive"
    ACTIVE = "active"
    FINALIZED = "finalized"
    ERROR = "error"


@dataclass(frozen=True)
class AxisFeedback:
    """What one axis reports in one period, in axis units (mm for X/Y, degrees for Z)."""

    name: str
    statusword: int
    position: float
    velocity: float
    following_error: float
    fault_code: int = 0  # CiA 301 emergency error code of the active fault, 0 when none
    homed: bool = False
    homing_active: bool = False
    home_switch: bool = False
    limit_positive: bool = False
    limit_negative: bool = False

    @property
    def power_state(self) -> Cia402State:
        return decode_statusword(self.statusword)

    @property
    def enabled(self) -> bool:
        return self.power_state is Cia402State.OPERATION_ENABLED

    @property
    def faulted(self) -> bool:
        return self.power_state in (Cia402State.FAULT, Cia402State.FAULT_REACTION_ACTIVE)


@dataclass(frozen=True)
class InputImage:
    """The machine's digital inputs, by function (the backend maps them to terminals).

    ``estop_ok`` and ``guard_closed`` are True when the safety chain is healthy: a broken
    wire reads as a stop, as the hard-wired chain itself does."""

    part_present: bool = False
    centering_extended: bool = False
    centering_retracted: bool = True
    clamps_closed: bool = False
    clamps_open: bool = True
    spindle_running: bool = False
    guard_closed: bool = True
    estop_ok: bool = True
    start_button: bool = False
    stop_button: bool = False
    reset_button: bool = False
    # The handwheel's axis selector (none on: off), its multiplier (neither on: x1) and the
    # enable (dead-man) button of the handwheel and the joystick; unwired they read off.
    handwheel_x: bool = False
    handwheel_y: bool = False
    handwheel_z: bool = False
    handwheel_x10: bool = False
    handwheel_x100: bool = False
    jog_enable: bool = False
    # Raw values of registers and analog inputs: the handwheel's 16-bit counter (0..65535)
    # and the joystick's analog inputs (counts); None when not wired or not read.
    handwheel_count: int | None = None
    joystick_x: int | None = None
    joystick_y: int | None = None
    joystick_z: int | None = None


DIGITAL_INPUTS: tuple[str, ...] = tuple(
    f.name for f in fields(InputImage) if f.type in ("bool", bool)
)
"""The inputs a terminal bit carries (the I/O maps name them)."""
PENDANT_INPUTS: tuple[str, ...] = (
    "handwheel_x",
    "handwheel_y",
    "handwheel_z",
    "handwheel_x10",
    "handwheel_x100",
    "jog_enable",
)
"""Digital inputs only a machine with a handwheel or a joystick wires (optional in a map)."""
ANALOG_INPUTS: tuple[str, ...] = ("handwheel_count", "joystick_x", "joystick_y", "joystick_z")
"""The inputs a register or an analog input carries."""


@dataclass(frozen=True)
class OutputImage:
    """The machine's digital outputs, by function."""

    centering_extend: bool = False
    clamps_close: bool = False
    spindle_on: bool = False
    lamp_green: bool = False
    lamp_yellow: bool = False
    lamp_red: bool = False


class DeviceEventKind(enum.Enum):
    EMERGENCY = "emergency"  # EMCY message or fault code reported by a drive
    COMMUNICATION_LOST = "communication lost"
    COMMUNICATION_RESTORED = "communication restored"
    RECEIVE_THREAD_DIED = "receive thread died"


@dataclass(frozen=True)
class DeviceEvent:
    """Something a device said (or stopped saying) between two periods."""

    kind: DeviceEventKind
    device: str
    code: int = 0
    text: str = ""


class Lifecycle(ABC):
    """configure -> activate -> deactivate -> shutdown; every transition may raise DriverError."""

    @property
    @abstractmethod
    def lifecycle_state(self) -> LifecycleState: ...

    @abstractmethod
    def configure(self) -> None:
        """Open links and check the devices answer; no power is applied."""

    @abstractmethod
    def activate(self) -> None:
        """Start cyclic exchange; command positions are set to the measured ones."""

    @abstractmethod
    def deactivate(self) -> None:
        """Stop cyclic exchange; drives are disabled, outputs switched off."""

    @abstractmethod
    def shutdown(self) -> None:
        """Release every resource; safe to call in any state, more than once."""

    def events(self) -> list[DeviceEvent]:
        """Asynchronous events since the last call (EMCY, link lost, ...)."""
        return []


class MotionBackend(Lifecycle):
    """Servo axes driven in cyclic synchronous position mode.

    Power-state requests (``enable``, ``disable``, ``quick_stop``, ``fault_reset``,
    ``start_homing``) are non-blocking: they set the controlword, and the drive's answer
    appears in the following ``read_axes`` results. The machine layer decides when to call
    them; a backend never re-enables or resets a drive on its own.
    """

    @property
    @abstractmethod
    def axis_names(self) -> tuple[str, ...]: ...

    @abstractmethod
    def read_axes(self) -> Mapping[str, AxisFeedback]:
        """Feedback of every axis for this period."""

    @abstractmethod
    def write_setpoints(self, positions: Mapping[str, float]) -> None:
        """Target positions for this period, applied on all axes at the same instant
        (one SYNC, one Modbus transaction set, one simulation step): no skew between axes."""

    @abstractmethod
    def enable(self, axis: str) -> None:
        """Walk the CiA 402 machine to OPERATION ENABLED (shutdown, switch on, enable)."""

    @abstractmethod
    def disable(self, axis: str) -> None:
        """Disable voltage: the drive ends in SWITCH ON DISABLED."""

    @abstractmethod
    def quick_stop(self, axis: str) -> None:
        """Quick stop: the drive decelerates on its own ramp and holds."""

    @abstractmethod
    def fault_reset(self, axis: str) -> None:
        """Controlword 0x00 then 0x80 (rising edge of bit 7). Only ever called on an
        operator's action; the drive ends in SWITCH ON DISABLED, not enabled."""

    @abstractmethod
    def start_homing(self, axis: str) -> None:
        """Start the drive's homing method; ``AxisFeedback.homing_active``/``homed`` follow."""


class DigitalIO(Lifecycle):
    """The machine's discrete inputs and outputs."""

    @abstractmethod
    def read_inputs(self) -> InputImage: ...

    @abstractmethod
    def write_outputs(self, outputs: OutputImage) -> None: ...


@dataclass(frozen=True)
class GaugeReading:
    """One answer of the width gauge: a width, or the reason there is none."""

    width_mm: float | None
    raw: str = ""
    error: str = ""

    @property
    def ok(self) -> bool:
        return self.width_mm is not None and not self.error


class WidthGauge(Lifecycle):
    """The board width gauge. ``request`` asks for a fresh reading (no-op for streaming
    gauges); ``poll`` never blocks and returns the first complete reading since the request,
    or None while there is none yet. An unplugged gauge raises CommunicationError."""

    @abstractmethod
    def request(self) -> None: ...

    @abstractmethod
    def poll(self) -> GaugeReading | None: ...


@runtime_checkable
class TimeDriven(Protocol):
    """Implemented by simulated devices: the machine loop advances them by one period."""

    def advance(self, dt_s: float) -> None: ...


@runtime_checkable
class FaultInjector(Protocol):
    """Implemented by the simulation: faults a test, ``stave simulate`` or a technician
    injects. ``kind`` is one of FAULT_KINDS; ``target`` an axis name where it applies."""

    def inject(self, kind: str, target: str = "") -> None: ...

    def clear_injections(self) -> None: ...


@runtime_checkable
class LinkReporter(Protocol):
    """Implemented by a fieldbus backend's link (found in ``MachineBackend.extras``): what
    ``stave probe`` prints about it (settings, counters, the state of each node)."""

    def probe_report(self) -> Mapping[str, object]: ...


FAULT_KINDS: tuple[str, ...] = (
    "drive_fault",
    "following_error",
    "limit_switch",
    "estop",
    "comms_loss",
    "gauge_none",
    "gauge_garbage",
    "gauge_out_of_range",
    "clamp_sensor",
    "centering_sensor",
    "spindle",
)


@dataclass
class MachineBackend:
    """What one backend provides: the axes and the I/O (one fieldbus usually carries both).

    ``extras`` holds backend-specific objects the tools may use (for example the simulated
    world, for fault injection), looked up by name, never required by the machine layer."""

    name: str
    motion: MotionBackend
    io: DigitalIO
    extras: dict[str, object] = field(default_factory=dict)

    def devices(self) -> list[Lifecycle]:
        return [self.motion, self.io]


@dataclass(frozen=True)
class PendantReading:
    """One period of a USB pendant or gamepad: its enable button, its wheel's axis ("" off)
    and multiplier, the increments its wheel turned since the last read (the multiplier
    applied), and each stick's deflection (-1..1, no deadband: the machine applies it)."""

    enable: bool = False
    axis: str = ""
    multiplier: int = 1
    increments: int = 0
    sticks: Mapping[str, float] = field(default_factory=dict)


@runtime_checkable
class PendantDevice(Protocol):
    """A USB pendant the machine polls once per period. ``read`` never blocks; a device that
    is missing or unplugged reads as at rest (``connected`` False) until it is back."""

    @property
    def connected(self) -> bool: ...

    def read(self) -> PendantReading: ...

    def close(self) -> None: ...
