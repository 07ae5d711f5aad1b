"""The OPC UA server: the woodworking model, fed by snapshots, with the two job methods.

Why values are written only when they change: a snapshot arrives 50 times a second and most
of it stays the same; writing only the changes keeps the server's work (and the clients'
notifications) proportional to what happens on the machine.
"""

from __future__ import annotations

import logging
import socket
import tempfile
import time
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from asyncua import Server, ua
from asyncua.common.utils import ServiceError
from asyncua.crypto.cert_gen import setup_self_signed_certificate
from cryptography import x509
from cryptography.hazmat.primitives.serialization import Encoding
from cryptography.x509.oid import ExtendedKeyUsageOID

from app.data.database import Database
from app.data.exchange import production_to_csv, read_recipes
from app.data.production_counts import run_counts
from app.data.recipe_files import RecipeFileError
from app.data.shifts import ShiftPlan, current_shift
from app.machine.barrel_view import BarrelView
from app.machine.commands import SelectRecipe
from app.machine.snapshot import AlarmState, MachineSnapshot
from app.plant.access import CALLER, PlantRuleset, PlantUserManager, monotonic_clock
from app.plant.alarm_events import AlarmChange, alarm_changes
from app.plant.alarm_texts import alarm_titles
from app.plant.jobs import PlantJob, PlantJobs
from app.plant.login_throttle import LoginThrottle
from app.plant.message_arguments import complete_argument_type, message_arguments
from app.plant.model import WW_BASE_EVENT_TYPE_ID, MachineNodes, build_machine, load_models
from app.plant.settings import OpcuaSettings
from app.plant.state_map import unit_flags, unit_mode, unit_state
from app.plant.state_times import SAVE_EVERY_S, StateTimes, load_state_times, save_state_times
from app.plant.trust import TrustList

log = logging.getLogger(__name__)

APPLICATION_URI = "urn:stave-jointer:opcua:server"
_EVENT_CATEGORY = {"fault": 4, "warning": 3}  # WwEventCategoryEnumeration ALARM, WARNING
_SEVERITY = {"fault": 800, "warning": 400}
RECOUNT_S = 10.0  # how long after a change of the machine's count the records are counted
RECOUNT_EVERY_S = 0.5
_EVENT_FIELD_TYPES = {
    "MessageId": ua.VariantType.String,
    "MessageName": ua.VariantType.String,
    "Group": ua.VariantType.String,
    "PathParts": ua.VariantType.String,
    "EventCategory": ua.VariantType.Int32,
    "LocalizedMessages": ua.VariantType.LocalizedText,
    "Arguments": ua.VariantType.ExtensionObject,
}


def security_policies(settings: OpcuaSettings) -> list[ua.SecurityPolicyType]:
    policies = [
        ua.SecurityPolicyType.Basic256Sha256_SignAndEncrypt,
        ua.SecurityPolicyType.Aes128Sha256RsaOaep_SignAndEncrypt,
    ]
    if settings.allow_security_none:
        policies.append(ua.SecurityPolicyType.NoSecurity)
    return policies


