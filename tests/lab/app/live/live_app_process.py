"""Starting ``scanlab app`` in a subprocess for the tests (not a test file)."""
from __future__ import annotations

import os
import re
import select
import signal
import subprocess
import sys
import time
from contextlib import contextmanager
from pathlib import Path

ADDRESS = re.compile(r"scanlab live lab: (http://127\.0\.0\.1:(\d+)/)")


@contextmanager
def running_app(*args: str, cwd: Path | None = None, timeout: float = 120.0):
    """``python -m lab app --port 0 ARGS`` until the block ends: yields (url, port, process).
    Stopped with SIGINT (Ctrl-C), as a user stops it."""
    process = subprocess.Popen([sys.executable, "-m", "lab", "app", "--port", "0", *args], cwd=cwd,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env={**os.environ, "PYTHONUNBUFFERED": "1"})
    try:
        line, printed, t0 = "", [], time.monotonic()
        while not ADDRESS.search(line):
            left = timeout - (time.monotonic() - t0)
            if left <= 0 or not select.select([process.stdout], [], [], left)[0]:
                raise TimeoutError(f"scanlab app printed no loopback address in {timeout:.0f} s: {printed}")
            line = process.stdout.readline()
            printed.append(line)
            if not line and process.poll() is not None:
                raise RuntimeError(f"scanlab app ended: {process.stderr.read()}")
        match = ADDRESS.search(line)
        yield match.group(1), int(match.group(2)), process
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGINT)
            try:
                process.wait(20)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def children(pid: int) -> list[int]:
    """The process ids whose parent is ``pid`` (from /proc)."""
    out = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            out.append(int(stat.parent.name))
    return out


def listening_addresses(port: int) -> list[str]:
    """The local addresses with a listening TCP socket on ``port`` (IPv4 and IPv6, from /proc)."""
    found = []
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        for row in Path(table).read_text().splitlines()[1:]:
            local, state = row.split()[1], row.split()[3]
            address, _, hex_port = local.partition(":")
            if state == "0A" and int(hex_port, 16) == port:
                found.append(_address(address))
    return found


def _address(hex_address: str) -> str:
    if len(hex_address) == 8:
        return ".".join(str(int(hex_address[i:i + 2], 16)) for i in (6, 4, 2, 0))
    return hex_address  # IPv6, raw
