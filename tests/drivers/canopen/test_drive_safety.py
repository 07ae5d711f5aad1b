"""The CiA 402 state machine of the simulated world's drives over the bus: enable, a fault
mid-cut with its EMCY, the operator's fault reset (0x00 then 0x80, ending disabled), quick
stop, homing, and the setpoint guards."""

from __future__ import annotations

import pytest

from app.drivers.cia402 import Cia402Master, Cia402State, OperationMode
from app.drivers.contracts import DeviceEventKind, DriverError
from tests.drivers.canopen.conftest import enable_all, period, run_until, start
from tests.drivers.canopen.world_nodes import WorldBus, WorldDrive

S = Cia402State
RESET_EDGE_PERIODS = Cia402Master(reports_mode=True).reset_edge_periods


def controlwords_since(drive: WorldDrive, sync: int) -> list[int]:
    return [cw for s, cw in drive.record.controlwords if s >= sync]


def collapse(words: list[int]) -> list[int]:
    """The controlword sequence without repetitions."""
    out: list[int] = []
    for word in words:
        if not out or out[-1] != word:
            out.append(word)
    return out


def assert_operator_reset(words: list[int]) -> None:
    """Bit 7 rises only after a period of 0x00, and nothing enables the drive afterwards."""
    first_edge = words.index(0x80)
    assert words[first_edge - 1] == 0x00
    assert all(w in (0x00, 0x80) for w in words[first_edge - 1 :])
    assert words[-1] == 0x00


def test_enable_walks_the_state_machine(backend, bus: WorldBus):
    start(backend)
    feedback = enable_all(backend)
    assert all(f.power_state is S.OPERATION_ENABLED for f in feedback.values())
    for drive in bus.drives.values():
        words = collapse(controlwords_since(drive, 0))
        assert words[-3:] == [0x06, 0x07, 0x0F]  # shutdown, switch on, enable operation
        assert not any(w & 0x80 for w in words)


