#!/usr/bin/python3
"""Compares two screens cell for cell: character, foreground and background.

  ansi_cells.py A B ROWS

A and B are text with SGR sequences (`tmux capture-pane -p -e`, or
`termshade render --format ansi`); the first ROWS rows of each are read into
cells (character, fg, bg, reverse; what a cell cannot show, a blank's fg
and a full block's bg, is not compared), trailing blank cells with the
default background dropped. Exits 1 naming the first cell that differs.
"""
import re
import sys

SEQUENCE = re.compile(r"\x1b\[([0-9;:]*)([A-Za-z])")


def Cells(line):
    fg = bg = None
    reverse = False
    cells = []
    at = 0
    for match in list(SEQUENCE.finditer(line)) + [None]:
        end = match.start() if match else len(line)
        for char in line[at:end]:
            # What a cell cannot show is not compared: a blank's fg, a full block's bg.
            cells.append((char, None if char == " " else fg, None if char == "\u2588" else bg,
                          reverse))
        if not match:
            break
        at = match.end()
        if match.group(2) != "m":
            continue
        params = [int(p) if p else 0 for p in re.split("[;:]", match.group(1))] or [0]
        i = 0
        while i < len(params):
            p = params[i]
            if p == 0:
                fg = bg = None
                reverse = False
            elif p == 7:
                reverse = True
            elif p == 27:
                reverse = False
            elif p == 39:
                fg = None
            elif p == 49:
                bg = None
            elif 30 <= p <= 37 or 90 <= p <= 97:
                fg = ("i", p - 30 if p < 90 else p - 82)
            elif 40 <= p <= 47 or 100 <= p <= 107:
                bg = ("i", p - 40 if p < 100 else p - 92)
            elif p in (38, 48) and i + 1 < len(params):
                if params[i + 1] == 5 and i + 2 < len(params):
                    colour = ("i", params[i + 2])
                    i += 2
                elif params[i + 1] == 2 and i + 4 < len(params):
                    colour = ("rgb", tuple(params[i + 2:i + 5]))
                    i += 4
                else:
                    colour = None
                if p == 38:
                    fg = colour
                else:
                    bg = colour
            i += 1
    while cells and cells[-1][0] == " " and cells[-1][2] is None and not cells[-1][3]:
        cells.pop()
    return cells


def Screen(path, rows):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    lines = (lines + [""] * rows)[:rows]
    return [Cells(line) for line in lines]


def main():
    a, b, rows = sys.argv[1], sys.argv[2], int(sys.argv[3])
    screenA, screenB = Screen(a, rows), Screen(b, rows)
    for row, (cellsA, cellsB) in enumerate(zip(screenA, screenB)):
        for col in range(max(len(cellsA), len(cellsB))):
            cellA = cellsA[col] if col < len(cellsA) else None
            cellB = cellsB[col] if col < len(cellsB) else None
            if cellA != cellB:
                print(f"ansi_cells: row {row} col {col}: {cellA} != {cellB}", file=sys.stderr)
                return 1
    print(f"ansi_cells: {rows} rows equal")
    return 0


if __name__ == "__main__":
    sys.exit(main())
