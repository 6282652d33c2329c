#!/usr/bin/env python3
"""effects.py - what each effect costs strand_core, and that a switched-off effect costs nothing.

Run from the repository root (scripts/effects.mk does):

    effects.py doc  [--out docs/effects.md] [--frames N] [options]
        For the body of scripts/synth.py (COMMON parameters, the 4x5 chain) with no
        effect, and with each effect of EFFECTS: a scene, `strand hwgen` on it (the
        parameters `make sim` would build), Yosys (generic `synth`, `synth_ice40
        -dsp`, `synth_ecp5`) on those parameters, and the Verilator harness in
        lockstep for N frames, whose measured cycles per frame must equal the
        formula hwgen exports (hw_cycles_per_frame); then writes the document.
    effects.py test [--effect NAME ...] [--frames N] [options]
        The gating check, on a small body, generic Yosys only. For each effect X and
        a scene S that names it: (a) S built with X's enable parameter(s) forced to
        0 (every other parameter as hwgen derives it from S, and the harness still
        writes X's registers and drives its inputs), (b) S without X's lines, the
        build that never had X. (a) and (b) must have the same generic cells, type
        by type, pass lockstep with the same cycles per frame and give the same
        outputs in every cycle; S as built must cost more cells than (b). One PASS
        or FAIL line per effect; exit status 1 on any FAIL.
    effects.py list
        the effects, one per line: name, Verilog parameters, scene lines.

Options: --rtl-dir DIR (default rtl: every DIR/*.v is read, so a scratch copy can be
checked), --build DIR (default build/effects), --jobs N. The generated headers, the
strand tool and the model library are make's (build/, or $BUILD).

Every step is one of scripts/strandflow's: `strand info` (hwgen.info), the parameter
files (hwgen.param_files), the harness (build.harness), its run and figures (run), and
Yosys (synth.yosys, the flow of make synth). Everything is cached under --build: per
parameter set, each Yosys flow and each harness build keeps a stamp holding a hash of
its commands, the tool version and the contents of its sources; a stale or missing stamp
runs it again. Standard library only.
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import os
import subprocess
import sys
import threading
import time

sys.dont_write_bytecode = True  # no scripts/__pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_effects  # noqa: E402  (the effects table: its rows join EFFECTS)
import synth  # noqa: E402  (make synth's builds: the body of the document)
from strandflow import build as flow_build, hwgen as flow_hwgen, run as flow_run, synth as flow_synth  # noqa: E402
from strandflow.core import GEN, LIBSTRAND, ROOT, STRAND, Failure, file_digest, tool_version  # noqa: E402

# ---- the effects: one row each ----
#
# name     short name (test output, --effect)
# title    what the document calls it
# scene    the lines that turn the effect on, by scene section: S is the body plus
#          these; "without the effect" is the body without them
# params   the strand_core parameters the effect sets, as hwgen must derive them from S
#          (these may differ from the body's: a graph has one unit of every node)
# enable   (optional) the parameters the gating test forces to 0; default: every EN_*
#          among params. A row with none (a body property: DIM, GRAPH) is measured
#          by `doc` but has no gating test.
# context  (optional) lines both S and the scene without the effect carry (an effect
#          that needs another one to act); its cost is measured over them
# replace  (optional) sections of the body that S has instead (None: S drops it)
#
# scene, replace and params may be functions of the body (a dict of strand_core
# parameters, below), for rows whose lines depend on its size. The values are
# run-time constants: they change no cell and no cycle, but the lockstep runs use
# them, so they must make a valid scene on both bodies.
GRAVITY = {"gravity": ["accel = 0.5 -9.8"]}
PAIRWISE = {"constraints": ["rule = pairwise"]}


def chain_3d(b):
    return {"chain": [f"units = {b['M']}", f"nodes_per_unit = {b['K']}", "start = -4 8 0", "step = 1.5 0 0.5",
                      "rest = 1.2", "pinned = 0"]}


def graph_of(b):
    """The body's chain as a graph: the same nodes, a rod on each link."""
    n = b["M"] * b["K"]
    return {"chain": None,
            "graph": [f"node = {-4 + 1.5 * i:g} 8" for i in range(n)]
            + [f"edge = {i} {i + 1} rod 1.2" for i in range(n - 1)] + ["pinned = 0"]}


