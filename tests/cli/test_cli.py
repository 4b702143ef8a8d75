#!/usr/bin/env python3
"""End-to-end tests of the rmsc command: help, rendering every AOV, opening glTF files directly,
and bad input. Each bad input must give a clear message naming the file and the place in it,
and a non-zero exit, never a crash.

usage: test_cli.py RMSC_BINARY REPOSITORY_ROOT
"""
import json
import os
import re
import struct
import subprocess
import sys
import tempfile

RMSC, ROOT = sys.argv[1], sys.argv[2]
SAMPLES = os.path.join(ROOT, "samples")
failures = []
passed = 0


def run(args, env=None):
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run([RMSC] + args, capture_output=True, text=True, timeout=60, env=full_env)


def check(name, condition, detail=""):
    global passed
    if condition:
        passed += 1
    else:
        failures.append(f"{name}: {detail}")
        print(f"FAIL {name}: {detail}")


def expect(name, args, code, stderr_has=(), stdout_has=(), env=None):
    r = run(args, env)
    check(name, r.returncode == code,
          f"exit {r.returncode}, expected {code}; stderr: {r.stderr.strip()[:600]}")
    check(name + " (no crash)", r.returncode >= 0, f"killed by signal {-r.returncode}")
    for text in stderr_has:
        check(name, text in r.stderr, f"stderr lacks {text!r}: {r.stderr.strip()[:600]}")
    for text in stdout_has:
        check(name, text in r.stdout, f"stdout lacks {text!r}: {r.stdout.strip()[:600]}")
    return r


def png_header(path):
    with open(path, "rb") as f:
        data = f.read(33)
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    width, height, depth, colour = struct.unpack(">IIBB", data[16:26])
    return width, height, depth, colour


def write(directory, name, text):
    path = os.path.join(directory, name)
    with open(path, "w" if isinstance(text, str) else "wb") as f:
        f.write(text)
    return path


def scene(**sections):
    return json.dumps(dict({"version": 1}, **sections))


