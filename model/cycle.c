/*
 * cycle.c - strand_core, edge by edge. Each block below names the RTL register or
 * always block it mirrors. Everything in one edge is computed from the state
 * before the edge (as nonblocking assignments do), in this order: port B samples
 * the storage (read before write), the storage writes of this edge happen (the
 * frame engine's per-node functions), then the control registers update.
 */
#include "cycle.h"

#include <stdlib.h>
#include <string.h>

#include "hwgen.h"
#include "strand_regs.h"

static fx_t from_word(const fx_format *fmt, uint32_t w)
{
    uint32_t mask = fmt->width == 32 ? 0xffffffffu : (1u << fmt->width) - 1;
    uint32_t sign = 1u << (fmt->width - 1);
    w &= mask;
    return (fx_t)(int32_t)((w ^ sign) - sign); /* sign-extend */
}

static uint32_t to_word(const fx_format *fmt, fx_t v) { return hw_word(fmt, v); }

/* the pipelined passes: a chain's (chain_stream, spring_stream) and a graph's rods (graph_stream) */
static bool chain_streams(const hw_params *hp) { return hp->arch && !hp->graph; }
static bool graph_streams(const hw_params *hp) { return hp->arch && hp->graph && hp->en_constraints; }

bool cyc_init(cyc_model *c, const hw_params *hp)
{
    int n = hp->m * hp->k;
    memset(c, 0, sizeof *c);
    if (hp->m > CYC_MAX_UNITS) return false;
    c->hp = *hp;
    c->hp.grab = hp->grab && hp->en_mouse; /* frame_ctrl: HAS_GRAB = EN_MOUSE && GRAB */
    /* A chain with the build's effects; every value 0, as after reset. */
    scene *sc = &c->sc;
    snprintf(sc->name, sizeof sc->name, "rtl");
    sc->dim = hp->dim;
    sc->number = NUMBER_FIXED;
    sc->fmt = (fx_format){hp->w, hp->f, hp->sqrt_bits, hp->div_bits, hp->mantissa};
    sc->dt = 1;
    sc->substeps = hp->substeps;
    sc->iterations = hp->iter;
    sc->integrator = INTEGRATOR_VERLET;
    sc->body = BODY_CHAIN;
    sc->units = hp->m;
    sc->nodes_per_unit = hp->k;
    sc->n_nodes = n;
    sc->mass = 1;
    sc->en_mouse = hp->en_mouse;
    sc->mouse = c->hp.grab ? MOUSE_GRAB : MOUSE_IMPULSE;
    sc->en_constraints = hp->en_constraints;
    sc->rule = hp->rule ? RULE_PAIRWISE : RULE_CENTRED;
    sc->projection = hp->projection ? PROJECTION_PREVIOUS : PROJECTION_CURRENT;
    sc->en_springs = hp->en_springs;
    sc->en_ground = hp->en_ground;
    sc->ground_axis = hp->ground_axis;
    sc->ground_sign = hp->ground_above ? 1 : -1;
    STRAND_EFFECT_SCENE_OF_HW(sc, hp) /* the effects table's */
    /* A graph's edge memories: rods, then springs, each filled by EDGE writes (reset: all 0). */
    if (hp->graph) {
        sc->n_edges = hp->e_rods + hp->e_springs;
        sc->edges = calloc((size_t)sc->n_edges, sizeof *sc->edges);
        if (!sc->edges) return false;
        for (int e = 0; e < sc->n_edges; e++) sc->edges[e].kind = e < hp->e_rods ? EDGE_ROD : EDGE_SPRING;
        c->spring0 = hp->e_rods;
    }
    /* The links the pair sequencers walk, as the scene reader lays a chain's edges out:
       rods (walked by the pairwise rule), then springs; every rest length comes from DIST. */
    else if (n > 1 && (hp->en_constraints || hp->en_springs)) {
        int links = n - 1, e = 0;
        sc->n_edges = links * ((hp->en_constraints ? 1 : 0) + (hp->en_springs ? 1 : 0));
        sc->edges = calloc((size_t)sc->n_edges, sizeof *sc->edges);
        if (!sc->edges) return false;
        if (hp->en_constraints)
            for (int i = 0; i < links; i++) sc->edges[e++] = (scene_edge){i, i + 1, EDGE_ROD, 0, 0, 0, 0};
        c->spring0 = e;
        if (hp->en_springs)
            for (int i = 0; i < links; i++) sc->edges[e++] = (scene_edge){i, i + 1, EDGE_SPRING, 0, 0, 0, 0};
    }
    sc->pos = calloc((size_t)n, sizeof *sc->pos);
    sc->prev = calloc((size_t)n, sizeof *sc->prev);
    sc->pinned = calloc((size_t)n, sizeof *sc->pinned);
    if (!sc->pos || !sc->prev || !sc->pinned || !sim_fx_init(&c->s, sc, &sc->fmt)) return false;
    c->lt = (int)hw_toward_latency(hp);
    c->lp = (int)hw_toward_pipe_latency(hp);
    if (hp->arch && !hp->graph) {
        c->st_period = (int)hw_stream_period(hp);
        c->st_last = (int)hw_stream_last(hp);
        for (int b = 0; b < 2; b++) {
            c->st_pend[b] = calloc((size_t)n, sizeof *c->st_pend[b]);
            c->st_pos[b] = calloc((size_t)n, sizeof *c->st_pos[b]);
            if (!c->st_pend[b] || !c->st_pos[b]) return false;
        }
        c->st_lag = hp->fuse ? (int)hw_fuse_lag() : 0;
        if (hp->fuse) {
            c->fz_write = calloc((size_t)n, sizeof *c->fz_write);
            c->fz_pos = calloc((size_t)n, sizeof *c->fz_pos);
            c->fz_prev = calloc((size_t)n, sizeof *c->fz_prev);
            c->fz_swap = calloc((size_t)n, sizeof *c->fz_swap);
            if (!c->fz_write || !c->fz_pos || !c->fz_prev || !c->fz_swap) return false;
        }
    }
    if (graph_streams(hp)) {
        c->gs_colour_end = calloc((size_t)hp->e_rods, sizeof *c->gs_colour_end);
        c->gs_ring = malloc((size_t)(c->lp + 1) * sizeof *c->gs_ring);
        if (!c->gs_colour_end || !c->gs_ring) return false;
        for (int i = 0; i <= c->lp; i++) c->gs_ring[i] = -1;
    }
    c->ls = (int)hw_spring_latency(hp);
    c->lsp = (int)hw_spring_pipe_latency(hp);
    return true;
}

void cyc_free(cyc_model *c)
{
    for (int b = 0; b < 2; b++) {
        free(c->st_pend[b]);
        free(c->st_pos[b]);
        c->st_pend[b] = NULL;
        c->st_pos[b] = NULL;
    }
    free(c->fz_write);
    free(c->fz_pos);
    free(c->fz_prev);
    free(c->fz_swap);
    c->fz_write = NULL;
    c->fz_pos = c->fz_prev = c->fz_swap = NULL;
    free(c->gs_colour_end);
    free(c->gs_ring);
    c->gs_colour_end = NULL;
    c->gs_ring = NULL;
    sim_fx_free(&c->s);
    scene_free(&c->sc);
}

