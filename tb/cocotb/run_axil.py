#!/usr/bin/env python3
"""run_axil.py SCENE [--frames N] [--build DIR] - the cocotb AXI4-Lite test of strand_axil on one scene.

Exports SCENE with `strand hwgen` (the build, the setup writes, the mouse script and the
model's positions at every frame end), builds tb/axil_top.v (strand_axil with the scene's
parameters and DEBUG = 0, the core as synthesised) under Icarus with cocotb's runner, runs
tb/cocotb/test_axil.py, and prints one PASS or FAIL line per test and a summary; the exit
status is 1 if any test failed. Needs the project's .venv (cocotb, cocotbext-axi) and
build/strand, build/gen (make model).
"""
import argparse
import contextlib
import glob
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

sys.dont_write_bytecode = True
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--frames", type=int, default=3)
    ap.add_argument("--build", default=os.path.join(ROOT, os.environ.get("BUILD", "build")))
    a = ap.parse_args()

    import logging
    import warnings
    warnings.filterwarnings("ignore", message="Python runners")  # the runner API is marked experimental
    logging.disable(logging.INFO)                                 # its progress lines; the logs keep all
    from cocotb.runner import get_runner  # noqa: E402 (from the venv)

    name = os.path.basename(a.scene).replace(".scene", "")
    out = os.path.join(os.path.abspath(a.build), "axil", name)
    gen = os.path.join(os.path.abspath(a.build), "gen")
    export = os.path.join(out, "hwgen")
    p = subprocess.run([os.path.join(a.build, "strand"), "hwgen", a.scene, export, "--frames", str(a.frames)],
                       capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stderr.strip())
        print(f"FAIL axil {name}: strand hwgen failed")
        return 1
    rtl = sorted(glob.glob(os.path.join(ROOT, "rtl", "*.v")))
    runner = get_runner("icarus")
    chatter = open(os.path.join(out, "runner.log"), "w")  # the runner prints each command it runs
    with contextlib.redirect_stdout(chatter):
        runner.build(verilog_sources=[os.path.join(ROOT, "tb", "axil_top.v")] + rtl, hdl_toplevel="axil_top",
                     includes=[export, gen, os.path.join(ROOT, "rtl")], parameters={"DEBUG": 0},
                     build_dir=os.path.join(out, "sim"), build_args=["-Wall"], always=True,
                     log_file=os.path.join(out, "build.log"))
    results = os.path.join(out, "results.xml")
    if os.path.exists(results):
        os.remove(results)
    try:
        with contextlib.redirect_stdout(chatter):
            runner.test(hdl_toplevel="axil_top", test_module="test_axil", test_dir=os.path.join(ROOT, "tb", "cocotb"),
                        build_dir=os.path.join(out, "sim"), results_xml=results,
                        extra_env={"STRAND_AXIL_DIR": export, "STRAND_GEN": gen, "STRAND_AXIL_FRAMES": str(a.frames)},
                        log_file=os.path.join(out, "test.log"))
    except SystemExit:
        pass
    chatter.close()
    passed = failed = 0
    if os.path.exists(results):
        for case in ET.parse(results).getroot().iter("testcase"):
            bad = case.find("failure") is not None or case.find("error") is not None
            why = ""
            if bad:
                node = case.find("failure") if case.find("failure") is not None else case.find("error")
                why = ": " + (node.get("message") or "").splitlines()[0] if node is not None else ""
            log = f" (log: {os.path.relpath(os.path.join(out, 'test.log'), ROOT)})" if bad else ""
            print(f"{'FAIL' if bad else 'PASS'} axil {name} {case.get('name')}{why}{log}")
            failed += bad
            passed += not bad
    if passed + failed == 0:
        print(f"FAIL axil {name}: no test ran (log: {os.path.join(out, 'test.log')})")
        return 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
