#!/usr/bin/env python3
"""lockstep_fuzz.py - random scenes in lockstep: the RTL against the cycle model.

    lockstep_fuzz.py N [--seed S] [--builds B] [--jobs J] [--scene FILE ...] [--faults] [--reset-seeds K]
    lockstep_fuzz.py --replay SEED [--seed S] [--builds B]

Every scene is drawn from a seed: its build (W, F, M, K, SQRT_BITS, DIV_BITS, ITER,
SUBSTEPS and the EN_* effects: springs, ground, the mouse's impulse or grab form, 2D or 3D,
a chain or a graph), its constants (start, step, rest length, gravity,
damping, pins), its mouse script and its length, all within what the RTL supports.
A Verilator build costs about a minute, so scenes share builds: the three builds of
the RTL test scenes and B more drawn from --seed. Each scene runs through the
harness with its own stimulus seed and random initial values
(+verilator+rand+reset+2); every third one is also reset at random cycles in the
middle of frames. A failure prints the scene's seed; --replay SEED runs that
one scene again (the scene file is kept in build/fuzz/).

--scene FILE runs a given scene (its whole length) too; --faults builds copies of
the RTL with the planted faults of tb/faults.py and checks that each is reported at
the cycle the model predicts; --reset-seeds K runs the first --scene with K random-initialisation seeds
and checks that every output of every cycle is the same as with zeros.
Harnesses live in build/vl/b_<hash of the build>, shared by every run.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import random
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("BUILD", "build")
sys.path.insert(0, os.path.join(ROOT, "tb"))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import faults  # noqa: E402  (the planted faults: copies of rtl/)

FIXED_BUILDS = ["sim/scenes/ref000_rope.scene", "tb/scenes/chain_q10_8.scene", "tb/scenes/chain_k4_bits.scene"]


def read_build(path, order=None):
    """The build a scene file needs: strand_core's parameters as 'strand info' derives them
    (the one source of parameters: model/hwgen.c and the table of scripts/gen_params.py);
    order (serial or redblack) replaces the scene's constraint order."""
    p = subprocess.run([os.path.join(ROOT, BUILD, "strand"), "info", path, "--json"] + (["--order", order] if order else []), cwd=ROOT,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    info = json.loads(p.stdout) if p.returncode == 0 and p.stdout.startswith("{") else None
    if info is None or not info["rtl"]:
        why = info["why"] if info else p.stdout.strip()
        sys.exit(f"{why}\nFAIL lockstep: no RTL build for {path}")
    return info["params"]


def random_build(rng):
    """A build drawn as strand_core parameters (the scene written for it makes hwgen derive them)."""
    w = rng.choice([12, 16, 18, 20, 24, 32])
    f = rng.randint(max(2, w // 3), w - 5)
    b = {"W": w, "F": f, "M": rng.randint(1, 4), "K": rng.randint(1, 6),
         "SQRT_BITS": rng.randint(max(3, w // 2), w - 1), "DIV_BITS": rng.randint(max(3, w // 2), w - 1),
         "ITER": rng.randint(1, 3), "SUBSTEPS": rng.randint(1, 2),
         "EN_GRAVITY": rng.random() < 0.8, "EN_DAMPING": rng.random() < 0.4, "EN_MOUSE": rng.random() < 0.7,
         "EN_CONSTRAINTS": rng.random() < 0.85, "RULE": rng.randint(0, 1),
         "EN_SPRINGS": rng.random() < 0.4, "EN_GROUND": rng.random() < 0.3, "GROUND_AXIS": rng.randint(0, 1),
         "GROUND_ABOVE": rng.random() < 0.5, "DIM": rng.choice([2, 2, 3]), "GRAPH": rng.random() < 0.3}
    if b["GRAPH"]:
        b["RULE"] = 1  # a graph has no chain to walk: the pairwise rule
    b["GRAB"] = b["EN_MOUSE"] and rng.random() < 0.35   # the grab form of the mouse
    if b["DIM"] == 3 and rng.random() < 0.4:
        b["GROUND_AXIS"] = 2    # the floor of a 3D scene
    # the red/black order: a chain's constraints on the pipelined pass, a graph's edges by colour
    b["ORDER"] = rng.random() < 0.5
    b["ARCH"] = b["ORDER"] and b["EN_CONSTRAINTS"] and not b["GRAPH"]
    return b


def builds_for(seed, extra):
    rng = random.Random(f"builds-{seed}")
    return [read_build(p) for p in FIXED_BUILDS] + [random_build(rng) for _ in range(extra)]


def scene_text(build, seed):
    """A valid scene for `build`, its run-time values drawn from `seed`: a chain or a graph, 2D or 3D."""
    rng = random.Random(f"scene-{seed}")
    w, f = build["W"], build["F"]
    dim = build["DIM"]
    graph = build["GRAPH"]
    span = 2.0 ** (w - f - 1)           # the format's range is +-span
    lsb = 2.0 ** -f
    n = build["M"] * build["K"]
    if graph:
        n = max(n, 2)
    reach = span / 4                    # keep the body well inside the range
    vec = lambda v: " ".join(f"{x:.6f}" for x in v[:dim])
    step = [rng.uniform(-1, 1) * reach / max(n, 1) for _ in range(3)]
    if rng.random() < 0.1:
        step = [0.0, 0.0, 0.0]          # every node on one point: zero lengths
    start = [rng.uniform(-reach, reach) - step[k] * n / 2 for k in range(3)]
    rest = max(sum(abs(x) for x in step[:dim]), 64 * lsb) * rng.uniform(0.5, 1.6)
    frames = rng.randint(3, 10)
    lines = [f"; random scene, seed {seed}", "[scene]", f"name = fuzz_{seed}", f"dim = {dim}",
             "[format]", f"width = {w}", f"frac = {f}", f"sqrt_bits = {build['SQRT_BITS']}", f"div_bits = {build['DIV_BITS']}",
             "[time]", "dt = 1", f"frames = {frames}", f"substeps = {build['SUBSTEPS']}", f"iterations = {build['ITER']}"]
    if build["EN_DAMPING"]:
        lines.append(f"damping = {rng.uniform(lsb * 4, 0.3):.6f}")
    pins = sorted(rng.sample(range(n), rng.randint(0, min(3, n))))
    nodes = [[start[k] + i * step[k] + (rng.uniform(-1, 1) * rest / 2 if graph else 0) for k in range(3)] for i in range(n)]
    if graph:
        # nodes near a line, so lengths stay small; edges between random pairs, every node on one
        lines += ["[graph]"]
        lines += [f"node = {vec(p)}" for p in nodes]
        kinds = (["rod", "strut"] if build["EN_CONSTRAINTS"] else []) + (["spring"] if build.get("EN_SPRINGS") else [])
        # the edge count is the build's (E_RODS, E_SPRINGS are build parameters); the pairs are the scene's
        extra = (build["M"] * 7 + build["K"] * 3 + build["W"]) % (n + 1)
        pairs = [(i, i + 1) for i in range(n - 1)] + [tuple(rng.sample(range(n), 2)) for _ in range(extra)]
        if kinds:
            for i, (a, b) in enumerate(pairs):
                rest_e = f" {rng.uniform(0.5, 1.5) * rest:.6f}" if rng.random() < 0.5 else ""
                lines.append(f"edge = {a} {b} {kinds[i % len(kinds)]}{rest_e}")
    else:
        lines += ["[chain]", f"units = {build['M']}", f"nodes_per_unit = {build['K']}",
                  f"start = {vec(start)}", f"step = {vec(step)}", f"rest = {rest:.6f}"]
    if pins:
        lines.append("pinned = " + " ".join(map(str, pins)))
    if rng.random() < 0.3:  # the whole body starts moving
        lines.append(f"velocity = {vec([rng.uniform(-1, 1) * reach / 20 for _ in range(3)])}")
    if build["EN_GRAVITY"]:
        g = rng.uniform(0, reach / 50) * build["SUBSTEPS"] ** 2
        lines += ["[gravity]", f"accel = {vec([rng.uniform(-0.3, 0.3) * g, -g, rng.uniform(-0.3, 0.3) * g])}"]
    if build["EN_CONSTRAINTS"]:
        lines += ["[constraints]", f"rule = {['centred', 'pairwise'][build['RULE']]}",
                  f"order = {'redblack' if build.get('ORDER') else 'serial'}"]
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
        while frame < frames:
            p = [rng.uniform(-reach, reach) for _ in range(3)]
            if rng.random() < 0.5 and n:         # aim at a node's start
                p = nodes[rng.randrange(n)]
            lines.append(f"event = {frame} {vec(p)} {rng.randint(0, 1)}")
            frame += rng.randint(1, 3)
    return "\n".join(lines) + "\n"


def build_key(build):
    return hashlib.sha1(repr(sorted(build.items())).encode()).hexdigest()[:10]


def harness_dir(build, fault=""):
    return os.path.join(BUILD, "vl", "b_" + build_key(build) + (f"_fault_{fault}" if fault else ""))


def run(cmd):
    p = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return p.returncode, p.stdout


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("n", nargs="?", type=int, default=50, help="scenes to run")
    ap.add_argument("--seed", type=int, default=1, help="base seed (scene i has seed base*100000 + i)")
    ap.add_argument("--builds", type=int, default=2, help="random builds beside the three fixed ones")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--replay", type=int, help="run the one scene with this seed")
    ap.add_argument("--scene", action="append", default=[], help="also run this scene (PATH, or PATH:FRAMES)")
    ap.add_argument("--redblack", action="store_true",
                    help="also run every --scene in the red/black order (a chain's pipelined build)")
    ap.add_argument("--harness-for", metavar="SCENE", help="build (if needed) the harness for SCENE's build, print its path")
    ap.add_argument("--order", choices=["serial", "redblack"], help="with --harness-for: the build of SCENE in this order")
    ap.add_argument("--faults", action="store_true", help="check the planted faults are caught")
    ap.add_argument("--reset-seeds", type=int, default=0, help="random-initialisation seeds for the first --scene")
    a = ap.parse_args()

    if a.harness_for:
        build = read_build(a.harness_for, a.order)
        rc, out = run(["scripts/build_harness.sh", a.harness_for, harness_dir(build), "rtl"] + ([a.order] if a.order else []))
        if rc != 0:
            sys.stderr.write(out)
            return 1
        print(os.path.join(harness_dir(build), "harness"))
        return 0

    builds = builds_for(a.seed, a.builds)
    seeds = [a.replay] if a.replay is not None else [a.seed * 100000 + i for i in range(a.n)]
    fuzz = os.path.join(BUILD, "fuzz")
    os.makedirs(os.path.join(ROOT, fuzz), exist_ok=True)
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
    if a.faults:
        fs = "tb/scenes/chain_q10_8.scene"
        for kind in faults.FAULTS:
            order = faults.ORDER.get(kind, "")
            jobs.append((f"fault {kind}", [fs, "--quiet", "--expect-fault", kind] + (["--order", order] if order else []),
                         read_build(fs, order or None), kind, order))
    for s in seeds:
        build = builds[s % len(builds)]
        path = os.path.join(fuzz, f"seed_{s}.scene")
        with open(os.path.join(ROOT, path), "w") as fh:
            fh.write(scene_text(build, s))
        # every third scene also gets resets at random cycles in the middle of frames
        jobs.append((f"fuzz seed {s}", [path, "--quiet", "--seed", str(s), "--resets", str(2 if s % 3 == 0 else 0),
                                        "+verilator+rand+reset+2", f"+verilator+seed+{s % 100000 + 1}"], build, "", ""))

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
        cmd = ["scripts/build_harness.sh", path, harness_dir(build, fault), rtl] + ([order] if order else [])
        return key, run(cmd)
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for key, (rc, out) in ex.map(make, needed.items()):
            if rc != 0:
                print(out)
                print(f"FAIL lockstep: the harness for build {key} did not build")
                return 1

    def one(job):
        label, args, build, fault, _ = job
        harness = os.path.abspath(os.path.join(ROOT, harness_dir(build, fault), "harness"))
        workdir = os.path.join(ROOT, BUILD, "fuzz")  # where a failing run leaves mismatch.fst
        p = subprocess.run([harness] + [os.path.join(ROOT, x) if x.endswith(".scene") else x for x in args], cwd=workdir,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        return job, p.returncode, p.stdout

    failed = 0
    digests = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for (label, args, build, fault, _), rc, out in ex.map(one, jobs):
            lines = [l for l in out.splitlines() if l.startswith(("PASS", "FAIL", "MISMATCH"))]
            digest = [l.split()[-1] for l in out.splitlines() if "output digest" in l]
            if label.startswith("reset-"):
                digests[label] = digest[0] if digest else None
                if rc != 0:
                    failed += 1
                    print("\n".join(lines) or out)
                continue
            if rc == 0:
                print(lines[-1] if lines else f"PASS {label}")
            else:
                failed += 1
                print("\n".join(lines[:12]) or out)
                if label.startswith("fuzz seed"):
                    s = label.split()[-1]
                    print(f"FAIL lockstep {label} ({args[0]}): replay with "
                          f"'scripts/lockstep_fuzz.py --replay {s} --seed {a.seed} --builds {a.builds}'")
                else:
                    print(f"FAIL lockstep {label}")
    if digests:
        same = len(set(digests.values())) == 1 and None not in digests.values()
        print(("PASS" if same else "FAIL") + f" reset defines everything: {len(digests) - 1} random-initialisation seeds and "
              f"zeros give {'the same' if same else 'different'} outputs in every cycle ({digests.get('reset-zero')})")
        failed += 0 if same else 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
