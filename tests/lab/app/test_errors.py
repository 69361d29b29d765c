"""Bad input: every case ends in one line naming the file and the key, exit status 2, no
traceback, nothing written. One table row per case (see ``CASES``); ``scanlab`` runs in
process (``lab.app.cli.main``), and a few cases again as real ``python -m lab`` processes.
"""
from __future__ import annotations

import base64
import hashlib
import os
import struct
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from lab.app.cli import main

REPO = Path(__file__).resolve().parents[3]

# --------------------------------------------------------------------------- scene files
BASE = {
    "image": {"size": "[64, 48]"},
    "camera": {"position": "[3.0, 2.0, 4.0]", "focal_point": "[0.0, 0.0, 0.0]", "view_up": "[0.0, 1.0, 0.0]"},
    "light": {"kind": '"scene"', "position": "[5.0, 5.0, 0.0]"},
    "object": {"shape": '"cube"'},
}
HEADERS = {"image": "[image]", "camera": "[camera]", "light": "[[light]]", "object": "[[object]]",
           "render": "[render]"}


def scene(**changes) -> str:
    """A small valid scene file, with ``changes[section][key] = value text`` (None deletes the key)."""
    sections = {name: dict(keys) for name, keys in BASE.items()}
    for name, keys in changes.items():
        sections.setdefault(name, {}).update(keys)
    out = []
    for name, keys in sections.items():
        out.append(HEADERS[name])
        out += [f"{k} = {v}" for k, v in keys.items() if v is not None]
    return "\n".join(out) + "\n"


def mesh_scene(file: str, **object_keys) -> str:
    return scene(object={"shape": None, "mesh": f'"{file}"', **object_keys})


TEXTURED = {"shape": '"icosphere"', "params": "{ level = 1, uv = 1 }"}

# --------------------------------------------------------------------------- mesh files
TRI = "0 0 0\n1 0 0\n0 1 0\n"


def ply(points=TRI, faces="3 0 1 2\n", n_points=3, n_faces=1) -> str:
    return ("ply\nformat ascii 1.0\n"
            f"element vertex {n_points}\nproperty float x\nproperty float y\nproperty float z\n"
            f"element face {n_faces}\nproperty list uchar int vertex_indices\nend_header\n{points}{faces}")


def obj(points=TRI, faces="f 1 2 3\n") -> str:
    return "".join(f"v {p}\n" for p in points.strip().split("\n")) + faces


def stl(points=TRI) -> str:
    corners = "".join(f"vertex {p}\n" for p in points.strip().split("\n"))
    return f"solid t\nfacet normal 0 0 1\nouter loop\n{corners}endloop\nendfacet\nendsolid t\n"


EMPTY_BINARY_STL = b"scanlab test".ljust(80, b" ") + (0).to_bytes(4, "little")
SHORT_BINARY_STL = b"scanlab test".ljust(80, b" ") + (5).to_bytes(4, "little") + bytes(50)

# MeshLab-style: face lines carry values (here per-corner texture coordinates) the header does not declare
MESHLAB_PLY = ply(points=TRI + "1 1 0\n", n_points=4, n_faces=2,
                  faces="3 0 1 2 6 0.599829 0.1 0.2 0.3 0.4 0.5\n3 0 2 3 6 0.599829 0.1 0.2 0.3 0.4 0.5\n")
STRIPS_PLY = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
              "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
              "4 0 1 2 3\n")
# A binary PLY cut short inside its face list (this crashed VTK's reader)
SHORT_BINARY_PLY = ("ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n").encode() \
    + bytes(36) + b"\x03" + struct.pack("<2i", 0, 1)


def vtk(points=TRI, polys="POLYGONS 1 4\n3 0 1 2\n", point_data="") -> str:
    return (f"# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n{points}{polys}"
            f"{point_data}")


