"""A demo run shared by the demo and page tests: a preset, a user's scene file and a mesh file."""
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def demo_run(tmp_path_factory):
    """``scanlab demo`` on three kinds of SCENE: (out folder, specs, exit status)."""
    from lab.app.cli import main

    root = tmp_path_factory.mktemp("demo")
    mine = root / "mine.toml"
    mine.write_text("# my own scene: two boxes, parallel camera\n"
                    + (REPO / "lab" / "scenes" / "unlit-parallel.toml").read_text().split("\n", 1)[1])
    specs = ["fill-rule", str(mine), str(REPO / "lab" / "scenes" / "models" / "torus.ply")]
    out = root / "out"
    status = main(["demo", "--out", str(out), *specs])
    return out, specs, status
