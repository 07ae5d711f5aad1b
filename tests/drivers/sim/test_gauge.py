"""The simulated width gauge: the board's width with seeded noise, after the measurement
time; its queue; its failure modes; and the gauge alone, beside another backend."""

from __future__ import annotations

import statistics

import pytest

from app.drivers import registry
from app.drivers.contracts import (
    CommunicationError,
    DeviceEventKind,
    GaugeReading,
    LifecycleError,
    LifecycleState,
    MachineBackend,
)
from app.drivers.sim.gauge import SimGauge, create_gauge
from tests.drivers.sim.rig import Rig, make_config


def gauge_rig(**gauge: object) -> tuple[Rig, SimGauge]:
    config = make_config(gauge=gauge)
    rig = Rig(config)
    sim_gauge = registry.create_gauge(config, rig.backend)
    assert isinstance(sim_gauge, SimGauge)
    assert sim_gauge.lifecycle_state is LifecycleState.INACTIVE
    sim_gauge.activate()
    return rig, sim_gauge


def measure(rig: Rig, gauge: SimGauge, timeout_s: float = 1.0) -> GaugeReading:
    gauge.request()
    reading: list[GaugeReading] = []

    def answered() -> bool:
        r = gauge.poll()
        if r is not None:
            reading.append(r)
        return bool(reading)

    rig.run_until(answered, timeout_s)
    return reading[0]


def test_the_reading_arrives_after_the_measurement_time_once() -> None:
    rig, gauge = gauge_rig(measurement_time_s=0.3, noise_mm=0.0)
    rig.world.load_board(151.234)
    gauge.request()
    waited = rig.run_until(lambda: gauge.poll() is not None, 1.0)
    assert waited == pytest.approx(0.3, abs=1e-9)
    gauge.request()
    rig.run(0.3)
    reading = gauge.poll()
    assert reading == GaugeReading(151.23, "W=151.23")  # 0.01 mm resolution, like the serial
    assert reading.ok
    assert gauge.poll() is None  # once


def test_noise_has_the_configured_spread_around_the_true_width() -> None:
    rig, gauge = gauge_rig(noise_mm=0.5, measurement_time_s=0.0)
    rig.world.load_board(200.0)
    widths = [measure(rig, gauge).width_mm or 0.0 for _ in range(400)]
    assert statistics.fmean(widths) == pytest.approx(200.0, abs=3 * 0.5 / 20)
    assert statistics.stdev(widths) == pytest.approx(0.5, rel=0.12)
    assert len(set(widths)) > 50


def test_readings_are_reproducible_with_a_seed() -> None:
    def readings(seed: int) -> list[float | None]:
        rig, gauge = gauge_rig(seed=seed, noise_mm=0.2)
        rig.world.load_board(150.0)
        return [measure(rig, gauge).width_mm for _ in range(5)]

    assert readings(7) == readings(7)
    assert readings(7) != readings(8)


def test_queued_widths_go_to_the_next_boards() -> None:
    rig, gauge = gauge_rig(noise_mm=0.0)
    gauge.queue_widths([140.0, 160.5])
    rig.world.load_board()
    assert measure(rig, gauge).width_mm == 140.0
    rig.world.load_board()
    assert measure(rig, gauge).width_mm == 160.5


def test_an_empty_table_reads_zero() -> None:
    rig, gauge = gauge_rig()
    assert measure(rig, gauge) == GaugeReading(0.0, "W=0.00")


def test_no_reply_ever() -> None:
    rig, gauge = gauge_rig()
    rig.world.load_board(150.0)
    rig.faults.inject("gauge_none")
    gauge.request()
    for _ in range(1000):  # 4 s
        rig.tick()
        assert gauge.poll() is None


def test_garbage() -> None:
    rig, gauge = gauge_rig()
    rig.world.load_board(150.0)
    rig.faults.inject("gauge_garbage")
    reading = measure(rig, gauge)
    assert reading.width_mm is None and not reading.ok
    assert reading.raw == "#?!x"
    assert reading.error.startswith("unparseable reply")


def test_out_of_range() -> None:
    rig, gauge = gauge_rig(out_of_range_mm=999.0)
    rig.world.load_board(150.0)
    rig.faults.inject("gauge_out_of_range")
    assert measure(rig, gauge) == GaugeReading(999.0, "W=999.00")
    rig.faults.clear_injections()
    reading = measure(rig, gauge)
    assert reading.width_mm is not None and abs(reading.width_mm - 150.0) < 0.5


def test_unplugged() -> None:
    rig, gauge = gauge_rig()
    rig.world.load_board(150.0)
    gauge.request()
    rig.faults.inject("comms_loss", "gauge")
    with pytest.raises(CommunicationError, match="unplugged"):
        gauge.poll()
    with pytest.raises(CommunicationError):
        gauge.request()
    assert [e.kind for e in gauge.events()] == [DeviceEventKind.COMMUNICATION_LOST]
    rig.tick()  # the machine and its I/O are not affected
    rig.faults.clear_injections()
    assert [e.kind for e in gauge.events()] == [DeviceEventKind.COMMUNICATION_RESTORED]
    assert measure(rig, gauge).ok


def test_lifecycle_refusals() -> None:
    config = make_config()
    rig = Rig(config)
    gauge = create_gauge(config, rig.backend)
    with pytest.raises(LifecycleError, match="request refused: the device is inactive"):
        gauge.request()
    gauge.activate()
    gauge.shutdown()
    with pytest.raises(LifecycleError):
        gauge.poll()
    gauge.shutdown()  # idempotent


def test_a_gauge_without_a_simulated_world_has_its_own_boards_and_counts_polls() -> None:
    config = make_config(
        gauge={
            "width_mean_mm": 150.0,
            "width_sd_mm": 10.0,
            "width_min_mm": 130.0,
            "width_max_mm": 170.0,
            "noise_mm": 0.0,
            "measurement_time_s": 0.2,
        }
    )
    rig = Rig(config)
    other = MachineBackend("modbus", rig.motion, rig.io)  # no world in its extras
    gauge = create_gauge(config, other)
    gauge.activate()
    gauge.queue_widths([142.5])
    gauge.request()
    polls = 1
    while (reading := gauge.poll()) is None:
        polls += 1
    assert polls == 50  # 0.2 s at one poll per 4 ms period
    assert reading == GaugeReading(142.5, "W=142.50")
    widths = []
    for _ in range(100):
        gauge.request()
        while (reading := gauge.poll()) is None:
            pass
        widths.append(reading.width_mm or 0.0)
    assert all(130.0 <= w <= 170.0 for w in widths) and len(set(widths)) > 50
    gauge.inject("gauge_garbage")
    gauge.request()
    while (reading := gauge.poll()) is None:
        pass
    assert not reading.ok
    gauge.inject("comms_loss", "gauge")
    with pytest.raises(CommunicationError):
        gauge.request()
    gauge.clear_injections()
    gauge.request()
    with pytest.raises(ValueError, match="not allowed on the gauge"):
        gauge.inject("drive_fault", "X")
