#!/usr/bin/env python3
"""Checks that every relative link in the project's Markdown points somewhere.

Usage: check_links.py REPO_ROOT

Scans README.md, CONTRIBUTING.md and docs/**/*.md for inline links and images
([text](target), ![alt](target)), reference definitions ([id]: target) and
HTML src/href attributes. Absolute URLs (scheme:..., //host) and pure in-page
anchors (#...) are left alone, as is anything inside fenced code blocks or
inline code. Every other target, without its #anchor and ?query, must exist
relative to the linking file (a leading / means the repository root); a
target FILE.md#anchor must also name a heading of FILE.md, by GitHub's slug
rules (lowercase; punctuation other than - and _ dropped; spaces to -;
repeats get -1, -2, ...).

Prints each broken link as FILE:LINE: broken link TARGET and exits 1 if there
is any; otherwise prints "N links checked, 0 broken" and exits 0.
"""
import pathlib
import re
import sys
import urllib.parse

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")
INLINE_CODE = re.compile(r"(`+)(?:(?!\1).)+?\1")
HTML_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)
# ](target) or ](<target>), with an optional "title"; the text before may nest.
INLINE_LINK = re.compile(r"\]\(\s*(<[^>\n]*>|[^)\s]+(?:\([^)\s]*\)[^)\s]*)*)(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
REFERENCE = re.compile(r"^ {0,3}\[[^\]]+\]:\s*(<[^>]*>|\S+)")
HTML_ATTRIBUTE = re.compile(r"<(?:img|a|source)\b[^>]*?\b(?:src|href|srcset)\s*=\s*[\"']([^\"']+)[\"']",
                            re.IGNORECASE)
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")
HEADING = re.compile(r"^ {0,3}(#{1,6})\s+(.*?)\s*#*\s*$")


def ProseLines(text, blankInlineCode=True):
    """(line number, line) outside fenced code blocks; HTML comments and inline code blanked."""
    text = HTML_COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        opening = FENCE.match(line)
        if fence is not None:
            closing = line.strip()
            if opening and set(closing) == {fence[0]} and len(closing) >= len(fence):
                fence = None
            continue
        if opening:
            fence = opening.group(1)
            continue
        if blankInlineCode:
            line = INLINE_CODE.sub(lambda m: " " * len(m.group(0)), line)
        yield number, line


def Slug(heading):
    """GitHub's anchor for a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links and images: their text
    text = re.sub(r"<[^>]+>", "", text)                          # inline HTML tags
    text = text.strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def Anchors(path, cache={}):
    if path not in cache:
        anchors, seen = set(), {}
        text = path.read_text(encoding="utf-8", errors="replace")
        for _, line in ProseLines(text, blankInlineCode=False):
            match = HEADING.match(line)
            if not match:
                continue
            slug = Slug(match.group(2))
            count = seen.get(slug, 0)
            seen[slug] = count + 1
            anchors.add(slug if count == 0 else f"{slug}-{count}")
        cache[path] = anchors
    return cache[path]


def Targets(line):
    for pattern in (INLINE_LINK, REFERENCE, HTML_ATTRIBUTE):
        for match in pattern.finditer(line):
            target = match.group(1).strip()
            if target.startswith("<") and target.endswith(">"):
                target = target[1:-1].strip()
            yield target


def Check(root, path):
    """(links checked, [(line, target)] broken) of one Markdown file."""
    checked, broken = 0, []
    for number, line in ProseLines(path.read_text(encoding="utf-8", errors="replace")):
        for target in Targets(line):
            if not target or target.startswith("#") or target.startswith("//") or SCHEME.match(target):
                continue
            checked += 1
            relative, _, anchor = target.partition("#")
            relative = urllib.parse.unquote(relative.partition("?")[0])
            if relative.startswith("/"):
                resolved = root / relative.lstrip("/")
            else:
                resolved = path.parent / relative
            if not resolved.exists():
                broken.append((number, target))
            elif not resolved.resolve().is_relative_to(root.resolve()):
                broken.append((number, target))  # outside the repository: gone in a clone
            elif anchor and resolved.is_file() and resolved.suffix.lower() == ".md" and \
                    urllib.parse.unquote(anchor).lower() not in Anchors(resolved.resolve()):
                broken.append((number, target))
    return checked, broken


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_links.py REPO_ROOT")
    root = pathlib.Path(sys.argv[1])
    files = [root / name for name in ("README.md", "CONTRIBUTING.md") if (root / name).is_file()]
    if (root / "docs").is_dir():
        files += sorted((root / "docs").rglob("*.md"))
    total, failures = 0, 0
    for path in files:
        checked, broken = Check(root, path)
        total += checked
        for number, target in broken:
            print(f"{path.relative_to(root).as_posix()}:{number}: broken link {target}")
        failures += len(broken)
    if failures:
        print(f"{total} links checked, {failures} broken")
        return 1
    print(f"{total} links checked, 0 broken")
    return 0


if __name__ == "__main__":
    sys.exit(main())
