"""The plant connection checked by node-opcua, an OPC UA stack we did not write.

One server (its own process, as on the panel) for the module: loading the OPC Foundation's
models takes seconds. It is fed by a real machine on the simulated backend, on a simulated
clock, through the same PlantFeedLink the operator application uses. Everything on
127.0.0.1 with a free ephemeral port.
"""

from __future__ import annotations

import io
import json
import time
from collections.abc import Iterator
from dataclasses import dataclass, replace
from pathlib import Path

import pytest

from app.cli import main as stave
from app.config import MachineConfig, load_config
from app.data.database import Database
from app.data.production_counts import run_counts
from app.data.recipe_files import recipes_to_json
from app.machine import commands as cmd
from app.machine.local_link import LocalMachineLink
from app.machine.states import MachineState
from app.plant.alarm_texts import alarm_titles
from app.plant.process import PlantFeedLink, PlantProcess
from app.plant.settings import OpcuaSettings
from app.plant.state_map import WwUnitMode, unit_flags, unit_state
from tests.plant.node_peer import NodeClient, free_port, require_node_opcua, wait_until

# Loading the OPC Foundation's models takes the server 10-20 s of CPU; on a loaded two-core
# machine the first test (which waits for it) and the cutting test need more than the default.
pytestmark = pytest.mark.timeout(600)

PASSWORD = "plant-pass-1"
BARRIQUE = "Barrique 225 l Bordeaux"
MACHINE = ["Machinery:Machines", "own:StaveJointer"]
STATE = [*MACHINE, "Woodworking:State", "Woodworking:Machine"]
CURRENT_STATE = [*STATE, "Woodworking:Overview", "Woodworking:CurrentState"]
SPECIFIC = [*MACHINE, "Woodworking:ManufacturerSpecific"]


def machine_config(tmp: Path, port: int) -> MachineConfig:
    config = load_config()
    axes = {n: replace(a, absolute_encoder=True) for n, a in config.axes.items()}
    sim = {**config.backend_settings.get("sim", {}), "auto_load": True}
    opcua = replace(OpcuaSettings(), enabled=True, port=port, serial_number="SJ-7")
    return replace(
        config.with_backend("sim", "sim"),
        axes=axes,
        backend_settings={**config.backend_settings, "sim": sim},
        opcua=opcua,
        log_dir=str(tmp / "log"),
    )


def cli(*args: str, stdin: str = "", monkeypatch: pytest.MonkeyPatch | None = None) -> int:
    import sys

    old = sys.stdin
    sys.stdin = io.StringIO(stdin)
    try:
        return stave(["opcua", *args])
    finally:
        sys.stdin = old


@dataclass
class Plant:
    tmp: Path
    config: MachineConfig
    db: Path
    link: LocalMachineLink
    plant: PlantProcess
    feed: PlantFeedLink
    first_refusal: dict[str, object]
    rejected_before_accept: int

    @property
    def endpoint(self) -> str:
        return self.config.opcua.endpoint_url

    def pump(self, machine_s: float, until=None, keep_cutting: bool = False) -> bool:  # type: ignore[no-untyped-def]
        """Run the machine (0.1 s per poll, several times real time) and feed the server;
        with ``keep_cutting`` the operator presses Start whenever the machine is READY."""
        steps = int(machine_s / self.link.advance_per_poll_s)
        for _ in range(steps):
            snapshot = self.feed.latest()
            if until is not None and snapshot is not None and until(snapshot):
                return True
            if (
                keep_cutting
                and snapshot is not None
                and snapshot.state is MachineState.READY
                and snapshot.allowed.get("Start") is None
            ):
                self.feed.send(cmd.Start())
            time.sleep(0.01)
        return until is None

    def client(self, name: str = "client") -> NodeClient:
        return NodeClient(self.endpoint, self.tmp / name)


