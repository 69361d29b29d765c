"""lab/suggest.py: the one name-suggestion function, and the places that use it."""
import subprocess
import sys

import pytest

from lab.loading import SceneError, load_scene, parse_scene
from lab.suggest import closest, did_you_mean


def test_the_closest_name_is_suggested_and_a_far_one_is_not():
    assert closest("spot-atenuation", ["spot-attenuation", "globe"]) == "spot-attenuation"
    assert closest("GOURAD", ["flat", "gouraud", "phong"]) == "gouraud"  # case is ignored
    assert closest("zzz", ["flat", "gouraud"]) is None
    assert did_you_mean("zzz", ["flat"]) == ""


@pytest.mark.parametrize("spec, suggestion", [
    ("spot-atenuation", "spot-attenuation"),  # a preset
    ("icosphre:level=2", "icosphere"),        # a shape
    ("icosphere:levl=2", "level"),            # a shape's parameter
])
def test_scene_names_suggest_the_same_way(spec, suggestion):
    with pytest.raises(SceneError, match=f"did you mean '{suggestion}'"):
        load_scene(spec)


def test_scene_file_keys_and_choices_suggest_the_same_way():
    with pytest.raises(SceneError, match="camera.view_angel: unknown key \\(did you mean 'view_angle'\\?\\)"):
        parse_scene(b'[camera]\nview_angel = 30\n[[object]]\nshape = "cube"\n')
    with pytest.raises(SceneError, match="shading: 'gourad' is not one of flat, gouraud, phong \\(did you mean "
                                         "'gouraud'\\?\\)"):
        parse_scene(b'[[object]]\nshape = "cube"\nshading = "gourad"\n')


@pytest.mark.parametrize("args, suggestion", [
    (["render", "spot-atenuation"], "did you mean 'spot-attenuation'"),
    (["render", "cube", "--shading", "gourad"], "did you mean 'gouraud'"),
    (["render", "cube", "--model", "opengel"], "did you mean 'opengl'"),
    (["demo", "fill-rul"], "did you mean 'fill-rule'"),
    (["rendr", "cube"], "did you mean 'render'"),
])
def test_the_command_line_suggests_the_same_way(args, suggestion, tmp_path):
    p = subprocess.run([sys.executable, "-m", "lab", *args, *(["-o", str(tmp_path / "x.png")]
                        if args[0] == "render" else [])], capture_output=True, text=True, timeout=300)
    assert p.returncode == 2 and suggestion in p.stderr and len(p.stderr.strip().splitlines()) == 1
