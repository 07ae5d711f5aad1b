"""Manual mode's "go to position": the operator types X, Y and the tilt, the machine goes
there, around the board on the table, or refuses with the reason.

Why a planned move and not three jogs: a straight line to the typed position may run the
cutter through the clamped board; the move is planned like every other move the machine makes
on its own (:func:`app.machine.planner.keepout.routed_chunks`: straight when clear, else
around the board's keep-out box within the axis travel), jerk-limited at the automatic
speeds, and only with every axis homed (a typed position means nothing on an axis that does
not know where it is).
"""

from __future__ import annotations

from collections.abc import Mapping

from app.config import AxisConfig
from app.machine.axes import AxisGroup
from app.machine.executor import PathExecutor
from app.machine.planner.chunked import ChunkedTrajectory
from app.machine.planner.keepout import KeepOutRefused, TableKeepOut, routed_chunks
from app.machine.planner.limits import MotionLimits
from app.machine.planner.point_to_point import point_to_point_chunk
from app.machine.planner.trajectory import Phase
from app.machine.refusals import Reason, Refusal, refusal

XYZ = tuple[float, float, float]


class ManualMove:
    def __init__(self, axes: Mapping[str, AxisConfig], period_s: float) -> None:
        self._axes = axes
        self._period_s = period_s
        self._executor: PathExecutor | None = None

    @property
    def running(self) -> bool:
        return self._executor is not None

    def start(
        self, where: XYZ, target: XYZ, board: TableKeepOut | None, limits: MotionLimits
    ) -> Refusal | None:
        """Plan the move from ``where`` to ``target``; why not, or None when it runs."""
        for name, value in zip(("X", "Y", "Z"), target, strict=True):
            cfg = self._axes[name]
            if not cfg.min_position <= value <= cfg.max_position:
                return refusal(
                    Reason.MOVE_OUTSIDE_TRAVEL, name, value, cfg.min_position, cfg.max_position
                )
        try:
            if board is not None:
                chunks = routed_chunks(board, where, target, limits, Phase.POINT_TO_POINT)
            else:
                chunk = point_to_point_chunk(where, target, limits, Phase.POINT_TO_POINT)
                chunks = [] if chunk is None else [chunk]
        except KeepOutRefused as exc:
            return refusal(Reason.MOVE_REFUSED, exc)
        if chunks:
            self._executor = PathExecutor(ChunkedTrajectory(chunks), self._period_s)
        return None

    def tick(self, axes: AxisGroup) -> bool:
        """One period of the move; True when it has ended (the jog then takes over)."""
        if self._executor is None or not axes.request_enable():
            return False
        out = self._executor.step()
        axes.command.update({"X": out.x, "Y": out.y, "Z": out.z})
        if out.done or self._executor.stopped:
            self._executor = None
            return True
        return False

    def abandon(self) -> None:
        """Forget the move (the controller stops the drives itself)."""
        self._executor = None

    def stop(self) -> None:
        """Stop: decelerate along the path and end there."""
        if self._executor is not None:
            self._executor.request_stop()
