"""``python -m app.cli`` is the ``stave`` command (the Debian package's /usr/bin/stave runs it)."""

import sys

from app.cli import main

sys.exit(main())
