/* hwgen.c - export a scene for the RTL: parameters, setup writes, mouse, expected positions. */
#define _POSIX_C_SOURCE 200809L
#include "hwgen.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cycle.h"
#include "strand_regs.h"

static const char *reject(const scene *sc, const char *section, char *err, size_t len, const char *what)
{
    snprintf(err, len, "%s:%d: the RTL does not run %s yet", sc->path, scene_section_line(sc, section), what);
    return err;
}

const char *hw_check(const scene *sc, char *err, size_t len)
{
    if (sc->integrator != INTEGRATOR_VERLET) return reject(sc, "time", err, len, "explicit Euler (a C-model-only contrast)");
    hw_params hp;
    hw_params_of(sc, &hp);
    char why[256];
    const char *bad;
    STRAND_PARAMS_CHECK(&hp, why, sizeof why, bad);
    if (bad) { /* a build strand_core refuses (the table of scripts/gen_params.py) */
        snprintf(err, len, "%s:%d: the RTL does not build this scene: %s", sc->path,
                 scene_section_line(sc, sc->body == BODY_GRAPH ? "graph" : "chain"), bad);
        return err;
    }
    if (sc->body == BODY_GRAPH) {
        if (sc->en_constraints && sc->rule != RULE_PAIRWISE)
            return reject(sc, "constraints", err, len, "the centred rule on a graph (it walks a chain)");
        return NULL; /* every node is loaded with its own position and previous position */
    }
    /* The init walk gives every free node the same previous-position offset (PREV_X/Y/Z),
       and a pinned one none: the frame engine's offsets, in the scene's format, must agree. */
    for (int k = 0; k < sc->dim; k++) {
        fx_t off = 0;
        bool seen = false;
        for (int i = 0; i < sc->n_nodes; i++) {
            fx_t o = fx_from_double(&sc->fmt, sc->prev[i][k] - sc->pos[i][k]);
            if (sc->pinned[i]) continue;
            if (seen && o != off)
                return reject(sc, "chain", err, len, "chains whose free nodes start with different velocities");
            off = o;
            seen = true;
        }
    }
    return NULL;
}

void hw_params_of(const scene *sc, hw_params *hp)
{
    memset(hp, 0, sizeof *hp);
    STRAND_PARAMS_DEFAULTS(hp);
    hp->debug = 1; /* a simulation build: the observation port for lockstep */
    hp->w = sc->fmt.width;
    hp->f = sc->fmt.frac;
    hp->dim = sc->dim;
    hp->graph = sc->body == BODY_GRAPH;
    if (hp->graph) { /* one unit holds every node: the edge passes dominate a graph's frame */
        hp->m = 1;
        hp->k = sc->n_nodes;
        hp->e_rods = hp->e_springs = 0;
        for (int e = 0; e < sc->n_edges; e++) {
            if (sc->edges[e].kind == EDGE_SPRING) hp->e_springs++;
            else hp->e_rods++;
        }
    } else {
        hp->m = sc->units;
        hp->k = sc->nodes_per_unit;
    }
    hp->sqrt_bits = sc->fmt.sqrt_bits;
    hp->div_bits = sc->fmt.div_bits;
    hp->mantissa = sc->fmt.mantissa;
    hp->iter = sc->iterations;
    hp->substeps = sc->substeps;
    hp->en_mouse = sc->en_mouse;
    hp->grab = sc->en_mouse && sc->mouse == MOUSE_GRAB;
    hp->en_constraints = sc->en_constraints && (!hp->graph || hp->e_rods > 0);
    hp->rule = sc->rule == RULE_PAIRWISE ? 1 : 0;
    hp->projection = hp->en_constraints && sc->projection == PROJECTION_PREVIOUS;
    hp->en_springs = sc->en_springs && (!hp->graph || hp->e_springs > 0);
    /* red/black: a chain's constraints stream through the pipelined pass, and so do its springs
       (their gathering keeps the link order); a graph's rods, already in colour order
       (scene_set_order), stream colour by colour (graph_stream), its springs take the serial pass */
    hp->arch = (hp->en_constraints || (hp->en_springs && !hp->graph)) && sc->order == ORDER_REDBLACK;
    hp->colours = hp->arch && hp->graph ? sc->n_colours : 1;
    hp->pipe_steps = hp->arch ? sc->pipe_steps : 1; /* the pipes' stages: nothing else reads it */
    if (hp->e_rods < 1) hp->e_rods = 1; /* the memories' sizes: at least one entry (unused in a chain) */
    if (hp->e_springs < 1) hp->e_springs = 1;
    hp->en_ground = sc->en_ground;
    hp->ground_axis = sc->en_ground ? sc->ground_axis : 1;
    hp->ground_above = !sc->en_ground || sc->ground_sign > 0;
    STRAND_EFFECT_HW_PARAMS(hp, sc) /* the effects table's switches */
    STRAND_PARAMS_DERIVE(hp);
}

