"""VTK's error and warning texts, made into the one-line messages scanlab prints.

VTK reports a problem as ``"ERROR: In vtkOBJReader.cxx, line 340\\nvtkOBJReader
(0x55…): Failed to parse 2th vertex value at L.1\\n\\n"``. :func:`one_line` keeps what the
reader said, puts a line number first (``"line 1: …"``), and rewords the few messages a
user of scanlab would not understand as VTK words them (:data:`REWORDED`).
"""
from __future__ import annotations

import re

REWORDED = [
    (r"Failed to parse \d+th vertex value", "a vertex needs 3 numbers (x y z)"),
    (r"Failed to parse \d+th normal value", "a normal needs 3 numbers"),
    (r"Failed to parse \d+th tcoord value", "a texture coordinate needs 2 numbers"),
    (r"Cannot read dataset type: (\S+)", "only DATASET POLYDATA is supported, not {0}"),
    (r"Unrecognized file type: .*", "not a legacy VTK file (no '# vtk DataFile' header)"),
    (r"Number of points don't match number data values!",
     "the point data (normals, texture coordinates, ...) does not have one value per point"),
    (r"Error parsing input file\.\s+ReadXMLInformation aborting\.", "not valid VTK XML"),
]
"""(VTK's words as a regular expression, ours) for messages that need rewording."""

_HEADER = re.compile(r"^(?:ERROR|Warning|Generic Warning|Debug): In [^\n]*, line \d+\n")
_SOURCE = re.compile(r"^\w+ \(0x[0-9a-fA-F]+\): ")
_FAILURE = "returned failure for request"


def _clean(text: str) -> str:
    """The message part of one VTK report, on one line."""
    text = _HEADER.sub("", text.strip())
    text = _SOURCE.sub("", text.strip())
    return " ".join(text.split())


def one_line(reports: list[str]) -> str | None:
    """The first informative report among VTK's ``reports`` as one line, or None if none.

    The pipeline's own "Algorithm … returned failure for request" only counts when the
    reader said nothing else. A trailing ``L.12`` (VTK's line number) becomes a leading
    ``line 12:``.

    Examples
    --------
    >>> one_line(["ERROR: In vtkOBJReader.cxx, line 340\\nvtkOBJReader (0x5): Failed to parse 2th vertex value at L.1\\n"])
    'line 1: a vertex needs 3 numbers (x y z)'
    """
    cleaned = [_clean(r) for r in reports if r and r.strip()]
    useful = [c for c in cleaned if _FAILURE not in c] or [
        "VTK's reader failed without saying why" for c in cleaned if _FAILURE in c]
    if not useful:
        return None
    text = useful[0]
    line = None
    match = re.search(r"\s*(?:in OBJ file )?at L\.\s?(\d+)\.?$|\s*L\.(\d+)$", text)
    if match:
        line = match.group(1) or match.group(2)
        text = text[:match.start()].rstrip()
    for pattern, ours in REWORDED:
        found = re.fullmatch(pattern, text)
        if found:
            text = ours.format(*found.groups())
            break
    text = text.rstrip(".")
    return f"line {line}: {text}" if line else text
