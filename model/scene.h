/*
 * scene.h - a scene: what to simulate and with which effects.
 *
 * Scenes are INI files parsed by libinih and validated completely before anything
 * runs; sim/scenes/README.md documents every key. Values are kept in double, as
 * written; each number format converts them (engine.c) and checks they fit.
 */
#ifndef STRAND_SCENE_H
#define STRAND_SCENE_H

#include <stdbool.h>
#include <stdio.h>

#include "fixed.h"
#include "strand_effects.h" /* the effects table's fields (scripts/gen_effects.py) */

#ifdef __cplusplus
extern "C" {
#endif

#define SCENE_MAX_NODES 65536
#define SCENE_MAX_EDGES 262144
#define SCENE_MAX_EVENTS 65536
#define SCENE_MAX_FRAMES 100000000
#define SCENE_MAX_SUBSTEPS 4096
#define SCENE_MAX_ITERATIONS 4096
#define SCENE_ERR_LEN 512
#define SCENE_MAX_KEYS 96 /* distinct keys a scene may give */

typedef enum { BODY_CHAIN, BODY_GRAPH } body_kind;
typedef enum { EDGE_ROD, EDGE_STRUT, EDGE_SPRING } edge_kind;
typedef enum { RULE_CENTRED, RULE_PAIRWISE } constraint_rule;
/* The order of a constraint pass: serial (node by node, link by link; each reads its
   just-updated neighbour) or redblack (chains: even nodes or links, then odd; graphs:
   the edges of a greedy edge colouring, colour by colour). Within a colour no two
   constraints share a node, so a pipeline may have a whole colour in flight. */
typedef enum { ORDER_SERIAL, ORDER_REDBLACK } constraint_order;
/* The direction a distance constraint corrects along: the current one (references 000-002:
   the node goes to the point at the rest length toward its neighbour as they are now) or
   the previous one (SHAKE: along the constraint's direction at the start of the substep,
   to where the length is the rest length; it keeps energy bounded). */
typedef enum { PROJECTION_CURRENT, PROJECTION_PREVIOUS } constraint_projection;
typedef enum { INTEGRATOR_VERLET, INTEGRATOR_EULER } integrator_kind;
typedef enum { MOUSE_IMPULSE, MOUSE_GRAB } mouse_mode;
typedef enum { NUMBER_FIXED, NUMBER_DOUBLE } number_kind;

typedef struct {
    int a, b;       /* node indices */
    edge_kind kind; /* rods and struts are distance constraints, springs are forces */
    double rest;    /* rest length */
    int src;        /* its index in the scene's own order (scene_set_order sorts the edges) */
    int colour;     /* redblack: its colour (constraint edges; 0 for springs and when serial) */
    int line;       /* the scene line that gives it (a graph's edge line, a chain's [chain] rest) */
} scene_edge;

typedef struct {
    int frame;      /* from this frame on (the mouse is sampled at each frame's start) */
    double pos[3];
    bool down;
} mouse_event;

typedef struct {
    char path[256];
    char name[64];
    int dim; /* 2 or 3 */
    bool y_down; /* pictures: y grows downward (screen coordinates, reference 000) */

    /* number format */
    number_kind number;
    fx_format fmt; /* used when number == NUMBER_FIXED (and by --format fixed) */

    /* time */
    double dt;  /* frame time */
    int frames; /* default run length */
    int substeps;
    int iterations; /* constraint iterations per substep */
    int pipe_steps; /* the pipelined root's and divider's iterations a stage ([format] pipe_steps;
                       timing only: hw_params.pipe_steps of a pipelined build) */
    integrator_kind integrator; /* ([time] damping: the effects table's, below) */

    /* body */
    body_kind body;
    int units, nodes_per_unit, n_nodes;
    double (*pos)[3];  /* initial positions */
    double (*prev)[3]; /* initial previous positions */
    bool *pinned;
    double mass;
    int n_edges;
    scene_edge *edges; /* chains get their neighbour edges here too */
    double chain_start[3], chain_step[3], chain_rest;

    /* effects: each off unless the scene names its section */
    bool en_mouse, en_constraints, en_springs, en_ground;
    STRAND_EFFECT_SCENE_FIELDS /* the effects table's (scripts/gen_effects.py) */
    mouse_mode mouse;
    double mouse_box[3];
    double mouse_impulse;
    int n_events;
    mouse_event *events;
    constraint_rule rule;
    constraint_order order;
    constraint_projection projection;
    int n_colours;  /* colours of the constraint edges (1 when serial or without edges) */
    double ks, kd;
    bool kd_per_step; /* damper acts on per-step velocity x - x- (reference 001) */
    int ground_axis;  /* 0, 1, 2 */
    int ground_sign;  /* +1: nodes stay at coordinate >= level + radius; -1: <= level - radius */
    double ground_level, ground_radius, ground_friction;

    int section_lines[9 + STRAND_EFFECT_SECTION_COUNT]; /* line of each section header (scene.c's nine and the table's), 0 if absent (scene_section_line) */
    struct {
        int section;
        char key[24];
        int line;
    } keys[SCENE_MAX_KEYS]; /* the line of each key given once (scene_key_line) */
    int n_keys;
} scene;

/* The scene's constants as the engines use them, before rounding to the number format:
   the per-step scalings are written here once (engine init, hwgen through it, and
   strand check's rounding warnings). */
typedef struct {
    double ks, kd;     /* Verlet: ks h^2/m and kd h/m (kd h^2/m per-step damper); Euler: /m */
    double impulse;    /* mouse impulse */
    double friction;   /* 1 - ground friction */
    double ground;     /* the ground boundary: level +- radius */
    double h;          /* the substep */
    STRAND_EFFECT_CONST_FIELDS /* the effects table's */
} scene_consts;
void scene_constants(const scene *sc, scene_consts *c);

/*
 * Parse and validate a scene file. On failure returns false and writes
 * "file:line: message" into err (SCENE_ERR_LEN bytes). The scene is freed on failure.
 */
bool scene_load(scene *sc, const char *path, char *err);
void scene_free(scene *sc);

/*
 * Write `out`: the scene file `in` with each of n_assign "SECTION.KEY=VALUE" set (a key's
 * line replaced, or added at the end of its section; a missing section added at the end),
 * comments and layout kept. The result must load (scene_load): else false, nothing written,
 * and in err the parser's message said of its source, "in:line: message" or
 * "'SECTION.KEY=VALUE': message" (scene_edit.c).
 */
bool scene_edit(const char *in, const char *out, int n_assign, const char *const *assign, char *err);

/*
 * Put the constraint edges (rods and struts) in the order a constraint pass takes them:
 * the scene's own order (serial), or colour by colour of a greedy edge colouring made in
 * the scene's order, each colour in the scene's order (redblack: a chain's links then
 * come even links first). Springs keep the scene's order. Returns the number of colours
 * (1 when serial), or -1 and a message without file or line in err (SCENE_ERR_LEN
 * bytes) when the colouring needs more than SCENE_MAX_COLOURS colours.
 */
#define SCENE_MAX_COLOURS 64
int scene_set_order(scene *sc, constraint_order order, char *err);

/* Substep length dt / substeps. */
static inline double scene_h(const scene *sc) { return sc->dt / sc->substeps; }

/* Nodes in the chain order/edge counts used by the stats. */
const char *scene_effects_string(const scene *sc, char *buf, size_t len);

/* Does every scene value fit the format? Returns NULL or a message naming the value. */
const char *scene_check_format(const scene *sc, const fx_format *fmt, char *buf, size_t len);

/* Line of a section's header ("springs", "ground", ...), or 1 if the scene has none. */
int scene_section_line(const scene *sc, const char *section);
/* The line of `key` in [section], else the section's header line, else 1. */
int scene_key_line(const scene *sc, const char *section, const char *key);

/* Mouse state at the start of a frame: the last event with event.frame <= frame. */
void scene_mouse_at(const scene *sc, int frame, double pos[3], bool *down);

#ifdef __cplusplus
}
#endif

#endif
