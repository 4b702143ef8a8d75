#!/usr/bin/env python3
"""Writes the seed inputs of the fuzz_gltf_accessors harness into tests/fuzz/seeds/gltf_accessors.

The harness reads its input with libFuzzer's FuzzedDataProvider: integers from the end of the
bytes (the most significant byte last in the file, as few bytes as the range needs), strings from
the front. Tape records the choices a seed makes, call by call in the harness's order, and lays
them out so the harness reads them back: each seed is a small glTF the importer should load (a
triangle, an indexed quad, interleaved attributes, a textured triangle, a strip drawn twice) or one
it must refuse (a sparse accessor, not supported; within the harness's budget, a zero-filled
accessor of 16 Mi vertices and a PNG header stating 65536x65536). Run it again after changing the order of the harness's reads.
"""
import os
import struct
import sys
import zlib

COMPONENTS = [5120, 5121, 5122, 5123, 5125, 5126, 5124, 0]
TYPES = ["SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4", "VEC5"]
SIZES = [1, 2, 3, 16, 255, 1024, 8193, 65536]
DEPTHS = [1, 2, 4, 8, 16]
COLOURS = [0, 2, 3, 4, 6]
EDGES = [0, 1, 3, 4, 255, 256, 65536, 1 << 24, 1 << 31, -1]
ATTRIBUTES = ["NORMAL", "TANGENT", "TEXCOORD_0", "COLOR_0", "TEXCOORD_1"]


class Tape:
    def __init__(self):
        self.front = bytearray()
        self.back = bytearray()  # in the order the harness reads it

    def integer(self, lo, hi, value):
        assert lo <= value <= hi, (lo, hi, value)
        span, offset = hi - lo, value - lo
        count = (span.bit_length() + 7) // 8
        self.back += offset.to_bytes(count, "big") if count else b""

    def boolean(self, value):
        self.integer(0, 255, 1 if value else 0)

    def pick(self, values, value):
        self.integer(0, len(values) - 1, values.index(value))

    def string(self, data):
        self.front += data

    def size(self, value):  # the harness's size(): small, or one of its edges
        if 0 <= value <= 64:
            self.boolean(True)
            self.integer(0, 64, value)
        else:
            self.boolean(False)
            self.pick(EDGES, value)

    def reference(self, count, index):  # -1 for none
        self.integer(-1, count, index)

    def bytes(self):
        return bytes(self.front) + bytes(reversed(self.back))


def png(tape, width, height, rgba_rows):
    """An 8-bit RGBA PNG header stating width x height, its IDAT holding rgba_rows."""
    for value in (width, height):
        tape.boolean(True)
        tape.pick(SIZES, value)
    tape.pick(DEPTHS, 8)
    tape.pick(COLOURS, 6)
    tape.integer(0, 1, 0)  # not interlaced
    tape.boolean(False)  # no palette
    raw = b"".join(b"\0" + row for row in rgba_rows)
    tape.integer(0, 512, len(raw))
    tape.string(raw)


def view(tape, offset, length, stride=None, whole=False):
    """A view of buffer 0 from `offset` bytes after the images (the accessors' data)."""
    tape.integer(0, 1, 0)  # buffer 0
    tape.boolean(True)  # the offset counts from the data's start
    tape.size(offset)
    tape.boolean(whole)  # the rest of the data
    if not whole:
        tape.size(length)
    tape.boolean(stride is not None)
    if stride is not None:
        tape.integer(0, 260, stride)
    tape.boolean(False)  # no target


def accessor(tape, views, component, count, type_, view_index, offset=None, bounds=False,
             sparse=None):
    tape.pick(COMPONENTS, component)
    tape.size(count)
    tape.pick(TYPES, type_)
    tape.boolean(False)
    tape.reference(views, view_index)
    tape.boolean(offset is not None)
    if offset is not None:
        tape.size(offset)
    tape.boolean(False)  # normalized left out
    tape.boolean(bounds)
    tape.boolean(sparse is not None)
    if sparse is not None:
        count, index_view, index_component, value_view = sparse
        tape.reference(views, index_view)
        tape.pick(COMPONENTS, index_component)
        tape.reference(views, value_view)
        tape.boolean(False)
        tape.boolean(False)
        tape.size(count)


