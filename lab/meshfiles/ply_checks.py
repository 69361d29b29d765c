"""A PLY file, checked where VTK's reader (vtkPLYReader, VTK 9.7) would misread it or crash.

Before VTK reads (:func:`check`):

- the header: the ``ply`` … ``end_header`` frame, known property types, a ``vertex``
  element with x, y, z and a ``face`` element with a ``vertex_indices`` list. Triangle
  strips (a ``tristrips`` element, as in several scanned models) are refused by name:
  VTK's reader skips them without a word and would give a mesh with no faces;
- binary data: exactly as long as the header says. A shorter file makes VTK's reader read
  past its end (it crashed on a face list cut short); a longer one holds values the
  header does not declare, which shift every record after them.

After VTK has read an ASCII file (the function :func:`check` returns): VTK reads the values
one after another, ignoring line ends, so a line with more values than its header declares
(MeshLab writes such files) or fewer makes every later record garbage, silently. The
quick test is that the file has one line per record and that the first and last vertex
and face lines hold what VTK read for them; when that fails, :func:`_diagnose_ascii` walks
the lines and names the first that does not match the header. (A file with one line too
long and another too short by the same count passes the quick test: not guarded.)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
         "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
         "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}
"""PLY property types and their numpy types (the types VTK's PLY reader knows)."""

FORMATS = {"ascii": None, "binary_little_endian": "<", "binary_big_endian": ">"}
FACE_LISTS = ("vertex_indices", "vertex_index")
STRIP_ELEMENTS = ("tristrips",)


@dataclass(frozen=True)
class Property:
    name: str
    type: np.dtype              # a scalar's type, or a list's item type
    count_type: np.dtype | None  # a list's count type; None for a scalar


@dataclass(frozen=True)
class Element:
    name: str
    count: int
    properties: tuple[Property, ...]

    def lists(self) -> list[Property]:
        return [p for p in self.properties if p.count_type is not None]


@dataclass(frozen=True)
class Header:
    format: str
    elements: tuple[Element, ...]
    size: int    # bytes up to and including the end_header line
    lines: int   # lines up to and including the end_header line

    def element(self, name: str) -> Element | None:
        return next((e for e in self.elements if e.name == name), None)


def parse_header(data: bytes) -> Header:
    """The header of a PLY file; ValueError for anything VTK's reader would not take."""
    end = data.find(b"end_header")
    newline = data.find(b"\n", end)
    if data[:3] != b"ply" or end < 0:
        raise ValueError("not a PLY file (no 'ply' ... 'end_header' header)")
    size = len(data) if newline < 0 else newline + 1
    lines = data[:size].decode("ascii", "replace").splitlines()
    fmt, elements = None, []
    for number, line in enumerate(lines[1:-1], 2):
        words = line.split()
        where = f"header line {number}"
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format" and len(words) == 3:
            fmt = words[1]
        elif words[0] == "element" and len(words) == 3 and words[2].isdigit():
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and elements and len(words) in (3, 5):
            types = words[2:4] if words[1] == "list" and len(words) == 5 else words[1:2]
            unknown = [t for t in types if t not in TYPES]
            if unknown:
                raise ValueError(f"{where}: unknown PLY property type {unknown[0]!r}")
            count_type = np.dtype(TYPES[types[0]]) if len(types) == 2 else None
            elements[-1][2].append(Property(words[-1], np.dtype(TYPES[types[-1]]), count_type))
        else:
            raise ValueError(f"{where}: cannot read {line.strip()[:60]!r}")
    if fmt not in FORMATS:
        raise ValueError(f"unsupported PLY format {fmt!r} (known: {', '.join(FORMATS)})")
    return Header(fmt, tuple(Element(n, c, tuple(p)) for n, c, p in elements), size, len(lines))


def _face_list(header: Header) -> Property | None:
    face = header.element("face")
    return None if face is None else next((p for p in face.lists() if p.name in FACE_LISTS), None)


def _check_elements(header: Header) -> None:
    """The elements VTK needs are there, and none it would skip in silence."""
    vertex = header.element("vertex")
    scalars = set() if vertex is None else {p.name for p in vertex.properties if p.count_type is None}
    if not {"x", "y", "z"} <= scalars:
        raise ValueError("no 'vertex' element with x, y, z properties")
    strips = [e.name for e in header.elements if e.name in STRIP_ELEMENTS]
    if strips:
        raise ValueError(f"triangle strips (element '{strips[0]}') are not supported: VTK's PLY reader "
                         "skips them (convert them to faces, e.g. in MeshLab)")
    if _face_list(header) is None:
        raise ValueError("no 'face' element with a vertex_indices list")


def check(data):
    """Check ``data`` (the file's bytes, or an ``mmap`` of them) before VTK reads it; return
    the check to run on what VTK read, or None.

    Raises
    ------
    ValueError
        A header VTK would not read right, triangle strips, binary data of the wrong
        length (see the module's docstring).
    """
    header = parse_header(data)
    _check_elements(header)
    if header.format != "ascii":
        _check_binary_length(data, header)
        return None
    return lambda arrays: _check_ascii(data, header, arrays)


# --------------------------------------------------------------------------- binary
def _binary_element_end(body, pos: int, element: Element, order: str) -> int:
    """Where ``element``'s records end in ``body``, starting at ``pos``; ValueError if the
    data ends first."""
    def ends_early(done):
        return ValueError(f"the file ends inside element '{element.name}' (after {done} of {element.count} "
                          "records): it is cut short or its header is wrong")

    layout, size, first = [], 0, pos
    for i, prop in enumerate(element.properties):  # the first record's layout
        if prop.count_type is None:
            layout.append((f"p{i}", prop.type.newbyteorder(order)))
            size += prop.type.itemsize
            continue
        if element.count and first + size + prop.count_type.itemsize > len(body):
            raise ends_early(0)
        k = int(np.frombuffer(body, prop.count_type.newbyteorder(order), 1, first + size)[0]) if element.count else 0
        layout += [(f"n{i}", prop.count_type.newbyteorder(order)), (f"p{i}", prop.type.newbyteorder(order), (k,))]
        size += prop.count_type.itemsize + k * prop.type.itemsize
    if element.count == 0:
        return pos
    record = np.dtype(layout)
    fits = (len(body) - pos) // record.itemsize
    lists = [name for name, *_ in layout if name.startswith("n")]
    if fits >= element.count:
        records = np.frombuffer(body, record, element.count, pos)
        if all((records[n] == records[n][0]).all() for n in lists):  # every record like the first
            return pos + element.count * record.itemsize
    elif not lists:
        raise ends_early(fits)
    for done in range(element.count):  # lists of different lengths: record by record
        for prop in element.properties:
            if prop.count_type is None:
                pos += prop.type.itemsize
                continue
            if pos + prop.count_type.itemsize > len(body):
                raise ends_early(done)
            k = int(np.frombuffer(body, prop.count_type.newbyteorder(order), 1, pos)[0])
            pos += prop.count_type.itemsize + k * prop.type.itemsize
        if pos > len(body):
            raise ends_early(done)
    return pos


def _check_binary_length(data: bytes, header: Header) -> None:
    body, pos = memoryview(data)[header.size:], 0
    for element in header.elements:
        pos = _binary_element_end(body, pos, element, FORMATS[header.format])
    if pos != len(body):
        raise ValueError(f"{len(body) - pos} bytes after the last element ('{header.elements[-1].name}'): "
                         "values its header does not declare")


# --------------------------------------------------------------------------- ascii
def _record_values(words: list[bytes], element: Element) -> int:
    """How many values a record of ``element`` has, its list lengths taken from ``words``."""
    n = 0
    for prop in element.properties:
        if prop.count_type is None:
            n += 1
        elif n < len(words):
            try:
                n += 1 + int(words[n])
            except ValueError:
                return -1
        else:
            return -1
    return n


def _list_values(words: list[bytes], element: Element, name: str) -> list[int] | None:
    """The integers of list property ``name`` in a record's ``words``, or None."""
    n = 0
    for prop in element.properties:
        if prop.count_type is None:
            n += 1
            continue
        k = int(words[n])
        if prop.name == name:
            return [int(w) for w in words[n + 1:n + 1 + k]]
        n += 1 + k
    return None


def _check_ascii(data, header: Header, arrays) -> None:
    """VTK read every record from its own line (quick test, else :func:`_diagnose_ascii`).

    The quick test: as many lines as records, and the first and the last line hold what
    VTK read for the first and the last record. VTK reads values one after another, so a
    line with values too many or too few anywhere before the last shifts the last record.
    """
    start, stop = header.size, len(data)
    while stop > start and data[stop - 1] in b" \t\r\n":  # trailing blank lines are nothing
        stop -= 1
    body = np.frombuffer(data, dtype=np.uint8, count=stop - start, offset=start)
    block = 1 << 22  # counted a block at a time: no array the size of the file
    lines = sum(int(np.count_nonzero(body[i:i + block] == ord("\n"))) for i in range(0, len(body), block))
    lines += 1 if stop > start else 0
    records = sum(e.count for e in header.elements)
    newline = data.find(b"\n", start, stop)
    first = data[start:stop if newline < 0 else newline]
    last = data[data.rfind(b"\n", start, stop) + 1 if newline >= 0 else start:stop]
    if lines != records or not (_record_matches(first.split(), header, 0, arrays)
                                and _record_matches(last.split(), header, records - 1, arrays)):
        _diagnose_ascii(bytes(data[header.size:]), header)


def _record_matches(words: list[bytes], header: Header, index: int, arrays) -> bool:
    """``words`` (one line) are record ``index`` of the file as the header lays it out, and
    hold what VTK read for it (a vertex's x, y, z; a face's vertex indices)."""
    for element in header.elements:
        if index >= element.count:
            index -= element.count
            continue
        if _record_values(words, element) != len(words):
            return False
        if element.name == "vertex" and not element.lists():
            names = [p.name for p in element.properties]
            xyz = np.array([float(words[names.index(c)]) for c in "xyz"], dtype=arrays.points.dtype)
            return bool(np.allclose(xyz, arrays.points[index], rtol=1e-6, atol=0, equal_nan=True))
        if element.name == "face":
            offsets, connectivity = arrays.polys
            return len(offsets) == element.count + 1 and _list_values(words, element, _face_list(header).name) \
                == connectivity[offsets[index]:offsets[index + 1]].tolist()
        return True
    return False


def _diagnose_ascii(body: bytes, header: Header) -> None:
    """Walk the lines: raise at the first record line whose values do not match the header;
    return if every record has its own line (blank lines aside)."""
    lines = body.split(b"\n")
    number = 0  # index into lines
    for element in header.elements:
        for r in range(element.count):
            while number < len(lines) and not lines[number].strip():
                number += 1
            if number >= len(lines):
                raise ValueError(f"the file ends after {r} of {element.count} '{element.name}' records")
            w = lines[number].split()
            n = _record_values(w, element)
            if n != len(w):
                declared = "values with a list length it cannot read" if n < 0 else str(n)
                raise ValueError(f"line {header.lines + number + 1}: {element.name} {r + 1} has {len(w)} values, "
                                 f"its header declares {declared}")
            number += 1
    rest = [i for i in range(number, len(lines)) if lines[i].strip()]
    if rest:
        raise ValueError(f"line {header.lines + rest[0] + 1}: values after the last element "
                         f"('{header.elements[-1].name}') that its header does not declare")