def vtp(points="0 0 0 1 0 0 0 1 0", conn="0 1 2", offsets="3", n_polys=1, point_data="") -> str:
    """A VTK XML PolyData file; ``points`` as text, or a list of numbers for base64 binary
    (VTK's XML reader parses neither "nan" nor "inf" in ASCII arrays, only in binary ones)."""
    def array(name, values, comps=1, kind="Int32"):
        if not isinstance(values, str):
            raw = struct.pack(f"<{len(values)}f", *values)
            return (f'<DataArray type="{kind}" Name="{name}" NumberOfComponents="{comps}" format="binary">'
                    f"{base64.b64encode(struct.pack('<I', len(raw)) + raw).decode()}</DataArray>")
        return (f'<DataArray type="{kind}" Name="{name}" NumberOfComponents="{comps}" format="ascii">'
                f"{values}</DataArray>")

    return ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian">'
            f'<PolyData><Piece NumberOfPoints="3" NumberOfPolys="{n_polys}">{point_data}'
            f'<Points>{array("p", points, 3, "Float32")}</Points>'
            f'<Polys>{array("connectivity", conn)}{array("offsets", offsets)}</Polys>'
            "</Piece></PolyData></VTKFile>\n")


VTP_TWO_NORMALS = ('<PointData Normals="n"><DataArray type="Float32" Name="n" NumberOfComponents="3" '
                   'format="ascii">0 0 1 0 0 1</DataArray></PointData>')
VTP_TWO_TCOORDS = ('<PointData TCoords="t"><DataArray type="Float32" Name="t" NumberOfComponents="2" '
                   'format="ascii">0 0 1 0</DataArray></PointData>')


# --------------------------------------------------------------------------- the table
@dataclass
class Case:
    """One bad input: the files to make, the command line, and words the message must hold.

    ``{dir}`` in args and words is the test's folder; ``scene.toml`` is the usual input.
    """

    id: str
    args: list[str]
    words: list[str]
    files: dict = field(default_factory=dict)


def render(*extra):
    return ["render", "{dir}/scene.toml", "-o", "{dir}/out/x.png", *extra]


def toml_case(id_, text, *words):
    return Case(id_, render(), ["{dir}/scene.toml", *words], {"scene.toml": text})


def mesh_case(id_, name, content, *words, **object_keys):
    return Case(id_, render(), ["{dir}/scene.toml", "object[0].mesh", f"{{dir}}/{name}", *words],
                {"scene.toml": mesh_scene(name, **object_keys), name: content})


