#!/usr/bin/env python3
"""accuracy.py - what accuracy costs in time and area: the sweep behind docs/accuracy.md.

    accuracy.py run  [--jobs N] [--out docs/accuracy.md] [--img docs/img]
        run every point of the study that is not cached, the Yosys builds and the
        RTL cycle samples, then write the document and its plots from the results.
    accuracy.py test [--jobs N] [--doc docs/accuracy.md]
        the quick slice for `make test`: runs a few points and checks the machinery
        (cache, cycle formula, checkers against known answers) and the claims the
        document makes (targets, recommended points, Small Steps verdicts); one
        PASS/FAIL line per check, exit status 1 on any failure.

A point is a scene with overrides (format, SQRT_BITS, DIV_BITS, substeps, iterations,
rule) and an analytic check. It is written as a derived scene file and run by
build/sweep (model/sweep.c), which prints one JSON line. Results are cached in
build/accuracy/cache/<key>.json, the key hashing the point, the derived scene text
and the build/sweep binary (the model code a point runs), so a re-run computes only what is new or changed.
Standard library, numpy and matplotlib only.
"""
import argparse
import concurrent.futures
import glob
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import synth  # noqa: E402  (make synth's builds: the 4x5 at other formats)
from strandflow import build as flow_build, hwgen as flow_hwgen, run as flow_run, synth as flow_synth  # noqa: E402
from strandflow.core import BUILD, ROOT, Failure, digest, file_digest, gen_files  # noqa: E402
ADIR = os.path.join(BUILD, "accuracy")
CACHE = os.path.join(ADIR, "cache")
SWEEP = os.path.join(BUILD, "sweep")
RTL_SRC = sorted(os.path.relpath(f, ROOT) for f in glob.glob(os.path.join(ROOT, "rtl", "*.v")))  # one module per file

# ---- the study ----

FORMATS = [(18, 8), (24, 12), (32, 16), (32, 12)]      # (W, F)
DEFAULT_FMT = (32, 16)
POW2 = [1, 2, 4, 8, 16, 32]
BITS = {(32, 16): [8, 12, 14, 15, 16, 17, 18, 20, 22, 24, 26, 28, 31],
        (18, 8): [5, 7, 8, 9, 10, 11, 12, 13, 14, 15, 17]}
SCENES = {
    "catenary": ("sim/scenes/catenary.scene", "catenary"),
    "pendulum": ("sim/scenes/pendulum_small.scene", "period"),
    "spring": ("sim/scenes/spring_pair.scene", "spring"),
    "energy": ("sim/scenes/pendulum_undamped.scene", "energy"),
    "swing": ("sim/scenes/swing_rope.scene", "none"),
    "hanging": ("sim/scenes/hanging_rope.scene", "none"),
    "ref002": ("sim/scenes/ref002_verlet.scene", "none"),
    "rope_rest": ("tb/bench/rope_rest.scene", "none"),
    "wind": ("tb/scenes/wind_rope.scene", "wind"),
}
# The rope in a wind (tb/scenes/wind_rope.scene, 12 nodes, 4 substeps x 4 iterations): long enough to
# come to rest along g + c w (drag's time constant 1/c = 1/3 s), in every format and at every MB
WIND_FRAMES = 240
# The normalised datapath's mantissa bits (the scene's `mantissa`; 0, the full-width root and divide,
# is the reference): the catenary, the hanging rope, the pendulum's period, the undamped pendulum's
# energy and the 1024-node rope at rest (64 substeps x 16 iterations: make bench's accurate row) at
# Q16.16, and the cells of a one-unit pipelined core (the centred rule, 256 nodes) at each
MANTISSAS = [6, 8, 10, 12, 14, 16, 17, 18, 20]
MANT_ROPE = dict(substeps=64, iterations=16)
MANT_BUILD = "m17_1x256_pipe"   # make synth's build whose cells and clock the table extends to every MB
# projection = previous against current on bodies of many links, at their cycles per frame:
# (scene, the points' fixed settings, substeps, iterations)
PROJECTION_GRID = [
    ("ref002", dict(damping=0), (8, 16, 32, 64), (1, 2, 4)),      # the reference-002 rope, undamped: energy is the method's
    ("catenary", dict(rule="centred"), (1, 2, 4, 8), (1, 2, 4, 8, 16)),
]
# Base of the one-knob sweeps: the catenary scene's own time settings.
BASE = dict(substeps=4, iterations=8, rule="centred")
# The targets of the issue for the default Q16.16 build (scene, field, bound, what).
TARGETS = [
    ("hanging", "stretch_final_fx", 0.1, "rest stretch of the hanging rope", "%"),
    ("pendulum", "check_fx.error_pct", 0.5, "pendulum period against 2 pi sqrt(L/g)", "%"),
    ("catenary", "check_fx.error_pct", 1.0, "catenary shape, largest node distance", "% of span"),
    ("energy", "check_fx.error_pct", 1.0, "energy drift of the undamped pendulum over 10^5 frames", "%"),
    ("energy", "check_fx.error_pct", 1.0, "the same, projection = previous (SHAKE)", "%",
     {"projection": "previous"}),
]


def target_kw(t):
    """A target's point settings beyond the scene's own (the sixth element, if any)."""
    return t[5] if len(t) > 5 else {}
SYNTH_MK = (4, 5)   # the build the cell counts are for (M units x K nodes)


def fmt_name(w, f):
    return f"Q{w - f}.{f}"


def point(scene, w=32, f=16, sqrt_bits=None, div_bits=None, substeps=None, iterations=None, rule=None, frames=None,
          order=None, projection=None, reverse=False, damping=None, mantissa=None):
    path, check = SCENES[scene]
    p = dict(scene=scene, path=path, check=check, width=w, frac=f, sqrt_bits=sqrt_bits or w - 1,
             div_bits=div_bits or w - 1, substeps=substeps, iterations=iterations, rule=rule, frames=frames,
             order=order)
    if projection:  # only when set, so that the other points keep their cache keys
        p["projection"] = projection
    if reverse:  # run back as long after the run (sweep --reverse)
        p["reverse"] = True
    if damping is not None:  # the scene's Verlet damping replaced
        p["damping"] = damping
    if mantissa:  # the normalised datapath; only when set, so that the other points keep their cache keys
        p["mantissa"] = mantissa
    return p


def study_points():
    pts = []
    # 1. the catenary: format x rule x iterations x substeps, full root and divider
    for (w, f) in FORMATS:
        for rule in ("centred", "pairwise"):
            for s in POW2:
                for i in POW2:
                    pts.append(point("catenary", w, f, substeps=s, iterations=i, rule=rule))
    # 2. SQRT_BITS and DIV_BITS, one at a time, at the base time settings
    for (w, f), bits in BITS.items():
        for b in bits:
            pts.append(point("catenary", w, f, sqrt_bits=b, **BASE))
            pts.append(point("catenary", w, f, div_bits=b, **BASE))
    # 3. the analytic references
    for (w, f) in FORMATS:
        for rule in ("centred", "pairwise"):
            for s in POW2:
                pts.append(point("pendulum", w, f, substeps=s, iterations=1, rule=rule))
        for s in (1, 2, 4, 8):
            pts.append(point("spring", w, f, substeps=s))
        for s in (2, 8, 32):
            pts.append(point("energy", w, f, substeps=s, iterations=1, rule="centred"))
    # 4. Small Steps: n substeps x 1 iteration against 1 substep x n iterations
    for (w, f) in [(32, 16), (18, 8)]:
        for rule in ("centred", "pairwise"):
            for n in POW2:
                pts.append(point("swing", w, f, substeps=n, iterations=1, rule=rule))
                pts.append(point("swing", w, f, substeps=1, iterations=n, rule=rule))
    # 5. the targets' own scenes at their own settings
    pts.append(point("hanging"))
    pts.append(point("pendulum"))
    pts.append(point("catenary"))
    pts.append(point("energy"))
    # 5b. projection = previous: the energy target and the energy table's Q16.16 rows
    pts.append(point("energy", projection="previous"))
    for s in (2, 8, 32):
        pts.append(point("energy", 32, 16, substeps=s, iterations=1, rule="centred", projection="previous"))
    # 5c. time reversibility: the undamped pendulum run forward, then back, in each projection
    pts.append(point("energy", reverse=True))
    pts.append(point("energy", projection="previous", reverse=True))
    # 5d. projection = previous against current on long bodies (PROJECTION_GRID)
    for scene, fixed, subs, iters in PROJECTION_GRID:
        for proj in (None, "previous"):
            for sub in subs:
                for it in iters:
                    pts.append(point(scene, substeps=sub, iterations=it, projection=proj, **fixed))
    # 6. the constraint order: red/black (the pipelined architecture) against the serial points of 1. and 5.
    for rule in ("centred", "pairwise"):
        for i in POW2:
            pts.append(point("catenary", substeps=BASE["substeps"], iterations=i, rule=rule, order="redblack"))
    pts.append(point("hanging", order="redblack"))
    # 7. the normalised datapath: every MB against the full width (mantissa 0: the points above)
    pts += mantissa_points()
    # 8. the rope in a wind: every format, both orders at Q16.16, and every MB
    pts += wind_points()
    return dedup(pts)


def wind_points():
    pts = [point("wind", w, f, frames=WIND_FRAMES) for (w, f) in FORMATS]
    pts.append(point("wind", frames=WIND_FRAMES, order="redblack"))
    pts += [point("wind", frames=WIND_FRAMES, mantissa=mb) for mb in MANTISSAS]
    return pts


def mantissa_points(mbs=None):
    """The points of the mantissa table, for MB in mbs (default MANTISSAS and 0, the full width)."""
    pts = []
    for mb in ([0] + MANTISSAS) if mbs is None else mbs:
        pts.append(point("catenary", mantissa=mb, **BASE))
        pts.append(point("hanging", mantissa=mb))
        pts.append(point("pendulum", mantissa=mb))
        pts.append(point("energy", mantissa=mb))
        pts.append(point("rope_rest", mantissa=mb, frames=200, **MANT_ROPE))
    return pts


def dedup(pts):
    seen, out = set(), []
    for p in pts:
        k = json.dumps(p, sort_keys=True)
        if k not in seen:
            seen.add(k)
            out.append(p)
    return out


# ---- derived scenes ----

def derive(p):
    """The scene text of a point: the scene file with its overrides written in."""
    want = {"format": {"width": p["width"], "frac": p["frac"], "sqrt_bits": p["sqrt_bits"], "div_bits": p["div_bits"]},
            "time": {}, "constraints": {}}
    if p["substeps"] is not None:
        want["time"]["substeps"] = p["substeps"]
    if p["iterations"] is not None:
        want["time"]["iterations"] = p["iterations"]
    if p["rule"] is not None:
        want["constraints"]["rule"] = p["rule"]
    if p.get("order"):
        want["constraints"]["order"] = p["order"]
    if p.get("projection"):
        want["constraints"]["projection"] = p["projection"]
    if p.get("damping") is not None:
        want["time"]["damping"] = p["damping"]
    if p.get("mantissa"):
        want["format"]["mantissa"] = p["mantissa"]
    fd, tmp = tempfile.mkstemp(prefix="derive-", suffix=".scene", dir=os.path.join(ROOT, BUILD))
    os.close(fd)
    try:
        flow_run.scene_set(p["path"], tmp, {f"{sec}.{k}": v for sec, keys in want.items() for k, v in keys.items()})
        with open(tmp) as fh:
            return fh.read()
    finally:
        os.remove(tmp)


_model_hash = None


