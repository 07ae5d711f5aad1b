"""Exported programs run through LinuxCNC's own interpreter and compared with the product's
tool path: every cutting move within 0.001 mm of it (chord programs: within the chord error
asked for, with the fewest chords), the same tilt on each side, the same feed; the parametric
program at five widths per recipe, and its refusal of the widths the product refuses."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from app.data.recipe import Recipe
from app.geometry.errors import GeometryError
from app.geometry.segments import ArcSegment, LineSegment, Segment
from app.geometry.toolpath import ToolPath
from app.machine.program_export import (
    ExportOptions,
    export_program,
    parametric_stave,
    program_info,
    stave_toolpath,
)
from tests.programs.conftest import LIMITS, PARAMS
from tests.programs.rs274 import CanonicalMove, interpret, rs274_path, without_standstill

TOLERANCE_MM = 0.001
PRINTED_MM = 0.0001  # rs274 prints 4 decimals, the program holds 4: rounding on top of a bound
FEED_MM_MIN = PARAMS["xy_speed_mm_s"] * 60.0


@pytest.fixture(scope="module", autouse=True)
def _interpreter() -> None:
    rs274_path()


def _run(tmp_path: Path, text: str, name: str = "stave.ngc") -> list[CanonicalMove]:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    result = interpret(path)
    assert result.returncode == 0, result.stderr
    assert "PROGRAM_END" in result.calls
    return without_standstill(result.moves, (0.0, 0.0, 0.0))


def _samples(move: CanonicalMove, start: tuple[float, float], count: int = 16):
    """Points along the canonical move (its own geometry, as the interpreter defines it)."""
    if move.center is None:
        for n in range(count + 1):
            f = n / count
            yield (start[0] + (move.x - start[0]) * f, start[1] + (move.y - start[1]) * f)
        return
    cx, cy = move.center
    a0 = math.atan2(start[1] - cy, start[0] - cx)
    a1 = math.atan2(move.y - cy, move.x - cx)
    sweep = a1 - a0
    if move.rotation < 0 and sweep > 0:
        sweep -= 2 * math.pi
    if move.rotation > 0 and sweep < 0:
        sweep += 2 * math.pi
    radius = math.hypot(start[0] - cx, start[1] - cy)
    for n in range(count + 1):
        angle = a0 + sweep * n / count
        yield (cx + radius * math.cos(angle), cy + radius * math.sin(angle))


def _check_segment(segment: Segment, move: CanonicalMove, start: tuple[float, float]) -> None:
    assert math.hypot(move.x - segment.end[0], move.y - segment.end[1]) <= TOLERANCE_MM
    assert move.a == pytest.approx(segment.z_end_deg, abs=TOLERANCE_MM)
    if not segment.cutting:
        assert move.call == "STRAIGHT_TRAVERSE"
        return
    assert move.feed_mm_min == pytest.approx(FEED_MM_MIN)
    if isinstance(segment, ArcSegment):
        assert move.call == "ARC_FEED"
        assert move.rotation == (-1 if segment.clockwise else 1)
        assert move.center is not None
        assert math.dist(move.center, segment.center) <= TOLERANCE_MM
    else:
        assert move.call == "STRAIGHT_FEED"
    for point in _samples(move, start):
        assert segment.distance_to(point) <= TOLERANCE_MM


def fewest_chords(arc: ArcSegment, chord_error_mm: float) -> int:
    """The smallest number of equal chords whose sagitta stays within the bound."""
    n = 1
    while 2 * arc.radius_mm * math.sin(arc.sweep_rad / (4 * n)) ** 2 > chord_error_mm:
        n += 1
    return n


def compare(toolpath: ToolPath, moves: list[CanonicalMove], chords_mm: float | None) -> None:
    """The canonical moves are the tool path: one per segment (or the chords of an arc)."""
    home = toolpath.segments[0].start
    position = (0.0, 0.0)
    queue = list(moves)
    if home != (0.0, 0.0) or toolpath.segments[0].z_start_deg != 0.0:
        first = queue.pop(0)
        assert first.call == "STRAIGHT_TRAVERSE"
        assert math.hypot(first.x - home[0], first.y - home[1]) <= TOLERANCE_MM
        position = (first.x, first.y)
    for segment in toolpath.segments:
        if chords_mm is not None and isinstance(segment, ArcSegment):
            count = fewest_chords(segment, chords_mm)
            for _ in range(count):
                chord = queue.pop(0)
                assert chord.call == "STRAIGHT_FEED"
                assert chord.a == pytest.approx(segment.z_end_deg, abs=TOLERANCE_MM)
                assert chord.feed_mm_min == pytest.approx(FEED_MM_MIN)
                end = (chord.x, chord.y)
                middle = ((position[0] + end[0]) / 2, (position[1] + end[1]) / 2)
                assert segment.distance_to(end) <= PRINTED_MM
                assert segment.distance_to(middle) <= chords_mm + PRINTED_MM
                position = end
            assert math.dist(position, segment.end) <= PRINTED_MM
            continue
        move = queue.pop(0)
        _check_segment(segment, move, position)
        position = (move.x, move.y)
    assert queue == []
    tilts = {side: {s.z_end_deg for s in toolpath.side_segments(side)} for side in ("A", "B")}
    cut = [m for m in moves if m.call != "STRAIGHT_TRAVERSE"]
    assert {round(m.a, 4) for m in cut} == {round(t, 4) for side in tilts.values() for t in side}


def _widths(recipe: Recipe) -> list[float]:
    stave = parametric_stave(recipe, PARAMS, LIMITS)
    low, high = stave.width_min_mm, stave.width_max_mm
    return [low, low + (high - low) * 0.3, (low + high) / 2, low + (high - low) * 0.8, high]


def test_fixed_programs_are_the_tool_path(recipe: Recipe, tmp_path: Path) -> None:
    for width in _widths(recipe)[1::2]:
        toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
        text = export_program(recipe, width, PARAMS, LIMITS, ExportOptions())
        compare(toolpath, _run(tmp_path, text), None)


@pytest.mark.parametrize("chords_mm", [0.001, 0.05, 1.0])
def test_chord_programs_keep_the_chord_error_with_the_fewest_chords(
    recipe: Recipe, chords_mm: float, tmp_path: Path
) -> None:
    width = _widths(recipe)[2]
    toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
    text = export_program(recipe, width, PARAMS, LIMITS, ExportOptions(chord_error_mm=chords_mm))
    compare(toolpath, _run(tmp_path, text), chords_mm)


def _with_width(program: str, width_mm: float) -> str:
    """The operator's edit: the parameter at the top set to this board's width."""
    lines = program.splitlines()
    (index,) = [i for i, line in enumerate(lines) if line.startswith("#<width> = ")]
    lines[index] = f"#<width> = {width_mm:.3f}"
    return "\n".join(lines) + "\n"


def test_parametric_program_matches_the_tool_path_at_five_widths(
    recipe: Recipe, tmp_path: Path
) -> None:
    program = export_program(recipe, None, PARAMS, LIMITS, ExportOptions())
    for number, exact_width in enumerate(_widths(recipe)):
        width = round(exact_width, 3)
        toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
        moves = _run(tmp_path, _with_width(program, width), f"width{number}.ngc")
        compare(toolpath, moves, None)


def test_parametric_program_aborts_where_the_product_refuses(
    recipe: Recipe, tmp_path: Path
) -> None:
    stave = parametric_stave(recipe, PARAMS, LIMITS)
    program = export_program(recipe, None, PARAMS, LIMITS, ExportOptions())
    for width in (stave.width_min_mm - 0.001, stave.width_max_mm + 0.001, 400.0, 10.0):
        if width <= LIMITS.max_width_mm:  # wider boards do not exist for the product at all
            with pytest.raises(GeometryError):
                stave_toolpath(recipe, width, PARAMS, LIMITS)
        path = tmp_path / "refused.ngc"
        path.write_text(_with_width(program, width), encoding="utf-8")
        result = interpret(path)
        assert result.returncode != 0
        assert "width outside what this recipe accepts" in result.stderr
        assert not [m for m in result.moves if m.call != "STRAIGHT_TRAVERSE"]
        assert "START_SPINDLE_CLOCKWISE" not in result.calls


def test_a_wrong_arc_is_an_interpreter_error(tmp_path: Path) -> None:
    """The judge can fail: a centre that does not fit both ends is refused."""
    path = tmp_path / "bad.ngc"
    path.write_text("G21 G17 G90 F100\nG0 X0 Y0\nG2 X10 Y0 I3 J1\nM2\n", encoding="utf-8")
    result = interpret(path)
    assert result.returncode != 0
    assert "ARC_FEED" not in result.calls


def test_comparison_catches_a_moved_point(tmp_path: Path) -> None:
    """The comparison can fail: one cutting point moved by 2 um is found."""
    from app.data.recipe import recipe_from_mapping

    recipe = recipe_from_mapping(
        {"name": "r", "length_mm": 1000, "thickness_mm": 27, "length_ratio": "1/4",
         "width_ratio": "3/4", "tilt_deg": 4}
    )  # fmt: skip
    toolpath = stave_toolpath(recipe, 150.0, PARAMS, LIMITS)
    text = export_program(recipe, 150.0, PARAMS, LIMITS, ExportOptions())
    moves = _run(tmp_path, text)
    index = next(i for i, m in enumerate(moves) if m.call == "STRAIGHT_FEED")
    bad = moves[index]
    moves[index] = CanonicalMove(bad.call, bad.x, bad.y + 0.002, bad.a, bad.feed_mm_min)
    with pytest.raises(AssertionError):
        compare(toolpath, moves, None)
    assert isinstance(toolpath.segments[1], LineSegment)


@pytest.mark.parametrize(
    ("home", "corners"),
    [((500.0, 780.0), 1), ((1400.0, 400.0), 2)],
    ids=["home above the board", "home level with the board, beyond it"],
)
def test_travel_around_the_board_from_other_home_positions(
    home: tuple[float, float], corners: int, tmp_path: Path
) -> None:
    """The routes round the keep-out box (one corner over the board's side, or two round its
    end) come out of the parametric program's own routing as they do out of the product's."""
    from tests.programs.conftest import RECIPES

    params = {**PARAMS, "home_x_mm": home[0], "home_y_mm": home[1]}
    for recipe in (RECIPES[0], RECIPES[1]):
        program = export_program(recipe, None, params, LIMITS, ExportOptions())
        for width in (130.0, 200.0):
            toolpath = stave_toolpath(recipe, width, params, LIMITS)
            approach = [s for s in toolpath.segments[:4] if not s.cutting]
            assert len(approach) == corners + 1  # the product's own route has the corners
            fixed = export_program(recipe, width, params, LIMITS, ExportOptions())
            compare(toolpath, _run(tmp_path, fixed), None)
            compare(toolpath, _run(tmp_path, _with_width(program, width), "p.ngc"), None)


def test_single_arc_recipe_has_the_parametric_program_of_length_ratio_0(tmp_path: Path) -> None:
    """A single-arc recipe is line-arc-line without straight sections whatever length ratio the
    recipe holds: its parametric program cuts the one arc at five widths, as the product does."""
    from dataclasses import replace

    from app.data.recipe_profile import RecipeProfile
    from app.geometry.profile_kinds import ProfileKind
    from tests.programs.conftest import RECIPES

    recipe = replace(RECIPES[2], profile=RecipeProfile(ProfileKind.SINGLE_ARC))
    assert recipe.length_ratio.value > 0  # kept in the recipe, not used by the single arc
    program = export_program(recipe, None, PARAMS, LIMITS, ExportOptions())
    assert "#<_length_ratio> = 0.0" in program.splitlines()
    for number, exact_width in enumerate(_widths(recipe)):
        width = round(exact_width, 3)
        toolpath = stave_toolpath(recipe, width, PARAMS, LIMITS)
        assert sum(s.cutting and isinstance(s, ArcSegment) for s in toolpath.segments) == 2
        compare(toolpath, _run(tmp_path, _with_width(program, width), f"w{number}.ngc"), None)


@pytest.mark.parametrize("kind", ["parabola", "ellipse", "superellipse"])
def test_curved_profiles_as_fixed_programs_and_no_parametric(kind: str, tmp_path: Path) -> None:
    """Other side profiles are chains of fitted arcs: the fixed program is still exactly the
    tool path (G2/G3 and chords); the parametric program, which solves the line-arc-line
    cubic itself, is refused with the reason."""
    from dataclasses import replace

    from app.data.recipe_profile import RecipeProfile
    from app.geometry.profile_kinds import ProfileKind, default_parameters
    from tests.programs.conftest import RECIPES

    profile_kind = ProfileKind(kind)
    profile = RecipeProfile(profile_kind, tuple(default_parameters(profile_kind).items()))
    recipe = replace(RECIPES[2], profile=profile, length_ratio=RECIPES[0].length_ratio)
    toolpath = stave_toolpath(recipe, 180.0, PARAMS, LIMITS)
    compare(toolpath, _run(tmp_path, export_program(recipe, 180.0, PARAMS, LIMITS,
                                                    ExportOptions())), None)  # fmt: skip
    chords = export_program(recipe, 180.0, PARAMS, LIMITS, ExportOptions(chord_error_mm=0.02))
    compare(toolpath, _run(tmp_path, chords, "chords.ngc"), 0.02)
    with pytest.raises(GeometryError, match=f"profile_kind = '{kind}' has no parametric program"):
        export_program(recipe, None, PARAMS, LIMITS, ExportOptions())


def test_drawn_profile_with_concave_dips_as_g2_and_g3(tmp_path: Path) -> None:
    """A drawn side that turns both ways (two concave dips): its counter-clockwise arcs are G3
    moves, and rs274's path is the tool path, fixed and in chords; no parametric program."""

    from tests.programs.conftest import curved_recipes

    recipe = curved_recipes()[1]
    toolpath = stave_toolpath(recipe, 150.0, PARAMS, LIMITS)
    moves = _run(tmp_path, export_program(recipe, 150.0, PARAMS, LIMITS, ExportOptions()))
    assert {m.rotation for m in moves if m.call == "ARC_FEED"} == {-1, 1}
    compare(toolpath, moves, None)
    chords = export_program(recipe, 150.0, PARAMS, LIMITS, ExportOptions(chord_error_mm=0.01))
    compare(toolpath, _run(tmp_path, chords, "chords.ngc"), 0.01)
    with pytest.raises(GeometryError, match="profile_kind = 'drawn' has no parametric program"):
        export_program(recipe, None, PARAMS, LIMITS, ExportOptions())


