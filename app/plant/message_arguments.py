"""The Arguments of a woodworking event: WwMessageArgumentDataType, one per alarm argument.

OPC 40550-1 (7.13, 7.14) defines WwMessageArgumentDataType as a subtype of the standard
Argument structure (Name, DataType, ValueRank, ArrayDimensions, Description) with one field
more, Value, a WwMessageArgumentValueDataType union (Boolean, integers, Double, String, ...).
The jointer's alarm arguments (the axis, the value measured, its limit) become one each:
Name the argument's name, DataType and Value the value's type, Description its unit.

Why the definition is completed here: a StructureDefinition lists the fields of the
supertype before its own (OPC 10000-3, StructureDefinition; node-opcua skips that many
fields when it decodes), and the Woodworking NodeSet2 file's Definition of
WwMessageArgumentDataType lists only Value, although its own binary dictionary has all six.
Served as it is, asyncua would encode, and a client decode, a structure with Value alone.
So the served definition gets Argument's five fields in front, and asyncua's class is made
from that definition.
"""

from __future__ import annotations

from typing import Any

from asyncua import Server, ua
from asyncua.common.structures104 import make_structure

from app.machine.snapshot import AlarmArgument

ARGUMENT_TYPE_ID = 3003  # WwMessageArgumentDataType, i=3003 in the Woodworking namespace
ARGUMENT_TYPE = "WwMessageArgumentDataType"
VALUE_TYPE = "WwMessageArgumentValueDataType"

# OPC 10000-3 Argument: field name -> (data type, value rank)
_ARGUMENT_FIELDS: tuple[tuple[str, int, int], ...] = (
    ("Name", ua.ObjectIds.String, -1),
    ("DataType", ua.ObjectIds.NodeId, -1),
    ("ValueRank", ua.ObjectIds.Int32, -1),
    ("ArrayDimensions", ua.ObjectIds.UInt32, 1),
    ("Description", ua.ObjectIds.LocalizedText, -1),
)


def _field(name: str, type_id: int, value_rank: int) -> ua.StructureField:
    item = ua.StructureField()
    item.Name = name
    item.DataType = ua.NodeId(type_id)
    item.ValueRank = value_rank
    item.ArrayDimensions = [0] if value_rank == 1 else []
    item.IsOptional = False
    return item


async def complete_argument_type(server: Server, ww: int) -> type:
    """Serve WwMessageArgumentDataType's definition with Argument's fields (see above);
    returns the class made from it (asyncua keeps ``ua.WwMessageArgumentDataType`` bound
    to the first class, made from the NodeSet's definition; encoding goes by the class)."""
    node = server.get_node(ua.NodeId(ARGUMENT_TYPE_ID, ww))
    definition = await node.read_data_type_definition()
    own = [f for f in definition.Fields if f.Name not in {n for n, _, _ in _ARGUMENT_FIELDS}]
    definition.Fields = [*(_field(*spec) for spec in _ARGUMENT_FIELDS), *own]
    await node.write_attribute(
        ua.AttributeIds.DataTypeDefinition, ua.DataValue(ua.Variant(definition))
    )
    made: type = make_structure(node.nodeid, ARGUMENT_TYPE, definition)[ARGUMENT_TYPE]
    ua.register_extension_object(ARGUMENT_TYPE, definition.DefaultEncodingId, made, node.nodeid)
    union = getattr(ua, VALUE_TYPE)
    # The union's first member is an array of the union itself; asyncua records it as a bare
    # ``list`` and cannot make an encoder for that.
    union._union_types[0] = list.__class_getitem__(union)
    return made


def _typed(value: float | int | str) -> tuple[str, int]:
    """The union member and the data type for one value."""
    if isinstance(value, bool):
        return "Boolean", ua.ObjectIds.Boolean
    if isinstance(value, int):
        return "Int64", ua.ObjectIds.Int64
    if isinstance(value, float):
        return "Double", ua.ObjectIds.Double
    return "String", ua.ObjectIds.String


def message_arguments(arguments: tuple[AlarmArgument, ...], argument_type: type) -> list[Any]:
    """The event's Arguments field, of the class ``complete_argument_type`` made."""
    made = []
    for argument in arguments:
        member, type_id = _typed(argument.value)
        value = getattr(ua, VALUE_TYPE)()
        setattr(value, member, argument.value)
        made.append(
            argument_type(
                Name=argument.name,
                DataType=ua.NodeId(type_id),
                ValueRank=-1,
                ArrayDimensions=[],
                Description=ua.LocalizedText(
                    argument.unit or None, "en" if argument.unit else None
                ),
                Value=value,
            )
        )
    return made
