#!/usr/bin/env bash
# The Assimp import module (termshade-assimp.so) as the program reaches it:
# not opened for .dat, OBJ, STL or PLY, opened for formats only Assimp reads
# (and --reader assimp) with the same frame; without it, or with a broken
# one, a clean error naming it (exit 1), while other formats still render;
# the same for the import helper that runs it (termshade-import).
# Usage: assimp_module_test.sh path/to/termshade source-dir
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
expect() {  # expect NAME COMMAND...
  local name=$1
  shift
  if "$@"; then pass; else fail "$name"; fi
}

# A cube as OBJ and as OFF (which only Assimp reads).
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n' >"$work/cube.obj"
printf 'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' >>"$work/cube.obj"
{
  printf 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n'
  printf '4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n'
} >"$work/cube.off"

# What the dynamic loader opens (LD_DEBUG=files), per model, in the program
# and in the import helper it starts (a log file a process).
opened() {  # opened FRAME MODEL [OPTIONS...]: the loader's log of the files it opened
  local frame=$1
  shift
  rm -f "$work"/ld.*
  LD_DEBUG=files LD_DEBUG_OUTPUT="$work/ld" "$bin" render "$@" --size 40x12 -o "$work/$frame" \
    >/dev/null 2>&1
  cat "$work"/ld.* 2>/dev/null | grep -E 'file=.*\[0\];  (needed|dynamically loaded)'
}
for model in "$work/cube.obj" "$src/data/cube.dat"; do
  log=$(opened "$(basename "$model").txt" "$model")
  expect "$(basename "$model"): the program runs" test -n "$log"
  expect "$(basename "$model"): no Assimp module or library opened: $(grep -i assimp <<<"$log")" \
    bash -c '! grep -qi assimp <<<"$1"' _ "$log"
done
log=$(opened off.txt "$work/cube.off")
expect "cube.off: the module is loaded" grep -q 'termshade-assimp.so.*dynamically loaded' <<<"$log"
expect "cube.off: the import helper runs" grep -q 'needed by .*/termshade-import ' <<<"$log"
expect "cube.off: same frame as cube.obj" cmp -s "$work/off.txt" "$work/cube.obj.txt"
log=$(opened assimp.txt "$work/cube.obj" --reader assimp)
expect "--reader assimp: the module is loaded" grep -q 'termshade-assimp.so' <<<"$log"
expect "--reader assimp: the import helper runs" grep -q 'needed by .*/termshade-import ' <<<"$log"
expect "--reader assimp: same frame" cmp -s "$work/assimp.txt" "$work/cube.obj.txt"

# The program and its import helper alone in a folder: no module next to
# them (nor in ../lib*/termshade).
mkdir -p "$work/alone/bin"
cp "$bin" "$work/alone/bin/termshade"
cp "$(dirname "$bin")/termshade-import" "$work/alone/bin/termshade-import"
run_alone() {  # run_alone MODEL: exit code, stderr in $work/err
  "$work/alone/bin/termshade" render "$1" --size 40x12 >"$work/out" 2>"$work/err" </dev/null
}
clean_error() {  # clean_error NAME WANT_TEXT: exit 1, the file and WANT_TEXT named, no control byte
  local name=$1 want=$2 code=$3
  expect "$name: exit 1 (got $code): $(head -c 300 "$work/err")" test "$code" -eq 1
  expect "$name: names cube.off" grep -qF "cube.off" "$work/err"
  expect "$name: says '$want'" grep -qF -- "$want" "$work/err"
  expect "$name: no control byte" bash -c '! LC_ALL=C grep -q "[[:cntrl:]]" <(tr -d "\n" <"$1")' _ "$work/err"
}
run_alone "$work/cube.obj"
expect "without the module: OBJ renders (exit $?)" test -s "$work/out"
run_alone "$work/cube.off"
clean_error "without the module" "the Assimp import module termshade-assimp.so is missing" $?
expect "without the module: says where it looked" grep -qF "$work/alone/bin/termshade-assimp.so" "$work/err"

# The man page and completions list Assimp's formats: without the module, a clean error.
for what in man bash; do
  "$work/alone/bin/termshade" --generate "$what" >"$work/out" 2>"$work/err" </dev/null
  code=$?
  expect "--generate $what without the module: exit 1 (got $code)" test "$code" -eq 1
  expect "--generate $what without the module: names it" grep -qF "termshade-assimp.so" "$work/err"
  expect "--generate $what without the module: no output" test ! -s "$work/out"
done

# Not a shared object; a shared object that is not ours.
printf 'not an ELF file\n' >"$work/alone/bin/termshade-assimp.so"
run_alone "$work/cube.off"
clean_error "a broken module" "cannot load the Assimp import module" $?
libz=$(ldconfig -p | awk '/libz\.so\.1 .*x86-64/ { print $NF; exit }')
if [ -n "$libz" ]; then
  cp "$libz" "$work/alone/bin/termshade-assimp.so"
  run_alone "$work/cube.off"
  clean_error "another library as the module" "is not a termshade module" $?
