"""``python3 -m cgal_constrained_fairing.batch``: the batch's command line, `main`."""

import sys

from . import main

if __name__ == "__main__":
    sys.exit(main())
