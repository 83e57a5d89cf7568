#!/usr/bin/env bash
# The file-manager previewer recipes of tools/previewers, run as lf, ranger,
# yazi and fzf run them: the same arguments, variables and quoting. Each
# gives a picture of exactly the pane's size, for hostile names too, and a
# broken model gives its escaped message instead of a picture.
# Usage: previewers_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
source "$src/tests/support/checks.sh"
mkdir "$work/bin"
ln -s "$(realpath "$bin")" "$work/bin/termshade"
export PATH="$work/bin:$PATH" LANG=C.UTF-8 TERM=xterm-256color
recipes=$src/tools/previewers
# A picture of COLS x ROWS cells in colour, with no byte a terminal would act on beyond SGR.
is_picture() {  # is_picture FILE COLS ROWS
  python3 - "$@" <<'PY'
import re, sys
path, cols, rows = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
text = open(path, encoding="utf-8").read()
lines = re.sub(r"\x1b\[[0-9;]*m", "", text).split("\n")
ok = (text.endswith("\n") and len(lines) == rows + 1 and all(len(l) == cols for l in lines[:-1])
      and "\x1b[38;5;" in text and any(c != " " for l in lines for c in l) and not re.search(r"[\x00-\x09\x0b-\x1f\x7f]", "".join(lines)))
sys.exit(0 if ok else 1)
PY
}
model="$work/-a model with spaces.obj"
"$bin" generate sphere --triangles 2000 -o "$model"
bad="$work/broken \$(touch pwned).stl"
printf 'solid x\nfacet normal 0 0 1\n\x1b]0;owned\x07\n' >"$bad"
printf 'not a model\n' >"$work/notes.txt"

# lf: SCRIPT FILE WIDTH HEIGHT X Y; exit 1 = "do not cache".
sh "$recipes/lf-preview.sh" "$model" 60 20 0 0 >"$work/lf.out"
expect lf_exit_1_no_cache test $? -eq 1
expect lf_picture_fits_the_pane is_picture "$work/lf.out" 60 20
sh "$recipes/lf-preview.sh" "$work/notes.txt" 60 20 0 0 >"$work/lf-text.out"
expect lf_other_files_no_preview test ! -s "$work/lf-text.out"

# ranger: scope.sh's variables; exit 7 = show the output as it is.
FILE_PATH=$model PV_WIDTH=45 PV_HEIGHT=14 sh "$recipes/ranger-scope.sh" >"$work/ranger.out"
expect ranger_exit_7 test $? -eq 7
expect ranger_picture_fits_the_pane is_picture "$work/ranger.out" 45 14
FILE_PATH=$bad PV_WIDTH=45 PV_HEIGHT=14 sh "$recipes/ranger-scope.sh" >"$work/ranger-bad.out"
expect ranger_broken_model_exit_1 test $? -eq 1
expect ranger_broken_model_named grep -q "broken" "$work/ranger-bad.out"
expect ranger_broken_model_escaped bash -c "! grep -q $'\\x1b' '$work/ranger-bad.out'"
expect ranger_name_never_run test ! -e pwned

# yazi: piper runs the command after "piper --" in sh with $1, $w and $h.
run=$(python3 -c 'import sys, tomllib; print(tomllib.load(open(sys.argv[1], "rb"))["plugin"]["prepend_previewers"][0]["run"])' "$recipes/yazi.toml")
expect yazi_run_is_piper test "${run#piper -- }" != "$run"
w=72 h=18 sh -c "export w h; ${run#piper -- }" sh "$model" >"$work/yazi.out" 2>&1
expect yazi_picture_fits_the_pane is_picture "$work/yazi.out" 72 18

# fzf: the --preview command, {} replaced by the line single-quoted (as fzf does).
preview=$(sed -n "s/^exec fzf --ansi --preview '\\(.*\\)' \"\\\$@\"$/\\1/p" "$recipes/fzf-preview.sh")
expect fzf_preview_found test -n "$preview"
quoted="'$(printf '%s' "$model" | sed "s/'/'\\\\''/g")'"
FZF_PREVIEW_COLUMNS=50 FZF_PREVIEW_LINES=16 sh -c "${preview//\{\}/$quoted}" >"$work/fzf.out"
expect fzf_picture_fits_the_pane is_picture "$work/fzf.out" 50 16

# --glyphs auto: what the viewer would pick, given the terminal and whether the frame has colour.
cube=$src/data/cube.dat
for case in "xterm-kitty C.UTF-8 ansi sextants" "xterm-256color C.UTF-8 ansi quadrants" \
            "xterm-256color C.UTF-8 text ascii" "xterm-kitty C ansi ascii"; do
  set -- $case
  TERM=$1 LANG=$2 LC_ALL= termshade render --size 30x10 --format "$3" --glyphs auto -- "$cube" >"$work/auto.out"
  TERM=$1 LANG=$2 LC_ALL= termshade render --size 30x10 --format "$3" --glyphs "$4" -- "$cube" >"$work/asked.out"
  expect "glyphs_auto_${1}_${2}_$3_is_$4" cmp -s "$work/auto.out" "$work/asked.out"
done
finish
