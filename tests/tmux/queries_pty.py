#!/usr/bin/env python3
"""The viewer's start-up queries against a terminal played here on a pty.

Usage: queries_pty.py TERMSHADE MODEL
A silent terminal (answers nothing): the first frame follows the queries
after the 100 ms wait, not much later, and the status line says 256. An
answering one (DA1 at once, RGB by XTGETTCAP, a light background, an
8x17-pixel cell): the frame comes at once, the status line says truecolor
and y's render command (copied by OSC 52) has the background and aspect. One answering
300 ms late (a slow link): the first frame after the wait, truecolor once
the answers come. One answering 1.5 s late (past the frame pacer's 1 s
give-up) in pieces cut inside every answer, up to 1.3 s apart: every answer
counts and none acts as keys (y gives the same command as at once). The
late ones record with --record: the header's theme is the answered light
background. Nothing of the answers appears in the output. Prints the
measured waits; exits 1 on a failure.
"""
import json
import base64
import os
import pty
import re
import select
import shutil
import sys
import tempfile
import time

QUERIES = b"\x1b]11;?\x1b\\\x1bP+q524742\x1b\\\x1bP+q5463\x1b\\\x1b[16t\x1b[c"
ANSWERS = (b"\x1b]11;rgb:ffff/ffff/ffff\x1b\\\x1bP1+r524742\x1b\\\x1bP0+r5463\x1b\\"
           b"\x1b[6;17;8t\x1b[?62;22c")
# The same answers 1.5 s late, cut after the OSC's ESC, inside the OSC, its
# ST, the DCS, the CSI t (then 1.3 s: past the decoder's 1 s gap) and the DA1.
SPLIT = [(1.5, b"\x1b"), (1.8, b"]11;rgb:ffff/ff"), (2.1, b"ff/ffff\x1b"),
         (2.4, b"\\\x1bP1+r5247"), (2.7, b"42\x1b\\\x1bP0+r5463\x1b\\\x1b[6;"),
         (4.0, b"17;8"), (4.3, b"t\x1b["), (4.6, b"?62;22c")]


def Run(binary, model, answers, record=None):
    """Returns (ms from the queries to the first frame, the output after the
    queries). answers: (seconds after the queries, bytes) the terminal
    sends, in order; record: --record's file, if any."""
    pid, fd = pty.fork()
    if pid == 0:
        os.environ.update(TERM="xterm-256color", LANG="C.UTF-8")
        for name in ("COLORTERM", "NO_COLOR", "COLORFGBG"):
            os.environ.pop(name, None)
        extra = ["--record", record] if record else []
        os.execv(binary, [binary, "--lod", "off", model] + extra)
    out, asked, framed, pending = b"", None, None, list(answers)
    last = max((at for at, _ in answers), default=0.0)
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        now = time.monotonic()
        while asked is not None and pending and now >= asked + pending[0][0]:
            os.write(fd, pending.pop(0)[1])
        settled = asked is not None and framed is not None and not pending and \
            now > max(framed, asked + last) + 0.4
        if settled:
            break
        ready, _, _ = select.select([fd], [], [], 0.002)
        if not ready:
            continue
        try:
            data = os.read(fd, 65536)
        except OSError:
            break
        now = time.monotonic()
        out += data
        if asked is None and QUERIES in out:
            asked = now
            out = out[out.index(QUERIES) + len(QUERIES):]
        elif asked is not None and framed is None and os.path.basename(model).encode() in out:
            framed = now
    # y: the status line shows the render command of the view, with what
    # the answers decided (background, cell aspect, colour).
    os.write(fd, b"y")
    end = time.monotonic() + 1.0
    while time.monotonic() < end and b"\x1b]52;" not in out:
        if select.select([fd], [], [], 0.05)[0]:
            try:
                out += os.read(fd, 65536)
            except OSError:
                break
    os.write(fd, b"q")
    os.waitpid(pid, 0)
    if asked is None or framed is None:
        return None, out
    return (framed - asked) * 1000.0, out


def Command(out):
    """The whole render command y copied (OSC 52): the status line elides it."""
    copied = re.search(rb"\x1b\]52;c;([A-Za-z0-9+/=]*)", out)
    return base64.b64decode(copied.group(1)) if copied else b""


def HeaderBackground(path):
    """The theme background of the recording's header, or None."""
    try:
        with open(path, encoding="utf-8") as cast:
            return json.loads(cast.readline())["theme"]["bg"]
    except (OSError, ValueError, KeyError):
        return None


def main():
    binary, model = sys.argv[1], sys.argv[2]
    work = tempfile.mkdtemp()
    failed = 0
    silent_ms, out = Run(binary, model, [])
    print(f"silent terminal: first frame {silent_ms} ms after the queries")
    if silent_ms is None or not 80 <= silent_ms <= 400:
        print("FAIL a silent terminal: the wait is not about 100 ms")
        failed += 1
    if b" 256 " not in out:
        print("FAIL a silent terminal: the status line does not say 256")
        failed += 1
    answered_ms, out = Run(binary, model, [(0.0, ANSWERS)])
    print(f"answering terminal: first frame {answered_ms} ms after the queries")
    if answered_ms is None or answered_ms > 80:
        print("FAIL an answering terminal: the wait did not end at the DA1 answer")
        failed += 1
    if b"truecolor" not in out:
        print("FAIL an answering terminal with RGB: the status line does not say truecolor")
        failed += 1
    command = Command(out)
    print(f"answering terminal: y gives {command.decode()}")
    for said in (b"--background light", b"--cell-aspect 2.125", b"--color truecolor"):
        if said not in command:
            print(f"FAIL an answering terminal: the render command lacks {said.decode()}")
            failed += 1
    slow_cast = os.path.join(work, "slow.cast")
    slow_ms, slow = Run(binary, model, [(0.3, ANSWERS)], slow_cast)
    print(f"terminal answering after 300 ms: first frame {slow_ms} ms after the queries")
    if slow_ms is None or not 80 <= slow_ms <= 290:
        print("FAIL a slow terminal: the first frame did not come after the 100 ms wait")
        failed += 1
    if b"truecolor" not in slow:
        print("FAIL a slow terminal: its late RGB answer did not make truecolor")
        failed += 1
    split_cast = os.path.join(work, "split.cast")
    split_ms, split = Run(binary, model, SPLIT, split_cast)
    print(f"terminal answering 1.5 s late in pieces: first frame {split_ms} ms after the queries")
    split_command = Command(split)
    print(f"terminal answering 1.5 s late in pieces: y gives {split_command.decode()}")
    if not command or split_command != command:
        print("FAIL late answers in pieces: the view is not the one of answers at once "
              "(answers read as keys, or lost)")
        failed += 1
    for cast in (slow_cast, split_cast):
        background = HeaderBackground(cast)
        print(f"{os.path.basename(cast)}: the header's theme background is {background}")
        if background != "#ffffff":
            print(f"FAIL {os.path.basename(cast)}: the header's theme is not the answered light one")
            failed += 1
    shutil.rmtree(work, ignore_errors=True)
    for leak in (b"rgb:", b"+r5", b"62;22"):
        if leak in out or leak in slow or leak in split:
            print(f"FAIL answer bytes {leak!r} came out in the picture")
            failed += 1
    print("FAILED" if failed else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
