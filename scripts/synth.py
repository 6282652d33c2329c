#!/usr/bin/env python3
"""synth.py - area and fmax of strand_top with Yosys and nextpnr; writes docs/resources.md.

Run from the repository root (tb/synth.mk does):

    synth.py all   --build DIR --gen GENDIR --out FILE [--jobs N] -- SRC...
        run every (build, flow) pair whose cached result is stale, N at a time,
        then write FILE (docs/resources.md) from the results.
    synth.py check --build DIR --gen GENDIR -- SRC...
        the quick check: the generic flow of the 4x5 build only (synth, check -assert,
        no latches); prints one line, PASS or FAIL, and exits non-zero on FAIL.
    synth.py report --build DIR --out FILE
        write FILE from the cached results only.
    synth.py configs
        print the build names.

Each build keeps its raw files in DIR/<build>/: <flow>.ys (the Yosys script),
<flow>.log, <flow>.stat.json (Yosys `stat -json`), ice40.json (the netlist for
nextpnr), pnr.log and pnr.report.json (nextpnr), and <flow>.ok, a stamp holding
a hash of the commands, the tool version and the contents of the RTL sources and
the generated header (for nextpnr: of its command and the netlist's stamp). A flow
is run again only when its stamp is missing or holds another hash.

Standard library only.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import re
import subprocess
import sys
import threading
import time

# ---- what is built ----

TOP = "strand_core"

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def param_table(gen):
    """The table of strand_core's parameters (scripts/gen_params.py writes it into gen/)."""
    with open(os.path.join(gen, "strand_params.json")) as f:
        return json.load(f)


def table_defaults(gen):
    """The defaults of the table, as integers (a default may name an earlier parameter)."""
    out = {}
    for p in param_table(gen)["params"]:
        out[p["name"]] = int(eval(p["default"], {}, dict(out)))  # the table's own integer expressions
    return out


# Every build is the table's defaults (Q16.16, a full-precision root and divider, the
# centred rule of reference 000, gravity and the mouse) with these changes; DEBUG = 0:
# the core as it is synthesised, without its observation port.
COMMON = [("DEBUG", 0)]

# name: (M units, K nodes per unit)
CONFIGS = [("4x5", 4, 5), ("8x8", 8, 8), ("16x16", 16, 16)]
CONFIG_MK = {name: (m, k) for name, m, k in CONFIGS}

CHECK_CONFIG = "4x5"      # the build that `check` and the target use
TARGET_CELLS = 18000      # the 4x5 build's budget in generic cells
COURSE_CELLS = 541785     # the course project's RTL, with no real square root nor divider

FLOWS = ["generic", "ice40", "ecp5", "xilinx"]
PNR_SEED = 1
PNR_ARGS = ["--up5k", "--package", "sg48", "--seed", str(PNR_SEED), "--timing-allow-fail"]
UP5K_LC = 5280            # logic cells of the UP5K (a LUT4 and a DFF each), for the table

TIMEOUT = int(os.environ.get("SYNTH_TIMEOUT", "7200"))  # seconds per tool run

# Latch cell types, before and after techmapping.
LATCH_SEL = "t:$dlatch* t:$adlatch* t:$_DLATCH*"

# synth_ice40 and synth_ecp5 end with a `check` stage that starts with `autoname`, which
# only renames nets for readable reports but on a large flat netlist takes longer than
# the whole synthesis (quadratic; YosysHQ/yosys issues #2816, #5394). The flows run each
# script up to that stage and then its other commands, so the cell counts are those
# of the full script.
CHECK_STAGE = ["hierarchy -check", "stat", "check -noinit", "blackbox =A:whitebox"]

SYNTH_CMDS = {
    "generic": [
        f"synth -top {TOP}",
        "tee -q -o generic.stat.json stat -json",
        "stat",
        # The checks run on the flattened netlist, so that they see every net once.
        "flatten",
        f"hierarchy -top {TOP}",
        "check -assert",
        f"select -assert-none {LATCH_SEL}",
    ],
    "ice40": [
        f"synth_ice40 -dsp -top {TOP} -run :check",
        *CHECK_STAGE,
        "write_json ice40.json",
        "tee -q -o ice40.stat.json stat -json",
    ],
    "ecp5": [
        f"synth_ecp5 -top {TOP} -run :check",
        *CHECK_STAGE,
        "tee -q -o ecp5.stat.json stat -json",
    ],
    "xilinx": [
        f"synth_xilinx -top {TOP}",
        "tee -q -o xilinx.stat.json stat -json",
        "stat",
    ],
}


