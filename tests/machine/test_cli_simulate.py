"""``stave simulate`` end to end, through the command-line entry point."""

from __future__ import annotations

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest

from app.cli import main
from app.config import default_config_path

BARRIQUE = "Barrique 225 l Bordeaux"


def simulate(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str, str]:
    code = main(["simulate", *args])
    out, err = capsys.readouterr()
    return code, out, err


def test_json_for_two_cycles_and_a_trace(capsys, tmp_path: Path) -> None:
    trace = tmp_path / "trace.csv"
    code, out, _ = simulate(
        capsys,
        "--recipe",
        BARRIQUE,
        "--width",
        "150",
        "--cycles",
        "2",
        "--json",
        "--trace",
        str(trace),
    )
    assert code == 0
    result = json.loads(out)
    assert result["pieces"] == 2 and result["final_state"] == "ready"
    assert result["restarted"] is False
    assert set(result["params"]) == {
        "P0",
        "tool_radius_mm",
        "machine_height_mm",
        "tilt_deg",
        "length_mm",
        "length_ratio",
        "width_ratio",
        "feed_mm_s",
        "accel_mm_s2",
    }
    assert result["params"]["length_mm"] == 950.0
    for cycle in result["cycles"]:
        assert cycle["result"] == "ok" and cycle["alarms"] == []
        assert 5.0 < cycle["D_mm"] < 15.0 and cycle["R_mm"] > 1000.0
        assert 0.0 < cycle["cycle_time_s"] < 90.0
        assert cycle["cut_time_s"]["A"] > 0 and cycle["cut_length_mm"]["B"] > 950.0
        assert 0.0 < cycle["max_contour_error_mm"] < 0.1
        steps = cycle["step_times_s"]
        # Every period is booked to one step: they add up to the cycle, and the cut's own.
        assert sum(steps.values()) == pytest.approx(cycle["cycle_time_s"], abs=1e-6)
        assert steps["side_a"] == pytest.approx(cycle["cut_time_s"]["A"], abs=0.01)
        assert {"centering", "clamping", "measuring", "approach", "side_b"} <= set(steps)
    with trace.open() as f:
        rows = list(csv.reader(f))
    assert rows[0] == [
        *("t_s", "state", "x_cmd", "y_cmd", "z_cmd", "x_act", "y_act", "z_act"),
        *("spindle", "step"),
    ]
    times = [float(r[0]) for r in rows[1:]]
    assert times == sorted(times) and len(times) > 10_000
    assert {r[1] for r in rows[1:]} >= {"homing", "ready", "automatic"}


def test_text_report_of_a_curved_profile_has_no_d_and_r(capsys) -> None:
    """Without --json the cycle's line says a fitted curve has no D and R (it has neither)."""
    code, out, err = simulate(capsys, "--recipe", BARRIQUE, "--width", "150", "--profile",
                              "parabola")  # fmt: skip
    assert code == 0, err
    (line,) = [text for text in out.splitlines() if text.startswith("width 150.00 mm:")]
    assert "a fitted curve (no D, R), cycle " in line and "max contour error" in line
    assert out.splitlines()[-1].startswith("pieces 1, final state ready")


def test_injected_fault_ends_in_alarm_and_nothing_restarts(capsys) -> None:
    code, out, _ = simulate(
        capsys,
        "--recipe",
        BARRIQUE,
        "--width",
        "150",
        "--json",
        "--inject",
        "drive_fault:Y@cutting_b",
    )
    assert code == 0
    result = json.loads(out)
    assert result["final_state"] == "error" and result["pieces"] == 0
    assert result["restarted"] is False
    assert result["cycles"][0]["result"] == "alarm" and "E010" in result["cycles"][0]["alarms"]


def test_a_stop_in_the_middle_of_a_side_leaves_the_board_partly_cut(capsys) -> None:
    """The operator's Stop is not a fault: nothing latches, the board stays on the table
    partly cut, nothing restarts and no piece is counted."""
    code, out, err = simulate(
        capsys, "--recipe", BARRIQUE, "--width", "150", "--json", "--inject", "stop@cutting_b+3"
    )
    assert code == 0, err
    result = json.loads(out)
    cycle = result["cycles"][0]
    assert (cycle["result"], cycle["alarms"]) == ("stopped", [])
    assert cycle["injection"] == "stop@cutting_b+3: stopped the cycle, the board partly cut"
    assert result["final_state"] == "ready" and result["pieces"] == 0
    assert result["restarted"] is False


