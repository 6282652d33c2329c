#!/usr/bin/env python3
"""bench.py - the core's physics throughput against a CPU, and simulation speed, written to
docs/performance.md (make bench).

Physics throughput: for the 4x5, 8x8, 16x16 and 8x128 builds (tb/bench/bench_<build>.scene,
and the same scene with the pairwise rule) in both architectures (serial: the scene's order; pipelined: --order redblack), the
Verilator harness runs the RTL alone and counts the cycles of each frame and of its
constraint passes; the constraint updates of a frame (node updates of the centred rule)
divided by them are the updates per clock. The ECP5-85F fmax is the median of make synth's
nextpnr runs of the same build (build/synth/, or make synth's record docs/synth_record.json
when it holds them for the same RTL; "not placed" where make synth has not placed it). In the
same run, build/cpu_rope (model/cpu_rope.c, -O3, one core) runs the same scene in the same order in double and in float,
timed CPU_REPEATS times, the fastest run kept (other work on the machine only slows it); its double frames are the frame engine's
bit for bit (make test checks it). Then the 1024-node rope (8x128, pipelined): the clock
that 60 frames per second need at each iteration count, the stretch the frame engine
reaches with that many iterations, and the iterations it fits at its fmax if placed.

Simulation speed: for the 4x5, 8x8 and 16x16 builds it runs the harness three ways - the RTL
and the cycle model in lockstep, the RTL alone, the cycle model alone - each REPEATS times,
and reports the median of the harness's own counter of simulated cycles per second, and
lockstep's cost against the RTL alone (target: at most 2x).
"""
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
PHYS_BUILDS = ["4x5", "8x8", "16x16", "8x128"]
RULES = ["centred", "pairwise"]   # the pairwise scenes: bench_<build>.scene with rule = pairwise
PHYS_FRAMES = 10          # frames of the RTL run (every frame takes the same cycles)
ARCHS = [("serial", "serial", ""), ("pipelined", "redblack", "_pipe")]  # name, order, make synth's suffix
SPRING_BUILDS = ["4x5", "8x128"]  # tb/bench/springs_<build>.scene: chains of springs
GRAPH_SCENE, GRAPH_BUILD = "tb/bench/graph_cloth.scene", "cloth"  # a graph: make synth's cloth_pipe
ROPE = "8x128"            # the 1024-node rope
ITER_STEPS = [1, 4, 16, 64, 256, 1024]  # its iteration counts in the rope table
CPU_SECONDS = "1.5"
CPU_REPEATS = 3           # cpu_rope runs of each row; the fastest is the CPU's figure
FRAMES = {"4x5": 400, "8x8": 120, "16x16": 30}
MODES = ["lockstep", "rtl", "model"]
REPEATS = 3
TARGET = 2.0
GOAL_PER_UNIT, GOAL_MHZ, GOAL_RATIO, GOAL_STRETCH = 0.9, 100.0, 10.0, 0.05  # the speed work's goals
GOALS = {}  # what physics(), rope() and springs() measured of them, for the page's first table


def sh(cmd):
    rc, out = run(cmd)
    if rc != 0:
        sys.stdout.write(out)
        raise SystemExit(f"bench: {' '.join(cmd)} failed")
    return out


def harness_for(scene, order=None):
    """The harness of the scene's build (in build/vl/, shared with make test's lockstep)."""
    try:
        info = flow_hwgen.info(scene, order)
        if not info["rtl"]:
            raise Failure(f"{scene}: {info['why']}")
        return flow_build.harness_for(scene, flow_build.harness_dir(info["params"]), order=order)
    except Failure as e:
        raise SystemExit(f"bench: {e}")


def rtl_figures(scene, frames, order):
    """The harness's counters of a run of the RTL alone (run.parse's keys)."""
    return flow_run.parse(sh([harness_for(scene, order), scene, "--frames", str(frames), "--mode", "rtl",
                              "--order", order]))


