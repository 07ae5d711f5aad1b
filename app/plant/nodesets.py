"""Where the OPC Foundation's NodeSet2 files are, and the order they load in.

Why not in the repository: they are the OPC Foundation's files (MIT), published in the npm
package ``node-opcua-nodesets``; ``scripts/fetch-nodesets.sh`` fetches that package at a pinned
version at install time into ``.venv/share/opcua-nodesets`` (the Debian package carries them in
``/opt/stave-jointer/nodesets``). Woodworking 1.02 builds on DI, Machinery (which needs IA),
ISA-95 job control and Machinery Jobs; each file must come after the ones it requires.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

NODESETS_PACKAGE = "node-opcua-nodesets"
NODESETS_VERSION = "2.185.0"

LOAD_ORDER: tuple[str, ...] = (
    "Opc.Ua.Di.NodeSet2.xml",
    "Opc.Ua.IA.NodeSet2.xml",
    "Opc.Ua.Machinery.NodeSet2.xml",
    "opc.ua.isa95-jobcontrol.nodeset2.xml",
    "Opc.Ua.Machinery.Jobs.Nodeset2.xml",
    "Opc.Ua.Woodworking.NodeSet2.xml",
)

DI_URI = "http://opcfoundation.org/UA/DI/"
MACHINERY_URI = "http://opcfoundation.org/UA/Machinery/"
WOODWORKING_URI = "http://opcfoundation.org/UA/Woodworking/"


class NodesetsMissing(RuntimeError):
    pass


def default_nodesets_dir() -> Path:
    """``$STAVE_OPCUA_NODESETS``, else ``share/opcua-nodesets`` of the running environment."""
    override = os.environ.get("STAVE_OPCUA_NODESETS")
    if override:
        return Path(override)
    return Path(sys.prefix) / "share" / "opcua-nodesets"


def nodeset_files(folder: Path | None = None) -> list[Path]:
    """The files in load order; NodesetsMissing names the folder and how to fetch them."""
    base = folder if folder is not None else default_nodesets_dir()
    files = [base / name for name in LOAD_ORDER]
    missing = [f.name for f in files if not f.is_file()]
    if missing:
        raise NodesetsMissing(
            f"opcua.nodesets_dir = {str(base)!r} is not usable: {missing[0]} is missing "
            f"(scripts/fetch-nodesets.sh fetches {NODESETS_PACKAGE}@{NODESETS_VERSION})"
        )
    return files
