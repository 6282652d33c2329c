/*
 * cpu_fast.c - the optimised CPU side of the speed comparison: a chain's frames on one
 * core, float or double, laid out and written so that the compiler vectorises them.
 *
 * usage: cpu_fast SCENE [--frames N] [--type float|double] [--order redblack]
 *                 [--min-seconds S] [--check | --stretch N]
 *
 * The physics is cpu_rope's and the frame engine's (model/engine_body.h) in the red/black
 * order: per substep the Verlet step (damping, gravity) and the mouse impulse of every
 * node, then `iterations` constraint passes, each the even nodes then the odd nodes (the
 * centred rule) or the even links then the odd links (the pairwise rule; the order
 * scene_set_order gives a chain). Chains in 2D and 3D with pinned nodes; anything else
 * (graphs, springs, the ground, the grab form of the mouse, projection = previous, Euler,
 * the serial order) is refused with the scene's file and line.
 *
 * What makes it fast is in cpu_fast_body.inc: structure of arrays, even and odd nodes in
 * separate contiguous runs, branch-free loops over one colour at a time, float and double
 * from one source (the body included once per number type and dimension). Each node's
 * arithmetic is the frame engine's, in its order, so in double the positions are the frame
 * engine's bit for bit: --check runs the frame engine in double beside it and compares
 * every position of every frame.
 *
 * Timing as cpu_rope: the scene's frames are run again and again from its start until at
 * least --min-seconds (default 1) have passed (CLOCK_MONOTONIC); the line printed gives
 * the constraint updates per second (node updates of the centred rule, link updates of the
 * pairwise rule, every iteration of every substep) and the flags it was built with
 * (make cpu-fast: -O3 -march=native -fno-math-errno, ISO C11, so no FMA contraction).
 *
 * --stretch N: the accuracy that goes beside the speed. Instead of timing, the frames are run
 * once from the scene's start in the chosen type and the line printed gives stretch_max, the
 * largest |length - rest| / rest of any link (i, i+1) of the chain in frames 1..frames, and
 * stretch_rest, the same over the last N frames only (the rope at rest), both in percent;
 * lengths are computed in double from the run's positions, as the frame engine's
 * stats_max_stretch computes them (model/engine.c), so in double stretch_max is the figure
 * `strand run SCENE --format double` prints as its max stretch (make test-model checks it).
 * A float run at a large distance from the origin may not hold the rope as double does: its
 * positions' resolution can be coarser than a substep's gravity step.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cpu_bench.h"
#include "scene.h"
#include "sim.h"

#ifndef CPU_FAST_CFLAGS
#define CPU_FAST_CFLAGS "?"
#endif

#define FAST_ALIGN 64 /* bytes: each colour's run starts on a cache line (and a vector boundary) */

/*
 * The three vectorised loops (Verlet, the centred rule, the pairwise rule) are functions whose
 * restrict-qualified array parameters tell the compiler that a colour's arrays do not overlap
 * the other colour's. GCC 12 drops that knowledge when it inlines such a function, and then
 * vectorises the 3D loops not at all (too many possible overlaps to test at run time), so
 * they stay calls: one per pass, not per node.
 */
#if defined(__GNUC__)
#define FAST_LOOP __attribute__((noinline))
#else
#define FAST_LOOP
#endif

/* A link with a pinned end, worked out apart from the vectorised pass. */
typedef struct {
    int a, b; /* nodes, a = b - 1 */
    bool a_pinned, b_pinned;
} fast_link;

/*
 * The chain as the engines share it (the same for every number type): the layout, slots
 * 0 .. even - 1 for the even nodes and odd .. odd + n - even - 1 for the odd ones, with at
 * least one slot of padding after each run for the centred rule's ghosts (cpu_fast_body.inc:
 * slot odd - 1 stands before node 0, slot even after an odd last node, slot odd + n - even
 * after an even last node); and the pins.
 */
typedef struct {
    const scene *sc;
    const sim_dbl *ref; /* the frame engine's initial state and constants (init has scaled them to the substep) */
    int n;              /* nodes */
    int even;           /* even nodes */
    int odd;            /* the first odd node's slot */
    int slots;          /* slots of an array, padding included */
    int n_pins, *pins;  /* pinned nodes */
    int n_pin_links[2]; /* per colour of links: the links with a pinned end */
    fast_link *pin_links[2];
} fast_shape;

