#!/usr/bin/env python3
"""End-to-end test of `rmsc view` under Xvfb: a replay script flies the camera, selects the
ball by clicking, moves it along X (G, X), undoes and redoes, rotates it a quarter turn about Z
(R, Z), scales it to twice its size (S), saves. Checks the saved scene
(parsed), the backup, that screenshots differ where the edit and the flight say they should, and
from the viewer's log that once the ball is selected the view is drawn with the map baked but
for the ball, that none of the edits to the ball compiles a shader, and that a duplicate of the
ball (a structural edit) is drawn in its own frame by the interpreter, built in the background,
and then by the baked map of the new structure.
A second run on a fresh copy of the scene makes things with the Add menu: a point light (moved
with G), a spot and a directional light, then selects the point light by clicking its marker
and moves it again, adds a revolution and a chamfer union group, and saves; the test checks
the saved file and that the window shows the lights' markers.
A third run marks both children of the root group as cut with the inspector's cut checkbox (a
group whose every child is cut does not compile), presses Ctrl+S and checks the save is refused
(the log names /sdf, the problems panel shows it, the file is unchanged), then undoes one cut,
turns the fog on in the Render tab's Environment section and saves successfully.
A fifth run selects two objects (a click in the Scene panel, a Shift+click in the view), groups
them into a smooth union from the Edit menu, undoes and redoes that, copies the group, saves,
opens a second scene, pastes the group into it and moves the scene's pillar along X with Ctrl
held (snapping); the test checks both saved files and that the window outlines every selected
object.
A sixth run drags the transform gizmo's X arrow, Z ring and X box with Ctrl held (snapping to
a move step typed into the view's toolbar), undoes and redoes the drag, looks from the top
(numpad 7) orthographically (numpad 5), keeps that as bookmark 1, looks from the front and goes
back to it, adds a box (put on the ball under the view's centre), and saves, telling the save's
question to update the scene camera; the test checks the saved scene, the orthographic view's
sizes against the analytic ones and the bookmark's view against the first.
A seventh run opens the shortcut sheet (F1), adds two shapes with the searchable add menu
(Shift+A, typing, arrows, Enter), shoots the progress bar of the shader build, types an
out-of-range radius (clamped, and the field says so), opens the file browser, drops a glTF model
and then a scene on the window (a replay script's `drop`, the event GLFW's drop callback queues),
saves when asked and checks the saved scene and the recent files; then a model is dropped for
real (tests/e2e/xdnd_drop.py speaks XDND to the window, as a file manager does).
An eighth run selects the ball, exports it with File > Export selection (its dialog, a
resolution typed in, Export), and checks the .glb it writes (the ball's box, its material, the
notice's triangle count, no temporary file left) and, from window shots, the dialog and the
progress bar shown while the export runs on its thread. A run checks that `--ui-scale 2`
doubles the panels' sizes. A last run opens a .gltf written by the test, chooses its animation,
plays it for 30 frames and pauses it, chooses its second scene and saves; the test checks the
saved mesh's animation, time (1 s) and scene, and that the quad moved in the view.
Usage: test_viewer.py RMSC SOURCE_DIR. Exits 77 (skipped) only when no X server can be started."""
import base64, json, math, os, re, shutil, struct, subprocess, sys, tempfile, zlib

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


def marker_pixels(shot, centre, radius=14):
    """Pixels within `radius` of window pixel `centre` in a window shot in a marker's colours:
    near white (a light of white light) or the selection's orange (neither is the view's grey
    ground, its dark background or the red ball)."""
    width, height, channels, rows = shot
    count = 0
    for y in range(max(0, centre[1] - radius), min(height, centre[1] + radius + 1)):
        for x in range(max(0, centre[0] - radius), min(width, centre[0] + radius + 1)):
            r, g, b = rows[y][x * channels:x * channels + 3]
            if min(r, g, b) > 200 or (r > 220 and 110 < g < 190 and b < 100):
                count += 1
    return count


# The passing checks and the viewer's logs are printed only with RMSC_E2E_VERBOSE=1: a failing
# run then prints its failures and little else, which CI's shortened log keeps whole.
VERBOSE = os.environ.get("RMSC_E2E_VERBOSE") == "1"


class Checks:
    """The test's checks: check(name, ok, detail) records one (printing it when it fails, or
    every one when VERBOSE); summary() prints the count and returns the exit code."""

    def __init__(self):
        self.failures, self.count = [], 0

    def __call__(self, name, ok, detail=""):
        if not ok or VERBOSE:
            print(("ok   " if ok else "FAIL ") + name + ("" if ok else f": {detail}"))
        self.count += 1
        if not ok:
            self.failures.append(name)

    def summary(self):
        if self.failures:
            print(f"{len(self.failures)} of {self.count} checks failed")
            return 1
        print(f"all {self.count} checks passed (RMSC_E2E_VERBOSE=1 prints each, and the viewer's log)")
        return 0


def run_viewer(xvfb_run, rmsc, scene, script, size="640x360", tail=2000, extra=(),
               screen="800x600"):
    """Runs `rmsc view SCENE --script SCRIPT` under Xvfb and prints the end of its log (SCENE
    None: the built-in demo). Its configuration folder (the recent files) is `config` beside the
    script, never the user's."""
    command = [xvfb_run, "-a", "-s", f"-screen 0 {screen}x24", rmsc, "view"] + \
        ([scene] if scene else []) + ["--script", script, "--size", size, "--embedded-shaders"] + \
        list(extra)
    env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(os.path.dirname(os.path.abspath(script)),
                                                        "config"))
    run = subprocess.run(command, capture_output=True, text=True, timeout=540, env=env)
    if run.returncode != 0 or VERBOSE:
        print(run.stderr[-tail:])
    return run


def run_folder(source, tmp, name, script_name):
    """A run's folder in `tmp`: a copy of the viewer's scene (scene.json) and of the script
    tests/e2e/SCRIPT_NAME with OUT/ replaced by the folder. Returns (folder, scene, script)."""
    folder = os.path.join(tmp, name)
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e", script_name)).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    return folder, scene, script


