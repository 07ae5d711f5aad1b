"""Every fault kind injected at every cycle step where it can happen.

Each case must end with the motion stopped, the right alarm raised, the state latched, and
nothing moving again until the operator resets and starts (a Reset alone moves nothing).
Axes have absolute encoders here so that no case spends time homing."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from app.config import load_config
from app.machine import commands as cmd
from app.machine.states import LATCHED_STATES, CycleStep, MachineState
from tests.machine.conftest import make_rig

S = CycleStep
BEFORE_MOTION = (S.CENTERING, S.CLAMPING, S.MEASURING, S.STARTING_SPINDLE)
MOVING = (S.CUTTING_A, S.REPOSITIONING, S.CUTTING_B, S.RETURNING)
EVERY = (*BEFORE_MOTION, *MOVING, S.UNCLAMPING)

# (kind, target, steps where it can happen, expected alarm, latched state)
MATRIX: list[tuple[str, str, tuple[CycleStep, ...], str, MachineState]] = [
    ("drive_fault", "X", EVERY, "E010", MachineState.ERROR),
    ("drive_fault", "Z", EVERY, "E010", MachineState.ERROR),
    ("following_error", "Y", (*BEFORE_MOTION, *MOVING), "E011", MachineState.ERROR),
    ("limit_switch", "X", EVERY, "E012", MachineState.ERROR),
    ("estop", "", EVERY, "E001", MachineState.EMERGENCY_STOP),
    ("comms_loss", "", EVERY, "E020", MachineState.ERROR),
    ("gauge_none", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E030", MachineState.ERROR),
    ("gauge_garbage", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E031", MachineState.ERROR),
    ("gauge_out_of_range", "", (S.CENTERING, S.CLAMPING, S.MEASURING), "E032", MachineState.ERROR),
    ("comms_loss", "gauge", (S.CENTERING, S.CLAMPING), "E033", MachineState.ERROR),
    ("clamp_sensor", "closed", (S.CENTERING, S.CLAMPING), "E040", MachineState.ERROR),
    ("clamp_sensor", "open", (*MOVING, S.UNCLAMPING), "E040", MachineState.ERROR),
    ("centering_sensor", "extended", (S.CENTERING,), "E041", MachineState.ERROR),
    (
        "centering_sensor",
        "retracted",
        (S.CENTERING, S.CLAMPING, S.MEASURING),
        "E041",
        MachineState.ERROR,
    ),
    ("spindle", "", BEFORE_MOTION, "E042", MachineState.ERROR),
    ("spindle", "", (S.CUTTING_A, S.REPOSITIONING, S.CUTTING_B), "E043", MachineState.ERROR),
]

CASES = [
    (kind, target, step, code, state)
    for kind, target, steps, code, state in MATRIX
    for step in steps
]
COVERED: list[str] = []


@pytest.fixture(scope="module")
def absolute_config():  # type: ignore[no-untyped-def]
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    return replace(config, axes=axes)


@pytest.mark.parametrize(
    ("kind", "target", "step", "code", "latched"),
    CASES,
    ids=[f"{k}:{t}@{s.name.lower()}" for k, t, s, _c, _l in CASES],
)
def test_fault_at_step(
    kind: str,
    target: str,
    step: CycleStep,
    code: str,
    latched: MachineState,
    absolute_config,
    tmp_path: Path,
) -> None:
    rig = make_rig(tmp_path, absolute_config)
    try:
        assert rig.state is MachineState.READY
        rig.select("Barrique 225 l Bordeaux")
        rig.load(150.0)
        rig.send(cmd.Start())
        rig.until(lambda c: c.cycle is not None and c.cycle.step is step, 120.0)
        rig.faults.inject(kind, target)
        rig.until(lambda c: c.state in LATCHED_STATES, 30.0)
        assert rig.state is latched
        codes = {a.code for a in rig.controller.snapshot().alarms}
        assert code in codes, f"expected {code}, got {codes}"
        rig.run(3.0)  # stopping ramps end (and a lost link's watchdogs act)
        assert not rig.world.outputs.spindle_on
        still = rig.positions()
        rig.run(3.0)
        assert rig.positions() == pytest.approx(still, abs=0.01), "moved while latched"
        assert not rig.moving()

        rig.faults.clear_injections()
        rig.send(cmd.Reset(), run_s=1.0)
        assert rig.state in (MachineState.READY, MachineState.NOT_HOMED), rig.controller.message
        rig.run(2.0)
        assert rig.positions() == pytest.approx(still, abs=0.01), "moved after Reset alone"
        assert not any(a.enabled for a in rig.controller.snapshot().axes)
        COVERED.append(f"{kind}:{target}@{step.name.lower()}")
    finally:
        rig.runtime.shutdown()


def test_matrix_report(capsys: pytest.CaptureFixture[str]) -> None:
    """Prints how many cases the matrix covered (runs after the cases, in file order)."""
    with capsys.disabled():
        print(
            f"\nfault matrix: {len(COVERED)} of {len(CASES)} cases passed "
            f"({len({c.split('@')[0] for c in COVERED})} fault kinds and targets)"
        )
    assert len(CASES) >= 80
