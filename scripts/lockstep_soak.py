#!/usr/bin/env python3
"""lockstep_soak.py [--scenes N] [--chunk C] [--builds B] [--jobs J] [--first-seed S] [--doc FILE] [--restart]

Random scenes in lockstep at scale: N scenes (default 10^4) in chunks of C (default 2000).
Chunk k is one run of scripts/lockstep_fuzz.py with seed S + k: its own B drawn builds (the
planned ones of PLAN and B - 6 random ones, default B = 12) beside the three fixed ones, and
C scenes on them, so every chunk covers every build class and the soak as a whole draws
N / C x B builds. A scene runs in a few hundredths of a second and a build takes about a
minute, so a chunk's cost is its builds: C sets how many scenes each build gets. Progress is kept after every chunk in a record that the repository
tracks (docs/lockstep_soak.json, --record), so that a soak stopped on one machine or
checkout goes on from its next chunk on another (--restart forgets it). The record holds a
digest of the sources a chunk ran on (rtl/, model/, the parameter table, the harness): a
record made on other sources is of another design, and the soak starts again.
Each chunk's log is build/soak/chunk_<seed>.log; a failing scene's replay command is in it.
A chunk's own harnesses (those of its drawn builds that were not there before it) are
removed when it ends (about 30 MB each); nothing else in build/vl is touched.

With --doc FILE the soak's totals (scenes, chunks, builds, failures, and how many scenes
covered each class) are written into FILE's generated region 'fuzz' (scripts/doc_region.py)
after every chunk, so that the page says how far the soak got.
Prints a progress line per chunk and ends with a PASS or FAIL line.
"""
import argparse
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.environ.get("BUILD", "build")
SOAK = os.path.join(ROOT, BUILD, "soak")
VL = os.path.join(ROOT, BUILD, "vl")
sys.path.insert(0, os.path.join(ROOT, "scripts"))
sys.dont_write_bytecode = True
import lockstep_fuzz  # noqa: E402  (CLASSES, the classes every chunk covers)

# what a chunk's verdict is about: the RTL the harness builds (not the board tops) with its
# parameter table, the model it is compared with, and the harness that compares them. The
# scripts that draw scenes are not in it: a scene that passed stays passed if they change.
SOURCES = ["rtl", "model", "scripts/gen_params.py", "tb/harness.h", "tb/harness_run.cpp", "tb/harness.cpp", "tb/sim_top.v"]


def sources_digest():
    h = hashlib.sha256()
    files = []
    for src in SOURCES:
        path = os.path.join(ROOT, src)
        if os.path.isdir(path):
            files += [os.path.join(src, f) for f in sorted(os.listdir(path))
                      if os.path.isfile(os.path.join(path, f))]
        else:
            files.append(src)
    for f in files:
        with open(os.path.join(ROOT, f), "rb") as fh:
            h.update(f.encode() + b"\0" + fh.read() + b"\0")
    return h.hexdigest()[:16]


def load(path):
    try:
        with open(path) as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


