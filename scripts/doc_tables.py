#!/usr/bin/env python3
"""doc_tables.py [--check] FILE... - the tables docs/ quote from the project's one sources.

Rewrites, in each FILE, every region between

    <!-- BEGIN generated: NAME -->
    <!-- END generated: NAME -->

with the table NAME, made from the one source of its facts:

    registers   the register map: scripts/gen_regs.py's REGS
    parameters  strand_core's parameters: scripts/gen_params.py's PARAMS, DERIVED, CHECKS
    timing      the cycle counts of the default scene's build: `strand info` (model/timing.c)
    timing_pipelined  the same with --order redblack: the pipelined build (ARCH = 1)
    timing_graph      the tensegrity of reference 001 with --order redblack: a graph's pipelined pass

With --check nothing is written: the exit status is 1 and a FAIL line names each file
whose regions are not what they would be (make test runs this).
"""
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import gen_params  # noqa: E402
import gen_regs  # noqa: E402

BUILD = os.environ.get("BUILD", "build")
DEFAULT_SCENE = "sim/scenes/ref000_rope.scene"


def registers():
    lines = ["| name | address | byte address (strand_axil) | what is written there |", "|---|--:|--:|---|"]
    for name, addr, what in gen_regs.REGS:
        lines.append(f"| {name} | {addr} | 0x{4 * addr:03X} | {what} |")
    return lines


def parameters():
    lines = ["| parameter | default | range | effect | what it sets | no effect without |",
             "|---|---|---|---|---|---|"]
    for name, default, lo, hi, effect, meaning in gen_params.PARAMS:
        rng = "0, 1 (a switch)" if gen_params.is_switch(lo, hi) else f"{lo} .. {hi}"
        lines.append(f"| {name} | {default} | {rng} | {effect} | {meaning} | {gen_params.ONLY.get(name, '')} |")
    lines += ["", "Derived (parameters of the header, for the ports; set by nobody, checked at elaboration):", "",
              "| name | formula | what it is |", "|---|---|---|"]
    for name, expr, meaning in gen_params.DERIVED:
        lines.append(f"| {name} | `{expr}` | {meaning} |")
    lines += ["", "Combinations refused at elaboration (and by `strand hwgen`):", ""]
    for label, cond, why in gen_params.CHECKS:
        lines.append(f"- `{cond}`: {why}")
    return lines


def timing(order=None, scene=DEFAULT_SCENE):
    strand = os.path.join(ROOT, BUILD, "strand")
    extra = ["--order", order] if order else []
    p = subprocess.run([strand, "info", scene] + extra, cwd=ROOT, capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"doc_tables.py: strand info failed: {p.stderr.strip()} (make model first)")
    text = p.stdout.split("cycles (model/timing.c):\n", 1)[1]
    what = f"the {scene.split('/')[-1]} build" + (", pipelined" if order == "redblack" else "")
    return [f"`strand info {scene}{' --order ' + order if order else ''}` ({what}), from model/timing.c:", "",
            "```"] + text.rstrip("\n").splitlines() + ["```"]


MAKERS = {"registers": registers, "parameters": parameters, "timing": timing,
          "timing_pipelined": lambda: timing("redblack"),
          "timing_graph": lambda: timing("redblack", "sim/scenes/ref001_video3.scene")}
REGION = re.compile(r"(<!-- BEGIN generated: (\w+) -->\n)(.*?)(<!-- END generated: \2 -->)", re.S)


def main():
    args = sys.argv[1:]
    check = "--check" in args
    files = [a for a in args if a != "--check"]
    stale = 0
    for path in files:
        text = open(path).read()

        def fill(m):
            name = m.group(2)
            if name not in MAKERS:
                raise SystemExit(f"{path}: unknown generated region '{name}'")
            return m.group(1) + "\n".join(MAKERS[name]()) + "\n" + m.group(4)

        new = REGION.sub(fill, text)
        if new == text:
            continue
        if check:
            print(f"FAIL doc-tables: {path} is out of date with its sources (make docs-tables)")
            stale += 1
        else:
            with open(path + ".tmp", "w") as f:
                f.write(new)
            os.replace(path + ".tmp", path)
            print(f"doc_tables: rewrote the generated regions of {path}")
    if check and not stale:
        print(f"PASS doc-tables: the generated regions of {', '.join(files)} match their sources")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
