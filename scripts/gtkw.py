#!/usr/bin/env python3
"""gtkw.py SCENE OUT.gtkw TRACE.fst [--check] - a GTKWave save file for the trace of one scene's build.

The save file shows clk, reset, the mouse (only when the scene has one), step and
frame_done. It then shows the phase, FV, FEC, the walk (uidx, nidx, counter), the
state of every FSM of unit 0 and of the sequencer, and each unit's write-back lane
(x, y and, in 3D, z). Positions and the mouse are shown as decimals: the real-valued
companions sim_top keeps of each Q(W-F).F word (g_lane[u].wb_x_val, mouse_x_val, ...).

The signals come from the trace itself (its header, read with fst2vcd). So the file
names only signals that exist in this build, at their widths: a save file written for
another build would ask GTKWave for names it silently drops.

The build (M, DIM, the mouse) comes from `strand info SCENE --json`.
--check: write nothing; exit 1 if a signal the build must have is missing from the
trace (make test runs it on three builds).
make wave writes build/sim/<scene>/strand.gtkw this way after make sim WAVES=1.
"""
import json
import os
import re
import subprocess
import sys

HEX, DEC, BIN, RJUSTIFY, BLANK, SIGNED = 0x2, 0x4, 0x8, 0x20, 0x200, 0x400  # GTKWave trace flags
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build_of(scene):
    strand = os.path.join(ROOT, os.environ.get("BUILD", "build"), "strand")
    p = subprocess.run([strand, "info", scene, "--json"], capture_output=True, text=True, check=True)
    info = json.loads(p.stdout)
    return dict(info["params"], **info["derived"])


def trace_signals(fst):
    """Every variable of the trace, as GTKWave names it: TOP.scope.name[msb:lsb]."""
    names, scope = [], []
    with subprocess.Popen(["fst2vcd", fst], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True) as p:
        for line in p.stdout:
            t = line.split()
            if not t:
                continue
            if t[0] == "$scope":
                scope.append(t[2])
            elif t[0] == "$upscope":
                scope.pop()
            elif t[0] == "$var":
                # $var TYPE SIZE ID NAME [RANGE] $end
                rng = t[5] if len(t) > 6 and t[5].startswith("[") else ""
                m = re.fullmatch(r"\[(\d+):(\d+)\]", rng)
                if m and m.group(1) == m.group(2):
                    rng = f"[{m.group(1)}]"   # GTKWave names a one-bit vector [n:n] as [n]
                names.append(".".join(scope + [t[4]]) + rng)
            elif t[0] == "$enddefinitions":
                p.kill()   # the header is all that is needed
                break
    return names


def pick(names, pattern):
    """The first name matching the pattern (a regular expression over the whole name), or None."""
    rx = re.compile(pattern)
    return next((n for n in names if rx.fullmatch(n)), None)


def layout(p, names):
    """The save file's rows: (name or None for a label, flags, label text); and the missing."""
    m, dim, ports = p["M"], p["DIM"], 1 + p["PAIR"]
    rows, missing = [], []

    def sig(pattern, flags, required=True):
        n = pick(names, pattern)
        if n:
            rows.append((n, flags, None))
        elif required:
            missing.append(pattern)

    def label(text):
        rows.append((None, BLANK, text))

    num = r"(\[\d+(:\d+)?\])?"
    label("clock, reset, inputs")
    sig(r"TOP\.clk", BIN | RJUSTIFY)
    sig(r"TOP\.reset", BIN | RJUSTIFY)
    if p["EN_MOUSE"]:
        for axis in "xyz"[:dim]:
            sig(rf"TOP\.sim_top\.mouse_{axis}_val", RJUSTIFY)
        sig(r"TOP\.mouse_down", BIN | RJUSTIFY)
    sig(r"TOP\.step", BIN | RJUSTIFY)
    sig(r"TOP\.frame_done", BIN | RJUSTIFY)
    label("progress")
    sig(r"TOP\.phase" + num, DEC | RJUSTIFY)
    sig(r"TOP\.fv", BIN | RJUSTIFY)
    sig(r"TOP\.fec", BIN | RJUSTIFY)
    sig(r"TOP\.uidx" + num, DEC | RJUSTIFY)
    sig(r"TOP\.nidx" + num, DEC | RJUSTIFY)
    sig(r"TOP\.counter" + num, DEC | RJUSTIFY)
    # every FSM state of the core, but only unit 0's of the per-unit ones
    states = [n for n in names if re.search(r"\.state_q(\[\d+:\d+\])?$", n) and n.startswith("TOP.sim_top.u_core.")
              and not re.search(r"\[(?!0\])\d+\]\.", n)]
    if states:
        label("FSM states")
        for n in states:
            rows.append((n, DEC | RJUSTIFY, None))
    label("write-back lanes: valid and node index of every unit's write ports (unit 0 the lowest bits)")
    sig(r"TOP\.wb_valid" + num, BIN | RJUSTIFY)
    sig(r"TOP\.wb_idx" + num, HEX | RJUSTIFY)
    for lane in range(m * ports):
        u, port = divmod(lane, ports)
        label(f"unit {u}: the position written back" + (f" (write port {port})" if ports > 1 else ""))
        for axis in "xyz"[:dim]:
            sig(rf"TOP\.sim_top\.g_lane\[{lane}\]\.wb_{axis}_val", RJUSTIFY)
    return rows, missing


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    check = "--check" in sys.argv[1:]
    if len(args) != 3:
        sys.exit(__doc__.split("\n")[0])
    scene, out, fst = args
    if not os.path.exists(fst):
        sys.exit(f"gtkw.py: {fst}: no such trace (make sim SCENE={scene} WAVES=1 writes it)")
    p = build_of(scene)
    names = trace_signals(fst)
    rows, missing = layout(p, names)
    if missing:
        print(f"gtkw.py: {fst}: the trace of {scene} lacks " + ", ".join(missing), file=sys.stderr)
        if check:
            return 1
    if check:
        print(f"PASS gtkw {os.path.basename(scene)}: {len([r for r in rows if r[0]])} signals of the save file, "
              f"every one in the trace ({len(names)} variables)")
        return 0
    lines = ["[*] GTKWave save file for strand_core in sim_top (generated by scripts/gtkw.py from the trace)",
             f'[dumpfile] "{os.path.basename(fst)}"', "[timestart] 0", "[size] 1600 900", "[signals_width] 360",
             "[sst_expanded] 1"]
    for name, flags, text in rows:
        lines.append(f"@{flags:x}")
        lines.append(name if name else f"-{text}")
    lines += ["[pattern_trace] 1", "[pattern_trace] 0"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
