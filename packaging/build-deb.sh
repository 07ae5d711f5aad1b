#!/usr/bin/env bash
# Build the Debian package of the stave jointer for the panel PC (Debian 12).
#
#   packaging/build-deb.sh [--version V] [--out DIR] [--python PATH] [--maintainer "N <M>"]
#                          [--compression zstd|xz|gzip|none] [--update-lock]
#
# Writes DIR/stave-jointer_<version>_<arch>.deb (DIR defaults to packaging/build; the version
# to app.__version__). The package holds the application with all its Python dependencies in
# a virtualenv under /opt/stave-jointer, so installing needs no network; building does (pip
# fetches the wheels pinned in packaging/requirements.lock, through pip's usual index, cache
# and configuration). --update-lock resolves the dependencies afresh from pyproject.toml and
# rewrites the lock file (do it when pyproject.toml's dependencies change).
#
# Why the virtualenv is built in a staging directory and then moved: it is created with the
# panel's interpreter (Debian's /usr/bin/python3.X, the same on the build machine), so its
# bin/python links to a path the panel has; the few text files that name the staging
# directory (script shebangs, activate, pyvenv.cfg) are rewritten to /opt/stave-jointer/venv,
# the .pyc files are compiled with their final paths, and a check refuses any file that still
# names the staging directory. The wrappers /usr/bin/stave and /usr/bin/stave-jointer run
# the venv's python explicitly and so depend on no shebang.
set -euo pipefail
umask 022

here="$(cd "$(dirname "$0")" && pwd)"
repo="$(dirname "$here")"
prefix=/opt/stave-jointer

die() {
  echo "build-deb: $*" >&2
  exit 2
}
step() { echo "build-deb: $*" >&2; }

version=""
out="$here/build"
python=/usr/bin/python3
maintainer="Stave jointer software <stave-jointer@localhost>"
compression=zstd
update_lock=0
while [ $# -gt 0 ]; do
  case "$1" in
    --version) [ $# -ge 2 ] || die "--version needs a value"; version="$2"; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a directory"; out="$2"; shift 2 ;;
    --python) [ $# -ge 2 ] || die "--python needs a path"; python="$2"; shift 2 ;;
    --maintainer) [ $# -ge 2 ] || die "--maintainer needs a value"; maintainer="$2"; shift 2 ;;
    --compression) [ $# -ge 2 ] || die "--compression needs a value"; compression="$2"; shift 2 ;;
    --update-lock) update_lock=1; shift ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed -e '$d' -e 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown option '$1' (see --help)" ;;
  esac
done

# ---- checks: tools, interpreter, version ------------------------------------------------
command -v dpkg-deb >/dev/null 2>&1 || die "dpkg-deb not found: build on Debian (package dpkg)"
arch="$(dpkg --print-architecture)"
case "$compression" in xz | zstd | gzip | none) ;; *)
  die "--compression '$compression' is not allowed: xz, zstd, gzip or none" ;;
esac

interpreter="$(readlink -f "$python" 2>/dev/null || true)"
case "$interpreter" in
  /usr/bin/python3.[0-9]*) ;;
  *) die "--python '$python' is '$interpreter'; the virtualenv must link to Debian's" \
    "/usr/bin/python3.X, which the panel has (install python3 and python3-venv)" ;;
esac
py_version="$("$interpreter" -c 'import sys; print("%d.%d" % sys.version_info[:2])')"
"$interpreter" -c 'import sys; sys.exit(sys.version_info < (3, 11))' ||
  die "Python 3.11 or newer is needed ($interpreter is $py_version)"
"$interpreter" -c 'import ensurepip, venv' 2>/dev/null ||
  die "the venv module is missing: sudo apt-get install python${py_version}-venv"

app_version="$(sed -n 's/^__version__ = "\(.*\)"$/\1/p' "$repo/app/__init__.py")"
[ -n "$app_version" ] || die "no __version__ = \"...\" line in app/__init__.py"
version="${version:-$app_version}"
[[ "$version" =~ ^[0-9][A-Za-z0-9.+~-]*$ ]] ||
  die "--version '$version' is not allowed: a Debian version, a digit first, then" \
    "letters, digits and . + ~ - (e.g. 0.1.0 or 0.1.0-2)"
