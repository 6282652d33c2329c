#!/usr/bin/env python3
"""gen_effects.py OUTDIR - the effects table: one row an effect, every side generated.

EFFECTS below is the only hand-written description of the table's effects beside their
physics. From it:

  scripts/gen_params.py   takes each row's enable parameter (EN_<NAME>)
  scripts/gen_regs.py     takes each row's registers (after the fixed map's addresses)
  OUTDIR/strand_effects.h     (C) the scene's fields and section, the parsing and checks of
                          its keys, the constants (scene_consts, the engines' state, their
                          scaling), the build parameter from a scene and back, the register
                          writes (hwgen) and their decode (the cycle model), the rounding
                          warnings, the effect's name in summaries, the CPU baseline's refusal
  strand_regs.vh          (Verilog, through gen_regs.py) the run-time constants' bus: its
                          width, each constant's slot, and the registers behind it
  OUTDIR/scene.dict       the scene fuzzer's dictionary: tb/fuzz/scene.dict and the table's
                          sections and keys
  scripts/effects.py      the effects document's row and the gating check (EFFECT_ROWS)
  scripts/lockstep_fuzz.py  the random scenes' draws and coverage classes

Hand-written for an effect: its row here, its physics in model/engine_body.h (the frame
engine, both number types) and rtl/node_lane.v (the Verlet step of one axis), the CPU
baseline's lines in model/cpu_rope.c when `cpu` says it runs it, and its scenes.
docs/architecture.md ("How to add an effect") walks through it.

A row:
  name      the effect and its scene section [name]; the effect is on when the section is there
  section   (optional) the section its keys are in instead (damping: [time]); then
  on        says when it is on (a C expression of the scene, sc)
  after     (optional) the parameter its switch follows in the parameter table
  default   (optional) its switch's default in strand_core (0 unless given)
  title     what the documents call it
  param     its enable parameter of strand_core (a switch, default 0)
  meaning   the parameter's description (docs/architecture.md's parameter table)
  keys      the section's keys: key, kind ("num" or "vec": a value per axis), lo, hi (the
            legal range of a value), required (else 0), what (docs)
  consts    the run-time constants the hardware reads, each a register (a "vec" one a register
            per axis, _X _Y _Z) and a field of the engines' state: name, expr (a C expression of
            the scene's keys, `sc->NAME_KEY`, the substep `h` and, for a vector, the axis `k`),
            lo, hi (the range the constant must keep, else the scene is refused), symbol (how
            warnings name it; symbol_c: a C expression for it instead), key (the key a warning
            points at), what (the register map), addr (optional: its fixed address, a list of
            three for a vector, for a register older than the table)
  verlet    the effect acts in the Verlet step only: explicit Euler refuses it
  cpu       model/cpu_rope.c (the CPU baseline) runs it; else it refuses such a scene
  cpu_fast  model/cpu_fast.c (the optimised CPU program) runs it; else it refuses such a scene
  doc       the scene lines of effects.py's row (context: lines the scene without it keeps too)
  fuzz      the random scenes: hand (lockstep_fuzz.py draws it itself), or p (the share of builds with it), draws (key: (lo, hi) uniform,
            or (lo, hi, scale) with scale a Python expression of reach (a quarter of the format's
            range), substeps and lsb; a vector drawn per axis; the values are multiples of the
            format's LSB), off_class (optional: the coverage class of builds without it)
"""
import os
import sys

