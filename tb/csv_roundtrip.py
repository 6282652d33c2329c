#!/usr/bin/env python3
"""csv_roundtrip.py STRAND SCENE - strand run --csv reads back to the fixed-point integers.

Runs the scene in fixed point with --csv and --hex (the raw W-bit integers of every
coordinate), then checks that every CSV coordinate, read as an exact decimal and scaled by
2^F, is the integer --hex gives. Prints one PASS or FAIL line; exit status 1 on a failure.
"""
import configparser
import fractions
import os
import subprocess
import sys
import tempfile


def main():
    strand, scene = sys.argv[1], sys.argv[2]
    ini = configparser.ConfigParser(inline_comment_prefixes=(";",), strict=False)
    ini.read(scene)
    width, frac = int(ini.get("format", "width", fallback="32")), int(ini.get("format", "frac", fallback="16"))
    name = os.path.basename(scene)
    with tempfile.TemporaryDirectory() as tmp:
        csv_path, hex_path = os.path.join(tmp, "p.csv"), os.path.join(tmp, "p.hex")
        subprocess.run([strand, "run", scene, "--format", "fixed", "--csv", csv_path, "--hex", hex_path],
                       check=True, stdout=subprocess.DEVNULL)
        rows = open(csv_path).read().split("\n")[1:]
        words = open(hex_path).read().split()
    values = [v for r in rows if r for v in r.split(",")[2:]]
    if len(values) != len(words):
        print(f"FAIL csv-roundtrip {name}: {len(values)} CSV coordinates, {len(words)} --hex words")
        return 1
    bad = 0
    for text, word in zip(values, words):
        raw = int(word, 16)
        if raw >= 1 << (width - 1):
            raw -= 1 << width
        back = fractions.Fraction(text) * (1 << frac)
        if back != raw:
            if bad < 5:
                print(f"  {text} reads back as {float(back):.4f} / 2^{frac}, the core's integer is {raw} ({word})")
            bad += 1
    if bad:
        print(f"FAIL csv-roundtrip {name}: {bad} of {len(values)} coordinates do not read back to their integer")
        return 1
    print(f"PASS csv-roundtrip {name}: {len(values)} coordinates read back to their Q{width - frac}.{frac} integers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
