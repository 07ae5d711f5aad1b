"""``stave simulate --barrel``: an oval barrel raised on the simulated machine until it closes,
every stave at the bevels of its place, the closing stave cut to the gap in several passes."""

from __future__ import annotations

import csv
import json
import math
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.cli import main
from app.data.barrel_records import BarrelState
from app.data.database import Database
from app.data.recipe import BarrelType
from app.geometry.barrel_section import BarrelSection, plan_barrel
from app.resources import resource_path

OVAL_RECIPE = {
    "name": "Oval 320 x 280",
    "length_mm": 900,
    "thickness_mm": 27,
    "length_ratio": "1/4",
    "width_ratio": "3/4",
    "tilt_mode": "barrel",
    "tilt_deg": 8,
    "barrel_diameter_mm": 320,
    "barrel_minor_diameter_mm": 280,
}
WIDTHS = [100.0] * 8 + [250.0]  # eight staves, then a wide board for the closing stave


@pytest.fixture
def files(tmp_path: Path) -> tuple[Path, Path]:
    """The recipe, and the machine with a tilt axis reaching 30 deg (a small oval's bevels)."""
    recipe = tmp_path / "oval.json"
    recipe.write_text(json.dumps(OVAL_RECIPE), encoding="utf-8")
    text = resource_path("machine.toml").read_text(encoding="utf-8")
    z_axis = text.index("[axes.Z]")
    head, tail = text[:z_axis], text[z_axis:]
    tail = tail.replace("min_position = -15.0", "min_position = -30.0", 1)
    tail = tail.replace("max_position = 15.0", "max_position = 30.0", 1)
    config = tmp_path / "machine.toml"
    config.write_text(head + tail, encoding="utf-8")
    return recipe, config


def test_an_oval_barrel_closes_every_stave_at_its_own_bevels(capsys, files, tmp_path) -> None:
    recipe, config = files
    trace, db_path = tmp_path / "trace.csv", tmp_path / "simulation.db"
    widths = ",".join(f"{w:g}" for w in WIDTHS)
    code = main(
        ["simulate", "--recipe-file", str(recipe), "--config", str(config), "--barrel",
         "--widths", widths, "--json", "--trace", str(trace), "--db", str(db_path)]
    )  # fmt: skip
    out, err = capsys.readouterr()
    assert code == 0, err
    result = json.loads(out)
    assert result["barrel_closed"] is True and result["barrel_staves"] == 9
    assert result["closing_gap_mm"] == pytest.approx(0.0, abs=0.01)
    cycles = result["cycles"]
    assert [c["result"] for c in cycles] == ["ok"] * 9
    assert [c["barrel_stave_number"] for c in cycles] == list(range(1, 10))
    # The bevels follow the widths the gauge measured (the simulated gauge has its noise).
    measured = [c["measured_width_mm"] for c in cycles[:8]]
    assert measured == pytest.approx(WIDTHS[:8], abs=0.5)
    expected = plan_barrel(BarrelSection(160.0, 140.0), measured)
    for cycle, stave in zip(cycles, expected.staves, strict=False):
        assert cycle["tilt_a_deg"] == pytest.approx(stave.bevel_start_deg, abs=1e-7)
        assert cycle["tilt_b_deg"] == pytest.approx(stave.bevel_end_deg, abs=1e-7)
        assert cycle["target_width_mm"] is None and cycle["passes"] == 1
    closing, last = expected.closing, cycles[-1]
    assert closing is not None
    assert last["target_width_mm"] == pytest.approx(closing.width_mm, abs=1e-6)
    assert last["tilt_a_deg"] == pytest.approx(closing.bevel_start_deg, abs=1e-6)
    assert last["tilt_b_deg"] == pytest.approx(closing.bevel_end_deg, abs=1e-6)
    depth = (250.0 - 0.75 * closing.width_mm) / 2.0  # at the heads, per side
    assert last["passes"] == math.ceil(depth / 40.0) == 2  # the default depth of cut, 40 mm
    assert last["cycle_time_s"] > 1.5 * cycles[0]["cycle_time_s"]  # the extra passes cost time
    # The database keeps the barrel, its staves as cut, and each board's barrel and stave.
    with Database.open(db_path) as db:
        (barrel,) = db.list_barrels()
        assert barrel.state is BarrelState.CLOSED and barrel.barrel_type is BarrelType.OVAL
        staves = db.barrel_staves(barrel.number)
        pieces = {p.id: p for p in db.list_production(barrel.started_at, datetime.now(UTC))}
    assert [s.closing for s in staves] == [False] * 8 + [True]
    for cycle, stave in zip(cycles, staves, strict=True):
        assert (stave.bevel_a_deg, stave.bevel_b_deg) == (cycle["tilt_a_deg"], cycle["tilt_b_deg"])
        record = pieces[stave.production_id]
        assert (record.barrel_number, record.stave_number) == (barrel.number, stave.number)
    assert staves[-1].width_mm == pytest.approx(closing.width_mm, abs=1e-6)
    # The trace holds Z at +alpha_A while side A is cut and at -alpha_B on side B, per stave.
    with trace.open() as f:
        tilts = {float(row["z_cmd"]) for row in csv.DictReader(f)}  # 4 decimals

    def held(z_deg: float) -> bool:
        return any(abs(z - z_deg) <= 6e-5 for z in tilts)

    for cycle in cycles:
        assert held(cycle["tilt_a_deg"]) and held(-cycle["tilt_b_deg"])


def test_a_board_too_narrow_to_close_is_refused_before_cutting(capsys, files) -> None:
    recipe, config = files
    widths = ",".join(["100"] * 8 + ["110"])  # leaves 13 mm: no stave; the operator decides
    code = main(
        ["simulate", "--recipe-file", str(recipe), "--config", str(config), "--barrel",
         "--widths", widths, "--json"]
    )  # fmt: skip
    out, _ = capsys.readouterr()
    assert code == 0
    result = json.loads(out)
    assert result["barrel_closed"] is False and result["barrel_staves"] == 8
    last = result["cycles"][-1]
    assert last["result"] == "alarm" and last["alarms"] == ["E034"]
    assert "cut_time_s" in last and last["cut_time_s"] == {}  # nothing was cut


@pytest.mark.parametrize(
    ("args", "text"),
    [
        (["--barrel", "--widths", "100,abc"], "--widths: 'abc' is not allowed"),
        (["--widths", "100"], "--widths is only for --barrel"),
        ([], "--width is missing"),
    ],
)
def test_bad_barrel_options_are_one_line(capsys, files, args, text) -> None:
    recipe, _ = files
    code = main(["simulate", "--recipe-file", str(recipe), *args])
    _, err = capsys.readouterr()
    assert code == 2 and err.count("\n") == 1 and text in err
