"""``stave opcua``: commissioning of the plant connection without the screen.

    stave opcua users add NAME --role read-only|plant    (password from a prompt or stdin)
    stave opcua users remove NAME | users list
    stave opcua trust list | trust accept THUMBPRINT | trust reject THUMBPRINT
    stave opcua endpoints

Why the password never comes from the command line: argv is visible to every user of the
panel PC (``ps``) and lands in shell histories. Exit status: 0 done; 2 bad input, one line.
"""

from __future__ import annotations

import argparse
import getpass
import sys
from pathlib import Path

from app.config import ConfigError, MachineConfig, load_config
from app.data.database import Database
from app.data.errors import DataError
from app.data.paths import default_database_path
from app.data.plant_users import (
    PlantRole,
    add_plant_user,
    list_plant_users,
    remove_plant_user,
)
from app.plant.process import default_pki_dir
from app.plant.trust import TrustList


def add_arguments(parser: argparse.ArgumentParser) -> None:
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--config", type=Path, help="machine configuration file (TOML)")
    common.add_argument("--db", type=Path, metavar="PATH", help="database file")
    areas = parser.add_subparsers(dest="opcua_area", metavar="AREA")
    areas.required = True

    users = areas.add_parser("users", help="OPC UA users and their roles")
    user_actions = users.add_subparsers(dest="opcua_action", metavar="ACTION")
    user_actions.required = True
    add = user_actions.add_parser("add", parents=[common], help="add a user (or change one)")
    add.add_argument("name")
    add.add_argument("--role", required=True, choices=[r.value for r in PlantRole])
    remove = user_actions.add_parser("remove", parents=[common], help="remove a user")
    remove.add_argument("name")
    user_actions.add_parser("list", parents=[common], help="list the users")

    trust = areas.add_parser("trust", help="client certificates")
    trust_actions = trust.add_subparsers(dest="opcua_action", metavar="ACTION")
    trust_actions.required = True
    trust_actions.add_parser("list", parents=[common], help="trusted and rejected certificates")
    for action, text in (("accept", "trust a rejected certificate"), ("reject", "stop trusting")):
        p = trust_actions.add_parser(action, parents=[common], help=text)
        p.add_argument("thumbprint")

    areas.add_parser("endpoints", parents=[common], help="the endpoints the server offers")


def _config(args: argparse.Namespace) -> MachineConfig:
    return load_config(args.config)


def _db_path(args: argparse.Namespace, config: MachineConfig) -> Path:
    if args.db is not None:
        return Path(args.db)
    return Path(config.database_path) if config.database_path else default_database_path()


def _trust_list(args: argparse.Namespace, config: MachineConfig) -> TrustList:
    settings = config.opcua
    pki = Path(settings.pki_dir) if settings.pki_dir else default_pki_dir(_db_path(args, config))
    return TrustList(pki)


def _read_password(name: str) -> str:
    if not sys.stdin.isatty():
        return sys.stdin.readline().rstrip("\r\n")
    first = getpass.getpass(f"password for {name}: ")
    if getpass.getpass("again: ") != first:
        raise ValueError("password: the two entries differ")
    return first


def run(args: argparse.Namespace) -> int:
    try:
        config = _config(args)
        if args.opcua_area == "endpoints":
            from app.plant.server import describe_endpoints

            for line in describe_endpoints(config.opcua):
                print(line)
            for warning in config.opcua.insecure_choices():
                print(f"warning: {warning} is on", file=sys.stderr)
            return 0
        if args.opcua_area == "trust":
            return _trust(args, _trust_list(args, config))
        with Database.open(_db_path(args, config)) as db:
            return _users(args, db)
    except (ConfigError, DataError, ValueError) as exc:
        print(f"stave opcua: {exc}", file=sys.stderr)
        return 2


def _users(args: argparse.Namespace, db: Database) -> int:
    if args.opcua_action == "add":
        user = add_plant_user(db, args.name, PlantRole(args.role), _read_password(args.name))
        print(f"user {user.name} ({user.role.value}) stored")
    elif args.opcua_action == "remove":
        remove_plant_user(db, args.name)
        print(f"user {args.name} removed")
    else:
        for user in list_plant_users(db):
            print(f"{user.name}\t{user.role.value}")
    return 0


def _trust(args: argparse.Namespace, trust: TrustList) -> int:
    if args.opcua_action == "list":
        for label, found in (("trusted", trust.trusted()), ("rejected", trust.rejected())):
            for info in found:
                print(f"{label}\t{info.line()}")
        return 0
    info = (
        trust.accept(args.thumbprint)
        if args.opcua_action == "accept"
        else trust.reject(args.thumbprint)
    )
    verb = "trusted" if args.opcua_action == "accept" else "no longer trusted"
    print(f"{info.thumbprint} {verb} ({info.subject})")
    return 0
