#!/usr/bin/env bash
# Exit codes and messages of the real binary (SPEC 9): 0 ok, 1 bad input, 2 bad usage.
# Usage: cli_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

check() {  # check NAME EXPECTED_CODE EXPECTED_STDERR_SUBSTRING -- command...
  local name=$1 want=$2 message=$3
  shift 4
  "$@" >"$work/out" 2>"$work/err" </dev/null
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL $name: exit $got, expected $want; stderr: $(head -c 400 "$work/err")"
    failed=$((failed + 1))
  elif [ -n "$message" ] && ! grep -qF -- "$message" "$work/err"; then
    echo "FAIL $name: stderr lacks '$message'; it was: $(head -c 400 "$work/err")"
    failed=$((failed + 1))
  else
    passed=$((passed + 1))
  fi
}

expect() {  # expect NAME CONDITION-COMMAND...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}

# Good runs.
check render_ok 0 "" -- "$bin" render "$src/data/cube.dat"
expect render_is_24_lines_of_80 test "$(awk 'length($0) == 80' "$work/out" | wc -l)" -eq 24
check render_without_term 0 "" -- env -u TERM "$bin" render "$src/data/wedge.dat" --size 40x12
expect render_without_term_size test "$(wc -l <"$work/out")" -eq 12
check help 0 "" -- "$bin" --help
expect help_lists_render grep -q "render" "$work/out"
check version 0 "" -- "$bin" --version
expect version_names_the_program grep -qE '^termshade [0-9]+\.[0-9]+\.[0-9]+$' "$work/out"
check render_help 0 "" -- "$bin" render --help
for option in --size --cell-aspect --theta --phi --rho --method --shade --ramp --glyphs --format --frames --step --output --no-cull --color --mono --up --reader; do
  expect "render_help_documents_$option" grep -q -- "$option" "$work/out"
done
check turntable 0 "" -- "$bin" render "$src/data/cube.dat" --frames 3 --step 0.5 --size 20x10
expect turntable_has_three_frames test "$(wc -l <"$work/out")" -eq 30
# A turntable of 100 frames or more of a scene with 150 triangles a sample
# or more (20k at 8x4) casts rays through its triangle hierarchy: its frames
# are those of a shorter turntable, drawn by clusters.
"$bin" generate sphere --triangles 20000 -o "$work/sphere20k.ply"
check turntable_by_hierarchy 0 "" -- "$bin" render "$work/sphere20k.ply" --size 8x4 --frames 100 --step 0.2
cp "$work/out" "$work/turntable100.txt"
check turntable_by_clusters 0 "" -- "$bin" render "$work/sphere20k.ply" --size 8x4 --frames 99 --step 0.2
expect turntable_frames_same_either_way cmp -s -n "$(wc -c <"$work/out")" "$work/out" "$work/turntable100.txt"
check output_file 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/frame.txt"
expect output_file_written test "$(wc -l <"$work/frame.txt")" -eq 24
check json 0 "" -- "$bin" render "$src/data/beams.dat" --format json --size 30x10
expect json_has_schema grep -q '"format": "termshade-frame/1"' "$work/out"
check ansi 0 "" -- "$bin" render "$src/data/cube.dat" --format ansi --size 30x10
expect ansi_has_sgr grep -q $'\x1b\\[38;5;' "$work/out"
"$bin" render "$src/data/sphere_cone.dat" --size 50x16 --format ansi | sed 's/\x1b\[[0-9;]*m//g' >"$work/stripped"
"$bin" render "$src/data/sphere_cone.dat" --size 50x16 >"$work/plain"
expect ansi_is_text_plus_colour cmp -s "$work/stripped" "$work/plain"
# --color: 24-bit or none for ansi; never a background; auto follows the environment.
check ansi_truecolor 0 "" -- "$bin" render "$src/data/cube.dat" --format ansi --size 30x10 --color truecolor
expect ansi_truecolor_has_24bit grep -q $'\x1b\\[38;2;' "$work/out"
expect ansi_no_background bash -c "! grep -q '48;' '$work/out'"
check ansi_color_none 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --format ansi --size 50x16 --color none
expect ansi_color_none_is_text cmp -s "$work/out" "$work/plain"
# Without colours the block modes' glyphs are the mono ones (shade glyphs,
# dither), not two-colour patterns stripped of their colours: as text.
check text_quadrants 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --size 50x16 --glyphs quadrants
cp "$work/out" "$work/quadrants_text"
check ansi_quadrants_color_none 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --format ansi --size 50x16 --glyphs quadrants --color none
expect ansi_quadrants_color_none_is_text cmp -s "$work/out" "$work/quadrants_text"
# On a light background mono ink is dark: the frame follows darkness (not a negative).
check text_light_background 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --size 50x16 --glyphs quadrants --background light
expect text_light_background_differs bash -c "! cmp -s '$work/out' '$work/quadrants_text'"
expect json_ignores_light_background bash -c "'$bin' render '$src/data/sphere_cone.dat' --size 30x10 --format json --background light | cmp -s - <('$bin' render '$src/data/sphere_cone.dat' --size 30x10 --format json)"
check ansi_mono 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --format ansi --size 50x16 --mono
expect ansi_mono_is_text cmp -s "$work/out" "$work/plain"
check ansi_auto_no_color 0 "" -- env NO_COLOR=1 COLORTERM=truecolor "$bin" render "$src/data/sphere_cone.dat" --format ansi --size 50x16 --color auto
expect ansi_auto_no_color_is_text cmp -s "$work/out" "$work/plain"
check ansi_auto_truecolor 0 "" -- env -u NO_COLOR COLORTERM=truecolor "$bin" render "$src/data/cube.dat" --format ansi --size 30x10 --color auto
expect ansi_auto_truecolor_24bit grep -q $'\x1b\\[38;2;' "$work/out"
check ansi_auto_256 0 "" -- env -u NO_COLOR -u COLORTERM TERM=xterm-256color "$bin" render "$src/data/cube.dat" --format ansi --size 30x10 --color auto
expect ansi_auto_256_indexed grep -q $'\x1b\\[38;5;' "$work/out"
check bad_color 2 "--color" -- "$bin" render "$src/data/cube.dat" --color 8
# --background: shades made for a light terminal differ from the dark default, with the same text.
"$bin" render "$src/data/sphere_cone.dat" --format ansi --color truecolor --size 50x16 >"$work/dark.ans"
check background_light 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --format ansi --color truecolor --size 50x16 --background light
expect background_light_other_colours bash -c "! cmp -s '$work/out' '$work/dark.ans'"
expect background_light_same_text cmp -s <(sed 's/\x1b\[[0-9;]*m//g' "$work/out") "$work/plain"
check background_dark_is_the_default 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --format ansi --color truecolor --size 50x16 --background dark
expect background_dark_is_the_default_same cmp -s "$work/out" "$work/dark.ans"
check bad_background 2 "--background" -- "$bin" render "$src/data/cube.dat" --background grey
# Glyph modes (SPEC 11): each one renders; ramp is render's default; a bad name is usage.
for mode in ascii blocks quadrants sextants braille; do
  check "glyphs_$mode" 0 "" -- "$bin" render "$src/data/cube.dat" --glyphs "$mode" --size 30x10
  expect "glyphs_${mode}_is_10_lines" test "$(wc -l <"$work/out")" -eq 10
done
"$bin" render "$src/data/cube.dat" --glyphs ramp --size 30x10 >"$work/ramp"
"$bin" render "$src/data/cube.dat" --size 30x10 >"$work/plain"
expect glyphs_ramp_is_the_default cmp -s "$work/ramp" "$work/plain"
check glyphs_bad 2 "--glyphs" -- "$bin" render "$src/data/cube.dat" --glyphs sixel
check glyphs_json 0 "" -- "$bin" render "$src/data/cube.dat" --glyphs sextants --format json --size 20x8
expect glyphs_json_has_samples grep -q '"samples": \[2, 3\]' "$work/out"
check glyphs_blocks_ansi 0 "" -- "$bin" render "$src/data/sphere_cone.dat" --glyphs blocks --format ansi --color truecolor --size 50x16
expect glyphs_blocks_ansi_has_background grep -q $'\x1b\\[48;2;' "$work/out"
check auto_method 0 "" -- "$bin" render "$src/data/cube.dat" --method auto --format json --size 20x8
expect auto_reports_itself grep -q '"method": "auto"' "$work/out"
check generate 0 "" -- "$bin" generate wedge
expect generate_matches_data cmp -s "$work/out" "$src/data/wedge.dat"
# Exported formats: a sphere written as .dat and as binary STL (both z-up) draws the same frame.
for format in dat obj stl ply; do
  check "generate_sphere_$format" 0 "" -- "$bin" generate sphere --triangles 2000 -o "$work/sphere.$format"
done
"$bin" render "$work/sphere.dat" --size 40x16 >"$work/sphere-dat.txt"
"$bin" render "$work/sphere.stl" --size 40x16 >"$work/sphere-stl.txt"
expect stl_export_draws_as_dat cmp -s "$work/sphere-dat.txt" "$work/sphere-stl.txt"
check render_obj_export 0 "" -- "$bin" render "$work/sphere.obj" --size 40x16
check render_ply_export 0 "" -- "$bin" render "$work/sphere.ply" --size 40x16
expect sphere_triangle_count test "$(grep -c '^f ' "$work/sphere.obj")" -ge 1900
check generate_unknown_extension 2 "extension" -- "$bin" generate sphere -o "$work/sphere.xyz"
check bench_load 0 "" -- "$bin" bench load --triangles 2000 --formats stl --repeats 1 --dir "$work/bench"
expect bench_load_reports_a_row grep -q '^| 2k triangles, stl | auto |' "$work/out"
expect bench_load_reports_assimp grep -q '^| 2k triangles, stl | assimp |' "$work/out"
check bench_frame 0 "" -- "$bin" bench frame --triangles 2000 --sizes 40x12 --frames 4
expect bench_frame_interleaved_row awk -F'|' '$2 ~ /sphere 2k/ && NF == 17 {found = 1} END {exit !found}' "$work/out"
expect bench_frame_runs_rows test "$(grep -cE '^\| sphere 2k \| 1980 \| 40x12 \| (rays|clusters) \|' "$work/out")" -eq 2
check obj_import 0 "" -- "$bin" render "$src/tests/models/good/quad_and_triangle.obj" --size 20x8

# Several models: each model's frames in turn, one after another.
check two_models 0 "" -- "$bin" render "$src/data/cube.dat" "$src/data/wedge.dat" --size 30x10
"$bin" render "$src/data/cube.dat" --size 30x10 >"$work/cube"
"$bin" render "$src/data/wedge.dat" --size 30x10 >>"$work/cube"
expect two_models_are_each_in_turn cmp -s "$work/out" "$work/cube"
check two_models_turntable 0 "" -- "$bin" render "$src/data/cube.dat" "$src/data/wedge.dat" --size 30x10 --frames 2
expect two_models_two_frames_each test "$(wc -l <"$work/out")" -eq 40
check one_model_bad 1 "nope.dat: cannot open" -- "$bin" render "$work/nope.dat" "$src/data/wedge.dat" --size 30x10
expect the_good_model_is_still_drawn test "$(wc -l <"$work/out")" -eq 10
check bad_model_with_output 1 "nope.dat: cannot open" -- "$bin" render "$work/nope.dat" -o "$work/none.txt"
expect bad_model_leaves_no_output_file test ! -e "$work/none.txt"

# Angles: radians, or degrees with a deg suffix.
"$bin" render "$src/data/steps.dat" --theta 0.5235987755982988 --phi 1.0471975511965976 --size 40x12 >"$work/radians"
check theta_in_degrees 0 "" -- "$bin" render "$src/data/steps.dat" --theta 30deg --phi 60deg --size 40x12
expect degrees_equal_radians cmp -s "$work/out" "$work/radians"
"$bin" render "$src/data/steps.dat" --frames 2 --step 0.5235987755982988 --size 40x12 >"$work/radians"
check step_in_degrees 0 "" -- "$bin" render "$src/data/steps.dat" --frames 2 --step 30deg --size 40x12
expect step_degrees_equal_radians cmp -s "$work/out" "$work/radians"
check bad_angle 2 "--theta" -- "$bin" render "$src/data/cube.dat" --theta 30dg
check bad_angle_phi 2 "--phi" -- "$bin" render "$src/data/cube.dat" --phi deg
check viewer_bad_angle 2 "--theta" -- "$bin" --theta north

# Up axis: --up overrides the file's; a y-up reading of a z-up file differs.
check up_override 0 "" -- "$bin" render "$src/data/steps.dat" --up y --size 40x12
"$bin" render "$src/data/steps.dat" --size 40x12 >"$work/zup"
expect up_override_turns_the_model bash -c "! cmp -s '$work/out' '$work/zup'"
check up_z_is_the_dat_default 0 "" -- "$bin" render "$src/data/steps.dat" --up z --size 40x12
expect up_z_equals_default cmp -s "$work/out" "$work/zup"
check bad_up 2 "--up" -- "$bin" render "$src/data/cube.dat" --up w

# Level of detail: off (render's default) draws exactly what render draws
# without the option; auto draws a big model's level, the frame still whole.
"$bin" generate sphere --triangles 100000 -o "$work/lod_sphere.ply" >/dev/null
for model in "$work/lod_sphere.ply" "$src/data/beams.dat"; do
  name=$(basename "$model" | tr . _)
  "$bin" render "$model" --size 60x20 --format json >"$work/lod_default"
  check "lod_off_$name" 0 "" -- "$bin" render "$model" --size 60x20 --format json --lod off
  expect "lod_off_is_exact_$name" cmp -s "$work/out" "$work/lod_default"
done
check lod_auto 0 "" -- "$bin" render "$work/lod_sphere.ply" --size 60x20 --lod auto --frames 2
expect lod_auto_two_whole_frames test "$(awk 'length($0) == 60' "$work/out" | wc -l)" -eq 40
"$bin" render "$src/data/beams.dat" --size 60x20 >"$work/lod_default"
check lod_auto_small_model 0 "" -- "$bin" render "$src/data/beams.dat" --size 60x20 --lod auto
expect lod_auto_small_model_is_exact cmp -s "$work/out" "$work/lod_default"
check bad_lod 2 "--lod" -- "$bin" render "$src/data/cube.dat" --lod on
check viewer_bad_up 2 "--up" -- "$bin" --up sideways

# Without --size: the terminal's size (one row less) when stdout is a terminal.
check terminal_size 0 "" -- script -qec "stty cols 100 rows 30; '$bin' render '$src/data/cube.dat'" "$work/typescript"
expect terminal_size_is_used test "$(tr -d '\r' <"$work/typescript" | awk 'length($0) == 100' | wc -l)" -eq 29
check terminal_size_not_for_output_file 0 "" -- script -qec "stty cols 100 rows 30; '$bin' render '$src/data/cube.dat' -o '$work/frame100.txt'" "$work/typescript"
expect output_file_is_80x24 test "$(awk 'length($0) == 80' "$work/frame100.txt" | wc -l)" -eq 24

# bench models: one tab-separated row per file, the up axis and outward turn as prepared.
check bench_models 0 "" -- "$bin" bench models "$src/tests/models/real/wuson_inside_out.off" "$src/data/cube.dat" --up z
expect bench_models_rows test "$(wc -l <"$work/out")" -eq 3
expect bench_models_turns_wuson_outward awk -F'\t' '$1 ~ /wuson/ && $2 == "yes" && $6 == "+z" && $7 > 3000 {found = 1} END {exit !found}' "$work/out"
check bench_models_bad_file 1 "" -- "$bin" bench models "$work/nope.dat"
expect bench_models_says_why grep -q "cannot open" "$work/out"

# Bad input: exit 1 with file:line:col.
check missing_file 1 "nope.dat: cannot open: No such file or directory" -- "$bin" render "$work/nope.dat"
check malformed_file 1 "undefined_vertex.dat:14:7: vertex 12 is not defined (highest is 9)" -- \
  "$bin" render "$src/tests/models/bad/undefined_vertex.dat"
check directory_as_model 1 "" -- "$bin" render "$src"
check unwritable_output 1 "cannot write" -- "$bin" render "$src/data/cube.dat" -o /nonexistent/dir/f.txt
printf '1 0 0 0\nFaces:\n' >"$work/$(printf 'evil\033[31mname').dat"
check escape_in_file_name 1 "" -- "$bin" render "$work/$(printf 'evil\033[31mname').dat.missing"
expect escape_never_reaches_stderr bash -c "! grep -q $'\x1b' '$work/err'"
expect escape_shown_escaped grep -qF 'evil\x1B[31mname' "$work/err"

# Hostile input and every source (issues 7 and 8).
check stdin_dat 0 "" -- bash -c "'$bin' render - --size 20x8 <'$src/data/cube.dat'"
check stdin_with_format 0 "" -- bash -c "'$bin' render - --input-format obj --size 20x8 <'$src/tests/models/good/quad_and_triangle.obj'"
check stdin_png 1 "-: not a model file (looks like PNG image)" -- bash -c "'$bin' render - <'$src/tests/models/bad/png_image_without_extension'"
check memory_budget 1 "more than the memory budget of 1.0 KiB" -- "$bin" render "$src/data/cube.dat" --memory-budget 1K
check memory_budget_from_environment 1 "more than the memory budget of 2.0 KiB" -- env TERMSHADE_MEMORY_BUDGET=2K "$bin" render "$src/data/cube.dat"
check bad_memory_budget 2 "--memory-budget" -- "$bin" render "$src/data/cube.dat" --memory-budget lots
# A small file whose mesh is large (one triangle a million times over): within
# the reader's estimate per file byte, refused once its real counts are known.
awk 'BEGIN { print "v 0 0 0\nv 1 0 0\nv 0 1 0"; for (i = 0; i < 1000000; ++i) print "f 1 2 3" }' >"$work/dense.obj"
check dense_obj_over_budget 1 "dense.obj: loading it needs about" -- "$bin" render "$work/dense.obj" --memory-budget 60M
expect dense_obj_over_budget_says_budget grep -q "more than the memory budget of 60.0 MiB" "$work/err"
check dense_obj_within_budget 0 "" -- "$bin" render "$work/dense.obj" --memory-budget 256M --size 20x8
cp "$src/data/cube.dat" "$work/model.dat"
check output_onto_model 2 "is the model itself" -- "$bin" render "$work/model.dat" -o "$work/model.dat"
expect output_onto_model_keeps_model cmp -s "$work/model.dat" "$src/data/cube.dat"
check output_full_disk 1 "No space left on device" -- "$bin" render "$src/data/cube.dat" -o /dev/full
echo previous >"$work/kept.txt"
check failed_render_keeps_output 1 "" -- "$bin" render "$src/tests/models/bad/undefined_vertex.dat" -o "$work/kept.txt"
expect failed_render_keeps_output_content grep -qx previous "$work/kept.txt"
check output_replaced 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/kept.txt" --size 10x4
expect output_replaced_whole test "$(wc -l <"$work/kept.txt")" -eq 4
expect output_leaves_no_temporary_file test "$(ls -A "$work" | grep -c '^\.kept')" -eq 0
check escape_in_option_value 2 "--method" -- "$bin" render "$src/data/cube.dat" --method $'\e]0;x\a'
expect escape_in_option_value_escaped bash -c "! grep -q $'\x1b' '$work/err' && grep -qF '\x1B]0;x\x07' '$work/err'"
check hostile_argv0_help 0 "" -- bash -c "exec -a $'\e]0;x\a' '$bin' --help"
expect hostile_argv0_help_escaped bash -c "! grep -q $'\x1b' '$work/out'"
check bench_terminal_missing_model 1 "cannot open" -- "$bin" bench terminal "$work/NONEXISTENT"
check refused_reference 1 "refused to read '/etc/passwd'" -- "$bin" render "$src/tests/models/bad/obj_mtllib_absolute_path.obj"

# Output through links, devices and standard output (issue 32, items 1, 9, 11).
echo original >"$work/real.txt"
ln -s real.txt "$work/link.txt"
check output_through_symlink 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/link.txt" --size 10x4
expect output_through_symlink_keeps_the_link test -L "$work/link.txt"
expect output_through_symlink_writes_its_target test "$(wc -l <"$work/real.txt")" -eq 4
ln -s link.txt "$work/link2.txt"
check output_through_two_symlinks 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/link2.txt" --size 10x3
expect output_through_two_symlinks_keeps_both bash -c "test -L '$work/link2.txt' && test -L '$work/link.txt' && test \"\$(wc -l <'$work/real.txt')\" -eq 3"
expect output_through_symlink_leaves_no_temporary_file test "$(ls -A "$work" | grep -c '^\.\(real\|link\)')" -eq 0
ln -s new_target.txt "$work/dangling.txt"
check output_through_dangling_symlink 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/dangling.txt" --size 10x4
expect output_through_dangling_symlink_creates_target bash -c "test -L '$work/dangling.txt' && test \"\$(wc -l <'$work/new_target.txt')\" -eq 4"
ln -s /dev/null "$work/null_link"
check output_symlink_to_device 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/null_link"
expect output_symlink_to_device_keeps_link bash -c "test -L '$work/null_link' && test -c /dev/null"
ln -s loop_b "$work/loop_a"
ln -s loop_a "$work/loop_b"
check output_symlink_loop 1 "cannot write" -- "$bin" render "$src/data/cube.dat" -o "$work/loop_a"
expect output_symlink_loop_keeps_links bash -c "test -L '$work/loop_a' && test -L '$work/loop_b'"
# /dev/stdout's own link, made here: a broken build run as root would replace
# the system's /dev/stdout (as the one of issue 32 did).
ln -s /proc/self/fd/1 "$work/stdout_link"
check output_dev_stdout 0 "" -- "$bin" render "$src/data/cube.dat" -o "$work/stdout_link" --size 10x4
expect output_dev_stdout_reaches_stdout test "$(wc -l <"$work/out")" -eq 4
expect output_dev_stdout_still_a_link test -L "$work/stdout_link"
check output_proc_self_fd_1 0 "" -- "$bin" render "$src/data/cube.dat" -o /proc/self/fd/1 --size 10x5
expect output_proc_self_fd_1_reaches_stdout test "$(wc -l <"$work/out")" -eq 5
check output_proc_self_fd_1_pipe 0 "" -- bash -c "'$bin' render '$src/data/cube.dat' -o /proc/self/fd/1 --size 10x6 | wc -l | grep -qx 6"
# stdout onto a file deleted after it was opened: no folder to replace it in, written in place, said why.
check output_proc_self_fd_1_deleted 0 "written in place" -- bash -c "exec 3>'$work/deleted.txt'; rm '$work/deleted.txt'; '$bin' render '$src/data/cube.dat' -o /proc/self/fd/3 --size 10x7; wc -l </proc/self/fd/3 | grep -qx 7"
check output_dash_is_stdout 0 "" -- bash -c "cd '$work' && '$bin' render '$src/data/cube.dat' -o - --size 10x4"
expect output_dash_is_stdout_lines test "$(wc -l <"$work/out")" -eq 4
expect output_dash_writes_no_file test ! -e "$work/-"
check output_empty_name 2 "--output" -- "$bin" render "$src/data/cube.dat" -o ''
check generate_output_empty_name 2 "--output" -- "$bin" generate wedge -o ''
check generate_output_dash 0 "" -- bash -c "cd '$work' && '$bin' generate wedge -o -"
expect generate_output_dash_is_stdout cmp -s "$work/out" "$src/data/wedge.dat"
echo original >"$work/gen_real.dat"
ln -s gen_real.dat "$work/gen_link.dat"
check generate_through_symlink 0 "" -- "$bin" generate wedge -o "$work/gen_link.dat"
expect generate_through_symlink_keeps_link bash -c "test -L '$work/gen_link.dat' && cmp -s '$work/gen_real.dat' '$src/data/wedge.dat'"

# A closed or failing standard output ends the run at the first failed write (item 7).
check closed_stdout 1 "standard output" -- timeout 20 bash -c "exec '$bin' render '$src/data/cube.dat' --size 4096x2048 --frames 100000 >&-"
check broken_pipe_sigpipe_ignored 1 "Broken pipe" -- timeout 20 bash -c "trap '' PIPE; '$bin' render '$src/data/cube.dat' --size 200x100 --frames 100000 | head -c 1 >/dev/null; exit \${PIPESTATUS[0]}"
check closed_stdout_generate 1 "standard output" -- timeout 20 bash -c "exec '$bin' generate wedge >&-"

# Frames are strict JSON whatever the step; steps past 1e6 radians are refused (item 8).
check json_huge_step_refused 2 "--step" -- "$bin" render "$src/data/cube.dat" --step 1e308 --frames 3 --format json --size 10x4
check json_big_step 0 "" -- "$bin" render "$src/data/cube.dat" --step 1e6 --frames 3 --format json --size 10x4
expect json_big_step_is_strict_json python3 -c 'import json, sys
text = open(sys.argv[1]).read()
decoder, at, frames = json.JSONDecoder(), 0, 0
reject = lambda name: (_ for _ in ()).throw(ValueError(name))
while text[at:].strip():
    while text[at].isspace(): at += 1
    frame, at = json.JSONDecoder(parse_constant=reject).raw_decode(text, at)
    frames += 1
sys.exit(frames != 3)' "$work/out"

# Environment values checked as their options are: exit 2, the variable named, escaped (item 10).
for value in 1x -1 99999T 0 $'\e[31m'; do
  check "bad_memory_budget_environment_$(printf %q "$value" | tr -dc 'a-zA-Z0-9-')" 2 "TERMSHADE_MEMORY_BUDGET" -- env TERMSHADE_MEMORY_BUDGET="$value" "$bin" render "$src/data/cube.dat"
done
expect bad_environment_escaped bash -c "! grep -q $'\x1b' '$work/err' && grep -qF '\x1B[31m' '$work/err'"
for value in 0 -5 1.5 86401 x; do
  check "bad_import_seconds_environment_$value" 2 "TERMSHADE_IMPORT_SECONDS" -- env TERMSHADE_IMPORT_SECONDS="$value" "$bin" render "$src/data/cube.dat"
done
check good_import_seconds_environment 0 "" -- env TERMSHADE_IMPORT_SECONDS=5 "$bin" render "$src/data/cube.dat" --size 10x4
check bad_environment_viewer 2 "TERMSHADE_MEMORY_BUDGET" -- env TERMSHADE_MEMORY_BUDGET=lots "$bin" "$src/data/cube.dat"

# Smaller (item 11): --input-format names a known format; generate checks
# its arguments before any work; leading zeros are no reason to refuse a size.
check unknown_input_format 2 "known: " -- "$bin" render - --input-format xyz
expect unknown_input_format_lists_obj grep -q ' obj ' "$work/err"
check unknown_input_format_escaped 2 "--input-format" -- "$bin" render "$src/data/cube.dat" --input-format $'\e[2J'
expect unknown_input_format_escaped_no_escape bash -c "! grep -q $'\x1b' '$work/err'"
check input_format_with_dot 0 "" -- bash -c "'$bin' render - --input-format .OBJ --size 20x8 <'$src/tests/models/good/quad_and_triangle.obj'"
check generate_bad_extension_first 2 "extension" -- timeout 5 "$bin" generate sphere --triangles 50000000 -o /dev/null
check size_leading_zeros 0 "" -- "$bin" render "$src/data/cube.dat" --size 0000000080x0000000024
expect size_leading_zeros_is_80x24 test "$(awk 'length($0) == 80' "$work/out" | wc -l)" -eq 24

# Bad usage: exit 2.
check unknown_method 2 "--method" -- "$bin" render "$src/data/cube.dat" --method foo
check bad_size 2 "--size" -- "$bin" render "$src/data/cube.dat" --size 0x5
check bad_size_text 2 "--size" -- "$bin" render "$src/data/cube.dat" --size big
check bad_aspect 2 "--cell-aspect" -- "$bin" render "$src/data/cube.dat" --cell-aspect 0
check bad_rho 2 "--rho" -- "$bin" render "$src/data/cube.dat" --rho -3
check nan_aspect 2 "--cell-aspect: must be a number from 0.25 to 8" -- "$bin" render "$src/data/cube.dat" --cell-aspect nan
check zero_rho 2 "--rho: must be finite and positive" -- "$bin" render "$src/data/cube.dat" --rho 0
expect zero_rho_message_is_short test "$(wc -c <"$work/err")" -lt 120
check huge_size 2 "COLS must be 1..4096 and ROWS 1..2048" -- "$bin" render "$src/data/cube.dat" --size 100000x100000
check nan_seconds 2 "--seconds: must be a number" -- "$bin" bench methods --seconds nan --csv "$work/nan.csv" --svg "$work/nan.svg"
check blank_ramp 2 "blank" -- "$bin" render "$src/data/cube.dat" --ramp ' .:'
check block_ramp 0 "" -- env LC_ALL=C "$bin" render "$src/data/cube.dat" --size 40x12 --ramp '░▒▓█'
expect block_ramp_rows_are_40_characters test "$(python3 -c 'import sys; print(set(len(l.rstrip("\n")) for l in open(sys.argv[1], encoding="utf-8")))' "$work/out")" = "{40}"
expect block_ramp_uses_blocks grep -q '█' "$work/out"
check wide_ramp 2 "U+6F22 cannot be a ramp character" -- "$bin" render "$src/data/cube.dat" --ramp '漢字'
check escape_in_ramp 2 "U+001B" -- "$bin" render "$src/data/cube.dat" --ramp $'.:\e[7m'
check invalid_utf8_ramp 2 "not valid UTF-8" -- "$bin" render "$src/data/cube.dat" --ramp $'.:\xff'
check unknown_option 2 "" -- "$bin" render "$src/data/cube.dat" --frobnicate
check missing_model 2 "model" -- "$bin" render
check unknown_scene 2 "unknown scene" -- "$bin" generate nothing
check viewer_needs_terminal 2 "termshade render" -- "$bin" "$src/data/cube.dat"
check viewer_dumb_terminal 2 "termshade render" -- env TERM=dumb "$bin"

# Help that teaches: -V, examples in every command's help, the nearest option.
check short_version 0 "" -- "$bin" -V
expect short_version_names_the_program grep -qE '^termshade [0-9]+\.[0-9]+\.[0-9]+$' "$work/out"
"$bin" --generate commands >"$work/commands"
expect every_command_listed grep -qx 'bench methods' "$work/commands"
while IFS= read -r command; do
  # shellcheck disable=SC2086  # the command's words
  check "help_of_${command// /_}" 0 "" -- "$bin" $command --help
  expect "examples_in_help_of_${command// /_}" grep -q '^Examples:' "$work/out"
  expect "examples_run_${command// /_}" grep -q "^  termshade${command:+ $command}" "$work/out"
done <"$work/commands"
check suggests_method 2 "did you mean --method?" -- "$bin" render "$src/data/cube.dat" --meth wire
check suggests_every_extension 2 "did you mean --memory-budget or --method?" -- "$bin" render "$src/data/cube.dat" --me wire
check suggests_mono 2 "did you mean --mono?" -- "$bin" --mnoo
check suggests_seconds 2 "did you mean --seconds?" -- "$bin" bench methods --secs=1
check no_wild_suggestion 2 "" -- "$bin" render "$src/data/cube.dat" --zzzzzzzzzz
expect no_wild_suggestion_said test -z "$(grep "did you mean" "$work/err")"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
