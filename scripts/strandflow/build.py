"""The Verilator harness: tb/harness.cpp (with the library tb/harness_run.cpp) on tb/sim_top.v (strand_core with one build's
parameters, its observation port unpacked), linked with the C model library.

    python3 -m strandflow.build SCENE OUTDIR [RTLDIR [ORDER]]   (scripts/build_harness.sh)

builds OUTDIR/harness for SCENE's build. RTLDIR (default rtl/) is where the RTL comes from:
a copy with a planted fault (tb/faults.py) is built the same way. ORDER (serial or
redblack) replaces the scene's constraint order (redblack: a chain's pipelined build).
Environment: HARNESS_OPT=fast compiles the C++ without optimisation (a build that runs
only a few frames, such as make mutate's: about half the compile time); DEMO=1 builds
OUTDIR/demo instead (tb/demo.cpp, the harness's run in an SDL2 window: make demo);
TRACE=deep traces every signal of the core (make wave's build).

Tracing: a harness traces (--trace, and the replay of a lockstep mismatch) the signals of
sim_top only, which are the core's ports and its observation port, every signal lockstep
compares (Verilator --trace-depth 1): the code that traces every signal inside the core is
a third of the generated C++ and some 40 % of a build's compile time, which most of make
test is. A deep build (trace="deep", its own directory: harness_dir(..., deep=True)) traces
everything, for make wave and make sim WAVES=1.
An unchanged build is not rebuilt: the stamp OUTDIR/<binary>.ok holds a digest of the
command, the tool's version, the parameters and every source's contents."""
import fcntl
import glob
import hashlib
import os
import shutil
import subprocess
import sys

if __package__ in (None, ""):      # run as a file: make the package importable
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    __package__ = "strandflow"     # noqa: A001

from .core import BUILD, GEN, LIBSTRAND, ROOT, Failure, digest, file_digest, gen_files, run_logged, stamp_fresh, \
    tool_version, write_stamp  # noqa: E402
from . import hwgen as _hwgen  # noqa: E402

BUILD_TIMEOUT = 3600


def pkg_flags(kind, *pkgs):
    p = subprocess.run(["pkg-config", kind] + list(pkgs), capture_output=True, text=True)
    if p.returncode != 0:
        raise Failure(f"pkg-config {' '.join(pkgs)} failed (make bootstrap installs them): {p.stderr.strip()}")
    return p.stdout.strip()


