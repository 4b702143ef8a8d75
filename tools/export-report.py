#!/usr/bin/env python3
"""Writes the measurement tables of docs/export.md.

The first: over sample scenes, `rmsc export`'s dual contouring with its adaptive octree (the
default tolerance), without it (tolerance 0: a vertex per cell) and, as a baseline on the same
grid, plain marching cubes: triangles, the largest and mean |distance| of the vertices and of
points spread over the triangles (in voxels), the distance of known sharp corners to the
nearest vertex (in voxels), whether the mesh is a closed 2-manifold, its self-intersections,
and the time (wall clock, and the CPU time of all threads: on a machine other jobs share, the
wall clock says more about them).

The second, triangles at equal accuracy: for marching cubes at a resolution, the mesh of the
adaptive dual contouring with the fewest triangles (over a few tolerances, each at the coarsest
resolution that does it) whose largest and mean surface errors (in world units) are both at
most marching cubes', and the two triangle counts.

Run from the repository root after building the tool:
    cmake --build build --target rmsc_export_measure
    python3 tools/export-report.py [--measure build/bin/rmsc_export_measure] [--threads N]"""
import argparse
import itertools
import json
import os
import platform
import subprocess
import tempfile

BOX = {"version": 1, "sdf": {"shape": "box", "half_extents": [0.4, 0.3, 0.25],
                             "rotation": [23, 37, 11], "position": [0.011, 0.003, -0.017]}}


def csg_subtraction_corners():
    """The corners of the subtraction sample's box that the sphere does not cut."""
    centre, half = (-0.7, 0.5, 0.0), 0.35
    sphere, radius = (0.25, 0.2, 0.2), 0.45
    corners = []
    for signs in itertools.product((-1, 1), repeat=3):
        local = [s * half for s in signs]
        if sum((l - c) ** 2 for l, c in zip(local, sphere)) ** 0.5 > radius + 0.02:
            corners.append(",".join(f"{c + l:.6f}" for c, l in zip(centre, local)))
    return corners


def small(value):
    """A mean error: four decimals, or "< 0.0001"."""
    return "< 0.0001" if value < 0.00005 else f"{value:.4f}"


# Scenes of the equal-accuracy table: name, scene, node (None: the whole tree), and marching
# cubes' resolution.
EQUAL_ACCURACY = [
    ("pawn (smooth CSG)", "samples/scenes/pawn.json", None, 128),
    ("pawn (smooth CSG)", "samples/scenes/pawn.json", None, 256),
    ("CSG sample, whole", "samples/scenes/csg.json", None, 128),
    ("CSG sample, whole", "samples/scenes/csg.json", None, 256),
]


# The tolerances (voxels) the equal-accuracy search tries.
TOLERANCES = [0.1, 0.05, 0.03]


def millimetres(m):
    """The largest and mean surface errors of a measurement in millimetres."""
    return (m["max_surface_error"] * m["voxel"] * 1000, m["mean_surface_error"] * m["voxel"] * 1000)


def grid_text(m):
    return f"{m['grid'][0]}x{m['grid'][1]}x{m['grid'][2]}"


