/*
 * stability.c - the hard cases: run each sim/scenes/hard_*.scene in fixed point and in
 * double, frame by frame, and check its stated criteria on every frame.
 *
 *   stability [--soak] [--frames N] [--only NAME] [--json FILE] [--series FILE] [--list]
 *
 * One line per case: "PASS name: figures" or "FAIL name: the first criterion broken,
 * where". Exit status 0 if every case passed, 1 if one failed, 2 for a bad argument or
 * a scene that does not load. --json writes the figures for docs/stability.md;
 * --series writes the energy of reference 002's rope under Euler and Verlet, frame by
 * frame, for the plot. docs/stability.md states every criterion and why it is the right one.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "engine.h"
#include "hwgen.h"
#include "scene.h"
#include "stability_bound.h"

#ifndef STRAND_ROOT
#define STRAND_ROOT "."
#endif

/* Criteria; every case checks FINITE, INSIDE and NOWRAP. */
enum {
    C_ENERGY = 1 << 0,    /* no input: E(t) <= E(0) + energy_tol * scale, every frame, both formats */
    C_STRETCH = 1 << 1,   /* max stretch from frame stretch_from on <= stretch_limit, both formats */
    C_RECOVER = 1 << 2,   /* the stretch at the last frame <= recover_limit, both formats */
    C_CREEP = 1 << 3,     /* fixed: no node moves between frame creep_from and the last by more than creep_lsb LSBs */
    C_GROUND = 1 << 4,    /* no node below the ground boundary at any frame end */
    C_WALL = 1 << 5,      /* fixed: on each axis gravity pulls along, a node reaches the limit of the range and the
                             rope is still there, saturated, at the end */
    C_SKIPPED = 1 << 6,   /* zero lengths occurred and their corrections were skipped */
    C_AGREE = 1 << 7,     /* fixed and double agree to agree_rms rest lengths (RMS over the run) */
    C_BOUND = 1 << 8,     /* the springs' bound: below it (as written) double diverges, at --auto-substeps it does not */
};

typedef struct {
    const char *name; /* sim/scenes/<name>.scene */
    const char *proves;
    int test_frames, soak_frames;
    unsigned checks;
    double energy_tol;
    int energy_from;    /* the reference energy is the largest of frames 0..energy_from (a transient's input) */
    double stretch_limit;
    int stretch_from;
    double recover_limit;
    int creep_from;
    double creep_lsb;
    double agree_rms;
    int agree_frames;   /* RMS over the first agree_frames frames (0: the whole run) */
    bool auto_substeps; /* run at stab_auto_substeps (the scene as written crosses the bound) */
} hard_case;

