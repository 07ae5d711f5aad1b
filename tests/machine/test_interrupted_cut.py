"""An interrupted board on the simulated machine: stop, E-stop, spindle fault, comms loss or
a killed machine process in side A, the repositioning or side B; then Start (refused: the board
is partly cut), Resume or Abandon. In every run the commanded cutter never touches the board
except along the tool path, the spindle never starts on the board, and the production record
says resumed / aborted."""

from __future__ import annotations

from datetime import datetime
from pathlib import Path

import pytest

from app.config import load_config
from app.data.database import Database
from app.data.records import PieceResult
from app.machine import commands as cmd
from app.machine.database_store import open_store
from app.machine.runtime import MachineRuntime
from app.machine.states import CycleStep, MachineState
from tests.machine.conftest import Rig, make_rig
from tests.machine.keepout_watch import KeepOutWatch

WIDTH_MM = 150.0
POINTS = {
    "side A": (CycleStep.CUTTING_A, 4.0),
    "reposition": (CycleStep.REPOSITIONING, 0.6),
    "side B": (CycleStep.CUTTING_B, 4.0),
}


def _watch(rig: Rig) -> KeepOutWatch:
    c = rig.controller
    assert c.recipe is not None
    watch = KeepOutWatch(dict(c.store.parameters()), c.recipe.length_mm, WIDTH_MM)
    rig.runtime.on_tick.append(watch)
    return watch


def _crash(rig: Rig, tmp_path: Path, io_drops_outputs: bool = False) -> Rig:
    """The machine process dies without its shutdown: the drives see their master gone and
    disable (the I/O coupler holds its outputs, unless ``io_drops_outputs``: then the
    clamps open); a new machine process starts on the same machine and database."""
    old = rig.runtime
    held = rig.world.outputs
    for _ in range(round(0.5 / old.period_s)):
        rig.world.advance(old.period_s)  # no new setpoints: the drives stop at the last one
    for device in (*old.backend.devices(), old.gauge):
        device.deactivate()
    if not io_drops_outputs:
        rig.world.write_outputs(held)  # before any time passes: nothing moved
    old.controller.store.close()
    config = load_config()
    store = open_store(tmp_path / "stave.db", config, threaded=False)
    runtime = MachineRuntime(config, store, old.backend, old.gauge)
    runtime.start()
    runtime.on_tick.extend(old.on_tick)
    return Rig(runtime)


def _interrupt(rig: Rig, kind: str, tmp_path: Path) -> Rig:
    if kind == "stop":
        rig.send(cmd.Stop())
        rig.until(lambda c: c.state is MachineState.READY, 20.0)
        return rig
    if kind == "crash":
        rig = _crash(rig, tmp_path)
        rig.run(0.5)
        if rig.state is MachineState.ERROR:  # a drive stopped short faulted (following error)
            rig.send(cmd.Reset())
        rig.until(lambda c: c.state is MachineState.READY, 5.0)
        return rig
    if kind == "estop":
        rig.world.set_estop(True)
        rig.run(1.0)
        rig.world.set_estop(False)
    else:
        rig.faults.inject(kind)
        rig.until(lambda c: c.state is MachineState.ERROR, 20.0)
        rig.run(1.0)
        rig.faults.clear_injections()
    rig.run(0.5)
    rig.send(cmd.Reset())
    rig.until(lambda c: c.state is MachineState.READY, 5.0)
    return rig


def _last_record(tmp_path: Path):  # type: ignore[no-untyped-def]
    with Database.open(tmp_path / "stave.db") as db:
        records = db.list_production(
            datetime(2000, 1, 1).astimezone(), datetime(2100, 1, 1).astimezone()
        )
    return records[-1]


def _run(tmp_path: Path, kind: str, point: str, choice: str) -> tuple[Rig, KeepOutWatch]:
    rig = make_rig(tmp_path)
    rig.home()
    rig.select()
    rig.load(WIDTH_MM)
    watch = _watch(rig)
    step, after_s = POINTS[point]
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is step, 200.0)
    if kind == "spindle" and step is CycleStep.REPOSITIONING:
        rig.run(after_s)  # the spindle's feedback is watched while cutting: it fails at B
    elif kind != "spindle":
        rig.run(after_s)
    rig = _interrupt(rig, kind, tmp_path)
    c = rig.controller
    assert c.partly_cut.board is not None, c.message
    rig.send(cmd.Start())
    assert "partly cut" in str(c.message)
    assert c.cycle is None and rig.positions() == pytest.approx(rig.positions())
    if kind == "comms_loss":
        # The lost I/O coupler switched its outputs off: the board was unclamped and may
        # have moved, so it cannot be resumed, even once the clamps close again.
        rig.run(1.0)
        assert rig.world.inputs().clamps_closed
        rig.send(cmd.Resume())
        assert "unclamped" in str(c.message) and c.cycle is None
    rig.send(cmd.Resume() if choice == "resume" else cmd.Abandon())
    assert str(c.message) in ("resuming the board", "abandoning the board"), c.message
    rig.until(lambda m: m.state is MachineState.READY and m.cycle is None, 200.0)
    assert c.partly_cut.board is None
    assert not rig.world.outputs.spindle_on
    return rig, watch


@pytest.mark.parametrize("point", list(POINTS))
@pytest.mark.parametrize("kind", ["stop", "estop", "spindle", "crash"])
def test_interrupted_board_resumed_never_crosses_the_board(
    tmp_path: Path, kind: str, point: str
) -> None:
    rig, watch = _run(tmp_path, kind, point, "resume")
    try:
        assert watch.violations == []
        assert watch.touching_periods > 0, "the watch saw the cut"
        record = _last_record(tmp_path)
        assert record.result is PieceResult.OK and record.resumed
        assert rig.controller.pieces_total == 1
    finally:
        rig.runtime.shutdown()


@pytest.mark.parametrize(
    ("kind", "point"),
    [
        ("stop", "side A"),
        ("estop", "side B"),
        ("spindle", "side A"),
        ("comms_loss", "reposition"),
        ("comms_loss", "side A"),
        ("crash", "side B"),
    ],
)
def test_interrupted_board_abandoned_is_aborted(tmp_path: Path, kind: str, point: str) -> None:
    rig, watch = _run(tmp_path, kind, point, "abandon")
    try:
        assert watch.violations == []
        record = _last_record(tmp_path)
        assert record.result is PieceResult.ABORTED and not record.resumed
        assert rig.controller.pieces_total == 0
        assert not rig.world.outputs.clamps_close, "the abandoned board is unclamped"
    finally:
        rig.runtime.shutdown()


def test_a_crash_that_unclamps_the_board_allows_only_abandon(tmp_path: Path) -> None:
    rig = make_rig(tmp_path)
    rig.home()
    rig.select()
    rig.load(WIDTH_MM)
    rig.send(cmd.Start())
    rig.until(lambda c: c.cycle is not None and c.cycle.step is CycleStep.CUTTING_A, 200.0)
    rig.run(3.0)
    rig = _crash(rig, tmp_path, io_drops_outputs=True)
    try:
        rig.run(1.0)
        c = rig.controller
        assert c.partly_cut.board is not None and c.partly_cut.board.reason == "restart"
        assert rig.world.inputs().clamps_closed, "the restarted machine keeps the board clamped"
        rig.send(cmd.Resume())
        assert "unclamped" in str(c.message) and c.cycle is None
        rig.send(cmd.Abandon())
        rig.until(lambda m: m.state is MachineState.READY and m.cycle is None, 200.0)
        assert _last_record(tmp_path).result is PieceResult.ABORTED
    finally:
        rig.runtime.shutdown()
