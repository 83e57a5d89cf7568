#!/usr/bin/env python3
"""Hostile inputs that expand or degenerate (issue 32), made here at sizes CI
affords, each rendered by termshade under a time cap with a memory budget:
it must end with exit 0 or 1 within the cap, and its peak resident memory
(the process, or its import helper: wait4's ru_maxrss is the larger) must stay
within the budget given plus 64 MiB (docs/reliability.md).

Usage: budget_test.py TERMSHADE [--markdown] [--no-memory-check] [--seconds S]
  --markdown: print the table for docs/reliability.md instead of failing.
  --no-memory-check: sanitizer builds (their shadow memory is no model's).
"""
import argparse
import base64
import math
import os
import struct
import zlib
import subprocess
import sys
import tempfile
import time

SLACK_BYTES = 64 << 20  # the documented constant above the budget
MIB = 1 << 20


def expanding_face_obj(path):
    """4 vertices and one face line of 2.5M corners (5 MB of file)."""
    with open(path, "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf" + " 1 2 3 4" * 625000 + "\n")


def expanding_face_dat(path):
    """The same face in the .dat format."""
    with open(path, "w") as f:
        f.write("1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\nFaces:\n" + "1 2 3 4 " * 625000 + ".\n")


def many_meshes_gltf(path):
    """100,000 meshes (nodes, primitives) of one shared triangle: 8 MB of JSON."""
    count = 100000
    data = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0) + struct.pack("<3H", 0, 1, 2)
    uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    with open(path, "w") as f:
        f.write('{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[%s]}],'
                % ",".join(map(str, range(count))))
        f.write('"nodes":[%s],' % ",".join('{"mesh":%d}' % i for i in range(count)))
        f.write('"meshes":[%s],' % ",".join(
            '{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}' for _ in range(count)))
        f.write('"buffers":[{"uri":"%s","byteLength":42}],' % uri)
        f.write('"bufferViews":[{"buffer":0,"byteLength":36},'
                '{"buffer":0,"byteOffset":36,"byteLength":6}],')
        f.write('"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",'
                '"min":[0,0,0],"max":[1,1,0]},'
                '{"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]}\n')


def repeated_triangle_obj(path):
    """One triangle, 1M times over (8 MB): level of detail on."""
    with open(path, "w") as f:
        f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n" * 1000000)


def repeated_triangle_stl(path):
    """One triangle, 200,000 times over in binary STL (10 MB)."""
    count = 200000
    with open(path, "wb") as f:
        f.write(b"\0" * 80 + struct.pack("<I", count))
        f.write(struct.pack("<12fH", 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0) * count)


def repeated_ngon_obj(path):
    """2,000 faces, each the same 1000-gon over the same 1000 vertices (7.8 MB)."""
    with open(path, "w") as f:
        for i in range(1000):
            angle = 2 * math.pi * i / 1000
            f.write("v %.6f %.6f 0\n" % (math.cos(angle), math.sin(angle)))
        f.write(("f " + " ".join(str(i + 1) for i in range(1000)) + "\n") * 2000)


def ply_255_corners(path):
    """40,000 binary PLY faces of 255 corners over 4 vertices (41 MB)."""
    count = 40000
    with open(path, "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
                b"property float y\nproperty float z\nelement face %d\n"
                b"property list uchar int vertex_indices\nend_header\n" % count)
        f.write(struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0))
        f.write((struct.pack("<B", 255) + struct.pack("<255i", *[i % 4 for i in range(255)]))
                * count)


