#!/usr/bin/env python3
"""Writes docs/performance.md from `rmsc bench --json`: every benchmark scene under every
scene-to-shader strategy (and the hand-written yardstick shaders in bench/), with ms per frame,
the march pass's GPU time, the shader compile time and the ratios the performance targets are
stated in. What the file holds after the HAND_KEPT marker line is written by hand and kept as it
is. Run from the repository root after building (docs/performance.md is made at 160x120):
    python3 tools/bench-report.py [--rmsc build/bin/rmsc] [--size 320x180] [--frames 5]"""
import argparse
import datetime
import json
import os
import platform
import subprocess

# The line after which the output file is written by hand (the measurements of the cells, the
# UI's frame times): kept when the file is written again.
HAND_KEPT = "<!-- Kept by hand from here on: tools/bench-report.py leaves what follows as it is. -->"

SCENES = [
    ("samples/bench/grid_1.json", "1 primitive"),
    ("samples/bench/grid_10.json", "10 primitives"),
    ("samples/bench/grid_100.json", "100 primitives"),
    ("samples/bench/grid_1000.json", "1,000 primitives"),
    ("samples/scenes/pawn.json", "smooth-CSG character (the pawn)"),
    ("samples/bench/repetition_field.json", "repetition field"),
    ("samples/bench/mandelbulb.json", "the Mandelbulb"),
    ("samples/scenes/demo.json", "mixed mesh + SDF (the demo)"),
    ("samples/scenes/chessboard.json", "the chessboard"),
    ("samples/scenes/shells.json", "shells (proxy meshes) and the same all fullscreen"),
]


def cpu_name():
    try:
        with open("/proc/cpuinfo") as info:
            for line in info:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def bench(rmsc, scene, size, frames):
    command = [rmsc, "bench", scene, "--size", size, "--frames", str(frames), "--warmup", "3",
               "--sdf-strategy", "all", "--json"]
    hand = os.path.join("bench", os.path.splitext(os.path.basename(scene))[0] + ".glsl")
    if os.path.exists(hand):
        command += ["--sdf-map", hand]
    output = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    return json.loads(output), hand if os.path.exists(hand) else None


