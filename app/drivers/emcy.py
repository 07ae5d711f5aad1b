"""Text of CiA 301 and CiA 402 emergency error codes, for alarms an operator can read; the
one table for every backend (a CANopen EMCY, the error code 0x603F a Modbus drive maps, the
simulated drives).

Why a table of our own: canopen's ``EmcyError.get_desc()`` knows only the dozen classes
("Current", "Monitoring"); an operator needs "DC link over-voltage" or "Following error".
A code not in the table falls back to its class (the code with its low nibble, then its low
byte, then its low 12 bits cleared), so every code gets some text. Manufacturer-specific
codes (0xFF00-0xFFFF) mean what the drive's manual says: a caller that knows the drive passes
its texts as ``vendor``.
"""

from __future__ import annotations

from collections.abc import Mapping

EMCY_TEXTS: dict[int, str] = {
    0x0000: "Error reset or no error",
    0x1000: "Generic error",
    0x2000: "Current",
    0x2100: "Current, device input side",
    0x2110: "Short circuit or earth leakage, input side",
    0x2120: "Earth leakage, input side",
    0x2200: "Current inside the device",
    0x2300: "Current, device output side",
    0x2310: "Continuous over-current",
    0x2320: "Short circuit or earth leakage, motor side",
    0x2330: "Earth leakage, motor side",
    0x3000: "Voltage",
    0x3100: "Mains voltage",
    0x3110: "Mains over-voltage",
    0x3120: "Mains under-voltage",
    0x3130: "Mains phase failure",
    0x3200: "DC link voltage",
    0x3210: "DC link over-voltage",
    0x3220: "DC link under-voltage",
    0x3300: "Output voltage",
    0x4000: "Temperature",
    0x4100: "Ambient temperature",
    0x4200: "Device temperature",
    0x4210: "Excess temperature, device",
    0x4300: "Drive temperature",
    0x4310: "Excess temperature, drive",
    0x5000: "Device hardware",
    0x5100: "Supply",
    0x5200: "Control",
    0x5300: "Operating unit",
    0x5400: "Power section",
    0x5410: "Output stages",
    0x5500: "Data storage",
    0x6000: "Device software",
    0x6100: "Internal software",
    0x6200: "User software",
    0x6300: "Data set",
    0x6320: "Parameter error",
    0x7000: "Additional modules",
    0x7100: "Power",
    0x7110: "Brake chopper",
    0x7120: "Motor",
    0x7121: "Motor blocked",
    0x7122: "Motor error or commutation malfunction",
    0x7300: "Sensor",
    0x7305: "Incremental sensor 1 fault",
    0x7310: "Speed sensor",
    0x7320: "Position sensor",
    0x7500: "Communication",
    0x8000: "Monitoring",
    0x8100: "Communication",
    0x8110: "CAN overrun (objects lost)",
    0x8120: "CAN in error passive mode",
    0x8130: "Life guard or heartbeat error",
    0x8140: "Recovered from bus off",
    0x8150: "CAN-ID collision",
    0x8200: "Protocol error",
    0x8210: "PDO not processed due to length error",
    0x8220: "PDO length exceeded",
    0x8250: "RPDO timeout",
    0x8300: "Torque control",
    0x8311: "Excess torque",
    0x8400: "Velocity speed controller",
    0x8500: "Position controller",
    0x8600: "Positioning controller",
    0x8611: "Following error",
    0x8612: "Reference limit",
    0x8700: "Sync controller",
    0x8800: "Winding controller",
    0x9000: "External error",
    0xF000: "Additional functions",
    0xFF00: "Device specific",
}


def emcy_text(code: int, vendor: Mapping[int, str] | None = None) -> str:
    """The operator text of an emergency error code (never empty); ``vendor``: the drive
    manufacturer's texts of its own codes, looked up first."""
    if vendor is not None and code in vendor:
        return vendor[code]
    for mask in (0xFFFF, 0xFFF0, 0xFF00, 0xF000):
        text = EMCY_TEXTS.get(code & mask)
        if text is not None:
            if mask != 0xFFFF and code & mask != code:
                return f"{text} (code 0x{code:04X})"
            return text
    return f"Unknown error (code 0x{code:04X})"
