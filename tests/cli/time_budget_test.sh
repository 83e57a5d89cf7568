#!/usr/bin/env bash
# render --budget: a big model under a budget loading alone overruns still
# gives a picture (a clustered copy, said in one note) and exit 0; a
# generous budget, a small model and the wire frame give the exact bytes;
# bad durations are usage errors (exit 2).
# Usage: time_budget_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
source "$src/tests/support/checks.sh"
big="$work/big.ply"
"$bin" generate sphere --triangles 400000 -o "$big"
cells() { tr -d ' \n' <"$1" | wc -c; }  # non-blank cells of a text frame
differ() { ! cmp -s "$1" "$2"; }

"$bin" render "$big" >"$work/exact.txt"
check tight_budget_draws 0 "drew a clustered copy" -- "$bin" render "$big" --budget 1ms
cp "$work/out" "$work/coarse.txt"
expect tight_budget_one_note test "$(wc -l <"$work/err")" -eq 1
expect tight_budget_full_frame test "$(wc -l <"$work/coarse.txt")" -eq 24
# The copy moves vertices by about a sample: nearly the same cells covered.
exact_cells=$(cells "$work/exact.txt") coarse_cells=$(cells "$work/coarse.txt")
expect tight_budget_same_silhouette test $((100 * (exact_cells - coarse_cells) / exact_cells)) -le 3 -a \
  $((100 * (coarse_cells - exact_cells) / exact_cells)) -le 3
expect tight_budget_not_exact differ "$work/exact.txt" "$work/coarse.txt"
check tight_budget_again 0 "drew a clustered copy" -- "$bin" render "$big" --budget 1ms
expect tight_budget_deterministic cmp -s "$work/out" "$work/coarse.txt"
check tight_budget_turntable 0 "exact frames predicted" -- "$bin" render "$big" --budget 1ms --frames 3
expect tight_budget_keeps_every_frame test "$(wc -l <"$work/out")" -eq 72

check generous_budget 0 "" -- "$bin" render "$big" --budget 1000s
expect generous_budget_exact_bytes cmp -s "$work/out" "$work/exact.txt"
expect generous_budget_no_note test ! -s "$work/err"
"$bin" render "$src/data/cube.dat" --size 60x20 >"$work/cube.txt"
check small_model_budget 0 "" -- "$bin" render "$src/data/cube.dat" --size 60x20 --budget 1ms
expect small_model_exact_bytes cmp -s "$work/out" "$work/cube.txt"
"$bin" render "$big" --method wire --size 40x12 >"$work/wire.txt"
check wire_budget 0 "" -- "$bin" render "$big" --method wire --size 40x12 --budget 1ms
expect wire_exact_bytes cmp -s "$work/out" "$work/wire.txt"

for bad in 0 0ms -1s 5 300 1x abc ms s nans infs 100000s 1e400s ''; do
  check "bad_budget_'$bad'" 2 "--budget" -- "$bin" render "$src/data/cube.dat" --budget "$bad"
done
check good_budget_units 0 "" -- "$bin" render "$src/data/cube.dat" --budget 1.5s
check good_budget_ms 0 "" -- "$bin" render "$src/data/cube.dat" --budget 300ms
finish
