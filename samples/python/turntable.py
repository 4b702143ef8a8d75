#!/usr/bin/env python3
"""Renders a turntable of a scene with the rmsc Python module: the camera circles the scene's
target at its own height and distance, one PNG file per frame.

    PYTHONPATH=build/python python3 samples/python/turntable.py samples/scenes/pawn.json out/ \
        --frames 36 --size 320x180
"""
import argparse
import math
import os
import struct
import zlib

import rmsc


def write_png(path, pixels):
    """Writes an (height, width, 3) uint8 array as an 8-bit RGB PNG (no filter, zlib)."""
    height, width, _ = pixels.shape
    raw = b"".join(b"\x00" + pixels[y].tobytes() for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        out.write(chunk(b"IEND", b""))


def turntable(scene_path, out_dir, frames, size):
    """Renders `frames` views around the scene's camera target into out_dir/frame_NNN.png and
    returns the paths written."""
    scene = rmsc.Scene.load(scene_path)
    position = scene.get("/camera/position")
    target = scene.get("/camera/target") if "target" in scene.get("/camera") else [0, 0, 0]
    dx, dz = position[0] - target[0], position[2] - target[2]
    radius, start = math.hypot(dx, dz), math.atan2(dx, dz)
    os.makedirs(out_dir, exist_ok=True)
    paths = []
    for frame in range(frames):
        angle = start + 2.0 * math.pi * frame / frames
        scene.set("/camera/position", [target[0] + radius * math.sin(angle), position[1],
                                       target[2] + radius * math.cos(angle)])
        path = os.path.join(out_dir, "frame_%03d.png" % frame)
        write_png(path, scene.render(size=size, aov="color"))
        paths.append(path)
    return paths


def main():
    """Command line: SCENE OUT_DIR [--frames N] [--size WxH]."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("out_dir")
    parser.add_argument("--frames", type=int, default=36)
    parser.add_argument("--size", default="320x180", help="WxH")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    for path in turntable(args.scene, args.out_dir, args.frames, (width, height)):
        print(path)


if __name__ == "__main__":
    main()
