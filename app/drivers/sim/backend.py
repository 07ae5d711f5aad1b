"""The simulated machine behind the backend contracts: :class:`SimMotion` and :class:`SimIO`
are thin adapters onto one :class:`~app.drivers.sim.world.SimWorld`.

Why thin: the world is the machine; the adapters only do what a fieldbus master does, so that
the machine layer meets the same behaviour here as on Modbus or CANopen:

- The lifecycle is :class:`~app.drivers.lifecycle.ManagedLifecycle`'s, as on every backend;
  a transition or a call while the link is down fails with CommunicationError and leaves
  ERROR.
  Reading is allowed when INACTIVE or ACTIVE; every command and write only when ACTIVE,
  otherwise :class:`LifecycleError`, except disable and quick stop, which are always taken.
  On activation the command positions are set to the measured ones.
- Power requests go to the shared CiA 402 master (:mod:`app.drivers.cia402`), one per
  drive, exactly as on Modbus and CANopen; at every SYNC the master reads the drive's
  statusword and mode display and sends its controlword, mode and target. Nothing is re-sent
  or re-enabled on its own: after an E-stop or a fault the machine layer must ask again.
- Targets written by :meth:`SimMotion.write_setpoints` go out at the next SYNC, all axes
  together; while a drive does not follow setpoints (not enabled, homing) the master
  commands it to its own position.
- With the link down every call on the adapter raises CommunicationError (a missing reply)
  and ``events()`` reports COMMUNICATION_LOST (and later COMMUNICATION_RESTORED); drive EMCY
  messages arrive as EMERGENCY events with their code.

The machine loop finds :meth:`SimMotion.advance` (``TimeDriven``): only the motion adapter
advances the world, so it advances exactly once per period. ``extras["world"]`` is the world
(operator actions, the board), ``extras["faults"]`` the :class:`SimFaultInjector`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import replace

from app.config import MachineConfig
from app.drivers.cia402 import (
    Cia402Master,
    RequestRefusedError,
)
from app.drivers.contracts import (
    AxisFeedback,
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    DigitalIO,
    DriverError,
    InputImage,
    LifecycleState,
    MachineBackend,
    MotionBackend,
    OutputImage,
)
from app.drivers.lifecycle import ManagedLifecycle
from app.drivers.sim.drive import SimDrive
from app.drivers.sim.faults import SimFaultInjector
from app.drivers.sim.world import SimWorld

L = LifecycleState


class _DriveLink:
    """One simulated drive on the simulated bus: the shared master's side of it and the
    target the machine last wrote. At every SYNC the drive's statusword and mode display go
    to the master, and the master's controlword, mode and target go to the drive, as a
    cyclic PDO pair does on CANopen."""

    def __init__(self, drive: SimDrive, homed: bool) -> None:
        self.drive = drive
        self.master = Cia402Master(reports_mode=True, homed=homed)
        self.master.observe(drive.statusword, int(drive.mode))
        self.target = drive.position

    def feedback(self) -> AxisFeedback:
        """The drive's registers as a read returns them; the master observes every read
        (as on Modbus), with what it knows of homing in place of the drive's own flags."""
        drive = self.drive
        master = self.master
        master.observe(drive.statusword, int(drive.mode))
        return replace(drive.feedback(), homed=master.homed, homing_active=master.homing_active)

    def sync(self) -> None:
        """The drive answers the SYNC with its statusword (as a TPDO sampled at SYNC), then
        takes this SYNC's command: mode, controlword, then target."""
        drive = self.drive
        self.master.observe(drive.statusword, int(drive.mode))
        command = self.master.command()
        drive.set_mode(command.mode)
        drive.write_controlword(command.controlword)
        if not command.follows_setpoints:
            self.target = drive.position  # enabling or leaving homing never jumps
        drive.write_target(self.target)


