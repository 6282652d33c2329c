#!/usr/bin/env python3
"""stability_doc.py CASES.json SERIES.csv FUZZ.json BOUND.txt OUT.md OUT.png

Write docs/stability.md and the Euler-against-Verlet energy plot from the figures of one
`make stability` run. Nothing in the document is typed by hand: every number below comes
from the JSON, CSV and text files this run produced.
"""
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

cases_path, series_path, fuzz_path, bound_path, out_md, out_png = sys.argv[1:7]
doc = json.load(open(cases_path))
fuzz = json.load(open(fuzz_path))
bound_lines = [l.rstrip() for l in open(bound_path) if l.strip()]
rows = list(csv.DictReader(open(series_path)))


def g(x, digits=3):
    """A figure, short."""
    if x is None:
        return "-"
    if isinstance(x, bool):
        return "yes" if x else "no"
    if x == 0:
        return "0"
    if abs(x) >= 1e6 or abs(x) < 1e-3:
        return f"{x:.{digits - 1}e}"
    return f"{x:.{digits}g}"


# ---- the plot: energy gained since frame 0, Euler against Verlet ----
frames = [int(r["frame"]) for r in rows]
fig, ax = plt.subplots(figsize=(8, 4.5), dpi=110)
for key, label, style in [
    ("euler_double", "explicit Euler, double", "-"),
    ("euler_fixed", "explicit Euler, fixed Q16.16", "--"),
    ("verlet_double", "Verlet, double", "-"),
    ("verlet_fixed", "Verlet, fixed Q16.16", "--"),
]:
    ys = []
    for r in rows:
        v = float(r[key])
        ys.append(v if v == v and abs(v) < 1e30 else float("nan"))  # past 1e30 Euler is off the chart
    ax.plot(frames, ys, style, label=label)
ax.set_yscale("symlog", linthresh=1.0)
ax.set_xlabel("frame (64 substeps of 1/64 each)")
ax.set_ylabel("energy gained since frame 0 (symlog)")
ax.set_title("Reference 002's rope, the same springs: Euler against Verlet")
ax.grid(True, which="both", alpha=0.3)
ax.legend(loc="upper left")
fig.tight_layout()
fig.savefig(out_png)

# ---- the document ----
try:
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
except OSError:
    commit = "?"
cases = doc["cases"]
ev = doc["euler_vs_verlet"]
n_pass = sum(c["pass"] for c in cases) + (1 if ev["pass"] else 0)
n_all = len(cases) + 1
img_rel = os.path.relpath(out_png, os.path.dirname(out_md))


def special(c):
    """The figure that is particular to a case."""
    n, fx, db = c["name"], c["fixed"], c["double"]
    if n == "hard_coincident" or n == "hard_collapse":
        return f"zero-length corrections skipped: fixed {fx['skipped']}, double {db['skipped']}"
    if n == "hard_stiff_k10000":
        return (f"as written ({c['substeps_scene']} substeps): double non-finite at frame {c['bound_diverged_at']}; "
                f"run at {c['substeps']} substeps")
    if n == "hard_resting":
        return (f"widest excursion after frame 10000: fixed {g(fx['creep'])} LSB, double {g(db['creep'])} rest lengths; "
                f"fixed last moved at frame {fx['last_move']}")
    if n == "hard_saturate":
        return f"fixed: a node at the range's limit on every gravity axis from frame {fx['wall_frame']} to the end"
    if n == "hard_ground_impact":
        return f"closest approach to the ground: fixed {g(fx['ground_gap'])}, double {g(db['ground_gap'])} rest lengths"
    if n.startswith("hard_mouse"):
        return f"stretch at the last frame: fixed {g(fx['final_stretch_pct'])} %, double {g(db['final_stretch_pct'])} %"
    if n == "hard_narrow_q10_8":
        return f"fixed against double over the first 240 frames: RMS {g(c['rms_rest'])} rest lengths"
    return f"final stretch: fixed {g(fx['final_stretch_pct'])} %"


def energy(c, k):
    e = c[k]["energy_growth"]
    if "energy" in CRITERIA[c["name"]]:
        return g(e)
    return "(input)" if c["name"].startswith(("hard_mouse", "hard_many", "hard_narrow")) else "(not checked)"


CRITERIA = {
    "hard_coincident": "finite, no wrap, energy (after frame 200), stretch <= 10 % from frame 1000, zero lengths skipped",
    "hard_collapse": "finite, no wrap, energy (after frame 12), stretch <= 100 %, zero length skipped, fixed = double to 1e-3 rest lengths RMS (1000 frames)",
    "hard_stiff_k1000": "finite, no wrap, energy (tolerance 0.001), stretch <= 40 %",
    "hard_stiff_k10000": "the bound: diverges as written, finite at --auto-substeps; energy (0.001), stretch <= 40 %",
    "hard_large_dt": "finite, no wrap, energy, stretch <= 100 %",
    "hard_long_rope": "finite, no wrap, energy, stretch <= 50 %",
    "hard_many_iterations": "finite, no wrap, stretch <= 5 %",
    "hard_resting": "finite, no wrap, energy, stretch <= 10 %, no creep: within 8 LSB of the frame-10000 positions to the end",
    "hard_mouse_impulse": "finite, no wrap, recovers: stretch <= 10 % at the last frame",
    "hard_mouse_grab": "finite, no wrap (grab frames exempt), recovers: stretch <= 10 % at the last frame",
    "hard_saturate": "no wrap, rests saturated against the limits of the range",
    "hard_ground_impact": "finite, no wrap, energy, never below the ground",
    "hard_narrow_q10_8": "finite, no wrap, stretch <= 200 %",
}

