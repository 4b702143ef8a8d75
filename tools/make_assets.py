#!/usr/bin/env python3
"""Writes the sample glTF assets into samples/assets/ (python3 standard library only).

Output is deterministic: running it twice produces identical files. The assets:
  plane.gltf            2x2 quad in the xz plane, normal +y, uvs
  cube.gltf             unit cube [-0.5, 0.5]^3, 24 vertices, flat normals
  sphere.gltf           UV sphere, radius 0.5, 64 segments x 32 rings, smooth normals, uvs
  checker_plane.gltf    the quad with an embedded 64x64 checkerboard PNG as base colour texture
  cube.glb              the cube as binary glTF (JSON + BIN chunk)
  cube_external.gltf    the cube with its buffer in cube_external.bin
  textures/*.png        brick base colour (sRGB), its normal map and roughness map, a tile
                        colour map at another size, and the glTF test maps below
  textured_cube.gltf    the cube with every glTF texture kind: base colour, metallic-roughness,
                        normal (no TANGENT: tangents are generated), emissive with
                        KHR_materials_emissive_strength, occlusion read through TEXCOORD_1;
                        samplers with nearest / clamp / mirrored settings; images in textures/
Buffers are data URIs except for the .glb and the external one. Usage: tools/make_assets.py
"""

import base64
import json
import math
import pathlib
import struct
import zlib

OUT = pathlib.Path(__file__).resolve().parent.parent / "samples" / "assets"


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def orient(positions, triangles, outward):
    """Swaps triangles whose geometric normal disagrees with outward(centroid)."""
    result = []
    for a, b, c in triangles:
        pa, pb, pc = positions[a], positions[b], positions[c]
        n = cross(sub(pb, pa), sub(pc, pa))
        centroid = tuple((pa[i] + pb[i] + pc[i]) / 3.0 for i in range(3))
        result.append((a, c, b) if dot(n, outward(centroid)) < 0 else (a, b, c))
    return result


def plane_mesh():
    positions = [(-1.0, 0.0, -1.0), (1.0, 0.0, -1.0), (1.0, 0.0, 1.0), (-1.0, 0.0, 1.0)]
    normals = [(0.0, 1.0, 0.0)] * 4
    uvs = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    triangles = orient(positions, [(0, 1, 2), (0, 2, 3)], lambda c: (0.0, 1.0, 0.0))
    return positions, normals, uvs, triangles


def cube_mesh():
    positions, normals, uvs, triangles = [], [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            normal = [0.0, 0.0, 0.0]
            normal[axis] = sign
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            base = len(positions)
            for u, v in ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)):
                p = [0.0, 0.0, 0.0]
                p[axis] = 0.5 * sign
                p[u_axis] = u
                p[v_axis] = v
                positions.append(tuple(p))
                normals.append(tuple(normal))
                uvs.append((u + 0.5, v + 0.5))
            triangles += [(base, base + 1, base + 2), (base, base + 2, base + 3)]
    return positions, normals, uvs, orient(positions, triangles, lambda c: c)


