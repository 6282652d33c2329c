/*
 * hwgen.h - a scene as the hardware sees it: parameters, register writes, the mouse
 * script and the expected positions, all computed by the fixed-point engine's own
 * initialisation so that the RTL and the model start from the same words.
 */
#ifndef STRAND_HWGEN_H
#define STRAND_HWGEN_H

#include <stdint.h>

#include "scene.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The RTL build a scene needs. */
typedef struct {
    int w, f, m, k, sqrt_bits, div_bits, iter, substeps;
    bool en_gravity, en_damping, en_mouse, en_constraints, en_springs, en_ground;
    int ground_axis;   /* 0 x, 1 y */
    bool ground_above; /* nodes stay at or above the boundary (the scene's normal is +axis) */
    int rule; /* 0 centred (chain_sequencer), 1 pairwise (pair_sequencer) */
    int dim;    /* 2 or 3 */
    bool graph; /* a graph body: edge memories (e_rods, e_springs entries), nodes loaded one by one */
    int e_rods, e_springs;
    bool grab;  /* the mouse's grab form (EN_MOUSE with GRAB) */
    int uw, iw, cw; /* derived widths, as strand_top computes them */
} hw_params;

typedef struct {
    int addr;
    uint32_t data; /* W-bit word */
} hw_write;

/* Can the RTL run this scene? NULL, or "file:line: message" in err. */
const char *hw_check(const scene *sc, char *err, size_t len);
void hw_params_of(const scene *sc, hw_params *hp);
/* The register writes that set up a scene (constants, pins, then CMD init); returns the count. */
int hw_setup_writes(const scene *sc, const sim_fx *s, hw_write *out, int max);
/* A W-bit word of a fixed-point value. */
uint32_t hw_word(const fx_format *fmt, fx_t v);
/* A {unit, node} address of a node index. */
uint32_t hw_node_addr(const hw_params *hp, int node);
/* Cycles per frame (step to frame_done, back to back), docs/architecture.md. */
long hw_cycles_per_frame(const hw_params *hp);

/*
 * Write DIR/params.vh, DIR/config.hex, DIR/mouse.hex and DIR/expected.hex for
 * `frames` frames. Returns false with a message in err.
 */
bool hw_export(const scene *sc, const char *dir, int frames, char *err, size_t len);

#ifdef __cplusplus
}
#endif

#endif
