#!/usr/bin/env python3
"""gen_params.py OUTDIR - the build parameters of strand_core: the one table, every side generated.

PARAMS below is the only hand-written list of the core's parameters. From it this
script writes, into OUTDIR (build/gen):

  strand_params.vh        the parameter declarations of strand_core (and of every module
                          that takes the whole set): `#( `include "strand_params.vh" )`
  strand_params_scene.vh  the same declarations with the defaults of one scene's build
                          (`STRAND_<NAME> from the params.vh that `strand hwgen` writes),
                          for the simulation wrappers in tb/
  strand_params_scene_local.vh  the same build as localparams, for testbenches
  strand_params_pass.vh   `.W(W), .F(F), ...`: pass the whole set on to an instance
  strand_params_check.vh  the legal ranges and combinations as elaboration errors
                          ($error for Yosys, $fatal for the simulators)
  strand_params.h         the same table for C: an X-macro of every parameter, the
                          derived widths and the checks as a function
  strand_params.json      the same table for scripts

Expressions (defaults, ranges, derived widths, checks) are written once in a small
language both sides read: integers, parameter names, + - * / % ( ), comparisons,
&& || !, ?:, and the functions clog2(x) (bits to index x values, at least 1 here:
clog2_1) and max(a, b).
"""
import json
import os
import re
import sys

sys.dont_write_bytecode = True  # no scripts/__pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_effects  # noqa: E402  (the effects table: its enable parameters)

# ---- the table ----
#
# name      the Verilog parameter (C field: its lower-case name); a switch (0 or 1,
#           declared [0:0]) when its range is 0 .. 1
# default   an expression of earlier parameters
# lo, hi    the legal range (expressions; inclusive)
# effect    what it belongs to (docs/effects.md, docs/architecture.md)
# meaning   what it sets
#
# ONLY below names the switch without which a parameter has no effect: an instance
# below strand_core receives its default then (strand_params_pass.vh), so that a
# build's modules do not depend on a parameter its effects never read (synthesis
# names a module by its parameters, and the effects gating check compares builds).
PARAMS = [
    # name            default   lo  hi      effect         meaning
    ("W",              "32",     "8", "32",   "format",      "word width, bits: signed two's complement Q(W-F).F"),
    ("F",              "16",     "1", "W - 2", "format",     "fraction bits"),
    ("M",              "4",      "1", "256",  "body",        "node units (a graph: 1)"),
    ("K",              "5",      "1", "4096", "body",        "nodes per unit (a graph: every node)"),
    ("SQRT_BITS",      "W - 1",  "1", "W - 1", "accuracy",   "square-root bits resolved, one per cycle"),
    ("DIV_BITS",       "W - 1",  "1", "W - 1", "accuracy",   "quotient bits resolved, one per cycle"),
    ("MANTISSA",       "0",      "0", "20",   "accuracy",   "0: the full-width root and divide; 6 .. 20: the normalised distance datapath, a constraint's correction and a spring's length and direction computed on MANTISSA-bit mantissas that share one exponent (MANTISSA + 1-bit words: 17 makes every product of the ratio one 18 x 18 multiplier)"),
    ("PIPE_STEPS",     "2",      "1", "4",    "constraints", "ARCH = 1: root and divide iterations a pipeline stage in the distance and spring pipes (fx_sqrt_pipe, fx_div_pipe): fewer stages, so a shorter latency and fewer registers, for a longer path a stage"),
    ("ITER",           "1",      "1", "1024", "time",        "constraint passes per substep"),
    ("SUBSTEPS",       "1",      "1", "1024", "time",        "substeps per frame"),
    ("EN_MOUSE",       "1",      "0", "1",    "mouse",       "the mouse: the reference-000 impulse, or with GRAB the grab form"),
    ("GRAB",           "0",      "0", "1",    "mouse",       "with EN_MOUSE: the nearest node in the box follows the pointer"),
    ("EN_CONSTRAINTS", "1",      "0", "1",    "constraints", "distance constraints (rods, struts, chain links)"),
    ("RULE",           "0",      "0", "1",    "constraints", "their rule: 0 centred (reference 000), 1 pairwise (references 001, 002)"),
    ("ARCH",           "0",      "0", "1",    "constraints", "the constraint and spring passes: 0 serial (one toward / spring_force datapath, node by node or link by link, the order of reference 000), 1 pipelined (every unit streams its nodes through its own toward_pipe in red/black order, and its links through its own spring_force_pipe: one constraint or spring a clock; a graph streams its rod memory through one toward_pipe, colour by colour, an edge every two clocks, and keeps the serial spring pass)"),
    ("PROJECTION",     "0",      "0", "1",    "constraints", "the direction of each correction: 0 the current one (references 000-002), 1 the constraint's direction at the substep's start (projection = previous, SHAKE: toward_prev, or toward_prev_pipe in the pipelined pass)"),
    ("EN_SPRINGS",     "0",      "0", "1",    "springs",     "damped springs (references 001, 004): a spring pass before each Verlet pass"),
    ("EN_GROUND",      "0",      "0", "1",    "ground",      "ground collision with friction (reference 001)"),
    ("GROUND_AXIS",    "1",      "0", "DIM - 1", "ground",   "the ground's normal axis: 0 x, 1 y, 2 z"),
    ("GROUND_ABOVE",   "1",      "0", "1",    "ground",      "1: nodes stay at or above the boundary, 0: at or below"),
    ("DIM",            "2",      "2", "3",    "3D",          "2, or 3: a z lane in every unit, datapath and sequencer"),
    ("GRAPH",          "0",      "0", "1",    "graph",       "0: a chain (implied links), 1: a graph (edge memories)"),
    ("E_RODS",         "1",      "1", "65536", "graph",      "GRAPH: entries of the rod (constraint) edge memory"),
    ("E_SPRINGS",      "1",      "1", "65536", "graph",      "GRAPH: entries of the spring edge memory"),
    ("COLOURS",        "1",      "1", "64",   "graph",       "GRAPH with ARCH = 1: the colours of the rod memory's edges (the pipelined pass drains its pipeline after each; the cycle formula counts them, the hardware reads the colour ends from the EDGE words)"),
    ("DEBUG",          "0",      "0", "1",    "observability", "1: the dbg port carries phase, FV, FEC, the walk and the write-back lanes (simulation); 0: dbg is one constant bit"),
    ("RAM_BLOCK_MIN",  "64",     "1", "1048576", "storage",  "a node or edge memory of at least this many entries asks for block RAM; smaller ones for LUT RAM or flip-flops"),
]

