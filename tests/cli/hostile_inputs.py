#!/usr/bin/env python3
"""The hostile-input corpus: small files that cost quadratic time, gigabytes of memory or
megabytes of messages when read naively, and malformed values that were reported as something
else. Each input is generated into OUTPUT_DIR and given to the rmsc command under a 2 GiB
address-space cap and a time cap. Each must end in a clear refusal (exit 1, the message naming
the file, the JSON pointer and the limit) or in the correct result, never in a signal, and print
a bounded amount (the diagnostics are capped, with "... and N more").

usage: hostile_inputs.py RMSC_BINARY OUTPUT_DIR [--time-factor F] [--only NAME] [--list]

Prints one line per input: its exit code, seconds and peak memory (for the figures in reports).
The time caps are hang guards with a wide margin: inputs that took quadratic time get 10 s
(they take about 1 s now, and took 14 to 40 s), the others 60 s; --time-factor multiplies them
(tools/sanitize.sh's slower build). Under AddressSanitizer (ASAN_OPTIONS set), which reserves
terabytes of address space, there is no address-space cap.
"""
import base64
import json
import os
import resource
import signal
import struct
import sys
import tempfile
import time
import zlib

RMSC, OUT = sys.argv[1], sys.argv[2]


def option(name, default):
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv else default


ONLY = option("--only", None)
TIME_FACTOR = float(option("--time-factor", "1"))
MEMORY_CAP = None if "ASAN_OPTIONS" in os.environ else 2 << 30  # bytes of address space
QUADRATIC_TIME_CAP = 10  # seconds, for the inputs that took quadratic time
TIME_CAP = 60            # seconds, for the others
OUTPUT_CAP = 200 * 1024  # bytes of stdout and stderr together
failures = []
cases = []


def case(name, args, code, has=(), files=None, time_cap=TIME_CAP):
    """An input: `files` maps names in the case's folder to bytes or text; `args` may use
    {dir}; the run must exit with `code` within `time_cap` seconds and its output contain every
    text of `has`."""
    cases.append((name, args, code, has, files or {}, time_cap))


def check(name, condition, detail):
    if not condition:
        failures.append(f"{name}: {detail}")
        print(f"FAIL {name}: {detail}")


# ---- generators ----

def data_uri(payload, media="application/octet-stream"):
    return f"data:{media};base64," + base64.b64encode(payload).decode()


def triangle_gltf(**extra):
    """One triangle mesh (node 0) in a data-URI buffer, plus `extra` top-level members."""
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    gltf = {
        "asset": {"version": "2.0"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": len(positions)}],
        "buffers": [{"byteLength": len(positions), "uri": data_uri(positions)}],
    }
    gltf.update(extra)
    return gltf


def png(width, height, rows=None):
    """An 8-bit greyscale PNG of zeros (compressed row by row, so 8192x8192 is 65 KB), or just
    a header and an empty image data chunk when `rows` is False."""
    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))
    header = chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
    if rows is False:
        data = zlib.compress(b"\0" * 64)
    else:
        packer = zlib.compressobj(9)
        row = b"\0" * (width + 1)
        data = b"".join(packer.compress(row) for _ in range(height)) + packer.flush()
    return b"\x89PNG\r\n\x1a\n" + header + chunk(b"IDAT", data) + chunk(b"IEND", b"")


def scene(**sections):
    return json.dumps(dict({"version": 1}, **sections))


# ---- 19.3: quadratic work ----

gltf = triangle_gltf()
gltf["scenes"][0]["nodes"] = [0] * 3000
case("roots-repeated-3000", ["validate", "{dir}/roots.gltf"], 1,
     ["roots.gltf: /scenes/0/nodes/1: /nodes/0 is listed 3000 times in the scene"],
     {"roots.gltf": json.dumps(gltf)})

gltf = triangle_gltf()
gltf["nodes"] = [{}] * 300000
gltf["scenes"][0]["nodes"] = list(range(300000))
case("roots-300000", ["validate", "{dir}/roots.gltf"], 0, ["ok"],
     {"roots.gltf": json.dumps(gltf)}, QUADRATIC_TIME_CAP)

gltf = triangle_gltf()
gltf["nodes"] = [{"mesh": 0}] * 200000
gltf["scenes"][0]["nodes"] = list(range(200000))
case("instances-200000", ["validate", "{dir}/instances.gltf"], 0, ["ok"],
     {"instances.gltf": json.dumps(gltf)}, QUADRATIC_TIME_CAP)

