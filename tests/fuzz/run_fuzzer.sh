#!/usr/bin/env bash
# Builds the .dat fuzzer (clang, ASan, UBSan) and runs it for SECONDS (default 60)
# from a seed corpus of the shipped scenes and test models.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz
corpus=$(mktemp -d)
trap 'rm -rf "$corpus"' EXIT
cp data/*.dat tests/models/good/*.dat tests/models/bad/*.dat "$corpus"/
./build-fuzz/dat_fuzzer -artifact_prefix="${ARTIFACTS:-$corpus/}" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "$corpus"
