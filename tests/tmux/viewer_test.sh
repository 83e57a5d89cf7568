#!/usr/bin/env bash
# Drives the real viewer in tmux: send-keys in, capture-pane out.
# Usage: viewer_test.sh path/to/termshade source-dir
set -u
bin=$(realpath "$1")
src=$(realpath "$2")
socket="termshade-test-$$"
work=$(mktemp -d)
passed=0
failed=0

# -u: UTF-8 whatever this script's locale (CI may have none).
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
cleanup() { tm kill-server 2>/dev/null; sleep 0.2; rm -rf "$work"; }
trap cleanup EXIT

pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }

# A pane running an interactive shell (so exit and terminal state can be seen).
start_shell() {  # start_shell COLS ROWS
  tm kill-server 2>/dev/null
  tm new-session -d -s v -x "$1" -y "$2" "env -i PATH=$PATH HOME=$work TERM=tmux-256color PS1='$ ' bash --norc --noprofile"
  tm set-option -t v status off >/dev/null
  wait_for '\$ ' 5 >/dev/null
}

screen() { tm capture-pane -t v -p; }
# The sanitizer build runs several times slower, more so beside other tests.
wait_scale=1
[ -n "${TERMSHADE_SANITIZED:-}" ] && wait_scale=4
# The screen with wrapped lines joined: a long path in a message may wrap.
joined_screen() { tm capture-pane -t v -p -J; }

# The glyph mode the viewer names on its status line (a long message may hide
# it: then the last one seen).
glyph_mode_shown() { screen | tail -n 1 | grep -oE ' (ramp|ascii|blocks|quadrants|sextants|braille) ' | head -n 1 | tr -d ' '; }
# The colour mode named after it ("quadrants | 256"), or nothing.
colour_mode_shown() {
  screen | tail -n 1 | grep -oE ' (ramp|ascii|blocks|quadrants|sextants|braille) \| (truecolor|256|16|mono) ' |
    head -n 1 | sed 's/.*| //; s/ $//'
}
last_glyphs=""
last_colour=""
note_glyphs() {
  local shown colour
  shown=$(glyph_mode_shown)
  if [ -n "$shown" ]; then last_glyphs=$shown; fi
  colour=$(colour_mode_shown)
  if [ -n "$colour" ]; then last_colour=$colour; fi
}

wait_for() {  # wait_for REGEX SECONDS: until the screen matches (4x SECONDS under the sanitizers)
  local deadline=$((SECONDS + $2 * ${wait_scale}))
  while [ $SECONDS -le "$deadline" ]; do
    if joined_screen | grep -qE -- "$1"; then note_glyphs; return 0; fi
    sleep 0.1
  done
  screen
  return 1
}

# Waits until the screen has not changed for 0.3 s (the viewer drew its frame).
settle() {
  local previous="" current stable=0
  for _ in $(seq 1 100); do
    sleep 0.1
    current=$(screen)
    if [ "$current" = "$previous" ]; then stable=$((stable + 1)); else stable=0; fi
    [ "$stable" -ge 3 ] && return 0
    previous=$current
  done
}

frame_matches_render() {  # NAME ROWS RENDER-ARGS...: screen minus status line == render
  local name=$1 rows=$2
  shift 2
  settle
  screen | head -n "$rows" | sed 's/[[:space:]]*$//' >"$work/screen.txt"
  # The viewer picks its glyph mode for the terminal and names it on the status line.
  note_glyphs
  # With colour, the screen's cells are the ansi dump's (compared by its
  # characters: SGR sequences dropped).
  local colour=()
  case " $* " in
    *" --format "*) ;;
    *) [ -n "$last_colour" ] && [ "$last_colour" != mono ] && colour=(--format ansi --color "$last_colour") ;;
  esac
  "$bin" render "$@" --fit "${colour[@]}" --glyphs "${last_glyphs:-none-seen}" | sed 's/\x1b\[[0-9;]*m//g; s/[[:space:]]*$//' >"$work/render.txt"
  if cmp -s "$work/screen.txt" "$work/render.txt"; then pass; else
    fail "$name: screen differs from 'termshade render $*'"
    diff "$work/screen.txt" "$work/render.txt" | head -20
  fi
}

run() { tm send-keys -t v -l -- "$1"; tm send-keys -t v Enter; }

# Types TEXT at the viewer's open prompt (o), then KEY (Enter unless given).
# Until no load runs (the status line says "loading", "preparing" or
# "turning up axis" while one does): `o` during a load is refused, and the
# text typed after it would be taken as keys.
until_loaded() {
  local deadline=$((SECONDS + 10 * wait_scale))
  while [ $SECONDS -le "$deadline" ] &&
    screen | tail -n 1 | grep -qE '^(loading|preparing|turning up axis) '; do sleep 0.1; done
}
at_prompt() {  # at_prompt TEXT [KEY]
  until_loaded
  tm send-keys -t v o
  tm send-keys -t v -l -- "$1"
  tm send-keys -t v "${2:-Enter}"
}

# Types an X10 mouse report (ESC [ M, then button, column, row, each + 32),
# the bytes a terminal sends when ncurses has asked for mouse reports.
mouse() {  # mouse BUTTON-CODE COL ROW (0-based cells)
  local report
  report=$(printf '\033[M\%03o\%03o\%03o' $(($1 + 32)) $(($2 + 33)) $(($3 + 33)))
  tm send-keys -t v -l "$(printf "$report")"
}

