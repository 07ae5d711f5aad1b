"""The serial width gauge (RS-232/RS-485 or USB-serial, read with pyserial).

- :mod:`.settings`: the ``[gauge.serial]`` table, checked.
- :mod:`.lines`: line framing and parsing, pure (partial lines, garbage, range).
- :mod:`.gauge`: :class:`WidthGauge` on a serial port; ``create_gauge`` for the registry.
"""
