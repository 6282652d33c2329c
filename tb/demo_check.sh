#!/usr/bin/env bash
# demo_check.sh - make demo without a person: the demo runs under Xvfb with a pointer fed
# through SDL's own event queue (--events). On a grab build (hard_mouse_grab) the pointer
# presses, holds, moves while held and holds again: the node it took must end under it,
# with lockstep held every cycle. On the default scene (the impulse form) a press beside
# the rope: lockstep must hold. Each run writes a screenshot (HUD included).
set -uo pipefail
cd "$(dirname "$0")/.."
build=${BUILD:-build}
out=$build/demo
mkdir -p "$out"
bad=0
run() {   # NAME SCENE FRAMES EVENTS
  local name=$1 scene=$2 frames=$3 events=$4 d=$out/$1
  DEMO=1 scripts/build_harness.sh "$scene" "$d" > "$out/$name.build.log" 2>&1 || { echo "FAIL demo $name: build ($out/$name.build.log)"; return 1; }
  printf "%s\n" "$events" > "$out/$name.events"
  xvfb-run -a "$d/demo" "$scene" --frames "$frames" --events "$out/$name.events" --screenshot "$out/$name.png" > "$out/$name.log" 2>&1
}
# grab: press at (350, 160), hold; at frame 40 move to (310, 190) still held; 80 frames (the
# window maps the Q16.16 range to about 130 pixels square around (332, 174))
if run grab sim/scenes/hard_mouse_grab.scene 80 "0 350 160 1
40 310 190 1"; then
  line=$(grep "^demo " "$out/grab.log")
  away=$(sed -n 's/.* \([0-9.]*\) away$/\1/p' <<<"$line")
  if grep -q "lockstep held" <<<"$line" && grep -q "held, nearest" <<<"$line" && awk -v a="$away" 'BEGIN{exit !(a != "" && a < 0.01)}'; then
    echo "PASS demo grab: the pointer held and moved through SDL's event queue, the grabbed node followed it ($away away), lockstep held ($line)"
  else
    echo "FAIL demo grab: $line"; bad=$((bad + 1))
  fi
else
  echo "FAIL demo grab: $(tail -2 "$out/grab.log")"; bad=$((bad + 1))
fi
# impulse: the default scene, a press beside node 9 at frame 30, released at 40
if run impulse sim/scenes/ref000_rope.scene 60 "0 100 100 0
30 330 360 1
40 330 360 0" && grep -q "lockstep held" "$out/impulse.log"; then
  echo "PASS demo impulse: 60 frames of the default scene with a live press, lockstep held"
else
  echo "FAIL demo impulse: $(tail -2 "$out/impulse.log")"; bad=$((bad + 1))
fi
for s in grab impulse; do
  [ -s "$out/$s.png" ] || { echo "FAIL demo $s: no screenshot"; bad=$((bad + 1)); }
done
exit $((bad > 0))
