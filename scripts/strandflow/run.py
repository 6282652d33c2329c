"""Running a harness or the `strand` tool, and reading its figures back.

The harness (tb/harness.cpp) writes every figure of a run to a JSON file (--json); harness()
returns that object beside the run's output, which is for people to read."""
import json
import os
import tempfile

from .core import ROOT, STRAND, run as _run, run_checked


def harness(exe, scene, args=(), cwd=ROOT, timeout=None, env=None):
    """Run a harness binary on SCENE with ARGS; (exit status, output, figures). figures is the
    run's --json object (tb/harness.cpp's Report: verdict, cycles, cycles_per_frame,
    output_digest, resets, the update rates, ...), {} when the harness wrote none (it did not
    start, or it crashed). The scene's path is made absolute, so that cwd can be where a
    failing run should leave its trace."""
    os.makedirs(cwd, exist_ok=True)
    fd, path = tempfile.mkstemp(prefix=".harness-", suffix=".json", dir=cwd)
    os.close(fd)
    os.unlink(path)  # the harness writes it whole (a rename) or not at all
    try:
        rc, out = _run([os.path.abspath(exe), os.path.abspath(os.path.join(ROOT, scene))] + list(args) + ["--json", path],
                       cwd=cwd, timeout=timeout, env=env)
        try:
            with open(path) as fh:
                figures = json.load(fh)
        except (OSError, ValueError):
            figures = {}
    finally:
        for f in (path, path + ".tmp"):
            if os.path.exists(f):
                os.unlink(f)
    return rc, out, figures


def verdicts(out):
    """The PASS / FAIL / MISMATCH lines of a run's output, to show a person."""
    return [ln for ln in out.splitlines() if ln.startswith(("PASS", "FAIL", "MISMATCH"))]


def strand(args, what=None):
    """`strand ARGS`: its output; Failure with its message when it refuses."""
    return run_checked([STRAND] + list(args), what=what or "strand " + " ".join(args[:2]))


def scene_set(scene, out, keys):
    """Write OUT: SCENE with keys set ({"section.key": value}) by `strand set`, the one scene
    writer (the C parser's rules; comments and layout kept). Failure with its message (which
    assignment or line is wrong) when the result would not be a valid scene."""
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    run_checked([STRAND, "set", os.path.join(ROOT, scene), os.path.join(ROOT, out)]
                + [f"{k}={v}" for k, v in keys.items()], what=f"strand set {scene}")
    return out
