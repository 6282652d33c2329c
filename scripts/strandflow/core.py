"""Paths, failures, running a tool, and the content digests that key every cache."""
import glob
import hashlib
import json
import os
import subprocess
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("BUILD", "build")           # relative to ROOT, as make gives it
GEN = os.path.join(ROOT, BUILD, "gen")              # make's generated headers (gen_params.py, gen_regs.py)
STRAND = os.path.join(ROOT, BUILD, "strand")        # the command-line tool
LIBSTRAND = os.path.join(ROOT, BUILD, "libstrand.a")


class Failure(Exception):
    """A step that did not give its result; the message says which and why."""


def run(cmd, cwd=ROOT, timeout=None, env=None):
    """Run cmd; (exit status, stdout and stderr together). A timeout raises
    subprocess.TimeoutExpired for the caller to judge."""
    p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=timeout, env=env)
    return p.returncode, p.stdout


def run_checked(cmd, cwd=ROOT, what=None):
    """Run cmd; its output, or Failure with the output's last lines."""
    rc, out = run(cmd, cwd=cwd)
    if rc != 0:
        tail = "; ".join(ln for ln in out.strip().splitlines()[-3:])
        raise Failure(f"{what or ' '.join(cmd)}: exit {rc}" + (f": {tail}" if tail else ""))
    return out


def run_logged(cmd, cwd, log, timeout, env=None):
    """Run a long tool in cwd with its output to log; (exit status, wall s, CPU s). CPU time
    counts the tool's own children (Yosys's ABC). Killed after timeout seconds."""
    t0 = time.time()
    with open(log, "w") as f:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=f, stderr=subprocess.STDOUT, env=env)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        _, status, ru = os.wait4(p.pid, 0)
        timer.cancel()
        rc = p.returncode = os.waitstatus_to_exitcode(status)
        if rc < 0 and time.time() - t0 >= timeout:
            f.write(f"\n{os.path.basename(cmd[0])}: timed out after {timeout} s\n")
    return rc, time.time() - t0, ru.ru_utime + ru.ru_stime


_versions = {}


def tool_version(tool):
    """The first line a tool prints about its version, or None when it is not installed."""
    if tool not in _versions:
        flag = "-V" if os.path.basename(tool) == "yosys" else "--version"
        try:
            out = subprocess.run([tool, flag], capture_output=True, text=True, timeout=120)
            text = [ln for ln in (out.stdout + out.stderr).strip().splitlines() if "Preparing" not in ln]
            _versions[tool] = text[0].strip() if text else "unknown"
        except (OSError, subprocess.SubprocessError):
            _versions[tool] = None
    return _versions[tool]


def digest(*parts):
    h = hashlib.sha256()
    for p in parts:
        h.update(p.encode())
        h.update(b"\0")
    return h.hexdigest()


def file_digest(paths):
    """A digest of the files' names and contents, in the order given."""
    h = hashlib.sha256()
    for p in paths:
        h.update(p.encode() + b"\0")
        try:
            with open(p, "rb") as f:
                h.update(f.read())
        except OSError as e:
            raise Failure(f"cannot read {e.filename}: {e.strerror}")
    return h.hexdigest()


def gen_files(gen=GEN):
    """The generated headers the RTL includes, and rtl/'s own: part of every RTL cache key."""
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
