/*
 * sim.h - the frame engine's state and per-node functions, in two number types.
 *
 * One algorithm (engine_body.h) is compiled twice: sim_fx runs Strand's fixed-point
 * arithmetic (fixed.h) and is bit-exact with the RTL at every frame end; sim_dbl runs
 * the same steps in double and is the reference that fixed-point error is measured
 * against. The per-node functions are public so that the cycle model can call
 * exactly the code the frame engine runs.
 */
#ifndef STRAND_SIM_H
#define STRAND_SIM_H

#include "fixed.h"
#include "scene.h"

#ifdef __cplusplus
extern "C" {
#endif

#define STRAND_SIM_FIELDS(NUM)                                                                          \
    const scene *sc;                                                                                    \
    fx_format fmt; /* the format (fixed only) */                                                        \
    int n, dim;                                                                                         \
    NUM (*pos)[3];                                                                                      \
    NUM (*prev)[3]; /* Verlet: previous position */                                                     \
    NUM (*acc)[3];  /* spring pass: position change per substep^2 (Verlet) or acceleration (Euler) */ \
    NUM (*vel)[3];  /* Euler only */                                                                    \
    NUM *rest;      /* per edge */                                                                      \
    NUM dist;       /* the chain's rest length: the centred rule's 'dist' */                            \
    NUM impulse;    /* mouse impulse 'a' */                                                             \
    NUM box[3];     /* mouse in-touch half-widths minX, minY, minZ */                                   \
    NUM ks, kd;     /* spring constants scaled to the integrator (see engine_body.h) */                 \
    NUM friction;   /* ground: previous position pulled toward current by this fraction (1-u) */       \
    NUM ground;     /* ground boundary: level + sign * radius */                                        \
    NUM h;          /* substep length (Euler) */                                                        \
    STRAND_EFFECT_SIM_FIELDS(NUM) /* the effects table's constants (scripts/gen_effects.py) */          \
    NUM mouse[3];   /* mouse position sampled at the frame start */                                     \
    bool mouse_down;                                                                                    \
    int grabbed; /* node following the pointer, or -1 */                                                \
    int frame;   /* frames completed */                                                                 \
    long skipped; /* corrections skipped for a zero length */                                          \
    long fallbacks; /* projection = previous: corrections made along the current direction instead */

typedef struct sim_fx {
    STRAND_SIM_FIELDS(fx_t)
} sim_fx;

typedef struct sim_dbl {
    STRAND_SIM_FIELDS(double)
} sim_dbl;

#define STRAND_SIM_API(SIM, P)                                                                           \
    /* Allocate and set the initial state (reset). fmt is ignored by the double engine. */              \
    bool P##init(SIM *s, const scene *sc, const fx_format *fmt);                                         \
    void P##free(SIM *s);                                                                                \
    /* Run one frame: sample the mouse, then the scene's substeps. */                                   \
    void P##frame(SIM *s);                                                                               \
    /* The steps of a frame, in order, for the cycle model. */                                          \
    void P##begin_frame(SIM *s);     /* sample the mouse; grab or release a node */                     \
    void P##grab_update(SIM *s);     /* grab or release a node for the sampled pointer */              \
    void P##spring_edge(SIM *s, int e);  /* accumulate one spring's force on its ends */                \
    bool P##verlet_node(SIM *s, int i);  /* Verlet step of one node (or follow the pointer); false if pinned */ \
    void P##mouse_node(SIM *s, int i);   /* mouse impulse on one node, after its Verlet step */         \
    bool P##centred_node(SIM *s, int i); /* centred chain constraint on node i; true if it was written */ \
    void P##pair_edge(SIM *s, int e);    /* pairwise constraint on one rod or strut */                  \
    bool P##ground_node(SIM *s, int i);  /* ground collision with friction; true if the node was written */                           \
    void P##substep(SIM *s);                                                                             \
    bool P##node_fixed(const SIM *s, int i); /* pinned or grabbed: constraints do not move it */

STRAND_SIM_API(sim_fx, sim_fx_)
STRAND_SIM_API(sim_dbl, sim_dbl_)

#ifdef __cplusplus
}
#endif

#endif
