#!/usr/bin/env python3
"""The range of colours an ansi dump shows: relative luminance (WCAG 2) of
the darkest and brightest 24-bit or 256-colour SGR colour, foreground and
background, and their contrast against black and white.

Usage: termshade render MODEL --format ansi --color truecolor ... | colour_range.py
"""
import re
import sys


def Palette(index):
    if index < 16:
        return None
    if index < 232:
        levels = [0, 95, 135, 175, 215, 255]
        index -= 16
        return (levels[index // 36], levels[index // 6 % 6], levels[index % 6])
    grey = 8 + 10 * (index - 232)
    return (grey, grey, grey)


def Luminance(rgb):
    def Linear(c):
        c /= 255.0
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (Linear(c) for c in rgb)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def main():
    colours = set()
    for match in re.finditer(r"\x1b\[([34]8);(2;(\d+);(\d+);(\d+)|5;(\d+))m", sys.stdin.read()):
        if match.group(3):
            colours.add(tuple(int(match.group(i)) for i in (3, 4, 5)))
        elif Palette(int(match.group(6))):
            colours.add(Palette(int(match.group(6))))
    if not colours:
        sys.exit("colour_range: no 256-colour or 24-bit SGR colour in the input")
    lums = sorted(Luminance(c) for c in colours)
    lo, hi = lums[0], lums[-1]
    print(f"{len(colours)} colours, luminance {lo:.3f}-{hi:.3f}, "
          f"contrast of the darkest against black {(lo + 0.05) / 0.05:.2f}, "
          f"of the brightest against white {1.05 / (hi + 0.05):.2f}")


if __name__ == "__main__":
    main()
