"""Writing files so that a crash never leaves half of one, and nobody else can read them.

An export or a backup is written to a temporary file beside the target, flushed to disk, and
renamed over the target in one step (``os.replace`` is atomic on the same filesystem): a reader
sees the old file or the new one, never a truncated mix.

The temporary file is created exclusively (``O_CREAT | O_EXCL | O_NOFOLLOW``) under a random
name: a name planted in advance (a symbolic link to some other file, in a shared folder) makes
the creation fail instead of writing through the link. Files are created 0600 and the database
folder 0700: PIN hashes, recipes and counts belong to the machine's user account alone.
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Iterator
from pathlib import Path
from typing import BinaryIO

PRIVATE_FILE_MODE = 0o600
"""Database, journal, backups and exports: readable and writable by the owner only."""
PRIVATE_DIR_MODE = 0o700
"""The database folder."""

_CREATE_FLAGS = (
    os.O_WRONLY
    | os.O_CREAT
    | os.O_EXCL
    | getattr(os, "O_NOFOLLOW", 0)
    | getattr(os, "O_CLOEXEC", 0)
)
_ATTEMPTS = 100


def create_private_file(path: Path) -> int:
    """Create ``path`` exclusively (never through a link), mode 0600; returns the descriptor."""
    return os.open(path, _CREATE_FLAGS, PRIVATE_FILE_MODE)


def create_temporary_sibling(path: Path) -> tuple[Path, int]:
    """A new, empty, private file beside ``path`` (same filesystem: the rename is atomic).

    The name is random (``.<name>.<hex>.partial``), so it cannot be predicted and planted.
    """
    for _ in range(_ATTEMPTS):
        candidate = path.with_name(f".{path.name}.{secrets.token_hex(8)}.partial")
        try:
            return candidate, create_private_file(candidate)
        except FileExistsError:
            continue
    raise FileExistsError(f"{path.parent}: no free temporary name beside {path.name}")


def ensure_private_directory(directory: Path) -> None:
    """Create ``directory`` (and parents) as 0700; an existing one is left as the owner set it."""
    if directory.is_dir():
        return
    directory.mkdir(mode=PRIVATE_DIR_MODE, parents=True, exist_ok=True)
    with contextlib.suppress(OSError):
        os.chmod(directory, PRIVATE_DIR_MODE)


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


@contextlib.contextmanager
def atomic_replacement(path: Path) -> Iterator[BinaryIO]:
    """Write ``path`` through a private temporary sibling renamed over it at the end.

    If the block raises, the temporary file is removed and ``path`` is untouched.
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    partial, fd = create_temporary_sibling(path)
    try:
        with os.fdopen(fd, "wb") as stream:
            yield stream
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(partial, path)
    except BaseException:
        partial.unlink(missing_ok=True)
        raise
    fsync_directory(path.parent)


def atomic_write_text(path: Path, text: str, encoding: str = "utf-8") -> None:
    """Replace ``path`` with ``text`` all at once (created with its parent directories, 0600)."""
    with atomic_replacement(path) as stream:
        stream.write(text.encode(encoding))
