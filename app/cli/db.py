"""``stave db``: recipe import/export, production export, backup, restore and listings.

For the office and for commissioning: everything the screens do with files, from a shell.
Every action takes ``--db PATH`` (default: the user's data directory, or $STAVE_JOINTER_DB).

Exit status: 0 done; 1 import done but some rows were rejected (the valid ones were stored,
the report lists the others); 2 bad input (one line on stderr naming what and why).
"""

from __future__ import annotations

import argparse
import getpass
import os
import sys
from collections.abc import Sequence
from datetime import UTC, date, datetime, tzinfo
from pathlib import Path

from app.cli.pin_input import NEW_PIN_ENV, PinMissing, read_pin
from app.data.backup import backup_database, restore_database, service_pin_check
from app.data.barrel_card import export_barrel_card
from app.data.database import Database
from app.data.errors import DataError
from app.data.exchange import (
    export_production_csv,
    export_production_day,
    export_production_shift,
    export_recipes,
    import_recipes,
)
from app.data.parameters import PARAMETERS
from app.data.paths import default_database_path
from app.data.recipe import BarrelType
from app.geometry.errors import format_value

LIST_CHOICES = ("recipes", "parameters", "users", "barrels")


class UsageError(Exception):
    """Bad command-line input: reported as one line, exit status 2."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Add the ``db`` actions to ``parser`` (the ``stave db`` subparser)."""
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument(
        "--db",
        type=Path,
        metavar="PATH",
        help=f"database file (default: {default_database_path()})",
    )
    actions = parser.add_subparsers(dest="db_action", metavar="ACTION")
    actions.required = True

    p = actions.add_parser(
        "import", parents=[common], help="import recipes from a .json or .csv file"
    )
    p.add_argument("file", type=Path, metavar="FILE")

    p = actions.add_parser("export", parents=[common], help="export all recipes (.json or .csv)")
    p.add_argument("file", type=Path, metavar="FILE")

    p = actions.add_parser(
        "export-production",
        parents=[common],
        help="export production records (.csv) for a day, a shift or a range",
    )
    p.add_argument("file", type=Path, metavar="FILE.csv")
    p.add_argument("--day", type=_date, metavar="YYYY-MM-DD", help="a calendar day")
    p.add_argument(
        "--shift", type=int, metavar="N", help="shift N (1 = first) of --day (default today)"
    )
    p.add_argument("--from", dest="start", type=_datetime, metavar="ISO", help="range start")
    p.add_argument("--to", dest="end", type=_datetime, metavar="ISO", help="range end (excl.)")
    p.add_argument("--utc", action="store_true", help="days, shifts and times in UTC")

    p = actions.add_parser(
        "export-barrel",
        parents=[common],
        help="write a barrel's cooper's card (.csv): its staves in order, widths, bevels",
    )
    p.add_argument("file", type=Path, metavar="FILE")
    p.add_argument(
        "--barrel", type=_barrel_number, metavar="N", help="the barrel's number (default: newest)"
    )

    p = actions.add_parser("backup", parents=[common], help="copy the database to a file")
    p.add_argument("destination", type=Path, metavar="FILE_OR_DIR")
    p.add_argument("--overwrite", action="store_true", help="replace an existing file")

    p = actions.add_parser(
        "restore",
        parents=[common],
        help="replace the database by a checked backup (service PIN; the current one is kept)",
    )
    p.add_argument("backup", type=Path, metavar="BACKUP")
    p.add_argument(
        "--with-users",
        action="store_true",
        help="bring back the backup's users and PINs too (default: keep the current ones)",
    )

    p = actions.add_parser(
        "set-pin",
        parents=[common],
        help="change a user's PIN (your PIN, then the new one: prompt, $STAVE_PIN and "
        "$STAVE_NEW_PIN, or two lines on standard input)",
    )
    p.add_argument("user", metavar="NAME")

    actions.add_parser(
        "unlock-pins",
        parents=[common],
        help="end a PIN lockout (for the machine's own account, which owns the database file)",
    )

    p = actions.add_parser("list", parents=[common], help="print recipes, parameters or users")
    p.add_argument("what", nargs="?", choices=LIST_CHOICES, default="recipes")


