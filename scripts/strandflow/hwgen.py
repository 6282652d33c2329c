"""The build a scene needs, and the parameter files of a build.

strand_core's parameters have one source: the table of scripts/gen_params.py, written into
build/gen/strand_params.json; `strand info` and `strand hwgen` (model/hwgen.c) derive a
scene's values of them."""
import json
import os

from .core import GEN, STRAND, Failure, run


def info(scene, order=None):
    """`strand info SCENE --json`: the build ('params'), whether the RTL builds it ('rtl',
    'why') and its timing. order (serial or redblack) replaces the scene's constraint order.
    Failure with strand's own message (file:line) when the scene is refused."""
    rc, out = run([STRAND, "info", scene, "--json"] + (["--order", order] if order else []))
    try:
        return json.loads(out)
    except ValueError:
        raise Failure(f"strand info {scene}: " + (out.strip() or f"exit {rc}"))


def hwgen(scene, out_dir, order=None, frames=1):
    """`strand hwgen`: params.vh, params.h and the expected-output files of SCENE in out_dir."""
    rc, out = run([STRAND, "hwgen", scene, out_dir, "--frames", str(frames)] + (["--order", order] if order else []))
    if rc != 0:
        raise Failure(f"strand hwgen {scene}: " + (out.strip() or f"exit {rc}"))


def param_table(gen=GEN):
    """The table of strand_core's parameters (name, default, switch, ...), in order."""
    with open(os.path.join(gen, "strand_params.json")) as f:
        return json.load(f)["params"]


def table_defaults(gen=GEN):
    """The table's defaults as integers (a default may name an earlier parameter)."""
    out = {}
    for p in param_table(gen):
        out[p["name"]] = int(eval(p["default"], {}, dict(out)))  # the table's own integer expressions
    return out


def param_files(params, gen=GEN, writer="scripts/strandflow"):
    """params.vh and params.h of a build with these strand_core parameters (every one of the
    table; switches written 1'b0 / 1'b1 in Verilog), as strand hwgen writes them for a scene."""
    vh = [f"// the build of one parameter set; written by {writer}"]
    h = [f"/* the build params.vh describes; written by {writer} */"]
    for p in param_table(gen):
        v = params[p["name"]]
        vh.append(f"`define STRAND_{p['name']} {'1' + chr(39) + 'b' if p['switch'] else ''}{v}")
        h.append(f"#define STRAND_{p['name']} {v}")
    return "\n".join(vh) + "\n", "\n".join(h) + "\n"