start_shell 80 25
# Without colour on a light background the ink follows each face's
# darkness (no negative): the screen is render's with --background light.
run "$bin --color none --background light --glyphs quadrants"
wait_for '\? help' 5 >/dev/null || fail "the light mono viewer did not start"
frame_matches_render light_mono_matches_render 24 "$src/data/sphere_cone.dat" --size 80x24 --background light
screen | head -n 24 >"$work/light.txt"
"$bin" render "$src/data/sphere_cone.dat" --size 80x24 --fit --glyphs quadrants | sed 's/[[:space:]]*$//' >"$work/dark.txt"
sed -i 's/[[:space:]]*$//' "$work/light.txt"
cmp -s "$work/light.txt" "$work/dark.txt" && fail "light_mono_differs_from_dark" || pass
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 1. The first screen is the headless render of the same view and size.
run "$bin"
wait_for '\? help' 5 >/dev/null || fail "demo did not start"
frame_matches_render first_screen_is_render 24 "$src/data/sphere_cone.dat" --size 80x24

# 2. Arrows change the view exactly as theta/phi do.
tm send-keys -t v Right Right Up
wait_for 'theta 0\.50 phi 1\.20' 5 >/dev/null || fail "arrows did not move theta/phi"
frame_matches_render arrows_match_render 24 "$src/data/sphere_cone.dat" --size 80x24 --theta 0.5 --phi 1.2
tm send-keys -t v h k k
wait_for 'theta 0\.40 phi 1\.00' 5 >/dev/null && pass || fail "vim keys did not orbit"

# 3. Method and distance keys match render's options.
tm send-keys -t v m
wait_for 'painter' 5 >/dev/null || fail "m did not switch to painter"
frame_matches_render method_key_matches_render 24 "$src/data/sphere_cone.dat" --size 80x24 --theta 0.4 --phi 1.0 --method painter
tm send-keys -t v m m m -
wait_for 'rho 19\.7' 5 >/dev/null || fail "- did not double rho"
default_rho=$("$bin" render "$src/data/sphere_cone.dat" --format json --size 4x2 |
  python3 -c 'import json, sys; print(repr(json.load(sys.stdin)["camera"]["rho"]))')
doubled_rho=$(python3 -c "print(repr(2 * $default_rho))")
frame_matches_render distance_key_matches_render 24 "$src/data/sphere_cone.dat" --size 80x24 --theta 0.4 --phi 1.0 --rho "$doubled_rho"
tm send-keys -t v r
wait_for 'theta 0\.30 phi 1\.30 rho 9\.85' 5 >/dev/null && pass || fail "r did not reset"

# 3b. Mouse: a drag turns the model with the pointer (0.1 rad a column, 0.1
# rad a cell height, rows being 2 columns tall), the wheel changes the distance.
mouse 0 40 12   # button 1 pressed
mouse 32 45 12  # moved with button 1 held
mouse 3 50 14   # released
wait_for 'theta -0\.70 phi 1\.10' 5 >/dev/null || fail "mouse drag did not orbit"
frame_matches_render mouse_drag_matches_render 24 "$src/data/sphere_cone.dat" --size 80x24 --theta -0.7 --phi 1.1 --method auto
mouse 65 40 12  # wheel down: farther
wait_for 'rho 19\.7' 5 >/dev/null && pass || fail "wheel down did not double rho"
mouse 64 40 12  # wheel up: closer
wait_for 'rho 9\.85' 5 >/dev/null && pass || fail "wheel up did not halve rho"
tm send-keys -t v r
wait_for 'theta 0\.30 phi 1\.30 rho 9\.85' 5 >/dev/null || fail "r did not reset after the mouse"

# 3c. A held key: 25 presses sent at once all count, and the view stops where
# they put it (the frames drawn for them are counted in etiquette_test.sh).
tm send-keys -t v $(printf 'Right %.0s' $(seq 1 25))
wait_for 'theta 2\.80 phi 1\.30' 5 >/dev/null || fail "queued arrow presses were lost"
frame_matches_render held_key_matches_render 24 "$src/data/sphere_cone.dat" --size 80x24 --theta 2.8 --method auto
tm send-keys -t v r
wait_for 'theta 0\.30 phi 1\.30 rho 9\.85' 5 >/dev/null || fail "r did not reset after the held key"

# 4. Resizing re-renders at the new size.
tm resize-window -t v -x 100 -y 31
wait_for 'theta 0\.30' 5 >/dev/null
frame_matches_render resize_rerenders 30 "$src/data/sphere_cone.dat" --size 100x30

# 5. A terminal too small for a frame gets a message, then recovers.
tm resize-window -t v -x 12 -y 3
wait_for 'terminal too' 5 >/dev/null && pass || fail "no too-small message"
tm resize-window -t v -x 80 -y 25
wait_for 'theta 0\.30' 5 >/dev/null || fail "no frame after growing again"
frame_matches_render recovers_after_too_small 24 "$src/data/sphere_cone.dat" --size 80x24

# 6. A bad path typed at 'o' shows an error and keeps the model.
at_prompt "$src/tests/models/bad/undefined_vertex.dat"
wait_for 'undefined_vertex.dat:14:7: vertex 12 is not defined' 5 >/dev/null && pass || fail "open error not shown"
frame_matches_render model_kept_after_bad_open 24 "$src/data/sphere_cone.dat" --size 80x24