def test_recipe_file(capsys, tmp_path: Path) -> None:
    recipe = {
        "name": "Test 900",
        "length_mm": 900,
        "thickness_mm": 27,
        "length_ratio": "1/5",
        "width_ratio": "3/4",
        "tilt_deg": 6.0,
    }
    path = tmp_path / "recipe.json"
    path.write_text(json.dumps(recipe))
    code, out, _ = simulate(capsys, "--recipe-file", str(path), "--width", "120", "--json")
    assert code == 0
    result = json.loads(out)
    assert result["pieces"] == 1 and result["params"]["tilt_deg"] == 6.0


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--recipe", "Nope", "--width", "150"], "is not in the database"),
        (
            ["--recipe", BARRIQUE, "--width", "150", "--inject", "meteor@cutting_a"],
            "kind 'meteor' is not allowed",
        ),
        (
            ["--recipe", BARRIQUE, "--width", "150", "--inject", "estop@lunch"],
            "step 'lunch' is not allowed",
        ),
        (["--recipe", BARRIQUE, "--width", "150", "--cycles", "0"], "--cycles 0"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(capsys, args: list[str], message: str) -> None:
    code, _, err = simulate(capsys, *args)
    assert code == 2
    assert message in err and err.count("\n") == 1


def test_console_script_runs_without_traceback(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    result = subprocess.run(
        [sys.executable, "-m", "app.cli", "simulate", "--recipe-file", str(bad), "--width", "150"],
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert result.returncode == 2
    assert "Traceback" not in result.stderr and "--recipe-file" in result.stderr


@pytest.mark.parametrize(
    "injection",
    [
        "spindle@cutting_b",
        "estop@repositioning",
        "estop@cutting_a+5",
        "following_error:X@cutting_b+4",
        "stop@cutting_a+5",
    ],
)
def test_inject_then_resume_never_crosses_the_board_in_the_trace(
    capsys, tmp_path: Path, injection: str
) -> None:
    """Checked from outside: the trace's commanded positions and spindle output against the
    board (from the JSON's parameters) and the tool path of the measured width."""
    from app.config import load_config
    from app.data.database import Database
    from app.machine.cycle_plan import plan_board
    from app.machine.process_params import motion_limits, stave_limits
    from tests.machine.keepout_watch import KeepOutWatch

    trace = tmp_path / "trace.csv"
    db = tmp_path / "sim.db"
    code, out, err = simulate(
        capsys,
        *("--recipe", BARRIQUE, "--width", "150", "--inject", injection, "--resume"),
        *("--json", "--trace", str(trace), "--db", str(db)),
    )
    assert code == 0, err
    result = json.loads(out)
    cycle = result["cycles"][0]
    assert cycle["result"] == "resumed" and cycle["resume"] == "resumed and finished"
    assert result["pieces"] == 1
    config = load_config()
    with Database.open(db) as database:
        params = database.get_parameters()
        recipe = database.get_recipe_by_name(BARRIQUE)
    assert recipe is not None
    planned = plan_board(
        recipe,
        cycle["measured_width_mm"],
        params,
        stave_limits(config),
        motion_limits(config, params),
        (params["home_x_mm"], params["home_y_mm"], params["home_z_deg"]),
    )
    watch = KeepOutWatch(dict(params), recipe.length_mm, 150.0, planned.toolpath)
    with trace.open(encoding="utf-8") as f:
        for row in csv.DictReader(f):
            watch.check(
                float(row["t_s"]),
                row["step"] or row["state"],
                float(row["x_cmd"]),
                float(row["y_cmd"]),
                float(row["z_cmd"]),
                row["spindle"] == "1",
            )
    assert watch.touching_periods > 1000, "the trace holds the cut"
    assert watch.violations == []


@pytest.mark.parametrize(
    ("injection", "why"),
    [
        ("estop@cutting_a+", "seconds into the step ''"),
        ("estop@cutting_a+-1", "seconds into the step '-1'"),
        ("estop@cutting_a+nan", "seconds into the step 'nan'"),
        ("estop@cutting_a+1e999", "seconds into the step '1e999'"),
        ("estop@cutting_a+601", "seconds into the step '601'"),
    ],
)
def test_a_bad_time_into_the_step_is_refused(capsys, injection: str, why: str) -> None:
    code, _, err = simulate(capsys, "--recipe", BARRIQUE, "--width", "150", "--inject", injection)
    assert code == 2 and why in err and "a number from 0 to 600" in err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_an_injection_later_than_the_step_lasts_says_so(capsys) -> None:
    code, out, err = simulate(
        capsys, "--recipe", BARRIQUE, "--width", "150", "--inject", "estop@measuring+500", "--json"
    )
    assert code == 0, err
    cycle = json.loads(out)["cycles"][0]
    assert cycle["result"] == "ok" and "never reached that step" in cycle["injection"]


def test_resume_needs_an_injection(capsys) -> None:
    code, _, err = simulate(capsys, "--recipe", BARRIQUE, "--width", "150", "--resume")
    assert code == 2 and "--resume is not allowed without --inject" in err


def test_handwheel_and_joystick_in_manual_mode_report_where_the_axes_ended(
    capsys, tmp_path: Path
) -> None:
    config = tmp_path / "machine.toml"  # absolute encoders: ready at power-up, no homing run
    shipped = default_config_path().read_text(encoding="utf-8")
    config.write_text(shipped.replace('encoder = "incremental"', 'encoder = "absolute"'))
    trace = tmp_path / "jog.csv"
    code, out, _ = simulate(
        capsys,
        *("--recipe", BARRIQUE, "--config", str(config), "--trace", str(trace), "--json"),
        *("--handwheel", "y:-100:10", "--joystick", "X:0.5:0.5"),
    )
    assert code == 0
    result = json.loads(out)
    assert result["cycles"] == [] and result["final_state"] == "ready"
    wheel, stick = result["jogs"]
    assert (wheel["source"], wheel["axis"], wheel["multiplier"]) == ("handwheel", "Y", 10)
    assert wheel["moved"] == pytest.approx(-1.0, abs=1e-9)  # -100 counts x10 x 0.001 mm
    assert wheel["actual"]["Y"] == pytest.approx(wheel["command"]["Y"], abs=0.005)
    assert stick["source"] == "joystick" and stick["moved"] > 0.1
    assert stick["command"]["Y"] == wheel["command"]["Y"]  # the stick on X left Y alone
    with trace.open(encoding="utf-8") as rows:
        states = {row["state"] for row in csv.DictReader(rows)}
    assert "manual" in states


def test_a_bad_handwheel_turn_is_one_line_and_exit_2(capsys) -> None:
    code, _, err = simulate(capsys, "--recipe", BARRIQUE, "--handwheel", "X:10:5")
    assert code == 2
    assert "--handwheel 'X:10:5': multiplier '5' is not allowed: 1, 10 or 100" in err
    assert err.count("\n") == 1