CASES = [
    # --- TOML syntax, keys, types
    toml_case("toml-syntax-error", "[camera\nposition = [1, 2, 3]\n", "TOML syntax error", "line 1", "column"),
    toml_case("toml-syntax-bad-value", scene(camera={"view_angle": "3 0"}), "TOML syntax error", "line 7, column 16"),
    toml_case("toml-duplicate-key", scene() + "[image]\nsize = [1, 1]\n", "TOML syntax error", "line"),
    toml_case("not-utf8", "[image]\nsize = [64, 48] # \xff\n".encode("latin-1"), "not a UTF-8"),
    toml_case("huge-integer-literal", scene(image={"size": "[" + "9" * 5000 + ", 2]"}), "TOML", "too long"),
    toml_case("nested-too-deep", scene(image={"background": "[" * 3000 + "]" * 3000}), "nested too deeply"),
    toml_case("unknown-top-table", scene() + "[cammera]\n", ": cammera: unknown key", "did you mean 'camera'"),
    toml_case("unknown-camera-key", scene(camera={"view_angel": "30.0"}), "camera.view_angel",
              "did you mean 'view_angle'"),
    toml_case("unknown-object-key", scene(object={"colour": "[1, 0, 0]"}), "object[0].colour",
              "did you mean 'color'"),
    toml_case("unknown-light-key", scene(light={"intensty": "1.0"}), "light[0].intensty",
              "did you mean 'intensity'"),
    toml_case("unknown-render-key", scene(render={"zbuffer": "true"}), "render.zbuffer", "unknown key"),
    toml_case("number-is-string", scene(camera={"view_angle": '"30"'}), "camera.view_angle",
              "expected a number"),
    toml_case("number-is-bool", scene(object={"ambient": "true"}), "object[0].ambient", "expected a number"),
    toml_case("flag-is-number", scene(camera={"parallel": "1"}), "camera.parallel", "expected true or false"),
    toml_case("table-is-number", "camera = 3\n[[object]]\nshape = 'cube'\n", ": camera: expected a table"),
    toml_case("objects-not-tables", "object = [1, 2]\n", ": object: expected tables [[object]]"),
    toml_case("no-objects", "[image]\nsize = [64, 48]\n", "object", "no [[object]]"),
    toml_case("vector-is-date", scene(object={"scale": "1979-05-27"}), "object[0].scale",
              "expected a list of 3 numbers"),
    toml_case("vector-too-short", scene(camera={"position": "[1, 2]"}), "camera.position",
              "expected a list of 3 numbers"),
    toml_case("vector-too-long", scene(object={"translate": "[1, 2, 3, 4]"}), "object[0].translate",
              "expected a list of 3 numbers"),
    toml_case("size-one-number", scene(image={"size": "[64]"}), "image.size", "expected a list of 2 numbers"),
    toml_case("nan-number", scene(camera={"view_angle": "nan"}), "camera.view_angle", "finite"),
    toml_case("inf-number", scene(light={"intensity": "inf"}), "light[0].intensity", "finite"),
    toml_case("nan-in-vector", scene(camera={"focal_point": "[0, nan, 0]"}), "camera.focal_point", "finite"),
    toml_case("inf-in-vector", scene(object={"rotate": "[0, -inf, 0]"}), "object[0].rotate", "finite"),
    toml_case("number-beyond-1e15", scene(camera={"position": "[1e308, 0, 0]"}), "camera.position",
              "[-1e+15, 1e+15]"),
    toml_case("integer-beyond-float", scene(light={"position": "[" + "1" + "0" * 400 + ", 0, 0]"}),
              "light[0].position", "finite"),
    toml_case("colour-above-1", scene(image={"background": "[1.5, 0, 0]"}), "image.background", "[0, 1]"),
    toml_case("colour-negative", scene(object={"color": "[0.5, -0.1, 0]"}), "object[0].color", "[0, 1]"),
    toml_case("light-colour-above-1", scene(light={"color": "[1, 1, 2]"}), "light[0].color", "[0, 1]"),
    toml_case("size-zero", scene(image={"size": "[0, 48]"}), "image.size", "at least 1"),
    toml_case("size-negative", scene(image={"size": "[64, -48]"}), "image.size", "at least 1"),
    toml_case("size-fractional", scene(image={"size": "[64.5, 48]"}), "image.size", "whole numbers"),
    toml_case("size-beyond-limit", scene(image={"size": "[8193, 48]"}), "image.size", "8192x8192",
              "--allow-large"),
    Case("size-beyond-large-limit", render("--allow-large"), ["{dir}/scene.toml", "image.size", "65536x65536"],
         {"scene.toml": scene(image={"size": "[65537, 2]"})}),
    toml_case("intensity-negative", scene(light={"intensity": "-1"}), "light[0].intensity", "[0, 1000]"),
    toml_case("intensity-huge", scene(light={"intensity": "1e4"}), "light[0].intensity", "[0, 1000]"),
    toml_case("specular-power-negative", scene(object={"specular_power": "-5"}), "object[0].specular_power",
              "[0, 1000]"),
    toml_case("specular-power-huge", scene(object={"specular_power": "5000"}), "object[0].specular_power",
              "[0, 1000]"),
    toml_case("shininess-above-128", scene(object={"shininess": "200"}), "object[0].shininess", "[0, 128]"),
    toml_case("ambient-above-1", scene(object={"ambient": "1.5"}), "object[0].ambient", "[0, 1]"),
    toml_case("spot-exponent-above-128", scene(light={"exponent": "300"}), "light[0].exponent", "[0, 128]"),
    toml_case("cone-angle-zero", scene(light={"cone_angle": "0"}), "light[0].cone_angle", "(0, 180]"),
    toml_case("attenuation-all-zero", scene(light={"attenuation": "[0, 0, 0]"}), "light[0].attenuation",
              "positive"),
    toml_case("opacity-above-1", scene(object={"opacity": "1.5"}), "object[0].opacity", "[0, 1]"),
    toml_case("unknown-transparency", scene(render={"transparency": '"peeling"'}), "render.transparency",
              "oit, depth_peeling, sorted"),
    toml_case("zero-scale", scene(object={"scale": "[1, 0, 1]"}), "object[0].scale", "zero scale"),
    # --- names
    toml_case("unknown-shading", scene(object={"shading": '"gourad"'}), "object[0].shading",
              "flat, gouraud, phong"),
    toml_case("shading-is-a-list", scene(object={"shading": '["flat"]'}), "object[0].shading",
              "['flat'] is not one of flat, gouraud, phong"),
    toml_case("unknown-model", scene(object={"model": '"phong"'}), "object[0].model", "vtk, opengl, classic"),
    toml_case("unknown-light-kind", scene(light={"kind": '"spot"'}), "light[0].kind",
              "scene, camera, headlight, eye"),
    toml_case("unknown-shape", scene(object={"shape": '"sphere"'}), "object[0].shape", "unknown shape 'sphere'",
              "cube, quad, icosahedron, icosphere"),
    toml_case("shape-is-a-list", scene(object={"shape": '["cube"]'}), "object[0].shape", "unknown shape",
              "icosphere"),
    toml_case("unknown-shape-param", scene(object={"params": "{ sides = 3 }"}), "object[0].shape",
              "no parameter 'sides'", "size"),
    toml_case("shape-level-too-high", scene(object={"shape": '"icosphere"', "params": "{ level = 9 }"}),
              "object[0].shape", "level", "0..7"),
    toml_case("unknown-normals", scene(object={"normals": '"smooth"'}), "object[0].normals",
              "file, computed, face, radial"),
    toml_case("unknown-interpolation", scene(render={"interpolation": '"linear"'}), "render.interpolation",
              "perspective, screen"),
    toml_case("unknown-hidden-surface", scene(render={"hidden_surface": '"zbufer"'}), "render.hidden_surface",
              "zbuffer, painter, none"),
    toml_case("unknown-texture-filter", scene(object={**TEXTURED, "texture_filter": '"cubic"'}),
              "object[0].texture_filter", "nearest, linear"),
    toml_case("unknown-csg-op", scene(object={"shape": None, "csg": '{ op = "xor", children = [] }'}),
              "object[0].csg", "unknown op 'xor'", "union, difference, intersection"),
    toml_case("two-sources", scene(object={"mesh": '"a.ply"'}), "object[0].mesh", "exactly one"),
    toml_case("matrix-and-scale", scene(object={"scale": "[1, 1, 1]", "matrix": "[[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"}),
              "object[0].matrix", "not both"),
    toml_case("matrix-three-rows", scene(object={"matrix": "[[1,0,0,0],[0,1,0,0],[0,0,1,0]]"}), "object[0].matrix",
              "4 rows of 4 numbers"),
    toml_case("matrix-row-short", scene(object={"matrix": "[[1,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"}),
              "object[0].matrix", "4 numbers"),
    toml_case("matrix-projective", scene(object={"matrix": "[[1,0,0,0.5],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"}),
              "object[0].matrix", "affine"),
    toml_case("matrix-singular", scene(object={"matrix": "[[0,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]"}),
              "object[0].matrix", "flattens"),
    # --- camera
    toml_case("camera-position-is-focal-point", scene(camera={"position": "[0, 0, 0]"}), "camera.position",
              "focal_point"),
    toml_case("camera-up-parallel", scene(camera={"position": "[0, 5, 0]"}), "camera.view_up", "parallel"),
    toml_case("camera-up-zero", scene(camera={"view_up": "[0, 0, 0]"}), "camera.view_up", "zero"),
    toml_case("view-angle-zero", scene(camera={"view_angle": "0"}), "camera.view_angle", "(0, 180)"),
    toml_case("view-angle-180", scene(camera={"view_angle": "180"}), "camera.view_angle", "(0, 180)"),
    toml_case("view-angle-negative", scene(camera={"view_angle": "-30"}), "camera.view_angle", "(0, 180)"),
    toml_case("clipping-near-zero", scene(camera={"clipping_range": "[0, 10]"}), "camera.clipping_range",
              "0 < near < far"),
    toml_case("clipping-near-negative", scene(camera={"clipping_range": "[-1, 10]"}), "camera.clipping_range",
              "0 < near < far"),
    toml_case("clipping-far-before-near", scene(camera={"clipping_range": "[5, 2]"}), "camera.clipping_range",
              "0 < near < far"),
    toml_case("clipping-far-equals-near", scene(camera={"clipping_range": "[5, 5]"}), "camera.clipping_range",
              "0 < near < far"),
    toml_case("parallel-scale-zero", scene(camera={"parallel_scale": "0"}), "camera.parallel_scale", "(0,"),
    toml_case("parallel-scale-negative", scene(camera={"parallel_scale": "-2"}), "camera.parallel_scale", "(0,"),
    # --- meshes
    Case("mesh-missing", render(), ["{dir}/scene.toml", "object[0].mesh", "{dir}/none.ply", "No such file"],
         {"scene.toml": mesh_scene("none.ply")}),
    Case("mesh-is-a-folder", render(), ["{dir}/scene.toml", "object[0].mesh", "{dir}/dir.ply",
                                        "is a folder"],
         {"scene.toml": mesh_scene("dir.ply"), "dir.ply/": ""}),
    Case("mesh-is-a-folder-without-suffix", render(), ["{dir}/scene.toml", "object[0].mesh", "{dir}/models",
                                                       "is a folder"],
         {"scene.toml": mesh_scene("models"), "models/": ""}),
    Case("mesh-pyvista-example-unknown", render(), ["object[0].mesh", "no example file 'globe.vtkk'",
                                                    "did you mean 'globe.vtk'", "ant.ply"],
         {"scene.toml": mesh_scene("pyvista-examples:globe.vtkk")}),
    Case("mesh-name-too-long", render(), ["{dir}/scene.toml", "object[0].mesh", "File name too long"],
         {"scene.toml": mesh_scene("x" * 5000 + ".ply")}),
    mesh_case("mesh-unknown-suffix", "m.txt", "hello", "unknown mesh file suffix", ".ply, .obj"),
    mesh_case("mesh-ply-empty-file", "m.ply", "", "not a PLY file"),
    mesh_case("mesh-ply-not-a-mesh", "m.ply", "hello, world\n", "not a PLY file"),
    mesh_case("mesh-obj-not-a-mesh", "m.obj", "v 1 2\n", "line 1", "a vertex needs 3 numbers"),
    mesh_case("mesh-stl-not-a-mesh", "m.stl", "hello", "not an STL file"),
    mesh_case("mesh-vtk-not-a-mesh", "m.vtk", "hello\n", "not a legacy VTK file"),
    mesh_case("mesh-vtp-not-a-mesh", "m.vtp", "hello", "not valid VTK XML"),
    mesh_case("mesh-ply-no-triangles", "m.ply", ply(faces="", n_faces=0), "no triangles"),
    mesh_case("mesh-obj-no-triangles", "m.obj", obj(faces=""), "no triangles"),
    mesh_case("mesh-stl-no-triangles", "m.stl", EMPTY_BINARY_STL, "no triangles"),
    mesh_case("mesh-vtk-no-triangles", "m.vtk", vtk(polys=""), "no triangles"),
    mesh_case("mesh-vtp-no-triangles", "m.vtp", vtp(conn="", offsets="", n_polys=0), "no triangles"),
    mesh_case("mesh-ply-nan", "m.ply", ply(points="nan 0 0\n1 0 0\n0 1 0\n"), "NaN or infinity"),
    mesh_case("mesh-obj-nan", "m.obj", obj(points="0 0 0\n1 inf 0\n0 1 0"), "NaN or infinity"),
    mesh_case("mesh-stl-nan", "m.stl", stl(points="0 0 0\n1 0 nan\n0 1 0"), "NaN or infinity"),
    mesh_case("mesh-vtk-nan", "m.vtk", vtk(points="0 0 0 1 0 0 nan 1 0\n"), "NaN or infinity"),
    mesh_case("mesh-vtp-nan", "m.vtp", vtp(points=[0, 0, 0, 1, 0, 0, 0, 1, float("inf")]), "NaN or infinity"),
    mesh_case("mesh-ply-index-out-of-range", "m.ply", ply(faces="3 0 1 7\n"), "index 7 out of range"),
    mesh_case("mesh-obj-index-out-of-range", "m.obj", obj(faces="f 1 2 9\n"), "vertex 9", "there are 3"),
    mesh_case("mesh-vtk-index-out-of-range", "m.vtk", vtk(polys="POLYGONS 1 4\n3 0 1 3\n"),
              "index 3 out of range"),
    mesh_case("mesh-vtp-index-out-of-range", "m.vtp", vtp(conn="0 1 5"), "index 5 out of range"),
    mesh_case("mesh-vtk-normals-wrong-count", "m.vtk",
              vtk(point_data="POINT_DATA 2\nNORMALS n float\n0 0 1 0 0 1\n"), "point data",
              "one value per point"),
    mesh_case("mesh-vtp-normals-wrong-count", "m.vtp", vtp(point_data=VTP_TWO_NORMALS), 'point data array "n"',
              "too short"),
    mesh_case("mesh-vtk-tcoords-wrong-count", "m.vtk",
              vtk(point_data="POINT_DATA 2\nTEXTURE_COORDINATES t 2 float\n0 0 1 0\n"), "point data",
              "one value per point"),
    mesh_case("mesh-vtp-tcoords-wrong-count", "m.vtp", vtp(point_data=VTP_TWO_TCOORDS), 'point data array "t"',
              "too short"),
    # --- what VTK's readers would misread or crash on, refused before or after they read
    mesh_case("mesh-ply-meshlab-extra-face-values", "m.ply", MESHLAB_PLY, "line 14", "face 1 has 11 values",
              "declares 4"),
    mesh_case("mesh-ply-face-line-short", "m.ply", ply(faces="3 0 1\n"), "line 13", "face 1 has 3 values"),
    mesh_case("mesh-ply-triangle-strips", "m.ply", STRIPS_PLY, "triangle strips", "tristrips", "not supported"),
    mesh_case("mesh-ply-binary-cut-short", "m.ply", SHORT_BINARY_PLY, "ends inside element 'face'", "cut short"),
    mesh_case("mesh-ply-unknown-type", "m.ply", ply().replace("property float y", "property real y"),
              "header line 5", "unknown PLY property type 'real'"),
    mesh_case("mesh-obj-tcoord-index-out-of-range", "m.obj", obj(faces="vt 0 0\nf 1/1 2/1 3/99999999\n"),
              "line 5", "texture coordinate 99999999", "there are 1"),
    mesh_case("mesh-obj-normal-index-out-of-range", "m.obj", obj(faces="vn 0 0 1\nf 1//1 2//1 3//2\n"),
              "line 5", "normal 2", "there are 1"),
    mesh_case("mesh-obj-polygon-not-a-fan", "m.obj",
              obj(points="0 0 0\n2 0 0\n1 0.5 0\n2 2 0\n0 2 0", faces="f 2 3 4 5 1\n"),
              "polygon 1 (5 vertices) is concave where a fan from its first vertex fails"),
    mesh_case("mesh-stl-binary-cut-short", "m.stl", SHORT_BINARY_STL, "cut short", "5 triangles"),
    Case("texture-missing", render(), ["{dir}/scene.toml", "object[0].texture", "{dir}/none.png", "No such file"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"none.png"'})}),
    Case("texture-name-too-long", render(), ["{dir}/scene.toml", "object[0].texture", "File name too long"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"' + "x" * 5000 + '.png"'})}),
    Case("texture-not-an-image", render(), ["{dir}/scene.toml", "object[0].texture", "{dir}/t.png",
                                            "not an image"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"t.png"'}), "t.png": "not a png"}),
    Case("texture-is-a-folder", render(), ["{dir}/scene.toml", "object[0].texture", "{dir}/t.png",
                                           "is a folder"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"t.png"'}), "t.png/": ""}),
    toml_case("texture-without-tcoords", scene(object={"texture": '"t.png"'}), "object[0].texture",
              "no texture coordinates"),
    # --- the command line
    Case("cli-unknown-option", render("--sise", "10x10"), ["scanlab render", "--sise", "did you mean --size?"],
         {"scene.toml": scene()}),
    Case("cli-unknown-command", ["rendr", "cube"], ["scanlab", "invalid choice: 'rendr'", "render"]),
    Case("cli-missing-scene", ["render"], ["scanlab render", "required: scene"]),
    Case("cli-missing-out", ["compare", "cube"], ["scanlab compare", "required: --out"]),
    Case("cli-bad-choice", render("--shading", "gourad"), ["--shading", "invalid choice: 'gourad'", "gouraud"],
         {"scene.toml": scene()}),
    Case("cli-size-not-wxh", render("--size", "big"), ["--size", "WIDTHxHEIGHT"], {"scene.toml": scene()}),
    Case("cli-size-zero", render("--size", "0x10"), ["--size", "at least 1"], {"scene.toml": scene()}),
    Case("cli-size-beyond-limit", render("--size", "9000x10"), ["--size", "8192x8192", "--allow-large"],
         {"scene.toml": scene()}),
    Case("cli-no-such-scene", ["render", "{dir}/nope.toml", "-o", "{dir}/out/x.png"],
         ["{dir}/nope.toml", "cannot read"]),
    Case("cli-scene-is-a-folder", ["render", "{dir}", "-o", "{dir}/x.png"], ["{dir}", "is a folder"]),
    Case("cli-scene-toml-is-a-folder", ["render", "{dir}/s.toml", "-o", "{dir}/x.png"], ["{dir}/s.toml", "is a folder"],
         {"s.toml/": ""}),
    Case("cli-mesh-file-scene-broken", ["render", "{dir}/m.obj", "-o", "{dir}/x.png"], ["{dir}/m.obj", "line 1"],
         {"m.obj": "v 1 2\n"}),
    Case("cli-mesh-file-scene-unknown-suffix", ["render", "{dir}/m.txt", "-o", "{dir}/x.png"],
         ["{dir}/m.txt", "unknown mesh file suffix"], {"m.txt": "hello"}),
    Case("cli-bench-repeat-zero", ["bench", "cube", "--repeat", "0"], ["--repeat", "at least 1"]),
    Case("cli-bench-repeat-not-a-number", ["bench", "cube", "--repeat", "x"], ["--repeat", "whole number"]),
    Case("cli-fuzz-cases-negative", ["fuzz", "--cases", "-5", "--save", "{dir}/f"], ["--cases", "at least 1"]),
    Case("cli-fail-above-nan", ["compare", "cube", "--out", "{dir}/o", "--fail-above", "nan"],
         ["--fail-above", "finite"]),
    Case("cli-bar-unknown", ["compare", "cube", "--out", "{dir}/o", "--bar", "maen=0.1"],
         ["--bar", "unknown bar 'maen'", "did you mean 'mean'"]),
    Case("cli-bar-not-a-number", ["compare", "cube", "--out", "{dir}/o", "--bar", "mean=lots"],
         ["--bar", "expected a number"]),
    Case("cli-demo-scene-file-broken", ["demo", "--out", "{dir}/out", "{dir}/scene.toml"],
         ["{dir}/scene.toml", "camera.view_angel"], {"scene.toml": scene(camera={"view_angel": "30"})}),
    Case("cli-stages-missing-out", ["stages", "cube"], ["scanlab stages", "required: --out"]),
    Case("cli-scene-name-too-long", ["render", "x" * 5000, "-o", "{dir}/x.png"], ["xxxxxxxx", "cannot read: File name too long"]),
    Case("cli-unknown-shape-param", ["render", "cube:sides=3", "-o", "{dir}/out/x.png"], ["cube:sides=3", "sides"]),
    Case("cli-demo-unknown-preset", ["demo", "--out", "{dir}/out", "fill-rul"], ["fill-rul", "fill-rule"]),
    Case("cli-export-unknown-format", ["export", "{dir}/scene.toml", "-o", "{dir}/out/x.dae"],
         ["{dir}/out/x.dae", ".ply, .obj, .stl, .vtp", ".toml"], {"scene.toml": scene()}),
    # --- outputs that would overwrite an input, or cannot be made
    Case("out-overwrites-scene", ["render", "{dir}/scene.toml", "-o", "{dir}/scene.toml"],
         ["{dir}/scene.toml", "would overwrite the input"], {"scene.toml": scene()}),
    Case("out-overwrites-scene-relative", ["render", "{dir}/scene.toml", "-o", "{dir}/out/../scene.toml"],
         ["scene.toml", "would overwrite the input"], {"scene.toml": scene(), "out/": ""}),
    Case("export-overwrites-mesh", ["export", "{dir}/scene.toml", "-o", "{dir}/m.obj"],
         ["{dir}/m.obj", "would overwrite the input"], {"scene.toml": mesh_scene("m.obj"), "m.obj": obj()}),
    Case("out-overwrites-texture", ["render", "{dir}/scene.toml", "-o", "{dir}/t.png"],
         ["{dir}/t.png", "would overwrite the input"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"t.png"'}), "t.png": "PNG"}),
    Case("compare-overwrites-texture", ["compare", "{dir}/scene.toml", "--out", "{dir}"],
         ["{dir}/ours.png", "would overwrite the input"],
         {"scene.toml": scene(object={**TEXTURED, "texture": '"ours.png"'}), "ours.png": "PNG"}),
    Case("out-is-a-folder", ["render", "{dir}/scene.toml", "-o", "{dir}/out"], ["{dir}/out", "is a folder"],
         {"scene.toml": scene(), "out/": ""}),
    Case("out-under-a-file", ["render", "{dir}/scene.toml", "-o", "{dir}/scene.toml/x.png"],
         ["{dir}/scene.toml/x.png", "cannot create the folder"], {"scene.toml": scene()}),
    Case("compare-out-is-a-file", ["compare", "{dir}/scene.toml", "--out", "{dir}/scene.toml"],
         ["--out {dir}/scene.toml", "is a file"], {"scene.toml": scene()}),
]

# Texture files in rows above that must really be PNGs for the scene to get as far as the output check.
PNG_FILES = {"out-overwrites-texture": "t.png", "compare-overwrites-texture": "ours.png"}


def _make_files(root: Path, files: dict, case_id: str) -> None:
    for name, content in files.items():
        path = root / name
        if name.endswith("/"):
            path.mkdir(parents=True, exist_ok=True)
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        if PNG_FILES.get(case_id) == name:
            from lab.png import write_png
            import numpy as np

            write_png(path, np.zeros((4, 4, 3), np.uint8))
        elif isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)


def _snapshot(root: Path) -> dict:
    """Every file and folder under root, with a hash of each file's bytes."""
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest() if p.is_file() else "dir"
            for p in sorted(root.rglob("*"))}


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_is_one_line_status_2_and_writes_nothing(case, tmp_path, capsys):
    """Exit 2; stderr is one line naming the file and key; no traceback; no file written or changed."""
    _make_files(tmp_path, case.files, case.id)
    before = _snapshot(tmp_path)
    status = main([a.replace("{dir}", str(tmp_path)) for a in case.args])
    out, err = capsys.readouterr()
    assert status == 2, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    for word in case.words:
        assert word.replace("{dir}", str(tmp_path)) in err, f"{word!r} not in {err!r}"
    assert _snapshot(tmp_path) == before, "an output was written or an input changed"


def test_the_table_covers_each_kind_of_bad_input():
    """At least one row per issue item (guards against rows being dropped by accident)."""
    ids = " ".join(c.id for c in CASES)
    for word in ("toml-syntax", "unknown-camera-key", "number-is-string", "vector-too-short", "nan", "inf",
                 "colour-above-1", "size-zero", "size-negative", "size-beyond-limit", "intensity", "specular-power",
                 "unknown-shading", "unknown-model", "unknown-light-kind", "unknown-shape",
                 "camera-position-is-focal-point", "camera-up-parallel", "view-angle", "clipping-near-zero",
                 "clipping-far-before-near", "parallel-scale-zero", "mesh-missing", "mesh-is-a-folder",
                 "not-a-mesh", "no-triangles", "mesh-ply-nan", "index-out-of-range", "normals-wrong-count",
                 "tcoords-wrong-count", "texture-not-an-image", "cli-unknown-option", "cli-missing-scene",
                 "out-overwrites-scene", "export-overwrites-mesh", "out-overwrites-texture"):
        assert word in ids, word
    for fmt in ("ply", "obj", "stl", "vtk", "vtp"):
        assert f"mesh-{fmt}-nan" in ids and f"mesh-{fmt}-no-triangles" in ids, fmt


# --------------------------------------------------------------------------- real processes
def run(*args, cwd=None):
    """``python -m lab ARGS`` in a child process: (status, stdout, stderr)."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    p = subprocess.run([sys.executable, "-m", "lab", *args], capture_output=True, text=True, env=env,
                       timeout=300, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


@pytest.mark.parametrize("text, args, words", [
    ("[camera\n", [], ["TOML syntax error", "line 1, column"]),
    (scene(object={"shading": '"gourad"'}), [], ["object[0].shading", "flat, gouraud, phong"]),
    (scene(), ["--sise", "9x9"], ["unrecognized arguments: --sise", "did you mean --size?"]),
], ids=["toml-syntax", "unknown-shading", "unknown-option"])
def test_a_real_process_exits_2_with_one_line(text, args, words, tmp_path):
    """The same rule for a real ``python -m lab`` process: status 2, one line, no traceback."""
    (tmp_path / "scene.toml").write_text(text)
    status, out, err = run("render", str(tmp_path / "scene.toml"), "-o", str(tmp_path / "x.png"), *args)
    assert status == 2 and "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert all(w in err for w in words), err
    assert not (tmp_path / "x.png").exists()
