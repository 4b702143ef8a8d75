#!/usr/bin/env python3
"""The installed package from outside the tree: `cmake --install` into a fresh prefix (only the
public headers, librmsc.a, the CMake package and the pkg-config file), samples/embed configured
and built against it with find_package(rmsc CONFIG), programs built with pkg-config alone (the
README's snippet and the complete C++ examples of docs/embedding.md, run with its Python ones),
and the sample's headless frame compared with `rmsc render` of the equivalent scene (the
sample's SDF objects with its cube placed as the sample draws it, lit by the sample's light).
The expected frame is rmsc's colour where the SDF objects are in front, the host's own shading
of the cube (from rmsc's normals) where it is, and the host's background elsewhere; tolerance
as the reference images (a pixel differs past 8/255 in a channel, at most 0.5% may). On a
mismatch it writes embed.actual.png, embed.expected.png and embed.diff.png to test-output/.

    test_embed.py RMSC_BINARY SOURCE_DIR BUILD_DIR [PYTHON]

PYTHON (default: this interpreter) runs the Python snippets.
"""
import json
import math
import os
import shutil
import struct
import subprocess
import sys
import zlib

import numpy

SIZE = (160, 120)
ANGLE = 30.0
# samples/embed/main.cpp's look.
MESH_COLOR = numpy.array([0.80, 0.80, 0.84])
LIGHT = numpy.array([0.3, 0.9, 0.5]) / numpy.linalg.norm([0.3, 0.9, 0.5])
LIGHT_INTENSITY = 3.0
BACKGROUND = numpy.array([0.10, 0.11, 0.13])