EFFECTS = [
    dict(
        name="gravity",
        title="gravity",
        param="EN_GRAVITY",
        default=1,
        after="SUBSTEPS",
        meaning="add g h^2 in the Verlet step",
        keys=[
            dict(key="accel", kind="vec", lo=-1e12, hi=1e12, required=True, field="gravity",
                 what="the acceleration g"),
        ],
        consts=[
            dict(name="gravity", reg="GDT2", vector=True, addr=[0, 1, 19],
                 expr="(sc->integrator == INTEGRATOR_VERLET ? sc->gravity[k] * h * h : sc->gravity[k])", lo=None, hi=None,
                 symbol="g h^2", symbol_c="(sc->integrator == INTEGRATOR_VERLET ? \"g h^2\" : \"g\")", key="accel",
                 what="gravity times h^2 (explicit Euler, in the model only: g)"),
        ],
        verlet=False,
        cpu=True,
        cpu_fast=True,
        doc=dict(scene=["accel = 0.5 -9.8"]),
        # drawn by scripts/lockstep_fuzz.py itself, in its build's and scene's own stream (mostly
        # downward, scaled to the body), as before the table: the table gives its classes only
        fuzz=dict(hand=True, off_class="no gravity"),
    ),
    dict(
        name="damping",
        title="Verlet damping",
        param="EN_DAMPING",
        after="EN_GRAVITY",
        meaning="Verlet damping v -= v d",
        section="time", on="sc->damping > 0",
        keys=[
            dict(key="damping", kind="num", lo=0, hi=0.999999, required=False,
                 what="Verlet damping d: x+ = x + (1 - d)(x - x-) + a h^2 (0: none)"),
        ],
        consts=[
            dict(name="damping", reg="DAMPING", addr=6, expr="sc->damping", lo=None, hi=None, symbol="damping",
                 key="damping", what="Verlet damping d, 0 <= d < 1 (Q.F)"),
        ],
        verlet=True,
        cpu=True,
        cpu_fast=True,
        doc=dict(scene=["damping = 0.02"], context={"gravity": ["accel = 0.5 -9.8"]}),  # it acts on velocity: a force first
        fuzz=dict(p=0.4, draws={"damping": (0.0, 0.3)}),
    ),
    dict(
        name="wind",
        title="air drag in a wind",
        param="EN_WIND",
        meaning="air drag toward a wind: in the Verlet step v -= c h (v - w h), after damping",
        keys=[
            dict(key="velocity", kind="vec", lo=-1e12, hi=1e12, required=False,
                 what="the wind's velocity w (units a second; default 0: still air)"),
            dict(key="drag", kind="num", lo=0, hi=1e12, required=True,
                 what="the drag coefficient c (a second^-1): the acceleration -c (v - w)"),
        ],
        consts=[
            dict(name="drag", reg="DRAG", expr="sc->wind_drag * h", lo=0, hi=0.999999, symbol="c h", key="drag",
                 what="wind: the drag per substep c h, 0 <= c h < 1 (Q.F)"),
            dict(name="wind", reg="WIND", vector=True, expr="sc->wind_velocity[k] * h", lo=None, hi=None, symbol="w h",
                 key="velocity", what="wind: the wind's motion per substep w h"),
        ],
        verlet=True,
        cpu=True,
        cpu_fast=False,
        doc=dict(scene=["velocity = 3 0.5", "drag = 0.8"], context={"gravity": ["accel = 0.5 -9.8"]}),
        # (the random scenes have dt = 1: c h = drag / substeps stays below 1)
        fuzz=dict(p=0.3, draws={"velocity": (-2.0, 2.0), "drag": (0.0, 0.9)}),
    ),
]

# The hand-written files of an effect of this table (docs/architecture.md lists them).
HAND_WRITTEN = [
    ("scripts/gen_effects.py", "its row of EFFECTS: section, keys, constants and registers, switch, draws, document row"),
    ("model/engine_body.h", "its physics in the frame engine (fixed and double, and through it the cycle model)"),
    ("rtl/node_lane.v", "its physics in the hardware's Verlet step, reading its constants from fx_consts"),
    ("model/cpu_rope.c", "its lines in the CPU baseline (or `cpu=False`: cpu_rope refuses such a scene)"),
    ("tb/scenes/*.scene", "its scenes: each runs in lockstep on both architectures in make test (a glob)"),
]

AXES = "XYZ"


def sec(e):
    """The scene section an effect's keys are in."""
    return e.get("section", e["name"])


def own(e):
    """Does the effect have a section of its own (on when it is there)?"""
    return sec(e) == e["name"]


def field(e, k):
    """The scene's field of a key: its own name, or NAME_KEY, or NAME when the key is the effect's name."""
    return k.get("field") or (e["name"] if k["key"] == e["name"] else f"{e['name']}_{k['key']}")


def registers(taken):
    """The table's registers, (name, address, what): those with a fixed address at it, the others
    from the first address above every one in `taken` (the hand-written map's) and the fixed ones."""
    fixed = [a for e in EFFECTS for c in e["consts"] if "addr" in c for a in (c["addr"] if c.get("vector") else [c["addr"]])]
    nxt = max(list(taken) + fixed) + 1
    out = []
    for e in EFFECTS:
        for c in e["consts"]:
            names = [f"{c['reg']}_{a}" for a in AXES] if c.get("vector") else [c["reg"]]
            for i, n in enumerate(names):
                what = c["what"] + (f", {AXES[i].lower()}" + (" (DIM = 3)" if i == 2 else "") + " (Q.F)" if c.get("vector") else "")
                if "addr" in c:
                    out.append((n, c["addr"][i] if c.get("vector") else c["addr"], what))
                else:
                    out.append((n, nxt, what))
                    nxt += 1
    return out