/* Node i's slot: even nodes first, then the odd ones. */
static inline int fast_slot(const fast_shape *sh, int i) { return (i & 1) ? sh->odd + i / 2 : i / 2; }

/* An instantiation of cpu_fast_body.inc, type-erased so that main picks one at run time. */
typedef struct {
    void *(*create)(const fast_shape *sh);
    void (*reset)(void *st, const fast_shape *sh);                 /* the scene's initial state */
    void (*frame)(void *st, const fast_shape *sh, int frame);      /* frame number `frame` (from 0) */
    double (*position)(const void *st, const fast_shape *sh, int node, int axis);
    void (*destroy)(void *st);
} fast_ops;

#define T float
#define DIM 2
#define SQRT sqrtf
#define FABS fabsf
#define FAST(name) fast_flt2_##name
#include "cpu_fast_body.inc"

#define T float
#define DIM 3
#define SQRT sqrtf
#define FABS fabsf
#define FAST(name) fast_flt3_##name
#include "cpu_fast_body.inc"

#define T double
#define DIM 2
#define SQRT sqrt
#define FABS fabs
#define FAST(name) fast_dbl2_##name
#include "cpu_fast_body.inc"

#define T double
#define DIM 3
#define SQRT sqrt
#define FABS fabs
#define FAST(name) fast_dbl3_##name
#include "cpu_fast_body.inc"

static int usage(const char *why)
{
    if (why) fprintf(stderr, "cpu_fast: %s\n", why);
    fprintf(stderr, "usage: cpu_fast SCENE [--frames N] [--type float|double] [--order redblack] [--min-seconds S] "
                    "[--check | --stretch N]\n");
    return 2;
}

/* What the scene asks that cpu_fast does not run, with the line that asks it; NULL if it runs it. */
static const char *unsupported(const scene *sc, int *line)
{
    struct {
        bool when;
        const char *section, *key, *what;
    } refusals[] = {
        {sc->body != BODY_CHAIN, "graph", NULL, "a graph (cpu_rope runs graphs)"},
        {sc->integrator != INTEGRATOR_VERLET, "time", "integrator", "explicit Euler"},
        {sc->en_springs, "springs", NULL, "springs"},
        {sc->en_ground, "ground", NULL, "the ground"},
        {sc->en_mouse && sc->mouse == MOUSE_GRAB, "mouse", "mode", "the grab form of the mouse"},
        {sc->projection == PROJECTION_PREVIOUS, "constraints", "projection", "projection = previous"},
        STRAND_EFFECT_CPU_FAST_REFUSALS(sc) /* the effects table's it does not run */
        {sc->order != ORDER_REDBLACK, "constraints", "order",
         "the serial order (give --order redblack; cpu_rope runs both orders)"},
    };
    for (size_t r = 0; r < sizeof refusals / sizeof refusals[0]; r++)
        if (refusals[r].when) {
            *line = refusals[r].key ? scene_key_line(sc, refusals[r].section, refusals[r].key)
                                    : scene_section_line(sc, refusals[r].section);
            return refusals[r].what;
        }
    return NULL;
}

/*
 * The layout and the pins. The loops assume the links scene_set_order gives a chain in the
 * red/black order (even links i-(i+1), then odd ones, each at the chain's rest length);
 * returns why not if the scene's are not those, or NULL.
 */
static const char *shape_chain(fast_shape *sh, const scene *sc, const sim_dbl *ref)
{
    const int n = sc->n_nodes;
    const int per_line = FAST_ALIGN / (int)sizeof(float); /* slots a cache line holds at the narrower type */
    memset(sh, 0, sizeof *sh);
    sh->sc = sc;
    sh->ref = ref;
    sh->n = n;
    sh->even = (n + 1) / 2;
    sh->odd = (sh->even + 1 + per_line - 1) / per_line * per_line;        /* a ghost's slot after the even run */
    sh->slots = (sh->odd + n / 2 + 1 + per_line - 1) / per_line * per_line; /* and after the odd run */
    sh->pins = calloc((size_t)n, sizeof *sh->pins);
    for (int c = 0; c < 2; c++) sh->pin_links[c] = calloc((size_t)n, sizeof *sh->pin_links[c]);
    if (!sh->pins || !sh->pin_links[0] || !sh->pin_links[1]) return "out of memory";
    for (int i = 0; i < n; i++)
        if (sc->pinned[i]) sh->pins[sh->n_pins++] = i;
    int e = 0;
    for (int colour = 0; colour < 2; colour++)
        for (int a = colour; a + 1 < n; a += 2, e++) {
            if (sc->en_constraints && (e >= sc->n_edges || sc->edges[e].kind == EDGE_SPRING || sc->edges[e].a != a ||
                                       sc->edges[e].b != a + 1 || sc->edges[e].rest != sc->chain_rest))
                return "the chain's links are not the red/black order's (even links, then odd ones)";
            if (sc->pinned[a] || sc->pinned[a + 1]) {
                fast_link l = {a, a + 1, sc->pinned[a], sc->pinned[a + 1]};
                sh->pin_links[colour][sh->n_pin_links[colour]++] = l;
            }
        }
    return NULL;
}