def test_disable_ends_switch_on_disabled(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    backend.motion.disable("X")
    feedback = run_until(backend, lambda fb: fb["X"].power_state is S.SWITCH_ON_DISABLED)
    assert feedback["Y"].enabled and feedback["Z"].enabled


def test_quick_stop_then_enable_again(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    backend.motion.quick_stop("Y")
    run_until(backend, lambda fb: fb["Y"].power_state is S.QUICK_STOP_ACTIVE)
    backend.motion.enable("Y")  # transition 16, an explicit request
    run_until(backend, lambda fb: fb["Y"].enabled)


def ramp(start_mm: float, step_mm: float):
    return lambda n: {"X": start_mm + step_mm * n, "Y": start_mm + step_mm * n}


def test_a_drive_fault_mid_cut_is_an_alarm_and_stays_disabled(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    for n in range(10):  # cutting: X and Y move together
        period(backend, ramp(0.0, 0.2)(n))
    bus.drives["Y"].drive.inject_power_stage_fault(True)  # continuous over-current
    feedback = run_until(backend, lambda fb: fb["Y"].faulted, positions=ramp(2.0, 0.2))
    bus.drives["Y"].drive.inject_power_stage_fault(False)  # gone: a reset would now succeed
    assert feedback["Y"].fault_code == 0x2310  # from the EMCY, before 0x603F comes in
    feedback = run_until(
        backend, lambda fb: fb["Y"].power_state is S.FAULT, positions=ramp(2.0, 0.0)
    )
    feedback = run_until(
        backend, lambda fb: fb["Y"].fault_code == 0x2310, 20, positions=ramp(2.0, 0.0)
    )
    events = backend.motion.events()
    emergencies = [e for e in events if e.kind is DeviceEventKind.EMERGENCY]
    assert [(e.device, e.code) for e in emergencies] == [("Y (node 2)", 0x2310)]
    assert "over-current" in emergencies[0].text
    assert feedback["X"].enabled  # the machine layer decides what X does next
    with pytest.raises(DriverError, match="FAULT"):
        backend.motion.enable("Y")
    sync = bus.drives["Y"].sync_count
    for _ in range(30):
        period(backend)
    y = backend.motion.read_axes()["Y"]
    assert y.power_state is S.FAULT  # nothing reset it
    assert not any(w & 0x80 for w in controlwords_since(bus.drives["Y"], sync))


def test_fault_reset_is_0x00_then_0x80_and_ends_disabled(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    bus.drives["Y"].drive.inject_power_stage_fault(True)
    run_until(backend, lambda fb: fb["Y"].faulted)
    bus.drives["Y"].drive.inject_power_stage_fault(False)
    sync = bus.drives["Y"].sync_count
    backend.motion.fault_reset("Y")  # the operator pressed Reset
    feedback = run_until(backend, lambda fb: fb["Y"].power_state is S.SWITCH_ON_DISABLED)
    assert feedback["Y"].fault_code == 0
    for _ in range(20):  # and it stays there: nothing enables it by itself
        feedback, _ = period(backend)
    assert feedback["Y"].power_state is S.SWITCH_ON_DISABLED
    assert_operator_reset(controlwords_since(bus.drives["Y"], sync))


def test_fault_reset_with_the_cause_still_present_leaves_the_drive_faulted(backend, bus: WorldBus):
    start(backend)
    bus.drives["Z"].drive.inject_power_stage_fault(True)  # the cause lasts
    run_until(backend, lambda fb: fb["Z"].faulted)
    sync = bus.drives["Z"].sync_count
    backend.motion.fault_reset("Z")
    for _ in range(RESET_EDGE_PERIODS + 5):
        feedback, _ = period(backend)
    assert feedback["Z"].power_state is S.FAULT
    words = controlwords_since(bus.drives["Z"], sync)
    assert_operator_reset(words)  # bit 7 dropped again: a later reset makes a new edge
    assert words.count(0x80) == RESET_EDGE_PERIODS
    bus.drives["Z"].drive.inject_power_stage_fault(False)
    backend.motion.fault_reset("Z")
    run_until(backend, lambda fb: fb["Z"].power_state is S.SWITCH_ON_DISABLED)


def test_a_setpoint_jump_is_refused_and_nothing_is_sent(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    sync = bus.drives["X"].sync_count
    with pytest.raises(DriverError, match=r"X \(node 1\).*jumps 100"):
        backend.motion.write_setpoints({"X": 100.0, "Y": 0.0, "Z": 0.0})
    with pytest.raises(DriverError, match="not a finite number"):
        backend.motion.write_setpoints({"X": float("nan"), "Y": 0.0, "Z": 0.0})
    feedback, _ = period(backend)
    assert feedback["X"].position == pytest.approx(0.0, abs=1e-3)  # held where it was
    assert bus.drives["X"].wait(lambda: bus.drives["X"].sync_count == sync + 1)


def test_a_disabled_axis_is_commanded_to_where_it_is(backend, bus: WorldBus):
    """An axis moved by hand while disabled does not jump back when enabled."""
    start(backend)
    period(backend, {"X": 0.0})
    bus.drives["X"].move_by_hand(7_500)  # pushed by hand: 7.5 mm
    feedback, _ = period(backend, {"X": 0.0})  # the machine still says 0: ignored
    feedback = run_until(backend, lambda fb: fb["X"].position == 7.5)
    backend.motion.enable("X")
    feedback = run_until(
        backend, lambda fb: fb["X"].enabled, positions=lambda n: {}
    )  # machine commands the measured position
    for _ in range(5):
        feedback, _ = period(backend)
    assert feedback["X"].position == pytest.approx(7.5, abs=1e-3)
    assert all(t == 7_500 for _, t in bus.drives["X"].record.targets)


def test_homing_through_the_drive(backend, bus: WorldBus):
    start(backend)
    enable_all(backend)
    feedback = backend.motion.read_axes()
    assert not feedback["X"].homed
    backend.motion.start_homing("X")
    feedback, _ = period(backend)
    feedback = backend.motion.read_axes()
    assert feedback["X"].homing_active
    feedback = run_until(backend, lambda fb: not fb["X"].homing_active, 2000)
    assert feedback["X"].homed
    # at the home switch's edge (home_position of X), stopped a little past it on the creep
    assert feedback["X"].position == pytest.approx(-5.0, abs=0.05)
    assert bus.drives["X"].drive.mode is OperationMode.CYCLIC_SYNC_POSITION  # back in CSP
    home = feedback["X"].position
    for n in range(1, 6):  # and it follows setpoints again, from where it is
        feedback, _ = period(backend, {"X": home + 0.1 * n})
    for _ in range(20):
        period(backend, {"X": home + 0.5})
    assert backend.motion.read_axes()["X"].position == pytest.approx(home + 0.5, abs=1e-3)


def test_a_homing_error_ends_homing_without_homed(backend, bus: WorldBus):
    start(backend)
    with bus.lock:  # both limit switches read active: no home switch between them
        bus.drives["Y"].drive.stick_limit_switch(positive=True, active=True)
        bus.drives["Y"].drive.stick_limit_switch(positive=False, active=True)
    enable_all(backend)
    backend.motion.start_homing("Y")
    feedback = run_until(backend, lambda fb: fb["Y"].homing_active)
    feedback = run_until(backend, lambda fb: not fb["Y"].homing_active, 500)
    assert not feedback["Y"].homed
    feedback = run_until(backend, lambda fb: fb["Y"].fault_code == 0xFF03, 20)


def test_homing_needs_an_enabled_drive(backend):
    start(backend)
    with pytest.raises(DriverError, match="homing needs OPERATION ENABLED"):
        backend.motion.start_homing("X")
    with pytest.raises(DriverError, match="unknown axis 'W'"):
        backend.motion.enable("W")


def test_following_error_window_faults_the_drive(backend, bus: WorldBus):
    """The drive enforces following_error_limit (written to 0x6065) by itself."""
    start(backend)
    enable_all(backend)
    with bus.lock:
        bus.drives["X"].drive.set_jammed(True)  # the load does not follow the motor
    feedback = run_until(
        backend, lambda fb: fb["X"].faulted, positions=lambda n: {"X": 1.5 * (n + 1)}
    )
    feedback = run_until(backend, lambda fb: fb["X"].fault_code == 0x8611, 20)
    assert feedback["X"].faulted
