#!/usr/bin/env bash
# The viewer over a real SSH connection and a slow link: a private sshd on
# loopback (its own port, host key, authorized key and config in a temporary
# folder), `ssh -tt` from a tmux pane through throttle_relay.py (256 kbit/s,
# 50 ms each way), sextants in truecolor on duck.dae at 160x48 (the colour
# glyph modes are the ones whose frames outrun such a link). Asserts what a
# user would: no key lost and the final screen equal to `termshade render` of
# the same view, cell for cell with its colours (frames drawn while the view
# moves are cheaper on such a link; the full one must follow), the picture settling and stopping soon after the keys, q
# giving the prompt back soon, nothing of the viewer's left on the shell's
# line. Caps are generous (times are the bench's: `termshade bench terminal
# --link`); before flow control (issue 31) the picture kept turning for
# about 30 s after space here.
# Usage: ssh_test.sh path/to/termshade source-dir     (exit 77: no sshd)
set -u
bin=$(realpath "$1")
src=$(realpath "$2")
model=/usr/share/assimp/models/Collada/duck.dae
[ -f "$model" ] || model="$src/data/sphere_cone.dat"
sshd=$(command -v sshd || echo /usr/sbin/sshd)
if [ ! -x "$sshd" ] || ! command -v ssh >/dev/null || ! command -v ssh-keygen >/dev/null; then
  echo "SKIP openssh-server/openssh-client not installed (scripts/install-deps.sh test)"
  exit 77
