"""The mesh exercises' shared judge: a code reported once, for its first case; the picture drawn."""
from lab import shapes
from lab.app.exercises.catalogue.icosphere import SPEC
from lab.app.exercises.meshexercise import judge_meshes
from lab.app.exercises.exercise_registry import get


def results(make):
    return [[m.points, m.triangles] for m in (make(c.args[0]) for c in get("icosphere").cases())]


def test_a_mistake_in_every_case_is_reported_once_for_the_first():
    cases = get("icosphere").cases()
    j = judge_meshes(SPEC, cases, results(lambda n: (lambda m: type(m)(m.points, m.triangles[:, ::-1]))(
        shapes.icosphere(n))))
    assert [f.code for f in j.findings] == ["faces-inward"]
    assert j.findings[0].details["case"] == "icosphere(0)"
    assert len(j.checked["en"]) == len(cases) + 1 and j.checked["en"][-1].startswith("icosphere(2) drawn")


def test_the_reference_is_right_and_drawn():
    j = judge_meshes(SPEC, get("icosphere").cases(), results(shapes.icosphere))
    assert j.findings == [] and j.panels[0].failed == []