FIRST_DAY = date(1970, 1, 2)
LAST_DAY = date(9998, 12, 30)
"""Days a production export can name (a day's window in any zone stays a valid time)."""


def _date(text: str) -> date:
    try:
        day = date.fromisoformat(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a date YYYY-MM-DD") from None
    if not FIRST_DAY <= day <= LAST_DAY:
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed: {FIRST_DAY} to {LAST_DAY}")
    return day


def _datetime(text: str) -> datetime:
    try:
        return datetime.fromisoformat(text)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"{text!r} is not a date and time (e.g. 2024-05-02T06:00)"
        ) from None


def run(args: argparse.Namespace) -> int:
    """Run the chosen action; returns the exit status."""
    action = str(args.db_action)
    try:
        return _ACTIONS[action](args)
    except BrokenPipeError:  # output piped into `head`: not an error of ours
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 - keeps Python's exit flush quiet
        return 0
    except (UsageError, PinMissing, DataError, ValueError, OSError) as exc:
        message = str(exc).replace("\n", "; ")
        print(f"stave db {action}: {message}", file=sys.stderr)
        return 2


def _db_path(args: argparse.Namespace) -> Path:
    return Path(args.db) if args.db is not None else default_database_path()


def _open_existing(args: argparse.Namespace) -> Database:
    path = _db_path(args)
    if not path.is_file():
        raise UsageError(
            f"--db {path}: no database there (file not found; the application or an import "
            "creates one)"
        )
    return Database.open(path)


def _import(args: argparse.Namespace) -> int:
    if not args.file.is_file():
        raise UsageError(f"{args.file}: file not found")
    pin = read_pin("importing needs the PIN of a technician")
    with Database.open(_db_path(args)) as db:
        user = db.authenticate(pin)
        if user is None:
            raise UsageError("pin: this PIN belongs to no user")
        report = import_recipes(db, args.file, user)
    for line in report.lines():
        print(line)
    return 1 if report.rejected else 0


def _export(args: argparse.Namespace) -> int:
    with _open_existing(args) as db:
        count = export_recipes(db, args.file)
    print(f"{count} recipes written to {args.file}")
    return 0


def _export_production(args: argparse.Namespace) -> int:
    tz: tzinfo | None = UTC if args.utc else None
    ranged = args.start is not None or args.end is not None
    if ranged and (args.day is not None or args.shift is not None):
        raise UsageError("--from/--to cannot be combined with --day or --shift")
    with _open_existing(args) as db:
        if ranged:
            if args.start is None or args.end is None:
                raise UsageError("--from and --to go together")
            start, end = _aware(args.start, tz), _aware(args.end, tz)
            count = export_production_csv(db, args.file, start, end, tz)
            what = f"{start.isoformat()} to {end.isoformat()}"
        elif args.shift is not None:
            day = args.day if args.day is not None else datetime.now(tz).date()
            count = export_production_shift(db, args.file, day, args.shift, tz=tz)
            what = f"shift {args.shift} of {day.isoformat()}"
        elif args.day is not None:
            count = export_production_day(db, args.file, args.day, tz)
            what = args.day.isoformat()
        else:
            raise UsageError("choose what to export: --day, --shift or --from/--to")
    print(f"{count} production records ({what}) written to {args.file}")
    return 0


def _barrel_number(text: str) -> int:
    try:
        number = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a barrel number (1, 2, ...)") from None
    if number < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not allowed: a barrel number >= 1")
    return number


def _export_barrel(args: argparse.Namespace) -> int:
    with _open_existing(args) as db:
        barrel = export_barrel_card(db, args.file, args.barrel)
        count = len(db.barrel_staves(barrel.number))
    print(
        f"cooper's card of barrel {barrel.number} ({barrel.state.value}, {count} staves) "
        f"written to {args.file}"
    )
    return 0


def _aware(moment: datetime, tz: tzinfo | None) -> datetime:
    """A time typed without an offset is in ``tz`` (local time if None)."""
    if moment.tzinfo is not None:
        return moment
    return moment.astimezone() if tz is None else moment.replace(tzinfo=tz)


def _backup(args: argparse.Namespace) -> int:
    path = _db_path(args)
    if not path.is_file():
        raise UsageError(f"--db {path}: no database there (file not found)")
    written = backup_database(path, args.destination, overwrite=args.overwrite)
    print(f"backup written to {written}")
    return 0


