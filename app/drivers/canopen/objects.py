"""Object numbers of CiA 301/402/401 the backend uses, and object dictionaries built in code.

Why in code and not an EDS file: canopen 2.4.1 ships no EDS, every drive vendor's EDS differs
in what it names and what it leaves out, and the backend only ever touches the handful of
standard objects listed here. The same builders give the simulated drives of the tests their
dictionary, and ``canopen.export_od(build_drive_od(1), "drive.eds")`` writes the EDS a
commissioning tool can show.
"""

from __future__ import annotations

from canopen.objectdictionary import (
    INTEGER8,
    INTEGER16,
    INTEGER32,
    UNSIGNED8,
    UNSIGNED16,
    UNSIGNED32,
    ObjectDictionary,
    ODArray,
    ODRecord,
    ODVariable,
)

# ---- CiA 301 communication profile -------------------------------------------------------
DEVICE_TYPE = 0x1000  # device type: low word = profile number (402 drive, 401 I/O)
ERROR_REGISTER = 0x1001  # error register
SYNC_COB_ID = 0x1005  # COB-ID SYNC
COMM_CYCLE_PERIOD = 0x1006  # communication cycle period, microseconds
CONSUMER_HEARTBEAT_TIME = 0x1016  # consumer heartbeat time: producer id << 16 | timeout ms
PRODUCER_HEARTBEAT_TIME = 0x1017  # producer heartbeat time, ms
RPDO_COMM = 0x1400  # RPDO communication parameter, +n for RPDO n+1
RPDO_MAPPING = 0x1600  # RPDO mapping parameter
TPDO_COMM = 0x1800  # TPDO communication parameter
TPDO_MAPPING = 0x1A00  # TPDO mapping parameter

PROFILE_DRIVE = 402
PROFILE_IO = 401

# ---- CiA 402 drive profile ----------------------------------------------------------------
ERROR_CODE = 0x603F  # error code of the last fault
CONTROLWORD = 0x6040  # controlword
STATUSWORD = 0x6041  # statusword
MODES_OF_OPERATION = 0x6060  # modes of operation
MODES_DISPLAY = 0x6061  # modes of operation display
POSITION_ACTUAL = 0x6064  # position actual value, increments
FOLLOWING_ERROR_WINDOW = 0x6065  # following error window, increments
TARGET_POSITION = 0x607A  # target position, increments
HOME_OFFSET = 0x607C  # home offset, increments
HOMING_METHOD = 0x6098  # homing method
HOMING_SPEEDS = 0x6099  # homing speeds: 1 search for switch, 2 search for zero
HOMING_ACCELERATION = 0x609A  # homing acceleration
INTERPOLATION_TIME_PERIOD = 0x60C2  # 1 value, 2 index: period = value * 10^index s
DIGITAL_INPUTS = 0x60FD  # digital inputs: bit 0 neg. limit, 1 pos. limit, 2 home switch
SUPPORTED_DRIVE_MODES = 0x6502  # supported drive modes (bit 5 homing, bit 7 CSP)

SUPPORTED_HOMING_BIT = 1 << 5
SUPPORTED_CSP_BIT = 1 << 7

DI_NEGATIVE_LIMIT = 1 << 0
DI_POSITIVE_LIMIT = 1 << 1
DI_HOME_SWITCH = 1 << 2


# ---- CiA 401 generic I/O profile ------------------------------------------------------------
READ_INPUT_8BIT = 0x6000  # digital inputs, 8 per sub-index
READ_ANALOG_INPUT_16BIT = 0x6401  # analog inputs (and a counter module's count), one per sub
ANALOG_INPUTS = 4  # the builder's I/O node has four of them
WRITE_OUTPUT_8BIT = 0x6200  # digital outputs, 8 per sub-index
IO_BYTES = 4  # the builder's I/O node has 32 inputs and 32 outputs

PDO_SLOTS = 4  # PDO 1..4 of the pre-defined connection set