# 7. A good path typed at 'o' opens it; n and p step between models.
at_prompt "$src/data/cube.dat"
wait_for 'opened' 5 >/dev/null || fail "open of a good file failed"
frame_matches_render opened_model_shown 24 "$src/data/cube.dat" --size 80x24
tm send-keys -t v p
wait_for 'demo' 5 >/dev/null && pass || fail "p did not go back to the demo"

# 7a. Paths as people type or drop them: ~ is the home directory, and the
# quotes a terminal puts around a dragged-in file are not part of the name.
mkdir -p "$work/my models"
cp "$src/data/wedge.dat" "$work/my models/wedge.dat"
cp "$src/data/cube.dat" "$work/home_cube.dat"
at_prompt "~/home_cube.dat"
wait_for "opened .*home_cube\.dat" 5 >/dev/null && pass || fail "~ in a typed path not expanded"
at_prompt " '$work/my models/wedge.dat' "
wait_for "opened .*my models/wedge\.dat" 5 >/dev/null && pass || fail "quoted dropped path not opened"
frame_matches_render dropped_path_opened 24 "$src/data/wedge.dat" --size 80x24

# Tab completes a name as a shell does; several matches are counted.
at_prompt "~/home_c" Tab
wait_for 'open: ~/home_cube\.dat' 5 >/dev/null && pass || fail "Tab did not complete the name"
tm send-keys -t v C-u
tm send-keys -t v -l "$work/my models/"
tm send-keys -t v Tab
wait_for 'open: .*my models/wedge\.dat' 5 >/dev/null && pass || fail "Tab did not complete in a directory"
tm send-keys -t v C-u
tm send-keys -t v -l "~/"
tm send-keys -t v Tab
wait_for 'open \([0-9]+ matches\): ~/' 5 >/dev/null && pass || fail "Tab did not count several matches"
tm send-keys -t v Escape

# A completed name keeps the control bytes typing drops (shown as '?'), so it opens
# (a copy of the wedge: the model shown stays the one the next steps expect).
cp "$src/data/wedge.dat" "$work/"$'evil\e[31mRED\a.dat'
at_prompt "~/evil" Tab
wait_for 'open: ~/evil\?\[31mRED\?\.dat' 5 >/dev/null && pass || fail "Tab did not complete a name with control bytes"
tm send-keys -t v Enter
wait_for 'opened .*evil\\x1B\[31mRED\\x07\.dat' 5 >/dev/null && pass || fail "completed name with control bytes not opened"

# 7b. A big model (half a million vertices, about a second to load) shows
# "loading" on the status line while it loads.
python3 - "$work/big.dat" <<'PY'
import math, sys
n = 700
with open(sys.argv[1], "w") as out:
    for i in range(1, n):
        for j in range(n):
            t, p = math.pi * i / n, 2 * math.pi * j / n
            out.write("%d %.6f %.6f %.6f\n" % ((i - 1) * n + j + 1, math.sin(t) * math.cos(p),
                                                math.sin(t) * math.sin(p), math.cos(t)))
    out.write("Faces:\n")
    for i in range(n - 2):
        for j in range(n):
            k = (j + 1) % n
            out.write("%d %d %d %d.\n" % (i * n + j + 1, (i + 1) * n + j + 1, (i + 1) * n + k + 1,
                                           i * n + k + 1))
PY
# The load runs on a worker: the viewer answers keys meanwhile, and Esc
# cancels it, keeping the model shown.
at_prompt "$work/big.dat"
wait_for 'loading .*big\.dat.*Esc cancels' 5 >/dev/null && pass || fail "no loading message for a big model"
tm send-keys -t v Right
tm send-keys -t v Escape
wait_for 'cancelled loading .*big\.dat' 5 >/dev/null && pass || fail "Esc did not cancel the load"
# The model shown before (the wedge), turned by the key pressed while loading.
frame_matches_render key_while_loading_and_model_kept 24 "$src/data/wedge.dat" --size 80x24 --theta 0.4
tm send-keys -t v r
at_prompt "$work/big.dat"
wait_for 'loading .*big\.dat' 5 >/dev/null && pass || fail "no loading message the second time"
wait_for 'opened .*big\.dat' 30 >/dev/null && pass || fail "the big model did not open"
# u turns the big model on the worker: keys are answered meanwhile (the help
# comes up beside "turning up axis"), then the turned model is shown.
tm send-keys -t v u '?'
if wait_for 'turning up axis to .*big\.dat' 5 >/dev/null && screen | grep -q 'termshade keys'; then
  pass
else
  fail "u on a big model: no help while it was being turned"
fi
wait_for '^up axis [-+][xyz] ' 30 >/dev/null && pass || fail "u on a big model: never turned"
tm send-keys -t v '?'  # closes the help
wait_for '\? help' 5 >/dev/null
# Opening a small model after the big one hands the big one's pages back to
# the system (the heap keeps freed memory for reuse while loading).
viewer_rss_kib() { awk '/^VmRSS:/ { print $2 }' "/proc/$(pgrep -P "$(tm list-panes -t v -F '#{pane_pid}')" | head -n 1)/status"; }
big_rss=$(viewer_rss_kib)
at_prompt "$src/data/cube.dat"
wait_for 'opened .*cube\.dat' 10 >/dev/null || fail "cube.dat after the big model did not open"
# (A level-of-detail build of the big model may still be ending: it was asked to stop.)
small_rss=$(viewer_rss_kib)
for _ in $(seq 1 100); do
  [ "$((small_rss * 3))" -lt "${big_rss:-0}" ] && break
  sleep 0.1
  small_rss=$(viewer_rss_kib)
