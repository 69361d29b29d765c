"""Messages between worker and case process: what is written is what is read, and the end is seen."""
from __future__ import annotations

import io

import numpy as np

from lab.app.sweep.protocol import HEADER, encode, read_message, write_message


def test_messages_come_back_as_written_in_order_then_none_at_the_end():
    stream = io.BytesIO()
    first = {"status": "ok", "frames": np.arange(12, dtype=np.uint8).tobytes()}
    write_message(stream, first)
    write_message(stream, {"n": 2})
    stream.seek(0)
    assert read_message(stream) == first
    assert read_message(stream) == {"n": 2}
    assert read_message(stream) is None


def test_a_message_cut_short_reads_as_the_end():
    data = encode({"a": 1})
    assert HEADER.unpack(data[:HEADER.size])[0] == len(data) - HEADER.size
    assert read_message(io.BytesIO(data[:-1])) is None
    assert read_message(io.BytesIO(data[:3])) is None
