# scripts/effects.mk - what each effect costs strand_core (docs/effects.md), and the check
# that an effect switched off costs nothing.
#
# Included by the top Makefile:
#     make effects       # regenerate docs/effects.md
#     make test-effects  # the gating check (part of make test)
#
# effects: for the 4x5 Q16.16 body of make synth, with no effect and with each effect
# of the table at the top of scripts/effects.py: strand hwgen, Yosys (generic,
# synth_ice40, synth_ecp5) and the Verilator harness in lockstep, whose measured
# cycles per frame must equal hw_cycles_per_frame(); the gating check below; then
# docs/effects.md is rewritten with both.
# test-effects: on a small body, for each effect, the scene with its switch forced off
# against the scene without it: the same generic cells, cycles per frame and outputs;
# one PASS/FAIL line per effect. Results are cached in $(BUILD)/effects/ by the contents
# of the sources and the parameters. Variables are prefixed EFFECTS_ (BUILD, GEN, JOBS,
# PYTHON, STRAND, MODEL_LIB and GEN_HDRS come from the top Makefile).

EFFECTS_SAVED_GOAL := $(.DEFAULT_GOAL)

EFFECTS_JOBS ?= $(if $(JOBS),$(JOBS),2)
EFFECTS_PY   := $(if $(PYTHON),$(PYTHON),.venv/bin/python3) scripts/effects.py
EFFECTS_ARGS  = --build $(BUILD)/effects --jobs $(EFFECTS_JOBS)

.PHONY: effects test-effects

effects: bootstrap
	@$(MAKE) --no-print-directory -s $(STRAND) $(GEN_HDRS)
	@$(EFFECTS_PY) test $(EFFECTS_ARGS) --json $(BUILD)/effects/test.json
	@$(EFFECTS_PY) doc $(EFFECTS_ARGS) --out docs/effects.md --test-json $(BUILD)/effects/test.json

test-effects: $(STRAND) $(GEN_HDRS)
	@$(EFFECTS_PY) test $(EFFECTS_ARGS)

# Including this file does not change the default goal.
.DEFAULT_GOAL := $(EFFECTS_SAVED_GOAL)