done
if [ -n "${TERMSHADE_SANITIZED:-}" ]; then :; elif [ "${small_rss:-0}" -gt 0 ] && [ "$((small_rss * 3))" -lt "${big_rss:-0}" ]; then pass; else
  fail "memory 10 s after replacing the big model: ${small_rss:-?} KiB, with it ${big_rss:-?} KiB"
fi
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null || fail "q after the big model"
# The first model loads with the screen already taken: Esc cancels it (exit
# 1, saying so) and Ctrl-C quits at once with its own status.
run "clear; $bin $work/big.dat; echo status=\$?"
wait_for 'loading .*big\.dat' 5 >/dev/null && pass || fail "no loading message for the first model"
tm send-keys -t v Escape
wait_for 'cancelled loading .*big\.dat' 5 >/dev/null && pass || fail "Esc did not cancel the first load"
wait_for '^status=1' 5 >/dev/null && pass || fail "cancelled first load: exit status not 1"
run "clear; bash -c 'trap \"\" INT; $bin $work/big.dat; echo status=\$?'"
wait_for 'loading .*big\.dat' 5 >/dev/null || fail "no loading message for the first model (Ctrl-C)"
tm send-keys -t v C-c
wait_for '^status=130' 3 >/dev/null && pass || fail "Ctrl-C during the first load: status not 130 at once"
# An import through Assimp runs in the import helper, a child of the viewer:
# one that hangs (stopped here, so it uses no processor time) is cancelled by
# Esc at once, and no helper is left behind.
python3 - "$work/big.off" <<'PY'
import math, sys
n = 1000
out = ["OFF\n%d %d 0\n" % ((n - 1) * n, (n - 2) * n)]
for i in range(1, n):
    for j in range(n):
        t, p = math.pi * i / n, 2 * math.pi * j / n
        out.append("%.6f %.6f %.6f\n" % (math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t)))
for i in range(n - 2):
    for j in range(n):
        k = (j + 1) % n
        out.append("4 %d %d %d %d\n" % (i * n + j, i * n + k, (i + 1) * n + k, (i + 1) * n + j))
open(sys.argv[1], "w").write("".join(out))
PY
run "clear; $bin $work/big.off; echo status=\$?"
pane=$(tm list-panes -t v -F '#{pane_pid}')
# Stopped as soon as it runs the helper's program (often before it asks to
# die with the viewer), as a helper hung inside Assimp would be: the viewer,
# leaving, stops its load and the load kills and reaps the helper.
helper=""
runs_helper() { case "$(readlink "/proc/$1/exe" 2>/dev/null)" in */termshade-import) return 0 ;; esac; return 1; }
for _ in $(seq 1 $((2000 * wait_scale))); do
  viewer=$(pgrep -P "$pane" | head -n 1)
  candidate=""
  [ -n "$viewer" ] && candidate=$(pgrep -P "$viewer" | head -n 1)
  if [ -n "$candidate" ] && runs_helper "$candidate"; then
    helper=$candidate
    break
  fi
  sleep 0.002
done
if [ -n "$helper" ] && kill -STOP "$helper" 2>/dev/null; then pass; else fail "no import helper seen for big.off"; fi
wait_for 'loading .*big\.off' 5 >/dev/null && pass || fail "no loading message for big.off"
tm send-keys -t v Escape
wait_for 'cancelled loading .*big\.off' 5 >/dev/null && pass || fail "Esc did not cancel a hung Assimp import"
wait_for '^status=1' 5 >/dev/null && pass || fail "cancelled Assimp import: exit status not 1"
helper_alive() { [ -n "$helper" ] && [ -e "/proc/$helper" ] && ! grep -q '^[0-9]* ([^)]*) Z' "/proc/$helper/stat" 2>/dev/null; }
for _ in $(seq 1 $((200 * wait_scale))); do helper_alive || break; sleep 0.01; done
if helper_alive; then fail "the import helper was left running"; else pass; fi
# Exact one-sample frames of a big model (--lod off --glyphs ramp): its
# triangle hierarchy (977k triangles, 500 a sample at 80x24) is built on a
# worker once the first frame is up, and the frames drawn by walking it are render's (which draws one
# frame by clusters), before and after a turn.
run "clear; $bin --lod off --glyphs ramp $work/big.dat"
wait_for 'big\.dat' $((10 * wait_scale)) >/dev/null || fail "the big model did not open with --lod off"
settle
sleep $((1 * wait_scale))
frame_matches_render big_model_by_hierarchy 24 "$work/big.dat" --size 80x24
tm send-keys -t v Right Right Up
wait_for 'theta 0\.50 phi 1\.20' 5 >/dev/null || fail "arrows did not turn the big model"
frame_matches_render big_model_by_hierarchy_turned 24 "$work/big.dat" --size 80x24 --theta 0.5 --phi 1.2
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

rm -f "$work/big.dat"
run "clear; $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start again after the big model"

# 7c. A FIFO typed at 'o' is refused at once (regular files only), and the
# viewer goes on.
mkfifo "$work/pipe.obj"
at_prompt "$work/pipe.obj"
wait_for 'pipe\.obj: .*(regular|FIFO|fifo)' 3 >/dev/null && pass || fail "o on a FIFO did not fail at once (the loader must refuse what is not a regular file: issue 7 item 3)"
tm send-keys -t v Escape
tm send-keys -t v Right
wait_for 'theta 0\.40' 5 >/dev/null && pass || fail "keys dead after o on a FIFO"
tm send-keys -t v r