def fmax_of(name):
    """(median MHz or None, text) of make synth's ECP5-85F runs of build `name`."""
    try:
        runs = synth.load_pnr(os.path.join(ROOT, BUILD, "synth"), name, "ecp5")
    except synth.Failure:
        try:  # a build make synth packs but does not place: whether it fits
            pack = synth.load_pack(os.path.join(ROOT, BUILD, "synth"), name)
            comb = pack.get("util", {}).get("TRELLIS_COMB")
            return None, ("packs into the device" + (f" ({100 * comb[0] / comb[1]:.0f} % of TRELLIS_COMB)" if comb else "")
                          if pack.get("fits") else "does not fit") + ", not placed"
        except synth.Failure:
            return None, "not placed"
    text, med = synth.fmax_cells(runs)
    return med, (f"{med:.1f}" if med is not None else text)


def cpu_rate(scene, order, kind):
    """(updates/s, cflags) of cpu_rope on the scene: the fastest of CPU_REPEATS timed runs, since
    the machine's other work can only slow a run down and the CPU should get its best figure."""
    rates = []
    for _ in range(CPU_REPEATS):
        text = sh([os.path.join(BUILD, "cpu_rope"), scene, "--order", order, "--type", kind,
                   "--min-seconds", CPU_SECONDS])
        rates.append(float(re.search(r"updates_per_s=([\d.]+)", text).group(1)))
    return max(rates), re.search(r'cflags="([^"]*)"', text).group(1)


