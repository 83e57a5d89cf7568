#!/usr/bin/env bash
# Textures in the viewer, in a real terminal (tmux, 24-bit colour): the
# Collada duck opens yellow (its texture duckCM.tga), `t` turns it to its
# white material with the status line saying "untextured", `t` again brings
# the yellow back (a window wide enough for the status line's method field).
# Usage: textures_test.sh path/to/termshade
set -u
bin=$(realpath "$1")
duck=/usr/share/assimp/models/Collada/duck.dae
[ -f "$duck" ] || { echo "skip: no $duck (assimp-testmodels)"; exit 77; }
socket="termshade-textures-$$"
work=$(mktemp -d)
failed=0
source "$(dirname "$0")/../support/tmux_session.sh"
scale=1
[ -n "${TERMSHADE_SANITIZED:-}" ] && scale=4
# The foreground colours of the pane: "R G B" a line.
colours() { tm capture-pane -t v -p -e | grep -oE '38;2;[0-9]+;[0-9]+;[0-9]+' | cut -d';' -f3- | tr ';' ' '; }
yellow() { awk '$1 > 150 && $2 > 120 && $3 < 0.5 * $1 {n++} END {exit !(n > 100)}'; }
settle() {  # the screen unchanged for 0.3 s
  local previous="" current stable=0
  for _ in $(seq 1 $((100 * scale))); do
    sleep 0.1
    current=$(tm capture-pane -t v -p -e)
    if [ "$current" = "$previous" ]; then stable=$((stable + 1)); else stable=0; fi
    [ "$stable" -ge 3 ] && return 0
    previous=$current
  done
}

tm new-session -d -s v -x 200 -y 40 \
  "env COLORTERM=truecolor TERM=xterm-256color $bin $duck --glyphs sextants --color truecolor"
wait_for 'duck\.dae' $((10 * scale)) || fail "the viewer did not open the duck"
settle
colours | yellow || fail "the duck is not yellow"
tm send-keys -t v t
wait_for 'untextured' $((5 * scale)) || fail "t: the status line does not say untextured"
settle
colours | yellow && fail "t: the duck is still yellow"
tm send-keys -t v t
wait_for ' textured' $((5 * scale)) || fail "t again: the status line does not say textured"
settle
colours | yellow || fail "t again: the duck is not yellow"
tm send-keys -t v q
[ "$failed" -eq 0 ] && echo "ok" || echo "$failed failed"
exit $((failed > 0))
