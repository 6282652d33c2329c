/*
 * cpu_rope.c - the CPU side of the speed comparison: a chain's or a graph's frames in plain
 * C, float or double, on one core, timed.
 *
 * usage: cpu_rope SCENE [--frames N] [--type float|double] [--order serial|redblack]
 *                 [--min-seconds S] [--check]
 *
 * The algorithm is the frame engine's (model/engine_body.h), written out as tight loops
 * over flat arrays in one number type: per substep the Verlet step (damping, gravity)
 * and the mouse impulse of every node, then `iterations` constraint passes (the centred
 * rule node by node, or the pairwise rule link by link or edge by edge, in the scene's order
 * or --order),
 * with the same operations in the same order, so in double it computes the frame
 * engine's double results bit for bit (--check runs both side by side and compares every
 * position of every frame). Chains and graphs, with the effects the benchmark scenes use:
 * gravity, damping, the mouse impulse, constraints, 2D or 3D; anything else is refused.
 *
 * Timing: the scene's frames are run again and again from its start until at least
 * --min-seconds (default 1) have passed (CLOCK_MONOTONIC); the line printed gives the
 * constraint updates per second: node updates (centred) or link updates (pairwise) of
 * every iteration of every substep, divided by the time of the whole frames. Build with
 * -O3 (make cpu-rope); the Makefile's flags are printed with the result.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cpu_bench.h"
#include "scene.h"
#include "sim.h"

#ifndef CPU_ROPE_CFLAGS
#define CPU_ROPE_CFLAGS "?"
#endif

typedef struct {
    const scene *sc;
    const sim_dbl *ref; /* the frame engine's constants (init has scaled them to the step) */
    int n, dim, links;
    int *link_a, *link_b, *link_e; /* the constraint links (a chain's, a graph's rods) in pass order: ends, edge */
} rope_shape;

