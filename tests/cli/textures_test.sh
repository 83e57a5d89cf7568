#!/usr/bin/env bash
# Textures (issue 33, item 2) through the real binary and the import helper:
# an OBJ whose material maps a PNG draws its texels where colours are shown
# (and its face colour with --textures off); hostile textures (dimensions past
# the budget, a truncated file, a path out of the folder) are reported by
# `info` and leave the model drawn without them, exit 0; the duck is yellow.
# Usage: textures_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
source "$src/tests/support/checks.sh"
mkdir -p "$work/sub"
# PNGs written by zlib alone: halves (red left, blue right), one whose header
# claims 4000 x 4000 texels, one cut in half, one outside the model's folder.
python3 - "$work" <<'PY'
import struct, sys, zlib
def png(path, w, h, pixel, truncate=False, claim=None):
    raw = b"".join(b"\0" + b"".join(bytes(pixel(x, y)) for x in range(w)) for y in range(h))
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    cw, ch = claim or (w, h)
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", cw, ch, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
    open(path, "wb").write(data[:len(data) // 2] if truncate else data)
w = sys.argv[1]
png(w + "/sub/halves.png", 8, 8, lambda x, y: (255, 0, 0) if x < 4 else (0, 0, 255))
png(w + "/sub/huge.png", 8, 8, lambda x, y: (0, 255, 0), claim=(4000, 4000))
png(w + "/sub/truncated.png", 64, 64, lambda x, y: (0, 255, 0), truncate=True)
png(w + "/outside.png", 8, 8, lambda x, y: (0, 255, 0))
PY
for name in halves huge truncated outside; do
  texture=$name.png
  [ "$name" = outside ] && texture=../outside.png
  printf 'newmtl m\nKd 1 1 1\nmap_Kd %s\n' "$texture" >"$work/sub/$name.mtl"
  printf 'mtllib %s.mtl\nv 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3 4/4\n' \
    "$name" >"$work/sub/$name.obj"
done

# The colours of an ansi dump's foregrounds: "R G B" lines.
colours() { grep -oE '38;2;[0-9]+;[0-9]+;[0-9]+' | cut -d';' -f3- | tr ';' ' '; }
view=(--theta 0 --phi 1.5708 --size 40x12 --color truecolor --format ansi --no-cull)

check info_drawn 0 "" -- "$bin" info "$work/sub/halves.obj"
expect info_says_drawn grep -q 'halves.png (found; drawn, 8 x 8 texels)' "$work/out"
check render_textured 0 "" -- "$bin" render "$work/sub/halves.obj" "${view[@]}"
colours <"$work/out" >"$work/on.txt"
expect red_cells awk '$1 > 150 && $2 == 0 && $3 == 0 {n++} END {exit !(n >= 2)}' "$work/on.txt"
expect blue_cells awk '$1 == 0 && $2 == 0 && $3 > 150 {n++} END {exit !(n >= 2)}' "$work/on.txt"
check render_untextured 0 "" -- "$bin" render "$work/sub/halves.obj" "${view[@]}" --textures off
colours <"$work/out" >"$work/off.txt"
expect untextured_grey awk '$1 != $2 || $2 != $3 {n++} END {exit !(NR > 0 && n == 0)}' "$work/off.txt"
check textures_bad_value 2 "--textures" -- "$bin" render "$work/sub/halves.obj" --textures maybe

# Hostile textures: reported, the model still drawn (exit 0).
check huge_info 0 "" -- "$bin" info --memory-budget 64M "$work/sub/huge.obj"
expect huge_refused_before_decoding grep -q 'not drawn: 4000x4000 texels need' "$work/out"
check huge_render 0 "" -- "$bin" render --memory-budget 64M "$work/sub/huge.obj" "${view[@]}"
check truncated_info 0 "" -- "$bin" info "$work/sub/truncated.obj"
expect truncated_reported grep -q 'truncated.png (found; not drawn: cannot decode' "$work/out"
check truncated_render 0 "" -- "$bin" render "$work/sub/truncated.obj" "${view[@]}"
check outside_info 0 "" -- "$bin" info "$work/sub/outside.obj"
expect outside_not_read grep -q 'not drawn: a path that leaves the model.s folder' "$work/out"
check outside_render 0 "" -- "$bin" render "$work/sub/outside.obj" "${view[@]}"
expect outside_never_green bash -c "! grep -q '38;2;0;[0-9]*;0m' '$work/out'"

# No colours, no textures: an ansi dump without colour is the same either way.
mono=(--theta 0 --phi 1.5708 --size 40x12 --format ansi --no-cull --glyphs sextants --color none)
check mono_on 0 "" -- "$bin" render "$work/sub/halves.obj" "${mono[@]}"
mv "$work/out" "$work/none-on.txt"
check mono_off 0 "" -- "$bin" render "$work/sub/halves.obj" "${mono[@]}" --textures off
expect mono_drawn grep -q '[^ ]' "$work/none-on.txt"
expect mono_untouched cmp -s "$work/none-on.txt" "$work/out"

# A name that matches a file but for case is read, not when that file is a
# link out of the folder (it is resolved and checked again).
mkdir -p "$work/case"
cp "$work/sub/halves.png" "$work/case/Halves.PNG"
cp "$work/outside.png" "$work/secret.png"
ln -s ../secret.png "$work/case/Secret.png"
for name in halves secret; do
  printf 'newmtl m\nKd 1 1 1\nmap_Kd %s.png\n' "$name" >"$work/case/$name.mtl"
  sed "s/halves.mtl/$name.mtl/" "$work/sub/halves.obj" >"$work/case/$name.obj"
done
check case_info 0 "" -- "$bin" info "$work/case/halves.obj"
expect case_read_as grep -q 'halves.png (found; read as Halves.PNG, drawn, 8 x 8 texels)' "$work/out"
check case_link_info 0 "" -- "$bin" info "$work/case/secret.obj"
expect case_link_refused grep -q 'secret.png (missing; not drawn: a path that leaves the model.s folder)' "$work/out"

# Snapshots compare the texture's colours too: the same texture matches, a
# changed one (its halves swapped) or a missing one fails with the count.
golden="$work/halves.snapshot"
check snapshot_update 0 "wrote" -- "$bin" render "$work/sub/halves.obj" --expect "$golden" --update
expect snapshot_records_textures grep -q '^textures 80x24$' "$golden"
check snapshot_same_texture 0 "" -- "$bin" render "$work/sub/halves.obj" --expect "$golden"
cp "$work/sub/halves.png" "$work/halves.png.saved"
python3 - "$work/sub/halves.png" <<'PY'
import struct, sys, zlib
raw = b"".join(b"\0" + b"".join(bytes((0, 0, 255) if x < 4 else (255, 0, 0)) for x in range(8)) for y in range(8))
def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
open(sys.argv[1], "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 8, 8, 8, 2, 0, 0, 0)) +
                              chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))
PY
check snapshot_changed_texture 1 "texture colours:" -- "$bin" render "$work/sub/halves.obj" --expect "$golden"
expect snapshot_changed_names_count grep -qE 'texture colours: [1-9][0-9]* cells? of [0-9]+ differ' "$work/err"
rm "$work/sub/halves.png"
check snapshot_missing_texture 1 "texture colours:" -- "$bin" render "$work/sub/halves.obj" --expect "$golden"
cp "$work/halves.png.saved" "$work/sub/halves.png"
check snapshot_restored_texture 0 "" -- "$bin" render "$work/sub/halves.obj" --expect "$golden"

# The Collada duck (its texture duckCM.tga): yellow, not grey.
duck=/usr/share/assimp/models/Collada/duck.dae
if [ -f "$duck" ]; then
  check duck_render 0 "" -- "$bin" render "$duck" --fit --size 80x30 --glyphs sextants \
    --color truecolor --format ansi
  colours <"$work/out" >"$work/duck.txt"
  expect duck_yellow awk '{r += $1; g += $2; b += $3} END {exit !(NR > 100 && r / NR > 1.5 * b / NR + 60 && g / NR > 1.3 * b / NR + 40)}' "$work/duck.txt"
fi
finish
