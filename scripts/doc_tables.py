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
    make_targets      the make targets a user sees (README.md): scripts/make_targets.tsv's user rows
    make_targets_dev  the developer targets (docs/architecture.md): its dev rows
    effects_keys      the effects table's scene sections and keys (sim/scenes/README.md):
                      scripts/gen_effects.py's EFFECTS
    effects_files     the files an effect of that table is written in (docs/architecture.md)

and checks that every numeric [VAR=N] a target's arguments show is VAR's default (VAR ?= N) in
the Makefile or the files it includes (a FAIL line names each that is not).

With --check nothing is written: the exit status is 1 and a FAIL line names each file
whose regions are not what they would be (make test runs this).
"""
import glob
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import gen_effects  # noqa: E402
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


def effects_keys():
    lines = []
    for e in gen_effects.EFFECTS:
        head = f"### `[{e['name']}]`" if gen_effects.own(e) else f"### {e['title']}: in `[{gen_effects.sec(e)}]`"
        lines += [head, f"{e['title'][0].upper()}{e['title'][1:]} ({e['param']}): {e['meaning']}."
                  + (" Verlet only." if e.get("verlet") else "")
                  + ("" if e["cpu"] else " `cpu_rope` refuses it.") + ("" if e["cpu_fast"] else " `cpu_fast` refuses it."), "",
                  "| key | value | range | default |", "|---|---|---|---|"]
        for k in e["keys"]:
            vec = "a vector (2 or 3 numbers, as `dim`): " if k["kind"] == "vec" else ""
            lines.append(f"| `{k['key']}` | {vec}{k['what']} | {k['lo']:g} .. {k['hi']:g} | {'(required)' if k['required'] else '0'} |")
        if not gen_effects.own(e):
            lines += ["", f"On when `{e['on'].replace('sc->', '')}`."]
        lines += ["", "The hardware's constants (each a register; `strand check` warns, at the key's line, when one "
                  "rounds away):", ""]
        for c in e["consts"]:
            rng = f"; the scene is refused outside {c['lo']:g} .. {c['hi']:g}" if c["lo"] is not None else ""
            lines.append(f"- `{c['symbol']}` = `{c['expr']}` (register {c['reg']}{'_X, _Y, _Z' if c.get('vector') else ''}{rng})")
        lines.append("")
    return lines[:-1]


def effects_files():
    return [f"- `{f}`: {why}" for f, why in gen_effects.HAND_WRITTEN]


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


TARGETS = os.path.join(ROOT, "scripts", "make_targets.tsv")


def target_rows():
    """(target, arguments, audience, help line, README text) of scripts/make_targets.tsv."""
    rows = []
    for n, line in enumerate(open(TARGETS, encoding="utf-8"), 1):
        if line.startswith("#") or not line.strip():
            continue
        f = line.rstrip("\n").split("\t")
        if len(f) != 5 or f[2] not in ("user", "dev"):
            raise SystemExit(f"{TARGETS}:{n}: want target, arguments, user or dev, help line, README text (tab-separated)")
        rows.append(f)
    return rows


def make_targets(audience):
    lines = ["| target | what it does |", "|---|---|"]
    for name, args, aud, _, text in target_rows():
        if aud == audience:
            lines.append(f"| `make {name}{' ' + args if args else ''}` | {text} |")
    return lines


def stale_target_defaults():
    """The [VAR=N] of the targets' arguments that are not the Makefile's VAR ?= N."""
    defaults = {}
    for mk in ["Makefile"] + sorted(glob.glob(os.path.join(ROOT, "tb", "*.mk")) + glob.glob(os.path.join(ROOT, "scripts", "*.mk"))):
        for m in re.finditer(r"^(\w+) \?= (\S+)\s*$", open(os.path.join(ROOT, mk)).read(), re.M):
            defaults.setdefault(m.group(1), m.group(2))
    bad = []
    for name, args, *_ in target_rows():
        for var, val in re.findall(r"\[(\w+)=(\d+)\]", args):
            if var in defaults and re.fullmatch(r"\d+", defaults[var]) and defaults[var] != val:
                bad.append(f"make {name}: [{var}={val}], but the Makefile's default is {var} ?= {defaults[var]}")
    return bad


MAKERS = {"make_targets": lambda: make_targets("user"), "make_targets_dev": lambda: make_targets("dev"),
          "registers": registers, "parameters": parameters, "timing": timing,
          "effects_keys": effects_keys, "effects_files": effects_files,
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
    for why in stale_target_defaults():
        print(f"FAIL doc-tables: scripts/make_targets.tsv: {why}")
        stale += 1
    if check and not stale:
        print(f"PASS doc-tables: the generated regions of {', '.join(files)} match their sources")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
