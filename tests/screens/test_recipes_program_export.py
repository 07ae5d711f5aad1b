"""Recipes screen: the selected recipe's program or drawing, written through the touch file
chooser, is exactly what ``stave gcode`` writes for the same width and parameters."""

from __future__ import annotations

import ezdxf

from app.machine.program_export import ExportFormat, export_text
from app.screens.widgets.dialogs import ChoiceOverlay, MessageOverlay
from app.screens.widgets.file_chooser import FileChooser
from tests.screens.helpers import find_button
from tests.screens.test_recipes_screen import open_recipes


def _choose(window, tap, index: int) -> None:
    choice = window.overlay()
    assert isinstance(choice, ChoiceOverlay)
    tap(find_button(choice, f"choice_{index}"))


def _without_stamp(text: str) -> str:
    return "\n".join(line for line in text.splitlines() if "written 20" not in line)


def test_program_drawing_and_parametric_through_the_file_chooser(
    qtbot, window, database, tap, tmp_path
) -> None:
    screen = open_recipes(window, tap)
    recipe = database.list_recipes()[0]
    screen.select_recipe(recipe.id)
    screen.set_preview_width(150.0)
    tmp_path = tmp_path / "stick"
    tmp_path.mkdir()
    tap(find_button(window, "exportProgram"))
    assert isinstance(window.overlay(), ChoiceOverlay)
    tap(find_button(window.overlay(), "cancelButton"))
    assert window.overlay() is None

    for index, export_format in enumerate(ExportFormat):
        screen.export_program(tmp_path)
        _choose(window, tap, index)
        chooser = window.overlay()
        assert isinstance(chooser, FileChooser)
        tap(find_button(chooser, "okButton"))
        assert window.overlay() is None
        (written,) = tmp_path.glob(f"*{'parametric' if export_format.parametric else '150mm'}"
                                   f"{export_format.suffix}")  # fmt: skip
        expected = export_text(recipe, export_format, 150.0, screen.parameters, screen.limits)
        if export_format is ExportFormat.DXF:
            doc = ezdxf.readfile(written)
            assert len(doc.modelspace().query('ARC[layer=="OUTLINE"]')) == 2
        else:
            assert _without_stamp(written.read_text(encoding="utf-8")) == _without_stamp(expected)
        written.unlink()


def test_refused_width_and_unsaved_changes_are_explained(qtbot, window, database, tap, tmp_path):
    screen = open_recipes(window, tap)
    recipe = database.list_recipes()[0]
    screen.select_recipe(recipe.id)
    screen.set_preview_width(40.0)  # the heads would be narrower than 60 mm
    out = tmp_path / "out"
    out.mkdir()
    screen.export_program(out)
    _choose(window, tap, 0)
    message = window.overlay()
    assert isinstance(message, MessageOverlay)
    assert "head_width_mm = 32 is out of range" in message.message_label.text()
    tap(find_button(message, "okButton"))
    assert list(out.iterdir()) == []

    screen.set_field("thickness_mm", 33.0)
    assert screen.dirty
    screen.export_program(out)
    assert isinstance(window.overlay(), MessageOverlay)
