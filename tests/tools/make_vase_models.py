#!/usr/bin/env python3
"""Writes the generated models of tests/models/real: a y-up vase (a surface of
revolution, open at the top, closed at the foot) as glTF 2.0 with an external
.bin buffer and two coloured materials, and as an ASCII PLY with vertex
colours. Deterministic: re-running gives the same bytes.

Usage: make_vase_models.py [OUTPUT_DIRECTORY]   (default: tests/models/real)
"""
import json
import math
import os
import struct
import sys

SEGMENTS = 24  # around the axis
RINGS = 14  # up the profile
HEIGHT = 2.0


def radius_at(t):
    """Profile radius at height fraction t in [0, 1]: foot, belly, neck, lip."""
    return 0.32 + 0.38 * math.sin(math.pi * (0.15 + 0.85 * t)) ** 2 - 0.12 * t + 0.1 * t**6


def vase():
    """Vertices (x, y, z) and outward faces (counter-clockwise seen from outside)."""
    vertices = []
    for ring in range(RINGS + 1):
        t = ring / RINGS
        r = radius_at(t)
        for s in range(SEGMENTS):
            a = 2.0 * math.pi * s / SEGMENTS
            vertices.append((round(r * math.cos(a), 6), round(HEIGHT * t, 6), round(-r * math.sin(a), 6)))
    body = []
    for ring in range(RINGS):
        for s in range(SEGMENTS):
            a = ring * SEGMENTS + s
            b = ring * SEGMENTS + (s + 1) % SEGMENTS
            # Angle grows counter-clockwise seen from +y; up and around gives an outward normal.
            body.append((a, b, b + SEGMENTS, a + SEGMENTS))
    foot = [tuple(reversed(range(SEGMENTS)))]  # seen from below (-y), counter-clockwise
    return vertices, body, foot


def check_outward(vertices, faces, outward):
    for face in faces:
        p = [vertices[i] for i in face]
        n = [0.0, 0.0, 0.0]
        for i in range(len(p)):  # Newell's normal
            q, r = p[i], p[(i + 1) % len(p)]
            n[0] += (q[1] - r[1]) * (q[2] + r[2])
            n[1] += (q[2] - r[2]) * (q[0] + r[0])
            n[2] += (q[0] - r[0]) * (q[1] + r[1])
        c = [sum(v[k] for v in p) / len(p) for k in range(3)]
        assert sum(a * b for a, b in zip(n, outward(c))) > 0.0, face


def triangles(faces):
    for face in faces:
        for i in range(1, len(face) - 1):
            yield (face[0], face[i], face[i + 1])


def write_gltf(directory, vertices, body, foot):
    name = "vase_y_up"
    positions = b"".join(struct.pack("<3f", *v) for v in vertices)
    parts = [list(triangles(body)), list(triangles(foot))]
    index_blobs = [b"".join(struct.pack("<3H", *t) for t in part) for part in parts]
    buffer = positions + b"".join(index_blobs)
    with open(os.path.join(directory, name + ".bin"), "wb") as out:
        out.write(buffer)
    views = [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions), "target": 34962}]
    offset = len(positions)
    for blob in index_blobs:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(blob), "target": 34963})
        offset += len(blob)
    low = [min(v[k] for v in vertices) for k in range(3)]
    high = [max(v[k] for v in vertices) for k in range(3)]
    accessors = [{"bufferView": 0, "componentType": 5126, "count": len(vertices), "type": "VEC3",
                  "min": low, "max": high}]
    for i, part in enumerate(parts):
        accessors.append({"bufferView": i + 1, "componentType": 5123, "count": 3 * len(part),
                          "type": "SCALAR"})
    document = {
        "asset": {"version": "2.0", "generator": "termshade tests/tools/make_vase_models.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "vase"}],
        "meshes": [{"name": "vase", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
            {"attributes": {"POSITION": 0}, "indices": 2, "material": 1}]}],
        "materials": [
            {"name": "glaze", "pbrMetallicRoughness": {"baseColorFactor": [0.15, 0.35, 0.75, 1.0]}},
            {"name": "foot", "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.6, 0.2, 1.0]}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"uri": name + ".bin", "byteLength": len(buffer)}],
    }
    with open(os.path.join(directory, name + ".gltf"), "w", encoding="ascii") as out:
        json.dump(document, out, indent=1)
        out.write("\n")


def write_ply(directory, vertices, body, foot):
    faces = body + foot
    lines = ["ply", "format ascii 1.0",
             "comment termshade tests/tools/make_vase_models.py: y-up vase, vertex colours by height",
             f"element vertex {len(vertices)}", "property float x", "property float y",
             "property float z", "property uchar red", "property uchar green", "property uchar blue",
             f"element face {len(faces)}", "property list uchar int vertex_indices", "end_header"]
    for x, y, z in vertices:
        t = y / HEIGHT  # terracotta at the foot to sea green at the lip
        colour = (round(190 - 150 * t), round(80 + 90 * t), round(50 + 110 * t))
        lines.append(f"{x:g} {y:g} {z:g} {colour[0]} {colour[1]} {colour[2]}")
    for face in faces:
        lines.append(" ".join(str(v) for v in (len(face),) + tuple(face)))
    with open(os.path.join(directory, "vase_vertex_colours.ply"), "w", encoding="ascii") as out:
        out.write("\n".join(lines) + "\n")


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join("tests", "models", "real")
    vertices, body, foot = vase()
    check_outward(vertices, body, lambda c: (c[0], 0.0, c[2]))
    check_outward(vertices, foot, lambda c: (0.0, -1.0, 0.0))
    write_gltf(directory, vertices, body, foot)
    write_ply(directory, vertices, body, foot)


if __name__ == "__main__":
    main()
