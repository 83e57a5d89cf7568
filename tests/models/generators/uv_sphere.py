#!/usr/bin/env python3
"""Writes a UV sphere with about TRIANGLES triangles as OBJ, ASCII/binary PLY or binary STL,
for load-time and memory measurements: uv_sphere.py TRIANGLES FORMAT OUT
(FORMAT: obj, ply, plyascii, stl)."""
import math
import struct
import sys


def sphere(triangles):
    rings = max(3, int(math.sqrt(triangles / 2)))
    segments = max(3, triangles // (2 * rings))
    vertices = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        t = math.pi * i / rings
        for j in range(segments):
            p = 2 * math.pi * j / segments
            vertices.append((math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)))
    vertices.append((0.0, 0.0, -1.0))
    faces = []
    last = len(vertices) - 1

    def ring(i, j):
        return 1 + (i - 1) * segments + j % segments

    for j in range(segments):
        faces.append((0, ring(1, j), ring(1, j + 1)))
        faces.append((last, ring(rings - 1, j + 1), ring(rings - 1, j)))
    for i in range(1, rings - 1):
        for j in range(segments):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            faces.append((a, b, c))
            faces.append((a, c, d))
    return vertices, faces


def main():
    triangles, fmt, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    vertices, faces = sphere(triangles)
    if fmt == "obj":
        with open(out, "w") as f:
            f.writelines(f"v {x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in vertices)
            f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in faces)
    elif fmt in ("ply", "plyascii"):
        binary = fmt == "ply"
        with open(out, "wb") as f:
            kind = "binary_little_endian" if binary else "ascii"
            f.write((f"ply\nformat {kind} 1.0\nelement vertex {len(vertices)}\n"
                     "property float x\nproperty float y\nproperty float z\n"
                     f"element face {len(faces)}\nproperty list uchar int vertex_indices\n"
                     "end_header\n").encode())
            if binary:
                f.write(b"".join(struct.pack("<3f", *v) for v in vertices))
                f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))
            else:
                f.write("".join(f"{x:.6f} {y:.6f} {z:.6f}\n" for x, y, z in vertices).encode())
                f.write("".join(f"3 {a} {b} {c}\n" for a, b, c in faces).encode())
    elif fmt == "stl":
        with open(out, "wb") as f:
            f.write(b"uv sphere".ljust(80, b" ") + struct.pack("<I", len(faces)))
            for t in faces:
                f.write(struct.pack("<3f", 0, 0, 0))
                for k in t:
                    f.write(struct.pack("<3f", *vertices[k]))
                f.write(b"\0\0")
    else:
        sys.exit("FORMAT must be obj, ply, plyascii or stl")


main()
