/*
 * sweep.c - one point of the accuracy study (docs/accuracy.md, scripts/accuracy.py).
 *
 *   sweep SCENE [--check none|period|catenary|spring|energy|wind] [--frames N] [--reverse]
 *
 * Runs SCENE in fixed point (its [format]) and in double, frame by frame, and prints
 * one JSON object on stdout:
 *   - the error of fixed against double: RMS and largest node distance over every
 *     frame and node, in rest lengths (as `strand compare`);
 *   - the largest segment stretch of each over the run and at the last frame (%);
 *   - cycles per frame: the RTL's formula (hw_cycles_per_frame) for a scene the RTL
 *     builds (hw_check), else an estimate (see cycles_estimate below), labelled as such;
 *   - the C model's time per frame for each engine (microseconds);
 *   - the analytic check (--check), on both runs:
 *       period    pendulum: period from the zero crossings of the free node's offset
 *                 from the pin, against 2 pi sqrt(L/g);
 *       catenary  chain between two pins at one height: largest distance of a node from
 *                 the catenary of the same length and span, at the last frame, % of span;
 *       spring    spring pair: damped angular frequency from the zero crossings of the
 *                 stretch, decay rate from the peaks, against sqrt(w0^2 - g^2) and kd/m;
 *       energy    pendulum: turning-point height above the lowest point (the energy at
 *                 zero speed), last swings against the first, % drift;
 *       wind      a rope pinned at one end in a wind ([wind], no other force but gravity):
 *                 at rest every node carries the same load g + c w (drag on the wind's
 *                 speed), so the rope hangs straight along it; the angle of the line from
 *                 the pin to the last node from g, at the last frame, against the angle of
 *                 g + c w from g; the error: the line's angle from g + c w, as a % of the
 *                 latter's from g (a rope blown the wrong way is off by 200 %).
 * --reverse: then run the scene back as long (current and previous positions swapped,
 * swapped again at the end) and report how far each run lands from its start: Verlet is
 * time-reversible, so a free body returns bit for bit; a constraint mode departs by what
 * it does not undo ("back_fx"/"back_dbl": largest node distance in rest lengths, and for
 * fixed point in LSB).
 * Exit status: 0, or 2 for a bad scene or argument (message on stderr).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "engine.h"
#include "hwgen.h"
#include "scene.h"

#define SWEEP_PI 3.14159265358979323846

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/*
 * Cycles per frame for a scene the RTL does not build (explicit Euler; a chain whose free
 * nodes start at different velocities; hw_check says why), an estimate on the serial
 * datapath, as if the body were a graph: a rod costs one `toward` sequence (SQRT_BITS + DIV_BITS + 9 cycles)
 * plus 5, as pair_sequencer does for a chain's link; a spring
 * costs a root, one signed divide per axis and 8 cycles of multiply-adds. The
 * Verlet pass and the pass overheads are the chain's (K + 2 per substep, 2 per pass).
 */
static long cycles_estimate(const scene *sc)
{
    hw_params hp;
    long toward, rods = 0, springs = 0, pass, substep;
    hw_params_of(sc, &hp);
    toward = hp.sqrt_bits + hp.div_bits + 9;
    for (int e = 0; e < sc->n_edges; e++) {
        if (sc->edges[e].kind == EDGE_SPRING) springs++;
        else rods++;
    }
    pass = rods * (toward + 5);
    substep = hp.k + 2;
    if (sc->en_constraints) substep += (long)sc->iterations * pass;
    if (sc->en_springs) substep += 2 + springs * (hp.sqrt_bits + 1 + (long)sc->dim * (hp.div_bits + 1) + 8);
    return (long)sc->substeps * substep + 1;
}

/* ---- series helpers ---- */

/* Times of the sign changes of x (linear interpolation); returns the count. */
static int crossings(const double *x, int n, double dt, double *out)
{
    int c = 0;
    for (int i = 1; i < n; i++)
        if ((x[i - 1] < 0 && x[i] >= 0) || (x[i - 1] >= 0 && x[i] < 0)) {
            double f = x[i - 1] / (x[i - 1] - x[i]);
            out[c++] = (i - 1 + f) * dt;
        }
    return c;
}

