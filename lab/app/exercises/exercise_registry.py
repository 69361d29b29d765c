"""The exercise registry: every exercise by name, each defined in one module of
:mod:`lab.app.exercises.catalogue` that calls :func:`register` when imported.

An :class:`Exercise` carries what the command line, the checker and the lesson site need:
its name and lesson, title and statement in English and Japanese, the starter file, the
function's signature and outputs, the cases it is called on, and the judge that turns
the returned arrays into findings. Nothing outside the catalogue branches on a name.

>>> sorted(exercises())[:3]
['cone', 'covered_pixels', 'cylinder']
"""
from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding

LESSONS = {
    "01-polygon-model": {"en": "The polygon model", "ja": "ポリゴンモデル"},
    "02-homogeneous": {"en": "Homogeneous coordinates and transforms", "ja": "同次座標と座標変換"},
    "03-camera": {"en": "The camera", "ja": "カメラ"},
    "04-clipping": {"en": "Clipping and the window", "ja": "クリッピングとウィンドウ変換"},
    "05-scanline": {"en": "Drawing a triangle: the scanline fill", "ja": "三角形の描画: スキャンライン"},
    "06-hidden-surfaces": {"en": "Hidden surfaces", "ja": "隠面消去"},
    "07-reflection": {"en": "The reflection model", "ja": "反射モデル"},
    "08-lights": {"en": "Lights", "ja": "光源"},
    "09-shading": {"en": "Flat, Gouraud and Phong shading", "ja": "フラット・グーロー・フォンシェーディング"},
    "10-interpolation": {"en": "Perspective-correct interpolation", "ja": "透視補正補間"},
    "11-textures": {"en": "Textures", "ja": "テクスチャ"},
    "12-transparency": {"en": "Transparency", "ja": "透明"},
    "13-csg": {"en": "CSG", "ja": "CSG"},
}
"""The lessons of the course (issue 13), by slug: an exercise belongs to one of them."""


@dataclass(frozen=True)
class Output:
    """One returned array: its name, shape (ints; None = any length; a str = the value of
    that argument) and the dtype kinds accepted ("f" float, "iu" integers, "b" bool)."""

    name: str
    shape: tuple
    kinds: str


@dataclass(frozen=True)
class Case:
    """One call of the student's function: its arguments (lists become float64 arrays in
    the child) and how it is written in messages, e.g. ``menger(2)``."""

    args: tuple
    call: str


@dataclass
class Judgement:
    """What a judge found: findings (none = right), lines saying what was checked
    (``{"en": [...], "ja": [...]}``) and panels to draw (objects with ``write(folder, stem)``)."""

    findings: list[Finding] = field(default_factory=list)
    checked: dict = field(default_factory=lambda: {"en": [], "ja": []})
    panels: list = field(default_factory=list)


@dataclass(frozen=True)
class Exercise:
    """One exercise. ``judge(cases, results)`` gets the cases and, per case, the returned
    arrays (already checked against ``outputs``) and returns a :class:`Judgement`."""

    name: str
    lesson: str
    title: dict
    statement: dict
    parameters: tuple[str, ...]
    outputs: tuple[Output, ...]
    starter: str
    cases: Callable[[], list[Case]]
    judge: Callable[[list[Case], list[list[np.ndarray]]], Judgement]

    @property
    def function(self) -> str:
        """The function the student writes: the exercise's name."""
        return self.name

    @property
    def signature(self) -> str:
        outs = ", ".join(o.name for o in self.outputs)
        return f"{self.name}({', '.join(self.parameters)}) -> {outs if len(self.outputs) == 1 else '(' + outs + ')'}"

    @property
    def starter_file(self) -> str:
        return f"{self.name}.py"

    @property
    def check_command(self) -> str:
        return f"scanlab exercise check {self.name} {self.starter_file}"

    def page(self, lang: str) -> dict:
        """What the lesson site shows for this exercise in ``lang``: title, lesson, statement,
        starter file, command."""
        return {"name": self.name, "lesson": self.lesson, "lesson_title": LESSONS[self.lesson][lang],
                "title": self.title[lang], "statement": self.statement[lang], "signature": self.signature,
                "starter": self.starter, "command": self.check_command}


EXERCISES: dict[str, Exercise] = {}


def register(exercise: Exercise) -> Exercise:
    """Add an exercise (called by its catalogue module); names are unique, lessons known."""
    if exercise.name in EXERCISES:
        raise ValueError(f"exercise {exercise.name!r} is registered twice")
    if exercise.lesson not in LESSONS:
        raise ValueError(f"exercise {exercise.name!r}: unknown lesson {exercise.lesson!r}")
    EXERCISES[exercise.name] = exercise
    return exercise


def exercises() -> dict[str, Exercise]:
    """Every exercise, by name: imports each module of the catalogue (each registers itself)."""
    import lab.app.exercises.catalogue as catalogue

    for info in pkgutil.iter_modules(catalogue.__path__):
        importlib.import_module(f"{catalogue.__name__}.{info.name}")
    return dict(sorted(EXERCISES.items()))


def get(name: str) -> Exercise:
    """The exercise called ``name``; KeyError with the valid names otherwise."""
    found = exercises()
    if name not in found:
        raise KeyError(name)
    return found[name]