# 8. q exits and leaves the shell usable (echo on, canonical input).
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null || fail "q did not return to the shell"
run "stty -a | tr ' ' '\n' | grep -xE 'echo|icanon' | tr '\n' ' '; echo; echo done-\$((6*7))"
wait_for '^(icanon echo|echo icanon)' 5 >/dev/null && pass || fail "terminal not sane after q"
wait_for 'done-42' 5 >/dev/null && pass || fail "shell not usable after q"

# 9. Signals: the terminal is given back (alternate screen left, cursor
# shown, mouse reports off, echo and canonical input on) and the exit status
# is the signal's, 128 + N. SIGTERM, SIGHUP and Ctrl-C end the event loop;
# SIGSEGV, SIGABRT, SIGUSR1 and SIGALRM restore the terminal in the handler.
terminal_given_back() {  # NAME
  local flags
  flags=$(tm display-message -p -t v '#{alternate_on} #{cursor_flag} #{mouse_any_flag}')
  if [ "$flags" = "0 1 0" ]; then pass; else
    fail "$1: alternate screen, cursor, mouse = '$flags' (want '0 1 0')"
  fi
  run "clear; stty -a | tr ' ' '\n' | grep -xE 'echo|icanon' | tr '\n' ' '; echo"
  wait_for '^(icanon echo|echo icanon)' 5 >/dev/null && pass || fail "terminal not sane after $1"
}
for how in TERM HUP INT SEGV ABRT USR1 ALRM; do
  number=$(kill -l "$how")
  tm send-keys -t v C-l
  # The wrapper shell ignores SIGINT, so Ctrl-C reaches the viewer alone
  # and the wrapper lives to print the status.
  run "clear; bash -c 'trap \"\" INT; $bin; echo status=\$?'"
  wait_for '\? help' 5 >/dev/null || fail "viewer did not start for SIG$how"
  if [ "$(tm display-message -p -t v '#{alternate_on} #{mouse_any_flag}')" != "1 1" ]; then
    fail "SIG$how: the viewer did not take the screen and mouse"
  fi
  if [ "$how" = INT ]; then
    tm send-keys -t v C-c
  else
    pkill -"$how" -f "^$bin\$" || fail "no viewer process for SIG$how"
  fi
  wait_for "^status=$((128 + number))" 5 >/dev/null && pass || fail "SIG$how: exit status not $((128 + number))"
  terminal_given_back "SIG$how"
done

# 9b. Ctrl-Z gives the shell a sane terminal; fg brings the whole screen back
# (not a blank one) with keys working.
tm send-keys -t v C-l
run "clear; $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start for Ctrl-Z"
tm send-keys -t v C-z
wait_for 'Stopped' 5 >/dev/null && pass || fail "Ctrl-Z did not stop the viewer"
run "stty -a | tr ' ' '\n' | grep -xE 'echo|icanon' | tr '\n' ' '; echo; echo stopped-\$((6*7))"
wait_for '^(icanon echo|echo icanon)' 5 >/dev/null && pass || fail "terminal not sane after Ctrl-Z"
wait_for 'stopped-42' 5 >/dev/null || fail "shell not usable after Ctrl-Z"
run "fg"
wait_for 'theta 0\.30 phi 1\.30' 5 >/dev/null || fail "no status line after fg"
frame_matches_render whole_screen_after_fg 24 "$src/data/sphere_cone.dat" --size 80x24
tm send-keys -t v Right
wait_for 'theta 0\.40' 5 >/dev/null && pass || fail "arrow keys dead after fg"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null || fail "q after fg"

# 10. Bad models, escapes in names, dumb terminals.
run "clear; $bin $src/tests/models/bad/undefined_vertex.dat; echo exit=\$?"
wait_for 'undefined_vertex.dat:14:7: vertex 12 is not defined' 5 >/dev/null && pass || fail "bad model at start"
wait_for 'exit=1' 5 >/dev/null && pass || fail "bad model exit code"
# The viewer's --memory-budget reaches its loads (the first one included).
run "clear; $bin --memory-budget 1K $src/data/cube.dat; echo budget_exit=\$?"
wait_for 'more than the memory budget of 1.0 KiB' 5 >/dev/null && pass || fail "viewer --memory-budget not applied"
wait_for 'budget_exit=1' 5 >/dev/null && pass || fail "viewer over budget: exit code not 1"
cp "$src/data/wedge.dat" "$work/$(printf 'evil\033[7mname').dat"
run "clear; cd $work && $bin evil*name.dat"
wait_for 'evil\\x1B\[7mname' 5 >/dev/null || fail "escape in the model name not shown escaped"
at_prompt "nothing-here.dat"
wait_for 'nothing-here.dat: cannot open' 5 >/dev/null && pass || fail "missing file at o"
tm send-keys -t v '?'
wait_for 'termshade keys' 5 >/dev/null && pass || fail "help overlay"
tm send-keys -t v x q
wait_for '^\$ ?$' 5 >/dev/null || fail "q after help"
# 11. Colour where the terminal has it (256 colours here, 24-bit with
# COLORTERM=truecolor), none with NO_COLOR, --mono or --color none; never a
# background of our own in a one-colour mode (ascii here); nothing of it left
# on the shell's line afterwards.
colour_codes() { grep -oE '38;(5;[0-9]+|2;[0-9]+;[0-9]+)' | sort -u; }
run "clear; $bin"
wait_for '\? help' 5 >/dev/null
settle
tm capture-pane -t v -p -e >"$work/colours.txt"
if grep -q '48;' "$work/colours.txt"; then fail "a background colour was painted"; else pass; fi
if grep -q '38;5;' "$work/colours.txt"; then pass; else fail "no 256-colour faces"; fi
# The ansi dump carries the same colours as the screen.
head -n 24 "$work/colours.txt" | colour_codes >"$work/screen_colours.txt"
"$bin" render "$src/data/sphere_cone.dat" --fit --size 80x24 --format ansi --color 256 | colour_codes >"$work/dump_colours.txt"
if [ -s "$work/dump_colours.txt" ] && cmp -s "$work/screen_colours.txt" "$work/dump_colours.txt"; then pass; else
  fail "screen and ansi dump colours differ"
  diff "$work/screen_colours.txt" "$work/dump_colours.txt" | head -5
