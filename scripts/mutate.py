#!/usr/bin/env python3
"""mutate.py [--mutants N] [--seed S] [--jobs J] [--budget SECONDS] [--only ID,...] [--list] [--doc FILE]

Mutation testing of the RTL: how many small, realistic faults do the fast checks catch?

The mutants are generated from rtl/*.v (and the .vh step functions they include), one
edit each, of four kinds:
  op       an operator swapped: + -, & |, && ||, == !=, < <=, > >=, ^ ~^ (binary)
  const    a constant off by one: a sized literal (4'd5 -> 4'd4 / 4'd6, 1'b1 -> 1'b0)
           or an unsized one in an expression (2 -> 1 / 3)
  enable   an enable dropped: 'if (c)' guarding an assignment becomes 'if (1'b1)'
  invert   a condition inverted: 'if (c)' -> 'if (!(c))', 'c ? a : b' -> '!(c) ? a : b'
in statements and continuous assignments only (never declarations, ranges, indices,
parameters or comments). N of them (--mutants, default 120) are drawn with --seed,
spread over the kinds and files; --list prints every site instead.

Each mutant is a copy of rtl/ in build/mutate/m<ID>/rtl with its one edit (rtl/ itself is
never written) and runs these checks in order, stopping at the first that fails it (a
kill), within --budget seconds (default 300) a mutant:
  compile   iverilog -Wall on strand_core: an error makes the mutant stillborn (not
            counted), a new warning kills it (make lint would fail)
  units     the unit benches of the mutated file (tb/units.mk's configurations: the
            arithmetic units' Icarus benches, toward, toward_pipe, spring_force and
            spring_force_pipe in 2D and 3D), when it has one
  frames    the Icarus frame bench (positions, cycles, FV, FEC, the status of every
            cycle) on every test scene in tb/scenes and tb/scenes/previous, 20 frames, both orders
  lockstep  Verilator lockstep (every output, every cycle, random stimulus and resets)
            on six builds: sim/scenes/ref000_rope.scene (serial chain),
            tb/scenes/graph3d_pin_grab.scene (3D graph), tb/scenes/chain_grab_3d.scene
            in the red/black order (pipelined 3D chain), the two chains of
            tb/scenes/previous/ (projection = previous, pipelined and serial) and
            tb/scenes/chain_springs_q12.scene in the red/black order (the pipelined
            spring pass); the build that uses the mutated file most goes first
A mutant no check fails in its budget survives. A survivor shown to be equivalent to the
RTL (no input sequence can tell them apart) is listed in tb/mutate_equivalent.txt with the
argument, and is not counted; any other survivor fails the run. Results go to
build/mutate/results.json; a table of the score (killed / counted, by check) and of the
survivors to stdout, and with --doc FILE into FILE's generated region 'mutate'
(scripts/doc_region.py). --report writes the table again from results.json; --resume keeps
the results of a stopped run (same seed, same sites) and runs only the mutants it had not
finished (those whose budget ran out included) (the checks must not have changed in between).
"""
import argparse
import concurrent.futures
import glob
import json
import os
import random
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
from strandflow.core import BUILD, ROOT, run as flow_run  # noqa: E402
OUT = os.path.join(ROOT, BUILD, "mutate")

# files whose edits the checks below can see (the AXI4-Lite shell is test-axil's: cocotb, not here)
SKIP_FILES = {"strand_axil.v", "strand_defs.vh", "strand_addr.vh"}
DECL = re.compile(r"^\s*(wire|reg|input|output|inout|localparam|parameter|integer|genvar|function|task|module|"
                  r"`|endmodule|endfunction|endtask|end\b|begin\b|else\s*$|generate|endgenerate|case|endcase|default\s*:\s*$)")
FRAME_SCENES = sorted(glob.glob(os.path.join(ROOT, "tb", "scenes", "*.scene")) + glob.glob(os.path.join(ROOT, "tb", "scenes", "previous", "*.scene")))
LOCKSTEP = [("tb/scenes/graph3d_pin_grab.scene", ""), ("tb/scenes/chain_grab_3d.scene", "redblack"),
            ("sim/scenes/ref000_rope.scene", ""),
            # projection = previous, pipelined and serial; the pipelined spring pass
            ("tb/scenes/previous/chain_pair_q16.scene", "redblack"), ("tb/scenes/previous/rope_centred.scene", ""),
            ("tb/scenes/chain_springs_q12.scene", "redblack")]
