"""The plant connection under load: a plant of simulated machines and a client of all of them,
and the machine loop's lateness with OPC UA clients subscribed.

    .venv/bin/python benchmarks/plant_bench.py plant [--machines 10] [--seconds 60]
    .venv/bin/python benchmarks/plant_bench.py lateness [--clients 10] [--seconds 60]

``plant``: N simulated machines cutting staves (each in this process on the simulated
backend, kept at real time), each with its own OPC UA server process on loopback, and one
client (its own process, SignAndEncrypt, a user) subscribed to every machine's CurrentState
and AbsolutePiecesOut. Prints the notification latency from the machine's state change (the
value's source timestamp) to the client, p50/p99; the servers' CPU and memory; and whether
the client saw every state change and every counted stave.

``lateness``: the machine process at 4 ms cutting staves, the operator application's link
feeding the OPC UA server, and N clients subscribed at 100 ms to state, flags and counters:
the machine loop's lateness as in latency_bench.py.
"""

from __future__ import annotations

import argparse
import asyncio
import math
import multiprocessing
import os
import statistics
import sys
import tempfile
import time
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))
from latency_bench import bench_config, keep_cutting, ready_to_start, show

from app.data.database import Database
from app.data.plant_users import PlantRole, add_plant_user
from app.data.production_counts import run_counts
from app.machine import commands as cmd
from app.machine.local_link import LocalMachineLink
from app.machine.process_link import ProcessMachineLink
from app.plant.process import PlantFeedLink, PlantProcess, default_pki_dir
from app.plant.settings import OpcuaSettings
from app.plant.state_map import unit_flags, unit_state
from app.plant.trust import thumbprint

USER, PASSWORD = "bench", "bench-password"
WW = "http://opcfoundation.org/UA/Woodworking/"
MACHINERY = "http://opcfoundation.org/UA/Machinery/"
OWN = "urn:stave-jointer:opcua"


def free_port() -> int:
    import socket

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


async def _client_certificate(folder: Path) -> tuple[Path, Path]:
    from asyncua.crypto.cert_gen import setup_self_signed_certificate
    from cryptography.x509.oid import ExtendedKeyUsageOID

    folder.mkdir(parents=True, exist_ok=True)
    cert, key = folder / "client.der", folder / "client.pem"
    await setup_self_signed_certificate(
        key,
        cert,
        "urn:stave-jointer:bench-client",
        "localhost",
        [ExtendedKeyUsageOID.CLIENT_AUTH],
        {"commonName": "bench client"},
    )
    return cert, key


def trust_client(cert: Path, pki_dir: Path) -> None:
    der = cert.read_bytes()
    (pki_dir / "trusted").mkdir(parents=True, exist_ok=True)
    (pki_dir / "trusted" / f"{thumbprint(der)}.der").write_bytes(der)


async def _connect_unit(url: str, cert: Path, key: Path) -> tuple[Any, Any, int]:
    """A client as a plant system connects (SignAndEncrypt, a user), the machine unit's
    State/Machine node, and the Woodworking namespace index."""
    from asyncua import Client

    client = Client(url, timeout=30)
    client.application_uri = "urn:stave-jointer:bench-client"
    await client.set_security_string(f"Basic256Sha256,SignAndEncrypt,{cert},{key}")
    client.set_user(USER)
    client.set_password(PASSWORD)
    await client.connect()
    ww = await client.get_namespace_index(WW)
    machinery = await client.get_namespace_index(MACHINERY)
    own = await client.get_namespace_index(OWN)
    unit = await client.nodes.objects.get_child(
        [f"{machinery}:Machines", f"{own}:StaveJointer", f"{ww}:State", f"{ww}:Machine"]
    )
    return client, unit, ww


async def _watch(
    endpoints: list[str], cert: Path, key: Path, seconds: float, out: multiprocessing.Queue
) -> None:  # type: ignore[type-arg]
    received: list[tuple[int, str, object, float, float]] = []

    class Handler:
        def __init__(self, machine: int) -> None:
            self.machine = machine

        def datachange_notification(self, node, val, data) -> None:  # type: ignore[no-untyped-def]
            source = data.monitored_item.Value.SourceTimestamp
            sent = source.timestamp() if source else float("nan")
            received.append((self.machine, str(node.nodeid.Identifier), val, sent, time.time()))

    clients = []
    for index, url in enumerate(endpoints):
        client, unit, ww = await _connect_unit(url, cert, key)
        nodes = [
            await unit.get_child([f"{ww}:Overview", f"{ww}:CurrentState"]),
            await unit.get_child([f"{ww}:Values", f"{ww}:AbsolutePiecesOut"]),
        ]
        subscription = await client.create_subscription(100, Handler(index))
        await subscription.subscribe_data_change(nodes, queuesize=1000)
        clients.append(client)
    out.put(("ready", len(clients)))
    await asyncio.sleep(seconds)
    for client in clients:
        await client.disconnect()
    out.put(("done", received))


