"""The configuration refuses everything it cannot run on with one line and exit status 2,
in the operator application's own process before the machine process starts: a wrong key in
any backend's or the gauge's table, absurd numbers, deep nesting, bytes that are not UTF-8,
rules across keys, and an empty or truncated file under a real backend. Then fuzzed."""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from app.config import ConfigError, load_config
from app.drivers.settings_check import check_settings
from app.main import main
from app.resources import resource_path

MODBUS = resource_path("machine-modbus.toml").read_text(encoding="utf-8")
CANOPEN = resource_path("machine-canopen.toml").read_text(encoding="utf-8")
SIM = resource_path("machine.toml").read_text(encoding="utf-8")


def start(tmp_path: Path, text: str | bytes, *extra: str) -> tuple[int, str]:
    """``python -m app --config FILE`` as far as it gets without a display."""
    path = tmp_path / "machine.toml"
    if isinstance(text, bytes):
        path.write_bytes(text)
    else:
        path.write_text(text, encoding="utf-8")
    code = main(["--config", str(path), "--db", str(tmp_path / "stave.db"), *extra])
    return code, ""


def refused(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, text: str | bytes, *extra: str
) -> str:
    code, _ = start(tmp_path, text, *extra)
    err = capsys.readouterr().err
    assert code == 2, err
    assert err.count("\n") == 1 and err.startswith("stave: configuration error: "), err
    return err


def with_line(text: str, table: str, line: str) -> str:
    assert f"[{table}]\n" in text
    return text.replace(f"[{table}]\n", f"[{table}]\n{line}\n", 1)


@pytest.mark.parametrize(
    ("text", "table"),
    [
        (MODBUS, "backend.modbus"),
        (CANOPEN, "backend.canopen"),
        (SIM, "backend.sim"),
        (MODBUS, "gauge.serial"),
    ],
    ids=["modbus", "canopen", "sim", "gauge.serial"],
)
def test_a_misspelt_key_in_a_backend_table_stops_the_start_up(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, text: str, table: str
) -> None:
    err = refused(capsys, tmp_path, with_line(text, table, "timeuot_ms = 50"))
    assert f"{table}.timeuot_ms" in err


@pytest.mark.parametrize(
    ("line", "key"),
    [
        ("min_position = -1e12", "axes.Y.min_position"),
        ("min_position = 1e400", "axes.Y.min_position"),
        (f"max_position = {10**400}", "axes.Y.max_position"),
        ("min_position = 0.0\nhome_switch_position = -5.0", "axes.Y.home_switch_position"),
    ],
)
def test_axis_limits_must_make_physical_sense(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, line: str, key: str
) -> None:
    text = (
        SIM + f"\n[axes.Y]\n{line}\n"
        if "[axes.Y]" not in SIM
        else SIM.replace("[axes.Y]\n", f"[axes.Y]\n{line}\n", 1)
    )
    if "[axes.Y]" in SIM:
        text = _drop_duplicates(text)
    assert key in refused(capsys, tmp_path, text)


def _drop_duplicates(text: str) -> str:
    """Keep the first assignment of each key within a table (the inserted line wins)."""
    seen: set[tuple[str, str]] = set()
    table = ""
    out = []
    for line in text.splitlines():
        stripped = line.split("#", 1)[0].strip()
        if stripped.startswith("["):
            table = stripped
        elif "=" in stripped:
            key = (table, stripped.split("=", 1)[0].strip())
            if key in seen:
                continue
            seen.add(key)
        out.append(line)
    return "\n".join(out) + "\n"