def physics():
    """Rows of the throughput table, the rope figures and notes (as markdown lines)."""
    rows = []
    flags = ""
    for b, rule in [(b, rule) for rule in RULES for b in PHYS_BUILDS]:
        scene = f"tb/bench/bench_{b}.scene" if rule == "centred" else rule_variant(f"tb/bench/bench_{b}.scene", rule)
        m, k = (int(x) for x in b.split("x"))
        for arch, order, suffix in ARCHS:
            f = rtl_figures(scene, PHYS_FRAMES, order)
            cyc, upf, per_clock, per_clock_c = (f["cycles_per_frame"], f["updates_per_frame"], f["updates_per_clock"],
                                                f["updates_per_clock_passes"])
            # make synth places the centred builds only (another rule is another build)
            mhz, mhz_text = fmax_of(b + suffix) if rule == "centred" else (None, "not placed")
            cpu_d, flags = cpu_rate(scene, order, "double")
            cpu_f, _ = cpu_rate(scene, order, "float")
            hw = per_clock * mhz * 1e6 if mhz else None
            rows.append(dict(build=b, rule=rule, arch=arch, nodes=m * k, m=m, cycles=cyc, upf=upf, per_clock=per_clock,
                             per_clock_c=per_clock_c, mhz=mhz, mhz_text=mhz_text, hw=hw, cpu_d=cpu_d, cpu_f=cpu_f))
            print(f"bench {b} {rule} {arch}: {cyc} cycles/frame, {per_clock:.4f} updates/clock, fmax {mhz_text}, "
                  f"CPU {cpu_d / 1e6:.1f} M/s double, {cpu_f / 1e6:.1f} M/s float", flush=True)
    mega = lambda v: f"{v / 1e6:.2f}" if v is not None else "-"
    lines = ["| build | rule | architecture | nodes | cycles per frame (RTL) | updates per clock, whole frame | "
             "updates per clock in the constraint passes (of M) | fmax ECP5-85F, MHz (median) | updates/s at fmax, M | "
             "CPU double, M/s | CPU float, M/s | core / CPU double |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        ratio = f"**{r['hw'] / r['cpu_d']:.2f}x**" if r["hw"] else "-"
        lines.append(f"| {r['build']} | {r['rule']} | {r['arch']} | {r['nodes']} | {r['cycles']} | {r['per_clock']:.4f} | "
                     f"{r['per_clock_c']:.4f} ({r['per_clock_c'] / r['m']:.3f} M) | {r['mhz_text']} | {mega(r['hw'])} | "
                     f"{mega(r['cpu_d'])} | {mega(r['cpu_f'])} | {ratio} |")
    notes = ["", f"CPU: `{flags}`, one core, the same scene in the same order, the fastest of {CPU_REPEATS} timed runs of "
             f"at least {CPU_SECONDS} s each; its double frames are the frame "
             "engine's bit for bit (`cpu_rope --check`, in make test).", ""]
    # the goals: updates per clock per unit on long bodies (N >= 256), per rule
    for rule in RULES:
        long_pipe = [r for r in rows if r["arch"] == "pipelined" and r["rule"] == rule and r["nodes"] >= 256]
        if long_pipe:
            best = max(long_pipe, key=lambda r: r["per_clock_c"] / r["m"])
            GOALS[f"per_unit_{rule}"] = (best["build"], best["per_clock_c"] / best["m"])
    # the largest placed pipelined build against the CPU, and the rope
    pipe = [r for r in rows if r["arch"] == "pipelined" and r["hw"]]
    if pipe:
        GOALS["fmax"] = max((r["mhz"], r["build"]) for r in pipe)
    bigger = [r for r in rows if r["arch"] == "pipelined" and r["rule"] == "centred" and not r["hw"]
              and pipe and r["nodes"] > max(x["nodes"] for x in pipe) and "packs into" in r["mhz_text"]]
    if bigger:  # a larger build fits the device but has no fmax: the ratio above is not the largest's
        GOALS["unplaced"] = "; " + ", ".join(f"{r['build']} {r['mhz_text']}" for r in bigger)
    if pipe:
        big = max(pipe, key=lambda r: r["nodes"] * 1000 + r["m"])
        GOALS["ratio"] = (big["build"], big["hw"] / big["cpu_d"], big["mhz"])
        notes.append(f"The largest pipelined build placed on the ECP5-85F is **{big['build']}** ({big['nodes']} nodes, "
                     f"{big['m']} units): {mega(big['hw'])} M constraint updates/s at {big['mhz']:.1f} MHz, "
                     f"**{big['hw'] / big['cpu_d']:.2f}x** one CPU core in double and {big['hw'] / big['cpu_f']:.2f}x in float "
                     "(goal: 10x).")
    else:
        notes.append("No pipelined build has an fmax yet (run `make synth`): the updates per second and the "
                     "ratio to the CPU need it.")
    return lines + notes + rope(rows)


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
        hw = f["updates_per_clock"] * mhz * 1e6 if mhz else None
        colours = info["COLOURS"] if info["ARCH"] else "-"
        lines.append(f"| {arch} | {info['K']} | {info['E_RODS']} | {colours} | {f['cycles_per_frame']} | "
                     f"{f['updates_per_clock_passes']:.4f} | {mhz_text} | {mega(hw)} | {mega(cpu_d)} | {mega(cpu_f)} | "
                     f"{f'**{hw / cpu_d:.2f}x**' if hw else '-'} |")
        print(f"bench graph {arch}: {f['cycles_per_frame']} cycles/frame, {f['updates_per_clock_passes']:.4f} "
              f"updates/clock in the passes, fmax {mhz_text}, CPU {cpu_d / 1e6:.1f} M/s double", flush=True)
    return lines


def rope(rows):
    """The 1024-node rope at 60 frames per second: the clock each iteration count needs on the
    pipelined build, the stretch it reaches, and the iterations it fits at its fmax if placed."""
    r = next(x for x in rows if x["build"] == ROPE and x["arch"] == "pipelined" and x["rule"] == "centred")
    scene = f"tb/bench/bench_{ROPE}.scene"
    # the cycles of one constraint iteration and of the rest of a frame, measured with 1 and 2
    # iterations (the iteration count is a build parameter: a harness for each)
    cyc = []
    for it in (1, 2):
        path = write_variant(scene, it, f"rope_iter{it}")
        cyc.append(rtl_figures(path, 3, "redblack")["cycles_per_frame"])
    per_iter, rest = cyc[1] - cyc[0], 2 * cyc[0] - cyc[1]

    def stretch(iters):
        path = write_variant(scene, iters, f"rope_{iters}it")
        text = sh([os.path.join(BUILD, "strand"), "run", path, "--order", "redblack"])
        st = re.search(r"max stretch ([\d.]+) % \(final ([\d.]+) %\)", text)
        return path, st.group(1), st.group(2)

    cpu_iters = r["cpu_d"] / 60 / r["nodes"]
    mhz = r["mhz"]
    out = ["", f"**The 1024-node rope at 60 frames per second** ({ROPE}, pipelined, red/black). Measured on the "
               f"RTL: {per_iter} cycles per constraint iteration and {rest} for the rest of a frame (runs of 1 and 2 "
               "iterations; every other figure of the table's first columns follows from these two). For each iteration "
               "count: the clock a frame of 1/60 s needs; the constraint updates per clock over the whole frame; "
               "with the build's fmax, its updates per second against one CPU core (cpu_rope, double, the same scene "
               f"with that many iterations, the fastest of {CPU_REPEATS} runs, measured now; the CPU's rate per update "
               "changes little with the iterations, the core's grows as its fixed costs a frame, the Verlet pass and "
               "the pipe's drain, are shared by more of them); and the stretch the frame engine reaches with it "
               f"(`{scene}` with that many iterations, 100 frames, the mouse pulling for 20; the largest stretch counts "
               "frames 1 to 100, not the scene as written, where the rope lies 20 % short of its rest length; goal: at "
               "most 0.05 % at rest):", "",
           "| iterations per substep | clock for 60 frames/s, MHz | updates per clock, whole frame (of M) | "
           f"updates/s at {mhz:.1f} MHz, M | CPU double, M/s | core / CPU double | largest stretch | stretch at the end |"
           if mhz else "| iterations per substep | clock for 60 frames/s, MHz | updates per clock, whole frame (of M) | "
           "largest stretch | stretch at the end |",
           "|--:|--:|--:|--:|--:|--:|--:|--:|" if mhz else "|--:|--:|--:|--:|--:|"]
    for n in ITER_STEPS:
        path, smax, sfin = stretch(n)
        per_clock = r["nodes"] * n / (rest + n * per_iter)
        cells = [f"{n}", f"{60 * (rest + n * per_iter) / 1e6:.2f}", f"{per_clock:.3f} ({per_clock / r['m']:.3f} M)"]
        if mhz:
            cpu_n, _ = cpu_rate(path, "redblack", "double")
            hw = per_clock * mhz * 1e6
            cells += [f"{hw / 1e6:.1f}", f"{cpu_n / 1e6:.2f}", f"**{hw / cpu_n:.2f}x**"]
            print(f"bench rope {n} iterations: {per_clock:.3f} updates/clock, {hw / 1e6:.1f} M/s at {mhz:.1f} MHz, "
                  f"CPU {cpu_n / 1e6:.2f} M/s double", flush=True)
        out.append("| " + " | ".join(cells + [f"{smax} %", f"{sfin} %"]) + " |")
        GOALS["stretch"] = (n, float(sfin))
    out.append("")
    if r["mhz"]:
        iters = int((r["mhz"] * 1e6 / 60 - rest) // per_iter)
        _, smax, sfin = stretch(iters)
        if iters > GOALS["stretch"][0]:  # the most iterations a frame measured
            GOALS["stretch"] = (iters, float(sfin))
        out.append(f"At its fmax of {r['mhz']:.1f} MHz the build fits **{iters} iterations** a frame (largest "
                   f"stretch {smax} %, {sfin} % at the end).")
    else:
        out.append(f"The {ROPE} pipelined build is not placed by make synth (docs/resources.md), so how many "
                   "iterations it fits at its own clock is not measured.")
    out.append(f"One CPU core (double, the same scene and order) fits {cpu_iters:.0f} iterations a frame; the "
               f"core would need {60 * (rest + cpu_iters * per_iter) / 1e6:.1f} MHz to match it.")
    return out


def springs():
    """The spring pass in both architectures: spring updates per clock in the spring passes,
    counted by the harness on the RTL (as markdown lines)."""
    lines = ["| build | architecture | springs | cycles per frame (RTL) | spring updates per clock in the spring "
             "passes (of M) |", "|---|---|---|---|---|"]
    for b in SPRING_BUILDS:
        scene = f"tb/bench/springs_{b}.scene"
        m, k = (int(x) for x in b.split("x"))
        for arch, order, _ in ARCHS:
            f = rtl_figures(scene, 3, order)
            cyc, per_clock = f["cycles_per_frame"], f["springs_per_clock"]
            lines.append(f"| {b} | {arch} | {m * k - 1} | {cyc} | {per_clock:.4f} ({per_clock / m:.3f} M) |")
            if arch == "pipelined" and m * k >= 256:
                GOALS["per_unit_springs"] = (b, per_clock / m)
            print(f"bench springs {b} {arch}: {cyc} cycles/frame, {per_clock:.4f} spring updates/clock", flush=True)
    return lines


def rule_variant(scene, rule):
    """scene with its constraint rule replaced, written under build/bench/."""
    name = os.path.basename(scene).replace(".scene", f"_{rule}.scene")
    out = os.path.join(BUILD, "bench", name)
    os.makedirs(os.path.join(ROOT, BUILD, "bench"), exist_ok=True)
    text, n = re.subn(r"^rule = \w+$", f"rule = {rule}", open(os.path.join(ROOT, scene)).read(), flags=re.M)
    if n != 1:
        raise SystemExit(f"bench: {scene} names no constraint rule to replace")
    with open(os.path.join(ROOT, out), "w") as f:
        f.write(text)
    return out


def write_variant(scene, iterations, name):
    """scene with `iterations` constraint iterations per substep, written under build/bench/."""
    out = os.path.join(BUILD, "bench", f"{name}.scene")
    os.makedirs(os.path.join(ROOT, BUILD, "bench"), exist_ok=True)
    text = open(os.path.join(ROOT, scene)).read()
    text = re.sub(r"^\[time\]\n", f"[time]\niterations = {iterations}\n", text, count=1, flags=re.M)
    with open(os.path.join(ROOT, out), "w") as f:
        f.write(text)
    return out


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "docs/performance.md"
    os.chdir(ROOT)  # the RTL sources by the names make gives them (they are part of synth's keys)
    missing = synth.restore(os.path.join(BUILD, "synth"), os.path.join(BUILD, "gen"), synth.rtl_sources())
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
                text = sh([harness, scene, "--frames", str(FRAMES[b]), "--mode", mode])
                m = re.search(r"simulated cycles/s\s+(\d+)", text)
                c = re.search(r"(\d+) cycles", text)
                runs[mode].append(float(m.group(1)))
                cycles = int(c.group(1))
        speeds = {mode: statistics.median(v) for mode, v in runs.items()}
        for mode in MODES:
            print(f"bench {b} {mode}: {speeds[mode]:.0f} cycles/s (median of {REPEATS}, {cycles} cycles each)", flush=True)
        rows.append((b, cycles, speeds))

    cpu = "unknown"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    verilator = sh(["verilator", "--version"]).strip()
    load = os.getloadavg()
    lines = ["# Performance", "",
             "Generated by `make bench` (scripts/bench.py); every figure below comes from that run, except the fmax, "
             "which comes from `make synth`'s place and route of the same RTL (its record, docs/synth_record.json; "
             "docs/resources.md shows the figures of the last complete make synth).",
             f"Machine: {cpu}, {os.cpu_count()} cores; {verilator}; {platform.python_implementation()} "
             f"{platform.python_version()} for the driver. Measured {time.strftime('%Y-%m-%d')}; load average "
             f"{load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} (1 / 5 / 15 min) when the run ended: other work on the "
             "machine slows the CPU and simulation columns, so compare the columns of one row rather than rows of "
             "different runs.", "",
             "## Physics throughput: the core against one CPU core", "",
             "Constraint updates are node updates of the centred rule (each node moved to the mean of its two "
             "targets: two distance evaluations) or link updates of the pairwise rule (one distance evaluation, "
             "both ends moved), counted over every iteration of every substep of the benchmark "
             "scenes (`tb/bench/bench_<build>.scene`: a rope of M x K nodes, Q16.16 with full-precision root and "
             "divide, gravity, the mouse, one iteration; the pairwise rows run the same scene with `rule = "
             "pairwise`, another build, which make synth does not place). *Serial* is the reference-000 sequencer (one distance "
             "datapath for the whole body, the scene's order); *pipelined* is ARCH = 1 (the red/black order, every "
             "unit streaming its nodes through its own toward_pipe: one distance evaluation a clock per unit, so its "
             "ceiling is 0.5 x M updates a clock (centred: a node takes two evaluations; pairwise: a sweep's K + 1 "
             "slots carry the K / 2 links of its colour); a sweep takes max(K + 3, LP + 4) cycles, so a short body waits for "
             "the pipe's latency LP at every colour switch, and a long one pays its drain once a substep). Cycles are "
             "counted by the harness on the RTL (Verilator, RTL alone); updates/s = updates per clock over whole "
             "frames x fmax.", "",
             *phys, "",
             "## The spring pass", "",
             "Spring updates are spring forces gathered (one a link, both ends), counted over every substep of "
             "`tb/bench/springs_<build>.scene` (a chain of damped springs, no rods, Q16.16). *Serial* is "
             "pair_sequencer (one spring_force datapath for the body, link after link); *pipelined* is ARCH = 1 "
             "(spring_stream: every unit streams its links through its own spring_force_pipe, one a clock, and "
             "gathers its nodes' forces in link order, so its ceiling is M springs a clock less one fill and drain "
             "of the pipe a pass). Cycles counted by the harness on the RTL.", "",
             *springs(), "",
             "## A graph: the cloth", "",
             f"`{GRAPH_SCENE}`: 16 x 16 nodes joined by 480 rods (the grid's edges), the top row pinned, Q16.16 at "
             "full precision, the pairwise rule, gravity and the mouse, one iteration. *Serial* walks the rods one "
             "at a time through one toward (pair_sequencer); *pipelined* is graph_stream (ARCH = 1): the rods by the "
             "colours of an edge colouring, one toward_pipe, a new rod every two clocks (a rod reads two nodes and "
             "writes two through the unit's one read and one write port), the pipe drained after each colour, so its "
             "ceiling is 0.5 rod updates a clock. Updates are rod updates, counted by the harness on the RTL; "
             "updates/s = updates per clock over whole frames x fmax; the CPU (cpu_rope, as above) runs the same "
             "scene in the same order.", "",
             *graph(), "",
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
        if key in GOALS:
            b, v = GOALS[key]
            rows.append(f"| >= {GOAL_PER_UNIT} x M updates per clock on a long body (N >= 256), {what} | {b} "
                        f"pipelined: {v:.3f} M (the ceiling of one distance datapath a unit: "
                        f"{'1' if key == 'per_unit_springs' else '0.5'} M) | {met(v >= GOAL_PER_UNIT)} |")
    if "fmax" in GOALS:
        mhz, b = GOALS["fmax"]
        rows.append(f"| ECP5-85F fmax >= {GOAL_MHZ:g} MHz | the best placed pipelined build, {b}: {mhz:.1f} MHz | "
                    f"{met(mhz >= GOAL_MHZ)} |")
    else:
        rows.append(f"| ECP5-85F fmax >= {GOAL_MHZ:g} MHz | no pipelined build placed | **not measured** |")
    if "ratio" in GOALS:
        b, ratio, mhz = GOALS["ratio"]
        rows.append(f"| the largest ECP5-85F build >= {GOAL_RATIO:g}x one CPU core | the largest placed pipelined chain, "
                    f"{b}, at {mhz:.1f} MHz: {ratio:.2f}x (double){GOALS.get('unplaced', '')} | {met(ratio >= GOAL_RATIO)} |")
    else:
        rows.append(f"| the largest ECP5-85F build >= {GOAL_RATIO:g}x one CPU core | no pipelined build placed | "
                    "**not measured** |")
    if "stretch" in GOALS:
        n, st = GOALS["stretch"]
        rows.append(f"| the 1024-node rope at rest: stretch <= {GOAL_STRETCH} % | {st} % after 100 frames at {n} "
                    f"iterations | {met(st <= GOAL_STRETCH)} |")
    return ["## The goals, measured", "",
            "The speed work's four goals against the figures of this page (the sections below say how each is "
            "measured).", "", "| goal | measured | |", "|---|---|---|", *rows, ""]


if __name__ == "__main__":
    main()
