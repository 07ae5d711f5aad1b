"""``create_backend(config)`` for the registry: drives and I/O coupler on one Modbus bus.

Why one bus object shared by the motion and the I/O side: on RTU they are on the same wire
and on TCP often behind the same gateway; a loss seen by either must stop both, and must be
reported once. Each side ``acquire``s the bus in its ``configure`` and ``release``s it in its
``shutdown``; the last one out closes the connections.
"""

from __future__ import annotations

from collections.abc import Mapping

from app.config import MachineConfig
from app.drivers.contracts import MachineBackend
from app.drivers.modbus.bus import DeviceAddress, ModbusBus
from app.drivers.modbus.coupler import ModbusIO
from app.drivers.modbus.drives import ModbusMotion
from app.drivers.modbus.rtu_timing import check_period, estimate_rtu_cycle
from app.drivers.modbus.settings import ModbusSettings, parse_modbus_settings


class LinkReport:
    """What ``stave probe`` prints about the link (found in ``MachineBackend.extras``)."""

    def __init__(self, settings: ModbusSettings, bus: ModbusBus, period_s: float) -> None:
        self.settings = settings
        self.bus = bus
        self.period_s = period_s

    def probe_report(self) -> Mapping[str, object]:
        stats = self.bus.statistics
        per_period = 2 * len(self.settings.drives) + (
            2 if self.settings.coupler.output_count else 1
        )
        report: dict[str, object] = {
            "links": ", ".join(self.bus.link_names),
            "transactions per period": per_period,
            "transactions": stats.transactions,
            "retries": stats.retries,
            "failures": stats.failures,
            "exception replies": stats.exception_replies,
            "mean transaction ms": round(stats.mean_time_s * 1000.0, 3),
            "max transaction ms": round(stats.max_time_s * 1000.0, 3),
            "configured period ms": round(self.period_s * 1000.0, 3),
        }
        if stats.transactions:
            report["estimated period traffic ms"] = round(
                per_period * stats.mean_time_s * 1000.0, 3
            )
        estimate = estimate_rtu_cycle(self.settings)
        if estimate is not None:
            report["rtu period traffic ms (computed)"] = round(estimate.cycle_s * 1000.0, 2)
            report["rtu X-Y skew ms (computed)"] = round(estimate.xy_skew_s * 1000.0, 2)
        return report


def create_backend(config: MachineConfig) -> MachineBackend:
    """Check ``[backend.modbus]`` (ConfigError on the first bad key), build the bus, the
    axes and the I/O. Nothing is opened before ``configure``."""
    settings = parse_modbus_settings(config.backend_settings.get("modbus", {}), config)
    check_period(settings, config.period_s, config.source)
    devices = [DeviceAddress(d.axis, d.endpoint, d.device_id) for d in settings.drives.values()]
    devices.append(DeviceAddress("io", settings.coupler.endpoint, settings.coupler.device_id))
    bus = ModbusBus(settings.link, devices)
    motion = ModbusMotion(settings.drives, config.axes, bus)
    io = ModbusIO(settings.coupler, bus)
    report = LinkReport(settings, bus, config.period_s)
    return MachineBackend(
        "modbus",
        motion,
        io,
        extras={"modbus_settings": settings, "modbus_bus": bus, "link_report": report},
    )
