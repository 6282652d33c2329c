/*
 * timing.h - how many cycles the RTL takes: every latency and phase length, written
 * once. The cycle model, the harness, the CLI (strand hwgen, strand info), the docs
 * and the scripts all get them from here.
 */
#ifndef STRAND_TIMING_H
#define STRAND_TIMING_H

#include <stdbool.h>

#include "hw_params.h"

#ifdef __cplusplus
extern "C" {
#endif

/* fx_along_pipe.v (MANTISSA > 0, the normalised distance datapath): inputs in cycle 0, t in this cycle. */
long hw_along_pipe_latency(const hw_params *hp);
/* fx_sqrt.v, fx_div.v: start to done (a load cycle, BITS + 1 iterations, done). */
long hw_sqrt_latency(const hw_params *hp);
long hw_div_latency(const hw_params *hp);
/* fx_mul_pipe.v: operands on the inputs in cycle 0, the product in cycle 2. */
long hw_mul_pipe_latency(void);
/* toward.v: start to done (the distance datapath of the constraints). */
long hw_toward_latency(const hw_params *hp);
/* fx_sqrt_pipe.v, fx_div_pipe.v (rtl/pipe_latency.vh): operands sampled at edge e give their
   result after edge e + this (ceil((BITS + 1) / PIPE_STEPS) + 1). */
long hw_sqrt_pipe_latency(const hw_params *hp);
long hw_div_pipe_latency(const hw_params *hp);
/* toward_pipe.v (toward_prev_pipe.v with PROJECTION): an operation on its inputs in cycle 0 is
   on its outputs in this cycle. */
long hw_toward_pipe_latency(const hw_params *hp);
/* spring_force.v: start to done. */
long hw_spring_latency(const hw_params *hp);
/* spring_force_pipe.v's latency and a spring_stream.v sweep (ARCH = 1 with EN_SPRINGS) */
long hw_spring_pipe_latency(const hw_params *hp);
long hw_spring_sweep(const hw_params *hp);
/* chain_stream.v (ARCH = 1): a sweep (one colour of a pass), its start to the next sweep's
   (SP = max(floor(K/2) + 2, LP + 4): the drain of one overlaps the next), and the last sweep of the
   constraint passes of a substep, to its drain (SL = floor(K/2) + LP + 3). */
long hw_stream_period(const hw_params *hp);
/* node_unit: the steps of a Verlet or ground pass: K nodes, or with PAIR (a chain's pipelined
   build) ceil(K / 2) rows of two, one node of each bank a clock */
long hw_pass_steps(const hw_params *hp);
long hw_stream_last(const hw_params *hp);
long hw_fuse_lag(void);
bool hw_stream_slot_bound(const hw_params *hp); /* sweep period set by the slots (NS + 1), not the pipe */
/* One constraint pass (chain_sequencer, pair_sequencer or chain_stream), start to done, without the start cycle. */
long hw_constraint_pass(const hw_params *hp);
/* One spring pass, from its start cycle to its done. */
long hw_spring_pass(const hw_params *hp);
/* Cycles per frame: step to frame_done, back to back (docs/architecture.md shows the terms). */
long hw_cycles_per_frame(const hw_params *hp);

/* The formula as text, one term per line ("name = value: how"), for docs and `strand info`. */
int hw_timing_text(const hw_params *hp, char *out, int len);

#ifdef __cplusplus
}
#endif

#endif
