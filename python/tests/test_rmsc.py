"""The rmsc Python module: the calls the README promises, edits by pointer and by node id or
name, validation as `rmsc validate` reports it, errors, the back end choice, docstrings and the
turntable example.
Run by ctest with PYTHONPATH naming the built module, RMSC_BINARY the rmsc command and
RMSC_SOURCE_DIR the repository."""
import inspect
import os
import subprocess
import sys

import numpy
import pytest

import rmsc

SOURCE = os.environ.get("RMSC_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
PAWN = os.path.join(SOURCE, "samples", "scenes", "pawn.json")
SPHERE = """{"version": 1,
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov": 45},
  "lights": [{"type": "directional", "direction": [0, -1, -1], "intensity": 3}],
  "sdf": {"shape": "sphere", "radius": 1}}"""


def test_render_color_and_depth_as_documented():
    scene = rmsc.Scene.load(PAWN)
    image = scene.render(size=(32, 18), aov="color")
    assert image.shape == (18, 32, 3) and image.dtype == numpy.uint8
    assert image.std() > 1.0  # not one flat colour
    depth = scene.render(size=(32, 18), aov="depth")
    assert depth.shape == (18, 32) and depth.dtype == numpy.float32
    assert numpy.isfinite(depth).any()


def test_every_aov_and_its_values():
    scene = rmsc.Scene.from_json(SPHERE)
    depth = scene.render(size=(16, 16), aov="depth")
    assert depth[8, 8] == pytest.approx(2.0, abs=0.02)
    assert numpy.isinf(depth[0, 0])
    ids = scene.render(size=(16, 16), aov="id")
    assert ids.dtype == numpy.uint32 and ids[8, 8] == 65536 and ids[0, 0] == 0
    normal = scene.render(size=(16, 16), aov="normal")
    assert normal.shape == (16, 16, 3) and normal[8, 8, 2] == pytest.approx(1.0, abs=0.05)
    steps = scene.render(size=(16, 16), aov="steps")
    assert steps.dtype == numpy.float32 and steps[8, 8] > 0
    with pytest.raises(rmsc.Error) as error:
        scene.render(size=(16, 16), aov="colour")
    assert error.value.kind == "usage"


def test_edit_by_pointer():
    scene = rmsc.Scene.from_json(SPHERE)
    scene.set("/sdf/radius", 0.5)
    assert scene.get("/sdf/radius") == 0.5
    assert scene.render(size=(16, 16), aov="depth")[8, 8] == pytest.approx(2.5, abs=0.02)
    scene.set("/sdf/position", [0, 0, 0.5])
    assert scene.render(size=(16, 16), aov="depth")[8, 8] == pytest.approx(2.0, abs=0.02)
    revision = scene.revision
    with pytest.raises(rmsc.Error) as error:
        scene.set("/sdf/radius", -1)
    assert error.value.kind == "bad_input"
    assert error.value.problems[0].pointer == "/sdf/radius"
    assert scene.get("/sdf/radius") == 0.5 and scene.revision == revision


PAIR = """{"version": 1,
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0], "fov": 45},
  "lights": [{"type": "directional", "name": "sun", "intensity": 3}],
  "sdf": {"op": "union", "children": [
    {"shape": "sphere", "name": "ball", "radius": 0.5, "position": [-0.7, 0, 0]},
    {"shape": "box", "name": "crate", "position": [0.7, 0, 0]}]}}"""


def test_edit_by_node_id_and_name():
    scene = rmsc.Scene.from_json(PAIR)
    ids = scene.render(size=(32, 24), aov="id")
    ball = int(ids[12, 10])  # the left one, as the id output shows it
    assert ball == 65537
    assert scene.node_pointer(ball) == "/sdf/children/0"
    assert scene.node_pointer("crate") == "/sdf/children/1"
    assert scene.node_pointer("sun") == "/lights/0"
    scene.set_node(ball, "radius", 0.3)
    assert scene.get("/sdf/children/0/radius") == 0.3
    scene.set_node("crate", "half_extents", [0.2, 0.2, 0.2])
    assert scene.get_node(65538, "half_extents") == [0.2, 0.2, 0.2]
    scene.set_node("sun", "intensity", 5)
    assert scene.get_node("sun", "intensity") == 5
    revision = scene.revision
    with pytest.raises(rmsc.Error) as error:
        scene.set_node("ball", "radius", -1)
    assert error.value.kind == "bad_input"
    assert error.value.problems[0].pointer == "/sdf/children/0/radius"
    assert scene.revision == revision
    with pytest.raises(rmsc.Error) as error:
        scene.set_node(65600, "radius", 1)
    assert error.value.kind == "usage" and "65600" in str(error.value)
    with pytest.raises(rmsc.Error) as error:
        scene.set_node("crat", "radius", 1)
    assert error.value.kind == "usage" and '"crat"' in str(error.value)
    assert '"crate"' in str(error.value)  # the names there are
    with pytest.raises(rmsc.Error):
        scene.node_pointer(-1)
    with pytest.raises(TypeError):
        scene.node_pointer(1.5)


def test_load_errors_carry_file_pointer_and_message(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1, "sdf": {"shape": "spere"}}')
    with pytest.raises(rmsc.Error) as error:
        rmsc.Scene.load(str(bad))
    problem = error.value.problems[0]
    assert (problem.file, problem.pointer, problem.severity) == (str(bad), "/sdf/shape", "error")
    assert 'unknown shape "spere"' in problem.message
    assert str(problem) in str(error.value)


def test_validate_reports_what_rmsc_validate_prints(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"version": 1, "camera": {"fovv": 3, "fov": -3},'
                   ' "sdf": {"shape": "sphere", "radius": "big"}}')
    problems = rmsc.validate(str(bad))
    assert [p.severity for p in problems] == ["warning", "error", "error"]
    assert [p.pointer for p in problems] == ["/camera/fovv", "/camera/fov", "/sdf/radius"]
    binary = os.environ.get("RMSC_BINARY")
    if binary:
        printed = subprocess.run([binary, "validate", str(bad)], capture_output=True, text=True)
        assert printed.returncode == 1
        assert printed.stderr.splitlines() == [str(p) for p in problems]
    assert rmsc.validate(PAWN) == []
    # Text as the file holding it.
    same = rmsc.validate_json(bad.read_text(), str(bad))
    assert [str(p) for p in same] == [str(p) for p in problems]
    assert rmsc.validate_json(open(PAWN).read(), PAWN) == []


def test_backend_choice():
    with pytest.raises(rmsc.Error) as error:
        rmsc.use_backend("vulkan")
    assert error.value.kind == "usage"
    rmsc.Scene.from_json(SPHERE).render(size=(4, 4))
    assert rmsc.backend() in ("egl", "osmesa")
    other = "osmesa" if rmsc.backend() == "egl" else "egl"
    with pytest.raises(rmsc.Error):
        rmsc.use_backend(other)  # the process already renders through the first


@pytest.mark.parametrize("backend", ["egl", "osmesa"])
def test_each_backend_in_its_own_process(backend):
    code = ("import rmsc; rmsc.use_backend(%r); s = rmsc.Scene.from_json(%r);"
            "img = s.render(size=(8, 8)); assert img.shape == (8, 8, 3); print(rmsc.backend())"
            % (backend, SPHERE))
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if result.returncode != 0 and "no headless OpenGL context" in result.stderr:
        pytest.skip(backend + " is not available here: " + result.stderr.strip()[-200:])
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == backend


def test_every_function_has_a_docstring():
    undocumented = []
    for owner in (rmsc, rmsc.Scene, rmsc.Problem):
        for name, member in inspect.getmembers(owner):
            if name.startswith("_") or not callable(member) or inspect.isclass(member):
                continue
            if not (member.__doc__ or "").strip():
                undocumented.append(owner.__name__ + "." + name)
    for name in ("file", "pointer", "message", "severity"):
        assert getattr(rmsc.Problem, name).__doc__
    assert not undocumented


def test_turntable_example(tmp_path):
    sys.path.insert(0, os.path.join(SOURCE, "samples", "python"))
    import turntable

    paths = turntable.turntable(PAWN, str(tmp_path), 3, (24, 16))
    assert len(paths) == 3
    frames = [open(p, "rb").read() for p in paths]
    assert all(f.startswith(b"\x89PNG\r\n\x1a\n") for f in frames)
    assert frames[0] != frames[1]  # the camera moved
