`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * chain_stream - the pipelined constraint pass over a chain of M x K nodes (ARCH = 1):
 * every unit streams its own nodes through its own toward_pipe, one constraint a clock.
 *
 * Order (red/black, model/engine_body.h with order = redblack): a pass is two sweeps,
 * the even nodes (centred rule) or the links (2j, 2j+1) (pairwise), then the odd ones.
 * Within a sweep no two constraints share a node, and every constraint reads only
 * nodes its sweep does not write (the other colour) and the node(s) it writes itself,
 * so the whole sweep can be in flight at once and the result is the one of taking its
 * constraints one by one.
 *
 * Directions: even units stream their nodes upward (0 .. K-1), odd units downward
 * (K-1 .. 0), so the two nodes of every unit border are taken at the same time: both
 * first (the border between an odd unit and the next) or both last (an even unit and
 * the next). In a unit's stream order (position s = the node, or K-1-node downward)
 * every node is written a fixed time after it is read, the later the further along the
 * stream, and the next sweep reads it as far along again: so the next sweep may start
 * long before this one drains. Its start waits only for the toward_pipe latency (a
 * node written LT + 4 cycles after its position's read, read again LT + 4 later at
 * the earliest) and for this sweep's slots (port A and the pipe's input are each used
 * once a cycle). The order within a colour does not change a result.
 *
 * A sweep, counting its first cycle as t = 0 (every unit in step; LT is toward_pipe's
 * latency, model/timing.c hw_toward_pipe_latency):
 *   t = 1 .. K   port A reads stream position t-1 (rd_idx upward, rd_idx_down in odd
 *                units); its data arrive at t+1
 *   t = s + 2    slot s = 0 .. K: position s arrives (slot K: "after", the neighbour
 *                across the stream's end, its position K-1, held since t = K+1);
 *                position s-1 is the previous arrival (slot 0: "before", the
 *                neighbour across the stream's start, its position 0, arriving now);
 *                the slot issues at most one operation:
 *      centred:  position s of this colour: the point at rest from s-1 toward s ("up");
 *                else position s-1 of this colour: the point from s toward s-1 ("down").
 *                A node's two results leave the pipe on consecutive cycles; the second
 *                forms the node (fx_avg of both, or the one that exists), written the
 *                cycle after; a pinned (or held) node is not written.
 *      pairwise: the link between positions s-1 and s, if it has this colour (its lower
 *                node's: position s-1 upward, s downward): its excess e
 *                (toward_pipe excess mode along the chain: from the lower node a to
 *                the higher b, P and C carried along), a += e/2 and b -= e/2 (a fixed
 *                end: the other takes e; both fixed or a zero length: nothing);
 *                position s-1 is written the cycle after the result, position s the
 *                cycle after that. A link across a unit border is computed by both
 *                units alike, and each writes its own end.
 *   Position s is written in cycle s + LT + 4 at the latest. The next sweep starts at
 *   t = SP = max(K + 3, LT + 4) (its first read, t = 1, comes after position 0's write;
 *   its slots after this sweep's last, t = K + 2), so sweeps overlap by their drain;
 *   the last sweep of the pass runs to t = SL - 1, SL = K + LT + 4 (its last write lands
 *   in cycle K + LT + 3), and done is high the cycle after (2 ITER sweeps a pass:
 *   (2 ITER - 1) SP + SL cycles).
 * Global node g = u K + x has colour g mod 2; the chain's end nodes have one neighbour
 * (the operation runs and its result is dropped), so every sweep takes the same time.
 *
 * Observation (DEBUG): uidx is the sweep's colour, nidx port A's upward address,
 * counter the slots issued in this sweep (0 .. K+1), FEC = every slot issued.
 *
 * Ports: port A of the even units at rd_idx, of the odd units at rd_idx_down (data the
 * next cycle, per unit in rd_pos_all, rd_pin_all: pinned or held); one write per unit
 * per cycle at most (wr_en[u], wr_idx_all, wr_pos_all).
 */
module chain_stream #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,      // synchronous, active high
    input  wire             start,      // one-cycle pulse: run ITER passes
    output reg              done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]     rest_len,

    output reg  [IW-1:0]    rd_idx,     // port A address of the even units (upward)
    output reg  [IW-1:0]    rd_idx_down, //   and of the odd ones (downward)
    input  wire [M*DIM*W-1:0] rd_pos_all,
    input  wire [M-1:0]     rd_pin_all,
    input  wire [M*DIM*W-1:0] rd_prev_all, // PROJECTION: the previous positions, read with them

    output wire [M-1:0]     wr_en,
    output wire [M*IW-1:0]  wr_idx_all,
    output wire [M*DIM*W-1:0] wr_pos_all,

    output wire [UW-1:0]    uidx,       // observation: the colour
    output wire [IW-1:0]    nidx,       //   port A's address
    output reg  [CW-1:0]    counter,    //   slots issued in this sweep
    output wire             fec         //   every slot of the sweep issued
);

    localparam integer DW     = DIM * W;
    localparam integer LT     = PROJECTION ? 2 * SQRT_BITS + DIV_BITS + 34   // toward_prev_pipe's latency
                                           : SQRT_BITS + DIV_BITS + 15;      // toward_pipe's
    localparam integer SP     = K + 3 > LT + 4 ? K + 3 : LT + 4; // a sweep's cycles before the next
    localparam integer SL     = K + LT + 4;                    // the last sweep's, to its last write
    localparam integer TW     = $clog2(SL + 1);
    localparam integer XW     = IW + 1;                        // a slot number, 0 .. K
    localparam integer ITW    = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer TAG_W  = XW + 4;                      // s, down, exists, a's pin, b's pin
    localparam integer SP_LAST_I = SP - 1, SL_LAST_I = SL - 1, K_I = K, K1_I = K + 1, K2_I = K + 2;
    localparam integer ITER_LAST_I = ITER - 1;
    localparam [TW-1:0]  SP_LAST = SP_LAST_I[TW-1:0];
    localparam [TW-1:0]  SL_LAST = SL_LAST_I[TW-1:0];
    localparam [TW-1:0]  T_K     = K_I[TW-1:0];
    localparam [TW-1:0]  T_K1    = K1_I[TW-1:0];
    localparam [TW-1:0]  T_K2    = K2_I[TW-1:0];
    localparam [XW-1:0]  X_K     = K_I[XW-1:0];
    localparam [CW-1:0]  SLOTS   = K1_I[CW-1:0];
    localparam [ITW-1:0] ITER_LAST = ITER_LAST_I[ITW-1:0];
    localparam integer   K_LAST_I = K - 1;
    localparam [IW-1:0]  K_LAST  = K_LAST_I[IW-1:0];

    `STRAND_CHECK(chain_stream_CW, (1 << CW) > K + 1, ("chain_stream: CW=%0d cannot count K+1=%0d slots in %m", CW, K + 1))

    // ---- the sweeps ----
    reg           running;
    reg [TW-1:0]  t;
    reg           colour;
    reg [ITW-1:0] iter_q;
    wire          last      = colour && iter_q == ITER_LAST;  // the pass's last sweep
    wire          sweep_end = running && t == (last ? SL_LAST : SP_LAST);
    wire          slot = running && t >= 2 && t <= T_K2;  // slot s = t - 2 is issued
    localparam [TW-1:0] T_TWO = 2;
    /* verilator lint_off UNUSEDSIGNAL */
    // a slot number needs the low bits only
    wire [TW-1:0] t_minus_2 = t - T_TWO;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [XW-1:0] x = t_minus_2[XW-1:0];
    wire          take_after = running && t == T_K1;  // the neighbour's position K-1 arrives

    always @(posedge clk) begin
        if (reset) begin
            running <= 1'b0;
            t       <= {TW{1'b0}};
            colour  <= 1'b0;
            iter_q  <= {ITW{1'b0}};
            done    <= 1'b0;
            counter <= {CW{1'b0}};
        end else begin
            done <= sweep_end && last;
            if (start && !running) begin
                running <= 1'b1;
                t       <= {TW{1'b0}};
                colour  <= 1'b0;
                iter_q  <= {ITW{1'b0}};
                counter <= {CW{1'b0}};
            end else if (sweep_end) begin
                t       <= {TW{1'b0}};
                counter <= {CW{1'b0}};
                if (last) running <= 1'b0;
                colour <= !colour;
                if (colour) iter_q <= iter_q + 1'b1;
            end else if (running) begin
                t <= t + 1'b1;
                if (slot) counter <= counter + 1'b1;
            end
        end
    end

    // port A: stream positions 0 .. K-1 at t = 1 .. K (upward in even units, downward in odd)
    /* verilator lint_off UNUSEDSIGNAL */
    // an address needs the low bits only
    wire [TW-1:0] t_minus_1 = t - 1'b1;
    /* verilator lint_on UNUSEDSIGNAL */
    always @* begin
        if (!running || t == {TW{1'b0}} || t > T_K) begin
            rd_idx      = {IW{1'b0}};
            rd_idx_down = {IW{1'b0}};
        end else begin
            rd_idx      = t_minus_1[IW-1:0];
            rd_idx_down = K_LAST - t_minus_1[IW-1:0];
        end
    end

    assign uidx = {{(UW-1){1'b0}}, colour};
    assign nidx = rd_idx;
    assign fec  = counter == SLOTS;

    // ---- the units ----
    genvar u;
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam [0:0] DOWN  = u % 2 == 1;       // the unit streams K-1 .. 0
            // colour of stream position 0: node 0, or node K-1 downward
            localparam integer S_PAR_I = (u * K + (u % 2 == 1 ? K - 1 : 0)) % 2;
            localparam [0:0] S_PAR = S_PAR_I[0:0];
            // the neighbours across the stream's start and end (upward: u-1 and u+1)
            localparam integer BEFORE_U = u % 2 == 1 ? u + 1 : u - 1;
            localparam integer AFTER_U  = u % 2 == 1 ? u - 1 : u + 1;
            localparam [0:0] HAS_BEFORE = BEFORE_U >= 0 && BEFORE_U < M;
            localparam [0:0] HAS_AFTER  = AFTER_U >= 0 && AFTER_U < M;
            localparam integer BEFORE_I = HAS_BEFORE ? BEFORE_U : u;  // (an index in range)
            localparam integer AFTER_I  = HAS_AFTER ? AFTER_U : u;

            wire [DW-1:0] own     = rd_pos_all[u*DW +: DW];
            wire [DW-1:0] own_pv  = rd_prev_all[u*DW +: DW];
            wire          own_pin = rd_pin_all[u];
            // nb_first: the neighbour's position 0, read with ours (slot 0 only)
            wire [DW-1:0] nb_first     = HAS_BEFORE ? rd_pos_all[BEFORE_I*DW +: DW] : {DW{1'b0}};
            wire [DW-1:0] nb_first_pv  = HAS_BEFORE ? rd_prev_all[BEFORE_I*DW +: DW] : {DW{1'b0}};
            wire          nb_first_pin = HAS_BEFORE && rd_pin_all[BEFORE_I];
            reg  [DW-1:0] after_q, prev_q;
            reg  [DW-1:0] after_pv, prev_pv;               // their previous positions (PROJECTION)
            reg           after_pin, prev_pin;
            wire          at_k    = x == X_K;
            wire          at_0    = x == {XW{1'b0}};
            wire [DW-1:0] arr     = at_k ? after_q : own;       // position s
            wire [DW-1:0] arr_pv  = at_k ? after_pv : own_pv;
            wire          arr_pin = at_k ? after_pin : own_pin;
            wire [DW-1:0] prv     = at_0 ? nb_first : prev_q;     // position s-1
            wire [DW-1:0] prv_pv  = at_0 ? nb_first_pv : prev_pv;
            wire          prv_pin = at_0 ? nb_first_pin : prev_pin;
            wire          col_x   = S_PAR ^ x[0];               // colour of position s
            always @(posedge clk) begin
                if (take_after) begin
                    after_q   <= HAS_AFTER ? rd_pos_all[AFTER_I*DW +: DW] : {DW{1'b0}};
                    after_pv  <= HAS_AFTER ? rd_prev_all[AFTER_I*DW +: DW] : {DW{1'b0}};
                    after_pin <= HAS_AFTER && rd_pin_all[AFTER_I];
                end
                if (slot) begin
                    prev_q   <= arr;
                    prev_pv  <= arr_pv;
                    prev_pin <= arr_pin;
                end
            end

            // the operation of slot s (x)
            reg           op_valid, op_down, op_exists, op_pin_a, op_pin_b;
            reg [DW-1:0]  op_p, op_c, op_pp, op_pc;  // P, C and their previous positions
            always @* begin
                op_down   = 1'b0;
                op_pin_a  = prv_pin;
                op_pin_b  = arr_pin;
                if (RULE == 0) begin
                    if (col_x == colour) begin            // up: position s from s-1 (none at slot K)
                        op_valid  = slot && !at_k;
                        op_p      = prv;
                        op_c      = arr;
                        op_pp     = prv_pv;
                        op_pc     = arr_pv;
                        op_exists = !(!HAS_BEFORE && at_0);
                        op_pin_b  = arr_pin;              // the node's pin
                    end else begin                        // down: position s-1 from s
                        op_valid  = slot && !at_0;
                        op_down   = 1'b1;
                        op_p      = arr;
                        op_c      = prv;
                        op_pp     = arr_pv;
                        op_pc     = prv_pv;
                        op_exists = !(!HAS_AFTER && at_k);
                        op_pin_b  = prv_pin;
                    end
                end else begin                            // the link (s-1, s), from its lower node a
                    // a link has its lower node's colour: position s-1 upward, s downward
                    op_valid  = slot && (DOWN ? col_x == colour : col_x != colour);
                    op_p      = DOWN ? arr : prv;
                    op_c      = DOWN ? prv : arr;
                    op_pp     = DOWN ? arr_pv : prv_pv;
                    op_pc     = DOWN ? prv_pv : arr_pv;
                    op_pin_a  = DOWN ? arr_pin : prv_pin;
                    op_pin_b  = DOWN ? prv_pin : arr_pin;
                    op_exists = !(!HAS_BEFORE && at_0) && !(!HAS_AFTER && at_k);
                end
            end

            wire             o_valid, o_ok;
            wire [DW-1:0]    o_t, o_p, o_c;
            wire [TAG_W-1:0] o_tag;
            if (PROJECTION) begin : g_previous
                toward_prev_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W),
                                   .CARRY(RULE == 1), .BLOCK_MIN(RAM_BLOCK_MIN)) u_pipe (
                    .clk(clk), .reset(reset), .in_valid(op_valid), .in_excess(RULE == 1),
                    .in_p(op_p), .in_c(op_c), .in_pp(op_pp), .in_pc(op_pc), .in_rest(rest_len),
                    .in_tag({x, op_down, op_exists, op_pin_a && RULE == 1, op_pin_b}),
                    .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(o_tag), .out_p(o_p), .out_c(o_c));
            end else begin : g_current
                toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM), .TAG_W(TAG_W),
                              .CARRY(RULE == 1), .BLOCK_MIN(RAM_BLOCK_MIN)) u_pipe (
                    .clk(clk), .reset(reset), .in_valid(op_valid), .in_excess(RULE == 1),
                    .in_p(op_p), .in_c(op_c), .in_rest(rest_len), .in_tag({x, op_down, op_exists, op_pin_a && RULE == 1, op_pin_b}),
                    .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(o_tag), .out_p(o_p), .out_c(o_c));
                wire unused_prev = &{1'b0, op_pp, op_pc};
            end
            wire [XW-1:0] o_x      = o_tag[TAG_W-1 -: XW];
            wire          o_down   = o_tag[3];
            wire          o_exists = o_tag[2];
            wire          o_pin_a  = o_tag[1];
            wire          o_pin_b  = o_tag[0];
            wire          ok       = o_valid && o_ok && o_exists;
            /* verilator lint_off UNUSEDSIGNAL */
            // node indices need the low bits only (positions s-1 and s are < K where written)
            wire [XW-1:0] o_x_m1   = o_x - 1'b1;
            wire [XW-1:0] o_x_up   = X_K - o_x;                 // K - s: position s-1 downward
            wire [XW-1:0] o_x_dn   = X_K - 1'b1 - o_x;          // K-1-s: position s downward
            /* verilator lint_on UNUSEDSIGNAL */
            wire [IW-1:0] node_s_m1 = DOWN ? o_x_up[IW-1:0] : o_x_m1[IW-1:0];  // the node at position s-1

            reg           wr_en_q;
            reg [IW-1:0]  wr_idx_q;
            reg [DW-1:0]  wr_pos_q;
            genvar k;
            if (RULE == 0) begin : g_centred
                reg          up_ok;
                reg [DW-1:0] up_t;
                wire [DW-1:0] avg;
                for (k = 0; k < DIM; k = k + 1) begin : g_lane
                    fx_avg #(.W(W)) u_avg (.a(up_t[k*W +: W]), .b(o_t[k*W +: W]), .y(avg[k*W +: W]));
                end
                always @(posedge clk) begin
                    if (o_valid && !o_down) begin
                        up_t  <= o_t;
                        up_ok <= ok;
                    end
                    wr_idx_q <= node_s_m1;
                    wr_pos_q <= up_ok && ok ? avg : up_ok ? up_t : o_t;
                    if (reset) wr_en_q <= 1'b0;
                    else wr_en_q <= o_valid && o_down && (up_ok || ok) && !o_pin_b;
                end
                wire unused_c = &{1'b0, o_pin_a, o_p, o_c};
            end else begin : g_pairwise
                wire [DW-1:0] half, new_a, new_b;
                /* verilator lint_off PINCONNECTEMPTY */
                // saturation flags: the saturated value is the result
                for (k = 0; k < DIM; k = k + 1) begin : g_lane
                    fx_avg #(.W(W)) u_half (.a(o_t[k*W +: W]), .b({W{1'b0}}), .y(half[k*W +: W]));
                    fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(o_p[k*W +: W]),
                                                  .b(o_pin_b ? o_t[k*W +: W] : half[k*W +: W]), .y(new_a[k*W +: W]), .sat());
                    fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(o_c[k*W +: W]),
                                                  .b(o_pin_a ? o_t[k*W +: W] : half[k*W +: W]), .y(new_b[k*W +: W]), .sat());
                end
                /* verilator lint_on PINCONNECTEMPTY */
                // position s-1 is written first, position s waits a cycle: results come every
                // other cycle, so the write port is free then. Upward a is at s-1, downward at s.
                wire [IW-1:0] node_s   = DOWN ? o_x_dn[IW-1:0] : o_x[IW-1:0];  // the node at position s
                wire [DW-1:0] new_s_m1 = DOWN ? new_b : new_a;
                wire [DW-1:0] new_s    = DOWN ? new_a : new_b;
                wire          pin_s_m1 = DOWN ? o_pin_b : o_pin_a;
                wire          pin_s    = DOWN ? o_pin_a : o_pin_b;
                reg          b_en;
                reg [IW-1:0] b_idx;
                reg [DW-1:0] b_pos;
                always @(posedge clk) begin
                    if (o_valid) begin
                        wr_idx_q <= node_s_m1;
                        wr_pos_q <= new_s_m1;
                        b_idx    <= node_s;
                        b_pos    <= new_s;
                    end else begin
                        wr_idx_q <= b_idx;
                        wr_pos_q <= b_pos;
                    end
                    if (reset) begin
                        wr_en_q <= 1'b0;
                        b_en    <= 1'b0;
                    end else if (o_valid) begin
                        wr_en_q <= ok && !pin_s_m1 && o_x != {XW{1'b0}};   // position s-1 is this unit's from s = 1
                        b_en    <= ok && !pin_s && o_x != X_K;             // position s up to s = K-1
                    end else begin
                        wr_en_q <= b_en;
                        b_en    <= 1'b0;
                    end
                end
                wire unused_down = &{1'b0, o_down};
            end
            assign wr_en[u] = wr_en_q;
            assign wr_idx_all[u*IW +: IW] = wr_idx_q;
            assign wr_pos_all[u*DW +: DW] = wr_pos_q;
        end
    endgenerate

endmodule

`resetall
