#!/usr/bin/env python3
"""bench.py - the core's physics throughput against a CPU, and simulation speed, written to
docs/performance.md (make bench).

Physics throughput: for the 4x5, 8x8, 16x16, 1x256, 8x128 and 4x256 builds (tb/bench/bench_<build>.scene,
and the same scene with the pairwise rule) in both architectures (serial: the scene's order; pipelined: --order redblack), the
Verilator harness runs the RTL alone and counts the cycles of each frame and of its
constraint passes; the constraint updates of a frame (node updates of the centred rule)
divided by them are the updates per clock. The ECP5-85F fmax is the median of make synth's
nextpnr runs of the same build (build/synth/, or make synth's record docs/synth_record.json
when it holds them for the same RTL; "not placed" where make synth has not placed it). In the
same run, build/cpu_rope (model/cpu_rope.c, -O3, one core) runs the same scene in the same order in double and in float,
timed CPU_REPEATS times, the fastest run kept (other work on the machine only slows it); its double frames are the frame engine's
bit for bit (make test checks it). Beside it, build/cpu_fast (model/cpu_fast.c: the same physics as structure of
arrays, vectorised, -O3 -march=native) times the rows it runs, the red/black ones, the same way. The long bodies'
updates per clock at more iterations.
Then the 1024-node rope at rest (4x256, pipelined): for each split of a frame's constraint
passes into substeps and iterations, the cycles a frame takes on the RTL, the clock 60 frames
per second need, the stretch the frame engine reaches at rest, and one CPU core's frame rate.

Simulation speed: for the 4x5, 8x8 and 16x16 builds it runs the harness three ways - the RTL
and the cycle model in lockstep, the RTL alone, the cycle model alone - each REPEATS times,
and reports the median of the harness's own counter of simulated cycles per second, and
lockstep's cost against the RTL alone (target: at most 2x).

Every command's output is kept in build/bench/measured.json; `bench.py --reuse [OUT]` (make
bench-report) rewrites the page from those measurements and make synth's results as they are
then, measuring nothing.
"""
import json
import os
import platform
import re
import statistics
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import synth  # noqa: E402  (make synth's results: the fmax of a build)
from strandflow import build as flow_build, hwgen as flow_hwgen, run as flow_run  # noqa: E402
from strandflow.core import BUILD, ROOT, Failure, run  # noqa: E402

BUILDS = ["4x5", "8x8", "16x16"]
# 1x256, 2x256: pipelined chains make synth places; 2x512: units of 512 nodes, over which a pass's
# fixed costs (the pipe's drain) spread twice as thin as over 256
PHYS_BUILDS = ["4x5", "8x8", "16x16", "1x256", "2x256", "8x128", "4x256", "2x512"]
# Q10.8 chains (W = 18: a third of the multipliers a unit), pipelined only, with their rule: the
# 1024-node and 1536-node ropes make synth places; the 2048-node one (its routing does not finish)
# and the 3072-node one of the pairwise rule (its logic does not fit the device) it packs:
# docs/resources.md
NARROW_BUILDS = [("q10_4x256", "centred"), ("q10_6x256", "centred"), ("q10_8x256", "centred"),
                 ("q10_12x256", "pairwise")]
RULES = ["centred", "pairwise"]   # the pairwise scenes: bench_<build>.scene with rule = pairwise
PHYS_FRAMES = 10          # frames of the RTL run (every frame takes the same cycles)
ARCHS = [("serial", "serial", ""), ("pipelined", "redblack", "_pipe")]  # name, order, make synth's suffix
SPRING_BUILDS = ["4x5", "8x128", "4x256", "2x512", "1x1024"]  # tb/bench/springs_<build>.scene: chains of springs
GRAPH_SCENE, GRAPH_BUILD = "tb/bench/graph_cloth.scene", "cloth"  # a graph: make synth's cloth_pipe
ROPE = "4x256"            # the 1024-node rope: the largest centred chain an ECP5-85F holds (8 distance pipes)
ROPE_REST = "tb/bench/rope_rest.scene"  # the same rope hanging at rest
# the ropes at rest the page measures: (make synth's build of the rope, its scene at rest);
# the Q10.8 one is scaled to the format's range, a rope make synth places
ROPES = [(ROPE, ROPE_REST), ("q10_4x256", "tb/bench/rope_rest_q10.scene"), ("m17_4x256", "tb/bench/rope_rest_m17.scene")]
# the headline: the rope at rest on the normalised datapath (Q16.16 positions, 17-bit mantissas), the
# build whose own scene meets the stretch goal; against the optimised CPU program in float
HEADLINE = "m17_4x256"
GOAL_HEADLINE = 7.0       # x one optimised CPU core in float, on the same frames
# (substeps, iterations) of the rope at rest: 1024 constraint passes a frame, split differently
ROPE_POINTS = [(1, 1024), (4, 256), (16, 64), (32, 32), (64, 16), (128, 8)]
ROPE_FRAMES = 200         # frames of the rope at rest on the frame engine (it settles in a few dozen)
GOAL_ITERS = 16           # iterations of the per-clock goal's runs on the long bodies (besides the scenes' one)
CPU_SECONDS = "1.5"
CPU_REPEATS = 3           # cpu_rope runs of each row; the fastest is the CPU's figure
FRAMES = {"4x5": 400, "8x8": 120, "16x16": 30}
MODES = ["lockstep", "rtl", "model"]
REPEATS = 3
TARGET = 2.0
GOAL_PER_UNIT, GOAL_MHZ, GOAL_STRETCH = 0.9, 100.0, 0.05  # the speed work's goals (and GOAL_HEADLINE above)
GOALS = {}  # what physics(), rope() and springs() measured of them, for the page's first table


# Every command's output of a run is kept in MEASURED, so that `bench.py --reuse` can rewrite the
# page from that run's measurements with make synth's results as they are later (an fmax placed
# after the run): nothing is measured again and nothing is mixed from two runs.
MEASURED = os.path.join(ROOT, BUILD, "bench", "measured.json")
RUNS = {"reuse": False, "meta": {}, "out": {}, "taken": {}}  # out: command -> its outputs, in the order run


