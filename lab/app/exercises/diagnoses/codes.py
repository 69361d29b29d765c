"""The diagnosis registry: stable codes → what they mean, in English and Japanese.

A :class:`Diagnosis` is registered once, in the module of its family, with a message
template per language (``str.format`` fields filled from a :class:`Finding`'s details, or
a function of the details when the sentence needs a choice). The codes are stable: they
go into ``grades.csv`` and scripts read them. Exit status: 1 for a wrong solution, 2 for a
file that cannot be judged (the runtime family).

>>> text(Finding("faces-inward", {"count": 3, "total": 20, "case": "level 0"}), "en")[:25]
'3 of 20 triangles (level '
"""
from __future__ import annotations

import importlib
import pkgutil
import string
from dataclasses import dataclass, field
from typing import Callable

LANGUAGES = ("en", "ja")

Template = str | Callable[[dict], str]


@dataclass(frozen=True)
class Diagnosis:
    """One failure signature. ``status`` is the exit status it leads to (1 wrong, 2 cannot be judged)."""

    code: str
    family: str
    en: Template
    ja: Template
    status: int = 1


@dataclass(frozen=True)
class Finding:
    """A diagnosis found in one submission, with the figures its message names."""

    code: str
    details: dict = field(default_factory=dict)


DIAGNOSES: dict[str, Diagnosis] = {}
FAMILIES = ("runtime", "mesh", "normals", "matrices", "raster")


def register(code: str, family: str, en: Template, ja: Template, status: int = 1) -> Diagnosis:
    """Add a diagnosis; a code can be registered once only."""
    if code in DIAGNOSES:
        raise ValueError(f"diagnosis code {code!r} is registered twice")
    DIAGNOSES[code] = Diagnosis(code, family, en, ja, status)
    return DIAGNOSES[code]


def load_families() -> dict[str, Diagnosis]:
    """Import every family module of this package (each registers its codes); the registry."""
    import lab.app.exercises.diagnoses as package

    for info in pkgutil.iter_modules(package.__path__):
        if info.name != "codes":
            importlib.import_module(f"{package.__name__}.{info.name}")
    return DIAGNOSES


def diagnosis(code: str) -> Diagnosis:
    load_families()
    return DIAGNOSES[code]


class _Details(dict):
    def __missing__(self, key):
        return "?"


def text(finding: Finding, lang: str = "en") -> str:
    """The finding's message in ``lang`` ("en" or "ja")."""
    template = getattr(diagnosis(finding.code), lang if lang in LANGUAGES else "en")
    if callable(template):
        return template(dict(finding.details))
    return string.Formatter().vformat(template, (), _Details(finding.details))


def status(findings: list[Finding]) -> int:
    """0 when there is nothing to say, else the highest exit status among the findings."""
    return max((diagnosis(f.code).status for f in findings), default=0)