def params(config):
    m, k = CONFIG_MK[config]
    return [("M", m), ("K", k)] + COMMON


def yosys_script(flow, params, gen, srcs, title):
    """The Yosys script of one flow on strand_core with these parameters (name, value pairs).
    Every report (resources.md, effects.md, accuracy.md) uses this one function."""
    lines = [f"# {flow} flow of {TOP}, {title}; written by scripts/synth.py"]
    lines.append("read_verilog -I" + os.path.abspath(gen) + " -I" + os.path.join(ROOT, "rtl") + " "
                 + " ".join(os.path.abspath(s) for s in srcs))
    lines.append("chparam " + " ".join(f"-set {n} {v}" for n, v in params) + f" {TOP}")
    lines.append(f"hierarchy -check -top {TOP}")
    lines += SYNTH_CMDS[flow]
    return "\n".join(lines) + "\n"


def ys_text(config, flow, gen, srcs):
    """The Yosys script of one flow of one build (paths absolute: Yosys runs in the build dir)."""
    return yosys_script(flow, params(config), gen, srcs, f"build {config}")


def pnr_cmd():
    return ["nextpnr-ice40"] + PNR_ARGS + ["--json", "ice40.json", "--report", "pnr.report.json"]


# ---- tools ----

_versions = {}


def tool_version(tool):
    if tool not in _versions:
        flag = "-V" if tool == "yosys" else "--version"
        try:
            out = subprocess.run([tool, flag], capture_output=True, text=True, timeout=60)
            text = (out.stdout + out.stderr).strip().splitlines()
            _versions[tool] = text[0].strip() if text else "unknown"
        except (OSError, subprocess.SubprocessError):
            _versions[tool] = None
    return _versions[tool]


def nextpnr_version_short(v):
    m = re.search(r"\(Version ([^)]*)\)", v or "")
    return f"nextpnr-ice40 {m.group(1)}" if m else (v or "nextpnr-ice40 (unknown version)")


# ---- caching ----

def digest(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode())
        h.update(b"\0")
    return h.hexdigest()


def file_digest(paths):
    h = hashlib.sha256()
    for p in paths:
        h.update(p.encode() + b"\0")
        with open(p, "rb") as f:
            h.update(f.read())
    return h.hexdigest()


def gen_files(gen):
    """The generated headers the RTL includes (part of every cache key), and rtl/'s own."""
    import glob
    return sorted(glob.glob(os.path.join(gen, "*.vh"))) + sorted(glob.glob(os.path.join(ROOT, "rtl", "*.vh")))


def stamp_fresh(stamp, key):
    try:
        with open(stamp) as f:
            return json.load(f).get("key") == key
    except (OSError, ValueError):
        return False


def write_stamp(stamp, key, **extra):
    tmp = stamp + ".tmp"
    with open(tmp, "w") as f:
        json.dump(dict(key=key, **extra), f, indent=1)
    os.replace(tmp, stamp)


class Failure(Exception):
    pass


def run_tool(cmd, cwd, log):
    """Run a tool in cwd with its output to log; returns (returncode, wall seconds, CPU seconds).
    CPU time includes the tool's own children (ABC)."""
    t0 = time.time()
    with open(log, "w") as f:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT)
        timer = threading.Timer(TIMEOUT, p.kill)
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)
        timer.cancel()
        rc = p.returncode = os.waitstatus_to_exitcode(status)
        if rc < 0 and time.time() - t0 >= TIMEOUT:
            f.write(f"\nsynth.py: timed out after {TIMEOUT} s\n")
    return rc, time.time() - t0, ru.ru_utime + ru.ru_stime


