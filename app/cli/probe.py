"""``stave probe [--config FILE] [--json]``: connect to the configured hardware and show it.

A technician's first tool at commissioning: it connects with the configured backend and
gauge, reads once, and prints per axis the CiA 402 power state, position and fault code, the
inputs, one gauge reading and, where the backend offers one, a report on the link. It goes
through the same registry and lifecycle as the machine (configure, activate, read,
deactivate, shutdown), so a probe that works means the machine's start-up will too. It
never enables a drive and never sets an output (activation switches outputs off).

Exit codes: 0 everything answered; 1 a device could not be reached or refused (one line on
stderr says which and why); 2 the configuration is wrong (one line naming the key). A gauge
that answers with garbage or an out-of-range value is shown as such with exit code 0: the
link works, and "out of range" is what most gauges say with no board in front of them.

Generic over the contracts: it works the same with ``sim``, ``modbus`` and ``canopen``.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import asdict
from typing import Any

from app.config import ConfigError, MachineConfig, load_config
from app.drivers.contracts import (
    DriverError,
    GaugeReading,
    Lifecycle,
    LifecycleState,
    LinkReporter,
    MachineBackend,
    TimeDriven,
    WidthGauge,
)

GAUGE_WAIT_S = 3.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--config", metavar="FILE", help="machine configuration (default: the shipped machine.toml)"
    )
    parser.add_argument(
        "--json", action="store_true", help="print one JSON document instead of text"
    )


def _gauge_reading(
    gauge: WidthGauge, devices: list[Lifecycle], period_s: float
) -> GaugeReading | None:
    """One reading, waiting at most GAUGE_WAIT_S; simulated devices are advanced instead of
    waiting in real time."""
    gauge.request()
    driven = [d for d in devices if isinstance(d, TimeDriven)]
    for _ in range(max(1, round(GAUGE_WAIT_S / period_s))):
        reading = gauge.poll()
        if reading is not None:
            return reading
        if driven:
            for device in driven:
                device.advance(period_s)
        else:
            time.sleep(period_s)
    return None


def _bring_up(device: Lifecycle) -> None:
    """configure + activate from wherever the factory left the device (some factories
    return it configured already)."""
    if device.lifecycle_state in (LifecycleState.UNCONFIGURED, LifecycleState.ERROR):
        device.configure()
    if device.lifecycle_state is LifecycleState.INACTIVE:
        device.activate()


def _cleanup(devices: list[Lifecycle]) -> None:
    for device in reversed(devices):
        try:
            if device.lifecycle_state is LifecycleState.ACTIVE:
                device.deactivate()
        except DriverError:
            pass  # the first failure is what the technician needs to see
        finally:
            device.shutdown()


def _probe(config: MachineConfig, report: dict[str, Any]) -> None:
    """Fill ``report`` as far as the hardware answers; raises DriverError or ConfigError."""
    from app.drivers.registry import create_backend, create_gauge

    backend: MachineBackend = create_backend(config)
    started: list[Lifecycle] = []
    try:
        for device in backend.devices():
            started.append(device)
            _bring_up(device)
        axes = backend.motion.read_axes()
        report["axes"] = {
            name: {
                "power_state": fb.power_state.value,
                "statusword": f"0x{fb.statusword:04X}",
                "position": round(fb.position, 4),
                "unit": config.axes[name].unit if name in config.axes else "",
                "fault_code": f"0x{fb.fault_code:04X}",
                "homed": fb.homed,
                "home_switch": fb.home_switch,
                "limit_negative": fb.limit_negative,
                "limit_positive": fb.limit_positive,
            }
            for name, fb in axes.items()
        }
        report["inputs"] = asdict(backend.io.read_inputs())
        gauge = create_gauge(config, backend)
        started.append(gauge)
        _bring_up(gauge)
        reading = _gauge_reading(gauge, [gauge, *backend.devices()], config.period_s)
        if reading is None:
            raise DriverError("gauge", f"no reading within {GAUGE_WAIT_S:g} s")
        report["gauge"] = {"width_mm": reading.width_mm, "raw": reading.raw, "error": reading.error}
    finally:
        for device in started:
            for event in device.events():
                report["events"].append(
                    {
                        "kind": event.kind.value,
                        "device": event.device,
                        "code": f"0x{event.code:04X}",
                        "text": event.text,
                    }
                )
        for name, extra in backend.extras.items():
            if isinstance(extra, LinkReporter):
                report["link"][name] = dict(extra.probe_report())
        _cleanup(started)


def _text(report: dict[str, Any]) -> str:
    lines = [
        f"backend: {report['backend']}   gauge: {report['gauge_name']}   config: {report['config']}"
    ]
    axes = report.get("axes")
    if axes:
        lines.append(
            f"{'axis':<5}{'power state':<24}{'position':>10}{'':4}  {'fault':<8}"
            f"{'homed':<7}switches"
        )
        for name, a in axes.items():
            switches = (
                " ".join(
                    label
                    for label, key in (
                        ("home", "home_switch"),
                        ("limit-", "limit_negative"),
                        ("limit+", "limit_positive"),
                    )
                    if a[key]
                )
                or "-"
            )
            lines.append(
                f"{name:<5}{a['power_state']:<24}{a['position']:>10.3f} "
                f"{a['unit']:<3}  {a['fault_code']:<8}"
                f"{'yes' if a['homed'] else 'no':<7}{switches}"
            )
    inputs = report.get("inputs")
    if inputs:
        # Digital inputs as 0/1, the handwheel's count and analog values as read (unwired: left out)
        shown = (f"{k}={int(v)}" for k, v in inputs.items() if v is not None)
        lines.append("inputs: " + "  ".join(shown))
    gauge = report.get("gauge")
    if gauge:
        if gauge["width_mm"] is not None:
            lines.append(f"gauge: {gauge['width_mm']:.3f} mm   (raw {gauge['raw']!r})")
        else:
            lines.append(f"gauge: no width: {gauge['error']}")
    for event in report["events"]:
        lines.append(
            f"event: {event['device']}: {event['kind']} {event['code']} {event['text']}".rstrip()
        )
    for name, values in report["link"].items():
        lines.append(f"{name}: " + ", ".join(f"{k} {v}" for k, v in values.items()))
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    try:
        config = load_config(args.config)
        from app.drivers.settings_check import check_settings

        check_settings(config, to_run=False)  # it never enables a drive
    except ConfigError as exc:
        print(f"stave probe: {exc}", file=sys.stderr)
        return 2
    report: dict[str, Any] = {
        "config": config.source,
        "backend": config.backend,
        "gauge_name": config.gauge,
        "events": [],
        "link": {},
        "error": None,
    }
    code = 0
    try:
        _probe(config, report)
    except ConfigError as exc:
        report["error"] = str(exc)
        code = 2
    except DriverError as exc:
        report["error"] = str(exc)
        code = 1
    if args.json:
        print(json.dumps(report, indent=2))
    elif code != 2:
        print(_text(report))
    if report["error"]:
        print(f"stave probe: {report['error']}", file=sys.stderr)
    return code
