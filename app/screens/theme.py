"""The dark, high-contrast industrial theme, scaled to the panel.

Why scaling: the same screens run on a 1024x768 panel and on 1920x1080. Sizes in the QSS
template are tokens (``$fs_normal``, ``$button_h``, ...) substituted here for a scale factor
derived from the window size, so fonts stay readable at arm's length and buttons stay
finger-sized on both, without a second stylesheet to keep in step.
"""

from __future__ import annotations

from functools import cache
from string import Template

from PySide6.QtGui import QColor, QFont, QPalette
from PySide6.QtWidgets import QApplication, QWidget

from app.resources import resource_path

BASE_WIDTH_PX = 1024
BASE_HEIGHT_PX = 768
MAX_SCALE = 1.45

# The smallest thing a finger is asked to hit, in px at scale 1.0 (about 12 mm on a 12"
# 1024x768 panel). Buttons, list and table rows that open something, and the alarm banner are
# at least this high and wide; the button sizes below are content heights, to which the theme
# adds 2 x 4 px padding and 2 x 2 px border (a list row: 2 x 4 px padding and a 1 px line).
TOUCH_PX = 60

# Sizes in px at scale 1.0 (a 1024x768 panel).
_SIZES_PX: dict[str, float] = {
    "fs_small": 14,
    "fs_normal": 17,
    "fs_button": 18,
    "fs_big": 22,
    "fs_huge": 28,
    "fs_key": 26,
    "fs_position": 36,
    "button_h": 50,
    "button_w": 60,
    "big_button_h": 76,
    "nav_h": 48,
    "key_h": 54,
    "key_w": 74,
    "smallkey_w": 56,
    "jog_h": 78,
    "row_h": 51,
    "touch": TOUCH_PX,
    "bar_h": 48,
    "recipe_h": 60,
    "arrow_w": 56,
    "banner_h": 52,
    "scroll_w": 40,
    "progress_h": 24,
    "radius": 6,
}

BACKGROUND = "#0e1116"
PANEL = "#171c23"
TEXT = "#f2f4f8"
DIM_TEXT = "#aab4c3"
ACCENT = "#ffb000"
GREEN = "#3cd066"
RED = "#ff4040"
YELLOW = "#ffc21a"
BLUE = "#5aa0ff"
GREY = "#6c7685"


def scale_for_size(width_px: int, height_px: int) -> float:
    """The theme scale for a window of that size: 1.0 at 1024x768, larger on bigger panels
    (never smaller: below 1024x768 the layout scrolls rather than shrinking the text)."""
    scale = min(width_px / BASE_WIDTH_PX, height_px / BASE_HEIGHT_PX)
    return round(max(1.0, min(MAX_SCALE, scale)), 2)


@cache
def _template() -> Template:
    return Template(resource_path("theme", "stave.qss").read_text(encoding="utf-8"))


def scaled_px(name: str, scale: float) -> int:
    """One theme size in whole pixels at ``scale``."""
    return round(_SIZES_PX[name] * scale)


@cache
def stylesheet(scale: float = 1.0) -> str:
    """The theme's QSS with every size token replaced for ``scale``."""
    values = {name: f"{scaled_px(name, scale)}px" for name in _SIZES_PX}
    return _template().substitute(values)


def apply_palette(app: QApplication) -> None:
    """Fusion style with a dark palette, so widgets the stylesheet does not cover match."""
    app.setStyle("Fusion")
    palette = QPalette()
    roles = {
        QPalette.ColorRole.Window: BACKGROUND,
        QPalette.ColorRole.WindowText: TEXT,
        QPalette.ColorRole.Base: "#05070a",
        QPalette.ColorRole.AlternateBase: PANEL,
        QPalette.ColorRole.Text: TEXT,
        QPalette.ColorRole.Button: "#2a323e",
        QPalette.ColorRole.ButtonText: TEXT,
        QPalette.ColorRole.Highlight: ACCENT,
        QPalette.ColorRole.HighlightedText: BACKGROUND,
        QPalette.ColorRole.ToolTipBase: TEXT,
        QPalette.ColorRole.ToolTipText: BACKGROUND,
        QPalette.ColorRole.PlaceholderText: DIM_TEXT,
    }
    for role, colour in roles.items():
        palette.setColor(role, QColor(colour))
    app.setPalette(palette)
    font = QFont("DejaVu Sans")
    font.setPixelSize(round(_SIZES_PX["fs_normal"]))
    app.setFont(font)


def set_style_property(widget: QWidget, name: str, value: str) -> None:
    """Set a dynamic property the stylesheet selects on, re-polishing only when it changed
    (re-polishing is what makes Qt apply the new rule, and it is not free at 30 Hz)."""
    if widget.property(name) == value:
        return
    widget.setProperty(name, value)
    style = widget.style()
    style.unpolish(widget)
    style.polish(widget)