# the effects table's switches (scripts/gen_effects.py): each after the parameter its row names,
# or after the ground's
for _row, _after in gen_effects.params():
    _at = [r[0] for r in PARAMS].index(_after or "GROUND_ABOVE") + 1
    PARAMS[_at:_at] = [_row]

ONLY = {
    "SQRT_BITS": "EN_CONSTRAINTS || EN_SPRINGS",
    "DIV_BITS": "EN_CONSTRAINTS || EN_SPRINGS",
    "MANTISSA": "EN_CONSTRAINTS || EN_SPRINGS",
    "PIPE_STEPS": "ARCH",
    "ITER": "EN_CONSTRAINTS",
    "GRAB": "EN_MOUSE",
    "RULE": "EN_CONSTRAINTS",
    "ARCH": "EN_CONSTRAINTS || (EN_SPRINGS && !GRAPH)",
    "PROJECTION": "EN_CONSTRAINTS",
    "GROUND_AXIS": "EN_GROUND",
    "GROUND_ABOVE": "EN_GROUND",
    "E_RODS": "GRAPH && EN_CONSTRAINTS",
    "E_SPRINGS": "GRAPH && EN_SPRINGS",
    "COLOURS": "GRAPH && EN_CONSTRAINTS && ARCH",
}

# Derived widths: parameters of the header too (ports need them) that nobody sets;
# strand_params_check.vh stops elaboration when one is overridden with another value.
DERIVED = [
    ("UW", "clog2_1(M)", "unit index bits"),
    ("IW", "clog2_1(K)", "node index bits within a unit"),
    ("AW", "UW + IW", "a node address {unit, node}"),
    ("CW", "clog2(max(M * K, max(GRAPH && EN_CONSTRAINTS ? E_RODS : 1, GRAPH && EN_SPRINGS ? E_SPRINGS : 1)) + 1)",
     "the walk's counter: nodes or edges of a pass"),
    ("SW", "clog2_1(SUBSTEPS)", "substep counter bits"),
    ("PAIR", "ARCH && !GRAPH && EN_CONSTRAINTS ? 1 : 0",
     "a chain's pipelined constraint pass: every unit reads a pair of neighbouring nodes and writes up to two a clock, so its node memories are two banks (even and odd nodes)"),
    ("FUSE", "PAIR == 1 && RULE == 0 ? 1 : 0",
     "a chain's pipelined centred pass takes the Verlet step into its first sweep: the units step each pair of nodes as the sweep reads it and hand the new positions to the sweep, so a substep has no Verlet pass of its own"),
    ("WB", "M * (1 + PAIR)", "the write-back lanes of the dbg port: one a unit, two with PAIR (one a write port)"),
    ("DBG_W", "DEBUG ? 3 + 2 + UW + IW + CW + WB * (1 + IW + 3 * W) : 1",
     "the dbg port: {wb_z, wb_y, wb_x, wb_idx, wb_valid, counter, nidx, uidx, fec, fv, phase} per write-back lane, or 1"),
    ("AXIL_NB", "max(12, AW + 4)", "strand_axil: the address bit of its node window (16 bytes a node)"),
    ("AXIL_AW", "AXIL_NB + 1", "strand_axil: its address bits"),
]

