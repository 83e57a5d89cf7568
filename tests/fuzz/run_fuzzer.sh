#!/usr/bin/env bash
# Builds the fuzzers (clang, ASan, UBSan) and runs them for SECONDS in total
# (default 60), split between them: the .dat reader and pipeline (dat_fuzzer),
# the Assimp path of the model loader (model_fuzzer: OBJ, PLY, STL, OFF,
# glTF, GLB, COLLADA, unnamed content) and our readers against their plain
# forms (reader_fuzzer), and the import helper's answer as termshade reads it
# (wire_fuzzer), the viewer's input decoder on keys, mouse reports and the
# terminal's answers (input_fuzzer), and option values, the environment and
# configuration files (option_fuzzer), each from a seed corpus of our files.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
datSeconds=$((seconds / 4))
readerSeconds=$((seconds / 4))
wireSeconds=$((seconds / 4))
inputSeconds=$((seconds / 10 > 0 ? seconds / 10 : 1))
optionSeconds=$((seconds / 20 > 0 ? seconds / 20 : 1))  # 0 would mean no limit
modelSeconds=$((seconds - datSeconds - readerSeconds - wireSeconds - inputSeconds - optionSeconds))
fuzzers=(dat_fuzzer model_fuzzer reader_fuzzer wire_fuzzer input_fuzzer option_fuzzer)
cmake --preset fuzz >/dev/null
# Build exactly the fuzzers run below (a fuzzer missing from the preset's
# target list once failed CI only at its run).
cmake --build --preset fuzz --target "${fuzzers[@]}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/dat" "$work/model" "$work/reader" "$work/wire" "$work/input" "$work/option"
cp data/*.dat tests/models/good/*.dat tests/models/bad/*.dat "$work/dat"/
# Model seeds: the first byte picks the format (index into model_fuzzer's kNames).
seed() {  # seed INDEX FILE
  { printf "\\x$(printf %02x "$1")"; head -c 4000 "$2"; } >"$work/model/$(basename "$2").$1"
}
for f in tests/models/good/*.obj tests/models/bad/*.obj; do seed 0 "$f"; done
cp "$work/model"/* "$work/reader"/  # reader_fuzzer: OBJ text after a chunk-count byte
for f in tests/models/bad/*.ply; do seed 1 "$f"; done
for f in tests/models/bad/*.off; do seed 3 "$f"; done
for f in tests/models/bad/*.gltf; do seed 4 "$f"; done
for f in tests/models/bad/*.glb; do seed 5 "$f"; done
for f in tests/models/bad/opengex_* tests/models/bad/q3d_*; do seed 7 "$f"; done
printf '\x02solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' >"$work/model/ascii.stl"
printf '\x03OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$work/model/triangle.off"
# Wire seeds: a progress frame, then a result frame with a tetrahedron (four
# triangles, one hidden edge, face colours, one line), and one with an error.
python3 - "$work/wire" <<'PY'
import struct, sys
def text(s): return struct.pack("<Q", len(s)) + s
def array(fmt, items):
    return struct.pack("<Q", len(items)) + b"".join(struct.pack(fmt, *i) for i in items)
vertices = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
corners = [(c,) for f in faces for c in f]
mesh = (text(b"seed.off") + b"\x04" + array("<3d", vertices) + array("<I", corners) +
        array("<I", [(3 * i,) for i in range(5)]) +
        array("<B", [(1 if i == 1 else 0,) for i in range(12)]) + array("<2I", [(0, 3)]) +
        array("<3f", [(0.5, 0.25, 1.0)] * 4) + struct.pack("<Q", 1) + text(b"tex.png") +
        struct.pack("<Q", 1) + struct.pack("<II", 1, 1) + array("<3B", [(255, 200, 0)]) + text(b"") +
        array("<I", [(0,), (0,), (0,), (0,)]) + array("<2f", [(0.5, 0.5)] * 12))
progress = b"P" + struct.pack("<d", 0.5)
result = b"R" + struct.pack("<i", 0) + text(b"") + b"\x01" + mesh
error = b"R" + struct.pack("<i", 0) + text(b"") + b"\x00" + text(b"seed.off") + struct.pack("<ii", 3, 7) + text(b"a message")
open(sys.argv[1] + "/mesh", "wb").write(progress + result)
open(sys.argv[1] + "/error", "wb").write(error)
PY
# Input seeds: a burst of SGR reports, X10 reports, a report split by a gap
# (0xFE), arrow keys as key codes (0xFD, 259 - 256) around reports.
printf '\x1b[<0;41;13M\x1b[<32;46;13M\x1b[<0;51;15m' >"$work/input/sgr"
printf '\x1b[M !!\x1b[M#AB' >"$work/input/x10"
printf '\x1b[<0;4\xfe1;13Mq' >"$work/input/split"
printf 'a\xfd\x03\x1b[<64;3;4M\xfd\x02' >"$work/input/keys"
printf '\x1b]11;rgb:ffff/ffff/ffff\x1b\\\x1bP1+r524742\x1b\\\x1bP0+r5463\x1b\\\x1b[6;17;8t\x1b[?62;22c' >"$work/input/answers"
printf '\x1b\xfe[?6\xfe\x032;\xfe22c\x1b]11;rgb:0/0/0\x07' >"$work/input/answers_split"
# Option seeds: the first byte picks the parser (option_fuzzer.cpp).
printf '\x004G' >"$work/option/bytes"
printf '\x011.5GiB' >"$work/option/bytes-suffix"
printf '\x0186400' >"$work/option/seconds"
printf '\x02512M' >"$work/option/environment"
printf '\x03sextants' >"$work/option/mode"
printf '\x04-1e308' >"$work/option/number"
printf '\x05glyphs = "braille"\ncolor = "256"\nrho = 4.5\n[render]\nglyphs = "ascii"\n' >"$work/option/config"
for f in tools/previewers/*.toml; do [ -f "$f" ] && { printf '\x05'; cat "$f"; } >"$work/option/$(basename "$f")"; done
run() {  # run FUZZER SECONDS CORPUS
  "./build-fuzz/$1" -artifact_prefix="${ARTIFACTS:-$work/}" -max_total_time="$2" -max_len=4096 \
    -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "$3"
}
run dat_fuzzer "$datSeconds" "$work/dat"
run model_fuzzer "$modelSeconds" "$work/model"
run reader_fuzzer "$readerSeconds" "$work/reader"
run wire_fuzzer "$wireSeconds" "$work/wire"
run input_fuzzer "$inputSeconds" "$work/input"
run option_fuzzer "$optionSeconds" "$work/option"
