"""Shared by the exercise tests: the fixtures folder, a cached check of a fixture file, and
the check that every diagnosis of a report reads in English and in Japanese."""
from __future__ import annotations

import functools
import re
import string
from pathlib import Path

from lab.app.exercises.checker import check_file
from lab.app.exercises.diagnoses.codes import diagnosis, text
from lab.app.exercises.exercise_registry import get
from lab.app.exercises.sandbox import Limits

FIXTURES = Path(__file__).parent / "fixtures"
LIMITS = Limits(cpu_seconds=3)
"""Short limits for the tests: every fixture that returns does so in well under a second."""

JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")


@functools.lru_cache(maxsize=None)
def judged(exercise: str, fixture: str):
    """The checker's report on ``fixtures/<exercise>/<fixture>.py`` (judged once per session)."""
    return check_file(get(exercise), FIXTURES / exercise / f"{fixture}.py", LIMITS)


def speaks_both_languages(report) -> None:
    """Every finding's message is complete (no missing figure) in English and in Japanese."""
    for finding in report.findings:
        d = diagnosis(finding.code)
        for lang in ("en", "ja"):
            template = getattr(d, lang)
            if isinstance(template, str):
                string.Formatter().vformat(template, (), finding.details)  # KeyError if a figure is missing
            message = text(finding, lang)
            assert message.strip(), (finding.code, lang)
            assert bool(JAPANESE.search(message)) == (lang == "ja"), (finding.code, lang, message)
    for lang in ("en", "ja"):
        assert report.lines(lang)[0].startswith(f"{report.exercise}: ")


def expect(exercise: str, fixture: str, verdict: str, code: str | None) -> None:
    """The fixture's verdict, its first diagnosis code, and messages in both languages."""
    report = judged(exercise, fixture)
    assert report.verdict == verdict, report.lines("en")
    if code is None:
        assert report.findings == []
    else:
        assert report.codes[0] == code, report.lines("en")
    speaks_both_languages(report)