uint32_t cyc_node_word(const cyc_model *c, int i, int axis) { return to_word(&c->s.fmt, c->s.pos[i][axis]); }

void cyc_get_outputs(const cyc_model *c, cyc_outputs *o)
{
    const fx_format *f = &c->s.fmt;
    int m = c->hp.m;
    /* every field below is written: no memset of the 256-lane arrays each cycle */
    o->frame_done = c->frame_done;
    o->busy = c->phase != PH_IDLE;
    o->irq = c->irq;
    o->rd_x = c->rd_u_q2 < (uint32_t)m ? to_word(f, c->bq_x[c->rd_u_q2]) : 0;
    o->rd_y = c->rd_u_q2 < (uint32_t)m ? to_word(f, c->bq_y[c->rd_u_q2]) : 0;
    o->rd_z = c->rd_u_q2 < (uint32_t)m ? to_word(f, c->bq_z[c->rd_u_q2]) : 0;
    o->phase = c->phase;
    o->fv = c->done;
    /* FEC: the pass's last node (centred), link (pairwise chain) or edge (graph) is done */
    const int fec_at = c->hp.graph ? c->hp.e_rods : m * c->hp.k - (c->hp.rule ? 1 : 0);
    o->fec = c->hp.en_constraints && (c->hp.rule ? c->pair.counter : c->counter) == fec_at;
    if (chain_streams(&c->hp) && c->hp.en_constraints) o->fec = c->st_counter == c->hp.k / 2 + 1; /* chain_stream: every slot issued */
    if (graph_streams(&c->hp)) o->fec = c->gs_counter == c->hp.e_rods; /* graph_stream: every edge of the pass read */
    /* strand_core shows the spring pass's walk in phase FORCE, else the constraint sequencer's */
    if (c->phase == PH_FORCE && chain_streams(&c->hp)) { /* spring_stream: 0, port A's address, the slots issued */
        int k = c->hp.k, t = c->sp_t;
        o->uidx = 0;
        o->nidx = !c->sp_running || t > k ? 0u : t == 0 ? (uint32_t)(k - 1) : (uint32_t)(t - 1);
        o->counter = (uint32_t)c->sp_counter;
    } else if (c->phase == PH_FORCE) {
        o->uidx = (uint32_t)c->force.uidx;
        o->nidx = (uint32_t)c->force.nidx;
        o->counter = (uint32_t)c->force.counter;
    } else if (graph_streams(&c->hp)) { /* graph_stream: the current edge's a, the edges read */
        o->uidx = (uint32_t)(c->gs_a / c->hp.k);
        o->nidx = (uint32_t)(c->gs_a % c->hp.k);
        o->counter = (uint32_t)c->gs_counter;
    } else if (c->hp.arch) { /* chain_stream: the colour, the pair read (t - 1 at t = 1 .. PJ), the slots issued */
        int pairs = (c->hp.k + 1) / 2, t = c->st_t;
        o->uidx = (uint32_t)c->st_colour;
        o->nidx = !c->st_running || t > pairs || t == 0 ? 0u : (uint32_t)(t - 1);
        o->counter = (uint32_t)c->st_counter;
    } else if (c->hp.rule) {
        o->uidx = (uint32_t)c->pair.uidx;
        o->nidx = (uint32_t)c->pair.nidx;
        o->counter = (uint32_t)c->pair.counter;
    } else {
        o->uidx = (uint32_t)c->uidx;
        o->nidx = (uint32_t)c->nidx;
        o->counter = (uint32_t)c->counter;
    }
    o->lanes = c->hp.wb;
    for (int u = 0; u < c->hp.wb; u++) {
        o->wb_valid[u] = c->wb_valid[u];
        o->wb_idx[u] = c->wb_idx[u];
        o->wb_x[u] = to_word(f, c->wb_x[u]);
        o->wb_y[u] = to_word(f, c->wb_y[u]);
        o->wb_z[u] = to_word(f, c->wb_z[u]);
    }
}

static void reset_all(cyc_model *c)
{
    int n = c->hp.m * c->hp.k;
    for (int i = 0; i < n; i++) {
        memset(c->s.pos[i], 0, sizeof c->s.pos[i]);
        memset(c->s.prev[i], 0, sizeof c->s.prev[i]);
        c->sc.pinned[i] = false;
    }
    for (int k = 0; k < 3; k++) c->s.box[k] = c->s.mouse[k] = 0;
    c->s.dist = c->s.impulse = 0;
    for (int e = 0; e < c->sc.n_edges; e++) c->s.rest[e] = 0;
    for (int i = 0; i < n; i++) memset(c->s.acc[i], 0, sizeof c->s.acc[i]);
    c->s.ks = c->s.kd = c->s.ground = c->s.friction = 0;
    STRAND_EFFECT_RESET(c->s)
    memset(c->prev_off, 0, sizeof c->prev_off);
    memset(c->init_prev, 0, sizeof c->init_prev);
    memset(c->init_ahead, 0, sizeof c->init_ahead);
    c->pin_pend = -1;
    c->ground_pass = false;
    memset(&c->pair, 0, sizeof c->pair);   /* PQ_IDLE, counters 0 */
    memset(&c->force, 0, sizeof c->force);
    c->s.mouse_down = false;
    c->s.grabbed = -1;
    c->scan_i = 0;
    c->phase = PH_IDLE;
    c->substep = 0;
    c->frame_done = false;
    c->irq = false;
    memset(c->mouse_q, 0, sizeof c->mouse_q);
    c->mouse_down_q = false;
    c->init_u = c->init_n = c->init_count = 0;
    memset(c->init_pos, 0, sizeof c->init_pos);
    memset(c->start, 0, sizeof c->start);
    memset(c->step, 0, sizeof c->step);
    memset(c->load, 0, sizeof c->load);
    c->edge_rest = 0;
    if (c->hp.graph) { /* the edge memories are emptied */
        for (int e = 0; e < c->sc.n_edges; e++) {
            c->sc.edges[e].a = c->sc.edges[e].b = 0;
            c->s.rest[e] = 0;
        }
        c->fill[0] = c->fill[1] = 0;
    }
    c->gs_state = GS_IDLE;
    c->gs_j = c->gs_iter = c->gs_drain = c->gs_counter = c->gs_a = 0;
    c->gs_issue = c->gs_done = c->gs_write_b = false;
    if (c->gs_colour_end) memset(c->gs_colour_end, 0, (size_t)c->hp.e_rods * sizeof *c->gs_colour_end);
    if (c->gs_ring)
        for (int i = 0; i <= c->lp; i++) c->gs_ring[i] = -1;
    c->running = c->done = false;
    c->vidx = 0;
    c->pass_a = c->pass_b = c->pass_c = c->pass_d = false;
    for (int u = 0; u < c->hp.m; u++) c->b_x[u] = c->b_y[u] = c->b_z[u] = c->bq_x[u] = c->bq_y[u] = c->bq_z[u] = 0;
    for (int l = 0; l < c->hp.wb; l++) {
        c->wb_valid[l] = false;
        c->wb_idx[l] = 0;
        c->wb_x[l] = c->wb_y[l] = c->wb_z[l] = 0;
    }
    c->st_running = c->st_done = c->st_fused = false;
    c->sp_running = c->sp_done = false;
    c->sp_t = c->sp_counter = 0;
    c->st_t = c->st_colour = c->st_iter = c->st_counter = 0;
    for (int b = 0; b < 2; b++)
        if (c->st_pend[b]) memset(c->st_pend[b], 0, (size_t)n * sizeof *c->st_pend[b]);
    c->sq_state = SQ_IDLE;
    c->sq_iter = c->sq_timer = 0;
    c->uidx = c->nidx = c->counter = 0;
    c->sq_done = false;
}

