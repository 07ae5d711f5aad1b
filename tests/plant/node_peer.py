"""node-opcua as the test client: a stack we did not write, driven line by line.

The suite installs it (``scripts/ensure-env.sh dev`` runs ``npm ci`` in
``tests/plant/node_client``); when it is missing the tests fail under CI and skip elsewhere.
"""

from __future__ import annotations

import contextlib
import json
import os
import queue
import shutil
import socket
import subprocess
import threading
import time
from pathlib import Path
from typing import Any

import pytest

CLIENT_DIR = Path(__file__).parent / "node_client"
PREFIX = "@@ "


def require_node_opcua() -> None:
    missing = ""
    if shutil.which("node") is None:
        missing = "node is not installed"
    elif not (CLIENT_DIR / "node_modules" / "node-opcua-client").is_dir():
        missing = "node-opcua-client is not installed (run scripts/ensure-env.sh dev)"
    if missing:
        if os.environ.get("CI"):
            pytest.fail(f"node-opcua peer missing under CI: {missing}")
        pytest.skip(missing)


def free_port() -> int:
    """A loopback port nobody listens on now (never the standard 4840)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class NodeClient:
    def __init__(self, endpoint: str, pki: Path) -> None:
        options = json.dumps({"endpoint": endpoint, "pki": str(pki)})
        self.process = subprocess.Popen(
            ["node", str(CLIENT_DIR / "client.js"), options],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
            text=True,
            cwd=CLIENT_DIR,
        )
        self._replies: queue.Queue[dict[str, Any]] = queue.Queue()
        self.notifications: list[dict[str, Any]] = []
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            if not line.startswith(PREFIX):
                continue  # node-opcua's own warnings
            message = json.loads(line[len(PREFIX) :])
            if "reply" in message:
                self._replies.put(message)
            else:
                self.notifications.append(message)

    def ask(self, op: str, timeout_s: float = 90.0, **fields: Any) -> dict[str, Any]:
        assert self.process.stdin is not None
        self.process.stdin.write(json.dumps({"op": op, **fields}) + "\n")
        self.process.stdin.flush()
        try:
            return self._replies.get(timeout=timeout_s)
        except queue.Empty:
            raise AssertionError(f"node-opcua gave no answer to {op} in {timeout_s} s") from None

    def close(self) -> None:
        if self.process.poll() is None:
            with contextlib.suppress(AssertionError, BrokenPipeError, OSError):
                self.ask("quit", timeout_s=10.0)
            try:
                self.process.wait(5.0)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(5.0)
        for stream in (self.process.stdin, self.process.stdout):
            if stream is not None:
                stream.close()
        self._reader.join(5.0)


def wait_until(predicate, timeout_s: float, step_s: float = 0.05) -> bool:  # type: ignore[no-untyped-def]
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(step_s)
    return bool(predicate())
