#!/usr/bin/env bash
# build_harness.sh SCENE OUTDIR [RTLDIR [ORDER]] - the Verilator harness for SCENE's build.
#
# The step itself is scripts/strandflow/build.py (its header says what it builds and how it
# is cached); this wrapper is make's and the shell scripts' way in. RTLDIR (default rtl/) is
# where the RTL comes from (a copy with a planted fault is built the same way); ORDER
# (serial or redblack) replaces the scene's constraint order. HARNESS_OPT=fast compiles the
# C++ without optimisation; DEMO=1 builds OUTDIR/demo (make demo) instead of OUTDIR/harness.
set -euo pipefail
cd "$(dirname "$0")/.."
PYTHONPATH="$(pwd)/scripts${PYTHONPATH:+:$PYTHONPATH}" PYTHONDONTWRITEBYTECODE=1 exec python3 -m strandflow.build "$@"
