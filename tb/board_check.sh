#!/usr/bin/env bash
# board_check.sh [SCENE [FRAMES]] - the board path end to end, in simulation: the iCEBreaker
# top (rtl/boards/icebreaker_top.v: the UART bridge, strand_axil, the core) under Verilator
# with its UART pins on a pseudo-terminal (tb/board_sim.cpp), and `strand board` talking to
# it as to a real board. Every frame's positions, read back over the serial link, must
# equal the C model's (strand run --hex) byte for byte.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
scene=${1:-sim/scenes/board_rope.scene}
frames=${2:-45}
out=$build/board_sim
mkdir -p "$out"
root=$(pwd)
rm -rf "$out/hw"
"$build/strand" hwgen "$scene" "$out/hw" --frames 1 > /dev/null || { echo "FAIL board: strand hwgen $scene"; exit 1; }
if ! verilator --cc --exe --build -j 2 -O3 --top-module icebreaker_top --prefix Vboard -Mdir "$out/obj" -o "$root/$out/board_sim" \
     -I"$root/$build/gen" -I"$root/rtl" -I"$root/$out/hw" "$root"/rtl/boards/*.v "$root"/rtl/*.v "$root/tb/board_sim.cpp" \
     > "$out/build.log" 2>&1; then
  echo "FAIL board: the Verilator build of icebreaker_top ($out/build.log)"; exit 1
fi
rm -f "$out/pty"
"$out/board_sim" --pty-file "$out/pty" --max-seconds 300 > "$out/sim.log" 2>&1 &
sim=$!
trap 'kill $sim 2>/dev/null' EXIT
for _ in $(seq 100); do [ -s "$out/pty" ] && break; sleep 0.1; done
[ -s "$out/pty" ] || { echo "FAIL board: the simulated board gave no pseudo-terminal ($out/sim.log)"; exit 1; }
t0=$SECONDS
if ! "$build/strand" board --port "$(cat "$out/pty")" "$scene" --frames "$frames" --hex "$out/board.hex" > "$out/host.log" 2>&1; then
  echo "FAIL board: strand board: $(tail -1 "$out/host.log")"; exit 1
fi
"$build/strand" run "$scene" --frames "$frames" --hex "$out/model.hex" > /dev/null
if cmp -s "$out/board.hex" "$out/model.hex"; then
  echo "PASS board: $(basename "$scene" .scene), $frames frames through the iCEBreaker top's UART (simulated, on a pseudo-terminal): every node read back equals the C model's, bit for bit ($((SECONDS - t0)) s)"
else
  echo "FAIL board: the positions read over the serial link differ from the C model's ($out/board.hex, $out/model.hex)"; exit 1
fi
