#!/usr/bin/env bash
# Snapshot tests as a user runs them (docs/snapshot-testing.md): render --expect
# GOLDEN, --update, TERMSHADE_UPDATE=1, GOLDEN.new, exit codes 0/1/2.
# Usage: snapshot_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/checks.sh"



# A model a user keeps goldens of, and the same model with one vertex moved.
# cube.dat: vertex 7 is (1 1 1), a corner the default view sees; the
# diagonal is sqrt(3), so 1% of it is 0.0173 and 1e-5 of it 0.0000173.
cp "$src/data/cube.dat" "$work/cube.dat"
moved() {  # moved DZ: the cube with vertex 7's z raised by DZ
  awk -v dz="$1" '$1 == 7 && NF == 4 { printf "7 1 1 %.9f\n", 1 + dz; next } { print }' \
    "$src/data/cube.dat" >"$work/moved.dat"
}
golden=$work/goldens/cube.snap
mkdir -p "$work/goldens"

check missing_golden 1 "no golden yet: run with --update" -- \
  "$bin" render "$work/cube.dat" --expect "$golden"
expect missing_golden_writes_new test -s "$golden.new"
expect missing_golden_writes_no_golden test ! -e "$golden"
check update_writes 0 "wrote" -- "$bin" render "$work/cube.dat" --expect "$golden" --update
expect update_wrote_golden head -1 "$golden" | grep -q '^termshade-snapshot/1$'
expect update_removed_new test ! -e "$golden.new"
expect golden_records_options grep -q '^views default opposite top bottom$' "$golden"
expect golden_has_frames test "$(grep -c '^|' "$golden")" -eq 96
check match 0 "" -- "$bin" render "$work/cube.dat" --expect "$golden"
expect match_is_silent test ! -s "$work/err"
expect match_writes_no_new test ! -e "$golden.new"
check same_options_given 0 "" -- "$bin" render "$work/cube.dat" --expect "$golden" --size 80x24 --theta 0.3 --method zbuffer --threads 1

moved 0.0173
cp "$golden" "$work/before.snap"
check one_percent_caught 1 "views differ" -- "$bin" render "$work/moved.dat" --expect "$golden"
expect one_percent_names_view grep -q '^view default: [0-9]* samples\? of [0-9]* differ' "$work/err"
expect one_percent_marks_cells grep -q '\^' "$work/err"
expect one_percent_no_escape_bytes sh -c "! grep -q \$'\\x1b' '$work/err'"
expect one_percent_writes_new head -1 "$golden.new" | grep -q '^termshade-snapshot/1$'
expect one_percent_keeps_golden cmp -s "$golden" "$work/before.snap"
check one_percent_tolerated 0 "" -- "$bin" render "$work/moved.dat" --expect "$golden" --tolerance 100%
moved 0.0000173
check one_in_100000_not_caught 0 "" -- "$bin" render "$work/moved.dat" --expect "$golden"
expect match_removes_stale_new test ! -e "$golden.new"

moved 0.0173
check env_update 0 "wrote" -- env TERMSHADE_UPDATE=1 "$bin" render "$work/moved.dat" --expect "$golden"
expect env_update_rewrote sh -c "! cmp -s '$golden' '$work/before.snap'"
check after_env_update_matches 0 "" -- "$bin" render "$work/moved.dat" --expect "$golden"
check env_update_zero_compares 1 "views differ" -- env TERMSHADE_UPDATE=0 "$bin" render "$work/cube.dat" --expect "$golden"

# Options: contradicting the golden is bad usage unless --update.
check contradicting_size 2 "--size contradicts the golden's size 80x24" -- \
  "$bin" render "$work/cube.dat" --expect "$golden" --size 100x30
check contradicting_glyphs 2 "--glyphs contradicts the golden's glyphs ramp" -- \
  "$bin" render "$work/cube.dat" --expect "$golden" --glyphs braille
check contradicting_views 2 "--views" -- "$bin" render "$work/cube.dat" --expect "$golden" --views top
check contradicting_with_update 0 "" -- \
  "$bin" render "$work/cube.dat" --expect "$golden" --update --size 60x20 --glyphs sextants --views default,top
expect update_records_new_options grep -q '^size 60x20$' "$golden"
expect update_records_glyphs grep -q '^glyphs sextants$' "$golden"
check rerender_with_golden_options 0 "" -- "$bin" render "$work/cube.dat" --expect "$golden"
check update_keeps_golden_options 0 "wrote" -- env TERMSHADE_UPDATE=1 "$bin" render "$work/cube.dat" --expect "$golden" --theta 0.5
expect update_kept_size grep -q '^size 60x20$' "$golden"
expect update_kept_views grep -q '^views default top$' "$golden"
expect update_took_theta grep -q '^theta 0.5$' "$golden"
printf 'not a golden\n' >"$work/broken.snap"
check update_replaces_unreadable_golden 0 "wrote" -- "$bin" render "$work/cube.dat" --expect "$work/broken.snap" --update
check update_without_expect 2 "--update needs --expect" -- "$bin" render "$work/cube.dat" --update
check expect_with_output 2 "--output cannot be used with --expect" -- \
  "$bin" render "$work/cube.dat" --expect "$golden" -o "$work/x.txt"
check expect_with_format 2 "--format cannot be used" -- \
  "$bin" render "$work/cube.dat" --expect "$golden" --format json
check bad_tolerance 2 "--tolerance must be" -- "$bin" render "$work/cube.dat" --expect "$golden" --tolerance lots
check bad_views 2 "--views must be" -- "$bin" render "$work/cube.dat" --expect "$golden" --update --views side
check two_models 2 "one model" -- "$bin" render "$work/cube.dat" "$work/cube.dat" --expect "$golden"

# Bad input: a bad model and a bad golden are exit 1 with their own messages.
printf '1 0 0 0\nFaces:\n1 2 3.\n' >"$work/bad.dat"
check bad_model 1 "bad.dat:3" -- "$bin" render "$work/bad.dat" --expect "$golden"
printf 'termshade-snapshot/1\nsize 80x24\nbo\033[2Jgus 1\n' >"$work/bad.snap"
check bad_golden 1 "bad.snap:3: unknown header line" -- "$bin" render "$work/cube.dat" --expect "$work/bad.snap"
expect bad_golden_escaped sh -c "! grep -q \$'\\x1b' '$work/err'"
check golden_is_folder 1 "" -- "$bin" render "$work/cube.dat" --expect "$work/goldens"
finish