def _restore(args: argparse.Namespace) -> int:
    path = _db_path(args)

    def authorize(current: Database) -> None:  # asked only once the backup passed its checks
        service_pin_check(read_pin("restoring needs the PIN of a service user"))(current)

    report = restore_database(args.backup, path, authorize=authorize, restore_users=args.with_users)
    info = report.restored
    print(
        f"restored {info.path} (schema version {info.schema_version}, {info.recipes} recipes, "
        f"{info.production_records} production records) into {_db_path(args)}"
    )
    if report.previous_copy is not None:
        print(f"the previous database is kept as {report.previous_copy}")
    return 0


def _set_pin(args: argparse.Namespace) -> int:
    with _open_existing(args) as db:
        target = next(
            (u for u in db.list_users() if u.name.casefold() == args.user.casefold()), None
        )
        if target is None:
            names = ", ".join(u.name for u in db.list_users())
            raise UsageError(f"user = {args.user!r} is not a user: one of {names}")
        actor = db.authenticate(read_pin(f"changing the PIN of {target.name} needs your PIN"))
        if actor is None:
            raise UsageError("pin: this PIN belongs to no user")
        new_pin = read_pin("the new PIN", env=NEW_PIN_ENV, prompt="new PIN: ")
        db.set_pin(target, new_pin, actor)
    print(f"PIN of {target.name} changed (by {actor.name})")
    return 0


def _unlock_pins(args: argparse.Namespace) -> int:
    """Whoever may write the database file (0600, the machine's account) could change any
    value in it anyway; so this needs no PIN, which the lockout would refuse."""
    with _open_existing(args) as db:
        was = db.pin_guard_state()
        db.reset_pin_guard(by=f"the command line ({getpass.getuser()})")
    print(f"PIN entry unlocked ({was.failures} wrong PINs in a row before)")
    return 0


def _list(args: argparse.Namespace) -> int:
    with _open_existing(args) as db:
        if args.what == "recipes":
            print("id  name                                      L mm   H mm  lambda  k      tilt")
            for r in db.list_recipes():
                if r.barrel_type is BarrelType.FIXED_TILT:
                    tilt = f"{format_value(r.tilt_deg)} deg"
                elif r.barrel_type is BarrelType.ROUND:
                    tilt = f"round barrel D {format_value(r.barrel_diameter_mm)} mm"
                else:
                    tilt = (
                        f"oval barrel {format_value(r.barrel_diameter_mm)} x "
                        f"{format_value(r.barrel_minor_diameter_mm)} mm"
                    )
                print(
                    f"{r.id:<3} {r.name:<40} {format_value(r.length_mm):>6} "
                    f"{format_value(r.thickness_mm):>5}  {r.length_ratio!s:<6}  "
                    f"{r.width_ratio!s:<5}  {tilt}"
                )
        elif args.what == "parameters":
            values = db.get_parameters()
            for spec in PARAMETERS:
                print(f"{spec.name:<22} {format_value(values[spec.name]):>10} {spec.unit}")
        elif args.what == "barrels":
            print("barrel  state      staves  belly mm      recipe")
            for b in db.list_barrels():
                belly = f"{format_value(b.belly_major_mm)} x {format_value(b.belly_minor_mm)}"
                count = len(db.barrel_staves(b.number))
                print(f"{b.number:<7} {b.state.value:<10} {count:>6}  {belly:<12}  {b.recipe_name}")
        else:
            for user in db.list_users():
                print(f"{user.id:<3} {user.name:<20} {user.role.label}")
    return 0


_ACTIONS = {
    "import": _import,
    "export": _export,
    "export-production": _export_production,
    "export-barrel": _export_barrel,
    "backup": _backup,
    "restore": _restore,
    "list": _list,
    "set-pin": _set_pin,
    "unlock-pins": _unlock_pins,
}


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m app.cli.db ACTION ...`` (the same as ``stave db ACTION ...``)."""
    parser = argparse.ArgumentParser(prog="stave db", description=__doc__.splitlines()[0])
    add_arguments(parser)
    return run(parser.parse_args(argv))


if __name__ == "__main__":
    sys.exit(main())