def test_two_bevels_each_side_its_own_tilt_offset_and_pivot_shift(tmp_path: Path) -> None:
    """Side A at +alpha_A, side B at -alpha_B (a barrel whose joints differ): the fixed and the
    parametric programs follow the tool path of both bevels."""
    from dataclasses import replace
    from datetime import UTC, datetime

    from app.geometry.profile import solve_profile
    from app.geometry.toolpath import ToolPathParams, build_toolpath
    from app.programs import linuxcnc
    from app.programs.moves import stave_moves
    from app.programs.parametric import write_parametric_program
    from tests.programs.conftest import RECIPES

    recipe = RECIPES[2]
    info = program_info(recipe, None, PARAMS, ExportOptions(), datetime(2026, 1, 1, tzinfo=UTC))
    stave = replace(parametric_stave(recipe, PARAMS, LIMITS), tilt_a_deg=9.5, tilt_b_deg=6.0)
    program = write_parametric_program(stave, info)
    for width in (120.0, 175.5, 240.0):
        profile = solve_profile(recipe.length_mm, width, 0.3, 0.6, LIMITS)
        params = ToolPathParams.from_parameters(PARAMS, 9.5, 6.0)
        toolpath = build_toolpath(profile, params)
        assert {round(s.z_end_deg, 6) for s in toolpath.side_segments("B")} == {-6.0}
        fixed = linuxcnc.write_program(stave_moves(toolpath), replace(info, width_mm=width))
        compare(toolpath, _run(tmp_path, fixed), None)
        compare(toolpath, _run(tmp_path, _with_width(program, width), "p.ngc"), None)


