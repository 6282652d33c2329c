#!/usr/bin/env bash
# build_harness.sh SCENE OUTDIR [RTLDIR [ORDER]] - the Verilator harness for SCENE's build.
#
# 'strand hwgen' writes OUTDIR/params.vh and params.h (the build the scene needs);
# Verilator compiles sim_top (strand_core with those parameters, its observation port
# unpacked) with the C++ harness, linked with the C model library. RTLDIR (default
# rtl/) is where the RTL comes from: a copy with a planted fault (tb/faults.py) is
# built the same way. ORDER (serial or redblack) replaces the scene's constraint order
# (redblack: a chain's pipelined build). The binary is OUTDIR/harness; an unchanged build
# is not rebuilt. HARNESS_OPT=fast compiles the C++ without optimisation (a build that
# runs only a few frames, such as make mutate's: about half the compile time). DEMO=1
# builds OUTDIR/demo instead (tb/demo.cpp, the harness's run with an SDL2 window: make demo).
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1 out=$2 rtl=${3:-rtl} order=${4:-}
build=${BUILD:-build}
root=$(pwd)
case $rtl in /*) ;; *) rtl=$root/$rtl ;; esac
case $out in /*) ;; *) out=$root/$out ;; esac
mkdir -p "$out"
# one build of a directory at a time (two runs may want the same harness at once)
exec 9>"$out.lock"
flock 9
"$build/strand" hwgen "$scene" "$out.gen" --frames 1 ${order:+--order "$order"} >/dev/null
# rebuild only when the build parameters or a source changed
opt=${HARNESS_OPT:-}
bin=harness main=tb/harness.cpp extra_cflags="" extra_libs=""
if [ "${DEMO:-}" = 1 ]; then
  bin=demo main=tb/demo.cpp extra_cflags="$(pkg-config --cflags sdl2) -I$root/tb" extra_libs="$(pkg-config --libs sdl2)"
fi
stamp="$(grep -v Generated "$out.gen/params.vh") $rtl $opt $bin $(cat "$rtl"/*.v "$rtl"/*.vh "$build"/gen/*.vh tb/sim_top.v tb/harness.cpp $main "$build/libstrand.a" | md5sum)"
if [ -x "$out/$bin" ] && [ -f "$out/stamp" ] && [ "$(cat "$out/stamp")" = "$stamp" ]; then exit 0; fi
cp "$out.gen/params.vh" "$out.gen/params.h" "$out/"
rm -rf "$out/obj"
# ccache (when installed) compiles Verilator's runtime (verilated*.cpp, the same for every
# build) once; with the repository as base directory the command lines of all builds match.
objcache=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_DIR="$root/$build/ccache" CCACHE_BASEDIR="$root"
  objcache=(-MAKEFLAGS "OBJCACHE=ccache")
fi
optflags=(-O3)
cxxopt=-O2
if [ "$opt" = fast ]; then
  optflags=(-O3 -MAKEFLAGS "OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0")
  cxxopt=-O0
fi
verilator --cc --exe --build -j 2 "${optflags[@]}" --trace-fst --x-assign unique --x-initial unique "${objcache[@]}" \
  -Mdir "$out/obj" --top-module sim_top -o "$out/$bin" \
  -I"$root/$build/gen" -I"$out" -I"$rtl" \
  -CFLAGS "$cxxopt -I$root/model -I$root/$build/gen -I$out $(pkg-config --cflags inih cairo) $extra_cflags" \
  -LDFLAGS "$root/$build/libstrand.a $(pkg-config --libs inih cairo) $extra_libs -lm" \
  "$root/tb/sim_top.v" $(for f in "$rtl"/*.v; do echo "$f"; done) "$root/$main" >"$out/build.log" 2>&1 \
  || { cat "$out/build.log"; exit 1; }
echo "$stamp" >"$out/stamp"
