#!/usr/bin/env bash
# The viewer's build needs no test or benchmark package: configures the
# release preset (and with --build, builds it) in a mount namespace where an
# empty folder hides the CMake packages of GoogleTest, Google Benchmark and
# nlohmann-json, then checks the test preset refuses to configure there.
# Usage: without_test_packages.sh SOURCE_DIR [--build]
# Exit 77 (skipped) where no mount namespace can be made.
set -u
src=$(cd "$1" && pwd)
build_too=${2:-}

if [ -z "${TERMSHADE_IN_NAMESPACE:-}" ]; then
  as=(-m)
  [ "$(id -u)" -eq 0 ] || as=(-r -m)
  if ! unshare "${as[@]}" true 2>/dev/null; then
    echo "SKIP: unshare ${as[*]} is not allowed here (no mount namespace)"
    exit 77
  fi
  TERMSHADE_IN_NAMESPACE=1 exec unshare "${as[@]}" bash "$0" "$@"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/empty"
hidden=0
for dir in /usr/lib/cmake /usr/lib/*/cmake /usr/share/cmake /usr/local/lib/cmake /usr/local/lib/*/cmake \
           /usr/local/share/cmake; do
  for name in GTest gtest benchmark nlohmann_json; do
    if [ -d "$dir/$name" ]; then
      mount --bind "$work/empty" "$dir/$name" ||
        { echo "SKIP: cannot bind-mount over $dir/$name here"; exit 77; }
      hidden=$((hidden + 1))
    fi
  done
done
echo "hid $hidden package folders"

failed=0
if ! cmake --preset release -S "$src" -B "$work/release" >"$work/release.log" 2>&1; then
  echo "FAIL: the release preset does not configure without the test packages:"
  tail -20 "$work/release.log"
  exit 1
fi
grep -q 'GoogleTest or nlohmann-json not found' "$work/release.log" ||
  { echo "FAIL: GoogleTest was still found (not hidden?)"; failed=1; }
grep -q 'Google Benchmark not found' "$work/release.log" ||
  { echo "FAIL: Google Benchmark was still found (not hidden?)"; failed=1; }
grep -q '^build termshade:' "$work/release/build.ninja" ||
  { echo "FAIL: no termshade target"; failed=1; }
if grep -qE '^build (termshade_tests|termshade_microbench):' "$work/release/build.ninja"; then
  echo "FAIL: test or benchmark targets without their packages"
  failed=1
fi
if [ "$build_too" = --build ]; then
  if cmake --build "$work/release" -j 2 >"$work/build.log" 2>&1; then
    "$work/release/termshade" --version || failed=1
    "$work/release/termshade" bench methods --help >/dev/null || failed=1
  else
    echo "FAIL: the release build without the test packages:"
    tail -30 "$work/build.log"
    failed=1
  fi
fi
# The test preset requires them: it must stop, naming the missing package.
if cmake --preset test -S "$src" -B "$work/test" >"$work/test.log" 2>&1; then
  echo "FAIL: the test preset configured without GoogleTest"
  failed=1
elif ! grep -qE 'GTest|benchmark|nlohmann_json' "$work/test.log"; then
  echo "FAIL: the test preset failed for another reason:"
  tail -20 "$work/test.log"
  failed=1
fi
[ "$failed" -eq 0 ] && echo "PASS: release preset configures${build_too:+ and builds} without the test packages"
exit "$failed"
