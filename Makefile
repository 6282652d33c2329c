# Strand: every flow. 'make help' lists the targets.
#
# Generated files go to $(BUILD). Targets that need tools call scripts/bootstrap.sh
# first, which installs what is missing (Debian packages, .venv) and nothing else.

BUILD    ?= build
CC       ?= cc
PYTHON   := .venv/bin/python3
JOBS     ?= 2

WARN     := -Wall -Wextra -Werror
CSTD     := -std=c11
COPT     := -O2 -g
DEP_CFLAGS = $(shell pkg-config --cflags inih cairo 2>/dev/null)
DEP_LIBS   = $(shell pkg-config --libs inih cairo 2>/dev/null)
GEN       := $(BUILD)/gen
GEN_HDRS  := $(GEN)/strand_regs.h $(GEN)/strand_regs.vh
MODEL_CFLAGS = $(CSTD) $(WARN) $(COPT) -Imodel -I$(GEN) $(DEP_CFLAGS)

MODEL_SRC := model/fixed.c model/scene.c model/engine.c model/engine_fixed.c model/engine_double.c model/render.c \
             model/hwgen.c model/cycle.c
MODEL_HDR := $(wildcard model/*.h)
MODEL_OBJ := $(MODEL_SRC:model/%.c=$(BUILD)/model/%.o)
MODEL_LIB := $(BUILD)/libstrand.a
STRAND    := $(BUILD)/strand

SCENES    := $(wildcard sim/scenes/*.scene)

# The RTL: the top and everything under it (rtl/ holds one module per file).
TOP_SRC   := rtl/strand_top.v rtl/node_unit.v rtl/chain_sequencer.v rtl/toward.v \
             rtl/fx_add.v rtl/fx_mul.v rtl/fx_avg.v rtl/fx_sqrt.v rtl/fx_div.v
# Scenes whose every frame the RTL must reproduce bit for bit (tb/scenes/ hold test-only builds).
RTL_SCENES := sim/scenes/ref000_rope.scene $(wildcard tb/scenes/*.scene)
# Parameter sets the top is linted with, beyond its defaults.
LINT_SETS := "-GEN_DAMPING=1'b1 -GEN_MOUSE=1'b0 -GEN_GRAVITY=1'b0 -GM=1 -GK=4" \
             "-GM=16 -GK=16 -GITER=4 -GSUBSTEPS=3 -GSQRT_BITS=12 -GDIV_BITS=9" \
             "-GEN_CONSTRAINTS=1'b0 -GW=18 -GF=8"

SCENE     ?= sim/scenes/ref000_rope.scene
RUN_DIR    = $(BUILD)/run/$(basename $(notdir $(SCENE)))

.PHONY: help bootstrap model run sim wave test test-model test-scenes test-rtl-frames test-lockstep lockstep-fuzz \
        lint lint-c lint-rtl clean
.DEFAULT_GOAL := help

help:
	@echo "Strand make targets:"
	@echo "  make test        install what is missing, then run every test (ends with 'N passed, N failed')"
	@echo "  make sim [SCENE=...] [WAVES=1]  the RTL in lockstep with the C model: summary, CSV, picture (build/sim/)"
	@echo "  make wave [SCENE=...]  run make sim with WAVES=1 and open GTKWave on the trace"
	@echo "  make run [SCENE=...]  run a scene on the C model: summary, CSV and pictures in $(BUILD)/run/"
	@echo "  make lockstep-fuzz [N=200] [SEED=1] [BUILDS=4]  random scenes in lockstep; a failure prints its seed"
	@echo "  make model       build the C model library and the CLI, $(STRAND)"
	@echo "  make lint        C with -Wall -Wextra -Werror and -std=c11 -pedantic; Verilog lint"
	@echo "  make bootstrap   install the Debian packages and the Python environment"
	@echo "  make clean       remove $(BUILD)/"

bootstrap:
	@scripts/bootstrap.sh

# ---- generated headers: the register map, one source for C and Verilog ----

$(GEN_HDRS) &: scripts/gen_regs.py
	python3 scripts/gen_regs.py $(GEN)

# ---- the C model ----

$(BUILD)/model/%.o: model/%.c $(MODEL_HDR) $(GEN_HDRS)
	@mkdir -p $(dir $@)
	$(CC) $(MODEL_CFLAGS) -c $< -o $@

$(MODEL_LIB): $(MODEL_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(STRAND): model/strand.c $(MODEL_LIB)
	$(CC) $(MODEL_CFLAGS) $< $(MODEL_LIB) $(DEP_LIBS) -lm -o $@

model: $(STRAND)

run: bootstrap
	@$(MAKE) --no-print-directory -s model
	@mkdir -p $(RUN_DIR)
	$(STRAND) run $(SCENE) --csv $(RUN_DIR)/positions.csv --png $(RUN_DIR)/frames
	$(STRAND) compare $(SCENE)
	@echo "positions: $(RUN_DIR)/positions.csv   pictures: $(RUN_DIR)/frames/"

# ---- the RTL in lockstep with the cycle model (Verilator) ----

sim: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@scripts/sim.sh $(SCENE) $(if $(WAVES),--waves)

wave: bootstrap
	@$(MAKE) --no-print-directory -s sim WAVES=1
	@if [ "$(SCENE)" = "sim/scenes/ref000_rope.scene" ]; then save=sim/strand.gtkw; else save=$(BUILD)/sim/$(basename $(notdir $(SCENE)))/strand.gtkw; fi; \
	  echo "gtkwave $$save"; gtkwave --dump=$(BUILD)/sim/$(basename $(notdir $(SCENE)))/waves.fst --save=$$save

# make test: the RTL test scenes, the planted faults, random initial values, 50 random scenes
test-lockstep: $(STRAND) $(GEN_HDRS)
	@python3 scripts/lockstep_fuzz.py 50 --seed 1 --builds 2 $(foreach s,$(RTL_SCENES),--scene $(s)) --faults --reset-seeds 3

N ?= 200
SEED ?= 1
BUILDS ?= 4
lockstep-fuzz: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@python3 scripts/lockstep_fuzz.py $(N) --seed $(SEED) --builds $(BUILDS)

# ---- C unit tests (cmocka) ----

MODEL_TESTS := $(patsubst model/tests/%.c,$(BUILD)/tests/%,$(wildcard model/tests/test_*.c))

$(BUILD)/tests/%: model/tests/%.c $(MODEL_LIB) $(MODEL_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(MODEL_CFLAGS) -D_POSIX_C_SOURCE=200809L -DSTRAND_ROOT='"$(CURDIR)"' -DSTRAND_BIN='"$(CURDIR)/$(STRAND)"' \
	  $< $(MODEL_LIB) $(DEP_LIBS) -lcmocka -lm -o $@

test-model: $(MODEL_TESTS) $(STRAND)
	@for t in $(MODEL_TESTS); do $$t || exit 1; done

# Every shipped scene runs in both formats.
test-scenes: $(STRAND)
	@for s in $(SCENES); do for f in fixed double; do \
	  if $(STRAND) run $$s --format $$f > $(BUILD)/scene-run.log 2>&1; \
	  then echo "PASS run $$s --format $$f"; else echo "FAIL run $$s --format $$f"; cat $(BUILD)/scene-run.log; fi; \
	done; done

# ---- the RTL against the frame engine, every frame, bit for bit ----

test-rtl-frames: $(STRAND) $(GEN_HDRS)
	@rc=0; for s in $(RTL_SCENES); do scripts/top_frames.sh $$s || rc=1; done; exit $$rc

# ---- lint ----

lint-c: $(GEN_HDRS)
	@for f in $(MODEL_SRC) model/strand.c; do $(CC) -std=c11 -pedantic $(WARN) -Imodel -I$(GEN) $(DEP_CFLAGS) -fsyntax-only $$f || exit 1; done
	@echo "lint-c: clean (-std=c11 -pedantic -Wall -Wextra -Werror)"

lint-rtl: $(GEN_HDRS)
	@verilator --lint-only -Wall -I$(GEN) $(TOP_SRC) --top-module strand_top
	@for g in $(LINT_SETS); do verilator --lint-only -Wall -I$(GEN) $$g $(TOP_SRC) --top-module strand_top || exit 1; done
	@out=$$(iverilog -Wall -g2005 -I$(GEN) -o /dev/null $(TOP_SRC) 2>&1); if [ -n "$$out" ]; then echo "$$out"; exit 1; fi
	@echo "lint-rtl: clean (verilator --lint-only -Wall, 4 parameter sets; iverilog -Wall)"

lint: lint-c lint-rtl $(if $(wildcard tb/units.mk),lint-units)

# ---- everything ----

TEST_STEPS := lint test-model test-scenes $(if $(wildcard tb/units.mk),test-units) test-rtl-frames test-lockstep

test: bootstrap
	@scripts/run_tests.sh $(TEST_STEPS)

clean:
	rm -rf $(BUILD)

-include tb/units.mk
