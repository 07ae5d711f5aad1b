"""Fixtures: the simulated world's drives and I/O on a virtual CAN channel unique to each
test, a machine configuration naming that channel, and the backend under test.

Real time: the bus is real-time (heartbeats, timeouts), so these tests wait on conditions
(frames arriving) with short bounds; the heartbeat is 50 ms and its timeout 250 ms, both ways
(our watchdog of the nodes, the drives' consumer of the controller's heartbeat).
"""

from __future__ import annotations

import threading
import time
import uuid
from collections.abc import Callable, Iterator, Mapping
from typing import Any

import pytest

from app.config import MachineConfig, parse_config
from app.drivers.canopen.backend import create_backend
from app.drivers.canopen.settings import INPUT_FUNCTIONS, OUTPUT_FUNCTIONS
from app.drivers.contracts import AxisFeedback, InputImage, MachineBackend, OutputImage
from app.drivers.sim.settings import SimSettings
from app.drivers.sim.world import SimWorld
from tests.drivers.canopen.world_nodes import WorldBus

NODE_IDS = {"X": 1, "Y": 2, "Z": 3}
IO_NODE = 10
COUNTS = {"X": 1000.0, "Y": 1000.0, "Z": 10000.0}  # per mm, per mm, per degree
INPUT_BITS = {name: bit for bit, name in enumerate(INPUT_FUNCTIONS)}
OUTPUT_BITS = {name: bit for bit, name in enumerate(OUTPUT_FUNCTIONS)}


def canopen_settings(channel: str, **overrides: Any) -> dict[str, Any]:
    settings: dict[str, Any] = {
        "interface": "virtual",
        "channel": channel,
        "bitrate": 1_000_000,
        "heartbeat_ms": 50,
        "heartbeat_timeout_ms": 250,
        "master_heartbeat_timeout_ms": 250,
        # Far above a healthy answer (~1 ms): a loaded two-core test machine can starve the
        # simulated nodes' thread for a few hundred ms; the timeout tests set their own.
        "sdo_timeout_ms": 1000,
        "startup_timeout_ms": 1000,
        "pdo_miss_limit": 25,
        "axes": {
            name: {"node_id": node, "counts_per_unit": COUNTS[name]}
            for name, node in NODE_IDS.items()
        },
        "io": {"node_id": IO_NODE, "inputs": dict(INPUT_BITS), "outputs": dict(OUTPUT_BITS)},
    }
    settings.update(overrides)
    return settings


def machine_data(channel: str, **overrides: Any) -> dict[str, Any]:
    return {
        "backend": {
            "name": "canopen",
            "period_ms": 4.0,
            "canopen": canopen_settings(channel, **overrides),
        },
        "axes": {
            "X": {"encoder": "incremental"},
            "Y": {"encoder": "incremental"},
            "Z": {"encoder": "absolute"},
        },
    }


def world_bus(
    world: SimWorld,
    channel: str,
    input_bits: Mapping[str, int] = INPUT_BITS,
    analog: Mapping[str, int] | None = None,
    **options: Any,
) -> WorldBus:
    """The world's drives and I/O as CANopen nodes on ``channel``, wired as
    :func:`machine_data` configures the backend (or as ``input_bits``, ``analog`` and the
    :class:`WorldBus` ``options`` say)."""
    return WorldBus(
        world, channel, NODE_IDS, COUNTS, IO_NODE, input_bits, OUTPUT_BITS, analog, **options
    )


@pytest.fixture(autouse=True)
def no_threads_left() -> Iterator[None]:
    """Fail a test that leaves a thread behind (notifier, heartbeat producer, ...)."""
    before = set(threading.enumerate())
    yield
    deadline = time.monotonic() + 3.0
    for thread in set(threading.enumerate()) - before:
        thread.join(max(0.0, deadline - time.monotonic()))
    alive = [t.name for t in set(threading.enumerate()) - before if t.is_alive()]
    assert not alive, f"threads left running: {alive}"


@pytest.fixture
def channel() -> str:
    return f"stave-test-{uuid.uuid4().hex[:12]}"


@pytest.fixture
def config(channel: str) -> MachineConfig:
    return parse_config(machine_data(channel))


def zero_world(config: MachineConfig) -> SimWorld:
    """The world with every axis at 0 on its encoder (absolute or not), so that counts in a
    test are plain numbers."""
    return SimWorld(config, SimSettings(start_position=dict.fromkeys(NODE_IDS, 0.0)))


@pytest.fixture
def bus(config: MachineConfig, channel: str) -> Iterator[WorldBus]:
    """The simulated world's drives and I/O on the test's channel."""
    created = world_bus(zero_world(config), channel)
    yield created
    created.close()


@pytest.fixture
def backend(config: MachineConfig, bus: WorldBus) -> Iterator[MachineBackend]:
    """The backend under test, against the nodes of ``bus``."""
    created = create_backend(config)
    yield created
    for device in created.devices():
        device.shutdown()


def start(backend: MachineBackend) -> None:
    for device in backend.devices():
        device.configure()
    for device in backend.devices():
        device.activate()


def period(
    backend: MachineBackend,
    positions: Mapping[str, float] | None = None,
    outputs: OutputImage | None = None,
    *,
    settle: bool = True,
) -> tuple[dict[str, AxisFeedback], InputImage]:
    """One machine period: read everything, then write everything (as the machine loop).
    ``settle``: wait for the nodes' answers (a test that expects a node to fail does not)."""
    feedback = dict(backend.motion.read_axes())
    inputs = backend.io.read_inputs()
    targets = {name: fb.position for name, fb in feedback.items()}
    targets.update(positions or {})
    backend.motion.write_setpoints(targets)
    backend.io.write_outputs(outputs or OutputImage())
    # periods run back to back here: wait for the answers a real period would have waited for
    if settle:
        assert backend.extras["canopen"].wait_for_answers(1.0)  # type: ignore[attr-defined]
    return feedback, inputs


def run_until(
    backend: MachineBackend,
    done: Callable[[dict[str, AxisFeedback]], bool],
    max_periods: int = 200,
    positions: Callable[[int], Mapping[str, float]] | None = None,
) -> dict[str, AxisFeedback]:
    """Run periods until ``done(feedback)``; fails after ``max_periods``."""
    for n in range(max_periods):
        feedback, _ = period(backend, positions(n) if positions else None)
        if done(feedback):
            return feedback
    raise AssertionError(f"condition not reached in {max_periods} periods: {feedback}")


def enable_all(backend: MachineBackend) -> dict[str, AxisFeedback]:
    for name in backend.motion.axis_names:
        backend.motion.enable(name)
    return run_until(backend, lambda fb: all(f.enabled for f in fb.values()))
