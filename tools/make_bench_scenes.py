#!/usr/bin/env python3
"""Writes the generated benchmark scenes of samples/bench/: N primitives (1, 10, 100, 1000,
10000) on a grid facing the camera, sized so that every scene covers about the same share of
the view (the issue's "equal screen coverage": the same total area of cells), cycling through
a few primitive kinds and materials; binary trees of 256 and 4096 spheres whose levels alternate union and smooth_union
over an SDF plane, seen with the horizon; a "molecule" of 1000 spheres in one smooth union; and
1000 mixed shapes with subtractions and modifiers. Run from the repository root:
python3 tools/make_bench_scenes.py"""
import json
import math
import os
import random

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


def common(name, camera, children):
    return {
        "version": 1,
        "camera": camera,
        "render": {"background": [0.18, 0.2, 0.24]},
        "materials": {"m%d" % i: {"base_color": c, "roughness": 0.45}
                      for i, c in enumerate(COLOURS)},
        "lights": [{"type": "directional", "direction": [-0.4, -0.7, -1.0], "intensity": 3.0}],
        "sdf": {"name": name, "children": children},
    }


def grid_scene(n):
    """n shapes in rows of ceil(sqrt(n)), centred on the view. Each shape's cell is 4 / sqrt(n)
    across, so the cells' total area is 16 square metres for every n: equal coverage also
    when n is not a square (10 shapes in cells of 4 / ceil(sqrt(10)) would cover 10/16 of it)."""
    side = math.ceil(math.sqrt(n))
    rows = math.ceil(n / side)
    cell = 4.0 / math.sqrt(n)
    children = []
    for i in range(n):
        row, col = divmod(i, side)
        x = (col - (side - 1) / 2) * cell
        y = ((rows - 1) / 2 - row) * cell
        node = scaled(KINDS[i % len(KINDS)], cell)
        node["position"] = [round(x, 5), round(y, 5), 0.0]
        node["material"] = "m%d" % (i % len(COLOURS))
        children.append(node)
    camera = {"position": [0, 0, 7.5], "target": [0, 0, 0], "fov": 40}
    return common("%d primitives" % n, camera, children)


def tree_scene(n):
    """n spheres on a square of side 8 on the plane y = 0, united by a binary tree (split by
    position, halves of the list) whose levels alternate union and smooth_union (k = 0.02)."""
    side = math.ceil(math.sqrt(n))
    cell = 8.0 / side
    spheres = []
    for i in range(n):
        row, col = divmod(i, side)
        spheres.append({"shape": "sphere", "radius": round(0.4 * cell, 5),
                        "position": [round((col - (side - 1) / 2) * cell, 5),
                                     round(0.4 * cell, 5),
                                     round((row - (side - 1) / 2) * cell, 5)],
                        "material": "m%d" % (i % len(COLOURS))})

    def build(items, depth):
        if len(items) == 1:
            return items[0]
        half = len(items) // 2
        node = {"op": "union" if depth % 2 == 0 else "smooth_union",
                "children": [build(items[:half], depth + 1), build(items[half:], depth + 1)]}
        if depth % 2 == 1:
            node["smoothness"] = 0.02
        return node

    floor = {"shape": "plane", "normal": [0, 1, 0], "offset": 0, "material": "m3"}
    camera = {"position": [0, 2.2, 7.5], "target": [0, 0.2, 0], "fov": 50}
    return common("binary tree of %d spheres over a plane" % n, camera,
                  [floor, build(spheres, 0)])


def molecule_scene(n):
    """n spheres at random in a ball of radius 2, all in one smooth union (k = 0.12)."""
    rng = random.Random(1000)
    spheres = []
    while len(spheres) < n:
        p = [rng.uniform(-2, 2) for _ in range(3)]
        if sum(v * v for v in p) > 4:
            continue
        spheres.append({"shape": "sphere", "radius": round(rng.uniform(0.12, 0.24), 4),
                        "position": [round(v, 4) for v in p],
                        "material": "m%d" % (len(spheres) % len(COLOURS))})
    camera = {"position": [0, 0, 7.5], "target": [0, 0, 0], "fov": 40}
    return common("molecule of %d spheres" % n, camera,
                  [{"op": "smooth_union", "smoothness": 0.12, "children": spheres}])


def mixed_scene(n):
    """n shapes in groups of four on a grid: a box minus a sphere (subtraction), a twisted
    capsule, a rounded onion torus and a repeated... small sphere, cycling materials."""
    rng = random.Random(7)
    groups = n // 4
    side = math.ceil(math.sqrt(groups))
    cell = 4.0 / side
    children = []
    for g in range(groups):
        row, col = divmod(g, side)
        x = (col - (side - 1) / 2) * cell
        y = ((side - 1) / 2 - row) * cell
        s = cell * 0.25
        m = "m%d" % (g % len(COLOURS))
        children.append({
            "position": [round(x, 5), round(y, 5), 0.0], "rotation": [0, rng.uniform(-40, 40), 0],
            "children": [
                {"op": "subtraction", "position": [-s, s, 0], "material": m, "children": [
                    {"shape": "box", "half_extents": [0.8 * s] * 3},
                    {"shape": "sphere", "radius": round(0.95 * s, 5), "position": [0.4 * s, 0.4 * s, 0.4 * s]}]},
                {"shape": "capsule", "half_height": round(0.6 * s, 5), "radius": round(0.3 * s, 5),
                 "position": [s, s, 0], "material": m,
                 "modifiers": [{"type": "twist", "amount": 60, "radius": round(0.3 * s, 5)}]},
                {"shape": "torus", "major_radius": round(0.6 * s, 5), "minor_radius": round(0.25 * s, 5),
                 "rotation": [90, 0, 0], "position": [-s, -s, 0], "material": m,
                 "modifiers": [{"type": "onion", "thickness": round(0.05 * s, 5)},
                               {"type": "round", "radius": round(0.02 * s, 5)}]}]})
    camera = {"position": [0, 0, 7.5], "target": [0, 0, 0], "fov": 40}
    return common("%d mixed shapes" % (groups * 4), camera, children)


def write(folder, name, scene):
    path = os.path.join(folder, name)
    with open(path, "w") as out:
        json.dump(scene, out, indent=1 if len(json.dumps(scene)) < 200000 else None)
        out.write("\n")
    print("wrote", path)


def main():
    folder = os.path.join("samples", "bench")
    os.makedirs(folder, exist_ok=True)
    for n in (1, 10, 100, 1000, 10000):
        write(folder, "grid_%d.json" % n, grid_scene(n))
    for n in (256, 4096):
        write(folder, "tree_%d.json" % n, tree_scene(n))
    write(folder, "molecule_1000.json", molecule_scene(1000))
    write(folder, "mixed_1000.json", mixed_scene(1000))


if __name__ == "__main__":
    main()
