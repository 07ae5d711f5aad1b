"""Where the shipped resources (theme, translations, default configuration, sample recipes)
live: ``resources/`` beside the package in a source checkout or an editable install, or the
directory named by ``STAVE_RESOURCES`` (set by the Debian package)."""

from __future__ import annotations

import os
from pathlib import Path


def resources_dir() -> Path:
    override = os.environ.get("STAVE_RESOURCES")
    if override:
        return Path(override)
    return Path(__file__).resolve().parent.parent / "resources"


def resource_path(*parts: str) -> Path:
    return resources_dir().joinpath(*parts)
