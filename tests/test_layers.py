"""The floors of the house, checked in fresh interpreters through ``sys.modules``.

ground floor (``lab``, but ``lab.app``) → ``renderer`` → ``compare`` → the application
(``lab.app``, ``lessons``). Each floor may import only what lies below it; a lazy import
inside a function counts too, because the check runs the code that imports.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _modules(package: str, skip: tuple[str, ...] = ()) -> list[str]:
    names = []
    for path in sorted((ROOT / package).rglob("*.py")):
        parts = path.relative_to(ROOT).with_suffix("").parts
        if parts[-1] == "__main__" or any(".".join(parts).startswith(s) for s in skip):
            continue
        names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


GROUND = _modules("lab", skip=("lab.app",))
RENDERER = _modules("renderer")
COMPARE = _modules("compare")

ABOVE_GROUND = ("renderer", "compare", "lessons", "lab.app", "vtk", "vtkmodules", "pyvista", "matplotlib", "numba")
ABOVE_RENDERER = ("compare", "lessons", "lab.app", "vtk", "vtkmodules", "pyvista", "matplotlib")
ABOVE_COMPARE = ("lessons", "lab.app")


def loaded_after(code: str) -> list[str]:
    """The module names in ``sys.modules`` after running ``code`` in a fresh interpreter."""
    probe = code + "\nimport sys, json\nprint(json.dumps(sorted(sys.modules)))"
    done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def forbidden(loaded: list[str], above: tuple[str, ...]) -> list[str]:
    return sorted(m for m in loaded if any(m == a or m.startswith(a + ".") for a in above))


def test_the_floors_are_found():
    assert "lab.scene" in GROUND and "lab.loading" in GROUND and "lab.app.cli" not in GROUND
    assert "renderer.pipeline" in RENDERER and "compare.metrics" in COMPARE


@pytest.mark.parametrize("module", GROUND)
def test_a_ground_floor_module_loads_nothing_above_it(module):
    assert forbidden(loaded_after(f"import {module}"), ABOVE_GROUND) == []


@pytest.mark.parametrize("spec", ["menger", "csg", "cube", "icosphere:level=2", "cylinder-cone"])
def test_loading_a_scene_of_built_in_shapes_loads_nothing_above_the_ground(spec):
    """Presets and shapes made of built-in shapes: not even VTK is loaded to read them."""
    assert forbidden(loaded_after(f"import lab; lab.load_scene({spec!r})"), ABOVE_GROUND) == []


@pytest.mark.parametrize("module", RENDERER)
def test_a_renderer_module_loads_neither_compare_nor_vtk(module):
    assert forbidden(loaded_after(f"import {module}"), ABOVE_RENDERER) == []


def test_rendering_a_preset_loads_neither_compare_nor_vtk_nor_matplotlib():
    loaded = loaded_after("import lab, renderer; renderer.render(lab.load_scene('menger'))")
    assert forbidden(loaded, ABOVE_RENDERER) == []


def test_a_mesh_file_is_read_through_the_door_and_rendering_adds_nothing_above():
    """torus-mesh reads a PLY file: VTK's reader is loaded (through the ground floor's door,
    lab.meshfiles.vtk_readers), but neither renderer, compare nor the application; rendering
    the scene then loads no VTK of its own, nor compare or matplotlib."""
    loaded = loaded_after("import lab; lab.load_scene('torus-mesh')")
    assert "vtkmodules.vtkIOPLY" in loaded and "lab.meshfiles.vtk_readers" in loaded
    assert forbidden(loaded, ("renderer", "compare", "lessons", "lab.app", "pyvista", "matplotlib", "numba")) == []
    probe = ("import lab, sys, json; scene = lab.load_scene('torus-mesh'); before = set(sys.modules); import renderer; "
             "renderer.render(scene); print(json.dumps(sorted(set(sys.modules) - before)))")
    done = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    added = json.loads(done.stdout.strip().splitlines()[-1])
    assert "renderer.pipeline" in added and forbidden(added, ABOVE_RENDERER) == []


@pytest.mark.parametrize("module", COMPARE)
def test_a_compare_module_loads_nothing_of_the_application(module):
    assert forbidden(loaded_after(f"import {module}"), ABOVE_COMPARE) == []


def test_the_check_catches_an_upward_import():
    """The probe itself works: importing the command line does load the floors above the ground."""
    loaded = loaded_after("import lab.app.cli, lab.app.demo; lab.app.demo.run_demo")
    assert "lab.app.cli" in forbidden(loaded, ABOVE_GROUND)
