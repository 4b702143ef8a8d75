#!/usr/bin/env python3
"""End-to-end test of `rmsc view` under Xvfb: a replay script flies the camera, selects the
ball by clicking, moves it along X (G, X), undoes and redoes, rotates it a quarter turn about Z
(R, Z), scales it to twice its size (S), saves. Checks the saved scene
(parsed), the backup, that screenshots differ where the edit and the flight say they should, and
from the viewer's log that once the ball is selected the view is drawn with the map baked but
for the ball, that none of the edits to the ball compiles a shader, and that a duplicate of the
ball (a structural edit) is drawn in its own frame by the interpreter, built in the background,
and then by the baked map of the new structure.
Usage: test_viewer.py RMSC SOURCE_DIR. Exits 77 (skipped) only when no X server can be started."""
import json, math, os, re, shutil, struct, subprocess, sys, tempfile, zlib

SKIP = 77


def read_png(path):
    """Minimal decoder for the 8-bit RGB/RGBA non-interlaced PNGs rmsc writes."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and color in (2, 6), (depth, color)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 3 if color == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b = prev[x]
            c = prev[x - channels] if x >= channels else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return width, height, channels, rows


def differing_pixels(a, b, threshold=24):
    """Pixels whose largest channel difference exceeds `threshold`, as (x, y) lists."""
    wa, ha, ca, ra = a
    wb, hb, cb, rb = b
    assert (wa, ha) == (wb, hb), ((wa, ha), (wb, hb))
    out = []
    for y in range(ha):
        for x in range(wa):
            pa = ra[y][x * ca:x * ca + 3]
            pb = rb[y][x * cb:x * cb + 3]
            if max(abs(p - q) for p, q in zip(pa, pb)) > threshold:
                out.append((x, y))
    return out


def main():
    rmsc, source = sys.argv[1], sys.argv[2]
    xvfb_run = shutil.which("xvfb-run")
    if not xvfb_run or not shutil.which("Xvfb"):
        print("SKIP: xvfb-run / Xvfb not installed")
        return SKIP
    failures = []

    def check(name, ok, detail=""):
        print(("ok   " if ok else "FAIL ") + name + ("" if ok else f": {detail}"))
        if not ok:
            failures.append(name)

    with tempfile.TemporaryDirectory(prefix="rmsc-e2e-") as tmp:
        scene = os.path.join(tmp, "scene.json")
        shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
        original = open(scene).read()
        script = os.path.join(tmp, "script.txt")
        text = open(os.path.join(source, "tests/e2e/viewer_script.txt")).read()
        open(script, "w").write(text.replace("OUT/", tmp + "/"))
        command = [xvfb_run, "-a", "-s", "-screen 0 800x600x24", rmsc, "view", scene, "--script",
                   script, "--size", "640x360", "--embedded-shaders"]
        run = subprocess.run(command, capture_output=True, text=True, timeout=540)
        print(run.stderr[-3000:])
        if run.returncode != 0 and "cannot open a window" in run.stderr and "Xvfb" in run.stderr:
            print("SKIP: Xvfb could not start")
            return SKIP
        check("viewer exits 0", run.returncode == 0, run.returncode)

        # "rmsc view: frame N: ..." lines: which map is drawn, which shaders were built.
        log = [(int(m.group(1)), m.group(2)) for m in
               re.finditer(r"rmsc view: frame (\d+): (.*)", run.stderr)]
        selected = 11  # the script's wait-shaders frame
        duplicated, rebuilt = 48, 50  # the duplicate (a structural edit), then wait-shaders
        switches = [(f, what) for f, what in log if "drawing with the" in what]
        check("the baked map with the ball live is drawn from the selection on",
              any(f == selected and "baked map" in what for f, what in switches), log)
        check("and no other map after it until the structural edit",
              not any(selected < f < duplicated for f, _ in switches), log)
        check("no shader built on the drawing thread from the selection on",
              not any(f >= selected and what.startswith("built") for f, what in log), log)
        check("the duplicate is drawn in its own frame by the interpreter, built in the background",
              any(f == duplicated and "interpreter map (built in the background" in what
                  for f, what in switches), log)
        check("then by the baked map of the new structure",
              any(duplicated < f <= rebuilt and "baked map" in what for f, what in switches), log)

        saved = json.load(open(scene))
        ball = saved["sdf"]["children"][0]
        base = saved["sdf"]["children"][1]
        position = ball.get("position", [0, 0, 0])
        # 50 pixels at ~3.7 m with a 40 degree fov over 341 pixels: about 0.4 m along X.
        check("ball moved along +X by the dragged amount", 0.2 < position[0] < 0.6, position)
        check("Y and Z stayed (axis constraint)", abs(position[1]) < 1e-6 and abs(position[2]) < 1e-6, position)
        q = ball.get("quaternion", [0, 0, 0, 1])  # x, y, z, w
        turn = math.degrees(2 * math.atan2(q[2], q[3]))
        check("ball turned about Z only (R, Z)", abs(q[0]) < 1e-3 and abs(q[1]) < 1e-3, q)
        check("by about a quarter turn counter-clockwise", 70 < turn < 110, turn)
        scale = ball.get("scale", 1)
        check("ball scaled uniformly (S)", isinstance(scale, (int, float)), scale)
        check("to about twice its size", isinstance(scale, (int, float)) and 1.7 < scale < 2.3, scale)
        check("ball keeps its shape", ball.get("shape") == "sphere" and abs(ball.get("radius", 0) - 0.5) < 1e-6, ball)
        check("base untouched", base.get("position") == [0, -0.9, 0] or
              all(abs(a - b) < 1e-6 for a, b in zip(base.get("position", []), [0, -0.9, 0])), base)
        check("camera not saved into the scene (not asked)",
              all(abs(a - b) < 1e-6 for a, b in zip(saved["camera"]["position"], [0, 0.3, 4])), saved["camera"])
        backup = scene + ".bak"
        check("backup holds the previous file", os.path.exists(backup) and open(backup).read() == original)

        shots = {}
        for name in ("before", "after", "undone", "redone"):
            path = os.path.join(tmp, name + ".png")
            check(f"screenshot {name} written", os.path.exists(path))
            if os.path.exists(path):
                shots[name] = read_png(path)
        if len(shots) == 4:
            width = shots["after"][0]
            edit = differing_pixels(shots["after"], shots["undone"])
            check("the move changes the image", len(edit) > 200, len(edit))
            if edit:
                mean_x = sum(x for x, _ in edit) / len(edit)
                check("the change is around the ball, not everywhere", len(edit) < 0.5 * width * shots["after"][1], len(edit))
                check("the change reaches right of the centre (moved +X)", mean_x > width * 0.5, mean_x)
            check("redo gives the edited image again", len(differing_pixels(shots["after"], shots["redone"])) < 20)
            check("flying changed the view", len(differing_pixels(shots["before"], shots["undone"])) > 200)
    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
