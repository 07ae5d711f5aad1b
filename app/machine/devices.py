"""The machine's devices as one link: bring them up, read them each period, turn their
events into findings, reconnect them on the operator's Reset, and release them.

Why apart from the controller: what a lost link means (alarm E020 for the drives and the
I/O, E033 for the width gauge, whose loss only prevents a new measurement) and how a Reset
brings the devices up again is one job, and the only place that talks to the lifecycle.
"""

from __future__ import annotations

import logging
from collections.abc import Callable

from app.drivers.contracts import (
    AxisFeedback,
    CommunicationError,
    DeviceEvent,
    DeviceEventKind,
    DriverError,
    InputImage,
    MachineBackend,
    WidthGauge,
)
from app.machine.alarms import AlarmCode
from app.machine.supervision import Finding, fault_detail

log = logging.getLogger(__name__)

LOST = (DeviceEventKind.COMMUNICATION_LOST, DeviceEventKind.RECEIVE_THREAD_DIED)


class DeviceLink:
    """The backend's devices and the width gauge, and whether their links are up."""

    def __init__(self, backend: MachineBackend, gauge: WidthGauge) -> None:
        self.backend = backend
        self.gauge = gauge
        self.comms_ok = True  # drives and I/O answer
        self.gauge_ok = True

    def power_up(self) -> tuple[dict[str, AxisFeedback], InputImage]:
        """Configure and activate every device; raises DriverError (the link is then down)."""
        try:
            devices = (*self.backend.devices(), self.gauge)
            for device in devices:
                device.configure()
            for device in devices:
                device.activate()
            return dict(self.backend.motion.read_axes()), self.backend.io.read_inputs()
        except DriverError:
            self.comms_ok = False
            raise

    def read(self) -> tuple[dict[str, AxisFeedback], InputImage, list[Finding]]:
        """One period's feedback, inputs and the faults the devices' events report; raises
        DriverError when the drives or the I/O do not answer."""
        feedback = dict(self.backend.motion.read_axes())
        inputs = self.backend.io.read_inputs()
        findings: list[Finding] = []
        for device in (*self.backend.devices(), self.gauge):
            for event in device.events():
                finding = self._event(event, from_gauge=device is self.gauge)
                if finding is not None:
                    findings.append(finding)
        return feedback, inputs, findings

    def _event(self, event: DeviceEvent, from_gauge: bool) -> Finding | None:
        detail = event.text or event.kind.value
        if event.kind in LOST:
            if from_gauge:
                # The axes and I/O still answer; only a new measurement is impossible.
                self.gauge_ok = False
                return Finding(AlarmCode.GAUGE_DISCONNECTED, "gauge", detail)
            self.comms_ok = False
            return Finding(AlarmCode.COMMUNICATION_LOST, event.device, detail)
        if event.kind is DeviceEventKind.EMERGENCY and event.code:
            log.warning("EMCY %s %s", fault_detail(event.device, event.code), event.text)
        elif event.kind is DeviceEventKind.COMMUNICATION_RESTORED:
            log.info("communication restored: %s (reset needed)", event.device)
        return None

    def lost(self, exc: DriverError) -> Finding:
        """A failed read or write: a lost link (E020), or a device that answered and refused
        the request (E021, with its code: a Modbus exception reply, an SDO abort), whose
        link still works."""
        if not isinstance(exc, CommunicationError):
            return Finding(AlarmCode.DEVICE_REFUSED, exc.device, str(exc))
        self.comms_ok = False
        return Finding(AlarmCode.COMMUNICATION_LOST, exc.device, str(exc))

    def gauge_lost(self) -> None:
        self.gauge_ok = False

    @property
    def all_up(self) -> bool:
        return self.comms_ok and self.gauge_ok

    def reconnect(self) -> str:
        """Operator's Reset after a lost link: bring the lost devices up again (disabled).
        Returns why that failed, or ""."""
        lost = [*self.backend.devices(), self.gauge] if not self.comms_ok else [self.gauge]
        try:
            for device in lost:
                device.deactivate()
                device.configure()  # drops the events of the old connection
                device.activate()
        except DriverError as exc:
            return str(exc)
        self.comms_ok = True
        self.gauge_ok = True
        return ""

    def call(self, action: Callable[[], None]) -> None:
        """A stop or power request while the link may be gone: a failure is logged, never
        raised, because the latched state already holds and the drives stop on their own
        watchdog when the link is lost."""
        if not self.comms_ok:
            return
        try:
            action()
        except DriverError as exc:
            log.warning("%s", exc)

    def release(self) -> None:
        """Shut down every device (shutdown deactivates an active device first and never
        raises)."""
        for device in (self.gauge, *self.backend.devices()):
            device.shutdown()
