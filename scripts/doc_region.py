#!/usr/bin/env python3
"""doc_region.py FILE NAME - replace one generated region of a doc with standard input.

The region is the text between

    <!-- BEGIN generated: NAME -->
    <!-- END generated: NAME -->

(the markers scripts/doc_tables.py also uses). The make target that measures a figure
pipes its table here, so each region of a doc is written by the one target that owns it
and the rest of the file is left alone. Exit 1, with FILE:LINE, when the region is
missing; the file is written whole (a temporary file renamed) or not at all.
"""
import os
import re
import sys


def rewrite(path, name, body):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    pattern = re.compile(r"(<!-- BEGIN generated: %s -->\n)(.*?)(<!-- END generated: %s -->)" % (re.escape(name), re.escape(name)), re.S)
    if not pattern.search(text):
        sys.exit(f"{path}:1: no region '{name}' (<!-- BEGIN generated: {name} --> ... <!-- END generated: {name} -->)")
    if body and not body.endswith("\n"):
        body += "\n"
    new = pattern.sub(lambda m: m.group(1) + body + m.group(3), text, count=1)
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(new)
    os.replace(tmp, path)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: doc_region.py FILE NAME < table")
    rewrite(sys.argv[1], sys.argv[2], sys.stdin.read())