/*
 * --stretch: the largest |length - rest| / rest (percent) of the chain's links (i, i+1) at
 * the run's positions, in double whatever the run's type, with stats_max_stretch's
 * arithmetic (a 2D chain's z is 0, which adds nothing to a length's square). A NaN is kept
 * (stats_max_stretch lets a later finite value replace it): a diverged run must not
 * report a finite stretch.
 */
static double worse(double worst, double s) { return isnan(worst) || s <= worst ? worst : s; }

static double chain_stretch(const fast_ops *ops, const void *st, const fast_shape *sh)
{
    const double rest = sh->sc->chain_rest;
    double worst = 0, a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
    for (int k = 0; k < sh->sc->dim; k++) a[k] = ops->position(st, sh, 0, k);
    for (int i = 0; i + 1 < sh->n; i++) {
        for (int k = 0; k < sh->sc->dim; k++) b[k] = ops->position(st, sh, i + 1, k);
        double len = sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        worst = worse(worst, fabs(len - rest) / rest * 100.0);
        memcpy(a, b, sizeof a);
    }
    return worst;
}

/* The scene's frames once from its start: stretch_max over frames 1..frames, stretch_rest over the last `last`. */
static void run_stretch(const fast_ops *ops, void *st, const fast_shape *sh, int frames, int last, const char *type)
{
    double max = 0, rest = 0;
    int max_frame = 0;
    ops->reset(st, sh);
    for (int f = 1; f <= frames; f++) {
        ops->frame(st, sh, f - 1);
        double s = chain_stretch(ops, st, sh);
        if (f == 1 || (!isnan(max) && !(s <= max))) { /* the first frame that reached it; a NaN stays */
            max = s;
            max_frame = f;
        }
        if (f > frames - last) rest = f == frames - last + 1 ? s : worse(rest, s);
    }
    /* %.17g: the figures round-trip, so that make test-model can compare them with the frame engine's exactly */
    printf("cpu_fast %s type=%s order=redblack nodes=%d substeps=%d iterations=%d frames=%d rest_frames=%d "
           "stretch_max=%.17g stretch_max_frame=%d stretch_rest=%.17g\n",
           sh->sc->name, type, sh->n, sh->sc->substeps, sh->sc->iterations, frames, last, max, max_frame, rest);
}

/* The timed loop's run: the scene's frames from its start. */
typedef struct {
    const fast_ops *ops;
    void *st;
    const fast_shape *sh;
    int frames;
    double sink; /* the last node's x, so that the work is used */
} timed_run;

static void run_frames(void *ctx)
{
    timed_run *r = ctx;
    r->ops->reset(r->st, r->sh);
    for (int f = 0; f < r->frames; f++) r->ops->frame(r->st, r->sh, f);
    r->sink += r->ops->position(r->st, r->sh, r->sh->n - 1, 0);
}

