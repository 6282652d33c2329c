"""Running a harness or the `strand` tool, and reading its figures back.

The harness (tb/harness.cpp) ends a run with one PASS or FAIL line and, indented below it,
its counters; parse() is the one reader of them."""
import os
import re

from .core import ROOT, STRAND, run as _run, run_checked


def harness(exe, scene, args=(), cwd=ROOT, timeout=None, env=None):
    """Run a harness binary on SCENE with ARGS; (exit status, output). The scene's path is
    made absolute, so that cwd can be where a failing run should leave its trace."""
    os.makedirs(cwd, exist_ok=True)
    return _run([os.path.abspath(exe), os.path.abspath(os.path.join(ROOT, scene))] + list(args),
                cwd=cwd, timeout=timeout, env=env)


def strand(args, what=None):
    """`strand ARGS`: its output; Failure with its message when it refuses."""
    return run_checked([STRAND] + list(args), what=what or "strand " + " ".join(args[:2]))


def _int(m, i=1):
    return int(m.group(i)) if m else None


def _float(m, i=1):
    return float(m.group(i)) if m else None


def parse(out):
    """The harness's verdict and counters. Keys: verdicts (its PASS / FAIL / MISMATCH lines),
    cycles_per_frame and cycles_note (what follows the figure: empty when every frame took
    the formula's cycles), digest (of every output in every cycle), updates_per_frame,
    updates_per_clock (over the frame), updates_per_clock_passes (in the constraint
    passes), springs_per_frame, springs_per_clock (in the spring passes). A figure the run
    did not print is None."""
    cyc = re.search(r"^\s*cycles per frame\s+(\d+)(.*)$", out, re.M)
    dg = re.search(r"^\s*output digest\s+(\S+)", out, re.M)
    upd = re.search(r"constraint updates\s+(\d+) per frame: ([\d.]+) per clock over the frame, ([\d.]+) per clock in", out)
    spr = re.search(r"spring updates\s+(\d+) per frame: ([\d.]+) per clock", out)
    return dict(verdicts=[ln for ln in out.splitlines() if ln.startswith(("PASS", "FAIL", "MISMATCH"))],
                cycles_per_frame=_int(cyc), cycles_note=cyc.group(2).strip() if cyc else "",
                digest=dg.group(1) if dg else None,
                updates_per_frame=_int(upd), updates_per_clock=_float(upd, 2), updates_per_clock_passes=_float(upd, 3),
                springs_per_frame=_int(spr), springs_per_clock=_float(spr, 2))