keys = ", ".join(f'"key{i}": {i}' for i in range(200000))
case("scene-keys-200000", ["validate", "{dir}/keys.json"], 0,
     ['keys.json: /key0: warning: unknown key "key0"', "... and 199900 more warnings"],
     {"keys.json": '{"version": 1, ' + keys + "}"}, QUADRATIC_TIME_CAP)

materials = {f"m{i}": {} for i in range(200000)}
case("scene-materials-200000", ["validate", "{dir}/materials.json"], 1,
     ["materials.json: /materials: the scene has 200000 materials; at most 4096"],
     {"materials.json": scene(materials=materials)}, QUADRATIC_TIME_CAP)

duplicates = ", ".join(f'"k{i % 100000}": 0' for i in range(200000))
case("scene-duplicate-keys-100000", ["validate", "{dir}/duplicates.json"], 1,
     ['duplicates.json: /camera/k0: duplicate key "k0"', "... and 99900 more errors"],
     {"duplicates.json": '{"version": 1, "camera": {' + duplicates + "}}"}, QUADRATIC_TIME_CAP)

# Each unknown name was compared with every material (2,000 nodes: 1.7 s; 20,000: 17 s); known
# names were looked up in a list.
nodes = [{"shape": "sphere", "material": "nosuch" if i % 2 else f"mat{i % 4096:04d}"}
         for i in range(40000)]
case("scene-unknown-material-20000", ["validate", "{dir}/unknown.json"], 1,
     ['unknown.json: /sdf/children/1/material: unknown material "nosuch"', "and 4032 more",
      "... and 19900 more errors"],
     {"unknown.json": scene(materials={f"mat{i:04d}": {} for i in range(4096)},
                            sdf={"op": "union", "children": nodes})}, QUADRATIC_TIME_CAP)

# ---- 19.4: tiny files that take gigabytes ----

gltf = triangle_gltf()
gltf["accessors"].append({"componentType": 5126, "count": (16 << 20) - 1, "type": "VEC3"})
gltf["meshes"] = [{"primitives": [{"attributes": {"POSITION": 1}}] * 64}]
case("accessor-16Mi-64-primitives", ["validate", "{dir}/vertices.gltf"], 1,
     ["vertices.gltf: /nodes/0: instancing /meshes/0 here brings the file's scene to "
      "1073741760 vertices, more than the 16777216 allowed per glTF file", "\"glTF vertices\""],
     {"vertices.gltf": json.dumps(gltf)})

gltf = triangle_gltf()
gltf["accessors"].append({"componentType": 5126, "count": (1 << 20) - 1, "type": "VEC3"})
gltf["meshes"] = [{"primitives": [{"attributes": {"POSITION": 1}}]}]
gltf["nodes"] = [{"mesh": 0}] * 40
gltf["scenes"][0]["nodes"] = list(range(40))
case("accessor-1Mi-instanced-40", ["validate", "{dir}/instanced.gltf"], 1,
     ["instanced.gltf: /nodes/16: instancing /meshes/0 here brings the file's scene to "
      "17825775 vertices"],
     {"instanced.gltf": json.dumps(gltf)})

big = png(8192, 8192)
gltf = triangle_gltf(images=[{"uri": "big.png"}] * 12)
case("image-8192-listed-12-times", ["validate", "{dir}/images.gltf"], 0, ["ok"],
     {"images.gltf": json.dumps(gltf), "big.png": big})

gltf = triangle_gltf(images=[{"uri": name} for name in ["a.png", "b.png", "c.png"]])
case("images-8192-3-distinct", ["validate", "{dir}/images.gltf"], 1,
     ["images.gltf: /images/2/uri: image \"c.png\": image is 8192x8192, which brings the "
      "file's images to 201326592 texels, more than the 134217728 allowed per glTF file",
      "\"glTF texels\""],
     {"images.gltf": json.dumps(gltf), "a.png": big, "b.png": big, "c.png": big})

gltf = triangle_gltf()
gltf["buffers"] += [{"byteLength": 400 << 20, "uri": "big.bin"}] * 3
case("buffer-400MiB-listed-3-times", ["validate", "{dir}/buffers.gltf"], 1,
     ["buffers.gltf: /buffers/3/byteLength: this buffer brings the file's buffers to "
      "1258291236 bytes, more than the 1073741824 allowed per glTF file",
      "\"glTF buffer bytes\""],
     {"buffers.gltf": json.dumps(gltf), "big.bin": ("sparse", 400 << 20)})