def sh(cmd):
    key = " ".join(cmd)
    if RUNS["reuse"]:  # a command run several times (timed repeats) gives its outputs back in turn
        n = RUNS["taken"].get(key, 0)
        if n >= len(RUNS["out"].get(key, [])):
            raise SystemExit(f"bench --reuse: {MEASURED} holds no run {n + 1} of '{key}' (run make bench)")
        RUNS["taken"][key] = n + 1
        return RUNS["out"][key][n]
    rc, out = run(cmd)
    if rc != 0:
        sys.stdout.write(out)
        raise SystemExit(f"bench: {' '.join(cmd)} failed")
    RUNS["out"].setdefault(key, []).append(out)
    return out


def harness_figures(cmd):
    """The figures (tb/harness.cpp's --json object) of a harness run, cmd = [harness, scene, args...];
    recorded and given back in turn with --reuse, as sh() does for other commands' output."""
    key = " ".join(cmd) + " --json"
    if RUNS["reuse"]:
        return json.loads(sh(cmd + ["--json"]))
    rc, out, figures = flow_run.harness(cmd[0], cmd[1], cmd[2:])
    if rc != 0 or not figures:
        sys.stdout.write(out)
        raise SystemExit(f"bench: {' '.join(cmd)} failed")
    RUNS["out"].setdefault(key, []).append(json.dumps(figures))
    return figures


def harness_for(scene, order=None):
    """The harness of the scene's build (in build/vl/, shared with make test's lockstep)."""
    try:
        info = flow_hwgen.info(scene, order)
        if not info["rtl"]:
            raise Failure(f"{scene}: {info['why']}")
        out = flow_build.harness_dir(info["params"])
        if RUNS["reuse"]:  # nothing is run again: only the binary's path, the key of its recorded runs
            return os.path.join(os.path.abspath(os.path.join(ROOT, out)), "harness")
        return flow_build.harness_for(scene, out, order=order)
    except Failure as e:
        raise SystemExit(f"bench: {e}")


def rtl_figures(scene, frames, order):
    """The harness's figures of a run of the RTL alone (its --json keys)."""
    return harness_figures([harness_for(scene, order), scene, "--frames", str(frames), "--mode", "rtl", "--order", order])


SYNTH = {"pnr": {}, "packs": {}, "mults": {}}  # make synth's results for this RTL (main() fills it from synth.gather)


def fmax_of(name):
    """(median MHz or None, text) of make synth's ECP5-85F runs of build `name`, for this RTL only
    (a result of other sources left in build/synth does not count)."""
    runs = (SYNTH["pnr"].get(name) or {}).get("ecp5")
    pack = SYNTH["packs"].get(name)
    packs = None
    if pack is not None:  # a build make synth packs: whether it fits
        comb = pack.get("util", {}).get("TRELLIS_COMB")
        packs = ("packs into the device" + (f" ({100 * comb[0] / comb[1]:.0f} % of TRELLIS_COMB)" if comb else "")
                 if pack.get("fits") else "does not fit")
    if runs is None:
        if packs is not None:  # packed but not placed
            return None, packs + ", not placed"
        # placed (or packed) by make synth, but not for this RTL; or not placed at all
        run_by_synth = name in synth.BUILD_MAP and bool(synth.ecp5_steps(name))
        need = SYNTH["mults"].get(name)
        if not run_by_synth and need and need > synth.ECP5_85_MULTS:  # its pipes' multipliers do not fit
            return None, f"does not fit: its pipes need {need:g} MULT18X18D, the device has {synth.ECP5_85_MULTS}"
        return None, "no make synth result for this RTL" if run_by_synth else "not placed"
    text, med = synth.fmax_cells(runs)
    return med, (f"{med:.1f}" if med is not None else text + (f"; {packs}" if packs else ""))


def cpu_rate(scene, order, kind):
    """(updates/s, cflags) of cpu_rope on the scene: the fastest of CPU_REPEATS timed runs, since
    the machine's other work can only slow a run down and the CPU should get its best figure."""
    rates = []
    for _ in range(CPU_REPEATS):
        text = sh([os.path.join(BUILD, "cpu_rope"), scene, "--order", order, "--type", kind,
                   "--min-seconds", CPU_SECONDS])
        rates.append(float(re.search(r"updates_per_s=([\d.]+)", text).group(1)))
    return max(rates), re.search(r'cflags="([^"]*)"', text).group(1)


def cpu_fast_stretch(scene, kind, rest_frames):
    """The stretch at rest (%) cpu_fast's own run reaches on the scene in float or double: the largest of any link
    in the last rest_frames frames (cpu_fast --stretch), or None with --reuse of a run that measured nothing of it."""
    cmd = [os.path.join(BUILD, "cpu_fast"), scene, "--order", "redblack", "--type", kind, "--stretch", str(rest_frames)]
    if RUNS["reuse"] and " ".join(cmd) not in RUNS["out"]:
        return None
    return float(re.search(r"stretch_rest=([\d.eE+-]+)", sh(cmd)).group(1))


def cpu_fast_rate(scene, order, kind):
    """(updates/s, cflags) of cpu_fast (the optimised CPU program) on the scene, the fastest of CPU_REPEATS timed runs
    as cpu_rate's; (None, None) where it does not run the scene (the serial order) or, with --reuse, where the run
    measured nothing of it (a run before cpu_fast)."""
    cmd = [os.path.join(BUILD, "cpu_fast"), scene, "--order", order, "--type", kind, "--min-seconds", CPU_SECONDS]
    if order != "redblack" or (RUNS["reuse"] and " ".join(cmd) not in RUNS["out"]):
        return None, None
    rates = []
    for _ in range(CPU_REPEATS):
        text = sh(cmd)
        rates.append(float(re.search(r"updates_per_s=([\d.]+)", text).group(1)))
    return max(rates), re.search(r'cflags="([^"]*)"', text).group(1)


