#!/usr/bin/env bash
# stability_cli.sh STRAND - strand check's stability bound and --auto-substeps.
set -uo pipefail
strand=$1
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rc=0
pass() { echo "PASS $*"; }
fail() { echo "FAIL $*"; rc=1; }

s=sim/scenes/hard_stiff_k10000.scene
line=$(grep -n '^\[springs\]' "$s" | cut -d: -f1)
"$strand" check "$s" > "$tmp/out" 2> "$tmp/err"; r=$?
if [ "$r" -eq 0 ] && grep -q "^$s:$line: warning: the springs cross the stability bound" "$tmp/err" && grep -q "UNSTABLE" "$tmp/out"
then pass "strand check warns at $s:$line that the springs cross the bound"; else fail "strand check $s: exit $r, no warning at line $line"; fi

"$strand" check sim/scenes/hard_stiff_k1000.scene > "$tmp/out" 2> "$tmp/err"
if [ ! -s "$tmp/err" ] && grep -q "(stable below 1)" "$tmp/out"; then pass "strand check: the reference-004 chain is inside the bound, no warning"
else fail "strand check hard_stiff_k1000: unexpected warning or no bound: $(cat "$tmp/err")"; fi

"$strand" check "$s" --auto-substeps 4096 > "$tmp/out" 2>/dev/null
n=$(sed -n 's/^auto-substeps: \([0-9]*\) .*/\1/p' "$tmp/out")
if [ -n "$n" ] && [ "$n" -gt 8 ]; then
  sed "s/^substeps = .*/substeps = $n/" "$s" > "$tmp/auto.scene"
  # (only the bound's warning: at that many substeps g h^2 may round by more than 1 %, which
  # strand check rightly names too)
  if "$strand" check "$tmp/auto.scene" 2>&1 >/dev/null | grep -q "warning: the springs cross the stability bound"; then
    fail "--auto-substeps picked $n, still warned"
  else pass "--auto-substeps picks $n substeps for $s, and the scene at $n is inside the bound"; fi
else fail "--auto-substeps printed no choice"; fi

"$strand" run "$s" --auto-substeps 10 --csv "$tmp/x.csv" > /dev/null 2> "$tmp/err"; r=$?
if [ "$r" -eq 2 ] && grep -q "^$s:$line: " "$tmp/err" && [ ! -e "$tmp/x.csv" ] && [ ! -e "$tmp/x.csv.tmp" ]
then pass "--auto-substeps 10 (too few allowed): exit 2 at $s:$line, nothing written"; else fail "--auto-substeps 10: exit $r"; fi

"$strand" run "$s" --auto-substeps x > /dev/null 2>&1; r=$?
[ "$r" -eq 2 ] && pass "--auto-substeps x: bad argument, exit 2" || fail "--auto-substeps x: exit $r"

"$strand" run "$s" --auto-substeps 4096 --format double --frames 600 > "$tmp/out" 2>&1
if ! grep -q "non-finite" "$tmp/out"; then pass "strand run --auto-substeps: $s stays finite for 600 frames"
else fail "strand run --auto-substeps: $s diverged"; fi
exit $rc
