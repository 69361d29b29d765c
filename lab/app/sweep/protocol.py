"""Messages between a Dask worker and its case process: length-prefixed pickles on pipes.

Each message is an 8-byte little-endian length, then that many bytes of a pickled dict. The
worker writes requests to the case process's stdin; the case process answers on a private
copy of its original stdout (its fd 1 is pointed at stderr, so whatever a library prints
cannot corrupt a message).
"""
from __future__ import annotations

import pickle
import struct
from typing import BinaryIO

HEADER = struct.Struct("<Q")


def encode(message: dict) -> bytes:
    """The bytes of one message (header and pickle)."""
    body = pickle.dumps(message, protocol=pickle.HIGHEST_PROTOCOL)
    return HEADER.pack(len(body)) + body


def write_message(stream: BinaryIO, message: dict) -> None:
    stream.write(encode(message))
    stream.flush()


def _read_exactly(stream: BinaryIO, n: int) -> bytes | None:
    chunks, left = [], n
    while left:
        chunk = stream.read(left)
        if not chunk:
            return None
        chunks.append(chunk)
        left -= len(chunk)
    return b"".join(chunks)


def read_message(stream: BinaryIO) -> dict | None:
    """The next message from a blocking stream, or None at its end (the other side closed it)."""
    header = _read_exactly(stream, HEADER.size)
    if header is None:
        return None
    body = _read_exactly(stream, HEADER.unpack(header)[0])
    return None if body is None else pickle.loads(body)