#define SOAK 1000000
/* Limits are in docs/stability.md with the reason for each. Stretch in % of the rest length. */
static const hard_case cases[] = {
    {.name = "hard_coincident",
     .proves = "all nodes on one point at reset: every length is zero and every correction skipped until gravity separates them",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH | C_SKIPPED,
     .energy_tol = 0.01, .energy_from = 200, .stretch_limit = 10, .stretch_from = 1000},
    {.name = "hard_collapse",
     .proves = "a segment collapses to exactly zero length mid-run; fixed and double skip the same correction",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH | C_SKIPPED | C_AGREE,
     .energy_tol = 0.01, .energy_from = 12, .stretch_limit = 100, .agree_rms = 1e-3, .agree_frames = 1000},
    {.name = "hard_stiff_k1000",
     .proves = "the reference-004 chain, k = 1000, d = 100: stiff and heavily damped, it stays finite and loses energy",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH, .energy_tol = 0.001, .stretch_limit = 40},
    {.name = "hard_stiff_k10000",
     .proves = "ten times stiffer: as written it crosses the bound and diverges; at the substeps --auto-substeps picks it is stable",
     .test_frames = 20000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH | C_BOUND, .energy_tol = 0.001, .stretch_limit = 40,
     .auto_substeps = true},
    {.name = "hard_large_dt",
     .proves = "a large step: gravity moves a node a third of a rest length per step; position-based constraints have no step limit",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH, .energy_tol = 0.01, .stretch_limit = 100},
    {.name = "hard_long_rope",
     .proves = "1024 nodes: the centred rule carries a correction one node per pass; the stretch stays bounded, the energy does not grow",
     .test_frames = 3000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH, .energy_tol = 0.01, .stretch_limit = 50},
    {.name = "hard_many_iterations",
     .proves = "64 centred passes per step on the default rope and its mouse script converge: the rope is nearly rigid",
     .test_frames = 20000, .soak_frames = SOAK, .checks = C_STRETCH, .stretch_limit = 5},
    {.name = "hard_resting",
     .proves = "a hanging rope at rest does not creep: every frame after 10000 stays within 8 LSB of frame 10000",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_STRETCH | C_CREEP, .energy_tol = 0.01, .stretch_limit = 10,
     .creep_from = 10000, .creep_lsb = 8},
    {.name = "hard_mouse_impulse",
     .proves = "impulses every step from a pointer thrown to the corners of the range: nodes saturate, never wrap, and the rope recovers",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_RECOVER, .recover_limit = 10},
    {.name = "hard_mouse_grab",
     .proves = "grab and release every few frames with the pointer at the corners: nodes saturate, never wrap, and the rope recovers",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_RECOVER, .recover_limit = 10},
    {.name = "hard_saturate",
     .proves = "positions driven to the limits of Q8.8: the rope ends against the walls of the range, saturated, and none wraps",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_WALL},
    {.name = "hard_ground_impact",
     .proves = "a rope hits the ground at 600 m/s, twice its height per step: no node is ever below the ground",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_ENERGY | C_GROUND, .energy_tol = 0.01},
    {.name = "hard_narrow_q10_8",
     .proves = "the default rope and mouse script in Q10.8 (18 bits): finite and bounded",
     .test_frames = 100000, .soak_frames = SOAK, .checks = C_STRETCH, .stretch_limit = 200, .agree_frames = 240},
};
#define N_CASES (int)(sizeof cases / sizeof *cases)

/* Figures of one number type over a run. */
typedef struct {
    double max_stretch, final_stretch, e0, e_max, e_final, e_scale;
    double growth; /* the largest (E - e_ref) / scale after frame energy_from */
    double max_jump;   /* largest per-frame move of a node, as a fraction of the format's span (fixed) */
    double creep;      /* fixed: LSBs; double: rest lengths */
    double ground_gap; /* smallest (position - boundary) along the normal, in rest lengths */
    int first_nonfinite;
    int last_move;     /* fixed: the last frame in which any position word changed */
    int wall_frame;    /* first frame with a node at the range's limit on every gravity axis (fixed) */
    double e_ref;      /* the reference energy: the largest of frames 0..energy_from */
    long skipped;
} figures;

typedef struct {
    const hard_case *c;
    scene sc;
    int frames, substeps_used, substeps_scene;
    figures fx, dbl;
    double rms, max_err; /* fixed against double, rest lengths */
    int bound_diverged_at; /* C_BOUND: frame where the scene as written became non-finite (0: never) */
    double bound_stretch;
    double seconds;
    bool pass;
    char why[512];
    bool rtl;
} result;

static bool fail(result *r, const char *fmt, ...)
{
    if (r->pass) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(r->why, sizeof r->why, fmt, ap);
        va_end(ap);
        r->pass = false;
    }
    return false;
}

static bool load_case(const char *name, scene *sc)
{
    char path[600], err[SCENE_ERR_LEN];
    snprintf(path, sizeof path, "%s/sim/scenes/%s.scene", STRAND_ROOT, name);
    if (!scene_load(sc, path, err)) {
        fprintf(stderr, "%s\n", err);
        return false;
    }
    return true;
}

/* The scale energies are judged against: the largest of |E0|, the peak kinetic energy and m g (rope length) N. */
static double energy_scale(const scene *sc, double e0, double ke_max)
{
    double g = sc->en_gravity ? sqrt(sc->gravity[0] * sc->gravity[0] + sc->gravity[1] * sc->gravity[1] + sc->gravity[2] * sc->gravity[2]) : 0;
    double len = 0, s;
    for (int e = 0; e < sc->n_edges; e++) len += sc->edges[e].rest;
    s = sc->mass * g * len * sc->n_nodes;
    if (fabs(e0) > s) s = fabs(e0);
    if (ke_max > s) s = ke_max;
    return s > 0 ? s : 1;
}

