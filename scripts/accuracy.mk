# scripts/accuracy.mk - the accuracy study (docs/accuracy.md).
#
# Included by the top Makefile; also works alone from the repository root:
#     make -f Makefile -f scripts/accuracy.mk accuracy       # regenerate docs/accuracy.md
#     make -f Makefile -f scripts/accuracy.mk test-accuracy  # the quick slice and the claims
#
# accuracy: builds build/sweep (model/sweep.c: one point, fixed against double and the
# analytic checks, printed as JSON), then scripts/accuracy.py runs every point of the
# study that build/accuracy/cache/ does not hold (ACCURACY_JOBS at a time), the Yosys
# builds and the RTL cycle samples, and rewrites docs/accuracy.md and
# docs/img/accuracy_*.png. test-accuracy prints one PASS/FAIL line per check and fails
# on any FAIL. Variables are prefixed ACCURACY_ (BUILD, CC, JOBS, MODEL_LIB, GEN_HDRS
# come from the top Makefile when it includes this file).

ACCURACY_SAVED_GOAL := $(.DEFAULT_GOAL)

BUILD ?= build
ACCURACY_JOBS   ?= $(if $(JOBS),$(JOBS),2)
ACCURACY_PY     := .venv/bin/python3
ACCURACY_SWEEP  := $(BUILD)/sweep
ACCURACY_LIB    := $(if $(MODEL_LIB),$(MODEL_LIB),$(BUILD)/libstrand.a)
ACCURACY_CFLAGS := -std=c11 -Wall -Wextra -Werror -O2 -g -Imodel -I$(BUILD)/gen $(shell pkg-config --cflags inih cairo 2>/dev/null)
ACCURACY_LIBS   := $(shell pkg-config --libs inih cairo 2>/dev/null) -lm

.PHONY: accuracy test-accuracy

$(ACCURACY_SWEEP): model/sweep.c $(ACCURACY_LIB) $(wildcard model/*.h)
	$(CC) $(ACCURACY_CFLAGS) $< $(ACCURACY_LIB) $(ACCURACY_LIBS) -o $@

accuracy: bootstrap
	@$(MAKE) --no-print-directory -s $(ACCURACY_SWEEP) $(BUILD)/strand $(BUILD)/gen/strand_regs.vh
	@$(ACCURACY_PY) scripts/accuracy.py run --jobs $(ACCURACY_JOBS)

test-accuracy: $(ACCURACY_SWEEP)
	@$(ACCURACY_PY) scripts/accuracy.py test --jobs $(ACCURACY_JOBS)

# Including this file does not change the default goal.
.DEFAULT_GOAL := $(ACCURACY_SAVED_GOAL)
