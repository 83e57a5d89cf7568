#!/usr/bin/env bash
# The start-up queries (issue 33, item 3). In tmux: the status line names the
# colour mode, c cycles the modes the terminal has (256, 16, mono, 256), and
# after q the shell's line holds nothing of the terminal's answers. On a pty
# played by queries_pty.py: a silent terminal costs the 100 ms wait, an
# answering one ends it at its DA1 answer and its RGB makes truecolor, a
# late one (300 ms) gets the first frame after the wait and truecolor later;
# one 1.5 s late in pieces up to 1.3 s apart has every answer count, none
# read as keys; --record's header takes the answered (light) background.
# Usage: queries_test.sh path/to/termshade
set -u
bin=$(realpath "$1")
here=$(dirname "$(realpath "$0")")
model=$(realpath "$here/../../data/cube.dat")
socket="termshade-queries-$$"
failed=0

source "$here/../support/tmux_session.sh"

tm new-session -d -s v -x 120 -y 30 "env -u COLORTERM -u NO_COLOR PS1='shell> ' TERM=tmux-256color bash --norc --noprofile -i"
tm set-option -t v status off >/dev/null
wait_for '^shell> ' 5 || { echo "FAIL no shell"; exit 1; }
tm send-keys -t v "$bin --lod off $model" Enter
wait_for 'cube\.dat \| [a-z]+ \| 256 \|' 10 || fail "the status line does not name 256"
for mode in 16 mono 256; do
  tm send-keys -t v c
  wait_for "cube\\.dat \\| [a-z]+ \\| $mode \\|" 5 >/dev/null || fail "c did not go to $mode"
done
tm send-keys -t v q
wait_for '^shell> $' 5 >/dev/null || fail "the shell's line after q is not empty"
if tm capture-pane -t v -p -J | grep -qE 'rgb:|\+r|\[\?|16t|62;'; then
  fail "answer bytes on the screen"
  tm capture-pane -t v -p
fi
python3 "$here/queries_pty.py" "$bin" "$model" || failed=$((failed + 1))
[ "$failed" -eq 0 ] && echo "ok" || echo "$failed failures"
exit $((failed > 0))
