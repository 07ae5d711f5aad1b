"""Where the command-line tools take a PIN from: ``$STAVE_PIN``, a prompt, or standard input.

Never from an argument: the arguments of every process are visible to every local user
(``ps``, ``/proc/PID/cmdline``), and a PIN in them also ends up in the shell's history.
"""

from __future__ import annotations

import getpass
import os
import sys

PIN_ENV = "STAVE_PIN"
NEW_PIN_ENV = "STAVE_NEW_PIN"


class PinMissing(Exception):
    """No PIN given (one line: where it may come from)."""


def read_pin(purpose: str, env: str = PIN_ENV, prompt: str = "PIN: ") -> str:
    """The PIN for ``purpose`` ("importing needs ... a technician"), from the environment
    variable ``env``, a prompt on a terminal, or the next line of standard input."""
    from_env = os.environ.get(env, "").strip()
    if from_env:
        return from_env
    try:
        if sys.stdin is not None and sys.stdin.isatty():
            typed = getpass.getpass(prompt)
        else:
            typed = sys.stdin.readline() if sys.stdin is not None else ""
    except (OSError, EOFError, KeyboardInterrupt):
        typed = ""
    pin = typed.strip()
    if not pin:
        raise PinMissing(
            f"pin: {purpose}; type it at the prompt, or give it in ${env} or on standard input"
        )
    return pin
