/*
 * unit_latency.c - the latency of one arithmetic unit or datapath, from model/timing.c, for
 * the unit benches (+latency=) and the formal tasks (the LATENCY they check), so that no
 * bench or property restates a latency formula.
 *
 * usage: unit_latency UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION
 *        unit_latency -   (lines "UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION" on
 *                          stdin, each echoed with its latency appended: units-latency-formulas)
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

/* The latency of one unit and configuration (argv-style: 8 words), or exit 2. */
static long latency_of(char **w)
{
    hw_params hp;
    memset(&hp, 0, sizeof hp);
    hp.w = number(w[1], 4, 64, "W");
    hp.sqrt_bits = number(w[2], 1, 64, "SQRT_BITS");
    hp.div_bits = number(w[3], 1, 64, "DIV_BITS");
    hp.dim = number(w[4], 2, 3, "DIM");
    hp.pipe_steps = number(w[5], 1, 64, "STEPS");
    hp.mantissa = number(w[6], 0, 32, "MANTISSA");
    hp.projection = number(w[7], 0, 1, "PROJECTION");
    const char *u = w[0];
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
        exit(2);
    }
    return lat;
}

int main(int argc, char **argv)
{
    if (argc == 2 && !strcmp(argv[1], "-")) {
        char line[256], copy[256];
        while (fgets(line, sizeof line, stdin)) {
            char *w[8];
            int n = 0;
            line[strcspn(line, "\r\n")] = 0;
            memcpy(copy, line, sizeof copy);
            for (char *t = strtok(copy, " \t"); t && n < 8; t = strtok(NULL, " \t")) w[n++] = t;
            if (n == 0) continue;
            if (n != 8) {
                fprintf(stderr, "unit_latency: want 8 words, not '%s'\n", line);
                return 2;
            }
            printf("%s %ld\n", line, latency_of(w));
        }
        return 0;
    }
    if (argc != 9) {
        fprintf(stderr, "usage: unit_latency UNIT W SQRT_BITS DIV_BITS DIM STEPS MANTISSA PROJECTION | unit_latency -\n");
        return 2;
    }
    printf("%ld\n", latency_of(argv + 1));
    return 0;
}
