/*
 * cycle.h - the cycle model: strand_core, register for register, clock by clock.
 *
 * It holds the RTL's control state (phases, counters, the sequencer's states and
 * the datapath's fixed latency) and its visible registers (read port, write-back
 * lanes, status), and predicts every output of strand_core on every cycle. Node
 * positions live in a sim_fx, and are changed by the frame engine's own per-node
 * functions (verlet_node, mouse_node, centred_node) at the edge where the RTL
 * writes that node, so the cycle model and the frame engine cannot drift apart.
 *
 * Use: cyc_init() for a build; each cycle, cyc_outputs() gives what the RTL shows
 * now, and cyc_edge() applies the inputs present before the rising edge.
 */
#ifndef STRAND_CYCLE_H
#define STRAND_CYCLE_H

#include <stdint.h>

#include "hw_params.h"
#include "timing.h"
#include "sim.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CYC_MAX_UNITS 256
#define CYC_MAX_LANES (2 * CYC_MAX_UNITS) /* write-back lanes: one a unit, two with PAIR */

enum { PH_IDLE = 0, PH_INIT = 1, PH_VERLET = 2, PH_CONSTRAIN = 3, PH_FORCE = 4, PH_GROUND = 5, PH_GRAB = 6 };
enum { SQ_IDLE, SQ_LOAD_C, SQ_LOAD_D, SQ_UP, SQ_UP_W, SQ_DN_W, SQ_NEXT };             /* chain_sequencer */
enum { PQ_IDLE, PQ_RD_A, PQ_RD_B, PQ_GO, PQ_WAIT, PQ_WR_A, PQ_WR_B };                 /* pair_sequencer */
enum { GS_IDLE, GS_A, GS_B, GS_DRAIN };                                                /* graph_stream */

/* The inputs of strand_core during one cycle (all W-bit words raw). */
typedef struct {
    bool reset;
    uint32_t mouse_x, mouse_y, mouse_z;
    bool mouse_down;
    bool step;
    bool cfg_we;
    uint32_t cfg_addr, cfg_data;
    uint32_t rd_addr;
} cyc_inputs;

/* The outputs of strand_core during one cycle. */
typedef struct {
    bool frame_done, busy, irq;
    uint32_t rd_x, rd_y, rd_z;
    int phase;
    bool fv, fec;
    uint32_t uidx, nidx, counter;
    int lanes; /* the build's WB: lane u (1 + PAIR) + l is unit u's write port l */
    bool wb_valid[CYC_MAX_LANES];
    uint32_t wb_idx[CYC_MAX_LANES], wb_x[CYC_MAX_LANES], wb_y[CYC_MAX_LANES], wb_z[CYC_MAX_LANES];
} cyc_outputs;

/* pair_sequencer: one instance (the pairwise constraints, or the spring pass). */
typedef struct {
    int state, iter, timer;
    int uidx, nidx, counter;
    bool done;
    bool write_b; /* constraints: b's new position waits for its write cycle */
    fx_t b_new[3];
} cyc_pair_seq;

