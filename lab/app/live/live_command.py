"""``scanlab app``: its options and their checks.

:func:`add_parser` is called by :func:`lab.app.cli.build_parser` with the CLI's UsageError,
so a bad option ends in one line and exit status 2 like every other command.
"""
from __future__ import annotations

import argparse
import errno
import socket
from pathlib import Path

from lab.app.option_types import whole

DESCRIPTION = """\
Starts the live lab, a local web page: pick a scene (presets, the lessons' scenes, built-in
shapes with their parameters, the files named here), change shading, reflection model,
interpolation, hidden-surface removal, material, lights and camera, or break a rule on
purpose, and see our image at once, then VTK's, the ΔE2000 map, the metrics and the verdict.
Drag on our image to orbit the camera. "Save scene" writes a scene file into --save-dir that
`scanlab compare` reproduces. Listens on 127.0.0.1 unless --host says otherwise; Ctrl-C stops it.
"""


def add_parser(sub, usage_error) -> None:
    p = sub.add_parser("app", help="the live lab: a local web page where every control re-renders both renderers",
                       description=DESCRIPTION, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scene", nargs="?", default="course-phong",
                   help="the scene shown first: a preset, a built-in shape such as icosphere:level=3, a scene file "
                        "or a mesh file (default course-phong)")
    p.add_argument("--open", action="append", default=[], metavar="FILE",
                   help="also offer this scene file or mesh file in the picker (repeatable)")
    p.add_argument("--port", type=whole(0, 65535, "a port number", " (0: any free one)"), default=8080, help="port to listen on (default 8080; 0: any free port)")
    p.add_argument("--host", default="127.0.0.1",
                   help="address to listen on (default 127.0.0.1, this machine only; 0.0.0.0 opens it to the network)")
    p.add_argument("--save-dir", default=".", metavar="DIR",
                   help="folder where 'Save scene' writes scene files (default: the current folder)")
    p.set_defaults(func=lambda args: cmd_app(args, usage_error))


def _check_address(host: str, port: int, usage_error) -> None:
    """Refuse, in one line, an address the server could not listen on."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as exc:
        raise usage_error(f"--host {host}: {exc.strerror}") from None
    family, kind, proto, _, address = infos[0]
    with socket.socket(family, kind, proto) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(address)
        except OSError as exc:
            why = "in use" if exc.errno == errno.EADDRINUSE else exc.strerror
            raise usage_error(f"--port {port}: cannot listen on {host}:{port}: {why} "
                              "(try another --port, or --port 0 for any free one)") from None


def _check_trame(usage_error) -> None:
    """trame is an extra (``live``): say how to install it rather than fail on an import."""
    try:
        import trame.app  # noqa: F401
        import trame.widgets.vuetify3  # noqa: F401
    except ImportError as exc:
        raise usage_error(f"the live lab needs trame and trame-vuetify ({exc.name} is missing): "
                          "pip install -e '.[live]' in scanlab's folder (make venv does it)") from None


def cmd_app(args, usage_error) -> int:
    _check_trame(usage_error)
    from lab.app.live.live_server import run

    save_dir = Path(args.save_dir)
    if save_dir.exists() and not save_dir.is_dir():
        raise usage_error(f"--save-dir {args.save_dir}: is a file, not a folder")
    _check_address(args.host, args.port, usage_error)
    files = list(args.open)
    if Path(args.scene).is_file() or args.scene.lower().endswith(".toml"):
        files.insert(0, args.scene)
    return run(args.scene, tuple(files), args.host, args.port, save_dir)
