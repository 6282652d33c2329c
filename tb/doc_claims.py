#!/usr/bin/env python3
"""doc_claims.py STRAND - the shipped-scene table of sim/scenes/README.md says which scenes
run on the C model only; strand hwgen must refuse exactly those.

Each row `| `name.scene` | what |` (`ref001_video1..4.scene` stands for four files) is
checked: marked "C model only" <=> `strand hwgen` refuses the scene; and every scene of
sim/scenes/ has a row. Prints one PASS or FAIL line per scene; exit status 1 if any is wrong.
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOC = os.path.join("sim", "scenes", "README.md")


def rows():
    for line in open(os.path.join(ROOT, DOC)):
        m = re.match(r"\|\s*`([\w.]+)\.scene`\s*\|(.*)\|\s*$", line)
        if not m:
            continue
        name, what = m.group(1), m.group(2)
        r = re.match(r"(.*?)(\d+)\.\.(\d+)$", name)
        names = [f"{r.group(1)}{i}" for i in range(int(r.group(2)), int(r.group(3)) + 1)] if r else [name]
        yield names, "C model only" in what


def main():
    strand = sys.argv[1]
    failed = n = 0
    with tempfile.TemporaryDirectory() as tmp:
        for names, model_only in rows():
            for name in names:
                n += 1
                path = os.path.join("sim", "scenes", name + ".scene")
                # one frame: whether hwgen refuses a scene depends on its build, not on its length
                # (the expected positions of every frame of the long scenes take minutes)
                r = subprocess.run([strand, "hwgen", path, os.path.join(tmp, name), "--frames", "1"], cwd=ROOT,
                                   capture_output=True, text=True)
                refused = r.returncode != 0
                if refused == model_only:
                    print(f"PASS doc-claims {name}: {DOC} says {'C model only' if model_only else 'the RTL builds it'}, "
                          f"and strand hwgen {'refuses' if refused else 'builds'} it")
                else:
                    failed += 1
                    print(f"FAIL doc-claims {name}: {DOC} says {'C model only' if model_only else 'the RTL builds it'}, "
                          f"but strand hwgen {'refuses it: ' + r.stderr.strip() if refused else 'builds it'}")
    listed = {name for names, _ in rows() for name in names}
    for f in sorted(os.listdir(os.path.join(ROOT, "sim", "scenes"))):
        if f.endswith(".scene") and f[:-6] not in listed:
            failed += 1
            print(f"FAIL doc-claims {f[:-6]}: sim/scenes/{f} has no row in {DOC}")
    if n == 0:
        print(f"FAIL doc-claims: no scene rows found in {DOC}")
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
