#!/usr/bin/env python3
"""docs/real-models.md's table of real models from the Assimp test corpus (Debian
package assimp-testmodels): for each file, whether termshade loads it, the up
axis it uses and where that comes from, whether the model stands upright at the
default view, the colours the file gives, and ms per frame (from
`termshade bench models`, 160x48 turntable, median of 20 frames). Also the
before/after frames of the duck.

Usage (from the source tree, after a release build):
  tests/tools/corpus_table.py [--termshade build/termshade] [--corpus /usr/share/assimp/models]
                              [--readme docs/real-models.md]
Without --readme it prints the Markdown; with it, it replaces the text between
the corpus-table markers in that file.

"Upright" is judged by a stated rule: UPRIGHT_AXIS below names, for each file,
the axis that points up in the model, found by looking at its default-view
frames rendered with --up y and --up z (`--look` prints them again); the model
is upright by default when the axis termshade picks without --up is that axis.
"""
import argparse
import csv
import io
import os
import subprocess
import sys

# File (under the corpus) -> the axis that is up in the model, judged by looking.
UPRIGHT_AXIS = {
    "OBJ/spider.obj": "+y",
    "OBJ/WusonOBJ.obj": "+z",
    "STL/Spider_binary.stl": "+z",
    "STL/Wuson.stl": "+z",
    "PLY/Wuson.ply": "+z",
    "OFF/Wuson.off": "+z",
    "Collada/duck.dae": "+y",
    "Collada/teapots.DAE": "+y",
    "FBX/spider.fbx": "+y",
    "X/Testwuson.X": "+y",
    "MD2/sydney.md2": "+y",
    "MD2/faerie.md2": "+y",
    "MS3D/jeep1.ms3d": "+y",
    "AC/Wuson.ac": "+y",
    "Q3D/E-AT-AT.q3o": "+z",
    "B3D/WusonBlitz.b3d": "+z",
    "SMD/WusonSMD.smd": "+y",
    "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf": "+y",
    "OBJ/cube_with_vertexcolors.obj": None,  # a cube: no up to judge
}

BEFORE_AFTER = "Collada/duck.dae"


def convention(path):
    """SPEC 10: the format's up axis when the file declares none."""
    ext = os.path.splitext(path)[1].lower()
    return "+z" if ext in (".dat", ".stl") else "+y"


def run(command):
    return subprocess.run(command, capture_output=True, text=True, check=False)


def bench_rows(termshade, corpus):
    paths = [os.path.join(corpus, name) for name in UPRIGHT_AXIS]
    result = run([termshade, "bench", "models", *paths])
    rows = list(csv.DictReader(io.StringIO(result.stdout), delimiter="\t"))
    if len(rows) != len(paths):
        sys.exit("bench models gave %d rows for %d files:\n%s" % (len(rows), len(paths), result.stderr))
    return rows


def table(rows, corpus):
    lines = [
        "| file | format | loads | faces | up axis used | from | upright by default | colours from the file | ms per frame |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for name, row in zip(UPRIGHT_AXIS, rows):
        fmt = os.path.splitext(name)[1].lstrip(".").upper()
        if row["loads"] != "yes":
            error = row["error"].replace("|", "\\|").replace(corpus + "/", "")
            lines.append(f"| `{name}` | {fmt} | no: {error[:90]} | | | | | | |")
            continue
        axis = row["up_axis"]
        source = "convention" if axis == convention(name) else "the file"
        judged = UPRIGHT_AXIS[name]
        upright = "n/a" if judged is None else ("yes" if axis == judged else f"no (up is {judged}: `--up {judged.lstrip('+')}`)")
        count = row["face_colours"]
        colours = "none" if count == "0" else f"{count} colour" + ("" if count == "1" else "s")
        turned = int(row["faces_turned_outward"])
        if turned:
            fmt += f", {turned} faces turned outward"
        lines.append(f"| `{name}` | {fmt} | yes | {row['faces']} | {axis} | {source} | {upright} | {colours} | {float(row['frame_ms']):.2f} |")
    return "\n".join(lines)


def frame(termshade, path, *options):
    result = run([termshade, "render", path, "--size", "64x20", *options])
    return "\n".join(line.rstrip() for line in result.stdout.splitlines() if line.strip())


def before_after(termshade, corpus):
    path = os.path.join(corpus, BEFORE_AFTER)
    before = frame(termshade, path, "--up", "z")
    after = frame(termshade, path)
    return (f"Before: `termshade render {BEFORE_AFTER} --up z --size 64x20` (every file read as z-up, "
            f"as termshade did before it knew up axes):\n\n```\n{before}\n```\n\n"
            f"After: `termshade render {BEFORE_AFTER} --size 64x20` (the default view):\n\n```\n{after}\n```")


def look(termshade, corpus):
    for name in UPRIGHT_AXIS:
        for axis in ("y", "z"):
            print(f"=== {name} --up {axis}")
            print(frame(termshade, os.path.join(corpus, name), "--up", axis))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--termshade", default="build/termshade")
    parser.add_argument("--corpus", default="/usr/share/assimp/models")
    parser.add_argument("--readme")
    parser.add_argument("--look", action="store_true", help="print the frames the judgement is made on")
    args = parser.parse_args()
    if args.look:
        look(args.termshade, args.corpus)
        return
    text = (table(bench_rows(args.termshade, args.corpus), args.corpus) + "\n\n" +
            before_after(args.termshade, args.corpus))
    if not args.readme:
        print(text)
        return
    begin, end = "<!-- corpus-table:begin -->", "<!-- corpus-table:end -->"
    with open(args.readme, encoding="utf-8") as readme:
        content = readme.read()
    if begin not in content or end not in content:
        sys.exit(f"{args.readme} has no {begin} ... {end} markers")
    head, rest = content.split(begin, 1)
    tail = rest.split(end, 1)[1]
    with open(args.readme, "w", encoding="utf-8") as readme:
        readme.write(head + begin + "\n" + text + "\n" + end + tail)


if __name__ == "__main__":
    main()
