"""Legacy VTK (``.vtk``) reader: DATASET POLYDATA, ASCII or big-endian BINARY."""
from __future__ import annotations

import re

import numpy as np

from lab.mesh import Mesh
from lab.meshfiles._common import make_mesh, polygon_triangles, reading, split_counted, strip_triangles


_VTK_TYPES = {"bit": "u1", "unsigned_char": "u1", "char": "i1", "signed_char": "i1", "unsigned_short": "u2",
              "short": "i2", "unsigned_int": "u4", "int": "i4", "unsigned_long": "u8", "long": "i8",
              "vtktypeint64": "i8", "vtktypeuint64": "u8", "vtkidtype": "i4", "float": "f4", "double": "f8"}


class _Legacy:
    """A cursor over a legacy VTK file: keyword lines, each followed by ASCII or binary data."""

    def __init__(self, data, pos, binary):
        self.data, self.pos, self.binary = data, pos, binary

    def line(self):
        """Words of the next non-blank line; [] at the end of the file."""
        while self.pos < len(self.data):
            end = self.data.find(b"\n", self.pos)
            end = len(self.data) if end < 0 else end
            words = self.data[self.pos:end].decode("latin-1").split()
            self.pos = end + 1
            if words:
                return words
        return []

    def values(self, n, vtk_type):
        """The next ``n`` values of a VTK type (big-endian when binary)."""
        if vtk_type.lower() not in _VTK_TYPES:
            raise ValueError(f"unsupported legacy VTK data type {vtk_type!r}")
        dtype = np.dtype(_VTK_TYPES[vtk_type.lower()]).newbyteorder(">")
        if self.binary:
            nbytes = (n + 7) // 8 if vtk_type.lower() == "bit" else n * dtype.itemsize
            values = np.frombuffer(self.data, dtype, nbytes // dtype.itemsize, self.pos)
            self.pos += nbytes
            return values
        words = self.data[self.pos:].split(None, n)
        if len(words) < n:
            raise ValueError("file ends inside a data array")
        self.pos = len(self.data) - (len(words[n]) if len(words) > n else 0)
        return np.array(words[:n]).astype(dtype.newbyteorder("="))  # parsed as declared, like VTK

    def cells(self, n, size):
        """(offsets, connectivity) of a cell section, classic or 5.1 (OFFSETS) layout."""
        start = self.pos
        words = self.line()
        if words[:1] != ["OFFSETS"]:
            self.pos = start
            return split_counted(self.values(size, "int"), n)
        offsets = self.values(n, words[1])
        words = self.line()
        if words[:1] != ["CONNECTIVITY"]:
            raise ValueError("OFFSETS without CONNECTIVITY")
        return offsets, self.values(size, words[1])


def read_vtk_legacy(path) -> Mesh:
    """Read a legacy ``.vtk`` file holding ``DATASET POLYDATA``, ASCII or BINARY.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Triangles of POLYGONS, then of TRIANGLE_STRIPS; normals from POINT_DATA NORMALS;
        texture coordinates from the first POINT_DATA TEXTURE_COORDINATES (the one VTK
        makes active) when it has 2 components (1- or 3-component ones give none).

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
        head = data.split(b"\n", 3)
        if not data.startswith(b"# vtk DataFile") or len(head) < 4:
            raise ValueError("not a legacy VTK file (no '# vtk DataFile' header)")
        mode = head[2].strip().upper()
        if mode not in (b"ASCII", b"BINARY"):
            raise ValueError(f"third line must be ASCII or BINARY, not {head[2].strip()[:20]!r}")
        f = _Legacy(data, len(data) - len(head[3]), mode == b"BINARY")
        words = f.line()
        if [w.upper() for w in words[:2]] != ["DATASET", "POLYDATA"]:
            raise ValueError(f"only DATASET POLYDATA is supported, not {' '.join(words)[:40]!r}")
        points = normals = tcoords = None
        seen_tcoords = False  # only the first point TEXTURE_COORDINATES is the active one
        polys, strips = (np.zeros(1), np.zeros(0)), (np.zeros(1), np.zeros(0))
        n_values, point_data = 0, False  # tuples per attribute in the current *_DATA section
        byte = "unsigned_char" if f.binary else "float"
        sizes = {"VECTORS": 3, "NORMALS": 3, "TENSORS": 9, "TENSORS6": 6}  # components; type in words[2]
        while words := f.line():
            key = words[0].upper()
            if key == "POINTS":
                points = f.values(3 * int(words[1]), words[2])
            elif key in ("VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"):
                cells = f.cells(int(words[1]), int(words[2]))
                polys = cells if key == "POLYGONS" else polys
                strips = cells if key == "TRIANGLE_STRIPS" else strips
            elif key in ("POINT_DATA", "CELL_DATA"):
                n_values, point_data = int(words[1]), key == "POINT_DATA"
            elif key in sizes:
                values = f.values(sizes[key] * n_values, words[2])
                if key == "NORMALS" and point_data and normals is None:
                    normals = values
            elif key == "SCALARS":
                if f.line()[:1] != ["LOOKUP_TABLE"]:
                    raise ValueError("SCALARS without LOOKUP_TABLE")
                f.values(n_values * (int(words[3]) if len(words) > 3 else 1), words[2])
            elif key in ("GLOBAL_IDS", "PEDIGREE_IDS"):
                f.values(n_values, words[2])
            elif key == "TEXTURE_COORDINATES":
                values = f.values(n_values * int(words[2]), words[3])
                if point_data and not seen_tcoords:
                    seen_tcoords = True
                    tcoords = values if int(words[2]) == 2 else None
            elif key == "COLOR_SCALARS":
                f.values(n_values * int(words[2]), byte)
            elif key == "LOOKUP_TABLE":
                f.values(4 * int(words[2]), byte)
            elif key == "FIELD":
                for _ in range(int(words[2])):
                    array = f.line()
                    if array[:1] != ["NULL_ARRAY"]:
                        f.values(int(array[1]) * int(array[2]), array[3])
            elif key == "METADATA":  # information keys, up to an empty line
                end = re.compile(rb"\n[ \t\r]*\n").search(data, f.pos - 1)
                f.pos = len(data) if end is None else end.end()
            else:
                raise ValueError(f"unexpected keyword {words[0][:40]!r}")
        if points is None:
            raise ValueError("no POINTS")
        triangles = np.concatenate([polygon_triangles(*polys), strip_triangles(*strips)])
        return make_mesh(points, triangles, normals, tcoords)
