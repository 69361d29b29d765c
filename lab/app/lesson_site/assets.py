"""Files the site serves itself, so that no page loads anything from outside.

- MathJax 3, from the npm package pinned in ``lessons/package.json`` and its lockfile,
  installed with ``npm ci`` into ``lessons/node_modules/`` (not in git): only
  ``es5/tex-chtml.js`` and its CHTML fonts are published, as ``_static/mathjax/``
  (``mathjax_path`` in ``conf.py`` names it).
- The IPAex Gothic font that the PyPI package ``matplotlib-fontja``
  ships (IPA Font License): the plots' Japanese labels are drawn with it, and the pages
  offer it for Japanese text as a web font after the reader's own Japanese fonts, so a machine without any
  still shows Japanese rather than empty boxes.
"""
from __future__ import annotations

import importlib.util
import json
import shutil
import subprocess
from pathlib import Path

from lab.app.lesson_site.places import LESSONS
NODE_MODULES = LESSONS / "node_modules"
MATHJAX = NODE_MODULES / "mathjax"
MATHJAX_FILES = ("es5/tex-chtml.js", "es5/output/chtml/fonts")


class AssetError(RuntimeError):
    """A file the site needs cannot be had; the message says what to install."""


def locked_mathjax_version() -> str:
    """The MathJax version ``lessons/package-lock.json`` pins."""
    lock = json.loads((LESSONS / "package-lock.json").read_text())
    return lock["packages"]["node_modules/mathjax"]["version"]


def ensure_mathjax() -> Path:
    """``lessons/node_modules/mathjax`` at the locked version, installed by ``npm ci`` if missing."""
    want = locked_mathjax_version()
    installed = MATHJAX / "package.json"
    if installed.is_file() and json.loads(installed.read_text()).get("version") == want:
        return MATHJAX
    npm = shutil.which("npm")
    if npm is None:
        raise AssetError("npm is needed to install MathJax for the lesson site (Debian: apt-get install npm)")
    done = subprocess.run([npm, "ci", "--no-audit", "--no-fund", "--loglevel=error"], cwd=LESSONS,
                          capture_output=True, text=True)
    if done.returncode != 0 or not installed.is_file():
        raise AssetError(f"npm ci in {LESSONS} failed: {(done.stderr or done.stdout).strip().splitlines()[-1:]}")
    return MATHJAX


def japanese_font() -> Path:
    """IPAex Gothic (``ipaexg.ttf``) from the installed ``matplotlib-fontja`` package.

    Found without importing the package (its import changes matplotlib's global font).
    """
    spec = importlib.util.find_spec("matplotlib_fontja")
    if spec is None or not spec.submodule_search_locations:
        raise AssetError("the Python package matplotlib-fontja is missing (pip install -e '.[lessons]')")
    font = Path(list(spec.submodule_search_locations)[0]) / "fonts" / "ipaexg.ttf"
    if not font.is_file():
        raise AssetError(f"{font}: the Japanese font is missing from matplotlib-fontja")
    return font


def static_folder(dest: Path) -> Path:
    """Fill ``dest`` with ``mathjax/`` and ``fonts/ipaexg.ttf`` for ``html_static_path``;
    files already there and the same size are kept."""
    mathjax = ensure_mathjax()
    pairs = []
    for rel in MATHJAX_FILES:
        src = mathjax / rel
        target = dest / "mathjax" / Path(rel).relative_to("es5")
        pairs += [(f, target / f.relative_to(src)) for f in src.rglob("*") if f.is_file()] if src.is_dir() \
            else [(src, target)]
    pairs.append((japanese_font(), dest / "fonts" / "ipaexg.ttf"))
    for src, target in pairs:
        copy_file(src, target)
    return dest


def copy_file(src: Path, target: Path) -> None:
    """Copy ``src`` to ``target`` (folders made), atomically (:func:`lab.atomic.atomic_file`);
    a target of the same size is taken to be the same file and kept."""
    from lab.atomic import atomic_file

    if target.is_file() and target.stat().st_size == src.stat().st_size:
        return
    target.parent.mkdir(parents=True, exist_ok=True)
    with atomic_file(target) as f:
        f.write(src.read_bytes())
