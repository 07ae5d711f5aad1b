"""The panel PC's Debian package, built by packaging/build-deb.sh and run from an unpacked root.

Why the real package: what breaks a packaged install is the packaging itself (a virtualenv
that still points at the build directory, a resource left out, a missing system library, a
unit file systemd refuses), so the package is built once per module (about half a minute with
a warm pip cache), unpacked with ``dpkg-deb -x`` into a temporary root, and its files are
checked and run from there with the system's Python, as /usr/bin/stave runs them. Installing
it (root, a running systemd) is not done here.

The kiosk test runs the package's kiosk wrapper in the real cage compositor (headless
backend) when cage and Xwayland are installed; elsewhere it is skipped with the reason.
"""

from __future__ import annotations

import importlib.machinery
import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest

import app
from app.config import load_config

pytestmark = [pytest.mark.slow, pytest.mark.timeout(900)]

REPO = Path(__file__).resolve().parents[2]
BUILD_SCRIPT = REPO / "packaging" / "build-deb.sh"
HELPERS = REPO / "packaging" / "helpers"
PREFIX = "opt/stave-jointer"
VERSION = f"{app.__version__}+test1"
KIOSK_LEAVE_EXIT_STATUS = 64
SOLVE_ARGS = ["solve", "--length", "1000", "--width", "150", "--length-ratio", "1/4"]
SOLVE_ARGS += ["--width-ratio", "3/4", "--json"]


def _debian_python() -> str:
    """Debian's python3.X the package is built with, or "" when this system has none."""
    target = os.path.realpath("/usr/bin/python3")
    if not re.fullmatch(r"/usr/bin/python3\.\d+", target):
        return ""
    check = "import sys, venv, ensurepip; sys.exit(sys.version_info < (3, 11))"
    if subprocess.run([target, "-c", check], capture_output=True, check=False).returncode:
        return ""
    return target


def _run(command: list[str], **options: Any) -> subprocess.CompletedProcess[str]:
    """Run a command, capturing its text output; the caller checks the exit status."""
    return subprocess.run(command, check=False, capture_output=True, text=True, **options)


@dataclass(frozen=True)
class Built:
    deb: Path
    root: Path  # the package unpacked with dpkg-deb -x
    python: str  # /usr/bin/python3.X


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> Built:
    if shutil.which("dpkg-deb") is None:
        pytest.skip("dpkg-deb not found: the package is built on Debian")
    python = _debian_python()
    if not python:
        pytest.skip("no Debian /usr/bin/python3 (3.11 or newer, with venv) to build with")
    out = tmp_path_factory.mktemp("deb")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONHOME", "PYTHONPATH")}
    done = subprocess.run(
        [str(BUILD_SCRIPT), "--version", VERSION, "--out", str(out)],
        capture_output=True,
        text=True,
        env=env,
        check=False,
    )
    assert done.returncode == 0, done.stderr[-5000:]
    deb = Path(done.stdout.strip().splitlines()[-1])
    root = tmp_path_factory.mktemp("root")
    subprocess.run(["dpkg-deb", "-x", str(deb), str(root)], check=True)
    return Built(deb, root, python)


def _env(built: Built, home: Path) -> dict[str, str]:
    """A clean environment: nothing of this test run's own Python leaks into the package's."""
    home.mkdir(exist_ok=True)
    return {
        "PATH": "/usr/bin:/bin",
        "HOME": str(home),
        "LANG": "C.UTF-8",
        "STAVE_RESOURCES": str(built.root / PREFIX / "resources"),
    }


def _relocated(built: Built, relative: str, dest: Path, **extra: str) -> Path:
    """A copy of an installed script with /opt/stave-jointer (and ``extra``) moved into the
    unpacked root, so that the script itself runs here."""
    text = (built.root / relative).read_text(encoding="utf-8")
    for old, new in {
        "/opt/stave-jointer": str(built.root / PREFIX),
        "/usr/bin/stave-jointer": str(built.root / "usr/bin/stave-jointer"),
        **extra,
    }.items():
        text = text.replace(old, new)
    dest.write_text(text, encoding="utf-8")
    dest.chmod(0o755)
    return dest


