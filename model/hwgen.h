/*
 * hwgen.h - a scene as the hardware sees it: parameters, register writes, the mouse
 * script and the expected positions, all computed by the fixed-point engine's own
 * initialisation so that the RTL and the model start from the same words.
 */
#ifndef STRAND_HWGEN_H
#define STRAND_HWGEN_H

#include <stdint.h>

#include "hw_params.h"
#include "scene.h"
#include "sim.h"
#include "timing.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    int addr;
    uint32_t data; /* W-bit word */
} hw_write;

/* Can the RTL run this scene? NULL, or "file:line: message" in err. */
const char *hw_check(const scene *sc, char *err, size_t len);
/* The build a scene needs, for simulation (DEBUG = 1: the observation port). */
void hw_params_of(const scene *sc, hw_params *hp);
/* The register writes that set up a scene (constants, pins, then CMD init); returns the count. */
int hw_setup_writes(const scene *sc, const sim_fx *s, hw_write *out, int max);
/* A W-bit word of a fixed-point value. */
uint32_t hw_word(const fx_format *fmt, fx_t v);
/* A {unit, node} address of a node index. */
uint32_t hw_node_addr(const hw_params *hp, int node);

/*
 * Write DIR/params.vh, DIR/config.hex, DIR/mouse.hex, DIR/expected.hex (positions from
 * the frame engine) and DIR/status.hex (per frame: the FV and FEC cycles, the first FEC
 * cycle and a signature of the status in every cycle, from the cycle model) for
 * `frames` frames. Returns false with a message in err.
 */
bool hw_export(const scene *sc, const char *dir, int frames, char *err, size_t len);

#ifdef __cplusplus
}
#endif

#endif