/* Local maxima of y (3-point parabolic interpolation): times and values; returns the count. */
static int peaks(const double *y, int n, double dt, double *t, double *v)
{
    int c = 0;
    for (int i = 1; i + 1 < n; i++)
        if (y[i] > y[i - 1] && y[i] >= y[i + 1]) {
            double a = y[i - 1], b = y[i], d = y[i + 1];
            double den = a - 2 * b + d;
            double off = den != 0 ? 0.5 * (a - d) / den : 0;
            t[c] = (i + off) * dt;
            v[c] = b - 0.25 * (a - d) * off;
            c++;
        }
    return c;
}

/* ---- the catenary ---- */

typedef struct {
    double a, xm, ytop, half, span, length;
} catenary;

/* The catenary of `length` hanging between (x0, y) and (x1, y). */
static void catenary_solve(catenary *c, double x0, double x1, double y, double length)
{
    double s = fabs(x1 - x0), lo = 1e-6 * s, hi = 1e6 * s;
    c->span = s;
    c->length = length;
    c->xm = 0.5 * (x0 + x1);
    c->ytop = y;
    c->half = 0.5 * s;
    /* 2 a sinh(s / 2a) decreases in a toward s: bisect (in log a) */
    for (int i = 0; i < 200; i++) {
        double a = sqrt(lo * hi);
        double l = 2 * a * sinh(s / (2 * a));
        if (!isfinite(l) || l > length) lo = a;
        else hi = a;
    }
    c->a = sqrt(lo * hi);
}

static double catenary_y(const catenary *c, double x)
{
    return c->ytop + c->a * (cosh((x - c->xm) / c->a) - cosh(c->half / c->a));
}

/* Distance from p to the curve between the pins (dense search, then golden refinement). */
static double catenary_dist(const catenary *c, const double *p)
{
    const int n = 4000;
    double x0 = c->xm - c->half, best = INFINITY, bx = x0, step = 2 * c->half / n;
    for (int i = 0; i <= n; i++) {
        double x = x0 + i * step, dx = p[0] - x, dy = p[1] - catenary_y(c, x), d = dx * dx + dy * dy;
        if (d < best) best = d, bx = x;
    }
    {
        double lo = fmax(x0, bx - step), hi = fmin(x0 + 2 * c->half, bx + step);
        const double g = 0.6180339887498949;
        for (int i = 0; i < 80; i++) {
            double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            double d1 = (p[0] - m1) * (p[0] - m1) + (p[1] - catenary_y(c, m1)) * (p[1] - catenary_y(c, m1));
            double d2 = (p[0] - m2) * (p[0] - m2) + (p[1] - catenary_y(c, m2)) * (p[1] - catenary_y(c, m2));
            if (d1 < d2) hi = m2;
            else lo = m1;
            best = fmin(best, fmin(d1, d2));
        }
    }
    return sqrt(best);
}

/* ---- one run's trace for the checks ---- */

typedef struct {
    double *a; /* per frame: the check's signal */
    double (*last)[3]; /* positions at the last frame */
    double last_speed; /* largest node speed at the last frame */
} trace;

static void json_num(const char *key, double v, int last)
{
    if (isfinite(v)) printf("\"%s\": %.9g%s", key, v, last ? "" : ", ");
    else printf("\"%s\": null%s", key, last ? "" : ", ");
}