def cold_build(rmsc, scene, size, strategy):
    """A strategy's programs built with no shader cache to help (what the viewer's background
    build of a new structure costs): milliseconds to build them plus those the first frame adds
    to a normal one (drivers finish programs at their first draw)."""
    command = [rmsc, "bench", scene, "--size", size, "--frames", "1", "--warmup", "1",
               "--sdf-strategy", strategy, "--json"]
    env = dict(os.environ, MESA_SHADER_CACHE_DISABLE="true")
    output = subprocess.run(command, check=True, capture_output=True, text=True, env=env).stdout
    run = json.loads(output)["strategies"][0]
    return run["shader_build_ms"] + run["first_frame_ms"] - run["frame_ms"]["median"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rmsc", default="build/bin/rmsc")
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--output", default="docs/performance.md")
    args = parser.parse_args()

    rows = []
    results = {}
    renderer = ""
    for scene, label in SCENES:
        print("bench", scene, flush=True)
        result, hand = bench(args.rmsc, scene, args.size, args.frames)
        renderer = result["renderer"]
        by_name = {s["strategy"]: s for s in result["strategies"]}
        results[scene] = by_name
        first = result["strategies"][0]["frame_ms"]["median"]
        for s in result["strategies"]:
            marched = s.get("marched_fragments", {})
            rows.append("| %s | %s | %.1f | %.1f | %.1f | %.0f | %d + %d | %.0f | %.2fx |" % (
                label, s["strategy"], s["frame_ms"]["median"],
                s["pass_gpu_ms"]["march"]["median"] + s["pass_gpu_ms"]["cone"]["median"],
                s["march_steps_per_pixel"],
                s.get("evaluations_per_pixel", 0.0), marched.get("fullscreen", 0),
                marched.get("shells", 0), s["shader_build_ms"],
                s["frame_ms"]["median"] / first))

    def ratio(scene, a, b, key="frame_ms"):
        runs = results.get(scene, {})
        if a in runs and b in runs:
            value = lambda run: run[key]["median"] if key == "frame_ms" else run[key]
            return "%.2fx" % (value(runs[a]) / value(runs[b]))
        return "not measured"

    cone_rows = []
    for scene, label in SCENES:
        runs = results.get(scene, {})
        for name, without in runs.items():
            if not name.endswith(", no cone pass"):
                continue
            base = name[:-len(", no cone pass")]
            default = runs.get(base) or runs.get(base + ", shells")
            if not default:
                continue
            cone_rows.append("| %s | %s | %.1f -> %.1f (%.2fx) | %.1f -> %.1f (%.2f) | %d -> %d |" % (
                label, default["strategy"], without["frame_ms"]["median"],
                default["frame_ms"]["median"],
                default["frame_ms"]["median"] / without["frame_ms"]["median"],
                without["march_steps_per_pixel"], default["march_steps_per_pixel"],
                default.get("cone_steps_per_pixel", 0.0),
                without["marched_fragments"]["fullscreen"],
                default["marched_fragments"]["fullscreen"]))

    def evaluations(scene):
        """Primitive evaluations per pixel through the hierarchy (the interpreter: generated
        code evaluates every part)."""
        runs = results.get(scene, {})
        return runs["interpreter"]["evaluations_per_pixel"] if "interpreter" in runs else None

    structural = cold_build(args.rmsc, "samples/bench/grid_100.json", args.size, "baked")
    edit = results.get("samples/bench/grid_100.json", {}).get(
        "interpreter, after a structural edit")
    edit_text = ("%.0f ms to build, %.0f ms for its first frame" % (
        edit["shader_build_ms"], edit["first_frame_ms"]) if edit else "not measured")
    def evaluations_per_marched(scene):
        """The same per pixel that marched: the cone pass spares whole tiles, more of them
        around 10 large shapes than around 1,000 small ones."""
        run = results.get(scene, {}).get("interpreter")
        width, height = (int(n) for n in args.size.split("x"))
        marched = run["marched_fragments"]["fullscreen"] if run else 0
        return run["evaluations_per_pixel"] * width * height / marched if marched else None

    growth = "not measured"
    e10, e1000 = evaluations("samples/bench/grid_10.json"), evaluations(
        "samples/bench/grid_1000.json")
    m10, m1000 = evaluations_per_marched("samples/bench/grid_10.json"), evaluations_per_marched(
        "samples/bench/grid_1000.json")
    if e10 and e1000 and m10 and m1000:
        growth = ("%.0f -> %.0f per pixel: %.1fx for 100x the primitives (logarithmic would be "
                  "3x); per pixel that marched, %.0f -> %.0f: %.1fx" % (
                      e10, e1000, e1000 / e10, m10, m1000, m1000 / m10))

    lines = [
        "# Performance",
        "",
        "Generated by `tools/bench-report.py` from `rmsc bench --json` on %s: %s, %d cores, "
        "OpenGL renderer \"%s\". Frames of %s, median of %d after at least three warm-up frames "
        "and 300 ms (per strategy, one strategy after the other), wall time with "
        "`glFinish`. Shader compile times are with Mesa's shader cache as it was (a cached "
        "program builds in tens of milliseconds)." % (
            datetime.date.today().isoformat(), cpu_name(), os.cpu_count(), renderer, args.size,
            args.frames),
        "",
        "Strategies (see the README, \"How a frame is made\"): `baked` is generated GLSL with the "
        "parameters as literals (the default), `buffer` the same code reading parameters from the "
        "program buffer (what the viewer draws after the selection changes, until the next one "
        "is built), `baked, editing one shape` what the viewer draws once a "
        "background thread has built it: the tree without the bounding hierarchy, baked but for "
        "the selection (here the first shape), whose numbers come from the buffer, so dragging "
        "its parameters compiles nothing. `interpreter, after a structural edit` is what the "
        "viewer draws in the frame of a structural edit (here the last shape duplicated) while "
        "generated code for the new structure builds in the background: the interpreter's "
        "program depends only on the kinds of shapes, so its build time is that of a cache hit. "
        "Generated code evaluates every part: only the "
        "interpreter skips subtrees by their boxes, so generated rows count the evaluations of "
        "the whole tree. `interpreter` is a loop over the program buffer: the lean one for "
        "programs of box tests and one-shape parts (the grids), the generic one otherwise. Scenes "
        "of more than 160 shapes use `cells` instead of `baked` (the program pruned per cell, see "
        "\"Per-cell pruning\" below): generated code costs compile time in proportion to the "
        "scene on llvmpipe. "
        "`hand-written` is a shader in `bench/` written for that one scene, the yardstick.",
        "",
        "Rows ending in `, shells` draw the scene's shells through their proxy meshes, `, "
        "fullscreen` the same scene with every node in the fullscreen pass. "
        "`interpreter, no bounds` is the interpreter on the tree without the bounding hierarchy "
        "(the baseline for bounds). Primitive evaluations per pixel come from one frame of an "
        "instrumented cone and march pass: every primitive evaluated for the pixel's tile's "
        "cone (shared among the tile's pixels), its march, normal, "
        "shading, soft shadows and AO in the fullscreen pass (shells' own marching is not "
        "counted). The march steps per pixel include the cone pass's, shared among the pixels "
        "of each tile, and the GPU time is that of the cone and the march pass together. "
        "`..., no cone pass` is the default without the cone pass (every pixel marches from the "
        "near plane): the baseline the cone pass is measured against, below.",
        "",
        "| scene | strategy | ms / frame | cone + march pass, GPU ms | march steps / pixel "
        "| primitive evaluations / pixel | fragments marched (fullscreen + shells) "
        "| shader build ms | vs. first row |",
        "|---|---|---|---|---|---|---|---|---|",
    ] + rows + [
        "",
        "## The cone pass",
        "",
        "Before the march pass, the cone pass marches one cone per tile of 8x8 pixels, holding "
        "every ray of the tile, and writes how far all of them may skip; each pixel's march "
        "starts there (`shaders/passes/cone.frag`). Pixels whose tile ends behind a mesh, or "
        "past the farthest distance, do not march at all. The hand-written shaders run behind "
        "it too: the rows above compare maps, not pipelines.",
        "",
        "| scene | strategy | ms / frame without -> with | march steps / pixel without -> "
        "with (the cone pass's part) | fragments marched in the fullscreen pass |",
        "|---|---|---|---|---|",
    ] + cone_rows + [
        "",
        "## Targets",
        "",
        "| target | measured |",
        "|---|---|",
        "| default strategy within 1.25x of the hand-written shader (10 primitives) | %s |"
        % ratio("samples/bench/grid_10.json", "baked", "hand-written"),
        "| while editing one shape (the rest baked) within 3x of baked (10 primitives) | %s |"
        % ratio("samples/bench/grid_10.json", "baked, editing one shape", "baked"),
        "| while editing one shape (the rest baked) within 3x of baked (the pawn) | %s |"
        % ratio("samples/scenes/pawn.json", "baked, editing one shape", "baked"),
        "| while editing one shape (the rest baked) within 3x of baked (the chessboard) | %s |"
        % ratio("samples/scenes/chessboard.json", "baked, editing one shape", "baked"),
        "| before the background build is ready (buffer) vs. baked: 10 primitives, the pawn "
        "| %s, %s |"
        % (ratio("samples/bench/grid_10.json", "buffer", "baked"),
           ratio("samples/scenes/pawn.json", "buffer", "baked")),
        "| structural edit to 100 primitives: the edited scene drawn in the edit's frame by the "
        "interpreter, already built (target: new shader ready in 200 ms) | %s |" % edit_text,
        "| the same edit: baked code for the new structure, built in the background with the "
        "shader cache off, first frame included | %.0f ms |" % structural,
        "| default strategy vs. the hand-written shader (the pawn) | %s |"
        % ratio("samples/scenes/pawn.json", "baked", "hand-written"),
        "| interpreter vs. baked (100 primitives) | %s |"
        % ratio("samples/bench/grid_100.json", "interpreter", "baked"),
        "| 1,000 primitives: interpreter without bounds vs. with (target: at least 20x) | %s |"
        % ratio("samples/bench/grid_1000.json", "interpreter, no bounds", "interpreter"),
        "| 1,000 primitives: evaluations without bounds vs. with | %s |"
        % ratio("samples/bench/grid_1000.json", "interpreter, no bounds", "interpreter",
                "evaluations_per_pixel"),
        "| evaluations per pixel from 10 to 1,000 primitives | %s |" % growth,
        "",
    ]
    # What follows the marker in the file written before is kept by hand: carried over as is.
    kept = ""
    try:
        with open(args.output) as previous:
            text = previous.read()
        if HAND_KEPT in text:
            kept = text[text.index(HAND_KEPT):]
    except OSError:
        pass
    with open(args.output + ".tmp", "w") as out:
        out.write("\n".join(lines))
        out.write("\n" + kept if kept else "")
    os.replace(args.output + ".tmp", args.output)
    print("wrote", args.output, "(keeping the part after its marker)" if kept else "")


if __name__ == "__main__":
    main()
