"""``scanlab bench-revisions``: another revision exported once, each child process timing one
tree, the two trees taking turns, and the rounds' ratios paired."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from lab.app import bench_revisions as br


def scanlab(*args):
    return subprocess.run([sys.executable, "-m", "lab", *args], capture_output=True, text=True, timeout=600)


def git(repo: Path, *args) -> str:
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@t", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@t"}
    return subprocess.run(["git", "-C", str(repo), *args], check=True, capture_output=True, text=True,
                          env=env).stdout.strip()


@pytest.fixture
def repo(tmp_path):
    """A repository of two commits: renderer/kernel.py says 'old', then 'new'."""
    root = tmp_path / "repo"
    (root / "renderer").mkdir(parents=True)
    git(root, "init", "-q")
    for text in ("old", "new"):
        (root / "renderer" / "kernel.py").write_text(f"VERSION = {text!r}\n")
        git(root, "add", "-A")
        git(root, "commit", "-q", "-m", text)
    return root


def test_a_revision_is_exported_once_with_its_own_sources(repo, tmp_path):
    old = br.commit_of("HEAD~1", repo)
    assert len(old) == 40 and old != br.commit_of("HEAD", repo)
    tree = br.export_revision(old, repo, tmp_path / "cache")
    assert tree == tmp_path / "cache" / old / "tree"
    assert (tree / "renderer" / "kernel.py").read_text() == "VERSION = 'old'\n"
    (tree / "renderer" / "__pycache__").mkdir()  # what a first run leaves beside the sources: kept
    assert br.export_revision(old, repo, tmp_path / "cache") == tree
    assert (tree / "renderer" / "__pycache__").is_dir()


def test_a_name_that_is_no_commit_is_said_in_one_line(repo):
    with pytest.raises(br.RevisionError, match="'nosuch' names no commit"):
        br.commit_of("nosuch", repo)
    done = scanlab("bench-revisions", "no-such-revision-here", "ico5-phong")
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [
        f"scanlab bench-revisions: 'no-such-revision-here' names no commit of the git repository at {br.TREE}"]


def test_a_misspelt_scene_fails_before_anything_is_exported():
    done = scanlab("bench-revisions", "HEAD", "icosfere")
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1 and "icosfere" in done.stderr
    assert "exported" not in done.stdout


def test_a_child_runs_its_own_tree_with_its_own_kernel_cache(monkeypatch, tmp_path):
    monkeypatch.setenv("SCANLAB_KERNEL_CACHE", str(tmp_path / "shared"))
    monkeypatch.setenv("PYTHONPATH", "/elsewhere")
    env = br.child_environment(tmp_path / "tree")
    assert env["PYTHONPATH"].split(os.pathsep) == [str(tmp_path / "tree"), "/elsewhere"]
    assert "SCANLAB_KERNEL_CACHE" not in env


def test_rounds_are_paired_before_the_median_is_taken():
    summary = br.paired_summary([1.0, 4.0, 3.0], [2.0, 2.0, 6.0])  # ratios 0.5, 2.0, 0.5
    assert summary["ratio"] == 0.5 and summary["ratio_min"] == 0.5 and summary["ratio_max"] == 2.0
    assert summary["ours_ms"] == 3000.0 and summary["theirs_ms"] == 2000.0
    with pytest.raises(ValueError):
        br.paired_summary([1.0], [1.0, 2.0])


def test_the_trees_take_turns_and_differing_images_are_said(monkeypatch):
    calls = []

    def fake_child(tree, scene, size, frames, threads):
        calls.append(tree)
        return {"median_s": 0.01 if tree == "ours-tree" else 0.02, "image": "a" if tree == "ours-tree" else "b"}

    monkeypatch.setattr(br, "time_in_child", fake_child)
    row = br.compare_scene({"ours": "ours-tree", "theirs": "theirs-tree"}, "ico5-phong", (64, 64), rounds=3,
                           frames=2, threads="default", say=lambda text: None)
    assert calls == ["ours-tree", "theirs-tree", "theirs-tree", "ours-tree", "ours-tree", "theirs-tree"]
    assert row["ratio"] == 0.5 and row["size"] == "64x64" and row["same_image"] is False
    assert "images differ" in br.report_line(row)


def test_revisions_live_beside_the_kernels_in_the_users_cache(monkeypatch, tmp_path):
    from renderer.jit import user_cache_root

    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert br.cache_folder() == tmp_path / "scanlab" / "revisions"
    assert br.cache_folder().parent == user_cache_root().parent