def test_bytes_that_are_not_utf8_nesting_and_size(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert "UTF-8" in refused(capsys, tmp_path, b'[backend]\nname = "sim\xff"\n')
    deep = "x = " + "[" * 100_000 + "]" * 100_000 + "\n"
    assert "nested" in refused(capsys, tmp_path, deep) or "TOML" in refused(capsys, tmp_path, deep)
    assert "bytes" in refused(capsys, tmp_path, "# " + "x" * (2 * 1024 * 1024) + "\n")


def test_an_empty_or_truncated_file_never_runs_real_drives(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert "not in the file" in refused(capsys, tmp_path, "", "--backend", "modbus")
    truncated = MODBUS[: MODBUS.index("[axes.Y]")] if "[axes.Y]" in MODBUS else MODBUS[:2000]
    try:
        tomllib.loads(truncated)
    except tomllib.TOMLDecodeError:
        truncated = truncated[: truncated.rindex("\n[")]
    assert "is not allowed" in refused(capsys, tmp_path, truncated)


def test_the_gauge_range_must_fit_the_machine(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    text = _drop_duplicates(with_line(MODBUS, "gauge.serial", "max_width_mm = 5000.0"))
    assert "gauge.serial.max_width_mm" in refused(capsys, tmp_path, text)


def test_the_shipped_samples_pass_every_check() -> None:
    for name in ("machine.toml", "machine-modbus.toml", "machine-canopen.toml"):
        check_settings(load_config(resource_path(name)))


TABLE_KEYS = {
    "backend": ["name", "period_ms", "modbus", "sim", "canopen"],
    "gauge": ["name", "sim", "serial"],
    "axes": ["X", "Y", "Z"],
    "io": ["centering_time_s", "clamp_time_s", "sensor_timeout_s"],
    "process": ["tool_radius_mm", "lead_mm", "feed_mm_s"],
    "database": ["path"],
    "ui": ["language"],
}
AXIS_KEYS = ["min_position", "max_position", "home_position", "home_switch_position", "max_jerk"]
scalars = st.one_of(
    st.integers(min_value=-(10**30), max_value=10**30),
    st.floats(allow_nan=True, allow_infinity=True),
    st.text(max_size=8),
    st.booleans(),
)
values = st.recursive(scalars, lambda inner: st.lists(inner, max_size=3), max_leaves=6)


@st.composite
def documents(draw: st.DrawFn) -> dict[str, object]:
    doc: dict[str, object] = {}
    for table, keys in TABLE_KEYS.items():
        if draw(st.booleans()):
            chosen = draw(st.lists(st.sampled_from([*keys, "bogus"]), max_size=3, unique=True))
            section: dict[str, object] = {}
            for key in chosen:
                if table == "axes" and key in ("X", "Y", "Z"):
                    axis_keys = draw(st.lists(st.sampled_from(AXIS_KEYS), max_size=3, unique=True))
                    section[key] = {k: draw(values) for k in axis_keys}
                elif key in ("modbus", "sim", "canopen", "serial"):
                    section[key] = {
                        draw(st.sampled_from(["timeout_ms", "seed", "port", "x"])): draw(values)
                    }
                else:
                    section[key] = draw(values)
            doc[table] = section
    return doc


def _toml(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return '"' + value.encode("unicode_escape").decode("ascii").replace('"', '\\\\"') + '"'
    assert isinstance(value, list)
    return "[" + ", ".join(_toml(v) for v in value) + "]"


def _render(doc: dict[str, object], prefix: str = "") -> str:
    lines: list[str] = []
    tables: list[tuple[str, dict[str, object]]] = []
    for key, value in doc.items():
        if isinstance(value, dict):
            tables.append((f"{prefix}{key}", value))
        else:
            lines.append(f"{key} = {_toml(value)}")
    out = "\n".join(lines) + "\n"
    for name, table in tables:
        out += f"\n[{name}]\n" + _render(table, f"{name}.")
    return out


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(documents(), st.sampled_from([None, "sim", "modbus", "canopen"]))
@example({"backend": {"modbus": {"timeuot_ms": 50}}}, "modbus")
@example({"axes": {"Y": {"min_position": -1e12}}}, None)
@example({"process": {"lead_mm": 10**400}}, None)
def test_any_configuration_is_accepted_or_refused_with_a_config_error(
    tmp_path_factory: pytest.TempPathFactory, doc: dict[str, object], backend: str | None
) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "machine.toml"
    path.write_text(_render(doc), encoding="utf-8")
    try:
        config = load_config(path).with_backend(backend)
        check_settings(config)
    except ConfigError as exc:
        assert "\n" not in str(exc) and " = " in str(exc)
