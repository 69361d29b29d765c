"""The grades page: one row per submission, both languages, everything a submission made escaped."""
from lab.app.exercises.page import grades_page
from lab.app.exercises.exercise_registry import get
from lab.app.exercises.sandbox import Limits

ROW = {"file": "<img src=x onerror=alert(1)>.py", "verdict": "cannot-judge", "status": 2, "codes": ["exception"],
       "seconds": 0.5, "messages": {"en": ["[exception] <b>boom</b>"], "ja": ["[exception] 例外 <b>"]},
       "checked": {"en": [], "ja": []}, "panels": [], "output": ["<script>alert(2)</script>"]}
RIGHT = {**ROW, "file": "ok.py", "verdict": "right", "status": 0, "codes": [], "messages": {"en": [], "ja": []},
         "panels": ["panels/ok-panel.png", "panels/ok-vtk.png"], "output": []}


def page(lang):
    return grades_page(get("menger"), [ROW, RIGHT], lang, 3.0, 2, Limits())


def test_a_submission_cannot_put_markup_on_the_page():
    html = page("en")
    assert "<img src=x" not in html and "<script>" not in html and "<b>boom" not in html
    assert "&lt;img src=x onerror=alert(1)&gt;.py" in html


def test_rows_panels_and_summary():
    html = page("en")
    assert html.count("<tr id=") == 2
    assert "src='panels/ok-panel.png'" in html and "src='panels/ok-vtk.png'" in html
    assert "2 submissions: 1 right, 0 wrong, 1 cannot be judged" in html


def test_the_japanese_page_is_in_japanese():
    html = page("ja")
    assert "<html lang='ja'>" in html and "採点結果" in html and "正解" in html and "メンガーのスポンジ" in html
