"""The child side, run as the sandbox runs it: limits first, then the file, one status file, no pickle."""
import json
import subprocess
import sys

import numpy as np

from lab.app.exercises.runner import as_outputs
from lab.app.exercises.sandbox import RUNNER


def run_job(tmp_path, source, cases, n_outputs=1, limits=None):
    (tmp_path / "s.py").write_text(source)
    job = {"file": str(tmp_path / "s.py"), "function": "f", "cases": cases, "n_outputs": n_outputs,
           "limits": limits or {"cpu_seconds": 5, "memory_mb": 1024, "file_mb": 16, "wall_seconds": 20}}
    (tmp_path / "job.json").write_text(json.dumps(job))
    subprocess.run([sys.executable, "-I", str(RUNNER), str(tmp_path)], cwd=tmp_path, timeout=60, check=True)
    return json.loads((tmp_path / "status.json").read_text())


def test_results_are_plain_npy_files(tmp_path):
    assert run_job(tmp_path, "def f(n):\n    return [n, n + 1]\n", [[1], [2]]) == {"kind": "ok", "cases": 2}
    assert np.load(tmp_path / "c1_0.npy", allow_pickle=False).tolist() == [2, 3]


def test_the_limits_are_set_before_the_file_runs(tmp_path):
    source = ("import resource\ndef f(n):\n    raise RuntimeError(str([resource.getrlimit(r)[0] for r in "
              "(resource.RLIMIT_CPU, resource.RLIMIT_AS, resource.RLIMIT_FSIZE, resource.RLIMIT_CORE)]))\n")
    status = run_job(tmp_path, source, [[0]])
    assert status["message"] == str([5, 1024 * 2 ** 20, 16 * 2 ** 20, 0])


def test_writing_beyond_the_file_limit_fails_in_the_child(tmp_path):
    status = run_job(tmp_path, "import numpy as np\ndef f(n):\n    return np.zeros(10 ** 7)\n", [[0]])
    assert status["kind"] == "wrong-return-type" and "too large to hand back (80,000,000 bytes" in status["message"]


def test_a_tuple_of_the_wrong_length_is_named():
    assert as_outputs((1, 2, 3), 2)[1] == "returned a tuple of 3 items; expected a tuple of 2 arrays"
    assert as_outputs(np.zeros(3), 2)[1] == "returned a ndarray; expected a tuple of 2 arrays"
    assert as_outputs((np.zeros(3),), 1)[0][0].shape == (3,)
