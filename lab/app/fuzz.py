"""Fuzzing the scene loader: seeded random mutations of the preset scene files.

The rule under test: :func:`lab.loading.parse_scene` either returns a
:class:`lab.scene.Scene` or raises :class:`lab.loading.SceneError` with a one-line
message. Any other exception (or a multi-line message) is a failure: a bad input that
would end in a traceback instead of one clear line.

Each case takes one preset (``lab/scenes/*.toml``), chosen by the case's own random
generator, and applies one to three mutations (:data:`MUTATIONS`): delete, duplicate or
swap lines, flip a byte, replace a number by NaN, infinity, a huge, negative or zero
value or a string, replace any value by one of another type, rename a key, change a table
header, insert a line from another preset, or truncate the file. Case ``i`` of seed ``s``
uses ``random.Random(f"{s}:{i}")``, so a case is reproduced from its two numbers alone.

Only the scene *text* is mutated; the mesh and texture files it names are not. So the
readers of those files are memoised (:func:`fast_readers`), and CSG trees are meshed
with 16 segments instead of 128; the validation under test is the same.

Run it with ``scanlab fuzz --cases N --seed S`` (or ``make fuzz``); failing inputs are
saved to ``--save DIR``.
"""
from __future__ import annotations

import contextlib
import functools
import random
import re
import time
import traceback
import warnings
from dataclasses import dataclass, field
from pathlib import Path

from lab.loading import SceneError, parse_scene
from lab.presets import SCENES_DIR

NUMBER = re.compile(rb"(?<![\w.])[-+]?\d+(?:\.\d*)?(?:[eE][-+]?\d+)?(?![\w.])")
KEY = re.compile(rb"^(\s*)([A-Za-z_][A-Za-z0-9_]*)(\s*=)", re.M)
HEADER = re.compile(rb"^\s*\[\[?[^\]]*\]\]?\s*$", re.M)

NUMBER_SWAPS = [b"nan", b"inf", b"-inf", b"+inf", b"-nan", b"1e308", b"-1e308", b"1e-320", b"0", b"-0.0", b"-1",
                b"-2.5", b"9223372036854775807", b"1" + b"0" * 400, b"1" * 5000, b"0x" + b"f" * 5000, b"0.5", b"3",
                b'"1.0"', b"true", b"[]"]
VALUE_SWAPS = [b"nan", b"1e308", b"-1", b"0", b'""', b'"x"', b'"cube"', b'"flat"', b'"/"', b'"."', b"true",
               b"[]", b"[1, 2]", b"[1, 2, 3, 4]", b"[nan, 0, 0]", b"[0, 0, 0]", b"[[1, 2, 3]]", b'["a", "b", "c"]',
               b"{}", b"{ level = 3 }", b"{ a = 1 }", b"1979-05-27", b"1979-05-27T07:32:00Z", b"07:32:00",
               b'{ op = "union", children = [] }', b'{ primitive = "sphere" }', b"[1e999, 0, 0]",
               b"[" * 3000 + b"]" * 3000, b'"' + b"x" * 10000 + b'"', b'"models"', b'"models/torus.ply"',
               b'"pyvista-examples:"', b'"pyvista-examples:../.."', b'"/dev/null"', b'"torus-mesh.toml"']
KEY_SWAPS = [b"position", b"focal_point", b"view_up", b"size", b"color", b"kind", b"shape", b"mesh", b"csg",
             b"params", b"texture", b"normals", b"shading", b"model", b"scale", b"clipping_range", b"op",
             b"children", b"primitive", b"radius", b"level", b"name", b"opacity", b"crease_angle", b"image",
             b"object", b"light", b"camera", b"render"]
HEADER_SWAPS = [b"[image]", b"[camera]", b"[render]", b"[[light]]", b"[[object]]", b"[light]", b"[object]",
                b"[[image]]", b"[[camera]]", b"[object.csg]", b"[object.params]", b"[[object.csg]]", b"[camera.x]"]


# --------------------------------------------------------------------------- mutations
def _lines(data: bytes) -> list[bytes]:
    return data.split(b"\n")