@pytest.fixture(scope="module")
def plant(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Plant]:
    require_node_opcua()
    tmp = tmp_path_factory.mktemp("plant")
    config = machine_config(tmp, free_port())
    db = tmp / "stave.db"
    link = LocalMachineLink.create(config, db)
    for name, role in (("mes", "plant"), ("viewer", "read-only"), ("guesser", "read-only")):
        assert (
            cli("users", "add", name, "--role", role, "--db", str(db), stdin=PASSWORD + "\n") == 0
        )
    plant_process = PlantProcess.start(config.opcua, db, config.log_dir)
    feed = PlantFeedLink(link, plant_process)
    try:
        feed.latest()
        assert wait_until(
            lambda: (
                (plant_process.commands() or True)
                and any("listening" in n for n in plant_process.notices)
            ),
            400.0,
            0.2,
        ), f"the OPC UA server did not start: {plant_process.notices}"
        # A new client's certificate is refused until a technician trusts it.
        node = NodeClient(config.opcua.endpoint_url, tmp / "client")
        refusal = node.ask("connect", user="mes", password=PASSWORD)
        node.close()
        pki = tmp / "opcua-pki"
        rejected = sorted((pki / "rejected").glob("*.der"))
        for path in rejected:
            assert cli("trust", "accept", path.stem, "--db", str(db)) == 0
        yield Plant(tmp, config, db, link, plant_process, feed, refusal, len(rejected))
    finally:
        feed.close()


def test_an_unknown_client_certificate_is_refused_until_trusted(plant: Plant) -> None:
    assert plant.first_refusal["ok"] is False
    assert plant.rejected_before_accept == 1
    node = plant.client()
    try:
        assert node.ask("connect", user="mes", password=PASSWORD)["ok"] is True
    finally:
        node.close()
    trusted = list((plant.tmp / "opcua-pki" / "trusted").glob("*.der"))
    assert len(trusted) == 1
    # What the System screen's OPC UA page reads of the connection.
    status = plant.feed.plant_status()
    assert status.listening and status.pki_dir == plant.tmp / "opcua-pki"


def test_browse_identification_and_state_by_standard_names(plant: Plant) -> None:
    node = plant.client()
    try:
        assert node.ask("connect", user="viewer", password=PASSWORD)["ok"]
        names = node.ask("browse", path=MACHINE)["names"]
        for expected in ("Identification", "State", "Events", "ManufacturerSpecific"):
            assert expected in names
        ident = [*MACHINE, "DI:Identification"]
        values = node.ask(
            "read",
            paths={
                "manufacturer": [*ident, "DI:Manufacturer"],
                "model": [*ident, "DI:Model"],
                "serial": [*ident, "DI:SerialNumber"],
                "software": [*ident, "DI:SoftwareRevision"],
                "year": [*ident, "Machinery:YearOfConstruction"],
                "state": CURRENT_STATE,
                "machine_on": [*STATE, "Woodworking:Flags", "Woodworking:MachineOn"],
                "staves": [*SPECIFIC, "own:BarrelStavesDone"],
            },
        )
        assert values["ok"], values
        v = values["values"]
        from app import __version__

        assert v["serial"] == "SJ-7"
        assert v["manufacturer"] == plant.config.opcua.manufacturer
        assert v["model"] == plant.config.opcua.model
        assert v["software"] == __version__
        assert v["year"] == plant.config.opcua.year_of_construction
        assert v["machine_on"] is True
        assert v["staves"] == 0  # single staves: no barrel
        on_time = {"on_ms": [*STATE, "Woodworking:Values", "Woodworking:AbsoluteMachineOnTime"]}
        assert wait_until(
            lambda: (
                (plant.pump(0.2) or True) and node.ask("read", paths=on_time)["values"]["on_ms"] > 0
            ),
            30.0,
        )
        expected_state = unit_state(unit_flags(plant.link.latest()))
        assert v["state"] == int(expected_state)
    finally:
        node.close()