def params():
    """The table's rows for gen_params.PARAMS, each with the parameter it follows (None: the default place)."""
    return [((e["param"], str(e.get("default", 0)), "0", "1", e["name"], e["meaning"]), e.get("after")) for e in EFFECTS]


def slots():
    """[(effect, const, offset expression)]: each constant's first slot on the bus; a vector takes DIM."""
    scal = [(e, c) for e in EFFECTS for c in e["consts"] if not c.get("vector")]
    vec = [(e, c) for e in EFFECTS for c in e["consts"] if c.get("vector")]
    out = [(e, c, str(i)) for i, (e, c) in enumerate(scal)]
    out += [(e, c, f"{len(scal)} + {i} * DIM") for i, (e, c) in enumerate(vec)]
    return out, f"{len(scal)} + {len(vec)} * DIM"


def effect_rows():
    """effects.py's rows (see its EFFECTS): the document and the gating check."""
    return [dict(name=e["name"], title=e["title"], scene={sec(e): list(e["doc"]["scene"])}, params={e["param"]: 1},
                 **({"context": e["doc"]["context"]} if e["doc"].get("context") else {})) for e in EFFECTS]


def drawn():
    """The effects whose random draws the table makes (not those lockstep_fuzz.py draws itself)."""
    return [e for e in EFFECTS if not e["fuzz"].get("hand")]


def fuzz_build(rng, build):
    """Draw each effect's switch into build (rng: the fuzz's per-build generator for the table)."""
    for e in drawn():
        build[e["param"]] = rng.random() < e["fuzz"]["p"]


def fuzz_lines(rng, build, lsb, reach):
    """The scene lines of the build's table effects (a dict: section -> lines)."""
    out = {}
    for e in drawn():
        if not build.get(e["param"]):
            continue
        lines = []
        for key in e["keys"]:
            lo, hi, *scale = e["fuzz"]["draws"][key["key"]]
            s = eval(scale[0], {}, {"reach": reach, "substeps": build["SUBSTEPS"], "lsb": lsb}) if scale else 1
            n = build["DIM"] if key["kind"] == "vec" else 1
            vals = [round(rng.uniform(lo, hi) * s / lsb) * lsb for _ in range(n)]
            lines.append(f"{key['key']} = " + " ".join(f"{v:.9g}" for v in vals))
        out.setdefault(sec(e), []).extend(lines)
    return out


def fuzz_classes(build):
    """The coverage classes a build's table effects give."""
    return [e["name"] if build.get(e["param"]) else e["fuzz"]["off_class"] for e in EFFECTS
            if build.get(e["param"]) or e["fuzz"].get("off_class")]


def fuzz_class_rows():
    """The table's rows of the fuzz's CLASSES: (class, what it is)."""
    return [(e["name"], f"{e['param']} = 1") for e in EFFECTS] + \
        [(e["fuzz"]["off_class"], f"{e['param']} = 0") for e in EFFECTS if e["fuzz"].get("off_class")]


# ---- C ----