def delete_line(data, rng, corpus):
    """Remove one line."""
    lines = _lines(data)
    del lines[rng.randrange(len(lines))]
    return b"\n".join(lines)


def duplicate_line(data, rng, corpus):
    """Repeat one line right after itself."""
    lines = _lines(data)
    i = rng.randrange(len(lines))
    lines.insert(i, lines[i])
    return b"\n".join(lines)


def swap_lines(data, rng, corpus):
    """Exchange two lines."""
    lines = _lines(data)
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    lines[i], lines[j] = lines[j], lines[i]
    return b"\n".join(lines)


def flip_byte(data, rng, corpus):
    """Replace one byte by a random byte (which may break UTF-8)."""
    if not data:
        return data
    i = rng.randrange(len(data))
    new = rng.choice([rng.randrange(256), rng.choice(b'[]{}="#,.\n 0-')])
    return data[:i] + bytes([new]) + data[i + 1:]


def _replace_match(data, rng, pattern, replacements):
    matches = list(pattern.finditer(data))
    if not matches:
        return data
    m = rng.choice(matches)
    return data[:m.start()] + rng.choice(replacements) + data[m.end():]


def change_number(data, rng, corpus):
    """Replace one number by NaN, infinity, a huge, tiny, negative or zero value, or a string."""
    return _replace_match(data, rng, NUMBER, NUMBER_SWAPS)


def negate_number(data, rng, corpus):
    """Put a minus sign before one number."""
    matches = list(NUMBER.finditer(data))
    if not matches:
        return data
    m = rng.choice(matches)
    return data[:m.start()] + b"-" + m.group().lstrip(b"+-") + data[m.end():]


def change_value(data, rng, corpus):
    """Replace the value after one ``key =`` by a value of some other type or shape."""
    lines = _lines(data)
    candidates = [i for i, line in enumerate(lines) if KEY.match(line)]
    if not candidates:
        return data
    i = rng.choice(candidates)
    key = KEY.match(lines[i])
    lines[i] = key.group(0) + b" " + rng.choice(VALUE_SWAPS)
    return b"\n".join(lines)


def rename_key(data, rng, corpus):
    """Rename one key: a typo, or another key that is valid somewhere else."""
    matches = list(KEY.finditer(data))
    if not matches:
        return data
    m = rng.choice(matches)
    name = m.group(2)
    if rng.random() < 0.5 and len(name) > 1:
        j = rng.randrange(len(name))
        name = name[:j] + name[j + 1:]  # a typo: one letter dropped
    else:
        name = rng.choice(KEY_SWAPS)
    return data[:m.start(2)] + name + data[m.end(2):]


def change_header(data, rng, corpus):
    """Replace one table header (``[camera]``, ``[[object]]`` ...) by another."""
    return _replace_match(data, rng, HEADER, HEADER_SWAPS)


def insert_foreign_line(data, rng, corpus):
    """Insert a line taken from another preset."""
    lines = _lines(data)
    donor = _lines(rng.choice(corpus))
    lines.insert(rng.randrange(len(lines) + 1), rng.choice(donor))
    return b"\n".join(lines)


def truncate(data, rng, corpus):
    """Cut the file at a random byte."""
    return data[:rng.randrange(len(data) + 1)]


MUTATIONS = (delete_line, duplicate_line, swap_lines, flip_byte, change_number, negate_number, change_value,
             rename_key, change_header, insert_foreign_line, truncate)


def mutate(data: bytes, rng: random.Random, corpus: list[bytes]) -> tuple[bytes, list[str]]:
    """Apply one to three random mutations; return the result and their names."""
    names = []
    for _ in range(rng.choice((1, 1, 2, 3))):
        m = rng.choice(MUTATIONS)
        data = m(data, rng, corpus)
        names.append(m.__name__)
    return data, names


# --------------------------------------------------------------------------- running
@contextlib.contextmanager
def fast_readers():
    """Memoise the mesh and texture readers and mesh CSG with 16 segments, for this block.

    The fuzzer mutates the scene text only, so the files it names always read the same.
    """
    import lab.loading as loading
    import lab.meshfiles as meshfiles
    import lab.texture as texture

    saved = meshfiles.read_mesh, texture.load_texture, loading.CSG_SEGMENTS
    meshfiles.read_mesh = functools.lru_cache(maxsize=64)(saved[0])
    texture.load_texture = functools.lru_cache(maxsize=64)(saved[1])
    loading.CSG_SEGMENTS = 16
    try:
        yield
    finally:
        meshfiles.read_mesh, texture.load_texture, loading.CSG_SEGMENTS = saved