out = []
w = out.append
w("# Stability: hard cases, the step bound, and bad input")
w("")
w(f"Regenerated by `make stability` (commit `{commit}`); every figure on this page comes from")
w("that run. `make test` runs the same cases (`make test-stability`) and a short fuzz run")
w("(`make test-fuzz`); `make soak` runs 10^6 frames of every case; `make fuzz` a longer fuzz run.")
w("")
w(f"**Result of this run: {n_pass} of {n_all} cases passed.**")
w("")
w("## What every case checks")
w("")
w("`model/stability.c` runs each `sim/scenes/hard_*.scene` in fixed point (the scene's")
w("format, bit-exact with the RTL) and in double, side by side, and checks on every frame:")
w("")
w("- **finite**: no position or velocity of the double run is NaN or infinite;")
w("- **inside**: every fixed-point position is inside the W-bit range;")
w("- **no wrap**: no fixed-point node moves by half the format's span or more in one frame.")
w("  Saturating arithmetic keeps values inside the range whatever happens, so *inside* alone")
w("  proves nothing; a wrap-around, though, moves a value by the whole span (2^(W-F)), which")
w("  no physical step in these scenes comes near (the largest jump is in the table). While")
w("  a node is grabbed the pointer itself may cross the range, so grab frames are exempt.")
w("  A run that diverges can jump that far too (saturated velocities), so the check is")
w("  meant for runs that are otherwise stable;")
w("- **energy** (where the scene has no input): kinetic + gravitational + spring energy,")
w("  velocities from `(x - x-)/h`, never exceeds the reference energy by more than a")
w("  tolerance (0.01 of the scale unless stated) times the scale. The reference is the")
w("  energy at frame 0, or the largest energy up to a stated frame where the start itself is")
w("  an input (coincident nodes pushed apart; the collapse case's impulse). The scale is the")
w("  largest of |E0|, the peak kinetic energy and `m g (total rest length) N`;")
w("- and each case's own criterion, below.")
w("")
w("## The cases")
w("")
w("| case | what it proves | RTL subset | frames | format, substeps x iterations | criteria | max stretch fixed / double | energy growth fixed / double | largest jump (of span) | its own figure | result |")
w("|---|---|---|---|---|---|---|---|---|---|---|")
for c in cases:
    fx, db = c["fixed"], c["double"]
    w(f"| `{c['name']}` | {c['proves']} | {'yes' if c['rtl_subset'] else 'no'} | {c['frames']} | "
      f"{c['format']}, {c['substeps']} x {c['iterations']} | {CRITERIA[c['name']]} | "
      f"{g(fx['max_stretch_pct'])} % / {g(db['max_stretch_pct'])} % | {energy(c, 'fixed')} / {energy(c, 'double')} | "
      f"{g(fx['max_jump_span'])} | {special(c)} | {'PASS' if c['pass'] else 'FAIL: ' + c['why']} |")
w("")
w("Max stretch is the largest |l - rest| / rest of any segment over the run (from frame 1000")
w("for `hard_coincident`). The mouse cases stretch the rope by hundreds of thousands of")
w("percent on purpose: the pointer drags nodes to the corners of the range, and the")
w("criterion is that they saturate there, never wrap, and that the rope comes back.")
w("Energy growth is the largest (E - E_ref) / scale after the reference frame; negative")
w("means the run only lost energy. \"RTL subset\": the RTL builds every effect the scene")
w("names (`strand hwgen` accepts it), so it can run in lockstep: `make lockstep-hard` runs")
w("each such case on the RTL against the cycle model.")
w("")
w("Time on the model for this run (both formats, one core):")
w("")
w("| case | seconds |")
w("|---|---|")
for c in cases:
    w(f"| `{c['name']}` | {c['seconds']:.1f} |")