# the build that uses a file most goes first (the budget may not reach the last)
LOCKSTEP_FIRST = {"chain_stream.v": 1, "toward_pipe.v": 1, "fx_mul_pipe.v": 1, "fx_sqrt_pipe.v": 1, "fx_div_pipe.v": 1,
                  "delay_line.v": 1, "chain_sequencer.v": 2, "toward.v": 2, "toward_prev_pipe.v": 3, "toward_prev.v": 4,
                  "spring_stream.v": 5, "spring_force_pipe.v": 5}
CHECKS = ["compile", "units", "frames", "lockstep"]
EQUIV_FILE = os.path.join(ROOT, "tb", "mutate_equivalent.txt")


def equivalents():
    """tb/mutate_equivalent.txt: 'FILE:LINE:COL OLD -> NEW  # why it is equivalent' per mutant."""
    out = {}
    if not os.path.exists(EQUIV_FILE):
        return out
    for n, line in enumerate(open(EQUIV_FILE), 1):
        if not line.strip() or line.startswith("#"):
            continue
        m = re.match(r"^(\S+):(\d+):(\d+)\s+(.+?)\s+->\s+(.+?)\s+#\s*(.+)$", line.rstrip("\n"))
        if not m:
            raise SystemExit(f"{EQUIV_FILE}:{n}: expected 'FILE:LINE:COL OLD -> NEW  # why'")
        out[(m.group(1), int(m.group(2)), int(m.group(3)), m.group(4), m.group(5))] = m.group(6)
    return out


def equivalence(r, eq):
    return eq.get((r["file"], r["line"], r["col"], r["old"].strip(), r["new"].strip()))


# ---- the sites ----

def code_spans(line):
    """(start, end) of the parts of a line outside comments, strings and [...] (ranges, indices)."""
    spans, depth, start, i = [], 0, 0, 0
    cut = len(line)
    m = re.search(r"//|/\*", line)
    if m:
        cut = m.start()
    while i < cut:
        c = line[i]
        if c == '"':
            j = line.find('"', i + 1)
            if depth == 0 and i > start:
                spans.append((start, i))
            i = (j if j >= 0 else cut) + 1
            start = i
            continue
        if c == "[":
            if depth == 0 and i > start:
                spans.append((start, i))
            depth += 1
        elif c == "]":
            depth -= 1
            if depth == 0:
                start = i + 1
        i += 1
    if depth == 0 and cut > start:
        spans.append((start, cut))
    return spans


OPS = [  # (regex of the operator in context, replacement)
    (r"(?<=[\w)\] ])\s\+\s(?=[\w({~!'])", " - "), (r"(?<=[\w)\] ])\s-\s(?=[\w({~!'])", " + "),
    (r"&&", "||"), (r"\|\|", "&&"),
    (r"(?<=[\w)\] ])\s&\s(?=[\w({~!])", " | "), (r"(?<=[\w)\] ])\s\|\s(?=[\w({~!])", " & "),
    (r"==", "!="), (r"!=", "=="),
    (r"(?<=[\w)\] ])\s<\s(?=[\w({~!])", " <= "), (r"(?<=[\w)\] ])\s<=\s(?=[\w({~!])(?![^;]*<=)", None),
    (r"(?<=[\w)\] ])\s>\s(?=[\w({~!])", " >= "), (r"(?<=[\w)\] ])\s>=\s(?=[\w({~!])", " > "),
    (r"(?<=[\w)\] ])\s\^\s(?=[\w({~!])", " ~^ "),
]


def statement_line(text):
    """A line that is (part of) a statement or an assign: not a declaration, header or comment."""
    s = text.strip()
    if not s or s.startswith(("//", "/*", "*")) or DECL.match(text):
        return False
    return "assign" in s or "<=" in s or re.search(r"\bif\s*\(", s) or "=" in s or "?" in s