@dataclass
class Failure:
    """One input that broke the rule: the case, what was done, and what came out."""

    seed: int
    case: int
    preset: str
    mutations: list[str]
    data: bytes
    error: str


@dataclass
class Summary:
    """What a fuzz run did: counts of loaded scenes and rejections, failures, timing."""

    cases: int = 0
    loaded: int = 0
    rejected: int = 0
    failures: list[Failure] = field(default_factory=list)
    seconds: float = 0.0
    slowest: tuple[float, str] = (0.0, "")

    def line(self) -> str:
        return (f"{self.cases} cases in {self.seconds:.1f} s: {self.loaded} loaded, {self.rejected} rejected with "
                f"SceneError, {len(self.failures)} failures; slowest case {self.slowest[0] * 1e3:.0f} ms "
                f"({self.slowest[1]})")


def check_case(data: bytes, source: str) -> tuple[str, str]:
    """Load ``data`` as a scene file named ``source``: ("loaded" | "rejected" | "failure", detail).

    The rule: a Scene, or a SceneError whose message is one line starting with ``source``;
    anything else is a "failure", with the exception (and its traceback) as the detail. A
    numpy RuntimeWarning (overflow, invalid value) while loading is a failure too: a value
    that should have been refused at the edge got through to arithmetic.
    """
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error", RuntimeWarning)
            parse_scene(data, source=source, base=SCENES_DIR)
    except SceneError as exc:
        message = str(exc)
        if "\n" in message or not message.startswith(f"{source}: "):
            return "failure", f"SceneError message is not one line starting with the file name: {message!r}"
        return "rejected", message
    except Exception as exc:  # noqa: BLE001 -- any other exception is what we are looking for
        return "failure", f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}"
    return "loaded", ""


def run_fuzz(cases: int, seed: int, save: Path | None = None, presets: list[Path] | None = None,
             progress=None) -> Summary:
    """Run ``cases`` mutated preset files through the loader; save failing inputs to ``save``.

    ``progress(i, summary)`` is called after every tenth of the cases (at least 1000) if given.
    """
    presets = sorted(presets or SCENES_DIR.glob("*.toml"))
    corpus = [p.read_bytes() for p in presets]
    summary, started = Summary(), time.perf_counter()
    with fast_readers():
        for i in range(cases):
            rng = random.Random(f"{seed}:{i}")
            k = rng.randrange(len(presets))
            data, names = mutate(corpus[k], rng, corpus)
            source = f"fuzz-{seed}-{i}-{presets[k].stem}.toml"
            t0 = time.perf_counter()
            outcome, detail = check_case(data, source)
            took = time.perf_counter() - t0
            if took > summary.slowest[0]:
                summary.slowest = (took, source)
            summary.cases += 1
            if outcome == "loaded":
                summary.loaded += 1
            elif outcome == "rejected":
                summary.rejected += 1
            else:
                failure = Failure(seed, i, presets[k].stem, names, data, detail)
                summary.failures.append(failure)
                if save is not None:
                    save_failure(save, source, failure)
            if progress and (i + 1) % max(1000, cases // 10) == 0:
                progress(i + 1, summary)
    summary.seconds = time.perf_counter() - started
    return summary


def save_failure(folder: Path, source: str, failure: Failure) -> Path:
    """Write the failing input as ``folder/source`` and what happened beside it (``.txt``)."""
    from lab.atomic import atomic_file

    folder.mkdir(parents=True, exist_ok=True)
    path = folder / source
    with atomic_file(path) as f:
        f.write(failure.data)
    with atomic_file(path.with_suffix(".txt")) as f:
        f.write(f"preset {failure.preset}, case {failure.case} of seed {failure.seed}, mutations "
                f"{', '.join(failure.mutations)}\n{failure.error}\n".encode("utf-8", "replace"))
    return path