def create_run(rmsc, source, tmp, xvfb_run, check):
    """The second run (tests/e2e/viewer_create_script.txt): lights, a revolution, a group."""
    folder, scene, script = run_folder(source, tmp, "create", "viewer_create_script.txt")
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("second run: viewer exits 0", run.returncode == 0, run.returncode)
    keep = os.environ.get("RMSC_E2E_KEEP")  # a folder to copy the run's files to, for a look
    if keep:
        shutil.copytree(folder, keep, dirs_exist_ok=True)

    saved = json.load(open(scene))
    lights = saved.get("lights", [])
    check("one light of each type added after the scene's own",
          [l.get("type") for l in lights] == ["directional", "point", "spot", "directional"],
          [l.get("type") for l in lights])
    if len(lights) == 4:
        point, spot, sun = lights[1], lights[2], lights[3]
        # Added at the view's focus, the ball's centre (0, 0, 0), then moved in the plane facing
        # the camera: 60 pixels right and 40 up, then (selected again by a click on its marker)
        # 40 more up. One pixel is 2 * 4 m * tan(20 degrees) / 341 pixels = 8.5 mm there.
        pixel = 2 * math.hypot(0.3, 4) * math.tan(math.radians(20)) / 341
        position = point.get("position", [0, 0, 0])
        check("the point light moved right with G", abs(position[0] - 60 * pixel) < 0.1, position)
        check("and up twice (the click on its marker selected it again)",
              abs(position[1] - 80 * pixel) < 0.1, position)
        check("and stayed in the plane facing the camera", abs(position[2]) < 0.1, position)
        check("the point light is named after its type", point.get("name", "").startswith("point light"),
              point)
        check("the spot light stands at the view's focus and shines straight down",
              all(abs(a) < 1e-3 for a in spot.get("position", [1, 1, 1])) and
              spot.get("direction") == [0, -1, 0], spot)
        check("the spot light has its cone", spot.get("outer_angle") == 45 and "inner_angle" in spot, spot)
        check("the directional light has a direction and no position",
              "direction" in sun and "position" not in sun, sun)
    children = saved["sdf"]["children"]
    shapes = [c.get("shape") for c in children]
    revolution = next((c for c in children if c.get("shape") == "revolution"), None)
    check("a revolution was added", revolution is not None, shapes)
    if revolution:
        check("of the catalogue's circle, set 1 out from the axis",
              revolution.get("profile") == {"type": "circle", "radius": 0.5} and
              revolution.get("offset") == 1, revolution)
    group = next((c for c in children if c.get("op") == "chamfer_union"), None)
    check("a chamfer union group was added, with its smoothness", group is not None and
          group.get("smoothness", 0) > 0, children)

    shots = {}
    for name in ("lights", "moved-again", "made"):
        path = os.path.join(folder, name + ".png")
        check(f"second run: window shot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if "lights" in shots and "moved-again" in shots:
        # The point light's marker where it was put, then where it went.
        check("the moved point light's marker is drawn", marker_pixels(shots["lights"], (357, 150)) > 10,
              marker_pixels(shots["lights"], (357, 150)))
        check("and drawn where it went next", marker_pixels(shots["moved-again"], (357, 110)) > 10,
              marker_pixels(shots["moved-again"], (357, 110)))
        check("and no longer where it was", marker_pixels(shots["moved-again"], (357, 150), 6) == 0,
              marker_pixels(shots["moved-again"], (357, 150), 6))


def refuse_run(rmsc, source, tmp, xvfb_run, check):
    """The third run (tests/e2e/viewer_refuse_script.txt): a save the viewer refuses."""
    folder = os.path.join(tmp, "refuse")
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    original = open(scene).read()
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e/viewer_refuse_script.txt")).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("third run: viewer exits 0", run.returncode == 0, run.returncode)
    refusal = re.search(r"rmsc view: save failed: the scene is not valid, so nothing was written"
                        r".*\n/sdf: every child of the group is marked \"cut\"", run.stderr)
    check("the save with every child cut was refused, naming /sdf", refusal is not None, run.stderr[-2000:])
    saved = run.stderr.find("rmsc view: saved ")
    check("then the save after the undo succeeded", refusal is not None and saved > refusal.start(),
          run.stderr[-2000:])
    # The only save that wrote made the backup: the file as it was before the run, so the refused
    # save wrote nothing.
    backup = scene + ".bak"
    check("the refused save left the file as it was (the later save's backup is the original)",
          os.path.exists(backup) and open(backup).read() == original)
    children = json.load(open(scene))["sdf"]["children"]
    check("the file holds the scene after the undo: the ball cut, the base not",
          [c.get("cut", False) for c in children] == [True, False], children)
    fog = json.load(open(scene)).get("environment", {}).get("fog", {})
    check("the Render tab's fog checkbox turned the fog on in the saved file",
          abs(fog.get("density", 0) - 0.05) < 1e-6, fog)
    path = os.path.join(folder, "refused.png")
    check("third run: window shot refused written", os.path.exists(path))
    if os.path.exists(path):
        width, height, channels, rows = read_png(path)
        # The problems panel over the lower part of the view, in red text.
        red = sum(1 for y in range(180, 345) for x in range(160, 430)
                  if rows[y][x * channels] > 180 and rows[y][x * channels + 1] < 120 and
                  rows[y][x * channels + 2] < 120)
        check("the refusal is shown in the problems panel", red > 300, red)


def large_scene_run(rmsc, source, tmp, xvfb_run, check):
    """The fourth run (tests/e2e/viewer_large_script.txt): a shape of the 10,000-shape grid moved,
    drawn with the cells map, whose cells are pruned again from the kept state; then the Scene
    panel scrolled and the row under the mouse moved too (the panel draws only the rows it shows:
    the rows above take their room without being drawn); last, a shape clicked in the view, whose
    row the panel brings into view, and the row below it, clicked in the panel."""
    folder = os.path.join(tmp, "large")
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "samples/bench/grid_10000.json"), scene)
    original = json.load(open(scene))
    script = os.path.join(folder, "script.txt")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_large_script.txt"), script)
    run = run_viewer(xvfb_run, rmsc, scene, script, "480x300")
    check("fourth run: viewer exits 0", run.returncode == 0, run.returncode)
    check("the 10,000-shape grid is drawn with the cells map",
          re.search(r"frame \d+: drawing with the cells map", run.stderr) is not None, run.stderr[-2000:])
    full = re.search(r"frame \d+: pruned (\d+) cells in \d+ ms \(all\)", run.stderr)
    again = re.findall(r"frame (\d+): pruned (\d+) cells in \d+ ms \(again, after an edit of numbers\)",
                       run.stderr)
    check("its cells are pruned once when it opens", full is not None, run.stderr[-2000:])
    check("the move prunes them again from the kept state, nothing anew",
          bool(again) and "(all)" not in run.stderr[full.end():] if full else False, run.stderr[-2000:])
    if full and again:
        most = max(int(cells) for _, cells in again)
        check("each edit prunes a small part of the cells again", most * 5 < int(full.group(1)),
              (most, full.group(1)))
    saved = json.load(open(scene))
    before, after = original["sdf"]["children"], saved["sdf"]["children"]
    check("the grid still has its 10,000 shapes", len(after) == len(before) == 10000, len(after))
    # (The writer may spell a rotation another way: positions and shapes are compared.)
    changed = [i for i, (a, b) in enumerate(zip(before, after))
               if a["shape"] != b["shape"] or
               any(abs(x - y) > 1e-6 for x, y in zip(a["position"], b["position"]))]
    # Child 39: the panel's rows are 17 pixels apart from y 113, scrolled by 650 pixels. Then the
    # shape clicked in the view (child k, wherever it is in the list) and, below its row in the
    # panel, child k + 1. Had the panel stayed where the wheel left it, the row clicked there
    # would be child 42 (a build without the panel's reveal moved 42 and k), not next to k.
    check("the first shape, the one clicked in the scrolled panel, the one clicked in the view and "
          "the one below it in the panel moved",
          len(changed) == 4 and changed[:2] == [0, 39] and changed[3] == changed[2] + 1 and
          changed[2] > 60, changed[:10])
    for i in changed:
        p, q = before[i]["position"], after[i]["position"]
        check(f"shape {i} moved along +X only", q[0] > p[0] + 0.01 and abs(q[1] - p[1]) < 1e-6 and
              abs(q[2] - p[2]) < 1e-6, (p, q))


