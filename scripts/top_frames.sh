#!/usr/bin/env bash
# top_frames.sh SCENE [FRAMES [ORDER [RTLDIR]]] - run tb/tb_top_frames.v on SCENE under Icarus.
#
# Exports the scene with 'strand hwgen' (build, setup, mouse, expected positions from
# the C frame engine, expected status from the cycle model), compiles the bench with
# iverilog -Wall (any warning fails), runs it, and prints its PASS or FAIL line. ORDER
# (serial or redblack) replaces the scene's constraint order: redblack runs a chain on
# the pipelined build. RTLDIR (default rtl) is where the RTL comes from: a copy with a
# planted fault or a mutation is run the same way; HW_DIR (default $BUILD/hw) is where
# the run is kept.
set -uo pipefail
cd "$(dirname "$0")/.."
scene=$1
frames=${2:-}
order=${3:-}
rtldir=${4:-rtl}
build=${BUILD:-build}
name=$(basename "$scene" .scene)${order:+_$order}
dir=${HW_DIR:-$build/hw}/$name
rtl="tb/sim_top.v $(ls "$rtldir"/*.v)"
rm -rf "$dir"
if ! "$build/strand" hwgen "$scene" "$dir" ${frames:+--frames "$frames"} ${order:+--order "$order"}; then
  echo "FAIL top_frames $name: strand hwgen failed"; exit 1
fi
if ! out=$(iverilog -Wall -g2005 -I "$build/gen" -I "$rtldir" -I "$dir" -o "$dir/top.vvp" tb/tb_top_frames.v $rtl 2>&1) || [ -n "$out" ]; then
  echo "$out"; echo "FAIL top_frames $name: iverilog reported problems"; exit 1
fi
result=$(cd "$dir" && timeout 900 vvp -n top.vvp 2>&1)
echo "$result" | grep -E '^(PASS|FAIL)' | sed "s/tb_top_frames/tb_top_frames $name/"
echo "$result" | grep -q '^PASS'
