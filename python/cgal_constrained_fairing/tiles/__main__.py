"""``python3 -m cgal_constrained_fairing.tiles IN OUT --eps ...``: see `fair_tiled`."""

import sys

from ._command_line import main

sys.exit(main())