def physics():
    """Rows of the throughput table, the rope figures and notes (as markdown lines)."""
    rows = []
    flags = fast_flags = ""
    narrow = [b for b, _ in NARROW_BUILDS]
    for b, rule in [(b, rule) for rule in RULES for b in PHYS_BUILDS] + NARROW_BUILDS:
        scene = f"tb/bench/bench_{b}.scene" if rule == "centred" else rule_variant(f"tb/bench/bench_{b}.scene", rule)
        m, k = units_nodes(b)
        for arch, order, suffix in ARCHS if b not in narrow else ARCHS[1:]:
            f = rtl_figures(scene, PHYS_FRAMES, order)
            cyc, upf, per_clock, per_clock_c = (f["cycles_per_frame"], f["constraint_updates_per_frame"], f["constraint_updates_per_clock"],
                                                f["constraint_updates_per_clock_in_passes"])
            # make synth's build of this one (another rule is another build: "_pair")
            name = b + ("_pair" if rule == "pairwise" else "") + suffix
            mhz, mhz_text = fmax_of(name) if name in synth.BUILD_MAP else (None, "not placed")
            cpu_d, flags = cpu_rate(scene, order, "double")
            cpu_f, _ = cpu_rate(scene, order, "float")
            fast_d, fast_flags_d = cpu_fast_rate(scene, order, "double")
            fast_f, _ = cpu_fast_rate(scene, order, "float")
            fast_flags = fast_flags_d or fast_flags
            hw = per_clock * mhz * 1e6 if mhz else None
            rows.append(dict(build=b, rule=rule, arch=arch, nodes=m * k, m=m, cycles=cyc, upf=upf, per_clock=per_clock,
                             per_clock_c=per_clock_c, mhz=mhz, mhz_text=mhz_text, hw=hw, cpu_d=cpu_d, cpu_f=cpu_f,
                             fast_d=fast_d, fast_f=fast_f))
            print(f"bench {b} {rule} {arch}: {cyc} cycles/frame, {per_clock:.4f} updates/clock, fmax {mhz_text}, "
                  f"CPU {cpu_d / 1e6:.1f} M/s double, {cpu_f / 1e6:.1f} M/s float"
                  + (f"; optimised {fast_d / 1e6:.1f} / {fast_f / 1e6:.1f} M/s" if fast_d else ""), flush=True)
    mega = lambda v: f"{v / 1e6:.2f}" if v is not None else "-"
    lines = ["| build | rule | architecture | nodes | cycles per frame (RTL) | updates per clock, whole frame | "
             "updates per clock in the constraint passes (of M) | fmax ECP5-85F, MHz (median) | updates/s at fmax, M | "
             "CPU double, M/s | CPU float, M/s | CPU optimised double, M/s | CPU optimised float, M/s | core / CPU optimised float |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        ratio = f"**{r['hw'] / r['fast_f']:.3f}x**" if r["hw"] and r["fast_f"] else "-"
        lines.append(f"| {r['build']} | {r['rule']} | {r['arch']} | {r['nodes']} | {r['cycles']} | {r['per_clock']:.4f} | "
                     f"{r['per_clock_c']:.4f} ({r['per_clock_c'] / r['m']:.3f} M) | {r['mhz_text']} | {mega(r['hw'])} | "
                     f"{mega(r['cpu_d'])} | {mega(r['cpu_f'])} | {mega(r['fast_d'])} | {mega(r['fast_f'])} | {ratio} |")
    notes = ["", f"CPU: `{flags}`, one core, the same scene in the same order, the fastest of {CPU_REPEATS} timed runs of "
             f"at least {CPU_SECONDS} s each; its double frames are the frame "
             "engine's bit for bit (`cpu_rope --check`, in make test).",
             f"CPU optimised: `{fast_flags}` (model/cpu_fast.c), the same physics written as structure of arrays, even and "
             "odd nodes apart, so that the compiler vectorises each colour of a pass; one core, the red/black rows only "
             "(\"-\" otherwise), timed as above; its double frames are the frame engine's bit for bit too "
             "(`cpu_fast --check`, in make test).", ""]
    notes += long_bodies(rows)
    # the largest placed pipelined build against the CPU, and the rope
    pipe = [r for r in rows if r["arch"] == "pipelined" and r["hw"]]
    bigger = [r for r in rows if r["arch"] == "pipelined" and not r["hw"]
              and pipe and r["nodes"] > max(x["nodes"] for x in pipe) and "packs into" in r["mhz_text"]]  # (placed or not)
    if bigger:  # a larger build fits the device but has no fmax: the ratio above is not the largest's
        GOALS["unplaced"] = "; " + ", ".join(f"{r['build']} {r['mhz_text']}" for r in bigger)
    if pipe:
        big = max(pipe, key=lambda r: r["nodes"] * 1000 + r["m"])
        GOALS["ratio"] = (big["build"], big["hw"] / big["cpu_d"], big["mhz"])
        vs_fast = (f"**{big['hw'] / big['fast_f']:.3f}x** one optimised core in float and {big['hw'] / big['fast_d']:.3f}x "
                   "in double; " if big["fast_f"] else "")
        notes.append(f"The largest pipelined build placed on the ECP5-85F is **{big['build']}** ({big['nodes']} nodes, "
                     f"{big['m']} unit{'s' if big['m'] > 1 else ''}, {width_of(big['build'])}): {mega(big['hw'])} M constraint updates/s at {big['mhz']:.1f} MHz, "
                     + vs_fast + f"{big['hw'] / big['cpu_d']:.2f}x cpu_rope in double (these bench scenes run one "
                     "iteration a frame: they measure throughput, not a rope that holds its shape; the ropes at rest below "
                     "do, with their stretch).")
    else:
        notes.append("No pipelined build has an fmax yet (run `make synth`): the updates per second and the "
                     "ratio to the CPU need it.")
    # the clock each pipelined build would need for the ratio goal: its updates per clock are measured
    # above, so this is what the place and route has to reach (not a figure of the device)
    need = [f"{r['build']} {r['rule']} ({width_of(r['build'])}, {r['m']} units; {r['mhz_text']}) "
            f"{GOAL_HEADLINE * r['fast_f'] / r['per_clock'] / 1e6:,.0f} MHz"
            for r in rows if r["arch"] == "pipelined" and r["nodes"] >= 1024 and r["fast_f"]]
    if need:
        notes.append("")
        notes.append(f"The clock at which a pipelined build would reach {GOAL_HEADLINE:g}x one optimised core in float, "
                     "from the updates per clock measured above and the CPU's row (what its place and route would have "
                     "to reach, not a measured fmax): " + "; ".join(need) + ".")
    return lines + notes + [x for b, sc in ROPES for x in rope(rows, b, sc)]


def counted(n, word):
    """'1 substep', '4 substeps'."""
    return f"{n} {word}{'' if n == 1 else 's'}"


def units_nodes(b):
    """(M, K) of a bench build's name: 4x256, q10_4x256."""
    m, k = re.search(r"(\d+)x(\d+)$", b).groups()
    return int(m), int(k)


def width_of(b):
    """The bench build's number format as the page names it, from its scene's [format]."""
    text = open(os.path.join(ROOT, f"tb/bench/bench_{b}.scene")).read()
    w, f = (int(re.search(rf"^{k} = (\d+)$", text, re.M).group(1)) for k in ("width", "frac"))
    return f"Q{w - f}.{f}"


def long_bodies(rows):
    """The per-clock goal on the long bodies (N >= 256): updates per clock in the constraint passes per
    unit, measured on the RTL at the scenes' one iteration and at GOAL_ITERS (as markdown lines)."""
    long_pipe = [r for r in rows if r["arch"] == "pipelined" and r["nodes"] >= 256]
    out = ["", f"**Long bodies.** The pipelined builds of at least 256 nodes, their updates per clock in the constraint "
               f"passes per unit (of the one a clock a unit can take) at the scenes' one iteration and at {GOAL_ITERS}: a "
               "substep pays the pipe's drain once, whatever the iterations, and a sweep of a unit of K nodes waits for "
               "the pipe's latency unless floor(K/2) + 2 >= LP + 4 (docs/architecture.md, section 3b). Measured on the RTL.", "",
           f"| build | rule | nodes per unit | 1 iteration | {GOAL_ITERS} iterations |", "|---|---|--:|--:|--:|"]
    for r in long_pipe:
        scene = f"tb/bench/bench_{r['build']}.scene" if r["rule"] == "centred" else \
            rule_variant(f"tb/bench/bench_{r['build']}.scene", r["rule"])
        path = write_variant(scene, f"{os.path.basename(scene)[:-6]}_{GOAL_ITERS}it", iterations=GOAL_ITERS)
        f = rtl_figures(path, 2, "redblack")
        k = r["nodes"] // r["m"]
        per = (r["per_clock_c"] / r["m"], f["constraint_updates_per_clock_in_passes"] / r["m"])
        out.append(f"| {r['build']} | {r['rule']} | {k} | {per[0]:.3f} | {per[1]:.3f} |")
        key = f"per_unit_{r['rule']}"
        if key not in GOALS or per[0] > GOALS[key][2]:  # the best at one iteration, the hard case
            GOALS[key] = (r["build"], per[1], per[0])
        print(f"bench long body {r['build']} {r['rule']}: {per[0]:.3f} / {per[1]:.3f} updates per clock a unit "
              f"at 1 / {GOAL_ITERS} iterations", flush=True)
    return out


def graph():
    """The cloth (a graph of rods) in both architectures against the CPU (as markdown lines)."""
    lines = ["| architecture | nodes | rods | colours | cycles per frame (RTL) | updates per clock in the constraint "
             "passes | fmax ECP5-85F, MHz | updates/s at fmax, M | CPU double, M/s | CPU float, M/s | "
             "core / CPU double |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    mega = lambda v: f"{v / 1e6:.2f}" if v is not None else "-"
    for arch, order, suffix in ARCHS:
        info = flow_hwgen.info(GRAPH_SCENE, order)["params"]
        f = rtl_figures(GRAPH_SCENE, PHYS_FRAMES, order)
        # make synth places the pipelined cloth only
        mhz, mhz_text = fmax_of(GRAPH_BUILD + suffix) if suffix else (None, "not placed")
        cpu_d, _ = cpu_rate(GRAPH_SCENE, order, "double")
        cpu_f, _ = cpu_rate(GRAPH_SCENE, order, "float")
        hw = f["constraint_updates_per_clock"] * mhz * 1e6 if mhz else None
        colours = info["COLOURS"] if info["ARCH"] else "-"
        lines.append(f"| {arch} | {info['K']} | {info['E_RODS']} | {colours} | {f['cycles_per_frame']} | "
                     f"{f['constraint_updates_per_clock_in_passes']:.4f} | {mhz_text} | {mega(hw)} | {mega(cpu_d)} | {mega(cpu_f)} | "
                     f"{f'**{hw / cpu_d:.2f}x**' if hw else '-'} |")
        print(f"bench graph {arch}: {f['cycles_per_frame']} cycles/frame, {f['constraint_updates_per_clock_in_passes']:.4f} "
              f"updates/clock in the passes, fmax {mhz_text}, CPU {cpu_d / 1e6:.1f} M/s double", flush=True)
    return lines


def rope(rows, rope_b, rest_scene):
    """The 1024-node rope of build rope_b, scene rest_scene: at rest, the stretch each split of a frame's constraint passes into substeps
    and iterations reaches, the cycles a frame takes on the RTL and the clock 60 frames per second
    need, and one CPU core on the same frames (as markdown lines)."""
    r = next((x for x in rows if x["build"] == rope_b and x["arch"] == "pipelined" and x["rule"] == "centred"), None)
    if r is None:  # a rope without a row in the throughput table: its build's figures directly
        m_, k_ = units_nodes(rope_b)
        r = dict(mhz=fmax_of(f"{rope_b}_pipe")[0], nodes=m_ * k_, m=m_)
    mhz = r["mhz"]
    text = open(os.path.join(ROOT, rest_scene)).read()
    accel = [float(v) for v in re.search(r"^accel = (.*)$", text, re.M).group(1).split()]
    g = sum(v * v for v in accel) ** 0.5
    lsb = 2.0 ** -int(re.search(r"^frac = (\d+)$", text, re.M).group(1))
    rest = float(re.search(r"^rest = (\S+)$", text, re.M).group(1))
    points = []
    for subs, iters in ROPE_POINTS:
        tag = os.path.basename(rest_scene)[:-6]
        path = write_variant(rest_scene, f"{tag}_s{subs}_i{iters}", iterations=iters, substeps=subs, frames=ROPE_FRAMES)
        f = rtl_figures(path, 1, "redblack")
        csv = os.path.join(BUILD, "bench", f"{tag}_s{subs}_i{iters}.csv")
        st = re.search(r"max stretch ([\d.]+) %", sh([os.path.join(BUILD, "strand"), "run", path, "--csv", csv]))
        cpu_d, _ = cpu_rate(path, "redblack", "double")
        fast_d, _ = cpu_fast_rate(path, "redblack", "double")
        fast_f, _ = cpu_fast_rate(path, "redblack", "float")
        p = dict(subs=subs, iters=iters, cyc=f["cycles_per_frame"], per_clock=f["constraint_updates_per_clock"],
                 per_clock_c=f["constraint_updates_per_clock_in_passes"], smax=float(st.group(1)), sfin=rest_stretch(csv, rest),
                 cpu_fps=cpu_d / f["constraint_updates_per_frame"], gh2=g / subs ** 2 / lsb,
                 upf=f["constraint_updates_per_frame"], fast_d_fps=fast_d / f["constraint_updates_per_frame"] if fast_d else None,
                 fast_f_fps=fast_f / f["constraint_updates_per_frame"] if fast_f else None,
                 cpu_st_d=cpu_fast_stretch(path, "double", ROPE_FRAMES // 2),
                 cpu_st_f=cpu_fast_stretch(path, "float", ROPE_FRAMES // 2))
        points.append(p)
        print(f"bench rope {rope_b} at rest, {subs} substeps x {iters} iterations: {p['cyc']} cycles/frame, stretch "
              f"{p['sfin']} % at rest, CPU {p['cpu_fps']:.1f} frames/s", flush=True)
    fmt_ = format_of(rest_scene)
    out = ["", f"### The 1024-node rope at rest, {fmt_} ({rope_b})", "",
           f"`{rest_scene}`: the rope of {rope_b} ({r['nodes']} nodes, {fmt_}) hanging from one pin, starting unstretched at "
           "rest, gravity, damping 0.01, the centred rule in the red/black order. Every row runs 1,024 constraint "
           "passes a frame, split into substeps and iterations differently. *Cycles per frame* and *updates per "
           "clock* are the RTL's (the pipelined build, one frame, counted by the harness); *clock for 60 frames/s* "
           "is cycles per frame x 60; the stretch is the frame engine's (bit for bit the RTL's) over "
           f"{ROPE_FRAMES} frames: the largest of any link, and *at rest* the largest of any link in the last "
           f"{ROPE_FRAMES // 2} frames, when the rope hangs still but for a small tremor (goal: at most 0.05 %); *g h^2* is gravity's step in LSBs of the format (below a few LSBs "
           "its rounding changes gravity noticeably; below 0.5 it vanishes). The CPU columns are one core on the same "
           f"frames, the fastest of {CPU_REPEATS} runs each, measured now: cpu_rope (double, the frame engine's order and "
           "operations) and cpu_fast (the optimised program, double and float); *core / CPU* is against cpu_fast in "
           "float, the fastest. The CPU's own stretch at rest, in double and in float, is cpu_fast's run of the same "
           "frames (`--stretch`): the accuracy each side reaches beside its speed.", "",
           "| substeps | iterations | g h^2, LSB | cycles per frame (RTL) | updates per clock in the constraint passes "
           "(of M) | clock for 60 frames/s, MHz | " + (f"frames/s at {mhz:.1f} MHz | " if mhz else "")
           + "CPU double (cpu_rope), frames/s | CPU optimised double, frames/s | CPU optimised float, frames/s | "
           + ("core / CPU optimised float | " if mhz else "") + "largest stretch | stretch at rest | "
           "CPU's stretch at rest, double / float |",
           "|--:|--:|--:|--:|--:|--:|" + ("--:|" if mhz else "") + "--:|--:|--:|" + ("--:|" if mhz else "") + "--:|--:|--:|"]
    for p in points:
        cells = [str(p["subs"]), str(p["iters"]), f"{p['gh2']:.1f}", str(p["cyc"]),
                 f"{p['per_clock_c']:.3f} ({p['per_clock_c'] / r['m']:.3f} M)", f"{60 * p['cyc'] / 1e6:.1f}"]
        if mhz:
            cells.append(f"{mhz * 1e6 / p['cyc']:.0f}")
        cells += [f"{p['cpu_fps']:.1f}", f"{p['fast_d_fps']:.1f}" if p["fast_d_fps"] else "-",
                  f"{p['fast_f_fps']:.1f}" if p["fast_f_fps"] else "-"]
        if mhz:
            cells.append(f"**{mhz * 1e6 / p['cyc'] / p['fast_f_fps']:.3f}x**" if p["fast_f_fps"] else "-")
        cells += [f"{p['smax']:.4f} %", f"**{p['sfin']:.4f} %**",
                  (f"{p['cpu_st_d']:.4f} / {p['cpu_st_f']:.4f} %" if p["cpu_st_d"] is not None else "-")]
        out.append("| " + " | ".join(cells) + " |")
    out.append("")
    # the goal: the best stretch at rest that 60 frames per second allow at the build's fmax
    ok = [p for p in points if p["gh2"] >= 0.5 and (not mhz or 60 * p["cyc"] <= mhz * 1e6)]
    best = min(ok, key=lambda p: p["sfin"]) if ok else None
    if best:
        GOALS.setdefault("stretch", []).append((rope_b, best["subs"], best["iters"], best["sfin"], mhz, rest_scene))
    # the headline: of the splits within the stretch goal that run at 60 frames/s, the fastest against the CPU
    if rope_b == HEADLINE:
        good = [p for p in points if p["sfin"] <= GOAL_STRETCH and p["gh2"] >= 0.5 and p["fast_f_fps"]]
        if good:
            h = min(good, key=lambda p: p["cyc"])
            GOALS["headline"] = dict(build=rope_b, scene=rest_scene, mhz=mhz, point=h, per_unit=h["per_clock_c"] / r["m"])
    cpu_ok = [p for p in points if p["cpu_fps"] >= 60 and p["gh2"] >= 0.5]
    if mhz:
        out.append(f"At {rope_b}'s fmax of {mhz:.1f} MHz every row but those over {mhz:.1f} MHz runs at 60 frames/s"
                   + (f"; among those whose gravity does not vanish (g h^2 at least 0.5 LSB) the best stretch at rest "
                      f"is **{best['sfin']:.4f} %** ({counted(best['subs'], 'substep')} x "
                      f"{counted(best['iters'], 'iteration')})." if best else
                      ": none of them with a gravity that does not vanish (g h^2 at least 0.5 LSB)."))
    else:
        out.append(f"The {rope_b} pipelined build has no fmax from make synth (docs/resources.md), so which rows run at "
                   "60 frames/s on it is not measured; the column *clock for 60 frames/s* says what each needs.")
    out.append("One CPU core (double) runs " + (", ".join(f"{p['subs']} x {p['iters']}" for p in cpu_ok)
                                                 + " at 60 frames/s" if cpu_ok else "none of these rows at 60 frames/s")
               + f": it manages {max(p['cpu_fps'] for p in points):.0f} frames/s at best, "
               f"{min(p['cpu_fps'] for p in points):.0f} at worst.")
    return out


def format_of(scene):
    """A scene's number format as the page names it, with its mantissa when it has one."""
    text = open(os.path.join(ROOT, scene)).read()
    w, f = (int(re.search(rf"^{k} = (\d+)$", text, re.M).group(1)) for k in ("width", "frac"))
    mb = re.search(r"^mantissa = (\d+)$", text, re.M)
    return f"Q{w - f}.{f}" + (f", {mb.group(1)}-bit mantissas" if mb and int(mb.group(1)) else "")


def rest_stretch(csv, rest):
    """The largest |length - rest| / rest (%) of any link of a chain in the second half of the
    frames of a `strand run --csv` file (frame,node,x,y[,z], nodes in chain order)."""
    frames = {}
    with open(os.path.join(ROOT, csv)) as fh:
        next(fh)
        for line in fh:
            v = line.split(",")
            frames.setdefault(int(v[0]), []).append([float(x) for x in v[2:]])
    last = max(frames)
    worst = 0.0
    for fr in range(last // 2 + 1, last + 1):
        pts = frames[fr]
        for a, b in zip(pts, pts[1:]):
            length = sum((p - q) ** 2 for p, q in zip(a, b)) ** 0.5
            worst = max(worst, abs(length - rest) / rest)
    return 100 * worst


def springs():
    """The spring pass in both architectures: spring updates per clock in the spring passes,
    counted by the harness on the RTL (as markdown lines)."""
    lines = ["| build | architecture | springs | cycles per frame (RTL) | spring updates per clock in the spring "
             "passes (of M) |", "|---|---|---|---|---|"]
    for b in SPRING_BUILDS:
        scene = f"tb/bench/springs_{b}.scene"
        m, k = units_nodes(b)
        for arch, order, _ in ARCHS:
            f = rtl_figures(scene, 3, order)
            cyc, per_clock = f["cycles_per_frame"], f["spring_updates_per_clock_in_passes"]
            lines.append(f"| {b} | {arch} | {m * k - 1} | {cyc} | {per_clock:.4f} ({per_clock / m:.3f} M) |")
            if arch == "pipelined" and m * k >= 256 and per_clock / m > GOALS.get("per_unit_springs", ("", -1))[1]:
                GOALS["per_unit_springs"] = (b, per_clock / m)  # the best long body
            print(f"bench springs {b} {arch}: {cyc} cycles/frame, {per_clock:.4f} spring updates/clock", flush=True)
    return lines


def rule_variant(scene, rule):
    """scene with its constraint rule replaced, written under build/bench/."""
    name = os.path.basename(scene).replace(".scene", f"_{rule}.scene")
    return derived(scene, name, {"constraints.rule": rule})


def write_variant(scene, name, **keys):
    """scene with [time] keys set (iterations, substeps, frames), written under build/bench/."""
    return derived(scene, f"{name}.scene", {f"time.{k}": v for k, v in keys.items()})


def derived(scene, name, keys):
    """build/bench/NAME: scene with keys set (strand set)."""
    try:
        return flow_run.scene_set(scene, os.path.join(BUILD, "bench", name), keys)
    except Failure as e:
        raise SystemExit(f"bench: {e}")


# the centred rule's passes take the Verlet step in their first sweep (FUSE): its 4 cycles are the passes' too
FUSED_NOTE = ", and the 4 cycles by which the first sweep, which takes the Verlet step, is longer"


def main():
    args = sys.argv[1:]
    if "-h" in args or "--help" in args:  # (else the name would be taken for OUT and the whole bench run)
        print(__doc__.strip() + "\n\nusage: bench.py [--reuse] [OUT]   (OUT: docs/performance.md; make bench, make bench-report)")
        return
    if "--reuse" in args:
        args.remove("--reuse")
        try:
            with open(MEASURED) as f:
                RUNS.update(json.load(f), reuse=True)
        except (OSError, ValueError) as e:
            raise SystemExit(f"bench --reuse: {MEASURED}: {e} (run make bench first)")
    out = args[0] if args else "docs/performance.md"
    os.chdir(ROOT)  # the RTL sources by the names make gives them (they are part of synth's keys)
    res, SYNTH["pnr"], SYNTH["packs"], missing_steps = synth.gather(os.path.join(BUILD, "synth"), os.path.join(BUILD, "gen"),
                                                                   synth.rtl_sources())
    SYNTH["mults"] = synth.pipe_mults(res)[1]
    missing = len(missing_steps)
    print(f"bench: make synth's results for this RTL taken from build/synth and its record "
          f"({missing} step(s) not run for it)", flush=True)
    phys = physics()
    rows = []
    for b in BUILDS:
        scene = f"tb/bench/bench_{b}.scene"
        harness = harness_for(scene)
        # the modes take turns within each repeat, so a change in the machine's load
        # falls on all three alike
        runs = {mode: [] for mode in MODES}
        for _ in range(REPEATS):
            for mode in MODES:
                f = harness_figures([harness, scene, "--frames", str(FRAMES[b]), "--mode", mode])
                runs[mode].append(f["simulated_cycles_per_s"])
                cycles = f["cycles"]
        speeds = {mode: statistics.median(v) for mode, v in runs.items()}
        for mode in MODES:
            print(f"bench {b} {mode}: {speeds[mode]:.0f} cycles/s (median of {REPEATS}, {cycles} cycles each)", flush=True)
        rows.append((b, cycles, speeds))

    spring_lines, graph_lines = springs(), graph()
    cpu = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    verilator = sh(["verilator", "--version"]).strip()
    if not RUNS["reuse"]:  # the machine and its load when the measurements ended, kept with them
        RUNS["meta"] = dict(cpu=cpu, cores=os.cpu_count(), date=time.strftime("%Y-%m-%d"), load=list(os.getloadavg()),
                            python=f"{platform.python_implementation()} {platform.python_version()}")
        os.makedirs(os.path.dirname(MEASURED), exist_ok=True)
        with open(MEASURED + ".tmp", "w") as f:
            json.dump({"meta": RUNS["meta"], "out": RUNS["out"]}, f)
        os.replace(MEASURED + ".tmp", MEASURED)
    meta = RUNS["meta"]
    load = meta["load"]
    rewritten = (f" This page was rewritten on {time.strftime('%Y-%m-%d')} from that run's measurements "
                 "(`scripts/bench.py --reuse`, build/bench/measured.json) with make synth's results as they were "
                 "then." if RUNS["reuse"] else "")
    lines = ["# Performance", "",
             "Generated by `make bench` (scripts/bench.py); every figure below comes from that run, except the fmax, "
             "which comes from `make synth`'s place and route of the same RTL (its record, docs/synth_record.json; "
             "docs/resources.md shows the figures of the last complete make synth).",
             f"Machine: {meta['cpu']}, {meta['cores']} cores; {verilator}; {meta['python']} for the driver. "
             f"Measured {meta['date']}; load average "
             f"{load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} (1 / 5 / 15 min) when the run ended: other work on the "
             "machine slows the CPU and simulation columns, so compare the columns of one row rather than rows of "
             f"different runs.{rewritten}", "",
             "## Physics throughput: the core against one CPU core", "",
             "Constraint updates are node updates of the centred rule (each node moved to the mean of its two "
             "targets: two distance evaluations) or link updates of the pairwise rule (one distance evaluation, "
             "both ends moved), counted over every iteration of every substep of the benchmark "
             "scenes (`tb/bench/bench_<build>.scene`: a rope of M x K nodes, Q16.16 with full-precision root and "
             "divide, gravity, the mouse, one iteration; the pairwise rows run the same scene with `rule = "
             "pairwise`, another build: make synth's `_pair` builds). *Serial* is the reference-000 sequencer (one "
             "distance datapath for the whole body, the scene's order); *pipelined* is ARCH = 1 (the red/black order, "
             "every unit reading a pair of neighbours a clock from its two memory banks and taking one constraint a "
             "clock: a node of the centred rule through two distance pipes, a link of the pairwise rule through one, "
             "so its ceiling is M updates a clock; a sweep takes max(floor(K/2) + 2, LP + 4) cycles, so a short body waits "
             "for the pipe's latency LP at every colour switch, and a long one pays its drain once a substep; with the "
             "centred rule the first sweep of a substep also takes the Verlet step, 4 cycles later, where the pairwise "
             "rule has a Verlet pass of ceil(K/2) + 6 cycles: docs/architecture.md, section 3b). Cycles "
             "are counted by the harness on the RTL (Verilator, RTL alone); updates/s = updates per clock over whole "
             "frames x fmax.", "",
             *phys, "",
             "## The spring pass", "",
             "Spring updates are spring forces gathered (one a link, both ends), counted over every substep of "
             "`tb/bench/springs_<build>.scene` (a chain of damped springs, no rods, Q16.16). *Serial* is "
             "pair_sequencer (one spring_force datapath for the body, link after link); *pipelined* is ARCH = 1 "
             "(spring_stream: every unit streams its links through its own spring_force_pipe, one a clock, and "
             "gathers its nodes' forces in link order, so its ceiling is M springs a clock less one fill and drain "
             "of the pipe a pass). Cycles counted by the harness on the RTL.", "",
             *spring_lines, "",
             "## A graph: the cloth", "",
             f"`{GRAPH_SCENE}`: 16 x 16 nodes joined by 480 rods (the grid's edges), the top row pinned, Q16.16 at "
             "full precision, the pairwise rule, gravity and the mouse, one iteration. *Serial* walks the rods one "
             "at a time through one toward (pair_sequencer); *pipelined* is graph_stream (ARCH = 1): the rods by the "
             "colours of an edge colouring, one toward_pipe, a new rod every two clocks (a rod reads two nodes and "
             "writes two through the unit's one read and one write port), the pipe drained after each colour, so its "
             "ceiling is 0.5 rod updates a clock. Updates are rod updates, counted by the harness on the RTL; "
             "updates/s = updates per clock over whole frames x fmax; the CPU (cpu_rope, as above) runs the same "
             "scene in the same order.", "",
             *graph_lines, "",
             "## Simulation speed", "",
             "Simulated clock cycles per second of the Verilator harness (`tb/harness.cpp`), the median of "
             f"{REPEATS} runs (the three modes take turns within each repeat), by its own counter (wall-clock time of the run loop). Each run resets the core, writes "
             "the setup and runs the frames of `tb/bench/bench_<build>.scene`. *Lockstep* steps the RTL and the C "
             "cycle model by the same edge and compares every output every cycle; *RTL alone* drives the same "
             "stimulus without the model; *cycle model alone* runs the model without the RTL.", "",
             "| build | nodes | cycles run | lockstep (cycles/s) | RTL alone (cycles/s) | cycle model alone (cycles/s) | lockstep cost |",
             "|---|---|---|---|---|---|---|"]
    worst = 0.0
    for b, cycles, s in rows:
        m, k = (int(x) for x in b.split("x"))
        cost = s["rtl"] / s["lockstep"]
        worst = max(worst, cost)
        lines.append(f"| {b} | {m * k} | {cycles} | {s['lockstep']:.0f} | {s['rtl']:.0f} | {s['model']:.0f} | {cost:.2f}x |")
    lines += ["", f"Target: lockstep costs at most {TARGET:g}x the RTL alone. Measured: at most {worst:.2f}x, "
              f"so the target is {'met' if worst <= TARGET else 'not met'}.", ""]
    # the goals first, under the header: every figure is one the sections below measured
    at = lines.index("## Physics throughput: the core against one CPU core")
    lines[at:at] = goals_table()
    with open(os.path.join(ROOT, out), "w") as f:
        f.write("\n".join(lines))
    print(f"wrote {out}")


def goals_table():
    """The speed work's goals against this run's figures (from GOALS), as markdown lines."""
    met = lambda ok: "**met**" if ok else "**missed**"
    rows = []
    for key, what in (("per_unit_centred", "centred rule"), ("per_unit_pairwise", "pairwise rule"),
                      ("per_unit_springs", "spring pass")):
        if key == "per_unit_springs" and key in GOALS:
            b, v = GOALS[key]
            rows.append(f"| >= {GOAL_PER_UNIT} x M updates per clock on a long body (N >= 256), {what} | {b} "
                        f"pipelined ({units_nodes(b)[1]} nodes a unit): {v:.3f} M (one spring a clock a unit, less the pipe's fill and drain each pass) "
                        f"| {met(v >= GOAL_PER_UNIT)} |")
        elif key in GOALS:
            b, v, v1 = GOALS[key]
            rows.append(f"| >= {GOAL_PER_UNIT} x M updates per clock on a long body (N >= 256), {what} | {b} "
                        f"pipelined ({units_nodes(b)[1]} nodes a unit; the long-body table has every build): "
                        f"{v:.4f} M at {GOAL_ITERS} iterations, {v1:.4f} M at 1 (one constraint a clock a "
                        f"unit, less the pipe's drain each substep{FUSED_NOTE if what == 'centred rule' else ''}) | "
                        f"{met(v >= GOAL_PER_UNIT)} at {GOAL_ITERS}, "
                        f"{met(v1 >= GOAL_PER_UNIT)} at 1 |")
    # the fmax is make synth's: every pipelined build it placed for this RTL, whether or not a row above runs it
    placed = sorted(((fmax_of(b)[0], b) for b in synth.PIPE if fmax_of(b)[0] is not None), reverse=True)
    if placed:
        mhz, b = placed[0]
        chains = [x for x in placed if not synth.BUILD_MAP[x[1]][0].get("GRAPH")]
        each = ", ".join(f"{x[1]} {x[0]:.1f}" for x in placed)
        # the goal is judged on the best build and, apart, on the largest (the CPU ratio's)
        largest = GOALS.get("ratio")
        status = met(mhz >= GOAL_MHZ)
        of_largest = ""
        if largest is not None and largest[0] != b.removesuffix("_pipe"):
            of_largest = f"; the largest placed pipelined chain, {largest[0]}: {largest[2]:.1f} MHz"
            status = f"{met(mhz >= GOAL_MHZ)} ({b}); {met(largest[2] >= GOAL_MHZ)} ({largest[0]})"
        rows.append(f"| ECP5-85F fmax >= {GOAL_MHZ:g} MHz | the best pipelined build make synth placed, {b}: "
                    f"{mhz:.1f} MHz{of_largest} (all placed: {each} MHz"
                    f"{'' if chains else '; no pipelined chain placed for this RTL'}) | {status} |")
    else:
        rows.append(f"| ECP5-85F fmax >= {GOAL_MHZ:g} MHz | no pipelined build placed for this RTL | **not measured** |")
    for rope_b, subs, iters, st, mhz, rest_scene in GOALS.get("stretch", []):
        where = f"at 60 frames/s on {rope_b} at its fmax, {mhz:.1f} MHz" if mhz else \
            f"({rope_b} has no fmax: at the clock its row says 60 frames/s need)"
        rows.append(f"| the 1024-node rope at rest: stretch <= {GOAL_STRETCH} % | {format_of(rest_scene)}: {st:.4f} % with "
                    f"{counted(subs, 'substep')} x {counted(iters, 'iteration')}, {where} | {met(st <= GOAL_STRETCH)} |")
    rows += headline_rows(met)
    return ["## The goals, measured", "",
            "The speed work's goals against the figures of this page (the sections below say how each is "
            "measured).", "", "| goal | measured | |", "|---|---|---|", *rows, ""]


def headline_rows(met):
    """The headline: the rope at rest within the stretch goal on the normalised build, against the optimised CPU
    core in float (and double), and the device's bound from make synth's unit cost (as goal-table rows)."""
    h = GOALS.get("headline")
    if h is None:
        return [f"| the 1024-node rope at rest within {GOAL_STRETCH} % at 60 frames/s, >= {GOAL_HEADLINE:g}x one "
                f"optimised CPU core in float | no split of {HEADLINE}'s rope at rest meets the stretch goal, or no CPU "
                "figure | **not measured** |"]
    p, mhz = h["point"], h["mhz"]
    what = (f"{HEADLINE} ({format_of(h['scene'])}), {counted(p['subs'], 'substep')} x {counted(p['iters'], 'iteration')}: "
            f"stretch at rest {p['sfin']:.4f} %, {p['cyc']} cycles a frame on the RTL")
    if not mhz:
        return [f"| the 1024-node rope at rest within {GOAL_STRETCH} % at 60 frames/s, >= {GOAL_HEADLINE:g}x one "
                f"optimised CPU core in float | {what}; {HEADLINE} has no fmax from make synth for this RTL | "
                "**not measured** |"]
    fps = mhz * 1e6 / p["cyc"]
    ratio = fps / p["fast_f_fps"]
    rows = [f"| the 1024-node rope at rest within {GOAL_STRETCH} % at 60 frames/s, >= {GOAL_HEADLINE:g}x one "
            f"optimised CPU core in float | {what}, at {mhz:.1f} MHz {fps:.0f} frames/s; one core (cpu_fast, the same "
            f"frames): {p['fast_f_fps']:.0f} frames/s in float (its own stretch at rest {p['cpu_st_f']:.4f} %), "
            f"{p['fast_d_fps']:.0f} in double ({p['cpu_st_d']:.4f} %): "
            f"**{ratio:.3f}x** (float), {fps / p['fast_d_fps']:.3f}x (double) | "
            f"{met(p['sfin'] <= GOAL_STRETCH and fps >= 60)} (stretch, 60 frames/s); {met(ratio >= GOAL_HEADLINE)} "
            f"({GOAL_HEADLINE:g}x) |"]
    # the device's bound: the units of this kind the ECP5-85F holds (make synth's unit cost) at this clock
    res_b = synth.unit_bound("m17_1x256_pipe", "m17_5x256_pipe", SYNTH["pnr"], SYNTH["packs"])
    if res_b and res_b["units"]:
        cpu = p["fast_f_fps"] * p["upf"]                      # one core's updates/s in float
        bound = res_b["units"] * h["per_unit"] * mhz * 1e6   # the device full of such units at this clock
        headline = 4 * h["per_unit"] * mhz * 1e6
        rows.append(f"| the device's bound | a unit of this kind takes {res_b['per'].get('TRELLIS_COMB', 0):,.0f} logic "
                    f"slots, {res_b['per'].get('MULT18X18D', 0):.0f} MULT18X18D and {res_b['per'].get('DP16KD', 0):.0f} "
                    f"DP16KD (docs/resources.md): the ECP5-85F holds {res_b['units']} (bound by {res_b['by']}), "
                    f"{bound / 1e9:.2f} G updates/s at {h['per_unit']:.3f} a clock a unit and {mhz:.1f} MHz: "
                    f"**{bound / cpu:.3f}x** one optimised core in float; the headline's 4 units are "
                    f"{100 * headline / bound:.0f} % of it | {met(bound / cpu >= GOAL_HEADLINE)} ({GOAL_HEADLINE:g}x) |")
    return rows


if __name__ == "__main__":
    main()
