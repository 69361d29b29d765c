"""Specification of ``lab.meshfiles.messages``: VTK's reports as one line each."""
from __future__ import annotations

from lab.meshfiles.messages import one_line

OBJ = "ERROR: In vtkOBJReader.cxx, line 340\nvtkOBJReader (0x55d7001b530): Failed to parse 2th vertex value at L.1\n\n"
FAILURE = ("ERROR: In vtkExecutive.cxx, line 729\nvtkCompositeDataPipeline (0x55d6f920ad0): Algorithm vtkOBJReader "
           "(0x55d7001b530) returned failure for request: vtkInformation (0x55d7049a550)\n  Debug: Off\n")


def test_line_number_first_and_reworded():
    assert one_line([OBJ, FAILURE]) == "line 1: a vertex needs 3 numbers (x y z)"


def test_the_pipeline_failure_counts_only_alone():
    assert one_line([FAILURE]) == "VTK's reader failed without saying why"
    assert one_line([FAILURE, OBJ]) == "line 1: a vertex needs 3 numbers (x y z)"


def test_warnings_and_plain_messages():
    warning = "Warning: In vtkOBJReader.cxx, line 190\nvtkOBJReader (0x1): unexpected data at end of line in OBJ file L.4\n"
    assert one_line([warning]) == "line 4: unexpected data at end of line in OBJ file"
    plain = "ERROR: In vtkPolyDataReader.cxx, line 130\nvtkPolyDataReader (0x2): Cannot read dataset type: unstructured_grid\n"
    assert one_line([plain]) == "only DATASET POLYDATA is supported, not unstructured_grid"
    assert one_line(["ERROR: In x.cxx, line 1\nvtkXMLDataParser (0x3): Error parsing XML\n  at byte 0\n"]) == \
        "Error parsing XML at byte 0"


def test_nothing_said():
    assert one_line([]) is None and one_line(["", "  \n"]) is None
