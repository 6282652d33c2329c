#!/usr/bin/env bash
# bad_input_cli.sh STRAND - every malformed committed scene (tb/fuzz/corpus/bad_*) gets
# "file:line: message" and exit status 2 from strand check and strand run, within 10 s,
# and strand run --csv leaves neither the CSV nor its temporary file behind; strand set refuses
# a bad key or value the same way and writes nothing; a bad FRAMES
# for make sim and make movie stops before anything is built, with exit status 2.
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
for script in sim movie; do
  for frames in abc 0 -3 1e3; do
    n=$((n + 1))
    FRAMES=$frames timeout 10 scripts/$script.sh sim/scenes/ref000_rope.scene > /dev/null 2> "$tmp/err"; rc=$?
    if [ "$rc" -ne 2 ] || ! grep -q "FRAMES must be a whole number" "$tmp/err"; then
      echo "FAIL bad input FRAMES=$frames for $script.sh: exit $rc, stderr: $(head -1 "$tmp/err")"; bad=$((bad + 1))
    fi
  done
done
# strand set: a value the parser refuses names the assignment, a key that makes another line
# contradictory names that line; exit 2 and neither OUT nor its temporary file written
for args in "time.substeps=0|'time.substeps=0': " "format.width=12|sim/scenes/pendulum.scene:10: " "nodot=1|want SECTION.KEY=VALUE"; do
  n=$((n + 1))
  timeout 10 "$strand" set sim/scenes/pendulum.scene "$tmp/set.scene" "${args%%|*}" > /dev/null 2> "$tmp/err"; rc=$?
  if [ "$rc" -ne 2 ] || ! grep -qF "${args#*|}" "$tmp/err" || [ -e "$tmp/set.scene" ] || [ -e "$tmp/set.scene.tmp" ]; then
    echo "FAIL bad input strand set ${args%%|*}: exit $rc, stderr: $(head -1 "$tmp/err")"; bad=$((bad + 1))
  fi
done
# strand board: no port (exit 2, a usage message), a port that does not exist (exit 1,
# named), and no file left behind
n=$((n + 1))
timeout 10 "$strand" board sim/scenes/board_rope.scene > /dev/null 2> "$tmp/err"; rc=$?
if [ "$rc" -ne 2 ] || ! grep -q "needs --port" "$tmp/err"; then
  echo "FAIL bad input strand board without --port: exit $rc, stderr: $(head -1 "$tmp/err")"; bad=$((bad + 1))
fi
n=$((n + 1))
timeout 10 "$strand" board --port "$tmp/no-such-port" sim/scenes/board_rope.scene --csv "$tmp/b.csv" > /dev/null 2> "$tmp/err"; rc=$?
if [ "$rc" -ne 1 ] || ! grep -q "no-such-port" "$tmp/err" || [ -e "$tmp/b.csv" ] || [ -e "$tmp/b.csv.tmp" ]; then
  echo "FAIL bad input strand board --port (missing): exit $rc, stderr: $(head -1 "$tmp/err")"; bad=$((bad + 1))
fi
[ "$bad" -eq 0 ] && echo "PASS bad input: $n malformed inputs: scenes (strand check and strand run --csv exit 2 with file:line: message, no output file), FRAMES of make sim and make movie (exit 2), strand set refusing a key or value (exit 2, nothing written), strand board without a port or with a missing one"
exit $((bad > 0))