def _var(
    name: str,
    index: int,
    subindex: int,
    data_type: int,
    access: str,
    default: int = 0,
    *,
    mappable: bool = False,
) -> ODVariable:
    var = ODVariable(name, index, subindex)
    var.data_type = data_type
    var.access_type = access
    var.default = default
    var.pdo_mappable = mappable
    return var


def _record(
    od: ObjectDictionary,
    name: str,
    index: int,
    members: list[ODVariable],
    sub0: ODVariable | None = None,
) -> None:
    record = ODRecord(name, index)
    record.add_member(
        sub0
        or _var(
            "Highest sub-index supported",
            index,
            0,
            UNSIGNED8,
            "const",
            max(m.subindex for m in members),
        )
    )
    for member in members:
        record.add_member(member)
    od.add_object(record)


def _array(
    od: ObjectDictionary,
    name: str,
    index: int,
    count: int,
    data_type: int,
    access: str,
    *,
    mappable: bool = False,
) -> None:
    array = ODArray(name, index)
    array.add_member(_var("Highest sub-index supported", index, 0, UNSIGNED8, "const", count))
    for sub in range(1, count + 1):
        array.add_member(_var(f"{name} {sub}", index, sub, data_type, access, mappable=mappable))
    od.add_object(array)


def _add(od: ObjectDictionary, var: ODVariable) -> None:
    od.add_object(var)


def _communication_objects(od: ObjectDictionary, node_id: int, device_type: int) -> None:
    _add(od, _var("Device type", DEVICE_TYPE, 0, UNSIGNED32, "ro", device_type))
    _add(od, _var("Error register", ERROR_REGISTER, 0, UNSIGNED8, "ro", mappable=True))
    _add(od, _var("COB-ID SYNC", SYNC_COB_ID, 0, UNSIGNED32, "rw", 0x80))
    _add(od, _var("Communication cycle period", COMM_CYCLE_PERIOD, 0, UNSIGNED32, "rw"))
    _add(od, _var("Producer heartbeat time", PRODUCER_HEARTBEAT_TIME, 0, UNSIGNED16, "rw"))
    for n in range(PDO_SLOTS):
        rx_cob = (0x200 + 0x100 * n + node_id) | (1 << 31)  # pre-defined, not valid
        tx_cob = (0x180 + 0x100 * n + node_id) | (1 << 31)
        _record(
            od,
            f"RPDO {n + 1} communication parameter",
            RPDO_COMM + n,
            [
                _var("COB-ID used by RPDO", RPDO_COMM + n, 1, UNSIGNED32, "rw", rx_cob),
                _var("Transmission type", RPDO_COMM + n, 2, UNSIGNED8, "rw", 255),
            ],
        )
        _record(
            od,
            f"RPDO {n + 1} mapping parameter",
            RPDO_MAPPING + n,
            [
                _var(f"Mapped object {s}", RPDO_MAPPING + n, s, UNSIGNED32, "rw")
                for s in range(1, 9)
            ],
            _var("Number of mapped objects", RPDO_MAPPING + n, 0, UNSIGNED8, "rw"),
        )
        _record(
            od,
            f"TPDO {n + 1} communication parameter",
            TPDO_COMM + n,
            [
                _var("COB-ID used by TPDO", TPDO_COMM + n, 1, UNSIGNED32, "rw", tx_cob),
                _var("Transmission type", TPDO_COMM + n, 2, UNSIGNED8, "rw", 255),
                _var("Inhibit time", TPDO_COMM + n, 3, UNSIGNED16, "rw"),
                _var("Event timer", TPDO_COMM + n, 5, UNSIGNED16, "rw"),
            ],
        )
        _record(
            od,
            f"TPDO {n + 1} mapping parameter",
            TPDO_MAPPING + n,
            [
                _var(f"Mapped object {s}", TPDO_MAPPING + n, s, UNSIGNED32, "rw")
                for s in range(1, 9)
            ],
            _var("Number of mapped objects", TPDO_MAPPING + n, 0, UNSIGNED8, "rw"),
        )


