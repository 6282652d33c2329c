/*
 * unit_latency.c - the latency of one arithmetic unit or datapath, from model/timing.c, for
 * the unit benches (+latency=) and the formal tasks (the LATENCY they check), so that no
 * bench or property restates a latency formula.
 *
 * usage: unit_latency UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION
 *   UNIT: sqrt div mul_pipe sqrt_pipe div_pipe toward toward_pipe spring spring_pipe
 *   (toward and toward_pipe with PROJECTION = 1 are toward_prev and toward_prev_pipe).
 * Prints the latency in cycles: a serial unit's start cycle to its done cycle, a pipe's
 * operands on its inputs in cycle 0 to its result in cycle LATENCY (fx_sqrt_pipe's and
 * fx_div_pipe's latency in timing.c counts from the edge that samples the operands, the
 * edge that ends cycle 0: one less). Exit 2 on bad arguments.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "timing.h"

static int number(const char *s, int lo, int hi, const char *what)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (!*s || *end || v < lo || v > hi) {
        fprintf(stderr, "unit_latency: %s must be %d..%d, not '%s'\n", what, lo, hi, s);
        exit(2);
    }
    return (int)v;
}

int main(int argc, char **argv)
{
    if (argc != 9) {
        fprintf(stderr, "usage: unit_latency UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION\n");
        return 2;
    }
    hw_params hp;
    memset(&hp, 0, sizeof hp);
    hp.w = number(argv[2], 4, 64, "W");
    hp.sqrt_bits = number(argv[3], 1, 64, "SQRT_BITS");
    hp.div_bits = number(argv[4], 1, 64, "DIV_BITS");
    hp.dim = number(argv[5], 2, 3, "DIM");
    hp.pipe_steps = number(argv[6], 1, 64, "STEPS");
    hp.mantissa = number(argv[7], 0, 32, "MANTISSA");
    hp.projection = number(argv[8], 0, 1, "PROJECTION");
    const char *u = argv[1];
    long lat = !strcmp(u, "sqrt") ? hw_sqrt_latency(&hp)
             : !strcmp(u, "div") ? hw_div_latency(&hp)
             : !strcmp(u, "mul_pipe") ? hw_mul_pipe_latency()
             : !strcmp(u, "sqrt_pipe") ? hw_sqrt_pipe_latency(&hp) + 1 /* sampled at the edge ending cycle 0 */
             : !strcmp(u, "div_pipe") ? hw_div_pipe_latency(&hp) + 1
             : !strcmp(u, "toward") ? hw_toward_latency(&hp)
             : !strcmp(u, "toward_pipe") ? hw_toward_pipe_latency(&hp)
             : !strcmp(u, "spring") ? hw_spring_latency(&hp)
             : !strcmp(u, "spring_pipe") ? hw_spring_pipe_latency(&hp) : -1;
    if (lat < 0) {
        fprintf(stderr, "unit_latency: unknown unit '%s'\n", u);
        return 2;
    }
    printf("%ld\n", lat);
    return 0;
}