/* node_unit's write-back lanes: a write by unit u's write port `port` (0, or 1 with PAIR)
   shows on lane u (1 + PAIR) + port in the next cycle. */
static void lane_write_port(cyc_model *c, bool *written, int u, int port, int idx, int node)
{
    int l = u * (1 + c->hp.pair) + port;
    written[l] = true;
    c->wb_idx[l] = (uint32_t)idx;
    c->wb_x[l] = c->s.pos[node][0];
    c->wb_y[l] = c->s.pos[node][1];
    c->wb_z[l] = c->s.pos[node][2];
}
static void lane_write(cyc_model *c, bool *written, int u, int idx, int node) { lane_write_port(c, written, u, 0, idx, node); }

/* frame_ctrl: the walk's next and previous positions, registered with the walk's position
 * (init_pos, just updated) and the STEP and PREV registers as they stand before this edge's
 * write. */
static void walk_ahead(cyc_model *c)
{
    for (int a = 0; a < 3; a++) {
        c->init_ahead[a] = fx_add(&c->s.fmt, c->init_pos[a], c->step[a]);
        c->init_prev[a] = fx_add(&c->s.fmt, c->init_pos[a], c->prev_off[a]);
    }
}

/* node_unit: the flags, as they stand next cycle (with the PIN on its way through pin_pend_q). */
static bool pinned_next(const cyc_model *c, int node) { return c->sc.pinned[node] || c->pin_pend == node; }

/* A node index from a {unit, node} address (the address decoders of strand_core), or -1. */
static int node_of(const cyc_model *c, uint32_t addr)
{
    const hw_params *hp = &c->hp;
    uint32_t u = addr >> hp->iw & ((1u << hp->uw) - 1), nn = addr & ((1u << hp->iw) - 1);
    if (u >= (uint32_t)hp->m || nn >= (uint32_t)hp->k) return -1;
    return (int)(u * (uint32_t)hp->k + nn);
}

/* strand_core's EDGE register: append {spring, b, a} to the spring or the rod memory. */
static void edge_write(cyc_model *c, uint32_t data)
{
    const hw_params *hp = &c->hp;
    const int aw = hp->uw + hp->iw, bit = 2 * aw < hp->w ? 2 * aw : hp->w - 1;
    const int spring = (int)(data >> bit & 1u), size = spring ? hp->e_springs : hp->e_rods;
    if (!hp->graph || c->fill[spring] >= size) return;
    int e = (spring ? c->spring0 : 0) + c->fill[spring]++;
    /* hwgen writes valid addresses only; an edge to a node that does not exist is not
       supported (the RTL would read no node there); here it is taken as node 0 */
    int a = node_of(c, data & ((1u << aw) - 1)), b = node_of(c, data >> aw & ((1u << aw) - 1));
    c->sc.edges[e].a = a < 0 ? 0 : a;
    c->sc.edges[e].b = b < 0 ? 0 : b;
    c->s.rest[e] = c->edge_rest;
    if (c->gs_colour_end && !spring) c->gs_colour_end[e] = 2 * aw + 1 < hp->w && (data >> (2 * aw + 1) & 1u);
}

/*
 * The pairwise rule's writes of edge e (pair_sequencer S_WR_A, graph_stream's result): pair_edge()
 * now, a written (unless fixed); b's new position goes to b_new, to be written the cycle after.
 * Returns whether b is to be written then.
 */
static bool pair_write_a(cyc_model *c, int e, bool *written, fx_t b_new[3])
{
    const int k = c->hp.k, a = c->sc.edges[e].a, b = c->sc.edges[e].b;
    bool fa = sim_fx_node_fixed(&c->s, a), fb = sim_fx_node_fixed(&c->s, b);
    if (fa && fb) return false;
    long skipped = c->s.skipped;
    fx_t b_old[3];
    memcpy(b_old, c->s.pos[b], sizeof b_old);
    sim_fx_pair_edge(&c->s, e);
    bool valid = c->s.skipped == skipped;
    memcpy(b_new, c->s.pos[b], 3 * sizeof *b_new);
    memcpy(c->s.pos[b], b_old, sizeof b_old);
    if (valid && !fa) lane_write(c, written, a / k, a % k, a);
    return valid && !fb;
}

/*
 * pair_sequencer (one instance): the writes of a link's ends, then the control.
 * spring: the spring pass (spring_edge() on the link's spring edge; the forces are
 * not positions, so nothing shows on the write-back lanes); else the pairwise
 * constraints (pair_edge() on the link's rod).
 */
static void pair_sequencer_edge(cyc_model *c, cyc_pair_seq *q, bool start, bool spring, bool *written)
{
    const hw_params *hp = &c->hp;
    const int k = hp->k, n = hp->m * k, iter = spring ? 1 : hp->iter;
    const int links = hp->graph ? (spring ? hp->e_springs : hp->e_rods) : n - 1;
    const bool last_link = q->counter == (links > 0 ? links - 1 : 0);
    const bool last_iter = q->iter == iter - 1;
    /* this link: edge `counter` of the memory (the chain's links are edges (i, i+1) of sc) */
    const int base = spring ? c->spring0 : 0;
    const int e = base + (q->counter < links ? q->counter : 0);
    const int b = links > 0 ? c->sc.edges[e].b : 0;
    const int first_a = hp->graph && links > 0 ? c->sc.edges[base].a : 0;
    const int next_a = links > 0 ? c->sc.edges[base + (q->counter + 1 < links ? q->counter + 1 : 0)].a : 0;
    if (q->state == PQ_WR_A && spring) {
        sim_fx_spring_edge(&c->s, e); /* a's force now, b's next cycle: nothing reads between */
    } else if (q->state == PQ_WR_A) { /* pair_edge() now; b's half is written next cycle */
        q->write_b = pair_write_a(c, e, written, q->b_new);
    } else if (q->state == PQ_WR_B && q->write_b) {
        memcpy(c->s.pos[b], q->b_new, sizeof q->b_new);
        lane_write(c, written, b / k, b % k, b);
        q->write_b = false;
    }
    int next = q->state;
    q->done = false;
    switch (q->state) {
    case PQ_IDLE:
        if (start) {
            q->iter = 0;
            q->uidx = first_a / k;
            q->nidx = first_a % k;
            q->counter = 0;
            if (links < 1) q->done = true;
            else next = PQ_RD_A;
        }
        break;
    case PQ_RD_A:
        if (q->counter == links) q->counter = 0;
        next = PQ_RD_B;
        break;
    case PQ_RD_B: next = PQ_GO; break;
    case PQ_GO:
        q->timer = spring ? c->ls : c->lt;
        next = PQ_WAIT;
        break;
    case PQ_WAIT:
        if (--q->timer == 0) next = PQ_WR_A;
        break;
    case PQ_WR_A: next = PQ_WR_B; break;
    case PQ_WR_B:
        if (last_link) {
            q->counter = links;
            if (last_iter) {
                q->done = true;
                next = PQ_IDLE;
            } else {
                q->iter++;
                q->uidx = first_a / k;
                q->nidx = first_a % k;
                next = PQ_RD_A;
            }
        } else {
            q->counter++;
            q->uidx = next_a / k;
            q->nidx = next_a % k;
            next = PQ_RD_A;
        }
        break;
    }
    q->state = next;
}

