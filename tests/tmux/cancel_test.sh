#!/usr/bin/env bash
# Cancelling a big load in the viewer (issue 32, item 3): `o` on a big model,
# Esc during its load or preparation, four times over. Each time the worker
# must end (the viewer's thread count back where it was), its memory go back
# (resident within 200 MB of the start) and the viewer keep answering; then
# the model loads whole and `q` quits.
# Usage: cancel_test.sh path/to/termshade [TRIANGLES | MODEL]
# (MODEL: a file to open instead of the generated sphere, for measurements.)
set -u
bin=$(realpath "$1")
triangles=${2:-3000000}
socket="termshade-cancel-$$"
work=$(mktemp -d)
failed=0
loadedEarly=""

source "$(dirname "$(realpath "$0")")/../support/tmux_session.sh"
status_field() { awk -v f="$2:" '$1 == f { print $2 }' "/proc/$1/status"; }
now_ms() { date +%s%3N; }

name=big.ply
if [ -f "$triangles" ]; then
  name=big.${triangles##*.}
  ln -s "$(realpath "$triangles")" "$work/$name"
else
  "$bin" generate sphere --triangles "$triangles" -o "$work/$name" >/dev/null || { echo "FAIL generate"; exit 1; }
fi
re_name=${name//./\\.}
"$bin" generate sphere --triangles 2000 -o "$work/small.ply" >/dev/null || exit 1

tm new-session -d -s v -x 100 -y 30 "cd $work && TERM=tmux-256color $bin --lod off small.ply; sleep 30"
tm set-option -t v status off >/dev/null
wait_for 'small\.ply' 10 || { echo "FAIL the viewer did not start"; exit 1; }
pid=$(tm display-message -p -t v '#{pane_pid}')
for child in $(pgrep -P "$pid"); do
  [ "$(readlink /proc/"$child"/exe)" = "$bin" ] && pid=$child
done
[ "$(readlink /proc/"$pid"/exe)" = "$bin" ] || { echo "FAIL no viewer process ($pid)"; exit 1; }
sleep 0.5
threads0=$(status_field "$pid" Threads)
rss0=$(status_field "$pid" VmRSS)
echo "start: $threads0 threads, resident $((rss0 / 1024)) MiB"

for round in 1 2 3 4; do
  tm send-keys -t v o
  wait_for 'open:|Open|path' 5 >/dev/null || true
  tm send-keys -t v -l "$name"
  tm send-keys -t v Enter
  wait_for "(loading|preparing) $re_name" 5 >/dev/null || fail "round $round: no 'loading big.ply'"
  # Odd rounds: Esc while the file is read; even rounds: while it is prepared.
  if [ $((round % 2)) -eq 0 ]; then
    # At once: a 3M-triangle sphere is prepared in a few tenths of a second.
    wait_for "preparing $re_name" 60 >/dev/null || fail "round $round: no 'preparing big.ply'"
  else
    sleep 0.3
  fi
  peak=$(status_field "$pid" VmRSS)
  peakThreads=$(status_field "$pid" Threads)
  tm send-keys -t v Escape
  pressed=$(now_ms)
  stopped=""
  while [ $(($(now_ms) - pressed)) -lt 5000 ]; do
    if [ "$(status_field "$pid" Threads)" -le "$threads0" ]; then stopped=$(($(now_ms) - pressed)); break; fi
    sleep 0.01
  done
  if tm capture-pane -t v -p -J | tail -n 1 | grep -q "opened $re_name"; then
    echo "round $round: the preparation ended before Esc reached the viewer; rounds end here"
    loadedEarly=1
    break
  fi
  wait_for "cancelled loading $re_name" 5 >/dev/null || fail "round $round: no 'cancelled loading'"
  sleep 0.3
  rss=$(status_field "$pid" VmRSS)
  echo "round $round: $peakThreads threads and $((peak / 1024)) MiB at Esc; worker ended ${stopped:-never} ms after it; resident then $((rss / 1024)) MiB"
  [ -n "$stopped" ] || fail "round $round: threads still $(status_field "$pid" Threads) (started with $threads0)"
  if [ -z "${TERMSHADE_SANITIZED:-}" ] && [ "$rss" -gt $((rss0 + 200 * 1024)) ]; then
    fail "round $round: resident $((rss / 1024)) MiB, started at $((rss0 / 1024)) MiB"
  fi
done

# Still answering: the model loads whole, then q quits.
[ -n "$loadedEarly" ] || {
tm send-keys -t v o
wait_for 'open:|Open|path' 5 >/dev/null || true
tm send-keys -t v -l "$name"
tm send-keys -t v Enter
wait_for "(loading|preparing) $re_name" 5 >/dev/null || fail "no 'loading big.ply' the fifth time"
loaded=""
for _ in $(seq 1 1200); do
  shown=$(tm capture-pane -t v -p -J | tail -n 1)
  if echo "$shown" | grep -q "$re_name" && ! echo "$shown" | grep -qE '(loading|preparing|cancelled)'; then
    loaded=1
    break
  fi
  sleep 0.1
done
[ -n "$loaded" ] || { tm capture-pane -t v -p | tail -n 2; fail "big.ply did not load after the cancels"; }
}
tm send-keys -t v q
for _ in $(seq 1 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && fail "q did not end the viewer"

if [ "$failed" -gt 0 ]; then echo "$failed failed"; exit 1; fi
echo "all passed"