def primitive(tape, accessors, position, attributes=(), indices=-1, mode=None, material=None):
    tape.integer(0, accessors - 1, position)
    chosen = dict(attributes)
    for name in ATTRIBUTES:
        tape.boolean(name in chosen)
        if name in chosen:
            tape.reference(accessors, chosen[name])
    tape.reference(accessors, indices)
    tape.boolean(mode is not None)
    if mode is not None:
        tape.integer(0, 7, mode)
    if material is not None:
        tape.boolean(material)


def floats(*values):
    return struct.pack("<%df" % len(values), *values)


TRIANGLE = floats(0, 0, 0, 1, 0, 0, 0, 1, 0)


def seed_triangle():
    tape = Tape()
    tape.integer(0, 3, 0)  # no images
    tape.integer(0, 1024, len(TRIANGLE))
    tape.string(TRIANGLE)
    tape.boolean(True)  # byteLength: the data's length
    tape.integer(1, 4, 1)
    view(tape, 0, 0, whole=True)
    tape.integer(1, 6, 1)
    accessor(tape, 1, 5126, 3, "VEC3", 0, bounds=True)
    tape.integer(1, 3, 1)
    primitive(tape, 1, 0)
    tape.boolean(False)  # one node
    return tape.bytes()


def seed_indexed_quad():
    data = floats(0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) + struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    tape = Tape()
    tape.integer(0, 3, 0)
    tape.integer(0, 1024, len(data))
    tape.string(data)
    tape.boolean(True)
    tape.integer(1, 4, 2)
    view(tape, 0, 48)
    view(tape, 48, 12)
    tape.integer(1, 6, 2)
    accessor(tape, 2, 5126, 4, "VEC3", 0, bounds=True)
    accessor(tape, 2, 5123, 6, "SCALAR", 1)
    tape.integer(1, 3, 1)
    primitive(tape, 2, 0, indices=1)
    tape.boolean(False)
    return tape.bytes()


def seed_interleaved():
    # Position and normal interleaved, stride 24; the normals read at byteOffset 12.
    data = b"".join(floats(x, y, 0, 0, 0, 1) for x, y in ((0, 0), (1, 0), (0, 1)))
    tape = Tape()
    tape.integer(0, 3, 0)
    tape.integer(0, 1024, len(data))
    tape.string(data)
    tape.boolean(True)
    tape.integer(1, 4, 1)
    view(tape, 0, 0, stride=24, whole=True)
    tape.integer(1, 6, 2)
    accessor(tape, 1, 5126, 3, "VEC3", 0, bounds=True)
    accessor(tape, 1, 5126, 3, "VEC3", 0, offset=12)
    tape.integer(1, 3, 1)
    primitive(tape, 2, 0, attributes=[("NORMAL", 1)])
    tape.boolean(False)
    return tape.bytes()


def seed_sparse():
    # Three zero positions (no buffer view) with two of them replaced through a sparse part.
    data = struct.pack("<2H", 1, 2) + floats(1, 0, 0, 0, 1, 0)
    tape = Tape()
    tape.integer(0, 3, 0)
    tape.integer(0, 1024, len(data))
    tape.string(data)
    tape.boolean(True)
    tape.integer(1, 4, 2)
    view(tape, 0, 4)
    view(tape, 4, 24)
    tape.integer(1, 6, 1)
    accessor(tape, 2, 5126, 3, "VEC3", -1, bounds=True, sparse=(2, 0, 5123, 1))
    tape.integer(1, 3, 1)
    primitive(tape, 1, 0)
    tape.boolean(False)
    return tape.bytes()


