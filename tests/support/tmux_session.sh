# Sourced by the tmux scripts (tests/tmux/*_test.sh): a private tmux server
# on socket "$socket" with one session "v", failures counted in $failed,
# the server killed (and "$work", when set, removed) on exit.
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
cleanup() {
  tm kill-server 2>/dev/null
  if [ -n "${work:-}" ]; then sleep 0.2; rm -rf "$work"; fi
}
trap cleanup EXIT
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
wait_for() {  # wait_for REGEX SECONDS: until the pane (wrapped lines joined) matches
  local deadline=$((SECONDS + $2))
  while [ $SECONDS -le "$deadline" ]; do
    if tm capture-pane -t v -p -J | grep -qE -- "$1"; then return 0; fi
    sleep 0.05
  done
  tm capture-pane -t v -p | tail -n 3
  return 1
}
