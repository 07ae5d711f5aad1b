"""Jobs from the plant: a recipe to select, never a motion.

Why a pending job: the plant may ask at any moment, but a recipe change in the middle of a
cycle or of homing would surprise the operator. So a job waits until the machine is READY
(and its own rule for a recipe selection allows it), then becomes one ``SelectRecipe``
command; starting the cycle stays the operator's action at the panel. The job and who asked
are shown on the panel. A newer job replaces a waiting one.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.machine.commands import SelectRecipe
from app.machine.snapshot import MachineSnapshot
from app.machine.states import MachineState


@dataclass(frozen=True)
class PlantJob:
    recipe_id: int
    recipe_name: str
    requested_by: str  # the OPC UA user name

    def notice(self, done: bool) -> str:
        verb = "selected" if done else "waits for READY"
        return f"plant job: recipe {self.recipe_name!r} {verb} (asked by {self.requested_by})"


class PlantJobs:
    def __init__(self) -> None:
        self.pending: PlantJob | None = None
        self.last_done: PlantJob | None = None

    def request(self, job: PlantJob) -> None:
        self.pending = job

    def due(self, snapshot: MachineSnapshot | None) -> SelectRecipe | None:
        """The command to send now, if a job waits and the machine is READY for it."""
        job = self.pending
        if job is None or snapshot is None or snapshot.state is not MachineState.READY:
            return None
        if snapshot.allowed.get("SelectRecipe") is not None:
            return None
        self.pending = None
        self.last_done = job
        return SelectRecipe(job.recipe_id)

    def notice(self) -> str:
        if self.pending is not None:
            return self.pending.notice(done=False)
        if self.last_done is not None:
            return self.last_done.notice(done=True)
        return ""