fi
tm send-keys -t v c
settle
if tm capture-pane -t v -p -e | grep -q '38;'; then fail "c did not turn colour off"; else pass; fi
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
run "echo after-viewer"
wait_for '^after-viewer' 5 >/dev/null
if tm capture-pane -t v -p -e | grep 'after-viewer' | grep -q '[34]8;'; then fail "colour left on the shell"; else pass; fi
# colour_case yes|no PATTERN COMMAND: starts the viewer by COMMAND and checks
# whether the screen's SGR sequences match PATTERN.
colour_case() {
  local got=no
  run "clear; $3"
  wait_for '\? help' 5 >/dev/null
  settle
  if tm capture-pane -t v -p -e | grep -qE "$2"; then got=yes; fi
  if [ "$got" = "$1" ]; then pass; else fail "colour '$2' expected $1 with: $3"; fi
  tm send-keys -t v q
  wait_for '^\$ ?$' 5 >/dev/null
}
colour_case yes '38;2;' "COLORTERM=truecolor $bin"
for mono in "NO_COLOR=1 $bin" "$bin --mono" "$bin --color none" "COLORTERM=truecolor $bin --mono"; do
  colour_case no '38;' "$mono"
done
colour_case yes '38;5;' "NO_COLOR=1 $bin --color 256"

# 12. Several models on the command line: n and p step through them.
run "clear; $bin $src/data/cube.dat $src/data/beams.dat"
wait_for 'cube.dat \[1/2\]' 5 >/dev/null && pass || fail "first of two models"
frame_matches_render first_of_two_models 24 "$src/data/cube.dat" --size 80x24
tm send-keys -t v n
wait_for 'beams.dat \[2/2\]' 5 >/dev/null && pass || fail "n did not step to the second model"
frame_matches_render second_of_two_models 24 "$src/data/beams.dat" --size 80x24
tm send-keys -t v n
wait_for 'cube.dat \[1/2\]' 5 >/dev/null && pass || fail "n did not wrap around"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
# n after a model that fails moves on to the next one.
run "clear; $bin $src/data/cube.dat $src/tests/models/bad/undefined_vertex.dat $src/data/beams.dat"
wait_for 'cube.dat \[1/3\]' 5 >/dev/null || fail "first of three models"
tm send-keys -t v n
wait_for 'undefined_vertex.dat:14:7' 5 >/dev/null && pass || fail "n to a bad model: no error"
tm send-keys -t v n
wait_for 'beams.dat \[3/3\]' 5 >/dev/null && pass || fail "n after a failed model did not move on"
frame_matches_render next_after_failed_model 24 "$src/data/beams.dat" --size 80x24
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 12b. The up axis: --up and degrees as render takes them; u cycles the axis
# (+z +y +x ...), keeps the view, and says so on the status line.
spider="$src/tests/models/real/spider_z_up_binary.stl"
run "clear; $bin --theta 20deg $spider"
wait_for 'spider_z_up_binary.stl' 5 >/dev/null || fail "z-up STL did not open"
frame_matches_render viewer_degrees_match_render 24 "$spider" --size 80x24 --theta 20deg
tm send-keys -t v Right u
wait_for 'up axis \+y' 5 >/dev/null && pass || fail "u did not turn the up axis to +y"
turned_theta=$(python3 -c 'import math; print(repr(20 * (math.pi / 180) + 0.1))')
frame_matches_render u_key_matches_render_up 24 "$spider" --size 80x24 --theta "$turned_theta" --up y
tm send-keys -t v u
wait_for 'up axis \+x' 5 >/dev/null && pass || fail "u did not cycle on to +x"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
run "clear; $bin --up -y $spider"
wait_for 'spider_z_up_binary.stl' 5 >/dev/null || fail "--up -y did not open"
frame_matches_render viewer_up_option_matches_render 24 "$spider" --size 80x24 --up -y
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 13. The same first screen in a UTF-8 locale as in the C locale.
run "clear; LANG=C.UTF-8 LC_ALL=C.UTF-8 $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start in C.UTF-8"
# (With colour the block modes split each cell into fg and bg, as the ansi dump does.)
frame_matches_render utf8_locale_first_screen 24 "$src/data/sphere_cone.dat" --size 80x24 --format ansi --color 256
# g cycles the glyph modes; each frame is render's in that mode.
for mode in sextants braille ramp ascii blocks; do
  tm send-keys -t v g
  wait_for " $mode " 5 >/dev/null || fail "g did not reach $mode"
  case $mode in
    blocks | sextants) as_dump=(--format ansi --color 256) ;;
    *) as_dump=() ;;
  esac
  frame_matches_render "glyphs_$mode" 24 "$src/data/sphere_cone.dat" --size 80x24 "${as_dump[@]}"
