"""lab/app/live/live_command.py: ``scanlab app`` refuses bad options in one line, listens on
127.0.0.1 only, prints its address, serves the page, and Ctrl-C stops it and its workers."""
from __future__ import annotations

import signal
import socket
import sys
import time
import urllib.request

import pytest

from lab.app.cli import main

from .live_app_process import children, listening_addresses, running_app


@pytest.mark.parametrize("args,message", [
    (["--port", "70000"], "--port: expected a port number from 0 to 65535"),
    (["--port", "x"], "--port: expected a port number, got 'x'"),
    (["course-phomg"], "did you mean 'course-phong'"),
    (["missing.toml"], "missing.toml"),
    (["--host", "no.such.host.invalid"], "--host no.such.host.invalid"),
])
def test_a_bad_option_is_one_line_and_exit_status_2(capsys, args, message):
    assert main(["app", *args]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1 and "Traceback" not in err


def test_without_trame_it_says_how_to_install_it(capsys, monkeypatch):
    monkeypatch.setitem(sys.modules, "trame.widgets.vuetify3", None)  # an import of it fails
    assert main(["app"]) == 2
    err = capsys.readouterr().err
    assert "needs trame and trame-vuetify" in err and "'.[live]'" in err and err.count("\n") == 1


def test_a_port_in_use_is_named(capsys):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        assert main(["app", "--port", str(port)]) == 2
    assert f"--port {port}: cannot listen on 127.0.0.1:{port}: in use" in capsys.readouterr().err


def test_a_save_folder_that_is_a_file_is_refused(capsys, tmp_path):
    (tmp_path / "f").write_text("x")
    assert main(["app", "--save-dir", str(tmp_path / "f")]) == 2
    assert "is a file, not a folder" in capsys.readouterr().err


def test_it_serves_on_loopback_only_and_ctrl_c_stops_it_with_its_workers(tmp_path):
    with running_app("cube", "--save-dir", str(tmp_path)) as (url, port, process):
        assert listening_addresses(port) == ["127.0.0.1"]
        with urllib.request.urlopen(url, timeout=30) as response:
            assert response.status == 200 and b"<div id=\"app\">" in response.read()
        workers = children(process.pid)
        assert len(workers) >= 2  # the two render workers (and multiprocessing's helper)
        process.send_signal(signal.SIGINT)
        assert process.wait(20) == 0
        assert "Traceback" not in process.stderr.read()
    assert _all_ended(workers, within=15.0) == {}


def _all_ended(pids: list[int], within: float) -> dict[int, str]:
    """Wait up to ``within`` seconds for ``pids`` to end; the command lines of those still alive."""
    deadline = time.monotonic() + within
    while (alive := [pid for pid in pids if _alive(pid)]) and time.monotonic() < deadline:
        time.sleep(0.1)
    return {pid: _command_line(pid) for pid in alive}


def _command_line(pid: int) -> str:
    try:
        with open(f"/proc/{pid}/cmdline") as f:
            return f.read().replace("\0", " ").strip()
    except OSError:
        return "?"


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False