def sites_of(path):
    name = os.path.basename(path)
    lines = open(path).read().split("\n")
    out = []
    in_block_comment = False
    in_decl = False
    for ln, text in enumerate(lines, 1):
        if in_block_comment:
            if "*/" in text:
                in_block_comment = False
            continue
        if text.strip().startswith("/*") and "*/" not in text:
            in_block_comment = True
            continue
        code = text.split("//")[0].rstrip()
        if in_decl:   # the rest of a declaration over several lines (state encodings, ...)
            in_decl = not code.endswith((";", ")")) and not code.endswith("(")
            continue
        if DECL.match(text) and re.match(r"^\s*(localparam|parameter|wire|reg|integer)\b", text) and not code.endswith(";"):
            in_decl = True
            continue
        # loop headers and elaboration-time choices (generate if on parameters) are not mutated
        if not statement_line(text) or re.search(r"\bfor\s*\(|\bbegin\s*:", text):
            continue
        spans = code_spans(text)
        inside = lambda a, b: any(s <= a and b <= e for s, e in spans)
        depth_at = []   # parenthesis depth before each character
        d = 0
        for ch in text:
            depth_at.append(d)
            d += ch == "("
            d -= ch == ")"
        for pat, rep in OPS:
            for m in re.finditer(pat, text):
                if not inside(m.start(), m.end()):
                    continue
                if "<=" in m.group(0):
                    # at depth 0 '<=' is a nonblocking assignment, inside parentheses a comparison
                    if depth_at[m.start()] == 0:
                        continue
                    rep = rep or " < "
                out.append({"file": name, "line": ln, "col": m.start(), "old": m.group(0), "new": rep, "kind": "op"})
        # constants: sized literals and small unsized numbers in expressions
        for m in re.finditer(r"\b(\d+)'([bdh])([0-9a-fA-F]+)\b", text):
            if not inside(m.start(), m.end()):
                continue
            width, base, digits = int(m.group(1)), m.group(2), m.group(3)
            v = int(digits, {"b": 2, "d": 10, "h": 16}[base])
            for nv in ([1 - v] if width == 1 else [v - 1, v + 1]):
                if 0 <= nv < (1 << width):
                    lit = f"{width}'{base}" + (format(nv, "b") if base == "b" else format(nv, "x") if base == "h" else str(nv))
                    out.append({"file": name, "line": ln, "col": m.start(), "old": m.group(0), "new": lit, "kind": "const"})
        for m in re.finditer(r"(?<=[\s(+\-*])(\d+)(?=[\s)+\-*;,])", text):
            if not inside(m.start(), m.end()) or text[max(0, m.start() - 1)] == "'":
                continue
            v = int(m.group(1))
            for nv in (v - 1, v + 1):
                if nv >= 0:
                    out.append({"file": name, "line": ln, "col": m.start(), "old": m.group(0), "new": str(nv), "kind": "const"})
        # if (c): dropped enable, inverted condition
        m = re.search(r"\bif\s*\((.*)\)\s*(begin)?\s*(//.*)?$", text) or re.search(r"\bif\s*\((.*?)\)\s*\w", text)
        if m and inside(m.start(), m.start() + 2):
            cond = m.group(1)
            # the condition's own parentheses must balance; a condition on parameters alone
            # (a generate if: an elaboration-time choice) is left alone
            if cond.count("(") == cond.count(")") and re.search(r"\b[a-z]\w*", re.sub(r"\d+'[bdh]\w+", "", cond)):
                a = text.index("(", m.start())
                out.append({"file": name, "line": ln, "col": a, "old": f"({cond})", "new": "(1'b1)", "kind": "enable"})
                out.append({"file": name, "line": ln, "col": a, "old": f"({cond})", "new": f"(!({cond}))", "kind": "invert"})
        # c ? a : b (a simple condition before '?')
        for m in re.finditer(r"([=(,]\s*)([\w.\[\]:' ]+?|\([^()?]*\))\s*\?", text):
            if not inside(m.start(2), m.end(2)) and not inside(m.end(2) - 1, m.end(2)):
                continue
            cond = m.group(2).strip()
            if not cond or "?" in cond:
                continue
            col = text.index(cond, m.start(2))
            out.append({"file": name, "line": ln, "col": col, "old": cond, "new": f"!({cond})", "kind": "invert"})
    return out


