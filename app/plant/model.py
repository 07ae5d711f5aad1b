"""The address space: the OPC Foundation's models, and one WwMachineType under Machines.

Why instantiate the type and then remove: asyncua instantiates a type with all its optional
children; a plant client must not find variables that never change (a jointer has no air
pressure, no dust suction flag and no sub-units), so the optional nodes the jointer does not
serve are deleted, and everything left has a value.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, field
from pathlib import Path

from asyncua import Node, Server, ua
from asyncua.common.manage_nodes import delete_nodes

from app import __version__
from app.plant.nodesets import MACHINERY_URI, WOODWORKING_URI, nodeset_files
from app.plant.settings import OpcuaSettings
from app.plant.state_map import OFFLINE_FLAGS
from app.plant.state_times import VALUE_NAMES as STATE_TIME_NAMES

OWN_URI = "urn:stave-jointer:opcua"
MACHINE_BROWSE_NAME = "StaveJointer"
WW_MACHINE_TYPE_ID = 2  # WwMachineType, i=2 in the Woodworking namespace
WW_BASE_EVENT_TYPE_ID = 13  # WwBaseEventType

FLAG_NAMES = tuple(OFFLINE_FLAGS.as_browse_names())
VALUE_NAMES = (
    "AbsolutePiecesOut",
    "RelativePiecesOut",
    "AbsoluteRunsGood",
    "AbsoluteRunsAborted",
    "AbsoluteRunsTotal",
    "RelativeRunsGood",
    "RelativeRunsAborted",
    "RelativeRunsTotal",
    *STATE_TIME_NAMES,
    "ActualCycle",
    "AxisOverride",
    "FeedSpeed",
)
# Manufacturer-specific variables: browse name -> (variant type, initial value)
SPECIFIC: dict[str, tuple[ua.VariantType, object]] = {
    "SelectedRecipe": (ua.VariantType.String, ""),
    "LastWidth_mm": (ua.VariantType.Double, 0.0),
    "LastD_mm": (ua.VariantType.Double, 0.0),
    "LastR_mm": (ua.VariantType.Double, 0.0),
    "LastCycleTime_s": (ua.VariantType.Double, 0.0),
    "PiecesThisShift": (ua.VariantType.UInt64, 0),
    "ShiftProductionCsv": (ua.VariantType.String, ""),
    "PlantJob": (ua.VariantType.String, ""),
    "StateText": (ua.VariantType.String, ""),
    "BarrelNumber": (ua.VariantType.UInt32, 0),
    "BarrelStavesDone": (ua.VariantType.UInt32, 0),
    "BarrelStavesPlanned": (ua.VariantType.UInt32, 0),
    "BarrelGap_mm": (ua.VariantType.Double, 0.0),
    "BarrelClosed": (ua.VariantType.Boolean, False),
}


@dataclass
class MachineNodes:
    machine: Node
    events: Node
    specific: Node
    current_state: Node
    current_mode: Node
    flags: dict[str, Node] = field(default_factory=dict)
    values: dict[str, Node] = field(default_factory=dict)
    own: dict[str, Node] = field(default_factory=dict)
    ww: int = 0
    own_ns: int = 0


async def load_models(server: Server, folder: Path | None) -> None:
    """Import the NodeSet2 files. Their notes about nodes asyncua cannot represent (design-
    tool-only objects in DI, two job structures in Machinery Jobs) are not about anything the
    jointer serves; they are kept out of the log."""
    quiet = [
        logging.getLogger(n) for n in ("asyncua.common.xmlimporter", "asyncua.common.structures104")
    ]
    levels = [q.level for q in quiet]
    for q in quiet:
        q.setLevel(logging.CRITICAL)
    try:
        for path in nodeset_files(folder):
            await server.import_xml(str(path), strict_mode=False)
    finally:
        for q, level in zip(quiet, levels, strict=True):
            q.setLevel(level)


async def _subtree(node: Node) -> list[Node]:
    found = [node]
    for child in await node.get_children():
        found.extend(await _subtree(child))
    return found


async def _delete(server: Server, parent: Node, child: Node) -> None:
    """Delete ``child`` and everything below it. asyncua's own delete searches the whole
    address space for references to each node (minutes for the woodworking model); an
    instance's nodes are referenced only by their parent and each other, so the parent's
    references are all that must go."""
    doomed = await _subtree(child)
    await delete_nodes(server.iserver.isession, doomed, delete_target_references=False)
    gone = {n.nodeid for n in doomed}
    parent_data = server.iserver.aspace[parent.nodeid]
    parent_data.references[:] = [r for r in parent_data.references if r.NodeId not in gone]


async def _delete_unserved(server: Server, parent: Node, keep: set[str]) -> dict[str, Node]:
    kept: dict[str, Node] = {}
    for child in await parent.get_children():
        name = (await child.read_browse_name()).Name
        if name in keep:
            kept[name] = child
        else:
            await _delete(server, parent, child)
    return kept


async def build_machine(server: Server, settings: OpcuaSettings) -> MachineNodes:
    ww = await server.get_namespace_index(WOODWORKING_URI)
    machinery = await server.get_namespace_index(MACHINERY_URI)
    own = await server.register_namespace(OWN_URI)
    machines = await server.nodes.objects.get_child([f"{machinery}:Machines"])
    machine = await machines.add_object(
        ua.NodeId(MACHINE_BROWSE_NAME, own),
        ua.QualifiedName(MACHINE_BROWSE_NAME, own),
        objecttype=ua.NodeId(WW_MACHINE_TYPE_ID, ww),
        instantiate_optional=True,
    )
    # What the jointer does not have: sub-units, the job management of Machinery Jobs (the
    # jobs are the two methods below), and the building blocks' duplicates.
    for child in await machine.get_children():
        if (await child.read_browse_name()).Name in ("JobManagement", "MachineryBuildingBlocks"):
            await _delete(server, machine, child)
    state = await machine.get_child([f"{ww}:State"])
    for child in await state.get_children():
        if (await child.read_browse_name()).Name == "SubUnits":
            await _delete(server, state, child)
    unit = await state.get_child([f"{ww}:Machine"])
    overview = await unit.get_child([f"{ww}:Overview"])
    flags_node = await unit.get_child([f"{ww}:Flags"])
    values_node = await unit.get_child([f"{ww}:Values"])
    events = await machine.get_child([f"{ww}:Events"])
    specific = await machine.get_child([f"{ww}:ManufacturerSpecific"])
    nodes = MachineNodes(
        machine=machine,
        events=events,
        specific=specific,
        current_state=await overview.get_child([f"{ww}:CurrentState"]),
        current_mode=await overview.get_child([f"{ww}:CurrentMode"]),
        ww=ww,
        own_ns=own,
    )
    nodes.flags = await _delete_unserved(server, flags_node, set(FLAG_NAMES))
    nodes.values = await _delete_unserved(server, values_node, set(VALUE_NAMES))
    await _delete_unserved(server, specific, set())
    for name, (vtype, initial) in SPECIFIC.items():
        nodes.own[name] = await specific.add_variable(
            ua.NodeId(f"{MACHINE_BROWSE_NAME}.{name}", own),
            ua.QualifiedName(name, own),
            ua.Variant(initial, vtype),
        )
    await _write_identification(server, machine, settings)
    await events.write_attribute(
        ua.AttributeIds.EventNotifier,
        ua.DataValue(ua.Variant(1, ua.VariantType.Byte)),  # SubscribeToEvents
    )
    return nodes


async def _write_identification(server: Server, machine: Node, settings: OpcuaSettings) -> None:
    """From the configuration; the optional fields it has nothing for are removed."""
    identification = None
    for child in await machine.get_children():
        if (await child.read_browse_name()).Name == "Identification":
            identification = child
    if identification is None:
        return
    values: dict[str, ua.Variant] = {
        "Manufacturer": ua.Variant(ua.LocalizedText(settings.manufacturer, "en")),
        "Model": ua.Variant(ua.LocalizedText(settings.model, "en")),
        "SerialNumber": ua.Variant(settings.serial_number, ua.VariantType.String),
        "SoftwareRevision": ua.Variant(__version__, ua.VariantType.String),
        "YearOfConstruction": ua.Variant(settings.year_of_construction, ua.VariantType.UInt16),
        "Location": ua.Variant(settings.location, ua.VariantType.String),
        "ProductInstanceUri": ua.Variant(
            f"urn:stave-jointer:{settings.serial_number}", ua.VariantType.String
        ),
        "DeviceClass": ua.Variant("Stave jointer", ua.VariantType.String),
        "ComponentName": ua.Variant(ua.LocalizedText(settings.model, "en")),
    }
    for name, child in (await _delete_unserved(server, identification, set(values))).items():
        await child.write_value(values[name])
