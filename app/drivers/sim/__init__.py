"""The simulated machine: a faithful stand-in for the hardware, on a simulated clock.

Recipe preparation in the office, training, the demo and nearly every test run on this
backend, so it behaves like the real machine, including when things go wrong:

- :mod:`.world` (:class:`SimWorld`): everything physical, integrated in fixed substeps of at
  most 1 ms; operator actions (buttons, E-stop, guard, boards).
- :mod:`.drive` (:class:`SimDrive`): a CiA 402 drive in cyclic synchronous position mode with
  a PI position loop, velocity feed-forward, current limit, switches, homing and fault codes.
- :mod:`.cia402`: the standard's tables (commands, transitions, statusword, EMCY codes).
- :mod:`.io`: cylinders with end sensors, spindle contactor, buttons, E-stop chain, lamps.
- :mod:`.backend`: ``create_backend(config)``, the MotionBackend and DigitalIO adapters.
- :mod:`.gauge`: ``create_gauge(config, backend)``, the width gauge.
- :mod:`.faults`: the fault injector (``extras["faults"]``).
- :mod:`.settings`: the ``[backend.sim]`` and ``[gauge.sim]`` options.

Nothing here reads the wall clock or sleeps: the machine loop advances the world by one
period per period in real time, and tests advance it as fast as they like.
"""
