"""The grading worker: JSON jobs in, JSON answers out on its own channel, whatever libraries print."""
import json
import subprocess
import sys

from .checked_fixtures import FIXTURES


def test_a_job_gets_one_answer_line_and_noise_goes_to_stderr(tmp_path):
    jobs = [{"exercise": "perspective", "file": str(FIXTURES / "perspective" / "degrees.py"), "out": str(tmp_path),
             "stem": "degrees", "limits": {"cpu_seconds": 5}},
            {"exercise": "nope", "file": "x.py", "out": str(tmp_path), "stem": "x"}]
    code = ("import runpy, builtins; print('noise on stdout'); "
            "runpy.run_module('lab.app.exercises.worker', run_name='__main__')")
    done = subprocess.run([sys.executable, "-c", code], input="".join(json.dumps(j) + "\n" for j in jobs),
                          capture_output=True, text=True, timeout=300)
    lines = done.stdout.splitlines()
    assert lines[0] == "noise on stdout"          # before the worker took over its channel
    first, second = map(json.loads, lines[1:])
    assert (first["verdict"], first["codes"], first["file"]) == ("wrong", ["fov-in-degrees"], "degrees.py")
    assert set(first["messages"]) == {"en", "ja"}
    assert second == {"error": "KeyError: 'nope'"}