w("")
w("## Euler against Verlet")
w("")
w(f"![energy gained, explicit Euler against Verlet]({img_rel})")
w("")
w("Reference 002's rope (16 nodes, ks = 100, kd = 0.5, 64 substeps of 1/64 per frame):")
w("`ref002_euler.scene` integrates it with explicit Euler, `ref002_verlet_springs.scene`")
w(f"with Verlet, the same forces. Over {ev['frames']} frames Euler's energy grew to")
w(f"{g(ev['euler_growth_fixed'])} times the scale in fixed point (where it saturates) and")
dbl = "became non-finite at frame %d" % ev["euler_nonfinite_double"] if ev["euler_nonfinite_double"] else "grew %s times" % g(ev["euler_growth_double"])
w(f"{dbl} in double; Verlet's grew at most {g(ev['verlet_growth_fixed'])} (fixed) and")
w(f"{g(ev['verlet_growth_double'])} (double) of the scale: bounded. The test requires Euler")
w("above 1000 times the scale and Verlet below 0.001. The bound below says why: for Euler")
w("an underdamped spring mode grows unless h < kd/ks = 0.005, and this scene's h is 1/64.")
w("")
w("## The step bound of springs and dampers")
w("")
w("Position-based constraints, gravity, the mouse and the ground have no step limit.")
w("Springs and dampers are explicit forces, and a step too long for the stiffest mode")
w("diverges. `strand check` computes the bound (`model/stability_bound.h`):")
w("")
w("- **The stiffest mode.** Linearised, the springs couple the nodes through ks times the")
w("  Laplacian of the spring graph. By Gershgorin's theorem its largest eigenvalue is at most")
w("  lambda = 2D, D the most springs at one node, so omega <= sqrt(2 D ks / m): the")
w("  two-body mode sqrt(2 ks/m) for one link, 2 sqrt(ks/m) for a chain, the top of the")
w("  monatomic chain's band omega(q) = 2 sqrt(ks/m) |sin(qa/2)| (Kittel, *Introduction to")
w("  Solid State Physics*, ch. 4).")
w("- **Verlet.** Per mode, `x+ = x + (1 - c)(x - x-) - a x` with a = h^2 lambda ks/m,")
w("  c = d + h lambda kd/m (Verlet damping d plus the damper; h^2 lambda kd/m for")
w("  `damper_velocity = per_step`). Both roots of z^2 - (2 - a - c) z + (1 - c) are inside")
w("  the unit circle (Jury's test) iff c < 2 and a + 2c < 4. `strand check` prints the")
w("  index a/4 + c/2, stable below 1: without the damper that is the familiar h omega < 2,")
w("  without the spring h lambda kd/m < 2 - d (for a chain, h kd/m < 0.5).")
w("- **Explicit Euler.** Per mode z = 1 + h mu, mu^2 + (lambda kd/m) mu + lambda ks/m = 0:")
w("  an underdamped mode grows unless h < kd/ks, an overdamped one unless")
w("  h lambda kd/m < 2; undamped springs grow at any step.")
w("")
w("A scene whose index is 1 or more gets a warning on stderr at its `[springs]` line.")
w("`--auto-substeps MAX` (check, run, compare) picks the fewest substeps up to MAX whose h")
w("would still be stable if doubled (a safety factor of 2 on the step), scaling the initial")
w("motion so that initial velocities are kept. From this run:")
w("")
w("```")
for l in bound_lines:
    w(l)
w("```")
k = next(c for c in cases if c["name"] == "hard_stiff_k10000")
w("")
w(f"The bound is right on both sides for this scene: `hard_stiff_k10000` as written ({k['substeps_scene']} substeps)")
w(f"became non-finite in double at frame {k['bound_diverged_at']}, and at the {k['substeps']} substeps")
w(f"`--auto-substeps` picks it ran {k['frames']} frames with a largest stretch of {g(k['double']['max_stretch_pct'])} %.")
w("")
w("## Bad input: the fuzzer")
w("")
w("`tb/fuzz/fuzz_scene.c` is a libFuzzer target built with clang, AddressSanitizer and")
w("UndefinedBehaviorSanitizer. Each input is written to a file and loaded with")
w("`scene_load`. It must never crash, hang (10 s limit), leak or hit undefined behaviour,")
w("and a rejection must read exactly `PATH:LINE: message` with LINE between 1 and the")
w("file's line count. A scene that loads and is small is then run for three frames in")
w("both number types, so the engine also sees whatever the parser lets through. The seed")
w("corpus (`tb/fuzz/corpus/`) holds shipped scenes and malformed ones (`bad_*`);")
w("`tb/fuzz/crashes/` holds every reproducer found, replayed by every run.")
w("")
w(f"This run: {fuzz['executions']} executions in {fuzz['seconds']} s, **{fuzz['crashes']} crashes**,")
w(f"{fuzz['coverage_edges']} coverage edges, a working corpus of {fuzz['corpus']} inputs; the")
w(f"{fuzz['committed_inputs']} committed inputs were replayed first. libFuzzer stops at its first")
w("finding, so a crash here ends the run early; each one found so far is described, with")
w("its reproducer, in `tb/fuzz/crashes/README.md`.")
w("")
w("`scripts/bad_input_cli.sh` runs every `bad_*` scene through `strand check` and")
w("`strand run --csv --hex`: exit status 2, a `file:line: message`, and neither the output")
w("files nor their `.tmp` files left behind.")
w("")
w("## The soak")
w("")
w("`make soak` runs 10^6 frames of every case above with the same criteria, two cases at a")
w("time (`SOAK_JOBS`); each prints its PASS/FAIL line with its figures, and the run writes")
w("[soak.md](soak.md), the table of their figures.")
w("")
open(out_md, "w").write("\n".join(out))
print(f"wrote {out_md} and {out_png}")
