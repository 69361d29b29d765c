"""Mesh family: the figures of the surface in the message."""
from lab.app.exercises.diagnoses.codes import Finding, text


def test_mesh_messages_quote_the_figures():
    f = Finding("wrong-subcubes", {"case": "menger(1)", "volume": 26 / 27, "cells": 26, "side": 3, "expected": 20,
                                   "expected_volume": 20 / 27})
    assert "26 cubes of side 1/3, not of 20" in text(f, "en") and "26 個分" in text(f, "ja")
    misplaced = Finding("wrong-subcubes", {**f.details, "cells": 20, "misplaced": 48})
    assert "right number of cubes (20) but not the right ones: 48 triangles" in text(misplaced, "en")
