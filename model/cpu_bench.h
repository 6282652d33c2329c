/*
 * cpu_bench.h - what the two CPU programs of the speed comparison (cpu_rope, cpu_fast)
 * share: their common options, and the timed loop that gives a figure.
 *
 * Options: SCENE, --frames N (default: the scene's), --type float|double (default double),
 * --order O (each program says which orders it runs), --min-seconds S (default 1), --check.
 *
 * Timing: a run (the scene's frames from its start) is repeated until at least min_seconds
 * have passed on CLOCK_MONOTONIC, so that a short scene's figure is not one clock tick.
 */
#ifndef CPU_BENCH_H
#define CPU_BENCH_H

#include "scene.h"

typedef struct {
    const char *path;   /* the scene file; NULL until given */
    const char *type;   /* "float" or "double" */
    const char *order;  /* --order's word, NULL without it */
    int frames;         /* -1: the scene's */
    int check;          /* --check */
    double min_seconds; /* the timed loop's least duration */
} cpu_bench_args;

void cpu_bench_defaults(cpu_bench_args *a);

/* argv[*i]: a common option (its value taken, *i moved past it) or the scene: returns NULL;
 * not one of them: returns "" (the program's own option, or unknown); a mistake in it:
 * returns the message for the program's usage line. */
const char *cpu_bench_option(cpu_bench_args *a, int argc, char **argv, int *i);

/* After the options: NULL, or what is wrong with them (no scene, a bad type, ...). */
const char *cpu_bench_validate(const cpu_bench_args *a);

/* Loads the scene at path into *sc and, with order >= 0, puts its edges in that order.
 * Returns 0, or 2 after printing `file:line: message` on stderr. */
int cpu_bench_load(scene *sc, const char *path, int order);

/* Calls run(ctx) until min_seconds have passed (at least once); *runs: how many times.
 * Returns the seconds they took. */
double cpu_bench_repeat(void (*run)(void *ctx), void *ctx, double min_seconds, long *runs);

#endif