def yosys_failure(log):
    """The first error Yosys reported, as one line."""
    try:
        text = open(log).read()
    except OSError:
        return "no log"
    m = re.search(r"^ERROR: (.*)$", text, re.M)
    if m:
        msg = m.group(1)
        if "Assertion failed: selection is not empty" in msg:
            cells = re.findall(r"^\s*(\S+/\S+)\s*$", text[m.end():], re.M)
            return f"{len(cells)} latch cell(s), e.g. " + (", ".join(cells[:3]) or msg)
        return msg
    if "timed out" in text:
        return text.strip().splitlines()[-1]
    return "yosys failed (see the log)"


def run_flow(config, flow, build, gen, srcs, quiet=False):
    """Run one Yosys flow unless cached; raise Failure on an error. Returns a status word."""
    d = os.path.join(build, config)
    os.makedirs(d, exist_ok=True)
    ys = ys_text(config, flow, gen, srcs)
    ver = tool_version("yosys")
    if ver is None:
        raise Failure("yosys not found (make bootstrap installs it)")
    # The key covers the commands, the tool and the sources' contents, read before the
    # run: a source edited while Yosys runs makes the next run see a different key.
    key = digest(ys, ver, file_digest(list(srcs) + gen_files(gen)))
    stamp = os.path.join(d, f"{flow}.ok")
    if stamp_fresh(stamp, key):
        return "cached"
    if os.path.exists(stamp):
        os.remove(stamp)
    with open(os.path.join(d, f"{flow}.ys"), "w") as f:
        f.write(ys)
    log = os.path.join(d, f"{flow}.log")
    rc, secs, cpu = run_tool(["yosys", "-q", "-l", f"{flow}.log", f"{flow}.ys"], d, os.devnull)
    if rc != 0:
        raise Failure(f"{config} {flow}: {yosys_failure(log)} (log: {log})")
    write_stamp(stamp, key, tool=ver, seconds=round(secs, 1), cpu_seconds=round(cpu, 1))
    return f"{secs:.0f} s (CPU {cpu:.0f} s)"


def pnr_outcome(text, rc):
    """Parse a nextpnr-ice40 log: fits or not, utilisation, fmax."""
    util = {}
    for name, used, avail in re.findall(r"^Info:\s+(\w+):\s+(\d+)/\s*(\d+)\s+\d+%", text, re.M):
        util[name] = [int(used), int(avail)]
    fmax = re.findall(r"Max frequency for clock\s+'([^']*)':\s+([\d.]+) MHz", text)
    errors = re.findall(r"^ERROR: (.*)$", text, re.M)
    over = {n: u for n, u in util.items() if u[0] > u[1]}
    if rc == 0:
        return dict(fits=True, util=util, fmax_mhz=float(fmax[-1][1]) if fmax else None,
                    clock=fmax[-1][0] if fmax else None)
    if over or any("no BELs remaining" in e or "Unable to place" in e for e in errors):
        return dict(fits=False, util=util, over=over, error=errors[0] if errors else "")
    return dict(fits=None, util=util, error=errors[0] if errors else f"nextpnr exited {rc}")


def run_pnr(config, build):
    """Place and route the ice40 netlist unless cached. A build that does not fit is a result."""
    d = os.path.join(build, config)
    ver = tool_version("nextpnr-ice40")
    if ver is None:
        raise Failure("nextpnr-ice40 not found (make bootstrap installs it)")
    with open(os.path.join(d, "ice40.ok")) as f:
        netlist_key = json.load(f)["key"]
    key = digest(" ".join(pnr_cmd()), ver, netlist_key)
    stamp = os.path.join(d, "pnr.ok")
    if stamp_fresh(stamp, key):
        return "cached"
    if os.path.exists(stamp):
        os.remove(stamp)
    log = os.path.join(d, "pnr.log")
    rc, secs, cpu = run_tool(pnr_cmd(), d, log)
    outcome = pnr_outcome(open(log).read(), rc)
    if outcome["fits"] is None:
        raise Failure(f"{config} nextpnr: {outcome['error']} (log: {log})")
    write_stamp(stamp, key, tool=ver, seconds=round(secs, 1), cpu_seconds=round(cpu, 1), rc=rc, **outcome)
    return f"{secs:.0f} s (CPU {cpu:.0f} s)" + ("" if outcome["fits"] else ", does not fit the UP5K")


# ---- reading the results ----

