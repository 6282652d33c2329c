#!/usr/bin/env bash
# sim.sh SCENE [--waves] [ORDER] - the main job: SCENE on the RTL in lockstep with the C model.
# FRAMES (environment) runs that many frames instead of the scene's.
#
# Builds strand_core with exactly the scene's parameters and effects (cached), runs
# it cycle for cycle against the cycle model, and writes into build/sim/<scene>/:
# positions.csv (every frame end), final.png (the last frame), and with --waves an
# FST trace (one clock cycle 10 ns) and a GTKWave save file written from it
# (scripts/gtkw.py); a lockstep mismatch leaves mismatch.fst there.
# ORDER (serial or redblack) replaces the scene's constraint order, as `strand run --order`
# does: redblack builds a chain's pipelined passes (make sim ORDER=redblack).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1
waves=${2:-}
order=${3:-}
case "$order" in ""|serial|redblack) ;; *) echo "sim.sh: ORDER must be serial or redblack (not '$order')" >&2; exit 2;; esac
frames=${FRAMES:-}
if [ -n "$frames" ] && ! [[ "$frames" =~ ^[1-9][0-9]{0,7}$ ]]; then
  echo "sim.sh: FRAMES must be a whole number of frames >= 1 (not '$frames')" >&2; exit 2
fi
build=${BUILD:-build}
name=$(basename "$scene" .scene)
out=$build/sim/$name
"$build/strand" check "$scene" ${order:+--order "$order"} >/dev/null   # a bad scene stops here, with file:line
mkdir -p "$out"
echo "building strand_core for $scene (Verilator; cached once built)..."
# with --waves the build that traces every signal of the core (a build of its own), else the
# one make test runs, whose traces hold the core's ports and its observation port
harness=$(python3 scripts/lockstep_fuzz.py --harness-for "$scene" ${order:+--order "$order"} ${waves:+--deep-trace})
# the harness runs in $out, so that a lockstep mismatch leaves its trace (mismatch.fst) there
harness=$(realpath "$harness")
scene_abs=$(realpath "$scene")
out_abs=$(realpath "$out")
args=(--csv "$out_abs/positions.csv" --png "$out_abs/final.png" --progress ${order:+--order "$order"} ${frames:+--frames "$frames"})
if [ "$waves" = "--waves" ]; then
  args+=(--trace "$out_abs/waves.fst")
fi
(cd "$out" && "$harness" "$scene_abs" "${args[@]}")
if [ "$waves" = "--waves" ]; then
  # the save file is written from the trace's own signal list: only names this build has
  python3 scripts/gtkw.py "$scene" "$out/strand.gtkw" "$out/waves.fst"
fi
echo "positions: $out/positions.csv   picture: $out/final.png${waves:+   trace: $out/waves.fst}"