def harness(out, params_vh, params_h, rtl="rtl", opt="", demo=False, jobs=2, trace="top", netlist=None):
    """Build (unless its stamp is fresh) the harness of the build params_vh / params_h
    describe, from the RTL in rtl, in directory out; returns the binary's path. Failure
    with the first error and the log's path when Verilator or the compiler refuses it.
    netlist: (the Verilog of sim_top as a synthesis tool mapped it, its cell library's
    simulation models) to build the harness on instead of tb/sim_top.v and the RTL
    (scripts/gatesim.py: the lockstep of a synthesised netlist)."""
    out = os.path.abspath(os.path.join(ROOT, out))
    rtl = os.path.abspath(os.path.join(ROOT, rtl))
    os.makedirs(out, exist_ok=True)
    ver = tool_version("verilator")
    if ver is None:
        raise Failure("verilator not found (make bootstrap installs it)")
    binary, main = ("demo", "tb/demo.cpp") if demo else ("harness", "tb/harness.cpp")
    extra_cflags = f" {pkg_flags('--cflags', 'sdl2')} -I{ROOT}/tb" if demo else ""
    extra_libs = f" {pkg_flags('--libs', 'sdl2')}" if demo else ""
    if trace not in ("top", "deep"):
        raise Failure(f"harness: trace must be top or deep, not {trace!r}")
    tracing = ["--trace-fst"] + (["--trace-depth", "1"] if trace == "top" else [])
    trace_def = " -DSTRAND_TRACE_TOP=1" if trace == "top" else ""
    optflags, cxxopt = ["-O3"], "-O2"
    if opt == "fast":
        optflags, cxxopt = ["-O3", "-MAKEFLAGS", "OPT_FAST=-O0 OPT_SLOW=-O0 OPT_GLOBAL=-O0"], "-O0"
    # ccache (when installed) compiles Verilator's runtime (verilated*.cpp, the same for every
    # build) once; with the repository as base directory the command lines of all builds match.
    env = dict(os.environ)
    objcache = []
    if shutil.which("ccache"):
        env.setdefault("CCACHE_DIR", os.path.join(ROOT, BUILD, "ccache"))
        env.setdefault("CCACHE_BASEDIR", ROOT)
        objcache = ["-MAKEFLAGS", "OBJCACHE=ccache"]
    srcs = sorted(glob.glob(os.path.join(rtl, "*.v")))
    if not srcs:
        raise Failure(f"no Verilog sources in {rtl}")
    top_src = [os.path.join(ROOT, "tb", "sim_top.v")]
    lint = []
    if netlist is not None:
        # the netlist and the vendor's cell models in place of sim_top and the RTL; their
        # warnings (unused cell pins, the models' own style) are the tools', not the design's
        # (the RTL is linted clean by make test), so for this build only they do not stop it
        top_src, srcs = [netlist[0]], list(netlist[1:])
        lint = ["-Wno-fatal", "-Wno-lint", "-Wno-style"] + sorted({f"-I{os.path.dirname(f)}" for f in srcs})
    cmd = (["verilator", "--cc", "--exe", "--build", "-j", str(jobs)] + optflags
           + tracing + ["--x-assign", "unique", "--x-initial", "unique"] + lint + objcache
           + ["-Mdir", os.path.join(out, "obj"), "--top-module", "sim_top", "-o", os.path.join(out, binary),
              f"-I{GEN}", f"-I{out}", f"-I{rtl}",
              "-CFLAGS", f"{cxxopt}{trace_def} -I{ROOT}/model -I{GEN} -I{out} {pkg_flags('--cflags', 'inih', 'cairo')}"
                         f"{extra_cflags}",
              "-LDFLAGS", f"{LIBSTRAND} {pkg_flags('--libs', 'inih', 'cairo')}{extra_libs} -lm",
              ] + top_src + srcs + [os.path.join(ROOT, "tb", "harness_run.cpp"), os.path.join(ROOT, main)])
    inputs = (([netlist[0]] if netlist is not None else []) + srcs + sorted(glob.glob(os.path.join(rtl, "*.vh"))) + gen_files()
              + [os.path.join(ROOT, f) for f in ("tb/sim_top.v", "tb/harness.h", "tb/harness_run.cpp", "tb/harness.cpp", main)]
              + sorted(glob.glob(os.path.join(ROOT, "model", "*.h"))) + [LIBSTRAND])
    # params.vh's own header line names the scene it came from: not part of the build
    body = lambda text: "".join(ln + "\n" for ln in text.splitlines() if "Generated" not in ln and "written by" not in ln)
    key = digest(" ".join(cmd), ver, body(params_vh), body(params_h), file_digest(inputs))
    stamp = os.path.join(out, binary + ".ok")
    exe = os.path.join(out, binary)
    with open(out + ".lock", "w") as lock:       # one build of a directory at a time
        fcntl.flock(lock, fcntl.LOCK_EX)
        if stamp_fresh(stamp, key) and os.access(exe, os.X_OK):
            return exe
        if os.path.exists(stamp):
            os.remove(stamp)
        for name, text in (("params.vh", params_vh), ("params.h", params_h)):
            with open(os.path.join(out, name), "w") as f:
                f.write(text)
        shutil.rmtree(os.path.join(out, "obj"), ignore_errors=True)
        log = os.path.join(out, "build.log")
        rc, secs, cpu = run_logged(cmd, out, log, BUILD_TIMEOUT, env=env)
        if rc != 0:
            errs = [ln for ln in open(log).read().splitlines() if "%Error" in ln or "error:" in ln]
            raise Failure(f"verilator: {errs[0] if errs else 'build failed'} (log: {os.path.relpath(log, ROOT)})")
        write_stamp(stamp, key, tool=ver, seconds=round(secs, 1), cpu_seconds=round(cpu, 1))
    return exe


def harness_for(scene, out, rtl="rtl", order=None, opt="", demo=False, trace="top"):
    """`strand hwgen` for SCENE's build into OUT.gen, then harness() in OUT."""
    out = os.path.abspath(os.path.join(ROOT, out))
    gen_dir = out + ".gen"
    _hwgen.hwgen(scene, gen_dir, order)
    with open(os.path.join(gen_dir, "params.vh")) as f:
        vh = f.read()
    with open(os.path.join(gen_dir, "params.h")) as f:
        h = f.read()
    return harness(out, vh, h, rtl=rtl, opt=opt, demo=demo, trace=trace)


def build_key(params):
    return hashlib.sha1(repr(sorted(params.items())).encode()).hexdigest()[:10]


def harness_dir(params, fault="", deep=False, fast=False):
    """Where the harness of a build (strand_core's parameters) lives under build/vl/, so that
    every script that needs the same build finds the same binary (deep: the build that traces
    every signal; fast: compiled without optimisation, opt="fast")."""
    return os.path.join(BUILD, "vl", "b_" + build_key(params) + (f"_fault_{fault}" if fault else "")
                        + ("_deep" if deep else "") + ("_fast" if fast else ""))


def main(argv):
    if not 2 <= len(argv) <= 4:
        sys.stderr.write("usage: build_harness.sh SCENE OUTDIR [RTLDIR [ORDER]]\n")
        return 2
    scene, out = argv[0], argv[1]
    rtl = argv[2] if len(argv) > 2 else "rtl"
    order = argv[3] if len(argv) > 3 and argv[3] else None
    try:
        harness_for(scene, out, rtl, order, opt=os.environ.get("HARNESS_OPT", ""), demo=os.environ.get("DEMO") == "1",
                    trace="deep" if os.environ.get("TRACE") == "deep" else "top")
    except Failure as e:
        log = os.path.join(os.path.abspath(os.path.join(ROOT, out)), "build.log")
        if "verilator" in str(e) and os.path.exists(log):
            sys.stdout.write(open(log).read())
        sys.stderr.write(f"build_harness: {e}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
