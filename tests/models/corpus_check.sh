#!/usr/bin/env bash
# Renders one model file under hostile-input rules and prints one line:
#   OUTCOME<TAB>FILE[<TAB>why]
# OUTCOME: rendered (exit 0), error (exit 1 with a clean message), or FAIL.
# A clean run: exit 0 or 1 (never a signal, 2 or 3), within the time cap,
# no control byte on stderr, a message naming the file on exit 1, and no file
# opened outside the model's folder once the model itself was opened.
# Usage: corpus_check.sh TERMSHADE SECONDS MEMORY_KIB FILE  (MEMORY_KIB 0: no cap)
set -u
bin=$1 seconds=$2 memoryKib=$3 file=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cap=()
[ "$memoryKib" -gt 0 ] && cap=(prlimit --as=$((memoryKib * 1024)) --)
# timeout runs under strace, so killing it never leaves a detached tracee behind.
"${cap[@]}" strace --seccomp-bpf -f -qq -e trace=open,openat -o "$work/trace" \
  timeout -s KILL "$seconds" "$bin" render "$file" --size 40x12 >/dev/null 2>"$work/err" </dev/null
code=$?

fail() {
  printf 'FAIL\t%s\t%s\n' "$file" "$1"
  exit 0
}
case $code in
  0 | 1) ;;
  137) fail "no result within ${seconds} s (hang or runaway)" ;;
  *) fail "exit $code: $(head -c 300 "$work/err" | tr -d '\000-\037')" ;;
esac
if LC_ALL=C grep -q $'[\x01-\x09\x0b-\x1f\x7f]' "$work/err" || tr -d '\n' <"$work/err" | grep -qaP '\x00'; then
  fail "control byte on stderr"
fi
if [ "$code" -eq 1 ]; then
  base=$(basename -- "$file")
  if ! LC_ALL=C grep -qF -- "$base" "$work/err"; then
    if [[ "$base" =~ ^[[:print:]]+$ ]] || [ ! -s "$work/err" ]; then
      fail "the message does not name the file: $(head -c 200 "$work/err")"
    fi
  fi
fi
# Files opened after the model itself: only inside its folder, besides the
# program's own Assimp module and import helper (opened once a file needs
# them), the libraries the dynamic loader opens for them, and what the
# sanitizer runtime reads of its own process (/proc/self/cmdline, environ,
# maps) as a sanitized helper starts.
folder=$(cd "$(dirname -- "$file")" && pwd -P)
if [ -n "${CORPUS_OWN_FILES:-}" ]; then
  cp "$CORPUS_OWN_FILES" "$work/own"
else
  bash "$(dirname "$0")/own_files.sh" "$bin" >"$work/own"
fi
outside=$(grep -oP 'open(at)?\((AT_FDCWD, )?"\K([^"\\]|\\.)*' "$work/trace" |
  awk -v model="$file" 'started { print } $0 == model { started = 1 }' |
  { mapfile -t opened; [ "${#opened[@]}" -gt 0 ] && realpath -m -- "${opened[@]}"; } |
  grep -vxFf "$work/own" |
  grep -vxE '/proc/[0-9]+/(cmdline|environ|maps)' |
  awk -v folder="$folder" '$0 != folder && index($0, folder "/") != 1 { print; exit }')
[ -n "$outside" ] && fail "opened a file outside the model's folder: $outside"
if [ "$code" -eq 0 ]; then
  printf 'rendered\t%s\n' "$file"
else
  printf 'error\t%s\t%s\n' "$file" "$(head -n 1 "$work/err")"
fi
