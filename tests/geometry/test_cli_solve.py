import json
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from app.cli.solve import (
    DEFAULT_TILT_DEG,
    PROCESS_DEFAULTS,
    build_parser,
    main,
    run,
    settings_from_config,
)
from app.config import parse_config
from app.geometry.limits import StaveLimits
from app.geometry.profile import solve_profile
from app.geometry.toolpath import build_toolpath
from tests.geometry.strategies import DEFAULT_PARAMS

REPO = Path(__file__).resolve().parents[2]
EXAMPLE_ARGS = ["--length", "1000", "--width", "150", "--length-ratio", "1/4"]
EXAMPLE_ARGS += ["--width-ratio", "3/4"]


def solve_json(capsys, *extra: str) -> dict:
    assert main([*EXAMPLE_ARGS, "--json", *extra]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert out.count("\n") == 1  # one object on one line
    return json.loads(out)


def test_json_has_the_documented_keys_and_values(capsys):
    data = solve_json(capsys)
    assert list(data) == [
        "A", "B", "C", "D", "R", "W1", "points", "arc_center_a", "arc_center_b",
        "tilt_a_deg", "tilt_b_deg", "toolpath",
    ]  # fmt: skip
    assert (data["A"], data["B"], data["C"], data["W1"]) == (250.0, 250.0, 18.75, 112.5)
    assert round(data["D"], 6) == 12.502603
    assert round(data["R"], 4) == 5005.2066
    assert list(data["points"]) == [f"P{i}" for i in range(1, 9)]
    assert data["points"]["P1"] == [0.0, 56.25]
    assert data["arc_center_a"] == [500.0, 75.0 - data["R"]]
    assert data["arc_center_b"] == [500.0, -(75.0 - data["R"])]


def test_json_toolpath_segments(capsys):
    segments = solve_json(capsys)["toolpath"]
    for segment in segments:
        assert segment["type"] in ("line", "arc")
        assert len(segment["start"]) == len(segment["end"]) == 2
        assert isinstance(segment["cutting"], bool)
        if segment["type"] == "arc":
            assert segment["direction"] in ("cw", "ccw") and len(segment["center"]) == 2
        else:
            assert "center" not in segment and "direction" not in segment
    cutting_tilts = {s["z_deg"] for s in segments if s["cutting"]}
    assert cutting_tilts == {DEFAULT_TILT_DEG, -DEFAULT_TILT_DEG}
    assert [s["type"] for s in segments].count("arc") == 2
    assert segments[0]["start"] == [PROCESS_DEFAULTS["home_x_mm"], PROCESS_DEFAULTS["home_y_mm"]]


def test_json_toolpath_is_the_library_toolpath(capsys):
    data = solve_json(capsys, "--tilt", "3.5", "--tool-radius", "40", "--machine-height", "250")
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    assert data["toolpath"] == build_toolpath(profile, DEFAULT_PARAMS).to_json_list()


def test_flags_override_the_defaults(capsys):
    data = solve_json(capsys, "--tool-radius", "30", "--machine-height", "0", "--tilt", "10")
    params = replace(DEFAULT_PARAMS, tool_radius_mm=30.0, machine_height_mm=0.0, tilt_deg=10.0)
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    assert data["toolpath"] == build_toolpath(profile, params).to_json_list()


def test_decimal_ratios_are_accepted(capsys):
    args = ["--length", "1000", "--width", "150", "--length-ratio", "0.25"]
    assert main([*args, "--width-ratio", "0.75", "--json"]) == 0
    assert round(json.loads(capsys.readouterr().out)["D"], 6) == 12.502603


def test_human_readable_output(capsys):
    assert main(EXAMPLE_ARGS) == 0
    out, err = capsys.readouterr()
    assert err == ""
    assert "length ratio 1/4, width ratio 3/4" in out
    assert "  D  =    12.502603 mm  rise of the straight section" in out
    assert "  R  =  5005.206598 mm  arc radius" in out
    assert "P2 (  250.000000,    68.752603)" in out
    assert "arc cw" in out and "(travel)" in out
    assert "cutting length: side A" in out


def test_run_with_a_namespace(capsys):
    args = build_parser().parse_args([*EXAMPLE_ARGS, "--json"])
    assert run(args) == 0
    assert json.loads(capsys.readouterr().out)["W1"] == 112.5


@pytest.mark.parametrize(
    ("changes", "expected"),
    [
        ({"--width": "300"}, "width_mm = 300 is out of range: allowed 0 < width <= 280 mm"),
        ({"--width": "nan"}, "width_mm = nan is not a finite number: allowed 0 < width <= 280 mm"),
        ({"--length": "abc"}, "length_mm = 'abc' is not a finite number: allowed 900 <= length"),
        ({"--length": "800"}, "length_mm = 800 is out of range: allowed 900 <= length <= 3500 mm"),
        ({"--length-ratio": "1/2"}, "length_ratio = 0.5 is out of range: allowed 0 <= length"),
        ({"--length-ratio": "x"}, "length_ratio = 'x' is not a finite number: allowed 0 <="),
        ({"--width-ratio": "1/1"}, "width_ratio = 1 leaves nothing to cut"),
        ({"--width-ratio": "3/0"}, "width_ratio = '3/0' is not a finite number"),
        ({"--width": "70"}, "head_width_mm = 52.5 is out of range: allowed head width >= 60 mm"),
        ({"--thickness": "10"}, "thickness_mm = 10 is out of range: allowed 25 <= thickness"),
        ({"--tilt": "50"}, "tilt_deg = 50 is out of range: allowed 0 <= tilt <= 45 deg"),
        ({"--tilt": "1"}, "tilt_deg = 1 is out of range: allowed 1.910 <= tilt <= 38.682 deg"),
        ({"--tool-radius": "abc"}, "tool_radius_mm = 'abc' is not a finite number: allowed"),
        ({"--tool-radius": "-1"}, "tool_radius_mm = -1 is out of range: allowed tool radius > 0"),
        ({"--tool-radius": "70"}, "lead_mm = 60 is out of range: allowed lead > 70.171 mm"),
        ({"--machine-height": "inf"}, "machine_height_mm = 'inf' is not a finite number"),
    ],
)
def test_invalid_input_exits_2_with_one_line(capsys, changes, expected):
    args = dict(zip(EXAMPLE_ARGS[::2], EXAMPLE_ARGS[1::2], strict=True))
    args.update(changes)
    argv = [item for pair in args.items() for item in pair]
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("stave solve: ")
    assert expected in err


def test_several_errors_still_one_line(capsys):
    argv = ["--length", "5000", "--width", "300", "--length-ratio", "1/2", "--width-ratio", "1"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    for field in ("length_mm", "width_mm", "length_ratio", "width_ratio"):
        assert f"{field} = " in err


def test_usage_errors_are_one_line(capsys):
    assert main(["--length", "1000"]) == 2
    err = capsys.readouterr().err
    assert err == ("stave solve: the following arguments are required: --width, --width-ratio\n")


def test_help_exits_0(capsys):
    assert main(["--help"]) == 0
    assert "--length-ratio N/D" in capsys.readouterr().out


def test_settings_from_the_machine_configuration():
    config = parse_config(
        {
            "process": {"tool_radius_mm": 30.0, "start_x_mm": 150.0, "lead_mm": 50.0},
            "axes": {"X": {"max_position": 3900.0}, "Z": {"min_position": -10.0}},
        }
    )
    settings = settings_from_config(config)
    assert settings.process["tool_radius_mm"] == 30.0
    assert settings.process["start_x_mm"] == 150.0
    assert settings.process["machine_height_mm"] == 250.0  # the config file's default
    assert settings.limits == replace(
        StaveLimits(),
        x_min_mm=-5.0,
        x_max_mm=3900.0,
        y_min_mm=-5.0,
        y_max_mm=800.0,
        z_min_deg=-10.0,
        z_max_deg=15.0,
    )


def test_config_file_travel_limits_are_checked(capsys, tmp_path):
    config = tmp_path / "machine.toml"
    config.write_text("[axes.X]\nmax_position = 1000.0\n", encoding="utf-8")
    assert main([*EXAMPLE_ARGS, "--config", str(config)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert "x_mm = 1190.000 is out of range: allowed -5 <= X <= 1000 mm" in err


def test_config_file_process_values_are_used(capsys, tmp_path):
    config = tmp_path / "machine.toml"
    config.write_text("[process]\nstart_x_mm = 250.0\n", encoding="utf-8")
    assert main([*EXAMPLE_ARGS, "--json", "--config", str(config)]) == 0
    segments = json.loads(capsys.readouterr().out)["toolpath"]
    # The file's other process values and home equal DEFAULT_PARAMS; the tilt is the default.
    params = replace(DEFAULT_PARAMS, start_x_mm=250.0, tilt_deg=DEFAULT_TILT_DEG)
    profile = solve_profile(1000.0, 150.0, 0.25, 0.75)
    assert segments == build_toolpath(profile, params).to_json_list()


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        (None, "is not allowed: a readable file"),
        ("[process]\ntool_radius = 40\n", "process.tool_radius = 40 is not allowed"),
        ("not toml [", "is not allowed: valid TOML"),
    ],
)
def test_bad_config_file_is_one_line(capsys, tmp_path, text, fragment):
    config = tmp_path / "machine.toml"
    if text is not None:
        config.write_text(text, encoding="utf-8")
    assert main([*EXAMPLE_ARGS, "--config", str(config)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and fragment in err


def run_process(*argv: str) -> subprocess.CompletedProcess[str]:
    code = "import sys; from app.cli.solve import main; sys.exit(main(sys.argv[1:]))"
    return subprocess.run(
        [sys.executable, "-c", code, *argv],
        capture_output=True,
        text=True,
        cwd=REPO,
        check=False,
        timeout=60,
    )


def test_subprocess_json():
    result = run_process(*EXAMPLE_ARGS, "--json")
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert round(json.loads(result.stdout)["D"], 6) == 12.502603


def test_subprocess_invalid_input_has_no_traceback():
    result = run_process(*EXAMPLE_ARGS[:2], "--width", "300", *EXAMPLE_ARGS[4:])
    assert result.returncode == 2
    assert result.stdout == ""
    assert result.stderr == (
        "stave solve: width_mm = 300 is out of range: allowed 0 < width <= 280 mm\n"
    )


def test_module_entry_point():
    result = subprocess.run(
        [sys.executable, "-m", "app.cli.solve", *EXAMPLE_ARGS[:2], "--width", "nan"],
        capture_output=True,
        text=True,
        cwd=REPO,
        check=False,
        timeout=60,
    )
    assert result.returncode == 2
    assert "Traceback" not in result.stderr and result.stderr.count("\n") == 1


def test_a_reader_that_goes_away_is_not_an_error():
    # `stave solve ... | head -3`: the pipe closes before the output is written.
    code = "import sys; from app.cli.solve import main; sys.exit(main(sys.argv[1:]))"
    process = subprocess.Popen(
        [sys.executable, "-c", code, *EXAMPLE_ARGS],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=REPO,
    )
    assert process.stdout is not None and process.stderr is not None
    process.stdout.close()
    error = process.stderr.read().decode()
    process.stderr.close()
    assert process.wait(timeout=60) == 0
    assert error == ""