# Combinations that are not built (each: a condition that must hold, and why).
CHECKS = [
    ("graph_needs_the_pairwise_rule", "!GRAPH || !EN_CONSTRAINTS || RULE == 1",
     "a graph's rods and struts use the pairwise rule (RULE = 1)"),
    ("pipelined_graph_needs_constraints", "!ARCH || !GRAPH || EN_CONSTRAINTS",
     "a graph's pipelined pass (ARCH = 1) streams its rods; a graph of springs alone has the serial spring pass only"),
    ("colours_within_the_rods", "!GRAPH || !ARCH || COLOURS <= E_RODS",
     "a graph's rod memory of E_RODS edges has at most E_RODS colours"),
    ("graph_edge_word_wider_than_W", "!GRAPH || 2 * AW + 1 <= W", "a graph's EDGE word {spring, b, a} must fit W bits"),
    ("graph_colour_bit_wider_than_W", "!GRAPH || !ARCH || 2 * AW + 2 <= W",
     "a pipelined graph's EDGE word {colour end, spring, b, a} must fit W bits"),
    ("mantissa_is_0_or_6_to_20", "MANTISSA == 0 || MANTISSA >= 6",
     "MANTISSA is 0 (the full-width datapath) or 6 .. 20 bits"),
    ("node_address_wider_than_W", "AW <= W", "a node address {unit, node} must fit W bits (PIN, NODE writes)"),
]

# ---- the expression language ----

TOKEN = re.compile(r"\s*(?:(\d+)|([A-Za-z_][A-Za-z0-9_]*)|(&&|\|\||==|!=|<=|>=|[-+*/%()<>!?:,]))")


def tokens(expr):
    pos, out = 0, []
    expr = expr.strip()
    while pos < len(expr):
        m = TOKEN.match(expr, pos)
        if not m or m.end() == pos:
            raise SystemExit(f"gen_params.py: cannot read '{expr}' at '{expr[pos:]}'")
        out.append(m.group(1) or m.group(2) or m.group(3))
        pos = m.end()
    return out


def translate(expr, names, lang):
    """expr in Verilog ('v'), C ('c': names as p->name) or Python ('py': names as p['NAME'])."""
    out = []
    toks = tokens(expr)
    for i, t in enumerate(toks):
        if t in names:
            out.append(t if lang == "v" else f"p->{t.lower()}" if lang == "c" else f"p[{t!r}]")
        elif t in ("clog2", "clog2_1", "max"):
            out.append({"v": {"clog2": "$clog2", "clog2_1": "STRAND_CLOG2_1", "max": "STRAND_MAX"},
                        "c": {"clog2": "strand_clog2", "clog2_1": "strand_clog2_1", "max": "strand_max"},
                        "py": {"clog2": "clog2", "clog2_1": "clog2_1", "max": "max"}}[lang][t])
        elif lang == "py" and t in ("&&", "||", "!"):
            out.append({"&&": " and ", "||": " or ", "!": " not "}[t])
        elif lang == "py" and t in ("?", ":"):
            raise SystemExit(f"gen_params.py: ?: is not used from Python ('{expr}')")
        elif re.fullmatch(r"[A-Za-z_]\w*", t):
            raise SystemExit(f"gen_params.py: unknown name '{t}' in '{expr}'")
        else:
            out.append(t)
    text = " ".join(out)
    # Verilog has no max(): a macro would need the arguments twice; spell it out
    if lang == "v":
        text = expand_max(text)
    return text


