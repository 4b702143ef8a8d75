#!/usr/bin/env python3
"""Writes the measurement table of docs/export.md: `rmsc export`'s dual contouring and, as a
baseline at the same voxel size, plain marching cubes, over sample scenes: triangles, the
largest and mean |distance| of the vertices and of points spread over the triangles (in voxels),
the distance of known sharp corners to the nearest vertex (in voxels), whether the mesh is a
closed 2-manifold, and the time. Run from the repository root after building the tool:
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
             "mean | sharp corners | closed 2-manifold | time |",
             "|---|---|---|---|---|---|---|---|---|"]
    for name, scene, args, corners in rows:
        corner_args = [a for c in corners for a in ("--corner", c)]
        for method, extra in (("dual contouring", []), ("marching cubes", ["--marching-cubes"])):
            m = measure(options.measure, scene, args + corner_args + extra, options.threads)
            corner = "—" if m["corner_error"] is None else f"{m['corner_error']:.3f}"
            lines.append(
                f"| {name} | {method} | {m['grid'][0]}x{m['grid'][1]}x{m['grid'][2]} | "
                f"{m['triangles']:,} | {m['max_vertex_error']:.3f} / {small(m['mean_vertex_error'])} | "
                f"{m['max_surface_error']:.3f} / {small(m['mean_surface_error'])} | {corner} | "
                f"{'yes' if m['closed_manifold'] else 'no'} | {m['seconds']:.2f} s |")
            print(lines[-1], flush=True)
    table = "\n".join(lines) + "\n"
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
