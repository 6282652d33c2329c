#!/usr/bin/env python3
"""lockstep_fuzz.py - random scenes in lockstep: the RTL against the cycle model.

    lockstep_fuzz.py N [--seed S] [--builds B] [--jobs J] [--scene FILE ...] [--faults] [--reset-seeds K]
                      [--partial] [--coverage-json FILE]
    lockstep_fuzz.py --replay SEED [--seed S] [--builds B]

Every scene is drawn from a seed: its build (W, F, M, K, SQRT_BITS, DIV_BITS, ITER,
SUBSTEPS and the EN_* effects: springs, ground, the mouse's impulse or grab form, 2D or 3D,
a chain or a graph), its constants (start, step, rest length, gravity,
damping, pins), its mouse script and its length, all within what the RTL supports.
A Verilator build costs half a minute or more, so scenes share builds: the three builds
of the RTL test scenes and B more drawn from --seed. Scene i runs on build i mod (3 + B).
The harnesses of a run are compiled without optimisation (build/vl/*_fast): that halves a
build and slows a run about four times, and a run here is mostly its build.

Coverage by construction: the first len(PLAN) drawn builds each fix the classes of one
row of PLAN below (2D/3D, chain/graph, rule, serial/pipelined, K=1, springs, ground
axis and side, mouse form, narrow/full SQRT_BITS and DIV_BITS, ...) and draw the rest
from the seed; the first scenes of every build (its slots 0, 1, 2) pin a rod end,
hold a rod end with the grab, and put every node on one point. Whatever the seed, a
run of at least 3 x (3 + B) scenes therefore covers every class of CLASSES; the run
prints the classes it covered, and a FAIL line naming those it missed (and the
fewest scenes that cover them all) when it did not. A class is read from what ran:
the parameters 'strand info' derives from the scene written, the scene's pins,
edges and mouse script, and the harness's count of random resets.

Each scene runs through the harness with its own stimulus seed and random initial
values (+verilator+rand+reset+2); every third scene of a build is also reset at random
cycles in the middle of frames. A failure prints the scene's seed; --replay SEED runs
that one scene again (the scene file is kept in build/fuzz/).

--scene FILE runs a given scene (its whole length) too; --faults builds copies of
the RTL with the planted faults of tb/faults.py and checks that each is reported at
the cycle the model predicts; --reset-seeds K runs the first --scene with K random-initialisation seeds
and checks that every output of every cycle is the same as with zeros.
Harnesses live in build/vl/b_<hash of the build>, shared by every run.
"""
import argparse
import concurrent.futures
import json
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import gen_effects  # noqa: E402  (the effects table: its switches, draws and classes)
from strandflow import build as flow_build, hwgen as flow_hwgen, run as flow_run  # noqa: E402
from strandflow.core import BUILD, ROOT, Failure  # noqa: E402
from strandflow.build import build_key, harness_dir  # noqa: E402,F401  (lockstep_soak.py uses harness_dir)
sys.path.insert(0, os.path.join(ROOT, "tb"))
import faults  # noqa: E402  (the planted faults: copies of rtl/)

FIXED_BUILDS = ["sim/scenes/ref000_rope.scene", "tb/scenes/chain_q10_8.scene", "tb/scenes/chain_k4_bits.scene"]


def read_build(path, order=None):
    """The build a scene file needs: strand_core's parameters as 'strand info' derives them
    (the one source of parameters: model/hwgen.c and the table of scripts/gen_params.py);
    order (serial or redblack) replaces the scene's constraint order."""
    try:
        info = flow_hwgen.info(path, order)
    except Failure as e:
        sys.exit(f"{e}\nFAIL lockstep: no RTL build for {path}")
    if not info["rtl"]:
        sys.exit(f"{info['why']}\nFAIL lockstep: no RTL build for {path}")
    return info["params"]


