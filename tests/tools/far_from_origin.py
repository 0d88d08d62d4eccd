"""edgelight-render draws a tetrahedron 1e7 from the origin as it draws it at the origin (the
camera framed on each): the same PNG, pixel for pixel. Drawn in world coordinates, single
precision kept one unit of 1e7 and the part became a sliver a pixel or two wide.

    python3 far_from_origin.py EDGELIGHT_RENDER OUT_DIR
"""
import os
import subprocess
import sys
import zlib


def png_rows(path):
    """The raw scanlines of an 8-bit PNG (filter bytes included): equal images, equal bytes."""
    data = open(path, "rb").read()
    chunks, at = [], 8
    while at < len(data):
        n = int.from_bytes(data[at:at + 4], "big")
        if data[at + 4:at + 8] == b"IDAT":
            chunks.append(data[at + 8:at + 8 + n])
        at += 12 + n
    return zlib.decompress(b"".join(chunks))


def main(tool, out):
    os.makedirs(out, exist_ok=True)
    faces = "f 1 2 3\nf 1 2 4\nf 2 3 4\nf 1 3 4\n"
    images = []
    for offset in (0, 10_000_000):
        obj = os.path.join(out, f"tetra_{offset}.obj")
        with open(obj, "w") as f:
            for v in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)):
                f.write("v " + " ".join(str(c + offset) for c in v) + "\n")
            f.write(faces)
        png = os.path.join(out, f"tetra_{offset}.png")
        subprocess.run([tool, obj, "--out", png, "--size", "200x150", "--samples", "1"], check=True)
        images.append(png_rows(png))
    differ = sum(a != b for a, b in zip(*images)) + abs(len(images[0]) - len(images[1]))
    print(f"far from the origin: {differ} bytes differ from the part at the origin")
    if differ:
        sys.exit(1)


if __name__ == "__main__":
    main(*sys.argv[1:])