def build_drive_od(node_id: int) -> ObjectDictionary:
    """The CiA 402 objects of one servo drive, as the backend expects them."""
    od = ObjectDictionary()  # type: ignore[no-untyped-call]
    od.node_id = node_id
    _communication_objects(od, node_id, 0x00020000 | PROFILE_DRIVE)  # servo drive, 402
    # sub 1 watches the controller's heartbeat (master_heartbeat.py)
    _array(od, "Consumer heartbeat time", CONSUMER_HEARTBEAT_TIME, 1, UNSIGNED32, "rw")
    _add(od, _var("Error code", ERROR_CODE, 0, UNSIGNED16, "ro", mappable=True))
    _add(od, _var("Controlword", CONTROLWORD, 0, UNSIGNED16, "rw", mappable=True))
    _add(od, _var("Statusword", STATUSWORD, 0, UNSIGNED16, "ro", mappable=True))
    _add(od, _var("Modes of operation", MODES_OF_OPERATION, 0, INTEGER8, "rw", mappable=True))
    _add(od, _var("Modes of operation display", MODES_DISPLAY, 0, INTEGER8, "ro", mappable=True))
    _add(od, _var("Position actual value", POSITION_ACTUAL, 0, INTEGER32, "ro", mappable=True))
    _add(
        od, _var("Following error window", FOLLOWING_ERROR_WINDOW, 0, UNSIGNED32, "rw", 0xFFFFFFFF)
    )
    _add(od, _var("Target position", TARGET_POSITION, 0, INTEGER32, "rw", mappable=True))
    _add(od, _var("Home offset", HOME_OFFSET, 0, INTEGER32, "rw"))
    _add(od, _var("Homing method", HOMING_METHOD, 0, INTEGER8, "rw"))
    _array(od, "Homing speeds", HOMING_SPEEDS, 2, UNSIGNED32, "rw")
    _add(od, _var("Homing acceleration", HOMING_ACCELERATION, 0, UNSIGNED32, "rw"))
    _record(
        od,
        "Interpolation time period",
        INTERPOLATION_TIME_PERIOD,
        [
            _var(
                "Interpolation time period value", INTERPOLATION_TIME_PERIOD, 1, UNSIGNED8, "rw", 1
            ),
            _var("Interpolation time index", INTERPOLATION_TIME_PERIOD, 2, INTEGER8, "rw", -3),
        ],
    )
    _add(od, _var("Digital inputs", DIGITAL_INPUTS, 0, UNSIGNED32, "ro", mappable=True))
    _add(
        od,
        _var(
            "Supported drive modes",
            SUPPORTED_DRIVE_MODES,
            0,
            UNSIGNED32,
            "ro",
            SUPPORTED_CSP_BIT | SUPPORTED_HOMING_BIT,
        ),
    )
    return od


def build_io_od(node_id: int) -> ObjectDictionary:
    """The CiA 401 objects of an I/O node with 32 digital inputs, 32 outputs and four
    16-bit analog inputs."""
    od = ObjectDictionary()  # type: ignore[no-untyped-call]
    od.node_id = node_id
    _communication_objects(od, node_id, 0x00030000 | PROFILE_IO)  # digital in + out, 401
    _array(od, "Read input 8-bit", READ_INPUT_8BIT, IO_BYTES, UNSIGNED8, "ro", mappable=True)
    _array(od, "Write output 8-bit", WRITE_OUTPUT_8BIT, IO_BYTES, UNSIGNED8, "rw", mappable=True)
    _array(
        od,
        "Read analog input 16-bit",
        READ_ANALOG_INPUT_16BIT,
        ANALOG_INPUTS,
        INTEGER16,
        "ro",
        mappable=True,
    )
    return od
