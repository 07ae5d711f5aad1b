"""The OPC UA server in its own OS process, fed with the snapshots the screens receive.

Why a process: the server's work (encryption, subscriptions, a slow or hostile client) must
delay neither a setpoint (the machine has its own process anyway) nor the panel's screens.
The operator application hands it each new snapshot with ``put_nowait`` on a small queue (a
full queue drops the snapshot: the next one carries everything again), and collects the only
thing that comes back: a ``SelectRecipe`` command for a plant job, and notices for the panel.

``PlantFeedLink`` wraps the machine link the screens use, so neither the screens nor the
machine know the plant connection exists; it lets nothing but ``SelectRecipe`` through.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import multiprocessing
import multiprocessing.queues
import os
import queue
from dataclasses import replace
from pathlib import Path
from typing import Any

from app.machine.commands import Command, SelectRecipe
from app.machine.link import MachineLink
from app.machine.refusals import Reason, Refusal, refusal
from app.machine.snapshot import MachineSnapshot, PlanPreview
from app.plant.settings import OpcuaSettings
from app.plant.status import LISTENING, PlantStatus

log = logging.getLogger(__name__)

_QUEUE_SIZE = 8
POLL_S = 0.01
_STOP = "stop"


def default_pki_dir(db_path: Path) -> Path:
    return db_path.parent / "opcua-pki"


async def _serve(
    settings: OpcuaSettings,
    db_path: Path,
    pki_dir: Path,
    nodesets_dir: Path | None,
    inbox: multiprocessing.queues.Queue[Any],
    outbox: multiprocessing.queues.Queue[Any],
    parent_pid: int,
) -> None:
    from app.plant.server import PlantServer

    def send(command: SelectRecipe) -> None:
        with contextlib.suppress(queue.Full):
            outbox.put_nowait(command)

    def notice(text: str) -> None:
        with contextlib.suppress(queue.Full):
            outbox.put_nowait(("notice", text))

    server = PlantServer(settings, db_path, pki_dir, send, nodesets_dir, on_event=notice)
    try:
        await server.start()
    except Exception as exc:
        log.exception("OPC UA server did not start")
        notice(f"OPC UA server did not start: {exc}")
        return
    notice(f"{LISTENING} {settings.endpoint_url}")
    for warning in settings.insecure_choices():
        notice(f"warning: OPC UA {warning} is on (commissioning only)")
    try:
        while os.getppid() == parent_pid:
            latest: MachineSnapshot | str | None = None
            got = False
            while True:
                try:
                    item = inbox.get_nowait()
                except queue.Empty:
                    break
                if item == _STOP:
                    return
                latest, got = item, True
            if got:
                try:
                    await server.publish(latest if isinstance(latest, MachineSnapshot) else None)
                except Exception:  # one bad update must not end the plant connection
                    log.exception("OPC UA: publishing a snapshot failed")
            await asyncio.sleep(POLL_S)
    finally:
        await server.stop()


def plant_process_main(
    settings: OpcuaSettings,
    db_path: str,
    pki_dir: str,
    nodesets_dir: str,
    log_dir: str,
    log_level: str,
    inbox: multiprocessing.queues.Queue[Any],
    outbox: multiprocessing.queues.Queue[Any],
    parent_pid: int,
) -> None:
    import signal

    from app.logging_setup import setup_logging

    setup_logging(log_dir, log_level, console=False, file_name="opcua.log")
    logging.getLogger("asyncua").setLevel(logging.WARNING)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    asyncio.run(
        _serve(
            settings,
            Path(db_path),
            Path(pki_dir),
            Path(nodesets_dir) if nodesets_dir else None,
            inbox,
            outbox,
            parent_pid,
        )
    )


class PlantProcess:
    def __init__(
        self,
        process: multiprocessing.process.BaseProcess,
        inbox: multiprocessing.queues.Queue[Any],
        outbox: multiprocessing.queues.Queue[Any],
        settings: OpcuaSettings,
        pki_dir: Path,
    ) -> None:
        self._process = process
        self._inbox = inbox
        self._outbox = outbox
        self.settings = settings
        self.pki_dir = pki_dir
        self.notices: list[str] = []
        self._listening_notice = ""

    @classmethod
    def start(
        cls,
        settings: OpcuaSettings,
        db_path: Path,
        log_dir: str = "",
        log_level: str = "INFO",
    ) -> PlantProcess:
        context = multiprocessing.get_context("spawn")
        inbox: multiprocessing.queues.Queue[Any] = context.Queue(_QUEUE_SIZE)
        outbox: multiprocessing.queues.Queue[Any] = context.Queue(_QUEUE_SIZE * 4)
        pki_dir = Path(settings.pki_dir) if settings.pki_dir else default_pki_dir(db_path)
        process = context.Process(
            target=plant_process_main,
            name="opcua",
            args=(
                settings,
                str(db_path),
                str(pki_dir),
                settings.nodesets_dir,
                log_dir,
                log_level,
                inbox,
                outbox,
                os.getpid(),
            ),
            daemon=True,
        )
        process.start()
        return cls(process, inbox, outbox, settings, pki_dir)

    def publish(self, snapshot: MachineSnapshot | None) -> None:
        """Hand over a snapshot; never waits (a full queue drops it)."""
        with contextlib.suppress(queue.Full, ValueError, OSError):
            self._inbox.put_nowait(snapshot)

    def commands(self) -> list[SelectRecipe]:
        """Recipe selections of plant jobs that are due (and the notices, kept aside)."""
        found: list[SelectRecipe] = []
        while True:
            try:
                item = self._outbox.get_nowait()
            except (queue.Empty, ValueError, OSError):
                break
            if isinstance(item, SelectRecipe):
                found.append(item)
            elif isinstance(item, tuple) and len(item) == 2 and item[0] == "notice":
                text = str(item[1])
                if text.startswith(LISTENING):
                    self._listening_notice = text  # kept when later notices push it out
                self.notices.append(text)
                del self.notices[:-20]
        return found

    def status(self) -> PlantStatus:
        notices = tuple(self.notices)
        if self._listening_notice and self._listening_notice not in notices:
            notices = (self._listening_notice, *notices)
        return PlantStatus(self.settings, self.pki_dir, self.alive(), notices)

    def alive(self) -> bool:
        return self._process.is_alive()

    def close(self, timeout_s: float = 5.0) -> None:
        if self._process.is_alive():
            with contextlib.suppress(queue.Full, ValueError, OSError):
                self._inbox.put(_STOP, timeout=1.0)
            self._process.join(timeout_s)
            if self._process.is_alive():
                self._process.terminate()
                self._process.join(timeout_s)
        for q in (self._inbox, self._outbox):
            q.close()
            q.cancel_join_thread()


class PlantFeedLink:
    """A MachineLink that also feeds the plant connection (see the module docstring)."""

    def __init__(self, link: MachineLink, plant: PlantProcess) -> None:
        self._link = link
        self._plant = plant
        self._fed_seq = -1
        self._notice = ""
        self._covered_message: Refusal | None = None

    def send(self, command: Command) -> None:
        self._link.send(command)

    def latest(self) -> MachineSnapshot | None:
        snapshot = self._link.latest()
        if snapshot is not None and snapshot.seq != self._fed_seq:
            self._fed_seq = snapshot.seq
            self._plant.publish(snapshot if self._link.alive() else None)
        for command in self._plant.commands():
            if isinstance(command, SelectRecipe):  # the only command the plant may cause
                self._link.send(command)
        if snapshot is None:
            return None
        if self._plant.notices and self._plant.notices[-1] != self._notice:
            # A new notice from the plant shows until the machine has something newer to say.
            self._notice = self._plant.notices[-1]
            self._covered_message = snapshot.message
        if self._notice and snapshot.message == self._covered_message:
            return replace(snapshot, message=refusal(Reason.PLANT_NOTICE, self._notice))
        return snapshot

    def plan(self, plan_id: int) -> PlanPreview | None:
        return self._link.plan(plan_id)

    def plant_status(self) -> PlantStatus:
        return self._plant.status()

    def alive(self) -> bool:
        return self._link.alive()

    def close(self) -> None:
        self._plant.close()
        self._link.close()
