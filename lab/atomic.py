"""Writing output files atomically: a temporary file beside the target, then a rename.

Every file scanlab writes (PNG, JSON, HTML, exported meshes, saved fuzz inputs) goes
through :func:`atomic_file`, so an interrupted run never leaves a truncated file: the
target is either untouched or complete. The temporary file is ``.<name>.<random>.tmp``
in the target's own folder (a rename is atomic only within one file system), and it is
removed again if anything fails before the rename.
"""
from __future__ import annotations

import os
import tempfile
from contextlib import contextmanager, suppress
from typing import BinaryIO, Iterator


@contextmanager
def atomic_file(path: str | os.PathLike) -> Iterator[BinaryIO]:
    """Open a temporary binary file next to ``path``; on success move it onto ``path``.

    The finished file has mode 0644 (``mkstemp`` makes 0600). The folder must exist.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "a.txt"
    >>> with atomic_file(target) as f:
    ...     _ = f.write(b"all or nothing")
    >>> target.read_bytes()
    b'all or nothing'
    """
    path = os.fspath(path)
    directory, name = os.path.split(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=f".{name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as f:
            yield f
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        with suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def write_text(path: str | os.PathLike, text: str) -> None:
    """Write ``text`` as UTF-8, atomically (see :func:`atomic_file`)."""
    with atomic_file(path) as f:
        f.write(text.encode("utf-8"))
