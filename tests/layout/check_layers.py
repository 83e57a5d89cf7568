#!/usr/bin/env python3
"""Checks that the source tree's includes point one way, floor by floor.

Usage: check_layers.py REPO_ROOT

Floors, bottom to top (docs/architecture.md):
  0 process       memory and thread set-up
  1 geometry      math, camera, mesh, scene, hierarchies
  2 shade         lighting, ramps, glyphs, colours
  3 raster        the renderer and its stages
  4 io/read, io/scenes, io/write   (siblings: none includes another)
  5 io/import     the isolated import through Assimp
  6 io/load       picks a reader or the import
  7 tui, bench    the viewer (the only code that includes ncurses); benchmarks
  8 cli           the executable
A file may include files of its own folder and of lower floors only. The
Assimp module's files (src/io/import/module) and the helper's
(src/io/import/helper) belong to io/import, and nothing else includes them.
Every file name is unique in src/ and bench/. Prints each violation as
FILE:LINE: message and exits 1 if there is any.
"""
import pathlib
import re
import sys

FLOORS = {
    "process": 0, "geometry": 1, "shade": 2, "raster": 3,
    "io/read": 4, "io/scenes": 4, "io/write": 4,
    "io/import": 5, "io/load": 6, "tui": 7, "bench": 7, "cli": 8,
}
PRIVATE = ("io/import/module", "io/import/helper")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')
CURSES = re.compile(r"^(n?curses|ncursesw/|term\.h|panel\.h|menu\.h|form\.h)")


def FolderOf(relative):
    """The floor folder of a path relative to src/ ("io/read/DatReader.h" -> "io/read")."""
    parts = relative.split("/")
    if parts[0] == "io" and len(parts) > 2:
        return "io/" + parts[1]
    return parts[0]


def Check(root):
    problems = []
    names = {}
    files = sorted(p for folder in ("src", "bench") for p in (root / folder).rglob("*")
                   if p.suffix in (".h", ".cpp", ".in"))
    for path in files:
        shown = path.relative_to(root).as_posix()
        names.setdefault(path.name, []).append(shown)
        if shown.startswith("bench/"):
            folder, ownDir = "bench", "bench"
        else:
            inSrc = path.relative_to(root / "src").as_posix()
            folder, ownDir = FolderOf(inSrc), inSrc.rsplit("/", 1)[0]
        if folder not in FLOORS:
            problems.append(f"{shown}:1: folder '{folder}' has no floor in check_layers.py")
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            bracket, target = match.groups()
            if bracket == "<":
                if CURSES.match(target) and folder != "tui":
                    problems.append(f"{shown}:{number}: <{target}> outside src/tui")
                continue
            if (root / "src" / target).exists():
                targetFolder = FolderOf(target)
                targetDir = target.rsplit("/", 1)[0]
            elif (path.parent / target).exists() or (root / "bench" / target).exists():
                targetFolder, targetDir = ("bench", "bench") if folder in ("bench", "cli") else (folder, ownDir)
            else:
                problems.append(f"{shown}:{number}: \"{target}\" not found under src/ or beside the file")
                continue
            if targetFolder not in FLOORS:
                problems.append(f"{shown}:{number}: \"{target}\" is in no floor")
            elif targetDir.startswith(PRIVATE) and not ownDir.startswith(targetDir):
                problems.append(f"{shown}:{number}: \"{target}\" is private to src/{targetDir}")
            elif targetFolder != folder and FLOORS[targetFolder] >= FLOORS[folder]:
                problems.append(f"{shown}:{number}: {folder} (floor {FLOORS[folder]}) includes "
                                f"{targetFolder} (floor {FLOORS[targetFolder]}): not downward")
    for name, paths in sorted(names.items()):
        if len(paths) > 1:
            problems.append(f"{paths[1]}:1: file name '{name}' also at {', '.join(paths[:1] + paths[2:])}")
    return len(files), problems


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_layers.py REPO_ROOT")
    count, problems = Check(pathlib.Path(sys.argv[1]))
    for problem in problems:
        print(problem)
    if problems:
        print(f"{len(problems)} layering problems in {count} files")
        return 1
    print(f"{count} files checked: every include points down, every name unique")
    return 0


if __name__ == "__main__":
    sys.exit(main())