def _test_config(built: Built, tmp: Path) -> Path:
    """The package's /etc machine.toml with its /var paths moved into ``tmp``."""
    text = (built.root / "etc/stave-jointer/machine.toml").read_text(encoding="utf-8")
    text = text.replace("/var/lib/stave-jointer", str(tmp / "lib"))
    text = text.replace("/var/log/stave-jointer", str(tmp / "log"))
    path = tmp / "machine.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _load_script(path: Path, name: str) -> ModuleType:
    """Import a Python script installed without the .py suffix."""
    loader = importlib.machinery.SourceFileLoader(name, str(path))
    spec = importlib.util.spec_from_loader(name, loader)
    assert spec is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        loader.exec_module(module)
    finally:
        del sys.modules[name]
    return module


def _unit(path: Path) -> dict[str, list[str]]:
    """A systemd unit file's settings, ``Section.Key`` -> values (keys may repeat)."""
    settings: dict[str, list[str]] = {}
    section = ""
    for raw in path.read_text(encoding="utf-8").splitlines():
        line = raw.strip()
        if line.startswith("[") and line.endswith("]"):
            section = line[1:-1]
        elif line and not line.startswith("#") and "=" in line:
            key, value = line.split("=", 1)
            settings.setdefault(f"{section}.{key}", []).append(value)
    return settings


# ---- the package file and its control data ---------------------------------------------------


