#!/usr/bin/env bash
# The whole test suite, headless, then the linters and the type checker.
# Non-zero exit on any failure. Extra arguments go to pytest.
set -euo pipefail
cd "$(dirname "$0")"
scripts/ensure-env.sh dev
export QT_QPA_PLATFORM=offscreen
status=0
# One worker per core; a test file stays on one worker (its module fixtures start once).
.venv/bin/python -m pytest -p no:cacheprovider -n auto --dist loadfile "$@" || status=$?
echo "== ruff" && { .venv/bin/ruff check app tests benchmarks || status=1; }
echo "== ruff format" && { .venv/bin/ruff format --check app tests benchmarks || status=1; }
echo "== mypy (strict, whole app)" && { .venv/bin/mypy || status=1; }
exit $status