uint32_t hw_word(const fx_format *fmt, fx_t v)
{
    return (uint32_t)v & (fmt->width == 32 ? 0xffffffffu : (1u << fmt->width) - 1);
}

uint32_t hw_node_addr(const hw_params *hp, int node)
{
    return (uint32_t)(node / hp->k) << hp->iw | (uint32_t)(node % hp->k);
}

int hw_setup_writes(const scene *sc, const sim_fx *s, hw_write *out, int max)
{
    const fx_format *f = &s->fmt;
    hw_params hp;
    int n = 0;
    hw_params_of(sc, &hp);
#define PUT(a, v)                                                                                                       \
    do {                                                                                                                \
        if (n < max) out[n] = (hw_write){(a), hw_word(f, (v))};                                                         \
        n++;                                                                                                            \
    } while (0)
    PUT(STRAND_REG_DIST, s->dist);
    PUT(STRAND_REG_IMPULSE, s->impulse);
    PUT(STRAND_REG_BOX_X, s->box[0]);
    PUT(STRAND_REG_BOX_Y, s->box[1]);
    PUT(STRAND_REG_KS, s->ks);
    PUT(STRAND_REG_KD, s->kd);
    PUT(STRAND_REG_GROUND, s->ground);
    PUT(STRAND_REG_FRICTION, s->friction);
    if (hp.dim == 3) PUT(STRAND_REG_BOX_Z, s->box[2]);
    STRAND_EFFECT_PUTS /* the effects table's registers (0 for an effect the scene does not have) */
    for (int i = 0; i < sc->n_nodes; i++)
        if (sc->pinned[i]) PUT(STRAND_REG_PIN, (fx_t)hw_node_addr(&hp, i));
    if (hp.graph) {
        /* every node as the frame engine starts it, then the edges in the scene's order */
        static const int load[2][3] = {{STRAND_REG_LOAD_X, STRAND_REG_LOAD_Y, STRAND_REG_LOAD_Z},
                                       {STRAND_REG_LOAD_PX, STRAND_REG_LOAD_PY, STRAND_REG_LOAD_PZ}};
        for (int i = 0; i < sc->n_nodes; i++) {
            for (int k = 0; k < hp.dim; k++) {
                PUT(load[0][k], s->pos[i][k]);
                PUT(load[1][k], s->prev[i][k]);
            }
            PUT(STRAND_REG_NODE, (fx_t)hw_node_addr(&hp, i));
        }
        for (int e = 0; e < sc->n_edges; e++) {
            const scene_edge *ed = &sc->edges[e];
            uint32_t aw = (uint32_t)(hp.uw + hp.iw);
            PUT(STRAND_REG_EDGE_REST, s->rest[e]);
            /* graph_stream (ARCH): bit 2 AW + 1 marks a rod that ends its colour */
            bool colour_end = hp.arch && ed->kind != EDGE_SPRING &&
                              (e + 1 == sc->n_edges || sc->edges[e + 1].kind == EDGE_SPRING || sc->edges[e + 1].colour != ed->colour);
            PUT(STRAND_REG_EDGE, (fx_t)((uint32_t)colour_end << (2 * aw + 1) | (uint32_t)(ed->kind == EDGE_SPRING) << (2 * aw) |
                                        hw_node_addr(&hp, ed->b) << aw | hw_node_addr(&hp, ed->a)));
        }
    } else {
        static const int start[3] = {STRAND_REG_START_X, STRAND_REG_START_Y, STRAND_REG_START_Z};
        static const int stepr[3] = {STRAND_REG_STEP_X, STRAND_REG_STEP_Y, STRAND_REG_STEP_Z};
        static const int prev[3] = {STRAND_REG_PREV_X, STRAND_REG_PREV_Y, STRAND_REG_PREV_Z};
        for (int i = 0; i < sc->n_nodes; i++) /* the free nodes' offset (hw_check: they share it) */
            if (!sc->pinned[i]) {
                for (int k = 0; k < hp.dim; k++) PUT(prev[k], fx_from_double(f, sc->prev[i][k] - sc->pos[i][k]));
                break;
            }
        for (int k = 0; k < hp.dim; k++) {
            PUT(start[k], fx_from_double(f, sc->chain_start[k]));
            PUT(stepr[k], fx_from_double(f, sc->chain_step[k]));
        }
        PUT(STRAND_REG_CMD, 1);
    }
#undef PUT
    return n;
}