EFFECTS = [
    dict(name="mouse", title="mouse impulse",
         scene={"mouse": ["box = 2 2", "impulse = 1", "event = 0 -2.5 8 1", "event = 2 -2.5 8 0",
                          "event = 3 0.5 8 1"]},
         params={"EN_MOUSE": 1}),
    dict(name="grab", title="mouse, grab form",
         scene={"mouse": ["mode = grab", "box = 2 2", "event = 0 -2.5 8 1", "event = 1 -2 9 1", "event = 3 -1 9.5 0"]},
         params={"EN_MOUSE": 1, "GRAB": 1}),
    dict(name="springs", title="damped springs",
         scene={"springs": ["ks = 40", "kd = 0.8"]},
         params={"EN_SPRINGS": 1}),
    dict(name="ground", title="ground collision with friction",
         scene={"ground": ["normal = +y", "level = 7.5", "radius = 0.1", "friction = 0.5"]},
         context=GRAVITY,  # the chain falls onto it
         params={"EN_GROUND": 1, "GROUND_AXIS": 1, "GROUND_ABOVE": 1}),
    dict(name="centred", title="constraints, centred rule (RULE 0)",
         scene={"constraints": ["rule = centred"]},
         params={"EN_CONSTRAINTS": 1, "RULE": 0}),
    dict(name="pairwise", title="constraints, pairwise rule (RULE 1)",
         scene=PAIRWISE,
         params={"EN_CONSTRAINTS": 1, "RULE": 1}),
    dict(name="centred_pipe", title="constraints, centred rule, pipelined (RULE 0, ARCH 1: red/black)",
         scene={"constraints": ["rule = centred", "order = redblack"]},
         params={"EN_CONSTRAINTS": 1, "RULE": 0, "ARCH": 1}),
    dict(name="pairwise_pipe", title="constraints, pairwise rule, pipelined (RULE 1, ARCH 1: red/black)",
         scene={"constraints": ["rule = pairwise", "order = redblack"]},
         params={"EN_CONSTRAINTS": 1, "RULE": 1, "ARCH": 1}),
    dict(name="previous", title="projection = previous, centred rule (PROJECTION 1: toward_prev)",
         scene={"constraints": ["projection = previous"]},
         context={"constraints": ["rule = centred"]},  # it changes how a constraint is corrected
         params={"EN_CONSTRAINTS": 1, "RULE": 0, "PROJECTION": 1}, enable=["PROJECTION"]),
    dict(name="previous_pairwise", title="projection = previous, pairwise rule (PROJECTION 1: toward_prev)",
         scene={"constraints": ["projection = previous"]},
         context=PAIRWISE,
         params={"EN_CONSTRAINTS": 1, "RULE": 1, "PROJECTION": 1}, enable=["PROJECTION"]),
    dict(name="previous_pipe", title="projection = previous, centred rule, pipelined (PROJECTION 1, ARCH 1: toward_prev_pipe)",
         scene={"constraints": ["projection = previous"]},
         context={"constraints": ["rule = centred", "order = redblack"]},
         params={"EN_CONSTRAINTS": 1, "RULE": 0, "ARCH": 1, "PROJECTION": 1}, enable=["PROJECTION"]),
    dict(name="3d", title="3D (a z lane)",
         scene={"scene": ["dim = 3"]}, replace=chain_3d,
         params={"DIM": 3}),
    dict(name="graph", title="graph body (edge memory; one unit)",
         scene={}, replace=graph_of,
         context=PAIRWISE,  # a graph's rods are constraints
         params=lambda b: {"GRAPH": 1, "M": 1, "K": b["M"] * b["K"], "E_RODS": b["M"] * b["K"] - 1}),
] + gen_effects.effect_rows()  # the effects table's rows (scripts/gen_effects.py: wind, ...)

# The run-time part of every body: a horizontal chain pinned at node 0, its links
# longer than their rest length, so that constraints and springs have work to do.
BODY_RUNTIME = {
    "time": ["dt = 0.25"],
    "chain": ["start = -4 8", "step = 1.5 0", "rest = 1.2", "pinned = 0"],
}


def doc_body():
    """The body of docs/resources.md: synth.py's 4x5 build (the table's defaults)."""
    c = flow_hwgen.table_defaults()
    c.update(synth.BUILD_MAP[synth.CHECK_CONFIG][0])
    m, k = c["M"], c["K"]
    build = {"W": c["W"], "F": c["F"], "M": m, "K": k, "SQRT_BITS": c["SQRT_BITS"], "DIV_BITS": c["DIV_BITS"],
             "ITER": c["ITER"], "SUBSTEPS": c["SUBSTEPS"]}
    return f"{synth.CHECK_CONFIG} chain", build


# The gating test's body: small, so that Yosys and Verilator take seconds.
TEST_BUILD = {"W": 16, "F": 8, "M": 2, "K": 2, "SQRT_BITS": 6, "DIV_BITS": 6, "ITER": 2, "SUBSTEPS": 2}

SECTION_ORDER = ["scene", "format", "time", "chain", "graph", "mouse", "constraints", "springs", "ground"] + \
    [e["name"] for e in gen_effects.EFFECTS]


def body_sections(build):
    """Scene sections for a body given as strand_core parameters."""
    b = build
    return {
        "format": [f"width = {b['W']}", f"frac = {b['F']}", f"sqrt_bits = {b['SQRT_BITS']}", f"div_bits = {b['DIV_BITS']}"],
        "time": [f"substeps = {b['SUBSTEPS']}", f"iterations = {b['ITER']}"] + BODY_RUNTIME["time"],
        "chain": [f"units = {b['M']}", f"nodes_per_unit = {b['K']}"] + BODY_RUNTIME["chain"],
    }


def field(row, key, build, default=None):
    """A row's field, called on the body when it is a function."""
    v = row.get(key, default)
    return v(build) if callable(v) else v


def enable_params(row, build):
    return row.get("enable") or [p for p in field(row, "params", build) if p.startswith("EN_")]


def resolved(row, build):
    """The row with its fields evaluated on this body."""
    return dict(row, **{k: field(row, k, build, {}) for k in ("scene", "params", "context", "replace")})


