#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, then: the installed program runs,
# its man page renders without warnings, the completion scripts parse and
# complete, the README and licence are in share/doc/termshade.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
src=$2
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
passed=0
failed=0
skipped=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
skip() { echo "SKIP $1"; skipped=$((skipped + 1)); }
expect() {  # expect NAME COMMAND...
  local name=$1
  shift
  if "$@"; then pass; else fail "$name"; fi
}

if ! cmake --install "$build" --prefix "$prefix" >"$prefix.log" 2>&1; then
  echo "FAIL cmake --install:"
  cat "$prefix.log"
  rm -f "$prefix.log"
  exit 1
fi
rm -f "$prefix.log"

bin=$prefix/bin/termshade
man_page=$prefix/share/man/man1/termshade.1
bash_completion=$prefix/share/bash-completion/completions/termshade
zsh_completion=$prefix/share/zsh/vendor-completions/_termshade
fish_completion=$prefix/share/fish/vendor_completions.d/termshade.fish
for file in "$bin" "$man_page" "$bash_completion" "$zsh_completion" "$fish_completion" \
            "$prefix/share/doc/termshade/README.md" "$prefix/share/doc/termshade/LICENSE"; do
  expect "installed: ${file#"$prefix"/}" test -s "$file"
done

# The program runs from the prefix, away from the source tree.
expect "version" bash -c '"$1" -V | grep -qxE "termshade [0-9]+\.[0-9]+\.[0-9]+"' _ "$bin"
expect "renders the demo scene" bash -c \
  'cd / && "$1" render "$2/data/sphere_cone.dat" --size 40x12 | grep -q "[@#%]"' _ "$bin" "$src"
# The Assimp module, installed where the installed program looks for it.
expect "installed: the Assimp module" bash -c 'ls "$1"/lib*/termshade/termshade-assimp.so "$1"/lib/*/termshade/termshade-assimp.so 2>/dev/null | grep -q .' _ "$prefix"
expect "installed: the import helper beside it" bash -c 'ls "$1"/lib*/termshade/termshade-import "$1"/lib/*/termshade/termshade-import 2>/dev/null | grep -q .' _ "$prefix"
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' \
  >"$prefix/tetrahedron.off"
expect "renders an OFF file through the installed module" bash -c \
  'cd / && "$1" render "$2" --size 40x12 | grep -q "[^ ]"' _ "$bin" "$prefix/tetrahedron.off"

# The man page: every section the issue asks for, no warnings from man or groff.
for section in NAME SYNOPSIS DESCRIPTION OPTIONS COMMANDS KEYS FILES ENVIRONMENT "EXIT STATUS" EXAMPLES; do
  expect "man section $section" grep -q "^\.SH \"\{0,1\}$section" "$man_page"
done
for variable in NO_COLOR COLORTERM TERM LANG; do
  expect "man documents $variable" grep -q "$variable" "$man_page"
done
if command -v man >/dev/null; then
  warnings=$(MANWIDTH=80 LC_ALL=C.UTF-8 man --warnings -l "$man_page" 2>&1 >/dev/null)
  expect "man -l without warnings${warnings:+: $warnings}" test -z "$warnings"
  expect "man -l renders the keys" bash -c \
    'MANWIDTH=80 man -l "$1" 2>/dev/null | grep -q "refit the model to the window"' _ "$man_page"
else
  skip "man -l: man-db is not installed (scripts/install-deps.sh test)"
fi
if command -v groff >/dev/null; then
  warnings=$(groff -man -ww -z -Tutf8 "$man_page" 2>&1)
  expect "groff -ww without warnings${warnings:+: $warnings}" test -z "$warnings"
fi

# bash: parses, and completes as a person would see it.
expect "bash -n" bash -n "$bash_completion"
complete_bash() {  # complete_bash DIR WORD... (the last word is being completed)
  local dir=$1
  shift
  (cd "$dir" && bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _termshade
                         printf "%s\n" "${COMPREPLY[@]}"' _ "$bash_completion" "$@")
}
expect "bash: render --me offers --method" \
  grep -qx -- "--method" <<<"$(complete_bash / termshade render --me)"
expect "bash: render --meth offers --method alone" \
  test "$(complete_bash / termshade render --meth)" = "--method"
expect "bash: --method offers its values" \
  test "$(complete_bash / termshade render m.obj --method "" | tr '\n' ' ')" = "zbuffer painter cull wire auto "
expect "bash: --method=w" test "$(complete_bash / termshade --method = w)" = "wire"
expect "bash: the subcommands of bench" test "$(complete_bash / termshade bench "" | sort)" = \
  "$("$bin" --generate commands | sed -n 's/^bench //p' | sort)"
expect "bash: model files by extension" \
  test "$(complete_bash "$src/data" termshade render sphere | tr '\n' ' ')" = "sphere_cone.dat "
expect "bash: no README offered as a model" test -z "$(complete_bash "$src/data" termshade READ)"
expect "bash: directories offered for models" \
  test "$(complete_bash "$src" termshade dat)" = "data"

# zsh and fish: parse; fish also completes.
if command -v zsh >/dev/null; then
  expect "zsh -n" zsh -n "$zsh_completion"
else
  skip "zsh -n: zsh is not installed (scripts/install-deps.sh test)"
fi
if command -v fish >/dev/null; then
  expect "fish -n" fish -n "$fish_completion"
  complete_fish() {
    (cd "$1" && fish -c 'source $argv[1]; complete -C $argv[2]' "$fish_completion" "$2" | cut -f1)
  }
  expect "fish: render --me offers --method" \
    grep -qx -- "--method" <<<"$(complete_fish / 'termshade render --me')"
  expect "fish: render --meth offers --method alone" \
    test "$(complete_fish / 'termshade render --meth')" = "--method"
  expect "fish: model files by extension" \
    test "$(complete_fish "$src/data" 'termshade render sphere')" = "sphere_cone.dat"
else
  skip "fish: fish is not installed (scripts/install-deps.sh test)"
fi

echo "install: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
