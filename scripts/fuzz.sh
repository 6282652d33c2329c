#!/usr/bin/env bash
# fuzz.sh FUZZER SECONDS WORKDIR [JSON] - replay the committed corpus and crash
# reproducers, then fuzz the scene parser for SECONDS (0: replay only).
#
# The working corpus grows in WORKDIR/corpus (seeded from tb/fuzz/corpus); a crash,
# leak, hang or bad message leaves WORKDIR/crash-* (or leak-, timeout-): copy it to
# tb/fuzz/crashes/ so every later run replays it. Prints PASS/FAIL lines; with JSON,
# writes the run's figures (executions, seconds, crashes) for docs/stability.md.
set -uo pipefail
fuzzer=$1 seconds=$2 work=$3 json=${4:-}
cd "$(dirname "$0")/.."
mkdir -p "$work/corpus"
rc=0

# 1. replay: every committed input runs once under the sanitizers, each on its own
inputs=(tb/fuzz/corpus/* $(ls tb/fuzz/crashes/* 2>/dev/null | grep -v '\.md$'))
bad=()
: > "$work/replay.log"
for f in "${inputs[@]}"; do
  "$fuzzer" "$f" >> "$work/replay.log" 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -eq 0 ]; then
  echo "PASS fuzz replay: ${#inputs[@]} committed inputs (corpus and crash reproducers) under ASan and UBSan"
else
  for f in "${bad[@]}"; do
    echo "FAIL fuzz replay $f: $("$fuzzer" "$f" 2>&1 | grep -E '^fuzz_scene:|ERROR: [A-Za-z]+Sanitizer|runtime error' | head -1)"
  done
  rc=1
fi

# 2. a bounded coverage-guided run
if [ "$seconds" -gt 0 ]; then
  cp -n tb/fuzz/corpus/* "$work/corpus/" 2>/dev/null
  rm -f "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-*
  start=$(date +%s)
  "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 -dict=tb/fuzz/scene.dict \
    -artifact_prefix="$work/" -print_final_stats=1 "$work/corpus" > "$work/fuzz.log" 2>&1
  frc=$?
  elapsed=$(( $(date +%s) - start ))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/fuzz.log" | tail -1)
  newu=$(sed -n 's/^stat::new_units_added: *//p' "$work/fuzz.log" | tail -1)
  cov=$(grep -oE 'cov: [0-9]+' "$work/fuzz.log" | tail -1 | grep -oE '[0-9]+')
  crashes=$(ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null | wc -l)
  if [ "$frc" -eq 0 ] && [ "$crashes" -eq 0 ]; then
    echo "PASS fuzz run: ${runs:-0} executions in ${elapsed} s, 0 crashes, coverage ${cov:-?} edges, corpus $(ls "$work/corpus" | wc -l) inputs"
  else
    echo "FAIL fuzz run: exit $frc after ${runs:-?} executions; artifacts: $(ls "$work"/crash-* "$work"/leak-* "$work"/timeout-* "$work"/oom-* 2>/dev/null | tr '\n' ' ')"
    echo "     copy each artifact to tb/fuzz/crashes/ (it is replayed by every later run); log: $work/fuzz.log"
    grep -E 'ERROR|fuzz_scene:|SUMMARY' "$work/fuzz.log" | head -5
    rc=1
  fi
  if [ -n "$json" ]; then
    printf '{"seconds": %s, "executions": %s, "crashes": %s, "new_units": %s, "coverage_edges": %s, "corpus": %s, "committed_inputs": %s}\n' \
      "$elapsed" "${runs:-0}" "$crashes" "${newu:-0}" "${cov:-0}" "$(ls "$work/corpus" | wc -l)" "${#inputs[@]}" > "$json"
  fi
fi
exit $rc
