#!/usr/bin/env python3
"""soak_doc.py OUT.md SOAK.json... - docs/soak.md from the JSON files `make soak` writes.

One row per hard case: the frames run (10^6), the format, the figures of
model/stability.c at the end of the run (fixed point and double) and PASS/FAIL.
Standard library only.
"""
import json
import sys


def fmt(v, spec="{:.4g}"):
    return "n/a" if v is None else spec.format(v)


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: soak_doc.py OUT.md SOAK.json...")
    cases = []
    for path in sys.argv[2:]:
        try:
            with open(path) as f:
                data = json.load(f)
        except (OSError, ValueError) as e:
            sys.exit(f"{path}:1: cannot read the soak result: {e}")
        for c in data["cases"]:
            if "energy_checked" not in c:  # results of an older run: its log line says
                log = path[:-len(".json")] + ".log"
                try:
                    c["energy_checked"] = "energy growth not checked" not in open(log).read()
                except OSError as e:
                    sys.exit(f"{path}:1: no energy_checked and no log to tell: {e}")
            cases.append(c)
    cases.sort(key=lambda c: c["name"])
    out = ["# The soak: 10^6 frames of every hard case", "",
           "Written by `make soak` from its results (`build/stability/soak-*.json`); the cases, their",
           "criteria and the shorter runs of `make test` are in [stability.md](stability.md). Each case",
           "runs in Strand's fixed point (bit-exact with the RTL) and in double, one core each.", "",
           "| case | frames | format, substeps x iterations | max stretch fixed / double | energy growth fixed / double "
           "| largest jump (of span) | seconds | result |",
           "|---|---|---|---|---|---|---|---|"]
    for c in cases:
        fx, db = c["fixed"], c["double"]
        growth = f"{fmt(fx.get('energy_growth'), '{:+.3g}')} / {fmt(db.get('energy_growth'), '{:+.3g}')}"
        if not c["energy_checked"]:
            growth = "not a criterion"  # energy is put in by the mouse, or the case checks something else
        out.append(f"| `{c['name']}` | {c['frames']} | {c['format']}, {c['substeps']} x {c['iterations']} | "
                   f"{fmt(fx['max_stretch_pct'])} % / {fmt(db['max_stretch_pct'])} % | {growth} | "
                   f"{fmt(fx['max_jump_span'], '{:.3g}')} | {c['seconds']:.0f} | "
                   f"{'PASS' if c['pass'] else 'FAIL: ' + c.get('why', '')} |")
    passed = sum(1 for c in cases if c["pass"])
    out += ["", f"{passed} of {len(cases)} cases passed.", ""]
    with open(sys.argv[1], "w") as f:
        f.write("\n".join(out))
    print(f"wrote {sys.argv[1]}: {passed} of {len(cases)} cases passed")


if __name__ == "__main__":
    main()
