"""One real sweep of 48 cases on a local cluster of 2 workers, shared by the tests that read it."""
from __future__ import annotations

import subprocess

import pytest

from .sweeps import IDENTITY_GRID, IDENTITY_SOURCES, sweep_command


@pytest.fixture(scope="session")
def identity_sweep(tmp_path_factory):
    """(out folder, finished process) of ``scanlab sweep`` over the 48 identity cases."""
    out = tmp_path_factory.mktemp("identity") / "sweep"
    done = subprocess.run(sweep_command(out, IDENTITY_SOURCES, IDENTITY_GRID, "--workers", "2", "--worst", "5"),
                          capture_output=True, text=True, timeout=900)
    assert done.returncode in (0, 1), done.stderr
    return out, done
