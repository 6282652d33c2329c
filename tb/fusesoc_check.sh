#!/usr/bin/env bash
# fusesoc_check.sh [--synth] - strand.core through FuseSoC and edalize (the pinned PyPI
# versions in .venv): the core lists every rtl/*.v and rtl/*.vh; its lint target (Verilator
# -Wall) passes; its sim target (the Icarus frame bench) passes on a build of
# tb/scenes/chain_q10_8.scene; with --synth its synth target (Yosys, ECP5) writes a netlist.
# Work in build/fusesoc/.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
root=$(pwd)
out=$build/fusesoc
mkdir -p "$out"
bad=0
missing=$(for f in rtl/*.v rtl/*.vh; do grep -q "^      - $f\b" strand.core || echo "$f"; done)
if [ -n "$missing" ]; then
  echo "FAIL fusesoc core: strand.core does not list $(echo $missing)"; bad=$((bad + 1))
else
  echo "PASS fusesoc core: strand.core lists every rtl/*.v and rtl/*.vh ($(ls rtl/*.v rtl/*.vh | wc -l) files)"
fi
target() {   # NAME ARGS... : run one target, its log in build/fusesoc/NAME.log
  local name=$1; shift
  (cd "$out" && "$root/.venv/bin/fusesoc" --cores-root "$root" run --target "$name" "$@") > "$out/$name.log" 2>&1
}
why() { echo "see $out/$1.log: $(grep -m1 -iE 'error|fail' "$out/$1.log")"; }
if target lint ::strand:0.1; then
  echo "PASS fusesoc lint: Verilator -Wall through edalize on strand_axil and strand_core"
else
  echo "FAIL fusesoc lint: $(why lint)"; bad=$((bad + 1))
fi
rm -rf "$out/hw"
if "$build/strand" hwgen tb/scenes/chain_q10_8.scene "$out/hw" --frames 3 > /dev/null &&
   target sim ::strand:0.1 --HW_DIR="$(realpath "$out/hw")" && grep -q "^PASS tb_top_frames" "$out/sim.log"; then
  echo "PASS fusesoc sim: $(grep -m1 '^PASS tb_top_frames' "$out/sim.log")"
else
  echo "FAIL fusesoc sim: $(why sim)"; bad=$((bad + 1))
fi
if [ "${1:-}" = --synth ]; then
  json=$out/build/strand_0.1/synth-yosys/strand_0.1.json
  rm -f "$json"
  if target synth ::strand:0.1 && [ -s "$json" ]; then
    echo "PASS fusesoc synth: Yosys synth_ecp5 through edalize wrote $json"
  else
    echo "FAIL fusesoc synth: no netlist; $(why synth)"; bad=$((bad + 1))
  fi
fi
exit $((bad > 0))