done
# The two-colour modes paint their background: the ansi dump's bg colours (SGR 48).
bg_codes() { grep -oE '[[;]48;(5;[0-9]+|2;[0-9]+;[0-9]+)' | cut -c2- | sort -u; }
tm capture-pane -t v -p -e | head -n 24 | bg_codes >"$work/screen_bg.txt"
"$bin" render "$src/data/sphere_cone.dat" --fit --size 80x24 --glyphs blocks --format ansi --color 256 | bg_codes >"$work/dump_bg.txt"
if [ -s "$work/dump_bg.txt" ] && cmp -s "$work/screen_bg.txt" "$work/dump_bg.txt"; then pass; else
  fail "blocks: the screen's background colours are not the ansi dump's"
  diff "$work/screen_bg.txt" "$work/dump_bg.txt" | head -5
fi
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 13a. A ramp beyond ASCII: the same screen as render's in a UTF-8 locale,
# a clear refusal in the C locale (the terminal could not show it).
run "clear; LANG=C.UTF-8 LC_ALL=C.UTF-8 $bin --ramp '░▒▓█'"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start with a block ramp"
frame_matches_render block_ramp_first_screen 24 "$src/data/sphere_cone.dat" --size 80x24 --ramp '░▒▓█' --format ansi --color 256
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
# The prompt takes UTF-8: a path typed with an accent opens, and the status
# line shows the name as it is (one cell per code point); a right-to-left
# override in a name stays escaped, so it cannot reorder the line.
cp "$src/data/cube.dat" "$work/café.dat"
run "clear; LANG=C.UTF-8 LC_ALL=C.UTF-8 $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start in C.UTF-8 for the prompt"
tm send-keys -t v o
tm send-keys -t v -l "$work/café.dat"
wait_for 'open: .*café\.dat' 5 >/dev/null && pass || fail "prompt did not show the accented path"
tm send-keys -t v Enter
wait_for 'opened .*café\.dat' 5 >/dev/null && pass || fail "accented path did not open as café.dat"
frame_matches_render accented_path_opened 24 "$work/café.dat" --size 80x24 --format ansi --color 256
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
cp "$src/data/cube.dat" "$work/évil$(printf '\xe2\x80\xae')tad.dat"
run "clear; LANG=C.UTF-8 LC_ALL=C.UTF-8 $bin $work/évil*tad.dat"
wait_for '/évil\\xE2\\x80\\xAEtad\.dat' 5 >/dev/null && pass || fail "bidi override in a name not escaped"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
# A wide (CJK) name: two cells a code point, so "? help" stays at the right
# edge; typed at the prompt it opens, the cursor after its last cell.
cp "$src/data/cube.dat" "$work/模型.dat"
run "clear; LANG=C.UTF-8 LC_ALL=C.UTF-8 $bin $work/模型.dat"
wait_for '/模型\.dat' 5 >/dev/null && pass || fail "wide name not shown"
if screen | tail -n 1 | grep -qE '\? help$'; then pass; else fail "wide name pushed the status line: $(screen | tail -n 1)"; fi
tm send-keys -t v o
tm send-keys -t v C-u
tm send-keys -t v -l "$work/模型.dat"
wait_for 'open: .*模型\.dat' 5 >/dev/null || fail "prompt did not show the wide name"
cursor_col=$(tm display -p -t v '#{cursor_x}')
prompt_cells=$(screen | tail -n 1 | sed 's/ *$//' | python3 -c 'import sys, unicodedata as u; t=sys.stdin.read().rstrip("\n"); print(sum(2 if u.east_asian_width(c) in "WF" else 1 for c in t))')
[ "$cursor_col" = "$prompt_cells" ] && pass || fail "prompt cursor at $cursor_col, text ends at $prompt_cells"
tm send-keys -t v Enter
wait_for 'opened .*模型\.dat' 5 >/dev/null && pass || fail "wide name typed at the prompt did not open"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
run "clear; LANG=C LC_ALL=C $bin $work/café.dat"
wait_for '/caf\\xC3\\xA9\.dat' 5 >/dev/null && pass || fail "accented name in the C locale not escaped"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null
run "clear; LANG=C LC_ALL=C $bin --ramp '░▒▓█'; echo exit=\$?"
wait_for 'need a UTF-8 locale' 5 >/dev/null && pass || fail "block ramp in the C locale not refused"
wait_for 'exit=2' 5 >/dev/null && pass || fail "block ramp in the C locale: exit code"

# 13b. Old terminal descriptions: vt100's strings carry padding ($<5>),
# which must not reach the screen; ansi would scroll on its bottom-right
# cell, so the status line ends one cell early there; neither has an
# alternate screen.
for term in vt100 ansi; do
  run "clear; TERM=$term $bin"
  wait_for '\? help' 5 >/dev/null || fail "viewer did not start as $term"
  frame_matches_render "first_screen_as_$term" 24 "$src/data/sphere_cone.dat" --size 80x24
  if screen | grep -qF '$<'; then fail "padding shown as $term"; else pass; fi
  if screen | tail -n 1 | grep -qE '\? help ?$'; then pass; else fail "status line cut as $term"; fi
  tm send-keys -t v q
  wait_for '^\$ ?$' 5 >/dev/null
  # No alternate screen there: quitting clears the frame and the status line.
  if [ "$(screen | grep -cvE '^(\$ ?)? *$')" -eq 0 ]; then pass; else
    fail "frame left on the screen after quitting as $term: $(screen | grep -vE '^ *$' | head -n 3)"
  fi
