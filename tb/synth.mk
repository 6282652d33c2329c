# tb/synth.mk - synthesis figures of strand_core (Yosys, nextpnr-ecp5, nextpnr-ice40).
#
# Included by the top Makefile; also works alone from the repository root:
#     make -f tb/synth.mk synth             # regenerate docs/resources.md
#     make -f tb/synth.mk test-synth-check  # 4x5 generic synth, check -assert, no latches
#
# synth: the builds of scripts/synth.py (4x5, 8x8, 16x16 at Q16.16 and the UP5K
# candidates) through generic `synth` (hierarchical and flattened), synth_ice40 -dsp,
# synth_ecp5 and synth_xilinx, then place and route of the core with its AXI4-Lite shell
# (tb/pnr_wrap.v) with nextpnr-ecp5 (LFE5U-85F, from the project's .venv) and
# nextpnr-ice40 (UP5K), the seeds synth.py lists, SYNTH_JOBS at a time; then docs/resources.md
# is rewritten from the results. Raw logs and netlists stay in $(BUILD)/synth/<build>/;
# a step whose inputs are unchanged (by content) is not run again, nor one whose result
# the tracked record docs/synth_record.json holds for the same inputs (make synth keeps
# every result there). A latch or a failed `check -assert` fails the target; a build that
# does not fit a device does not.
# test-synth-check runs Yosys itself (a recorded result does not count), then checks the
# record on its result (kept, taken back, refused for other sources) and that
# docs/synth_record.json, if it holds that build for these sources, agrees with it.
# It prints one line, "PASS synth-check (...)" or "FAIL synth-check: ...".
# All variables are prefixed SYNTH_ (BUILD, GEN, TOP_SRC and JOBS come from the top
# Makefile when it includes this file).

SYNTH_SAVED_GOAL := $(.DEFAULT_GOAL)

BUILD ?= build
SYNTH_GEN  := $(if $(GEN),$(GEN),$(BUILD)/gen)
SYNTH_DIR  := $(BUILD)/synth
# TOP_SRC (the top Makefile's list) if set, else every RTL file: `hierarchy -top` drops the rest.
SYNTH_SRC  := $(if $(TOP_SRC),$(TOP_SRC),$(sort $(wildcard rtl/*.v)))
SYNTH_JOBS ?= $(if $(JOBS),$(JOBS),2)
SYNTH_PY   := python3 scripts/synth.py
SYNTH_DOC  := docs/resources.md

.PHONY: synth test-synth-check

# The generated register map and parameter table the RTL includes (the top Makefile has the same rules).
ifeq ($(GEN_HDRS),)
$(SYNTH_GEN)/strand_regs.vh: scripts/gen_regs.py scripts/gen_effects.py
	python3 scripts/gen_regs.py $(SYNTH_GEN)
$(SYNTH_GEN)/strand_params.vh: scripts/gen_params.py scripts/gen_effects.py
	python3 scripts/gen_params.py $(SYNTH_GEN)
endif

# The script decides per step whether its cached result is still good. SYNTH_ONLY=BUILD[,BUILD]
# runs only those builds' steps (scripts/synth.py's BUILDS names them) and writes the page from
# what the record holds for the rest.
synth: $(SYNTH_GEN)/strand_regs.vh $(SYNTH_GEN)/strand_params.vh
	@scripts/bootstrap.sh
	@$(SYNTH_PY) all --build $(SYNTH_DIR) --gen $(SYNTH_GEN) --jobs $(SYNTH_JOBS) $(if $(SYNTH_ONLY),--only $(SYNTH_ONLY)) \
	  --out $(SYNTH_DOC) $(SYNTH_SRC)

test-synth-check: $(SYNTH_GEN)/strand_regs.vh $(SYNTH_GEN)/strand_params.vh
	@$(SYNTH_PY) check --build $(SYNTH_DIR) --gen $(SYNTH_GEN) $(SYNTH_SRC)

# Including this file does not change the default goal.
.DEFAULT_GOAL := $(SYNTH_SAVED_GOAL)