int main(int argc, char **argv)
{
    cpu_bench_args a;
    cpu_bench_defaults(&a);
    int stretch = 0; /* --stretch N's N, 0 without it */
    for (int i = 1; i < argc; i++) {
        const char *why = cpu_bench_option(&a, argc, argv, &i);
        if (!why) continue;
        if (*why) return usage(why);
        if (!strcmp(argv[i], "--stretch") && i + 1 < argc) {
            char *end;
            long v = strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end || v < 1 || v > 1000000000)
                return usage("--stretch N: N, the frames at rest (the last N of the run), must be a whole number >= 1");
            stretch = (int)v;
        } else return usage("unknown option or missing value");
    }
    const char *wrong = cpu_bench_validate(&a);
    if (wrong) return usage(wrong);
    if (a.order && !strcmp(a.order, "serial"))
        return usage("--order serial: cpu_fast runs the red/black order (cpu_rope runs both)");
    if (a.order && strcmp(a.order, "redblack")) return usage("--order takes redblack");
    if (a.check && stretch) return usage("--check and --stretch: one at a time");
    const char *path = a.path, *type = a.type;
    const int redblack = a.order != NULL, is_float = !strcmp(type, "float");
    int frames = a.frames;

    scene sc;
    if (cpu_bench_load(&sc, path, redblack ? ORDER_REDBLACK : -1)) return 2;
    int line = 1;
    const char *why = unsupported(&sc, &line);
    if (why) {
        fprintf(stderr, "%s:%d: cpu_fast runs chains in the red/black order with gravity, damping, the mouse impulse, "
                        "pins and constraints; not %s\n", path, line, why);
        return 2;
    }
    if (frames < 0) frames = sc.frames;
    if (stretch > frames) {
        fprintf(stderr, "cpu_fast: --stretch %d: more frames at rest than the run's %d frames (the scene's, or --frames)\n",
                stretch, frames);
        scene_free(&sc);
        return usage(NULL);
    }

    sim_dbl ref;
    fast_shape sh;
    if (!sim_dbl_init(&ref, &sc, NULL)) {
        fprintf(stderr, "cpu_fast: out of memory\n");
        return 1;
    }
    const char *bad = shape_chain(&sh, &sc, &ref);
    if (bad) {
        fprintf(stderr, "cpu_fast: %s: %s\n", path, bad);
        return 1;
    }
    const fast_ops *ops = is_float ? (sc.dim == 3 ? &fast_flt3_ops : &fast_flt2_ops)
                                   : (sc.dim == 3 ? &fast_dbl3_ops : &fast_dbl2_ops);
    void *st = ops->create(&sh);
    if (!st) {
        fprintf(stderr, "cpu_fast: out of memory\n");
        return 1;
    }
    const int links = sh.n > 1 ? sh.n - 1 : 0;
    const long per_frame =
        sc.en_constraints ? (long)sc.substeps * sc.iterations * (sc.rule == RULE_CENTRED ? sh.n : links) : 0;

    if (a.check) { /* the frame engine in double, side by side: every position of every frame */
        sim_dbl eng;
        if (!sim_dbl_init(&eng, &sc, NULL)) {
            fprintf(stderr, "cpu_fast: out of memory\n");
            return 1;
        }
        ops->reset(st, &sh);
        for (int f = 0; f < frames; f++) {
            sim_dbl_frame(&eng);
            ops->frame(st, &sh, f);
            for (int i = 0; i < sh.n; i++)
                for (int k = 0; k < sc.dim; k++) {
                    double mine = ops->position(st, &sh, i, k);
                    if (memcmp(&eng.pos[i][k], &mine, sizeof mine)) {
                        printf("FAIL cpu_fast %s --order redblack: frame %d node %d axis %d: %.17g, the frame engine %.17g\n",
                               sc.name, f + 1, i, k, mine, eng.pos[i][k]);
                        return 1;
                    }
                }
        }
        printf("PASS cpu_fast %s --order redblack (%s rule, %dD): %d frames x %d nodes equal to the frame engine's double, "
               "bit for bit\n", sc.name, sc.rule == RULE_CENTRED ? "centred" : "pairwise", sc.dim, frames, sh.n);
        sim_dbl_free(&eng);
        return 0;
    }

    if (stretch) run_stretch(ops, st, &sh, frames, stretch, type);
    else {
        timed_run tr = {ops, st, &sh, frames, 0};
        long runs;
        const double t = cpu_bench_repeat(run_frames, &tr, a.min_seconds, &runs);
        double updates = (double)per_frame * frames * runs;
        printf("cpu_fast %s type=%s order=redblack nodes=%d updates_per_frame=%ld frames=%ld seconds=%.6f "
               "updates_per_s=%.0f last_x=%g cflags=\"%s\"\n",
               sc.name, type, sh.n, per_frame, (long)frames * runs, t, t > 0 ? updates / t : 0, tr.sink / (double)runs,
               CPU_FAST_CFLAGS);
    }
    ops->destroy(st);
    free(sh.pins);
    free(sh.pin_links[0]);
    free(sh.pin_links[1]);
    sim_dbl_free(&ref);
    scene_free(&sc);
    return 0;
}