done

# 14. SGR (1006) mouse reports, which xterm-256color's terminfo asks for:
# ESC [ < button ; column ; row (1-based), M for press or motion, m for release.
run "clear; TERM=xterm-256color $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start as xterm-256color"
tm send-keys -t v -l "$(printf '\033[<0;41;13M')"
tm send-keys -t v -l "$(printf '\033[<32;46;13M')"
tm send-keys -t v -l "$(printf '\033[<0;51;15m')"
wait_for 'theta -0\.70 phi 1\.10' 5 >/dev/null && pass || fail "SGR mouse drag did not orbit"
tm send-keys -t v -l "$(printf '\033[<65;41;13M')"
wait_for 'rho 19\.7' 5 >/dev/null && pass || fail "SGR wheel down did not double rho"
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 14b. The same drag in one burst (press, motion and release read at once, as
# over SSH or while a frame is drawn): ncurses keeps only the last report of
# a burst, so the viewer decodes them itself; every report counts.
for encoding in sgr x10; do
  if [ "$encoding" = sgr ]; then
    run "clear; TERM=xterm-256color $bin"
    burst=$(printf '\033[<0;41;13M\033[<32;46;13M\033[<0;51;15m')
  else
    run "clear; $bin"
    burst=$(printf '\033[M\040\111\055\033[M\100\116\055\033[M\043\123\057')
  fi
  wait_for '\? help' 5 >/dev/null || fail "viewer did not start ($encoding burst)"
  tm send-keys -t v -l "$burst"
  wait_for 'theta -0\.70 phi 1\.10' 5 >/dev/null && pass || fail "$encoding mouse burst did not orbit"
  tm send-keys -t v q
  wait_for '^\$ ?$' 5 >/dev/null
done

# 15. A terminal that reports its pixel size sets the cell aspect: 10x18-pixel
# cells (aspect 1.8) give the frame 'render --cell-aspect 1.8' gives.
run "clear; python3 -c 'import fcntl, struct, termios; fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack(\"HHHH\", 25, 80, 800, 450))'; $bin"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start with a pixel size"
frame_matches_render pixel_size_sets_cell_aspect 24 "$src/data/sphere_cone.dat" --size 80x24 --cell-aspect 1.8
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

# 16. y: the status line shows the `termshade render` command of the view,
# and OSC 52 puts it in tmux's paste buffer (set-clipboard on). Run, it
# writes the screen's frame cell for cell, colours included: after orbiting,
# zooming, a refit (f) at the closer distance and zooming out again, another
# method, shading and cell aspect, the light moved (L), a model path with a
# space; then again with colour off.
tm set-option -s set-clipboard on
cp "$src/data/sphere_cone.dat" "$work/two words.dat"
run "clear; cd $work; LANG=C.UTF-8 LC_ALL=C.UTF-8 COLORTERM=truecolor $bin --glyphs quadrants 'two words.dat'; cd - >/dev/null"
wait_for '\? help' 5 >/dev/null || fail "viewer did not start for y"
tm send-keys -t v Right Right Up + f - m s a L Left Down L
wait_for 'theta 0\.50 phi 1\.20 rho 9\.8' 5 >/dev/null || fail "keys before y were not applied"
settle
view_command_matches() {  # NAME CAPTURE-OPTION: y, then the buffer's command against the screen
  tm delete-buffer 2>/dev/null
  tm send-keys -t v y
  wait_for 'termshade render' 5 >/dev/null || fail "$1: y did not show the command"
  settle
  local command
  command=$(tm show-buffer 2>/dev/null)
  case $command in
    "termshade render '$work/two words.dat' "*" --fit --fit-rho 4."*) pass ;;
    *) fail "$1: no render command in tmux's buffer (OSC 52): '$command'" ;;
  esac
  screen | tail -n 1 | grep -q "^termshade render '" && pass || fail "$1: status line: $(screen | tail -n 1)"
  tm capture-pane -t v -p $2 >"$work/screen.ans"
  eval "\"\$bin\" ${command#termshade }" >"$work/render.ans" || fail "$1: the command failed: $command"
  if python3 "$src/tests/tmux/ansi_cells.py" "$work/screen.ans" "$work/render.ans" 24 >/dev/null; then pass; else
    fail "$1: the screen differs from: $command"
    python3 "$src/tests/tmux/ansi_cells.py" "$work/screen.ans" "$work/render.ans" 24
  fi
}
view_command_matches view_command_truecolor -e
# Shape-matched ascii with colour: the screen's cells are the ansi dump's too.
tm send-keys -t v g g g g
wait_for ' ascii \| truecolor ' 5 >/dev/null || fail "g did not reach ascii"
view_command_matches view_command_ascii_truecolor -e
# c steps down to 256, 16, then none.
tm send-keys -t v c c c
wait_for ' ascii \| mono ' 5 >/dev/null || fail "c did not reach mono"
view_command_matches view_command_mono -e
tm send-keys -t v q
wait_for '^\$ ?$' 5 >/dev/null

run "clear; TERM=dumb $bin; echo exit=\$?"
wait_for 'termshade render' 5 >/dev/null && pass || fail "dumb terminal message"
wait_for 'exit=2' 5 >/dev/null && pass || fail "dumb terminal exit code"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