def c_header():
    L = ["/* Generated by scripts/gen_effects.py: the effects table's C side. Do not edit. */",
         "#ifndef STRAND_EFFECTS_H", "#define STRAND_EFFECTS_H", ""]

    def macro(name, body, doc):
        L.append(f"/* {doc} */")
        if not body:
            L.append(f"#define {name}")
        else:
            L.append(f"#define {name} \\")
            L.extend(f"    {b} \\" for b in body[:-1])
            L.append(f"    {body[-1]}")
        L.append("")

    owned = [e for e in EFFECTS if own(e)]
    L.append(f"#define STRAND_EFFECT_SECTION_COUNT {len(owned)} /* scene sections of the table's effects */")
    L.append("")
    macro("STRAND_EFFECT_SECTION_ENUM", [f"S_{e['name'].upper()}," for e in owned], "scene.c: their section indices")
    macro("STRAND_EFFECT_SECTION_NAMES", [f"\"{e['name']}\"," for e in owned], "scene.c: their section names")
    fields = []
    for e in EFFECTS:
        fields.append(f"bool en_{e['name']}; /* {e['title']}: " + (f"[{e['name']}] is there */" if own(e) else f"{e['on']} */"))
        for k in e["keys"]:
            fields.append(f"double {field(e, k)}{'[3]' if k['kind'] == 'vec' else ''};")
    macro("STRAND_EFFECT_SCENE_FIELDS", fields, "scene.h: the scene's fields (the keys as written)")
    macro("STRAND_EFFECT_PARSER_FIELDS",
          [f"vec_value {field(e, k)};" for e in EFFECTS for k in e["keys"] if k["kind"] == "vec"] or ["/* none */"],
          "scene.c: the vector values checked against dim at the end")

    def parse(e, k):
        if k["kind"] == "vec":
            return f"return parse_vec(p, key, value, &p->{field(e, k)});"
        return f"return parse_double(p, key, value, {k['lo']!r}, {k['hi']!r}, &sc->{field(e, k)});"

    macro("STRAND_EFFECT_OTHER_KEYS",
          [f"if (s == S_{sec(e).upper()} && !strcmp(key, \"{k['key']}\")) {parse(e, k)}"
           for e in EFFECTS if not own(e) for k in e["keys"]] or ["/* none */"],
          "scene.c: the handler's keys of table effects in other sections (s, p, sc, key, value in scope)")
    macro("STRAND_EFFECT_CONST_FIELDS",
          [f"double {c['name']}{'[3]' if c.get('vector') else ''}; /* {c['symbol']} */" for e in EFFECTS for c in e["consts"]],
          "scene.h: scene_consts, the constants before rounding")
    macro("STRAND_EFFECT_SIM_FIELDS(NUM)",
          [f"NUM {c['name']}{'[3]' if c.get('vector') else ''}; /* {c['symbol']} */" for e in EFFECTS for c in e["consts"]],
          "sim.h: the engines' constants")
    cases = []
    for e in owned:
        cases.append(f"case S_{e['name'].upper()}:")
        cases += [f"    if (!strcmp(key, \"{k['key']}\")) {parse(e, k)}" for k in e["keys"]]
        cases.append("    break;")
    macro("STRAND_EFFECT_PARSE_CASES", cases, "scene.c: the handler's cases (p, sc, key, value in scope)")
    fin = []
    for e in EFFECTS:
        S = f"S_{sec(e).upper()}"
        fin.append(f"sc->en_{e['name']} = " + (f"p->section_line[{S}] != 0;" if own(e) else f"{e['on']};"))
        fin.append(f"if (sc->en_{e['name']}) {{")
        for k in e["keys"]:
            fld = field(e, k)
            if k["required"]:
                fin.append(f"    if (!key_line(p, {S}, \"{k['key']}\")) return fail_at(p, blame(p, {S}, NULL), \"[{sec(e)}] needs '{k['key']}'\");")
            if k["kind"] == "vec":
                fin.append(f"    if (!check_vec(p, &p->{fld}, \"{k['key']}\")) return false;")
                fin.append(f"    for (int k_ = 0; k_ < 3; k_++) {{")
                fin.append(f"        if (p->{fld}.v[k_] < {k['lo']!r} || p->{fld}.v[k_] > {k['hi']!r})")
                fin.append(f"            return fail_at(p, p->{fld}.line, \"{k['key']}: each value in [%g, %g]\", {k['lo']!r}, {k['hi']!r});")
                fin.append(f"        sc->{fld}[k_] = p->{fld}.v[k_];")
                fin.append("    }")
        if e.get("verlet") and own(e):
            fin.append(f"    if (sc->integrator == INTEGRATOR_EULER) return fail_at(p, blame(p, S_TIME, \"integrator\"), "
                       f"\"integrator: euler does not support [{e['name']}]; use verlet\");")
        elif e.get("verlet"):
            k0 = e["keys"][0]["key"]
            fin.append(f"    if (sc->integrator == INTEGRATOR_EULER) return fail_at(p, blame(p, {S}, \"{k0}\"), "
                       f"\"{k0}: {e['title']} has no meaning for euler\");")
        fin.append("}")
    macro("STRAND_EFFECT_FINISH", fin, "scene.c finish(): the effects on, their required keys and vectors")
    chk = []
    for e in EFFECTS:
        for c in e["consts"]:
            if c["lo"] is None:
                continue
            idx = "[k]" if c.get("vector") else ""
            rng_ = f"{c['lo']!r} <= {c['symbol']} <= {c['hi']!r}"
            loop = "for (int k = 0; k < sc->dim; k++) " if c.get("vector") else ""
            chk.append(f"if (sc->en_{e['name']}) {loop}if (c.{c['name']}{idx} < {c['lo']!r} || c.{c['name']}{idx} > {c['hi']!r}) "
                       f"return fail_at(p, blame(p, S_{sec(e).upper()}, \"{c['key']}\"), \"{c['key']}: {c['symbol']} = %g is outside "
                       f"{rng_} (h = dt / substeps = %g)\", c.{c['name']}{idx}, scene_h(sc));")
    macro("STRAND_EFFECT_CHECK_CONSTS(c)", chk or ["/* none */"],
          "scene.c finish(): the constants within their ranges (c: the scene_consts, p, sc in scope)")
    def each_const(assign):
        """A statement a constant: assign(effect, const, index) with index "[k]" in a loop over the
        axes for a vector, "" for a scalar."""
        return [(f"for (int k = 0; k < 3; k++) " if c.get("vector") else "") + assign(e, c, "[k]" if c.get("vector") else "")
                for e in EFFECTS for c in e["consts"]]

    macro("STRAND_EFFECT_CONSTANTS", each_const(lambda e, c, i: f"c->{c['name']}{i} = sc->en_{e['name']} ? {c['expr']} : 0;"),
          "scene_constants(): the constants (sc, c, h in scope)")
    macro("STRAND_EFFECT_SIM_INIT", each_const(lambda e, c, i: f"s->{c['name']}{i} = FROM(c.{c['name']}{i});"),
          "engine_body.h init(): the engines' constants (s, c, FROM in scope)")
    macro("STRAND_EFFECT_HW_PARAMS(hp, sc)", [f"(hp)->{e['param'].lower()} = (sc)->en_{e['name']};" for e in EFFECTS],
          "hwgen.c: the build parameter of each effect")
    macro("STRAND_EFFECT_SCENE_OF_HW(sc, hp)", [f"(sc)->en_{e['name']} = (hp)->{e['param'].lower()};" for e in EFFECTS],
          "cycle.c: the cycle model's scene has the build's effects")
    puts = []
    for e in EFFECTS:
        for c in e["consts"]:
            if c.get("vector"):
                for i, a in enumerate(AXES):
                    puts.append(f"{'if (hp.dim == 3) ' if i == 2 else ''}PUT(STRAND_REG_{c['reg']}_{a}, s->{c['name']}[{i}]);")
            else:
                puts.append(f"PUT(STRAND_REG_{c['reg']}, s->{c['name']});")
    macro("STRAND_EFFECT_PUTS", puts, "hwgen.c: the setup writes of the table's registers, 0 for an effect the scene does not "
          "have, as every constant register is written (hp, s, PUT in scope)")
    dec = []
    for e in EFFECTS:
        for c in e["consts"]:
            if c.get("vector"):
                dec += [f"case STRAND_REG_{c['reg']}_{a}: (st).{c['name']}[{i}] = (v); break;" for i, a in enumerate(AXES)]
            else:
                dec.append(f"case STRAND_REG_{c['reg']}: (st).{c['name']} = (v); break;")
    macro("STRAND_EFFECT_REG_CASES(st, v)", dec, "cycle.c: strand_regfile's decode of the table's registers")
    macro("STRAND_EFFECT_RESET(st)", each_const(lambda e, c, i: f"(st).{c['name']}{i} = 0;"), "cycle.c: the registers after reset")
    warn = []
    for e in EFFECTS:
        for c in e["consts"]:
            line = f"scene_key_line(sc, \"{sec(e)}\", \"{c['key']}\")"
            if c.get("vector"):
                warn.append(f"if (sc->en_{e['name']}) for (int k = 0; k < sc->dim; k++) {{")
                warn.append(f"    snprintf(what, sizeof what, \"%s (%c)\", {c.get('symbol_c') or repr(c['symbol']).replace(chr(39), chr(34))}, \"xyz\"[k]);")
                warn.append(f"    warnings += warn_constant(sc, {line}, what, c.{c['name']}[k]);")
                warn.append("}")
            else:
                warn.append(f"if (sc->en_{e['name']}) warnings += warn_constant(sc, {line}, \"{c['symbol']}\", c.{c['name']});")
    macro("STRAND_EFFECT_WARNINGS", warn, "strand.c: the rounding warnings (sc, c, what, warnings, warn_constant in scope)")
    names = [f"sc->en_{e['name']} ? \"{e['name']} \" : \"\"" for e in EFFECTS]
    L.append("/* scene.c: the effects' names in summaries (a format string and its arguments) */")
    L.append(f"#define STRAND_EFFECT_NAMES_FMT \"{'%s' * len(EFFECTS)}\"")
    L.append("#define STRAND_EFFECT_NAMES_ARGS(sc) " + ", ".join(f"(sc)->en_{e['name']} ? \"{e['name']} \" : \"\"" for e in EFFECTS))
    L.append("")
    macro("STRAND_EFFECT_CPU_FAST_REFUSALS(sc)",
          [f"{{(sc)->en_{e['name']}, \"{e['name']}\", NULL, \"{e['title']}\"}}," for e in EFFECTS if not e["cpu_fast"]]
          or ["/* none */"], "cpu_fast.c: its refusals, {when, section, key, what}, of the table's effects it does not run")
    refuse = " : ".join(f"(sc)->en_{e['name']} ? \"{e['title']}\"" for e in EFFECTS if not e["cpu"])
    macro("STRAND_EFFECT_CPU_REFUSES(sc)", [f"({refuse} : NULL)" if refuse else "((void)(sc), (const char *)0)"],
          "cpu_rope.c: the table's effect the CPU baseline does not run, or NULL")
    L.append("#endif")
    return "\n".join(L) + "\n"


