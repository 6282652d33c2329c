/* engine.c - runners and statistics over both engines. */
#include "engine.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

bool runner_init(runner *r, const scene *sc, number_kind kind, const fx_format *fmt)
{
    memset(r, 0, sizeof *r);
    r->kind = kind;
    r->sc = sc;
    if (kind == NUMBER_FIXED) return sim_fx_init(&r->fx, sc, fmt ? fmt : &sc->fmt);
    return sim_dbl_init(&r->dbl, sc, NULL);
}

void runner_free(runner *r)
{
    if (r->kind == NUMBER_FIXED) sim_fx_free(&r->fx);
    else sim_dbl_free(&r->dbl);
}

void runner_frame(runner *r)
{
    if (r->kind == NUMBER_FIXED) sim_fx_frame(&r->fx);
    else sim_dbl_frame(&r->dbl);
}

void runner_positions(const runner *r, double (*out)[3])
{
    for (int i = 0; i < r->sc->n_nodes; i++)
        for (int k = 0; k < 3; k++)
            out[i][k] = r->kind == NUMBER_FIXED ? fx_to_double(&r->fx.fmt, r->fx.pos[i][k]) : r->dbl.pos[i][k];
}

void runner_velocities(const runner *r, double (*out)[3])
{
    const scene *sc = r->sc;
    double h = scene_h(sc);
    for (int i = 0; i < sc->n_nodes; i++)
        for (int k = 0; k < 3; k++) {
            if (sc->integrator == INTEGRATOR_EULER)
                out[i][k] = r->kind == NUMBER_FIXED ? fx_to_double(&r->fx.fmt, r->fx.vel[i][k]) : r->dbl.vel[i][k];
            else if (r->kind == NUMBER_FIXED)
                out[i][k] = fx_to_double(&r->fx.fmt, r->fx.pos[i][k] - r->fx.prev[i][k]) / h;
            else
                out[i][k] = (r->dbl.pos[i][k] - r->dbl.prev[i][k]) / h;
        }
}

long runner_skipped(const runner *r) { return r->kind == NUMBER_FIXED ? r->fx.skipped : r->dbl.skipped; }
long runner_fallbacks(const runner *r) { return r->kind == NUMBER_FIXED ? r->fx.fallbacks : r->dbl.fallbacks; }

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double stats_max_stretch(const scene *sc, double (*pos)[3])
{
    double worst = 0;
    for (int e = 0; e < sc->n_edges; e++) {
        const scene_edge *ed = &sc->edges[e];
        double s = fabs(dist3(pos[ed->a], pos[ed->b]) - ed->rest) / ed->rest * 100.0;
        if (!(s <= worst)) worst = s; /* NaN propagates */
    }
    return worst;
}

void stats_strain(const scene *sc, double (*pos)[3], double *longer, double *shorter)
{
    *longer = *shorter = 0;
    for (int e = 0; e < sc->n_edges; e++) {
        const scene_edge *ed = &sc->edges[e];
        double s = (dist3(pos[ed->a], pos[ed->b]) - ed->rest) / ed->rest * 100.0;
        if (!(s <= *longer)) *longer = s;    /* NaN propagates */
        if (!(-s <= *shorter)) *shorter = -s;
    }
}

/* Keep the largest stretch and compression of the run, with their frames. */
static void note_strain(const scene *sc, double (*pos)[3], int f, run_stats *st)
{
    double longer, shorter;
    stats_strain(sc, pos, &longer, &shorter);
    if (f <= 1 || !(longer <= st->max_longer)) {
        st->max_longer = longer;
        st->longer_frame = f;
    }
    if (f <= 1 || !(shorter <= st->max_shorter)) {
        st->max_shorter = shorter;
        st->shorter_frame = f;
    }
}

static double gravity_norm(const scene *sc)
{
    return sc->en_gravity ? sqrt(sc->gravity[0] * sc->gravity[0] + sc->gravity[1] * sc->gravity[1] + sc->gravity[2] * sc->gravity[2]) : 0;
}

/* Height of a point along -g. */
static double height(const scene *sc, const double *p)
{
    double g = gravity_norm(sc);
    return g > 0 ? -(p[0] * sc->gravity[0] + p[1] * sc->gravity[1] + p[2] * sc->gravity[2]) / g : 0;
}

