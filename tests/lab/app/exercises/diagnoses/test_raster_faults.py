"""Raster family: the pixel classes with the first pixel and triangles of each."""
from lab.app.exercises.diagnoses.codes import Finding, text


def test_the_raster_summary_names_the_first_pixel_of_each_class():
    first = {"x": 3, "y": 4, "mesh": "fan", "mesh_ja": "扇", "triangles": [5, 6], "corners": "(0, 0) (1, 0) (0, 1)"}
    f = Finding("coverage-differs", {"counts": {"correct": 10, "missing": 0, "duplicated": 2, "unexpected": 0},
                                     "triangles": 7, "meshes": 1, "first": {"duplicated": first}})
    assert "duplicated 2: first pixel (3, 4) of mesh 'fan', triangles 5 and 6" in text(f, "en")
    assert "重複 2 画素" in text(f, "ja") and "三角形 5 と 6" in text(f, "ja")