def expand_max(text):
    """STRAND_MAX ( a , b ) -> ((a) > (b) ? (a) : (b)), innermost first; STRAND_CLOG2_1 likewise."""
    while True:
        m = re.search(r"(STRAND_MAX|STRAND_CLOG2_1) \(", text)
        if not m:
            return text
        depth, i, args, start = 1, m.end(), [], m.end()
        while depth:
            c = text[i]
            if c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
            elif c == "," and depth == 1:
                args.append(text[start:i].strip())
                start = i + 1
            i += 1
        args.append(text[start:i - 1].strip())
        if m.group(1) == "STRAND_MAX":
            a, b = args
            rep = f"(({a}) > ({b}) ? ({a}) : ({b}))"
        else:
            (a,) = args
            rep = f"(({a}) > 1 ? $clog2({a}) : 1)"
        text = text[:m.start()] + rep + text[i:]


def is_switch(lo, hi):
    return lo == "0" and hi == "1"


def main():
    if len(sys.argv) != 2:
        raise SystemExit("usage: gen_params.py OUTDIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    base = [r[0] for r in PARAMS]
    names = base + [d[0] for d in DERIVED]
    assert len(set(names)) == len(names), "a parameter is listed twice"
    for r in PARAMS:  # every expression reads
        for e in r[1:4]:
            translate(e, names, "v")
    head = "Generated by scripts/gen_params.py from its PARAMS table. Do not edit."

    def decls(default_of):
        lines = []
        for i, (name, default, lo, hi, effect, meaning) in enumerate(PARAMS):
            if is_switch(lo, hi):
                lines.append(f"    parameter [0:0]   {name:<15} = {default_of(name, default, True)}, // {meaning} [switch]")
            else:
                lines.append(f"    parameter integer {name:<15} = {default_of(name, default, False)}, // {meaning} [{lo} .. {hi}]")
        for name, expr, meaning in DERIVED:
            lines.append(f"    parameter integer {name:<15} = {translate(expr, names, 'v')}, // derived, leave it: {meaning}")
        lines[-1] = lines[-1].replace(", //", "  //", 1)
        return lines

    # Modules below strand_core take the whole set too (one list to pass on) and read
    # the parameters they need: the others are waived here, for these lines only.
    waive = ["    /* verilator lint_off UNUSEDPARAM */"]
    unwaive = ["    /* verilator lint_on UNUSEDPARAM */"]
    write(out, "strand_params.vh", [f"// {head}", "// The parameters of strand_core, with their defaults."]
          + waive + decls(lambda n, d, sw: f"1'b{d}" if sw else translate(d, names, "v")) + unwaive)
    write(out, "strand_params_scene.vh", [f"// {head}", "// The parameters of strand_core, with one scene's build as defaults",
                                          "// (the `STRAND_* macros of the params.vh that `strand hwgen` writes)."]
          + waive + decls(lambda n, d, sw: f"`STRAND_{n}") + unwaive)
    local = [f"    localparam integer {n:<15} = `STRAND_{n};" for n in base]
    local += [f"    localparam integer {n:<15} = {translate(x, names, 'v')};" for n, x, m in DERIVED]
    write(out, "strand_params_scene_local.vh", [f"// {head}", "// One scene's build (the `STRAND_* macros of hwgen's params.vh) as localparams,",
                                                "// for a testbench that drives sim_top."] + local)
    def passed(name, default, lo, hi):
        if name not in ONLY:
            return f".{name}({name})"
        dflt = f"1'b{default}" if is_switch(lo, hi) else translate(default, names, "v")
        return f".{name}(({translate(ONLY[name], names, 'v')}) ? {name} : {dflt})"
    write(out, "strand_params_pass.vh", [f"// {head}", "// Every parameter of strand_core, passed on to an instance; one that has no",
                                         "// effect in this build (ONLY in the table) is passed as its default."]
          + ["    " + ",\n    ".join(passed(r[0], r[1], r[2], r[3]) for r in PARAMS)])

    chk = [f"// {head}", "// The legal ranges and combinations of strand_core's parameters; included in its body",
           "// (rtl/strand_defs.vh defines STRAND_CHECK)."]
    for name, default, lo, hi, effect, meaning in PARAMS:
        if is_switch(lo, hi):
            continue  # [0:0]: nothing else fits
        cond = f"{name} >= {translate(lo, names, 'v')} && {name} <= {translate(hi, names, 'v')}"
        chk.append(f"`STRAND_CHECK({name}_out_of_range, {cond}, "
                   f"(\"strand_core: {name} must be {lo} .. {hi} ({name}=%0d) in %m\", {name}))")
    for name, expr, meaning in DERIVED:
        chk.append(f"`STRAND_CHECK({name}_is_derived_do_not_set_it, {name} == ({translate(expr, names, 'v')}), "
                   f"(\"strand_core: {name} is derived ({meaning}): do not set it (in %m)\"))")
    for label, cond, msg in CHECKS:
        chk.append(f"`STRAND_CHECK({label}, {translate(cond, names, 'v')}, (\"strand_core: {msg} (in %m)\"))")
    write(out, "strand_params_check.vh", chk)

    h = [f"/* {head} */", "#ifndef STRAND_PARAMS_H", "#define STRAND_PARAMS_H", "", "#include <stdio.h>", "",
         "/* X(NAME, name, switch, \"meaning\") for every parameter of strand_core, in header order;",
         "   switch: 1 for a [0:0] parameter (written 1'b0 / 1'b1 in Verilog). */",
         "#define STRAND_PARAMS(X) \\"]
    h += [f"    X({n}, {n.lower()}, {int(is_switch(r[2], r[3]))}, {json.dumps(r[5])}) \\" for n, r in zip(base, PARAMS)]
    h += ["", "/* The same for the derived widths. */", "#define STRAND_DERIVED(X) \\"]
    h += [f"    X({n}, {n.lower()}, {json.dumps(m)}) \\" for n, e, m in DERIVED]
    h += ["", "static inline int strand_clog2(long v) { int b = 0; while ((1L << b) < v) b++; return b; }",
          "static inline int strand_clog2_1(long v) { return v > 1 ? strand_clog2(v) : 1; }",
          "static inline long strand_max(long a, long b) { return a > b ? a : b; }", "",
          "/* Sets p's derived widths from its parameters (P: a struct with every field above). */",
          "#define STRAND_PARAMS_DERIVE(p) do { \\"]
    h += [f"    (p)->{n.lower()} = (int)({translate(e, names, 'c').replace('p->', '(p)->')}); \\" for n, e, m in DERIVED]
    h += ["} while (0)", "",
          "/* dst (a copy of src) as the modules below strand_core see it (strand_params_pass.vh): a",
          "   parameter its switch leaves without effect (ONLY in the table) takes its default, judged",
          "   on src's values. STRAND_PARAMS_DERIVE(dst) after it. */",
          "#define STRAND_PARAMS_PASSED(dst, src) do { \\"]
    for name, default, lo, hi, effect, meaning in PARAMS:
        if name in ONLY:
            c = lambda e: translate(e, names, "c").replace("p->", "(src)->")
            h.append(f"    if (!({c(ONLY[name])})) (dst)->{name.lower()} = (int)({c(default)}); \\")
    h += ["} while (0)", "",
          "/* Sets every parameter of p to its default. */",
          "#define STRAND_PARAMS_DEFAULTS(p) do { \\"]
    h += [f"    (p)->{n.lower()} = (int)({translate(r[1], names, 'c').replace('p->', '(p)->')}); \\" for n, r in zip(base, PARAMS)]
    h += ["    STRAND_PARAMS_DERIVE(p); \\", "} while (0)", "",
          "/* NULL when p (derived widths set) is a build strand_core accepts, else why not, in msg. */",
          "#define STRAND_PARAMS_CHECK(p, msg, len, result) do { \\", "    (result) = NULL; \\"]
    for name, default, lo, hi, effect, meaning in PARAMS:
        c = lambda e: translate(e, names, "c").replace("p->", "(p)->")
        h.append(f"    if (!(result) && !((p)->{name.lower()} >= {c(lo)} && (p)->{name.lower()} <= {c(hi)})) "
                 f"{{ snprintf((msg), (len), \"{name} must be {lo} .. {hi} ({name}=%d)\", (p)->{name.lower()}); (result) = (msg); }} \\")
    for label, cond, msg in CHECKS:
        c = translate(cond, names, "c").replace("p->", "(p)->")
        h.append(f"    if (!(result) && !({c})) {{ snprintf((msg), (len), \"%s\", {json.dumps(msg)}); (result) = (msg); }} \\")
    h += ["} while (0)", "", "#endif"]
    write(out, "strand_params.h", h)

    table = {"params": [{"name": n, "default": d, "lo": lo, "hi": hi, "switch": is_switch(lo, hi), "effect": e, "meaning": m}
                        for n, d, lo, hi, e, m in PARAMS],
             "derived": [{"name": n, "expr": e, "meaning": m} for n, e, m in DERIVED],
             "checks": [{"label": l, "cond": c, "why": m} for l, c, m in CHECKS]}
    write(out, "strand_params.json", [json.dumps(table, indent=1)])


def write(out, name, lines):
    path = os.path.join(out, name)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)


if __name__ == "__main__":
    main()