/* One implementation per number type: T is float or double. */
#define ROPE_IMPL(T, NAME)                                                                                          \
    typedef struct {                                                                                                \
        T (*pos)[3], (*prev)[3];                                                                                    \
        T *rest; /* per link */                                                                                     \
        T gravity[3], box[3], mouse[3], damping, impulse, dist, wind[3], drag;                                      \
        bool mouse_down;                                                                                            \
    } NAME##_state;                                                                                                 \
                                                                                                                    \
    static void NAME##_reset(NAME##_state *r, const rope_shape *sh)                                                 \
    {                                                                                                               \
        for (int i = 0; i < sh->n; i++)                                                                             \
            for (int k = 0; k < 3; k++) {                                                                           \
                r->pos[i][k] = (T)sh->ref->pos[i][k];                                                               \
                r->prev[i][k] = (T)sh->ref->prev[i][k];                                                             \
            }                                                                                                       \
        for (int k = 0; k < 3; k++) {                                                                               \
            r->gravity[k] = (T)sh->ref->gravity[k];                                                                 \
            r->box[k] = (T)sh->ref->box[k];                                                                         \
            r->wind[k] = (T)sh->ref->wind[k];                                                                       \
        }                                                                                                           \
        r->drag = (T)sh->ref->drag;                                                                                 \
        r->damping = (T)sh->ref->damping;                                                                           \
        r->impulse = (T)sh->ref->impulse;                                                                           \
        r->dist = (T)sh->ref->dist;                                                                                 \
        for (int l = 0; l < sh->links; l++) r->rest[l] = (T)sh->ref->rest[sh->link_e[l]];                           \
    }                                                                                                               \
                                                                                                                    \
    /* the point at dist from node `from` toward node c; 0 for a zero length */                                    \
    static inline int NAME##_toward(const NAME##_state *r, int dim, int from, int c, T out[3])                      \
    {                                                                                                               \
        T d[3] = {0, 0, 0};                                                                                         \
        for (int k = 0; k < dim; k++) d[k] = r->pos[c][k] - r->pos[from][k];                                        \
        T len = (T)sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);                                                   \
        if (len == 0) return 0;                                                                                     \
        T ratio = r->dist / len;                                                                                    \
        for (int k = 0; k < dim; k++) out[k] = r->pos[from][k] + d[k] * ratio;                                      \
        return 1;                                                                                                   \
    }                                                                                                               \
                                                                                                                    \
    static void NAME##_centred(NAME##_state *r, const rope_shape *sh, int i)                                        \
    {                                                                                                               \
        T up[3], down[3];                                                                                           \
        if (sh->sc->pinned[i]) return;                                                                              \
        int has_up = i > 0 && NAME##_toward(r, sh->dim, i - 1, i, up);                                              \
        int has_down = i + 1 < sh->n && NAME##_toward(r, sh->dim, i + 1, i, down);                                  \
        for (int k = 0; k < sh->dim; k++) {                                                                         \
            if (has_up && has_down) r->pos[i][k] = (up[k] + down[k]) * (T)0.5;                                      \
            else if (has_up) r->pos[i][k] = up[k];                                                                  \
            else if (has_down) r->pos[i][k] = down[k];                                                              \
        }                                                                                                           \
    }                                                                                                               \
                                                                                                                    \
    static void NAME##_pair(NAME##_state *r, const rope_shape *sh, int l)                                           \
    {                                                                                                               \
        int a = sh->link_a[l], b = sh->link_b[l], fa = sh->sc->pinned[a], fb = sh->sc->pinned[b];                   \
        T d[3] = {0, 0, 0};                                                                                         \
        if (fa && fb) return;                                                                                       \
        for (int k = 0; k < sh->dim; k++) d[k] = r->pos[b][k] - r->pos[a][k];                                       \
        T len = (T)sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);                                                   \
        if (len == 0) return;                                                                                       \
        T ratio = r->rest[l] / len;                                                                                 \
        for (int k = 0; k < sh->dim; k++) {                                                                         \
            T excess = d[k] - d[k] * ratio;                                                                         \
            if (!fa && !fb) {                                                                                       \
                T half = excess * (T)0.5;                                                                           \
                r->pos[a][k] = r->pos[a][k] + half;                                                                 \
                r->pos[b][k] = r->pos[b][k] - half;                                                                 \
            } else if (fa) {                                                                                        \
                r->pos[b][k] = r->pos[b][k] - excess;                                                               \
            } else {                                                                                                \
                r->pos[a][k] = r->pos[a][k] + excess;                                                               \
            }                                                                                                       \
        }                                                                                                           \
    }                                                                                                               \
                                                                                                                    \
    static void NAME##_frame(NAME##_state *r, const rope_shape *sh, int frame)                                      \
    {                                                                                                               \
        const scene *sc = sh->sc;                                                                                   \
        const int n = sh->n, dim = sh->dim;                                                                         \
        if (sc->en_mouse) {                                                                                         \
            double m[3];                                                                                            \
            bool down;                                                                                              \
            scene_mouse_at(sc, frame, m, &down);                                                                    \
            for (int k = 0; k < 3; k++) r->mouse[k] = (T)m[k];                                                      \
            r->mouse_down = down;                                                                                   \
        }                                                                                                           \
        for (int s = 0; s < sc->substeps; s++) {                                                                    \
            for (int i = 0; i < n; i++) {                                                                           \
                if (sc->pinned[i]) continue;                                                                        \
                for (int k = 0; k < dim; k++) {                                                                     \
                    T v = r->pos[i][k] - r->prev[i][k];                                                             \
                    if (sc->damping > 0) v = v - v * r->damping;                                                    \
                    if (sc->en_wind) v = v - (v - r->wind[k]) * r->drag;                                            \
                    r->prev[i][k] = r->pos[i][k];                                                                   \
                    T x = r->pos[i][k] + v;                                                                         \
                    if (sc->en_gravity) x = x + r->gravity[k];                                                      \
                    r->pos[i][k] = x;                                                                               \
                }                                                                                                   \
                if (sc->en_mouse && r->mouse_down) {                                                                \
                    int touch = 1;                                                                                  \
                    for (int k = 0; k < dim; k++)                                                                   \
                        if (!(fabs((double)(r->mouse[k] - r->pos[i][k])) < r->box[k])) touch = 0;                   \
                    if (touch)                                                                                      \
                        r->prev[i][0] = r->mouse[0] < r->prev[i][0] ? r->pos[i][0] + r->impulse                    \
                                                                    : r->pos[i][0] - r->impulse;                    \
                }                                                                                                   \
            }                                                                                                       \
            if (!sc->en_constraints) continue;                                                                      \
            for (int it = 0; it < sc->iterations; it++) {                                                           \
                if (sc->rule == RULE_CENTRED && sc->order == ORDER_REDBLACK) {                                      \
                    for (int i = 0; i < n; i += 2) NAME##_centred(r, sh, i);                                        \
                    for (int i = 1; i < n; i += 2) NAME##_centred(r, sh, i);                                        \
                } else if (sc->rule == RULE_CENTRED) {                                                              \
                    for (int i = 0; i < n; i++) NAME##_centred(r, sh, i);                                           \
                } else {                                                                                            \
                    for (int l = 0; l < sh->links; l++) NAME##_pair(r, sh, l);                                      \
                }                                                                                                   \
            }                                                                                                       \
        }                                                                                                           \
    }