# ---- scenes ----

def merge(*parts):
    """Sections in order; a later part adds lines to a section, or replaces it when it
    comes from a row's `body`."""
    out = {}
    for part, replace in parts:
        for sec, lines in part.items():
            if replace or sec not in out:
                out[sec] = list(lines)
            else:
                out[sec] += lines
    return out


def scene_text(name, sections, frames):
    secs = merge((sections, False), ({"scene": [f"name = {name}"], "time": [f"frames = {frames}"]}, False))
    order = sorted(secs, key=lambda s: SECTION_ORDER.index(s) if s in SECTION_ORDER else len(SECTION_ORDER))
    lines = [f"; written by scripts/effects.py: {name}"]
    for sec in order:
        lines.append(f"[{sec}]")
        lines += secs[sec]
    return "\n".join(lines) + "\n"


def scenes_of(row, build):
    """(S, S without the effect) as section dicts."""
    without = merge((body_sections(build), False), (field(row, "context", build, {}), False))
    with_ = merge((without, False), (field(row, "scene", build), False))
    for sec, lines in field(row, "replace", build, {}).items():
        if lines is None:
            with_.pop(sec, None)
        else:
            with_[sec] = list(lines)
    return with_, without


# ---- the steps (scripts/strandflow) ----

def top_parameters():
    """The parameter names of strand_core, in order (the table of scripts/gen_params.py)."""
    return [p["name"] for p in flow_hwgen.param_table()]


class Gen:
    """`strand info` on one scene: the build strand_core needs for it and its formula."""

    def __init__(self, scene_path, top_params):
        info = flow_hwgen.info(scene_path)
        if not info["rtl"]:
            raise Failure(f"strand info {scene_path}: {info['why']}")
        self.params = {n: info["params"][n] for n in top_params}
        self.formula = info["timing"]["cycles_per_frame"]


def build_files(params):
    return flow_hwgen.param_files(params, writer="scripts/effects.py")


def pkey(params):
    return hashlib.sha1(repr(sorted(params.items())).encode()).hexdigest()[:12]


FLOWS = ["generic", "ice40", "ecp5"]


def run_yosys(flow, params, d, srcs):
    """One flow of make synth on one parameter set (the core as synthesised: DEBUG = 0)
    unless cached; returns flat cell counts by type."""
    flow_synth.yosys(d, flow, list(dict(params, DEBUG=0).items()), srcs, "written for scripts/effects.py")
    return flow_synth.cells(d, flow)


def build_harness(d, vh, h, o):
    """The harness of one build unless cached; returns its path. One Verilator job per
    build: effects runs --jobs builds at once. Compiled without optimisation (opt="fast"):
    a run here is a few frames, whose cycles and digest do not depend on it, so the
    compile is most of the time (about half of it at -O0)."""
    return flow_build.harness(d, vh, h, rtl=o.rtl_dir, jobs=1, opt="fast")


def run_harness(exe, scene_path, frames, cwd, as_built=False):
    """Lockstep for `frames` frames: (cycles per frame, output digest). Failure on a
    mismatch, or when the frames do not all take the same number of cycles. as_built: the
    model follows the build (an effect switched off there), not the scene."""
    rc, out, r = flow_run.harness(exe, scene_path, ["--frames", str(frames)] + (["--as-built"] if as_built else []),
                                  cwd=cwd, timeout=3600)
    if rc != 0:
        lines = [ln for ln in out.splitlines() if ln.strip()]
        raise Failure(f"lockstep failed ({os.path.relpath(os.path.abspath(cwd), ROOT)}): " + "; ".join(lines[:3]))
    if r.get("verdict") != "pass" or "output_digest" not in r:
        raise Failure(f"the harness wrote no passing figures (verdict {r.get('verdict')!r})")
    if r["cycles_per_frame_min"] != r["cycles_per_frame"]:
        raise Failure(f"frames took {r['cycles_per_frame_min']} to {r['cycles_per_frame']} cycles")
    return r["cycles_per_frame"], r["output_digest"]


# ---- running many jobs ----

class Jobs:
    """Each distinct job once (by key), up to n at a time; results or Failures by key."""

    def __init__(self, n):
        self.ex = concurrent.futures.ThreadPoolExecutor(max_workers=n)
        self.futures = {}
        self.lock = threading.Lock()

    def submit(self, key, fn, *args):
        with self.lock:
            if key not in self.futures:
                self.futures[key] = self.ex.submit(fn, *args)
            return self.futures[key]

    def get(self, key):
        return self.futures[key].result()

    def close(self):
        self.ex.shutdown(wait=True)


def rtl_sources(rtl_dir):
    srcs = sorted(glob.glob(os.path.join(rtl_dir, "*.v")))
    if not srcs:
        raise Failure(f"no Verilog sources in {rtl_dir}")
    return srcs


def sources_digest(srcs):
    return file_digest([os.path.relpath(s, ROOT) if s.startswith(ROOT) else s for s in srcs])


# ---- the gating test ----

