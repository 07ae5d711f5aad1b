"""The server's PKI folder: its own certificate, and the client certificates it trusts.

Layout (``[opcua] pki_dir``, by default ``opcua-pki`` beside the database)::

    own/cert.der  own/key.pem   the server's application certificate, made on first start
    trusted/<thumbprint>.der    client certificates a technician accepted
    rejected/<thumbprint>.der   client certificates that tried to connect and were refused

Why files and thumbprints: this is the OPC UA convention (a technician copies a certificate
into ``trusted`` or accepts it with ``stave opcua trust accept``); the trust list is read at
every connection, so an accepted client can connect at once, without a restart. A refused
certificate is kept in ``rejected`` so the System screen and the command line can show it.
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

from cryptography import x509

_THUMBPRINT = re.compile(r"^[0-9a-f]{40}$")


def thumbprint(der: bytes) -> str:
    """SHA-1 of the DER certificate, as OPC UA identifies certificates (lowercase hex)."""
    return hashlib.sha1(der, usedforsecurity=False).hexdigest()


@dataclass(frozen=True)
class CertificateInfo:
    thumbprint: str
    subject: str
    application_uri: str
    not_after: datetime

    def line(self) -> str:
        return (
            f"{self.thumbprint}  {self.subject}  {self.application_uri}  "
            f"valid until {self.not_after:%Y-%m-%d}"
        )


def describe(der: bytes) -> CertificateInfo:
    cert = x509.load_der_x509_certificate(der)
    try:
        san = cert.extensions.get_extension_for_class(x509.SubjectAlternativeName)
        uris = san.value.get_values_for_type(x509.UniformResourceIdentifier)
    except x509.ExtensionNotFound:
        uris = []
    return CertificateInfo(
        thumbprint(der),
        cert.subject.rfc4514_string(),
        uris[0] if uris else "",
        cert.not_valid_after_utc,
    )


class TrustList:
    def __init__(self, pki_dir: Path) -> None:
        self.pki_dir = pki_dir
        self.own_dir = pki_dir / "own"
        self.trusted_dir = pki_dir / "trusted"
        self.rejected_dir = pki_dir / "rejected"

    def create_folders(self) -> None:
        for folder in (self.own_dir, self.trusted_dir, self.rejected_dir):
            folder.mkdir(parents=True, exist_ok=True)
        self.own_dir.chmod(0o700)

    @property
    def certificate_file(self) -> Path:
        return self.own_dir / "cert.der"

    @property
    def key_file(self) -> Path:
        return self.own_dir / "key.pem"

    def _list(self, folder: Path) -> list[CertificateInfo]:
        if not folder.is_dir():
            return []
        found = []
        for path in sorted(folder.glob("*.der")):
            try:
                found.append(describe(path.read_bytes()))
            except (OSError, ValueError):
                continue
        return found

    def trusted(self) -> list[CertificateInfo]:
        return self._list(self.trusted_dir)

    def rejected(self) -> list[CertificateInfo]:
        return self._list(self.rejected_dir)

    def is_trusted(self, der: bytes) -> bool:
        return (self.trusted_dir / f"{thumbprint(der)}.der").is_file()

    def note_rejected(self, der: bytes) -> str:
        """Keep a refused certificate for a technician to look at; returns its thumbprint."""
        print_ = thumbprint(der)
        self.rejected_dir.mkdir(parents=True, exist_ok=True)
        target = self.rejected_dir / f"{print_}.der"
        if not target.exists():
            target.write_bytes(der)
        return print_

    def _move(self, print_: str, source: Path, target: Path, what: str) -> CertificateInfo:
        key = print_.strip().lower()
        if not _THUMBPRINT.match(key):
            raise ValueError(f"thumbprint = {print_!r} is not allowed: 40 hexadecimal digits")
        path = source / f"{key}.der"
        if not path.is_file():
            raise ValueError(f"thumbprint = {print_!r} is not allowed: not a {what} certificate")
        target.mkdir(parents=True, exist_ok=True)
        info = describe(path.read_bytes())
        path.replace(target / path.name)
        return info

    def accept(self, print_: str) -> CertificateInfo:
        """A rejected certificate becomes trusted."""
        return self._move(print_, self.rejected_dir, self.trusted_dir, "rejected")

    def reject(self, print_: str) -> CertificateInfo:
        """A trusted certificate is no longer trusted (kept in ``rejected``)."""
        return self._move(print_, self.trusted_dir, self.rejected_dir, "trusted")

    def check_time(self, der: bytes) -> bool:
        cert = x509.load_der_x509_certificate(der)
        now = datetime.now(UTC)
        return cert.not_valid_before_utc <= now <= cert.not_valid_after_utc
