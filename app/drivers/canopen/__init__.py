"""CANopen backend: CiA 402 servo drives and a CiA 401 digital I/O node over python-can.

The package is named after the protocol; every module in it imports the ``canopen`` library
with absolute imports (``import canopen``), which always resolve to the installed library,
never to this package. The entry point for the registry is
:func:`app.drivers.canopen.backend.create_backend`; importing this package alone imports
neither ``canopen`` nor ``can``.
"""
