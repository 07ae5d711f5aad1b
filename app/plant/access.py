"""Who may do what on the plant connection.

Why a ruleset of our own: asyncua's default lets any logged-in user write attributes. Here
nobody may write anything (the model is read-only; a job is a method with checked input),
``read-only`` users may browse, read and subscribe, and only ``plant`` users may call methods.
The user of a method call is remembered for the call (a context variable of the request's
task), so a job records who asked.
"""

from __future__ import annotations

import contextvars
import logging
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from asyncua import ua
from asyncua.crypto.permission_rules import PermissionRuleset, User, UserRole
from asyncua.server.user_managers import UserManager

from app.data.database import Database
from app.data.plant_users import PlantRole, authenticate_plant_user
from app.plant.login_throttle import LoginThrottle

log = logging.getLogger(__name__)

_READ = (
    ua.ObjectIds.CreateSessionRequest_Encoding_DefaultBinary,
    ua.ObjectIds.CloseSessionRequest_Encoding_DefaultBinary,
    ua.ObjectIds.ActivateSessionRequest_Encoding_DefaultBinary,
    ua.ObjectIds.ReadRequest_Encoding_DefaultBinary,
    ua.ObjectIds.BrowseRequest_Encoding_DefaultBinary,
    ua.ObjectIds.BrowseNextRequest_Encoding_DefaultBinary,
    ua.ObjectIds.GetEndpointsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.FindServersRequest_Encoding_DefaultBinary,
    ua.ObjectIds.TranslateBrowsePathsToNodeIdsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.CreateSubscriptionRequest_Encoding_DefaultBinary,
    ua.ObjectIds.ModifySubscriptionRequest_Encoding_DefaultBinary,
    ua.ObjectIds.DeleteSubscriptionsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.TransferSubscriptionsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.CreateMonitoredItemsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.ModifyMonitoredItemsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.DeleteMonitoredItemsRequest_Encoding_DefaultBinary,
    ua.ObjectIds.PublishRequest_Encoding_DefaultBinary,
    ua.ObjectIds.RepublishRequest_Encoding_DefaultBinary,
    ua.ObjectIds.CloseSecureChannelRequest_Encoding_DefaultBinary,
    ua.ObjectIds.SetMonitoringModeRequest_Encoding_DefaultBinary,
    ua.ObjectIds.SetPublishingModeRequest_Encoding_DefaultBinary,
    ua.ObjectIds.RegisterNodesRequest_Encoding_DefaultBinary,
    ua.ObjectIds.UnregisterNodesRequest_Encoding_DefaultBinary,
)
_CALL = ua.NodeId(ua.ObjectIds.CallRequest_Encoding_DefaultBinary)
_READ_IDS = frozenset(ua.NodeId(i) for i in _READ)

# The user name of the method call being carried out ("" outside a call).
CALLER: contextvars.ContextVar[str] = contextvars.ContextVar("opcua_caller", default="")


@dataclass
class PlantSessionUser(User):  # type: ignore[misc]
    plant_role: PlantRole = PlantRole.READ_ONLY


class PlantRuleset(PermissionRuleset):  # type: ignore[misc]
    def check_validity(self, user: Any, action_type_id: ua.NodeId, body: Any) -> bool:
        if action_type_id in _READ_IDS:
            return isinstance(user, PlantSessionUser) or user is None
        allowed = (
            action_type_id == _CALL
            and isinstance(user, PlantSessionUser)
            and user.plant_role is PlantRole.PLANT
        )
        if allowed:
            CALLER.set(user.name or "")
        return allowed


class PlantUserManager(UserManager):  # type: ignore[misc]
    """User name and password against the database's ``opcua_users``, throttled."""

    def __init__(
        self,
        db_path: Path,
        throttle: LoginThrottle,
        allow_anonymous: bool,
        on_refused: Callable[[str], None] = lambda _reason: None,
    ) -> None:
        self._db_path = db_path
        self._throttle = throttle
        self._allow_anonymous = allow_anonymous
        self._on_refused = on_refused

    def get_user(
        self,
        iserver: Any,
        username: str | None = None,
        password: str | None = None,
        certificate: Any = None,
    ) -> User | None:
        if username is None:
            if self._allow_anonymous:
                return PlantSessionUser(role=UserRole.User, name="anonymous")
            self._on_refused("anonymous login refused")
            return None
        locked_s = self._throttle.locked_for_s(username)
        if locked_s > 0:
            log.warning("OPC UA login of %r refused: locked for %.0f s more", username, locked_s)
            self._on_refused(f"login of {username!r} refused: locked")
            return None
        with Database.open(self._db_path, load_samples=False) as db:
            found = authenticate_plant_user(db, username, password or "")
        if found is None:
            self._throttle.failed(username)
            log.warning("OPC UA login of %r refused: wrong user name or password", username)
            self._on_refused(f"login of {username!r} refused: wrong user name or password")
            return None
        self._throttle.succeeded(username)
        log.info("OPC UA login of %r (%s)", found.name, found.role.value)
        return PlantSessionUser(role=UserRole.User, name=found.name, plant_role=found.role)


def monotonic_clock() -> float:
    return time.monotonic()