def base_name(mod):
    """'$paramod$hash\\fx_div' or '$paramod\\fx_add\\W=...' or '\\toward' -> the module's own name."""
    parts = [p for p in mod.split("\\") if p]
    if mod.startswith("$paramod"):
        return parts[1]
    return parts[0]


def load_stat(path):
    """The modules of a `stat -json` file. Yosys 0.23 also prints the text hierarchy
    into that file, between the modules and the design; those lines are dropped."""
    with open(path) as f:
        text = f.read()
    try:
        data = json.loads(text)
    except ValueError:
        keep = [ln for ln in text.splitlines() if ln.strip()[:1] in ('"', "{", "}", "[", "]")]
        data = json.loads("\n".join(keep))
    return data["modules"]


def find_top(mods):
    for m in mods:
        if base_name(m) == TOP:
            return m
    raise Failure(f"no {TOP} in the statistics")


def flat_counts(mods, mod, memo=None):
    """Leaf cell counts by type under one instance of mod (submodule instances expanded)."""
    memo = {} if memo is None else memo
    if mod in memo:
        return memo[mod]
    out = {}
    for typ, n in mods[mod]["num_cells_by_type"].items():
        if typ in mods:
            for t2, n2 in flat_counts(mods, typ, memo).items():
                out[t2] = out.get(t2, 0) + n * n2
        else:
            out[typ] = out.get(typ, 0) + n
    memo[mod] = out
    return out


def own_counts(mods, mod):
    return {t: n for t, n in mods[mod]["num_cells_by_type"].items() if t not in mods}


def generic_classes(counts):
    ff = sum(n for t, n in counts.items() if "DFF" in t)
    mux = sum(n for t, n in counts.items() if t.startswith("$_MUX"))
    total = sum(counts.values())
    return dict(total=total, ff=ff, mux=mux, other=total - ff - mux)


def hierarchy_rows(mods, top):
    """The instance tree by module name (instances of one module with different
    parameters, e.g. a unit number, are merged), depth first, biggest subtree first.
    Each row: depth, name, instances (in all), per_parent, and cell totals over all
    its instances: own, own_ff, own_mux (the module's own cells) and subtree."""
    memo = {}
    acc = {}
    kids = {}

    def walk(mod, path, mult):
        own = own_counts(mods, mod)
        cls = generic_classes(own)
        r = acc.setdefault(path, dict(instances=0, own=0, own_ff=0, own_mux=0, subtree=0))
        r["instances"] += mult
        r["own"] += mult * cls["total"]
        r["own_ff"] += mult * cls["ff"]
        r["own_mux"] += mult * cls["mux"]
        r["subtree"] += mult * sum(flat_counts(mods, mod, memo).values())
        for t, n in mods[mod]["num_cells_by_type"].items():
            if t in mods:
                child = path + (base_name(t),)
                kids.setdefault(path, [])
                if child not in kids[path]:
                    kids[path].append(child)
                walk(t, child, mult * n)

    root = (base_name(top),)
    walk(top, root, 1)
    rows = []

    def emit(path):
        r = dict(acc[path], depth=len(path) - 1, name=path[-1])
        parent = acc.get(path[:-1])
        r["per_parent"] = r["instances"] // parent["instances"] if parent else 1
        rows.append(r)
        for c in sorted(kids.get(path, []), key=lambda c: -acc[c]["subtree"]):
            emit(c)

    emit(root)
    return rows


def results(build, config):
    d = os.path.join(build, config)
    r = {}
    for flow in FLOWS:
        stamp = os.path.join(d, f"{flow}.ok")
        if not os.path.exists(stamp):
            raise Failure(f"no result for {config} {flow}: run `make synth`")
        mods = load_stat(os.path.join(d, f"{flow}.stat.json"))
        top = find_top(mods)
        r[flow] = dict(counts=flat_counts(mods, top), mods=mods, top=top,
                       tool=json.load(open(stamp)).get("tool"))
    pstamp = os.path.join(d, "pnr.ok")
    if not os.path.exists(pstamp):
        raise Failure(f"no nextpnr result for {config}: run `make synth`")
    with open(pstamp) as f:
        r["pnr"] = json.load(f)
    return r


