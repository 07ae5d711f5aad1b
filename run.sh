#!/usr/bin/env bash
# Start the operator application (simulation backend and embedded database by default).
# Extra arguments pass through: --backend, --gauge, --config, --db, --kiosk, --lang,
# --screenshots DIR --size WxH, --version.
set -euo pipefail
cd "$(dirname "$0")"
scripts/ensure-env.sh
exec .venv/bin/python -m app "$@"