def seed_textured():
    rows = [bytes([255, 0, 0, 255, 0, 255, 0, 255]), bytes([0, 0, 255, 255, 255, 255, 255, 255])]
    uv = floats(0, 0, 1, 0, 0, 1)
    tape = Tape()
    tape.integer(0, 3, 1)
    png(tape, 2, 2, rows)
    tape.integer(0, 1024, len(TRIANGLE) + len(uv))
    tape.string(TRIANGLE + uv)
    tape.boolean(True)
    tape.integer(1, 4, 2)
    view(tape, 0, 36)
    view(tape, 36, 24)
    tape.integer(1, 6, 2)
    accessor(tape, 3, 5126, 3, "VEC3", 1, bounds=True)
    accessor(tape, 3, 5126, 3, "VEC2", 2)
    tape.integer(0, 0, 0)  # the texture's source
    tape.boolean(True)  # base colour texture
    tape.integer(0, 0, 0)
    for _ in range(4):  # metallic-roughness, normal, emissive, occlusion: none
        tape.boolean(False)
    tape.integer(1, 3, 1)
    primitive(tape, 2, 0, attributes=[("TEXCOORD_0", 1)], material=True)
    tape.boolean(False)
    return tape.bytes()


def seed_strip_twice():
    data = floats(0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0)
    tape = Tape()
    tape.integer(0, 3, 0)
    tape.integer(0, 1024, len(data))
    tape.string(data)
    tape.boolean(True)
    tape.integer(1, 4, 1)
    view(tape, 0, 0, whole=True)
    tape.integer(1, 6, 1)
    accessor(tape, 1, 5126, 4, "VEC3", 0, bounds=True)
    tape.integer(1, 3, 1)
    primitive(tape, 1, 0, mode=5)  # a triangle strip
    tape.boolean(True)  # a second node: the mesh instanced twice
    return tape.bytes()


def seed_zero_accessor_bomb():
    # 16 Mi vertices without a buffer view: nothing in the file, over the harness's budget.
    tape = Tape()
    tape.integer(0, 3, 0)
    tape.integer(0, 1024, len(TRIANGLE))
    tape.string(TRIANGLE)
    tape.boolean(True)
    tape.integer(1, 4, 1)
    view(tape, 0, 0, whole=True)
    tape.integer(1, 6, 1)
    accessor(tape, 1, 5126, 1 << 24, "VEC3", -1)
    tape.integer(1, 3, 1)
    primitive(tape, 1, 0)
    tape.boolean(False)
    return tape.bytes()


def seed_png_bomb():
    # A PNG header of 65536 x 65536 (16 GiB of RGBA) in a few bytes.
    tape = Tape()
    tape.integer(0, 3, 1)
    png(tape, 65536, 65536, [b"\0" * 8])
    tape.integer(0, 1024, len(TRIANGLE))
    tape.string(TRIANGLE)
    tape.boolean(True)
    tape.integer(1, 4, 1)
    view(tape, 0, 0, whole=True)
    tape.integer(1, 6, 1)
    accessor(tape, 2, 5126, 3, "VEC3", 1, bounds=True)
    tape.integer(0, 0, 0)
    tape.boolean(True)
    tape.integer(0, 0, 0)
    for _ in range(4):
        tape.boolean(False)
    tape.integer(1, 3, 1)
    primitive(tape, 1, 0, material=True)
    tape.boolean(False)
    return tape.bytes()


SEEDS = {
    "triangle": seed_triangle,
    "indexed-quad": seed_indexed_quad,
    "interleaved": seed_interleaved,
    "sparse": seed_sparse,
    "textured": seed_textured,
    "strip-twice": seed_strip_twice,
    "zero-accessor-bomb": seed_zero_accessor_bomb,
    "png-bomb": seed_png_bomb,
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "seeds", "gltf_accessors")
    os.makedirs(out, exist_ok=True)
    for name, make in SEEDS.items():
        with open(os.path.join(out, name + ".bin"), "wb") as f:
            f.write(make())
    print("wrote %d seeds to %s" % (len(SEEDS), out))


if __name__ == "__main__":
    main()
