"""An OBJ file's face indices, checked before VTK's reader sees them.

vtkOBJReader (VTK 9.7) does not check that a face's ``v/vt/vn`` indices refer to lines
that exist. Where it copies a point per face corner (a point used with several ``vt`` or
``vn``), an index past the end reads unrelated memory: a vertex at a made-up place, a
normal of zeros, or a crash of the whole process. So every positive index is compared
here with the number of ``v``, ``vt`` and ``vn`` lines in the whole file, as VTK resolves
them (negative, relative indices VTK checks itself).

Two ways, one answer:

- :func:`_index_maxima`, vectorised: the face lines are cut out with numpy, parsed in one
  call, and their largest index of each kind taken. It handles the usual files, whose
  corners all have one form (``a``, ``a/b``, ``a//c`` or ``a/b/c``);
- :func:`_scan_lines`, line by line, for any other file and to name the line of the first
  bad index in the error.
"""
from __future__ import annotations

import warnings

import numpy as np

KINDS = ("vertex", "texture coordinate", "normal")
"""What a face corner's first, second and third index refer to (``v``, ``vt``, ``vn`` lines)."""

_BLANK = (ord(" "), ord("\t"))

# Face lines → numbers: 'f' and '/' become spaces; digits, signs and whitespace stay; anything
# else becomes 'x', which sends the file to the line-by-line scan.
_KEEP = b"0123456789+- \t\r\n"
_TABLE = bytes(c if c in _KEEP else (ord(" ") if c in b"f/" else ord("x")) for c in range(256))


def check(data) -> None:
    """Refuse a face index past the end of the ``v``, ``vt`` or ``vn`` lines.

    Parameters
    ----------
    data : the file's bytes (``bytes`` or any buffer, e.g. an ``mmap``).

    Raises
    ------
    ValueError
        ``"line 12: a face refers to vertex 9, but there are 3"``.
    """
    maxima = None
    for read in (_faces_last, _statements):  # the usual layout first, cheaply; then any
        counts, faces = read(data)
        maxima = None if faces is None else _index_maxima(faces)
        if maxima is not None:
            break
    if maxima is not None and all(m <= n for m, n in zip(maxima, counts)):
        return
    _scan_lines(bytes(data))