def pick(counts, pred):
    return sum(n for t, n in counts.items() if pred(t))


# ---- the document ----

def fmt(n):
    return f"{n:,}"


def pct(a, b):
    return f"{100.0 * a / b:.1f}%" if b else "-"


def pnr_cell(p):
    util = p.get("util", {})
    if p.get("fits"):
        lc = util.get("ICESTORM_LC", [0, 0])
        f = p.get("fmax_mhz")
        fs = f"{f:.1f} MHz" if f is not None else "no clock reported"
        return f"fits ({fmt(lc[0])}/{fmt(lc[1])} LCs); fmax {fs}"
    over = p.get("over", {})
    parts = [f"{n} {fmt(u[0])}/{fmt(u[1])} ({pct(u[0], u[1])})" for n, u in sorted(over.items())]
    return "does not fit: " + ("; ".join(parts) if parts else p.get("error", ""))


def report(build, out):
    res = {c: results(build, c) for c, _, _ in CONFIGS}
    yver = {r[f]["tool"] for r in res.values() for f in FLOWS}
    pver = {r["pnr"].get("tool") for r in res.values()}
    L = []
    w = L.append
    w("# Resources: strand_top in gates, iCE40, ECP5 and Xilinx 7-series")
    w("")
    w("Generated by `make synth` (scripts/synth.py); do not edit by hand. Tools: "
      + ", ".join(sorted(v for v in yver if v)) + "; "
      + ", ".join(sorted(nextpnr_version_short(v) for v in pver)) + ".")
    w("Raw logs, `stat -json` files and netlists are kept in `build/synth/<build>/`.")
    w("")
    w("Every build is strand_top at Q16.16 with "
      + ", ".join(f"{n}={v}" for n, v in COMMON) + "; the builds differ in M (units) and K (nodes per unit):")
    w("")
    w("| build | M | K | nodes |")
    w("|---|--:|--:|--:|")
    for c, m, k in CONFIGS:
        w(f"| {c} | {m} | {k} | {m * k} |")
    w("")

    # target
    g = res[CHECK_CONFIG]["generic"]["counts"]
    total = sum(g.values())
    met = total <= TARGET_CELLS
    w("## Target")
    w("")
    w(f"The {CHECK_CONFIG} build at Q16.16 should need at most {fmt(TARGET_CELLS)} generic cells "
      f"(the course project's own RTL needed {fmt(COURSE_CELLS)}, with neither a real square root nor a real divider).")
    w("")
    w(f"Measured: **{fmt(total)} cells, target {'met' if met else 'not met'}**"
      + ("." if met else f" ({pct(total, TARGET_CELLS)} of the budget)."))
    w("")

    # generic
    w("## Generic gates (`synth -top strand_top`, then `stat`)")
    w("")
    w("Yosys's internal gate library; the netlist passes `check -assert` and has no latches "
      "(`make synth` fails otherwise). `synth` keeps the module hierarchy, so the count is the "
      "sum over instances of each module's cells, with no optimisation across module borders.")
    w("")
    w("| build | cells | flip-flops | 2:1 muxes | other gates |")
    w("|---|--:|--:|--:|--:|")
    for c, _, _ in CONFIGS:
        k = generic_classes(res[c]["generic"]["counts"])
        w(f"| {c} | {fmt(k['total'])} | {fmt(k['ff'])} | {fmt(k['mux'])} | {fmt(k['other'])} |")
    w("")

    # ice40
    w("## iCE40 UP5K (`synth_ice40 -dsp`, nextpnr-ice40 `" + " ".join(PNR_ARGS[:-1]) + "`)")
    w("")
    w(f"The UP5K has {fmt(UP5K_LC)} logic cells (one LUT4 and one DFF each), 8 SB_MAC16 and 30 SB_RAM40_4K. "
      "DFF counts every SB_DFF* kind. nextpnr places the whole top, with its ports as pins "
      f"(seed {PNR_SEED}); fmax is nextpnr's post-route figure for `clk`.")
    w("")
    w("| build | SB_LUT4 | DFF | SB_CARRY | SB_MAC16 | SB_RAM40_4K | UP5K sg48 place and route |")
    w("|---|--:|--:|--:|--:|--:|---|")
    for c, _, _ in CONFIGS:
        k = res[c]["ice40"]["counts"]
        w(f"| {c} | {fmt(pick(k, lambda t: t == 'SB_LUT4'))} | {fmt(pick(k, lambda t: t.startswith('SB_DFF')))} "
          f"| {fmt(pick(k, lambda t: t == 'SB_CARRY'))} | {fmt(pick(k, lambda t: t == 'SB_MAC16'))} "
          f"| {fmt(pick(k, lambda t: t.startswith('SB_RAM40_4K')))} | {pnr_cell(res[c]['pnr'])} |")
    w("")

    # ecp5
    w("## ECP5 (`synth_ecp5`)")
    w("")
    w("| build | LUT4 | FF (TRELLIS_FF) | CCU2C (carry) | MULT18X18D | DP16KD |")
    w("|---|--:|--:|--:|--:|--:|")
    for c, _, _ in CONFIGS:
        k = res[c]["ecp5"]["counts"]
        w(f"| {c} | {fmt(pick(k, lambda t: t == 'LUT4'))} | {fmt(pick(k, lambda t: t == 'TRELLIS_FF'))} "
          f"| {fmt(pick(k, lambda t: t == 'CCU2C'))} | {fmt(pick(k, lambda t: t == 'MULT18X18D'))} "
          f"| {fmt(pick(k, lambda t: t == 'DP16KD'))} |")
    w("")

    # xilinx
    w("## Xilinx 7-series (`synth_xilinx`)")
    w("")
    w("LUTs sum LUT1..LUT6; FFs sum the FD* kinds. `synth_xilinx` keeps the hierarchy by default; "
      "the counts are summed over instances.")
    w("")
    w("| build | LUTs | FFs | CARRY4 | DSP48E1 | RAMB18E1 | RAMB36E1 |")
    w("|---|--:|--:|--:|--:|--:|--:|")
    for c, _, _ in CONFIGS:
        k = res[c]["xilinx"]["counts"]
        w(f"| {c} | {fmt(pick(k, lambda t: re.fullmatch(r'LUT[1-6]', t) is not None))} "
          f"| {fmt(pick(k, lambda t: t.startswith('FD')))} | {fmt(pick(k, lambda t: t == 'CARRY4'))} "
          f"| {fmt(pick(k, lambda t: t == 'DSP48E1'))} | {fmt(pick(k, lambda t: t == 'RAMB18E1'))} "
          f"| {fmt(pick(k, lambda t: t == 'RAMB36E1'))} |")
    w("")

    # where the cells go
    gen = res[CHECK_CONFIG]["generic"]
    rows = hierarchy_rows(gen["mods"], gen["top"])
    w(f"## Where the cells go ({CHECK_CONFIG}, generic gates)")
    w("")
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
    # by module kind, summed over every instance
    kinds = {}
    for r in rows:
        k = kinds.setdefault(r["name"], dict(instances=0, cells=0, ff=0, mux=0))
        k["instances"] += r["instances"]
        k["cells"] += r["own"]
        k["ff"] += r["own_ff"]
        k["mux"] += r["own_mux"]
    order = sorted(kinds.items(), key=lambda kv: -kv[1]["cells"])
    w("In plain words, summing each module's own cells over all its instances, largest first:")
    w("")
    for name, k in order:
        w(f"- **{name}**: {fmt(k['cells'])} cells ({pct(k['cells'], total)}) in {fmt(k['instances'])} "
          f"instance{'s' if k['instances'] != 1 else ''}, {fmt(k['cells'] // max(k['instances'], 1))} each; "
          f"{fmt(k['ff'])} flip-flops and {fmt(k['mux'])} 2:1 muxes among them.")
    w("")
    m, kk = CONFIG_MK[CHECK_CONFIG]
    wbits = dict(COMMON)["W"]
    w(f"A node is four {wbits}-bit words (x, y, px, py) and a pin bit: the {m * kk} nodes of the "
      f"{CHECK_CONFIG} build are {fmt(m * kk * (4 * wbits + 1))} bits of state.")
    ram = {c: pick(res[c]["ice40"]["counts"], lambda t: t.startswith("SB_RAM40_4K"))
           + pick(res[c]["ecp5"]["counts"], lambda t: t == "DP16KD")
           + pick(res[c]["xilinx"]["counts"], lambda t: t.startswith("RAMB"))
           for c, _, _ in CONFIGS}
    if not any(ram.values()):
        w("No build maps any of it to block RAM on any FPGA family: it is all flip-flops and "
          "multiplexers, and it grows with the node count.")
    else:
        w("Block RAM used: " + ", ".join(f"{c}: {n}" for c, n in ram.items()) + ".")
    w("")
    per_node = [(c, m * k, sum(res[c]["generic"]["counts"].values())) for c, m, k in CONFIGS]
    w("Generic cells per node: " + ", ".join(f"{c} {fmt(t // n)}" for c, n, t in per_node) + ".")
    w("")

    w("## How to regenerate")
    w("")
    w("`make synth` runs, for each build, the Yosys scripts below (two at a time) and nextpnr on the iCE40 "
      "netlist, then rewrites this file. A build whose RTL, header and commands are unchanged is not "
      "synthesised again. `make test-synth-check` runs the generic flow of the "
      f"{CHECK_CONFIG} build only.")
    w("")
    w("```")
    w("read_verilog -I build/gen <strand_top and its modules>")
    w("chparam " + " ".join(f"-set {n} {v}" for n, v in [("M", "<M>"), ("K", "<K>")] + COMMON) + f" {TOP}")
    w(f"hierarchy -check -top {TOP}")
    for flow in FLOWS:
        w(f"# {flow}:")
        for line in SYNTH_CMDS[flow]:
            w("  " + line)
    w("# then: " + " ".join(pnr_cmd()))
    w("```")
    w("")
    w("`synth_ice40` and `synth_ecp5` are run up to their `check` stage, and that stage without its first "
      "command, `autoname`: it only renames nets (for readable timing reports), does not change the cells, and on "
      "the flat 16x16 netlist takes longer than the whole synthesis (YosysHQ/yosys issues #2816 and #5394).")
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
    lock = threading.Lock()
    failures = []

    def say(msg):
        with lock:
            print(msg, flush=True)

    def task(config, flow):
        t0 = time.time()
        try:
            st = run_flow(config, flow, a.build, a.gen, srcs)
            say(f"synth {config:6s} {flow:8s} {st}")
            if flow == "ice40":
                st = run_pnr(config, a.build)
                say(f"synth {config:6s} {'nextpnr':8s} {st}")
        except Failure as e:
            failures.append(str(e))
            say(f"FAIL synth {e}")
        return time.time() - t0

    # the biggest builds first, so that the two workers end together
    order = [(c, f) for c, _, _ in reversed(CONFIGS) for f in ["ice40", "ecp5", "xilinx", "generic"]]
    t0 = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
        list(ex.map(lambda cf: task(*cf), order))
    if failures:
        print(f"FAIL synth: {len(failures)} flow(s) failed; {a.out} not written", file=sys.stderr)
        return 1
    total, met = report(a.build, a.out)
    print(f"synth: wrote {a.out} in {time.time() - t0:.0f} s; {CHECK_CONFIG}: {fmt(total)} generic cells, "
          f"target of {fmt(TARGET_CELLS)} {'met' if met else 'not met'}")
    return 0


def cmd_check(a):
    try:
        run_flow(CHECK_CONFIG, "generic", a.build, a.gen, a.srcs)
        mods = load_stat(os.path.join(a.build, CHECK_CONFIG, "generic.stat.json"))
        total = sum(flat_counts(mods, find_top(mods)).values())
    except Failure as e:
        print(f"FAIL synth-check: {e}")
        return 1
    print(f"PASS synth-check ({CHECK_CONFIG}: {total} cells, no latches)")
    return 0


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
    s = sub.add_parser("report")
    s.add_argument("--build", default="build/synth")
    s.add_argument("--out", default="docs/resources.md")
    sub.add_parser("configs")
    a = p.parse_args()
    try:
        if a.cmd == "configs":
            print(" ".join(c for c, _, _ in CONFIGS))
            return 0
        if a.cmd == "report":
            total, met = report(a.build, a.out)
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
