#!/usr/bin/env bash
# waves_check.sh - the traces make wave opens, checked on three builds: a 2D chain with
# the mouse (ref000_rope), a 3D graph (ref001_video2) and a pipelined chain without a
# mouse (pendulum, red/black). For each: the save file scripts/gtkw.py writes names only
# signals the trace has (gtkw.py --check); GTKWave itself, under Xvfb, opens the trace
# with the save file and displays every signal the save file names (its Tcl
# getDisplayedSignals: a name GTKWave does not know is dropped without a word, which is
# what this catches); one clock cycle is 10 ns in the trace; and a scene without a mouse
# shows the mouse inputs held at 0.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
out=$build/waves_check
mkdir -p "$out"
bad=0
for spec in ref000_rope: ref001_video2: pendulum:redblack; do
  name=${spec%%:*} order=${spec#*:}
  scene=sim/scenes/$name.scene
  harness=$(python3 scripts/lockstep_fuzz.py --harness-for "$scene" ${order:+--order "$order"} --deep-trace) || { echo "FAIL waves $name: no harness"; bad=$((bad + 1)); continue; }
  fst=$out/$name.fst
  if ! "$harness" "$scene" --frames 2 --quiet --trace "$fst" ${order:+--order "$order"} > "$out/$name.log" 2>&1; then
    echo "FAIL waves $name: the traced run failed ($out/$name.log)"; bad=$((bad + 1)); continue
  fi
  python3 scripts/gtkw.py "$scene" "$out/$name.gtkw" "$fst" --check || bad=$((bad + 1))
  python3 scripts/gtkw.py "$scene" "$out/$name.gtkw" "$fst"
  printf 'set f [open %s w]\nputs $f [join [gtkwave::getDisplayedSignals] "\\n"]\nclose $f\ngtkwave::/File/Quit\n' \
    "$(realpath "$out")/$name.shown" > "$out/$name.tcl"
  rm -f "$out/$name.shown"
  (cd "$out" && timeout 120 xvfb-run -a gtkwave --dump="$name.fst" --save="$name.gtkw" --script="$name.tcl" > "$name.gtkwave.log" 2>&1)
  wanted=$(grep -c '^TOP' "$out/$name.gtkw")
  if [ -s "$out/$name.shown" ] && diff <(grep '^TOP' "$out/$name.gtkw") "$out/$name.shown" > /dev/null; then
    echo "PASS waves $name: GTKWave (under Xvfb) displays all $wanted signals of the save file"
  else
    echo "FAIL waves $name: GTKWave displays $(cat "$out/$name.shown" 2>/dev/null | grep -c .) of the $wanted signals of $out/$name.gtkw"
    bad=$((bad + 1))
  fi
  fst2vcd "$fst" 2> /dev/null > "$out/$name.vcd"
  # the clock: rising at every multiple of 10 ns (10000 ps), falling half way
  if ! awk '/^\$timescale/{getline; ts=$1} /^#/{t=substr($0,2); n++; if (n>1 && t!=last+5000) bad=1; last=t}
            END{exit !(ts=="1ps" && n>4 && !bad)}' "$out/$name.vcd"; then
    echo "FAIL waves $name: the trace's clock is not 10 ns a cycle"; bad=$((bad + 1))
  else
    echo "PASS waves $name: one clock cycle is 10 ns in the trace"
  fi
  if [ "$name" = pendulum ]; then
    id=$(awk '$1=="$var" && $5=="mouse_x" {print $4; exit}' "$out/$name.vcd")
    changes=$(awk -v id="$id" '/^#/{body=1} body && /^b/ && $2==id && $1 ~ /[1xz]/ {n++} END{print n+0}' "$out/$name.vcd")
    if [ -z "$id" ] || [ "$changes" -ne 0 ]; then
      echo "FAIL waves $name: a scene without a mouse shows mouse_x changing ($changes values other than 0)"; bad=$((bad + 1))
    else
      echo "PASS waves $name: no mouse in the scene, mouse_x held at 0 in the trace"
    fi
  fi
done
exit $((bad > 0))
