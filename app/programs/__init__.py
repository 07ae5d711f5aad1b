"""Programs for other controllers: the stave's tool path as G-code (LinuxCNC, SINUMERIK), as
one parametric LinuxCNC program for every board of a recipe, and as a DXF drawing.

Why a package of its own, pure like the geometry: the writers take a finished tool path (the
one the machine cuts) and turn it into text or a drawing; they decide nothing about the cut,
so a program can never disagree with the machine. Only `app.geometry` is imported here.
"""
