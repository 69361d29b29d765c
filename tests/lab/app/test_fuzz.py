"""Fuzzing the scene loader: mutated preset files load or raise SceneError, nothing else."""
from __future__ import annotations

import random

from lab.app.fuzz import MUTATIONS, check_case, mutate, run_fuzz
from lab.presets import SCENES_DIR

CASES = 4000
SEED = 20240611


def test_mutated_presets_load_or_raise_scene_error(tmp_path):
    """4000 seeded mutations of the presets: each gives a Scene or a one-line SceneError naming the
    file; any other exception fails, and its input is saved for `scanlab fuzz`-style replay."""
    summary = run_fuzz(CASES, SEED, save=tmp_path)
    report = "\n\n".join(f"{f.preset} case {f.case} ({', '.join(f.mutations)}):\n{f.error}"
                         for f in summary.failures[:5])
    assert not summary.failures, f"{summary.line()}\n{report}"
    assert summary.cases == CASES
    # the mutations reach both outcomes: many files still load, many are rejected
    assert summary.loaded > CASES // 20 and summary.rejected > CASES // 2, summary.line()


def test_every_mutation_changes_some_preset():
    """Each mutation, applied to the presets, changes at least one of them (none is a no-op)."""
    corpus = [p.read_bytes() for p in sorted(SCENES_DIR.glob("*.toml"))]
    for m in MUTATIONS:
        rng = random.Random(m.__name__)
        assert any(m(data, rng, corpus) != data for data in corpus), m.__name__


def test_a_case_is_reproduced_by_seed_and_index():
    """Case i of seed s is the same input whenever it is made."""
    corpus = [p.read_bytes() for p in sorted(SCENES_DIR.glob("*.toml"))]
    one = mutate(corpus[0], random.Random("7:3"), corpus)
    two = mutate(corpus[0], random.Random("7:3"), corpus)
    assert one == two


def test_check_case_flags_other_exceptions(monkeypatch):
    """The rule catches a loader that raises anything but SceneError."""
    import lab.app.fuzz

    def broken(*args, **kwargs):
        raise KeyError("boom")

    monkeypatch.setattr(lab.app.fuzz, "parse_scene", broken)
    outcome, detail = check_case(b"", "x.toml")
    assert outcome == "failure" and "KeyError" in detail


def test_the_fuzz_command_prints_a_summary(tmp_path, capsys):
    """`scanlab fuzz --cases N --seed S` prints one summary line and exits 0 when nothing fails."""
    from lab.app.cli import main

    assert main(["fuzz", "--cases", "60", "--seed", "3", "--save", str(tmp_path / "f")]) == 0
    out = capsys.readouterr().out
    assert "60 cases in" in out and "0 failures" in out
    assert not (tmp_path / "f").exists()  # nothing to save
