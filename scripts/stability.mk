# scripts/stability.mk - hard cases, the scene-parser fuzzer, the soak and docs/stability.md.
#
# Included by the Makefile after its own definitions (it uses BUILD, CC, GEN, GEN_HDRS,
# MODEL_CFLAGS, MODEL_HDR, MODEL_LIB, DEP_LIBS, STRAND and PYTHON).
#
#   make test-stability   the hard cases (10^5 frames of most, on the model) and the bound's CLI
#   make test-fuzz        replay the committed fuzz inputs, a short fuzz run, malformed scenes on the CLI
#   make fuzz [FUZZ_SECONDS=600]  a longer bounded fuzz run
#   make soak [SOAK_JOBS=2]       10^6 frames of every hard case; writes docs/soak.md
#   make stability        regenerate docs/stability.md and docs/img/stability_euler_verlet.png

STAB_DIR      := $(BUILD)/stability
STAB_BIN      := $(BUILD)/stability-check
FUZZ_DIR      := $(BUILD)/libfuzz
FUZZ_BIN      := $(FUZZ_DIR)/fuzz_scene
FUZZ_SRC      := model/fixed.c model/scene.c model/engine.c model/engine_fixed.c model/engine_double.c
FUZZ_SECONDS  ?= 600
FUZZ_SHORT    ?= 45
SOAK_JOBS     ?= 2

.PHONY: test-stability test-fuzz fuzz soak stability

$(STAB_BIN): model/stability.c $(MODEL_LIB) $(MODEL_HDR)
	$(CC) $(MODEL_CFLAGS) -pedantic -DSTRAND_ROOT='"$(CURDIR)"' $< $(MODEL_LIB) $(DEP_LIBS) -lm -o $@

# libFuzzer: clang with the fuzzer, address and undefined-behaviour sanitizers, over the
# parser and the engine (a scene that loads is run for a few frames).
$(FUZZ_BIN): tb/fuzz/fuzz_scene.c $(FUZZ_SRC) $(MODEL_HDR) $(GEN_HDRS)
	@mkdir -p $(dir $@)
	clang -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -Imodel -I$(GEN) \
	  $(shell pkg-config --cflags inih) tb/fuzz/fuzz_scene.c $(FUZZ_SRC) $(shell pkg-config --libs inih) -lm -o $@

test-stability: $(STAB_BIN) $(STRAND)
	@mkdir -p $(STAB_DIR)
	@rc=0; $(STAB_BIN) --json $(STAB_DIR)/test.json --series $(STAB_DIR)/euler_verlet.csv || rc=1; \
	  scripts/stability_cli.sh $(STRAND) || rc=1; exit $$rc

test-fuzz: $(FUZZ_BIN) $(STRAND)
	@rc=0; FUZZ_DICT=$(GEN)/scene.dict scripts/fuzz.sh $(FUZZ_BIN) $(FUZZ_SHORT) $(FUZZ_DIR) $(FUZZ_DIR)/short.json || rc=1; \
	  scripts/bad_input_cli.sh $(STRAND) || rc=1; exit $$rc

fuzz: bootstrap $(FUZZ_BIN) $(STRAND)
	@FUZZ_DICT=$(GEN)/scene.dict scripts/fuzz.sh $(FUZZ_BIN) $(FUZZ_SECONDS) $(FUZZ_DIR) $(FUZZ_DIR)/long.json

# 10^6 frames of each hard case, SOAK_JOBS at a time; one PASS/FAIL line per case.
soak: $(STAB_BIN)
	@mkdir -p $(STAB_DIR)
	@$(STAB_BIN) --list | grep '^hard_' | xargs -P $(SOAK_JOBS) -I{} sh -c \
	  '$(STAB_BIN) --soak --only {} --json $(STAB_DIR)/soak-{}.json > $(STAB_DIR)/soak-{}.log 2>&1; cat $(STAB_DIR)/soak-{}.log'; \
	  ! grep -q '^FAIL' $(STAB_DIR)/soak-*.log; rc=$$?; \
	  python3 scripts/soak_doc.py docs/soak.md $$($(STAB_BIN) --list | grep '^hard_' | sed 's|.*|$(STAB_DIR)/soak-&.json|') || rc=1; \
	  exit $$rc

# docs/stability.md: the hard cases at their make-test length, the Euler/Verlet series and
# plot, and a FUZZ_SHORT-second fuzz run; every figure comes from this run.
stability: bootstrap $(STAB_BIN) $(FUZZ_BIN) $(STRAND)
	@mkdir -p $(STAB_DIR) docs/img
	@$(STAB_BIN) --json $(STAB_DIR)/doc.json --series $(STAB_DIR)/euler_verlet.csv | tee $(STAB_DIR)/doc.log
	@FUZZ_DICT=$(GEN)/scene.dict scripts/fuzz.sh $(FUZZ_BIN) $(FUZZ_SHORT) $(FUZZ_DIR) $(FUZZ_DIR)/doc.json | tee -a $(STAB_DIR)/doc.log
	@$(STRAND) check sim/scenes/hard_stiff_k10000.scene --auto-substeps 4096 > $(STAB_DIR)/bound.txt 2>&1; \
	  $(STRAND) check sim/scenes/ref004_chain.scene >> $(STAB_DIR)/bound.txt 2>&1; \
	  $(STRAND) check sim/scenes/ref002_euler.scene --auto-substeps 4096 >> $(STAB_DIR)/bound.txt 2>&1; true
	$(PYTHON) scripts/stability_doc.py $(STAB_DIR)/doc.json $(STAB_DIR)/euler_verlet.csv $(FUZZ_DIR)/doc.json $(STAB_DIR)/bound.txt \
	  docs/stability.md docs/img/stability_euler_verlet.png
