"""strandflow - the steps every Strand report and check is made of, each written once.

    hwgen   the build a scene needs (`strand info --json`), the generated parameter files
            of a parameter set, `strand hwgen` into a directory
    build   the Verilator harness (tb/harness.cpp on tb/sim_top.v) of a scene's build or of
            a parameter set, cached by a digest of what goes into it
    run     a harness, `strand` or any tool, and the figures parsed from what it prints
    synth   the Yosys script of a flow, a cached Yosys run, nextpnr, and the cell counts
            read back from `stat -json`

scripts/build_harness.sh (make's harness builds), scripts/lockstep_fuzz.py,
lockstep_soak.py, mutate.py, bench.py, accuracy.py, effects.py and synth.py all go through
these functions, so a harness, a parameter file or a cell count means the same thing in
every report. Standard library only (make's Python, not the virtual environment).
FuseSoC and edalize (strand.core) drive the lint, simulation and synthesis targets a user
of the core runs; the reports call the tools here instead because they need what edalize
does not give: per-build caching keyed on contents, one Yosys script with `stat -json` for
every family, and nextpnr logs parsed per seed.
"""