def cmd_test(o):
    rows = [resolved(r, TEST_BUILD) for r in EFFECTS if not o.effect or r["name"] in o.effect]
    for r in rows:
        if not enable_params(r, TEST_BUILD):
            print(f"effects {r['name']}: no enable switch ({', '.join(r['params'])} is a property of the body), "
                  "so no gating test; make effects measures it")
    rows = [r for r in rows if enable_params(r, TEST_BUILD)]
    top = top_parameters()
    base = os.path.join(o.build, "test")
    jobs = Jobs(o.jobs)
    t0 = time.time()
    plans = []
    try:
        # scenes and their parameters first (quick), then every Yosys run and harness build at once
        for r in rows:
            s_sec, b_sec = scenes_of(r, TEST_BUILD)
            d = os.path.join(base, "scenes", r["name"])
            os.makedirs(d, exist_ok=True)
            paths = {}
            for tag, secs in (("S", s_sec), ("b", b_sec)):
                paths[tag] = os.path.join(d, f"{tag}.scene")
                with open(paths[tag], "w") as f:
                    f.write(scene_text(f"effects_{r['name']}_{tag}", secs, o.frames))
            plan = dict(row=r, paths=paths, problems=[])
            try:
                gS = Gen(paths["S"], top)
                gB = Gen(paths["b"], top)
            except Failure as e:
                plan["problems"].append(str(e))
                plans.append(plan)
                continue
            for p, v in r["params"].items():
                if gS.params.get(p) != v:
                    plan["problems"].append(f"the table says S sets {p}={v}, hwgen derives {p}={gS.params.get(p)}")
            enable = enable_params(r, TEST_BUILD)
            for p in enable:
                if gB.params.get(p) != 0:
                    plan["problems"].append(f"without the effect's lines hwgen still derives {p}={gB.params.get(p)}")
            pA = dict(gS.params)
            for p in enable:
                pA[p] = 0
            plan.update(gS=gS, gB=gB, pA=pA, enable=enable)
            plans.append(plan)
        # the harness builds take longest: they go first
        for plan in plans:
            if "gS" not in plan:
                continue
            for tag, params, gen in (("a", plan["pA"], plan["gS"]), ("b", plan["gB"].params, plan["gB"])):
                vh, h = build_files(params)
                k = hashlib.sha1((vh + h).encode()).hexdigest()[:12]
                plan[f"harness_{tag}"] = k
                jobs.submit(("harness", k), build_harness, os.path.join(base, "vl_" + k), vh, h, o)
        for plan in plans:
            if "gS" not in plan:
                continue
            for params in (plan["pA"], plan["gB"].params, plan["gS"].params):
                k = pkey(params)
                jobs.submit(("yosys", k), run_yosys, "generic", params, os.path.join(base, "p_" + k), o.srcs)

        failed = 0
        records = []  # for --json: the figures of every row, for docs/effects.md
        for plan in plans:
            r = plan["row"]
            why = list(plan["problems"])
            detail = {}
            if "gS" in plan:
                try:
                    ca = jobs.get(("yosys", pkey(plan["pA"])))
                    cb = jobs.get(("yosys", pkey(plan["gB"].params)))
                    cs = jobs.get(("yosys", pkey(plan["gS"].params)))
                    ta, tb_, ts = sum(ca.values()), sum(cb.values()), sum(cs.values())
                    detail.update(ta=ta, tb=tb_, ts=ts, types=len(cb))
                    if ca != cb:
                        diff = sorted(t for t in set(ca) | set(cb) if ca.get(t, 0) != cb.get(t, 0))
                        why.append(f"generic cells (a) {ta} != (b) {tb_}; types that differ: "
                                   + ", ".join(f"{t} {ca.get(t, 0)}/{cb.get(t, 0)}" for t in diff[:6]))
                    if not ts > tb_:
                        why.append(f"with the effect on: {ts} generic cells, not more than the {tb_} without it")
                except Failure as e:
                    why.append(str(e))
                try:
                    ea = jobs.get(("harness", plan["harness_a"]))
                    eb = jobs.get(("harness", plan["harness_b"]))
                    rd = os.path.join(base, "runs", r["name"])
                    cyc_a, dig_a = run_harness(ea, plan["paths"]["S"], o.frames, os.path.join(rd, "a"), as_built=True)
                    cyc_b, dig_b = run_harness(eb, plan["paths"]["b"], o.frames, os.path.join(rd, "b"), as_built=True)
                    detail.update(cyc_a=cyc_a, cyc_b=cyc_b, same_out=dig_a == dig_b)
                    if cyc_a != cyc_b:
                        why.append(f"cycles per frame (a) {cyc_a} != (b) {cyc_b}")
                    if cyc_b != plan["gB"].formula:
                        why.append(f"(b) measured {cyc_b} cycles per frame, hw_cycles_per_frame says {plan['gB'].formula}")
                    if dig_a != dig_b:
                        why.append(f"the outputs differ: (a) digest {dig_a}, (b) {dig_b} (X's registers or inputs leak)")
                except Failure as e:
                    why.append(str(e))
            name = r["name"]
            en = ", ".join(f"{p}=0" for p in plan.get("enable", []))
            records.append(dict(name=name, title=r["title"], forced=en, why=why,
                                same_params="pA" in plan and plan["pA"] == plan["gB"].params, **detail))
            if why:
                failed += 1
                print(f"FAIL effects {name}: " + "; ".join(why))
            else:
                same_params = plan["pA"] == plan["gB"].params
                print(f"PASS effects {name}: S with {en} = S without it: {detail['ta']} generic cells, all "
                      f"{detail['types']} types alike{' (the same parameters)' if same_params else ''}; "
                      f"{detail['cyc_a']} cycles per frame alike (= formula); outputs alike in every cycle; "
                      f"the effect on costs {detail['ts'] - detail['tb']} cells")
    finally:
        jobs.close()
    if o.json:
        with open(o.json, "w") as f:
            json.dump(dict(body=TEST_BUILD, frames=o.frames, rows=records), f, indent=1)
    print(f"effects test: {len(plans) - failed} passed, {failed} failed in {time.time() - t0:.0f} s "
          f"(RTL {o.rtl_dir}, {o.frames} frames each)")
    return 1 if failed else 0