/* mkdir -p */
static bool make_dirs(const char *dir)
{
    char path[1024];
    snprintf(path, sizeof path, "%s", dir);
    for (char *q = path + 1; *q; q++)
        if (*q == '/') {
            *q = 0;
            if (mkdir(path, 0777) != 0 && errno != EEXIST) return false;
            *q = '/';
        }
    return mkdir(path, 0777) == 0 || errno == EEXIST;
}

static FILE *open_in(const char *dir, const char *name, char *err, size_t len)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (!f) snprintf(err, len, "cannot write %s: %s", path, strerror(errno));
    return f;
}

/* One step of the status signature (FNV-1a's prime), the same 32-bit arithmetic as tb/tb_top_frames.v. */
static uint32_t status_mix(uint32_t h, uint32_t v) { return (h ^ v) * 16777619u; }

/*
 * status.hex: what strand_core's status shows in every frame, from the cycle model (model/cycle.c)
 * driven as tb/tb_top_frames.v drives the RTL: reset for three edges, one setup write an edge, idle
 * until the setup ends, then per frame the mouse and one step edge, and edges until frame_done. Per
 * frame, counted over the cycles from the step edge to the one frame_done shows in (the bench's
 * cycle count): the cycles FV is high, the cycles FEC is high, the first cycle FEC is high (0 for
 * none), and a signature of {phase, fv, fec, busy, irq, frame_done, uidx, nidx, counter} in every
 * one of those cycles.
 */
static bool write_status(FILE *f, const scene *sc, const hw_params *hp, const hw_write *writes, int nw, int frames)
{
    cyc_model *c = malloc(sizeof *c);
    cyc_inputs in = {0};
    cyc_outputs *o = malloc(sizeof *o);
    bool ok = c && o && cyc_init(c, hp);
    if (!ok) {
        free(c);
        free(o);
        return false;
    }
    in.reset = true;
    for (int i = 0; i < 3; i++) cyc_edge(c, &in);
    in.reset = false;
    for (int i = 0; i < nw; i++) {
        in.cfg_we = true;
        in.cfg_addr = (uint32_t)writes[i].addr;
        in.cfg_data = writes[i].data;
        cyc_edge(c, &in);
    }
    in.cfg_we = false;
    do cyc_edge(c, &in);
    while (c->phase != PH_IDLE);
    for (int fr = 0; fr < frames && ok; fr++) {
        double m[3];
        bool down;
        uint32_t fv = 0, fec = 0, fec_first = 0, sig = 2166136261u;
        long cycles = 0, limit = 4 * hw_cycles_per_frame(hp);
        scene_mouse_at(sc, fr, m, &down);
        in.mouse_down = sc->en_mouse && down;
        in.mouse_x = hw_word(&sc->fmt, fx_from_double(&sc->fmt, m[0]));
        in.mouse_y = hw_word(&sc->fmt, fx_from_double(&sc->fmt, m[1]));
        in.mouse_z = hp->dim == 3 ? hw_word(&sc->fmt, fx_from_double(&sc->fmt, m[2])) : 0u;
        in.step = true;
        do {
            cyc_edge(c, &in);
            in.step = false;
            cycles++;
            cyc_get_outputs(c, o);
            fv += o->fv;
            fec += o->fec;
            if (o->fec && !fec_first) fec_first = (uint32_t)cycles;
            sig = status_mix(sig, (uint32_t)o->phase);
            sig = status_mix(sig, (uint32_t)o->fv << 4 | (uint32_t)o->fec << 3 | (uint32_t)o->busy << 2 |
                                      (uint32_t)o->irq << 1 | (uint32_t)o->frame_done);
            sig = status_mix(sig, o->uidx);
            sig = status_mix(sig, o->nidx);
            sig = status_mix(sig, o->counter);
        } while (!o->frame_done && cycles < limit);
        ok = o->frame_done && fprintf(f, "%08x %08x %08x %08x\n", (unsigned)fv, (unsigned)fec, (unsigned)fec_first, (unsigned)sig) > 0;
    }
    cyc_free(c);
    free(c);
    free(o);
    return ok;
}

