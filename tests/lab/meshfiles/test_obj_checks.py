"""Specification of ``lab.meshfiles.obj_checks``: every face index refers to an existing line.

The quick way (:func:`_quick`: digit runs, no parsing), the vectorised parse
(:func:`_index_maxima`) and the line-by-line scan must agree; an index past the end is
refused with its line, before VTK's reader (which would read unrelated memory, or crash)
sees the file.
"""
from __future__ import annotations

import numpy as np
import pytest

from lab.meshfiles import obj_checks
from lab.meshfiles.obj_checks import check

HEAD = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 0 0 -1\n"  # 4 v, 3 vt, 2 vn


@pytest.mark.parametrize("faces, maxima", [
    ("f 1 2 3\nf 2 4 3\n", (4, 0, 0)),
    ("f 1/1 2/2 3/3\nf 2/2 4/3 3/3\n", (4, 3, 0)),
    ("f 1//1 2//1 3//2\nf 2//2 4//1 3//1\n", (4, 0, 2)),
    ("f 1/1/1 2/2/1 3/3/2\nf 2/2/2 4/3/1 3/3/1\n", (4, 3, 2)),
    ("f 1/1/1 2/2/1 3/3/2 4/1/1\n", (4, 3, 2)),         # a quad
    ("f -4/-3/-2 -3/-2/-2 -2/-1/-1\n", (-2, -1, -1)),     # relative indices: VTK checks those itself
])
def test_maxima_of_each_form(faces, maxima):
    assert obj_checks._index_maxima(faces.encode()) == maxima
    check((HEAD + faces).encode())  # all in range
    assert obj_checks._quick((HEAD + faces).encode())  # the quick way settles it


@pytest.mark.parametrize("faces", [
    "f 1 2 3\nf 1/1/1 2/2/2 3/3/2\n",         # plain and a/b/c corners
    "f 1/1 2/2 3/3\nf 1//1 2//1 3//2\n",       # a/b and a//c
    "f 1 2 3\nf 1/1/1 2/2/1 3/3/1 4/1/1\n",    # equal numbers of a and a/b/c corners mimic a/b
    "f  1/1 2/2 3/3\n",                        # two blanks before a corner
])
def test_mixed_forms_go_line_by_line(faces):
    assert obj_checks._index_maxima(faces.encode()) is None
    check((HEAD + faces).encode())


@pytest.mark.parametrize("faces, line, words", [
    ("f 1 2 5\n", 10, "vertex 5, but there are 4"),
    ("f 1/1 2/2 3/4\n", 10, "texture coordinate 4, but there are 3"),
    ("f 1//1 2//1 3//3\n", 10, "normal 3, but there are 2"),
    ("f 1/1/1 2/2/1 3/3/99999999999\n", 10, "normal 99999999999, but there are 2"),
    ("f 1 2 3\nf 1/1/1 2/2/2 3/3/2\nf 1 2 9\n", 12, "vertex 9"),      # mixed forms: line by line
    ("f 1 2 3 \\\n 4 9\n", 11, "vertex 9"),                           # a continued line
])
def test_index_past_the_end(faces, line, words):
    with pytest.raises(ValueError, match=rf"^line {line}: a face refers to {words}"):
        check((HEAD + faces).encode())


def test_counts_come_from_the_whole_file():
    """VTK resolves a positive index against all ``v`` lines, even those after the face."""
    check(b"v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n")
    with pytest.raises(ValueError, match="vertex 4, but there are 3"):
        check(b"v 0 0 0\nv 1 0 0\nf 1 2 4\nv 0 1 0\n")


def test_statements_among_faces_still_quick():
    """usemtl, g, s (with digits of their own) and v lines between faces: the quick way
    leaves those lines out and counts the v lines wherever they are."""
    text = HEAD + "usemtl mat7\nf 1/1/1 2/2/1 3/3/2\ns 12\ng part99\nv 5 5 5\nf 2/2/2 5/3/1 3/3/1\n"
    assert obj_checks._quick(text.encode())
    bad = HEAD + "usemtl mat7\nf 1/1/1 2/2/1 3/3/2\ns 12\nf 2/2/2 5/3/1 3/3/1\n"
    assert not obj_checks._quick(bad.encode())
    with pytest.raises(ValueError, match="line 13: a face refers to vertex 5, but there are 4"):
        check(bad.encode())


def test_statements_among_faces_and_leading_blanks():
    text = HEAD + "usemtl a\nf 1/1/1 2/2/1 3/3/2\ng b\n  f 2/2/2 4/3/1 3/3/5\n"
    with pytest.raises(ValueError, match="line 13: a face refers to normal 5"):
        check(text.encode())


@pytest.mark.parametrize("block", [1 << 22, 64], ids=["one block", "blocks of 64 bytes"])
def test_the_three_ways_agree(monkeypatch, block):
    """Random files of one form, some with an index past the end: the quick way passes
    exactly those the line scan passes, and the parse finds the same maxima."""
    monkeypatch.setattr(obj_checks, "BLOCK", block)
    rng = np.random.default_rng(7)
    head = "v 0 0 0\n" * 59 + "vt 0 0\n" * 99 + "vn 0 0 1\n" * 100
    counts = (59, 99, 100)
    for form in ("{0}", "{0}/{1}", "{0}//{2}", "{0}/{1}/{2}"):
        for trial in range(6):
            corners = rng.integers(1, [60, 100, 101] if trial % 2 else [59, 99, 100], size=(40, 3, 3), endpoint=True)
            faces = "".join("f " + " ".join(form.format(*c) for c in face) + "\n" for face in corners)
            used = [k for k in range(3) if "{%d}" % k in form]
            maxima = obj_checks._index_maxima(faces.encode())
            assert maxima == tuple(int(corners[:, :, k].max()) if k in used else 0 for k in range(3))
            within = all(maxima[k] <= counts[k] for k in range(3))
            assert obj_checks._quick((head + faces).encode()) == within
            if within:
                check((head + faces).encode())
            else:
                with pytest.raises(ValueError, match="a face refers to"):
                    check((head + faces).encode())


def test_the_usual_layout_is_settled_without_parsing(monkeypatch):
    """The load-time budget rests on it: a valid file in the usual layout never reaches the parse."""
    def parse(_):
        raise AssertionError("parsed")

    monkeypatch.setattr(obj_checks, "_index_maxima", parse)
    monkeypatch.setattr(obj_checks, "_scan_lines", parse)
    for faces in ("f 1 2 3\n", "f 1/1 2/2 3/3\n", "f 1//1 2//2 3//2\n", "f 1/1/1 2/2/2 3/3/2 4/1/1\n"):
        check((HEAD + faces).encode())
