"""lab/app/lesson_site/record.py: what pages note survives parallel reading and is forgotten on re-reading."""
from types import SimpleNamespace

from lab.app.lesson_site import record


def test_notes_are_merged_from_other_processes_and_purged_per_page():
    main, worker = SimpleNamespace(docname="a"), SimpleNamespace(docname="b")
    record.figure(main, "k1")
    record.figure(worker, "k2")
    record.problem(worker, "b: FAIL")
    record.merge(None, main, ["b"], worker)
    assert record.all_of(main, "scanlab_figures") == {"a": {"k1"}, "b": {"k2"}}
    assert record.all_of(main, "scanlab_problems") == {"b": ["b: FAIL"]}
    record.purge(None, main, "b")
    assert record.all_of(main, "scanlab_figures") == {"a": {"k1"}} and record.all_of(main, "scanlab_problems") == {}
