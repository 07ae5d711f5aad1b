"""The ``[gauge.serial]`` table.

Why the line format is configuration: every gauge maker has its own ASCII protocol
("W=123.45\\r\\n", "+0123.4 mm", "  12.345 in"), and a technician must be able to adapt
to it from the gauge's manual. A regular expression with a named group ``width`` says where
the number is; ``unit_scale`` turns the gauge's unit into mm; ``terminator`` ends a line.
TOML basic strings take the escapes (``"\\r\\n"``) directly.
"""

from __future__ import annotations

import enum
import re
from collections.abc import Mapping
from dataclasses import dataclass

from app.config import ConfigError, MachineConfig, Section

DEFAULT_PATTERN = r"^\s*(?:W\s*[=:]?\s*)?(?P<width>[-+]?\d+(?:\.\d*)?)\s*(?:mm)?\s*$"


class GaugeMode(enum.Enum):
    REQUEST = "request"  # the gauge answers one line per request string
    STREAM = "stream"  # the gauge sends lines on its own, continuously


@dataclass(frozen=True)
class SerialGaugeSettings:
    port: str
    baudrate: int
    bytesize: int
    parity: str
    stopbits: int
    mode: GaugeMode
    request: bytes
    terminator: bytes
    pattern: re.Pattern[str]
    unit_scale: float  # mm per gauge unit
    min_width_mm: float
    max_width_mm: float
    reply_timeout_s: float  # request mode: for the reply; stream mode: between two lines
    max_line_bytes: int
    encoding: str = "ascii"


def _encode(section: Section, name: str, text: str) -> bytes:
    try:
        return text.encode("ascii")
    except UnicodeEncodeError:
        raise section.error(
            name, text, "ASCII characters (escapes such as \\r, \\n, \\u0002 are fine)"
        ) from None


def parse_serial_gauge_settings(raw: object, config: MachineConfig) -> SerialGaugeSettings:
    """Check ``[gauge.serial]``; raises ConfigError naming the ``gauge.serial.*`` key."""
    path = "gauge.serial"
    if not isinstance(raw, Mapping):
        raise ConfigError(path, raw, "a table", config.source)
    s = Section(raw, path, config.source)
    port = s.text("port", "")
    if not port.strip():
        raise s.error("port", port, "a serial device such as /dev/ttyUSB0")
    baudrate = s.integer("baudrate", 9600, 300, 4_000_000)
    bytesize = s.integer("bytesize", 8, 7, 8)
    parity = s.text("parity", "N", ("N", "E", "O"))
    stopbits = s.integer("stopbits", 1, 1, 2)
    mode = GaugeMode(s.text("mode", "request", tuple(m.value for m in GaugeMode)))
    request = _encode(s, "request", s.text("request", "?\r\n"))
    if mode is GaugeMode.REQUEST and not request:
        raise s.error("request", "", 'a non-empty string for mode = "request"')
    terminator = _encode(s, "terminator", s.text("terminator", "\r\n"))
    if not terminator:
        raise s.error("terminator", "", 'a non-empty string such as "\\r\\n"')
    pattern_text = s.text("pattern", DEFAULT_PATTERN)
    try:
        pattern = re.compile(pattern_text)
    except re.error as exc:
        raise s.error("pattern", pattern_text, f"a valid regular expression ({exc})") from None
    if "width" not in pattern.groupindex:
        raise s.error(
            "pattern",
            pattern_text,
            "a regular expression with a named group (?P<width>...) around the number",
        )
    unit_scale = s.number("unit_scale", 1.0, 0.0, 1e6, exclusive_minimum=True)
    min_mm = s.number("min_width_mm", 30.0, 0.0, 10_000.0)
    max_mm = s.number("max_width_mm", 300.0, 0.0, 10_000.0)
    if max_mm <= min_mm:
        raise s.error("max_width_mm", max_mm, f"greater than min_width_mm ({min_mm:g})")
    timeout_s = s.number("reply_timeout_ms", 500.0, 1.0, 60_000.0) / 1000.0
    max_line = s.integer("max_line_bytes", 128, 8, 65536)
    s.finish()
    return SerialGaugeSettings(
        port.strip(),
        baudrate,
        bytesize,
        parity,
        stopbits,
        mode,
        request,
        terminator,
        pattern,
        unit_scale,
        min_mm,
        max_mm,
        timeout_s,
        max_line,
    )
