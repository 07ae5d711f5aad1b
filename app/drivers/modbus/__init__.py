"""The Modbus backend: servo drives (CiA 402 over Modbus registers) and a remote I/O coupler,
over Modbus TCP or Modbus RTU.

Module map, one job each:

- :mod:`.settings`: the ``[backend.modbus]`` table, checked, with the default register map.
- :mod:`.codec`: 16/32-bit integers and floats to and from registers, in either word order.
- :mod:`.link`: the only module that touches pymodbus' client; one connection each.
- :mod:`.bus`: the trade's error handling (retry timeouts and busy replies only, count
  consecutive failures, declare the link lost) over every link of the backend.
- :mod:`.cia402`: the controlword a drive gets each period (enable walk, fault-reset edge,
  homing start edge), pure logic.
- :mod:`.device`: the lifecycle the drives and the coupler share on the bus.
- :mod:`.drives` / :mod:`.coupler`: the contracts (:class:`MotionBackend`,
  :class:`DigitalIO`) on top of the bus.
- :mod:`.rtu_timing`: what period Modbus RTU can hold for a given register map and line.
- :mod:`.backend`: ``create_backend(config)`` for the registry.
- :mod:`.emulation` / :mod:`.emulator`: register-level drives and coupler served by a
  pymodbus server, for the tests and for commissioning demos without hardware.
"""