/* The analytic check of one run; prints "name": {...}. */
static void check_json(const char *name, const char *check, const scene *sc, const trace *tr, int frames)
{
    double dt = sc->dt;
    int n = frames;
    double *t = malloc(sizeof(double) * (size_t)(n + 1)), *v = malloc(sizeof(double) * (size_t)(n + 1));
    printf("\"%s\": {", name);
    if (!strcmp(check, "period")) {
        double g = fabs(sc->gravity[1]), l = sc->chain_rest;
        double t0 = 2 * SWEEP_PI * sqrt(l / g);
        int c = crossings(tr->a, n, dt, t);
        double period = c >= 3 ? 2 * (t[c - 1] - t[0]) / (c - 1) : NAN;
        double th = atan2(fabs(sc->pos[1][0] - sc->pos[0][0]), fabs(sc->pos[1][1] - sc->pos[0][1]));
        json_num("period", period, 0);
        json_num("reference", t0, 0);
        json_num("amplitude_deg", th * 180 / SWEEP_PI, 0);
        json_num("reference_finite_amplitude", t0 * (1 + th * th / 16 + 11 * pow(th, 4) / 3072), 0);
        json_num("crossings", c, 0);
        json_num("error_pct", 100 * (period - t0) / t0, 1);
    } else if (!strcmp(check, "catenary")) {
        int first = -1, lastp = -1;
        double worst = 0;
        for (int i = 0; i < sc->n_nodes; i++)
            if (sc->pinned[i]) {
                if (first < 0) first = i;
                lastp = i;
            }
        catenary c;
        catenary_solve(&c, sc->pos[first][0], sc->pos[lastp][0], sc->pos[first][1], (lastp - first) * sc->chain_rest);
        for (int i = first; i <= lastp; i++) {
            double d = catenary_dist(&c, tr->last[i]);
            if (!(d <= worst)) worst = d;
        }
        {
            double ymin = INFINITY;
            for (int i = first; i <= lastp; i++) ymin = fmin(ymin, tr->last[i][1]);
            json_num("sag", c.ytop - ymin, 0);
        }
        json_num("sag_reference", c.a * (cosh(c.half / c.a) - 1), 0);
        json_num("a", c.a, 0);
        json_num("span", c.span, 0);
        json_num("final_speed", tr->last_speed, 0);
        json_num("error_pct", 100 * worst / c.span, 1);
    } else if (!strcmp(check, "spring")) {
        double mu = sc->mass / 2, w0 = sqrt(sc->ks / mu), gam = sc->kd / (2 * mu);
        double wd_ref = sqrt(w0 * w0 - gam * gam);
        int c = crossings(tr->a, n, dt, t);
        double wd = c >= 3 ? SWEEP_PI * (c - 1) / (t[c - 1] - t[0]) : NAN;
        /* decay: least squares of ln|peak| over the peaks of |x| */
        double *ab = malloc(sizeof(double) * (size_t)n), *pt = malloc(sizeof(double) * (size_t)n),
               *pv = malloc(sizeof(double) * (size_t)n);
        for (int i = 0; i < n; i++) ab[i] = fabs(tr->a[i]);
        int np = peaks(ab, n, dt, pt, pv);
        double sx = 0, sy = 0, sxx = 0, sxy = 0, rate = NAN;
        int m = 0;
        for (int i = 0; i < np; i++)
            if (pv[i] > 0) {
                double y = log(pv[i]);
                sx += pt[i], sy += y, sxx += pt[i] * pt[i], sxy += pt[i] * y;
                m++;
            }
        if (m >= 3) rate = -(m * sxy - sx * sy) / (m * sxx - sx * sx);
        json_num("omega_d", wd, 0);
        json_num("omega_d_reference", wd_ref, 0);
        json_num("omega_0_reference", w0, 0);
        json_num("decay", rate, 0);
        json_num("decay_reference", gam, 0);
        json_num("decay_error_pct", 100 * (rate - gam) / gam, 0);
        json_num("error_pct", 100 * (wd - wd_ref) / wd_ref, 1);
        free(ab), free(pt), free(pv);
    } else if (!strcmp(check, "energy")) {
        /* tr->a: height of the free node above the lowest point of its circle */
        int np = peaks(tr->a, n, dt, t, v), k = np >= 8 ? 4 : np / 2;
        double first = 0, lastv = 0;
        for (int i = 0; i < k; i++) first += v[i], lastv += v[np - 1 - i];
        first /= k > 0 ? k : 1;
        lastv /= k > 0 ? k : 1;
        /* the decay rate of the swing's energy over the first 60 s: least squares of ln(peak) */
        {
            double sx = 0, sy = 0, sxx = 0, sxy = 0;
            int m = 0;
            for (int i = 0; i < np && t[i] <= 60.0; i++)
                if (v[i] > 0) {
                    sx += t[i], sy += log(v[i]), sxx += t[i] * t[i], sxy += t[i] * log(v[i]);
                    m++;
                }
            json_num("loss_rate_60s", m >= 3 ? -(m * sxy - sx * sy) / (m * sxx - sx * sx) : NAN, 0);
        }
        json_num("height_first", first, 0);
        json_num("height_last", lastv, 0);
        json_num("swings", np, 0);
        json_num("seconds", n * dt, 0);
        json_num("error_pct", k > 0 && first > 0 ? 100 * (lastv - first) / first : NAN, 1);
    } else if (!strcmp(check, "wind")) {
        int pin = 0, end = sc->n_nodes - 1;
        double load[3], rope[3], g2 = 0, l2 = 0, r2 = 0, gl = 0, gr = 0, lr = 0;
        for (int k = 0; k < 3; k++) {
            load[k] = sc->gravity[k] + sc->wind_drag * sc->wind_velocity[k];
            rope[k] = tr->last[end][k] - tr->last[pin][k];
            g2 += sc->gravity[k] * sc->gravity[k], l2 += load[k] * load[k], r2 += rope[k] * rope[k];
            gl += sc->gravity[k] * load[k], gr += sc->gravity[k] * rope[k], lr += load[k] * rope[k];
        }
        /* the rope's angle from g, the load's, and the rope's from the load (the error: a rope blown
           the wrong way hangs at the load's angle from g, but twice it from the load) */
        double ref = acos(fmin(1, gl / sqrt(g2 * l2))), got = acos(fmin(1, gr / sqrt(g2 * r2)));
        double off = acos(fmin(1, lr / sqrt(l2 * r2)));
        json_num("angle_deg", got * 180 / SWEEP_PI, 0);
        json_num("angle_reference_deg", ref * 180 / SWEEP_PI, 0);
        json_num("off_load_deg", off * 180 / SWEEP_PI, 0);
        json_num("final_speed", tr->last_speed, 0);
        json_num("error_pct", 100 * off / ref, 1);
    } else {
        printf("\"none\": true");
    }
    printf("}");
    free(t);
    free(v);
}