def test_subscribed_state_counters_and_alarm_events_while_staves_are_cut(plant: Plant) -> None:
    node = plant.client()
    try:
        assert node.ask(
            "connect", user="viewer", password=PASSWORD, policy="Aes128_Sha256_RsaOaep"
        )["ok"]
        values = [*STATE, "Woodworking:Values"]
        reply = node.ask(
            "subscribe",
            values={
                "state": CURRENT_STATE,
                "pieces": [*values, "Woodworking:AbsolutePiecesOut"],
                "runs": [*values, "Woodworking:AbsoluteRunsTotal"],
            },
            events=[*MACHINE, "Woodworking:Events"],
        )
        assert reply["ok"], reply
        with Database.open(plant.db) as db:
            recipe = db.get_recipe_by_name(BARRIQUE)
        assert recipe is not None and recipe.id is not None
        plant.feed.send(cmd.SelectRecipe(recipe.id))
        plant.feed.send(cmd.StartBarrel())  # the barrique's staves are raised as a barrel
        start_total = plant.link.latest().pieces_total  # type: ignore[union-attr]
        plant.pump(1.0)
        assert plant.pump(
            200.0, until=lambda s: s.pieces_total >= start_total + 2, keep_cutting=True
        ), "two staves were not cut"
        barrel = plant.link.latest().barrel  # type: ignore[union-attr]
        assert barrel is not None and barrel.staves_done >= 2
        progress = {
            name: [*SPECIFIC, f"own:{name}"]
            for name in ("BarrelStavesDone", "BarrelStavesPlanned", "BarrelGap_mm")
        }
        assert wait_until(
            lambda: (
                (plant.pump(0.1) or True)
                and node.ask("read", paths=progress)["values"]["BarrelStavesDone"]
                == plant.link.latest().barrel.staves_done  # type: ignore[union-attr]
            ),
            30.0,
        )
        seen = node.ask("read", paths=progress)["values"]
        assert seen["BarrelStavesPlanned"] > seen["BarrelStavesDone"]  # the barrel is open
        assert 0.0 < seen["BarrelGap_mm"] < 690.0
        plant.feed.send(cmd.Stop())
        assert plant.pump(60.0, until=lambda s: s.state is MachineState.READY)
        plant.feed.send(cmd.InjectFault("drive_fault", "Y"))
        assert plant.pump(10.0, until=lambda s: s.state is MachineState.ERROR)
        plant.pump(1.0)
        with Database.open(plant.db) as db:
            counts = run_counts(db)

        def last(key: str) -> object:
            seen = [n["value"] for n in node.notifications if n.get("notification") == key]
            return seen[-1] if seen else None

        assert wait_until(lambda: last("state") == 4, 30.0)  # ERROR
        states = {n["value"] for n in node.notifications if n.get("notification") == "state"}
        assert {2, 3, 4} <= states  # READY, WORKING, ERROR
        assert wait_until(lambda: last("pieces") == counts["ok"], 30.0), (last("pieces"), counts)
        assert last("runs") == sum(counts.values())
        events = [n for n in node.notifications if n.get("event")]
        drive = [e for e in events if e.get("messageId") == "E010"]
        assert drive, events[:3]
        first = drive[0]
        locales = {item["locale"]: item["text"] for item in first["localized"]}
        assert locales == {"en": "Drive fault", "sl": alarm_titles("E010")["sl"]}
        assert locales["sl"] != "Drive fault"
        assert first["severity"] == 800 and first["category"] == 4  # ALARM
        assert first["message"].startswith("E010 Drive fault")
        assert first["message"].endswith("[active, unacknowledged]")  # ISA-18.2 state
        # Arguments as WwMessageArgumentDataType: the axis and the drive's fault code, each
        # with its name and data type (node-opcua decodes a subtype of the standard Argument
        # with Argument's decoder: the fields up to Description).
        arguments = {a["name"]: a for a in first["arguments"]}
        assert set(arguments) == {"axis", "fault_code"}, first["arguments"]
        assert arguments["axis"]["dataType"] == "ns=0;i=12"  # String
        assert arguments["fault_code"]["dataType"] == "ns=0;i=8"  # Int64
        assert {a["valueRank"] for a in arguments.values()} == {-1}
    finally:
        node.close()
        plant.feed.send(cmd.ClearFaults())
        plant.feed.send(cmd.Reset())
        plant.pump(5.0, until=lambda s: s.state is MachineState.READY)