/*
 * chain_stream: the writes of the sweep that starts now. Every constraint of the sweep
 * reads nodes the sweep does not write (the other colour) and the nodes it writes
 * itself, each after the previous sweep's write of it has landed, so each is computed
 * here, from the storage with the previous sweep's pending writes in place, with the
 * frame engine's own function on the node (centred) or link (pairwise), and undone;
 * its result waits in st_pos[colour] for its write cycle.
 */
static void stream_swap_pending(cyc_model *c, int bank)
{
    const int n = c->hp.m * c->hp.k;
    for (int i = 0; i < n; i++)
        if (c->st_pend[bank][i]) {
            fx_t t[3];
            memcpy(t, c->s.pos[i], sizeof t);
            memcpy(c->s.pos[i], c->st_pos[bank][i], sizeof t);
            memcpy(c->st_pos[bank][i], t, sizeof t);
        }
}

/* FUSE: the fused sweep's Verlet step (node_unit's stage W, as the separate pass: verlet_node()
   then mouse_node()), every node's, from the storage as the sweep starts (it reads each pair
   before any write of it: the step writes a pair as it leaves stage W, and the sweep's own
   writes come later). The storage is left as it was, the results in fz_*. */
static void fuse_step_plan(cyc_model *c)
{
    const int n = c->hp.m * c->hp.k;
    sim_fx *s = &c->s;
    for (int a = 0; a < 3; a++) s->mouse[a] = c->mouse_q[a];
    s->mouse_down = c->mouse_down_q;
    for (int i = 0; i < n; i++) {
        fx_t old_pos[3], old_prev[3];
        memcpy(old_pos, s->pos[i], sizeof old_pos);
        memcpy(old_prev, s->prev[i], sizeof old_prev);
        c->fz_write[i] = sim_fx_verlet_node(s, i);
        if (c->fz_write[i] && c->hp.en_mouse && !c->hp.grab) sim_fx_mouse_node(s, i);
        memcpy(c->fz_pos[i], s->pos[i], sizeof c->fz_pos[i]);
        memcpy(c->fz_prev[i], s->prev[i], sizeof c->fz_prev[i]);
        memcpy(s->pos[i], old_pos, sizeof old_pos);
        memcpy(s->prev[i], old_prev, sizeof old_prev);
    }
}

/* FUSE: the Verlet step's writes of pair j (stream positions 2j and 2j+1 of every unit), as it
   leaves stage W: both nodes' previous positions and force (cleared); the position of the node
   of colour 1 (the sweep writes the other when its result comes) through write port 2. */
static void fuse_step_write(cyc_model *c, bool *written, int j)
{
    const int k = c->hp.k;
    if (j < 0 || j >= (k + 1) / 2) return;
    for (int u = 0; u < c->hp.m; u++)
        for (int p = 2 * j; p <= 2 * j + 1 && p < k; p++) {
            const int x = u % 2 ? k - 1 - p : p, node = u * k + x;
            for (int a = 0; a < 3; a++) c->s.acc[node][a] = 0;
            if (!c->fz_write[node]) continue; /* pinned */
            memcpy(c->s.prev[node], c->fz_prev[node], sizeof c->s.prev[node]);
            if (node % 2 == 1) {
                memcpy(c->s.pos[node], c->fz_pos[node], sizeof c->s.pos[node]);
                lane_write_port(c, written, u, 1, x, node);
            }
        }
}

static void stream_plan(cyc_model *c)
{
    const int n = c->hp.m * c->hp.k, colour = c->st_colour;
    sim_fx *s = &c->s;
    bool *pend = c->st_pend[colour];
    fx_t (*pos)[3] = c->st_pos[colour];
    fx_t (*saved)[3] = NULL, (*saved_prev)[3] = NULL;
    stream_swap_pending(c, !colour); /* the storage as this sweep reads it */
    for (int i = 0; i < n; i++) pend[i] = false;
    if (c->st_fused) { /* what the Verlet step gives, in place while the sweep is planned */
        fuse_step_plan(c);
        saved = c->st_pos[!colour]; /* (nothing of the other colour is pending: the last sweep has landed) */
        saved_prev = c->fz_swap;
        for (int i = 0; i < n; i++) {
            memcpy(saved[i], s->pos[i], sizeof saved[i]);
            memcpy(s->pos[i], c->fz_pos[i], sizeof s->pos[i]);
            memcpy(saved_prev[i], s->prev[i], sizeof saved_prev[i]);
            memcpy(s->prev[i], c->fz_prev[i], sizeof s->prev[i]);
        }
    }
    if (!c->hp.rule) {
        for (int i = colour; i < n; i += 2) {
            fx_t old[3];
            memcpy(old, s->pos[i], sizeof old);
            if (sim_fx_centred_node(s, i)) {
                pend[i] = true;
                memcpy(pos[i], s->pos[i], sizeof pos[i]);
            } else if (c->st_fused && (!c->sc.pinned[i] || s->grabbed == i)) {
                /* the step did not write it: where the step put it (held: on the pointer) */
                pend[i] = true;
                memcpy(pos[i], old, sizeof pos[i]);
            }
            memcpy(s->pos[i], old, sizeof old);
        }
    } else {
        for (int a = colour; a + 1 < n; a += 2) { /* the link (a, a+1) is the chain's rod a */
            int b = a + 1;
            bool fa = sim_fx_node_fixed(s, a), fb = sim_fx_node_fixed(s, b);
            if (fa && fb) continue;
            fx_t old_a[3], old_b[3];
            memcpy(old_a, s->pos[a], sizeof old_a);
            memcpy(old_b, s->pos[b], sizeof old_b);
            long skipped = s->skipped;
            sim_fx_pair_edge(s, a);
            if (s->skipped == skipped) {
                if (!fa) {
                    pend[a] = true;
                    memcpy(pos[a], s->pos[a], sizeof pos[a]);
                }
                if (!fb) {
                    pend[b] = true;
                    memcpy(pos[b], s->pos[b], sizeof pos[b]);
                }
            }
            memcpy(s->pos[a], old_a, sizeof old_a);
            memcpy(s->pos[b], old_b, sizeof old_b);
        }
    }
    stream_swap_pending(c, !colour); /* back: those writes land in their cycles */
    if (saved)
        for (int i = 0; i < n; i++) {
            memcpy(s->pos[i], saved[i], sizeof s->pos[i]);
            memcpy(s->prev[i], saved_prev[i], sizeof s->prev[i]);
        }
}