def all_sites():
    files = sorted(glob.glob(os.path.join(ROOT, "rtl", "*.v")) + glob.glob(os.path.join(ROOT, "rtl", "*.vh")))
    sites = []
    for f in files:
        if os.path.basename(f) not in SKIP_FILES:
            sites += sites_of(f)
    for i, s in enumerate(sites):
        s["site"] = i
    return sites


def draw(sites, n, seed):
    """n sites, spread over the kinds (in turn) and, within a kind, over the files (in turn)."""
    rng = random.Random(f"mutate-{seed}")
    pools = {}
    for s in sites:
        pools.setdefault(s["kind"], {}).setdefault(s["file"], []).append(s)
    for k in pools:
        for f in pools[k]:
            rng.shuffle(pools[k][f])
    kinds = sorted(pools)
    chosen, turn = [], 0
    files_turn = {k: 0 for k in kinds}
    while len(chosen) < min(n, len(sites)):
        k = kinds[turn % len(kinds)]
        turn += 1
        files = [f for f in sorted(pools[k]) if pools[k][f]]
        if not files:
            continue
        f = files[files_turn[k] % len(files)]
        files_turn[k] += 1
        chosen.append(pools[k][f].pop())
    return chosen


def apply(site, rtl_out):
    """Copy rtl/ to rtl_out with the one edit of `site`."""
    if os.path.exists(rtl_out):
        shutil.rmtree(rtl_out)
    shutil.copytree(os.path.join(ROOT, "rtl"), rtl_out)
    path = os.path.join(rtl_out, site["file"])
    lines = open(path).read().split("\n")
    text = lines[site["line"] - 1]
    c = site["col"]
    if text[c:c + len(site["old"])] != site["old"]:
        raise SystemExit(f"rtl/{site['file']}:{site['line']}: mutate.py: the site no longer matches ({site['old']!r})")
    lines[site["line"] - 1] = text[:c] + site["new"] + text[c + len(site["old"]):]
    with open(path, "w") as fh:
        fh.write("\n".join(lines))


# ---- the checks ----

BUDGET_SPENT = -1000   # run()'s status when the mutant's budget ran out: not a kill


