"""``python -m kresling`` runs the command line."""

import sys

from kresling.cli import main

sys.exit(main())