def measure(tool, scene, args, threads):
    cmd = [tool, scene, "--threads", str(threads)] + args
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--measure", default="build/bin/rmsc_export_measure")
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--doc", default="docs/export.md")
    options = parser.parse_args()
    tmp = tempfile.mkdtemp()
    box = os.path.join(tmp, "box.json")
    with open(box, "w") as f:
        json.dump(BOX, f)
    box_corners = subprocess.run([options.measure, "--box-corners", box], capture_output=True,
                                 text=True).stdout.split()
    rows = [
        ("rotated box (corners)", box, ["--resolution", "64"], box_corners),
        ("CSG sample: subtraction (corners)", "samples/scenes/csg.json",
         ["--node", "/sdf/children/1", "--resolution", "64"], csg_subtraction_corners()),
        ("CSG sample, whole", "samples/scenes/csg.json", ["--resolution", "256"], []),
        ("pawn (smooth CSG)", "samples/scenes/pawn.json", ["--resolution", "128"], []),
        ("pawn (smooth CSG)", "samples/scenes/pawn.json", ["--resolution", "256"], []),
    ]
    lines = ["| scene | method | grid | triangles | vertex error max / mean | surface error max / "
             "mean | sharp corners | closed 2-manifold | self-intersections | time (CPU) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    methods = (("dual contouring, adaptive octree", []),
               ("dual contouring, a vertex per cell", ["--tolerance", "0"]),
               ("marching cubes", ["--marching-cubes"]))
    for name, scene, args, corners in rows:
        corner_args = [a for c in corners for a in ("--corner", c)]
        for method, extra in methods:
            m = measure(options.measure, scene, args + corner_args + extra, options.threads)
            corner = "—" if m["corner_error"] is None else f"{m['corner_error']:.3f}"
            lines.append(
                f"| {name} | {method} | {m['grid'][0]}x{m['grid'][1]}x{m['grid'][2]} | "
                f"{m['triangles']:,} | {m['max_vertex_error']:.3f} / {small(m['mean_vertex_error'])} | "
                f"{m['max_surface_error']:.3f} / {small(m['mean_surface_error'])} | {corner} | "
                f"{'yes' if m['closed_manifold'] else 'no'} | {m['self_intersections']} | "
                f"{m['seconds']:.2f} s ({m['cpu_seconds']:.2f} s) |")
            print(lines[-1], flush=True)
    table = "\n".join(lines) + "\n"

    # Equal accuracy: errors in world units (voxels times the voxel size). For each tolerance,
    # the coarsest resolution (by bisection: the errors shrink as the grid gets finer) at which
    # the adaptive dual contouring's largest and mean surface errors are both at most marching
    # cubes'; the row is the tolerance whose mesh has the fewest triangles.
    equal = ["| scene | marching cubes: grid, triangles | its surface error max / mean (mm) | "
             "adaptive dual contouring at equal accuracy: tolerance, grid, triangles | its "
             "surface error max / mean (mm) | triangles, dual contouring / marching cubes |",
             "|---|---|---|---|---|---|"]
    for name, scene, node, mc_resolution in EQUAL_ACCURACY:
        node_args = ["--node", node] if node else []
        mc = measure(options.measure, scene,
                     node_args + ["--resolution", str(mc_resolution), "--marching-cubes"],
                     options.threads)
        mc_max, mc_mean = millimetres(mc)
        best = None
        for tolerance in TOLERANCES:
            def run(resolution):
                m = measure(options.measure, scene, node_args + [
                    "--resolution", str(resolution), "--tolerance", str(tolerance)], options.threads)
                e_max, e_mean = millimetres(m)
                return m if e_max <= mc_max and e_mean <= mc_mean else None
            lo, hi = mc_resolution // 4, mc_resolution  # the answer is in (lo, hi]
            found = run(hi)
            if found is None:
                continue
            while hi - lo > max(4, mc_resolution // 32):
                middle = (lo + hi) // 2
                m = run(middle)
                if m is None:
                    lo = middle
                else:
                    hi, found = middle, m
            print(f"  {name}: tolerance {tolerance}: {grid_text(found)}, {found['triangles']:,} "
                  f"triangles", flush=True)
            if best is None or found["triangles"] < best[1]["triangles"]:
                best = (tolerance, found)
        if best is None:
            equal.append(f"| {name} | {grid_text(mc)}, {mc['triangles']:,} | {mc_max:.3f} / "
                         f"{mc_mean:.4f} | not reached up to resolution {mc_resolution} | — | — |")
        else:
            tolerance, dc = best
            dc_max, dc_mean = millimetres(dc)
            equal.append(
                f"| {name} | {grid_text(mc)}, {mc['triangles']:,} | {mc_max:.3f} / {mc_mean:.4f} | "
                f"{tolerance}, {grid_text(dc)}, {dc['triangles']:,} | {dc_max:.3f} / {dc_mean:.4f} | "
                f"{dc['triangles'] / mc['triangles']:.2f} |")
        print(equal[-1], flush=True)
    table += "\n" + "\n".join(equal) + "\n"
    note = (f"Measured with `python3 tools/export-report.py --threads {options.threads}` on "
            f"{platform.machine()}, {options.threads} threads ({os.cpu_count()} cores seen).\n")
    with open(options.doc, encoding="utf-8") as f:
        doc = f.read()
    begin, end = "<!-- export-table:begin -->\n", "<!-- export-table:end -->"
    head, rest = doc.split(begin)
    doc = head + begin + note + "\n" + table + end + rest.split(end)[1]
    with open(options.doc, "w", encoding="utf-8") as f:
        f.write(doc)


if __name__ == "__main__":
    main()
