"""The controller's memory of a partly cut board: recorded when its cut begins and at each
new phase, kept across a restart, watched for opened clamps, ended by a Resume that
finishes it or an Abandon.

Why apart from the controller: what is remembered and when is bookkeeping around the
interrupted board (``interrupted.py`` holds the record, ``board_resume.py`` how to go on);
the controller only decides when the operator's Resume or Abandon runs.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from app.data.recipe import Recipe
from app.drivers.contracts import InputImage
from app.machine.board_resume import interruption
from app.machine.cycle import AutomaticCycle
from app.machine.interrupted import InterruptedBoard, InterruptedRecordError
from app.machine.planner.trajectory import Phase
from app.machine.states import CycleStep
from app.machine.store import MachineStore, PieceRecord


class PartlyCut:
    def __init__(self, store: MachineStore, wall_clock: Callable[[], float]) -> None:
        self._store = store
        self._wall_clock = wall_clock
        self.board = self._load()

    def _load(self) -> InterruptedBoard | None:
        try:
            board = self._store.interrupted_board()
        except InterruptedRecordError:
            # Unreadable: assume the worst (a partly cut board of unknown shape); it can only
            # be abandoned, and nothing moves for it.
            return InterruptedBoard(None, "unknown", 0.0, Phase.CUT_A, 0.0, 0.0, 0.0, "unreadable")
        if board is not None and not board.reason:
            # Recorded during the cut and never ended: the machine stopped without knowing why.
            board = replace(board, reason="restart")
        return board

    def _save(self, board: InterruptedBoard | None) -> None:
        self.board = board
        self._store.save_interrupted_board(board)

    def interrupted(
        self, cycle: AutomaticCycle, xyz: tuple[float, float, float], reason: str
    ) -> bool:
        """The cycle ends before its board is cut: if the cut had begun, the board is
        recorded as partly cut (to resume or abandon; not a piece yet) and True returned."""
        record = interruption(cycle, xyz, reason, self.board)
        if record is None:
            return False
        self._save(record)
        return True

    def remember(self, cycle: AutomaticCycle, xyz: tuple[float, float, float]) -> None:
        """Persist the board's phase each time the cut enters a new one, so that a crash or
        a power loss leaves a record of a partly cut board."""
        if not cycle.board_partly_cut:
            return
        if self.board is not None and self.board.phase is cycle.cut_phase:
            return
        record = interruption(cycle, xyz, "", self.board)
        if record is not None:
            self._save(record)

    def watch_clamps(self, inputs: InputImage, cycle: AutomaticCycle | None) -> None:
        """A partly cut board whose clamps open (a lost I/O coupler switches its outputs
        off, an operator unclamps in Manual) may move: from then on it can only be
        abandoned."""
        board = self.board
        if board is None or board.unclamped or inputs.clamps_closed:
            return
        if cycle is not None and cycle.step is CycleStep.UNCLAMPING:
            return
        self._save(replace(board, unclamped=True))

    def recipe(self) -> Recipe | None:
        """The board's recipe, if it still exists."""
        board = self.board
        if board is None or board.recipe_id is None:
            return None
        return self._store.recipe(board.recipe_id)

    def alarm(self) -> str | None:
        """The alarm code that interrupted the board, for its production record."""
        reason = self.board.reason if self.board is not None else ""
        return reason if reason.startswith(("E", "W")) else None

    def end(self, result: str, recorded: bool) -> None:
        """The board is finished (resumed) or abandoned: recorded here unless a cycle has
        recorded it (``recorded``), then forgotten."""
        board = self.board
        assert board is not None
        if not recorded:
            piece = PieceRecord(
                self._wall_clock(),
                board.recipe_id,
                board.recipe_name,
                board.width_mm or None,
                None,
                None,
                None,
                0.0,
                result,
                self.alarm(),
            )
            self._store.record_piece(piece)
        self._save(None)