# ---- 19.7: the cost of a march step ----

def nested_repeats(depth):
    """A sphere in `depth` groups, each repeating its child with the neighbour check."""
    node = {"shape": "sphere", "radius": 0.2}
    for _ in range(depth):
        node = {"op": "union", "children": [node], "modifiers": [
            {"type": "repeat", "period": [1, 1, 1], "neighbours": True}]}
    return node


# 22 k instructions a step: 77 s for a 160x90 image before it was refused.
case("sdf-neighbour-repeats-4", ["validate", "{dir}/repeats.json"], 1,
     ["repeats.json: /sdf/children/0/children/0/children/0: the SDF objects cost up to 6.0 M "
      "instructions a pixel (23.4 k a march step times max_steps 256)",
      "\"SDF cost per pixel\""],
     {"repeats.json": scene(sdf=nested_repeats(4))})

# 150 twisted shapes: generated code of about 750 statements took 3.5 GB and 24 s to compile cold;
# drawn by the per-cell programs now (a 32x18 render: 0.8 GB).
twisted = [{"shape": "box", "half_extents": [0.2, 0.4, 0.2], "position": [i % 15, 0, i // 15],
            "modifiers": [{"type": "twist", "amount": 40, "radius": 0.5}]} for i in range(150)]
case("sdf-twist-150", ["validate", "{dir}/twist.json"], 0,
     ["twist.json: ok", "statements of generated code (drawn by its per-cell programs "
      "instead)"],
     {"twist.json": scene(camera={"position": [7, 6, -8], "target": [7, 0, 5]},
                          sdf={"op": "union", "children": twisted})})

# A buffer just under the 1 GiB file limit was held twice while loading (read into a string,
# copied into the importer's vector): 2.1 GB, over the 2 GiB cap. Read once: 1.1 GB.
gltf = triangle_gltf()
gltf["buffers"][0] = {"byteLength": (1 << 30) - 64, "uri": "big.bin"}
gltf["bufferViews"][0]["byteLength"] = 36
case("buffer-1GiB-read-once", ["validate", "{dir}/big.gltf"], 0, ["big.gltf: ok"],
     {"big.gltf": json.dumps(gltf), "big.bin": ("sparse", (1 << 30) - 64)})

# ---- 19.11: smaller defects ----

huge = png(60000, 60000, rows=False)
case("png-60000-texture", ["validate", "{dir}/texture.json"], 1,
     ["texture.json: /materials/m/base_color_texture/file",
      "image is 60000x60000, expected at most 8192 on each side"],
     {"texture.json": scene(materials={"m": {"base_color_texture": {"file": "huge.png"}}},
                            sdf={"shape": "sphere", "material": "m"}),
      "huge.png": huge})
case("png-60000-gltf-image", ["validate", "{dir}/image.gltf"], 1,
     ["image.gltf: /images/0/uri: image \"huge.png\": image is 60000x60000, expected at most 8192"],
     {"image.gltf": json.dumps(triangle_gltf(images=[{"uri": "huge.png"}])), "huge.png": huge})

sky = {"sky": {"type": "image", "file": "huge.png"}}
case("png-60000-sky", ["validate", "{dir}/sky.json"], 1,
     ["sky.json: /environment/sky/file: the sky image is 60000x60000, expected at most 8192"],
     {"sky.json": scene(environment=sky), "huge.png": huge})

# A decompression bomb: a few bytes stating 20000x20000 (1.6 GB of RGBA), which stb_image would
# describe and decode; refused from the header on every image path.
bomb = png(20000, 20000, rows=False)
case("png-bomb-20000-texture", ["validate", "{dir}/texture.json"], 1,
     ["texture.json: /materials/m/base_color_texture/file",
      "image is 20000x20000, expected at most 8192 on each side"],
     {"texture.json": scene(materials={"m": {"base_color_texture": {"file": "huge.png"}}},
                            sdf={"shape": "sphere", "material": "m"}),
      "huge.png": bomb})
case("png-bomb-20000-sky", ["validate", "{dir}/sky.json"], 1,
     ["sky.json: /environment/sky/file: the sky image is 20000x20000, expected at most 8192"],
     {"sky.json": scene(environment=sky), "huge.png": bomb})
case("png-bomb-20000-gltf-image", ["validate", "{dir}/image.gltf"], 1,
     ["image.gltf: /images/0/uri: image \"huge.png\": image is 20000x20000, expected at most"],
     {"image.gltf": json.dumps(triangle_gltf(images=[{"uri": "huge.png"}])), "huge.png": bomb})

case("camera-view-overflow", ["validate", "{dir}/camera.json"], 1,
     ["camera.json: /camera/target: target - position is too long for float arithmetic"],
     {"camera.json": scene(camera={"position": [3e38, 0, 0], "target": [-3e38, 0, 0]})})
case("camera-up-overflow", ["validate", "{dir}/camera.json"], 1,
     ["camera.json: /camera/up: the \"up\" vector is too long for float arithmetic"],
     {"camera.json": scene(camera={"position": [0, 0, 5], "target": [0, 0, 0],
                                   "up": [3e38, 3e38, 0]})})

gltf = triangle_gltf(extensionsUsed=["KHR_lights_punctual"],
                     extensions={"KHR_lights_punctual": {"lights": [{"intensity": 2}]}})
gltf["nodes"][0]["mesh"] = 5
case("light-without-type", ["validate", "{dir}/light.gltf"], 1,
     ["light.gltf: /extensions/KHR_lights_punctual/lights/0/type: expected \"directional\", "
      "\"point\" or \"spot\"", "light.gltf: /nodes/0/mesh: refers to meshes 5"],
     {"light.gltf": json.dumps(gltf)})

case("bench-frames-0", ["bench", "--frames", "0"], 2,
     ["rmsc bench: --frames: expected a whole number of timed frames from 1", "got '0'"])


# ---- running ----

def limits():
    if MEMORY_CAP:
        resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def run(args, time_cap):
    """Runs rmsc under the caps; returns (exit code or -signal, output, seconds, peak MiB)."""
    with tempfile.TemporaryFile() as output:
        start = time.monotonic()
        pid = os.fork()
        if pid == 0:
            try:
                limits()
                os.dup2(output.fileno(), 1)
                os.dup2(output.fileno(), 2)
                os.execv(RMSC, [RMSC] + args)
            finally:
                os._exit(127)
        while True:
            done, status, usage = os.wait4(pid, os.WNOHANG)
            if done:
                break
            if time.monotonic() - start > time_cap:
                os.kill(pid, signal.SIGKILL)
                done, status, usage = os.wait4(pid, 0)
                break
            time.sleep(0.02)
        seconds = time.monotonic() - start
        code = os.waitstatus_to_exitcode(status)
        output.seek(0)
        text = output.read().decode("utf-8", "replace")
    return code, text, seconds, usage.ru_maxrss / 1024, seconds > time_cap


if "--list" in sys.argv:
    print("\n".join(name for name, *_ in cases))
    sys.exit(0)
for name, args, code, has, files, time_cap in cases:
    if ONLY and name != ONLY:
        continue
    folder = os.path.join(OUT, name)
    os.makedirs(folder, exist_ok=True)
    for file, content in files.items():
        path = os.path.join(folder, file)
        if isinstance(content, tuple):  # ("sparse", size): a file of zeros taking no disk
            with open(path, "wb") as f:
                f.truncate(content[1])
            continue
        with open(path, "w" if isinstance(content, str) else "wb") as f:
            f.write(content)
    time_cap *= TIME_FACTOR
    got, text, seconds, peak, killed = run([a.format(dir=folder) for a in args], time_cap)
    print(f"{name}: exit {got}, {seconds:.2f} s, peak {peak:.0f} MiB, {len(text)} bytes of output")
    check(name, not killed, f"still running after the time cap of {time_cap:.0f} s; killed")
    check(name, got >= 0, f"killed by signal {-got}; output: {text[-600:]}")
    check(name, got == code, f"exit {got}, expected {code}; output: {text[:600]}")
    check(name, len(text.encode()) <= OUTPUT_CAP,
          f"{len(text)} bytes of output, expected at most {OUTPUT_CAP}: {text[:300]}")
    for want in has:
        check(name, want in text, f"output lacks {want!r}: {text[:600]}")

print(f"{len(cases)} inputs, {len(failures)} failures")
sys.exit(1 if failures else 0)