fi
work=$(mktemp -d)
socket="termshade-ssh-$$"
sshd_pid=""
tm() { tmux -u -L "$socket" -f /dev/null "$@"; }
cleanup() {
  tm kill-server 2>/dev/null
  [ -n "$sshd_pid" ] && kill "$sshd_pid" 2>/dev/null && wait "$sshd_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
passed=0
failed=0
pass() { passed=$((passed + 1)); }
fail() { echo "FAIL $1"; failed=$((failed + 1)); }
scale=1
[ -n "${TERMSHADE_SANITIZED:-}" ] && scale=4

# Step 1: sshd on a free loopback port, its keys and config here.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
ssh-keygen -q -t ed25519 -N '' -f "$work/host_key" || exit 77
ssh-keygen -q -t ed25519 -N '' -f "$work/client_key" || exit 77
cp "$work/client_key.pub" "$work/authorized_keys"
cat >"$work/sshd_config" <<EOF
ListenAddress 127.0.0.1
Port $port
HostKey $work/host_key
AuthorizedKeysFile $work/authorized_keys
PidFile $work/sshd.pid
UsePAM no
StrictModes no
PermitRootLogin yes
PubkeyAuthentication yes
PasswordAuthentication no
KbdInteractiveAuthentication no
PrintMotd no
PrintLastLog no
EOF
# As root, sshd wants its privilege separation folder (the package's service makes it).
[ "$(id -u)" -eq 0 ] && mkdir -p /run/sshd
"$sshd" -D -e -f "$work/sshd_config" 2>"$work/sshd.log" &
sshd_pid=$!
for _ in $(seq 1 50); do
  python3 -c "import socket; socket.create_connection(('127.0.0.1', $port)).close()" 2>/dev/null && break
  sleep 0.1
done
if ! kill -0 "$sshd_pid" 2>/dev/null; then
  echo "SKIP sshd did not start:"
  cat "$work/sshd.log"
  exit 77
fi
ssh_options="-F /dev/null -i $work/client_key -o IdentitiesOnly=yes -o StrictHostKeyChecking=no -o UserKnownHostsFile=/dev/null -o LogLevel=ERROR -o BatchMode=yes"
relay="python3 $src/tests/ssh/throttle_relay.py 256000 50 127.0.0.1 %p"
# shellcheck disable=SC2086
if ! ssh $ssh_options -p "$port" "$(id -un)@127.0.0.1" true </dev/null; then
  echo "SKIP cannot log in to the test sshd:"
  cat "$work/sshd.log"
  exit 77
fi

# Step 2: a shell in a 160x48 pane; ssh -tt through the slow link runs the viewer.
tm new-session -d -s v -x 160 -y 48 "env -i PATH=$PATH HOME=$work TERM=tmux-256color PS1='$ ' bash --norc --noprofile"
tm set-option -t v status off >/dev/null
screen() { tm capture-pane -t v -p; }
joined_screen() { tm capture-pane -t v -p -J; }  # trailing blanks kept (the prompt's)
wait_for() {  # wait_for REGEX SECONDS
  local deadline=$((SECONDS + $2 * scale))
  while [ $SECONDS -le "$deadline" ]; do
    joined_screen | grep -qE -- "$1" && return 0
    sleep 0.1
  done
  return 1
}
# Seconds until the screen has not changed for 0.5 s (at most LIMIT); prints it.
settle_seconds() {  # settle_seconds LIMIT
  local start previous="" current stable_since
  start=$(date +%s.%N)
  stable_since=$start
  while :; do
    current=$(screen)
    now=$(date +%s.%N)
    if [ "$current" != "$previous" ]; then stable_since=$now; previous=$current; fi
    if awk -v n="$now" -v s="$stable_since" 'BEGIN { exit !(n - s >= 0.5) }'; then break; fi
    if awk -v n="$now" -v s="$start" -v l="$1" 'BEGIN { exit !(n - s >= l) }'; then break; fi
    sleep 0.05
  done
  awk -v a="$stable_since" -v b="$start" 'BEGIN { printf "%.2f", a - b }'
}
wait_for '\$ ' 5 || { fail "no shell prompt"; exit 1; }
tm send-keys -t v "ssh -tt $ssh_options -o ProxyCommand='$relay' -p $port $(id -un)@127.0.0.1 \"LANG=C.UTF-8 $bin $model --glyphs sextants --color truecolor\"" Enter
# The status line names the view once the model is up.
if wait_for 'theta 0.30 ' 60; then pass; else
  fail "the viewer did not start over ssh"
  screen | tail -5
  exit 1
fi
settle_seconds 10 >/dev/null

# Step 3: 20 quick presses: none lost, the picture settles soon, equal to the render.
for _ in $(seq 1 20); do
  tm send-keys -t v Right
  sleep 0.045
done
settle=$(settle_seconds 20)
echo "settle after 20 presses: ${settle} s (cap $((5 * scale)))"
if awk -v x="$settle" -v c="$((5 * scale))" 'BEGIN { exit !(x < c) }'; then pass; else fail "settle ${settle} s"; fi
if screen | tail -n 1 | grep -q 'theta 2.30 '; then pass; else
  fail "a key was lost: $(screen | tail -n 1)"
fi
screen | head -n 47 | sed 's/[[:space:]]*$//' >"$work/screen.txt"
"$bin" render "$model" --fit --size 160x47 --theta 2.3 --glyphs sextants --color truecolor --format ansi |
  sed 's/\x1b\[[0-9;]*m//g; s/[[:space:]]*$//' >"$work/render.txt"
if cmp -s "$work/screen.txt" "$work/render.txt"; then pass; else
  fail "the screen over ssh differs from termshade render"
  diff "$work/screen.txt" "$work/render.txt" | head -10
fi
# Colours too: frames drawn while the view moved use fewer colours on this
# link (MotionFrames); the full frame must have followed once it rested.
tm capture-pane -t v -p -e >"$work/screen.ans"
"$bin" render "$model" --fit --size 160x47 --theta 2.3 --glyphs sextants --color truecolor --format ansi >"$work/render.ans"
if python3 "$src/tests/tmux/ansi_cells.py" "$work/screen.ans" "$work/render.ans" 47 >/dev/null; then pass; else
  fail "the screen's colours over ssh differ from termshade render's"
fi

# Step 4: the turntable for 8 s, then space: the picture stops soon.
tm send-keys -t v Space
sleep 8
tm send-keys -t v Space
stop=$(settle_seconds 60)
echo "picture stops after space: ${stop} s (cap $((5 * scale)))"
if awk -v x="$stop" -v c="$((5 * scale))" 'BEGIN { exit !(x < c) }'; then pass; else fail "stop ${stop} s"; fi

# Step 5: the turntable again, then q while it turns: the prompt comes back soon, clean.
tm send-keys -t v Space
sleep 5
tm send-keys -t v q
start=$(date +%s.%N)
back=""
for _ in $(seq 1 $((600 * scale))); do
  if joined_screen | grep -v '^$' | tail -n 1 | grep -qE '^\$ $'; then back=$(date +%s.%N); break; fi
  sleep 0.1
done
if [ -n "$back" ]; then
  quit=$(awk -v a="$back" -v b="$start" 'BEGIN { printf "%.2f", a - b }')
  echo "q gives the prompt back: ${quit} s (cap $((5 * scale)))"
  if awk -v x="$quit" -v c="$((5 * scale))" 'BEGIN { exit !(x < c) }'; then pass; else fail "q ${quit} s"; fi
else
  fail "q did not give the prompt back in 60 s"
fi
# Nothing the viewer sent or asked for is left on the shell's lines (an
# answer to a request read after the viewer ended would show as typed text).
if screen | grep -qE '\?[0-9;]+c|\[\?|\^\['; then
  fail "something was left on the shell's lines:"
  screen | grep -v '^$' | tail -5
else
  pass
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
