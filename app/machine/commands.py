"""Commands the screens (or a test, or a command-line tool) post to the machine.

Why plain frozen dataclasses: they cross a process boundary (pickled through a queue) and a
command must never carry behaviour the GUI could run. The machine decides whether to accept
one; a refused command raises an event with the reason, visible in the next snapshot.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from app.machine.barrel_set import BoardChoice
from app.machine.planner.limits import MAX_OVERRIDE_PCT


@dataclass(frozen=True)
class Start:
    """Start the automatic cycle (screen button or push button)."""


@dataclass(frozen=True)
class Resume:
    """Go on with the interrupted board: clear of it with the spindle off, spindle up at the
    lead-in of the side not finished, then the rest of the cut."""


@dataclass(frozen=True)
class Abandon:
    """Give up the interrupted board: clear of it with the spindle off (if the axes know
    where they are), unclamp; it is recorded as aborted and must be taken off."""


@dataclass(frozen=True)
class Stop:
    """Controlled stop (IEC 60204-1 category 2): decelerate along the path and hold."""


@dataclass(frozen=True)
class Reset:
    """Operator's reset after an error or E-stop: fault-resets the drives (they end disabled)
    and unlatches the state if the cause is gone. Never restarts anything by itself."""


@dataclass(frozen=True)
class Home:
    """Home one axis ("X", "Y" or "Z"; manual mode) or all axes (axis = "")."""

    axis: str = ""


@dataclass(frozen=True)
class SelectRecipe:
    recipe_id: int


@dataclass(frozen=True)
class EnterManual:
    pass


@dataclass(frozen=True)
class LeaveManual:
    pass


@dataclass(frozen=True)
class JogContinuous:
    """Jog while held. The screen repeats it at least every ``JOG_REFRESH_S`` while the
    button is held; the machine stops the axis when the refresh stops (dead-man), so a
    lost release event or a frozen screen cannot leave an axis running."""

    axis: str
    direction: int  # -1 or +1
    hold: int = 0
    """Which hold of the button this is: the screen numbers each press and repeats the number
    in its refreshes. Once the dead-man has stopped a hold, its refreshes are refused: the
    overdue refresh of a screen that was frozen must not start the axis again (0: a sender
    that does not number its holds)."""


@dataclass(frozen=True)
class JogStep:
    """Move one axis by a fixed step (mm for X/Y, degrees for Z)."""

    axis: str
    step: float


@dataclass(frozen=True)
class MoveTo:
    """Manual mode: go to this position (X, Y in mm, the tilt in degrees), around the board on
    the table, or refused with the reason; Stop or JogRelease end it where it is."""

    x_mm: float
    y_mm: float
    z_deg: float


@dataclass(frozen=True)
class JogRelease:
    """The jog button was released: decelerate to standstill now."""

    axis: str = ""


@dataclass(frozen=True)
class SetClamps:
    closed: bool


@dataclass(frozen=True)
class SetSpindle:
    on: bool


@dataclass(frozen=True)
class SetFeedOverride:
    """The feed of every planned move, in percent of the recipe's (0 holds on the path).
    Kept across cycles; applied at once, without a jump in speed."""

    percent: float  # 0 to MAX_PCT
    MAX_PCT: ClassVar[float] = MAX_OVERRIDE_PCT  # the planner budgets for this much


@dataclass(frozen=True)
class Acknowledge:
    """Acknowledge one alarm (by its id) or every alarm (alarm_id = 0)."""

    alarm_id: int = 0


@dataclass(frozen=True)
class ReloadParameters:
    """The System screen saved parameters: reload them from the database."""


@dataclass(frozen=True)
class ResetShiftCounter:
    pass


@dataclass(frozen=True)
class InjectFault:
    """Technician's simulation menu: inject a fault (simulation backend only)."""

    kind: str
    target: str = ""


@dataclass(frozen=True)
class ClearFaults:
    """Technician's simulation menu: clear injected faults (the machine stays latched)."""


@dataclass(frozen=True)
class StartBarrel:
    """Start a new barrel of the selected recipe's belly section: the next stave is its first."""


@dataclass(frozen=True)
class ChooseBoard:
    """The operator's answer to a board too narrow to close the barrel (alarm E034)."""

    choice: BoardChoice


@dataclass(frozen=True)
class LoadBoard:
    """Simulation only: put a board of ``width_mm`` (or a random one) on the table."""

    width_mm: float | None = None


@dataclass(frozen=True)
class RemoveBoard:
    """Simulation only: take the board off the table, as the operator does after a piece."""


@dataclass(frozen=True)
class SelectHandwheel:
    """Simulation only: the handwheel's axis selector ("" off, "X", "Y", "Z") and its
    multiplier (1, 10 or 100)."""

    axis: str
    multiplier: int = 1


@dataclass(frozen=True)
class TurnHandwheel:
    """Simulation only: turn the handwheel by ``counts`` (negative: the other way), spread
    over time at ``rate_counts_s`` as a hand turns it."""

    counts: int
    rate_counts_s: float = 400.0


@dataclass(frozen=True)
class HoldJogEnable:
    """Simulation only: hold (or let go of) the enable button of the handwheel and the
    joystick."""

    held: bool


@dataclass(frozen=True)
class PushJoystick:
    """Simulation only: hold the joystick at these fractions of full deflection (-1..1);
    all 0 lets it go."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0


@dataclass(frozen=True)
class SetUser:
    """The logged-in user changed (for the audit trail of alarms and records). ``operator``
    is the operator of the shift as he named himself ("" while nobody has): production
    records name him, also while a technician is logged in at the panel."""

    name: str
    operator: str = ""


@dataclass(frozen=True)
class Shutdown:
    """Stop everything safely and end the machine process."""


Command = (
    Start
    | Resume
    | Abandon
    | Stop
    | Reset
    | Home
    | SelectRecipe
    | StartBarrel
    | ChooseBoard
    | EnterManual
    | LeaveManual
    | JogContinuous
    | JogStep
    | MoveTo
    | JogRelease
    | SetClamps
    | SetSpindle
    | SetFeedOverride
    | Acknowledge
    | ReloadParameters
    | ResetShiftCounter
    | InjectFault
    | ClearFaults
    | LoadBoard
    | RemoveBoard
    | SelectHandwheel
    | TurnHandwheel
    | HoldJogEnable
    | PushJoystick
    | SetUser
    | Shutdown
)

ManualCommand = (
    EnterManual
    | LeaveManual
    | JogContinuous
    | JogStep
    | MoveTo
    | JogRelease
    | SetClamps
    | SetSpindle
)
"""The Manual screen's commands (carried out by ``app.machine.manual_room``)."""

SimulationCommand = (
    InjectFault
    | ClearFaults
    | LoadBoard
    | RemoveBoard
    | SelectHandwheel
    | TurnHandwheel
    | HoldJogEnable
    | PushJoystick
)
"""The simulation page's commands (carried out by ``app.machine.sim_tools``; refused on any
backend but the simulation)."""

JOG_REFRESH_S = 0.1  # the screen repeats JogContinuous at least this often
JOG_DEADMAN_S = 0.3  # no refresh for this long: the machine stops the jog
