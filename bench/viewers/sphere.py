#!/usr/bin/env python3
"""Writes the viewer benchmark's spheres: a UV sphere of about 10,000 triangles with
vertex normals, in a glossy gold material (sphere.obj) and in glass at half opacity
(glass.obj), with their MTL files, into the folder given (default: the current one).

    python3 bench/viewers/sphere.py OUT_DIR
"""
import math
import os
import sys

RINGS, SEGMENTS = 70, 72


def sphere(material):
    lines = [f"mtllib {material}.mtl", f"usemtl {material}"]
    for i in range(RINGS + 1):
        th = math.pi * i / RINGS
        for j in range(SEGMENTS):
            ph = 2 * math.pi * j / SEGMENTS
            x, y, z = math.sin(th) * math.cos(ph), math.cos(th), math.sin(th) * math.sin(ph)
            lines.append(f"v {x:.6f} {y:.6f} {z:.6f}")
            lines.append(f"vn {x:.6f} {y:.6f} {z:.6f}")

    def at(i, j):
        return i * SEGMENTS + j % SEGMENTS + 1

    for i in range(RINGS):
        for j in range(SEGMENTS):
            a, b, c, d = at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)
            if i > 0:
                lines.append(f"f {a}//{a} {b}//{b} {c}//{c}")
            if i < RINGS - 1:
                lines.append(f"f {a}//{a} {c}//{c} {d}//{d}")
    return "\n".join(lines) + "\n"


out = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out, exist_ok=True)
materials = {
    "gold": "Kd 0.8 0.6 0.2\nKs 0.6 0.6 0.6\nNs 40\n",
    "glass": "Kd 0.3 0.5 0.8\nKs 0.6 0.6 0.6\nNs 40\nd 0.5\n",
}
for name, obj in (("sphere", "gold"), ("glass", "glass")):
    with open(os.path.join(out, f"{name}.obj"), "w") as f:
        f.write(sphere(obj))
    with open(os.path.join(out, f"{obj}.mtl"), "w") as f:
        f.write(f"newmtl {obj}\n{materials[obj]}")
