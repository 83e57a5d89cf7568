#!/usr/bin/env bash
# Installs the Debian packages a termshade build needs; nothing else is
# downloaded, at any time. Checks each package first (dpkg-query), refreshes the
# package lists and calls apt-get only when something is missing, and uses
# sudo only when not root.
#
# Usage: scripts/install-deps.sh [GROUP...]      (default: runtime)
#   runtime  build and run the viewer: compiler, CMake, Ninja, CLI11, Assimp, meshoptimizer, ncurses, stb_image
#   test     runtime + what `cmake --workflow --preset test` needs
#   ci       test + the sanitizer and fuzzer builds' extras (what .ci/run runs)
#   --list   print the packages of the groups instead of installing them
set -euo pipefail

runtime=(cmake ninja-build g++ libncurses-dev libcli11-dev libassimp-dev libmeshoptimizer-dev
         libstb-dev)
# GoogleTest, Google Benchmark, JSON for the dump tests; tmux and strace drive
# the viewer; Assimp's own model corpus; man-db renders the installed man page;
# zsh and fish check their completion scripts; rsvg-convert and Pillow read
# the SVG export back; the SSH test starts its own sshd.
test=(libgtest-dev libbenchmark-dev nlohmann-json3-dev tmux strace python3 assimp-testmodels
      man-db zsh fish librsvg2-bin python3-pil openssh-server openssh-client)
ci=(clang libclang-rt-14-dev)

list=false
groups=()
for arg in "$@"; do
  case "$arg" in
    runtime | test | ci) groups+=("$arg") ;;
    --list) list=true ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-deps.sh: unknown group '$arg' (runtime, test or ci)" >&2; exit 2 ;;
  esac
done
[ "${#groups[@]}" -gt 0 ] || groups=(runtime)

packages=()
for group in "${groups[@]}"; do
  case "$group" in
    runtime) packages+=("${runtime[@]}") ;;
    test) packages+=("${runtime[@]}" "${test[@]}") ;;
    ci) packages+=("${runtime[@]}" "${test[@]}" "${ci[@]}") ;;
  esac
done
mapfile -t packages < <(printf '%s\n' "${packages[@]}" | awk '!seen[$0]++')

if $list; then
  printf '%s\n' "${packages[@]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$' || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps.sh: all ${#packages[@]} packages (${groups[*]}) are installed"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps.sh: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "install-deps.sh: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
