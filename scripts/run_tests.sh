#!/usr/bin/env bash
# run_tests.sh STEP... - run each make step, keep its log, count the results.
#
# A result is a line "PASS ..." / "FAIL ..." (testbenches, checks) or a cmocka test
# ("[       OK ] name" / "[  FAILED  ] name"). A step that exits non-zero without
# printing a FAIL counts as one failure. In a git checkout the run must leave the tree as it
# found it: a file that `git status --porcelain` shows after the steps and did not before is
# a failure ("tree clean"). Ends with "N passed, N failed".
set -uo pipefail
cd "$(dirname "$0")/.."
logs=${BUILD:-build}/logs
mkdir -p "$logs"
passed=0 failed=0 failed_steps=()
in_git=false
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  in_git=true
  git status --porcelain > "$logs/status.before"
fi
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
if $in_git; then
  git status --porcelain > "$logs/status.after"
  new=$(grep -vxF -f "$logs/status.before" "$logs/status.after" || true)
  if [ -n "$new" ]; then
    echo "FAIL tree clean: the run left what git status shows: $(echo "$new" | head -5 | tr '\n' ';')"
    failed=$((failed + 1)) failed_steps+=("tree-clean")
  else
    echo "PASS tree clean: git status shows nothing the run added"
    passed=$((passed + 1))
  fi
fi
echo
[ ${#failed_steps[@]} -gt 0 ] && echo "failed steps: ${failed_steps[*]} (logs in $logs/)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