if [ "${version%%[-+~]*}" != "$app_version" ]; then
  step "note: package version $version, but the application says $app_version (app/__init__.py)"
fi
case "$maintainer" in *[\|\&]* | "") die "--maintainer '$maintainer' is not allowed: 'Name <mail>' without | and &" ;; esac
mkdir -p "$out"
out="$(cd "$out" && pwd)"
lock="$here/requirements.lock"

work="$(mktemp -d "${TMPDIR:-/tmp}/stave-deb.XXXXXX")"
trap 'rm -rf "$work"' EXIT
root="$work/root"
venv="$root$prefix/venv"

# ---- the virtualenv with the application and its dependencies --------------------------
step "virtualenv with $interpreter (Python $py_version)"
"$interpreter" -m venv "$venv"
vpy="$venv/bin/python"
pip=("$vpy" -m pip --disable-pip-version-check --no-input -q)

step "wheel of the application"
# From a copy: building in the checkout would leave build/ and *.egg-info behind in it.
mkdir "$work/src"
(cd "$repo" && tar --exclude=__pycache__ --exclude='*.pyc' -cf - pyproject.toml README.md app) |
  (cd "$work/src" && tar -xf -)
"${pip[@]}" wheel --no-deps -w "$work/wheels" "$work/src"
wheel="$(echo "$work"/wheels/stave_jointer-*.whl)"
[ -f "$wheel" ] || die "pip wheel made no stave_jointer wheel"

step "dependencies ($([ $update_lock = 1 ] && echo "resolved afresh" || echo "pinned by $lock"))"
# Wheels only, so that the package holds what PyPI built and tested; evdev (the USB pendant's
# reader) publishes no wheels, only its source, so it is compiled here (gcc and the kernel's
# input headers: scripts/ensure-env.sh installs them).
formats=(--only-binary=:all: --no-binary=evdev)
if [ $update_lock = 1 ]; then
  "${pip[@]}" install --no-compile "${formats[@]}" "$wheel"
  {
    echo "# The Python packages in the stave-jointer Debian package, exactly."
    echo "# Written by: packaging/build-deb.sh --update-lock (Python $py_version, $arch)."
    echo "# Rewrite it that way whenever pyproject.toml's dependencies change."
    "${pip[@]}" freeze --exclude stave-jointer
  } >"$lock"
  step "wrote $lock"
else
  [ -f "$lock" ] || die "$lock is missing: run packaging/build-deb.sh --update-lock"
  "${pip[@]}" install --no-compile "${formats[@]}" -c "$lock" "$wheel" ||
    die "pip could not install the pinned dependencies; if pyproject.toml's dependencies" \
      "changed, rewrite the lock: packaging/build-deb.sh --update-lock"
fi
# Every installed distribution must be pinned by the lock, so that two builds of one
# version hold the same code.
normalize() { grep -v '^#' | tr 'A-Z_.' 'a-z--' | sed 's/-\{2,\}/-/g' | sort; }
unpinned="$("${pip[@]}" freeze --exclude stave-jointer | normalize | comm -23 - <(normalize <"$lock"))"
[ -z "$unpinned" ] || die "installed but not pinned in $lock: $unpinned" \
  "(rewrite it: packaging/build-deb.sh --update-lock)"

step "OPC UA information models (OPC Foundation NodeSet2 files)"
# Fetched pinned with npm, into the venv's share/ where the server looks (sys.prefix).
"$repo/scripts/fetch-nodesets.sh" "$venv/share/opcua-nodesets" ||
  die "could not fetch the OPC UA NodeSet2 files (npm and internet access are needed to build)"

# pip and setuptools are for building; on the panel the package is the unit of change.
"${pip[@]}" uninstall -y pip setuptools
rm -f "$venv"/lib/python*/site-packages/stave_jointer-*.dist-info/direct_url.json
find "$venv" -name __pycache__ -type d -prune -exec rm -rf {} +

step "relocating the virtualenv to $prefix/venv"
{ grep -rlF --null "$venv" "$venv" || true; } | xargs -0 -r "$vpy" -I -c '
import sys
old, new = sys.argv[1].encode(), sys.argv[2].encode()
for name in sys.argv[3:]:
    with open(name, "rb") as f:
        data = f.read()
    with open(name, "wb") as f:
        f.write(data.replace(old, new))
