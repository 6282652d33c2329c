/*
 * stability_bound.h - the largest stable step of a scene's springs and dampers.
 *
 * Springs and dampers are integrated explicitly, so a step that is too long for the
 * stiffest spring mode makes the run diverge; position-based constraints, gravity, the
 * mouse and the ground have no such limit. docs/stability.md derives these bounds:
 *
 *  - The stiffest mode. Linearised, the springs couple the nodes through ks times the
 *    graph Laplacian of the spring edges (projected on each spring's direction). Its
 *    largest eigenvalue is at most 2 * D (Gershgorin: a node with D springs has D on the
 *    diagonal and D in the rest of its row), so omega <= sqrt(2 D ks / m). For one link
 *    (D = 1) that is the two-body mode sqrt(2 ks / m); for a chain (D = 2) it is
 *    2 sqrt(ks / m), the top of the monatomic chain's band. lambda = 2 D below.
 *  - Verlet, per mode: x+ = x + (1 - c)(x - x-) - a x with a = h^2 lambda ks / m (the
 *    spring) and c = d + b, b = h lambda kd / m (the damper; h^2 lambda kd / m when the
 *    damper acts on per-step velocity) and d the Verlet damping. Its characteristic
 *    polynomial z^2 - (2 - a - c) z + (1 - c) has both roots inside the unit circle
 *    (Jury) iff c < 2 and a + 2c < 4: the index a/4 + c/2 must be below 1. Without the
 *    damper that is h omega < 2; without the spring, h lambda kd / m < 2 - d.
 *  - Explicit Euler, per mode z = 1 + h mu with mu^2 + (lambda kd/m) mu + lambda ks/m = 0:
 *    an underdamped mode grows unless h < kd / ks, an overdamped one unless
 *    h lambda kd / m < 2. Undamped springs grow at any step.
 *
 * The index is nondecreasing in h, so the substeps that meet it are found by counting.
 * Header-only (static inline) so that the CLI and the tests share one definition.
 */
#ifndef STRAND_STABILITY_BOUND_H
#define STRAND_STABILITY_BOUND_H

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* --auto-substeps keeps this factor of room: the chosen h would still be stable if doubled. */
#define STAB_SAFETY 2.0

typedef struct {
    bool springs;        /* the scene has spring edges: a bound applies */
    int max_degree;      /* most springs at one node (D) */
    double lambda;       /* 2 D: bound on the Laplacian's largest eigenvalue */
    double h;            /* the substep the figures below are for */
    double omega;        /* sqrt(lambda ks / m), rad per unit time */
    double h_omega;      /* h omega: stable below 2 (Verlet, springs alone) */
    double h_kd_m;       /* h kd / m (per-step damper: h^2 kd / m): stable below (2 - d) / lambda */
    double index;        /* combined: stable below 1 */
    double h_max;        /* the largest stable substep (INFINITY without a limit, 0 if none is stable) */
} stab_bound;

/* The combined index at substep h (see the header comment). */
static inline double stab_index(const scene *sc, double lambda, double h)
{
    double m = sc->mass;
    double kd_eff = sc->kd_per_step ? sc->kd * h : sc->kd; /* per-step damper: kd h acts like a per-second one */
    if (!sc->en_springs || lambda <= 0) return 0;
    if (sc->integrator == INTEGRATOR_EULER) {
        double under = kd_eff > 0 ? h * sc->ks / kd_eff : (sc->ks > 0 ? INFINITY : 0);
        double over = h * lambda * kd_eff / m / 2.0;
        return under > over ? under : over;
    }
    {
        double a = h * h * lambda * sc->ks / m;
        double c = h * lambda * kd_eff / m + sc->damping;
        double i1 = a / 4.0 + c / 2.0;
        return i1;
    }
}

/* The bound of a scene at its own substep (or at h if h > 0). */
static inline stab_bound stab_compute(const scene *sc, double h)
{
    stab_bound b;
    int *deg;
    b.springs = false;
    b.max_degree = 0;
    b.h = h > 0 ? h : scene_h(sc);
    deg = sc->en_springs && sc->n_nodes > 0 ? (int *)calloc((size_t)sc->n_nodes, sizeof *deg) : NULL;
    if (deg) {
        for (int e = 0; e < sc->n_edges; e++) {
            if (sc->edges[e].kind != EDGE_SPRING) continue;
            b.springs = true;
            if (++deg[sc->edges[e].a] > b.max_degree) b.max_degree = deg[sc->edges[e].a];
            if (++deg[sc->edges[e].b] > b.max_degree) b.max_degree = deg[sc->edges[e].b];
        }
        free(deg);
    }
    b.lambda = 2.0 * b.max_degree;
    b.omega = sqrt(b.lambda * sc->ks / sc->mass);
    b.h_omega = b.h * b.omega;
    b.h_kd_m = (sc->kd_per_step ? b.h * b.h : b.h) * sc->kd / sc->mass;
    b.index = b.springs ? stab_index(sc, b.lambda, b.h) : 0;
    if (!b.springs || stab_index(sc, b.lambda, 1e300) < 1) {
        b.h_max = INFINITY;
    } else if (!(stab_index(sc, b.lambda, 0) < 1)) {
        b.h_max = 0; /* undamped springs under Euler, or d alone too large */
    } else {
        double lo = 0, hi = 1;
        while (stab_index(sc, b.lambda, hi) < 1) hi *= 2;
        for (int i = 0; i < 200; i++) {
            double mid = 0.5 * (lo + hi);
            if (stab_index(sc, b.lambda, mid) < 1) lo = mid;
            else hi = mid;
        }
        b.h_max = lo;
    }
    return b;
}

/*
 * The smallest substep count in 1..max_substeps whose h = dt / substeps would still be
 * stable at STAB_SAFETY * h; 0 if none is.
 */
static inline int stab_auto_substeps(const scene *sc, int max_substeps)
{
    stab_bound b = stab_compute(sc, 0);
    if (!b.springs) return 1;
    for (int s = 1; s <= max_substeps; s++)
        if (stab_index(sc, b.lambda, STAB_SAFETY * sc->dt / s) < 1) return s;
    return 0;
}

/*
 * Change a loaded scene's substeps. The initial motion (x - x-) is scaled with h so
 * that every node keeps its initial velocity.
 */
static inline void stab_set_substeps(scene *sc, int substeps)
{
    double ratio = (double)sc->substeps / substeps;
    for (int i = 0; i < sc->n_nodes; i++)
        for (int k = 0; k < 3; k++) sc->prev[i][k] = sc->pos[i][k] - (sc->pos[i][k] - sc->prev[i][k]) * ratio;
    sc->substeps = substeps;
}

#ifdef __cplusplus
}
#endif

#endif