/* Does the double engine stay finite over `frames` frames of sc? Returns the first non-finite frame, 0 if none. */
static int first_divergence(const scene *sc, int frames, double *max_stretch)
{
    runner r;
    double (*pos)[3] = calloc((size_t)sc->n_nodes, sizeof *pos);
    int bad = 0;
    *max_stretch = 0;
    if (!pos || !runner_init(&r, sc, NUMBER_DOUBLE, NULL)) {
        free(pos);
        return -1;
    }
    for (int f = 1; f <= frames && !bad; f++) {
        runner_frame(&r);
        runner_positions(&r, pos);
        double s = stats_max_stretch(sc, pos);
        if (!isfinite(s)) bad = f;
        else if (s > *max_stretch) *max_stretch = s;
    }
    runner_free(&r);
    free(pos);
    return bad;
}

/* On every axis gravity pulls along, is some free node exactly at that end of the range? */
static bool at_wall(const sim_fx *s)
{
    const scene *sc = s->sc;
    for (int k = 0; k < sc->dim; k++) {
        double g = sc->gravity[k];
        fx_t want = g > 0 ? fx_max(&s->fmt) : fx_min(&s->fmt);
        bool any = false;
        if (g == 0) continue;
        for (int i = 0; i < sc->n_nodes && !any; i++) any = !sc->pinned[i] && s->pos[i][k] == want;
        if (!any) return false;
    }
    return true;
}

