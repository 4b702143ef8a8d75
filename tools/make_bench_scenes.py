#!/usr/bin/env python3
"""Writes the generated benchmark scenes of samples/bench/: N primitives (1, 10, 100, 1000) on a
grid facing the camera, sized so that every scene covers about the same share of the view
(the issue's "equal screen coverage"), cycling through a few primitive kinds and materials.
Run from the repository root: python3 tools/make_bench_scenes.py"""
import json
import math
import os

KINDS = [
    {"shape": "sphere", "radius": 0.42},
    {"shape": "box", "half_extents": [0.34, 0.34, 0.34]},
    {"shape": "torus", "major_radius": 0.3, "minor_radius": 0.12, "rotation": [90, 0, 0]},
    {"shape": "round_box", "half_extents": [0.32, 0.32, 0.32], "radius": 0.08},
    {"shape": "capsule", "half_height": 0.2, "radius": 0.22},
]
COLOURS = ["#e76f51", "#f4a261", "#2a9d8f", "#457b9d", "#e9c46a"]


def scaled(shape, s):
    out = {}
    for key, value in shape.items():
        if key in ("shape", "rotation"):
            out[key] = value
        elif isinstance(value, list):
            out[key] = [round(v * s, 5) for v in value]
        else:
            out[key] = round(value * s, 5)
    return out


def grid_scene(n):
    side = math.ceil(math.sqrt(n))
    cell = 4.0 / side
    children = []
    for i in range(n):
        row, col = divmod(i, side)
        x = (col - (side - 1) / 2) * cell
        y = ((side - 1) / 2 - row) * cell
        node = scaled(KINDS[i % len(KINDS)], cell)
        node["position"] = [round(x, 5), round(y, 5), 0.0]
        node["material"] = "m%d" % (i % len(COLOURS))
        children.append(node)
    return {
        "version": 1,
        "camera": {"position": [0, 0, 7.5], "target": [0, 0, 0], "fov": 40},
        "render": {"background": [0.18, 0.2, 0.24]},
        "materials": {"m%d" % i: {"base_color": c, "roughness": 0.45}
                      for i, c in enumerate(COLOURS)},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"name": "%d primitives" % n, "children": children},
    }


def main():
    folder = os.path.join("samples", "bench")
    os.makedirs(folder, exist_ok=True)
    for n in (1, 10, 100, 1000):
        path = os.path.join(folder, "grid_%d.json" % n)
        with open(path, "w") as out:
            json.dump(grid_scene(n), out, indent=1)
            out.write("\n")
        print("wrote", path)


if __name__ == "__main__":
    main()
