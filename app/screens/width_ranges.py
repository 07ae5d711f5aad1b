"""Each recipe's range of board widths on this machine, for the Recipes screen's list.

Why a worker thread and a cache: the range is a scan of the machine's own composition (some
0.1 s per recipe, :func:`app.geometry.width_range.cuttable_widths`, the function the machine
checks a measured width with); a list of recipes must appear at once and fill its ranges in
as they come, and a recipe whose stave and parameters did not change is not scanned again.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping
from concurrent.futures import Future, ThreadPoolExecutor

from app.data.recipe import Recipe
from app.geometry.limits import StaveLimits
from app.geometry.width_range import WidthRange, cuttable_widths

log = logging.getLogger(__name__)

PENDING = "pending"
"""What :meth:`WidthRanges.get` answers while the worker is still scanning."""


class WidthRanges:
    def __init__(self, limits: StaveLimits) -> None:
        self._limits = limits
        self._pool: ThreadPoolExecutor | None = None
        self._known: dict[str, WidthRange | None] = {}
        self._running: dict[str, Future[WidthRange | None]] = {}

    @staticmethod
    def _key(recipe: Recipe, params: Mapping[str, float]) -> str:
        return repr((recipe.stave, sorted(params.items())))

    def get(self, recipe: Recipe, params: Mapping[str, float]) -> WidthRange | str | None:
        """The range (None: the recipe cuts no board here), or PENDING (asked for now)."""
        key = self._key(recipe, params)
        if key in self._known:
            return self._known[key]
        if key not in self._running:
            if self._pool is None:
                self._pool = ThreadPoolExecutor(max_workers=1, thread_name_prefix="width-ranges")
            stave, frozen = recipe.stave, dict(params)
            self._running[key] = self._pool.submit(cuttable_widths, stave, frozen, self._limits)
        return PENDING

    def now(self, recipe: Recipe, params: Mapping[str, float]) -> WidthRange | None:
        """The range at once (the draft's preview; computed here if not known yet)."""
        key = self._key(recipe, params)
        if key in self._running:  # the worker is at it: wait for its answer
            self._running[key].exception()
            self.collect()
        if key not in self._known:
            self._known[key] = cuttable_widths(recipe.stave, params, self._limits)
        return self._known[key]

    def collect(self) -> bool:
        """Take in what the worker has finished; True if anything new arrived."""
        done = [key for key, future in self._running.items() if future.done()]
        for key in done:
            future = self._running.pop(key)
            failed = future.exception()
            if failed is not None:  # a recipe the scan cannot handle cuts nothing we know of
                log.error("width range not computed: %s", failed)
            self._known[key] = None if failed is not None else future.result()
        return bool(done)

    @property
    def pending(self) -> bool:
        return bool(self._running)

    def close(self) -> None:
        if self._pool is not None:
            self._pool.shutdown(wait=True, cancel_futures=True)
            self._pool = None
