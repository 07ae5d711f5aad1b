"""The System screen's OPC UA page: the plant connection's state, its security, and the
client certificates it refused, with a button to trust one.

Why here and not over OPC UA: the panel is where a technician stands when a plant system
cannot connect. The page reads what the operator application knows of the server (a
``PlantStatus``) and the trust folder through the same functions ``stave opcua trust``
uses; trusting a certificate moves it into ``trusted/``, which the server reads at the next
connection (no restart). Trusting needs the service level and is logged with the user.
"""

from __future__ import annotations

import logging
import math
import time
from collections.abc import Callable

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractItemView,
    QFrame,
    QHBoxLayout,
    QHeaderView,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from app.data.users import Role
from app.plant.status import PlantStatus
from app.plant.trust import CertificateInfo, TrustList
from app.screens.base import ScreenContext
from app.screens.widgets.buttons import touch_button
from app.screens.widgets.readouts import set_text, styled_label

log = logging.getLogger(__name__)

StatusSource = Callable[[], PlantStatus | None]
REFRESH_S = 2.0


class OpcuaPage(QFrame):
    def __init__(
        self, context: ScreenContext, status: StatusSource, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self.setObjectName("panel")
        self.context = context
        self.status = status
        self.rejected: list[CertificateInfo] = []
        self.refreshed_s = -math.inf  # monotonic time of the last refresh
        self.title = styled_label("", "title")
        self.state_label = styled_label("", "value", "opcuaState")
        self.state_label.setWordWrap(True)
        self.endpoint_label = styled_label("", "field", "opcuaEndpoint")
        self.endpoint_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.warning_label = styled_label("", "error", "opcuaWarning")
        self.warning_label.setWordWrap(True)
        self.rejected_title = styled_label("", "caption")
        self.table = QTableWidget(0, 3)
        self.table.setObjectName("rejectedCertificates")
        self.table.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectRows)
        self.table.setSelectionMode(QAbstractItemView.SelectionMode.SingleSelection)
        self.table.verticalHeader().setVisible(False)
        self.table.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        self.table.itemSelectionChanged.connect(self._selection_changed)
        self.trust_button = touch_button("trustCertificate", "primary")
        self.trust_button.clicked.connect(self.trust_selected)
        self.refresh_button = touch_button("refreshOpcua")
        self.refresh_button.clicked.connect(self.refresh)
        actions = QHBoxLayout()
        actions.addWidget(self.trust_button)
        actions.addWidget(self.refresh_button)
        actions.addStretch(1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(10, 6, 10, 8)
        layout.addWidget(self.title)
        layout.addWidget(self.state_label)
        layout.addWidget(self.endpoint_label)
        layout.addWidget(self.warning_label)
        layout.addWidget(self.rejected_title)
        layout.addWidget(self.table, 1)
        layout.addLayout(actions)
        self.retranslate()

    def retranslate(self) -> None:
        self.title.setText(self.tr("OPC UA plant connection"))
        self.rejected_title.setText(
            self.tr(
                "Client certificates refused (not trusted yet). A plant system connects only "
                "after its certificate is trusted:"
            )
        )
        self.table.setHorizontalHeaderLabels(
            [self.tr("Certificate"), self.tr("Application"), self.tr("Valid until")]
        )
        header = self.table.horizontalHeader()
        for column in range(3):
            header.setSectionResizeMode(
                column,
                QHeaderView.ResizeMode.Stretch
                if column < 2
                else QHeaderView.ResizeMode.ResizeToContents,
            )
        self.trust_button.setText(self.tr("Trust the selected certificate"))
        self.refresh_button.setText(self.tr("Refresh"))
        self.refresh()

    # -- what is shown ----------------------------------------------------------------------------

    def state_text(self, status: PlantStatus | None) -> str:
        if status is None or not status.settings.enabled:
            return self.tr("Server off ([opcua] enabled = false in the configuration).")
        if status.listening:
            return self.tr("Server running: plant systems can connect.")
        if status.failure:
            return self.tr("Server not running: %1").replace("%1", status.failure)
        if not status.running:
            return self.tr("Server not running: its process has ended (see opcua.log).")
        return self.tr("Server starting (loading the information model)...")

    def warning_text(self, status: PlantStatus | None) -> str:
        if status is None or not status.settings.enabled:
            return ""
        lines = []
        if status.settings.allow_security_none:
            lines.append(
                self.tr(
                    "Warning: security policy None is on: clients may connect without "
                    "signing or encryption."
                )
            )
        if status.settings.allow_anonymous:
            lines.append(
                self.tr("Warning: anonymous access is on: clients may read without a user.")
            )
        if lines:
            lines.append(self.tr("Use these for commissioning only ([opcua] configuration)."))
        return "\n".join(lines)

    def refresh_now_and_then(self) -> None:
        """While the page is shown: the server's state and new refusals every few seconds."""
        if time.monotonic() - self.refreshed_s >= REFRESH_S:
            self.refresh()

    def refresh(self) -> None:
        self.refreshed_s = time.monotonic()
        status = self.status()
        set_text(self.state_label, self.state_text(status))
        enabled = status is not None and status.settings.enabled
        set_text(
            self.endpoint_label,
            self.tr("Endpoint: %1").replace("%1", status.settings.endpoint_url)
            if status is not None and enabled
            else "",
        )
        self.endpoint_label.setVisible(enabled)
        warning = self.warning_text(status)
        set_text(self.warning_label, warning)
        self.warning_label.setVisible(bool(warning))
        rejected = TrustList(status.pki_dir).rejected() if status is not None else []
        if [c.thumbprint for c in rejected] == [c.thumbprint for c in self.rejected]:
            return  # the same certificates: keep the table and the technician's selection
        self.rejected = rejected
        self.table.setRowCount(len(self.rejected))
        for row, info in enumerate(self.rejected):
            cells = (
                f"{info.thumbprint}\n{info.subject}",
                info.application_uri,
                f"{info.not_after:%Y-%m-%d}",
            )
            for column, text in enumerate(cells):
                self.table.setItem(row, column, QTableWidgetItem(text))
        self.table.resizeRowsToContents()
        self.table.clearSelection()
        self._selection_changed()

    def _selected(self) -> CertificateInfo | None:
        rows = {index.row() for index in self.table.selectedIndexes()}
        return self.rejected[rows.pop()] if len(rows) == 1 else None

    def _selection_changed(self) -> None:
        self.trust_button.setEnabled(self._selected() is not None)

    # -- trusting ---------------------------------------------------------------------------------

    def trust_selected(self) -> None:
        info = self._selected()
        if info is not None:
            self.context.require(Role.SERVICE, lambda: self.trust(info.thumbprint))

    def trust(self, thumbprint: str) -> None:
        """Move a refused certificate into the trust list (the service level only)."""
        status = self.status()
        user = self.context.session.user
        if status is None or user is None or not self.context.session.can(Role.SERVICE):
            return
        try:
            info = TrustList(status.pki_dir).accept(thumbprint)
        except (ValueError, OSError) as exc:
            self.context.notify(str(exc))
            self.refresh()
            return
        log.info(
            "OPC UA client certificate %s (%s) trusted by %s (%s) on the panel",
            info.thumbprint,
            info.subject,
            user.name,
            user.role.name.lower(),
        )
        self.context.notify(
            self.tr("Certificate %1 trusted by %2 (logged).")
            .replace("%1", info.thumbprint[:12])
            .replace("%2", user.name)
        )
        self.refresh()