/* chain_stream: the writes of slot j (in cycle j + LP + 3 of its sweep) of the sweep of this
   colour. Even units stream upward, odd ones downward (stream position s is node s, or
   K-1-s); slot j takes the constraint of the sweep's colour among positions 2j-1 and 2j:
   centred, the node at 2j (when position 0 has the sweep's colour) or 2j-1, on write port 0;
   pairwise, the link (2j, 2j+1) or (2j-1, 2j) (a link has its lower node's colour), its lower
   node a on port 0 and its higher node b on port 1, each if it is the unit's. The nodes of
   unit u that slot j writes (those with a result pending), and their write ports. */
static int stream_slot_nodes(const cyc_model *c, int u, int colour, int j, int node[2], int port[2])
{
    const int k = c->hp.k;
    const bool down = u % 2;
    const int s_par = (u * k + (down ? k - 1 : 0)) % 2; /* the colour of stream position 0 */
    int pos[2], n = 0, found = 0;
    if (j < 0 || j > k / 2) return 0;
    if (!c->hp.rule) {
        pos[n++] = s_par == colour ? 2 * j : 2 * j - 1;
    } else {
        int q = ((down ? !s_par : s_par) == colour) ? 2 * j : 2 * j - 1; /* the link (q, q+1) */
        pos[n++] = down ? q + 1 : q; /* a */
        pos[n++] = down ? q : q + 1; /* b */
    }
    for (int p = 0; p < n; p++) {
        if (pos[p] < 0 || pos[p] >= k) continue;
        int x = down ? k - 1 - pos[p] : pos[p];
        if (!c->st_pend[colour][u * k + x]) continue;
        node[found] = x;
        port[found++] = p;
    }
    return found;
}

/* ... and their landing: storage and the write-back lanes */
static void stream_write(cyc_model *c, bool *written, int colour, int j)
{
    for (int u = 0; u < c->hp.m; u++) {
        int x[2], port[2], n = stream_slot_nodes(c, u, colour, j, x, port);
        for (int i = 0; i < n; i++) {
            int node = u * c->hp.k + x[i];
            memcpy(c->s.pos[node], c->st_pos[colour][node], sizeof c->s.pos[node]);
            c->st_pend[colour][node] = false;
            lane_write_port(c, written, u, port[i], x[i], node);
        }
    }
}

bool cyc_stream_write_due(const cyc_model *c)
{
    if (!chain_streams(&c->hp) || !c->st_running) return false;
    for (int u = 0; u < c->hp.m; u++) {
        int x[2], port[2];
        if (stream_slot_nodes(c, u, c->st_colour, c->st_t - 3 - c->lp - (c->st_fused ? c->st_lag : 0), x, port) ||
            stream_slot_nodes(c, u, !c->st_colour, c->st_t + c->st_period - 3 - c->lp, x, port))
            return true;
    }
    return false;
}

/*
 * graph_stream: the writes of the edge whose result leaves the pipe (a now, b the cycle
 * after), then the control. Within a colour no edge shares a node with another, and the
 * previous colour's writes have all landed before this one's first read, so each edge is
 * computed in its write cycle, from the storage as it is then, with the frame engine's
 * pair_edge() (the same result as at its reads).
 */
static void graph_stream_edge(cyc_model *c, bool start, bool *written)
{
    const hw_params *hp = &c->hp;
    const int k = hp->k, edges = hp->e_rods;
    const int out = c->gs_ring[c->gs_ring_pos];
    if (out >= 0) { /* pair_edge() now; b's half is written next cycle */
        c->gs_write_b = pair_write_a(c, out, written, c->gs_b_new);
        c->gs_b_node = c->sc.edges[out].b;
    } else if (c->gs_write_b) {
        const int b = c->gs_b_node;
        memcpy(c->s.pos[b], c->gs_b_new, sizeof c->gs_b_new);
        lane_write(c, written, b / k, b % k, b);
        c->gs_write_b = false;
    }
    /* the edge that enters the pipe now (b arrives) is the one read in S_A and S_B */
    c->gs_ring[c->gs_ring_pos] = c->gs_issue ? c->gs_edge : -1;
    c->gs_ring_pos = c->gs_ring_pos == c->lp ? 0 : c->gs_ring_pos + 1;

    const bool drained = c->gs_state == GS_DRAIN && c->gs_drain == 0;
    const bool pass_end = drained && c->gs_j == 0;
    const bool last_iter = c->gs_iter == hp->iter - 1;
    const int j_next = c->gs_j == edges - 1 ? 0 : c->gs_j + 1;
    c->gs_done = pass_end && last_iter;
    c->gs_issue = c->gs_state == GS_B;
    switch (c->gs_state) {
    case GS_IDLE:
        if (start) {
            c->gs_state = GS_A;
            c->gs_j = c->gs_iter = c->gs_counter = 0;
            c->gs_entry = 0;
        }
        break;
    case GS_A: /* entries not filled are zero edges (node 0 to node 0, rest 0) with no colour end */
        c->gs_state = GS_B;
        c->gs_edge = c->gs_entry;
        c->gs_a = c->sc.edges[c->gs_entry].a;
        c->gs_last = c->gs_colour_end[c->gs_entry] || c->gs_j == edges - 1;
        break;
    case GS_B:
        c->gs_counter++;
        c->gs_j = j_next;
        c->gs_entry = j_next;
        if (c->gs_last) {
            c->gs_state = GS_DRAIN;
            c->gs_drain = c->lp + 2;
        } else {
            c->gs_state = GS_A;
        }
        break;
    case GS_DRAIN:
        c->gs_drain--;
        if (drained) {
            if (pass_end && last_iter) {
                c->gs_state = GS_IDLE;
            } else {
                c->gs_state = GS_A;
                if (pass_end) {
                    c->gs_iter++;
                    c->gs_counter = 0;
                }
            }
        }
        break;
    }
}

/*
 * One clock edge, block by block: each function below is one RTL block (named after its
 * module), computing its next state from its state before the edge and the signals of this
 * cycle; cyc_edge composes them in the order that keeps every read before the writes it
 * must not see (the storage's writes first, the registers last).
 */

/* frame_ctrl's combinational signals of this cycle (and the sequencers' done flags it reads),
   from the state before the edge. */
typedef struct {
    bool cmd_init, frame_start, verlet_end, seq_done, force_done, body_end, ground_start, substep_end,
        last_substep, scan_end, substep_start, force_start, body_start, verlet_start, seq_start;
} cyc_ctrl;