class _Adapter(ManagedLifecycle):
    """Link bookkeeping shared by the motion and I/O adapters; the lifecycle is the base's."""

    def __init__(self, world: SimWorld, link: str, device: str) -> None:
        super().__init__(device)
        self._world = world
        self._link = link
        self._device = device
        self._links_seen = len(world.link_log)
        self._lost = False  # ERROR latched by a lost link: calls say so until configure

    def _link_up(self) -> bool:
        return self._world.link_ok(self._link)

    def _require_link(self, what: str) -> None:
        """A call that finds the link down latches ERROR (only configure may follow), as a
        fieldbus backend does when a call loses its link."""
        if not self._link_up():
            self._latch_error()
            self._lost = self._state is L.ERROR
            raise CommunicationError(self._device, f"{what}: no reply (link lost)")

    def _require(self, what: str, *states: LifecycleState) -> None:
        """After a lost link a call fails as a lost link (CommunicationError), not as a
        lifecycle misuse, until configure reopens it (as on Modbus and CANopen)."""
        if self._state is L.ERROR and self._lost:
            raise CommunicationError(
                self._device, f"{what}: the link was lost; a reset must reconfigure the backend"
            )
        super()._require(what, *states)

    def _on_configure(self) -> None:
        self._require_link("configure failed")
        self._lost = False

    def _on_activate(self) -> None:
        self._require_link("activate failed")

    def _on_deactivate(self) -> None:
        self._require_link("deactivate failed")
        self._switch_off()

    def _on_error(self) -> None:
        if self._link_up():
            self._switch_off()

    def _switch_off(self) -> None:
        """Drives disabled or outputs off."""

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
        self._links = {name: _DriveLink(drive, drive.homed) for name, drive in world.drives.items()}
        self._emcy_seen = len(world.emcy_log)
        world.add_sync_hook(self._on_sync)

    @property
    def world(self) -> SimWorld:
        return self._world

    @property
    def axis_names(self) -> tuple[str, ...]:
        return tuple(self._links)

    @property
    def command_positions(self) -> Mapping[str, float]:
        """The targets the master sends at every SYNC (for tests and a technician's view)."""
        return {name: link.target for name, link in self._links.items()}

    def advance(self, dt_s: float) -> None:
        """TimeDriven: advance the whole simulated world by ``dt_s``."""
        self._world.advance(dt_s)

    def _on_sync(self) -> None:
        if self._state is L.ACTIVE:  # cyclic PDOs only while active
            for link in self._links.values():
                link.sync()

    # -- lifecycle hooks ------------------------------------------------------------------------
    def _on_activate(self) -> None:
        super()._on_activate()
        for name, link in self._links.items():
            self._links[name] = _DriveLink(link.drive, link.master.homed and link.drive.homed)

    def _switch_off(self) -> None:
        for link in self._links.values():
            link.master.disable()
            link.sync()

    # -- cyclic exchange -------------------------------------------------------------------
    def read_axes(self) -> Mapping[str, AxisFeedback]:
        self._require("read_axes", L.INACTIVE, L.ACTIVE)
        self._require_link("read_axes")
        return {name: link.feedback() for name, link in self._links.items()}

    def write_setpoints(self, positions: Mapping[str, float]) -> None:
        self._require("write_setpoints", L.ACTIVE)
        self._require_link("write_setpoints")
        for name, value in positions.items():
            link = self._drive_link(name)
            if (
                isinstance(value, bool)
                or not isinstance(value, int | float)
                or not math.isfinite(value)
            ):
                raise ValueError(f"setpoint {name} = {value!r} is not allowed: a finite number")
            link.target = float(value)  # the master sends it only while the drive follows

    def _drive_link(self, axis: str) -> _DriveLink:
        if axis not in self._links:
            raise ValueError(f"axis = {axis!r} is not allowed: one of {', '.join(self._links)}")
        return self._links[axis]

    def _request(self, what: str, axis: str, request: Callable[[Cia402Master], None]) -> None:
        self._require(what, L.ACTIVE)
        link = self._drive_link(axis)
        self._require_link(what)
        try:
            request(link.master)
        except RequestRefusedError as exc:
            raise DriverError(axis, f"{what.replace('_', ' ')} refused: {exc}") from None

    def enable(self, axis: str) -> None:
        self._request("enable", axis, Cia402Master.enable)

    def disable(self, axis: str) -> None:
        self._drive_link(axis).master.disable()  # always accepted: the safe direction

    def quick_stop(self, axis: str) -> None:
        self._drive_link(axis).master.quick_stop()  # always accepted: the safe direction

    def fault_reset(self, axis: str) -> None:
        self._request("fault_reset", axis, Cia402Master.fault_reset)

    def start_homing(self, axis: str) -> None:
        self._request("start_homing", axis, Cia402Master.start_homing)

    def _pending_events(self) -> list[DeviceEvent]:
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

    def _switch_off(self) -> None:
        self._world.write_outputs(OutputImage())

    def read_inputs(self) -> InputImage:
        self._require("read_inputs", L.INACTIVE, L.ACTIVE)
        self._require_link("read_inputs")
        return self._world.inputs()

    def write_outputs(self, outputs: OutputImage) -> None:
        self._require("write_outputs", L.ACTIVE)
        self._require_link("write_outputs")
        self._world.write_outputs(outputs)

    def _pending_events(self) -> list[DeviceEvent]:
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
