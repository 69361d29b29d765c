"""``python -m lab`` works like ``scanlab``."""
import sys

from lab.cli import main

sys.exit(main())
