#!/usr/bin/env bash
# termshade info: a model's report in text and json, each bad model named with
# exit 1 while the others are still reported, bad usage exit 2.
# Usage: info_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/checks.sh"
field() {  # field JSON-LINE-FILE LINE KEY: the value, as Python prints it
  python3 -c 'import json, sys; print(json.loads(open(sys.argv[1]).read().splitlines()[int(sys.argv[2])])[sys.argv[3]])' "$@"
}

"$bin" info "$src/data/cube.dat" >"$work/cube.txt"
expect text_exit_0 test $? -eq 0
expect text_names_the_file grep -q "data/cube.dat" "$work/cube.txt"
expect text_reader grep -qE '^  reader +termshade \.dat reader$' "$work/cube.txt"
expect text_counts grep -qE '^  faces +6 \(12 triangles once prepared\)$' "$work/cube.txt"
expect text_closed grep -qE '^  edges +0 open \(closed\)' "$work/cube.txt"

"$bin" generate sphere --triangles 2000 -o "$work/sphere.stl"
"$bin" info --format json "$src/data/cube.dat" "$work/sphere.stl" "$src/tests/models/good/quad_and_triangle.obj" >"$work/all.json"
expect json_exit_0 test $? -eq 0
expect json_one_line_each test "$(wc -l <"$work/all.json")" -eq 3
expect json_schema test "$(field "$work/all.json" 0 format)" = termshade-info/1
expect json_cube_vertices test "$(field "$work/all.json" 0 vertices)" = 8
expect json_cube_one_part test "$(field "$work/all.json" 0 parts)" = 1
expect json_stl_reader test "$(field "$work/all.json" 1 reader)" = "termshade STL reader"
expect json_stl_welded_closed test "$(field "$work/all.json" 1 openEdges)" = 0
expect json_stl_z_up test "$(field "$work/all.json" 1 upAxisFile)" = +z
expect json_obj_open test "$(field "$work/all.json" 2 openEdges)" -gt 0
if [ -f /usr/share/assimp/models/Collada/duck.dae ]; then
  "$bin" info --format json /usr/share/assimp/models/Collada/duck.dae >"$work/duck.json"
  expect json_duck_by_assimp grep -q '"reader": "Assimp (import helper), as dae"' "$work/duck.json"
  expect json_duck_y_up test "$(field "$work/duck.json" 0 upAxisFile)" = +y
  expect json_duck_helper_memory python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1]))["importHelperPeakMiB"] <= 0)' "$work/duck.json"
fi
# Textures the materials name, and where each is: an OBJ's map_Kd beside it,
# one its MTL names outside the folder (not looked at), a missing one.
mkdir -p "$work/tex/sub"
printf 'mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl wood\nf 1 3 2\nf 1 2 4\nusemtl stone\nf 1 4 3\nusemtl gone\nf 2 3 4\n' >"$work/tex/sub/box.obj"
printf 'newmtl wood\nKd 1 1 1\nmap_Kd wood.png\nnewmtl stone\nKd 1 1 1\nmap_Kd ../../outside.png\nnewmtl gone\nKd 1 1 1\nmap_Kd gone.png\n' >"$work/tex/sub/box.mtl"
printf 'PNG' >"$work/tex/sub/wood.png"
printf 'PNG' >"$work/outside.png"
"$bin" info "$work/tex/sub/box.obj" >"$work/tex.txt" 2>&1
expect textures_exit_0 test $? -eq 0
expect textures_found grep -qE '^  textures +3: .*wood\.png \(found; ' "$work/tex.txt"
expect textures_outside grep -q 'outside.png (outside the model.s folder (not looked at); ' "$work/tex.txt"
expect textures_missing grep -q 'gone.png (missing; ' "$work/tex.txt"
"$bin" info --format json "$work/tex/sub/box.obj" >"$work/tex.json"
expect textures_json python3 -c 'import json,sys; t=json.load(open(sys.argv[1]))["textures"]; sys.exit(sorted(x["where"] for x in t) != ["found", "missing", "outside the model'"'"'s folder (not looked at)"])' "$work/tex.json"
"$bin" info "$src/data/cube.dat" | grep -qE '^  textures +none named$'
expect textures_none test $? -eq 0

"$bin" info --up x --format json "$src/data/cube.dat" >"$work/up.json"
expect up_option_drawn test "$(field "$work/up.json" 0 upAxisDrawn)" = +x

# A bad model among good ones: named on stderr, exit 1, the good ones reported.
printf 'solid x\n\033]0;owned\007\n' >"$work/bad.stl"
"$bin" info "$src/data/cube.dat" "$work/bad.stl" "$src/data/wedge.dat" >"$work/mixed.txt" 2>"$work/mixed.err"
expect bad_model_exit_1 test $? -eq 1
expect bad_model_named grep -q "bad.stl" "$work/mixed.err"
expect bad_model_escaped bash -c "! grep -q $'\\x1b' '$work/mixed.err'"
expect others_reported test "$(grep -c '^  reader' "$work/mixed.txt")" -eq 2
"$bin" info --format xml "$src/data/cube.dat" >/dev/null 2>&1
expect bad_format_exit_2 test $? -eq 2
"$bin" info >/dev/null 2>&1
expect no_model_exit_2 test $? -eq 2
finish