static void run_case(const hard_case *c, int frames_override, bool soak, result *r)
{
    scene *sc = &r->sc;
    runner fx, dbl;
    double (*pf)[3], (*pd)[3], (*vf)[3], (*vd)[3], (*creep_ref)[3] = NULL;
    fx_t (*last)[3], (*creep_raw)[3] = NULL;
    double scale, ref_f, ref_d, ke, sum2 = 0, span;
    long samples = 0;
    bool ground_ok = true;
    clock_t t0 = clock();

    r->frames = frames_override > 0 ? frames_override : soak ? c->soak_frames : c->test_frames;
    r->substeps_scene = r->substeps_used = sc->substeps;
    {
        char err[600];
        r->rtl = hw_check(sc, err, sizeof err) == NULL;
    }
    if (c->checks & C_BOUND) { /* the scene as written: the bound says it diverges; it must */
        stab_bound b = stab_compute(sc, 0);
        r->bound_diverged_at = first_divergence(sc, 600, &r->bound_stretch);
        if (b.index < 1) fail(r, "the scene as written is meant to cross the bound, but its index is %.3g", b.index);
        else if (r->bound_diverged_at == 0 && r->bound_stretch < 50)
            fail(r, "the bound (index %.3g) says the scene as written is unstable, but 600 frames stayed bounded (max stretch %.3g %%)", b.index,
                 r->bound_stretch);
    }
    if (c->auto_substeps) {
        int s = stab_auto_substeps(sc, SCENE_MAX_SUBSTEPS);
        if (s == 0) {
            fail(r, "--auto-substeps found no substep count");
            return;
        }
        stab_set_substeps(sc, s);
        r->substeps_used = s;
    }
    scale = stats_length_scale(sc);
    span = ldexp(1.0, sc->fmt.width - sc->fmt.frac); /* the format's whole range, in units */

    pf = calloc((size_t)sc->n_nodes, sizeof *pf);
    pd = calloc((size_t)sc->n_nodes, sizeof *pd);
    vf = calloc((size_t)sc->n_nodes, sizeof *vf);
    vd = calloc((size_t)sc->n_nodes, sizeof *vd);
    last = calloc((size_t)sc->n_nodes, sizeof *last);
    if (c->checks & C_CREEP) {
        creep_ref = calloc((size_t)sc->n_nodes, sizeof *creep_ref);
        creep_raw = calloc((size_t)sc->n_nodes, sizeof *creep_raw);
    }
    if (!pf || !pd || !vf || !vd || !last || ((c->checks & C_CREEP) && (!creep_ref || !creep_raw)) || !runner_init(&fx, sc, NUMBER_FIXED, &sc->fmt) ||
        !runner_init(&dbl, sc, NUMBER_DOUBLE, NULL)) {
        fail(r, "out of memory");
        return;
    }
    memset(&r->fx, 0, sizeof r->fx);
    memset(&r->dbl, 0, sizeof r->dbl);
    r->fx.ground_gap = r->dbl.ground_gap = INFINITY;

    runner_positions(&fx, pf);
    runner_positions(&dbl, pd);
    runner_velocities(&fx, vf);
    runner_velocities(&dbl, vd);
    ref_f = stats_lowest(sc, pf);
    ref_d = stats_lowest(sc, pd);
    r->fx.e0 = r->fx.e_ref = r->fx.e_final = stats_energy(sc, pf, vf, ref_f, &ke);
    r->fx.e_scale = ke;
    r->fx.e_max = -INFINITY;
    r->dbl.e0 = r->dbl.e_ref = r->dbl.e_final = stats_energy(sc, pd, vd, ref_d, &ke);
    r->dbl.e_scale = ke;
    r->dbl.e_max = -INFINITY;
    memcpy(last, fx.fx.pos, (size_t)sc->n_nodes * sizeof *last);

    for (int f = 1; f <= r->frames; f++) {
        bool fixed_grab = sc->en_mouse && sc->mouse == MOUSE_GRAB && fx.fx.grabbed >= 0;
        runner_frame(&fx);
        runner_frame(&dbl);
        fixed_grab = fixed_grab || (sc->en_mouse && sc->mouse == MOUSE_GRAB && fx.fx.grabbed >= 0);
        runner_positions(&fx, pf);
        runner_positions(&dbl, pd);
        runner_velocities(&fx, vf);
        runner_velocities(&dbl, vd);

        /* double: no NaN, no infinity */
        for (int i = 0; i < sc->n_nodes && !r->dbl.first_nonfinite; i++)
            for (int k = 0; k < 3; k++)
                if (!isfinite(pd[i][k]) || !isfinite(vd[i][k])) {
                    r->dbl.first_nonfinite = f;
                    fail(r, "double: node %d is not finite at frame %d", i, f);
                    break;
                }
        /* fixed: inside the format, and no wrap-around: no node jumps by half the format's span or
           more in one frame (a wrap moves it by the whole span). While a node is grabbed the pointer
           itself may cross the range, so grab frames are exempt. */
        for (int i = 0; i < sc->n_nodes; i++)
            for (int k = 0; k < sc->dim; k++) {
                fx_t v = fx.fx.pos[i][k];
                double jump = fabs((double)v - (double)last[i][k]) * ldexp(1.0, -sc->fmt.frac) / span;
                if (v != last[i][k]) r->fx.last_move = f;
                if (v > fx_max(&sc->fmt) || v < fx_min(&sc->fmt))
                    fail(r, "fixed: node %d axis %d outside the format at frame %d", i, k, f);
                if (!fixed_grab && jump > r->fx.max_jump) r->fx.max_jump = jump;
                if (!fixed_grab && jump >= 0.5)
                    fail(r, "fixed: node %d axis %d jumped %.4g (%.0f %% of the span) at frame %d: wrap-around", i, k,
                         fx_to_double(&sc->fmt, v) - fx_to_double(&sc->fmt, last[i][k]), 100 * jump, f);
                last[i][k] = v;
            }

        /* stretch */
        {
            double sf = stats_max_stretch(sc, pf), sd = stats_max_stretch(sc, pd);
            if (f >= c->stretch_from) {
                if (sf > r->fx.max_stretch) r->fx.max_stretch = sf;
                if (sd > r->dbl.max_stretch || !isfinite(sd)) r->dbl.max_stretch = sd;
                if ((c->checks & C_STRETCH) && !(sf <= c->stretch_limit))
                    fail(r, "fixed: stretch %.4g %% > %.4g %% at frame %d", sf, c->stretch_limit, f);
                if ((c->checks & C_STRETCH) && !(sd <= c->stretch_limit))
                    fail(r, "double: stretch %.4g %% > %.4g %% at frame %d", sd, c->stretch_limit, f);
            }
            r->fx.final_stretch = sf;
            r->dbl.final_stretch = sd;
        }

        /* energy: no growth without input */
        {
            double ef = stats_energy(sc, pf, vf, ref_f, &ke);
            if (ke > r->fx.e_scale) r->fx.e_scale = ke;
            if (f <= c->energy_from) r->fx.e_ref = fmax(r->fx.e_ref, ef);
            else if (ef > r->fx.e_max) r->fx.e_max = ef;
            r->fx.e_final = ef;
            double ed = stats_energy(sc, pd, vd, ref_d, &ke);
            if (ke > r->dbl.e_scale) r->dbl.e_scale = ke;
            if (f <= c->energy_from) r->dbl.e_ref = isfinite(ed) ? fmax(r->dbl.e_ref, ed) : ed;
            else if (ed > r->dbl.e_max || !isfinite(ed)) r->dbl.e_max = ed;
            r->dbl.e_final = ed;
        }

        /* ground */
        if (sc->en_ground) {
            int ax = sc->ground_axis;
            for (int i = 0; i < sc->n_nodes; i++) {
                if (sc->pinned[i]) continue;
                double gf = sc->ground_sign * (fx_to_double(&sc->fmt, fx.fx.pos[i][ax] - fx.fx.ground)) / scale;
                double gd = sc->ground_sign * (dbl.dbl.pos[i][ax] - dbl.dbl.ground) / scale;
                if (gf < r->fx.ground_gap) r->fx.ground_gap = gf;
                if (gd < r->dbl.ground_gap) r->dbl.ground_gap = gd;
                if ((c->checks & C_GROUND) && ground_ok && (gf < 0 || gd < -1e-12)) {
                    ground_ok = false;
                    fail(r, "node %d below the ground at frame %d (fixed %.3g, double %.3g rest lengths)", i, f, gf, gd);
                }
            }
        }

        /* the walls of the range */
        if ((c->checks & C_WALL) && !r->fx.wall_frame && at_wall(&fx.fx)) r->fx.wall_frame = f;

        /* creep: positions at creep_from */
        if ((c->checks & C_CREEP) && f == c->creep_from) {
            memcpy(creep_raw, fx.fx.pos, (size_t)sc->n_nodes * sizeof *creep_raw);
            memcpy(creep_ref, pd, (size_t)sc->n_nodes * sizeof *creep_ref);
        }
        if ((c->checks & C_CREEP) && f > c->creep_from) /* the widest excursion from the frame-creep_from positions */
            for (int i = 0; i < sc->n_nodes; i++)
                for (int k = 0; k < sc->dim; k++) {
                    double d = fabs((double)fx.fx.pos[i][k] - (double)creep_raw[i][k]);
                    if (d > r->fx.creep) r->fx.creep = d;
                    d = fabs(pd[i][k] - creep_ref[i][k]) / scale;
                    if (d > r->dbl.creep) r->dbl.creep = d;
                }

        /* fixed against double */
        for (int i = 0; i < sc->n_nodes && (!c->agree_frames || f <= c->agree_frames); i++) {
            double e2 = 0;
            for (int k = 0; k < 3; k++) e2 += (pf[i][k] - pd[i][k]) * (pf[i][k] - pd[i][k]);
            sum2 += e2;
            samples++;
            if (!(sqrt(e2) / scale <= r->max_err)) r->max_err = sqrt(e2) / scale;
        }

    }
    r->seconds = (double)(clock() - t0) / CLOCKS_PER_SEC;
    r->rms = samples ? sqrt(sum2 / samples) / scale : 0;
    r->fx.skipped = runner_skipped(&fx);
    r->dbl.skipped = runner_skipped(&dbl);

    /* whole-run criteria */
    r->fx.e_scale = energy_scale(sc, r->fx.e0, r->fx.e_scale);
    r->dbl.e_scale = energy_scale(sc, r->dbl.e0, r->dbl.e_scale);
    r->fx.growth = (r->fx.e_max - r->fx.e_ref) / r->fx.e_scale;
    r->dbl.growth = (r->dbl.e_max - r->dbl.e_ref) / r->dbl.e_scale;
    if (c->checks & C_ENERGY) {
        if (!(r->fx.growth <= c->energy_tol))
            fail(r, "fixed: energy grew to %.6g from %.6g (%.3g of the scale %.4g, limit %.3g)", r->fx.e_max, r->fx.e_ref, r->fx.growth, r->fx.e_scale,
                 c->energy_tol);
        if (!(r->dbl.growth <= c->energy_tol))
            fail(r, "double: energy grew to %.6g from %.6g (%.3g of the scale %.4g, limit %.3g)", r->dbl.e_max, r->dbl.e_ref, r->dbl.growth,
                 r->dbl.e_scale, c->energy_tol);
    }
    if ((c->checks & C_RECOVER) && !(r->fx.final_stretch <= c->recover_limit && r->dbl.final_stretch <= c->recover_limit))
        fail(r, "the rope did not recover: final stretch fixed %.4g %%, double %.4g %% (limit %.4g %%)", r->fx.final_stretch, r->dbl.final_stretch,
             c->recover_limit);
    if ((c->checks & C_SKIPPED) && !(r->fx.skipped > 0 && r->dbl.skipped > 0))
        fail(r, "no zero length occurred (skipped: fixed %ld, double %ld)", r->fx.skipped, r->dbl.skipped);
    if ((c->checks & C_AGREE) && !(r->rms <= c->agree_rms))
        fail(r, "fixed and double differ by %.4g rest lengths RMS (limit %.3g)", r->rms, c->agree_rms);
    if ((c->checks & C_WALL) && !r->fx.wall_frame) fail(r, "fixed: the rope never reached the limits of the range");
    if ((c->checks & C_WALL) && r->fx.wall_frame && !at_wall(&fx.fx))
        fail(r, "fixed: the rope left the limits of the range after frame %d", r->fx.wall_frame);
    if (c->checks & C_CREEP) {
        if (r->frames <= c->creep_from) fail(r, "creep: the run is not longer than frame %d", c->creep_from);
        else if (!(r->fx.creep <= c->creep_lsb))
            fail(r, "fixed: the resting rope moved %.0f LSB away from its frame-%d position by frame %d (limit %.0f; it last moved at frame %d)",
                 r->fx.creep, c->creep_from, r->frames, c->creep_lsb, r->fx.last_move);
    }

    runner_free(&fx);
    runner_free(&dbl);
    free(pf);
    free(pd);
    free(vf);
    free(vd);
    free(last);
    free(creep_ref);
    free(creep_raw);
}

