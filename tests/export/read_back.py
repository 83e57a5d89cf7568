#!/usr/bin/python3
"""Reads termshade's exports back with what users read them with.

  read_back.py cast FILE.cast COLS ROWS FRAMES FPS
      The recording parses as asciicast v2: a header with the size and a
      theme, then an output event at 0 and one at each later frame's time
      (FRAMES at 1/FPS second steps; a frame equal to the one before has
      none) and a closing event at the last frame's time; prints the bytes
      of every event in order (for a terminal to replay).
  read_back.py svg-cells PICTURE.png FRAME.ans CELL_W CELL_H
      The picture (an SVG rasterised by rsvg-convert, on the default black
      theme) shows the ansi dump's cells: for block, quadrant, sextant and
      braille glyphs, the centre of each part of the cell has the glyph's
      colour where the glyph inks that part and the cell's background colour
      elsewhere; text glyphs have ink in their cell and blank cells have none
      (away from the cell's edges, where a neighbour's text glyph may reach).
      Prints the counts.
Exits 1 with a message on the first difference.
"""
import json
import re
import sys

THEME_FG = (192, 192, 192)
THEME_BG = (0, 0, 0)
XTERM16 = [(0, 0, 0), (205, 0, 0), (0, 205, 0), (205, 205, 0), (0, 0, 238), (205, 0, 205),
           (0, 205, 205), (229, 229, 229), (127, 127, 127), (255, 0, 0), (0, 255, 0),
           (255, 255, 0), (92, 92, 255), (255, 0, 255), (0, 255, 255), (255, 255, 255)]
QUADRANTS = " \u2598\u259D\u2580\u2596\u258C\u259E\u259B\u2597\u259A\u2590\u259C\u2584\u2599\u259F\u2588"
BRAILLE_BITS = [0x01, 0x08, 0x02, 0x10, 0x04, 0x20, 0x40, 0x80]


def Fail(message):
    print(f"read_back: {message}", file=sys.stderr)
    sys.exit(1)


def Palette(index):
    if index < 16:
        return XTERM16[index]
    if index < 232:
        levels = [0, 95, 135, 175, 215, 255]
        index -= 16
        return (levels[index // 36], levels[index // 6 % 6], levels[index % 6])
    grey = 8 + 10 * (index - 232)
    return (grey, grey, grey)


def Shape(glyph):
    """(across, down, pattern) of a block, quadrant, sextant or braille glyph; None for text."""
    code = ord(glyph)
    if 0x2801 <= code <= 0x28FF:
        dots = code - 0x2800
        return 2, 4, sum(1 << i for i, bit in enumerate(BRAILLE_BITS) if dots & bit)
    if glyph in QUADRANTS[1:]:
        return 2, 2, QUADRANTS.index(glyph)
    if 0x1FB00 <= code <= 0x1FB3B:
        pattern = code - 0x1FB00 + 1
        pattern += (pattern >= 0b010101) + (pattern >= 0b101010 - 1)
        return 2, 3, pattern
    return None


def ParseAnsi(text):
    """Rows of (glyph, foreground, background) cells, as a terminal shows an ansi dump."""
    rows = []
    for line in text.split("\n")[:-1]:
        fg, bg, cells = THEME_FG, THEME_BG, []
        for token in re.findall(r"\x1b\[[0-9;]*m|.", line):
            if not token.startswith("\x1b"):
                cells.append((token, fg, bg))
                continue
            params = [int(p) if p else 0 for p in token[2:-1].split(";")]
            while params:
                p = params.pop(0)
                if p == 0:
                    fg, bg = THEME_FG, THEME_BG
                elif p == 39:
                    fg = THEME_FG
                elif p == 49:
                    bg = THEME_BG
                elif p in (38, 48):
                    kind = params.pop(0)
                    colour = Palette(params.pop(0)) if kind == 5 else tuple(params[:3])
                    if kind == 2:
                        del params[:3]
                    if p == 38:
                        fg = colour
                    else:
                        bg = colour
        rows.append(cells)
    return rows


def CheckCast(path, cols, rows, frames, fps):
    lines = open(path, encoding="utf-8").read().splitlines()
    header = json.loads(lines[0])
    if header.get("version") != 2 or header.get("width") != cols or header.get("height") != rows:
        Fail(f"header {header}")
    theme = header.get("theme", {})
    if not theme.get("fg", "").startswith("#") or len(theme.get("palette", "").split(":")) != 16:
        Fail(f"theme {theme}")
    events = [json.loads(line) for line in lines[1:]]
    if not 2 <= len(events) <= frames + 1:
        Fail(f"{len(events)} events, expected at most {frames} frames and a closing event")
    # A frame equal to the one before has no event: the others keep their frame's time.
    last = -1
    for index, (seconds, kind, data) in enumerate(events[:-1]):
        frame = round(seconds * fps)
        if (kind != "o" or abs(seconds - frame / fps) > 1e-6 or not isinstance(data, str) or
                frame <= last or frame >= frames or (index == 0 and frame != 0)):
            Fail(f"event {index}: {seconds} {kind}")
        last = frame
    if abs(events[-1][0] - (frames - 1) / fps) > 1e-6 or events[-1][2] != "\x1b[?25h":
        Fail(f"closing event {events[-1]}")
    sys.stdout.write("".join(event[2] for event in events))


def Distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b))