static void frame_ctrl_signals(const cyc_model *c, const cyc_inputs *in, cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const int n = hp->m * hp->k;
    /* CMD starts the init walk of a chain (a graph has none); a step in the same cycle wins */
    x->cmd_init = in->cfg_we && in->cfg_addr == STRAND_REG_CMD && (in->cfg_data & 1) && !hp->graph && !in->step;
    x->frame_start = c->phase == PH_IDLE && in->step;
    x->verlet_end = c->phase == PH_VERLET && c->done;
    x->seq_done = graph_streams(hp) ? c->gs_done : hp->arch ? c->st_done : hp->rule ? c->pair.done : c->sq_done;
    x->force_done = chain_streams(hp) ? c->sp_done : c->force.done;
    x->body_end = hp->en_constraints ? c->phase == PH_CONSTRAIN && x->seq_done : x->verlet_end;
    x->ground_start = x->body_end && hp->en_ground;
    x->substep_end = hp->en_ground ? c->phase == PH_GROUND && c->done : x->body_end;
    x->last_substep = c->substep == hp->substeps - 1;
    x->scan_end = hp->grab && c->phase == PH_GRAB && c->scan_i == n;
    x->substep_start = (hp->grab ? x->scan_end : x->frame_start) || (x->substep_end && !x->last_substep);
    x->force_start = x->substep_start && hp->en_springs;
    /* FUSE: no Verlet pass; the constraint pass starts in its place and takes the step */
    x->body_start = (x->substep_start && !hp->en_springs) || (c->phase == PH_FORCE && x->force_done);
    x->verlet_start = x->body_start && !hp->fuse;
    x->seq_start = hp->fuse ? x->body_start : x->verlet_end && hp->en_constraints;
}

/* node_unit port B: every unit registers the word it read last cycle (b_pos_q) and samples
   node rd_n before this edge's writes. */
static void node_unit_read_port(cyc_model *c, uint32_t rd_n)
{
    const int m = c->hp.m, k = c->hp.k;
    for (int u = 0; u < m; u++) {
        bool ok = rd_n < (uint32_t)k;
        c->bq_x[u] = c->b_x[u];
        c->bq_y[u] = c->b_y[u];
        c->bq_z[u] = c->b_z[u];
        c->b_x[u] = ok ? c->s.pos[u * k + (int)rd_n][0] : 0;
        c->b_y[u] = ok ? c->s.pos[u * k + (int)rd_n][1] : 0;
        c->b_z[u] = ok ? c->s.pos[u * k + (int)rd_n][2] : 0;
    }
}

/* node_unit's storage writes: the init walk's node, a graph's NODE write, a pass's stage D. */
static void node_unit_writes(cyc_model *c, const cyc_inputs *in, bool *written)
{
    const hw_params *hp = &c->hp;
    const int m = hp->m, k = hp->k;
    /* Storage writes. The init walk (frame_ctrl PH_INIT): node (init_u, init_n) at rest. */
    if (c->phase == PH_INIT) {
        int node = c->init_u * k + c->init_n;
        for (int a = 0; a < hp->dim; a++) {
            c->s.pos[node][a] = c->init_pos[a];
            /* node_unit: a pinned node starts at rest, a free one PREV away */
            c->s.prev[node][a] = c->sc.pinned[node] ? c->init_pos[a] : c->init_prev[a];
        }
        lane_write(c, written, c->init_u, c->init_n, node);
    }
    /* A NODE write (strand_core: a graph's, idle only): the node takes LOAD; a pinned one at rest. */
    if (in->cfg_we && in->cfg_addr == STRAND_REG_NODE && c->phase == PH_IDLE && hp->graph) {
        int node = node_of(c, in->cfg_data);
        if (node >= 0) {
            for (int a = 0; a < hp->dim; a++) {
                c->s.pos[node][a] = c->load[0][a];
                c->s.prev[node][a] = pinned_next(c, node) ? c->load[0][a] : c->load[1][a];
            }
            lane_write(c, written, node / k, node % k, node);
        }
    }
    /* A pass's stage D (node_unit): node idx_d of every unit is written; with PAIR row idx_d,
       its even node through write port 0 and its odd one (if there is one) through port 1. Its
       read was four edges ago (ARCH = 1: five); nothing else writes a node during a pass, so
       computing it here, from the storage as it is now, is the same. */
    if (c->pass_d) {
        const int ways = hp->pair ? 2 : 1;
        for (int u = 0; u < m; u++)
            for (int way = 0; way < ways; way++) {
                const int idx = c->idx_d * ways + way;
                if (idx >= k) continue;
                const int node = u * k + idx;
                /* the node's pinned flag as node_unit read it (a PIN since then is not seen) */
                const bool pinned_now = c->sc.pinned[node];
                c->sc.pinned[node] = c->pin_d[u * ways + way];
                if (c->ground_d) {
                    if (sim_fx_ground_node(&c->s, node)) lane_write_port(c, written, u, way, idx, node);
                    c->sc.pinned[node] = pinned_now;
                    continue;
                }
                for (int a = 0; a < 3; a++) c->s.mouse[a] = c->mouse_q[a];
                c->s.mouse_down = c->mouse_down_q;
                if (sim_fx_verlet_node(&c->s, node)) {
                    if (hp->en_mouse && !hp->grab) sim_fx_mouse_node(&c->s, node);
                    lane_write_port(c, written, u, way, idx, node);
                }
                c->sc.pinned[node] = pinned_now;
                /* the force is consumed (pinned nodes' too): the next spring pass starts from 0 */
                for (int a = 0; a < 3; a++) c->s.acc[node][a] = 0;
            }
    }
}

/* chain_stream's writes: a sweep's writes are planned as it starts and land in their cycles, the
   previous sweep's (SP cycles along) while this one starts. */
static void chain_stream_writes(cyc_model *c, bool *written)
{
    const int lag = c->st_fused ? c->st_lag : 0;
    if (c->st_t == 1) stream_plan(c); /* a sweep's first cycle (t = 1), its first read */
    if (c->st_fused) fuse_step_write(c, written, c->st_t - 2 - lag); /* pair j leaves stage W with slot j */
    stream_write(c, written, c->st_colour, c->st_t - 3 - c->lp - lag);
    stream_write(c, written, !c->st_colour, c->st_t + c->st_period - 3 - c->lp);
}

/* chain_sequencer's write of C (wr_en is high in S_NEXT). */
static void chain_sequencer_write(cyc_model *c, bool *written)
{
    const int k = c->hp.k;
    if (c->sq_state == SQ_NEXT) {
        int node = c->uidx * k + c->nidx;
        if (sim_fx_centred_node(&c->s, node)) lane_write(c, written, c->uidx, c->nidx, node);
    }
}

/* spring_stream: the forces of the pass, gathered in link order as it starts; then its control. */
static void spring_stream_edge(cyc_model *c, const cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const int k = hp->k, n = hp->m * k;
    const int sweep = (int)hw_spring_sweep(hp);
    const bool slot = c->sp_running && c->sp_t >= 2 && c->sp_t <= k + 2;
    const bool sweep_end = c->sp_running && c->sp_t == sweep - 1;
    if (c->sp_running && c->sp_t == 0)
        for (int i = 0; i + 1 < n; i++) sim_fx_spring_edge(&c->s, c->spring0 + i);
    c->sp_done = sweep_end;
    if (x->force_start && !c->sp_running) {
        c->sp_running = true;
        c->sp_t = c->sp_counter = 0;
    } else if (sweep_end) {
        c->sp_running = false;
        c->sp_t = c->sp_counter = 0;
    } else if (c->sp_running) {
        c->sp_t++;
        if (slot) c->sp_counter++;
    }
}