/* ---- Euler against Verlet on reference 002's rope ---- */

typedef struct {
    int frames;
    double growth[2][2];   /* [euler, verlet][fixed, double]: max (E - E0) / scale */
    int nonfinite[2];      /* double: first non-finite frame, [euler, verlet] */
    bool pass;
    char why[256];
} euler_result;

static bool euler_vs_verlet(int frames, const char *series_path, euler_result *er)
{
    static const char *const names[2] = {"ref002_euler", "ref002_verlet_springs"};
    scene sc[2];
    runner run[2][2];
    double (*p)[3], (*v)[3], ref[2][2], e0[2][2], scale[2][2], ke;
    FILE *out = NULL;
    memset(er, 0, sizeof *er);
    er->frames = frames;
    er->pass = true;
    for (int s = 0; s < 2; s++)
        if (!load_case(names[s], &sc[s])) return false;
    p = calloc((size_t)sc[0].n_nodes, sizeof *p);
    v = calloc((size_t)sc[0].n_nodes, sizeof *v);
    if (!p || !v) return false;
    if (series_path && !(out = fopen(series_path, "w"))) {
        fprintf(stderr, "stability: cannot write %s\n", series_path);
        return false;
    }
    if (out) fprintf(out, "frame,euler_fixed,euler_double,verlet_fixed,verlet_double\n");
    for (int s = 0; s < 2; s++)
        for (int k = 0; k < 2; k++) {
            runner_init(&run[s][k], &sc[s], (number_kind)k, &sc[s].fmt);
            runner_positions(&run[s][k], p);
            runner_velocities(&run[s][k], v);
            ref[s][k] = stats_lowest(&sc[s], p);
            e0[s][k] = stats_energy(&sc[s], p, v, ref[s][k], &ke);
            scale[s][k] = energy_scale(&sc[s], e0[s][k], ke);
            er->growth[s][k] = 0;
        }
    for (int f = 1; f <= frames; f++) {
        if (out) fprintf(out, "%d", f);
        for (int s = 0; s < 2; s++)
            for (int k = 0; k < 2; k++) {
                double e, g;
                runner_frame(&run[s][k]);
                runner_positions(&run[s][k], p);
                runner_velocities(&run[s][k], v);
                e = stats_energy(&sc[s], p, v, ref[s][k], &ke);
                g = (e - e0[s][k]) / scale[s][k];
                if (!isfinite(g)) {
                    if (k == NUMBER_DOUBLE && !er->nonfinite[s]) er->nonfinite[s] = f;
                    g = INFINITY;
                }
                if (g > er->growth[s][k]) er->growth[s][k] = g;
                if (out) fprintf(out, ",%.9g", e - e0[s][k]);
            }
        if (out) fputc('\n', out);
    }
    if (out) fclose(out);
    /* Euler: energy grows by more than a thousand times the rope's energy scale, in both formats */
    for (int k = 0; k < 2; k++)
        if (!(er->growth[0][k] > 1000)) {
            er->pass = false;
            snprintf(er->why, sizeof er->why, "%s: explicit Euler's energy grew only %.3g times the scale", k ? "double" : "fixed", er->growth[0][k]);
        }
    /* Verlet: never above the start by more than 0.1 % of the scale */
    for (int k = 0; k < 2; k++)
        if (!(er->growth[1][k] <= 0.001)) {
            er->pass = false;
            snprintf(er->why, sizeof er->why, "%s: Verlet's energy grew %.3g of the scale", k ? "double" : "fixed", er->growth[1][k]);
        }
    for (int s = 0; s < 2; s++) {
        for (int k = 0; k < 2; k++) runner_free(&run[s][k]);
        scene_free(&sc[s]);
    }
    free(p);
    free(v);
    return true;
}