/* Time runs backward from here: swap the current and previous positions (Verlet). */
static void swap_time(runner *r)
{
    for (int i = 0; i < r->sc->n_nodes; i++)
        for (int k = 0; k < 3; k++) {
            if (r->kind == NUMBER_FIXED) {
                fx_t t = r->fx.pos[i][k];
                r->fx.pos[i][k] = r->fx.prev[i][k];
                r->fx.prev[i][k] = t;
            } else {
                double t = r->dbl.pos[i][k];
                r->dbl.pos[i][k] = r->dbl.prev[i][k];
                r->dbl.prev[i][k] = t;
            }
        }
}

/* Largest node distance between two position sets. */
static double largest_gap(int n, double (*a)[3], double (*b)[3])
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        double e2 = 0;
        for (int k = 0; k < 3; k++) e2 += (a[i][k] - b[i][k]) * (a[i][k] - b[i][k]);
        worst = fmax(worst, sqrt(e2));
    }
    return worst;
}

/* The check's per-frame signal. */
static double signal(const char *check, const scene *sc, double (*p)[3])
{
    if (!strcmp(check, "period")) return p[1][0] - p[0][0];
    if (!strcmp(check, "spring")) {
        double dx = p[1][0] - p[0][0], dy = p[1][1] - p[0][1], dz = p[1][2] - p[0][2];
        return sqrt(dx * dx + dy * dy + dz * dz) - sc->edges[0].rest;
    }
    if (!strcmp(check, "energy")) return p[1][1] - (p[0][1] - sc->chain_rest);
    return 0;
}

