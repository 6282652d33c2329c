/* cpu_bench.c - the CPU programs' common options and timed loop (cpu_bench.h). */
#define _POSIX_C_SOURCE 200809L
#include "cpu_bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cpu_bench_defaults(cpu_bench_args *a)
{
    a->path = NULL;
    a->type = "double";
    a->order = NULL;
    a->frames = -1;
    a->check = 0;
    a->min_seconds = 1.0;
}

const char *cpu_bench_option(cpu_bench_args *a, int argc, char **argv, int *i)
{
    const char *opt = argv[*i];
    const int has_value = *i + 1 < argc;
    if (!strcmp(opt, "--frames") && has_value) a->frames = atoi(argv[++*i]);
    else if (!strcmp(opt, "--type") && has_value) a->type = argv[++*i];
    else if (!strcmp(opt, "--order") && has_value) a->order = argv[++*i];
    else if (!strcmp(opt, "--min-seconds") && has_value) a->min_seconds = atof(argv[++*i]);
    else if (!strcmp(opt, "--check")) a->check = 1;
    else if (opt[0] == '-') return "";
    else if (a->path) return "more than one SCENE";
    else a->path = opt;
    return NULL;
}

const char *cpu_bench_validate(const cpu_bench_args *a)
{
    if (!a->path) return "no SCENE given";
    if (strcmp(a->type, "float") && strcmp(a->type, "double")) return "--type takes float or double";
    if (a->frames == 0 || a->frames < -1) return "--frames must be at least 1";
    if (!(a->min_seconds >= 0)) return "--min-seconds must be >= 0";
    if (a->check && !strcmp(a->type, "float")) return "--check compares the double type with the frame engine";
    return NULL;
}

double cpu_bench_repeat(void (*run)(void *ctx), void *ctx, double min_seconds, long *runs)
{
    const double t0 = now();
    double t;
    *runs = 0;
    do {
        run(ctx);
        ++*runs;
        t = now() - t0;
    } while (t < min_seconds);
    return t;
}

int cpu_bench_load(scene *sc, const char *path, int order)
{
    char err[SCENE_ERR_LEN];
    if (!scene_load(sc, path, err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    if (order >= 0 && scene_set_order(sc, (constraint_order)order, err) < 0) {
        fprintf(stderr, "%s:%d: --order: %s\n", path, scene_key_line(sc, "constraints", "order"), err);
        return 2;
    }
    return 0;
}
