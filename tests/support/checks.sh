# Shared by the CLI test scripts: `source` it after setting `work` (a scratch
# folder). Counts into passed/failed; finish prints the closing line and
# gives the exit status.

passed=0
failed=0

# check NAME EXPECTED_CODE EXPECTED_STDERR_SUBSTRING -- command...
# Runs the command (under `timeout $CHECK_TIMEOUT` when set), stdout to
# $work/out, stderr to $work/err, and checks its exit code and stderr.
check() {
  local name=$1 want=$2 message=$3
  shift 4
  ${CHECK_TIMEOUT:+timeout "$CHECK_TIMEOUT"} "$@" >"$work/out" 2>"$work/err" </dev/null
  local got=$?
  if [ "$got" -ne "$want" ]; then
    echo "FAIL $name: exit $got, expected $want; stderr: $(head -c 600 "$work/err")"
    failed=$((failed + 1))
  elif [ -n "$message" ] && ! grep -qF -- "$message" "$work/err"; then
    echo "FAIL $name: stderr lacks '$message'; it was: $(head -c 600 "$work/err")"
    failed=$((failed + 1))
  else
    passed=$((passed + 1))
  fi
}

# expect NAME CONDITION-COMMAND...
expect() {
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL $name"; failed=$((failed + 1)); fi
}

# The closing line ('N passed, N failed'), and the script's status.
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