# ---- the document ----

def fmt(n):
    return f"{n:,}"


def signed(n):
    return "0" if n == 0 else f"{'+' if n > 0 else '-'}{abs(n):,}"


def figures(counts):
    """The figures the document reports, from the three flows' cell counts."""
    g, i, e = counts["generic"], counts["ice40"], counts["ecp5"]
    pick = synth.pick
    return {
        "cells": sum(g.values()),
        "gen_ff": flow_synth.generic_classes(g)["ff"],
        "ice_lut": pick(i, lambda t: t == "SB_LUT4"),
        "ice_ff": pick(i, lambda t: t.startswith("SB_DFF")),
        "ice_carry": pick(i, lambda t: t == "SB_CARRY"),
        "ice_ram": pick(i, lambda t: t.startswith("SB_RAM40_4K")),
        "ice_dsp": pick(i, lambda t: t == "SB_MAC16"),
        "ecp_lut": pick(e, lambda t: t == "LUT4"),
        "ecp_mux": pick(e, lambda t: t in ("PFUMX", "L6MUX21")),
        "ecp_ff": pick(e, lambda t: t == "TRELLIS_FF"),
        "ecp_carry": pick(e, lambda t: t == "CCU2C"),
        "ecp_dsp": pick(e, lambda t: t == "MULT18X18D"),
        "ecp_ram": pick(e, lambda t: t == "DP16KD"),
    }


def git_note(rtl_dir):
    """'as committed in <hash>' when the RTL directory is the repository's and clean."""
    try:
        if os.path.realpath(rtl_dir) != os.path.realpath(os.path.join(ROOT, "rtl")):
            return ""
        st = subprocess.run(["git", "status", "--porcelain", "--", "rtl"], cwd=ROOT, capture_output=True, text=True)
        if st.returncode != 0 or st.stdout.strip():
            return " (uncommitted changes in rtl/)" if st.returncode == 0 else ""
        h = subprocess.run(["git", "log", "-1", "--format=%h", "--", "rtl"], cwd=ROOT, capture_output=True, text=True)
        return f" (rtl/ as of commit {h.stdout.strip()})" if h.returncode == 0 and h.stdout.strip() else ""
    except OSError:
        return ""


def cmd_doc(o):
    top = top_parameters()
    body_name, body = doc_body()
    base = os.path.join(o.build, "doc")
    jobs = Jobs(o.jobs)
    t0 = time.time()
    rows = [dict(name="baseline", title="baseline: the body, no effect", scene={}, params={})] + EFFECTS
    rows = [resolved(r, body) for r in rows]
    built = {}  # scene text -> (path, Gen)

    def export(tag, secs, row_params):
        text = scene_text(f"effects_{tag}", secs, o.frames)
        if text not in built:
            d = os.path.join(base, "scenes")
            os.makedirs(d, exist_ok=True)
            path = os.path.join(d, f"{tag}.scene")
            with open(path, "w") as f:
                f.write(text)
            g = Gen(path, top)
            for n, v in body.items():
                if n not in row_params and g.params.get(n) != v:
                    raise Failure(f"{path}: hwgen derives {n}={g.params.get(n)}, the body has {n}={v}")
            built[text] = (path, g)
        return built[text]

    try:
        for r in rows:
            s_sec, b_sec = scenes_of(r, body)
            r["S"] = export(r["name"], s_sec, r["params"])
            r["B"] = export(r["name"] + "_without", b_sec, {}) if r is not rows[0] else r["S"]
            for p, v in r["params"].items():
                if r["S"][1].params.get(p) != v:
                    raise Failure(f"{r['name']}: the table says the scene sets {p}={v}, hwgen derives {p}={r['S'][1].params.get(p)}")
        # every build: three flows and a harness each; the slowest first
        todo = {}
        for path, g in built.values():
            todo.setdefault(pkey(g.params), (path, g))  # named after its first scene
        for k, (path, g) in todo.items():
            d = os.path.join(base, "p_" + k)
            vh, h = build_files(g.params)
            jobs.submit(("harness", k), build_harness, os.path.join(d, "vl"), vh, h, o)
        for flow in ["ice40", "ecp5", "generic"]:
            for k, (path, g) in todo.items():
                jobs.submit((flow, k), run_yosys, flow, g.params, os.path.join(base, "p_" + k), o.srcs)
        res = {}
        errors = []
        for k, (path, g) in todo.items():
            try:
                counts = {f: jobs.get((f, k)) for f in FLOWS}
                exe = jobs.get(("harness", k))
                cyc, _ = run_harness(exe, path, o.frames, os.path.join(base, "p_" + k, "run"))
                if cyc != g.formula:
                    raise Failure(f"{path}: the RTL measured {cyc} cycles per frame, hw_cycles_per_frame "
                                  f"(model/hwgen.c) says {g.formula}")
                fig = figures(counts)
                fig.update(cycles=cyc, formula=g.formula)
                res[k] = fig
                print(f"effects {os.path.basename(path)[:-6]:18s} {fig['cells']:7d} generic cells, "
                      f"{cyc} cycles per frame (measured = formula)", flush=True)
            except Failure as e:
                errors.append(str(e))
        if errors:
            for e in errors:
                print(f"FAIL effects: {e}", file=sys.stderr)
            print(f"FAIL effects: {o.out} not written", file=sys.stderr)
            return 1
    finally:
        jobs.close()
    write_doc(o, rows, res, body_name, body)
    print(f"effects: wrote {o.out} in {time.time() - t0:.0f} s")
    return 0


