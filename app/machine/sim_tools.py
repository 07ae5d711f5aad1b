"""The technician's simulation page: inject and clear faults, put a board on the table, take
it off, work the simulated handwheel and joystick.

Why apart from the controller: these act on the simulated world only (the objects the sim
backend offers in ``MachineBackend.extras``: ``"faults"``, a :class:`FaultInjector`, and
``"world"``, the :class:`SimWorld`), never on a real machine; the permission rules refuse them
on any other backend, and here they do nothing if the world is not there.
"""

from __future__ import annotations

from typing import assert_never

from app.drivers.contracts import FaultInjector, MachineBackend
from app.drivers.sim.world import SimWorld
from app.machine import commands as cmd
from app.machine.refusals import Reason, Refusal, refusal


class SimulationTools:
    def __init__(self, backend: MachineBackend) -> None:
        faults = backend.extras.get("faults")
        world = backend.extras.get("world")
        self._faults = faults if isinstance(faults, FaultInjector) else None
        self._world = world if isinstance(world, SimWorld) else None
        self._pending_board: tuple[float | None] | None = None

    def handle(self, command: cmd.SimulationCommand) -> Refusal | None:
        """Carry out one command of the simulation page; returns why it was refused (a
        value the world does not take), or None."""
        try:
            self._carry_out(command)
        except (ValueError, TypeError) as exc:
            return refusal(Reason.SIMULATION_REFUSED, exc)
        return None

    def _carry_out(self, command: cmd.SimulationCommand) -> None:
        faults, world = self._faults, self._world
        match command:
            case cmd.InjectFault(kind=kind, target=target):
                if faults is not None:
                    faults.inject(kind, target)
            case cmd.ClearFaults():
                if faults is not None:
                    faults.clear_injections()
            case cmd.LoadBoard(width_mm=width_mm):
                self._replace_board(width_mm)
            case cmd.RemoveBoard():
                if world is not None:
                    world.remove_board()
                    self._pending_board = None
            case cmd.SelectHandwheel(axis=axis, multiplier=multiplier):
                if world is not None:
                    world.handwheel.select(axis, multiplier)
            case cmd.TurnHandwheel(counts=counts, rate_counts_s=rate):
                if world is not None:
                    world.handwheel.turn(counts, rate)
            case cmd.HoldJogEnable(held=held):
                if world is not None:
                    world.handwheel.enable = held
            case cmd.PushJoystick(x=x, y=y, z=z):
                if world is not None:
                    world.joystick.push(x, y, z)
            case _:
                assert_never(command)

    def _replace_board(self, width_mm: float | None) -> None:
        """Take the board off now and put a new one on once the part sensor has seen the
        table empty (see :meth:`tick`), as an operator would."""
        if self._world is not None:
            self._world.remove_board()
            self._pending_board = (width_mm,)

    def tick(self, part_present: bool) -> None:
        if self._pending_board is not None and not part_present:
            if self._world is not None:
                self._world.load_board(self._pending_board[0])
            self._pending_board = None