def test_file_name_version_and_architecture(built: Built):
    arch = subprocess.run(
        ["dpkg", "--print-architecture"], capture_output=True, text=True, check=True
    ).stdout.strip()
    assert built.deb.name == f"stave-jointer_{VERSION}_{arch}.deb"
    fields = subprocess.run(
        ["dpkg-deb", "--field", str(built.deb), "Package", "Version", "Architecture"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    assert fields.splitlines() == [
        "Package: stave-jointer",
        f"Version: {VERSION}",
        f"Architecture: {arch}",
    ]


def test_depends_on_the_interpreter_the_venv_links_to_and_the_kiosk_stack(built: Built):
    depends = subprocess.run(
        ["dpkg-deb", "--field", str(built.deb), "Depends"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    names = {d.strip().split(" ")[0] for d in depends.split(",")}
    interpreter = os.readlink(next((built.root / PREFIX / "venv/bin").glob("python3.*")))
    assert interpreter == built.python
    # The venv's bin/python links to this exact interpreter; cage 0.1.4 does not start
    # without Xwayland; Qt's wayland plugin needs libwayland-cursor and -egl.
    assert Path(interpreter).name in names
    assert "python3" in names  # the stdlib-only helpers run with /usr/bin/python3
    for needed in (
        "cage",
        "xwayland",
        "libegl1",
        "libgl1",
        "libwayland-client0",
        "libwayland-cursor0",
        "libwayland-egl1",
        "libxkbcommon0",
        "libfontconfig1",
        "fonts-dejavu-core",
        "iproute2",
        "adduser",
    ):
        assert needed in names, needed
    info = subprocess.run(
        ["dpkg-deb", "--info", str(built.deb)], capture_output=True, text=True, check=True
    ).stdout
    assert "python3 (>= 3.11)" in info


def test_conffiles_are_the_configuration_in_etc(built: Built, tmp_path: Path):
    subprocess.run(["dpkg-deb", "--control", str(built.deb), str(tmp_path)], check=True)
    conffiles = (tmp_path / "conffiles").read_text(encoding="utf-8").split()
    assert sorted(conffiles) == ["/etc/stave-jointer/kiosk.conf", "/etc/stave-jointer/machine.toml"]
    for conffile in conffiles:
        assert (built.root / conffile.lstrip("/")).is_file()
    for script in ("postinst", "prerm", "postrm"):
        assert os.access(tmp_path / script, os.X_OK), script
        syntax = _run(["sh", "-n", str(tmp_path / script)])
        assert syntax.returncode == 0, syntax.stderr
    assert "adduser --system" in (tmp_path / "postinst").read_text(encoding="utf-8")


# ---- the file layout ---------------------------------------------------------------------------


def test_layout(built: Built):
    root = built.root
    for executable in (
        "usr/bin/stave",
        "usr/bin/stave-jointer",
        "usr/sbin/stave-gauge-setup",
        "usr/lib/stave-jointer/stave-kiosk",
        "usr/lib/stave-jointer/stave-can-setup",
    ):
        assert os.access(root / executable, os.X_OK), executable
    for path in (
        "lib/systemd/system/stave-kiosk.service",
        "lib/systemd/system/stave-can@.service",
        "lib/udev/rules.d/70-stave-jointer.rules",
        "usr/share/doc/stave-jointer/INSTALL.md",
        f"{PREFIX}/resources/theme/stave.qss",
        f"{PREFIX}/resources/translations/stave_sl.qm",
        f"{PREFIX}/resources/recipes/sample_recipes.json",
        f"{PREFIX}/resources/machine-modbus.toml",
        f"{PREFIX}/resources/machine-canopen.toml",
        f"{PREFIX}/resources/machine-sim.toml",
    ):
        assert (root / path).is_file(), path
    for state in ("var/lib/stave-jointer", "var/log/stave-jointer"):
        assert (root / state).is_dir(), state
    # Every tool's default configuration is the machine's own, in /etc.
    link = root / PREFIX / "resources/machine.toml"
    assert os.readlink(link) == "../../../etc/stave-jointer/machine.toml"
    assert link.resolve() == (root / "etc/stave-jointer/machine.toml").resolve()
    # Development-only files stay out; so do the build tools.
    resources = root / PREFIX / "resources"
    assert not list(resources.rglob("*.py")) and not list(resources.rglob("*.ts"))
    site = next((root / PREFIX / "venv/lib").glob("python3.*/site-packages"))
    assert not list(site.glob("pip")) and not list(site.glob("setuptools"))
    assert (site / "app" / "__pycache__").is_dir()  # compiled: the service user cannot write


def test_nothing_names_the_build_directory(built: Built):
    """The venv was built in a staging directory and moved; no file may still point there."""
    cfg = (built.root / PREFIX / "venv/pyvenv.cfg").read_text(encoding="utf-8")
    assert "home = /usr/bin" in cfg
    leftovers = _run(["grep", "-rlF", "stave-deb.", str(built.root)])
    assert leftovers.returncode == 1, leftovers.stdout  # 1: no match
    shebang = (built.root / PREFIX / "venv/bin/stave").read_text(encoding="utf-8").splitlines()[0]
    assert shebang == "#!/opt/stave-jointer/venv/bin/python"
    pyc = next((built.root / PREFIX).rglob("app/cli/__pycache__/__init__.*.pyc"))
    assert b"/opt/stave-jointer/venv/lib/python3." in pyc.read_bytes()


def test_etc_configuration_keeps_state_under_var(built: Built):
    etc = built.root / "etc/stave-jointer/machine.toml"
    config = load_config(etc)
    assert config.database_path == "/var/lib/stave-jointer/stave.db"
    assert config.log_dir == "/var/log/stave-jointer"
    source = (REPO / "resources/machine.toml").read_text(encoding="utf-8").splitlines()
    packaged = etc.read_text(encoding="utf-8").splitlines()
    changed = [(a, b) for a, b in zip(source, packaged, strict=True) if a != b]
    assert [b.split("=")[0].strip() for _, b in changed] == ["path", "dir"]
    kiosk_conf = (built.root / "etc/stave-jointer/kiosk.conf").read_text(encoding="utf-8")
    assert re.search(r'^CAGE_OPTIONS="[^"]*"$', kiosk_conf, re.M)
    assert re.search(r'^STAVE_OPTIONS="[^"]*"$', kiosk_conf, re.M)


# ---- running the packaged program ---------------------------------------------------------------


def test_stave_version_from_the_unpacked_root(built: Built, tmp_path: Path):
    python = built.root / PREFIX / "venv/bin/python"
    where = subprocess.run(
        [str(python), "-c", "import app, sys; print(app.__file__); print(sys.prefix)"],
        capture_output=True,
        text=True,
        env=_env(built, tmp_path / "home"),
        cwd=tmp_path,
        check=True,
    ).stdout.split()
    app_file, prefix = where  # the unpacked package's code, not this checkout's
    assert Path(app_file).is_relative_to(built.root / PREFIX / "venv")
    assert prefix == str(built.root / PREFIX / "venv")
    done = subprocess.run(
        [str(python), "-m", "app.cli", "--version"],
        capture_output=True,
        text=True,
        env=_env(built, tmp_path / "home"),
        cwd=tmp_path,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"stave {app.__version__}"


def test_opcua_models_are_bundled_where_the_server_finds_them(built: Built, tmp_path: Path):
    python = built.root / PREFIX / "venv/bin/python"
    done = subprocess.run(
        [
            str(python),
            "-c",
            "from app.plant.nodesets import nodeset_files; print(len(nodeset_files()))",
        ],
        capture_output=True,
        text=True,
        env=_env(built, tmp_path / "home"),
        cwd=tmp_path,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "6"
    assert (
        built.root / PREFIX / "venv/share/opcua-nodesets/Opc.Ua.Woodworking.NodeSet2.xml"
    ).is_file()


def test_stave_solve_through_the_wrapper(built: Built, tmp_path: Path):
    wrapper = _relocated(built, "usr/bin/stave", tmp_path / "stave")
    env = _env(built, tmp_path / "home")
    del env["STAVE_RESOURCES"]  # the wrapper sets it
    done = _run([str(wrapper), *SOLVE_ARGS], env=env, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["D"] == pytest.approx(12.5026, abs=1e-4)
    assert result["W1"] == pytest.approx(112.5)
    bad = _run([str(wrapper), "solve", "--length", "-5", "--width", "150"], env=env, cwd=tmp_path)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr


def test_operator_application_renders_its_screens(built: Built, tmp_path: Path):
    """The packaged Qt, theme and translations: every screen rendered (offscreen)."""
    wrapper = _relocated(built, "usr/bin/stave-jointer", tmp_path / "stave-jointer")
    env = _env(built, tmp_path / "home") | {"QT_QPA_PLATFORM": "offscreen"}
    config = _test_config(built, tmp_path)
    done = _run(
        [str(wrapper), "--config", str(config), "--screenshots", str(tmp_path / "shots")],
        env=env,
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    shots = [Path(line) for line in done.stdout.split()]
    assert shots and all(p.suffix == ".png" and p.stat().st_size > 10_000 for p in shots)
    assert (tmp_path / "log" / "stave.log").is_file()  # [logging] dir of the config


def test_machine_process_starts_from_the_package(built: Built, tmp_path: Path):
    """The kiosk's machine runs in a spawned process: it must start with the wrapper's
    interpreter flags (-I -B) from the packaged venv."""
    script = (
        "import sys\n"
        "from pathlib import Path\n"
        "from app.config import load_config\n"
        "from app.machine.process_link import ProcessMachineLink\n"
        "link = ProcessMachineLink.start(load_config(sys.argv[1]), Path(sys.argv[2]), False)\n"
        "snapshot = link.wait_for_snapshot(60.0)\n"
        "print(type(snapshot).__name__)\n"
        "link.close()\n"
    )
    config = _test_config(built, tmp_path)
    python = str(built.root / PREFIX / "venv/bin/python")
    done = _run(
        [python, "-I", "-B", "-c", script, str(config), str(tmp_path / "machine.db")],
        env=_env(built, tmp_path / "home"),
        cwd=tmp_path,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert done.stdout.strip() == "MachineSnapshot"


# ---- systemd, the kiosk, udev, CAN ---------------------------------------------------------------


def test_kiosk_unit(built: Built):
    unit = _unit(built.root / "lib/systemd/system/stave-kiosk.service")
    assert unit["Service.User"] == ["stave"]
    assert unit["Service.PAMName"] == ["login"]
    assert unit["Service.TTYPath"] == ["/dev/tty1"]
    assert unit["Service.Restart"] == ["always"]
    assert unit["Service.RestartSec"] == ["2"]
    assert str(KIOSK_LEAVE_EXIT_STATUS) in unit["Service.RestartPreventExitStatus"][0].split()
    assert "getty@tty1.service" in unit["Unit.Conflicts"]
    assert "getty@tty1.service" in unit["Unit.OnFailure"]
    assert any("systemd-user-sessions.service" in v for v in unit["Unit.After"])
    exec_start = unit["Service.ExecStart"][0].split()
    assert exec_start[0] == "/usr/lib/stave-jointer/stave-kiosk"
    assert exec_start[1:7] == [
        "--kiosk",
        "--config",
        "/etc/stave-jointer/machine.toml",
        "--db",
        "/var/lib/stave-jointer/stave.db",
        "$STAVE_OPTIONS",
    ]
    assert unit["Install.WantedBy"] == ["graphical.target"]


def test_units_pass_systemd_analyze_verify(built: Built, tmp_path: Path):
    if shutil.which("systemd-analyze") is None or not Path("/lib/systemd/system").is_dir():
        pytest.skip("systemd-analyze or /lib/systemd/system not on this system")
    # A root with this system's units plus the package's, so that references resolve.
    verify_root = tmp_path / "verify"
    shutil.copytree("/lib/systemd/system", verify_root / "lib/systemd/system", symlinks=True)
    shutil.copytree(
        built.root / "lib/systemd/system", verify_root / "lib/systemd/system", dirs_exist_ok=True
    )
    shutil.copytree(built.root / "usr/lib/stave-jointer", verify_root / "usr/lib/stave-jointer")
    units = ["stave-kiosk.service", "stave-can@can0.service"]
    done = _run(["systemd-analyze", "verify", f"--root={verify_root}", *units])
    complaints = [line for line in done.stderr.splitlines() if "stave" in line]
    assert done.returncode == 0 and not complaints, done.stderr


def test_udev_rules_name_the_pinned_gauge_and_start_can_setup(built: Built):
    rules = (built.root / "lib/udev/rules.d/70-stave-jointer.rules").read_text(encoding="utf-8")
    gauge = next(line for line in rules.splitlines() if 'SYMLINK+="stave-gauge"' in line)
    assert 'ENV{STAVE_DEVICE}=="gauge"' in gauge and 'GROUP="dialout"' in gauge
    can = next(line for line in rules.splitlines() if "SYSTEMD_WANTS" in line)
    assert 'ENV{SYSTEMD_WANTS}+="stave-can@%k.service"' in can
    setup = _load_script(built.root / "usr/sbin/stave-gauge-setup", "stave_gauge_setup_installed")
    # The pin runs before the package's rule (udev reads all rules files in name order).
    assert setup.PIN_RULES.name < "70-stave-jointer.rules"
    ftdi = {
        "DEVNAME": "/dev/ttyUSB0",
        "SUBSYSTEM": "tty",
        "ID_BUS": "usb",
        "ID_VENDOR": "FTDI",
        "ID_MODEL": "FT232R_USB_UART",
        "ID_VENDOR_ID": "0403",
        "ID_MODEL_ID": "6001",
        "ID_SERIAL_SHORT": "A50285BI",
        "ID_USB_INTERFACE_NUM": "00",
        "ID_PATH": "pci-0000:00:14.0-usb-0:2:1.0",
    }
    rule = setup.pin_rule(ftdi).splitlines()[-1]
    assert rule == (
        'SUBSYSTEM=="tty", ENV{ID_VENDOR_ID}=="0403", ENV{ID_MODEL_ID}=="6001", '
        'ENV{ID_SERIAL_SHORT}=="A50285BI", ENV{ID_USB_INTERFACE_NUM}=="00", '
        'ENV{STAVE_DEVICE}="gauge"'
    )
    by_port = setup.pin_rule(ftdi, by_port=True).splitlines()[-1]
    assert by_port == (
        'SUBSYSTEM=="tty", ENV{ID_PATH}=="pci-0000:00:14.0-usb-0:2:1.0", ENV{STAVE_DEVICE}="gauge"'
    )
    no_serial = {k: v for k, v in ftdi.items() if k != "ID_SERIAL_SHORT"}
    assert "ENV{ID_PATH}==" in setup.pin_rule(no_serial)
    with pytest.raises(setup.SetupError, match="not a USB serial adapter"):
        setup.pin_rule(ftdi | {"ID_BUS": "pci"})
    with pytest.raises(setup.SetupError, match="ID_SERIAL_SHORT"):
        setup.pin_rule(ftdi | {"ID_SERIAL_SHORT": 'A5"0*'})
    assert setup.parse_properties("ID_BUS=usb\nDEVNAME=/dev/ttyUSB1\n") == {
        "ID_BUS": "usb",
        "DEVNAME": "/dev/ttyUSB1",
    }


def _can_setup(built: Built, config: Path, *args: str) -> subprocess.CompletedProcess[str]:
    script = str(built.root / "usr/lib/stave-jointer/stave-can-setup")
    command = [built.python, script, "--config", str(config), "--dry-run", *args]
    return _run(command, env={"PATH": "/usr/bin:/bin"})


def test_can_setup_uses_the_bitrate_of_machine_toml(built: Built, tmp_path: Path):
    sample = built.root / PREFIX / "resources/machine-canopen.toml"
    done = _can_setup(built, sample, "up", "can0")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[1:] == [
        "ip link set can0 down",
        "ip link set can0 type can bitrate 1000000 restart-ms 100",
        "ip link set can0 up",
    ]
    other = _can_setup(built, sample, "up", "can1")
    assert other.returncode == 0 and "left alone" in other.stdout and "ip link" not in other.stdout
    panel = built.root / "etc/stave-jointer/machine.toml"  # the simulated machine: no CAN
    assert "left alone" in _can_setup(built, panel, "up", "can0").stdout
    slow = tmp_path / "slow.toml"
    slow.write_text(
        sample.read_text(encoding="utf-8").replace("bitrate = 1000000", "bitrate = 500000"),
        encoding="utf-8",
    )
    assert "bitrate 500000" in _can_setup(built, slow, "up", "can0").stdout
    assert _can_setup(built, slow, "down", "can0").stdout.splitlines()[1:] == [
        "ip link set can0 down"
    ]
    wrong = tmp_path / "wrong.toml"
    wrong.write_text(
        sample.read_text(encoding="utf-8").replace("bitrate = 1000000", "bitrate = 300000"),
        encoding="utf-8",
    )
    bad = _can_setup(built, wrong, "up", "can0")
    assert bad.returncode == 2
    assert "backend.canopen.bitrate = 300000 is not allowed: one of" in bad.stderr


def test_can_setup_accepts_the_bitrates_of_the_canopen_backend(built: Built):
    from app.drivers.canopen.settings import BITRATES

    setup = _load_script(built.root / "usr/lib/stave-jointer/stave-can-setup", "can_setup_inst")
    assert setup.BITRATES == BITRATES


# ---- the kiosk in the real cage compositor ------------------------------------------------------


@pytest.fixture
def kiosk_dir(built: Built) -> Iterator[Path]:
    """A world-readable copy of the package: cage refuses to run as root, so as root the
    kiosk runs as nobody (65534), who cannot enter pytest's private temporary directories."""
    if shutil.which("cage") is None or not Path("/usr/bin/Xwayland").exists():
        missing = "cage and Xwayland are not installed (apt-get install cage xwayland)"
        if os.environ.get("CI"):  # scripts/ensure-env.sh installs them for the tests
            pytest.fail(missing)
        pytest.skip(missing)
    place = Path(tempfile.mkdtemp(prefix="stave-kiosk-test-"))
    try:
        place.chmod(0o755)
        subprocess.run(["dpkg-deb", "-x", str(built.deb), str(place / "root")], check=True)
        for sub in ("home", "runtime", "xdg", "lib", "log", "shots"):
            (place / sub).mkdir()
        if os.geteuid() == 0:
            for sub in ("home", "runtime", "xdg", "lib", "log", "shots"):
                os.chown(place / sub, 65534, 65534)
        (place / "xdg").chmod(0o700)
        moved = Built(built.deb, place / "root", built.python)
        for script in ("usr/bin/stave-jointer", "usr/lib/stave-jointer/stave-kiosk"):
            _relocated(moved, script, place / "root" / script)
        yield place
    finally:
        shutil.rmtree(place, ignore_errors=True)


def _kiosk(place: Path, *args: str) -> subprocess.CompletedProcess[str]:
    """The package's stave-kiosk (moved into ``place``) as stave-kiosk.service runs it."""
    kiosk = place / "root/usr/lib/stave-jointer/stave-kiosk"
    env = {
        "PATH": "/usr/bin:/bin",
        "HOME": str(place / "home"),
        "LANG": "C.UTF-8",
        "XDG_RUNTIME_DIR": str(place / "xdg"),
        "RUNTIME_DIRECTORY": str(place / "runtime"),
        # As stave-kiosk.service and kiosk.conf set them:
        "QT_QPA_PLATFORM": "wayland",
        "WLR_LIBINPUT_NO_DEVICES": "1",
        "CAGE_OPTIONS": "-d",
        # No screen here: wlroots' headless backend with its software renderer.
        "WLR_BACKENDS": "headless",
        "WLR_RENDERER": "pixman",
    }
    as_user = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"]
    command = [*(as_user if os.geteuid() == 0 else []), str(kiosk), *args]
    return _run(command, env=env, cwd=place, timeout=120)


def test_kiosk_runs_the_application_in_cage_and_passes_its_exit_status_on(
    built: Built, kiosk_dir: Path
):
    config = _test_config(Built(built.deb, kiosk_dir / "root", built.python), kiosk_dir)
    config.chmod(0o644)
    shown = _kiosk(kiosk_dir, "--config", str(config), "--screenshots", "shots")
    assert shown.returncode == 0, shown.stderr[-3000:]
    assert len(list((kiosk_dir / "shots").glob("*.png"))) >= 1  # rendered on cage's display
    # cage 0.1.4 itself exits 0 whatever its application returned; the wrapper must not.
    broken = _kiosk(kiosk_dir, "--config", str(kiosk_dir / "missing.toml"))
    assert broken.returncode == 2, broken.stderr[-3000:]
    assert "configuration error" in broken.stderr
