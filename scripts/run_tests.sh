#!/usr/bin/env bash
# run_tests.sh STEP... - run each make step, keep its log, count the results.
#
# A result is a line "PASS ..." / "FAIL ..." (testbenches, checks) or a cmocka test
# ("[       OK ] name" / "[  FAILED  ] name"). A step that exits non-zero without
# printing a FAIL counts as one failure. Ends with "N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.."
logs=${BUILD:-build}/logs
mkdir -p "$logs"
passed=0 failed=0 failed_steps=()
for step in "$@"; do
  echo "== $step"
  log="$logs/$step.log"
  t0=$SECONDS
  make --no-print-directory -s "$step" 2>&1 | tee "$log"
  rc=${PIPESTATUS[0]}
  echo "== $step: $((SECONDS - t0)) s"
  p=$(grep -cE '^(PASS |\[       OK \] )' "$log")
  f=$(grep -cE '^(FAIL |\[  FAILED  \] [^0-9])' "$log")
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; echo "FAIL $step: exit status $rc (log: $log)"; fi
  [ "$f" -gt 0 ] && failed_steps+=("$step")
  passed=$((passed + p)) failed=$((failed + f))
done
echo
[ ${#failed_steps[@]} -gt 0 ] && echo "failed steps: ${failed_steps[*]} (logs in $logs/)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
