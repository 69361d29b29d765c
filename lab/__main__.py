"""``python -m lab`` works like ``scanlab``."""
import sys

from lab.app.cli import main

sys.exit(main())
