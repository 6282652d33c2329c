`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"

/*
 * node_unit - K nodes of the body and the per-node FSM of reference 000.
 *
 * Holds, per node, a position and a previous position on each of DIM axes (one
 * node_lane per axis, its storage a reset-free strand_ram), a pinned flag and a
 * written flag (flip-flops, reset). A Verlet pass (verlet_start) updates node
 * 0 .. K-1, one node per clock (with PAIR two: row r, nodes 2r and 2r + 1, one from
 * each bank, through two copies of the step), each with model/engine_body.h
 * verlet_node() and then mouse_node() (node_lane has the arithmetic):
 *     v = x - px;  v = v - v*d (EN_DAMPING);  px = x;  x = x + v;  x = x + g h^2 (EN_GRAVITY)
 *     x = x + acc (EN_SPRINGS: the spring force of this substep, then acc = 0)
 *     mouse (EN_MOUSE, button down, |mouse - x| < box on every axis):
 *         px.x = (mouse.x < px.x) ? x.x + a : x.x - a
 *     grab (EN_MOUSE and GRAB; the core says which node is held): the held node is put
 *         on the pointer, px = its old x; it counts as pinned for the constraints
 *         and the ground
 * FUSE (a pipelined chain, the centred rule): there is no Verlet pass; the same stages step
 * the pairs chain_stream's first sweep reads (pair_fuse, in the sweep's order) and stage W
 * hands them to the sweep (pass_*), writing the previous positions, the forces' clears and
 * the position of the colour-1 node (write port 2); the sweep writes the colour-0 node.
 * A ground pass (EN_GROUND, ground_start) walks the nodes the same way with
 * ground_node(): a node past the boundary on the normal axis is put on it, its
 * velocity along the normal reversed, friction on the other axes. Pinned nodes are
 * not written.
 *
 * Storage reads are synchronous (data the cycle after the address), read before
 * write. Port A serves the pass and, between passes, the sequencers and the grab
 * scan; port B is the external position read port (the word two cycles after its
 * index: the memory's read, then a register): a node not written since reset reads as
 * 0 there (the written flags), so the port never shows undefined storage.
 * The node memories are filled by the init walk or NODE loads (w_at_rest), never by
 * reset: after reset a step before they are filled computes on undefined values.
 *
 * Timing (the cycle model mirrors it; with PAIR read "row" for "node" and K_ROWS =
 * ceil(K / 2) for K): verlet_start seen at edge 0 clears
 * verlet_done and presents address 0; node i's data arrive in cycle i + 1 (stage A:
 * the velocity), stage B (the rest of the Verlet step) is cycle i + 2, stage C (the
 * mouse's tests) cycle i + 3, and it is written at edge i + 4 (stage W: the impulse
 * chosen, the write); verlet_done rises at edge K + 3 and stays high until the next
 * start. With ARCH = 1 a stage R registers the words the cycle they arrive, so stage A
 * is cycle i + 2 and every later stage and verlet_done one cycle later (write at edge
 * i + 5, done at K + 4). The ground pass is timed the same. With DEBUG, every write to this unit (pass, init, load or
 * sequencer) shows on the write-back lane in the next cycle.
 */
module node_unit #(
`include "strand_params.vh"
    ,
    /* verilator lint_off UNUSEDPARAM */
    // the unit's number: names it in traces; nothing in the unit depends on it
    parameter integer UNIT_ID = 0
    /* verilator lint_on UNUSEDPARAM */
) (
    input  wire             clk,
    input  wire             reset,        // synchronous, active high: the pass FSM, pins and written flags

    input  wire             verlet_start, // one-cycle pulse: run the Verlet pass over all K nodes
    input  wire             ground_start, // one-cycle pulse: run the ground pass (EN_GROUND)
    output wire             verlet_done,  // this unit's FV: high from the end of a pass to the next start

    // the run-time constants and the pointer, DIM lanes each (lane k at bits k W +: W)
    input  wire [DIM*(W+1)-1:0] touch_lo, // the in-touch box: mouse - box and mouse + box,
    input  wire [DIM*(W+1)-1:0] touch_hi, //   W+1 bits per lane, exact
    input  wire [DIM*W-1:0] mouse,
    input  wire             mouse_down,
    input  wire [`STRAND_FX_SLOTS*W-1:0] fx_consts,  // the effects table's constants, to every lane
    input  wire [W-1:0]     impulse,
    input  wire [W-1:0]     ground,
    input  wire [W-1:0]     friction,
    input  wire             grab_here,    // GRAB: this unit holds the grabbed node,
    input  wire [IW-1:0]    grab_idx,     //   this one

    // port A between passes: the sequencers' and the scan's reads
    input  wire [IW-1:0]    a_idx,        // node to read; its data appear next cycle
    output wire [DIM*W-1:0] a_pos,
    output wire [DIM*W-1:0] a_prev,       // previous position (the spring pass's velocities)
    output wire [DIM*W-1:0] a_acc,        // the spring force gathered so far (EN_SPRINGS; else 0)
    output wire             a_pinned,     // pinned, or grabbed (constraints do not move it)

    // writes between passes
    input  wire             acc_we,       // the spring pass: node w_idx's force
    input  wire [DIM*W-1:0] acc_w,
    input  wire             w_en,         // write node w_idx
    input  wire [IW-1:0]    w_idx,
    input  wire [DIM*W-1:0] w_pos,
    input  wire             w_at_rest,    // also the previous position (and clear the force): init and loads
    input  wire [DIM*W-1:0] w_prev,       //   to this, or to w_pos for a pinned node
    input  wire [IW-1:0]    rest_idx,     // the node an at-rest write's pinned flag is looked up for: a
                                          //   graph's NODE load's (now); a chain's init walk's next node
    input  wire             rest_node0,   // a chain's init walk: the write is to node 0 (its flag is kept apart)
    input  wire             pin_en,       // pin node pin_idx (the flag is set from the second cycle after)
    input  wire [IW-1:0]    pin_idx,

    // PAIR (a chain's pipelined constraint pass): a pair read instead of port A, node
    // 2 pair_row_e (even bank) and node 2 pair_row_o + 1 (odd bank), data the next cycle
    // with their pinned (or held) flags; and a second write, to the other bank than w_idx's
    input  wire             pair_re,
    input  wire [IW-1:0]    pair_row_e,
    input  wire [IW-1:0]    pair_row_o,
    output wire [DIM*W-1:0] pair_pos_e,
    output wire [DIM*W-1:0] pair_pos_o,
    output wire [DIM*W-1:0] pair_prev_e,
    output wire [DIM*W-1:0] pair_prev_o,
    output wire             pair_pin_e,
    output wire             pair_pin_o,
    input  wire             w2_en,
    input  wire [IW-1:0]    w2_idx,
    input  wire [DIM*W-1:0] w2_pos,
    // FUSE: the pair read is the first sweep's, and the Verlet step takes it (the odd bank's
    // node of it when pair_has_o); the step's results go to the sweep STRAND_FUSE_LAG cycles
    // after the read, as the sweep's words, while the step writes the previous positions and
    // the positions of the nodes the sweep does not move (the other colour's)
    input  wire             pair_fuse,
    input  wire             pair_has_o,
    output wire [DIM*W-1:0] pass_pos_e,
    output wire [DIM*W-1:0] pass_pos_o,
    output wire [DIM*W-1:0] pass_prev_e,
    output wire [DIM*W-1:0] pass_prev_o,
    output wire             pass_pin_e,   // pinned or held
    output wire             pass_pin_o,
    output wire             pass_held_e,
    output wire             pass_held_o,

    // port B: external position reads, the word two cycles after the index
    input  wire [IW-1:0]    b_idx,
    output wire [DIM*W-1:0] b_pos,

    // DEBUG: the write-back lanes, a write to this unit shown the cycle after it happens:
    // lane 0 the first write port's, lane 1 (PAIR) the second's
    output wire [PAIR:0]           wb_valid,
    output wire [(1+PAIR)*IW-1:0]  wb_idx,
    output wire [(1+PAIR)*DIM*W-1:0] wb_pos
);

    localparam [IW:0]   K_COUNT  = K[IW:0];           // node count, one bit wider than an index
    // the steps of a pass: nodes, or with PAIR rows of two (the last one's odd node past K when K is odd)
    localparam integer  STEPS_I  = PAIR != 0 ? (K + 1) / 2 : K;
    localparam integer  S_LAST_I = STEPS_I - 1;
    localparam [IW-1:0] S_LAST   = S_LAST_I[IW-1:0];  // the last step

    // ---- the pass FSM: stage A (running, vidx: the node, with PAIR the row, whose data
    // arrive), stages B and C, and stage W (pass_w, idx_w: the node or row written). Per
    // way (PAIR: way 1 the row's odd node): pinned, grabbed, and (way 1) whether it exists ----
    reg          running_q, running_d;  // a pass is under way: a node is in stage A
    reg          done_q, done_d;        // FV
    reg [IW-1:0] vidx_q, vidx_d;        // node (row) whose data port A (the pair read) returns this cycle
    reg [IW-1:0] vrun_q;                // vidx_q + 1, a register: no incrementer before port A's address
    localparam [IW-1:0] IDX_ONE = 1;
    reg          ground_q, ground_d;    // the pass under way is the ground pass
    // idx: the row (way 0's, the even bank's); idx1 way 1's (the odd bank's): the same row but
    // in a fused step (FUSE), which takes the sweep's pairs; fused: a fused step's node
    wire         stage_a, ground_a, fused_a;  // stage A: a node of the pass (below)
    wire [PAIR:0] pin_a, grab_a, has_a;
    wire [IW-1:0] idx_a, idx1_a;
    reg          stage_b, ground_b, fused_b;  // stage B: a node of the pass, and how to write it
    reg [PAIR:0] pin_b, grab_b, has_b;
    reg [IW-1:0] idx_b, idx1_b;
    reg          stage_c, ground_c, fused_c;  // stage C
    reg [PAIR:0] pin_c, grab_c, has_c;
    reg [IW-1:0] idx_c, idx1_c;
    reg          pass_w, ground_w, fused_w;   // stage W: the write
    reg [PAIR:0] pin_w, grab_w, has_w;
    reg [IW-1:0] idx_w, idx1_w;

    wire last = vidx_q == S_LAST;
    wire pass_start = verlet_start || (EN_GROUND && ground_start);

    always @* begin
        running_d = running_q;
        done_d    = done_q;
        vidx_d    = vidx_q;
        ground_d  = ground_q;
        if (pass_start) begin
            running_d = 1'b1;
            done_d    = 1'b0;
            vidx_d    = {IW{1'b0}};
            ground_d  = !verlet_start;
        end else begin
            if (running_q) begin
                vidx_d = vrun_q;
                if (last) running_d = 1'b0;
            end
            if (pass_w && !fused_w && idx_w == S_LAST) done_d = 1'b1;  // the last node (row) is written
        end
    end

    always @(posedge clk) begin
        if (reset) begin
            running_q <= 1'b0;
            done_q    <= 1'b0;
            vidx_q    <= {IW{1'b0}};
            vrun_q    <= IDX_ONE;
            ground_q  <= 1'b0;
            stage_b   <= 1'b0;
            stage_c   <= 1'b0;
            pass_w    <= 1'b0;
        end else begin
            running_q <= running_d;
            done_q    <= done_d;
            vidx_q    <= vidx_d;
            vrun_q    <= vidx_d + 1'b1;
            ground_q  <= ground_d;
            stage_b   <= stage_a;
            stage_c   <= stage_b;
            pass_w    <= stage_c;
        end
        if (stage_a) begin  // what the later stages need of the node
            idx_b    <= idx_a;
            idx1_b   <= idx1_a;
            fused_b  <= fused_a;
            ground_b <= ground_a;
            pin_b    <= pin_a;
            grab_b   <= grab_a;
            has_b    <= has_a;
        end
        if (stage_b) begin
            idx_c    <= idx_b;
            idx1_c   <= idx1_b;
            fused_c  <= fused_b;
            ground_c <= ground_b;
            pin_c    <= pin_b;
            grab_c   <= grab_b;
            has_c    <= has_b;
        end
        if (stage_c) begin
            idx_w    <= idx_c;
            idx1_w   <= idx1_c;
            fused_w  <= fused_c;
            ground_w <= ground_c;
            pin_w    <= pin_c;
            grab_w   <= grab_c;
            has_w    <= has_c;
        end
    end

    assign verlet_done = done_q;

    // ---- the words a pass's step takes arrive now (arrive): its own walk's (running_q: node or
    // row vidx_q), or with FUSE the fused sweep's pair read's (the rows chain_stream read, one
    // a bank); with the nodes' flags, read with the words (assigned below) ----
    wire          arrive, arr_fused, arr_ground;
    wire [IW-1:0] arr_idx, arr_idx1;
    wire [PAIR:0] arr_pin, arr_grab, arr_has;

    // ---- stage A: serial, the cycle port A's data arrive; ARCH = 1, the cycle after (stage R
    // registers the words first: the path from a block RAM's unregistered output through the
    // velocity's subtract set the pipelined builds' clock) ----
    generate
        if (ARCH) begin : g_stage_r
            reg          stage_r_q, ground_r_q, fused_r_q;
            reg [PAIR:0] pin_r_q, grab_r_q, has_r_q;
            reg [IW-1:0] idx_r_q, idx1_r_q;
            always @(posedge clk) begin
                if (reset) stage_r_q <= 1'b0;
                else stage_r_q <= arrive;
                if (arrive) begin
                    idx_r_q    <= arr_idx;
                    idx1_r_q   <= arr_idx1;
                    fused_r_q  <= arr_fused;
                    ground_r_q <= arr_ground;
                    pin_r_q    <= arr_pin;
                    grab_r_q   <= arr_grab;
                    has_r_q    <= arr_has;
                end
            end
            assign stage_a  = stage_r_q;
            assign idx_a    = idx_r_q;
            assign idx1_a   = idx1_r_q;
            assign fused_a  = fused_r_q;
            assign ground_a = ground_r_q;
            assign pin_a    = pin_r_q;
            assign grab_a   = grab_r_q;
            assign has_a    = has_r_q;
        end else begin : g_no_stage_r
            assign stage_a  = arrive;
            assign idx_a    = arr_idx;
            assign idx1_a   = arr_idx1;
            assign fused_a  = arr_fused;
            assign ground_a = arr_ground;
            assign pin_a    = arr_pin;
            assign grab_a   = arr_grab;
            assign has_a    = arr_has;
        end
    endgenerate

    // ---- port A: during a pass the address runs ahead of vidx by one (node vidx+1 is
    // read while node vidx is written); with PAIR the pass reads rows through the pair
    // read, and port A reads the row's even node (for its flags) ----
    // A pass starts at node (row) 0, so a_addr is 0 at pass_start; a_addr_run is a_addr in
    // every other cycle (running: the node, or PAIR the row's even node, after vidx_q)
    wire [IW-1:0] v_run   = vrun_q;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [IW:0]   v_even  = {v_run, 1'b0};                   // PAIR: the row's nodes (the top bit is past K)
    /* verilator lint_on UNUSEDSIGNAL */
    wire [IW-1:0] a_addr_run = running_q ? (PAIR != 0 ? v_even[IW-1:0] : v_run) : a_idx;
    wire [IW-1:0] a_addr  = pass_start ? {IW{1'b0}} : a_addr_run;
    wire          a_re    = {1'b0, a_addr} < K_COUNT;
    wire          a_re_run = {1'b0, a_addr_run} < K_COUNT;
    wire [K-1:0]  pinned_q;       // the flags (below)
    reg           q_pin, q_grab;
    // pass_start comes from the frame's start (a command's decode): it chooses after the
    // K-way flag select, not before it
    always @(posedge clk)
        if (pass_start) begin
            q_pin  <= pinned_q[0];
            q_grab <= GRAB && grab_here && grab_idx == {IW{1'b0}};
        end else if (a_re_run) begin
            q_pin  <= pinned_q[a_addr_run];
            q_grab <= GRAB && grab_here && a_addr_run == grab_idx;
        end
    assign a_pinned = q_pin || q_grab;
    // the pass's words arrive with these flags (per way); the pair read is the pass's with PAIR
    wire [PAIR:0] v_pin, v_grab, v_has;
    wire          pair_re_i;
    wire [IW-1:0] pair_row_e_i, pair_row_o_i;
    generate
        if (PAIR != 0) begin : g_pass_pair
            wire          pass_rd = pass_start || running_q;  // the pass reads its next row
            wire [IW-1:0] v_step  = pass_start ? {IW{1'b0}} : v_run;
            // way 1: the row's odd node, its flags read like port A's (and whether it exists);
            // node 1 at pass_start, chosen after the flag select as on port A
            localparam [IW:0] ODD_FIRST = 1;
            /* verilator lint_off UNUSEDSIGNAL */
            wire [IW:0] v_odd = {v_run, 1'b1};
            /* verilator lint_on UNUSEDSIGNAL */
            reg q_pin1, q_grab1, q_has1;
            always @(posedge clk)
                if (pass_start) begin
                    q_has1  <= ODD_FIRST < K_COUNT;
                    q_pin1  <= ODD_FIRST < K_COUNT && pinned_q[ODD_FIRST[IW-1:0]];
                    q_grab1 <= GRAB && grab_here && ODD_FIRST[IW-1:0] == grab_idx;
                end else if (running_q) begin
                    q_has1  <= v_odd < K_COUNT;
                    q_pin1  <= v_odd < K_COUNT && pinned_q[v_odd[IW-1:0]];
                    q_grab1 <= GRAB && grab_here && v_odd[IW-1:0] == grab_idx;
                end
            assign v_pin  = {q_pin1, q_pin};
            assign v_grab = {q_grab1, q_grab};
            assign v_has  = {q_has1, 1'b1};
            assign pair_re_i    = pair_re || pass_rd;
            assign pair_row_e_i = pass_rd ? v_step : pair_row_e;
            assign pair_row_o_i = pass_rd ? v_step : pair_row_o;
        end else begin : g_pass_one
            assign v_pin  = q_pin;
            assign v_grab = q_grab;
            assign v_has  = 1'b1;
            assign pair_re_i    = pair_re;
            assign pair_row_e_i = pair_row_e;
            assign pair_row_o_i = pair_row_o;
        end
    endgenerate

    // ---- PAIR: the pair read's pinned (or held) flags, one per bank ----
    wire pair_pinned_e, pair_pinned_o, pair_held_e, pair_held_o;  // apart: the fused step tells them apart
    generate
        if (PAIR != 0) begin : g_pair_pins
            /* verilator lint_off UNUSEDSIGNAL */
            // a node index is the row and the bank bit; the row's top bit is past K
            wire [IW:0] node_e = {pair_row_e, 1'b0}, node_o = {pair_row_o, 1'b1};
            /* verilator lint_on UNUSEDSIGNAL */
            wire ok_e = node_e < K_COUNT, ok_o = node_o < K_COUNT;
            reg  pin_e_q, pin_o_q, held_e_q, held_o_q;
            always @(posedge clk)
                if (pair_re) begin
                    pin_e_q  <= ok_e && pinned_q[node_e[IW-1:0]];
                    pin_o_q  <= ok_o && pinned_q[node_o[IW-1:0]];
                    held_e_q <= ok_e && GRAB && grab_here && node_e[IW-1:0] == grab_idx;
                    held_o_q <= ok_o && GRAB && grab_here && node_o[IW-1:0] == grab_idx;
                end
            assign pair_pinned_e = pin_e_q;
            assign pair_pinned_o = pin_o_q;
            assign pair_held_e   = held_e_q;
            assign pair_held_o   = held_o_q;
            assign pair_pin_e    = pin_e_q || held_e_q;
            assign pair_pin_o    = pin_o_q || held_o_q;
        end else begin : g_no_pair_pins
            assign pair_pinned_e = 1'b0;
            assign pair_pinned_o = 1'b0;
            assign pair_held_e   = 1'b0;
            assign pair_held_o   = 1'b0;
            assign pair_pin_e    = 1'b0;
            assign pair_pin_o    = 1'b0;
        end
    endgenerate

    // ---- what arrives for the pass's step (declared above) ----
    generate
        if (FUSE != 0) begin : g_fuse_arrive
            // the fused sweep's read: registered with its rows, as the words arrive the cycle after
            reg          fuse_q, has_o_q;
            reg [IW-1:0] row_e_q, row_o_q;
            always @(posedge clk) begin
                fuse_q  <= !reset && pair_re && pair_fuse;
                has_o_q <= pair_has_o;
                row_e_q <= pair_row_e;
                row_o_q <= pair_row_o;
            end
            assign arrive     = running_q || fuse_q;
            assign arr_fused  = fuse_q;
            assign arr_ground = !fuse_q && ground_q;
            assign arr_idx    = fuse_q ? row_e_q : vidx_q;
            assign arr_idx1   = fuse_q ? row_o_q : vidx_q;
            assign arr_pin    = fuse_q ? {pair_pinned_o, pair_pinned_e} : v_pin;
            assign arr_grab   = fuse_q ? {pair_held_o, pair_held_e} : v_grab;
            assign arr_has    = fuse_q ? {has_o_q, 1'b1} : v_has;
        end else begin : g_walk_arrive
            assign arrive     = running_q;
            assign arr_fused  = 1'b0;
            assign arr_ground = ground_q;
            assign arr_idx    = vidx_q;
            assign arr_idx1   = vidx_q;
            assign arr_pin    = v_pin;
            assign arr_grab   = v_grab;
            assign arr_has    = v_has;
            wire unused_fuse = &{1'b0, pair_fuse, pair_has_o, pair_pinned_e, pair_pinned_o, pair_held_e, pair_held_o};
        end
    endgenerate

    // ---- writes: the pass's stage W, else port A's writer ----
    // The grabbed node (GRAB): the Verlet pass puts it on the pointer, px = its old x;
    // the ground pass leaves it alone.
    // per lane and way: touch[k (1 + PAIR) + way], hit likewise
    wire [DIM*(1+PAIR)-1:0] touch, hit;
    wire [PAIR:0]  in_touch, g_hit;
    genvar wy;
    generate
        for (wy = 0; wy <= PAIR; wy = wy + 1) begin : g_way_flags
            wire [DIM-1:0] touch_way, hit_way;
            genvar ax;
            for (ax = 0; ax < DIM; ax = ax + 1) begin : g_ax
                assign touch_way[ax] = touch[ax*(1+PAIR) + wy];
                assign hit_way[ax]   = hit[ax*(1+PAIR) + wy];
            end
            assign in_touch[wy] = mouse_down && &touch_way;
            assign g_hit[wy]    = |hit_way;    // only the normal axis's lane can hit
        end
    endgenerate
    wire           pass_we  = pass_w && !pin_w[0] && (!ground_w || (g_hit[0] && !grab_w[0]));
    /* verilator lint_off UNUSEDSIGNAL */
    wire [IW:0]    w_row    = {idx_w, 1'b0};  // PAIR: the written row's even and odd node (the top bit is past K)
    wire [IW:0]    w_row1   = {idx1_w, 1'b1};
    /* verilator lint_on UNUSEDSIGNAL */
    // FUSE: a fused step's positions go through write port 2, its node of the colour the sweep
    // does not move (the red one, of the first sweep's colour 0, the sweep writes through port 1
    // when its result comes); it writes both nodes' previous positions (and clears their
    // forces). RED_BANK: the bank of this unit's colour-0 nodes (node u K + x is colour x + u K
    // mod 2). pos1: port 1 takes the step's way 0, as in any other pass.
    localparam integer RED_I    = (UNIT_ID * K) % 2;
    localparam [0:0]   RED_BANK = RED_I[0:0];
    wire           pos1     = pass_w && !(FUSE != 0 && fused_w);
    wire           swap2    = FUSE != 0 && pass_w && fused_w && RED_BANK;  // port 2 takes way 0 (the black node is even)
    wire [IW-1:0]  widx     = pos1 ? (PAIR != 0 ? w_row[IW-1:0] : idx_w) : w_idx;
    wire           we       = ((pos1 && pass_we) || w_en) && {1'b0, widx} < K_COUNT;
    wire           wprev    = pass_w || w_at_rest;
    // A PIN reaches the flags through a register (pin_pend_q): the bus's address decode then
    // ends at a flip-flop of the unit, not in the walk's flag lookup across the device. So
    // the flags hold a PIN from the second cycle after its write (pin_pend_q says which PIN
    // is on its way there).
    reg           pin_pend_q;
    reg [IW-1:0]  pin_pend_idx_q;
    always @(posedge clk) begin
        pin_pend_q     <= !reset && pin_en;
        pin_pend_idx_q <= pin_idx;
    end
    // A pinned node starts at rest (w_pin is read only when w_at_rest). The lookup, a K-way
    // select over the flags, is kept off the memories' write data: a graph's NODE load
    // looks up rest_idx (= w_idx then) apart from w_idx's select among the four writers,
    // with the PIN on its way to the flags; a chain's init walk registers the flag of the
    // node it writes next (rest_idx), as the flags will hold it in that write's cycle
    // (with the PIN on its way); and node 0's flag, likewise, for the write of node 0
    // (rest_node0), whose lookup cannot come a cycle ahead: the walk starts at it, and the
    // command that starts it does not reach rest_idx (frame_ctrl).
    wire           w_pin;
    generate
        if (GRAPH) begin : g_load_pin
            assign w_pin = {1'b0, rest_idx} < K_COUNT && (pinned_q[rest_idx] || (pin_pend_q && pin_pend_idx_q == rest_idx));
            wire unused_node0 = &{1'b0, rest_node0};
        end else begin : g_walk_pin
            reg next_pin_q, node0_pin_q;
            always @(posedge clk)
                if (reset) begin
                    next_pin_q  <= 1'b0;
                    node0_pin_q <= 1'b0;
                end else begin
                    next_pin_q  <= {1'b0, rest_idx} < K_COUNT && (pinned_q[rest_idx] || (pin_pend_q && pin_pend_idx_q == rest_idx));
                    node0_pin_q <= pinned_q[0] || (pin_pend_q && pin_pend_idx_q == {IW{1'b0}});
                end
            assign w_pin = rest_node0 ? node0_pin_q : next_pin_q;
        end
    endgenerate
    // the previous positions' port 1: the pass's way 0, else the init walk and loads
    wire [IW-1:0]  pidx      = pass_w ? (PAIR != 0 ? w_row[IW-1:0] : idx_w) : w_idx;
    wire           pwe       = (FUSE != 0 ? (pass_w ? pass_we : w_en && w_at_rest) : (pass_we || w_en) && wprev) && {1'b0, pidx} < K_COUNT;
    // the force: the Verlet pass consumes node idx_w's (each way's), the init walk and loads clear node w_idx's
    wire           acc_clear = (pass_w && !ground_w) || (w_en && w_at_rest);
    // the second write port (PAIR): the pass's way 1 (FUSE, swap2: way 0), else the constraint pass's second write
    wire           pass_we2  = PAIR != 0 && pass_w && has_w[PAIR] && !pin_w[PAIR] && (!ground_w || (g_hit[PAIR] && !grab_w[PAIR]));
    wire [IW-1:0]  pidx2     = pass_w ? w_row1[IW-1:0] : w2_idx;
    wire [IW-1:0]  widx2     = swap2 ? w_row[IW-1:0] : pidx2;
    wire           we2       = PAIR != 0 && (pass_w ? (swap2 ? pass_we : pass_we2) : w2_en) && {1'b0, widx2} < K_COUNT;
    wire           pwe2      = PAIR != 0 && pass_w && pass_we2 && {1'b0, pidx2} < K_COUNT;
    wire           acc_clear2 = PAIR != 0 && pass_w && !ground_w && has_w[PAIR];
    wire [DIM*W-1:0] wdata, wdata2;
    wire [DIM*W-1:0] b_pos_raw;  // port B before the written flags
    // stage W's results, per lane and way (lane k at k (1 + PAIR) W, its way 1 W after): the
    // fused sweep's words (FUSE)
    wire [DIM*(1+PAIR)*W-1:0] step_pos, step_prev;

    // The in-touch box (EN_MOUSE, not GRAB): the unit's own registered copy (keep on the
    // process, which Yosys gives the flip-flops it makes: a keep on the reg marks the wire
    // only, and opt_merge then merges the units' equal flip-flops), so that frame_ctrl's box reaches every unit's
    // compares through a register beside them, not across the device in the compare's cycle
    // (that route set the clock of the largest build). The box is formed once a frame from
    // the pointer sampled at its start; its first test comes cycles later.
    wire [DIM*(W+1)-1:0] touch_lo_u, touch_hi_u;
    generate
        if (EN_MOUSE && !GRAB) begin : g_touch_copy
            reg [DIM*(W+1)-1:0] lo_q, hi_q;
            (* keep *) always @(posedge clk) begin
                lo_q <= touch_lo;
                hi_q <= touch_hi;
            end
            assign touch_lo_u = lo_q;
            assign touch_hi_u = hi_q;
        end else begin : g_no_touch_copy
            assign touch_lo_u = touch_lo;
            assign touch_hi_u = touch_hi;
        end
    endgenerate

    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            node_lane #(
`include "strand_params_pass.vh"
                , .AXIS(k)) u_lane (
                .clk(clk), .reset(reset),
                .a_re(a_re), .a_addr(a_addr), .b_addr(b_idx),
                .we(we), .widx(widx), .pos1(pos1), .pwe(pwe), .pidx(pidx),
                .acc_clear(acc_clear && {1'b0, pidx} < K_COUNT), .acc_clear_idx(pidx),
                .acc_we(acc_we && {1'b0, w_idx} < K_COUNT), .acc_w(acc_w[k*W +: W]),
                .pair_re(pair_re_i), .pair_row_e(pair_row_e_i), .pair_row_o(pair_row_o_i),
                .we2(we2), .widx2(widx2), .swap2(swap2), .pwe2(pwe2), .pidx2(pidx2),
                .acc_clear2(acc_clear2), .w2_pos(w2_pos[k*W +: W]),
                .stage_r(arrive), .stage_a(stage_a), .stage_b(stage_b), .stage_c(stage_c), .pass_w(pass_w), .ground_w(ground_w),
                .grab_w(grab_w), .pin_w(pin_w),
                .w_pin(w_pin),
                .w_pos(w_pos[k*W +: W]), .w_prev(w_prev[k*W +: W]),
                .impulse(impulse), .fx_consts(fx_consts),
                .touch_lo(touch_lo_u[k*(W+1) +: W+1]), .touch_hi(touch_hi_u[k*(W+1) +: W+1]),
                .mouse(mouse[k*W +: W]), .in_touch(in_touch), .ground(ground), .friction(friction),
                .q(a_pos[k*W +: W]), .qp(a_prev[k*W +: W]), .qa(a_acc[k*W +: W]), .b_data(b_pos_raw[k*W +: W]),
                .q_e(pair_pos_e[k*W +: W]), .q_o(pair_pos_o[k*W +: W]),
                .qp_e(pair_prev_e[k*W +: W]), .qp_o(pair_prev_o[k*W +: W]),
                .touch(touch[k*(1+PAIR) +: 1+PAIR]), .hit(hit[k*(1+PAIR) +: 1+PAIR]),
                .wdata(wdata[k*W +: W]), .wdata2(wdata2[k*W +: W]),
                .sweep_pos(step_pos[k*(1+PAIR)*W +: (1+PAIR)*W]), .sweep_prev(step_prev[k*(1+PAIR)*W +: (1+PAIR)*W]));
        end
    endgenerate

    // ---- the pinned and written flags, one decoder per node: a write at a variable bit
    // index (flags[idx] <= 1) synthesises to a mask shifted by the index, a carry chain
    // on the path from the write index that sets the clock. The write strobe is the
    // flags' one shared clock enable and the decoder's match goes into their data: an
    // iCE40 logic block's eight flip-flops share one enable, so a flag with an enable of
    // its own could not pack with the LUT before it (about 400 cells at K = 256) ----
    wire [K-1:0] written_q;
    genvar n;
    generate
        for (n = 0; n < K; n = n + 1) begin : g_flag
            localparam [IW-1:0] N_ID = n;
            reg pinned_n, written_n;
            always @(posedge clk)
                if (reset) begin
                    pinned_n  <= 1'b0;
                    written_n <= 1'b0;
                end else begin
                    if (pin_pend_q) pinned_n <= pinned_n  | (pin_pend_idx_q == N_ID);
                    if (we || we2)
                        written_n <= written_n | (PAIR != 0 ? (we && widx == N_ID) || (we2 && widx2 == N_ID) : widx == N_ID);
                end
            assign pinned_q[n]  = pinned_n;
            assign written_q[n] = written_n;
        end
    endgenerate

    // ---- port B: a node not written since reset reads as 0. The memory registers its word
    // once more (b_pos two cycles after b_idx; bank_ram B_REG), each bank's as the block RAM
    // gives it, so that the RAM's slow unregistered output reaches only a flip-flop; the
    // bank select, this mask and the core's selection over the units come after. (The word
    // registered after the bank select instead put the RAM's output, a long route and the
    // select on one path, which set the clock of the largest build.) ----
    // The written flag of b_idx is selected in two steps, one per cycle (the word takes two
    // cycles too): first, in each group of 2^B_LO flags, the flag at b_idx's low bits; then
    // the group at its high bits. The K-way select in one cycle, behind the host's read
    // address and its route to every unit, set the clock of the largest build. Both steps
    // read the flags as they stand when b_idx is given, as before.
    reg b_ok_r;  // the node was written, when b_idx was given (two cycles ago)
    generate
        if (IW >= 4) begin : g_b_ok_split
            localparam integer B_LO = IW / 2;        // low bits: the first step's select
            localparam integer B_HI = IW - B_LO;     // high bits: the group, the second's
            localparam integer PADDED = 1 << IW;
            /* verilator lint_off WIDTH */
            wire [PADDED-1:0] written_all = written_q;   // the flags past K read as 0
            /* verilator lint_on WIDTH */
            reg  [(1 << B_HI)-1:0] group_q;               // per group: the flag at the low bits
            reg  [B_HI-1:0]        b_hi_q;
            reg                    b_in_q;                // b_idx < K
            genvar g;
            for (g = 0; g < (1 << B_HI); g = g + 1) begin : g_group
                always @(posedge clk)
                    group_q[g] <= written_all[g * (1 << B_LO) + b_idx[B_LO-1:0]];
            end
            always @(posedge clk) begin
                b_hi_q <= b_idx[IW-1:B_LO];
                if (reset) begin
                    b_in_q <= 1'b0;
                    b_ok_r <= 1'b0;
                end else begin
                    b_in_q <= {1'b0, b_idx} < K_COUNT;
                    b_ok_r <= b_in_q && group_q[b_hi_q];
                end
            end
        end else begin : g_b_ok_one
            reg b_ok;  // a cycle after b_idx
            always @(posedge clk)
                if (reset) begin
                    b_ok   <= 1'b0;
                    b_ok_r <= 1'b0;
                end else begin
                    b_ok   <= {1'b0, b_idx} < K_COUNT && written_q[b_idx];
                    b_ok_r <= b_ok;
                end
        end
    endgenerate
    assign b_pos = b_ok_r ? b_pos_raw : {(DIM*W){1'b0}};

    // ---- FUSE: stage W's results, the fused sweep's words ----
    generate
        if (FUSE != 0) begin : g_pass_out
            genvar ax;
            for (ax = 0; ax < DIM; ax = ax + 1) begin : g_ax
                assign pass_pos_e[ax*W +: W]  = step_pos[ax*2*W +: W];
                assign pass_pos_o[ax*W +: W]  = step_pos[ax*2*W + W +: W];
                assign pass_prev_e[ax*W +: W] = step_prev[ax*2*W +: W];
                assign pass_prev_o[ax*W +: W] = step_prev[ax*2*W + W +: W];
            end
            assign pass_pin_e  = pin_w[0] || grab_w[0];
            assign pass_pin_o  = pin_w[PAIR] || grab_w[PAIR];
            assign pass_held_e = grab_w[0];
            assign pass_held_o = grab_w[PAIR];
        end else begin : g_no_pass_out
            assign pass_pos_e  = {(DIM*W){1'b0}};
            assign pass_pos_o  = {(DIM*W){1'b0}};
            assign pass_prev_e = {(DIM*W){1'b0}};
            assign pass_prev_o = {(DIM*W){1'b0}};
            assign {pass_pin_e, pass_pin_o, pass_held_e, pass_held_o} = 4'b0;
            wire unused_step = &{1'b0, step_pos, step_prev};
        end
    endgenerate

    // ---- the write-back lanes (DEBUG) ----
    generate
        if (DEBUG && PAIR != 0) begin : g_wb2
            reg             wb2_valid_q;
            reg [IW-1:0]    wb2_idx_q;
            reg [DIM*W-1:0] wb2_pos_q;
            always @(posedge clk) begin
                if (reset) begin
                    wb2_valid_q <= 1'b0;
                    wb2_idx_q   <= {IW{1'b0}};
                    wb2_pos_q   <= {(DIM*W){1'b0}};
                end else begin
                    wb2_valid_q <= we2;
                    if (we2) begin
                        wb2_idx_q <= widx2;
                        wb2_pos_q <= wdata2;
                    end
                end
            end
            assign wb_valid[PAIR] = wb2_valid_q;
            assign wb_idx[PAIR*IW +: IW] = wb2_idx_q;
            assign wb_pos[PAIR*DIM*W +: DIM*W] = wb2_pos_q;
        end else if (PAIR != 0) begin : g_no_wb2
            assign wb_valid[PAIR] = 1'b0;
            assign wb_idx[PAIR*IW +: IW] = {IW{1'b0}};
            assign wb_pos[PAIR*DIM*W +: DIM*W] = {(DIM*W){1'b0}};
            wire unused_wdata2 = &{1'b0, wdata2};
        end else begin : g_one_port
            wire unused_wdata2 = &{1'b0, wdata2};  // one write port: the lanes' second is 0
        end
        if (DEBUG) begin : g_wb
            reg             wb_valid_q;
            reg [IW-1:0]    wb_idx_q;
            reg [DIM*W-1:0] wb_pos_q;
            always @(posedge clk) begin
                if (reset) begin
                    wb_valid_q <= 1'b0;
                    wb_idx_q   <= {IW{1'b0}};
                    wb_pos_q   <= {(DIM*W){1'b0}};
                end else begin
                    // the lane changes only when a node is written
                    wb_valid_q <= we;
                    if (we) begin
                        wb_idx_q <= widx;
                        wb_pos_q <= wdata;
                    end
                end
            end
            assign wb_valid[0]        = wb_valid_q;
            assign wb_idx[0 +: IW]    = wb_idx_q;
            assign wb_pos[0 +: DIM*W] = wb_pos_q;
        end else begin : g_no_wb
            assign wb_valid[0]        = 1'b0;
            assign wb_idx[0 +: IW]    = {IW{1'b0}};
            assign wb_pos[0 +: DIM*W] = {(DIM*W){1'b0}};
            wire unused_wb = &{1'b0, wdata};
        end
    endgenerate

endmodule

`resetall