def coincident_own_vertices_dat(path):
    """200,000 copies of one triangle, each with its own three vertices (.dat:
    no welding), 7 MB: drawn once, not 200,000 times (15 s at 1000x500 before)."""
    count = 200000
    with open(path, "w") as f:
        for i in range(count):
            f.write("%d 0 0 0\n%d 1 0 0\n%d 0 1 0\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3))
        f.write("Faces:\n")
        for i in range(count):
            f.write("%d %d %d .\n" % (3 * i + 1, 3 * i + 2, 3 * i + 3))


def sphere_2m_ply(path):
    """termshade's own 2M-triangle test sphere (38 MB): levels of detail would
    take about 230 MiB beside it, more than the budget leaves."""
    subprocess.run([BINARY, "generate", "sphere", "--triangles", "2000000", "-o", path], check=True)


def textured_ngon_obj(path):
    """One 20,000-gon, textured by a plane projection through its MTL (a 64x64
    PNG beside it): each sample's texture lookup searched every triangle of
    the face (more than 300 s a frame before)."""
    folder = os.path.dirname(path)
    raw = b"".join(b"\0" + b"".join(bytes((4 * x, 4 * y, 128)) for x in range(64)) for y in range(64))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    with open(os.path.join(folder, "ngon.png"), "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 64, 64, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    with open(os.path.join(folder, "ngon.mtl"), "w") as f:
        f.write("newmtl m\nKd 1 1 1\nmap_Kd ngon.png\n")
    count = 20000
    with open(path, "w") as f:
        f.write("mtllib ngon.mtl\n")
        for i in range(count):
            angle = 2 * math.pi * i / count
            f.write("v %.7f %.7f 0\nvt %.7f %.7f\n" % (math.cos(angle), math.sin(angle),
                                                     0.5 + 0.5 * math.cos(angle),
                                                     0.5 + 0.5 * math.sin(angle)))
        f.write("usemtl m\nf " + " ".join("%d/%d" % (i + 1, i + 1) for i in range(count)) + "\n")


BINARY = None  # termshade, for the generators that use it

# name, generator, render arguments after the model, budget, standard input (bytes) or None
CASES = [
    ("expanding_face.obj", expanding_face_obj, ["--size", "40x12"], "100M"),
    ("expanding_face.dat", expanding_face_dat, ["--size", "40x12"], "100M"),
    ("expanding_face_lod.obj", expanding_face_obj, ["--size", "200x60", "--lod", "auto"], "400M"),
    ("many_meshes.gltf", many_meshes_gltf, ["--size", "40x12"], "250M"),
    ("repeated_triangle.obj", repeated_triangle_obj,
     ["--size", "1000x500", "--lod", "auto"], "200M"),
    ("repeated_triangle.stl", repeated_triangle_stl,
     ["--size", "1000x500", "--lod", "auto"], "200M"),
    ("repeated_1000gon.obj", repeated_ngon_obj, ["--size", "400x200", "--lod", "auto"], "300M"),
    ("ply_255_corners.ply", ply_255_corners, ["--size", "400x200"], "300M"),
    ("coincident_own_vertices.dat", coincident_own_vertices_dat,
     ["--size", "1000x500", "--lod", "auto"], "300M"),
    ("sphere_2m_lod.ply", sphere_2m_ply, ["--size", "160x48", "--lod", "auto"], "250M"),
    ("textured_20000gon.obj", textured_ngon_obj,
     ["--size", "160x48", "--glyphs", "sextants", "--color", "truecolor", "--format", "ansi",
      "--up", "z", "--phi", "0.01"], "200M"),
]
STDIN_BYTES = 200 << 20  # `yes 'v 1 2 3'`, cut at 200 MB: more than the budget lets load


def budget_bytes(text):
    return int(text[:-1]) << {"K": 10, "M": 20, "G": 30}[text[-1]]


def run(command, seconds, stdin_bytes=None):
    """Exit code (None: killed at the cap), seconds, peak KiB, stderr."""
    start = time.monotonic()
    process = subprocess.Popen(command, stdin=subprocess.PIPE if stdin_bytes else subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if stdin_bytes:
        try:
            chunk = b"v 1 2 3\n" * 131072
            sent = 0
            while sent < stdin_bytes:
                process.stdin.write(chunk)
                sent += len(chunk)
            process.stdin.close()
        except BrokenPipeError:
            pass
    try:
        _, stderr = process.communicate(timeout=seconds)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
        return None, time.monotonic() - start, 0, ""
    elapsed = time.monotonic() - start
    # communicate() reaped it: the children's peak since the last reap.
    return process.returncode, elapsed, peak_kib(), stderr.decode(errors="replace")


def peak_kib():
    # RUSAGE_CHILDREN's ru_maxrss: the largest of the reaped children so
    # far, so each case runs in a fresh child (see main).
    import resource
    return resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss


def one_case(binary, name, arguments, budget, seconds, directory, stdin):
    command = [binary, "render", "-" if stdin else os.path.join(directory, name),
               "--memory-budget", budget] + arguments
    code, elapsed, peak, stderr = run(command, seconds, STDIN_BYTES if stdin else None)
    return code, elapsed, peak, stderr.strip().splitlines()[-1:] if stderr else []


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--markdown", action="store_true")
    parser.add_argument("--no-memory-check", action="store_true")
    parser.add_argument("--seconds", type=float, default=float(os.environ.get("BUDGET_SECONDS", 8)))
    parser.add_argument("--case", help=argparse.SUPPRESS)  # run one case here (a fresh child)
    parser.add_argument("--dir", help=argparse.SUPPRESS)
    args = parser.parse_args()
    global BINARY
    BINARY = args.binary
    if args.case:  # the child: one case, its peak alone in RUSAGE_CHILDREN
        if args.case == "stdin":
            arguments, budget, stdin = ["--input-format", "obj", "--size", "40x12"], "100M", True
        else:
            _, _, arguments, budget = next(c for c in CASES if c[0] == args.case)
            stdin = False
        code, elapsed, peak, last = one_case(args.binary, args.case, arguments, budget,
                                             args.seconds, args.dir, stdin)
        print("%s\t%s\t%.2f\t%d\t%s\t%s" % (args.case, code, elapsed, peak, budget,
                                            last[0] if last else ""))
        return 0
    failures = 0
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for name, generate, _, _ in CASES:
            generate(os.path.join(directory, name))
        for name in [c[0] for c in CASES] + ["stdin"]:
            line = subprocess.run([sys.executable, __file__, args.binary, "--case", name,
                                   "--dir", directory, "--seconds", str(args.seconds)],
                                  capture_output=True, text=True).stdout.strip()
            case, code, elapsed, peak, budget, last = (line.split("\t") + [""] * 6)[:6]
            peak_bytes = int(peak or 0) * 1024
            limit = budget_bytes(budget) + SLACK_BYTES
            why = ""
            if code not in ("0", "1"):
                why = "no result within %g s" % args.seconds if code == "None" else "exit " + code
            elif not args.no_memory_check and peak_bytes > limit:
                why = "peak %d MiB over the budget %s + 64 MiB" % (peak_bytes // MIB, budget)
            if why:
                failures += 1
                print("FAIL %s: %s (%s)" % (name, why, last))
            rows.append((name, budget, code, elapsed, peak_bytes // MIB, why or "ok", last))
    if args.markdown:
        print("| input | budget | exit | seconds | peak MiB | verdict |")
        print("|---|---|---|---|---|---|")
        for name, budget, code, elapsed, peak, verdict, _ in rows:
            shown = "`yes 'v 1 2 3'` on stdin, 200 MB" if name == "stdin" else name
            print("| %s | %s | %s | %s | %d | %s |" % (shown, budget, code, elapsed, peak, verdict))
        return 0
    print("%d inputs: %d failures" % (len(rows), failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