/* chain_stream's control: sweeps of SP cycles (the last of the pass SL), colour 0 then 1, ITER times. */
static void chain_stream_control(cyc_model *c, const cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const int k = hp->k;
    const bool last = c->st_colour == 1 && c->st_iter == hp->iter - 1;
    /* FUSE: the fused sweep's slots (ts = t - lag), and its end, lag cycles later */
    const int lag = c->st_fused ? c->st_lag : 0, ts = c->st_t - lag;
    const int sweep = last ? c->st_last : c->st_period + lag; /* its cycles, t = 1 .. sweep */
    const bool slot = c->st_running && ts >= 2 && ts <= k / 2 + 2; /* slots 0 .. K/2 */
    const bool sweep_end = c->st_running && c->st_t == sweep;
    /* the count restarts at the sweep's first slot: it reaches K/2 + 1 (FEC) even when the
       last slot issues in the sweep's last cycle, and keeps it until the next sweep's first */
    const int counter_next = !slot ? c->st_counter : ts == 2 ? 1 : c->st_counter + 1;
    c->st_done = sweep_end && last;
    if (x->seq_start && !c->st_running) {
        c->st_running = true;
        c->st_fused = hp->fuse;
        c->st_colour = c->st_iter = c->st_counter = 0;
        c->st_t = 1;
    } else if (sweep_end) {
        c->st_t = last ? 0 : 1;
        c->st_fused = false;
        c->st_counter = counter_next;
        if (last) c->st_running = false;
        if (c->st_colour) c->st_iter++;
        c->st_colour ^= 1;
    } else if (c->st_running) {
        c->st_t++;
        c->st_counter = counter_next;
    }
}

/* chain_sequencer's control. */
static void chain_sequencer_control(cyc_model *c, const cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const int k = hp->k, n = hp->m * k;
    const bool last_node = c->counter == n - 1;
    const bool last_iter = c->sq_iter == hp->iter - 1;
    int next = c->sq_state;
    c->sq_done = false;
    switch (c->sq_state) {
    case SQ_IDLE:
        if (x->seq_start) {
            c->sq_iter = 0;
            next = SQ_LOAD_C;
        }
        break;
    case SQ_LOAD_C:
        c->uidx = c->nidx = c->counter = 0;
        next = SQ_LOAD_D;
        break;
    case SQ_LOAD_D: next = SQ_UP; break;
    case SQ_UP:
        c->sq_timer = c->lt; /* toward started now: done is high lt cycles later */
        next = SQ_UP_W;
        break;
    case SQ_UP_W:
    case SQ_DN_W:
        if (--c->sq_timer == 0) {
            c->sq_timer = c->lt; /* the second toward starts in the done cycle */
            next = c->sq_state == SQ_UP_W ? SQ_DN_W : SQ_NEXT;
        }
        break;
    case SQ_NEXT:
        c->counter++;
        if (!last_node) {
            if (c->nidx == k - 1) {
                c->nidx = 0;
                c->uidx++;
            } else {
                c->nidx++;
            }
            next = SQ_UP;
        } else if (last_iter) {
            c->sq_done = true;
            next = SQ_IDLE;
        } else {
            c->sq_iter++;
            next = SQ_LOAD_C;
        }
        break;
    }
    c->sq_state = next;
}

/* node_unit's pass FSM: the data arrive (running, vidx: a node, with PAIR a row); stage A (serial:
   the same cycle; ARCH = 1: pass_a, idx_a, the cycle after), stage B (pass_b, idx_b), stage C
   (pass_c, idx_c), stage D (pass_d, idx_d: the write, node_unit_writes). */
static void node_unit_pass(cyc_model *c, const cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const bool stage_a = hp->arch ? c->pass_a : c->running, ground_a = hp->arch ? c->ground_a : c->ground_pass;
    const int idx_a = hp->arch ? c->idx_a : c->vidx;
    const bool pass_a_next = c->running, ground_a_next = c->ground_pass;
    const int idx_a_next = c->vidx;
    const bool pass_b_next = stage_a, ground_b_next = ground_a;
    const int idx_b_next = idx_a;
    const bool pass_c_next = c->pass_b, ground_c_next = c->ground_b;
    const int idx_c_next = c->idx_b;
    const bool pass_d_next = c->pass_c, ground_d_next = c->ground_c;
    const int idx_d_next = c->idx_c;
    if (x->verlet_start || x->ground_start) {
        c->running = true;
        c->done = false;
        c->vidx = 0;
        c->ground_pass = !x->verlet_start;
    } else {
        const int last_step = (int)hw_pass_steps(hp) - 1; /* node, or with PAIR row, of the pass */
        if (c->running) {
            if (c->vidx == last_step) c->running = false;
            c->vidx = (c->vidx + 1) & ((1 << hp->iw) - 1);
        }
        if (c->pass_d && c->idx_d == last_step) c->done = true; /* the last node (row) is written */
    }
    c->pass_a = hp->arch && pass_a_next;
    if (c->pass_a) {
        c->idx_a = idx_a_next;
        c->ground_a = ground_a_next;
    }
    c->pass_b = pass_b_next;
    if (pass_b_next) {
        c->idx_b = idx_b_next;
        c->ground_b = ground_b_next;
    }
    c->pass_c = pass_c_next;
    if (pass_c_next) {
        c->idx_c = idx_c_next;
        c->ground_c = ground_c_next;
    }
    c->pass_d = pass_d_next;
    if (pass_d_next) {
        c->idx_d = idx_d_next;
        c->ground_d = ground_d_next;
    }
    /* the pinned flags travel with their nodes: each stage takes the one before it (as the
       indices above), and the node (row) whose data arrive next is read now, from the flags as
       they are in this cycle (a PIN of this cycle reaches them two edges on) */
    const int ways = hp->pair ? 2 : 1, lanes = hp->m * ways;
    for (int l = 0; l < lanes; l++) {
        if (pass_d_next) c->pin_d[l] = c->pin_c[l];
        if (pass_c_next) c->pin_c[l] = c->pin_b[l];
        if (pass_b_next) c->pin_b[l] = hp->arch ? c->pin_a[l] : c->pin_v[l];
        if (c->pass_a) c->pin_a[l] = c->pin_v[l];
        if (c->running) {
            const int idx = c->vidx * ways + l % ways;
            c->pin_v[l] = idx < hp->k && c->sc.pinned[(l / ways) * hp->k + idx];
        }
    }
}

/* frame_ctrl's FSM. FUSE: the phase after FORCE (or the frame's start) is CONSTRAIN. Returns
   whether a frame ended at this edge. */
