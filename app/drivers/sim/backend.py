"""The simulated machine behind the backend contracts: :class:`SimMotion` and :class:`SimIO`
are thin adapters onto one :class:`~app.drivers.sim.world.SimWorld`.

Why thin: the world is the machine; the adapters only do what a fieldbus master does, so that
the machine layer meets the same behaviour here as on Modbus or CANopen:

- The lifecycle is strict: ``configure`` (from UNCONFIGURED or ERROR), ``activate`` (from
  INACTIVE), ``deactivate`` (from ACTIVE), ``shutdown`` (any state, idempotent). A failure
  (the link is down) leaves the device in ERROR and raises CommunicationError. Reading is
  allowed when INACTIVE or ACTIVE; every command and write only when ACTIVE, otherwise
  :class:`LifecycleError`. On activation the command positions are set to the measured ones.
- Power requests are non-blocking, as on the real bus: the master walks the drive one
  controlword per SYNC (enable: 0x06, 0x07, 0x0F; fault reset: 0x00 then 0x80; homing: mode
  6, then bit 4), and gives up if the drive refuses a step (STO). Nothing is re-sent on its
  own: after an E-stop or a fault the machine layer must ask again.
- Targets written by :meth:`SimMotion.write_setpoints` go out at the next SYNC, all axes
  together. While an axis homes its targets are ignored (the drive is in homing mode); the
  first write after homing switches it back to cyclic synchronous position mode, so the
  machine layer should command the axis where it is.
- With the link down every call on the adapter raises CommunicationError (a missing reply)
  and ``events()`` reports COMMUNICATION_LOST (and later COMMUNICATION_RESTORED); drive EMCY
  messages arrive as EMERGENCY events with their code.

The machine loop finds :meth:`SimMotion.advance` (``TimeDriven``): only the motion adapter
advances the world, so it advances exactly once per period. ``extras["world"]`` is the world
(operator actions, the board), ``extras["faults"]`` the :class:`SimFaultInjector`.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Mapping

from app.config import MachineConfig
from app.drivers.contracts import (
    CW_DISABLE_VOLTAGE,
    CW_ENABLE_OPERATION,
    CW_FAULT_RESET,
    CW_QUICK_STOP,
    CW_SHUTDOWN,
    CW_SWITCH_ON,
    AxisFeedback,
    Cia402State,
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    DigitalIO,
    InputImage,
    LifecycleError,
    LifecycleState,
    MachineBackend,
    MotionBackend,
    OutputImage,
)
from app.drivers.sim.cia402 import CW_BIT_HOMING_START, OperationMode
from app.drivers.sim.drive import SimDrive
from app.drivers.sim.faults import SimFaultInjector
from app.drivers.sim.world import SimWorld

L = LifecycleState
S = Cia402State


class _Request(enum.Enum):
    ENABLE = "enable"
    DISABLE = "disable"
    QUICK_STOP = "quick stop"
    FAULT_RESET = "fault reset"
    HOMING = "start homing"


_ENABLE_STEP: dict[Cia402State, int] = {
    S.SWITCH_ON_DISABLED: CW_SHUTDOWN,
    S.READY_TO_SWITCH_ON: CW_SWITCH_ON,
    S.SWITCHED_ON: CW_ENABLE_OPERATION,
    S.QUICK_STOP_ACTIVE: CW_ENABLE_OPERATION,
}


class _AxisMaster:
    """The master's side of one drive: the cyclic controlword and target, and the walk
    through the power states that a request needs, one controlword per SYNC."""

    def __init__(self, drive: SimDrive) -> None:
        self.drive = drive
        self.controlword = CW_DISABLE_VOLTAGE
        self.target = drive.position
        self.new_target = False
        self.request: _Request | None = None
        self._step = 0
        self._state_at_last_step: Cia402State | None = None

    def ask(self, request: _Request) -> None:
        self.request = request
        self._step = 0
        self._state_at_last_step = None

    def _done(self) -> None:
        self.request = None

    def _walk(self) -> None:
        drive = self.drive
        state = drive.state
        request = self.request
        if request is _Request.ENABLE:
            if state is S.OPERATION_ENABLED:
                self._done()
                return
            if (
                state is S.FAULT
                or state is S.FAULT_REACTION_ACTIVE
                or state is self._state_at_last_step
            ):
                # The drive refused the last step (safe torque off, a fault): give up, and
                # leave nothing behind that could power it later on its own.
                self.controlword = CW_DISABLE_VOLTAGE
                self._done()
                return
            controlword = _ENABLE_STEP.get(state)
            if controlword is None:
                return  # not ready yet: wait
            if controlword == CW_ENABLE_OPERATION:
                self.target = drive.position  # the drive holds where it is
                self.new_target = False
            self.controlword = controlword
            self._state_at_last_step = state
        elif request is _Request.DISABLE:
            self.controlword = CW_DISABLE_VOLTAGE
            self._done()
        elif request is _Request.QUICK_STOP:
            self.controlword = CW_QUICK_STOP
            self._done()
        elif request is _Request.FAULT_RESET:
            self.controlword = (CW_DISABLE_VOLTAGE, CW_FAULT_RESET, CW_DISABLE_VOLTAGE)[self._step]
            self._step += 1
            if self._step == 3:
                self._done()
        elif request is _Request.HOMING:
            if self._step == 0:
                drive.set_mode(OperationMode.HOMING)
                self.controlword &= ~CW_BIT_HOMING_START
                self._step = 1
            else:
                self.controlword |= CW_BIT_HOMING_START
                self._done()

    def sync(self) -> None:
        """One SYNC: walk a pending request, send the controlword, then mode and target.

        A target written after a homing run has ended switches the drive back to cyclic
        synchronous position mode; while a homing request is still being walked, or the
        drive homes, targets are sent but the drive (in homing mode) ignores them."""
        drive = self.drive
        if self.request is not None:
            self._walk()
        drive.write_controlword(self.controlword)
        if self.new_target:
            self.new_target = False
            if (
                drive.mode is OperationMode.HOMING
                and not drive.homing_active
                and self.request is not _Request.HOMING
            ):
                drive.set_mode(OperationMode.CYCLIC_SYNC_POSITION)
                self.controlword &= ~CW_BIT_HOMING_START
        drive.write_target(self.target)


class _Adapter:
    """Lifecycle and link bookkeeping shared by the motion and I/O adapters."""

    def __init__(self, world: SimWorld, link: str, device: str) -> None:
        self._world = world
        self._link = link
        self._device = device
        self._lifecycle = L.UNCONFIGURED
        self._links_seen = len(world.link_log)

    @property
    def lifecycle_state(self) -> LifecycleState:
        return self._lifecycle

    def _link_up(self) -> bool:
        return self._world.link_ok(self._link)

    def _require_link(self, what: str) -> None:
        if not self._link_up():
            raise CommunicationError(self._device, f"{what}: no reply (link lost)")

    def _require(self, what: str, *states: LifecycleState) -> None:
        if self._lifecycle not in states:
            allowed = " or ".join(s.value for s in states)
            raise LifecycleError(
                self._device,
                f"{what} refused: the backend is {self._lifecycle.value}, it must be {allowed}",
            )

    def _transition(self, what: str, to: LifecycleState, *sources: LifecycleState) -> None:
        self._require(what, *sources)
        if not self._link_up():
            self._lifecycle = L.ERROR
            raise CommunicationError(self._device, f"{what} failed: no reply (link lost)")
        self._lifecycle = to

    def _link_events(self) -> list[tuple[float, DeviceEvent]]:
        """Changes of this adapter's link since the last call, with their times."""
        log = self._world.link_log
        events = [
            (
                change.time_s,
                DeviceEvent(
                    DeviceEventKind.COMMUNICATION_RESTORED
                    if change.ok
                    else DeviceEventKind.COMMUNICATION_LOST,
                    self._device,
                    text=f"{self._link} link {'restored' if change.ok else 'lost'}",
                ),
            )
            for change in log[self._links_seen :]
            if change.link == self._link
        ]
        self._links_seen = len(log)
        return events