def random_build(rng, plan=None):
    """A build drawn as strand_core parameters (the scene written for it makes hwgen derive them);
    plan (a row of PLAN) fixes some of them, the rest are drawn."""
    w = rng.choice([12, 16, 18, 20, 24, 32])
    b = {"W": w, "M": rng.randint(1, 4), "K": rng.randint(1, 6),
         "ITER": rng.randint(1, 3), "SUBSTEPS": rng.randint(1, 2),
         "EN_GRAVITY": rng.random() < 0.8, "EN_MOUSE": rng.random() < 0.7,
         "EN_CONSTRAINTS": rng.random() < 0.85, "RULE": rng.randint(0, 1),
         "EN_SPRINGS": rng.random() < 0.4, "EN_GROUND": rng.random() < 0.3, "GROUND_AXIS": rng.randint(0, 1),
         "GROUND_ABOVE": rng.random() < 0.5, "DIM": rng.choice([2, 2, 3]), "GRAPH": rng.random() < 0.3}
    b["GRAB"] = b["EN_MOUSE"] and rng.random() < 0.35   # the grab form of the mouse
    if b["DIM"] == 3 and rng.random() < 0.4:
        b["GROUND_AXIS"] = 2    # the floor of a 3D scene
    # the red/black order: a chain's constraints on the pipelined pass, a graph's edges by colour
    b["ORDER"] = rng.random() < 0.5
    # the projection of a distance constraint: the current positions' direction, or the previous ones'
    b["PROJECTION"] = rng.random() < 0.25
    b.update({k: v for k, v in (plan or {}).items() if k not in ("name", "SQRT", "DIV")})
    w = b["W"]
    b["F"] = rng.randint(max(2, w // 3), w - 5)
    # square root and divide: narrow (fewer than W - 1 bits resolved) or full width
    for key, pk in (("SQRT_BITS", "SQRT"), ("DIV_BITS", "DIV")):
        kind = (plan or {}).get(pk) or rng.choice(["narrow", "narrow", "full"])
        b[key] = w - 1 if kind == "full" else rng.randint(max(3, w // 2), w - 2)
    if b["GRAPH"]:
        b["RULE"] = 1  # a graph has no chain to walk: the pairwise rule
    b["GRAB"] = bool(b["EN_MOUSE"] and b["GRAB"])
    if b["GROUND_AXIS"] >= b["DIM"]:
        b["GROUND_AXIS"] = 1
    b["ARCH"] = b["ORDER"] and b["EN_CONSTRAINTS"]
    b["PROJECTION"] = bool(b["PROJECTION"] and b["EN_CONSTRAINTS"])
    # the pipes' root and divide iterations a stage, drawn from the build itself rather than rng,
    # so that the builds drawn after this one stay what they were before PIPE_STEPS existed
    b["PIPE_STEPS"] = (plan or {}).get("PIPE_STEPS") or random.Random(repr(sorted(b.items()))).choice([1, 1, 2, 3, 4])
    # the distance datapath: the full-width root and divide (0) or the normalised one's mantissa bits,
    # drawn likewise from the build
    mb = random.Random("mantissa " + repr(sorted(b.items()))).choice([0, 0, 6, 8, 11, 14, 17, 17, 20])
    b["MANTISSA"] = (plan or {}).get("MANTISSA", mb) if b["EN_CONSTRAINTS"] or b["EN_SPRINGS"] else 0
    # the effects table's switches, drawn likewise from the build; effect j is on in PLAN's row j
    # (modulo its length), so that every run covers it, and a row's own value wins
    gen_effects.fuzz_build(random.Random("effects " + repr(sorted(b.items()))), b)
    if plan in PLAN:
        for j, e in enumerate(gen_effects.drawn()):
            b[e["param"]] = bool(plan.get(e["param"], b[e["param"]] or j % len(PLAN) == PLAN.index(plan)))
    return b


# The planned builds: each row fixes the classes named in it (the rest is drawn from the
# seed), so that together with the fixed builds every class of CLASSES has a build.
# SQRT and DIV: "narrow" (SQRT_BITS, DIV_BITS < W - 1) or "full" (W - 1).
PLAN = [
    {"name": "chain 2D pairwise serial K=1, impulse, ground -x", "GRAPH": 0, "DIM": 2, "EN_CONSTRAINTS": 1, "RULE": 1,
     "ORDER": 0, "K": 1, "M": 3, "EN_MOUSE": 1, "GRAB": 0, "EN_GROUND": 1, "GROUND_AXIS": 0, "GROUND_ABOVE": 0,
     "SQRT": "narrow", "DIV": "full", "ITER": 3, "EN_DAMPING": 1, "W": 16, "MANTISSA": 8},
    {"name": "chain 3D pairwise pipelined, springs, grab, ground +z", "GRAPH": 0, "DIM": 3, "EN_CONSTRAINTS": 1, "RULE": 1,
     "ORDER": 1, "M": 3, "K": 3, "EN_MOUSE": 1, "GRAB": 1, "EN_SPRINGS": 1, "EN_GROUND": 1, "GROUND_AXIS": 2,
     "GROUND_ABOVE": 1, "SQRT": "full", "DIV": "narrow", "W": 32, "SUBSTEPS": 2, "PIPE_STEPS": 2, "MANTISSA": 17},
    {"name": "graph 3D rods pipelined and springs, grab, ground -y", "GRAPH": 1, "ORDER": 1, "DIM": 3, "EN_CONSTRAINTS": 1, "EN_SPRINGS": 1,
     "M": 2, "K": 3, "EN_MOUSE": 1, "GRAB": 1, "EN_GROUND": 1, "GROUND_AXIS": 1, "GROUND_ABOVE": 0, "SQRT": "full", "DIV": "full",
     "EN_GRAVITY": 1, "W": 24, "PIPE_STEPS": 3, "MANTISSA": 12},
    {"name": "graph 2D rods, previous projection, impulse, no gravity", "GRAPH": 1, "ORDER": 0, "DIM": 2,
     "EN_CONSTRAINTS": 1, "EN_SPRINGS": 0,
     "EN_MOUSE": 1, "GRAB": 0, "EN_GROUND": 0, "SQRT": "narrow", "DIV": "narrow", "EN_GRAVITY": 0, "W": 20,
     "PROJECTION": 1, "MANTISSA": 11},
    {"name": "chain 3D centred pipelined K=1, previous projection, ground +y", "GRAPH": 0, "DIM": 3, "EN_CONSTRAINTS": 1, "RULE": 0,
     "ORDER": 1, "K": 1, "M": 4, "EN_MOUSE": 1, "GRAB": 0, "EN_GROUND": 1, "GROUND_AXIS": 1, "GROUND_ABOVE": 1,
     "SQRT": "narrow", "DIV": "narrow", "EN_DAMPING": 1, "PROJECTION": 1},
    {"name": "chain 2D one unit, springs without constraints, no mouse, ground +x", "GRAPH": 0, "DIM": 2,
     "EN_CONSTRAINTS": 0, "EN_SPRINGS": 1, "M": 1, "EN_MOUSE": 0, "EN_GRAVITY": 0, "EN_GROUND": 1, "GROUND_AXIS": 0,
     "GROUND_ABOVE": 1, "SQRT": "full", "DIV": "narrow"},
    # floor(K/2) + 2 > LP + 4 (LP = SQRT_BITS + DIV_BITS + 15 <= 35 at W = 12, narrow): the sweeps wait for their slots
    {"name": "chain pipelined slot-bound K=80", "GRAPH": 0, "DIM": 2, "EN_CONSTRAINTS": 1, "ORDER": 1, "M": 2, "K": 80,
     "W": 12, "SQRT": "narrow", "DIV": "narrow", "PROJECTION": 0, "EN_SPRINGS": 0},
]

# Every class a run must cover: (name, what it means).
CLASSES = [
    ("2D", "DIM = 2"), ("3D", "DIM = 3"), ("chain", "GRAPH = 0"), ("graph", "GRAPH = 1"),
    ("chain centred", "a chain's constraints, RULE = 0"), ("chain pairwise", "a chain's constraints, RULE = 1"),
    ("chain serial", "a chain's constraints on the serial pass (order serial, ARCH = 0)"),
    ("chain pipelined", "a chain's constraints on the pipelined pass (order redblack, ARCH = 1)"),
    ("chain pipelined K=1", "the pipelined pass with one node per unit"),
    ("chain pipelined slot-bound", "the pipelined pass with sweeps set by their slots, not the pipe's latency "
                                   "(floor(K/2) + 2 > LP + 4)"),
    ("previous serial", "projection = previous on the serial pass or a graph's rods"),
    ("previous pipelined", "projection = previous on a pipelined pass"),
    ("pipe steps>1", "a pipelined pass whose root and dividers take several iterations a stage (PIPE_STEPS > 1)"),
    ("mantissa serial", "the normalised distance datapath (MANTISSA > 0) on a chain's serial pass"),
    ("mantissa pipelined", "the normalised distance datapath on a chain's pipelined pass"),
    ("mantissa graph", "the normalised distance datapath on a graph's rods"),
    ("mantissa springs", "a spring's length and direction on the normalised datapath"),
    ("mantissa previous", "projection = previous on the normalised datapath"),
    ("graph order serial", "a graph's rods in the scene's order (the serial pass, ARCH = 0)"),
    ("graph order redblack", "a graph's rods by colour on the pipelined pass (graph_stream, ARCH = 1)"),
    ("graph colours>1", "a pipelined graph whose rods take several colours (drains between them)"),
    ("K=1", "a chain of one node per unit"), ("M=1", "a chain of one unit"), ("M>1", "a chain of several units"),
    ("no constraints", "EN_CONSTRAINTS = 0"), ("chain springs", "EN_SPRINGS on a chain"), ("graph springs", "spring edges"),
    ("graph rods only", "a graph without springs"),
    ("ground x", "GROUND_AXIS = 0"), ("ground y", "GROUND_AXIS = 1"), ("ground z", "GROUND_AXIS = 2"),
    ("ground above", "GROUND_ABOVE = 1"), ("ground below", "GROUND_ABOVE = 0"),
    *gen_effects.fuzz_class_rows(),
    ("impulse", "the mouse's impulse form"), ("grab", "the mouse's grab form"), ("no mouse", "EN_MOUSE = 0"),
    ("sqrt narrow", "SQRT_BITS < W - 1"), ("sqrt full", "SQRT_BITS = W - 1"),
    ("div narrow", "DIV_BITS < W - 1"), ("div full", "DIV_BITS = W - 1"),
    ("W=32", "the widest word"), ("W<=16", "a narrow word"), ("ITER>1", "several constraint passes"),
    ("SUBSTEPS>1", "several substeps"),
    ("chain pinned rod end", "a pinned node of a constrained chain"),
    ("chain held rod end", "a node of a constrained chain held by the grab"),
    ("graph pinned rod end", "a pinned end of a rod or strut"), ("graph held rod end", "a rod end held by the grab"),
    ("3D graph pinned rod end", "the same in 3D"), ("3D graph held rod end", "the same in 3D"),
    ("coincident", "every node on one point at the start (zero lengths)"),
    ("initial velocity", "the whole body moving at the start"),
    ("random resets", "reset at random cycles in the middle of frames"),
]
SLOTS = 3   # the forced scenes of every build: 0 a pinned rod end, 1 a held rod end, 2 coincident nodes


def builds_for(seed, extra):
    """The fixed builds, then `extra` drawn ones: the first len(PLAN) of them by PLAN."""
    rng = random.Random(f"builds-{seed}")
    out = []
    for i in range(extra):
        plan = PLAN[i] if i < len(PLAN) else None
        for attempt in range(100):   # a draw the RTL does not build (edge word wider than W, ...) is drawn again
            b = random_build(rng, plan)
            params, timing = probe_params(b)
            if params:
                break
        else:
            sys.exit(f"FAIL lockstep: no RTL build drawn for {plan and plan['name']}")
        b["params"] = params
        b["slot_bound"] = timing["stream_slot_bound"]
        b["plan"] = plan["name"] if plan else "random"
        out.append(b)
    fixed = []
    for p in FIXED_BUILDS:
        params = read_build(p)
        fixed.append(dict(params, params=params, plan=p, slot_bound=flow_hwgen.info(p)["timing"]["stream_slot_bound"]))
    return fixed + out


def scene_info(path, why=None, timing=None):
    """strand info's parameters for a scene file, or None if the RTL does not build it (why, a list, gets the reason;
    timing, a dict, the build's timing: model/timing.c)."""
    try:
        info = flow_hwgen.info(path)
    except Failure as e:
        info, reason = None, str(e)
    if timing is not None and info:
        timing.update(info["timing"])
    if why is not None and not (info and info["rtl"]):
        why.append(info["why"] if info else reason)
    return info["params"] if info and info["rtl"] else None


def probe_params(build):
    """(the parameters hwgen derives for the scenes of a drawn build (from its slot-0 scene), or None; its timing)."""
    path = os.path.join(ROOT, BUILD, "fuzz", "probe.scene")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(scene_text(build, 0, 0)[0])
    timing = {}
    return scene_info(path, timing=timing), timing


def length(x):
    """A length as a scene line writes it: six decimals, or ten significant digits where six
    decimals would write 0 (a rest below 5e-7, at a wide fraction such as F = 26)."""
    return f"{x:.6f}" if f"{x:.6f}" != "0.000000" else f"{x:.10g}"


def scene_text(build, seed, slot):
    """A valid scene for `build`, its run-time values drawn from `seed`: a chain or a graph, 2D or 3D.
    slot (the scene's rank among its build's scenes) forces a class: 0 a pinned rod end, 1 a rod end
    held by the grab (and the whole body moving), 2 every node on one point.
    Returns the text and what it holds (facts for the coverage)."""
    rng = random.Random(f"scene-{seed}")
    w, f = build["W"], build["F"]
    dim = build["DIM"]
    graph = build["GRAPH"]
    facts = {"pinned_rod_end": False, "held_rod_end": False, "coincident": False, "velocity": False,
             "order": "redblack" if build.get("ORDER") else "serial", "slot_bound": bool(build.get("slot_bound"))}
    span = 2.0 ** (w - f - 1)           # the format's range is +-span
    lsb = 2.0 ** -f
    n = build["M"] * build["K"]
    if graph:
        n = max(n, 2)
    reach = span / 4                    # keep the body well inside the range
    vec = lambda v: " ".join(f"{x:.6f}" for x in v[:dim])
    step = [rng.uniform(-1, 1) * reach / max(n, 1) for _ in range(3)]
    if rng.random() < 0.1 or slot == 2:
        step = [0.0, 0.0, 0.0]          # every node on one point: zero lengths
    start = [rng.uniform(-reach, reach) - step[k] * n / 2 for k in range(3)]
    rest = max(sum(abs(x) for x in step[:dim]), 64 * lsb) * rng.uniform(0.5, 1.6)
    frames = rng.randint(3, 10)
    lines = [f"; random scene, seed {seed}", "[scene]", f"name = fuzz_{seed}", f"dim = {dim}",
             "[format]", f"width = {w}", f"frac = {f}", f"sqrt_bits = {build['SQRT_BITS']}", f"div_bits = {build['DIV_BITS']}",
             f"mantissa = {build.get('MANTISSA', 0)}",
             f"pipe_steps = {build.get('PIPE_STEPS', 1)}",
             "[time]", "dt = 1", f"frames = {frames}", f"substeps = {build['SUBSTEPS']}", f"iterations = {build['ITER']}"]
    pins = sorted(rng.sample(range(n), rng.randint(0, min(3, n))))
    nodes = [[start[k] + i * step[k] + (rng.uniform(-1, 1) * rest / 2 if graph and slot != 2 else 0) for k in range(3)]
             for i in range(n)]
    if slot == 2 and not graph:
        facts["coincident"] = True
    if graph and slot == 2:
        facts["coincident"] = True
    # the ends of distance constraints: every node of a constrained chain; a graph's rod and strut ends
    rod_ends = set()
    edges = []
    if graph:
        kinds = (["rod", "strut"] if build["EN_CONSTRAINTS"] else []) + (["spring"] if build.get("EN_SPRINGS") else [])
        # the edge count is the build's (E_RODS, E_SPRINGS are build parameters); the pairs are the
        # scene's, or in the red/black order the build's (their colours, COLOURS, are a parameter)
        extra = (build["M"] * 7 + build["K"] * 3 + build["W"]) % (n + 1)
        pick = random.Random(f"pairs-{n}-{build['W']}-{extra}") if build.get("ORDER") else rng
        pairs = [(i, i + 1) for i in range(n - 1)] + [tuple(pick.sample(range(n), 2)) for _ in range(extra)]
        if kinds:
            for i, (a, b) in enumerate(pairs):
                edges.append((a, b, kinds[i % len(kinds)]))
                if kinds[i % len(kinds)] != "spring":
                    rod_ends |= {a, b}
    elif build["EN_CONSTRAINTS"] and n > 1:
        rod_ends = set(range(n))
    held = None
    if slot == 0 and rod_ends:           # a rod end pinned
        pins = sorted(set(pins) | {rng.choice(sorted(rod_ends))})
    if slot == 1 and build["EN_MOUSE"] and build.get("GRAB") and rod_ends:
        # the grab takes the free node nearest the pointer, the lowest index on ties: the
        # pointer on the lowest rod end, which is free, takes it for sure
        held = min(rod_ends)
        pins = [p for p in pins if p != held]
    facts["pinned_rod_end"] = bool(set(pins) & rod_ends)
    if graph:
        # nodes near a line, so lengths stay small; edges between random pairs, every node on one
        lines += ["[graph]"]
        lines += [f"node = {vec(p)}" for p in nodes]
        for a, b, kind in edges:
            # coincident nodes have no initial distance: their rest length is given (also where
            # the ends are apart by less than the digits written: a short rest at a wide fraction)
            given = rng.random() < 0.5 or slot == 2 or vec(nodes[a]) == vec(nodes[b])
            rest_e = f" {length(rng.uniform(0.5, 1.5) * rest)}" if given else ""
            lines.append(f"edge = {a} {b} {kind}{rest_e}")
    else:
        lines += ["[chain]", f"units = {build['M']}", f"nodes_per_unit = {build['K']}",
                  f"start = {vec(start)}", f"step = {vec(step)}", f"rest = {length(rest)}"]
    if pins:
        lines.append("pinned = " + " ".join(map(str, pins)))
    if rng.random() < 0.3 or slot == 1:  # the whole body starts moving
        lines.append(f"velocity = {vec([rng.uniform(-1, 1) * reach / 20 for _ in range(3)])}")
        facts["velocity"] = True
    if build["EN_GRAVITY"]:  # the effects table's gravity, drawn here (its row says so): mostly downward
        g = rng.uniform(0, reach / 50) * build["SUBSTEPS"] ** 2
        lines += ["[gravity]", f"accel = {vec([rng.uniform(-0.3, 0.3) * g, -g, rng.uniform(-0.3, 0.3) * g])}"]
    if build["EN_CONSTRAINTS"]:
        lines += ["[constraints]", f"rule = {['centred', 'pairwise'][build['RULE']]}", f"order = {facts['order']}"]
        if build.get("PROJECTION"):
            lines.append("projection = previous")
    if build.get("EN_SPRINGS"):
        # ks h^2 / m up to 0.5 (h = 1 / substeps): from soft to near the stability bound
        sub = build["SUBSTEPS"]
        lines += ["[springs]", f"ks = {rng.uniform(0.01, 0.5) * sub * sub:.6f}", f"kd = {rng.uniform(0, 0.2) * sub:.6f}"]
    if build.get("EN_GROUND"):
        # a boundary through the body, so that nodes hit it from the start
        ax = build["GROUND_AXIS"]
        mid = start[ax] + step[ax] * n / 2
        normal = ("+" if build["GROUND_ABOVE"] else "-") + "xyz"[ax]
        lines += ["[ground]", f"normal = {normal}", f"level = {mid + rng.uniform(-1, 1) * abs(step[ax]) * n / 2:.6f}",
                  f"radius = {rng.uniform(0, 4 * lsb):.6f}", f"friction = {rng.uniform(0, 1):.4f}"]
    if build["EN_MOUSE"]:
        box = min(rng.uniform(rest, 4 * rest + 8 * lsb), reach)
        lines += ["[mouse]", f"box = {vec([box] * 3)}"]
        lines += ["mode = grab"] if build.get("GRAB") else [f"impulse = {rng.uniform(-rest, rest):.6f}"]
        frame = 0
        if held is not None:
            # the button goes down on the held node's start and stays down (the pointer moving) two frames
            lines.append(f"event = 0 {vec(nodes[held])} 1")
            lines.append(f"event = 1 {vec([x + rng.uniform(-1, 1) * rest / 4 for x in nodes[held]])} 1")
            facts["held_rod_end"] = True
            frame = 2
        while frame < frames:
            p = [rng.uniform(-reach, reach) for _ in range(3)]
            if rng.random() < 0.5 and n:         # aim at a node's start
                p = nodes[rng.randrange(n)]
            lines.append(f"event = {frame} {vec(p)} {rng.randint(0, 1)}")
            frame += rng.randint(1, 3)
    # the effects table's keys, from a generator of their own: into their section (after its
    # header when the scene has it, else a section of their own at the end)
    for section, keys in gen_effects.fuzz_lines(random.Random(f"effects-{seed}"), build, lsb, reach).items():
        at = lines.index(f"[{section}]") + 1 if f"[{section}]" in lines else None
        if at is None:
            lines += [f"[{section}]"] + keys
        else:
            lines[at:at] = keys
    return "\n".join(lines) + "\n", facts


def classes_of(p, facts, resets=0):
    """The classes one scene covers: p the parameters hwgen derived from it, facts what scene_text put in it."""
    c = {"2D" if p["DIM"] == 2 else "3D", "graph" if p["GRAPH"] else "chain"}
    c.update(gen_effects.fuzz_classes(p))   # the effects table's
    rods = p["EN_CONSTRAINTS"]
    if p["GRAPH"]:
        if rods:
            c.add("graph order redblack" if p["ARCH"] else "graph order serial")
            if p["ARCH"] and p["COLOURS"] > 1:
                c.add("graph colours>1")
            if p["ARCH"] and p["PIPE_STEPS"] > 1:
                c.add("pipe steps>1")
            if p["MANTISSA"]:
                c.add("mantissa graph")
        c.add("graph springs" if p["EN_SPRINGS"] else "graph rods only" if rods else "no constraints")
    else:
        c.add("K=1" if p["K"] == 1 else "")
        c.add("M=1" if p["M"] == 1 else "M>1")
        if rods:
            c.add(["chain centred", "chain pairwise"][p["RULE"]])
            c.add("chain pipelined" if p["ARCH"] else "chain serial")
            if p["MANTISSA"]:
                c.add("mantissa pipelined" if p["ARCH"] else "mantissa serial")
            if p["ARCH"] and p["PIPE_STEPS"] > 1:
                c.add("pipe steps>1")
            if p["ARCH"] and p["K"] == 1:
                c.add("chain pipelined K=1")
            if facts.get("slot_bound"):
                c.add("chain pipelined slot-bound")
        if p["EN_SPRINGS"]:
            c.add("chain springs")
    if rods and p["PROJECTION"]:
        c.add("previous pipelined" if p["ARCH"] else "previous serial")
    if not rods:
        c.add("no constraints")
    if p["EN_SPRINGS"] and p["MANTISSA"]:
        c.add("mantissa springs")
    if rods and p["PROJECTION"] and p["MANTISSA"]:
        c.add("mantissa previous")
    if p["EN_GROUND"]:
        c.add("ground " + "xyz"[p["GROUND_AXIS"]])
        c.add("ground above" if p["GROUND_ABOVE"] else "ground below")
    c.add(("grab" if p["GRAB"] else "impulse") if p["EN_MOUSE"] else "no mouse")
    if (rods and not p["MANTISSA"]) or p["EN_SPRINGS"]:   # the root and the divider in use
        c.add("sqrt full" if p["SQRT_BITS"] == p["W"] - 1 else "sqrt narrow")
        c.add("div full" if p["DIV_BITS"] == p["W"] - 1 else "div narrow")
    if p["W"] == 32:
        c.add("W=32")
    if p["W"] <= 16:
        c.add("W<=16")
    if rods and p["ITER"] > 1:
        c.add("ITER>1")
    if p["SUBSTEPS"] > 1:
        c.add("SUBSTEPS>1")
    body = "graph" if p["GRAPH"] else "chain"
    if rods and facts["pinned_rod_end"]:
        c.add(f"{body} pinned rod end")
        if p["GRAPH"] and p["DIM"] == 3:
            c.add("3D graph pinned rod end")
    if rods and facts["held_rod_end"] and p["EN_MOUSE"] and p["GRAB"]:
        c.add(f"{body} held rod end")
        if p["GRAPH"] and p["DIM"] == 3:
            c.add("3D graph held rod end")
    if facts["coincident"]:
        c.add("coincident")
    if facts["velocity"]:
        c.add("initial velocity")
    if resets:
        c.add("random resets")
    c.discard("")
    return c


def fewest_scenes(builds, seed):
    """The fewest scenes (from scene 0 on) whose classes, as written, cover CLASSES (random resets aside:
    the harness reports those), and the classes missed if no number up to 10 per build does."""
    want = {name for name, _ in CLASSES} - {"random resets"}
    got = set()
    for i in range(10 * len(builds)):
        b = builds[i % len(builds)]
        _, facts = scene_text(b, seed * 100000 + i, i // len(builds))
        got |= classes_of(b["params"], facts)
        if want <= got:
            return i + 1, []
    return None, [name for name, _ in CLASSES if name in want - got]


def build_harness(scene, build, rtl="rtl", order=None, fault="", deep=False, fast=False):
    """The harness of a scene's build (shared by every scene of that build): (path, None),
    or (None, why) when it did not build. deep: the build that traces every signal; fast:
    compiled without optimisation (a batch of runs: most of them short, so that the compile
    is most of their time and -O0 halves it, while it slows a run about four times)."""
    try:
        return flow_build.harness_for(scene, harness_dir(build, fault, deep, fast), rtl, order,
                                      opt="fast" if fast else "", trace="deep" if deep else "top"), None
    except Failure as e:
        log = os.path.join(ROOT, harness_dir(build, fault, deep, fast), "build.log")
        return None, (open(log).read() if "verilator" in str(e) and os.path.exists(log) else "") + str(e)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("n", nargs="?", type=int, default=50, help="scenes to run")
    ap.add_argument("--seed", type=int, default=1, help="base seed (scene i has seed base*100000 + i)")
    ap.add_argument("--builds", type=int, default=len(PLAN),
                    help=f"drawn builds beside the three fixed ones (the first {len(PLAN)} by PLAN)")
    ap.add_argument("--partial", action="store_true", help="run N scenes even if they cannot cover every class")
    ap.add_argument("--coverage-json", help="write the classes covered to this file")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--replay", type=int, help="run the one scene with this seed")
    ap.add_argument("--scene", action="append", default=[], help="also run this scene (PATH, or PATH:FRAMES)")
    ap.add_argument("--redblack", action="store_true",
                    help="also run every --scene in the red/black order (a chain's pipelined build)")
    ap.add_argument("--harness-for", metavar="SCENE", help="build (if needed) the harness for SCENE's build, print its path")
    ap.add_argument("--order", choices=["serial", "redblack"], help="with --harness-for: the build of SCENE in this order")
    ap.add_argument("--deep-trace", action="store_true",
                    help="with --harness-for: the build that traces every signal of the core (make wave's)")
    ap.add_argument("--faults", action="store_true", help="check the planted faults are caught")
    ap.add_argument("--reset-seeds", type=int, default=0, help="random-initialisation seeds for the first --scene")
    ap.add_argument("--late-pins-scene", action="append", default=[], metavar="PATH:SEEDS",
                    help="also run this scene with --late-pins, once for each of the seeds 1 .. SEEDS")
    ap.add_argument("--scenes-only", action="store_true",
                    help="write the N scenes and check that 'strand info' derives each one's build; build and run nothing")
    a = ap.parse_args()

    if a.harness_for:
        exe, why = build_harness(a.harness_for, read_build(a.harness_for, a.order), order=a.order, deep=a.deep_trace)
        if exe is None:
            sys.stderr.write(why + "\n")
            return 1
        print(os.path.relpath(exe, ROOT))
        return 0

    fuzz = os.path.join(BUILD, "fuzz")
    os.makedirs(os.path.join(ROOT, fuzz), exist_ok=True)
    seeds = [a.replay] if a.replay is not None else [a.seed * 100000 + i for i in range(a.n)]
    builds = builds_for(a.seed, a.builds) if seeds else []
    coverage = a.replay is None and a.n > 0
    if coverage:
        fewest, gaps = fewest_scenes(builds, a.seed)
        if fewest is None or a.n < fewest:
            need = (f"N >= {fewest} with --builds {a.builds}" if fewest else
                    f"builds for {', '.join(gaps)}" + (f" (--builds >= {len(PLAN)}: the planned builds)" if a.builds < len(PLAN) else
                                                       " (PLAN in scripts/lockstep_fuzz.py has none)"))
            print(f"{'note:' if a.partial else 'FAIL'} lockstep coverage: {a.n} scenes on {len(builds)} builds cannot cover "
                  f"every class; that needs {need}" + ("" if a.partial else " (--partial runs them anyway)"))
            if not a.partial:
                return 1
    jobs = []   # (label, harness args, build, planted fault or "", order or "")
    for spec in a.scene:  # PATH or PATH:FRAMES
        path, _, frames = spec.partition(":")
        for order in [""] + (["redblack"] if a.redblack else []):
            jobs.append((f"scene {path}" + (f" --order {order}" if order else ""),
                         [path] + (["--frames", frames] if frames else []) + (["--order", order] if order else []),
                         read_build(path, order or None), "", order))
    if a.reset_seeds and a.scene:
        first = a.scene[0].partition(":")[0]
        for k in range(a.reset_seeds):
            jobs.append((f"reset-seed {k + 1}", [first, "--frames", "20", "+verilator+rand+reset+2",
                                                  f"+verilator+seed+{k + 1}"], read_build(first), "", ""))
        jobs.append(("reset-zero", [first, "--frames", "20"], read_build(first), "", ""))
    for spec in a.late_pins_scene:  # its PINs drawn into the init walk, a seed a draw
        path, _, n = spec.partition(":")
        if not (n or "1").isdigit() or int(n or 1) < 1 or not os.path.isfile(os.path.join(ROOT, path)):
            print(f"lockstep_fuzz: --late-pins-scene {spec}: want PATH:SEEDS, an existing scene and a count >= 1")
            return 2
        for k in range(int(n or 1)):
            jobs.append((f"late-pins seed {k + 1} {path}", [path, "--quiet", "--late-pins", "--seed", str(k + 1)],
                         read_build(path), "", ""))
    if a.faults:
        fs = "tb/scenes/chain_q10_8.scene"
        for kind in faults.FAULTS:
            order, scene = faults.ORDER.get(kind, ""), faults.SCENE.get(kind, fs)
            jobs.append((f"fault {kind}", [scene, "--quiet", "--expect-fault", kind] + (["--order", order] if order else []),
                         read_build(scene, order or None), kind, order))
    scene_facts = {}   # label -> (the build's parameters, what the scene holds)
    for s in seeds:
        i = s - a.seed * 100000            # the scene's index: its build, and its rank among that build's scenes
        build = builds[i % len(builds)]
        slot = i // len(builds)
        path = os.path.join(fuzz, f"seed_{s}.scene")
        text, facts = scene_text(build, s, slot)
        with open(os.path.join(ROOT, path), "w") as fh:
            fh.write(text)
        why = []
        params = scene_info(path, why)
        if params != build["params"]:   # the scene must be the build's: its harness is shared
            print(f"FAIL lockstep fuzz seed {s} ({path}): 'strand info' derives another build than its harness's "
                  f"({build['plan']}): {params or why[0]}")
            return 1
        label = f"fuzz seed {s}"
        scene_facts[label] = (params, facts)
        # every third scene of a build also gets resets at random cycles in the middle of frames,
        # every second one some of its PINs during the init walk
        args = [path, "--quiet", "--seed", str(s), "--resets", str(2 if slot % 3 == 0 else 0)]
        args += ["--late-pins"] if slot % 2 else []
        args += ["+verilator+rand+reset+2", f"+verilator+seed+{s % 100000 + 1}"]
        jobs.append((label, args, params, "", ""))

    if a.scenes_only:
        print(f"PASS lockstep scenes: {len(seeds)} scenes of seed {a.seed} written to {fuzz}/, each its build's")
        return 0
    # one harness per build (cached by build_harness.sh), built two at a time
    needed = {}
    for label, args, build, fault, order in jobs:
        needed.setdefault((build_key(build), fault), (args[0], build, order))
    def make(item):
        (key, fault), (path, build, order) = item
        rtl = "rtl"
        if fault:  # a copy of rtl/ with the fault planted
            rtl = os.path.join(ROOT, BUILD, "faults", fault)
            faults.plant(fault, rtl)
        return key, build_harness(path, build, rtl, order or None, fault, fast=True)
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for key, (exe, why) in ex.map(make, needed.items()):
            if exe is None:
                print(why)
                print(f"FAIL lockstep: the harness for build {key} did not build")
                return 1

    def one(job):
        label, args, build, fault, _ = job
        harness = os.path.join(ROOT, harness_dir(build, fault, fast=True), "harness")
        workdir = os.path.join(ROOT, BUILD, "fuzz")  # where a failing run leaves mismatch.fst
        rc, out, figures = flow_run.harness(harness, args[0], args[1:], cwd=workdir)
        return job, rc, out, figures

    failed = passed = 0
    fuzz_runs = {True: 0, False: 0}   # the random scenes' runs: passed (True), failed
    digests = {}
    covered = {}   # class -> scenes that covered it
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for (label, args, build, fault, _), rc, out, figures in ex.map(one, jobs):
            lines = flow_run.verdicts(out)
            if label in scene_facts:
                for c in classes_of(*scene_facts[label], resets=figures.get("resets", 0)):
                    covered[c] = covered.get(c, 0) + 1
            if label.startswith("reset-"):
                digests[label] = figures.get("output_digest")
                if rc != 0:
                    failed += 1
                    print("\n".join(lines) or out)
                continue
            if label.startswith("fuzz seed"):
                fuzz_runs[rc == 0] += 1
            if rc == 0:
                passed += 1
                print(lines[-1] if lines else f"PASS {label}", flush=True)
            else:
                failed += 1
                print("\n".join(lines[:12]) or out)
                if label.startswith("fuzz seed"):
                    s = label.split()[-1]
                    print(f"FAIL lockstep {label} ({args[0]}): replay with "
                          f"'scripts/lockstep_fuzz.py --replay {s} --seed {a.seed} --builds {a.builds}'")
                else:
                    print(f"FAIL lockstep {label}")
    if coverage:
        missing = [name for name, _ in CLASSES if name not in covered]
        report = ", ".join(f"{name} {covered[name]}" for name, _ in CLASSES if name in covered)
        print(f"  classes covered (scenes): {report}")
        if missing:
            failed += 0 if a.partial else 1
            print(f"{'note:' if a.partial else 'FAIL'} lockstep coverage: {len(seeds)} scenes on {len(builds)} builds missed "
                  f"{len(missing)} of {len(CLASSES)} classes: {', '.join(missing)}")
        else:
            passed += 1
            print(f"PASS lockstep coverage: {len(seeds)} scenes on {len(builds)} builds covered every one of the "
                  f"{len(CLASSES)} classes (seed {a.seed}; the fewest scenes that do: {fewest})")
        if a.coverage_json:
            with open(a.coverage_json, "w") as fh:
                json.dump({"seed": a.seed, "scenes": len(seeds), "builds": len(builds), "fewest": fewest,
                           "harnesses": [harness_dir(b["params"], fast=True) for b in builds],
                           "covered": covered, "classes": CLASSES, "plans": [b["plan"] for b in builds],
                           "failed": failed, "fuzz_passed": fuzz_runs[True], "fuzz_failed": fuzz_runs[False]}, fh, indent=1)
    if digests:
        same = len(set(digests.values())) == 1 and None not in digests.values()
        print(("PASS" if same else "FAIL") + f" reset defines everything: {len(digests) - 1} random-initialisation seeds and "
              f"zeros give {'the same' if same else 'different'} outputs in every cycle ({digests.get('reset-zero')})")
        failed += 0 if same else 1
        passed += 1 if same else 0
    print(f"lockstep: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
