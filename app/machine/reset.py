"""The operator's Reset of a latched machine, over two periods.

Why two periods: the fault reset of the drives is sent first; only the next period's fresh
feedback can show whether they left FAULT. The state unlatches only when every cause is gone
(no drive in FAULT, the E-stop chain closed, the link up); otherwise the Reset fails after
``RESET_TIMEOUT_S`` with the causes, and nothing is retried without a new Reset.
"""

from __future__ import annotations

import enum
from collections.abc import Mapping

from app.drivers.contracts import AxisFeedback, InputImage
from app.machine.refusals import Reason, Refusal, refusal

RESET_TIMEOUT_S = 1.0  # how long a Reset waits for the drives to leave FAULT


class ResetStep(enum.Enum):
    IDLE = "idle"  # no Reset pending
    SEND_FAULT_RESET = "send the fault reset"  # the controller sends it now
    WAITING = "waiting"  # for the causes to go
    DONE = "done"  # every cause is gone: unlatch
    FAILED = "failed"  # timed out: ``causes`` says why


class ResetSequence:
    def __init__(self) -> None:
        self._since_s: float | None = None
        self._fault_reset_sent = False
        self.causes: tuple[Refusal, ...] = ()

    def request(self, now_s: float) -> None:
        self._since_s = now_s
        self._fault_reset_sent = False

    def cancel(self) -> None:
        self._since_s = None

    def step(
        self,
        now_s: float,
        feedback: Mapping[str, AxisFeedback],
        inputs: InputImage,
        link_up: bool,
    ) -> ResetStep:
        if self._since_s is None:
            return ResetStep.IDLE
        if not self._fault_reset_sent:
            self._fault_reset_sent = True
            return ResetStep.SEND_FAULT_RESET
        causes = [
            refusal(Reason.DRIVE_STILL_FAULTED, name, f"0x{fb.fault_code:04X}")
            for name, fb in feedback.items()
            if fb.faulted
        ]
        if not inputs.estop_ok:
            causes.append(Refusal(Reason.ESTOP_STILL_PRESSED))
        if not link_up:
            causes.append(Refusal(Reason.COMMS_NOT_RESTORED))
        self.causes = tuple(causes)
        if not self.causes:
            self._since_s = None
            return ResetStep.DONE
        if now_s - self._since_s > RESET_TIMEOUT_S:
            self._since_s = None
            return ResetStep.FAILED
        return ResetStep.WAITING