def test_job_methods_select_and_download_only_when_ready(plant: Plant) -> None:
    node = plant.client()
    try:
        assert node.ask("connect", user="mes", password=PASSWORD)["ok"]
        bad = node.ask("call", object=SPECIFIC, method="own:SelectRecipe", args=["No such barrel"])
        assert bad["ok"] and bad["outputs"][0] is False
        assert "RecipeName = 'No such barrel' is not allowed" in bad["outputs"][1]
        plant.feed.send(cmd.EnterManual())
        assert plant.pump(2.0, until=lambda s: s.state is MachineState.MANUAL)
        # The server runs in its own process: wait until it has the MANUAL snapshot too.
        mode = [*STATE, "Woodworking:Overview", "Woodworking:CurrentMode"]
        assert wait_until(
            lambda: (
                (plant.pump(0.1) or True)
                and node.ask("read", paths={"mode": mode})["values"]["mode"] == WwUnitMode.MANUAL
            ),
            30.0,
        )
        good = node.ask("call", object=SPECIFIC, method="own:SelectRecipe", args=["Hogshead 300 l"])
        assert good["ok"] and good["outputs"][0] is True, good
        assert "waits for READY" in good["outputs"][1]
        plant.pump(1.0)
        assert plant.link.latest().recipe_name != "Hogshead 300 l"  # type: ignore[union-attr]
        plant.feed.send(cmd.LeaveManual())
        assert plant.pump(5.0, until=lambda s: s.recipe_name == "Hogshead 300 l")
        snapshot = plant.feed.latest()
        assert snapshot is not None and "asked by mes" in str(snapshot.message)
        assert snapshot.state is MachineState.READY  # nothing started

        with Database.open(plant.db) as db:
            base = db.get_recipe_by_name(BARRIQUE)
        assert base is not None
        document = json.loads(recipes_to_json([replace(base, id=None, name="Plant barrique")]))
        downloaded = node.ask(
            "call", object=SPECIFIC, method="own:DownloadRecipe", args=[json.dumps(document)]
        )
        assert downloaded["outputs"][0] is True, downloaded
        assert plant.pump(5.0, until=lambda s: s.recipe_name == "Plant barrique")
        with Database.open(plant.db) as db:
            history = db.recipe_history()
        assert any(
            h.user_name == "opcua:mes" and h.recipe_name == "Plant barrique" for h in history
        )
        broken = json.loads(json.dumps(document))
        target = broken["recipes"][0] if "recipes" in broken else broken
        target["length_mm"] = 50
        target["name"] = "Too short"
        refused = node.ask(
            "call", object=SPECIFIC, method="own:DownloadRecipe", args=[json.dumps(broken)]
        )
        assert refused["outputs"][0] is False
        assert "length_mm = 50" in refused["outputs"][1]
        with Database.open(plant.db) as db:
            assert db.get_recipe_by_name("Too short") is None
    finally:
        node.close()


def connects(plant: Plant, **login: str) -> bool:
    node = plant.client()
    try:
        return bool(node.ask("connect", **login)["ok"])
    finally:
        node.close()


def test_refusals_anonymous_wrong_password_none_read_only_and_writes(plant: Plant) -> None:
    assert not connects(plant)  # anonymous
    assert not connects(plant, user="mes", password="not-the-password")
    assert not connects(plant, user="mes", password=PASSWORD, mode="None", policy="None")
    viewer = plant.client()
    try:
        assert viewer.ask("connect", user="viewer", password=PASSWORD)["ok"]
        call = viewer.ask("call", object=SPECIFIC, method="own:SelectRecipe", args=[BARRIQUE])
        assert call["ok"] is False and "BadUserAccessDenied" in json.dumps(call)
        methods = set(viewer.ask("methods", path=MACHINE)["methods"])
        assert methods == {"SelectRecipe", "DownloadRecipe"}  # nothing that could move it
    finally:
        viewer.close()
    mes = plant.client()
    try:
        assert mes.ask("connect", user="mes", password=PASSWORD)["ok"]
        flag = [*STATE, "Woodworking:Flags", "Woodworking:Emergency"]
        write = mes.ask("write", path=flag, value=False)
        assert write["ok"] is False
    finally:
        mes.close()


def test_failed_logins_lock_the_user_name(plant: Plant) -> None:
    for _ in range(plant.config.opcua.max_failed_logins):
        assert not connects(plant, user="guesser", password="wrong-guess")
    assert not connects(plant, user="guesser", password=PASSWORD)  # locked, right or not
