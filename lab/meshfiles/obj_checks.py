"""An OBJ file's face indices, checked before VTK's reader sees them.

vtkOBJReader (VTK 9.7) does not check that a face's ``v/vt/vn`` indices refer to lines
that exist. Where it copies a point per face corner (a point used with several ``vt`` or
``vn``), an index past the end reads unrelated memory: a vertex at a made-up place, a
normal of zeros, or a crash of the whole process. So every positive index is compared
here with the number of ``v``, ``vt`` and ``vn`` lines in the whole file, as VTK resolves
them (negative, relative indices VTK checks itself).

Three ways, from the quickest; each hands on to the next what it cannot settle:

- :func:`_quick`, for the usual layout (the corners all of one form: ``a``, ``a/b``,
  ``a//c`` or ``a/b/c``): numpy finds the digit runs of the face lines without parsing
  them, and compares each kind's longest ones with the number of its lines, digit by
  digit, a block of lines at a time;
- :func:`_index_maxima`, any layout: the face lines are cut out, parsed in one call and
  their largest index of each kind taken;
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
    if _quick(data):
        return
    counts, faces = _statements(data)
    maxima = None if faces is None else _index_maxima(faces)
    if maxima is not None and all(m <= n for m, n in zip(maxima, counts)):
        return
    _scan_lines(bytes(data))


# --------------------------------------------------------------------------- lines
def _line_starts(a: np.ndarray) -> np.ndarray:
    """Where each line of ``a`` starts (a line ends with "\\n" or the end of ``a``)."""
    if len(a) == 0:
        return np.zeros(0, dtype=np.int64)
    return np.concatenate([[0], np.flatnonzero(a[:-1] == ord("\n")) + 1])


def _first_bytes(a: np.ndarray, starts: np.ndarray, offset: int) -> np.ndarray:
    """The byte ``offset`` into each line ("\\n" past a line's end)."""
    ends = np.append(starts[1:], len(a))
    pos = starts + offset
    return np.where(pos < ends, a[np.minimum(pos, max(len(a) - 1, 0))], ord("\n"))


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


def _statements(data) -> tuple[tuple[int, int, int], bytes | None]:
    """Numbers of ``v``, ``vt`` and ``vn`` lines, and the bytes of all ``f`` lines, in any layout.

    The face bytes are None for a layout the vectorised ways do not read: a statement
    after leading blanks, or a line continued with a backslash.
    """
    a = np.frombuffer(data, dtype=np.uint8)
    if len(a) == 0:
        return (0, 0, 0), b""
    starts = _line_starts(a)
    c0, c1, c2 = (_first_bytes(a, starts, k) for k in range(3))
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


# --------------------------------------------------------------------------- forms
def _columns(n: int, slashes: int, blanks: int, faces: np.ndarray) -> int | None:
    """How many numbers each corner holds, if all corners have one form; else None.

    A corner holds at most 3 numbers and 2 slashes (VTK refuses more), and follows at least
    one blank, so there are at least as many blanks as corners. ``n = 3·blanks`` then
    means 3 numbers in every corner (``a/b/c``); ``n = 2·blanks`` with 2 slashes a corner
    means ``a//c`` everywhere; ``n = 2·blanks`` with one slash a corner on average may
    still mix ``a`` and ``a/b/c``, which :func:`_one_slash_per_corner` tells apart.
    Returns 1, 2 (``a//c``: the columns are v and vn), -2 (``a/b``: v and vt) or 3.
    """
    if slashes == 0:
        return 1
    if n == 3 * blanks:
        return 3
    if n == 2 * blanks and slashes == 2 * blanks:
        return 2
    if n == 2 * blanks and slashes == blanks and _one_slash_per_corner(faces):
        return -2
    return None


KIND_COLUMNS = {1: (0,), 2: (0, 2), -2: (0, 1), 3: (0, 1, 2)}
"""For each form, the kind (v 0, vt 1, vn 2) of each number in a corner."""


def _one_slash_per_corner(a: np.ndarray) -> bool:
    """True if no corner holds two slashes: after each '/', its digits end in a blank.

    (With ``2·slashes == numbers`` and no '//', corners ``a`` and ``a/b/c`` in equal
    numbers give the same totals as corners that are all ``a/b``.)
    """
    pos = np.flatnonzero(a == ord("/")) + 1
    for _ in range(24):  # past the sign and digits of one index
        c = a[np.minimum(pos, len(a) - 1)]
        more = (pos < len(a)) & (((c >= ord("0")) & (c <= ord("9"))) | (c == ord("-")) | (c == ord("+")))
        if not more.any():
            break
        pos = pos + more
    return not ((pos < len(a)) & (a[np.minimum(pos, len(a) - 1)] == ord("/"))).any()


# --------------------------------------------------------------------------- the quick way
BLOCK = 1 << 22
"""Bytes handled at once by the quick way (whole lines): its arrays stay small and reused."""


def _blocks(data, start: int, stop: int):
    """(begin, end) of consecutive pieces of ``data[start:stop]`` of about BLOCK bytes, each
    ending after a newline (or at ``stop``)."""
    while start < stop:
        end = stop if stop - start <= BLOCK else data.rfind(b"\n", start, start + BLOCK) + 1
        if end <= start:  # a line longer than a block
            end = stop if data.find(b"\n", start + BLOCK, stop) < 0 else data.find(b"\n", start + BLOCK, stop) + 1
        yield start, end
        start = end


def _quick(data) -> bool:
    """True if the usual layout shows every index within its kind's count, without parsing.

    The usual layout: no line starts with a blank or is continued with a backslash, and
    the corners of all faces have one form (``a``, ``a/b``, ``a//c`` or ``a/b/c``); other
    statements (``usemtl``, ``g``, ``s``, more ``v`` ...) may come between the faces.
    False means "not shown": the exact ways decide. The file is read in blocks of whole
    lines (:data:`BLOCK`): the ``v``, ``vt``, ``vn`` lines counted first, then the faces.
    """
    first = _first_face_line(data)
    if first < 0 or data.find(b"\\") >= 0:
        return False
    a = np.frombuffer(data, dtype=np.uint8)
    counts = [0, 0, 0]
    for lo, hi in _blocks(data, 0, len(a)):
        piece = a[lo:hi]
        starts = _line_starts(piece)
        c0, c1, c2 = (_first_bytes(piece, starts, k) for k in range(3))
        if ((c0 == _BLANK[0]) | (c0 == _BLANK[1])).any():
            return False
        counts = [n + m for n, m in zip(counts, _counts(c0, c1, c2))]
    form = None
    for lo, hi in _blocks(data, first, len(a)):
        piece = a[lo:hi]
        starts = _line_starts(piece)
        f0, f1 = _first_bytes(piece, starts, 0), _first_bytes(piece, starts, 1)
        other = ~(((f0 == ord("f")) & ((f1 == _BLANK[0]) | (f1 == _BLANK[1]))) | (f0 == ord("\n")) | (f0 == ord("\r")))
        if other.any():  # blank out the lines that are not faces: their digits are no indices
            piece = piece.copy()
            piece[np.repeat(other, np.diff(np.append(starts, len(piece))))] = ord("\n")
        here = _runs_within(counts, piece)
        if here is None or (form is not None and here != form):
            return False
        form = here
    return True


def _runs_within(counts, faces: np.ndarray) -> int | None:
    """The corners' form (see :func:`_columns`) if every index in ``faces`` (whole face
    lines, uint8) is at most its kind's count; None if that is not shown this way.

    The indices are the digit runs of the lines, found without parsing them; the k-th run
    belongs to kind ``k mod (numbers per corner)``. A run longer than its count's digits,
    or as long and greater digit by digit, may be too large (a sign or leading zeros make
    this cautious, never lenient).
    """
    digit = (faces - ord("0")) < 10  # uint8 arithmetic: every other byte wraps past 9
    edges = np.flatnonzero(digit[1:] != digit[:-1]) + 1  # where runs start and end, in turn
    if len(digit) and digit[0]:
        edges = np.concatenate([[0], edges])
    if len(digit) and digit[-1]:
        edges = np.append(edges, len(faces))
    starts, lengths = edges[0::2], edges[1::2] - edges[0::2]
    slashes = int(np.count_nonzero(faces == ord("/")))
    blanks = int(np.count_nonzero(faces == _BLANK[0])) + int(np.count_nonzero(faces == _BLANK[1]))
    form = _columns(len(starts), slashes, blanks, faces)
    if form is None:
        return None
    step = abs(form)
    within = all(_at_most(faces, starts[c::step], lengths[c::step], counts[kind])
                 for c, kind in enumerate(KIND_COLUMNS[form]))
    return form if within else None


def _at_most(a: np.ndarray, starts: np.ndarray, lengths: np.ndarray, limit: int) -> bool:
    """True if every digit run (``starts``, ``lengths`` into ``a``) reads as at most ``limit``."""
    if len(lengths) == 0:
        return True
    if limit <= 0:
        return False
    text = str(limit).encode()
    if lengths.max() > len(text):
        return False
    tied = starts[lengths == len(text)]  # as long as the limit: compare digit by digit
    for j, d in enumerate(text):
        c = a[tied + j]
        if (c > d).any():
            return False
        tied = tied[c == d]
        if len(tied) == 0:
            break
    return True


# --------------------------------------------------------------------------- the exact ways
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
    if len(numbers) == 0:
        return 0, 0, 0
    a = np.frombuffer(faces, dtype=np.uint8)
    form = _columns(len(numbers), faces.count(b"/"), faces.count(b" ") + faces.count(b"\t"), a)
    if form is None:
        return None
    step, maxima = abs(form), [0, 0, 0]
    for c, kind in enumerate(KIND_COLUMNS[form]):
        maxima[kind] = int(numbers[c::step].max())
    return tuple(maxima)


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
