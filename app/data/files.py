"""Writing files so that a crash never leaves half of one.

An export or a backup is written to a temporary file beside the target, flushed to disk, and
renamed over the target in one step (``os.replace`` is atomic on the same filesystem): a reader
sees the old file or the new one, never a truncated mix.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path


def temporary_sibling(path: Path) -> Path:
    """A name in the same directory (same filesystem, so the final rename is atomic)."""
    return path.with_name(f".{path.name}.{os.getpid()}.partial")


def fsync_directory(directory: Path) -> None:
    """Make a rename in ``directory`` durable (a no-op where directories cannot be opened)."""
    try:
        fd = os.open(directory, os.O_RDONLY)
    except OSError:
        return
    try:
        with contextlib.suppress(OSError):
            os.fsync(fd)
    finally:
        os.close(fd)


def atomic_write_text(path: Path, text: str, encoding: str = "utf-8") -> None:
    """Replace ``path`` with ``text`` all at once (created with its parent directories)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    partial = temporary_sibling(path)
    try:
        with partial.open("w", encoding=encoding, newline="") as stream:
            stream.write(text)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(partial, path)
    except BaseException:
        partial.unlink(missing_ok=True)
        raise
    fsync_directory(path.parent)