' "$venv" "$prefix/venv"
# Checked-hash .pyc files stay valid whatever the files' times become (tar, copies,
# SOURCE_DATE_EPOCH), and an edited source file is still noticed.
"$vpy" -I -m compileall -q -j 0 --invalidation-mode checked-hash -x '[.]tmpl[.]py$' \
  -s "$venv" -p "$prefix/venv" "$venv/lib" >/dev/null ||
  die "compiling the virtualenv's Python files failed (run compileall without -q to see which)"
left="$(grep -rlF "$work" "$root" || true)"
[ -z "$left" ] || die "files still name the staging directory: $left"

# ---- resources, the configuration, the files of the system integration -----------------
step "resources and configuration"
resources="$root$prefix/resources"
mkdir -p "$resources" "$root/etc/stave-jointer"
# Translation sources (.ts) and their tools (.py) are for development, not for the panel.
(cd "$repo/resources" && tar --exclude=__pycache__ --exclude='*.py' --exclude='*.pyc' \
  --exclude='*.ts' -cf - .) | (cd "$resources" && tar -xf -)
"$interpreter" -I "$here/helpers/panel_config.py" "$repo/resources/machine.toml" \
  "$root/etc/stave-jointer/machine.toml" || die "could not write the panel's machine.toml"
# The factory file (simulation backend) beside the samples; the resources' machine.toml,
# the default of every tool, is the machine's own configuration in /etc.
rm "$resources/machine.toml"
cp "$root/etc/stave-jointer/machine.toml" "$resources/machine-sim.toml"
ln -s ../../../etc/stave-jointer/machine.toml "$resources/machine.toml"
STAVE_RESOURCES="$resources" "$vpy" -I -B -c '
import sys
from app.config import ConfigError, load_config
try:
    load_config(sys.argv[1])
except ConfigError as exc:
    sys.exit(f"build-deb: the panel configuration is invalid: {exc}")
' "$root/etc/stave-jointer/machine.toml"

cp -R "$here/files/." "$root/"
install -m 0755 "$here/helpers/stave_can_setup.py" "$root/usr/lib/stave-jointer/stave-can-setup"
install -D -m 0755 "$here/helpers/stave_gauge_setup.py" "$root/usr/sbin/stave-gauge-setup"
install -D -m 0644 "$here/README-install.md" "$root/usr/share/doc/stave-jointer/INSTALL.md"
mkdir -p "$root/var/lib/stave-jointer" "$root/var/log/stave-jointer"
chmod -R u+rwX,go+rX,go-w "$root"
chmod 0755 "$root"/usr/bin/* "$root"/usr/sbin/* "$root"/usr/lib/stave-jointer/*

# ---- control files and the package --------------------------------------------------------
step "package"
mkdir -m 0755 "$root/DEBIAN"
installed_kib="$(du -sk "$root" | cut -f1)"
sed -e "s|@VERSION@|$version|" -e "s|@ARCH@|$arch|" -e "s|@MAINTAINER@|$maintainer|" \
  -e "s|@INSTALLED_SIZE@|$installed_kib|" -e "s|@PYTHON@|python$py_version|" \
  "$here/debian/control.in" >"$root/DEBIAN/control"
install -m 0755 "$here/debian/postinst" "$here/debian/prerm" "$here/debian/postrm" "$root/DEBIAN/"
conffiles=(/etc/stave-jointer/machine.toml /etc/stave-jointer/kiosk.conf)
printf '%s\n' "${conffiles[@]}" >"$root/DEBIAN/conffiles"
(cd "$root" && find . -path ./DEBIAN -prune -o -path ./etc -prune -o -type f -printf '%P\0' |
  LC_ALL=C sort -z | xargs -0 md5sum) >"$root/DEBIAN/md5sums"
chmod 0644 "$root/DEBIAN/control" "$root/DEBIAN/conffiles" "$root/DEBIAN/md5sums"

deb="$out/stave-jointer_${version}_${arch}.deb"
dpkg-deb --root-owner-group -Z"$compression" --build "$root" "$deb" >/dev/null
step "wrote $deb ($(du -h "$deb" | cut -f1))"
echo "$deb"
