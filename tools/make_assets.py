#!/usr/bin/env python3
"""Writes the sample glTF assets into samples/assets/ (python3 standard library only).

Output is deterministic: running it twice produces identical files. The assets:
  plane.gltf            2x2 quad in the xz plane, normal +y, uvs
  cube.gltf             unit cube [-0.5, 0.5]^3, 24 vertices, flat normals
  sphere.gltf           UV sphere, radius 0.5, 64 segments x 32 rings, smooth normals, uvs
  checker_plane.gltf    the quad with an embedded 64x64 checkerboard PNG as base colour texture
  cube.glb              the cube as binary glTF (JSON + BIN chunk)
  cube_external.gltf    the cube with its buffer in cube_external.bin
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


if __name__ == "__main__":
    main()
