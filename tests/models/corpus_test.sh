#!/usr/bin/env bash
# Renders every file of the hostile-input corpus (tests/models/bad) and, when
# installed, of the Assimp test models (/usr/share/assimp/models), two at a
# time, each under a time and memory cap, and fails on any crash, hang, stray
# control byte, unnamed error or read outside a model's folder.
# Usage: corpus_test.sh TERMSHADE [--markdown] [--no-memory-cap] DIR...
#   --markdown: print the outcome table for docs/real-models.md instead of failing.
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

# The program's own files it may open after a model (its Assimp module and
# the libraries the loader maps for it), listed once for every check.
own=$(mktemp)
bash "$here/own_files.sh" "$bin" >"$own"
export CORPUS_OWN_FILES=$own
trap 'rm -f "$results" "$own"' EXIT

# FIFOs, links and a folder as models: made here, listed by name (find -type f skips them).
special=$(mktemp -d)
trap 'rm -f "$results" "$own"; rm -rf "$special"' EXIT
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
row() {  # row LABEL PATTERN: one table row for the result lines whose file matches PATTERN
  local lines n r e c h o
  lines=$(grep -E -- "	($2)" "$results")
  n=$(grep -c . <<<"$lines")
  r=$(grep -c '^rendered' <<<"$lines")
  e=$(grep -c '^error' <<<"$lines")
  c=$(grep '^FAIL' <<<"$lines" | grep -c 'exit 1[2-9][0-9]')
  h=$(grep -c '^FAIL.*no result within' <<<"$lines")
  o=$(($(grep -c '^FAIL' <<<"$lines") - c - h))
  echo "| $1 | $n | $r | $e | $c | $h | $o |"
}
if [ "$markdown" -eq 1 ]; then
  echo "| corpus | files | rendered | clean errors | crashes | hangs | other failures |"
  echo "|---|---|---|---|---|---|---|"
  for dir in "$@"; do
    [ -d "$dir" ] && row "\`${dir#"$PWD/"}\`" "$dir/"
  done
  row "FIFOs, links, a folder, /dev/zero, 10 MB .dat (made at run time)" "$special/special/|/dev/zero"
  row "all" ""
  exit 0
fi
grep '^FAIL' "$results"
echo "$files files: $rendered rendered, $errors clean errors, $failures failures ($hangs hangs)"
[ "$failures" -eq 0 ] && [ "$files" -gt 0 ]
