#!/usr/bin/env bash
# Shared set-up for run.sh and test.sh: a .venv with the app (and, with "dev", its test tools)
# and the Qt runtime libraries this machine lacks. Idempotent and quiet when nothing is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
extra="${1:-}"

PYTHON="${PYTHON:-python3}"
if ! "$PYTHON" -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null; then
  echo "stave: Python 3.11 or newer is needed (found: $("$PYTHON" --version 2>&1))" >&2
  exit 2
fi

# Debian packages: the venv module, and the libraries PySide6's Qt needs (xcb on a desktop,
# offscreen in tests). Installed with apt-get when root, otherwise the exact command is shown.
debs=(python3-venv libgl1 libegl1 libopengl0 libxkbcommon0 libxkbcommon-x11-0 libfontconfig1
      libdbus-1-3 libglib2.0-0 libxcb-cursor0 libxcb-icccm4 libxcb-image0 libxcb-keysyms1
      libxcb-randr0 libxcb-render-util0 libxcb-shape0 libxcb-xinerama0 libxcb-xkb1
      libxcb-xfixes0 libx11-xcb1 fonts-dejavu-core
      gcc python3-dev linux-libc-dev)  # python-evdev (USB pendants) builds from source
# The test set-up also needs peers we did not write: LinuxCNC's standalone G-code interpreter
# rs274 (linuxcnc-uspace; without its recommends, which would pull in a real-time kernel), and
# an X server without a window manager (xvfb, x11-utils's xwininfo) for the kiosk test, and
# the panel's own kiosk compositor (cage, with Xwayland) for the Debian package's kiosk test.
dev_debs=()
if [ "$extra" = dev ]; then
  dev_debs=(linuxcnc-uspace xvfb x11-utils cage xwayland)
fi
if command -v dpkg >/dev/null 2>&1; then
  missing=()
  missing_dev=()
  for deb in "${debs[@]}"; do
    dpkg -s "$deb" >/dev/null 2>&1 || missing+=("$deb")
  done
  for deb in "${dev_debs[@]}"; do
    dpkg -s "$deb" >/dev/null 2>&1 || missing_dev+=("$deb")
  done
  all_missing=("${missing[@]}" "${missing_dev[@]}")
  if [ ${#all_missing[@]} -gt 0 ] && [ "$(id -u)" = 0 ]; then
    echo "stave: installing system packages: ${all_missing[*]}" >&2
    apt-get update -qq >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
      "${all_missing[@]}" >/dev/null
  elif [ ${#all_missing[@]} -gt 0 ]; then
    echo "stave: missing system packages; install them with:" >&2
    echo "  sudo apt-get install -y --no-install-recommends ${all_missing[*]}" >&2
    # Without the test peers a developer's suite still runs (their tests skip, saying why);
    # under CI those tests fail, and the application itself needs the Qt libraries.
    if [ ${#missing[@]} -gt 0 ] || [ -n "${CI:-}" ]; then
      exit 2
    fi
  fi
fi

if [ ! -x .venv/bin/python ]; then
  "$PYTHON" -m venv .venv
fi
# Reinstall only when pyproject.toml (the dependency list) changed.
stamp=".venv/.installed-${extra:-app}-$(sha256sum pyproject.toml | cut -c1-16)"
if [ ! -f "$stamp" ]; then
  .venv/bin/python -m pip install -q --disable-pip-version-check --upgrade pip >&2
  if [ -n "$extra" ]; then
    .venv/bin/python -m pip install -q --disable-pip-version-check -e ".[$extra]" >&2
  else
    .venv/bin/python -m pip install -q --disable-pip-version-check -e . >&2
  fi
  rm -f .venv/.installed-"${extra:-app}"-*
  touch "$stamp"
fi

# The OPC UA information models (OPC Foundation NodeSet2 files) for the plant connection,
# fetched at a pinned version into the venv (never into the repository).
scripts/fetch-nodesets.sh .venv/share/opcua-nodesets

# The test suite's OPC UA client, node-opcua (pinned in its package-lock.json).
if [ "$extra" = "dev" ]; then
  lock_stamp="tests/plant/node_client/node_modules/.installed-$(sha256sum tests/plant/node_client/package-lock.json | cut -c1-16)"
  if [ ! -f "$lock_stamp" ]; then
    if command -v npm >/dev/null 2>&1; then
      (cd tests/plant/node_client && npm ci --silent --no-audit --no-fund >/dev/null 2>&1) \
        && touch "$lock_stamp" \
        || echo "stave: npm ci in tests/plant/node_client failed; the OPC UA client tests cannot run" >&2
    else
      echo "stave: npm is missing; the OPC UA client tests (node-opcua) cannot run" >&2
    fi
  fi
fi