double stats_lowest(const scene *sc, double (*pos)[3])
{
    double low = 0;
    bool any = false;
    for (int i = 0; i < sc->n_nodes; i++) {
        if (sc->pinned[i]) continue;
        double hgt = height(sc, pos[i]);
        if (!any || hgt < low) low = hgt;
        any = true;
    }
    return low;
}

double stats_energy(const scene *sc, double (*pos)[3], double (*vel)[3], double ref_height, double *kinetic)
{
    double ke = 0, pe = 0, g = gravity_norm(sc);
    for (int i = 0; i < sc->n_nodes; i++) {
        if (sc->pinned[i]) continue;
        ke += 0.5 * sc->mass * (vel[i][0] * vel[i][0] + vel[i][1] * vel[i][1] + vel[i][2] * vel[i][2]);
        pe += sc->mass * g * (height(sc, pos[i]) - ref_height);
    }
    if (sc->en_springs)
        for (int e = 0; e < sc->n_edges; e++) {
            const scene_edge *ed = &sc->edges[e];
            if (ed->kind != EDGE_SPRING) continue;
            double x = dist3(pos[ed->a], pos[ed->b]) - ed->rest;
            pe += 0.5 * sc->ks * x * x;
        }
    if (kinetic) *kinetic = ke;
    return ke + pe;
}

double stats_drift_pct(double energy0, double energy, double ke_max)
{
    double scale = fabs(energy0) > ke_max ? fabs(energy0) : ke_max;
    return scale > 0 ? 100.0 * (energy - energy0) / scale : 0;
}

double stats_length_scale(const scene *sc)
{
    double sum = 0;
    if (sc->n_edges) {
        for (int e = 0; e < sc->n_edges; e++) sum += sc->edges[e].rest;
        return sum / sc->n_edges;
    }
    return sc->chain_rest > 0 ? sc->chain_rest : 1.0;
}

bool run_scene(const scene *sc, number_kind kind, const fx_format *fmt, int frames, frame_hook hook, void *user, run_stats *st)
{
    runner r;
    double (*pos)[3] = calloc((size_t)sc->n_nodes, sizeof *pos);
    double (*vel)[3] = calloc((size_t)sc->n_nodes, sizeof *vel);
    double ref, ke;
    bool ok = true;

    memset(st, 0, sizeof *st);
    st->finite = true;
    if (!pos || !vel || !runner_init(&r, sc, kind, fmt)) {
        free(pos);
        free(vel);
        return false;
    }
    runner_positions(&r, pos);
    runner_velocities(&r, vel);
    ref = stats_lowest(sc, pos);
    st->energy0 = st->energy = stats_energy(sc, pos, vel, ref, &ke);
    st->ke_max = ke;
    /* The scene as written (frame 0) is kept apart: the run's figures start at frame 1, as
       `strand compare` and the lockstep harness count them (with no frame, frame 0's). */
    st->initial_stretch = st->max_stretch = st->final_stretch = stats_max_stretch(sc, pos);
    note_strain(sc, pos, 0, st);
    for (int f = 1; f <= frames; f++) {
        runner_frame(&r);
        runner_positions(&r, pos);
        runner_velocities(&r, vel);
        st->frames = f;
        double s = stats_max_stretch(sc, pos);
        if (f == 1 || !(s <= st->max_stretch)) st->max_stretch = s;
        note_strain(sc, pos, f, st);
        st->energy = stats_energy(sc, pos, vel, ref, &ke);
        if (ke > st->ke_max) st->ke_max = ke;
        st->final_stretch = s;
        if ((!isfinite(st->energy) || !isfinite(s)) && st->finite) {
            st->finite = false;
            st->first_nonfinite = f;
        }
        if (hook && !hook(user, &r, f, pos)) {
            ok = false;
            break;
        }
    }
    st->drift = st->energy - st->energy0;
    st->drift_pct = stats_drift_pct(st->energy0, st->energy, st->ke_max);
    st->skipped = runner_skipped(&r);
    st->fallbacks = runner_fallbacks(&r);
    runner_free(&r);
    free(pos);
    free(vel);
    return ok;
}