def run(command, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if result.returncode != 0:
        sys.exit("failed: %s\n%s%s" % (" ".join(command), result.stdout, result.stderr))
    return result


def read_png(path):
    """8-bit RGB or RGBA, non-interlaced PNG -> (height, width, 3) uint8."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    offset, idat = 8, b""
    while offset < len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and color_type in (2, 6) and interlace == 0, path
        elif kind == b"IDAT":
            idat += body
        offset += 12 + length
    channels = 3 if color_type == 2 else 4
    raw = zlib.decompress(idat)
    stride = width * channels
    out = numpy.zeros((height, stride), numpy.int32)
    previous = numpy.zeros(stride, numpy.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = numpy.frombuffer(raw, numpy.uint8, stride, y * (stride + 1) + 1).astype(numpy.int32)
        row = numpy.zeros(stride, numpy.int32)
        for x in range(stride):
            a = row[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 0:
                predictor = 0
            elif kind == 1:
                predictor = a
            elif kind == 2:
                predictor = b
            elif kind == 3:
                predictor = (a + b) // 2
            else:  # Paeth
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                predictor = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            row[x] = (line[x] + predictor) & 255
        out[y] = row
        previous = row
    return out.reshape(height, width, channels)[:, :, :3].astype(numpy.uint8)


def write_png(path, pixels):
    height, width, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[y].astype(numpy.uint8).tobytes() for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                  + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def read_pfm(path):
    """PFM (bottom row first) -> (height, width[, 3]) float32, top row first."""
    data = open(path, "rb").read()
    header, rest = data.split(b"\n", 1)
    dims, rest = rest.split(b"\n", 1)
    scale, rest = rest.split(b"\n", 1)
    width, height = (int(v) for v in dims.split())
    channels = 3 if header.strip() == b"PF" else 1
    dtype = "<f4" if float(scale) < 0 else ">f4"
    values = numpy.frombuffer(rest, dtype, width * height * channels)
    shape = (height, width, channels) if channels == 3 else (height, width)
    return values.reshape(shape)[::-1]


def readme_snippets(readme):
    """The ```cpp and ```python blocks of the README's "Use rmsc from your code" section."""
    text = open(readme).read()
    section = text.split("## Use rmsc from your code", 1)[1].split("\n## ", 1)[0]
    blocks = {}
    for language in ("cpp", "python"):
        start = section.index("```" + language + "\n") + len(language) + 4
        blocks[language] = section[start:section.index("```", start)]
    return blocks["cpp"], blocks["python"]


def doc_examples(path):
    """The complete examples of a Markdown file: its ```cpp blocks with a main() and its ```python
    blocks that import rmsc."""
    text = open(path).read()
    examples = []
    for language, needle in (("cpp", "int main("), ("python", "import rmsc")):
        for block in text.split("```" + language + "\n")[1:]:
            code = block[:block.index("```")]
            if needle in code:
                examples.append((language, code))
    return examples


def project_version(source):
    for line in open(os.path.join(source, "CMakeLists.txt")):
        if line.startswith("project(rmsc VERSION "):
            return line.split()[2]
    raise AssertionError("no project version")


def main():
    rmsc, source, build = sys.argv[1:4]
    python_interpreter = sys.argv[4] if len(sys.argv) > 4 else sys.executable
    out = os.path.join(build, "test-output", "embed")
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    prefix = os.path.join(out, "prefix")

    # Install: only the public headers, the library, the CMake package and pkg-config.
    run(["cmake", "--install", build, "--prefix", prefix])
    installed = sorted(os.path.relpath(os.path.join(d, f), prefix)
                       for d, _, files in os.walk(prefix) for f in files)
    unexpected = [p for p in installed if not (
        (p.startswith("include/rmsc/") and p.endswith(".hpp")) or p == "lib/librmsc.a"
        or p.startswith("lib/cmake/rmsc/") or p == "lib/pkgconfig/rmsc.pc")]
    assert not unexpected, "installed more than the package: %s" % unexpected
    assert "include/rmsc/rmsc.hpp" in installed and "lib/cmake/rmsc/rmscConfigVersion.cmake" in installed

    # The README's snippets, exactly as printed: the C++ one built with pkg-config alone
    # against the prefix, the Python one with the built module; both run from the repository.
    cpp, python = readme_snippets(os.path.join(source, "README.md"))
    snippet = os.path.join(out, "readme_snippet.cpp")
    with open(snippet, "w") as f:
        f.write(cpp)
    env = dict(os.environ, PKG_CONFIG_PATH=os.path.join(prefix, "lib", "pkgconfig"))
    flags = run(["pkg-config", "--cflags", "--libs", "rmsc"], env=env).stdout.split()
    run(["g++", snippet, "-o", os.path.join(out, "readme_snippet")] + flags)
    printed = run([os.path.join(out, "readme_snippet")], cwd=source).stdout
    assert printed.startswith("rmsc %s: view depth at the centre " % project_version(source)), printed
    printed = run([python_interpreter, "-c", python], cwd=source,
                  env=dict(os.environ, PYTHONPATH=os.path.join(build, "python"),
                           PYTHONDONTWRITEBYTECODE="1")).stdout
    assert printed.strip() == "(180, 320, 3) uint8 float32 []", printed

    # docs/embedding.md's complete examples, as printed, the same way.
    examples = doc_examples(os.path.join(source, "docs", "embedding.md"))
    assert sum(1 for language, _ in examples if language == "cpp") >= 2, "no C++ examples found"
    for number, (language, code) in enumerate(examples):
        if language == "cpp":
            path = os.path.join(out, "doc_example_%d.cpp" % number)
            with open(path, "w") as f:
                f.write(code)
            run(["g++", path, "-o", path[:-4]] + flags)
            run([path[:-4]], cwd=source)
        else:
            run([python_interpreter, "-c", code], cwd=source,
                env=dict(os.environ, PYTHONPATH=os.path.join(build, "python"),
                         PYTHONDONTWRITEBYTECODE="1"))

    # The sample, configured and built against the installed package only.
    sample_build = os.path.join(out, "build")
    run(["cmake", "-S", os.path.join(source, "samples", "embed"), "-B", sample_build,
         "-DCMAKE_PREFIX_PATH=" + prefix, "-DCMAKE_BUILD_TYPE=Release"])
    run(["cmake", "--build", sample_build, "-j2"])
    actual_path = os.path.join(out, "frame.png")
    run([os.path.join(sample_build, "rmsc_embed"), "--headless", actual_path,
         "--size", "%dx%d" % SIZE, "--angle", str(ANGLE)])

    # The equivalent scene: the sample's SDF objects and its cube, where the sample draws it.
    with open(os.path.join(source, "samples", "embed", "scene.json")) as f:
        scene = json.load(f)
    scene["meshes"] = [{"file": os.path.join(source, "samples", "assets", "cube.gltf"),
                        "rotation": [0, ANGLE, 0]}]
    # The sample lights the SDF objects with its own light (drawInto's host lights).
    scene["lights"] = [{"type": "directional", "direction": [float(-v) for v in LIGHT],
                        "intensity": LIGHT_INTENSITY}]
    equivalent = os.path.join(out, "equivalent.json")
    with open(equivalent, "w") as f:
        json.dump(scene, f)
    del scene["sdf"]
    mesh_only = os.path.join(out, "mesh_only.json")
    with open(mesh_only, "w") as f:
        json.dump(scene, f)
    size = "%dx%d" % SIZE
    run([rmsc, "render", equivalent, "-o", os.path.join(out, "rmsc.png"), "--size", size])
    run([rmsc, "render", equivalent, "-o", os.path.join(out, "depth.pfm"), "--size", size, "--aov", "depth"])
    run([rmsc, "render", mesh_only, "-o", os.path.join(out, "mesh_depth.pfm"), "--size", size, "--aov", "depth"])
    run([rmsc, "render", mesh_only, "-o", os.path.join(out, "mesh_normal.pfm"), "--size", size, "--aov", "normal"])
    rendered = read_png(os.path.join(out, "rmsc.png")).astype(numpy.int32)
    depth = read_pfm(os.path.join(out, "depth.pfm"))
    mesh_depth = read_pfm(os.path.join(out, "mesh_depth.pfm"))
    mesh_normal = read_pfm(os.path.join(out, "mesh_normal.pfm"))

    mesh = mesh_depth < 1e29
    sdf = depth < mesh_depth - 1e-4  # the SDF objects are in front (or alone)
    shade = 0.55 + 0.45 * numpy.maximum(mesh_normal @ LIGHT, 0.0)
    host_mesh = numpy.rint(MESH_COLOR[None, None, :] * shade[:, :, None] * 255.0)
    expected = numpy.where(sdf[:, :, None], rendered,
                           numpy.where(mesh[:, :, None], host_mesh,
                                       numpy.rint(BACKGROUND * 255.0)[None, None, :]))
    actual = read_png(actual_path).astype(numpy.int32)
    assert actual.shape == expected.shape, (actual.shape, expected.shape)
    differing = (numpy.abs(actual - expected) > 8).any(axis=2)
    share = differing.mean()
    print("SDF pixels %d, mesh pixels %d, differing %d (%.3f%%)" %
          (sdf.sum(), (mesh & ~sdf).sum(), differing.sum(), 100 * share))
    assert sdf.sum() > 500 and (mesh & ~sdf).sum() > 500, "the frame should show both"
    if share > 0.005:
        outputs = os.path.join(build, "test-output")
        write_png(os.path.join(outputs, "embed.actual.png"), actual)
        write_png(os.path.join(outputs, "embed.expected.png"), expected)
        diff = numpy.where(differing[:, :, None], numpy.array([255, 0, 0]), actual // 3)
        write_png(os.path.join(outputs, "embed.diff.png"), diff)
        sys.exit("the sample's frame differs from rmsc render in %.3f%% of pixels (allowed 0.5%%); "
                 "see test-output/embed.*.png" % (100 * share))
    print("ok")


if __name__ == "__main__":
    main()
