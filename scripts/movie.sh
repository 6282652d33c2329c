#!/usr/bin/env bash
# movie.sh SCENE - an MP4 and a GIF of a scene, as reference 001 made its videos.
#
# Frames come from the RTL run when the RTL can run the scene (the lockstep harness
# renders the positions it verified every cycle), otherwise from the fixed-point
# frame engine, which the RTL matches bit for bit; the script says which. 3D scenes
# are drawn from an oblique camera. ffmpeg encodes build/movie/<scene>.mp4 (H.264)
# and build/movie/<scene>.gif. FRAMES (environment) draws that many frames instead of the scene's.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1
build=${BUILD:-build}
fps=${FPS:-50}
name=$(basename "$scene" .scene)
frames_n=${FRAMES:-}
if [ -n "$frames_n" ] && ! [[ "$frames_n" =~ ^[1-9][0-9]{0,7}$ ]]; then
  echo "movie.sh: FRAMES must be a whole number of frames >= 1 (not '$frames_n')" >&2; exit 2
fi
out=$build/movie
frames=$out/$name.frames
"$build/strand" check "$scene" >/dev/null
rm -rf "$frames"
mkdir -p "$frames"
if "$build/strand" hwgen "$scene" "$out/$name.gen" --frames 1 >/dev/null 2>&1; then
  echo "movie: frames from the RTL (lockstep with the C model)"
  harness=$(python3 scripts/lockstep_fuzz.py --harness-for "$scene")
  "$harness" "$scene" --png-dir "$frames" --quiet --progress ${frames_n:+--frames "$frames_n"}
else
  echo "movie: the RTL does not run this scene yet; frames from the fixed-point frame engine (bit-exact with the RTL's arithmetic)"
  "$build/strand" run "$scene" --png "$frames" ${frames_n:+--frames "$frames_n"} >/dev/null
fi
# the renderer draws even sizes (yuv420p needs them), so nothing is padded or cropped
ffmpeg -loglevel error -y -framerate "$fps" -i "$frames/frame_%05d.png" -c:v libx264 -pix_fmt yuv420p "$out/$name.mp4"
ffmpeg -loglevel error -y -framerate "$fps" -i "$frames/frame_%05d.png" \
  -vf "fps=25,scale=480:-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse" "$out/$name.gif"
echo "movie: $out/$name.mp4 ($(ls "$frames" | wc -l) frames at $fps fps), $out/$name.gif"
