"""Values to and from 16-bit Modbus registers.

Why our own few lines instead of pymodbus' ``convert_*_registers``: the conversion is part of
the register map (a drive's manual says "int32, low word first"), not of the transport, and
pymodbus' helpers have changed name and signature between releases. Bytes inside a register
are big-endian (Modbus defines that); only the order of the two words of a 32-bit value
varies between makers, and :class:`WordOrder` says which.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Sequence

from app.drivers.modbus.settings import DataType, Field, WordOrder

_STRUCT: dict[DataType, str] = {
    DataType.INT16: ">h",
    DataType.UINT16: ">H",
    DataType.INT32: ">i",
    DataType.UINT32: ">I",
    DataType.FLOAT32: ">f",
}

_RANGE: dict[DataType, tuple[int, int]] = {
    DataType.INT16: (-(2**15), 2**15 - 1),
    DataType.UINT16: (0, 2**16 - 1),
    DataType.INT32: (-(2**31), 2**31 - 1),
    DataType.UINT32: (0, 2**32 - 1),
}


class EncodeError(ValueError):
    """A value that does not fit its register type (for example a target beyond int32)."""


def decode(registers: Sequence[int], data_type: DataType, word_order: WordOrder) -> float:
    """The value held by ``registers`` (exactly ``data_type.registers`` of them)."""
    words = list(registers)
    if len(words) != data_type.registers:
        raise ValueError(
            f"{data_type.value} needs {data_type.registers} registers, got {len(words)}"
        )
    if word_order is WordOrder.LITTLE:
        words.reverse()
    raw = b"".join(w.to_bytes(2, "big") for w in words)
    value: float = struct.unpack(_STRUCT[data_type], raw)[0]
    return value


def encode(value: float, data_type: DataType, word_order: WordOrder) -> list[int]:
    """Registers holding ``value``; integers are rounded to the nearest count and must fit."""
    if data_type is DataType.FLOAT32:
        if not math.isfinite(value):
            raise EncodeError(f"{value!r} is not a finite number")
        raw = struct.pack(">f", value)
    else:
        if not math.isfinite(value):
            raise EncodeError(f"{value!r} is not a finite number")
        number = round(value)
        low, high = _RANGE[data_type]
        if not low <= number <= high:
            raise EncodeError(f"{number} does not fit {data_type.value} ({low} to {high})")
        raw = struct.pack(_STRUCT[data_type], number)
    words = [int.from_bytes(raw[i : i + 2], "big") for i in range(0, len(raw), 2)]
    if word_order is WordOrder.LITTLE:
        words.reverse()
    return words


def field_value(
    block: Sequence[int], block_start: int, field: Field, word_order: WordOrder
) -> float:
    """Decode ``field`` out of a block read from ``block_start``."""
    offset = field.address - block_start
    return decode(block[offset : offset + field.data_type.registers], field.data_type, word_order)


def put_field(
    block: list[int], block_start: int, field: Field, value: float, word_order: WordOrder
) -> None:
    """Encode ``value`` into ``block`` (a block written from ``block_start``) in place."""
    offset = field.address - block_start
    block[offset : offset + field.data_type.registers] = encode(value, field.data_type, word_order)


def bits_of(word: int, bit: int) -> bool:
    return bool(word >> bit & 1)