def burst_run(rmsc, source, tmp, xvfb_run, check):
    """The burst run (tests/e2e/viewer_burst_script.txt): Ctrl+D in 20 frames in a row, Ctrl+Z in
    the 5 after; every one arrives."""
    folder = os.path.join(tmp, "burst")
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    script = os.path.join(folder, "script.txt")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_burst_script.txt"), script)
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("burst run: viewer exits 0", run.returncode == 0, run.returncode)
    children = json.load(open(scene))["sdf"]["children"]
    balls = [c for c in children if c.get("shape") == "sphere"]
    check("20 Ctrl+D in 20 frames and 5 Ctrl+Z: 15 copies of the ball saved", len(balls) == 16,
          len(balls))


def timing_runs(rmsc, source, tmp, xvfb_run, check):
    """The timing runs (tests/e2e/viewer_timing_script.txt) at 1280x720 on copies of the demo
    and of the largest bench scene: every change is refined to the full image, and the scene is
    saved at the end; the UI frame times and the time from the last input to the refined image
    are printed (figures, not asserted: see docs/performance.md)."""
    script = os.path.join(tmp, "timing.txt")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_timing_script.txt"), script)
    for name, sample in (("demo", "samples/scenes/demo.json"),
                         ("grid_10000", "samples/bench/grid_10000.json")):
        scene = os.path.join(tmp, name + ".json")
        shutil.copy(os.path.join(source, sample), scene)
        run = run_viewer(xvfb_run, rmsc, scene, script, "1280x720", extra=["--stats"],
                         screen="1400x900")
        check(f"timing run ({name}): viewer exits 0", run.returncode == 0, run.returncode)
        # Saved on the worker, and the quit after it found nothing unsaved.
        check(f"timing run ({name}): the scene is saved", f"saved {scene}" in run.stderr and
              os.path.exists(scene + ".bak") and "unsaved" not in run.stderr, run.stderr[-1500:])
        refined = re.findall(r"frame (\d+): refined \d+x(\d+) in (\d+) frames, (\d+) ms after the "
                             r"last input; UI frames since the change: longest ([\d.]+) ms, "
                             r"mean ([\d.]+) ms", run.stderr)
        # The window's first frame does not wait for the scene's compile (the view is drawn
        # from a later frame on, or from the first when the compile was done before it looked).
        wait = re.search(r"first wait for a compile: frame (\d+)|no wait for a compile",
                         run.stderr)
        check(f"timing run ({name}): the first frame does not wait for the scene",
              wait is not None and wait.group(1) != "0", run.stderr[-800:])
        # The start, the flight and the look: each ends in a refined full-resolution image.
        check(f"timing run ({name}): the view is refined after each change", len(refined) >= 3,
              run.stderr[-1500:])
        summary = re.search(r"opening frame ([\d.]+) ms \(drawn before the window was shown\); "
                            r"UI frames: (\d+), longest ([\d.]+) ms, mean ([\d.]+) ms, (\d+) over.*",
                            run.stderr)
        check(f"timing run ({name}): the frame summary is logged", summary is not None)
        for frame, height, frames, latency, longest, mean in refined:
            print(f"TIMING {name}: frame {frame}: refined in {frames} frames, {latency} ms after "
                  f"the last input, UI frame longest {longest} ms, mean {mean} ms")
        if summary:
            print(f"TIMING {name}: " + summary.group(0))


def responsiveness_main(rmsc, source, xvfb_run, run):
    """`test_viewer.py RMSC SOURCE_DIR --burst` (ctest e2e.viewer_burst) or `--timing` (ctest
    e2e.viewer_timing): the burst or the timing runs, apart from the editing runs so each has its
    own time limit (and the sanitizer pass can leave out the timing runs, whose figures mean
    nothing there)."""
    check = Checks()

    with tempfile.TemporaryDirectory(prefix="rmsc-e2e-") as tmp:
        run(rmsc, source, tmp, xvfb_run, check)
    return check.summary()


# Window-shot rectangles (x0, y0, x1, y1) of the 640x360 window around what the view shows of
# tests/e2e/viewer_scene.json (one pixel is about 8.5 mm at the ball): the ball, centred at
# (297, 190), 59 pixels in radius; the base below it; and the second scene's pillar.
BALL_BOX = (227, 120, 367, 255)
BASE_BOX = (160, 262, 436, 330)
PILLAR_BOX = (390, 55, 438, 137)


def orange_pixels(shot, box):
    """Pixels of the selection outline's orange in the window-shot rectangle box (x0, y0, x1, y1)."""
    width, height, channels, rows = shot
    return sum(1 for y in range(box[1], box[3]) for x in range(box[0], box[2])
               if rows[y][x * channels] > 220 and 110 < rows[y][x * channels + 1] < 170 and
               rows[y][x * channels + 2] < 60)