def run(cmd, timeout, cwd=ROOT, env=None):
    try:
        return flow_run(cmd, cwd=cwd, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return BUDGET_SPENT, ""


def units_configs():
    """tb/units.mk's Icarus unit and datapath configurations."""
    mk = open(os.path.join(ROOT, "tb", "units.mk")).read()
    def lst(var):
        m = re.search(var + r" := \\\n((?:.*\\\n)*.*)\n", mk)
        return [w for w in m.group(1).replace("\\", " ").split() if ":" in w]
    return lst("UNITS_ICARUS_TESTS"), lst("UNITS_DP_TESTS")


UNIT_FILES = {"add": ["fx_add.v"], "mul": ["fx_mul.v", "fx_round.v"], "avg": ["fx_avg.v"], "sqrt": ["fx_sqrt.v"],
              "div": ["fx_div.v"], "mul_pipe": ["fx_mul_pipe.v", "fx_round.v"], "sqrt_pipe": ["fx_sqrt_pipe.v"],
              "div_pipe": ["fx_div_pipe.v"]}
# each datapath's file, then what it instantiates (tb/units.mk's UNITS_DP_DEPS_<module>: with
# MANTISSA > 0 the serial datapaths run their pipes, and the pipes fx_along_pipe)
DP_PIPE_DEPS = ["fx_sqrt_pipe.v", "fx_div_pipe.v", "fx_mul_pipe.v", "delay_line.v", "strand_ram.v", "fx_along_pipe.v",
                "fx_shr.v"]
DP_FILES = {"toward": ["toward.v", "toward_pipe.v"] + DP_PIPE_DEPS,
            "spring_force": ["spring_force.v", "spring_force_pipe.v"] + DP_PIPE_DEPS,
            "toward_pipe": ["toward_pipe.v"] + DP_PIPE_DEPS,
            "spring_force_pipe": ["spring_force_pipe.v"] + DP_PIPE_DEPS}
DP_COMMON = ["fx_add.v", "fx_mul.v", "fx_round.v", "fx_sqrt.v", "fx_div.v"]
SERIAL_BENCHES = ("tb_fx_sqrt.v", "tb_fx_div.v", "tb_toward.v", "tb_spring_force.v")
LATENCY_UNITS = ("sqrt", "div", "mul_pipe", "sqrt_pipe", "div_pipe")   # tb/units.mk's UNITS_LATENCY_UNITS


def unit_param(unit, w, f, bits, extra):
    """The bench's parameters, from tb/units.mk's UNITS_PARAMS_<unit> ($(1) W, $(2) F, $(3) BITS,
    $(or $(4),DEFAULT) the configuration's optional seventh field), as make test-units gives them."""
    mk = open(os.path.join(ROOT, "tb", "units.mk")).read()
    m = re.search(r"^UNITS_PARAMS_" + unit + r"\s*=\s*(.*)$", mk, re.M)
    if not m:
        raise SystemExit(f"tb/units.mk: no UNITS_PARAMS_{unit} for unit '{unit}'")
    text = re.sub(r"\$\(or \$\(4\),([^)]*)\)", lambda d: extra or d.group(1), m.group(1))
    for i, v in enumerate((w, f, bits), 1):
        text = text.replace(f"$({i})", v)
    return text.split()


def check_units(site, rtl, work, deadline):
    """The unit benches whose design reads the mutated file; (killed?, detail) or None if none applies."""
    icarus, dp = units_configs()
    f = site["file"]
    ran = 0
    for cfg in icarus + dp:
        parts = cfg.split(":")
        # a unit: name:unit:mode:W:F:BITS[:extra]; a datapath: name:module:W:F:SQRT_BITS:DIV_BITS:DIM[:STEPS]
        datapath = False
        if len(parts) in (6, 7) and parts[1] in UNIT_FILES:
            name, unit, _, w, fr, bits = parts[:6]
            files = UNIT_FILES[unit]
            if f not in files and not (f.endswith(".vh") and unit.replace("_pipe", "") in f):
                continue
            tb = f"tb/tb_fx_{unit}.v"
            params = unit_param(unit, w, fr, bits, parts[6] if len(parts) == 7 else "")
        elif len(parts) in (7, 8, 9) and parts[1] in DP_FILES:
            datapath = True
            name, mod, w, fr, sb, db, dim = parts[:7]
            files = DP_FILES[mod] + DP_COMMON
            if f not in files and not f.endswith(".vh"):
                continue
            tb = f"tb/tb_{mod}.v"
            params = [f"-Ptb_{mod}.{k}={v}" for k, v in (("W", w), ("F", fr), ("SQRT_BITS", sb), ("DIV_BITS", db), ("DIM", dim))]
            if len(parts) >= 8 and parts[7] and mod.endswith("_pipe"):
                params.append(f"-Ptb_{mod}.STEPS={parts[7]}")
            if len(parts) == 9 and parts[8]:
                params.append(f"-Ptb_{mod}.MANTISSA={parts[8]}")
        else:
            raise SystemExit(f"tb/units.mk: configuration '{cfg}' is neither a unit nor a datapath mutate.py knows")
        vec = os.path.join(ROOT, BUILD, "units", name, "vectors.hex")
        if not os.path.exists(vec):
            continue
        ran += 1
        vvp = os.path.join(work, f"{name}.vvp")
        srcs = [os.path.join(rtl, x) for x in files + (DP_COMMON if datapath else []) if os.path.exists(os.path.join(rtl, x))]
        # the serial units' benches instantiate the latency contract's checker
        checker = [os.path.join(ROOT, "tb", "serial_latency_check.v")] if tb.endswith(SERIAL_BENCHES) else []
        rc, out = run(["iverilog", "-g2005", "-I", rtl, "-I", os.path.join(ROOT, "tb"), "-o", vvp] + params + [tb]
                      + sorted(set(srcs)) + checker, max(1, deadline - time.time()))
        if rc == BUDGET_SPENT:
            return None
        if rc != 0:
            return True, f"{name}: does not compile"
        args = ["vvp", "-n", vvp, f"+vectors={vec}", f"+n={open(vec + '.n').read().strip()}", f"+name={name}"]
        if os.path.exists(vec + ".latency"):
            args.append(f"+latency={open(vec + '.latency').read().strip()}")
        elif not datapath and unit in LATENCY_UNITS:   # as tb/units.mk's UNITS_LATENCY_ARG
            steps = parts[6] if len(parts) == 7 and unit in ("sqrt_pipe", "div_pipe") else "1"
            rc, lat = run([os.path.join(ROOT, BUILD, "units", "unit_latency"), unit, w, bits, bits, "2", steps, "0", "0"], 30)
            if rc != 0:
                raise SystemExit(f"mutate: build/units/unit_latency failed ({lat.strip()}); run make test-units first")
            args.append(f"+latency={lat.strip()}")
        rc, out = run(args, max(1, deadline - time.time()))
        if rc == BUDGET_SPENT:
            return None
        if rc != 0 or "PASS" not in out:
            line = next((l for l in out.splitlines() if l.startswith("FAIL")), f"exit {rc}")
            return True, line[:200]
        if time.time() > deadline:
            return None
    return (False, f"{ran} benches pass") if ran else None


def check_frames(site, rtl, work, deadline):
    env = dict(os.environ, HW_DIR=os.path.join(work, "hw"))
    n = 0
    for scene in FRAME_SCENES:
        for order in ("serial", "redblack"):
            rc, out = run(["scripts/top_frames.sh", os.path.relpath(scene, ROOT), "20", order, rtl],
                          max(1, deadline - time.time()), env=env)
            n += 1
            if rc == BUDGET_SPENT:
                return None
            if rc != 0:
                line = next((l for l in out.splitlines() if l.startswith("FAIL")), f"exit {rc}")
                return True, line[:200]
            if time.time() > deadline:
                return None
    return False, f"{n} runs pass"


def check_lockstep(site, rtl, work, deadline):
    first = LOCKSTEP_FIRST.get(site["file"], 0)
    env = dict(os.environ, HARNESS_OPT="fast")   # a few frames: the C++ compiled without optimisation
    for scene, order in [LOCKSTEP[first]] + LOCKSTEP[:first] + LOCKSTEP[first + 1:]:
        hdir = os.path.join(work, "vl", os.path.basename(scene).replace(".scene", "") + (f"_{order}" if order else ""))
        rc, out = run(["scripts/build_harness.sh", scene, hdir, rtl] + ([order] if order else []), max(1, deadline - time.time()),
                      env=env)
        if rc == BUDGET_SPENT or time.time() > deadline:
            return None
        if rc != 0:   # iverilog took it, Verilator refuses it: make lint would fail too
            return True, f"Verilator refuses it ({scene}'s build): make lint would fail", "compile"
        for seed, extra in ((1, []), (2, ["--resets", "2"])):
            rc, out = run([os.path.join(hdir, "harness"), os.path.join(ROOT, scene), "--quiet", "--frames", "40", "--seed",
                           str(seed)] + extra + (["--order", order] if order else []), max(1, deadline - time.time()), cwd=work)
            if rc == BUDGET_SPENT:
                return None
            if rc == 2:   # the harness's usage or input error: no mutant does that
                raise SystemExit(f"mutate.py: the harness refused its arguments: {out.strip()[:300]}")
            if rc != 0:
                line = next((l for l in out.splitlines() if l.startswith(("MISMATCH", "FAIL"))), f"exit {rc}")
                return True, f"{os.path.basename(scene)}{' ' + order if order else ''}: {line[:160]}"
    return False, f"{len(LOCKSTEP)} builds agree"


def compile_check(rtl):
    """0 clean, 1 new warnings, 2 does not compile."""
    srcs = sorted(glob.glob(os.path.join(rtl, "*.v")))
    rc, out = run(["iverilog", "-Wall", "-g2005", "-I", os.path.join(ROOT, BUILD, "gen"), "-I", rtl, "-o", os.devnull] + srcs, 120)
    if rc != 0:
        return 2, out.strip().splitlines()[0][:200] if out.strip() else "error"
    return (1, out.strip().splitlines()[0][:200]) if out.strip() else (0, "")


def one(site, budget):
    mid = f"m{site['site']:04d}"
    work = os.path.join(OUT, mid)
    os.makedirs(work, exist_ok=True)
    rtl = os.path.join(work, "rtl")
    apply(site, rtl)
    t0 = time.time()
    deadline = t0 + budget
    res = dict(site, id=mid, status="survived", by="", detail="", ran=[], unfinished=False)
    c, why = compile_check(rtl)
    if c == 2:
        res.update(status="stillborn", detail=why)
    elif c == 1:
        res.update(status="killed", by="compile", detail=why)
    else:
        for name, fn in (("units", check_units), ("frames", check_frames), ("lockstep", check_lockstep)):
            r = fn(site, rtl, work, deadline)
            if r is None:
                if time.time() > deadline:
                    res.update(detail=f"budget of {budget} s spent in {name}", unfinished=True)
                    break
                continue
            res["ran"].append(name)
            killed, detail = r[:2]
            if killed:
                res.update(status="killed", by=r[2] if len(r) > 2 else name, detail=detail)
                break
            res["detail"] = detail
    res["seconds"] = round(time.time() - t0, 1)
    if res["status"] != "survived":  # keep the survivors' copies to look at
        shutil.rmtree(work, ignore_errors=True)
    return res


# ---- the report ----

def table(results, args):
    eq = equivalents()
    equiv = [r for r in results if r["status"] == "survived" and equivalence(r, eq)]
    counted = [r for r in results if r["status"] != "stillborn" and r not in equiv]
    killed = [r for r in counted if r["status"] == "killed"]
    lines = [f"{len(results)} mutants of rtl/ (seed {args.seed}; `make mutate MUTANTS={args.mutants}`): "
             f"{len(results) - len(counted) - len(equiv)} stillborn (do not compile) and {len(equiv)} equivalent, not counted.", "",
             f"**Score: {len(killed)} of {len(counted)} killed"
             + (f" ({100 * len(killed) / len(counted):.1f} %)**" if counted else "**"), "",
             "| kind | mutants | killed | by compile | by units | by frames | by lockstep | survived |", "|---|---|---|---|---|---|---|---|"]
    for kind in ["op", "const", "enable", "invert", "all"]:
        rs = [r for r in counted if kind == "all" or r["kind"] == kind]
        by = lambda c: sum(1 for r in rs if r["status"] == "killed" and r["by"] == c)
        k = sum(1 for r in rs if r["status"] == "killed")
        lines.append(f"| {kind} | {len(rs)} | {k} | {by('compile')} | {by('units')} | {by('frames')} | {by('lockstep')} | {len(rs) - k} |")
    surv = [r for r in counted if r["status"] == "survived"]
    if equiv:
        lines += ["", f"Equivalent survivors ({len(equiv)}; the arguments are in tb/mutate_equivalent.txt):", "",
                  "| mutant | site | edit | why no check can kill it |", "|---|---|---|---|"]
        for r in sorted(equiv, key=lambda r: (r["file"], r["line"])):
            lines.append(f"| {r['id']} | rtl/{r['file']}:{r['line']} | `{r['old'].strip()}` -> `{r['new'].strip()}` | "
                         f"{equivalence(r, eq)} |")
    unfinished = sum(1 for r in surv if r.get("unfinished"))
    lines += ["", (f"Survivors ({len(surv)}; {unfinished} of them only because the budget ran out before every check ran):"
                   if unfinished else f"Survivors ({len(surv)}):") if surv else "No survivors."]
    if surv:
        lines += ["", "| mutant | site | edit | note |", "|---|---|---|---|"]
        for r in sorted(surv, key=lambda r: (r["file"], r["line"])):
            lines.append(f"| {r['id']} | rtl/{r['file']}:{r['line']} | `{r['old'].strip()}` -> `{r['new'].strip()}` | "
                         f"{r['detail']} |")
    secs = sum(r["seconds"] for r in results)
    lines += ["", f"Time in the checks: {secs / 60:.0f} min summed over the mutants, {args.jobs} at a time "
              f"(budget {args.budget} s a mutant)" + (f"; the run took {args.wall / 60:.0f} min." if getattr(args, "wall", 0) else ".")]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mutants", type=int, default=120)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--budget", type=int, default=300, help="seconds of checks a mutant")
    ap.add_argument("--only", help="run these mutants (site numbers, m0042 or 42, comma-separated)")
    ap.add_argument("--list", action="store_true", help="print every site and exit")
    ap.add_argument("--doc", help="write the table into this file's region 'mutate'")
    ap.add_argument("--report", action="store_true", help="write the table from build/mutate/results.json, run nothing")
    ap.add_argument("--resume", action="store_true", help="keep a stopped run's results and run the other mutants")
    a = ap.parse_args()
    a.wall = 0
    sites = all_sites()
    if a.list:
        for s in sites:
            print(f"m{s['site']:04d} {s['kind']:6} rtl/{s['file']}:{s['line']}: {s['old'].strip()!r} -> {s['new'].strip()!r}")
        print(f"{len(sites)} sites")
        return 0
    done_path = os.path.join(OUT, "results.json")
    if a.report:
        saved = json.load(open(done_path))
        if isinstance(saved, list):   # the results alone: the run's settings are the arguments'
            saved = {"mutants": len(saved), "seed": a.seed, "jobs": a.jobs, "budget": a.budget, "results": saved}
        results, a.mutants, a.seed, a.jobs, a.budget, a.wall = (saved["results"], saved["mutants"], saved["seed"],
                                                                saved["jobs"], saved["budget"], saved.get("wall", 0))
    else:
        if a.only:
            ids = {int(x.strip().lstrip("m")) for x in a.only.split(",")}
            chosen = [s for s in sites if s["site"] in ids]
        else:
            chosen = draw(sites, a.mutants, a.seed)
        os.makedirs(OUT, exist_ok=True)
        key = lambda r: (r["file"], r["line"], r["col"], r["old"], r["new"])
        results, wall0 = [], 0
        if a.resume and os.path.exists(done_path):
            saved = json.load(open(done_path))
            if isinstance(saved, dict) and saved.get("seed") == a.seed:
                want = {key(s) for s in chosen}
                # a mutant whose budget ran out before every check ran is run again (with this run's budget)
                results = [r for r in saved["results"] if key(r) in want and not r.get("unfinished")]
                wall0 = saved.get("wall", 0)
        have = {key(r) for r in results}
        todo = [s for s in chosen if key(s) not in have]
        print(f"mutate: {len(chosen)} of {len(sites)} sites, {a.jobs} jobs, {a.budget} s a mutant"
              + (f"; {len(results)} kept from the stopped run" if results else ""), flush=True)
        t0 = time.time() - wall0
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
            for i, r in enumerate(ex.map(lambda s: one(s, a.budget), todo), len(results)):
                results.append(r)
                what = {"killed": f"killed by {r['by']}", "survived": "SURVIVED", "stillborn": "stillborn"}[r["status"]]
                print(f"[{i + 1}/{len(chosen)}] {r['id']} {r['kind']:6} rtl/{r['file']}:{r['line']}:{r['col']} "
                      f"{r['old'].strip()!r} -> {r['new'].strip()!r}: {what} ({r['seconds']} s) {r['detail']}", flush=True)
                a.wall = time.time() - t0
                if not a.only:
                    with open(done_path, "w") as fh:
                        json.dump({"mutants": a.mutants, "seed": a.seed, "jobs": a.jobs, "budget": a.budget, "wall": a.wall,
                                   "results": results}, fh, indent=1)
    text = table(results, a)
    print(text)
    with open(os.path.join(OUT, "table.md"), "w") as fh:
        fh.write(text)
    if a.doc and not a.only and len(results) == a.mutants:
        p = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "doc_region.py"), a.doc, "mutate"], input=text,
                           text=True, cwd=ROOT)
        if p.returncode:
            return p.returncode
    eq = equivalents()
    counted = [r for r in results if r["status"] != "stillborn" and not (r["status"] == "survived" and equivalence(r, eq))]
    surv = [r for r in counted if r["status"] == "survived"]
    print(f"{'PASS' if not surv else 'FAIL'} mutate: {len(counted) - len(surv)} of {len(counted)} mutants killed"
          + (f", {len(surv)} survived (neither killed nor in tb/mutate_equivalent.txt): {', '.join(r['id'] for r in surv)}"
             if surv else ""))
    return 1 if surv else 0


if __name__ == "__main__":
    sys.exit(main())
