"""The Modbus tests run emulator servers and relays on threads: none may outlive its test."""

from __future__ import annotations

from tests.drivers.thread_guard import no_thread_left_behind  # noqa: F401 (autouse fixture)
