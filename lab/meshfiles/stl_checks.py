"""A binary STL file's length, checked before VTK's reader sees it.

A binary STL is an 80-byte header, a triangle count n and n records of 50 bytes. VTK's
reader (vtkSTLReader, VTK 9.7) reads what is there without a word when the file is
shorter, so a cut-short file would lose triangles silently; extra bytes are values no
triangle holds. ASCII STL (text starting with ``solid`` and holding facets) VTK parses
and judges itself.
"""
from __future__ import annotations

import struct

HEADER, RECORD = 84, 50


def looks_ascii(data) -> bool:
    """Text that starts with ``solid`` and has a facet early on (binary headers may also
    start with ``solid``; their records hold no facet keywords)."""
    head = bytes(data[:4096])
    return head.lstrip()[:5].lower() == b"solid" and b"facet" in head.lower()


def check(data) -> None:
    """Refuse a binary STL whose length does not match its triangle count.

    Raises
    ------
    ValueError
    """
    if looks_ascii(data):
        return None
    if len(data) < HEADER:
        raise ValueError("not an STL file (neither ASCII 'solid ... facet' nor an 84-byte binary header)")
    n = struct.unpack_from("<I", data, 80)[0]
    expected = HEADER + RECORD * n
    if len(data) < expected:
        raise ValueError(f"the file is cut short: its header counts {n} triangles ({expected} bytes), "
                         f"the file has {len(data)} bytes")
    if len(data) > expected:
        raise ValueError(f"{len(data) - expected} bytes after the {n} triangles its header counts")
    return None