def Near(a, b):
    return all(abs(x - y) <= 2 for x, y in zip(a, b))


def CheckSvgCells(picturePath, ansiPath, cellWidth, cellHeight):
    from PIL import Image  # python3-pil

    picture = Image.open(picturePath).convert("RGB")
    rows = ParseAnsi(open(ansiPath, encoding="utf-8").read())
    if picture.size != (cellWidth * len(rows[0]), cellHeight * len(rows)):
        Fail(f"picture {picture.size} for {len(rows[0])}x{len(rows)} cells")
    pixels = picture.load()
    counts = {"shape": 0, "text": 0, "blank": 0}
    for row, cells in enumerate(rows):
        for col, (glyph, fg, bg) in enumerate(cells):
            left, top = col * cellWidth, row * cellHeight
            shape = Shape(glyph)
            if shape:
                across, down, pattern = shape
                for part in range(across * down):
                    x = left + int((part % across + 0.5) * cellWidth / across)
                    y = top + int((part // across + 0.5) * cellHeight / down)
                    want, other = (fg, bg) if pattern >> part & 1 else (bg, fg)
                    dots = across * down == 8  # braille: round dots, smoothed edges
                    if not (Near(pixels[x, y], want) or
                            dots and Distance(pixels[x, y], want) < Distance(pixels[x, y], other)):
                        Fail(f"cell {col},{row} ('{glyph}') part {part}: {pixels[x, y]}, expected {want}")
                counts["shape"] += 1
                continue
            inner = [pixels[x, y] for y in range(top + cellHeight // 8, top + cellHeight - cellHeight // 8)
                     for x in range(left + cellWidth // 4, left + cellWidth - cellWidth // 4)]
            ink = any(not Near(p, bg) for p in inner)
            if glyph == " " and ink:
                Fail(f"blank cell {col},{row}: ink in the picture")
            if glyph != " " and not any(not Near(pixels[x, y], bg)
                                        for y in range(top, top + cellHeight)
                                        for x in range(left, left + cellWidth)):
                Fail(f"cell {col},{row} ('{glyph}'): no ink in the picture")
            counts["text" if glyph != " " else "blank"] += 1
    print(f"{counts['shape']} shape cells, {counts['text']} text cells, {counts['blank']} blank cells agree")


def main():
    if len(sys.argv) == 7 and sys.argv[1] == "cast":
        CheckCast(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5]), float(sys.argv[6]))
    elif len(sys.argv) == 6 and sys.argv[1] == "svg-cells":
        CheckSvgCells(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]))
    else:
        Fail(__doc__)


if __name__ == "__main__":
    main()
