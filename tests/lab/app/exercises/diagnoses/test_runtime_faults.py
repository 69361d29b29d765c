"""Runtime family: what failed, where, while running which call."""
from lab.app.exercises.diagnoses.codes import Finding, text


def test_runtime_messages_say_where_and_what():
    f = Finding("exception", {"type": "ZeroDivisionError", "message": "division by zero", "line": 7,
                              "call": "menger(2)"})
    assert text(f, "en") == "the code raised ZeroDivisionError: division by zero (line 7, while running menger(2))"
    assert "7 行目" in text(f, "ja") and "menger(2) の実行中" in text(f, "ja")