with tempfile.TemporaryDirectory() as tmp:
    # Help on every command.
    expect("help", ["--help"], 0, stdout_has=["render", "validate", "bench", "primitives"])
    for command in ["render", "validate", "bench", "primitives"]:
        expect(f"{command} --help", [command, "--help"], 0, stdout_has=["usage: rmsc " + command])
    expect("no command", [], 2, stderr_has=["usage"])
    # Every command `rmsc --help` lists answers --help and refuses an unknown option the same way.
    listing = run(["--help"]).stdout.split("commands:\n")[1].split("\n\n")[0]
    listed = [line.split()[0] for line in listing.splitlines()]
    check("help lists the commands", {"render", "validate", "bench", "view", "schema"} <= set(listed),
          str(listed))
    for command in listed:
        expect(f"{command} --help (listed)", [command, "--help"], 0,
               stdout_has=["usage: rmsc " + command, "-h, --help"])
        expect(f"{command} unknown option", [command, "--frobnicate"], 2,
               stderr_has=[f"rmsc {command}: unknown option --frobnicate (see rmsc {command} --help)"])
    expect("unknown command", ["paint"], 2, stderr_has=["unknown command 'paint'"])

    # The built-in demo, every AOV.
    out = os.path.join(tmp, "demo.png")
    expect("render demo", ["render", "-o", out, "--size", "96x54"], 0)
    check("demo png size", png_header(out)[:3] == (96, 54, 8), png_header(out))
    depth = os.path.join(tmp, "depth.png")
    expect("depth aov", ["render", "-o", depth, "--size", "64x36", "--aov", "depth"], 0)
    check("depth is 16-bit grey", png_header(depth) == (64, 36, 16, 0), png_header(depth))
    pfm = os.path.join(tmp, "depth.pfm")
    expect("depth pfm", ["render", "-o", pfm, "--size", "64x36", "--aov", "depth"], 0)
    with open(pfm, "rb") as f:
        check("pfm header", f.read(3) == b"Pf\n")
    for aov in ["normal", "id", "steps"]:
        path = os.path.join(tmp, aov + ".png")
        expect(f"{aov} aov", ["render", "-o", path, "--size", "64x36", "--aov", aov], 0)
        check(f"{aov} is 8-bit RGB", png_header(path)[2:] == (8, 2), png_header(path))
    for backend in ["egl", "osmesa"]:
        path = os.path.join(tmp, backend + ".png")
        expect(f"backend {backend}", ["render", "-o", path, "--size", "32x18", "--backend", backend], 0)

    # glTF files open as scenes.
    for model in ["sphere.gltf", "cube.glb", "cube_external.gltf"]:
        path = os.path.join(tmp, model + ".png")
        expect(f"open {model}", ["render", os.path.join(SAMPLES, "assets", model), "-o", path,
                                 "--size", "48x48"], 0)
    expect("validate samples", ["validate"] + [os.path.join(SAMPLES, "scenes", s) for s in
                                               sorted(os.listdir(os.path.join(SAMPLES, "scenes")))], 0)
    expect("primitives", ["primitives"], 0, stdout_has=["sphere", "round_box", "half_extents"])
    # The shapes made of a profile, and the profiles they take, are listed too.
    expect("primitives lists the profile shapes", ["primitives"], 0,
           stdout_has=["\nextrusion (profile shape): ", "\nrevolution (profile shape): ",
                       "    depth ", "    offset ", "\ncircle: ", "\nrounded_rectangle: ",
                       "\npolygon: ", "    half_size "])

    # Bad usage: exit 2.
    expect("bad size", ["render", "-o", out, "--size", "0x10"], 2, stderr_has=["--size"])
    expect("size over the limit", ["render", "-o", out, "--size", "16385x8"], 2,
           stderr_has=["--size: expected WxH with sides 1..16384", "got '16385x8'"])
    # 16384x16384 would take about 18 GB: refused by its pixel count, before any GL work.
    expect("size over the pixel limit", ["render", "-o", out, "--size", "16384x16384"], 2,
           stderr_has=["at most 33554432 pixels", "got '16384x16384'"])
    expect("bad backend", ["render", "-o", out, "--backend", "vulkan"], 2, stderr_has=["--backend"])
    expect("bad aov", ["render", "-o", out, "--aov", "albedo"], 2, stderr_has=["--aov"])
    expect("no output", ["render"], 2, stderr_has=["-o"])
    expect("bad extension", ["render", "-o", os.path.join(tmp, "x.jpg")], 2, stderr_has=[".png"])
    expect("unknown option", ["render", "--frobnicate"], 2, stderr_has=["--frobnicate"])

    # Bad input: exit 1, message names the file and the JSON pointer.
    missing = os.path.join(tmp, "missing.json")
    expect("missing scene", ["render", missing, "-o", out], 1, stderr_has=[missing, "not found"])
    expect("directory as scene", ["validate", tmp], 1, stderr_has=[tmp])
    bad = write(tmp, "malformed.json", '{"version": 1,\n  "camera": {"fov": 45,,}\n}')
    expect("malformed json", ["render", bad, "-o", out], 1, stderr_has=[bad, "line 2"])
    bad = write(tmp, "shape.json", scene(sdf={"shape": "blob"}))
    expect("unknown shape", ["validate", bad], 1, stderr_has=[bad, "/sdf", "blob"])
    bad = write(tmp, "typo_shape.json", scene(sdf={"shape": "capped_cilinder"}))
    expect("unknown shape: did you mean", ["validate", bad], 1,
           stderr_has=[bad + ": /sdf/shape: unknown shape \"capped_cilinder\"; did you mean \"capped_cylinder\"?"])
    bad = write(tmp, "typo_profile_shape.json", scene(sdf={"shape": "extrusoin"}))
    expect("unknown profile shape: did you mean", ["validate", bad], 1,
           stderr_has=["/sdf/shape: unknown shape \"extrusoin\"; did you mean \"extrusion\"?"])

    # --strict: warnings fail as errors do. A misspelt key is a warning (and is ignored, so the
    # neighbour check stays off): exit 0 without --strict, 1 with it; a clean scene passes both.
    misspelt = write(tmp, "neighbors.json", scene(sdf={"shape": "sphere", "modifiers": [
        {"type": "repeat", "period": [2, 0, 0], "neighbors": True}]}))
    expect("misspelt key only warns", ["validate", misspelt], 0,
           stderr_has=["/sdf/modifiers/0/neighbors: warning: unknown key \"neighbors\"; "
                       "did you mean \"neighbours\"?"], stdout_has=[misspelt + ": ok"])
    expect("--strict refuses a warning", ["validate", "--strict", misspelt], 1,
           stderr_has=["/sdf/modifiers/0/neighbors: warning: unknown key \"neighbors\""],
           stdout_has=[misspelt + ": 1 warning (errors with --strict)"])
    clean = write(tmp, "neighbours.json", scene(sdf={"shape": "sphere", "modifiers": [
        {"type": "repeat", "period": [2, 0, 0], "neighbours": True}]}))
    expect("--strict passes a clean scene", ["validate", "--strict", clean], 0,
           stdout_has=[clean + ": ok"])
    expect("--strict with an error", ["validate", "--strict", misspelt, bad], 1,
           stdout_has=[misspelt + ": 1 warning", bad + ": 1 error"])
    expect("--strict on the samples", ["validate", "--strict"] + [
        os.path.join(SAMPLES, "scenes", s) for s in sorted(os.listdir(os.path.join(SAMPLES, "scenes")))], 0)
    bad = write(tmp, "op.json", scene(sdf={"op": "melt", "children": [{"shape": "sphere"}]}))
    expect("unknown operation", ["validate", bad], 1, stderr_has=["/sdf/op", "melt"])
    bad = write(tmp, "type.json", scene(camera={"fov": "wide"}))
    expect("wrong type", ["validate", bad], 1, stderr_has=["/camera/fov"])
    bad = write(tmp, "negative.json", scene(sdf={"children": [
        {"shape": "sphere"}, {"shape": "box"}, {"shape": "torus"}, {"shape": "sphere", "radius": -1}]}))
    expect("negative size", ["render", bad, "-o", out], 1, stderr_has=["/sdf/children/3/radius"])
    bad = write(tmp, "nan.json", '{"version": 1, "sdf": {"shape": "sphere", "radius": 1e999}}')
    expect("non-finite number", ["validate", bad], 1, stderr_has=["/sdf/radius"])
    bad = write(tmp, "several.json", scene(camera={"fov": -3}, sdf={"shape": "box", "half_extents": [1, -1, 1]}))
    r = expect("every problem reported", ["validate", bad], 1, stderr_has=["/camera/fov", "/sdf/half_extents"])
    missing_mesh = write(tmp, "missing_mesh.json", scene(meshes=[{"file": "nowhere.gltf"}]))
    expect("missing glTF", ["render", missing_mesh, "-o", out], 1, stderr_has=["/meshes/0", "nowhere.gltf"])
    write(tmp, "broken.gltf", '{"asset": {"version": "2.0"}, "meshes": [{"primitives": [{"attributes": {"POSITION": 7}}]}]}')
    broken = write(tmp, "broken_mesh.json", scene(meshes=[{"file": "broken.gltf"}]))
    expect("broken glTF", ["validate", broken], 1, stderr_has=["/meshes/0", "broken.gltf"])

    # Shells: a broken proxy mesh and an unbounded shell are refused at their pointers; a scene
    # with shells renders both ways, and bench runs both modes and counts marched fragments.
    shell_broken = write(tmp, "shell_broken.json", scene(sdf={"shape": "sphere", "shell": {
        "proxy": "mesh", "mesh": "broken.gltf"}}))
    expect("broken shell proxy", ["render", shell_broken, "-o", out], 1,
           stderr_has=["/sdf/shell/mesh", "broken.gltf"])
    shell_missing = write(tmp, "shell_missing.json", scene(sdf={"shape": "sphere", "shell": {
        "proxy": "mesh", "mesh": "nowhere.glb"}}))
    expect("missing shell proxy", ["validate", shell_missing], 1,
           stderr_has=["/sdf/shell/mesh", "nowhere.glb"])
    shell_plane = write(tmp, "shell_plane.json", scene(sdf={"op": "union", "children": [
        {"shape": "sphere"}, {"shape": "plane", "shell": True}]}))
    expect("unbounded shell", ["render", shell_plane, "-o", out], 1,
           stderr_has=["/sdf/children/1/shell", "reaches infinity", "\"bound\""])
    shells = os.path.join(SAMPLES, "scenes", "shells.json")
    for mode in ["scene", "fullscreen"]:
        path = os.path.join(tmp, f"shells-{mode}.png")
        expect(f"render shells {mode}", ["render", shells, "-o", path, "--size", "64x36",
                                         "--shells", mode], 0)
    expect("bad shells mode", ["render", shells, "-o", out, "--shells", "both"], 2,
           stderr_has=["--shells"])
    r = expect("bench shells", ["bench", shells, "--size", "64x36", "--frames", "1", "--warmup", "0",
                                "--json"], 0)
    try:
        runs = json.loads(r.stdout)["strategies"]
        names = [run["strategy"] for run in runs]
        check("bench runs both shell modes", names == ["baked, shells", "baked, fullscreen"], str(names))
        marched = [run["marched_fragments"] for run in runs]
        check("bench counts shell fragments", marched[0]["shells"] > 0 and marched[1]["shells"] == 0,
              str(marched))
        check("bench: shells march fewer fullscreen fragments",
              marched[0]["fullscreen"] <= marched[1]["fullscreen"], str(marched))
    except (ValueError, KeyError, IndexError) as e:
        check("bench shells json", False, f"{e}: {r.stdout[:400]}")
    # The cells of a tree over a plane: most of the plane's cells hold only it, and are counted.
    tree = os.path.join(SAMPLES, "bench", "tree_256.json")
    r = expect("bench cells", ["bench", tree, "--size", "32x18", "--frames", "1", "--warmup", "0",
                               "--sdf-strategy", "cells", "--json"], 0)
    try:
        cells = json.loads(r.stdout)["strategies"][0]["cells"]
        check("bench counts the cells holding one plane",
              0 < cells["affine_cells"] < cells["leaf_cells"], str(cells))
    except (ValueError, KeyError, IndexError) as e:
        check("bench cells json", False, f"{e}: {r.stdout[:400]}")

    # Material textures: a missing file and a file that is not an image, for validate and render.
    write(tmp, "not_an_image.png", "plain text, not a PNG")
    for label, file, words in [("missing texture", "no_such_texture.png", "cannot read texture"),
                               ("texture not an image", "not_an_image.png", "not a usable image")]:
        bad = write(tmp, label.replace(" ", "_") + ".json", scene(
            materials={"m": {"base_color_texture": {"file": file, "scale": 2}}},
            sdf={"shape": "sphere", "material": "m"}))
        for command in (["validate", bad], ["render", bad, "-o", os.path.join(tmp, "t.png")]):
            expect(f"{label} ({command[0]})", command, 1,
                   stderr_has=[bad, "/materials/m/base_color_texture/file", file, words])
    with open(os.path.join(SAMPLES, "assets", "cube.glb"), "rb") as f:
        glb = f.read()
    truncated = write(tmp, "truncated.glb", glb[: len(glb) // 2])
    expect("truncated glb", ["render", truncated, "-o", out], 1, stderr_has=["truncated.glb"])
    check("no output after failures", not os.path.exists(out) or png_header(out)[:2] == (96, 54))

    # Animation, cameras and scenes of a glTF file: a quad slid 2 units along +x between t = 0
    # and t = 1 (LINEAR), seen through its own camera; --time, --frames and each refusal, which
    # names what the file has.
    quad = struct.pack("<12f", -0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0)
    quad += struct.pack("<6H", 0, 1, 2, 0, 2, 3) + b"\0\0\0\0"  # the keys start at 64
    keys = struct.pack("<2f", 0, 1) + struct.pack("<6f", 0, 0, 0, 2, 0, 0)
    data = quad + keys
    import base64
    animated = {
        "asset": {"version": "2.0"}, "scene": 0,
        "scenes": [{"name": "main", "nodes": [0, 1, 2]}],
        "nodes": [{"mesh": 0, "name": "quad"},
                  {"camera": 0, "translation": [1, 0, 4]},
                  {"camera": 1, "translation": [0, 0, 4]}],
        "cameras": [{"name": "front", "type": "perspective",
                     "perspective": {"yfov": 0.9, "znear": 0.1, "zfar": 100}},
                    {"name": "flat", "type": "orthographic",
                     "orthographic": {"xmag": 2, "ymag": 2, "znear": 0.1, "zfar": 100}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "animations": [{"name": "slide",
                        "samplers": [{"input": 2, "output": 3}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                        {"buffer": 0, "byteOffset": 64, "byteLength": 32}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 4,
                       "min": [-0.5, -0.5, 0], "max": [0.5, 0.5, 0]},
                      {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 6},
                      {"bufferView": 2, "componentType": 5126, "type": "SCALAR", "count": 2,
                       "min": [0], "max": [1]},
                      {"bufferView": 2, "byteOffset": 8, "componentType": 5126, "type": "VEC3",
                       "count": 2}]}
    anim = write(tmp, "anim.gltf", json.dumps(animated))
    expect("validate animated glTF", ["validate", anim], 0)
    frames = os.path.join(tmp, "anim_%04d.png")
    expect("render frames", ["render", anim, "--frames", "0:2", "--fps", "2", "-o", frames,
                             "--size", "32x32", "--camera", "front"], 0)
    images = []
    for f in range(3):
        name = os.path.join(tmp, f"anim_{f:04d}.png")
        check(f"frame {f} written", os.path.exists(name), name)
        images.append(open(name, "rb").read() if os.path.exists(name) else b"")
    check("frames differ as the quad moves", len(set(images)) == 3, "some frames are equal")
    single = os.path.join(tmp, "anim_t1.png")
    expect("render --time at frame 2's time", ["render", anim, "--time", "1", "--animation",
                                               "slide", "--camera", "0", "-o", single, "--size",
                                               "32x32"], 0)
    check("--time 1 equals frame 2 (t = 2 / 2 fps)",
          os.path.exists(single) and open(single, "rb").read() == images[2])
    expect("--animation unknown", ["render", anim, "--time", "1", "--animation", "walk", "-o",
                                   single], 1,
           stderr_has=['anim.gltf: there is no animation "walk"; the file has animations 0 "slide"'])
    expect("--camera unknown", ["render", anim, "--camera", "7", "-o", single], 1,
           stderr_has=['there is no camera "7"; the file has cameras 0 "front", 1 "flat" '
                       '(orthographic)'])
    # The orthographic camera, 4 high (ymag 2) on 32 rows: the unit quad 4 in front of it is
    # 8 x 8 pixels at view depth 4 wherever it is seen (parallel rays).
    depth = os.path.join(tmp, "flat.pfm")
    expect("--camera orthographic", ["render", anim, "--camera", "flat", "--aov", "depth",
                                     "-o", depth, "--size", "32x32"], 0)
    if os.path.exists(depth):
        raw = open(depth, "rb").read()
        header = raw.split(b"\n", 3)
        width, height = map(int, header[1].split())
        values = struct.unpack(f"<{width * height}f", header[3][:4 * width * height])
        hits = [v for v in values if abs(v) < 1e3]
        check("the orthographic camera sees the quad 8 x 8 pixels", len(hits) == 64, len(hits))
        check("all at view depth 4", all(abs(v - 4) < 1e-4 for v in hits), hits[:5])
    expect("--scene unknown", ["render", anim, "--scene", "2", "-o", single], 1,
           stderr_has=['/scenes: there is no scene 2; the file has scenes 0 "main"'])
    expect("--frames without a pattern", ["render", anim, "--frames", "0:1", "-o", single], 2,
           stderr_has=["expected -o to hold one %d or %04d"])
    expect("--frames backwards", ["render", anim, "--frames", "3:1", "-o", frames], 2,
           stderr_has=["--frames: expected A:B"])
    expect("--time and --frames", ["render", anim, "--time", "1", "--frames", "0:1", "-o",
                                   frames], 2, stderr_has=["give one or the other"])
    expect("--time negative", ["render", anim, "--time", "-1", "-o", single], 2,
           stderr_has=["--time: expected seconds"])
    expect("--fps without --frames", ["render", anim, "--fps", "3", "-o", single], 2,
           stderr_has=["--fps is for --frames"])
    still = os.path.join(SAMPLES, "assets", "cube.gltf")
    expect("--time on a file without animations", ["render", still, "--time", "1", "-o",
                                                   single], 1,
           stderr_has=["the file has no animations"])
    # In a scene file, each mesh names its animation and time; a bad name is refused at the
    # mesh, naming the animations the file has.
    with open(os.path.join(tmp, "anim_scene.json"), "w") as f:
        f.write(scene(meshes=[{"file": "anim.gltf", "animation": "slide", "time": 0.5},
                              {"file": "anim.gltf", "position": [0, 2, 0]}]))
    expect("scene mesh animation", ["render", os.path.join(tmp, "anim_scene.json"), "-o", single,
                                    "--size", "32x32", "--time", "0.25"], 0)
    expect("--animation on a scene", ["render", os.path.join(tmp, "anim_scene.json"),
                                      "--animation", "slide", "-o", single], 2,
           stderr_has=["--animation is for a .gltf or .glb file"])
    with open(os.path.join(tmp, "anim_bad.json"), "w") as f:
        f.write(scene(meshes=[{"file": "anim.gltf", "animation": "walk"}]))
    expect("scene mesh unknown animation", ["validate", os.path.join(tmp, "anim_bad.json")], 1,
           stderr_has=['/meshes/0/animation: "anim.gltf": there is no animation "walk"; the '
                       'file has animations 0 "slide"'])

    # A glTF opened directly with more KHR_lights_punctual lights than a scene may hold is
    # refused like a scene with too many lights, by validate and render alike (it was drawn
    # with the extra lights dropped, exit 0).
    with open(os.path.join(SAMPLES, "assets", "plane.gltf")) as f:
        lit = json.load(f)
    lit["extensionsUsed"] = ["KHR_lights_punctual"]
    lit["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "point", "intensity": 1} for _ in range(17)]}}
    lit["nodes"] += [{"name": f"light {i}", "translation": [0, 1, 0],
                      "extensions": {"KHR_lights_punctual": {"light": i}}} for i in range(17)]
    lit["scenes"][0]["nodes"] += list(range(1, 18))
    many_lights = write(tmp, "many_lights.gltf", json.dumps(lit))
    for command in (["validate", many_lights],
                    ["render", many_lights, "-o", os.path.join(tmp, "lights.png")]):
        expect(f"glTF with 17 lights ({command[0]})", command, 1,
               stderr_has=["many_lights.gltf", "16 (the limit)"])
    check("glTF with 17 lights: no image", not os.path.exists(os.path.join(tmp, "lights.png")))

    # glTF extensions: one used but not supported is one warning naming it (validate prints it,
    # --strict fails on it); one required but not supported refuses the file, naming it.
    with open(os.path.join(SAMPLES, "assets", "plane.gltf")) as f:
        extended = json.load(f)
    extended["extensionsUsed"] = ["KHR_materials_sheen"]
    extended["materials"][0]["extensions"] = {"KHR_materials_sheen": {"sheenColorFactor": [1, 0, 0]}}
    sheen = write(tmp, "sheen.gltf", json.dumps(extended))
    r = expect("glTF extension used but unsupported", ["validate", sheen], 0,
               stderr_has=["sheen.gltf: /extensionsUsed/0: warning: extension KHR_materials_sheen "
                           "is not supported"])
    check("glTF extension warned once", r.stderr.count("KHR_materials_sheen") == 1, r.stderr)
    expect("glTF extension warning with --strict", ["validate", "--strict", sheen], 1,
           stderr_has=["KHR_materials_sheen"])
    extended["extensionsRequired"] = ["KHR_materials_sheen"]
    required = write(tmp, "sheen_required.gltf", json.dumps(extended))
    expect("glTF extension required but unsupported", ["validate", required], 1,
           stderr_has=["sheen_required.gltf: /extensionsRequired/0: the file requires extension "
                       "KHR_materials_sheen, which rmsc does not support"])

    # glTF buffer and image URIs must stay inside the glTF file's folder once symbolic links are
    # resolved (a link inside the folder reached any file, and validate said "ok"). A link that
    # stays inside still works.
    import shutil
    outside = os.path.join(tmp, "outside")
    os.makedirs(outside)
    shutil.copy(os.path.join(SAMPLES, "assets", "cube_external.bin"), outside)
    escape = os.path.join(tmp, "escape")
    os.makedirs(escape)
    shutil.copy(os.path.join(SAMPLES, "assets", "cube_external.gltf"), escape)
    os.symlink(os.path.join(outside, "cube_external.bin"), os.path.join(escape, "cube_external.bin"))
    escaping = os.path.join(escape, "cube_external.gltf")
    for command in (["validate", escaping], ["render", escaping, "-o", os.path.join(tmp, "esc.png")]):
        expect(f"buffer link out of the glTF folder ({command[0]})", command, 1,
               stderr_has=[escaping, "/buffers/0/uri", "cube_external.bin", "outside " + os.path.realpath(escape),
                           "must stay inside that folder"])
    escape_scene = write(escape, "scene.json", scene(meshes=[{"file": "cube_external.gltf"}]))
    expect("buffer link out of the glTF folder (scene)", ["validate", escape_scene], 1,
           stderr_has=[escape_scene, "/meshes/0/file", "/buffers/0/uri", "outside " + os.path.realpath(escape)])
    images = os.path.join(tmp, "linked_images")
    os.makedirs(images)
    shutil.copy(os.path.join(SAMPLES, "assets", "textured_cube.gltf"), images)
    os.symlink(os.path.join(SAMPLES, "assets", "textures"), os.path.join(images, "textures"))
    expect("image folder linked out of the glTF folder", ["validate", os.path.join(
        images, "textured_cube.gltf")], 1, stderr_has=["/images/0/uri", "outside " + os.path.realpath(images)])
    inside = os.path.join(tmp, "inside_link")
    os.makedirs(os.path.join(inside, "data"))
    shutil.copy(os.path.join(SAMPLES, "assets", "cube_external.gltf"), inside)
    shutil.copy(os.path.join(SAMPLES, "assets", "cube_external.bin"), os.path.join(inside, "data"))
    os.symlink(os.path.join("data", "cube_external.bin"), os.path.join(inside, "cube_external.bin"))
    expect("buffer link inside the glTF folder", ["validate", os.path.join(
        inside, "cube_external.gltf")], 0, stdout_has=["cube_external.gltf: ok"])

    # --sandbox DIR: every file a scene reads (the scene, meshes, textures, sky, shell proxies,
    # glTF buffers and images) must resolve inside DIR; the error names the file, the key that
    # referenced it and the rule. Outputs are not confined.
    box = os.path.join(tmp, "box")
    os.makedirs(box)
    shutil.copy(os.path.join(SAMPLES, "assets", "cube.gltf"), box)
    shutil.copy(os.path.join(SAMPLES, "assets", "cube.gltf"), outside)
    shutil.copy(os.path.join(SAMPLES, "assets", "textures", "tiles_color.png"), box)
    shutil.copy(os.path.join(SAMPLES, "assets", "textures", "tiles_color.png"), outside)
    good = write(box, "good.json", scene(
        meshes=[{"file": "cube.gltf"}],
        materials={"m": {"base_color_texture": "tiles_color.png"}},
        environment={"sky": {"type": "image", "file": "tiles_color.png"}},
        sdf={"shape": "sphere", "material": "m", "position": [2, 0, 0],
             "shell": {"proxy": "mesh", "mesh": "cube.gltf"}}))
    expect("sandbox: a scene inside validates", ["validate", "--sandbox", box, good], 0,
           stdout_has=[good + ": ok"])
    expect("sandbox: a scene inside renders", ["render", good, "--sandbox", box, "-o",
                                               os.path.join(tmp, "sandboxed.png"), "--size", "32x18"], 0)
    out_tex = os.path.join(outside, "tiles_color.png")
    for label, sections, pointer, named in [
            ("mesh", dict(meshes=[{"file": "../outside/cube.gltf"}]), "/meshes/0/file",
             "../outside/cube.gltf"),
            ("texture", dict(materials={"m": {"base_color_texture": out_tex}},
                             sdf={"shape": "sphere", "material": "m"}),
             "/materials/m/base_color_texture", out_tex),
            ("sky", dict(environment={"sky": {"type": "image", "file": out_tex}}),
             "/environment/sky/file", out_tex),
            ("shell proxy", dict(sdf={"shape": "sphere", "shell": {
                "proxy": "mesh", "mesh": "../outside/cube.gltf"}}), "/sdf/shell/mesh",
             "../outside/cube.gltf")]:
        bad = write(box, label.replace(" ", "_") + ".json", scene(**sections))
        for command in (["validate", bad, "--sandbox", box],
                        ["render", bad, "--sandbox", box, "-o", os.path.join(tmp, "box.png")]):
            expect(f"sandbox: {label} outside ({command[0]})", command, 1,
                   stderr_has=[bad, pointer, named, "outside " + os.path.realpath(box),
                               "--sandbox folder"])
        expect(f"sandbox: {label} outside is fine without --sandbox", ["validate", bad], 0)
    os.symlink(os.path.join(outside, "cube.gltf"), os.path.join(box, "linked.gltf"))
    linked = write(box, "linked.json", scene(meshes=[{"file": "linked.gltf"}]))
    expect("sandbox: a link out of the sandbox", ["validate", "--sandbox", box, linked], 1,
           stderr_has=[linked, "/meshes/0/file", "linked.gltf", os.path.realpath(outside)])
    expect("sandbox: the scene itself outside", ["validate", "--sandbox", box, escape_scene], 1,
           stderr_has=[escape_scene, "cannot read scene file", "--sandbox folder"])
    expect("sandbox: bench", ["bench", linked, "--sandbox", box, "--size", "16x16", "--frames", "1",
                              "--warmup", "0"], 1, stderr_has=["/meshes/0/file", "--sandbox folder"])
    expect("sandbox: not a folder", ["validate", "--sandbox", good, good], 2,
           stderr_has=["rmsc validate: --sandbox", good])
    expect("sandbox: missing folder", ["render", "--sandbox", os.path.join(tmp, "nobox"), "-o",
                                       os.path.join(tmp, "x.png")], 2, stderr_has=["--sandbox", "nobox"])
    for command in ["render", "validate", "bench", "view"]:
        expect(f"{command} --help lists --sandbox", [command, "--help"], 0, stdout_has=["--sandbox DIR"])
    # The viewer's panel scale: refused outside 0.5..4 before any window opens.
    expect("view --help lists --ui-scale", ["view", "--help"], 0, stdout_has=["--ui-scale S"])
    for scale in ["9", "0.1", "big", ""]:
        expect(f"view --ui-scale {scale!r}", ["view", "--ui-scale", scale], 2,
               stderr_has=["rmsc view: --ui-scale: expected a scale from 0.5 to 4", f"'{scale}'"])

    # An output that is a symbolic link: the image goes to the file it points to, and the link
    # stays a link (it was replaced by a regular file, and the target kept the old image).
    links = os.path.join(tmp, "links")
    os.makedirs(links)
    real = write(links, "real.png", "previous image")
    os.symlink("real.png", os.path.join(links, "link.png"))
    expect("render -o link.png", ["render", "-o", os.path.join(links, "link.png"), "--size", "16x9"], 0)
    check("render -o link.png: the link stays a link", os.path.islink(os.path.join(links, "link.png")))
    with open(real, "rb") as f:
        check("render -o link.png: the target gets the image",
              f.read(8) == b"\x89PNG\r\n\x1a\n" and png_header(real)[:2] == (16, 9))
    check("render -o link.png: nothing else", sorted(os.listdir(links)) == ["link.png", "real.png"],
          str(sorted(os.listdir(links))))
    os.symlink(os.path.join("gone", "x.png"), os.path.join(links, "dangling.png"))
    expect("render -o dangling link into a missing folder", ["render", "-o", os.path.join(
        links, "dangling.png"), "--size", "16x9"], 3, stderr_has=["dangling.png", "does not exist"])

    # No GL 4.5 context: a clear message and exit 3.
    expect("no GL context", ["render", "-o", os.path.join(tmp, "nogl.png"), "--size", "8x8"], 3,
           stderr_has=["no OpenGL", "EGL", "OSMesa"], env={"MESA_GL_VERSION_OVERRIDE": "3.3"})
    unwritable = os.path.join(tmp, "no-such-folder", "out.png")
    expect("unwritable output", ["render", "-o", unwritable, "--size", "8x8"], 3,
           stderr_has=["cannot write"])

    # A full disk: writes past a 1 KiB file size limit fail (EFBIG, as ENOSPC does on a full
    # disk; SIGXFSZ ignored so the write returns the error). Every output fails with exit 3,
    # keeps the previous file and leaves no temporary file.
    import resource
    import signal

    def small_disk():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (1024, resource.RLIM_INFINITY))

    full = os.path.join(tmp, "full")
    os.makedirs(full)
    for aov, name in [("color", "c.png"), ("depth", "d.png"), ("depth", "d.pfm"),
                      ("normal", "n.png"), ("id", "i.png"), ("steps", "s.png")]:
        target = write(full, name, "previous image")
        r = subprocess.run([RMSC, "render", "-o", target, "--aov", aov, "--size", "320x180"],
                           capture_output=True, text=True, timeout=60, preexec_fn=small_disk)
        check(f"full disk: {aov} {name} exits 3", r.returncode == 3,
              f"exit {r.returncode}; stderr: {r.stderr.strip()[:400]}")
        check(f"full disk: {aov} {name} says so", "cannot write" in r.stderr and name in r.stderr,
              r.stderr.strip()[:400])
        with open(target, "rb") as f:
            check(f"full disk: {aov} {name} keeps the old file", f.read() == b"previous image")
    leftovers = sorted(set(os.listdir(full)) - {"c.png", "d.png", "d.pfm", "n.png", "i.png", "s.png"})
    check("full disk: no temporary files", not leftovers, str(leftovers))

    # rmsc export: a mesh file, each refusal with the file, the pointer and what was expected,
    # and nothing written when it fails or is interrupted.
    exports = os.path.join(tmp, "export")
    os.makedirs(exports)
    pawn = os.path.join(SAMPLES, "scenes", "pawn.json")
    glb = os.path.join(exports, "pawn.glb")
    r = expect("export pawn", ["export", pawn, "-o", glb, "--resolution", "32"], 0,
               stdout_has=["triangles", "from /sdf"])
    with open(glb, "rb") as f:
        data = f.read()
    check("export pawn: a glb", data[:4] == b"glTF" and struct.unpack("<I", data[8:12])[0] == len(data))
    expect("export pawn: rmsc opens it", ["validate", glb], 0)
    # The adaptive octree (default tolerance 0.1 voxel) against a vertex per cell (0).
    uniform = expect("export pawn without the octree", ["export", pawn, "-o", glb, "--resolution",
                     "32", "--tolerance", "0"], 0, stdout_has=["triangles"])
    counts = [int(re.search(r"(\d+) triangles", x.stdout).group(1)) for x in (r, uniform)
              if re.search(r"(\d+) triangles", x.stdout)]
    check("export pawn: the octree makes fewer triangles than a vertex per cell",
          len(counts) == 2 and counts[0] < counts[1], counts)
    expect("export bad tolerance", ["export", pawn, "-o", glb, "--tolerance", "-1"], 2,
           stderr_has=["--tolerance", "voxels >= 0"])
    # The compute-shader sampler: the same mesh as the CPU's (the pawn's counts within 1%), and
    # the summary says which sampled the grid.
    gpu = expect("export pawn sampled on the GPU", ["export", pawn, "-o", glb, "--resolution", "32",
                 "--sampler", "gpu"], 0, stdout_has=["triangles", "on the GPU"])
    check("export pawn: the CPU sampled by default", "on the CPU" in r.stdout, r.stdout.strip())
    gpu_count = re.search(r"(\d+) triangles", gpu.stdout)
    check("export pawn: the GPU's mesh is the CPU's", gpu_count and counts and
          abs(int(gpu_count.group(1)) - counts[0]) <= 0.01 * counts[0], (gpu.stdout, counts))
    expect("export bad sampler", ["export", pawn, "-o", glb, "--sampler", "tpu"], 2,
           stderr_has=["--sampler", "cpu or gpu"])
    expect("export a node to stl", ["export", os.path.join(SAMPLES, "scenes", "csg.json"), "--node",
           "/sdf/children/1", "-o", os.path.join(exports, "cut.stl"), "--voxel", "0.05"], 0,
           stdout_has=["from /sdf/children/1"])
    planes = write(exports, "plane.json", scene(sdf={"op": "union", "children": [
        {"shape": "sphere"}, {"shape": "plane"}]}))
    expect("export unbounded", ["export", planes, "-o", os.path.join(exports, "p.glb")], 1,
           stderr_has=["plane.json: /sdf/children/1:", "--bounds"])
    expect("export unbounded with bounds", ["export", planes, "-o", os.path.join(exports, "p.obj"),
           "--bounds", "-1,-1,-1,1,0.5,1", "--resolution", "16"], 0)
    check("export obj writes its mtl", os.path.exists(os.path.join(exports, "p.mtl")))
    expect("export missing node", ["export", planes, "--node", "/sdf/children/5", "-o",
           os.path.join(exports, "m.glb")], 1, stderr_has=["/sdf/children/5:", "no SDF node"])
    thin = write(exports, "thin.json", scene(sdf={"shape": "sphere", "modifiers": [
        {"type": "onion", "thickness": 0.0001}]}))
    expect("export empty", ["export", thin, "-o", os.path.join(exports, "t.glb"), "--resolution",
           "8"], 1, stderr_has=["thin.json: /sdf:", "no surface"])
    expect("export over the voxel limit", ["export", pawn, "-o", os.path.join(exports, "big.glb"),
           "--voxel", "0.0001"], 1, stderr_has=["pawn.json: /sdf:", "voxels (", "limit", "--voxel"])
    expect("export bad bounds", ["export", planes, "-o", os.path.join(exports, "b.glb"),
           "--bounds", "1,1,1"], 2, stderr_has=["--bounds", "six numbers"])
    expect("export bad format", ["export", pawn, "-o", os.path.join(exports, "x.ply")], 2,
           stderr_has=[".glb, .gltf, .obj or .stl"])
    expect("export unwritable", ["export", pawn, "-o", os.path.join(tmp, "no-such-folder", "x.glb")],
           3, stderr_has=["cannot write"])
    target = write(full, "e.glb", "previous mesh")
    r = subprocess.run([RMSC, "export", pawn, "-o", target, "--resolution", "48"],
                       capture_output=True, text=True, timeout=60, preexec_fn=small_disk)
    check("export full disk exits 3", r.returncode == 3, f"exit {r.returncode}: {r.stderr[:400]}")
    check("export full disk says so", "cannot write" in r.stderr and "e.glb" in r.stderr, r.stderr[:400])
    with open(target, "rb") as f:
        check("export full disk keeps the old file", f.read() == b"previous mesh")
    # Ctrl-C while sampling: exit 130, no file, no temporary file.
    import time
    p = subprocess.Popen([RMSC, "export", pawn, "-o", os.path.join(exports, "ctrl-c.glb"),
                          "--resolution", "1000", "--threads", "1"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    p.send_signal(signal.SIGINT)
    out, err = p.communicate(timeout=60)
    check("export interrupted exits 130", p.returncode == 130, f"exit {p.returncode}: {err[:400]}")
    check("export interrupted says so", "interrupted" in err, err[:400])
    check("export interrupted leaves nothing", not [n for n in os.listdir(exports) if "ctrl-c" in n],
          str(os.listdir(exports)))

# The scene JSON Schema: `rmsc schema` prints docs/scene.schema.json exactly, every sample scene
# is valid under it, and scenes the reader refuses are invalid under it too.
r = run(["schema"])
check("schema command", r.returncode == 0, r.stderr.strip()[:600])
with open(os.path.join(ROOT, "docs", "scene.schema.json"), encoding="utf-8") as f:
    shipped_schema = f.read()
check("schema is up to date", r.stdout == shipped_schema,
      "docs/scene.schema.json differs from `rmsc schema`; refresh it")
try:
    import jsonschema
except ImportError:
    print("SKIP schema validation of the samples: python3-jsonschema is not installed")
else:
    validator = jsonschema.Draft202012Validator(json.loads(shipped_schema))
    scenes_dir = os.path.join(SAMPLES, "scenes")
    for name in sorted(os.listdir(scenes_dir)):
        with open(os.path.join(scenes_dir, name), encoding="utf-8") as f:
            errors = [e.message for e in validator.iter_errors(json.load(f))]
        check(f"schema accepts samples/scenes/{name}", not errors, "; ".join(errors)[:600])
    for name, bad in [("version 2", {"version": 2}),
                      ("no version", {"camera": {}}),
                      ("negative radius", {"version": 1, "sdf": {"shape": "sphere", "radius": -1}}),
                      ("unknown shape", {"version": 1, "sdf": {"shape": "spere"}}),
                      ("misspelt key", {"version": 1, "camera": {"fovv": 45}}),
                      ("mesh without file", {"version": 1, "meshes": [{}]}),
                      ("bad colour", {"version": 1, "render": {"background": "#12345"}}),
                      ("too many steps", {"version": 1, "render": {"max_steps": 5000}})]:
        check(f"schema refuses {name}", not validator.is_valid(bad), json.dumps(bad))

# The limit table: docs/limits.md shows `rmsc limits --markdown` exactly, and `rmsc limits`
# lists the same rows with their values.
r = run(["limits", "--markdown"])
check("limits command", r.returncode == 0, r.stderr.strip()[:600])
with open(os.path.join(ROOT, "docs", "limits.md"), encoding="utf-8") as f:
    limits_doc = f.read()
shipped_table = limits_doc.split("<!-- limits:begin -->\n")[-1].split("<!-- limits:end -->")[0]
check("limits table is up to date", r.stdout == shipped_table,
      "docs/limits.md differs from `rmsc limits --markdown`; paste its output between the markers")
rows = [line.split(" | ") for line in r.stdout.splitlines()[2:]]
check("limits table has rows", len(rows) > 20, str(len(rows)))
text = run(["limits"]).stdout
for cells in rows:
    name, value = cells[0].lstrip("| "), cells[1]
    check(f"limits lists {name}", f"\n{name}: {value} (limits::" in "\n" + text, text[:300])

print(f"{passed} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