def select_run(rmsc, source, tmp, xvfb_run, check):
    """The fifth run (tests/e2e/viewer_select_script.txt): multi-select, group, copy and paste
    into a second scene."""
    folder = os.path.join(tmp, "select")
    os.makedirs(folder)
    scene = os.path.join(folder, "first.json")
    second = os.path.join(folder, "second.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    shutil.copy(os.path.join(source, "tests/e2e/viewer_second_scene.json"), second)
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e/viewer_select_script.txt")).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("fifth run: viewer exits 0", run.returncode == 0, run.returncode)
    keep = os.environ.get("RMSC_E2E_KEEP")
    if keep:
        shutil.copytree(folder, keep, dirs_exist_ok=True)

    first = json.load(open(scene))
    children = first["sdf"]["children"]
    check("the first scene holds one group: the ball and the base grouped (redone after the undo)",
          len(children) == 1 and children[0].get("op") == "smooth_union", children)
    if len(children) == 1:
        group = children[0]
        check("with both, in tree order", [c.get("name") for c in group.get("children", [])] ==
              ["ball", "base"], group)
        check("and the smoothness a smooth union needs", group.get("smoothness", 0) > 0, group)
    pasted = json.load(open(second))
    children = pasted["sdf"]["children"]
    check("the second scene keeps its pillar and gets the pasted group after it",
          [c.get("name") for c in children] == ["pillar", "group"], children)
    if len(children) == 2:
        group = children[1]
        names = [c.get("name") for c in group.get("children", [])]
        check("the pasted group holds the ball and the base", names == ["ball", "base"], group)
        check("of the operation it was grouped into", group.get("op") == "smooth_union", group)
        if names == ["ball", "base"]:
            base = group["children"][1]
            check("the base is where it was in the first scene",
                  all(abs(a - b) < 1e-5 for a, b in zip(base.get("position", []), [0, -0.9, 0])),
                  base)
            check("with its material", base.get("material") == "grey" and
                  group["children"][0].get("material") == "red", group)
    pillar = children[0] if children else {}
    moved = pillar.get("position", [1, 0.8, 0])[0] - 1.0
    steps = moved / 0.1
    check("the pillar moved along X with Ctrl held, by whole steps of 0.1 m",
          moved > 0.05 and abs(steps - round(steps)) < 1e-3, pillar)
    check("and only along X", pillar.get("position", [0, 0, 0])[1:] == [0.8, 0], pillar)
    materials = pasted.get("materials", {})
    check("the second scene's own grey is kept, the first scene's red is added",
          sorted(materials) == ["grey", "red"] and
          materials["grey"].get("base_color") == [0.3, 0.6, 0.3], materials)

    shots = {}
    for name in ("both", "pasted"):
        path = os.path.join(folder, name + ".png")
        check(f"fifth run: window shot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if "both" in shots:
        ball, base = orange_pixels(shots["both"], BALL_BOX), orange_pixels(shots["both"], BASE_BOX)
        check("both selected objects are outlined: the ball", ball > 40, ball)
        check("and the base", base > 40, base)
    if "pasted" in shots:
        ball = orange_pixels(shots["pasted"], BALL_BOX)
        pillar = orange_pixels(shots["pasted"], PILLAR_BOX)
        check("the pasted objects are selected (outlined) in the second scene", ball > 40, ball)
        check("and the second scene's pillar is not", pillar < 5, pillar)


def ball_disc(shot):
    """The ball's red pixels in a view screenshot (red with green equal to blue: not the orange
    outline, the grid's red axis or the grey base): their count, the radius of a disc of that
    area, and their centroid's offset from the image's centre (x right, y down)."""
    width, height, channels, rows = shot
    count, sum_x, sum_y = 0, 0.0, 0.0
    for y in range(height):
        for x in range(width):
            r, g, b = rows[y][x * channels:x * channels + 3]
            if r - g > 50 and abs(g - b) <= 2:
                count += 1
                sum_x += x + 0.5
                sum_y += y + 0.5
    if not count:
        return 0, 0.0, (0.0, 0.0)
    return count, math.sqrt(count / math.pi), (sum_x / count - width / 2, sum_y / count - height / 2)


def gizmo_run(rmsc, source, tmp, xvfb_run, check):
    """The sixth run (tests/e2e/viewer_gizmo_script.txt): the transform gizmo with snapping, the
    numpad views, an orthographic view, a bookmark, a shape put in front of the camera and the
    save's question about the scene camera."""
    folder, scene, script = run_folder(source, tmp, "gizmo", "viewer_gizmo_script.txt")
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("sixth run: viewer exits 0", run.returncode == 0, run.returncode)
    keep = os.environ.get("RMSC_E2E_KEEP")
    if keep:
        shutil.copytree(folder, keep, dirs_exist_ok=True)

    saved = json.load(open(scene))
    children = saved["sdf"]["children"]
    ball = next((c for c in children if c.get("name") == "ball"), {})
    # The X arrow dragged 35 pixels (0.30 m) with Ctrl: in steps of 0.25 m, set in the toolbar.
    position = ball.get("position", [0, 0, 0])
    check("the gizmo's X arrow moved the ball 0.25 m: one step of the toolbar's 0.25",
          all(abs(a - b) < 1e-6 for a, b in zip(position, [0.25, 0, 0])), position)
    # The Z ring dragged from 45 to 135 degrees with Ctrl: a quarter turn, in 15 degree steps.
    q = ball.get("quaternion", [0, 0, 0, 1])
    half = math.sqrt(0.5)
    check("the Z ring turned it a quarter turn about Z, snapped",
          all(abs(a - b) < 1e-6 for a, b in zip(q, [0, 0, half, half])), q)
    # Its own X box dragged from 90 to 126 pixels out with Ctrl: 1.4.
    scale = ball.get("scale", 1)
    check("the X box scaled it 1.4 along its own X only, in tenths",
          isinstance(scale, list) and all(abs(a - b) < 1e-6 for a, b in zip(scale, [1.4, 1, 1])),
          scale)

    shots = {}
    for name in ("moved", "undone", "top", "front", "front-after-q", "top-again"):
        path = os.path.join(folder, name + ".png")
        check(f"sixth run: screenshot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    # One pixel is 8.56 mm at the ball (4.01 m away, 40 degrees over 341 rows): 0.25 m is 29 px.
    if "moved" in shots and "undone" in shots:
        moved, undone = ball_disc(shots["moved"])[2][0], ball_disc(shots["undone"])[2][0]
        check("the drag moved the ball's image right", 27 < moved < 32, moved)
        check("and one undo put all of it back (the drag is one undo step)", abs(undone) < 1, undone)
    # The top view, orthographic, 2.92 m high over 341 rows (the perspective view's height at
    # the 4.01 m it looked at): 116.8 px a metre at every depth. The ball is a circle of
    # 0.5 m (58.4 px, and the march's hit threshold, about 0.4 px) at x = 0.25 m; the base's top
    # face is 1.2 m deep (140 px; a perspective view would show it 119 px).
    if "top" in shots:
        count, radius, (dx, dy) = ball_disc(shots["top"])
        check("the orthographic top view shows the ball, 0.5 m in radius, as 58.8 px", abs(radius - 58.8) < 0.5,
              (count, radius))
        check("0.25 m right of the centre, 29.2 px", abs(dx - 29.2) < 0.5 and abs(dy) < 0.5, (dx, dy))
        width, height, channels, rows = shots["top"]
        base = sum(1 for y in range(height) if min(rows[y][40 * channels:40 * channels + 3]) > 170 and
                   max(rows[y][40 * channels:40 * channels + 3]) - min(rows[y][40 * channels:40 * channels + 3]) < 20)
        check("and the base 1.2 m deep as 140 px", abs(base - 140) <= 2, base)
    if "top" in shots and "top-again" in shots:
        check("bookmark 1 (Ctrl+1, then 1 from the front view) gives the top view back",
              len(differing_pixels(shots["top"], shots["top-again"])) < 20)
    if "front" in shots and "top" in shots:
        check("numpad 1 looks from the front", len(differing_pixels(shots["front"], shots["top"])) > 5000)
    if "front" in shots and "front-after-q" in shots:
        check("Q does not roll the view while roll is off",
              len(differing_pixels(shots["front"], shots["front-after-q"])) < 20)
    # The box added from the top view rests where the view's centre ray (straight down x = z = 0)
    # meets the ball: the ellipsoid of radii 0.5, 0.7 (its own X, turned to Y, times 1.4), 0.5
    # about (0.25, 0, 0), at y = 0.7 sqrt(1 - (0.25 / 0.5)^2); its origin moved out along the
    # ellipsoid's normal there by as far as its box (half extents 0.5) reaches against it.
    added = next((c for c in children if c.get("name") not in ("ball", "base")), None)
    check("a box was added", added is not None and added.get("shape") == "box", children)
    if added:
        top = 0.7 * math.sqrt(1 - 0.25 ** 2 / 0.5 ** 2)
        gradient = [(0 - 0.25) / 0.5 ** 2, top / 0.7 ** 2, 0.0]
        length = math.sqrt(sum(g * g for g in gradient))
        normal = [g / length for g in gradient]
        reach = 0.5 * sum(abs(n) for n in normal)
        expected = [p + n * reach for p, n in zip([0, top, 0], normal)]
        where = added.get("position", [0, 0, 0])
        check("resting on the ball's surface under the view's centre, not at the origin",
              all(abs(a - b) < 0.02 for a, b in zip(where, expected)), (where, expected))
    camera = saved.get("camera", {})
    check("the save asked about the scene camera", "the view is not the scene camera's" in run.stderr,
          run.stderr[-1500:])
    check("and the answer (Update) made the top orthographic view the scene's camera",
          camera.get("projection") == "orthographic" and
          abs(camera.get("ortho_height", 0) - 2.92) < 0.01 and
          all(abs(a - b) < 1e-3 for a, b in zip(camera.get("position", []), [0, 4.0112, 0])) and
          all(abs(a - b) < 1e-3 for a, b in zip(camera.get("up", []), [0, 0, -1])), camera)


def colour_pixels(shot, box, colour, tolerance=12):
    """Pixels of `colour` (r, g, b), each channel within `tolerance`, in the window-shot rectangle
    box (x0, y0, x1, y1)."""
    width, height, channels, rows = shot
    return sum(1 for y in range(box[1], min(box[3], height)) for x in range(box[0], min(box[2], width))
               if all(abs(rows[y][x * channels + c] - colour[c]) <= tolerance for c in range(3)))


# Colours of Dear ImGui's dark style and the viewer's own, as window shots show them: the shortcut
# sheet's section titles, a clamped field's notice, a progress bar's fill, the menu bar.
SECTION_TITLE = (255, 191, 89)
CLAMP_NOTICE = (255, 184, 64)
PROGRESS_FILL = (230, 179, 0)
MENU_BAR = (36, 36, 36)


def aids_run(rmsc, source, tmp, xvfb_run, check):
    """The seventh run (tests/e2e/viewer_aids_script.txt): the shortcut sheet, the searchable add
    menu, the shader build's progress bar, a typed value clamped, the file browser, a glTF model
    and a scene dropped on the window, the recent files."""
    folder = os.path.join(tmp, "aids")
    os.makedirs(folder)
    scene = os.path.join(folder, "first.json")
    second = os.path.join(folder, "second.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    shutil.copy(os.path.join(source, "tests/e2e/viewer_second_scene.json"), second)
    shutil.copy(os.path.join(source, "samples/assets/cube.glb"), os.path.join(folder, "cube.glb"))
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e/viewer_aids_script.txt")).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("seventh run: viewer exits 0", run.returncode == 0, run.returncode)
    keep = os.environ.get("RMSC_E2E_KEEP")
    if keep:
        shutil.copytree(folder, keep, dirs_exist_ok=True)

    saved = json.load(open(scene))
    children = saved["sdf"]["children"]
    names = [c.get("name") for c in children]
    check("Shift+A, 'cone', Down, Down, Enter added the third match, a capped cone; "
          "'torus', Enter a torus", names == ["ball", "base", "capped_cone", "torus"] and
          children[2].get("shape") == "capped_cone" and children[3].get("shape") == "torus", names)
    check("the radius typed as -2 was clamped to 0", children[0].get("radius") == 0, children[0])
    meshes = saved.get("meshes", [])
    check("the dropped cube.glb is a mesh of the saved scene", len(meshes) == 1 and
          meshes[0].get("file", "").endswith("cube.glb"), meshes)
    torus = next((c for c in children if c.get("shape") == "torus"), None)
    if len(meshes) == 1 and torus:
        # Where a new shape goes: the view looked from (0, 0.3, 4) at the origin, then flew right
        # (D held for 3 frames) before the drop, so its centre ray runs at y = 0.3 z / 4 right of
        # the origin; the ball is clamped to radius 0 by then, and the ray meets the torus added
        # in front of it (measured: (0.2, 0.109, 1.455), on the torus's surface).
        position = meshes[0].get("position", [0, 0, 0])
        centre = torus.get("position", [0, 0, 0])
        rel = [a - b for a, b in zip(position, centre)]
        ring = math.hypot(rel[0], rel[2]) - torus.get("major_radius", 0)
        surface = math.hypot(ring, rel[1]) - torus.get("minor_radius", 0)
        check("placed where a new shape goes: on the view's centre ray, right of the origin",
              0.05 < position[0] < 1.0 and abs(position[1] - 0.3 * position[2] / 4) < 1e-3,
              position)
        check("on the surface the ray meets (the torus), not at the view's focus",
              abs(surface) < 0.01, (position, surface))
    check("the dropped scene was opened after the first was saved",
          re.search(r"rmsc view: saved .*first\.json", run.stderr) is not None and
          re.search(r"rmsc view: opened .*second\.json", run.stderr) is not None,
          run.stderr[-1500:])
    recent_file = os.path.join(folder, "config", "rmsc", "recent.json")
    recent = json.load(open(recent_file)).get("files") if os.path.exists(recent_file) else None
    check("the recent files list the second scene, then the first",
          recent == [os.path.realpath(second), os.path.realpath(scene)] or
          recent == [second, scene], recent)

    shots = {}
    for name in ("sheet", "add-menu", "building", "clamped", "browser", "dropped", "ask", "second"):
        path = os.path.join(folder, name + ".png")
        check(f"seventh run: window shot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if "sheet" in shots:
        titles = colour_pixels(shots["sheet"], (0, 0, 640, 360), SECTION_TITLE)
        check("F1 shows the shortcut sheet (its section titles)", titles > 100, titles)
    if "clamped" in shots:
        notice = colour_pixels(shots["clamped"], (440, 285, 640, 315), CLAMP_NOTICE)
        check("the radius field says it clamped the value", notice > 40, notice)
        # The pointer is still on the field: its tooltip, placed over the field, says it too
        # (a tooltip placed below the pointer would cover the line under the field).
        tooltip = colour_pixels(shots["clamped"], (440, 205, 640, 280), CLAMP_NOTICE)
        check("the radius field's tooltip says it clamped the value", tooltip > 40, tooltip)
    if "building" in shots:
        # The bar shows while the new shape's shaders build; a machine that built them before
        # the shot (the log's first switch after the add) has nothing to show.
        frames = [int(f) for f in re.findall(r"frame (\d+): window shot .*building\.png", run.stderr)]
        switches = [int(f) for f in re.findall(r"frame (\d+): drawing with the", run.stderr)]
        after = [f for f in switches if f >= 25]
        fill = colour_pixels(shots["building"], (153, 19, 440, 120), PROGRESS_FILL)
        if frames and (not after or frames[0] < after[0]):
            check("a progress bar shows while the shaders build", fill > 50, fill)
        else:
            print("note: the shaders were built before the shot; the progress bar is not checked")


def real_drop_run(rmsc, source, tmp, xvfb_run, check):
    """A real drop: while a replay script idles, tests/e2e/xdnd_drop.py drops a glTF model on the
    viewer's window by the XDND protocol, as a file manager does; GLFW's drop callback queues it
    and the model is added (the scene saved at the end holds it)."""
    folder = os.path.join(tmp, "real-drop")
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    model = os.path.join(folder, "cube.glb")
    shutil.copy(os.path.join(source, "samples/assets/cube.glb"), model)
    script = os.path.join(folder, "script.txt")
    # Idle frames while the drop comes (it takes well under a second once the window is open).
    open(script, "w").write("0 move 297 190\n600 key ctrl+s\n603 quit\n")
    both = ('"$0" view "$1" --script "$2" --size 640x360 --embedded-shaders & viewer=$!; '
            '"$3" "$4" rmsc "$5"; drop=$?; wait $viewer; echo "exits: drop $drop viewer $?"')
    command = [xvfb_run, "-a", "-s", "-screen 0 800x600x24", "sh", "-c", both, rmsc, scene,
               script, sys.executable, os.path.join(source, "tests/e2e/xdnd_drop.py"), model]
    env = dict(os.environ, XDG_CONFIG_HOME=os.path.join(folder, "config"))
    run = subprocess.run(command, capture_output=True, text=True, timeout=300, env=env)
    if VERBOSE or "exits: drop 0 viewer 0" not in run.stdout:
        print(run.stdout[-500:] + run.stderr[-1000:])
    if "exits: drop 77" in run.stdout:
        print("note: libX11 cannot be loaded from Python; the real drop is not tried")
        return
    check("real drop: the target finished the XDND drop and the viewer exits 0",
          "exits: drop 0 viewer 0" in run.stdout, run.stdout[-300:])
    meshes = json.load(open(scene)).get("meshes", [])
    check("real drop: the dropped model is a mesh of the saved scene",
          len(meshes) == 1 and meshes[0].get("file", "").endswith("cube.glb"), meshes)


def scale_run(rmsc, source, tmp, xvfb_run, check):
    """`rmsc view --ui-scale 2` (tests/e2e/viewer_scale_script.txt): the menu bar twice as high."""
    folder, scene, script = run_folder(source, tmp, "scale", "viewer_scale_script.txt")
    run = run_viewer(xvfb_run, rmsc, scene, script, "1280x720", extra=["--ui-scale", "2"],
                     screen="1400x900")
    check("scaled run: viewer exits 0", run.returncode == 0, run.returncode)
    path = os.path.join(folder, "scaled.png")
    check("scaled run: window shot written", os.path.exists(path))
    if os.path.exists(path):
        width, height, channels, rows = read_png(path)
        # The menu bar's background at x = 4, in its padding left of "File" (the scene's path
        # at the right may be long), from the row under the window's top border: 17 rows at
        # scale 1 (measured), 36 at scale 2.
        bar = 1
        while bar < height and all(abs(rows[bar][4 * channels + c] - MENU_BAR[c]) <= 6
                                   for c in range(3)):
            bar += 1
        check("at --ui-scale 2 the menu bar is twice as high (36 rows, 17 at scale 1)",
              34 <= bar - 1 <= 38, bar - 1)


def shading_run(rmsc, source, tmp, xvfb_run, check):
    """The shading run (tests/e2e/viewer_shading_script.txt): shadows turned on, off and on again
    in the Render tab of a scene without them; the code for them is built once (logged), and
    the pictures follow each click."""
    folder, scene, script = run_folder(source, tmp, "shading", "viewer_shading_script.txt")
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("shading run: viewer exits 0", run.returncode == 0, run.returncode)
    builds = [int(m.group(1)) for m in re.finditer(
        r"rmsc view: frame (\d+): built the shaders of the view's shading settings", run.stderr)]
    check("turning shadows on builds their code once, right after the click; off and on "
          "again build nothing", len(builds) == 1 and 12 <= builds[0] <= 14, builds)
    shots = {}
    for name in ("off", "on", "off_again", "on_again"):
        path = os.path.join(folder, name + ".png")
        check(f"shading run: screenshot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if len(shots) == 4:
        shadowed = len(differing_pixels(shots["off"], shots["on"]))
        # (Measured: the ball's shadow on the base changes 2,134 pixels by more than 24.)
        check("shadows on darken the view", shadowed > 2000, shadowed)
        check("off again is the picture without them",
              len(differing_pixels(shots["off"], shots["off_again"], 2)) == 0,
              len(differing_pixels(shots["off"], shots["off_again"], 2)))
        check("on again is the picture with them",
              len(differing_pixels(shots["on"], shots["on_again"], 2)) == 0,
              len(differing_pixels(shots["on"], shots["on_again"], 2)))
    saved = json.load(open(scene))
    shadows = saved.get("render", {}).get("shadows")
    check("saved with shadows on", isinstance(shadows, dict) and shadows.get("enabled", True),
          shadows)


def gltf_run(rmsc, source, tmp, xvfb_run, check):
    """The glTF run (tests/e2e/viewer_gltf_script.txt): a .gltf with an animation, a camera and
    two scenes opened by itself; its animation played for 1 s and paused, its second scene
    chosen, the scene saved."""
    folder = os.path.join(tmp, "gltf")
    os.makedirs(folder)
    # A 2 x 2 quad facing +z; node 0 draws it (scene A) and animation "Rise" lifts it from y = 0
    # at 0 s to y = 2 at 2 s; node 1 draws it at x = 3 (scene B); camera 0 on node 2 (scene A).
    data = struct.pack("12f", -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0) + \
        struct.pack("6H", 0, 1, 2, 0, 2, 3) + bytes(4) + struct.pack("2f", 0, 2) + \
        struct.pack("6f", 0, 0, 0, 0, 2, 0)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0,
        "scenes": [{"name": "A", "nodes": [0, 2]}, {"name": "B", "nodes": [1]}],
        "nodes": [{"mesh": 0}, {"mesh": 0, "translation": [3, 0, 0]},
                  {"camera": 0, "translation": [0, 0, 6]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "cameras": [{"name": "Front", "type": "perspective",
                     "perspective": {"yfov": 0.6, "znear": 0.1, "zfar": 100}}],
        "animations": [{"name": "Rise",
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}],
                        "samplers": [{"input": 2, "output": 3}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 4,
             "min": [-1, -1, 0], "max": [1, 1, 0]},
            {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 6},
            {"bufferView": 2, "componentType": 5126, "type": "SCALAR", "count": 2,
             "min": [0], "max": [2]},
            {"bufferView": 3, "componentType": 5126, "type": "VEC3", "count": 2}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                        {"buffer": 0, "byteOffset": 64, "byteLength": 8},
                        {"buffer": 0, "byteOffset": 72, "byteLength": 24}],
        "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(data).decode()}]}
    model = os.path.join(folder, "model.gltf")
    json.dump(gltf, open(model, "w"))
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e/viewer_gltf_script.txt")).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    run = run_viewer(xvfb_run, rmsc, model, script, "640x480")
    check("glTF run: viewer exits 0", run.returncode == 0, run.returncode)
    saved_path = os.path.join(folder, "saved.json")
    check("glTF run: the scene was saved", os.path.exists(saved_path))
    if os.path.exists(saved_path):
        mesh = json.load(open(saved_path))["meshes"][0]
        check("the mesh shows the animation chosen", mesh.get("animation") == "Rise", mesh)
        check("played for 30 frames of 1/30 s: its time is 1 s",
              abs(mesh.get("time", 0) - 1.0) < 0.07, mesh.get("time"))
        check("and draws the file's second scene", mesh.get("scene") == 1, mesh)
    shots = {}
    for name in ("rest", "played"):
        path = os.path.join(folder, name + ".png")
        check(f"glTF run: window shot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if len(shots) == 2:
        # The view is x 153..440; the quad rose by 1 m, uncovering the ground below it.
        moved = [p for p in differing_pixels(shots["rest"], shots["played"])
                 if 160 <= p[0] <= 430 and 260 <= p[1] <= 340]
        check("playing moved the quad in the view", len(moved) > 2000, len(moved))


def glb_summary(path):
    """The JSON of a .glb and the box of its positions (the accessors' min and max)."""
    data = open(path, "rb").read()
    magic, version, length = struct.unpack("<4sII", data[:12])
    assert magic == b"glTF" and version == 2 and length == len(data), (magic, version, length)
    json_length, kind = struct.unpack("<I4s", data[12:20])
    assert kind == b"JSON", kind
    doc = json.loads(data[20:20 + json_length])
    lo, hi = [1e30] * 3, [-1e30] * 3
    for primitive in doc["meshes"][0]["primitives"]:
        accessor = doc["accessors"][primitive["attributes"]["POSITION"]]
        lo = [min(a, b) for a, b in zip(lo, accessor["min"])]
        hi = [max(a, b) for a, b in zip(hi, accessor["max"])]
    triangles = sum(doc["accessors"][p["indices"]]["count"] // 3
                    for p in doc["meshes"][0]["primitives"])
    return doc, lo, hi, triangles


# Window-shot rectangles of the eighth run: the export dialog's title bar, and the progress bar of
# the export's window at the bottom right of the view.
DIALOG_TITLE_BOX = (80, 58, 560, 72)
PROGRESS_BAR_BOX = (180, 300, 430, 322)


def near_colour_pixels(shot, box, colours, tolerance=10):
    """Pixels in box (x0, y0, x1, y1) within `tolerance` of one of `colours` (RGB) per channel."""
    width, height, channels, rows = shot
    count = 0
    for y in range(box[1], box[3]):
        for x in range(box[0], box[2]):
            pixel = rows[y][x * channels:x * channels + 3]
            if any(all(abs(p - c) <= tolerance for p, c in zip(pixel, colour)) for colour in colours):
                count += 1
    return count


def dialog_pixels(shot):
    """Dear ImGui's active title bar blue (41, 74, 122) where the export dialog's title is."""
    return near_colour_pixels(shot, DIALOG_TITLE_BOX, [(41, 74, 122)], 6)


def progress_pixels(shot):
    """A progress bar: its frame (39, 57, 83) or its fill (230, 179, 0)."""
    return near_colour_pixels(shot, PROGRESS_BAR_BOX, [(39, 57, 83), (230, 179, 0)])


def export_run(rmsc, source, tmp, xvfb_run, check):
    """The eighth run (tests/e2e/viewer_export_script.txt): File > Export selection of the ball,
    its dialog, its progress window and the file it writes."""
    folder = os.path.join(tmp, "export")
    os.makedirs(folder)
    scene = os.path.join(folder, "scene.json")
    shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
    original = open(scene).read()
    script = os.path.join(folder, "script.txt")
    text = open(os.path.join(source, "tests/e2e/viewer_export_script.txt")).read()
    open(script, "w").write(text.replace("OUT/", folder + "/"))
    run = run_viewer(xvfb_run, rmsc, scene, script)
    check("eighth run: viewer exits 0", run.returncode == 0, run.returncode)
    keep = os.environ.get("RMSC_E2E_KEEP")
    if keep:
        shutil.copytree(folder, keep, dirs_exist_ok=True)
    notice = re.search(r"rmsc view: exported /sdf/children/0 to (.*ball\.glb): (\d+) triangles",
                       run.stderr)
    check("the export's notice names the ball's node and the file", notice is not None,
          run.stderr[-2000:])
    glb = os.path.join(folder, "ball.glb")
    check("File > Export selection wrote the .glb", os.path.exists(glb))
    if os.path.exists(glb):
        doc, lo, hi, triangles = glb_summary(glb)
        # The ball alone (radius 0.5 at the origin), not the base below it.
        check("the mesh is the ball: its box is [-0.5, 0.5] on every axis",
              all(abs(a + 0.5) < 0.01 for a in lo) and all(abs(b - 0.5) < 0.01 for b in hi), (lo, hi))
        check("with the triangles the notice counted",
              notice is not None and int(notice.group(2)) == triangles, triangles)
        names = [m.get("name") for m in doc.get("materials", [])]
        check("and the ball's material only", names == ["red"], names)
    leftovers = [f for f in os.listdir(folder) if f.startswith("ball") and f != "ball.glb"]
    check("no temporary file is left beside it", leftovers == [], leftovers)
    check("the export did not change the scene file", open(scene).read() == original)
    shots = {}
    for name in ("dialog", "progress", "done"):
        path = os.path.join(folder, name + ".png")
        check(f"eighth run: window shot {name} written", os.path.exists(path))
        if os.path.exists(path):
            shots[name] = read_png(path)
    if "dialog" in shots and "progress" in shots:
        check("the dialog is open before Export", dialog_pixels(shots["dialog"]) > 2000,
              dialog_pixels(shots["dialog"]))
        check("and closed once the export runs", dialog_pixels(shots["progress"]) < 50,
              dialog_pixels(shots["progress"]))
    if "progress" in shots and "done" in shots:
        check("while it runs, its progress bar is at the bottom right of the view",
              progress_pixels(shots["progress"]) > 2000, progress_pixels(shots["progress"]))
        check("and gone once it has ended", progress_pixels(shots["done"]) < 50,
              progress_pixels(shots["done"]))


def main():
    rmsc, source = sys.argv[1], sys.argv[2]
    if len(sys.argv) > 3 and sys.argv[3] in ("--burst", "--timing"):
        xvfb_run = shutil.which("xvfb-run")
        if not xvfb_run or not shutil.which("Xvfb"):
            print("SKIP: xvfb-run / Xvfb not installed")
            return SKIP
        return responsiveness_main(rmsc, source, xvfb_run,
                                   burst_run if sys.argv[3] == "--burst" else timing_runs)
    xvfb_run = shutil.which("xvfb-run")
    if not xvfb_run or not shutil.which("Xvfb"):
        print("SKIP: xvfb-run / Xvfb not installed")
        return SKIP
    check = Checks()

    with tempfile.TemporaryDirectory(prefix="rmsc-e2e-") as tmp:
        scene = os.path.join(tmp, "scene.json")
        shutil.copy(os.path.join(source, "tests/e2e/viewer_scene.json"), scene)
        original = open(scene).read()
        script = os.path.join(tmp, "script.txt")
        text = open(os.path.join(source, "tests/e2e/viewer_script.txt")).read()
        open(script, "w").write(text.replace("OUT/", tmp + "/"))
        run = run_viewer(xvfb_run, rmsc, scene, script, tail=3000)
        if run.returncode != 0 and "cannot open a window" in run.stderr and "Xvfb" in run.stderr:
            print("SKIP: Xvfb could not start")
            return SKIP
        check("viewer exits 0", run.returncode == 0, run.returncode)

        # "rmsc view: frame N: ..." lines: which map is drawn, which shaders were built.
        log = [(int(m.group(1)), m.group(2)) for m in
               re.finditer(r"rmsc view: frame (\d+): (.*)", run.stderr)]
        selected, waited = 10, 11  # the script's click on the ball, then its wait-shaders frame
        duplicated, rebuilt = 48, 50  # the duplicate (a structural edit), then wait-shaders
        switches = [(f, what) for f, what in log if "drawing with the" in what]
        # The selection makes the ball live: the buffer map is drawn first, then the baked map
        # built in the background. That build usually ends in the wait-shaders frame, but on a
        # quick run it ends within the click's own frame; either is right.
        since_selection = [(f, what) for f, what in switches if selected <= f < duplicated]
        check("the baked map with the ball live is drawn from the selection on",
              bool(since_selection) and since_selection[-1][0] <= waited
              and "baked map" in since_selection[-1][1], log)
        check("and no other map after it until the structural edit",
              not any(waited < f < duplicated for f, _ in switches), log)
        check("no shader built on the drawing thread from the selection on",
              not any(f >= selected and what.startswith("built") for f, what in log), log)
        interpreted = [i for i, (f, what) in enumerate(switches)
                       if f == duplicated and "interpreter map (built in the background" in what]
        check("the duplicate is drawn in its own frame by the interpreter, built in the background",
              bool(interpreted), log)
        # (The render thread switches once the map is built, whichever UI frame that falls in.)
        check("then by the baked map of the new structure",
              bool(interpreted) and any(duplicated <= f <= rebuilt and "baked map" in what
                                        for f, what in switches[interpreted[0] + 1:]), log)

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
        check("camera not saved into the scene (the save's question answered: keep it)",
              all(abs(a - b) < 1e-6 for a, b in zip(saved["camera"]["position"], [0, 0.3, 4])), saved["camera"])
        backup = scene + ".bak"
        check("backup holds the previous file", os.path.exists(backup) and open(backup).read() == original)
        check("the save asked whether the scene camera should take the view (it flew)",
              "the view is not the scene camera's" in run.stderr, run.stderr[-1500:])

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
        create_run(rmsc, source, tmp, xvfb_run, check)
        refuse_run(rmsc, source, tmp, xvfb_run, check)
        large_scene_run(rmsc, source, tmp, xvfb_run, check)
        select_run(rmsc, source, tmp, xvfb_run, check)
        gizmo_run(rmsc, source, tmp, xvfb_run, check)
        aids_run(rmsc, source, tmp, xvfb_run, check)
        real_drop_run(rmsc, source, tmp, xvfb_run, check)
        export_run(rmsc, source, tmp, xvfb_run, check)
        scale_run(rmsc, source, tmp, xvfb_run, check)
        gltf_run(rmsc, source, tmp, xvfb_run, check)
        shading_run(rmsc, source, tmp, xvfb_run, check)
    return check.summary()


if __name__ == "__main__":
    sys.exit(main())
