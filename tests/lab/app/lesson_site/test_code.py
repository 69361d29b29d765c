"""lab/app/lesson_site/code.py: a lesson can only name code and tests that exist."""
from lab.app.lesson_site.code import problem


def test_existing_files_and_definitions_are_accepted():
    assert problem("renderer/raster.py::scanline_span") is None
    assert problem("lab/mesh.py::Mesh") is None
    assert problem("tests/renderer/test_raster.py") is None


def test_missing_files_and_definitions_are_named():
    assert problem("renderer/nothing.py") == "renderer/nothing.py: no such file in the repository"
    assert problem("renderer/raster.py::scanline_fill") == "renderer/raster.py: defines no scanline_fill"