def over(r):
    """What a row's cost is measured over."""
    parts = [f"[{s}]" for s in r["context"]]
    return "the baseline" + (" with " + " and ".join(parts) if parts else "")


def write_doc(o, rows, res, body_name, body):
    def fig(row, which):
        return res[pkey(row[which][1].params)]

    base = fig(rows[0], "S")
    L = []
    w = L.append
    yver = tool_version("yosys")
    vver = tool_version("verilator")
    srcs = [os.path.relpath(os.path.abspath(s), ROOT) for s in o.srcs]
    w("# What each effect costs")
    w("")
    w("Generated by `make effects` (scripts/effects.py); do not edit by hand. Tools: "
      f"{yver}; {vver}. RTL: {', '.join(f'`{s}`' for s in srcs)}, sha256 "
      f"`{sources_digest(o.srcs)[:16]}`{git_note(o.rtl_dir)}.")
    w("")
    w("Every effect of `strand_core` sits behind a `generate` switch, so a scene pays only for the "
      "effects it names. This is each effect's price in cells and in cycles per frame, "
      f"measured on one body: the {body_name} of [resources.md](resources.md), "
      + ", ".join(f"{n}={v}" for n, v in body.items())
      + f" ({body['M'] * body['K']} nodes), with no effect (the baseline) and with each effect.")
    w("")
    w("## Cost of each effect")
    w("")
    w("Each figure is the build with the effect minus the build without it (the baseline, or the baseline "
      "with what the effect needs to act, as the third column says); the baseline row gives absolute values.")
    w("")
    keys = ["cells", "ice_lut", "ice_ff", "ecp_lut", "ecp_ff", "ecp_dsp", "cycles"]
    w("| effect | parameters it sets | measured over | generic cells | iCE40 LUT4 | iCE40 DFF | ECP5 LUT4 | ECP5 FF "
      "| ECP5 MULT18X18D | cycles per frame |")
    w("|---|---|---|--:|--:|--:|--:|--:|--:|--:|")
    w(f"| {rows[0]['title']} | "
      + ", ".join(f"{n}={v}" for n, v in rows[0]["S"][1].params.items() if n not in body)
      + " | (absolute) | " + " | ".join(fmt(base[k]) for k in keys) + " |")
    for r in rows[1:]:
        s, b = fig(r, "S"), fig(r, "B")
        w(f"| {r['title']} | {', '.join(f'{n}={v}' for n, v in r['params'].items())} | {over(r)} | "
          + " | ".join(signed(s[k] - b[k]) for k in keys) + " |")
    w("")
    free = [r["title"] for r in rows[1:] if fig(r, "S")["cycles"] == fig(r, "B")["cycles"]]
    costly = [f"{r['title']} {signed(fig(r, 'S')['cycles'] - fig(r, 'B')['cycles'])}" for r in rows[1:]
              if fig(r, "S")["cycles"] != fig(r, "B")["cycles"]]
    w("Cycles per frame: " + (", ".join(free) + " add none" if free else "every effect adds some")
      + ("; " + ", ".join(costly) if costly else "") + ".")
    w("")
    prev = [r for r in rows[1:] if r["params"].get("PROJECTION")]
    if prev:
        w("`projection = previous` (SHAKE, docs/model.md) stores nothing extra: the previous positions it "
          "needs are the ones Verlet keeps, read from port A with the positions (the centred sequencer holds "
          "them in its window of three nodes beside the positions). It replaces `toward` by `toward_prev`, which "
          "keeps a `toward` for its fallback and adds a multiplier, a root and a divider of its own (in the "
          "pipelined pass `toward_prev_pipe` keeps a `toward_pipe` and adds two pipelined roots, DIM pipelined "
          "unit dividers and 4 DIM + 1 multipliers): "
          + "; ".join(f"{r['title']}: {signed(fig(r, 'S')['cells'] - fig(r, 'B')['cells'])} generic cells and "
                      f"{signed(fig(r, 'S')['cycles'] - fig(r, 'B')['cycles'])} cycles per frame "
                      f"({fig(r, 'S')['cycles'] / fig(r, 'B')['cycles']:.2f}x)" for r in prev)
          + ".")
        w("")
    cols = {"cells": "generic cells", "ice_lut": "iCE40 LUT4", "ice_ff": "iCE40 DFF", "ecp_lut": "ECP5 LUT4",
            "ecp_ff": "ECP5 FF", "ecp_dsp": "ECP5 MULT18X18D"}
    neg = [f"{r['title']}: {cols[k]} {signed(fig(r, 'S')[k] - fig(r, 'B')[k])}" for r in rows[1:] for k in cols
           if fig(r, "S")[k] < fig(r, "B")[k]]
    if neg:
        w("A negative figure (" + "; ".join(neg) + ") is no saving: each build is synthesised on its own, and "
          "the mapper's result for the rest of the design differs between the two builds (compare the rows "
          "of the table below), so the figures of one family are not additive.")
        w("")
    w("## Every build, absolute")
    w("")
    w("| build | generic cells | of which flip-flops | iCE40 SB_LUT4 | DFF | SB_CARRY | SB_MAC16 | SB_RAM40_4K "
      "| ECP5 LUT4 | PFUMX + L6MUX21 | TRELLIS_FF | CCU2C | MULT18X18D | DP16KD | cycles per frame, measured | formula |")
    w("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    listed = set()
    builds = [(r["title"], r["S"]) for r in rows] + [(f"{r['title']}: without it", r["B"]) for r in rows]
    for title, (path, g) in builds:
        k = pkey(g.params)
        if k in listed:
            continue
        listed.add(k)
        f_ = res[k]
        w(f"| {title} | " + " | ".join(fmt(f_[c]) for c in
                                       ["cells", "gen_ff", "ice_lut", "ice_ff", "ice_carry", "ice_dsp", "ice_ram",
                                        "ecp_lut", "ecp_mux", "ecp_ff", "ecp_carry", "ecp_dsp", "ecp_ram", "cycles",
                                        "formula"]) + " |")
    w("")
    w("## How it was measured")
    w("")
    w("For each row, scripts/effects.py writes a scene: the body below plus the effect's lines (the baseline "
      "has none), and runs `strand hwgen` on it, which derives the `strand_core` parameters exactly as "
      "`make sim` does. The script checks that they are the body's and that the effect sets the parameters "
      "the table names. Then, on those parameters:")
    w("")
    w("- Yosys, as `make synth` runs it ([resources.md](resources.md)): `synth -top strand_core` and `stat` "
      "(generic cells, summed over the module hierarchy; `check -assert`, no latches), `synth_ice40 -dsp` "
      "(SB_LUT4, DFF = every SB_DFF* kind, SB_CARRY, SB_MAC16, SB_RAM40_4K) and `synth_ecp5` (LUT4, the "
      "PFUMX and L6MUX21 muxes, TRELLIS_FF, CCU2C, MULT18X18D, DP16KD); no place and route.")
    w(f"- Cycles per frame: the `make sim` harness (tb/harness.cpp: the RTL under Verilator in lockstep with "
      f"the cycle model, every output in every cycle) runs the scene for {o.frames} frames and reports the "
      "cycles from `step` to `frame_done`, which must be the same in every frame. The script fails unless "
      "that equals `hw_cycles_per_frame()` (model/timing.c, the formula of [architecture.md](architecture.md)), "
      "which `strand hwgen` exports; both columns above are printed from the run.")
    w("")
    w("The body (its run-time values change no cell and no cycle; the lockstep runs use them):")
    w("")
    w("```ini")
    w(open(rows[0]["S"][0]).read().rstrip())
    w("```")
    w("")
    w("Each effect adds these lines (and the lines of the third column, in both builds):")
    w("")
    w("| effect | scene lines | with | parameters |")
    w("|---|---|---|---|")

    for r in rows[1:]:
        w(f"| {r['title']} | {show(r['scene'], r['replace'])} | {show(r['context'])} "
          f"| {', '.join(f'{n}={v}' for n, v in r['params'].items())} |")
    w("")
    w("## The check that a switched-off effect costs nothing")
    w("")
    w("`make test-effects` (part of `make test`) builds, for each effect, on a small body (generic Yosys "
      "only): (a) a scene that names the effect, with the effect's enable switch forced to 0 and every other "
      "parameter as hwgen derives it, the harness still writing the effect's registers and driving its "
      "inputs; (b) the same scene without the effect's lines. (a) and (b) must have the same generic cells, "
      "type by type, the same measured cycles per frame and the same outputs in every cycle (both in "
      "lockstep with the cycle model, which is told the effect is off); the scene with the effect on must "
      "cost more cells than (b). `scripts/effects.py test --rtl-dir DIR` runs the same check on a copy of "
      "the RTL.")
    w("")
    if getattr(o, "test_json", None):
        try:
            with open(o.test_json) as f:
                t = json.load(f)
        except (OSError, ValueError) as e:
            raise Failure(f"{o.test_json}: cannot read the test results: {e}")
        b = t["body"]
        w(f"The last run (this `make effects`), on the body W={b['W']}, F={b['F']}, M={b['M']}, K={b['K']}, "
          f"SQRT_BITS={b['SQRT_BITS']}, DIV_BITS={b['DIV_BITS']}, ITER={b['ITER']}, SUBSTEPS={b['SUBSTEPS']}, "
          f"{t['frames']} frames in lockstep each. An effect switched off costs no cell and no cycle when "
          "(a) equals (b):")
        w("")
        w("| effect | switched off | generic cells (a) / (b) | cycles per frame (a) / (b) | outputs in every cycle "
          "| cells when on, over (b) | result |")
        w("|---|---|--:|--:|---|--:|---|")
        for rec in t["rows"]:
            cells = f"{fmt(rec['ta'])} / {fmt(rec['tb'])}" if "ta" in rec else "-"
            cyc = f"{fmt(rec['cyc_a'])} / {fmt(rec['cyc_b'])}" if "cyc_a" in rec else "-"
            outs = ("alike" if rec["same_out"] else "differ") if "same_out" in rec else "-"
            on = signed(rec["ts"] - rec["tb"]) if "ts" in rec else "-"
            res_ = "PASS" if not rec["why"] else "FAIL: " + "; ".join(rec["why"])
            w(f"| {rec['title']} | {rec['forced']}{' (the same parameters as (b))' if rec['same_params'] else ''} "
              f"| {cells} | {cyc} | {outs} | {on} | {res_} |")
        w("")
        w("Where (a) has the same parameters as (b), the equal cell counts follow from the build; the row "
          "still checks that the effect's registers and inputs change no output and no cycle, and that the "
          "effect, when on, is really behind its switch. 3D and graph bodies have no switch to turn off: "
          "they are properties of the body, measured above.")
        w("")
    w("Regenerate with `make effects` (results are cached in `build/effects/` by the contents of the RTL, "
      "the headers and the parameters; a rerun on unchanged sources only writes this file).")
    text = "\n".join(L) + "\n"
    tmp = o.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, o.out)


