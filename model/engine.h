/*
 * engine.h - run a scene in either number type and measure it.
 *
 * A runner hides which engine (sim_fx or sim_dbl) runs; statistics are computed in
 * double from the positions either engine reports, so the two are measured alike.
 */
#ifndef STRAND_ENGINE_H
#define STRAND_ENGINE_H

#include "scene.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    number_kind kind;
    const scene *sc;
    sim_fx fx;
    sim_dbl dbl;
} runner;

bool runner_init(runner *r, const scene *sc, number_kind kind, const fx_format *fmt);
void runner_free(runner *r);
void runner_frame(runner *r);
/* Positions and velocities (units per second) in double. */
void runner_positions(const runner *r, double (*out)[3]);
void runner_velocities(const runner *r, double (*out)[3]);
long runner_skipped(const runner *r);
/* projection = previous: corrections made along the current direction instead */
long runner_fallbacks(const runner *r);

/* Largest |l - rest| / rest over the constraint and spring edges, in percent (0 without edges). */
double stats_max_stretch(const scene *sc, double (*pos)[3]);
/* The same split by sign: the largest (len - rest) / rest of any edge (*longer) and the
   largest (rest - len) / rest (*shorter), percent, each >= 0. */
void stats_strain(const scene *sc, double (*pos)[3], double *longer, double *shorter);
/* Kinetic + gravitational + spring energy of the free nodes. Heights are measured from ref_height. */
double stats_energy(const scene *sc, double (*pos)[3], double (*vel)[3], double ref_height, double *kinetic);
/* Height of the lowest free node along -gravity (the energy's zero), 0 without gravity. */
double stats_lowest(const scene *sc, double (*pos)[3]);
/* A length scale for errors: the mean rest length of the edges, else the chain spacing, else 1. */
double stats_length_scale(const scene *sc);
/* An energy change as % of the larger of the starting energy and the largest kinetic energy
   (a body that starts at rest at its lowest has energy 0: its swing sets the scale). */
double stats_drift_pct(double energy0, double energy, double ke_max);

typedef struct {
    int frames;
    double max_stretch;   /* percent: the largest |len - rest| / rest of frames 1..frames */
    double max_longer;    /* the largest (len - rest) / rest (a stretch), percent, same frames */
    double max_shorter;   /* the largest (rest - len) / rest (a compression), percent */
    int longer_frame, shorter_frame; /* the frames where they were reached */
    double initial_stretch; /* the scene as written (frame 0), percent */
    double final_stretch; /* percent, at the last frame */
    double energy0, energy; /* at the start and the end */
    double drift;         /* energy - energy0 */
    double drift_pct;     /* drift as % of the largest of energy0 and the peak kinetic energy */
    double ke_max;
    bool finite;          /* no NaN or infinity appeared */
    int first_nonfinite;  /* frame where one first appeared (0: none) */
    long skipped;
    long fallbacks;
} run_stats;

/* Callback after each frame (frame = frames completed, 1-based); return false to stop. */
typedef bool (*frame_hook)(void *user, const runner *r, int frame, double (*pos)[3]);

/* Run `frames` frames from reset, collecting statistics. */
bool run_scene(const scene *sc, number_kind kind, const fx_format *fmt, int frames, frame_hook hook, void *user, run_stats *st);

#ifdef __cplusplus
}
#endif

#endif
