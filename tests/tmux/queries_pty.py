#!/usr/bin/env python3
"""The viewer's start-up queries against a terminal played here on a pty.

Usage: queries_pty.py TERMSHADE MODEL
A silent terminal (answers nothing): the first frame follows the queries
after the 100 ms wait, not much later, and the status line says 256. An
answering one (DA1 at once, RGB by XTGETTCAP, a light background, an
8x17-pixel cell): the frame comes at once, the status line says truecolor
and y's render command (copied by OSC 52) has the background and aspect. One answering
300 ms late (a slow link): the first frame after the wait, truecolor once
the answers come. Nothing of the answers appears in the output. Prints the
measured waits; exits 1 on a failure.
"""
import base64
import os
import pty
import re
import select
import sys
import time

QUERIES = b"\x1b]11;?\x1b\\\x1bP+q524742\x1b\\\x1bP+q5463\x1b\\\x1b[16t\x1b[c"
ANSWERS = (b"\x1b]11;rgb:ffff/ffff/ffff\x1b\\\x1bP1+r524742\x1b\\\x1bP0+r5463\x1b\\"
           b"\x1b[6;17;8t\x1b[?62;22c")


def Run(binary, model, answer_after):
    """Returns (ms from the queries to the first frame, the output after the
    queries). answer_after: seconds after the queries the terminal answers
    (None: never)."""
    pid, fd = pty.fork()
    if pid == 0:
        os.environ.update(TERM="xterm-256color", LANG="C.UTF-8")
        os.environ.pop("COLORTERM", None)
        os.environ.pop("NO_COLOR", None)
        os.execv(binary, [binary, "--lod", "off", model])
    out, asked, framed, answered = b"", None, None, False
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        now = time.monotonic()
        if asked is not None and answer_after is not None and not answered and \
                now >= asked + answer_after:
            os.write(fd, ANSWERS)
            answered = True
        settled = asked is not None and framed is not None and \
            (answer_after is None or answered) and now > max(framed, asked + (answer_after or 0)) + 0.4
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


def main():
    binary, model = sys.argv[1], sys.argv[2]
    failed = 0
    silent_ms, out = Run(binary, model, None)
    print(f"silent terminal: first frame {silent_ms} ms after the queries")
    if silent_ms is None or not 80 <= silent_ms <= 400:
        print("FAIL a silent terminal: the wait is not about 100 ms")
        failed += 1
    if b" 256 " not in out:
        print("FAIL a silent terminal: the status line does not say 256")
        failed += 1
    answered_ms, out = Run(binary, model, 0.0)
    print(f"answering terminal: first frame {answered_ms} ms after the queries")
    if answered_ms is None or answered_ms > 80:
        print("FAIL an answering terminal: the wait did not end at the DA1 answer")
        failed += 1
    if b"truecolor" not in out:
        print("FAIL an answering terminal with RGB: the status line does not say truecolor")
        failed += 1
    # The whole command is in the OSC 52 copy to the clipboard (the status line elides it).
    copied = re.search(rb"\x1b\]52;c;([A-Za-z0-9+/=]*)", out)
    command = base64.b64decode(copied.group(1)) if copied else b""
    print(f"answering terminal: y gives {command.decode()}")
    for said in (b"--background light", b"--cell-aspect 2.125", b"--color truecolor"):
        if said not in command:
            print(f"FAIL an answering terminal: the render command lacks {said.decode()}")
            failed += 1
    slow_ms, slow = Run(binary, model, 0.3)
    print(f"terminal answering after 300 ms: first frame {slow_ms} ms after the queries")
    if slow_ms is None or not 80 <= slow_ms <= 290:
        print("FAIL a slow terminal: the first frame did not come after the 100 ms wait")
        failed += 1
    if b"truecolor" not in slow:
        print("FAIL a slow terminal: its late RGB answer did not make truecolor")
        failed += 1
    for leak in (b"rgb:", b"+r5", b"62;22"):
        if leak in out or leak in slow:
            print(f"FAIL answer bytes {leak!r} came out in the picture")
            failed += 1
    print("FAILED" if failed else "ok")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