int main(int argc, char **argv)
{
    const char *path = NULL, *check = "none";
    int frames = -1;
    bool reverse = false;
    char err[SCENE_ERR_LEN];
    scene sc;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--check") && i + 1 < argc) check = argv[++i];
        else if (!strcmp(argv[i], "--frames") && i + 1 < argc) frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--reverse")) reverse = true;
        else if (argv[i][0] != '-' && !path) path = argv[i];
        else {
            fprintf(stderr, "usage: sweep SCENE [--check none|period|catenary|spring|energy|wind] [--frames N] [--reverse]\n");
            return 2;
        }
    }
    if (!path || (strcmp(check, "none") && strcmp(check, "period") && strcmp(check, "catenary") && strcmp(check, "spring") &&
                  strcmp(check, "energy") && strcmp(check, "wind"))) {
        fprintf(stderr, "usage: sweep SCENE [--check none|period|catenary|spring|energy|wind] [--frames N] [--reverse]\n");
        return 2;
    }
    if (!scene_load(&sc, path, err)) {
        fprintf(stderr, "%s\n", err);
        return 2;
    }
    {
        char buf[160];
        const char *msg = scene_check_format(&sc, &sc.fmt, buf, sizeof buf);
        if (msg) {
            fprintf(stderr, "%s:1: %s\n", sc.path, msg);
            return 2;
        }
    }
    if (frames < 0) frames = sc.frames;

    int n = sc.n_nodes;
    runner fx, dbl;
    double (*pf)[3] = calloc((size_t)n, sizeof *pf), (*pd)[3] = calloc((size_t)n, sizeof *pd);
    double (*vf)[3] = calloc((size_t)n, sizeof *vf), (*vd)[3] = calloc((size_t)n, sizeof *vd);
    trace tf = {calloc((size_t)frames + 1, sizeof(double)), calloc((size_t)n, sizeof(double[3])), 0};
    trace td = {calloc((size_t)frames + 1, sizeof(double)), calloc((size_t)n, sizeof(double[3])), 0};
    double sum2 = 0, worst = 0, smax_f = 0, smax_d = 0, sfin_f = 0, sfin_d = 0, tfx = 0, tdbl = 0, scale;
    long samples = 0;
    int finite = 1;
    if (!pf || !pd || !vf || !vd || !tf.a || !td.a || !tf.last || !td.last || !runner_init(&fx, &sc, NUMBER_FIXED, &sc.fmt) ||
        !runner_init(&dbl, &sc, NUMBER_DOUBLE, NULL)) {
        fprintf(stderr, "sweep: out of memory\n");
        return 1;
    }
    scale = stats_length_scale(&sc);
    double (*start_f)[3] = calloc((size_t)n, sizeof *start_f), (*start_d)[3] = calloc((size_t)n, sizeof *start_d);
    if (!start_f || !start_d) {
        fprintf(stderr, "sweep: out of memory\n");
        return 1;
    }
    runner_positions(&fx, start_f);
    runner_positions(&dbl, start_d);
    /* energy (engine.c stats_energy, as strand run reports it): its change over the run as % of
       the larger of the starting energy and the largest kinetic energy */
    double ref_f = stats_lowest(&sc, start_f), ref_d = stats_lowest(&sc, start_d), ke, ke_f, ke_d, e0_f, e0_d, e_f, e_d;
    runner_velocities(&fx, vf);
    runner_velocities(&dbl, vd);
    e0_f = e_f = stats_energy(&sc, start_f, vf, ref_f, &ke_f);
    e0_d = e_d = stats_energy(&sc, start_d, vd, ref_d, &ke_d);
    for (int f = 0; f < frames; f++) {
        double t0 = now();
        runner_frame(&fx);
        double t1 = now();
        runner_frame(&dbl);
        double t2 = now();
        tfx += t1 - t0;
        tdbl += t2 - t1;
        runner_positions(&fx, pf);
        runner_positions(&dbl, pd);
        for (int i = 0; i < n; i++) {
            double e2 = 0;
            for (int k = 0; k < 3; k++) e2 += (pf[i][k] - pd[i][k]) * (pf[i][k] - pd[i][k]);
            sum2 += e2;
            samples++;
            if (!(sqrt(e2) <= worst)) worst = sqrt(e2);
        }
        sfin_f = stats_max_stretch(&sc, pf);
        sfin_d = stats_max_stretch(&sc, pd);
        if (!(sfin_f <= smax_f)) smax_f = sfin_f;
        if (!(sfin_d <= smax_d)) smax_d = sfin_d;
        if (!isfinite(sfin_f) || !isfinite(sfin_d)) finite = 0;
        tf.a[f] = signal(check, &sc, pf);
        td.a[f] = signal(check, &sc, pd);
        runner_velocities(&fx, vf);
        runner_velocities(&dbl, vd);
        e_f = stats_energy(&sc, pf, vf, ref_f, &ke);
        if (ke > ke_f) ke_f = ke;
        e_d = stats_energy(&sc, pd, vd, ref_d, &ke);
        if (ke > ke_d) ke_d = ke;
    }
    memcpy(tf.last, pf, sizeof(double[3]) * (size_t)n);
    memcpy(td.last, pd, sizeof(double[3]) * (size_t)n);
    runner_velocities(&fx, vf);
    runner_velocities(&dbl, vd);
    for (int i = 0; i < n; i++) {
        tf.last_speed = fmax(tf.last_speed, sqrt(vf[i][0] * vf[i][0] + vf[i][1] * vf[i][1] + vf[i][2] * vf[i][2]));
        td.last_speed = fmax(td.last_speed, sqrt(vd[i][0] * vd[i][0] + vd[i][1] * vd[i][1] + vd[i][2] * vd[i][2]));
    }

    double back_f = NAN, back_d = NAN;
    if (reverse) {
        double (*bf)[3] = calloc((size_t)n, sizeof *bf), (*bd)[3] = calloc((size_t)n, sizeof *bd);
        if (!bf || !bd) {
            fprintf(stderr, "sweep: out of memory\n");
            return 1;
        }
        swap_time(&fx);
        swap_time(&dbl);
        for (int f = 0; f < frames; f++) {
            runner_frame(&fx);
            runner_frame(&dbl);
        }
        swap_time(&fx);
        swap_time(&dbl);
        runner_positions(&fx, bf);
        runner_positions(&dbl, bd);
        back_f = largest_gap(n, bf, start_f);
        back_d = largest_gap(n, bd, start_d);
        free(bf), free(bd);
    }
    {
        hw_params hp;
        char why[SCENE_ERR_LEN];
        bool rtl = hw_check(&sc, why, sizeof why) == NULL; /* the RTL builds it: its formula is checked every frame */
        double lsb = ldexp(1.0, -sc.fmt.frac);
        double h = scene_h(&sc);
        double gh2 = sc.en_gravity ? sqrt(sc.gravity[0] * sc.gravity[0] + sc.gravity[1] * sc.gravity[1] + sc.gravity[2] * sc.gravity[2]) * h * h : 0;
        hw_params_of(&sc, &hp);
        printf("{\"scene\": \"%s\", \"width\": %d, \"frac\": %d, \"sqrt_bits\": %d, \"div_bits\": %d, ", sc.name, sc.fmt.width,
               sc.fmt.frac, sc.fmt.sqrt_bits, sc.fmt.div_bits);
        printf("\"substeps\": %d, \"iterations\": %d, \"rule\": \"%s\", \"nodes\": %d, \"frames\": %d, ", sc.substeps, sc.iterations,
               !sc.en_constraints ? "none" : sc.rule == RULE_CENTRED ? "centred" : "pairwise", n, frames);
        printf("\"cycles\": %ld, \"cycles_kind\": \"%s\", ", rtl ? hw_cycles_per_frame(&hp) : cycles_estimate(&sc),
               rtl ? "rtl-formula" : "estimate");
        json_num("err_rms", samples ? sqrt(sum2 / samples) / scale : 0, 0);
        json_num("err_max", worst / scale, 0);
        json_num("stretch_max_fx", smax_f, 0);
        json_num("stretch_max_dbl", smax_d, 0);
        json_num("stretch_final_fx", sfin_f, 0);
        json_num("stretch_final_dbl", sfin_d, 0);
        json_num("us_per_frame_fx", 1e6 * tfx / frames, 0);
        json_num("us_per_frame_dbl", 1e6 * tdbl / frames, 0);
        json_num("gravity_step_lsb", gh2 / lsb, 0);
        json_num("drift_pct_fx", stats_drift_pct(e0_f, e_f, ke_f), 0);
        json_num("drift_pct_dbl", stats_drift_pct(e0_d, e_d, ke_d), 0);
        printf("\"finite\": %s, \"skipped_fx\": %ld, \"fallbacks_fx\": %ld, ", finite ? "true" : "false", runner_skipped(&fx),
               runner_fallbacks(&fx));
        if (reverse) {
            json_num("back_fx", back_f / scale, 0);
            json_num("back_fx_lsb", back_f / lsb, 0);
            json_num("back_dbl", back_d / scale, 0);
        }
        check_json("check_fx", check, &sc, &tf, frames);
        printf(", ");
        check_json("check_dbl", check, &sc, &td, frames);
        printf(", \"check\": \"%s\"}\n", check);
    }
    runner_free(&fx);
    runner_free(&dbl);
    free(start_f), free(start_d);
    free(pf), free(pd), free(vf), free(vd), free(tf.a), free(td.a), free(tf.last), free(td.last);
    scene_free(&sc);
    return 0;
}
