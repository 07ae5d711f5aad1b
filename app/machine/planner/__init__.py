"""Trajectory planning: the whole stave along its exact tool path, point-to-point moves and
manual jog (see each module's docstring; ``chunk.py`` holds the limit math)."""
