"""The plant connection: an OPC UA server after OPC 40550-1 (woodworking machines).

Why a package of its own: a plant system (MES, SCADA) reads the jointer's state, counters and
alarms and may hand it jobs, but nothing from the network may move the machine or delay a
setpoint. So the server runs in its own process, fed by the machine's snapshots; it never
reaches into the machine loop, and the only command it can produce is a recipe selection
that takes effect while the machine is READY. Nothing here is imported by the machine layer.
"""
