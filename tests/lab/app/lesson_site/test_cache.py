"""lab/app/lesson_site/cache.py: a figure is drawn once per version of what decides its pixels."""
from __future__ import annotations

from lab.app.lesson_site.cache import cached, figure_key, prune, source_files, sources_hash


def test_the_key_changes_with_the_files_and_the_options(tmp_path):
    scene = tmp_path / "a.toml"
    scene.write_text("x = 1\n")
    first = figure_key([str(scene)], {"shading": None})
    assert figure_key([str(scene)], {"shading": None}) == first
    assert figure_key([str(scene)], {"shading": "phong"}) != first
    scene.write_text("x = 2\n")
    assert figure_key([str(scene)], {"shading": None}) != first


def test_the_sources_hash_covers_renderer_compare_and_the_site():
    names = {p.parent.name for p in source_files()}
    assert {"renderer", "compare", "lesson_site"} <= names and len(sources_hash()) == 16


def test_an_entry_is_made_once_and_found_again(tmp_path):
    calls = []

    def make(folder):
        calls.append(folder)
        (folder / "ours.png").write_bytes(b"png")
        return {"metrics": 1}

    entry, result = cached(tmp_path, "k1", make)
    again, result2 = cached(tmp_path, "k1", make)
    assert len(calls) == 1 and entry == again == tmp_path / "k1" and result == result2 == {"metrics": 1}
    assert sorted(p.name for p in entry.iterdir()) == ["ours.png", "result.json"]
    assert [p.name for p in tmp_path.iterdir()] == ["k1"]  # no temporary folder left behind


def test_a_failed_drawing_leaves_nothing(tmp_path):
    def make(folder):
        (folder / "half.png").write_bytes(b"p")
        raise RuntimeError("VTK died")

    try:
        cached(tmp_path, "k2", make)
    except RuntimeError:
        pass
    assert list(tmp_path.iterdir()) == []


def test_prune_keeps_what_the_pages_show(tmp_path):
    for key in ("a", "b", "c"):
        (tmp_path / key).mkdir()
    assert prune(tmp_path, {"b"}) == ["a", "c"] and [p.name for p in tmp_path.iterdir()] == ["b"]
