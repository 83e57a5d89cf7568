#!/usr/bin/env bash
# termshade MODEL --record FILE.cast: a short session in tmux (keys, the
# turntable), recorded; the recording parses as asciicast v2 (header with the
# terminal's size and a theme, events in time order), appears only when the
# viewer ends, and replayed in a tmux pane of the same size gives the
# viewer's final screen cell for cell, colours and status line included.
# Usage: record_test.sh path/to/termshade source-dir
set -u
bin=$(realpath "$1")
src=$(realpath "$2")
socket="termshade-record-$$"
work=$(mktemp -d)
passed=0
failed=0
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
cleanup() { tm kill-server 2>/dev/null; sleep 0.2; rm -rf "$work"; }
trap cleanup EXIT
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
scale=1
[ -n "${TERMSHADE_SANITIZED:-}" ] && scale=4
wait_for() {  # wait_for TARGET REGEX SECONDS
  local deadline=$((SECONDS + $3 * scale))
  while [ $SECONDS -le "$deadline" ]; do
    tm capture-pane -t "$1" -p -J | grep -qE -- "$2" && return 0
    sleep 0.1
  done
  return 1
}
settle() {  # settle TARGET: the screen unchanged for 0.3 s
  local previous="" current stable=0
  for _ in $(seq 1 100); do
    sleep 0.1
    current=$(tm capture-pane -t "$1" -p -e)
    if [ "$current" = "$previous" ]; then stable=$((stable + 1)); else stable=0; fi
    [ "$stable" -ge 3 ] && return 0
    previous=$current
  done
}

cast="$work/spin.cast"
tm new-session -d -s v -x 80 -y 25 "env -i PATH=$PATH HOME=$work TERM=tmux-256color LANG=C.UTF-8 PS1='$ ' bash --norc --noprofile"
tm set-option -t v status off >/dev/null
wait_for v '\$ ' 5 || { fail "no shell prompt"; exit 1; }

# 1. A path that cannot be written: said on the shell, exit 1, no file, the
# terminal never taken.
tm send-keys -t v "clear; $bin $src/data/cube.dat --record $work/no/such/folder/x.cast; echo exit=\$?" Enter
if wait_for v 'exit=1' 5 && wait_for v '--record .*no/such/folder' 1; then pass; else
  fail "unwritable --record: $(tm capture-pane -t v -p | grep -v '^$' | tail -3)"
fi
[ ! -e "$work/no" ] && pass || fail "unwritable --record left something behind"
tm send-keys -t v clear Enter

# 2. A session: keys, the turntable for a second, a method; the file appears at q.
tm send-keys -t v "COLORTERM=truecolor $bin $src/data/beams.dat --glyphs quadrants --record $cast" Enter
wait_for v '\? help' 10 || fail "the viewer did not start"
tm send-keys -t v Right Right Up
sleep 0.3
tm send-keys -t v Space
sleep 1
tm send-keys -t v Space
sleep 0.3
tm send-keys -t v m + a
settle v
[ ! -e "$cast" ] && pass || fail "the recording appeared before the viewer ended"
tm capture-pane -t v -p -e >"$work/viewer.ans"
tm send-keys -t v q
wait_for v '^\$ ?$' 5 || fail "q did not give the prompt back"
[ -s "$cast" ] && pass || { fail "no recording at $cast"; exit 1; }

# 3. The file as asciicast v2; its output events replayed in a pane of the same size.
if python3 - "$cast" "$work/replay.bin" <<'PY'; then pass; else fail "not a valid asciicast v2 recording"; fi
import json, sys
lines = open(sys.argv[1], encoding="utf-8").read().splitlines()
header = json.loads(lines[0])
assert header["version"] == 2 and header["width"] == 80 and header["height"] == 25, header
assert header["theme"]["fg"].startswith("#") and len(header["theme"]["palette"].split(":")) == 16
events = [json.loads(line) for line in lines[1:]]
assert len(events) >= 5, len(events)
times = [e[0] for e in events]
assert times == sorted(times) and times[0] < 1.0 and times[-1] > 1.5, times[:3] + times[-3:]
assert all(e[1] == "o" for e in events), "only output events in a fixed-size session"
with open(sys.argv[2], "w", encoding="utf-8") as out:
    out.write("".join(e[2] for e in events))
PY
tm new-session -d -s r -x 80 -y 25 "env TERM=tmux-256color LANG=C.UTF-8 sh -c 'cat $work/replay.bin; sleep 600'"
tm set-option -t r status off >/dev/null
sleep 0.5
settle r
tm capture-pane -t r -p -e >"$work/replay.ans"
if python3 "$src/tests/tmux/ansi_cells.py" "$work/viewer.ans" "$work/replay.ans" 25 >/dev/null; then pass; else
  fail "the replayed recording differs from the viewer's last screen"
  python3 "$src/tests/tmux/ansi_cells.py" "$work/viewer.ans" "$work/replay.ans" 25
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