static bool frame_ctrl_edge(cyc_model *c, const cyc_inputs *in, const cyc_ctrl *x)
{
    const hw_params *hp = &c->hp;
    const fx_format *f = &c->s.fmt;
    const int k = hp->k, n = hp->m * k;
    const int body_phase = hp->fuse ? PH_CONSTRAIN : PH_VERLET;
    bool frame_end = false;
    c->frame_done = false;
    switch (c->phase) {
    case PH_IDLE:
        if (x->cmd_init) {
            c->phase = PH_INIT;
            c->init_u = c->init_n = c->init_count = 0;
            for (int a = 0; a < 3; a++) c->init_pos[a] = a < hp->dim ? c->start[a] : 0;
            walk_ahead(c);
        } else if (in->step) {
            c->phase = hp->grab ? PH_GRAB : hp->en_springs ? PH_FORCE : body_phase;
            c->scan_i = 0;
            c->substep = 0;
            c->mouse_q[0] = from_word(f, in->mouse_x);
            c->mouse_q[1] = from_word(f, in->mouse_y);
            c->mouse_q[2] = hp->dim == 3 ? from_word(f, in->mouse_z) : 0;
            c->mouse_down_q = in->mouse_down;
        }
        break;
    case PH_INIT:
        for (int a = 0; a < 3; a++) c->init_pos[a] = c->init_ahead[a];
        walk_ahead(c);
        if (c->init_n == k - 1) {
            c->init_n = 0;
            c->init_u++;
        } else {
            c->init_n++;
        }
        if (c->init_count++ == n - 1) c->phase = PH_IDLE;
        break;
    case PH_FORCE:
        if (x->force_done) c->phase = body_phase;
        break;
    case PH_GRAB: /* grab_scan: the scan ends by grabbing or releasing (grab_update) */
        if (x->scan_end) {
            for (int a = 0; a < 3; a++) c->s.mouse[a] = c->mouse_q[a];
            c->s.mouse_down = c->mouse_down_q;
            sim_fx_grab_update(&c->s);
            c->phase = hp->en_springs ? PH_FORCE : body_phase;
        } else {
            c->scan_i++;
        }
        break;
    case PH_VERLET:
        if (x->seq_start) c->phase = PH_CONSTRAIN;
        break;
    default: break;
    }
    if (x->ground_start) c->phase = PH_GROUND;
    if (x->substep_end) {
        if (x->last_substep) {
            c->phase = PH_IDLE;
            c->frame_done = true;
            frame_end = true;
        } else {
            c->phase = hp->en_springs ? PH_FORCE : body_phase;
            c->substep++;
        }
    }
    return frame_end;
}

/* strand_regfile (and the units' pin flags): the register writes; a frame ending sets irq after
   IRQ_ACK clears it (frame_ctrl). phase_before: frame_ctrl's phase before this edge. */
static void strand_regfile_edge(cyc_model *c, const cyc_inputs *in, int phase_before, bool frame_end)
{
    const hw_params *hp = &c->hp;
    const fx_format *f = &c->s.fmt;
    const int m = hp->m, k = hp->k;
    /* node_unit: last cycle's PIN reaches the flags at this edge; this cycle's is on its way */
    if (c->pin_pend >= 0) c->sc.pinned[c->pin_pend] = true;
    c->pin_pend = -1;
    if (in->cfg_we) {
        fx_t v = from_word(f, in->cfg_data);
        switch (in->cfg_addr) {
        case STRAND_REG_DIST: /* the chain's rest length: every link (a graph's edges have their own) */
            c->s.dist = v;
            if (!hp->graph)
                for (int e = 0; e < c->sc.n_edges; e++) c->s.rest[e] = v;
            break;
        case STRAND_REG_IMPULSE: c->s.impulse = v; break;
        case STRAND_REG_BOX_X: c->s.box[0] = v; break;
        case STRAND_REG_BOX_Y: c->s.box[1] = v; break;
        case STRAND_REG_KS: c->s.ks = v; break;
        case STRAND_REG_KD: c->s.kd = v; break;
        case STRAND_REG_GROUND: c->s.ground = v; break;
        case STRAND_REG_FRICTION: c->s.friction = v; break;
        STRAND_EFFECT_REG_CASES(c->s, v) /* the effects table's registers */
        case STRAND_REG_PREV_X: c->prev_off[0] = v; break;
        case STRAND_REG_PREV_Y: c->prev_off[1] = v; break;
        case STRAND_REG_START_X: c->start[0] = v; break;
        case STRAND_REG_START_Y: c->start[1] = v; break;
        case STRAND_REG_START_Z: c->start[2] = v; break;
        case STRAND_REG_STEP_Z: c->step[2] = v; break;
        case STRAND_REG_PREV_Z: c->prev_off[2] = v; break;
        case STRAND_REG_BOX_Z: c->s.box[2] = v; break;
        case STRAND_REG_LOAD_X: c->load[0][0] = v; break;
        case STRAND_REG_LOAD_Y: c->load[0][1] = v; break;
        case STRAND_REG_LOAD_Z: c->load[0][2] = v; break;
        case STRAND_REG_LOAD_PX: c->load[1][0] = v; break;
        case STRAND_REG_LOAD_PY: c->load[1][1] = v; break;
        case STRAND_REG_LOAD_PZ: c->load[1][2] = v; break;
        case STRAND_REG_EDGE_REST: c->edge_rest = v; break;
        case STRAND_REG_EDGE: /* strand_core: idle only */
            if (phase_before == PH_IDLE) edge_write(c, in->cfg_data);
            break;
        case STRAND_REG_IRQ_ACK: c->irq = false; break;
        case STRAND_REG_STEP_X: c->step[0] = v; break;
        case STRAND_REG_STEP_Y: c->step[1] = v; break;
        case STRAND_REG_PIN: {
            uint32_t u = in->cfg_data >> hp->iw & ((1u << hp->uw) - 1), nn = in->cfg_data & ((1u << hp->iw) - 1);
            if (u < (uint32_t)m && nn < (uint32_t)k) c->pin_pend = (int)(u * k + nn);
            break;
        }
        default: break;
        }
    }
    if (frame_end) c->irq = true;
}

void cyc_edge(cyc_model *c, const cyc_inputs *in)
{
    const hw_params *hp = &c->hp;
    bool written[CYC_MAX_LANES] = {false};
    uint32_t rd_u = in->rd_addr >> hp->iw & ((1u << hp->uw) - 1), rd_n = in->rd_addr & ((1u << hp->iw) - 1);

    c->cycle++;
    c->rd_u_q2 = c->rd_u_q; /* strand_core rd_u_q, rd_u_q2: not reset, follow rd_addr */
    c->rd_u_q = rd_u;
    if (in->reset) {
        reset_all(c);
        return;
    }
    cyc_ctrl x;
    frame_ctrl_signals(c, in, &x);

    /* the storage: reads before writes, then every block's writes of this edge */
    node_unit_read_port(c, rd_n);
    node_unit_writes(c, in, written);
    if (chain_streams(hp) && c->st_running) chain_stream_writes(c, written);
    if (!hp->arch && !hp->rule) chain_sequencer_write(c, written);
    if (!hp->arch && hp->rule && hp->en_constraints) pair_sequencer_edge(c, &c->pair, x.seq_start, false, written);
    if (hp->en_springs && !chain_streams(hp)) pair_sequencer_edge(c, &c->force, x.force_start, true, written);
    if (graph_streams(hp)) graph_stream_edge(c, x.seq_start, written);
    if (hp->en_springs && chain_streams(hp)) spring_stream_edge(c, &x);
    for (int l = 0; l < hp->wb; l++) c->wb_valid[l] = written[l];

    /* the control */
    if (chain_streams(hp) && hp->en_constraints) chain_stream_control(c, &x);
    if (!hp->arch && !hp->rule && hp->en_constraints) chain_sequencer_control(c, &x);
    node_unit_pass(c, &x);
    const int phase_before = c->phase;
    const bool frame_end = frame_ctrl_edge(c, in, &x);
    strand_regfile_edge(c, in, phase_before, frame_end);
}