ROPE_IMPL(float, flt)
ROPE_IMPL(double, dbl)

static int usage(const char *why)
{
    if (why) fprintf(stderr, "cpu_rope: %s\n", why);
    fprintf(stderr, "usage: cpu_rope SCENE [--frames N] [--type float|double] [--order serial|redblack] "
                    "[--min-seconds S] [--check]\n");
    return 2;
}

/* The timed loop's run: the scene's frames from its start in one type. */
typedef struct {
    flt_state *fr;
    dbl_state *dr;
    const rope_shape *sh;
    int frames, is_float;
    double sink; /* the last node's x, so that the work is used */
} timed_run;

static void run_frames(void *ctx)
{
    timed_run *r = ctx;
    if (r->is_float) {
        flt_reset(r->fr, r->sh);
        for (int f = 0; f < r->frames; f++) flt_frame(r->fr, r->sh, f);
        r->sink += r->fr->pos[r->sh->n - 1][0];
    } else {
        dbl_reset(r->dr, r->sh);
        for (int f = 0; f < r->frames; f++) dbl_frame(r->dr, r->sh, f);
        r->sink += r->dr->pos[r->sh->n - 1][0];
    }
}

int main(int argc, char **argv)
{
    cpu_bench_args a;
    cpu_bench_defaults(&a);
    for (int i = 1; i < argc; i++) {
        const char *why = cpu_bench_option(&a, argc, argv, &i);
        if (why) return usage(*why ? why : "unknown option or missing value");
    }
    const char *wrong = cpu_bench_validate(&a);
    if (wrong) return usage(wrong);
    int order = -1;
    if (a.order) {
        order = !strcmp(a.order, "serial") ? ORDER_SERIAL : !strcmp(a.order, "redblack") ? ORDER_REDBLACK : -2;
        if (order == -2) return usage("--order takes serial or redblack");
    }
    const char *path = a.path, *type = a.type;
    int frames = a.frames;

    scene sc;
    if (cpu_bench_load(&sc, path, order)) return 2;
    const char *why = sc.integrator != INTEGRATOR_VERLET ? "explicit Euler"
                      : sc.en_springs ? "springs" : sc.en_ground ? "the ground" : sc.en_mouse && sc.mouse == MOUSE_GRAB ? "the grab form of the mouse"
                      : sc.projection == PROJECTION_PREVIOUS ? "projection = previous"
                      : STRAND_EFFECT_CPU_REFUSES(&sc);
    if (why) {
        fprintf(stderr, "%s:1: cpu_rope runs chains and graphs with gravity, damping, the mouse impulse, constraints and the effects scripts/gen_effects.py marks cpu; not %s\n", path, why);
        return 2;
    }
    if (frames < 0) frames = sc.frames;

    sim_dbl ref;
    if (!sim_dbl_init(&ref, &sc, NULL)) {
        fprintf(stderr, "cpu_rope: out of memory\n");
        return 1;
    }
    rope_shape sh = {&sc, &ref, sc.n_nodes, sc.dim, 0, NULL, NULL, NULL};
    sh.link_a = calloc((size_t)(sc.n_edges + 1), sizeof *sh.link_a);
    sh.link_b = calloc((size_t)(sc.n_edges + 1), sizeof *sh.link_b);
    sh.link_e = calloc((size_t)(sc.n_edges + 1), sizeof *sh.link_e);
    if (!sh.link_a || !sh.link_b || !sh.link_e) {
        fprintf(stderr, "cpu_rope: out of memory\n");
        return 1;
    }
    for (int e = 0; e < sc.n_edges; e++)
        if (sc.edges[e].kind != EDGE_SPRING) { /* in the order of the scene's edges: the frame engine's */
            sh.link_a[sh.links] = sc.edges[e].a;
            sh.link_b[sh.links] = sc.edges[e].b;
            sh.link_e[sh.links++] = e;
        }
    flt_state fr;
    dbl_state dr;
    fr.rest = calloc((size_t)(sh.links + 1), sizeof *fr.rest);
    dr.rest = calloc((size_t)(sh.links + 1), sizeof *dr.rest);
    fr.pos = calloc((size_t)sh.n, sizeof *fr.pos);
    fr.prev = calloc((size_t)sh.n, sizeof *fr.prev);
    dr.pos = calloc((size_t)sh.n, sizeof *dr.pos);
    dr.prev = calloc((size_t)sh.n, sizeof *dr.prev);
    if (!fr.rest || !dr.rest || !fr.pos || !fr.prev || !dr.pos || !dr.prev) {
        fprintf(stderr, "cpu_rope: out of memory\n");
        return 1;
    }
    const int is_float = !strcmp(type, "float");
    const long per_frame = sc.en_constraints ? (long)sc.substeps * sc.iterations * (sc.rule == RULE_CENTRED ? sh.n : sh.links) : 0;

    if (a.check) { /* the frame engine in double, side by side: every position of every frame */
        sim_dbl eng;
        sim_dbl_init(&eng, &sc, NULL);
        dbl_reset(&dr, &sh);
        for (int f = 0; f < frames; f++) {
            sim_dbl_frame(&eng);
            dbl_frame(&dr, &sh, f);
            for (int i = 0; i < sh.n; i++)
                for (int k = 0; k < 3; k++)
                    if (memcmp(&eng.pos[i][k], &dr.pos[i][k], sizeof(double))) {
                        printf("FAIL cpu_rope %s --order %s: frame %d node %d axis %d: %.17g, the frame engine %.17g\n", sc.name,
                               sc.order == ORDER_REDBLACK ? "redblack" : "serial", f + 1, i, k, dr.pos[i][k], eng.pos[i][k]);
                        return 1;
                    }
        }
        printf("PASS cpu_rope %s --order %s: %d frames x %d nodes equal to the frame engine's double, bit for bit\n", sc.name,
               sc.order == ORDER_REDBLACK ? "redblack" : "serial", frames, sh.n);
        sim_dbl_free(&eng);
        return 0;
    }

    timed_run tr = {&fr, &dr, &sh, frames, is_float, 0};
    long runs;
    const double t = cpu_bench_repeat(run_frames, &tr, a.min_seconds, &runs);
    double updates = (double)per_frame * frames * runs;
    printf("cpu_rope %s type=%s order=%s nodes=%d updates_per_frame=%ld frames=%ld seconds=%.6f updates_per_s=%.0f "
           "last_x=%g cflags=\"%s\"\n",
           sc.name, type, sc.order == ORDER_REDBLACK ? "redblack" : "serial", sh.n, per_frame, (long)frames * runs, t,
           t > 0 ? updates / t : 0, tr.sink / (double)runs, CPU_ROPE_CFLAGS);
    sim_dbl_free(&ref);
    scene_free(&sc);
    return 0;
}
