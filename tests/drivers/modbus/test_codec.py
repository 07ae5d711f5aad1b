"""Register codec, checked against pymodbus' own converter (an independent implementation)."""

from __future__ import annotations

import pytest
from pymodbus.client import ModbusTcpClient

from app.drivers.modbus.codec import EncodeError, decode, encode
from app.drivers.modbus.settings import DataType, WordOrder

DT = ModbusTcpClient.DATATYPE
PYMODBUS_TYPE = {
    DataType.INT16: DT.INT16,
    DataType.UINT16: DT.UINT16,
    DataType.INT32: DT.INT32,
    DataType.UINT32: DT.UINT32,
    DataType.FLOAT32: DT.FLOAT32,
}
VALUES = {
    DataType.INT16: [0, 1, -1, 32767, -32768],
    DataType.UINT16: [0, 1, 0x8000, 0xFFFF],
    DataType.INT32: [0, 1, -1, 123456789, -123456789, 2**31 - 1, -(2**31)],
    DataType.UINT32: [0, 70000, 2**32 - 1],
    DataType.FLOAT32: [0.0, 1.5, -1234.25, 3.0e8],
}


@pytest.mark.parametrize("order", list(WordOrder))
@pytest.mark.parametrize("data_type", list(DataType))
def test_round_trip_matches_pymodbus(data_type: DataType, order: WordOrder) -> None:
    for value in VALUES[data_type]:
        registers = encode(value, data_type, order)
        assert registers == ModbusTcpClient.convert_to_registers(
            value, PYMODBUS_TYPE[data_type], word_order=order.value
        )
        assert decode(registers, data_type, order) == value
        assert decode(registers, data_type, order) == ModbusTcpClient.convert_from_registers(
            registers, PYMODBUS_TYPE[data_type], word_order=order.value
        )


def test_word_order_on_the_wire() -> None:
    # 0x00012345 = 74565: big = high word first (Modicon), little = low word first.
    assert encode(74565, DataType.INT32, WordOrder.BIG) == [0x0001, 0x2345]
    assert encode(74565, DataType.INT32, WordOrder.LITTLE) == [0x2345, 0x0001]
    assert encode(-2, DataType.INT32, WordOrder.BIG) == [0xFFFF, 0xFFFE]


def test_positions_are_rounded_to_counts_and_must_fit() -> None:
    assert encode(10.6, DataType.INT32, WordOrder.BIG) == encode(11, DataType.INT32, WordOrder.BIG)
    with pytest.raises(EncodeError, match="does not fit int32"):
        encode(2.0**31, DataType.INT32, WordOrder.BIG)
    with pytest.raises(EncodeError, match="does not fit uint16"):
        encode(-1, DataType.UINT16, WordOrder.BIG)
    with pytest.raises(EncodeError, match="not a finite number"):
        encode(float("nan"), DataType.FLOAT32, WordOrder.BIG)
    with pytest.raises(ValueError, match="needs 2 registers"):
        decode([1], DataType.INT32, WordOrder.BIG)