typedef struct {
    hw_params hp;
    scene sc;    /* a chain of M x K nodes with the build's effects; pins come from PIN writes */
    sim_fx s;    /* node positions and the run-time constants */
    long cycle;  /* edges since cyc_init */
    int lt;      /* toward's latency (cycles) */
    int ls;      /* spring_force's latency (cycles) */
    int spring0; /* the first spring edge of sc (springs follow the rods) */
    int fill[2]; /* graph: edges loaded into the rod and the spring memory */

    /* strand_core */
    int phase, substep;
    int scan_i;  /* the grab scan: nodes addressed so far */
    bool frame_done;
    bool irq;    /* frame_ctrl: a frame ended since the last IRQ_ACK */
    fx_t mouse_q[3];
    bool mouse_down_q;
    int init_u, init_n, init_count;
    fx_t init_pos[3], start[3], step[3], prev_off[3];
    fx_t init_prev[3]; /* frame_ctrl prev_q: init_pos + prev_off, registered a cycle ahead */
    fx_t init_ahead[3]; /* frame_ctrl pos_ahead_q: init_pos + step, registered a cycle ahead */
    int pin_pend;       /* node_unit pin_pend_q: the node a PIN of the last cycle pins at this edge, or -1 */
    fx_t load[2][3];   /* LOAD_X..Z, LOAD_PX..PZ */
    fx_t edge_rest;    /* EDGE_REST */
    uint32_t rd_u_q, rd_u_q2; /* strand_core: the read port's unit, one and two cycles after rd_addr */
    /* node units (they run in step) */
    bool running, done;
    bool ground_pass; /* the pass under way is the ground pass */
    int vidx;         /* the node whose data arrive (stage A; ARCH = 1 stage R) */
    bool pass_a, ground_a; /* ARCH = 1, stage A: the words registered by stage R */
    int idx_a;
    bool pass_b, ground_b; /* stage B: a node of a pass (of the ground pass) */
    int idx_b;
    bool pass_c, ground_c; /* stage C */
    int idx_c;
    bool pass_d, ground_d; /* stage D: it is written */
    int idx_d;
    /* each way's pinned flag, as node_unit reads it with the node's address (q_pin, pin_e_q,
       pin_o_q) and carries it down the stages: a PIN written after the read does not reach a pass
       already under way (stage R/A: pin_v; then pin_a with ARCH, pin_b, pin_c, pin_d) */
    bool pin_v[CYC_MAX_LANES], pin_a[CYC_MAX_LANES], pin_b[CYC_MAX_LANES], pin_c[CYC_MAX_LANES], pin_d[CYC_MAX_LANES];
    fx_t b_x[CYC_MAX_UNITS], b_y[CYC_MAX_UNITS], b_z[CYC_MAX_UNITS]; /* port B: the word read (b_ok applied) */
    fx_t bq_x[CYC_MAX_UNITS], bq_y[CYC_MAX_UNITS], bq_z[CYC_MAX_UNITS]; /* node_unit b_pos_q: that word a cycle later */
    bool wb_valid[CYC_MAX_LANES];   /* the write-back lanes (WB of them) */
    uint32_t wb_idx[CYC_MAX_LANES];
    fx_t wb_x[CYC_MAX_LANES], wb_y[CYC_MAX_LANES], wb_z[CYC_MAX_LANES];
    /* chain_sequencer (rule 0) */
    int sq_state, sq_iter, sq_timer;
    int uidx, nidx, counter;
    bool sq_done;
    /* chain_stream (ARCH = 1): the sweep's time t, colour, iteration, slots issued; each
       node's write of a sweep, by the sweep's colour (computed when the sweep starts, from the
       storage with the previous sweep's writes that have not landed yet: a sweep reads only
       what it does not write, each node after the previous sweep's write of it), applied in
       its write cycle (the previous sweep's drain overlaps the next sweep's start) */
    int lp;      /* toward_pipe's latency */
    int st_period, st_last;  /* a sweep's cycles before the next, and the pass's last sweep's */
    bool st_running, st_done;
    int st_t, st_colour, st_iter, st_counter;
    bool *st_pend[2];      /* per node: written by the sweep of this colour */
    fx_t (*st_pos[2])[3];  /* its new position */
    /* FUSE: the first sweep of a pass is fused (st_fused): its slots are st_lag cycles later
       (node_unit's stages R, A, B, C) and it takes the Verlet step, planned as it starts (every
       node's step, fz_*: whether the step writes it, its new position and previous position,
       from the storage then) and written as each pair leaves stage W */
    bool st_fused;
    int st_lag;
    bool *fz_write;
    fx_t (*fz_pos)[3], (*fz_prev)[3];
    fx_t (*fz_swap)[3];  /* the storage's previous positions while the sweep is planned */
    /* spring_stream (ARCH = 1 with EN_SPRINGS): one sweep; every force of the pass is
       gathered when it starts (nothing reads a force until the Verlet pass after it) */
    int lsp;     /* spring_force_pipe's latency */
    bool sp_running, sp_done;
    int sp_t, sp_counter;
    /* graph_stream (ARCH = 1, GRAPH): its state, the edge on the memory's output and the one
       between its reads, the pass's edges read; the pipe is a ring of LP + 1 slots (an edge
       issued now has its a written LP + 1 cycles later, its b the cycle after) */
    int gs_state, gs_j, gs_iter, gs_drain, gs_counter;
    int gs_entry;         /* the memory's output: this edge's entry */
    int gs_edge, gs_a;    /* the edge between its reads (from S_A), its a */
    bool gs_last, gs_issue, gs_done;
    bool *gs_colour_end;  /* per rod memory entry: the EDGE word's colour end (reset: 0) */
    int *gs_ring, gs_ring_pos;
    bool gs_write_b;      /* b's new position waits a cycle for its write */
    int gs_b_node;
    fx_t gs_b_new[3];
    cyc_pair_seq pair;   /* pair_sequencer, the constraints (rule 1) */
    cyc_pair_seq force;  /* pair_sequencer, the spring pass (EN_SPRINGS) */
} cyc_model;

/* The model of a build (all nodes at 0, nothing pinned, registers 0: strand_core after reset). */
bool cyc_init(cyc_model *c, const hw_params *hp);
void cyc_free(cyc_model *c);
/* What strand_core shows in the current cycle. */
void cyc_get_outputs(const cyc_model *c, cyc_outputs *out);
/* One rising edge with these inputs. */
void cyc_edge(cyc_model *c, const cyc_inputs *in);
/* chain_stream: whether the coming edge lands a write of the pipelined pass (a planted
   fault's predicted cycle). */
bool cyc_stream_write_due(const cyc_model *c);
/* Node i's position (raw W-bit words), as the RTL's storage holds it now. */
uint32_t cyc_node_word(const cyc_model *c, int i, int axis);

#ifdef __cplusplus
}
#endif

#endif