# ---- Verilog (gen_regs.py writes it into strand_regs.vh, so every file list that names the
# register map has it) ----

def verilog():
    """The constants bus: its width, each constant's slot, and STRAND_EFFECT_REGFILE, the
    registers behind it (strand_regfile expands it; AB, DIM, W, the EN_ switches, the genvar k,
    clk, reset, cfg_* and fx_consts in scope)."""
    sl, width = slots()
    L = ["// The effects table (scripts/gen_effects.py): the run-time constants' bus fx_consts, which",
         "// strand_regfile drives and node_unit passes to every node_lane. A constant of an effect",
         "// the build does not have is 0 (no register is built for it).",
         f"`define STRAND_FX_SLOTS ({width}) // the bus's words (DIM in scope)"]
    for e, c, off in sl:
        L.append(f"`define STRAND_FX_{c['name'].upper()} ({off}) // {e['name']}: {c['symbol']}"
                 + (", lane k at slot + k" if c.get("vector") else ""))
    body = []
    for e, c, off in sl:
        r = f"fx_{c['name']}"
        if c.get("vector"):
            body += [f"localparam [3*AB-1:0] A_{c['reg']} = {{`STRAND_REG_{c['reg']}_Z, `STRAND_REG_{c['reg']}_Y, `STRAND_REG_{c['reg']}_X}};",
                     "generate",
                     f"for (k = 0; k < DIM; k = k + 1) begin : g_{r}",
                     f"reg [W-1:0] {r}_q;",
                     "always @(posedge clk)",
                     f"if (reset) {r}_q <= {{W{{1'b0}}}};",
                     f"else if (cfg_we && cfg_addr == A_{c['reg']}[k*AB +: AB]) {r}_q <= cfg_data;",
                     f"assign fx_consts[(`STRAND_FX_{c['name'].upper()} + k)*W +: W] = {e['param']} ? {r}_q : {{W{{1'b0}}}};",
                     "end",
                     "endgenerate"]
        else:
            body += [f"reg [W-1:0] {r}_q;",
                     "always @(posedge clk)",
                     f"if (reset) {r}_q <= {{W{{1'b0}}}};",
                     f"else if (cfg_we && cfg_addr == `STRAND_REG_{c['reg']}) {r}_q <= cfg_data;",
                     f"assign fx_consts[`STRAND_FX_{c['name'].upper()}*W +: W] = {e['param']} ? {r}_q : {{W{{1'b0}}}};"]
    L.append("// the registers: each resets to 0 and takes a write in the cycle after it")
    L.append("`define STRAND_EFFECT_REGFILE \\")
    L += [f"    {b} \\" for b in body[:-1]] + [f"    {body[-1]}"]
    return "\n".join(L) + "\n"


def fuzz_dict(base):
    words = []
    for e in EFFECTS:
        words.append(f"[{e['name']}]")
        words += [f"{k['key']} = " for k in e["keys"]]
    with open(base) as f:
        text = f.read()
    extra = "".join(f'"{w}"\n' for w in words)
    return text + ("" if text.endswith("\n") else "\n") + "# the effects table (scripts/gen_effects.py)\n" + extra


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    files = {"strand_effects.h": c_header(), "scene.dict": fuzz_dict(os.path.join(root, "tb", "fuzz", "scene.dict"))}
    for name, text in files.items():
        with open(os.path.join(out, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
