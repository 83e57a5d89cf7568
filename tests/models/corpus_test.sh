#!/usr/bin/env bash
# Renders every file of the hostile-input corpus (tests/models/bad) and, when
# installed, of the Assimp test models (/usr/share/assimp/models), two at a
# time, each under a time and memory cap, and fails on any crash, hang, stray
# control byte, unnamed error or read outside a model's folder.
# Usage: corpus_test.sh TERMSHADE [--markdown] [--no-memory-cap] DIR...
#   --markdown: print the outcome table for the README instead of failing.
set -u
bin=$1
shift
markdown=0
memoryKib=$((3 * 1024 * 1024))  # 3 GiB of address space, above the 2 GiB budget
while [ "${1:-}" != "" ] && [ "${1#--}" != "$1" ]; do
  case $1 in
    --markdown) markdown=1 ;;
    --no-memory-cap) memoryKib=0 ;;  # sanitizer builds reserve terabytes of address space
  esac
  shift
done
seconds=${CORPUS_SECONDS:-10}
here=$(cd "$(dirname "$0")" && pwd)
results=$(mktemp)
trap 'rm -f "$results"' EXIT

# FIFOs, links and a folder as models: made here, listed by name (find -type f skips them).
special=$(mktemp -d)
trap 'rm -f "$results"; rm -rf "$special"' EXIT
bash "$here/bad/make_special_files.sh" "$special/special"
{
  for dir in "$@"; do
    [ -d "$dir" ] || continue
    find "$dir" -type f -print0
  done
  find "$special/special" -mindepth 1 -maxdepth 1 ! -name 'fifo.*' ! -name 'symlink_*' -print0
  printf '%s\0' /dev/zero
} | sort -z | xargs -0 -P 2 -n 1 bash "$here/corpus_check.sh" "$bin" "$seconds" "$memoryKib" >"$results"

files=$(wc -l <"$results")
rendered=$(grep -c '^rendered' "$results")
errors=$(grep -c '^error' "$results")
failures=$(grep -c '^FAIL' "$results")
hangs=$(grep -c '^FAIL.*no result within' "$results")
if [ "$markdown" -eq 1 ]; then
  echo "| corpus | files | rendered | clean errors | crashes | hangs | other failures |"
  echo "|---|---|---|---|---|---|---|"
  for dir in "$@"; do
    [ -d "$dir" ] || continue
    n=$(grep -cF -- "	$dir/" "$results")
    r=$(grep -F -- "	$dir/" "$results" | grep -c '^rendered')
    e=$(grep -F -- "	$dir/" "$results" | grep -c '^error')
    c=$(grep -F -- "	$dir/" "$results" | grep '^FAIL' | grep -c 'exit 1[2-9][0-9]')
    h=$(grep -F -- "	$dir/" "$results" | grep -c '^FAIL.*no result within')
    o=$(($(grep -F -- "	$dir/" "$results" | grep -c '^FAIL') - c - h))
    echo "| \`$dir\` | $n | $r | $e | $c | $h | $o |"
  done
  exit 0
fi
grep '^FAIL' "$results"
echo "$files files: $rendered rendered, $errors clean errors, $failures failures ($hangs hangs)"
[ "$failures" -eq 0 ] && [ "$files" -gt 0 ]
