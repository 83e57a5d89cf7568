#!/usr/bin/env bash
# Turntable frame pacing of the real viewer in a real tmux session: tmux
# pipe-pane copies what the viewer sends to the pane into a reader that notes
# when each burst (frame) arrives. Prints the frame period's median, p90 and max.
# Usage: tmux_pacing.sh path/to/termshade MODEL [SETTLE-SECONDS [TURNTABLE-SECONDS [VIEWER-ARGS...]]]
# e.g.   tmux_pacing.sh build/termshade /tmp/big/s2m.ply 25 8 --lod off
set -u
bin=$(realpath "$1")
model=$(realpath "$2")
settle=${3:-20}
seconds=${4:-8}
shift 4 2>/dev/null || shift $#
socket="termshade-pacing-$$"
work=$(mktemp -d)
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
trap 'tm kill-server 2>/dev/null; rm -rf "$work"' EXIT

cat >"$work/stamp.py" <<'PY'
import os, sys, time
out = open(sys.argv[1], "w")
while True:
    chunk = os.read(0, 65536)
    if not chunk:
        break
    out.write("%.6f %d\n" % (time.monotonic(), len(chunk)))
    out.flush()
PY
tm new-session -d -s p -x 160 -y 49 "env TERM=tmux-256color $bin $* $model"
tm set-option -t p status off >/dev/null
sleep "$settle"
tm send-keys -t p ' '
sleep 1  # the turntable's first frames
tm pipe-pane -t p -o "python3 $work/stamp.py $work/times.txt"
sleep "$seconds"
tm pipe-pane -t p
last=$(tm capture-pane -t p -p | tail -n 1)
tm send-keys -t p q
python3 - "$work/times.txt" "$*" "$last" <<'PY'
import sys
times = [float(line.split()[0]) for line in open(sys.argv[1])]
starts = [t for i, t in enumerate(times) if i == 0 or t - times[i - 1] > 0.015]
periods = sorted(1000 * (b - a) for a, b in zip(starts, starts[1:]))
if not periods:
    sys.exit("no frames seen")
pick = lambda q: periods[min(len(periods) - 1, int(q * (len(periods) - 1) + 0.5))]
print("viewer args [%s]: %d frames, %.1f fps, period median %.1f p90 %.1f max %.1f ms"
      % (sys.argv[2], len(starts), (len(starts) - 1) / (starts[-1] - starts[0]),
         pick(0.5), pick(0.9), periods[-1]))
print("status line: " + " ".join(sys.argv[3].split()))
PY