fi
# The module beside it but not the import helper that runs it; then another
# program in the helper's place.
cp "$(dirname "$bin")/termshade-assimp.so" "$work/alone/bin/termshade-assimp.so"
rm -f "$work/alone/bin/termshade-import"
run_alone "$work/cube.off"
clean_error "without the import helper" "the import helper termshade-import is missing" $?
expect "without the import helper: says where it looked" grep -qF "$work/alone/bin/termshade-import" "$work/err"
cp "$(type -P true)" "$work/alone/bin/termshade-import"
run_alone "$work/cube.off"
clean_error "another program as the import helper" "the import helper ended without a result" $?
# A helper gone hostile (what a compromised importer could do): one that
# crashes, one that sends bytes that are no answer, one that promises an
# array of 2^60 vertices. Each is a clean error; nothing is allocated for the
# promise. (Sanitizer builds abort on a crashed helper, so tests see reports.)
hostile_helper() {  # hostile_helper SCRIPT: the helper replaced by a shell script
  printf '#!/bin/sh\n%s\n' "$1" >"$work/alone/bin/termshade-import"
  chmod +x "$work/alone/bin/termshade-import"
}
if [ -z "${TERMSHADE_SANITIZED:-}" ]; then
  hostile_helper 'kill -SEGV $$'
  run_alone "$work/cube.off"
  clean_error "a helper that crashes" "the importer (Assimp) crashed on the file (signal 11, SIGSEGV)" $?
  # Started with SIGCHLD ignored (inherited through exec, which would let the
  # kernel reap the helper unseen): termshade takes it back and still says why.
  python3 -c 'import os, signal, sys; signal.signal(signal.SIGCHLD, signal.SIG_IGN); os.execv(sys.argv[1], sys.argv[1:])' \
    "$work/alone/bin/termshade" render "$work/cube.off" --size 40x12 >"$work/out" 2>"$work/err" </dev/null
  clean_error "a helper that crashes, SIGCHLD ignored" "the importer (Assimp) crashed on the file (signal 11, SIGSEGV)" $?
fi
hostile_helper "printf 'garbage' >&3"
run_alone "$work/cube.off"
clean_error "a helper that sends garbage" "the import helper sent a broken result" $?
# R, status 0, empty text, a mesh: empty name, up axis 0, then 2^60 vertices.
hostile_helper "printf 'R\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\001\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\000\\020' >&3"
run_alone "$work/cube.off"
clean_error "a helper that promises 2^60 vertices" "an array longer than allowed" $?
# The processor limit the helper is given (its third argument):
# --import-seconds, else TERMSHADE_IMPORT_SECONDS, else 30 s and 1 s a MiB.
hostile_helper "echo \"\$3\" >'$work/cpu-seconds'"
limit_given() {  # limit_given [ENV=VALUE] [OPTION...]: the limit the helper saw
  rm -f "$work/cpu-seconds"
  env "$@" >/dev/null 2>&1 </dev/null
  cat "$work/cpu-seconds" 2>/dev/null
}
expect "--import-seconds 7 reaches the helper" test "$(limit_given TERMSHADE_IMPORT_SECONDS=9 "$work/alone/bin/termshade" render "$work/cube.off" --import-seconds 7)" = 7
expect "TERMSHADE_IMPORT_SECONDS=9 reaches the helper" test "$(limit_given TERMSHADE_IMPORT_SECONDS=9 "$work/alone/bin/termshade" render "$work/cube.off")" = 9
expect "the default limit: 30 s for a small file" test "$(limit_given -u TERMSHADE_IMPORT_SECONDS "$work/alone/bin/termshade" render "$work/cube.off")" = 30
"$work/alone/bin/termshade" render "$work/cube.off" --import-seconds 0 >/dev/null 2>"$work/err" </dev/null
code=$?
expect "--import-seconds 0: a usage error (exit $code)" test "$code" -eq 2
expect "--import-seconds 0: names the option" grep -qF -- "--import-seconds" "$work/err"
cp "$(dirname "$bin")/termshade-import" "$work/alone/bin/termshade-import"
run_alone "$work/cube.off"
expect "with the module and the helper: OFF renders (exit $?)" cmp -s "$work/out" "$work/cube.obj.txt"
# Never from the working directory.
rm -f "$work/alone/bin/termshade-assimp.so"
cp "$(dirname "$bin")/termshade-assimp.so" "$work/termshade-assimp.so"
(cd "$work" && "$work/alone/bin/termshade" render cube.off --size 40x12 >"$work/out" 2>"$work/err" </dev/null)
clean_error "a module in the working directory" "is missing" $?

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
