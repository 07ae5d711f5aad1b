"""Jogging from the machine's own controls: the handwheel (MPG), the joystick and USB
pendants, beside the screen jog, with one arbitration between them."""
