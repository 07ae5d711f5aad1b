"""``stave simulate`` never writes into production, and an injected fault cannot pass
silently: the step where it could not fire is not offered, an empty --inject is refused, and
a fault without effect in its step is reported as such."""

from __future__ import annotations

import hashlib
import json
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path

import pytest

from app.cli import main
from app.data.database import Database
from app.data.records import PieceResult, ProductionRecord
from app.data.users import CONFIGURATION_ACTOR, SIMULATION_ACTOR
from app.machine.database_store import open_store
from tests.drivers.sim.rig import make_config

BARRIQUE = "Barrique 225 l Bordeaux"


def simulate(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["simulate", *args])
    out, err = capsys.readouterr()
    return code, out, err


def digest(path: Path) -> str:
    return hashlib.sha256(
        b"".join(p.read_bytes() for p in (path, Path(f"{path}-wal")) if p.exists())
    ).hexdigest()


def test_the_panels_database_is_only_read(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    live = tmp_path / "stave.db"
    with Database.open(live) as db:
        db.record_piece(
            ProductionRecord(
                datetime(2024, 5, 2, tzinfo=UTC),
                None,
                BARRIQUE,
                150.0,
                10.0,
                5000.0,
                28.0,
                PieceResult.OK,
            )
        )
        stored = db.get_recipe_by_name(BARRIQUE)
        assert stored is not None
    recipe_file = tmp_path / "changed.json"
    recipe_file.write_text(
        json.dumps(
            {
                "name": BARRIQUE,
                "length_mm": 1000,
                "thickness_mm": 27,
                "length_ratio": "1/5",
                "width_ratio": "4/5",
                "tilt_deg": 8,
            }
        ),
        encoding="utf-8",
    )
    before = digest(live)
    code, out, err = simulate(
        capsys, "--recipe-file", str(recipe_file), "--width", "150", "--db", str(live), "--json"
    )
    assert code == 0, err
    assert "writes nothing into it" in err
    assert json.loads(out)["params"]["length_mm"] == 1000  # the file's recipe, as given
    assert digest(live) == before
    with Database.open(live) as db:
        assert db.get_recipe_by_name(BARRIQUE) == stored
        assert db.piece_counts(datetime(2000, 1, 1, tzinfo=UTC)) == (1, 1)


def test_a_new_database_is_the_simulations_own(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    own = tmp_path / "sim.db"
    for expected in (1, 2):
        code, _, err = simulate(capsys, "--recipe", BARRIQUE, "--width", "150", "--db", str(own))
        assert code == 0 and "writes nothing" not in err
        with Database.open(own) as db:
            assert db.for_simulation
            assert db.piece_counts(datetime(2000, 1, 1, tzinfo=UTC))[1] == expected


@pytest.mark.parametrize(
    ("inject", "message"),
    [
        ("", "empty is not allowed"),
        ("drive_fault:X@wait_for_part", "step 'wait_for_part' is not allowed"),
    ],
)
def test_an_injection_that_could_not_fire_is_refused(
    capsys: pytest.CaptureFixture[str], inject: str, message: str
) -> None:
    code, _, err = simulate(capsys, "--recipe", BARRIQUE, "--width", "150", "--inject", inject)
    assert code == 2 and message in err and err.count("\n") == 1


def test_a_fault_without_effect_in_its_step_is_said(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = simulate(
        capsys, "--recipe", BARRIQUE, "--width", "150", "--inject", "gauge_none@cutting_a", "--json"
    )
    assert code == 0
    cycle = json.loads(out)["cycles"][0]
    assert cycle["result"] == "ok" and "had no effect" in cycle["injection"]
    code, out, _ = simulate(
        capsys, "--recipe", BARRIQUE, "--width", "150", "--inject", "drive_fault:Y@cutting_b"
    )
    assert "injected drive_fault@cutting_b: raised E010" in out


@pytest.mark.parametrize(
    ("backend", "seeded", "logged"),
    [("sim", SIMULATION_ACTOR, SIMULATION_ACTOR), ("modbus", CONFIGURATION_ACTOR, "service")],
)
def test_what_the_simulated_machine_changes_is_logged_as_the_simulation(
    tmp_path: Path, backend: str, seeded: str, logged: str
) -> None:
    """Seeded factory parameters and a recipe the run is given: the simulation's, by name; on
    a real backend the factory values are the configuration's (nobody changed them) and a
    recipe the run is given is the service user's."""
    config = make_config()
    config = replace(
        config, backend=backend, process=replace(config.process, lead_mm=config.process.lead_mm + 1)
    )
    store = open_store(tmp_path / f"{backend}.db", config, threaded=False)
    try:  # the non-threaded store writes at once
        recipe = store.recipe_by_name(BARRIQUE)
        assert recipe is not None
        store.save_recipe(replace(recipe, id=None, name="Given by the run"))
        [change] = store.db.parameter_history("lead_mm")
        assert change.user_name == seeded
        assert store.db.recipe_history()[0].user_name == logged
    finally:
        store.close()
