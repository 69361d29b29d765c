"""lab/app/live/wording.py: every label, choice, verdict and problem exists in English and in
Japanese, and every value a select can hold has words."""
from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

from lab.app.live import wording
from lab.app.live.controls import Problem, SIZES
from lab.app.live.wording import CHOICES, PROBLEMS, TEXT, problem_text, strings
from lab.scene import HIDDEN_SURFACES, INTERPOLATIONS, LIGHT_KINDS, MODELS, SHADINGS, TRANSPARENCIES
from renderer.breakages import BREAKAGES
from compare.verdict import FAILS_AS_MEANT, FAIL, PASS, PASSES_UNEXPECTEDLY

LIVE = Path(wording.__file__).parent
JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")
SAME_IN_BOTH = {"shininess"}  # OpenGL's own word, kept as the course keeps it


def test_every_text_has_both_languages_and_the_japanese_is_japanese():
    for key, (en, ja) in TEXT.items():
        assert en and ja, key
        assert JAPANESE.search(ja) or key in SAME_IN_BOTH, f"{key}: {ja!r} is not Japanese"


@pytest.mark.parametrize("select,values", [("shading", ("scene", *SHADINGS)), ("model", ("scene", *MODELS)),
                                           ("interpolation", INTERPOLATIONS), ("hidden_surface", HIDDEN_SURFACES),
                                           ("transparency", TRANSPARENCIES), ("kind", LIGHT_KINDS), ("size", SIZES)])
def test_every_value_of_a_select_has_words(select, values):
    assert set(CHOICES[select]) == set(values)
    for lang in ("en", "ja"):
        titles = [item["title"] for item in strings(lang)["choices"][select]]
        assert all(titles) and len(set(titles)) == len(titles)


def test_every_verdict_and_breakage_has_words():
    for lang in ("en", "ja"):
        s = strings(lang)
        assert set(s["status"]) == {PASS, FAIL, FAILS_AS_MEANT, PASSES_UNEXPECTEDLY}
        assert [b["value"] for b in s["breakages"]] == ["none", *BREAKAGES]
        assert all(b["rule"] for b in s["breakages"][1:])


def _problem_codes() -> set[str]:
    """Every code the live lab's modules make a Problem with."""
    codes = set()
    for path in LIVE.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Problem" and node.args:
                codes.add(node.args[0].value)
    return codes


def test_every_problem_the_lab_makes_can_be_worded():
    assert {"number", "range", "name", "exists"} <= _problem_codes() <= set(PROBLEMS)
    assert problem_text(Problem("range", ("0", "1", "[", "]")), "en") == "must be in [0, 1]"
    assert problem_text(Problem("range", ("0", "180", "(", "]")), "ja") == "(0, 180] の範囲で入れてください"