def _kinds(a: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Line starts and the first three bytes of each line ("\n" past a line's end)."""
    starts = np.concatenate([[0], np.flatnonzero(a[:-1] == ord("\n")) + 1]) if len(a) else np.zeros(0, np.int64)
    ends = np.append(starts[1:], len(a))

    def at(offset):
        pos = starts + offset
        return np.where(pos < ends, a[np.minimum(pos, max(len(a) - 1, 0))], ord("\n"))

    return starts, at(0), at(1), at(2)


def _counts(c0, c1, c2) -> tuple[int, int, int]:
    """Numbers of ``v``, ``vt`` and ``vn`` lines from the lines' first three bytes."""
    blank1 = (c1 == _BLANK[0]) | (c1 == _BLANK[1])
    blank2 = (c2 == _BLANK[0]) | (c2 == _BLANK[1]) | (c2 == ord("\n")) | (c2 == ord("\r"))
    v = c0 == ord("v")
    return int((v & blank1).sum()), int((v & (c1 == ord("t")) & blank2).sum()), int((v & (c1 == ord("n")) & blank2).sum())


def _first_face_line(data) -> int:
    """Where the first ``f`` line starts, or -1 (a byte search: 'f' is rare outside faces)."""
    at = data.find(b"f")
    while at >= 0:
        if (at == 0 or data[at - 1] == ord("\n")) and data[at + 1:at + 2] in (b" ", b"\t"):
            return at
        at = data.find(b"f", at + 1)
    return -1


def _faces_last(data) -> tuple[tuple[int, int, int], bytes | None]:
    """The usual layout, read cheaply: all ``f`` lines come after all others.

    Returns the numbers of ``v``, ``vt``, ``vn`` lines before the first ``f`` line and the
    bytes from there to the end (:func:`_index_maxima` refuses them if anything but faces
    is among them), or ``(…, None)`` when the start does not fit.
    """
    first = _first_face_line(data)
    if first < 0:
        return (0, 0, 0), None
    faces = bytes(data[first:])
    if b"\\" in faces:
        return (0, 0, 0), None
    a = np.frombuffer(data, dtype=np.uint8)
    starts = np.concatenate([[0], np.flatnonzero(a[:first] == ord("\n"))[:-1] + 1]) if first else np.zeros(0, int)
    c0, c1, c2 = a[starts], a[starts + 1], a[starts + 2]  # every line before ``first`` ends in "\n"
    if ((c0 == _BLANK[0]) | (c0 == _BLANK[1])).any():
        return (0, 0, 0), None
    return _counts(c0, c1, c2), faces


def _statements(data) -> tuple[tuple[int, int, int], bytes | None]:
    """Numbers of ``v``, ``vt`` and ``vn`` lines, and the bytes of all ``f`` lines, in any layout.

    The face bytes are None for a layout the vectorised way does not read: a statement
    after leading blanks, or a line continued with a backslash.
    """
    a = np.frombuffer(data, dtype=np.uint8)
    if len(a) == 0:
        return (0, 0, 0), b""
    starts, c0, c1, c2 = _kinds(a)
    counts = _counts(c0, c1, c2)
    if ((c0 == _BLANK[0]) | (c0 == _BLANK[1])).any() or data.find(b"\\") >= 0:
        return counts, None
    face = np.flatnonzero((c0 == ord("f")) & ((c1 == _BLANK[0]) | (c1 == _BLANK[1])))
    if len(face) == 0:
        return counts, b""
    ends = np.append(starts[1:], len(a))
    breaks = np.flatnonzero(np.diff(face) != 1)  # face lines in runs of consecutive lines
    firsts = np.concatenate([[face[0]], face[breaks + 1]])
    lasts = np.append(face[breaks], face[-1])
    return counts, b"\n".join(bytes(data[s:e]) for s, e in zip(starts[firsts], ends[lasts]))


def _index_maxima(faces: bytes) -> tuple[int, int, int] | None:
    """The largest vertex, texture coordinate and normal index in ``faces`` (0 where none),
    or None if the corners are not all of one form."""
    text = faces.translate(_TABLE)
    if b"x" in text:
        return None
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:  # numpy's C parser: whitespace-separated integers
            numbers = np.fromstring(text, dtype=np.int64, sep=" ")
        except (ValueError, DeprecationWarning):  # a token it could not read to the end
            return None
    a = np.frombuffer(faces, dtype=np.uint8)
    n, slashes = len(numbers), int(np.count_nonzero(a == ord("/")))
    if n == 0:
        return 0, 0, 0
    # The totals tell the forms apart: a corner holds at most 3 numbers and 2 slashes (VTK
    # refuses more), and every corner follows a blank, so there are at least as many
    # blanks as corners. n = 3·blanks then means 3 numbers in every corner; n = 2·blanks
    # with 2 slashes a corner means a//c everywhere. n = 2·blanks with one slash a corner
    # on average may still mix a and a/b/c: _one_slash_per_corner tells.
    blanks = int(np.count_nonzero(a == ord(" "))) + (faces.count(b"\t") if b"\t" in faces else 0)
    if slashes == 0:                                                         # a
        columns = {0: numbers}
    elif n == 3 * blanks:                                                    # a/b/c
        columns = {0: numbers[0::3], 1: numbers[1::3], 2: numbers[2::3]}
    elif n == 2 * blanks and slashes == 2 * blanks:                          # a//c
        columns = {0: numbers[0::2], 2: numbers[1::2]}
    elif n == 2 * blanks and slashes == blanks and _one_slash_per_corner(faces):  # a/b
        columns = {0: numbers[0::2], 1: numbers[1::2]}
    else:
        return None
    return tuple(int(columns[k].max()) if k in columns else 0 for k in range(3))


def _one_slash_per_corner(faces: bytes) -> bool:
    """True if no corner holds two slashes: after each '/', its digits end in a blank.

    (With ``2·slashes == numbers`` and no '//', corners ``a`` and ``a/b/c`` in equal
    numbers give the same totals as corners that are all ``a/b``.)
    """
    a = np.frombuffer(faces, dtype=np.uint8)
    pos = np.flatnonzero(a == ord("/")) + 1
    for _ in range(24):  # past the sign and digits of one index
        c = a[np.minimum(pos, len(a) - 1)]
        more = (pos < len(a)) & (((c >= ord("0")) & (c <= ord("9"))) | (c == ord("-")) | (c == ord("+")))
        if not more.any():
            break
        pos = pos + more
    return not ((pos < len(a)) & (a[np.minimum(pos, len(a) - 1)] == ord("/"))).any()


def _scan_lines(data: bytes) -> None:
    """Line by line: raise at the first positive index past its kind's last line."""
    lines = data.split(b"\n")
    counts = [0, 0, 0]
    for line in lines:
        word = line.split(None, 1)[:1]
        if word in ([b"v"], [b"vt"], [b"vn"]):
            counts[(b"v", b"vt", b"vn").index(word[0])] += 1
    number, pending = 0, b""
    for number, line in enumerate(lines, 1):
        text = pending + line
        if text.rstrip().endswith(b"\\"):  # continued on the next line, as VTK reads it
            pending = text.rstrip()[:-1] + b" "
            continue
        pending = b""
        words = text.split()
        if words[:1] != [b"f"]:
            continue
        for corner in words[1:]:
            for kind, part in enumerate(corner.split(b"/")[:3]):
                try:
                    index = int(part)
                except ValueError:
                    continue  # not a number: VTK's reader says so itself
                if index > counts[kind]:
                    raise ValueError(f"line {number}: a face refers to {KINDS[kind]} {index}, "
                                     f"but there are {counts[kind]}")
