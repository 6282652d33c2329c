/*
 * hw_params.h - the RTL build a scene needs: every parameter of strand_core (the table of
 * scripts/gen_params.py, lower-case names: w, f, m, k, ..., en_springs, ...) and its derived
 * widths (uw, iw, aw, cw, sw, pair, wb, dbg_w, ...). Its own header, so that the cycle model,
 * the timing formulas and hwgen each include what they use and none includes another.
 */
#ifndef STRAND_HW_PARAMS_H
#define STRAND_HW_PARAMS_H

#include "strand_params.h"

typedef struct {
#define STRAND_FIELD(NAME, name, ...) int name;
    STRAND_PARAMS(STRAND_FIELD)
    STRAND_DERIVED(STRAND_FIELD)
#undef STRAND_FIELD
} hw_params;

#endif