class SimMotion(_Adapter, MotionBackend):
    """The three simulated drives as a MotionBackend; also advances the world."""

    def __init__(self, world: SimWorld) -> None:
        super().__init__(world, "drives", "sim drives")
        self._masters = {name: _AxisMaster(drive) for name, drive in world.drives.items()}
        self._emcy_seen = len(world.emcy_log)
        world.add_sync_hook(self._on_sync)

    @property
    def world(self) -> SimWorld:
        return self._world

    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(self._masters)

    @property
    def command_positions(self) -> Mapping[str, float]:
        """The targets the master sends at every SYNC (for tests and a technician's view)."""
        return {name: master.target for name, master in self._masters.items()}

    def advance(self, dt_s: float) -> None:
        """TimeDriven: advance the whole simulated world by ``dt_s``."""
        self._world.advance(dt_s)

    def _on_sync(self) -> None:
        if self._lifecycle is L.ACTIVE:  # cyclic PDOs only while active
            for master in self._masters.values():
                master.sync()

    # -- lifecycle --------------------------------------------------------------------------
    def configure(self) -> None:
        self._transition("configure", L.INACTIVE, L.UNCONFIGURED, L.ERROR)

    def activate(self) -> None:
        self._transition("activate", L.ACTIVE, L.INACTIVE)
        for master in self._masters.values():
            master.target = master.drive.position
            master.new_target = False
            master.request = None

    def deactivate(self) -> None:
        self._transition("deactivate", L.INACTIVE, L.ACTIVE)
        self._disable_all()

    def shutdown(self) -> None:
        if self._lifecycle in (L.INACTIVE, L.ACTIVE) and self._link_up():
            self._disable_all()
        self._lifecycle = L.FINALIZED

    def _disable_all(self) -> None:
        for master in self._masters.values():
            master.request = None
            master.controlword = CW_DISABLE_VOLTAGE
            master.drive.write_controlword(CW_DISABLE_VOLTAGE)

    # -- cyclic exchange -------------------------------------------------------------------
    def read_axes(self) -> Mapping[str, AxisFeedback]:
        self._require("read_axes", L.INACTIVE, L.ACTIVE)
        self._require_link("read_axes")
        return {name: master.drive.feedback() for name, master in self._masters.items()}

    def write_setpoints(self, positions: Mapping[str, float]) -> None:
        self._require("write_setpoints", L.ACTIVE)
        self._require_link("write_setpoints")
        for name, value in positions.items():
            master = self._master(name)
            if (
                isinstance(value, bool)
                or not isinstance(value, int | float)
                or not math.isfinite(value)
            ):
                raise ValueError(f"setpoint {name} = {value!r} is not allowed: a finite number")
            master.target = float(value)
            master.new_target = True

    def _master(self, axis: str) -> _AxisMaster:
        if axis not in self._masters:
            raise ValueError(f"axis = {axis!r} is not allowed: one of {', '.join(self._masters)}")
        return self._masters[axis]

    def _request(self, what: str, axis: str, request: _Request) -> None:
        self._require(what, L.ACTIVE)
        master = self._master(axis)
        self._require_link(what)
        master.ask(request)

    def enable(self, axis: str) -> None:
        self._request("enable", axis, _Request.ENABLE)

    def disable(self, axis: str) -> None:
        self._request("disable", axis, _Request.DISABLE)

    def quick_stop(self, axis: str) -> None:
        self._request("quick_stop", axis, _Request.QUICK_STOP)

    def fault_reset(self, axis: str) -> None:
        self._request("fault_reset", axis, _Request.FAULT_RESET)

    def start_homing(self, axis: str) -> None:
        self._request("start_homing", axis, _Request.HOMING)

    def events(self) -> list[DeviceEvent]:
        """Link changes and the drives' EMCY messages since the last call, oldest first."""
        log = self._world.emcy_log
        emcy = [
            (r.time_s, DeviceEvent(DeviceEventKind.EMERGENCY, r.device, r.code, r.text))
            for r in log[self._emcy_seen :]
        ]
        self._emcy_seen = len(log)
        merged = sorted(self._link_events() + emcy, key=lambda pair: pair[0])
        return [event for _, event in merged]


