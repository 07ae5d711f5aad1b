"""The System screen's OPC UA page: the server's state and endpoint, the warning for the
commissioning shortcuts, and a refused client certificate trusted at the service level."""

from __future__ import annotations

import logging
from dataclasses import replace
from pathlib import Path

from app.plant.settings import OpcuaSettings
from app.plant.status import LISTENING, PlantStatus
from app.plant.trust import TrustList
from tests.plant.certificates import client_certificate_der
from tests.screens.helpers import enter_pin, find_button
from tests.screens.test_other_screens import log_in


def test_opcua_page_shows_the_server_and_trusts_a_refused_certificate(
    qtbot, window, tap, tmp_path: Path, caplog
) -> None:
    log_in(qtbot, window, tap, "1234")  # technician
    tap(find_button(window, "nav_system"))
    tap(find_button(window, "group_opcua"))
    screen = window.page("system")
    page = screen.opcua_page
    assert screen.pages.currentWidget() is page
    # This window's link has no plant connection.
    assert page.state_label.text().startswith("Server off")
    assert page.warning_label.isHidden() and page.table.rowCount() == 0

    # A server with anonymous access on, which refused a client's certificate.
    trust = TrustList(tmp_path / "pki")
    trust.create_folders()
    thumbprint = trust.note_rejected(client_certificate_der("MES client", "urn:plant:mes"))
    settings = replace(OpcuaSettings(), enabled=True, allow_anonymous=True)
    status = PlantStatus(settings, trust.pki_dir, True, (f"{LISTENING} {settings.endpoint_url}",))
    page.status = lambda: status
    tap(find_button(window, "refreshOpcua"))
    assert page.state_label.text() == "Server running: plant systems can connect."
    assert settings.endpoint_url in page.endpoint_label.text()
    assert not page.warning_label.isHidden()
    assert "anonymous access is on" in page.warning_label.text()
    assert "security policy None" not in page.warning_label.text()
    assert page.table.rowCount() == 1 and thumbprint in page.table.item(0, 0).text()
    assert page.table.item(0, 1).text() == "urn:plant:mes"
    trust_button = find_button(window, "trustCertificate")
    assert not trust_button.isEnabled()  # nothing selected
    page.table.selectRow(0)
    caplog.set_level(logging.INFO, logger="app.screens.opcua_page")
    tap(trust_button)
    enter_pin(qtbot, window, tap, "9999")  # a technician is not enough: service
    assert trust.rejected() == [] and [c.thumbprint for c in trust.trusted()] == [thumbprint]
    assert page.table.rowCount() == 0
    assert any(
        thumbprint in r.getMessage() and "by service" in r.getMessage() for r in caplog.records
    )
    # A client refused while the page is shown appears by itself.
    trust.note_rejected(client_certificate_der("SCADA", "urn:plant:scada"))
    qtbot.waitUntil(lambda: page.table.rowCount() == 1, timeout=10_000)
    assert page.table.item(0, 1).text() == "urn:plant:scada"

    # In Slovenian, and a server that did not start.
    failed = PlantStatus(settings, trust.pki_dir, False, ("OPC UA server did not start: x",))
    page.status = lambda: failed
    tap(find_button(window, "languageButton"))
    tap(window.overlay().buttons[1])
    assert page.title.text() != "OPC UA plant connection"
    assert "OPC UA server did not start: x" in page.state_label.text()
    assert not page.state_label.text().startswith("Server")