bool hw_export(const scene *sc, const char *dir, int frames, char *err, size_t len)
{
    hw_params hp;
    sim_fx s;
    hw_write writes[65536];
    int nw;
    FILE *f;
    bool ok = true;

    if (hw_check(sc, err, len)) return false;
    if (!make_dirs(dir)) {
        snprintf(err, len, "cannot create %s: %s", dir, strerror(errno));
        return false;
    }
    hw_params_of(sc, &hp);
    if (!sim_fx_init(&s, sc, &sc->fmt)) {
        snprintf(err, len, "out of memory");
        return false;
    }
    nw = hw_setup_writes(sc, &s, writes, (int)(sizeof writes / sizeof *writes));
    if (nw > (int)(sizeof writes / sizeof *writes)) {
        snprintf(err, len, "%s:1: too many nodes, pins or edges for one setup (%d writes)", sc->path, nw);
        sim_fx_free(&s);
        return false;
    }

    if (!(f = open_in(dir, "params.vh", err, len))) ok = false;
    else {
        fprintf(f, "// Generated by 'strand hwgen %s': the RTL build and the test for this scene.\n", sc->path);
#define STRAND_DEFINE(NAME, name, sw, ...) fprintf(f, sw ? "`define STRAND_%s 1'b%d\n" : "`define STRAND_%s %d\n", #NAME, hp.name);
        STRAND_PARAMS(STRAND_DEFINE)
#undef STRAND_DEFINE
        fprintf(f, "`define STRAND_FRAMES %d\n`define STRAND_NCONFIG %d\n`define STRAND_CYCLES_PER_FRAME %ld\n", frames, nw,
                hw_cycles_per_frame(&hp));
        ok = fclose(f) == 0;
    }
    if (ok && (f = open_in(dir, "params.h", err, len))) { /* the same build, for the C++ harness */
        fprintf(f, "/* Generated by 'strand hwgen %s': the build params.vh describes. */\n", sc->path);
#define STRAND_DEFINE(NAME, name, ...) fprintf(f, "#define STRAND_%s %d\n", #NAME, hp.name);
        STRAND_PARAMS(STRAND_DEFINE)
#undef STRAND_DEFINE
        ok = fclose(f) == 0;
    } else ok = false;
    if (ok && (f = open_in(dir, "config.hex", err, len))) {
        for (int i = 0; i < nw; i++) fprintf(f, "%02x%08x\n", writes[i].addr, (unsigned)writes[i].data);
        ok = fclose(f) == 0;
    } else ok = false;
    if (ok && (f = open_in(dir, "mouse.hex", err, len))) { /* per frame: button, x, y, z */
        for (int fr = 0; fr < frames; fr++) {
            double m[3];
            bool down;
            scene_mouse_at(sc, fr, m, &down);
            fprintf(f, "%x %08x %08x %08x\n", sc->en_mouse && down, (unsigned)hw_word(&s.fmt, fx_from_double(&s.fmt, m[0])),
                    (unsigned)hw_word(&s.fmt, fx_from_double(&s.fmt, m[1])),
                    hp.dim == 3 ? (unsigned)hw_word(&s.fmt, fx_from_double(&s.fmt, m[2])) : 0u);
        }
        ok = fclose(f) == 0;
    } else ok = false;
    if (ok && (f = open_in(dir, "expected.hex", err, len))) { /* per frame, per node: x, y, z at the frame's end */
        for (int fr = 0; fr < frames; fr++) {
            sim_fx_frame(&s);
            for (int i = 0; i < sc->n_nodes; i++)
                fprintf(f, "%08x %08x %08x\n", (unsigned)hw_word(&s.fmt, s.pos[i][0]), (unsigned)hw_word(&s.fmt, s.pos[i][1]),
                        (unsigned)hw_word(&s.fmt, s.pos[i][2]));
        }
        ok = fclose(f) == 0;
    } else ok = false;
    if (ok && (f = open_in(dir, "status.hex", err, len))) { /* per frame: FV cycles, FEC cycles, first FEC, signature */
        bool done = write_status(f, sc, &hp, writes, nw, frames);
        ok = fclose(f) == 0 && done;
        if (!done) snprintf(err, len, "%s:1: the cycle model did not finish a frame (or out of memory)", sc->path);
    } else ok = false;
    sim_fx_free(&s);
    return ok;
}
