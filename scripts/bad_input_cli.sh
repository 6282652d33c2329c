#!/usr/bin/env bash
# bad_input_cli.sh STRAND - every malformed committed scene (tb/fuzz/corpus/bad_*) gets
# "file:line: message" and exit status 2 from strand check and strand run, within 10 s,
# and strand run --csv leaves neither the CSV nor its temporary file behind.
set -uo pipefail
strand=$1
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0 bad=0
for f in tb/fuzz/corpus/bad_*; do
  n=$((n + 1))
  timeout 10 "$strand" check "$f" > /dev/null 2> "$tmp/err"; rc=$?
  if [ "$rc" -ne 2 ] || ! grep -qE "^$f:[0-9]+: .+" "$tmp/err"; then
    echo "FAIL bad input $f: strand check exit $rc, stderr: $(head -1 "$tmp/err")"; bad=$((bad + 1)); continue
  fi
  timeout 10 "$strand" run "$f" --csv "$tmp/out.csv" --hex "$tmp/out.hex" > /dev/null 2> "$tmp/err"; rc=$?
  if [ "$rc" -ne 2 ] || [ -e "$tmp/out.csv" ] || [ -e "$tmp/out.csv.tmp" ] || [ -e "$tmp/out.hex" ] || [ -e "$tmp/out.hex.tmp" ]; then
    echo "FAIL bad input $f: strand run exit $rc, files left: $(ls "$tmp" | grep out | tr '\n' ' ')"; bad=$((bad + 1)); continue
  fi
done
[ "$bad" -eq 0 ] && echo "PASS bad input: $n malformed scenes: strand check and strand run --csv exit 2 with file:line: message, no output file"
exit $((bad > 0))