/* ---- output ---- */

static void json_figures(FILE *j, const char *key, const figures *fg, bool fixed)
{
    fprintf(j, "    \"%s\": {\"max_stretch_pct\": %.6g, \"final_stretch_pct\": %.6g, \"energy0\": %.9g, \"energy_max\": %.9g, "
               "\"energy_final\": %.9g, \"energy_scale\": %.9g, \"energy_growth\": %.6g, \"skipped\": %ld, \"energy_ref\": %.9g",
            key, fg->max_stretch, fg->final_stretch, fg->e0, fg->e_max, fg->e_final, fg->e_scale, fg->growth, fg->skipped, fg->e_ref);
    if (fixed) fprintf(j, ", \"max_jump_span\": %.6g, \"wall_frame\": %d, \"last_move\": %d", fg->max_jump, fg->wall_frame, fg->last_move);
    else fprintf(j, ", \"first_nonfinite\": %d", fg->first_nonfinite);
    fprintf(j, ", \"creep\": %.6g, \"ground_gap\": %.6g}", fg->creep, isfinite(fg->ground_gap) ? fg->ground_gap : 0.0);
}

static void print_result(const result *r)
{
    char fmtname[32];
    snprintf(fmtname, sizeof fmtname, "Q%d.%d,", r->sc.fmt.width - r->sc.fmt.frac, r->sc.fmt.frac);
    char efx[32] = "not checked", edbl[32] = "not checked";
    if (r->c->checks & C_ENERGY) {
        snprintf(efx, sizeof efx, "%+.3g", r->fx.growth);
        snprintf(edbl, sizeof edbl, "%+.3g", r->dbl.growth);
    }
    printf("%s %s: %d frames (%s substeps %d%s); fixed: stretch max %.4g %% final %.4g %%, energy growth %s, largest jump %.3g of the span; "
           "double: stretch max %.4g %%, energy growth %s; %.1f s\n",
           r->pass ? "PASS" : "FAIL", r->c->name, r->frames, fmtname, r->substeps_used,
           r->substeps_used != r->substeps_scene ? " (auto)" : "", r->fx.max_stretch, r->fx.final_stretch, efx, r->fx.max_jump,
           r->dbl.max_stretch, edbl, r->seconds);
    if (!r->pass) printf("     %s: %s\n", r->c->name, r->why);
    fflush(stdout);
}

