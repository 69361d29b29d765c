"""``python -m lab`` works like ``scanlab``."""
from lab.app.cli import run

run()