class SimIO(_Adapter, DigitalIO):
    """The simulated machine's discrete inputs and outputs."""

    def __init__(self, world: SimWorld) -> None:
        super().__init__(world, "io", "sim io")

    def configure(self) -> None:
        self._transition("configure", L.INACTIVE, L.UNCONFIGURED, L.ERROR)

    def activate(self) -> None:
        self._transition("activate", L.ACTIVE, L.INACTIVE)

    def deactivate(self) -> None:
        self._transition("deactivate", L.INACTIVE, L.ACTIVE)
        self._world.write_outputs(OutputImage())

    def shutdown(self) -> None:
        if self._lifecycle in (L.INACTIVE, L.ACTIVE) and self._link_up():
            self._world.write_outputs(OutputImage())
        self._lifecycle = L.FINALIZED

    def read_inputs(self) -> InputImage:
        self._require("read_inputs", L.INACTIVE, L.ACTIVE)
        self._require_link("read_inputs")
        return self._world.inputs()

    def write_outputs(self, outputs: OutputImage) -> None:
        self._require("write_outputs", L.ACTIVE)
        self._require_link("write_outputs")
        self._world.write_outputs(outputs)

    def events(self) -> list[DeviceEvent]:
        """Link changes since the last call."""
        return [event for _, event in self._link_events()]


def create_backend(config: MachineConfig) -> MachineBackend:
    """The simulated machine, configured (INACTIVE) but not yet active.

    ``[backend.sim]`` is checked here (ConfigError naming the ``backend.sim.*`` key)."""
    world = SimWorld.from_config(config)
    motion = SimMotion(world)
    io = SimIO(world)
    motion.configure()
    io.configure()
    return MachineBackend("sim", motion, io, {"world": world, "faults": SimFaultInjector(world)})
