"""Specification of ``lab.meshfiles.stl_checks``: a binary STL is as long as its triangle count says."""
from __future__ import annotations

import struct

import pytest

from lab.meshfiles.stl_checks import check, looks_ascii


def binary(n_declared: int, n_records: int, header=b"scanlab") -> bytes:
    return header.ljust(80, b" ") + struct.pack("<I", n_declared) + bytes(50 * n_records)


def test_exact_length_passes():
    check(binary(3, 3))
    check(binary(0, 0))


def test_a_binary_header_that_starts_with_solid_is_still_binary():
    """Some exporters start the 80-byte header with "solid"; its records hold no facet."""
    data = binary(2, 1, header=b"solid exported by a CAD program")
    assert not looks_ascii(data)
    with pytest.raises(ValueError, match="cut short"):
        check(data)


@pytest.mark.parametrize("declared, records, words", [
    (5, 1, "the file is cut short: its header counts 5 triangles (334 bytes), the file has 134 bytes"),
    (1, 2, "50 bytes after the 1 triangles its header counts"),
])
def test_wrong_length(declared, records, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        check(binary(declared, records))


def test_too_short_for_a_header():
    with pytest.raises(ValueError, match="not an STL file"):
        check(b"hello")


def test_ascii_is_left_to_vtk():
    assert looks_ascii(b"  solid x\nfacet normal 0 0 1\n")
    check(b"solid x\nfacet normal 0 0 1\n outer loop\n")  # whatever follows, VTK judges it