def doc_table(p, total_wanted):
    chunks = p["chunks"]
    scenes = sum(c["scenes"] for c in chunks)
    failed = sum(c["failed"] for c in chunks)
    builds = sum(c["builds"] for c in chunks)
    covered = {}
    for c in chunks:
        for k, v in c["covered"].items():
            covered[k] = covered.get(k, 0) + v
    hours = sum(c["seconds"] for c in chunks) / 3600
    lines = [f"`make lockstep-soak`: {scenes} of {total_wanted} random scenes run so far in {len(chunks)} chunks "
             f"(seeds {chunks[0]['seed']}..{chunks[-1]['seed']}), on {builds} builds drawn beside the three fixed ones, "
             f"in {hours:.1f} h; {failed} failed. Sources digest {p.get('sources')} (rtl/, model/, the harness: "
             f"docs/lockstep_soak.json)." if chunks else "`make lockstep-soak`: no chunk has run yet.", ""]
    if chunks:
        lines += [f"Scenes per class (each chunk covers every one of the {len(lockstep_fuzz.CLASSES)}):", "",
                  "| class | what | scenes |", "|---|---|---|"]
        for name, what in lockstep_fuzz.CLASSES:
            lines.append(f"| {name} | {what} | {covered.get(name, 0)} |")
        bad = [c for c in chunks if c["failed"]]
        if bad:
            lines += ["", "Failing chunks: " + ", ".join(f"seed {c['seed']} ({c['failed']} failed, build/soak/chunk_{c['seed']}.log)"
                                                          for c in bad)]
    return "\n".join(lines) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scenes", type=int, default=10000)
    ap.add_argument("--chunk", type=int, default=2000)
    ap.add_argument("--builds", type=int, default=12)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--first-seed", type=int, default=1001)
    ap.add_argument("--doc", help="write the totals into this file's region 'fuzz'")
    ap.add_argument("--record", default=os.path.join("docs", "lockstep_soak.json"),
                    help="the soak's record, kept after every chunk (default docs/lockstep_soak.json)")
    ap.add_argument("--restart", action="store_true", help="forget the progress and start from the first chunk")
    a = ap.parse_args()
    os.makedirs(SOAK, exist_ok=True)
    prog_path = os.path.join(ROOT, a.record)
    p = None if a.restart else load(prog_path)
    digest = sources_digest()
    want = {"scenes": a.scenes, "chunk": a.chunk, "builds": a.builds, "first_seed": a.first_seed}
    if p and p.get("sources") != digest:
        print(f"lockstep-soak: {a.record} was made on other sources (digest {p.get('sources')}, now {digest}: "
              f"{', '.join(SOURCES)} changed); starting again")
        p = None
    if p and p.get("plan") != want:
        print(f"lockstep-soak: {a.record} is of another soak ({p.get('plan')}); --restart starts this one")
        return 1
    if not p:
        p = {"plan": want, "sources": digest, "chunks": []}
    n_chunks = (a.scenes + a.chunk - 1) // a.chunk
    done = {c["seed"] for c in p["chunks"]}
    failed = sum(c["failed"] for c in p["chunks"])
    for k in range(n_chunks):
        seed = a.first_seed + k
        if seed in done:
            continue
        n = min(a.chunk, a.scenes - k * a.chunk)
        before = set(os.listdir(VL)) if os.path.isdir(VL) else set()
        t0 = time.time()
        cov = os.path.join(SOAK, f"coverage_{seed}.json")
        log = os.path.join(SOAK, f"chunk_{seed}.log")
        if os.path.exists(cov):
            os.remove(cov)  # this chunk's counts, not an earlier run's
        with open(log, "w") as fh:
            rc = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "lockstep_fuzz.py"), str(n), "--seed", str(seed),
                                 "--builds", str(a.builds), "--jobs", str(a.jobs), "--coverage-json", cov],
                                cwd=ROOT, stdout=fh, stderr=subprocess.STDOUT).returncode
        c = load(cov) or {}
        passes, fails = c.get("fuzz_passed", 0), c.get("fuzz_failed", 0)
        if rc != 0 and fails == 0:
            fails = max(1, n - passes)   # the chunk stopped before its scenes ran (a harness did not build, ...)
        entry = {"seed": seed, "scenes": passes + fails, "failed": fails, "builds": max(0, c.get("builds", 3) - 3),
                 "covered": c.get("covered", {}), "seconds": round(time.time() - t0), "rc": rc}
        p["chunks"].append(entry)
        failed += fails
        with open(prog_path + ".tmp", "w") as fh:
            json.dump(p, fh, indent=1)
            fh.write("\n")
        os.replace(prog_path + ".tmp", prog_path)
        # the chunk's own harnesses go: its builds' (from its coverage file) that were not there
        # before it, and not the fixed builds' (other runs may share build/vl)
        fixed = {os.path.basename(lockstep_fuzz.harness_dir(lockstep_fuzz.read_build(s), fast=True))
                 for s in lockstep_fuzz.FIXED_BUILDS}
        for h in c.get("harnesses", []):
            name = os.path.basename(h)
            if name in before or name in fixed:
                continue
            for sfx in ("", ".gen", ".lock"):
                path = os.path.join(VL, name + sfx)
                if os.path.isdir(path):
                    shutil.rmtree(path, ignore_errors=True)
                elif os.path.exists(path):
                    os.remove(path)
        ran = sum(x["scenes"] for x in p["chunks"])
        print(f"lockstep-soak: chunk {k + 1} of {n_chunks} (seed {seed}): {passes + fails} scenes, {fails} failed, "
              f"{entry['seconds']} s; {ran} of {a.scenes} scenes done, {failed} failed so far", flush=True)
        if a.doc:
            subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "doc_region.py"), a.doc, "fuzz"],
                           input=doc_table(p, a.scenes), text=True, cwd=ROOT, check=True)
    ran = sum(x["scenes"] for x in p["chunks"])
    print(f"{'PASS' if not failed else 'FAIL'} lockstep-soak: {ran} of {a.scenes} scenes in lockstep, {failed} failed"
          + ("" if not failed else " (build/soak/chunk_<seed>.log has each failing scene's replay command)"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
