"""The words of the recipe rules as an operator reads them: English templates with ``%1``,
``%2``... for the arguments, and no program identifiers.

Why beside the ``message``: a ``FieldError``'s message names the field as the program and the
files do (``width_ratio = 1 ...``), which a command line and an import report keep; a screen
shows the error under the field it belongs to, in the user's language, so it translates the
template (the screens list these texts for translation) and fills in the arguments.
"""

from __future__ import annotations

from enum import Enum


class RuleText(Enum):
    """One template per rule a recipe can break."""

    NOT_A_NUMBER = "%1 is not a number"
    BETWEEN = "%1 is outside the allowed range: %2 to %3 %4"
    OPTIONAL_BETWEEN = "%1 is outside the allowed range: empty, or %2 to %3 %4"
    LENGTH_RATIO = "%1 is not allowed: from 0 to below 1/2 (at 1/2 or more no arc is left)"
    WIDTH_RATIO_ONE = "%1 leaves nothing to cut (the head as wide as the belly): allowed below 1"
    WIDTH_RATIO_RANGE = "%1 is not allowed: above 0 and below 1"
    WIDTH_RATIO_NARROW = (
        "%1 makes the head narrower than %2 mm even on a board of %3 mm: allowed %4 to below 1"
    )
    TILT_FITS_NO_BARREL = (
        "%1° fits no barrel of %2 to %3 mm for the boards of this recipe: allowed %4 to %5°"
    )
    NAME_EMPTY = "The name is empty: allowed 1 to %1 characters"
    NAME_LENGTH = "The name must have 1 to %1 characters, with no space at its start or end"
    NAME_CONTROL = "The name contains a control character"
    NOT_TEXT = "%1 is not a text"
    NOTE_LONG = "The note has %1 characters: allowed at most %2"
    SHORT_AXIS_BETWEEN = "%1 mm is not allowed: the short axis is %2 mm up to the long axis, %3 mm"
    SHORT_AXIS_FIXED = (
        "%1 mm has no use with a fixed tilt: leave the short axis empty, or choose an oval barrel"
    )
    SHORT_AXIS_ROUND = (
        "%1 mm has no use with a round barrel: leave the short axis empty, or choose an oval barrel"
    )
    SHORT_AXIS_MISSING = "An oval barrel needs its short axis"
    DIAMETER_MISSING = "A round or oval barrel needs its belly diameter: allowed %1 to %2 mm"
    BARREL_TYPE = "%1 is not a barrel type: allowed fixed tilt, round or oval"
    TARGET_HEAD = "%1 mm would make the head %2 mm wide: allowed %3 mm or more"
    BARREL_FITS_NO_BOARD = (
        "%1 mm fits no board of this recipe: boards of %2 to %3 mm need a tilt of %4 to %5°"
    )
    BOARD_WIDTH = "A board of %1 mm is outside the widths this machine takes: up to %2 mm"
    HEAD_NARROW = "The head would be %1 mm wide: allowed %2 mm or more"
    TOP_FACE = (
        "At %1° the bevels of a %2 mm thick stave meet before the top face at the %3 mm wide "
        "heads: allowed below %4°"
    )
    BOARD_BARREL = (
        "At %1° a board of %2 mm belongs to a barrel of %3 mm, outside %4 to %5 mm: "
        "allowed %6 to %7°"
    )
    BOARD_NO_TILT = "No tilt fits a board of %1 mm: no barrel of %2 to %3 mm has such staves"
    BOARD_BELOW_TARGET = "A board of %1 mm is narrower than the stave it should become, %2 mm"
    BOARD_WIDER_THAN_BARREL = "A board of %1 mm does not fit a barrel of %2 mm"
    BARREL_TILT = "The barrel gives a board of %1 mm a tilt of %2°: allowed %3 to %4°"
    TRAVEL = "The tool path reaches %1 = %2 %3, beyond the axis travel %4 to %5 %3"
    DRAWING_MISSING = "A drawn profile needs a drawing: import a DXF file"
    DRAWING_FILE = "The drawing's file is not recorded: import the DXF file again"
    PROFILE_NO_DRAWING = "Only a drawn side profile keeps a drawing"
    PROFILE_NO_PARAMETERS = "This side profile has no parameters"
    PROFILE_UNKNOWN_PARAMETER = "This side profile has no such parameter"
