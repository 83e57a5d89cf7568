#!/usr/bin/env bash
# The exports, read back by what reads them: asciicast recordings parsed as
# v2 and replayed in a real terminal (tmux), whose screen must then be the
# last frame's text dump; SVG pictures rasterised by rsvg-convert, whose ink
# must show the ansi dump's cells: each block part's
# colour, braille dots, text glyphs' ink.
# Usage: export_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
socket="termshade-export-$$"
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
trap 'tm kill-server 2>/dev/null; rm -rf "$work"' EXIT
passed=0
failed=0
expect() {  # expect NAME COMMAND...
  local name=$1
  shift
  if "$@" >"$work/expect.out" 2>&1; then
    passed=$((passed + 1))
  else
    echo "FAIL $name: $(head -c 600 "$work/expect.out")"
    failed=$((failed + 1))
  fi
}
for tool in tmux rsvg-convert /usr/bin/python3; do
  command -v "$tool" >/dev/null || { echo "SKIP: $tool missing (scripts/install-deps.sh test)"; exit 77; }
done
/usr/bin/python3 -c 'import PIL' 2>/dev/null || { echo "SKIP: python3-pil missing"; exit 77; }
readback=(/usr/bin/python3 "$src/tests/export/read_back.py")
duck=/usr/share/assimp/models/Collada/duck.dae
[ -f "$duck" ] || duck=$src/data/sphere_cone.dat

# Replays a recording in a tmux pane of its size; the pane's text goes to $3.
replay() {  # replay CAST_BYTES COLS ROWS OUT
  tm kill-server 2>/dev/null
  tm new-session -d -s r -x "$2" -y "$3" "cat '$1'; sleep 30"
  sleep 0.5
  tm capture-pane -p -t r >"$4"
  tm capture-pane -p -e -t r >"$4.ans"
  tm kill-server 2>/dev/null
}

# Step 1: asciicast, in every glyph mode that draws differently, in colour and without.
for case in "ramp none" "sextants truecolor" "quadrants 256" "braille 256"; do
  set -- $case
  glyphs=$1 colour=$2 name="cast_${1}_$2"
  args=("$duck" --size 60x20 --glyphs "$glyphs" --color "$colour" --theta 0.2 --step 0.35)
  expect "${name}_renders" "$bin" render "${args[@]}" --frames 6 --fps 12.5 --format asciicast -o "$work/$name.cast"
  expect "${name}_is_asciicast_v2" bash -c "${readback[*]} cast '$work/$name.cast' 60 20 6 12.5 >'$work/$name.bytes'"
  "$bin" render "${args[@]}" --frames 6 --format ansi | tail -n 20 >"$work/$name.last.ans"
  sed 's/\x1b\[[0-9;]*m//g; s/ *$//' "$work/$name.last.ans" >"$work/$name.last"
  replay "$work/$name.bytes" 60 20 "$work/$name.screen"
  expect "${name}_replays_to_the_last_frame" diff "$work/$name.last" <(sed 's/ *$//' "$work/$name.screen")
  # Later frames send only what changed: the colours must still be the last frame's.
  expect "${name}_replays_the_last_frames_colours" /usr/bin/python3 "$src/tests/tmux/ansi_cells.py" \
    "$work/$name.last.ans" "$work/$name.screen.ans" 20
done
expect cast_steady_rate "$bin" render "$src/data/cube.dat" --size 20x8 --frames 3 --format asciicast -o "$work/rate.cast"
expect cast_default_fps_is_25 grep -q '^\[0.080000, "o"' "$work/rate.cast"
# Frames that look the same: one event draws them, the close keeps the last one's time.
expect cast_unchanged_frames_have_no_event bash -c "'$bin' render '$src/data/cube.dat' --size 20x8 --frames 3 --step 0 --format asciicast -o '$work/still.cast' && ${readback[*]} cast '$work/still.cast' 20 8 3 25 >/dev/null && [ \$(wc -l <'$work/still.cast') -eq 3 ]"
expect cast_same_bytes_every_run bash -c "'$bin' render '$src/data/cube.dat' --size 20x8 --frames 3 --format asciicast | cmp -s - '$work/rate.cast'"

# Step 2: SVG, rasterised at its own size (8 px wide cells, 16 px tall at aspect 2).
for case in "ramp none" "ascii 256" "blocks truecolor" "quadrants 256" "sextants truecolor" "braille none" "quadrants none" "sextants none"; do
  set -- $case
  name="svg_${1}_$2"
  args=("$duck" --size 50x16 --glyphs "$1" --color "$2" --theta 0.9)
  expect "${name}_renders" "$bin" render "${args[@]}" --format svg -o "$work/$name.svg"
  expect "${name}_rasterises" rsvg-convert "$work/$name.svg" -o "$work/$name.png"
  "$bin" render "${args[@]}" --format ansi >"$work/$name.ans"
  expect "${name}_shows_the_ansi_cells" "${readback[@]}" svg-cells "$work/$name.png" "$work/$name.ans" 8 16
done
expect svg_light_background bash -c "'$bin' render '$src/data/cube.dat' --format svg --background light --size 20x8 | grep -q 'fill=\"#ffffff\"/>'"
expect svg_one_frame_only bash -c "! '$bin' render '$src/data/cube.dat' --frames 2 --format svg >/dev/null 2>'$work/err' && grep -q 'one frame' '$work/err'"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