def sphere_mesh(radius=0.5, segments=64, rings=32):
    positions, normals, uvs = [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2.0 * math.pi * s / segments
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            positions.append(tuple(radius * x for x in n))
            normals.append(n)
            uvs.append((s / segments, r / rings))
    triangles = []
    row = segments + 1
    for r in range(rings):
        for s in range(segments):
            a, b = r * row + s, r * row + s + 1
            c, d = (r + 1) * row + s, (r + 1) * row + s + 1
            if r != 0:
                triangles.append((a, c, b))
            if r != rings - 1:
                triangles.append((b, c, d))
    return positions, normals, uvs, orient(positions, triangles, lambda c: c)


def pad4(data, fill=b"\0"):
    return data + fill * ((4 - len(data) % 4) % 4)


def build_gltf(name, mesh, color, texture_png=None):
    """Returns (gltf dict, binary buffer) for one mesh with one material."""
    positions, normals, uvs, triangles = mesh
    chunks = [
        b"".join(struct.pack("<3f", *p) for p in positions),
        b"".join(struct.pack("<3f", *n) for n in normals),
        b"".join(struct.pack("<2f", *t) for t in uvs),
        b"".join(struct.pack("<3H", *t) for t in triangles),
    ]
    binary, views = b"", []
    for i, chunk in enumerate(chunks):
        view = {"buffer": 0, "byteOffset": len(binary), "byteLength": len(chunk)}
        view["target"] = 34963 if i == 3 else 34962
        views.append(view)
        binary = pad4(binary + chunk)
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    count = len(positions)
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3", "min": lo,
         "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": count, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": 3 * len(triangles), "type": "SCALAR"},
    ]
    material = {
        "name": name + "_material",
        "pbrMetallicRoughness": {"baseColorFactor": color, "metallicFactor": 0.0,
                                 "roughnessFactor": 0.5},
    }
    gltf = {
        "asset": {"version": "2.0", "generator": "rmsc tools/make_assets.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": name, "mesh": 0}],
        "meshes": [{"name": name, "primitives": [{
            "attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
            "material": 0}]}],
        "materials": [material],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary)}],
    }
    if texture_png is not None:
        material["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
        gltf["textures"] = [{"source": 0, "sampler": 0}]
        gltf["samplers"] = [{"magFilter": 9728, "minFilter": 9987}]
        gltf["images"] = [{"uri": "data:image/png;base64," +
                           base64.b64encode(texture_png).decode("ascii")}]
    return gltf, binary


def with_data_uri(gltf, binary):
    gltf["buffers"][0]["uri"] = ("data:application/octet-stream;base64," +
                                 base64.b64encode(binary).decode("ascii"))
    return gltf


def to_json(gltf):
    return json.dumps(gltf, separators=(",", ":"))


def checker_png(size=64, square=8):
    """A size x size RGB checkerboard PNG (light/dark squares of `square` pixels)."""
    rows = b""
    for y in range(size):
        row = b"\0"  # filter type: none
        for x in range(size):
            light = ((x // square) + (y // square)) % 2 == 0
            row += bytes((230, 230, 230)) if light else bytes((40, 40, 40))
        rows += row

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def png(width, height, pixel, channels=3):
    """A PNG of width x height; pixel(x, y) returns a tuple of `channels` bytes (0..255)."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter type: none
        for x in range(width):
            rows += bytes(max(0, min(255, int(round(c)))) for c in pixel(x, y))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    color_type = {1: 0, 3: 2, 4: 6}[channels]
    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def hash_noise(x, y, seed=0):
    """Deterministic value noise in [0, 1) per integer cell (an integer hash, no randomness)."""
    h = (x * 374761393 + y * 668265263 + seed * 2147483647) & 0xFFFFFFFF
    h = ((h ^ (h >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65536.0


BRICK_SIZE = 256  # the brick textures: 4 courses of 2 bricks, running bond, 256 x 256 pixels
BRICK_W, BRICK_H, MORTAR, BEVEL = 128, 64, 6, 6


def brick_cell(x, y):
    """(brick column, course, distance in pixels to the nearest mortar edge, dx, dy) where
    dx, dy point from the pixel to that edge (for the bevel's slope)."""
    course = y // BRICK_H
    shift = (BRICK_W // 2) * (course % 2)
    bx = (x + shift) % BRICK_SIZE
    column = bx // BRICK_W
    lx, ly = bx % BRICK_W, y % BRICK_H
    half = MORTAR / 2.0
    edges = [(lx + 0.5 - half, -1, 0), (BRICK_W - half - lx - 0.5, 1, 0),
             (ly + 0.5 - half, 0, -1), (BRICK_H - half - ly - 0.5, 0, 1)]
    distance, dx, dy = min(edges)
    return column, course, distance, dx, dy


def brick_height(x, y):
    """1 on a brick's face, falling over the bevel to 0 in the mortar."""
    distance = brick_cell(x % BRICK_SIZE, y % BRICK_SIZE)[2]
    return max(0.0, min(1.0, distance / BEVEL))


def brick_color(x, y):
    column, course, distance, _, _ = brick_cell(x, y)
    if distance <= 0:
        grain = 0.9 + 0.2 * hash_noise(x // 2, y // 2, 7)
        return tuple(c * grain for c in (200, 196, 186))  # mortar
    tone = hash_noise(column, course, 1)
    base = (150 + 50 * tone, 62 + 22 * tone, 44 + 12 * tone)
    speckle = 0.88 + 0.24 * hash_noise(x // 3, y // 3, 2)
    return tuple(c * speckle for c in base)


def brick_normal(x, y):
    """Tangent-space normal (+x right, +y up the image) of the brick height field, as RGB."""
    strength = 2.5
    hx = (brick_height(x + 1, y) - brick_height(x - 1, y)) * 0.5
    hy = (brick_height(x, y + 1) - brick_height(x, y - 1)) * 0.5  # image y grows downwards
    n = (-hx * strength, hy * strength, 1.0)
    length = math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    return tuple(127.5 + 127.5 * c / length for c in n)


def brick_roughness(x, y):
    """Roughness in the green channel (also red and blue: a grey image)."""
    if brick_cell(x, y)[2] <= 0:
        value = 245
    else:
        value = 150 + 60 * hash_noise(x // 4, y // 4, 3)
    return (value, value, value)


def tile_color(x, y, size=96, tile=24, grout=2):
    """Blue-and-cream tiles at 96 x 96 pixels (a size unlike the bricks')."""
    tx, ty = x % tile, y % tile
    if tx < grout or ty < grout:
        return (70, 70, 75)
    return (40, 90, 170) if ((x // tile) + (y // tile)) % 2 == 0 else (225, 215, 190)


def metal_rough(x, y, size=64):
    """glTF metallic-roughness map: B = metallic (left half metal), G = roughness (top to
    bottom 0.15 .. 1), R unused."""
    metallic = 255 if x < size // 2 else 0
    roughness = 38 + (255 - 38) * y / (size - 1)
    return (0, roughness, metallic)


def emissive_map(x, y, size=64):
    """sRGB emissive map: a glowing orange ring on black."""
    r = math.hypot(x + 0.5 - size / 2, y + 0.5 - size / 2)
    glow = max(0.0, 1.0 - abs(r - size * 0.3) / 3.0)
    return (255 * glow, 150 * glow, 40 * glow)


def occlusion_map(x, y, size=32):
    """Occlusion in red: darker towards the image's edges (cavity-like)."""
    edge = min(x, y, size - 1 - x, size - 1 - y) / (size / 2.0)
    value = 255 * (0.35 + 0.65 * min(1.0, edge * 2.0))
    return (value, value, value)


def textured_cube():
    """The cube with every glTF texture kind (see the module docstring); images in textures/."""
    mesh = cube_mesh()
    gltf, binary = build_gltf("textured_cube", mesh, [1.0, 1.0, 1.0, 1.0])
    uvs1 = b"".join(struct.pack("<2f", 1.0 - u, v) for u, v in mesh[2])  # TEXCOORD_1: mirrored
    gltf["bufferViews"].append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(uvs1),
                                "target": 34962})
    binary = pad4(binary + uvs1)
    gltf["accessors"].append({"bufferView": 4, "componentType": 5126, "count": len(mesh[0]),
                              "type": "VEC2"})
    gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_1"] = 4
    gltf["buffers"][0]["byteLength"] = len(binary)
    gltf["images"] = [{"uri": "textures/" + name} for name in (
        "bricks_color.png", "test_metal_rough.png", "bricks_normal.png", "test_emissive.png",
        "test_occlusion.png")]
    gltf["samplers"] = [
        {},                                                      # defaults: linear, repeat
        {"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071},  # nearest, clamp
        {"magFilter": 9729, "minFilter": 9985, "wrapS": 33648, "wrapT": 10497},  # mirrored
    ]
    gltf["textures"] = [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 1},
                        {"source": 2, "sampler": 2}, {"source": 3}, {"source": 4, "sampler": 0}]
    gltf["materials"][0] = {
        "name": "textured_cube_material",
        "pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 1.0,
            "roughnessFactor": 1.0, "baseColorTexture": {"index": 0},
            "metallicRoughnessTexture": {"index": 1}},
        "normalTexture": {"index": 2, "scale": 1.0},
        "emissiveTexture": {"index": 3},
        "emissiveFactor": [1.0, 1.0, 1.0],
        "occlusionTexture": {"index": 4, "texCoord": 1, "strength": 0.8},
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 2.0}},
    }
    gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    return with_data_uri(gltf, binary)


def write_textures():
    (OUT / "textures").mkdir(parents=True, exist_ok=True)
    write("textures/bricks_color.png", png(BRICK_SIZE, BRICK_SIZE, brick_color))
    write("textures/bricks_normal.png", png(BRICK_SIZE, BRICK_SIZE, brick_normal))
    write("textures/bricks_roughness.png", png(BRICK_SIZE, BRICK_SIZE, brick_roughness))
    write("textures/tiles_color.png", png(96, 96, tile_color))
    write("textures/test_metal_rough.png", png(64, 64, metal_rough))
    write("textures/test_emissive.png", png(64, 64, emissive_map))
    write("textures/test_occlusion.png", png(32, 32, occlusion_map))


def glb(gltf, binary):
    json_chunk = pad4(to_json(gltf).encode("utf-8"), b" ")
    bin_chunk = pad4(binary)
    length = 12 + 8 + len(json_chunk) + 8 + len(bin_chunk)
    return (struct.pack("<4sII", b"glTF", 2, length) +
            struct.pack("<II", len(json_chunk), 0x4E4F534A) + json_chunk +
            struct.pack("<II", len(bin_chunk), 0x004E4942) + bin_chunk)


def write(name, data):
    path = OUT / name
    path.write_bytes(data if isinstance(data, bytes) else data.encode("utf-8"))
    print(f"{path.relative_to(OUT.parent.parent)}: {path.stat().st_size} bytes")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    write("plane.gltf", to_json(with_data_uri(*build_gltf("plane", plane_mesh(),
                                                          [0.8, 0.8, 0.8, 1.0]))))
    write("cube.gltf", to_json(with_data_uri(*build_gltf("cube", cube_mesh(),
                                                         [0.8, 0.2, 0.2, 1.0]))))
    write("sphere.gltf", to_json(with_data_uri(*build_gltf("sphere", sphere_mesh(),
                                                           [0.2, 0.4, 0.8, 1.0]))))
    write("checker_plane.gltf",
          to_json(with_data_uri(*build_gltf("checker_plane", plane_mesh(), [1.0, 1.0, 1.0, 1.0],
                                            texture_png=checker_png()))))
    write("cube.glb", glb(*build_gltf("cube_glb", cube_mesh(), [0.2, 0.8, 0.3, 1.0])))
    gltf, binary = build_gltf("cube_external", cube_mesh(), [0.9, 0.7, 0.2, 1.0])
    gltf["buffers"][0]["uri"] = "cube_external.bin"
    write("cube_external.gltf", to_json(gltf))
    write("cube_external.bin", binary)
    write_textures()
    write("textured_cube.gltf", to_json(textured_cube()))


if __name__ == "__main__":
    main()