def watch_main(
    endpoints: list[str], cert: str, key: str, seconds: float, out: multiprocessing.Queue
) -> None:  # type: ignore[type-arg]
    asyncio.run(_watch(endpoints, Path(cert), Path(key), seconds, out))


def process_usage(pid: int) -> tuple[float, float]:
    """(CPU seconds, resident MiB) of a process, from /proc."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    cpu_s = (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    rss_kib = next(
        int(line.split()[1])
        for line in Path(f"/proc/{pid}/status").read_text().splitlines()
        if line.startswith("VmRSS:")
    )
    return cpu_s, rss_kib / 1024.0


def wait_listening(plants: list[PlantProcess], timeout_s: float) -> None:
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        for plant in plants:
            plant.commands()
        if all(any("listening" in n for n in p.notices) for p in plants):
            return
        time.sleep(0.2)
    raise SystemExit(f"not every OPC UA server started in {timeout_s:.0f} s")


def run_plant(machines: int, seconds: float) -> None:
    config = bench_config(4.0)
    context = multiprocessing.get_context("spawn")
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        cert, key = asyncio.run(_client_certificate(root / "client"))
        links, feeds, plants, endpoints, dbs = [], [], [], [], []
        for index in range(machines):
            db = root / f"m{index}" / "stave.db"
            link = LocalMachineLink.create(config, db, advance_per_poll_s=0.0)
            with Database.open(db) as database:
                add_plant_user(database, USER, PlantRole.READ_ONLY, PASSWORD)
            trust_client(cert, default_pki_dir(db))
            settings = replace(
                OpcuaSettings(), enabled=True, port=free_port(), serial_number=f"M{index}"
            )
            plant = PlantProcess.start(settings, db, str(root / f"m{index}" / "log"))
            links.append(link)
            plants.append(plant)
            feeds.append(PlantFeedLink(link, plant))
            endpoints.append(settings.endpoint_url)
            dbs.append(db)
        started = time.monotonic()
        wait_listening(plants, 600.0)
        print(f"{machines} servers listening after {time.monotonic() - started:.0f} s")
        results: multiprocessing.Queue = context.Queue()  # type: ignore[type-arg]
        watcher = context.Process(
            target=watch_main, args=(endpoints, str(cert), str(key), seconds, results)
        )
        watcher.start()
        kind, count = results.get(timeout=300)
        assert kind == "ready" and count == machines
        usage_before = [process_usage(p._process.pid) for p in plants]  # type: ignore[arg-type]
        sent_states: list[list[tuple[int, float]]] = [[] for _ in range(machines)]
        last_state = [-1] * machines
        with Database.open(dbs[0]) as database:
            recipe = database.get_recipe_by_name("Barrique 225 l Bordeaux")
        assert recipe is not None and recipe.id is not None
        for link in links:
            link.send(cmd.SelectRecipe(recipe.id))
        # Nothing new is started in the last minute (longer than a cycle), and the machines
        # and their servers keep running until the client leaves: every stave started is
        # finished, recorded and published while the client listens.
        end = time.monotonic() + seconds - 1.0
        production_end = end - 60.0
        last = time.monotonic()
        while time.monotonic() < end:
            now = time.monotonic()
            for index, (link, feed) in enumerate(zip(links, feeds, strict=True)):
                link.run_for(now - last)
                snapshot = feed.latest()
                if snapshot is None:
                    continue
                state = int(unit_state(unit_flags(snapshot)))
                if state != last_state[index]:
                    last_state[index] = state
                    sent_states[index].append((state, snapshot.wall_time))
                if now < production_end and ready_to_start(snapshot):
                    link.send(cmd.Start())
            last = now
            time.sleep(0.02)
        usage_after = [process_usage(p._process.pid) for p in plants]  # type: ignore[arg-type]
        kind, received = results.get(timeout=120)
        watcher.join(30)
        counts = []
        for db in dbs:
            with Database.open(db) as database:
                counts.append(run_counts(database)["ok"])
        for feed in feeds:
            feed.close()
    # The first notification of each item is its value at subscription time, not a change.
    first_seen: set[tuple[int, str]] = set()
    latencies = []
    for machine_index, name, _, sent, got in received:
        if (machine_index, name) not in first_seen:
            first_seen.add((machine_index, name))
        elif not math.isnan(sent):  # a source timestamp was given
            latencies.append((got - sent) * 1000.0)
    latencies.sort()
    p50 = statistics.median(latencies)
    p99 = latencies[min(len(latencies) - 1, int(0.99 * len(latencies)))]
    cpu = [(b[0] - a[0]) / seconds * 100.0 for a, b in zip(usage_before, usage_after, strict=True)]
    rss = [b[1] for b in usage_after]
    missed_states = 0
    missed_pieces = 0
    for index in range(machines):
        seen_states = [
            v
            for m, name, v, _, _ in received
            if m == index and isinstance(v, int) and "CurrentState" in name
        ]
        expected = [s for s, _ in sent_states[index]]
        # the initial value arrives first; every later change must arrive, in order
        missed_states += sum(1 for s in expected[1:] if s not in seen_states)
        pieces = [
            v
            for m, name, v, _, _ in received
            if m == index and "AbsolutePiecesOut" in name and isinstance(v, int)
        ]
        final = max(pieces) if pieces else 0
        missed_pieces += counts[index] - int(final)
    print(
        f"{machines} machines, {seconds:.0f} s, {sum(counts)} staves cut "
        f"({min(counts)} to {max(counts)} per machine), "
        f"{len(received)} notifications to one client"
    )
    print(
        f"latency state change -> client: p50 {p50:.1f} ms, p99 {p99:.1f} ms, "
        f"max {latencies[-1]:.1f} ms"
    )
    print(
        f"servers: CPU {statistics.mean(cpu):.1f} % each on average (max {max(cpu):.1f} %), "
        f"memory {statistics.mean(rss):.0f} MiB each (max {max(rss):.0f} MiB)"
    )
    print(f"missed state changes: {missed_states}, counted staves not seen: {missed_pieces}")


async def _subscribers(url: str, cert: Path, key: Path, clients: int, seconds: float) -> int:
    seen = 0

    class Handler:
        def datachange_notification(self, node, val, data) -> None:  # type: ignore[no-untyped-def]
            nonlocal seen
            seen += 1

    connected = []
    for _ in range(clients):
        client, unit, ww = await _connect_unit(url, cert, key)
        nodes = [await unit.get_child([f"{ww}:Overview", f"{ww}:CurrentState"])]
        for group in ("Flags", "Values"):
            nodes.extend(await (await unit.get_child([f"{ww}:{group}"])).get_children())
        subscription = await client.create_subscription(100, Handler())
        await subscription.subscribe_data_change(nodes)
        connected.append(client)
    await asyncio.sleep(seconds)
    for client in connected:
        await client.disconnect()
    return seen


def subscribers_main(
    url: str, cert: str, key: str, clients: int, seconds: float, out: multiprocessing.Queue
) -> None:  # type: ignore[type-arg]
    out.put(asyncio.run(_subscribers(url, Path(cert), Path(key), clients, seconds)))


def run_lateness(clients: int, seconds: float) -> None:
    """The machine process cutting staves; with ``clients`` > 0 also the OPC UA server fed
    through the operator application's link and that many clients subscribed at 100 ms."""
    config = bench_config(4.0)
    context = multiprocessing.get_context("spawn")
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        db = root / "stave.db"
        with Database.open(db) as database:
            add_plant_user(database, USER, PlantRole.READ_ONLY, PASSWORD)
        plant = None
        watcher = None
        out: multiprocessing.Queue = context.Queue()  # type: ignore[type-arg]
        if clients:
            cert, key = asyncio.run(_client_certificate(root / "client"))
            trust_client(cert, default_pki_dir(db))
            settings = replace(OpcuaSettings(), enabled=True, port=free_port())
            plant = PlantProcess.start(settings, db, str(root / "log"))
            wait_listening([plant], 600.0)
            watcher = context.Process(
                target=subscribers_main,
                args=(settings.endpoint_url, str(cert), str(key), clients, seconds + 5, out),
            )
            watcher.start()
        machine = ProcessMachineLink.start(config, db)
        link = machine if plant is None else PlantFeedLink(machine, plant)
        with Database.open(db) as database:
            recipe = database.get_recipe_by_name("Barrique 225 l Bordeaux")
        assert recipe is not None and recipe.id is not None
        link.send(cmd.SelectRecipe(recipe.id))
        end = time.monotonic() + seconds
        while time.monotonic() < end and link.alive():
            keep_cutting(link)  # type: ignore[arg-type]
            time.sleep(0.02)  # the screens' 50 Hz sampling
        snapshot = link.latest()
        pieces = snapshot.pieces_total if snapshot else 0
        # At once, and patiently: its lateness figures come through the snapshot queue.
        machine.close(timeout_s=120.0)
        notifications = out.get(timeout=180) if watcher is not None else 0
        if watcher is not None:
            watcher.join(30)
        if plant is not None:
            plant.close()
    name = f"with {clients} OPC UA clients" if clients else "machine process alone"
    show(name, {**machine.lateness, "pieces": float(pieces)})
    if clients:
        print(f"  the clients received {notifications} notifications")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("plant", "lateness"))
    parser.add_argument("--machines", type=int, default=10)
    parser.add_argument("--clients", type=int, default=10)
    parser.add_argument("--seconds", type=float, default=60.0)
    args = parser.parse_args()
    print(f"{os.cpu_count()} cores, {datetime.now(UTC):%Y-%m-%d %H:%M} UTC")
    if args.mode == "plant":
        run_plant(args.machines, args.seconds)
    else:
        run_lateness(0, args.seconds)
        run_lateness(args.clients, args.seconds)


if __name__ == "__main__":
    main()