def test_offsets_the_control_held_do_not_move_the_program(tmp_path: Path) -> None:
    """A rotated G54 offset and a G92 offset left on the control: the program clears both
    before it moves (rs274 prints program coordinates and the offsets and rotation in force
    as calls of their own), so it runs in the jointer's machine coordinates."""
    from tests.programs.conftest import RECIPES

    toolpath = stave_toolpath(RECIPES[1], 150.0, PARAMS, LIMITS)
    lines = export_program(RECIPES[1], 150.0, PARAMS, LIMITS, ExportOptions()).splitlines()
    prelude = ["G10 L2 P1 R30 X100 Y-50 A5", "G54", "G0 X0 Y0", "G92 X10 Y10 A1"]
    path = tmp_path / "offsets.ngc"
    path.write_text("\n".join([lines[0], *prelude, *lines[1:]]) + "\n", encoding="utf-8")
    result = interpret(path)
    assert result.returncode == 0, result.stderr
    motion = [i for i, name in enumerate(result.calls) if name == "STRAIGHT_TRAVERSE"]
    in_force: dict[str, str] = {}
    for name, arguments in zip(
        result.calls[: motion[1]], result.arguments[: motion[1]], strict=True
    ):
        in_force[name] = arguments
    assert in_force["SET_XY_ROTATION"] == "0.0000"
    for offset in ("SET_G5X_OFFSET", "SET_G92_OFFSET"):
        assert {float(v) for v in in_force[offset].split(",")[-6:]} == {0.0}
    moves = without_standstill(result.moves, (0.0, 0.0, 0.0))
    compare(toolpath, moves[2:], None)  # after the prelude's move and the move home