def model_hash():
    global _model_hash
    if _model_hash is None:
        # The sweep binary holds exactly the model code a point runs (statically linked), so a
        # change elsewhere in model/ (the cycle model, the CLI) does not throw the cache away.
        h = hashlib.sha256()
        h.update(open(os.path.join(ROOT, SWEEP), "rb").read())
        _model_hash = h.hexdigest()
    return _model_hash


def point_key(p):
    h = hashlib.sha256()
    h.update(json.dumps(p, sort_keys=True).encode())
    h.update(derive(p).encode())
    h.update(model_hash().encode())
    return h.hexdigest()[:20]


def label(p):
    s = f"{p['scene']} {fmt_name(p['width'], p['frac'])}"
    if p["sqrt_bits"] != p["width"] - 1:
        s += f" sqrt{p['sqrt_bits']}"
    if p["div_bits"] != p["width"] - 1:
        s += f" div{p['div_bits']}"
    if p["substeps"] is not None:
        s += f" s{p['substeps']}"
    if p["iterations"] is not None:
        s += f" i{p['iterations']}"
    if p["rule"]:
        s += f" {p['rule']}"
    if p.get("order"):
        s += f" {p['order']}"
    if p.get("projection"):
        s += f" projection={p['projection']}"
    if p.get("damping") is not None:
        s += f" damping={p['damping']}"
    if p.get("mantissa"):
        s += f" mantissa={p['mantissa']}"
    return s