static const char *usage = "usage: stability [--soak] [--frames N] [--only NAME] [--json FILE] [--series FILE] [--list]\n"
                           "Run the hard cases (sim/scenes/hard_*.scene) in fixed point and double and check their criteria;\n"
                           "one PASS/FAIL line each. --soak runs 10^6 frames of each; --frames N overrides both.\n";

int main(int argc, char **argv)
{
    bool soak = false, list = false;
    int frames = 0, failed = 0, ran = 0;
    const char *only = NULL, *json = NULL, *series = NULL;
    FILE *j = NULL;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        bool more = i + 1 < argc;
        if (!strcmp(a, "--soak")) soak = true;
        else if (!strcmp(a, "--list")) list = true;
        else if (!strcmp(a, "--frames") && more) frames = atoi(argv[++i]);
        else if (!strcmp(a, "--only") && more) only = argv[++i];
        else if (!strcmp(a, "--json") && more) json = argv[++i];
        else if (!strcmp(a, "--series") && more) series = argv[++i];
        else {
            fprintf(stderr, "stability: bad argument '%s'\n%s", a, usage);
            return 2;
        }
    }
    if (list) {
        for (int c = 0; c < N_CASES; c++) printf("%s\n", cases[c].name);
        printf("euler_vs_verlet\n");
        return 0;
    }
    if (json && !(j = fopen(json, "w"))) {
        fprintf(stderr, "stability: cannot write %s\n", json);
        return 1;
    }
    if (j) fprintf(j, "{\n  \"mode\": \"%s\",\n  \"cases\": [\n", soak ? "soak" : "test");
    for (int c = 0; c < N_CASES; c++) {
        result r;
        if (only && strcmp(only, cases[c].name)) continue;
        memset(&r, 0, sizeof r);
        r.c = &cases[c];
        r.pass = true;
        if (!load_case(cases[c].name, &r.sc)) return 2;
        run_case(&cases[c], frames, soak, &r);
        print_result(&r);
        failed += !r.pass;
        if (j) {
            fprintf(j, "%s  {\"name\": \"%s\", \"proves\": \"%s\", \"pass\": %s, \"why\": \"%s\", \"frames\": %d, \"nodes\": %d, "
                       "\"format\": \"Q%d.%d\", \"substeps_scene\": %d, \"substeps\": %d, \"iterations\": %d, \"rtl_subset\": %s, "
                       "\"rms_rest\": %.6g, \"max_err_rest\": %.6g, \"seconds\": %.3f, \"bound_diverged_at\": %d, \"bound_stretch\": %.6g, "
                       "\"energy_checked\": %s,\n",
                    ran ? ",\n" : "", r.c->name, r.c->proves, r.pass ? "true" : "false", r.pass ? "" : r.why, r.frames, r.sc.n_nodes,
                    r.sc.fmt.width - r.sc.fmt.frac, r.sc.fmt.frac, r.substeps_scene, r.substeps_used, r.sc.iterations, r.rtl ? "true" : "false",
                    r.rms, r.max_err, r.seconds, r.bound_diverged_at, r.bound_stretch, r.c->checks & C_ENERGY ? "true" : "false");
            json_figures(j, "fixed", &r.fx, true);
            fprintf(j, ",\n");
            json_figures(j, "double", &r.dbl, false);
            fprintf(j, "}");
        }
        ran++;
        scene_free(&r.sc);
    }
    if (j) fprintf(j, "\n  ]");
    if (!only || !strcmp(only, "euler_vs_verlet")) {
        euler_result er;
        if (!euler_vs_verlet(300, series, &er)) return 2;
        printf("%s euler_vs_verlet: reference 002's rope, %d frames: Euler's energy grew %.3g (fixed) and %.3g (double) times the "
               "scale%s; Verlet's %.3g and %.3g\n",
               er.pass ? "PASS" : "FAIL", er.frames, er.growth[0][0], er.growth[0][1],
               er.nonfinite[0] ? " (double non-finite)" : "", er.growth[1][0], er.growth[1][1]);
        if (!er.pass) printf("     euler_vs_verlet: %s\n", er.why);
        failed += !er.pass;
        ran++;
        if (j)
            fprintf(j, ",\n  \"euler_vs_verlet\": {\"pass\": %s, \"frames\": %d, \"euler_growth_fixed\": %.6g, \"euler_growth_double\": %.6g, "
                       "\"euler_nonfinite_double\": %d, \"verlet_growth_fixed\": %.6g, \"verlet_growth_double\": %.6g}",
                    er.pass ? "true" : "false", er.frames, isfinite(er.growth[0][0]) ? er.growth[0][0] : 1e308,
                    isfinite(er.growth[0][1]) ? er.growth[0][1] : 1e308, er.nonfinite[0], er.growth[1][0], er.growth[1][1]);
    }
    if (j) {
        fprintf(j, "\n}\n");
        fclose(j);
    }
    if (ran == 0) {
        fprintf(stderr, "stability: no case named '%s' (see --list)\n", only);
        return 2;
    }
    return failed ? 1 : 0;
}
