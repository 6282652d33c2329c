#!/usr/bin/env python3
"""check_warnings.py STRAND - strand check names the constants that vanish, clip or lose
more than 1 % to rounding, at their line, and --strict makes them an error.

Each case is a scene written to a temporary file: the warning strand check must print
(file:line: warning: ...), its exit status without and with --strict. Prints a PASS or
FAIL line per case; exit status 1 if any fails.
"""
import os
import subprocess
import sys
import tempfile

Q10_8 = "[format]\nwidth = 18\nfrac = 8\n"                                        # lines 1-3
CHAIN = "[chain]\nunits = 2\nnodes_per_unit = 4\nstart = 0 0\nstep = 1 0\n"       # +5 lines

# name, scene text, the line and words of the warning (None: no warning)
CASES = [
    ("Q10.8 chain at 32 substeps: g h^2 rounds to 0 (the chain freezes)",
     Q10_8 + "[time]\ndt = 1\nsubsteps = 32\n" + CHAIN + "[constraints]\n[gravity]\naccel = 0 0.2\n",
     14, "g h^2 (y) = 0.000195313 rounds to 0 in Q10.8 (0.05 LSB): the effect vanishes; it needs 18 fraction bits"),
    ("a gravity beyond the format saturates",
     Q10_8 + "[time]\ndt = 1\n" + CHAIN + "[gravity]\naccel = 0 600\n",
     12, "g h^2 (y) = 600 does not fit Q10.8 (largest 511.996): it saturates; it needs 11 integer bits"),
    ("a rest length below half an LSB becomes 0",
     Q10_8 + "[time]\ndt = 1\n" + CHAIN + "rest = 0.001\n[constraints]\n",
     11, "the chain's rest length = 0.001 rounds to 0 in Q10.8"),
    ("a spring constant losing more than 1 %",
     Q10_8 + "[time]\ndt = 1\n" + CHAIN + "[springs]\nks = 0.0201\n",
     12, "ks h^2/m = 0.0201 becomes 0.0195312 in Q10.8 (-2.8 %): it needs 12 fraction bits"),
    ("the same chain at Q16.16 and 4 substeps is clean",
     "[time]\ndt = 1\nsubsteps = 4\n" + CHAIN + "[constraints]\n[gravity]\naccel = 0 0.5\n",
     None, None),
]


def run(strand, path, strict):
    r = subprocess.run([strand, "check", path] + (["--strict"] if strict else []), capture_output=True, text=True)
    return r.returncode, r.stderr


def main():
    strand = sys.argv[1]
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for i, (name, text, line, words) in enumerate(CASES):
            path = os.path.join(tmp, f"case{i}.scene")
            with open(path, "w") as f:
                f.write(text)
            rc, err = run(strand, path, False)
            rc_strict, _ = run(strand, path, True)
            if words is None:
                ok = rc == 0 and rc_strict == 0 and "warning" not in err
                want = "no warning, exit 0 with and without --strict"
            else:
                ok = f"{path}:{line}: warning: {words}" in err and rc == 0 and rc_strict == 2
                want = f"'{path}:{line}: warning: {words}', exit 0, and 2 with --strict"
            if ok:
                print(f"PASS check-warnings: {name}")
            else:
                failed += 1
                print(f"FAIL check-warnings: {name}: expected {want}; got exit {rc} / {rc_strict}:\n{err}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