def run_point(p, use_cache=True):
    """The result of one point (a dict), from the cache or computed; 'cached' says which."""
    key = point_key(p)
    path = os.path.join(ROOT, CACHE, key + ".json")
    if use_cache and os.path.exists(path):
        with open(path) as fh:
            r = json.load(fh)
        r["cached"] = True
        return r
    scene_file = os.path.join(ROOT, ADIR, "scenes", key + ".scene")
    os.makedirs(os.path.dirname(scene_file), exist_ok=True)
    with open(scene_file, "w") as fh:
        fh.write(derive(p))
    cmd = [os.path.join(ROOT, SWEEP), scene_file, "--check", p["check"]] + (["--reverse"] if p.get("reverse") else [])
    if p["frames"]:
        cmd += ["--frames", str(p["frames"])]
    t0 = time.time()
    out = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:
        r = dict(error=(out.stderr or out.stdout).strip().splitlines()[-1] if (out.stderr or out.stdout).strip() else
                 f"sweep exited {out.returncode}")
    else:
        r = json.loads(out.stdout)
    r["point"] = p
    r["key"] = key
    r["seconds"] = round(time.time() - t0, 3)
    os.makedirs(os.path.join(ROOT, CACHE), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as fh:
        json.dump(r, fh)
    os.replace(tmp, path)
    r["cached"] = False
    return r


def run_all(pts, jobs, what="points"):
    """Run points in parallel with a progress line; returns results in the order of pts."""
    results = [None] * len(pts)
    lock = threading.Lock()
    state = dict(done=0, cached=0, t0=time.time())

    def one(i):
        r = run_point(pts[i])
        with lock:
            state["done"] += 1
            state["cached"] += r["cached"]
            d = state["done"]
            if d == len(pts) or d % 20 == 0:
                print(f"  {what}: {d}/{len(pts)} ({state['cached']} cached), {time.time() - state['t0']:.0f} s",
                      file=sys.stderr, flush=True)
        return i, r

    # longest first, so that the pool ends together
    order = sorted(range(len(pts)), key=lambda i: -((pts[i]["substeps"] or 4) * (pts[i]["iterations"] or 8)))
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
        for i, r in ex.map(one, order):
            results[i] = r
    return results


def get(r, field):
    v = r
    for k in field.split("."):
        if not isinstance(v, dict) or k not in v:
            return None
        v = v[k]
    return v


# ---- the cycle formula: model/timing.c, through `strand info` ----

EXACT = "exact within 1 %"  # constants_of() of a point whose constants all hold


def constants_of(p):
    """strand check --strict on a point's scene: "exact within 1 %", or its first warning (without
    the file:line), so that a row says when a constant it depends on rounds away or clips."""
    path = os.path.join(ROOT, ADIR, "scenes", point_key(p) + ".scene")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(derive(p))
    r = subprocess.run([os.path.join(ROOT, BUILD, "strand"), "check", path, "--strict"], capture_output=True, text=True)
    if r.returncode == 0:
        return EXACT
    warn = [ln.split("warning: ", 1)[1] for ln in r.stderr.splitlines() if "warning: " in ln]
    return warn[0].split(":")[0] if warn else r.stderr.strip().splitlines()[-1]


def cycles_of_scene(path):
    """Cycles per frame of a scene's build, as the one formula (model/timing.c) gives them."""
    try:
        return flow_hwgen.info(path)["timing"]["cycles_per_frame"]
    except (Failure, KeyError):
        return None


# ---- Yosys: cells of the 4x5 build ----

SYNTH_POINTS = [  # (W, F, SQRT_BITS, DIV_BITS, flows)
    (18, 8, 17, 17, ("generic", "ice40", "ecp5")),
    (24, 12, 23, 23, ("generic",)),
    (32, 16, 31, 31, ("generic", "ice40", "ecp5")),
    (32, 12, 31, 31, ("generic",)),
    (32, 16, 16, 31, ("generic",)),
    (32, 16, 24, 31, ("generic",)),
    (32, 16, 31, 16, ("generic",)),
    (32, 16, 31, 24, ("generic",)),
]


def cached_yosys(flow, prm, title, result):
    """One Yosys flow of strand_core with parameters prm through make synth's yosys_script (so that this
    document and docs/resources.md quote the same cells for the same build), or its cached result:
    result, a dict, gains the cells by type (by_type), the seconds and whether it was cached."""
    gen = os.path.join(ROOT, BUILD, "gen")
    srcs = [os.path.join(ROOT, x) for x in RTL_SRC]
    text = flow_synth.yosys_script(flow, prm, gen, srcs, title)
    key = digest(text, file_digest(srcs + gen_files(gen)))[:20]
    path = os.path.join(ROOT, CACHE, "synth_" + key + ".json")
    if os.path.exists(path):
        with open(path) as fh:
            r = json.load(fh)
        r["cached"] = True
        return r
    d_ = os.path.join(ROOT, ADIR, "synth", key)
    t0 = time.time()
    r = dict(result, flow=flow)
    try:
        flow_synth.yosys(d_, flow, prm, srcs, title, gen=gen)
    except Failure as e:
        r["error"] = str(e)
        return r
    r["seconds"] = round(time.time() - t0, 1)
    r["by_type"] = flow_synth.cells(d_, flow)
    with open(path, "w") as fh:
        json.dump(r, fh)
    r["cached"] = False
    return r


def synth_one(w, f, s, d, flow):
    """One flow of make synth's 4x5 build at another format."""
    prm = synth.params(synth.CHECK_CONFIG) + [("W", w), ("F", f), ("SQRT_BITS", s), ("DIV_BITS", d)]
    r = cached_yosys(flow, prm, f"the {synth.CHECK_CONFIG} build at W={w} F={f}",
                     dict(width=w, frac=f, sqrt_bits=s, div_bits=d))
    cells = r.get("by_type")
    if cells is not None:
        r["cells"] = sum(cells.values())
        if flow == "ice40":
            r["luts"] = cells.get("SB_LUT4", 0)
            r["dsps"] = cells.get("SB_MAC16", 0)
        if flow == "ecp5":
            r["luts"] = cells.get("LUT4", 0)
            r["dsps"] = sum(v for k, v in cells.items() if k.startswith("MULT18X18"))
    return r


def synth_mantissa(mb, flow="ecp5"):
    """The cells of make synth's one-unit normalised build (MANT_BUILD) with MANTISSA = mb (0: the
    full-width datapath, make synth's 1x256_pipe)."""
    prm = [(n, v) for n, v in synth.params(MANT_BUILD) if n != "MANTISSA"] + ([("MANTISSA", mb)] if mb else [])
    return cached_yosys(flow, prm, f"{MANT_BUILD} with MANTISSA={mb}", dict(mantissa=mb))


def synth_all(jobs):
    tasks = [(w, f, s, d, fl) for (w, f, s, d, flows) in SYNTH_POINTS for fl in flows]
    out = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
        futs = [ex.submit(synth_one, *t) for t in tasks] + [ex.submit(synth_mantissa, mb) for mb in [0] + MANTISSAS]
        tasks += [None] * (len(MANTISSAS) + 1)
        for k, fu in enumerate(concurrent.futures.as_completed(futs)):
            r = fu.result()
            out.append(r)
            print(f"  yosys: {k + 1}/{len(tasks)} ({'cached' if r.get('cached') else str(r.get('seconds')) + ' s'})",
                  file=sys.stderr, flush=True)
    return out


# ---- RTL cycle samples: make sim's harness on a few chain/centred points ----

RTL_SAMPLES = [point("catenary", 32, 16, **BASE),
               point("catenary", 32, 16, substeps=4, iterations=8, rule="pairwise"),
               point("catenary", 18, 8, substeps=2, iterations=4, rule="centred"),
               point("pendulum", 24, 12, sqrt_bits=16, div_bits=20, substeps=8, iterations=1, rule="centred")]


def rtl_sample(p):
    key = point_key(p)
    path = os.path.join(ROOT, CACHE, "rtl_" + key + ".json")
    if os.path.exists(path):
        with open(path) as fh:
            return json.load(fh)
    scene_file = os.path.join(ROOT, ADIR, "scenes", key + ".scene")
    os.makedirs(os.path.dirname(scene_file), exist_ok=True)
    with open(scene_file, "w") as fh:
        fh.write(derive(p))
    r = dict(point=p)
    try:
        info = flow_hwgen.info(scene_file)
        if not info["rtl"]:
            raise Failure(info["why"])
        exe = flow_build.harness_for(scene_file, flow_build.harness_dir(info["params"]))
    except Failure as e:
        r["error"] = f"harness build failed: {e}"
        return r
    rc, out, figures = flow_run.harness(exe, scene_file, ["--frames", "2"])
    r["lockstep_pass"] = rc == 0 and figures.get("verdict") == "pass"
    r["measured"] = figures.get("cycles_per_frame")
    r["summary"] = (out.strip().splitlines() or [""])[0]
    with open(path, "w") as fh:
        json.dump(r, fh)
    return r


# ---- analysis ----

def pareto(items, xf, yf):
    """Indices of items on the lower-left front of (x, y): no other item is <= in both and < in one."""
    pts = [(xf(it), yf(it), i) for i, it in enumerate(items)]
    pts = [p for p in pts if p[0] is not None and p[1] is not None and math.isfinite(p[1])]
    pts.sort(key=lambda p: (p[0], p[1]))
    front, best = [], math.inf
    for x, y, i in pts:
        if y < best:
            front.append(i)
            best = y
    return front


def on_front(items, idx, xf, yf):
    x0, y0 = xf(items[idx]), yf(items[idx])
    for j, it in enumerate(items):
        if j == idx or xf(it) is None or yf(it) is None:
            continue
        if xf(it) <= x0 and yf(it) <= y0 and (xf(it) < x0 or yf(it) < y0):
            return False
    return True


def valid(r):
    return "error" not in r and r.get("finite") and (r.get("gravity_step_lsb", 1) == 0 or r["gravity_step_lsb"] >= 0.5)


def cat_err(r):
    return get(r, "check_fx.error_pct")


def recommend(front_items, bound):
    """Three budgets on a front sorted by cycles: smallest (fewest cycles within bound), most
    accurate (least error), balanced (the knee: least sum of normalised log cycles and log error)."""
    ok = [r for r in front_items if cat_err(r) <= bound]
    if not ok:
        return None
    ok.sort(key=lambda r: r["cycles"])
    small = ok[0]
    best = min(ok, key=cat_err)
    lc = [math.log(r["cycles"]) for r in ok]
    le = [math.log(max(cat_err(r), 1e-12)) for r in ok]
    sc = (max(lc) - min(lc)) or 1
    se = (max(le) - min(le)) or 1
    bal = min(ok, key=lambda r: (math.log(r["cycles"]) - min(lc)) / sc + (math.log(max(cat_err(r), 1e-12)) - min(le)) / se)
    return dict(smallest=small, balanced=bal, accurate=best)


def g(v, digits=3):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "n/a"
    if isinstance(v, int):
        return str(v)
    if v == 0:
        return "0"
    if abs(v) >= 1000:
        return f"{v:,.0f}"
    return f"{v:.{digits}g}"


def settings(r):
    p = r["point"]
    s = f"{fmt_name(p['width'], p['frac'])}, SQRT_BITS {r['sqrt_bits']}, DIV_BITS {r['div_bits']}, " \
        f"{r['substeps']} substeps x {r['iterations']} iterations, {r['rule']}"
    return s


def find(results, scene, **kw):
    out = []
    for r in results:
        p = r["point"]
        if p["scene"] != scene:
            continue
        if p.get("order") != kw.get("order"):  # the red/black points only when asked for
            continue
        if p.get("projection") != kw.get("projection"):  # so are the projection = previous points
            continue
        if p.get("reverse", False) != kw.get("reverse", False):  # and the run-back points
            continue
        if (p.get("mantissa") or 0) != (kw.get("mantissa") or 0):  # and the normalised datapath's
            continue
        if all(p.get(k) == v for k, v in kw.items()):
            out.append(r)
    return out


def one(results, scene, **kw):
    m = find(results, scene, **kw)
    return m[0] if m else None


def projection_section(A, results):
    """projection = previous against current on the PROJECTION_GRID bodies, and at equal cycles."""
    A("### Projection along the previous direction on long bodies, at equal cycles")
    A("")
    A("`projection = previous` costs cycles: `toward_prev` takes 2 SQRT_BITS + DIM DIV_BITS + 7 DIM + 20 cycles a "
      "correction where `toward` takes SQRT_BITS + DIV_BITS + 2 DIM + 10 (docs/architecture.md), about twice; in the "
      "pipelined pass only the pipe's latency LP grows (2 LSQ + LDV + 28 against LSQ + LDV + 11, LSQ and LDV the "
      "root's and the divider's latencies), which a sweep of max(floor(K/2) + 2, LP + 4) cycles waits for when the body is short. Each "
      "body below runs both ways over a grid of substeps and iterations (Q16.16; cycles per frame from the RTL "
      "formula, the serial build). Energy change is over the run, as % of the larger of the starting energy and the "
      "largest kinetic energy (the quantity `strand run` prints); stretch is the largest link stretch over the run.")
    A("")
    for scene, fixed, subs, iters in PROJECTION_GRID:
        # the grid's own points: Q16.16 at full precision (the one-knob sweeps share the scene)
        flt = dict(fixed, width=32, frac=16, sqrt_bits=31, div_bits=31)
        cur = {(r["substeps"], r["iterations"]): r for r in find(results, scene, **flt) if "error" not in r
               and r["substeps"] in subs and r["iterations"] in iters}
        prev = {(r["substeps"], r["iterations"]): r for r in find(results, scene, projection="previous", **flt)
                if "error" not in r and r["substeps"] in subs and r["iterations"] in iters}
        if not cur or not prev:
            continue
        any_r = next(iter(cur.values()))
        desc = (f"`{SCENES[scene][0]}`" + (", damping 0" if fixed.get("damping") == 0 else "")
                + f", {any_r['nodes']} nodes, {any_r['rule']} rule, {any_r['frames']} frames")
        shape = scene == "catenary"
        A(f"**{desc}.**")
        A("")
        A("| substeps x iterations | cycles/frame, current | energy | stretch | " + ("shape error | " if shape else "")
          + "cycles/frame, previous | energy | stretch | " + ("shape error | " if shape else "") + "fallbacks |")
        A("|---|--:|--:|--:|" + ("--:|" if shape else "") + "--:|--:|--:|" + ("--:|" if shape else "") + "--:|")
        for key in sorted(set(cur) & set(prev)):
            c, q = cur[key], prev[key]

            def cols(r):
                out = [g(r["cycles"]), f"{g(get(r, 'drift_pct_fx'))} %", f"{g(get(r, 'stretch_max_fx'))} %"]
                if shape:
                    out.append(f"{g(get(r, 'check_fx.error_pct'))} %")
                return out
            A(f"| {key[0]} x {key[1]} | " + " | ".join(cols(c) + cols(q)) + f" | {g(get(q, 'fallbacks_fx'))} |")
        A("")
        # equal cycles: for each previous point, the best current point that costs no more
        lines = []
        for key in sorted(prev):
            q = prev[key]
            within = [r for r in cur.values() if r["cycles"] <= q["cycles"]]
            if not within:
                continue
            best = min(within, key=lambda r: abs(get(r, "drift_pct_fx") or 1e9))
            lines.append((key, q, best))
        if lines:
            A("At equal cycles: each `previous` setting against the `current` setting of no more cycles that keeps "
              "energy best:")
            A("")
            A("| previous | cycles/frame | energy | stretch | best current within those cycles | cycles/frame | energy | stretch |")
            A("|---|--:|--:|--:|---|--:|--:|--:|")
            for key, q, b in lines:
                A(f"| {key[0]} x {key[1]} | {g(q['cycles'])} | {g(get(q, 'drift_pct_fx'))} % | "
                  f"{g(get(q, 'stretch_max_fx'))} % | {b['substeps']} x {b['iterations']} | {g(b['cycles'])} | "
                  f"{g(get(b, 'drift_pct_fx'))} % | {g(get(b, 'stretch_max_fx'))} % |")
            wins = sum(1 for _, q, b in lines if abs(get(q, "drift_pct_fx")) < abs(get(b, "drift_pct_fx")))
            A("")
            A(f"`previous` keeps energy better than every `current` setting of no more cycles in {wins} of "
              f"{len(lines)} budgets.")
            A("")


def small_steps(results):
    """Rows of the Small Steps comparison: (scene, fmt, rule, n, sub, it) with verdicts."""
    rows = []
    for scene, field in (("swing", "stretch_max_fx"), ("catenary", "stretch_max_fx"), ("catenary", "stretch_final_fx")):
        for (w, f) in [(32, 16), (18, 8)]:
            for rule in ("centred", "pairwise"):
                for n in POW2[1:]:
                    a = one(results, scene, width=w, frac=f, substeps=n, iterations=1, rule=rule,
                            sqrt_bits=w - 1, div_bits=w - 1)
                    b = one(results, scene, width=w, frac=f, substeps=1, iterations=n, rule=rule,
                            sqrt_bits=w - 1, div_bits=w - 1)
                    if not a or not b or "error" in a or "error" in b:
                        continue
                    ok = valid(a) and valid(b)
                    verdict = ("holds" if a[field] < b[field] else "fails") if ok else "n/a"
                    rows.append(dict(scene=scene, field=field, fmt=fmt_name(w, f), rule=rule, n=n, sub=a, it=b,
                                     verdict=verdict, why="" if ok else "g h^2 rounds to zero (gravity lost)"))
    return rows


# ---- the document ----

def plots(results, synth, img, cat_all, front_c, front_r, recs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(img, exist_ok=True)
    files = {}
    colors = {fmt_name(w, f): c for (w, f), c in zip(FORMATS, ["tab:red", "tab:orange", "tab:blue", "tab:green"])}

    def save(fig, name):
        path = os.path.join(img, f"accuracy_{name}.png")
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
        files[name] = os.path.relpath(path, os.path.join(ROOT, "docs"))

    # 1. error against cycles, Pareto front marked
    fig, axs = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, yf, front, yl in ((axs[0], cat_err, front_c, "catenary shape error (% of span)"),
                              (axs[1], lambda r: r["err_rms"], front_r, "RMS error against double (rest lengths)")):
        for fn, c in colors.items():
            for rule, mk in (("centred", "o"), ("pairwise", "^")):
                sel = [r for r in cat_all if fmt_name(r["width"], r["frac"]) == fn and r["rule"] == rule]
                ax.scatter([r["cycles"] for r in sel], [max(yf(r), 1e-9) for r in sel], s=14, c=c, marker=mk, alpha=0.55,
                           label=f"{fn} {rule}")
        fr = sorted([cat_all[i] for i in front], key=lambda r: r["cycles"])
        ax.step([r["cycles"] for r in fr], [max(yf(r), 1e-9) for r in fr], where="post", c="k", lw=1.2, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("cycles per frame")
        ax.set_ylabel(yl)
        ax.grid(True, which="both", alpha=0.3)
    if recs:
        for name, r in recs.items():
            axs[0].scatter([r["cycles"]], [cat_err(r)], s=120, facecolors="none", edgecolors="k", lw=1.5)
            axs[0].annotate(name, (r["cycles"], cat_err(r)), textcoords="offset points", xytext=(6, 6), fontsize=8)
    axs[0].legend(fontsize=6, loc="upper right")
    save(fig, "pareto_cycles")

    # 2. error against cells
    generic = {(s["width"], s["frac"], s["sqrt_bits"], s["div_bits"]): s["cells"] for s in synth
               if s.get("flow") == "generic" and "cells" in s}
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    xs, ys, labs = [], [], []
    for (w, f, s, d), cells in sorted(generic.items()):
        r = one(results, "catenary", width=w, frac=f, sqrt_bits=s, div_bits=d, **BASE)
        if r and "error" not in r:
            xs.append(cells)
            ys.append(max(r["err_rms"], 1e-9))
            labs.append(f"{fmt_name(w, f)}" + (f" sqrt{s}" if s != w - 1 else "") + (f" div{d}" if d != w - 1 else ""))
    ax.scatter(xs, ys, c="tab:blue")
    for x, y, l in zip(xs, ys, labs):
        ax.annotate(l, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_yscale("log")
    ax.set_xlabel(f"Yosys generic cells, {SYNTH_MK[0]}x{SYNTH_MK[1]} build")
    ax.set_ylabel("catenary RMS error against double (rest lengths)")
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "cells")

    # 3. one plot per knob
    # format
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for (w, f) in FORMATS:
        sel = sorted(find(results, "catenary", width=w, frac=f, substeps=4, rule="centred", sqrt_bits=w - 1, div_bits=w - 1),
                     key=lambda r: r["point"]["iterations"])
        sel = [r for r in sel if "error" not in r]
        ax.plot([r["iterations"] for r in sel], [max(r["err_rms"], 1e-9) for r in sel], "o-",
                c=colors[fmt_name(w, f)], label=f"{fmt_name(w, f)} (W={w})")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("iterations (4 substeps, centred)")
    ax.set_ylabel("catenary RMS error against double (rest lengths)")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "format")
    # SQRT_BITS, DIV_BITS
    for knob in ("sqrt_bits", "div_bits"):
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        for (w, f), bits in BITS.items():
            sel = []
            for b in bits:
                kw = dict(sqrt_bits=b, div_bits=w - 1) if knob == "sqrt_bits" else dict(sqrt_bits=w - 1, div_bits=b)
                r = one(results, "catenary", width=w, frac=f, **kw, **BASE)
                if r and "error" not in r:
                    sel.append((b, r))
            ax.plot([b for b, _ in sel], [max(r["err_rms"], 1e-9) for _, r in sel], "o-", c=colors[fmt_name(w, f)],
                    label=f"{fmt_name(w, f)}: RMS error against double")
            ax.plot([b for b, _ in sel], [max(cat_err(r), 1e-9) / 100 for _, r in sel], "s--", c=colors[fmt_name(w, f)],
                    alpha=0.6, label=f"{fmt_name(w, f)}: catenary error (fraction of span)")
        ax.set_yscale("log")
        ax.set_xlabel(knob.upper() + " (4 substeps x 8 iterations, centred)")
        ax.set_ylabel("error")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
        save(fig, knob)
    # iterations and substeps: stretch, both rules, Q16.16
    for knob, other in (("iterations", "substeps"), ("substeps", "iterations")):
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        for rule, ls in (("centred", "-"), ("pairwise", "--")):
            for ov, c in ((1, "tab:red"), (4, "tab:blue"), (32, "tab:green")):
                kw = {other: ov}
                sel = sorted([r for r in find(results, "catenary", width=32, frac=16, rule=rule, sqrt_bits=31, div_bits=31, **kw)
                              if "error" not in r], key=lambda r: r[knob])
                ax.plot([r[knob] for r in sel], [max(r["stretch_final_fx"], 1e-9) for r in sel], "o" + ls, c=c,
                        label=f"{rule}, {ov} {other}")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log")
        ax.set_xlabel(f"{knob} (Q16.16)")
        ax.set_ylabel("catenary rest stretch (%)")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
        save(fig, knob)
    # pendulum period against substeps
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for (w, f) in FORMATS:
        sel = sorted([r for r in find(results, "pendulum", width=w, frac=f, rule="centred", iterations=1) if "error" not in r],
                     key=lambda r: r["substeps"])
        ax.plot([r["substeps"] for r in sel], [abs(get(r, "check_fx.error_pct") or float("nan")) for r in sel], "o-",
                c=colors[fmt_name(w, f)], label=fmt_name(w, f))
    sel = sorted([r for r in find(results, "pendulum", width=32, frac=16, rule="centred", iterations=1) if "error" not in r],
                 key=lambda r: r["substeps"])
    ax.plot([r["substeps"] for r in sel], [abs(get(r, "check_dbl.error_pct")) for r in sel], "k:", label="double")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("substeps (pendulum, 3 degrees)")
    ax.set_ylabel("|period error| against 2 pi sqrt(L/g) (%)")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    save(fig, "period")
    # Small Steps
    fig, axs = plt.subplots(1, 2, figsize=(12, 4.5))
    for ax, (w, f) in zip(axs, [(32, 16), (18, 8)]):
        for rule, c in (("centred", "tab:blue"), ("pairwise", "tab:orange")):
            for mode, ls in (("sub", "-"), ("it", "--")):
                sel = []
                for n in POW2:
                    kw = dict(substeps=n, iterations=1) if mode == "sub" else dict(substeps=1, iterations=n)
                    r = one(results, "swing", width=w, frac=f, rule=rule, sqrt_bits=w - 1, div_bits=w - 1, **kw)
                    if r and "error" not in r:
                        sel.append(r)
                ax.plot([r["cycles"] for r in sel], [max(r["stretch_max_fx"], 1e-9) for r in sel], "o" + ls, c=c,
                        label=f"{rule}: n substeps x 1 iteration" if mode == "sub" else f"{rule}: 1 substep x n iterations")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(f"swing_rope, {fmt_name(w, f)}")
        ax.set_xlabel("cycles per frame (n = 1..32)")
        ax.set_ylabel("largest stretch over 2 s (%)")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    save(fig, "small_steps")
    return files


def wind_section(A, results, claims):
    """The rope in a wind: its angle at rest against the analytic one, in every format and at every MB."""
    A("## The rope in a wind")
    A("")
    A(f"`{SCENES['wind'][0]}` ({WIND_FRAMES} frames at 60 frames/s, 12 nodes pinned at one end, 4 substeps x 4 "
      "iterations, the centred rule, `[wind] velocity = 300 0, drag = 3`): at rest every node carries the same load, "
      "g + c w, so the rope hangs straight along it, at atan(c w / g) from the vertical (sweep's `wind` check: the "
      "line from the pin to the last node). The wind enters the Verlet step as two constants, c h and w h (docs/model.md); "
      "this is what the number format and the normalised datapath's mantissa do to the rope's angle, its stretch and "
      "its distance from the same run in double.")
    A("")
    A("| build | angle at rest (from g) | analytic: g + c w from g | off g + c w (% of the analytic angle) | fixed against double (RMS, rest lengths) | final stretch | cycles per frame |")
    A("|---|--:|--:|--:|--:|--:|--:|")
    rows = []

    def row(label, r):
        if not r or not valid(r):
            return
        rows.append(dict(build=label, error_pct=cat_err(r), angle=get(r, "check_fx.angle_deg"),
                         stretch=get(r, "stretch_final_fx"), rms=r.get("err_rms")))
        A(f"| {label} | {g(get(r, 'check_fx.angle_deg'), 4)} deg | {g(get(r, 'check_fx.angle_reference_deg'), 4)} deg "
          f"| {g(cat_err(r))} % | {g(r.get('err_rms'))} | {g(get(r, 'stretch_final_fx'))} % | {g(r['cycles'])} |")

    for (w, f) in FORMATS:
        row(f"{fmt_name(w, f)}, serial", one(results, "wind", width=w, frac=f, frames=WIND_FRAMES))
    row("Q16.16, red/black", one(results, "wind", frames=WIND_FRAMES, order="redblack"))
    for mb in MANTISSAS:
        row(f"Q16.16, mantissa {mb}", one(results, "wind", frames=WIND_FRAMES, mantissa=mb))
    d = one(results, "wind", frames=WIND_FRAMES)
    if d and valid(d):
        A("")
        A(f"The same run in double: {g(get(d, 'check_dbl.angle_deg'), 4)} deg ({g(get(d, 'check_dbl.error_pct'))} %): "
          "what is left is the solver's (4 iterations a substep leave the links stretched, and the rope not quite "
          "straight), not the arithmetic's.")
    A("")
    claims["wind"] = rows


def order_section(A, results, claims):
    """The constraint order: what red/black costs in convergence per iteration, and saves in cycles."""
    A("## The constraint order: serial or red/black")
    A("")
    A("The serial order (reference 000's: each node or link sees its neighbour's new position) converges faster "
      "per iteration; the red/black order (even nodes or links, then odd: `order = redblack`) is what the pipelined "
      "architecture (ARCH = 1, docs/architecture.md) can keep in flight, one constraint a clock per unit. "
      f"The catenary at Q16.16, {BASE['substeps']} substeps, full root and divider, in both orders: its error against "
      "the analytic shape (% of span) and the cycles per frame of the build each order gets (serial: the serial "
      "sequencer; red/black: the pipelined pass), from model/timing.c.")
    A("")
    A("| rule | iterations | serial: error | serial: cycles per frame | red/black: error | red/black: cycles per frame "
      "| cycles saved |")
    A("|---|--:|--:|--:|--:|--:|--:|")
    rows = []
    for rule in ("centred", "pairwise"):
        for i in POW2:
            kw = dict(width=32, frac=16, sqrt_bits=31, div_bits=31, substeps=BASE["substeps"], iterations=i, rule=rule)
            s = one(results, "catenary", **kw)
            r = one(results, "catenary", order="redblack", **kw)
            if not s or not r or not valid(s) or not valid(r):
                continue
            rows.append(dict(rule=rule, iterations=i, serial=cat_err(s), redblack=cat_err(r),
                             serial_cycles=s["cycles"], redblack_cycles=r["cycles"]))
            A(f"| {rule} | {i} | {g(cat_err(s))} % | {g(s['cycles'])} | {g(cat_err(r))} % | {g(r['cycles'])} "
              f"| {s['cycles'] / r['cycles']:.1f}x |")
    A("")
    hs, hr = one(results, "hanging"), one(results, "hanging", order="redblack")
    if hs and hr and valid(hs) and valid(hr):
        A(f"The hanging rope at its own settings: rest stretch {g(get(hs, 'stretch_final_fx'))} % serial, "
          f"{g(get(hr, 'stretch_final_fx'))} % red/black (Q16.16).")
        A("")
    claims["order"] = rows


def mant_rows(results, msynth):
    """The mantissa table's rows: MB (0 first), its points' results and its 1x256 core's cells."""
    by_mb = {s["mantissa"]: s for s in msynth if "by_type" in s}
    by_point = {json.dumps(r["point"], sort_keys=True): r for r in results}
    rows = []
    for mb in [0] + MANTISSAS:
        # the exact points mantissa_points() made for this MB, in its order
        cat, hang, pend, energy, rope = (by_point.get(json.dumps(p, sort_keys=True)) for p in mantissa_points([mb]))
        r = dict(mb=mb, cat=cat, hang=hang, pend=pend, energy=energy, rope=rope,
                 cells=(by_mb.get(mb) or {}).get("by_type"))
        if not all(r[k] and valid(r[k]) for k in ("cat", "hang", "pend", "energy", "rope")):
            continue
        rows.append(r)
    return rows


def mant_matches(r, full):
    """The catenary's errors and the hanging rope's stretch of row r within twice the full-width row's (the
    SQRT_BITS/DIV_BITS knees' rule). The 1024-node rope's stretch is left out: it is the unconverged solver's
    equilibrium, which rounding moves by an order of magnitude either way (the table shows it)."""
    pairs = [(cat_err(r["cat"]), cat_err(full["cat"])), (r["cat"]["err_rms"], full["cat"]["err_rms"]),
             (get(r["hang"], "stretch_final_fx"), get(full["hang"], "stretch_final_fx"))]
    return all(a is not None and b is not None and abs(a) <= 2 * abs(b) for a, b in pairs)


def mantissa_section(A, results, msynth, claims):
    """The normalised datapath's mantissa: error, cells and the device's bound, MB by MB."""
    rows = mant_rows(results, msynth)
    A("## The normalised datapath: mantissa bits")
    A("")
    A("With `[format] mantissa = MB` the distance constraints are computed on MB-bit mantissas that share one "
      "exponent (docs/model.md), the positions staying in their Q16.16 format; `mantissa = 0` is the full-width "
      "root and divide. Each row runs the same points at Q16.16 with that MB: the catenary at "
      f"{BASE['substeps']} substeps x {BASE['iterations']} iterations (centred, serial order; error against the "
      "analytic shape, % of span, and RMS distance from the double run, units), the hanging rope (pairwise, its "
      "own settings; stretch at the last frame), the small pendulum's period against 2 pi sqrt(L/g), the undamped "
      "pendulum's energy drift over its 10^5 frames, and the 1024-node rope at rest of make bench "
      f"(tb/bench/rope_rest.scene, {MANT_ROPE['substeps']} substeps x {MANT_ROPE['iterations']} iterations, "
      "red/black: its largest stretch over the run and at the last frame; the goal is 0.05 %). The cells are "
      f"Yosys's `synth_ecp5` of make synth's {MANT_BUILD} (one pipelined unit of 256 nodes, the centred rule: two "
      "distance pipes) with that MB, the same script make synth runs; *logic* is LUT4 + 2 CCU2C (a carry cell "
      "takes two of a slice's LUTs). *Units that fit* divides the ECP5-85F's 83,640 logic slots, 156 MULT18X18D "
      "and 208 DP16KD by this core's (which also holds the frame control and the registers a larger build shares, "
      "so it is a bound from below); the last column multiplies them by the rope's own updates a clock a unit "
      "(its cycles per frame from model/timing.c) and by the clock make synth placed that one-unit build at, where it "
      "did: a bound from above, as a device full of units places slower (make synth's four-unit m17_4x256_pipe: "
      "docs/resources.md; the speed headline, at that build's own clock: docs/performance.md).")
    A("")
    if not rows:
        A("No point of the table has a result: run make accuracy.")
        A("")
        return
    full = rows[0]
    fm = {0: synth_fmax("1x256_pipe"), 17: synth_fmax(MANT_BUILD)}
    A("| MB | catenary: error | catenary: RMS vs double | hanging rope: stretch | pendulum: period error "
      "| energy drift | 1024-node rope: largest / final stretch (double: final) | logic (LUT4 + 2 CCU2C) | MULT18X18D | DP16KD "
      "| units that fit | updates/s at fmax (device bound) |")
    A("|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    out = []
    for r in rows:
        c = r["cells"] or {}
        logic = c.get("LUT4", 0) + 2 * c.get("CCU2C", 0) if c else None
        mult, bram = c.get("MULT18X18D", 0), c.get("DP16KD", 0)
        fit = None
        if logic:
            fit = int(min(83640 / logic, 156 / mult if mult else math.inf, 208 / bram if bram else math.inf))
        rope = r["rope"]
        per_unit = 1024 * MANT_ROPE["substeps"] * MANT_ROPE["iterations"] / rope["cycles"] / 4  # 4 units of 256
        mhz = fm.get(r["mb"])
        rate = f"{fit * per_unit * mhz / 1e3:.2f} G ({fit} x {per_unit:.3f} x {mhz:.1f} MHz)" if fit and mhz else \
            ("not placed" if fit else "-")
        name = "full width" if r["mb"] == 0 else str(r["mb"])
        A(f"| {name} | {g(cat_err(r['cat']))} % | {g(r['cat']['err_rms'])} | {g(get(r['hang'], 'stretch_final_fx'))} % "
          f"| {g(get(r['pend'], 'check_fx.error_pct'))} % | {g(get(r['energy'], 'check_fx.error_pct'))} % "
          f"| {g(get(rope, 'stretch_max_fx'))} / {g(get(rope, 'stretch_final_fx'))} % ({g(get(rope, 'stretch_final_dbl'))} %) "
          f"| {fmt_int(logic)} | {fmt_int(mult if c else None)} | {fmt_int(bram if c else None)} | {fmt_int(fit)} | {rate} |")
        out.append(dict(mb=r["mb"], catenary=cat_err(r["cat"]), rms=r["cat"]["err_rms"],
                        hanging=get(r["hang"], "stretch_final_fx"), rope_final=get(rope, "stretch_final_fx"),
                        rope_max=get(rope, "stretch_max_fx"), logic=logic, units=fit))
    A("")
    knee = None
    for r in sorted(rows[1:], key=lambda x: x["mb"], reverse=True):
        if not mant_matches(r, full):
            break
        knee = r["mb"]
    if knee is not None:
        A(f"**From MB = {knee} up, the catenary's error and RMS distance and the hanging rope's stretch are within "
          "twice the full-width datapath's** (the rule the SQRT_BITS and DIV_BITS knees above use); below it at least "
          "one is not.")
    else:
        A("**No MB of the table keeps the catenary's errors and the hanging rope's stretch within twice the "
          "full-width datapath's.**")
    A("")
    A("The 1024-node rope's stretch is left out of that rule. Its 16 iterations a substep do not converge over "
      "1,024 links, so the stretch is the equilibrium the unconverged solver settles at, and rounding moves that "
      "equilibrium a long way: in double (the figure in brackets) the top links settle stretched in proportion to "
      "the weight they hold, while fixed point settles far tighter at most MB and looser at some. Read "
      "that column as the build's own figure, not as the mantissa's precision; the catenary and the hanging rope, "
      "whose solvers converge, measure that.")
    A("")
    claims["mantissa_knee"] = knee
    claims["mantissa"] = out


def synth_fmax(build):
    """make synth's median ECP5-85F fmax of a placed build for this RTL, or None (the record, as make bench reads it)."""
    try:
        _, pnr, _, _ = synth.gather(os.path.join(ROOT, BUILD, "synth"), os.path.join(ROOT, BUILD, "gen"),
                                    synth.rtl_sources())
    except (OSError, ValueError, KeyError):
        return None
    runs = (pnr.get(build) or {}).get("ecp5")
    return synth.fmax_cells(runs)[1] if runs else None


def fmt_int(v):
    return "-" if v is None else f"{v:,}"


def write_doc(out, img, results, synth, rtl, seconds, jobs):
    msynth = [s for s in synth if "mantissa" in s]   # the mantissa table's builds
    synth = [s for s in synth if "mantissa" not in s]
    cat_all = [r for r in find(results, "catenary") if valid(r) and cat_err(r) is not None]
    front_c = pareto(cat_all, lambda r: r["cycles"], cat_err)
    front_r = pareto(cat_all, lambda r: r["cycles"], lambda r: r["err_rms"])
    # the recommendations come from the points the RTL builds whose constants all hold within 1 %
    cent = [r for r in cat_all if r["cycles_kind"] == "rtl-formula" and constants_of(r["point"]) == EXACT]
    front_cent = pareto(cent, lambda r: r["cycles"], cat_err)
    front_items = sorted([cent[i] for i in front_cent], key=lambda r: r["cycles"])
    bound = [t for t in TARGETS if t[0] == "catenary"][0][2]
    recs = recommend(front_items, bound)
    files = plots(results, synth, img, cat_all, front_c, front_r, recs)
    claims = dict(targets=[], recommended={}, small_steps=[], sqrt_knee=None, div_knee=None, mantissa_knee=None)
    L = []
    A = L.append
    n_pts = len(results)
    n_comp = sum(1 for r in results if not r.get("cached"))
    A("# Accuracy: what each bit costs")
    A("")
    A("<!-- Generated by `make accuracy` (scripts/accuracy.py); do not edit by hand: every number below comes "
      "from that run. -->")
    A("")
    A(f"This page is written by `make accuracy` from {n_pts} points of the C model (each run in fixed point and in "
      f"double), {len([s for s in synth if 'cells' in s])} Yosys builds and {len(rtl)} RTL runs. "
      f"This run took {seconds:.0f} s on {jobs} worker(s) ({n_comp} points computed, the rest from the cache in "
      f"`{CACHE}/`).")
    A("")
    A("The knobs: the number format Q(W-F).F, `SQRT_BITS` and `DIV_BITS` (root and quotient bits resolved), "
      "constraint `iterations` per substep, `substeps` per frame at a fixed frame time (1/60 s: a substep is "
      "h = dt / substeps), and the constraint rule (`centred`, reference 000, which the RTL builds; `pairwise`, which it "
      "builds too). The errors:")
    A("")
    A("- **against double**: the same scene, knobs and rule run in `double` (model/engine_body.h compiled twice); RMS "
      "and largest node distance over every frame and node, in rest lengths. This isolates rounding.")
    A("- **against the analytic answer** where the scene has one (below): rounding plus the method (Verlet, "
      "position projection, too few iterations).")
    A("- **stretch**: the largest |l - rest| / rest of any link, over the run (`max`) and at the last frame (`rest`).")
    A("")
    est = sorted({r["scene"] for r in results if "error" not in r and r.get("cycles_kind") != "rtl-formula"})
    A("**Cycles per frame.** For a scene the RTL builds (`hw_check()` passes) the figure is `hw_cycles_per_frame()` "
      "(model/timing.c): the RTL's cycle formula for the build the scene gets (docs/architecture.md gives it for both "
      "architectures), which the test suite checks against the RTL every frame. "
      + (f"Scenes the RTL does not build ({', '.join(est)}) get an **estimate** from model/sweep.c (`cycles_estimate`); "
         "the study's fronts and recommendations use no estimate." if est else
         "Every point of this study is a scene the RTL builds: no figure here is an estimate."))
    A("")
    # RTL sample
    A("### The cycle formula against the RTL")
    A("")
    A("These sweep points were built with `scripts/lockstep_fuzz.py --harness-for` (the `make sim` harness: the RTL under "
      "Verilator in lockstep with the cycle model) and run for 2 frames; the harness measures the cycles from `step` to "
      "`frame_done`.")
    A("")
    A("| point | formula (sweep) | measured on the RTL | lockstep |")
    A("|---|---|---|---|")
    for s in rtl:
        r = one(results, s["point"]["scene"], **{k: s["point"][k] for k in ("width", "frac", "sqrt_bits", "div_bits",
                                                                            "substeps", "iterations", "rule")})
        f_ = r["cycles"] if r else None
        A(f"| {label(s['point'])} | {g(f_)} | {g(s.get('measured')) if 'error' not in s else s['error']} | "
          f"{'PASS' if s.get('lockstep_pass') else 'FAIL'} |")
    A("")
    # targets
    A("## Targets for the default Q16.16 build")
    A("")
    A("Each scene at its own settings (the scene file), Q16.16 with the full root and divider. The last column is "
      "`strand check --strict` on the point's scene: whether every constant the hardware uses (g h^2, ks h^2/m, "
      "kd h/m, damping, rest lengths, ...) holds within 1 % in the format, or the first that does not.")
    A("")
    A("| target | scene settings | bound | fixed point | double | met | constants (`strand check --strict`) |")
    A("|---|---|---|---|---|---|---|")
    for t in TARGETS:
        scene, field, bound_, what, unit = t[:5]
        kw = target_kw(t)
        r = one(results, scene, width=32, frac=16, substeps=None, iterations=None, rule=None, sqrt_bits=31, div_bits=31,
                **kw)
        v = get(r, field)
        vd = get(r, field.replace("_fx", "_dbl"))
        met = v is not None and abs(v) <= bound_
        claims["targets"].append(dict(scene=scene, field=field, bound=bound_, value=v, met=met, **kw))
        extra = "".join(f", {k} = {v_}" for k, v_ in kw.items())
        A(f"| {what} | {r['substeps']} substeps x {r['iterations']} iterations, {r['rule']}{extra} | {g(bound_)} {unit} | "
          f"{g(v, 4)} {unit} | {g(vd, 4)} {unit} | {'yes' if met else '**no**'} | {constants_of(r['point'])} |")
    A("")
    # analytic references
    A("## The analytic references")
    A("")
    pend = one(results, "pendulum", width=32, frac=16, substeps=None, sqrt_bits=31, div_bits=31)
    cat = one(results, "catenary", width=32, frac=16, substeps=None, sqrt_bits=31, div_bits=31)
    spr = one(results, "spring", width=32, frac=16, substeps=1, sqrt_bits=31, div_bits=31)
    en = one(results, "energy", width=32, frac=16, substeps=None, sqrt_bits=31, div_bits=31)
    A(f"- **Pendulum period** (`sim/scenes/pendulum_small.scene`, {g(get(pend, 'check_fx.amplitude_deg'))} degrees): "
      f"{g(get(pend, 'check_fx.period'), 6)} s in fixed point, {g(get(pend, 'check_dbl.period'), 6)} s in double, "
      f"against 2 pi sqrt(L/g) = {g(get(pend, 'check_fx.reference'), 6)} s (with the finite-amplitude correction "
      f"{g(get(pend, 'check_fx.reference_finite_amplitude'), 6)} s), from {g(get(pend, 'check_fx.crossings'))} zero "
      f"crossings.")
    A(f"- **Catenary** (`sim/scenes/catenary.scene`): the chain sags {g(get(cat, 'check_fx.sag'), 4)} cm (double "
      f"{g(get(cat, 'check_dbl.sag'), 4)} cm) where the catenary of the same length sags "
      f"{g(get(cat, 'check_fx.sag_reference'), 4)} cm (a = {g(get(cat, 'check_fx.a'), 4)} cm); the largest distance of a "
      f"node from the curve is {g(get(cat, 'check_fx.error_pct'))} % of the {g(get(cat, 'check_fx.span'))} cm span. "
      f"The links are {g(cat['stretch_final_fx'])} % too long at rest at these settings, which is most of the sag error.")
    cat_best_dbl = min((get(r, "check_dbl.error_pct") for r in find(results, "catenary") if "error" not in r
                        and get(r, "check_dbl.error_pct") is not None), default=None)
    A(f"  The best any setting reaches in double is {g(cat_best_dbl)} % of span: that floor is the difference "
      f"between a chain of {cat['nodes']} point masses and the continuous catenary, not an error of Strand.")
    A(f"- **Damped spring pair** (`sim/scenes/spring_pair.scene`): omega_d = "
      f"{g(get(spr, 'check_fx.omega_d'), 5)} rad/s in fixed point, {g(get(spr, 'check_dbl.omega_d'), 5)} in double, "
      f"against {g(get(spr, 'check_fx.omega_d_reference'), 5)} ({g(get(spr, 'check_fx.error_pct'))} %); decay rate "
      f"{g(get(spr, 'check_fx.decay'), 4)} /s (double {g(get(spr, 'check_dbl.decay'), 4)}) against "
      f"{g(get(spr, 'check_fx.decay_reference'), 4)} /s. Both runs agree with each other far better than with the "
      f"reference: the gap is the method. The damper reads the velocity x - x- of the last substep, half a substep "
      f"late, which acts like extra stiffness kd h / 2mu on top of Verlet's own (omega h)^2/24.")
    sp = sorted([r for r in find(results, "spring", width=32, frac=16) if "error" not in r], key=lambda r: r["substeps"])
    A("")
    A("  | substeps | omega_d error fixed | omega_d error double | decay error fixed | decay error double |")
    A("  |---|---|---|---|---|")
    for r in sp:
        A(f"  | {r['substeps']} | {g(get(r, 'check_fx.error_pct'))} % | {g(get(r, 'check_dbl.error_pct'))} % | "
          f"{g(get(r, 'check_fx.decay_error_pct'))} % | {g(get(r, 'check_dbl.decay_error_pct'))} % |")
    A("")
    met = [r for r in sp if abs(get(r, "check_fx.decay_error_pct") or 1e9) <= 1]
    missed = [r for r in sp if r not in met]
    A(f"  Target: the fixed-point decay rate within 1 % of {g(get(spr, 'check_fx.decay_reference'), 4)} /s at "
      f"{', '.join(str(r['substeps']) for r in sp)} substeps (Q16.16). "
      + (f"Met at {', '.join(str(r['substeps']) for r in met)}" if met else "Met at none")
      + (f"; missed at {', '.join(str(r['substeps']) + ' (' + g(get(r, 'check_fx.decay_error_pct')) + ' %)' for r in missed)}"
         if missed else "") + ". f = ks (len - rest) + kd vn is summed from the two exact products and rounded once "
      "(docs/model.md); rounded on its own, kd vn, a few LSBs a substep, rounded away.")
    bad_damp = [r for r in sp if abs(get(r, "check_fx.decay_error_pct") or 0) > 2 * abs(get(r, "check_dbl.decay_error_pct") or 0) + 1]
    if bad_damp:
        A("")
        A("  With more substeps the fixed-point damper goes wrong while the double one improves: at Q16.16 and "
          + ", ".join(f"{r['substeps']} substeps the decay rate is off by {g(get(r, 'check_fx.decay_error_pct'))} %"
                      for r in bad_damp)
          + ". The damper's position change per substep is kd h / m times the per-substep velocity x - x-, both "
          "shrinking with h, so it falls to a few LSBs and rounds away. A damper needs fraction bits or fewer substeps.")
    sp_low = [r for r in find(results, "spring") if "error" not in r and r["width"] < 32]
    dead = [r for r in sp_low if get(r, "check_fx.omega_d") is None]
    if dead:
        A("")
        A("  At " + ", ".join(sorted({fmt_name(r['width'], r['frac']) for r in dead})) + " some spring points have no "
          "oscillation to measure: the pre-scaled constant ks h^2 / m is a few LSBs or none, the spring is lost to "
          "rounding. Springs need fraction bits.")
    A("")
    A(f"- **Energy** (`sim/scenes/pendulum_undamped.scene`, {g(get(en, 'check_fx.seconds'))} s): the height of the turning points falls from "
      f"{g(get(en, 'check_fx.height_first'), 4)} cm to {g(get(en, 'check_fx.height_last'), 4)} cm, a drift of "
      f"{g(get(en, 'check_fx.error_pct'))} % in fixed point and {g(get(en, 'check_dbl.error_pct'))} % in double. "
      "Position projection with Verlet loses energy at first order in h (docs/model.md): this is the method, and "
      "more substeps shrink it:")
    A("")
    A("  | format | substeps | drift over the run, fixed | drift, double | energy loss rate over the first 60 s, fixed | double | rate x substeps (double) |")
    A("  |---|---|---|---|---|---|---|")
    erows = sorted([r for r in find(results, "energy") if "error" not in r and r["point"]["substeps"]],
                   key=lambda r: (-r["width"], -r["frac"], r["substeps"]))
    for r in erows:
        A(f"  | {fmt_name(r['width'], r['frac'])} | {r['substeps']} | {g(get(r, 'check_fx.error_pct'))} % | "
          f"{g(get(r, 'check_dbl.error_pct'))} % | {g(100 * (get(r, 'check_fx.loss_rate_60s') or float('nan')))} %/s | "
          f"{g(100 * get(r, 'check_dbl.loss_rate_60s'))} %/s | {g(get(r, 'check_dbl.loss_rate_60s') * r['substeps'])} |")
    A("")
    cs = [get(r, "check_dbl.loss_rate_60s") * r["substeps"] for r in erows if r["width"] == 32 and r["frac"] == 16]
    if cs and en:
        c = sum(cs) / len(cs)
        need = c * get(en, "check_fx.seconds") / -math.log(0.99)
        claims["energy_substeps_needed"] = need
        A(f"  The loss rate times the substeps is nearly constant ({', '.join(g(x) for x in cs)} at Q16.16): the energy "
          f"decays as exp(-c t / substeps), first order in h. Keeping the drift within 1 % over the "
          f"{g(get(en, 'check_fx.seconds'))} s of 10^5 frames would take about {g(need)} substeps per frame with this "
          "method; the 1 % target is out of reach of position projection at any practical cost. Over a long run "
          "the fixed-point swing dies a little slower than the double one at small amplitude, where rounding, not the "
          "method, sets the motion.")
        A("")
    prows = sorted([r for r in find(results, "energy", projection="previous") if "error" not in r and r["point"]["substeps"]],
                   key=lambda r: r["substeps"])
    if prows:
        A("  With `projection = previous` (SHAKE: each correction along the constraint's direction at the start of "
          "the substep, docs/model.md; the C model and both RTL passes run it, in lockstep in make test) the method no longer loses "
          "energy: over the run the drift is "
          + ", ".join(f"{g(get(r, 'check_fx.error_pct'))} % in Q16.16 and {g(get(r, 'check_dbl.error_pct'))} % in "
                      f"double at {r['substeps']} substeps" for r in prows)
          + ", where projection along the current direction loses nearly all of it. What remains in fixed point is "
          f"rounding: the double runs hold the energy within {g(max(abs(get(r, 'check_dbl.error_pct')) for r in prows))} %.")
        A("")
    backs = [(name, one(results, "energy", reverse=True, **kw)) for name, kw in
             (("current", {}), ("previous", {"projection": "previous"}))]
    if all(r and "error" not in r for _, r in backs):
        A("  **Time reversibility.** Verlet is time-reversible: run forward, swap the current and previous positions, "
          "run as long again, swap back, and a free body is where it started, bit for bit in fixed point "
          "(`test_verlet_is_time_reversible`: free bodies under gravity, a spring chain without a damper). A constraint "
          "mode departs from it by what it does not undo. The undamped pendulum, "
          f"{g(backs[0][1]['frames'])} frames forward and as many back, lands this far from its start (largest node "
          "distance, in rest lengths): "
          + "; ".join(f"projection = {name}: {g(get(r, 'back_fx'))} in Q16.16 ({g(get(r, 'back_fx_lsb'))} LSB), "
                      f"{g(get(r, 'back_dbl'))} in double" for name, r in backs)
          + ". Projection along the start-of-substep direction is reversible up to rounding (the double run returns "
          "to within rounding); along the current direction it is not.")
        A("")
    A("Period error against substeps, every format (centred rule, 1 iteration):")
    A("")
    A(f"![period]({files['period']})")
    A("")
    # Pareto
    projection_section(A, results)
    A("## Error against cycles per frame")
    A("")
    A(f"Every catenary point ({len(cat_all)} with finite results and gravity above half an LSB per substep): four "
      "formats x two rules x iterations 1..32 x substeps 1..32, and the SQRT_BITS / DIV_BITS sweeps, all with cycles "
      "from the RTL formula. The black line is the Pareto front (no other point is both cheaper and more accurate); "
      "circles are the recommendations.")
    A("")
    A(f"![error against cycles]({files['pareto_cycles']})")
    A("")
    A("The front of the points whose constants all hold within 1 % (`strand check --strict`; both rules; cycles "
      "from the RTL formula), by cycles per frame:")
    A("")
    A("| cycles/frame | settings | catenary error (% span) | rest stretch | max stretch | RMS vs double | C model us/frame |")
    A("|---|---|---|---|---|---|---|")
    for r in front_items:
        A(f"| {g(r['cycles'])} | {settings(r)} | {g(cat_err(r))} | {g(r['stretch_final_fx'])} % | "
          f"{g(r['stretch_max_fx'])} % | {g(r['err_rms'])} | {g(r['us_per_frame_fx'])} |")
    A("")
    # halving: fit log stretch against log cycles on the centred stretch front
    sf = pareto(cent, lambda r: r["cycles"], lambda r: r["stretch_final_fx"])
    sfi = sorted([cent[i] for i in sf], key=lambda r: r["cycles"])
    sfi = [r for r in sfi if r["stretch_final_fx"] > 0]
    conc = []
    if len(sfi) >= 3:
        import numpy as np
        x = np.log([r["cycles"] for r in sfi])
        y = np.log([r["stretch_final_fx"] for r in sfi])
        slope = float(np.polyfit(x, y, 1)[0])
        mult = 2 ** (-1 / slope) if slope < 0 else float("inf")
        claims["halving_multiplier"] = mult
        ref = recs["balanced"] if recs else sfi[len(sfi) // 2]
        half = [r for r in sfi if r["stretch_final_fx"] <= ref["stretch_final_fx"] / 2]
        txt = (f"**Halving the stretch costs about {g(mult)} times the cycles per frame**: along the front of rest "
               f"stretch against cycles, stretch goes as cycles^{g(slope)} (least squares over {len(sfi)} front points).")
        if half:
            h0 = min(half, key=lambda r: r["cycles"])
            txt += (f" From the balanced point ({g(ref['cycles'])} cycles, {g(ref['stretch_final_fx'])} % rest stretch) "
                    f"halving it costs {g(h0['cycles'] - ref['cycles'])} more cycles per frame "
                    f"({settings(h0)}: {g(h0['stretch_final_fx'])} %).")
        conc.append(txt)
    # rule comparison at equal cycles
    cp = []
    for r in cat_all:
        if r["rule"] == "centred" and r["width"] == 32 and r["frac"] == 16 and r["sqrt_bits"] == 31 and r["div_bits"] == 31:
            q = one(results, "catenary", width=32, frac=16, sqrt_bits=31, div_bits=31, substeps=r["substeps"],
                    iterations=r["iterations"], rule="pairwise")
            if q and valid(q):
                cp.append((r, q))
    if cp:
        better = sum(1 for r, q in cp if q["stretch_final_fx"] < r["stretch_final_fx"])
        ratio = sorted(q["cycles"] / r["cycles"] for r, q in cp)[len(cp) // 2]
        conc.append(f"**Rule.** At the same substeps and iterations the pairwise rule ends with less rest stretch than the "
                    f"centred rule in {better} of {len(cp)} Q16.16 settings, and its cycles (RTL formula) are "
                    f"{g(ratio)} times the centred rule's (median): one `toward` per link instead of two per node.")
    A("## Conclusions")
    A("")
    for c in conc:
        A("- " + c)
    # knees of the bit knobs
    for knob in ("sqrt_bits", "div_bits"):
        for (w, f), bits in BITS.items():
            full = one(results, "catenary", width=w, frac=f, sqrt_bits=w - 1, div_bits=w - 1, **BASE)
            series = []
            for b in bits:
                kw = dict(sqrt_bits=b, div_bits=w - 1) if knob == "sqrt_bits" else dict(sqrt_bits=w - 1, div_bits=b)
                r = one(results, "catenary", width=w, frac=f, **kw, **BASE)
                if r and "error" not in r:
                    series.append((b, r))
            if not full or not series:
                continue
            e_full = full["err_rms"]
            tol = 2 * e_full
            k = None
            for b, r in sorted(series, reverse=True):
                if r.get("finite") and r["err_rms"] <= tol:
                    k = b
                else:
                    break
            below = [(b, r) for b, r in series if k is not None and b < k]
            claims[("sqrt" if knob == "sqrt_bits" else "div") + "_knee" + ("" if (w, f) == DEFAULT_FMT else f"_{w}_{f}")] = k
            if k is None:
                continue
            name = knob.upper()
            kr = dict(series)[k]
            txt = (f"**{fmt_name(w, f)}: below {name}={k} the {'square root' if knob == 'sqrt_bits' else 'divider'} "
                   f"dominates the error.** From {name}={w - 1} (full) down to {k} the RMS error against double stays "
                   f"within twice the full-precision {g(e_full)} rest lengths ({g(kr['err_rms'])} at {k}), and saves "
                   f"{g(full['cycles'] - kr['cycles'])} cycles per frame ({g(100 * (full['cycles'] - kr['cycles']) / full['cycles'])} %)")
            if below:
                b1, r1 = max(below, key=lambda t: t[0])
                txt += (f"; at {name}={b1} it is {g(r1['err_rms'])} ({g(r1['err_rms'] / e_full) if e_full else 'n/a'} "
                        f"times), and the catenary error {g(cat_err(r1))} % of span against {g(cat_err(full))} %.")
            else:
                txt += "."
            A("- " + txt)
    # format
    fr = []
    for (w, f) in FORMATS:
        r = one(results, "catenary", width=w, frac=f, sqrt_bits=w - 1, div_bits=w - 1, **BASE)
        if r and "error" not in r:
            fr.append((w, f, r))
    if fr:
        A("- **Format** (catenary at 4 substeps x 8 iterations, centred): " + "; ".join(
            f"{fmt_name(w, f)}: RMS error against double {g(r['err_rms'])} rest lengths, catenary {g(cat_err(r))} % of span"
            for w, f, r in fr) + ". The gap to double shrinks with every fraction bit; the gap to the catenary does not, "
            "because at these settings it is the solver's stretch, not rounding.")
    lost = sorted({(r["width"], r["frac"], r["substeps"]) for r in results if "error" not in r and
                   r.get("gravity_step_lsb", 1) and 0 < r["gravity_step_lsb"] < 0.5})
    if lost:
        A("- **Gravity lost to rounding.** g h^2 is added every substep; when it is below half an LSB it rounds to zero "
          "and the body floats. This happens at: " + ", ".join(f"{fmt_name(w, f)} with {s} substeps" for w, f, s in lost) +
          ". Such points are left out of the fronts and the verdicts. More substeps need more fraction bits.")
    A("")
    A("One plot per knob:")
    A("")
    for k, cap in (("format", "format: error against double, by iterations"), ("sqrt_bits", "SQRT_BITS"),
                   ("div_bits", "DIV_BITS"), ("iterations", "iterations: rest stretch"),
                   ("substeps", "substeps: rest stretch")):
        A(f"![{cap}]({files[k]})")
        A("")
    # cells
    A("## Error against area")
    A("")
    A(f"Yosys cells of the {SYNTH_MK[0]}x{SYNTH_MK[1]} build of `strand_core` that [resources.md](resources.md) "
      "reports (the same flow: scripts/synth.py yosys_script), at each format and at a few SQRT_BITS / DIV_BITS; the "
      "cell count depends on W and the bits, not on the scene, the iterations or the substeps. Generic `synth` (the "
      "hierarchy kept); `synth_ice40 -dsp` and `synth_ecp5` for two formats.")
    A("")
    A("| W, F | SQRT_BITS | DIV_BITS | generic cells | iCE40 LUT4 / SB_MAC16 | ECP5 LUT4 / MULT18X18 | catenary RMS vs double |")
    A("|---|---|---|---|---|---|---|")
    by = {}
    for s in synth:
        by.setdefault((s["width"], s["frac"], s["sqrt_bits"], s["div_bits"]), {})[s["flow"]] = s
    for (w, f, sb, db), fl in sorted(by.items()):
        r = one(results, "catenary", width=w, frac=f, sqrt_bits=sb, div_bits=db, **BASE)
        ice = fl.get("ice40")
        ecp = fl.get("ecp5")
        A(f"| {fmt_name(w, f)} (W={w}) | {sb} | {db} | {g(get(fl.get('generic', {}), 'cells'))} | "
          f"{(g(ice.get('luts')) + ' / ' + g(ice.get('dsps'))) if ice and 'luts' in ice else '-'} | "
          f"{(g(ecp.get('luts')) + ' / ' + g(ecp.get('dsps'))) if ecp and 'luts' in ecp else '-'} | "
          f"{g(r['err_rms']) if r else 'n/a'} |")
    A("")
    A(f"![error against cells]({files['cells']})")
    A("")
    # recommendations
    A("## Recommended settings")
    A("")
    if recs:
        A(f"From the Pareto front of the catenary points the RTL builds whose constants all hold within 1 % "
          f"(`strand check --strict`: {len(cent)} of {len(cat_all)}; cycles from the RTL formula), all within "
          f"the {g(bound)} % of span bound: **smallest** is the fewest cycles per frame within the bound, **most accurate** "
          "the least error, **balanced** the knee (least sum of normalised log cycles and log error).")
        A("")
        A("| budget | settings | cycles/frame | catenary error (% span) | rest stretch | RMS vs double | generic cells (4x5) | "
          "constants (`strand check --strict`) |")
        A("|---|---|---|---|---|---|---|---|")
        for name, key in (("smallest", "smallest"), ("balanced", "balanced"), ("most accurate", "accurate")):
            r = recs[key]
            cells = get(by.get((r["width"], r["frac"], r["sqrt_bits"], r["div_bits"]), {}), "generic.cells")
            A(f"| {name} | {settings(r)} | {g(r['cycles'])} | {g(cat_err(r))} | {g(r['stretch_final_fx'])} % | "
              f"{g(r['err_rms'])} | {g(cells) if cells else 'not synthesised'} | {constants_of(r['point'])} |")
            claims["recommended"][key] = dict(point=r["point"], cycles=r["cycles"], error=cat_err(r))
    else:
        A("No centred point meets the bound.")
    A("")
    # Small Steps
    rows = small_steps(results)
    A("## Small Steps, re-tested")
    A("")
    A("Macklin et al. 2019 (\"Small Steps in Physics Simulation\") found that n substeps of one iteration give less "
      "constraint error than one step of n iterations at similar cost. In Strand's hardware terms the two cost nearly "
      "the same cycles per frame (the formula charges each substep its Verlet pass, K + 5 cycles with constraints in the "
      "serial build, so n substeps cost (n - 1)(K + 5) more; in the pipelined chain, 5 cycles a substep with the centred "
      "rule, whose first sweep takes the Verlet step, or ceil(K/2) + 6 with the pairwise rule, which steps two nodes a "
      "clock in a Verlet pass, and the pipe's drain n times instead of once); the table compares the largest stretch of the two at each n. `swing_rope` (a rope "
      "released horizontal, 2 s) is the dynamic case; `catenary` the static one, at the maximum over the run and at rest.")
    A("")
    A("| scene | measure | format | rule | n | cycles n x 1 / 1 x n | stretch n substeps x 1 | stretch 1 x n iterations | verdict |")
    A("|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        a, b = row["sub"], row["it"]
        A(f"| {row['scene']} | {'max' if row['field'] == 'stretch_max_fx' else 'rest'} | {row['fmt']} | {row['rule']} | "
          f"{row['n']} | {g(a['cycles'])} / {g(b['cycles'])} | {g(a[row['field']])} % | {g(b[row['field']])} % | "
          f"{row['verdict']}{' (' + row['why'] + ')' if row['why'] else ''} |")
        claims["small_steps"].append(dict(scene=row["scene"], field=row["field"], fmt=row["fmt"], rule=row["rule"], n=row["n"],
                                          verdict=row["verdict"]))
    A("")
    judged = [r for r in rows if r["verdict"] != "n/a"]
    held = [r for r in judged if r["verdict"] == "holds"]
    failed = [r for r in judged if r["verdict"] == "fails"]
    verdict = ("holds everywhere it could be measured" if judged and not failed else
               "does not hold" if judged and not held else "holds in part")
    claims["small_steps_verdict"] = verdict
    A(f"**Verdict: the claim {verdict}** in Strand's fixed-point terms: n substeps of 1 iteration stretch less than "
      f"1 substep of n iterations in {len(held)} of {len(judged)} comparisons"
      + (f" ({len(rows) - len(judged)} more could not be judged because gravity rounds to zero)" if len(rows) > len(judged) else "")
      + ".")
    if failed:
        groups = {}
        for r in failed:
            groups.setdefault((r["scene"], r["field"], r["fmt"], r["rule"]), []).append(r["n"])
        A("It fails at: " + "; ".join(f"{s} ({'max' if fl == 'stretch_max_fx' else 'rest'} stretch), {fm}, {ru}, n = "
                                      f"{', '.join(map(str, ns))}" for (s, fl, fm, ru), ns in sorted(groups.items())) + ".")
    if held:
        ratios = sorted(r["it"][r["field"]] / r["sub"][r["field"]] for r in held if r["sub"][r["field"]] > 0)
        if ratios:
            A(f"Where it holds, one step of n iterations stretches {g(ratios[0])} to {g(ratios[-1])} times as much "
              f"(median {g(ratios[len(ratios) // 2])}).")
    A("")
    A(f"![Small Steps]({files['small_steps']})")
    A("")
    # timing
    A("## The C model's time per frame")
    A("")
    A("Measured by model/sweep.c around each frame call (wall clock, both workers busy, so treat it as a guide). "
      "Fixed point runs the bit-serial root and divider bit by bit as the hardware does; double uses the FPU.")
    A("")
    A("| point | fixed us/frame | double us/frame |")
    A("|---|---|---|")
    for r in [recs[k] for k in ("smallest", "balanced", "accurate")] if recs else []:
        A(f"| {label(r['point'])} | {g(r['us_per_frame_fx'])} | {g(r['us_per_frame_dbl'])} |")
    A(f"| {label(en['point'])} (10^5 frames) | {g(en['us_per_frame_fx'])} | {g(en['us_per_frame_dbl'])} |")
    A("")
    order_section(A, results, claims)
    mantissa_section(A, results, msynth, claims)
    wind_section(A, results, claims)
    A("## How to regenerate")
    A("")
    A("`make accuracy` (scripts/accuracy.mk) builds `build/sweep` from model/sweep.c, runs scripts/accuracy.py, and "
      "rewrites this file and docs/img/accuracy_*.png. `make test-accuracy` runs a quick slice and checks the claims "
      "above against a fresh run. Raw results: one JSON file per point in `build/accuracy/cache/`.")
    A("")
    A("<!-- claims " + json.dumps(claims, sort_keys=True) + " -->")
    with open(out, "w") as fh:
        fh.write("\n".join(L) + "\n")
    return claims


# ---- commands ----

def cmd_run(a):
    t0 = time.time()
    pts = dedup(study_points() + RTL_SAMPLES)   # the RTL samples are sweep points too
    print(f"accuracy: {len(pts)} points on {a.jobs} workers", file=sys.stderr)
    results = run_all(pts, a.jobs)
    bad = [r for r in results if "error" in r]
    for r in bad:
        print(f"  note: {label(r['point'])}: {r['error']}", file=sys.stderr)
    print("accuracy: Yosys builds", file=sys.stderr)
    synth = [] if a.no_synth else synth_all(a.jobs)
    print("accuracy: RTL cycle samples (Verilator)", file=sys.stderr)
    rtl = []
    if not a.no_rtl:
        with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
            rtl = list(ex.map(rtl_sample, RTL_SAMPLES))
    write_doc(a.out, a.img, results, synth, rtl, time.time() - t0, a.jobs)
    print(f"accuracy: wrote {a.out} in {time.time() - t0:.0f} s", file=sys.stderr)
    return 0


def cmd_test(a):
    fails = 0

    def check(ok, what):
        nonlocal fails
        print(("PASS " if ok else "FAIL ") + what)
        fails += 0 if ok else 1

    t0 = time.time()
    # the claims of the document
    try:
        text = open(a.doc).read()
        claims = json.loads(re.search(r"<!-- claims (.*) -->", text).group(1))
    except (OSError, AttributeError, ValueError) as e:
        check(False, f"accuracy: {a.doc} has no claims block ({e}); run make accuracy")
        return 1
    # a slice: the targets' points, the recommended points, a Small Steps pair, a checker known answer
    tgt = [point(t[0], **target_kw(t)) for t in TARGETS]
    rec = [c["point"] for c in claims["recommended"].values()]
    ss = [c for c in claims["small_steps"] if c["scene"] == "swing" and c["fmt"] == "Q16.16" and c["n"] in (4, 8)]
    ssp = []
    for c in ss:
        for sub, it in ((c["n"], 1), (1, c["n"])):
            ssp.append(point("swing", 32, 16, substeps=sub, iterations=it, rule=c["rule"]))
    known = [point("pendulum", 32, 16, substeps=32, iterations=1, rule="centred")]
    wind = point("wind", frames=WIND_FRAMES)
    pts = dedup(tgt + rec + ssp + known + [wind])
    # fresh: no cache, so the figures are recomputed by this build of the model
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        results = list(ex.map(lambda p: run_point(p, use_cache=False), pts))
    byk = {json.dumps(r["point"], sort_keys=True): r for r in results}

    def res(p):
        return byk[json.dumps(p, sort_keys=True)]

    # machinery
    r = run_point(known[0])
    check(r.get("cached") is True, "accuracy cache: a point just computed is read back from the cache")
    check(point_key(known[0]) != point_key(dict(known[0], substeps=16)), "accuracy cache: the key changes with a knob")
    for p in pts:
        r = res(p)
        if r.get("cycles_kind") == "rtl-formula":
            scene_file = os.path.join(ROOT, ADIR, "scenes", point_key(p) + ".scene")
            os.makedirs(os.path.dirname(scene_file), exist_ok=True)
            with open(scene_file, "w") as fh:
                fh.write(derive(p))
            want = cycles_of_scene(scene_file)
            check(r["cycles"] == want, f"cycles: {label(p)}: sweep {r['cycles']} = strand info's formula {want}")
    d = derive(point("catenary", 18, 8, sqrt_bits=11, substeps=3, iterations=5, rule="pairwise"))
    check(all(s in d for s in ("width = 18", "frac = 8", "sqrt_bits = 11", "div_bits = 17", "substeps = 3",
                               "iterations = 5", "rule = pairwise")), "derive: a point's overrides reach its scene file")
    # checkers against known answers: the pendulum in double at 32 substeps
    kp = res(known[0])
    e = get(kp, "check_dbl.error_pct")
    check(e is not None and abs(e) < 0.05,
          f"period checker: double pendulum at 32 substeps within 0.05 % of 2 pi sqrt(L/g) ({g(e)} %)")
    ref = get(kp, "check_dbl.reference")
    check(ref is not None and abs(ref - 2 * math.pi * math.sqrt(100 / 981)) < 1e-6,
          f"period checker: reference 2 pi sqrt(100/981) = {g(ref, 6)} s")
    # the rope in a wind: the document's Q16.16 row reproduces, and the double run hangs within 1 % of the analytic angle
    wc = next((c for c in claims.get("wind", []) if c["build"] == "Q16.16, serial"), None)
    wr = res(wind)
    wa = get(wr, "check_fx.angle_deg")
    if "wind" in claims:
        check(wc is not None and wa is not None and abs(wa - wc["angle"]) <= 1e-9 * abs(wc["angle"]),
              f"wind: the rope at rest at {g(wa, 6)} deg (Q16.16), as docs/accuracy.md states")
    else:
        print(f"note: wind: the rope at rest at {g(wa, 6)} deg (Q16.16); {a.doc} predates the wind section "
              "(make accuracy writes it)")
    we = get(wr, "check_dbl.error_pct")
    check(we is not None and abs(we) < 1, f"wind checker: the double run's rope along g + c w within 1 % of that load's angle from g ({g(we)} %)")
    # targets: the document's verdicts hold for a fresh run
    for c in claims["targets"]:
        p = point(c["scene"], **({"projection": c["projection"]} if c.get("projection") else {}))
        v = get(res(p), c["field"])
        met = v is not None and abs(v) <= c["bound"]
        word = "met" if met else "not met"
        same = met == c["met"] and v is not None and abs(v - c["value"]) <= 1e-9 * max(1, abs(c["value"]))
        check(same, f"target {c['scene']} {c['field']} <= {c['bound']}: {word} ({g(v, 4)})" +
              (", as docs/accuracy.md states" if same else
               f"; docs/accuracy.md states {'met' if c['met'] else 'not met'} ({g(c['value'], 4)})"))
    # recommended points: figures reproduce, within the bound, not dominated by their neighbours in the claims
    bound = [t for t in TARGETS if t[0] == "catenary"][0][2]
    recs = claims["recommended"]
    for name, c in recs.items():
        r = res(c["point"])
        check(r["cycles"] == c["cycles"] and abs(cat_err(r) - c["error"]) <= 1e-9 * max(1, c["error"]),
              f"recommended {name}: {label(c['point'])} reproduces ({g(r['cycles'])} cycles, {g(cat_err(r))} % of span)")
        check(cat_err(r) <= bound, f"recommended {name}: within the {bound} % of span bound")
    rr = [res(c["point"]) for c in recs.values()]
    for i, r in enumerate(rr):
        check(on_front(rr, i, lambda x: x["cycles"], cat_err),
              f"recommended {list(recs)[i]}: not dominated by another recommendation")
    check(recs.get("smallest", {}).get("cycles", 0) <= recs.get("balanced", {}).get("cycles", 1) <=
          recs.get("accurate", {}).get("cycles", 2) and
          recs["accurate"]["error"] <= recs["balanced"]["error"] <= recs["smallest"]["error"],
          "recommended: smallest <= balanced <= most accurate in cycles, and the reverse in error")
    # front membership against the full cached sweep, when it is there
    cat_all = []
    for p in study_points():
        if p["scene"] != "catenary" or p.get("order"):  # the document's fronts are of the serial order
            continue
        path = os.path.join(ROOT, CACHE, point_key(p) + ".json")
        if os.path.exists(path):
            with open(path) as fh:
                q = json.load(fh)
            if valid(q) and q.get("cycles_kind") == "rtl-formula" and cat_err(q) is not None and \
                    constants_of(q["point"]) == EXACT:
                cat_all.append(q)
    if cat_all:
        for name, c in recs.items():
            idx = [i for i, q in enumerate(cat_all) if q["point"] == c["point"]]
            check(bool(idx) and on_front(cat_all, idx[0], lambda x: x["cycles"], cat_err),
                  f"recommended {name}: on the Pareto front of the {len(cat_all)} cached RTL-buildable catenary points "
                  "whose constants hold within 1 %")
    # Small Steps verdicts reproduce
    for c in ss:
        a_ = res(point("swing", 32, 16, substeps=c["n"], iterations=1, rule=c["rule"]))
        b_ = res(point("swing", 32, 16, substeps=1, iterations=c["n"], rule=c["rule"]))
        v = "holds" if a_[c["field"]] < b_[c["field"]] else "fails"
        check(v == c["verdict"], f"Small Steps swing Q16.16 {c['rule']} n={c['n']}: {v}, as docs/accuracy.md states")
    # the mantissa knee: fresh runs at the knee and at full width keep every error of the table but the
    # 1024-node rope's (minutes a run) within twice the full width's, and reproduce the document's figures
    knee = claims.get("mantissa_knee")
    if knee:
        full_c = next(c for c in claims["mantissa"] if c["mb"] == 0)
        knee_c = next(c for c in claims["mantissa"] if c["mb"] == knee)
        fresh = {}
        for mb in (0, knee):
            kw = dict(mantissa=mb) if mb else {}
            cat = run_point(point("catenary", **BASE, **kw), use_cache=False)
            hang = run_point(point("hanging", **kw), use_cache=False)
            fresh[mb] = dict(catenary=cat_err(cat), rms=cat["err_rms"], hanging=get(hang, "stretch_final_fx"))
        for field in ("catenary", "rms", "hanging"):
            a_, b_ = fresh[knee][field], fresh[0][field]
            check(abs(a_) <= 2 * abs(b_), f"mantissa knee {knee}: {field} {g(a_)} within twice the full width's {g(b_)}")
            for mb, c in ((0, full_c), (knee, knee_c)):
                check(abs(fresh[mb][field] - c[field]) <= 1e-9 * max(1, abs(c[field])),
                      f"mantissa {mb or 'full width'}: {field} {g(fresh[mb][field])} as docs/accuracy.md states")
    print(f"accuracy test slice: {len(pts)} points in {time.time() - t0:.1f} s")
    return 1 if fails else 0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--jobs", type=int, default=2)
    r.add_argument("--out", default="docs/accuracy.md")
    r.add_argument("--img", default="docs/img")
    r.add_argument("--no-synth", action="store_true")
    r.add_argument("--no-rtl", action="store_true")
    t = sub.add_parser("test")
    t.add_argument("--jobs", type=int, default=2)
    t.add_argument("--doc", default="docs/accuracy.md")
    a = ap.parse_args()
    os.chdir(ROOT)
    return cmd_run(a) if a.cmd == "run" else cmd_test(a)


if __name__ == "__main__":
    sys.exit(main())