class PlantServer:
    def __init__(
        self,
        settings: OpcuaSettings,
        db_path: Path,
        pki_dir: Path,
        send: Callable[[SelectRecipe], None],
        nodesets_dir: Path | None = None,
        clock: Callable[[], float] = monotonic_clock,
        on_event: Callable[[str], None] = lambda _text: None,
    ) -> None:
        self.settings = settings
        self.db_path = db_path
        self.trust = TrustList(pki_dir)
        self._send = send
        self._nodesets_dir = nodesets_dir
        self._clock = clock
        self._on_event = on_event
        self.jobs = PlantJobs()
        self.server = Server(
            user_manager=PlantUserManager(
                db_path,
                LoginThrottle(settings.max_failed_logins, settings.lockout_s, clock),
                settings.allow_anonymous,
                on_event,
            )
        )
        self.nodes: MachineNodes | None = None
        self._written: dict[str, Any] = {}
        self._last: MachineSnapshot | None = None
        self._last_time = clock()
        self._times = StateTimes()
        self._argument_type: type = object
        self._saved_at = clock()
        self._counted_total = -1
        self._recount_until = -1.0
        self._counted_at = -RECOUNT_EVERY_S
        self._start_counts: dict[str, int] | None = None
        self._events: Any = None
        self._source_time = datetime.now(UTC)

    # ------------------------------------------------------------------ start and stop

    async def start(self) -> None:
        for warning in self.settings.insecure_choices():
            log.warning(
                "OPC UA: %s is on ([opcua] configuration); use it for commissioning only", warning
            )
        await self.server.init()
        await self.server.set_application_uri(APPLICATION_URI)
        self.server.set_server_name("Stave jointer")
        self.server.set_endpoint(self.settings.endpoint_url)
        self.server.set_security_policy(
            security_policies(self.settings), permission_ruleset=PlantRuleset()
        )
        tokens: list[type] = [ua.UserNameIdentityToken]
        if self.settings.allow_anonymous:
            tokens.append(ua.AnonymousIdentityToken)
        self.server.set_identity_tokens(tokens)
        self.trust.create_folders()
        await setup_self_signed_certificate(
            self.trust.key_file,
            self.trust.certificate_file,
            APPLICATION_URI,
            socket.gethostname(),
            [ExtendedKeyUsageOID.SERVER_AUTH, ExtendedKeyUsageOID.CLIENT_AUTH],
            {
                "commonName": "stave-jointer OPC UA server",
                "organizationName": self.settings.manufacturer,
            },
        )
        self.trust.key_file.chmod(0o600)
        await self.server.load_certificate(str(self.trust.certificate_file))
        await self.server.load_private_key(str(self.trust.key_file))
        self.server.set_certificate_validator(self._validate_client)
        await load_models(self.server, self._nodesets_dir)
        self.nodes = await build_machine(self.server, self.settings)
        self._argument_type = await complete_argument_type(self.server, self.nodes.ww)
        self._times = load_state_times(self.db_path, time.time())
        await self._add_methods(self.nodes)
        self._events = await self.server.get_event_generator(
            ua.NodeId(WW_BASE_EVENT_TYPE_ID, self.nodes.ww), self.nodes.events.nodeid
        )
        # asyncua takes a property's variant type from its (empty) default value: name them.
        for name, vtype in _EVENT_FIELD_TYPES.items():
            self._events.event.data_types[name] = vtype
        await self.publish(None)
        await self.server.start()
        log.info("OPC UA server listening on %s", self.settings.endpoint_url)

    async def stop(self) -> None:
        self._save_times()
        await self.server.stop()

    def _save_times(self) -> None:
        """Keep the absolute state times (a busy or missing database costs only this save)."""
        self._saved_at = self._clock()
        try:
            save_state_times(self._times, self.db_path, time.time())
        except Exception as exc:  # the plant connection outlives a database that is busy
            log.warning("OPC UA: state times not saved: %s", exc)

    async def _validate_client(
        self, cert: x509.Certificate, _app: ua.ApplicationDescription
    ) -> None:
        der = cert.public_bytes(Encoding.DER)
        if not self.trust.check_time(der):
            raise ServiceError(ua.StatusCodes.BadCertificateTimeInvalid)
        if not self.trust.is_trusted(der):
            print_ = self.trust.note_rejected(der)
            log.warning("OPC UA client certificate %s refused: not in the trust list", print_)
            self._on_event(f"client certificate {print_} refused: not trusted")
            raise ServiceError(ua.StatusCodes.BadCertificateUntrusted)

    # ------------------------------------------------------------------ jobs

    async def _add_methods(self, nodes: MachineNodes) -> None:
        def arg(name: str, type_id: int, text: str) -> ua.Argument:
            argument = ua.Argument()
            argument.Name = name
            argument.DataType = ua.NodeId(type_id)
            argument.ValueRank = -1
            argument.Description = ua.LocalizedText(text)
            return argument

        outputs = [
            arg("Accepted", ua.ObjectIds.Boolean, "true if the job was accepted"),
            arg("Message", ua.ObjectIds.String, "what happens, or why not (field, value, allowed)"),
        ]
        await nodes.specific.add_method(
            ua.NodeId("StaveJointer.SelectRecipe", nodes.own_ns),
            ua.QualifiedName("SelectRecipe", nodes.own_ns),
            self._select_recipe,
            [arg("RecipeName", ua.ObjectIds.String, "the name of a stored recipe")],
            outputs,
        )
        await nodes.specific.add_method(
            ua.NodeId("StaveJointer.DownloadRecipe", nodes.own_ns),
            ua.QualifiedName("DownloadRecipe", nodes.own_ns),
            self._download_recipe,
            [
                arg(
                    "RecipeJson",
                    ua.ObjectIds.String,
                    "one recipe as recipe export writes it (JSON)",
                )
            ],
            outputs,
        )

    @staticmethod
    def _answer(accepted: bool, message: str) -> list[ua.Variant]:
        return [
            ua.Variant(accepted, ua.VariantType.Boolean),
            ua.Variant(message, ua.VariantType.String),
        ]

    async def _select_recipe(self, _parent: ua.NodeId, name: Any) -> list[ua.Variant]:
        text = name.Value if isinstance(name, ua.Variant) else name
        if not isinstance(text, str):
            return self._answer(False, "RecipeName is not allowed: a string")
        with Database.open(self.db_path, load_samples=False) as db:
            recipe = db.get_recipe_by_name(text)
        if recipe is None or recipe.id is None:
            return self._answer(
                False, f"RecipeName = {text!r} is not allowed: the name of a stored recipe"
            )
        return await self._queue_job(PlantJob(recipe.id, recipe.name, CALLER.get() or "?"))

    async def _download_recipe(self, _parent: ua.NodeId, document: Any) -> list[ua.Variant]:
        text = document.Value if isinstance(document, ua.Variant) else document
        if not isinstance(text, str) or len(text) > 65536:
            return self._answer(False, "RecipeJson is not allowed: a JSON text of at most 64 KiB")
        user = CALLER.get() or "?"
        with Database.open(self.db_path, load_samples=False) as db:
            with tempfile.TemporaryDirectory(prefix="stave-opcua-") as tmp:
                path = Path(tmp) / "download.json"
                path.write_text(text, encoding="utf-8")
                try:
                    valid, rejected = read_recipes(path, db.limits)
                except RecipeFileError as exc:
                    return self._answer(False, str(exc).replace(str(path), "RecipeJson"))
            if rejected:
                return self._answer(False, "; ".join(rejected[0].lines()))
            if len(valid) != 1:
                return self._answer(
                    False, f"RecipeJson holds {len(valid)} recipes: allowed exactly one"
                )
            stored = db.save_plant_recipe(valid[0][1], user)
        log.info("OPC UA: recipe %r downloaded by %s", stored.name, user)
        assert stored.id is not None
        return await self._queue_job(PlantJob(stored.id, stored.name, user))

    async def _queue_job(self, job: PlantJob) -> list[ua.Variant]:
        self.jobs.request(job)
        log.info("OPC UA: %s", job.notice(done=False))
        self._on_event(job.notice(done=False))
        await self._apply_jobs(self._last)
        return self._answer(True, self.jobs.notice())

    async def _apply_jobs(self, snapshot: MachineSnapshot | None) -> None:
        command = self.jobs.due(snapshot)
        if command is not None:
            self._send(command)
            self._on_event(self.jobs.notice())
        await self._write_own("PlantJob", self.jobs.notice(), ua.VariantType.String)

    # ------------------------------------------------------------------ publishing

    async def _write(self, key: str, node: Any, value: Any, vtype: ua.VariantType) -> None:
        if self._written.get(key, object()) == value:
            return
        self._written[key] = value
        # The source timestamp is when the machine's snapshot was taken, so a client sees
        # when the change happened, not when this process got to it.
        await node.write_value(
            ua.DataValue(ua.Variant(value, vtype), SourceTimestamp=self._source_time)
        )

    async def _write_own(self, name: str, value: Any, vtype: ua.VariantType) -> None:
        assert self.nodes is not None
        await self._write(f"own.{name}", self.nodes.own[name], value, vtype)

    async def publish(self, snapshot: MachineSnapshot | None) -> None:
        """Bring the address space up to ``snapshot`` (None: the machine process is gone)."""
        nodes = self.nodes
        if nodes is None:
            return
        self._source_time = datetime.fromtimestamp(
            snapshot.wall_time if snapshot is not None else time.time(), UTC
        )
        now = self._clock()
        flags = unit_flags(snapshot)
        state = unit_state(flags)
        # The flags of the snapshot before held over the time since it came.
        self._times.add(unit_flags(self._last), (now - self._last_time) * 1000.0)
        self._last_time = now
        if now - self._saved_at >= SAVE_EVERY_S:
            self._save_times()
        for name, value in flags.as_browse_names().items():
            if name in nodes.flags:
                await self._write(f"flag.{name}", nodes.flags[name], value, ua.VariantType.Boolean)
        await self._write("state", nodes.current_state, int(state), ua.VariantType.Int32)
        await self._write(
            "mode", nodes.current_mode, int(unit_mode(snapshot)), ua.VariantType.Int32
        )
        for name, ms in self._times.values().items():
            await self._write(name, nodes.values[name], ms, ua.VariantType.UInt64)
        if snapshot is not None:
            await self._publish_machine(snapshot)
            for change in alarm_changes(self._last.alarms if self._last else (), snapshot.alarms):
                await self._fire(change)
        await self._apply_jobs(snapshot)
        self._last = snapshot

    async def _publish_machine(self, snapshot: MachineSnapshot) -> None:
        nodes = self.nodes
        assert nodes is not None
        v = nodes.values
        await self._write(
            "AxisOverride",
            v["AxisOverride"],
            round(snapshot.feed_override_pct),
            ua.VariantType.UInt32,
        )
        cycle_s = snapshot.last_cycle_time_s
        per_min = 60.0 / cycle_s if cycle_s else 0.0
        await self._write("ActualCycle", v["ActualCycle"], per_min, ua.VariantType.Double)
        await self._write_own("SelectedRecipe", snapshot.recipe_name, ua.VariantType.String)
        await self._write_own("StateText", snapshot.state_text, ua.VariantType.String)
        await self._write_own("LastWidth_mm", snapshot.last_width_mm or 0.0, ua.VariantType.Double)
        await self._write_own("LastCycleTime_s", cycle_s or 0.0, ua.VariantType.Double)
        if snapshot.cycle.d_mm is not None:
            await self._write_own("LastD_mm", snapshot.cycle.d_mm, ua.VariantType.Double)
        if snapshot.cycle.r_mm is not None:
            await self._write_own("LastR_mm", snapshot.cycle.r_mm, ua.VariantType.Double)
        await self._write_own("PiecesThisShift", snapshot.pieces_shift, ua.VariantType.UInt64)
        await self._publish_barrel(snapshot.barrel)
        # The record of a board reaches the database a moment after the machine counts it
        # (its store writes in the background, later still when the database is busy): the
        # counters are read again for a while after each change of the machine's count.
        now = self._clock()
        if snapshot.pieces_total != self._counted_total:
            self._counted_total = snapshot.pieces_total
            self._recount_until = now + RECOUNT_S
            self._counted_at = -RECOUNT_EVERY_S
        if now <= self._recount_until and now - self._counted_at >= RECOUNT_EVERY_S:
            self._counted_at = now
            await self._publish_counts()

    async def _publish_barrel(self, barrel: BarrelView | None) -> None:
        """The barrel being raised; zeros and an empty gap when staves are cut singly."""
        done = barrel.staves_done if barrel else 0
        left = barrel.staves_left if barrel and barrel.staves_left is not None else 0
        gap = barrel.gap_mm if barrel and barrel.gap_mm is not None else 0.0
        u32 = ua.VariantType.UInt32
        await self._write_own("BarrelNumber", barrel.number if barrel else 0, u32)
        await self._write_own("BarrelStavesDone", done, u32)
        await self._write_own("BarrelStavesPlanned", done + left, u32)
        await self._write_own("BarrelGap_mm", gap, ua.VariantType.Double)
        await self._write_own(
            "BarrelClosed", bool(barrel and barrel.closed), ua.VariantType.Boolean
        )

    async def _publish_counts(self) -> None:
        """Counters from the database, the one record of every board (read when the
        machine's own count changes, so a client's counters match the records)."""
        nodes = self.nodes
        assert nodes is not None
        with Database.open(self.db_path, load_samples=False) as db:
            counts = run_counts(db)
            plan = ShiftPlan.from_parameters(db.get_parameters())
            feed_mm_s = db.get_parameter("xy_speed_mm_s")
            now = datetime.now(UTC)
            _, shift_start = current_shift(now, plan)
            shift_records = db.list_production(shift_start, now)
        if self._start_counts is None:
            self._start_counts = counts
        good, total = counts["ok"], sum(counts.values())
        aborted = total - good
        start = self._start_counts
        start_good, start_total = start["ok"], sum(start.values())
        v = nodes.values
        u64 = ua.VariantType.UInt64
        await self._write("AbsolutePiecesOut", v["AbsolutePiecesOut"], good, u64)
        await self._write("AbsoluteRunsGood", v["AbsoluteRunsGood"], good, u64)
        await self._write("AbsoluteRunsAborted", v["AbsoluteRunsAborted"], aborted, u64)
        await self._write("AbsoluteRunsTotal", v["AbsoluteRunsTotal"], total, u64)
        await self._write("RelativePiecesOut", v["RelativePiecesOut"], good - start_good, u64)
        await self._write("RelativeRunsGood", v["RelativeRunsGood"], good - start_good, u64)
        await self._write(
            "RelativeRunsAborted",
            v["RelativeRunsAborted"],
            aborted - (start_total - start_good),
            u64,
        )
        await self._write("RelativeRunsTotal", v["RelativeRunsTotal"], total - start_total, u64)
        await self._write("FeedSpeed", v["FeedSpeed"], feed_mm_s * 0.06, ua.VariantType.Double)
        await self._write_own(
            "ShiftProductionCsv", production_to_csv(shift_records), ua.VariantType.String
        )

    async def _fire(self, change: AlarmChange) -> None:
        """One woodworking event per ISA-18.2 transition."""
        alarm = change.alarm
        titles = alarm_titles(alarm.code)
        event = self._events.event
        event.MessageId = alarm.code
        event.MessageName = alarm.code
        event.EventCategory = _EVENT_CATEGORY.get(alarm.severity, 0)
        event.Group = alarm.source or "machine"
        event.PathParts = ["StaveJointer", alarm.source] if alarm.source else ["StaveJointer"]
        event.LocalizedMessages = [
            ua.LocalizedText(text, locale) for locale, text in titles.items()
        ]
        event.Arguments = message_arguments(alarm.arguments, self._argument_type)
        event.Severity = _SEVERITY.get(alarm.severity, 100)
        event.SourceName = "StaveJointer"
        event.SourceNode = self.nodes.machine.nodeid if self.nodes else ua.NodeId()
        state_text = change.to_state.value if change.to_state is not AlarmState.NORMAL else "normal"
        event.Message = ua.LocalizedText(f"{alarm.code} {alarm.text} [{state_text}]", "en")
        await self._events.trigger(time_attr=datetime.now(UTC))


def describe_endpoints(settings: OpcuaSettings) -> list[str]:
    """What ``stave opcua endpoints`` prints: one line per endpoint the server offers."""
    lines = []
    for policy in security_policies(settings):
        name = policy.name
        tokens = "UserName" + (", Anonymous" if settings.allow_anonymous else "")
        lines.append(f"{settings.endpoint_url}  {name}  users: {tokens}")
    return lines