# ---- command line ----

def show(scene, replace=None, md=True):
    """A row's lines, short: a replaced section by its first lines and its length."""
    q = (lambda t: f"`{t}`") if md else (lambda t: t)
    parts = [f"{q(f'[{sec}]')} " + ", ".join(q(ln) for ln in ls) for sec, ls in scene.items() if ls]
    for sec, ls in (replace or {}).items():
        if ls is None:
            parts.append(f"no {q(f'[{sec}]')}")
        else:
            parts.append(f"{q(f'[{sec}]')} instead: " + ", ".join(q(ln) for ln in (ls if len(ls) <= 6 else ls[:3]))
                         + (f", ... ({len(ls)} lines)" if len(ls) > 6 else ""))
    return "; ".join(parts) or "-"


def cmd_list():
    _, body = doc_body()
    for r in EFFECTS:
        r = resolved(r, body)
        print(f"{r['name']:9s} {' '.join(f'{n}={v}' for n, v in r['params'].items()):40s} "
              f"{show(r['scene'], r['replace'], md=False)}" + (f"; with {show(r['context'], md=False)}" if r["context"] else ""))
    return 0


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                epilog="See the top of scripts/effects.py for details.")
    sub = p.add_subparsers(dest="cmd", required=True)
    for name in ("doc", "test"):
        s = sub.add_parser(name)
        s.add_argument("--rtl-dir", default="rtl", help="the RTL to measure: every DIR/*.v (default rtl)")
        s.add_argument("--build", default="build/effects", help="cache and work directory")
        s.add_argument("--jobs", type=int, default=2)
        s.add_argument("--frames", type=int, default=3 if name == "doc" else 6, help="frames each lockstep run")
        if name == "doc":
            s.add_argument("--out", default="docs/effects.md")
            s.add_argument("--test-json", help="the results of `effects.py test --json`, shown in the document")
        else:
            s.add_argument("--json", help="also write the results here (for `doc --test-json`)")
            s.add_argument("--effect", action="append", default=[], metavar="NAME",
                           help="only this effect (repeatable); names: " + ", ".join(r["name"] for r in EFFECTS))
    sub.add_parser("list")
    o = p.parse_args()
    if o.cmd == "list":
        return cmd_list()
    if o.jobs < 1:
        p.error("--jobs must be at least 1")
    if o.frames < 1:
        p.error("--frames must be at least 1")
    if not os.path.isdir(o.rtl_dir):
        p.error(f"--rtl-dir {o.rtl_dir}: not a directory")
    if not os.path.isfile(os.path.join(o.rtl_dir, "strand_core.v")):
        p.error(f"--rtl-dir {o.rtl_dir}: no strand_core.v in it")
    for path in (STRAND, LIBSTRAND, os.path.join(GEN, "strand_regs.vh")):
        if not os.path.exists(path):
            p.error(f"{os.path.relpath(path, ROOT)} does not exist (make model builds it)")
    if o.cmd == "doc" and not os.path.isdir(os.path.dirname(os.path.abspath(o.out))):
        p.error(f"--out {o.out}: its directory does not exist")
    if o.cmd == "test":
        bad = [n for n in o.effect if n not in {r["name"] for r in EFFECTS}]
        if bad:
            p.error(f"--effect {bad[0]}: no such effect (names: {', '.join(r['name'] for r in EFFECTS)})")
    try:
        o.srcs = rtl_sources(o.rtl_dir)
        return cmd_doc(o) if o.cmd == "doc" else cmd_test(o)
    except Failure as e:
        print(f"FAIL effects: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
