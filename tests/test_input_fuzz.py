"""Every input surface of the command line and the files it reads, fuzzed: each input gives
a result or one line naming the field and what is allowed (exit status 2), never a traceback,
never a hang. The inputs that once froze or crashed the program are explicit examples."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from app.cli import main as stave
from app.data.exchange import read_recipes
from app.data.recipe import ROW_KEYS
from app.data.recipe_files import RecipeFileError

FUZZ = settings(
    max_examples=120,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)

HOSTILE_NUMBERS = [
    "1e99999999",
    "1e400",
    str(10**400),
    "-1",
    "0",
    "nan",
    "inf",
    "--",
    "",
    "1/0",
    "3/4" * 30,
]


def one_line_or_result(capsys: pytest.CaptureFixture[str], argv: list[str]) -> int:
    try:
        code = stave(argv)
    except SystemExit as exc:  # argparse's own usage errors: exit 2 with its usage text
        code = int(exc.code or 0)
        capsys.readouterr()
        assert code == 2
        return code
    err = capsys.readouterr().err
    assert code in (0, 1, 2), (argv, err)
    if code == 2:
        assert err.count("\n") == 1 and "Traceback" not in err, (argv, err)
    return code


number_text = st.one_of(
    st.sampled_from(HOSTILE_NUMBERS),
    st.from_regex(r"\A-?\d{0,6}(\.\d{0,4})?([eE][+-]?\d{1,9})?\Z"),
    st.from_regex(r"\A\d{1,500}/\d{1,500}\Z"),
    st.text(max_size=12),
)


@FUZZ
@given(number_text, number_text, number_text, number_text)
@example("1000", "150", "1e99999999", "3/4")
@example("1000", "150", str(10**400), "3/4")
@example("1e400", "150", "1/4", "3/4")
@example("--", "150", "1/4", "3/4")
def test_solve_arguments(
    capsys: pytest.CaptureFixture[str], length: str, width: str, lam: str, k: str
) -> None:
    one_line_or_result(
        capsys,
        [
            "solve",
            f"--length={length}",
            f"--width={width}",
            f"--length-ratio={lam}",
            f"--width-ratio={k}",
        ],
    )


json_values = st.recursive(
    st.one_of(
        st.none(),
        st.booleans(),
        st.integers(min_value=-(10**400), max_value=10**400),
        st.floats(allow_nan=False, allow_infinity=False),
        st.sampled_from(HOSTILE_NUMBERS),
        st.text(max_size=10),
    ),
    lambda inner: (
        st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner, max_size=3)
    ),
    max_leaves=8,
)
recipe_keys = st.sampled_from([*ROW_KEYS, "x"])


@FUZZ
@given(st.lists(st.dictionaries(recipe_keys, json_values, max_size=7), max_size=4))
@example(
    [
        {
            "name": "a",
            "length_mm": 1000,
            "thickness_mm": 28,
            "length_ratio": "1e99999999",
            "width_ratio": "3/4",
            "tilt_deg": 8,
        }
    ]
)
@example(
    [
        {
            "name": "a",
            "length_mm": 10**400,
            "thickness_mm": 28,
            "length_ratio": 1e300,
            "width_ratio": 10**400,
            "tilt_deg": 8,
        }
    ]
)
def test_recipe_json_files(
    tmp_path_factory: pytest.TempPathFactory, rows: list[dict[str, object]]
) -> None:
    path = tmp_path_factory.mktemp("json") / "in.json"
    path.write_text(json.dumps(rows), encoding="utf-8")
    try:
        valid, rejected = read_recipes(path)
    except RecipeFileError as exc:
        assert "\n" not in str(exc)
        return
    assert len(valid) + len(rejected) == len(rows)


@FUZZ
@given(
    st.lists(
        st.lists(st.one_of(st.sampled_from(HOSTILE_NUMBERS), st.text(max_size=8)), max_size=7),
        max_size=4,
    )
)
def test_recipe_csv_files(tmp_path_factory: pytest.TempPathFactory, rows: list[list[str]]) -> None:
    path = tmp_path_factory.mktemp("csv") / "in.csv"
    header = "name,length_mm,thickness_mm,length_ratio,width_ratio,tilt_deg"
    body = "\n".join(
        ",".join(cell.replace("\n", " ").replace("\r", " ") for cell in row) for row in rows
    )
    path.write_text(f"{header}\n{body}\n", encoding="utf-8")
    try:
        read_recipes(path)
    except RecipeFileError as exc:
        assert "\n" not in str(exc)


def test_deeply_nested_and_huge_json_is_one_line(tmp_path: Path) -> None:
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(RecipeFileError, match="nested"):
        read_recipes(deep)
    digits = tmp_path / "digits.json"
    digits.write_text('[{"name": "a", "length_mm": ' + "9" * 5000 + "}]")
    with pytest.raises(RecipeFileError, match=r"usable JSON|digits"):
        read_recipes(digits)


@pytest.mark.parametrize(
    "argv",
    [
        ["simulate", "--recipe", "Barrique 225 l Bordeaux", "--width", "0"],
        ["simulate", "--recipe", "Barrique 225 l Bordeaux", "--width", "-5"],
        ["simulate", "--recipe", "Barrique 225 l Bordeaux", "--width", "1e400"],
        [
            "simulate",
            "--recipe",
            "Barrique 225 l Bordeaux",
            "--width",
            "150",
            "--trace",
            "/proc/x/y.csv",
        ],
        [
            "simulate",
            "--recipe",
            "Barrique 225 l Bordeaux",
            "--width",
            "150",
            "--db",
            "/proc/x/stave.db",
        ],
        ["simulate", "--recipe", "Barrique 225 l Bordeaux", "--width", "150", "--inject", ""],
        [
            "simulate",
            "--recipe",
            "Barrique 225 l Bordeaux",
            "--width",
            "150",
            "--cycles",
            str(10**400),
        ],
        ["db", "export-production", "{tmp}/x.csv", "--day", "9999-12-31", "--db", "{db}"],
        ["db", "export-production", "{tmp}/x.csv", "--day", "0001-01-01", "--db", "{db}"],
    ],
)
def test_explicit_bad_arguments_are_one_line(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, argv: list[str]
) -> None:
    from app.data.database import Database

    db = tmp_path / "stave.db"
    Database.open(db).close()
    args = [a.format(tmp=tmp_path, db=db) for a in argv]
    assert one_line_or_result(capsys, args) in (0, 2)
