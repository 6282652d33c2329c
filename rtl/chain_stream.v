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
 * constraints one by one. The sweep drains (its last write lands) before the next
 * one reads: the hazard between colours is avoided by time, and the sweep's length is
 * fixed, whatever the data.
 *
 * A sweep, counting its first cycle as t = 0 (every unit in step; LT is toward_pipe's
 * latency, model/timing.c hw_toward_pipe_latency):
 *   t = 0        port A reads node K-1: the left neighbour's of the next unit
 *   t = 1 .. K   port A reads node t-1; its data arrive at t+1
 *   t = 1        each unit takes its left neighbour's node K-1 (left)
 *   t = 2        each unit takes its right neighbour's node 0 (right)
 *   t = x + 2    slot x = 0 .. K: node x arrives (slot K: right), node x-1 is the
 *                previous arrival (slot 0: left); the slot issues at most one operation:
 *      centred:  node x of this colour: the point at rest from x-1 toward x ("up");
 *                else node x-1 of this colour: the point from x toward x-1 ("down").
 *                A node's two results leave the pipe on consecutive cycles; the second
 *                forms the node (fx_avg of both, or the one that exists), written the
 *                cycle after; a pinned (or held) node is not written.
 *      pairwise: the link (x-1, x) of this colour: its excess e (toward_pipe excess
 *                mode, P and C carried along), a += e/2 and b -= e/2 (a fixed end:
 *                the other takes e; both fixed or a zero length: nothing); a is
 *                written the cycle after the result, b the cycle after that. A link
 *                across a unit border is computed by both units alike, and each
 *                writes its own end.
 *   The last write lands in cycle K + LT + 3; the next sweep starts at t = S =
 *   K + LT + 4. done is high the cycle after the last sweep (2 ITER sweeps a pass).
 * Global node g = u K + x has colour g mod 2; node 0 has no up, node N-1 no down (the
 * operation runs and its result is dropped), so every sweep takes the same time.
 *
 * Observation (DEBUG): uidx is the sweep's colour, nidx port A's address, counter
 * the slots issued in this sweep (0 .. K+1), FEC = every slot issued.
 *
 * Ports: port A of every unit at one address (rd_idx; data the next cycle, per unit
 * in rd_pos_all, rd_pin_all: pinned or held); one write per unit per cycle at most
 * (wr_en[u], wr_idx_all, wr_pos_all).
 */
module chain_stream #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,      // synchronous, active high
    input  wire             start,      // one-cycle pulse: run ITER passes
    output reg              done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]     rest_len,

    output reg  [IW-1:0]    rd_idx,     // port A address of every unit
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
    localparam integer S      = K + LT + 4;                    // a sweep's cycles
    localparam integer TW     = $clog2(S + 1);
    localparam integer XW     = IW + 1;                        // a slot number, 0 .. K
    localparam integer ITW    = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer TAG_W  = XW + 4;                      // x, down, exists, a's pin, b's pin
    localparam integer S_LAST_I = S - 1, K_I = K, K1_I = K + 1, K2_I = K + 2, ITER_LAST_I = ITER - 1;
    localparam [TW-1:0]  S_LAST  = S_LAST_I[TW-1:0];
    localparam [TW-1:0]  T_K     = K_I[TW-1:0];
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
    wire          sweep_end = running && t == S_LAST;
    wire          slot = running && t >= 2 && t <= T_K2;  // slot x = t - 2 is issued
    localparam [TW-1:0] T_TWO = 2;
    /* verilator lint_off UNUSEDSIGNAL */
    // a slot number needs the low bits only
    wire [TW-1:0] t_minus_2 = t - T_TWO;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [XW-1:0] x = t_minus_2[XW-1:0];
    wire          take_left  = running && t == 1;
    wire          take_right = running && t == 2;

    wire          last      = colour && iter_q == ITER_LAST;
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

    // port A: node K-1 first, then node 0 .. K-1
    /* verilator lint_off UNUSEDSIGNAL */
    // an address needs the low bits only
    wire [TW-1:0] t_minus_1 = t - 1'b1;
    /* verilator lint_on UNUSEDSIGNAL */
    always @* begin
        if (!running || t > T_K) rd_idx = {IW{1'b0}};
        else if (t == {TW{1'b0}}) rd_idx = K_LAST;
        else rd_idx = t_minus_1[IW-1:0];
    end


    assign uidx = {{(UW-1){1'b0}}, colour};
    assign nidx = rd_idx;
    assign fec  = counter == SLOTS;

    // ---- the units ----
    genvar u;
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam integer U_PAR_I = (u * K) % 2;
            localparam [0:0] U_PAR = U_PAR_I[0:0];     // colour of the unit's node 0
            localparam [0:0] FIRST = u == 0;          // node 0 of the chain is here
            localparam [0:0] FINAL = u == M - 1;      // node N-1 is here

            wire [DW-1:0] own     = rd_pos_all[u*DW +: DW];
            wire [DW-1:0] own_pv  = rd_prev_all[u*DW +: DW];
            wire          own_pin = rd_pin_all[u];
            reg  [DW-1:0] left_q, right_q, prev_q;
            reg  [DW-1:0] left_pv, right_pv, prev_pv;               // their previous positions (PROJECTION)
            reg           left_pin, right_pin, prev_pin;
            wire          at_k    = x == X_K;
            wire          at_0    = x == {XW{1'b0}};
            wire [DW-1:0] arr     = at_k ? right_q : own;       // node x
            wire [DW-1:0] arr_pv  = at_k ? right_pv : own_pv;
            wire          arr_pin = at_k ? right_pin : own_pin;
            wire [DW-1:0] prv     = at_0 ? left_q : prev_q;     // node x-1
            wire [DW-1:0] prv_pv  = at_0 ? left_pv : prev_pv;
            wire          prv_pin = at_0 ? left_pin : prev_pin;
            wire          col_x   = U_PAR ^ x[0];               // colour of node x
            always @(posedge clk) begin
                if (take_left) begin
                    left_q   <= u > 0 ? rd_pos_all[(u > 0 ? u - 1 : 0)*DW +: DW] : {DW{1'b0}};
                    left_pv  <= u > 0 ? rd_prev_all[(u > 0 ? u - 1 : 0)*DW +: DW] : {DW{1'b0}};
                    left_pin <= u > 0 && rd_pin_all[u > 0 ? u - 1 : 0];
                end
                if (take_right) begin
                    right_q   <= u < M - 1 ? rd_pos_all[(u < M - 1 ? u + 1 : u)*DW +: DW] : {DW{1'b0}};
                    right_pv  <= u < M - 1 ? rd_prev_all[(u < M - 1 ? u + 1 : u)*DW +: DW] : {DW{1'b0}};
                    right_pin <= u < M - 1 && rd_pin_all[u < M - 1 ? u + 1 : u];
                end
                if (slot) begin
                    prev_q   <= arr;
                    prev_pv  <= arr_pv;
                    prev_pin <= arr_pin;
                end
            end

            // the operation of slot x
            reg           op_valid, op_down, op_exists, op_pin_a, op_pin_b;
            reg [DW-1:0]  op_p, op_c, op_pp, op_pc;  // P, C and their previous positions
            always @* begin
                op_down   = 1'b0;
                op_pin_a  = prv_pin;
                op_pin_b  = arr_pin;
                if (RULE == 0) begin
                    if (col_x == colour) begin            // up: node x from x-1 (none at slot K)
                        op_valid  = slot && !at_k;
                        op_p      = prv;
                        op_c      = arr;
                        op_pp     = prv_pv;
                        op_pc     = arr_pv;
                        op_exists = !(FIRST && at_0);
                        op_pin_b  = arr_pin;              // the node's pin
                    end else begin                        // down: node x-1 from x
                        op_valid  = slot && !at_0;
                        op_down   = 1'b1;
                        op_p      = arr;
                        op_c      = prv;
                        op_pp     = arr_pv;
                        op_pc     = prv_pv;
                        op_exists = !(FINAL && at_k);
                        op_pin_b  = prv_pin;
                    end
                end else begin                            // the link (x-1, x)
                    op_valid  = slot && col_x != colour;
                    op_p      = prv;
                    op_c      = arr;
                    op_pp     = prv_pv;
                    op_pc     = arr_pv;
                    op_exists = !(FIRST && at_0) && !(FINAL && at_k);
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
            // a node index (x - 1 < K)
            wire [XW-1:0] o_x_m1   = o_x - 1'b1;
            /* verilator lint_on UNUSEDSIGNAL */

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
                    wr_idx_q <= o_x_m1[IW-1:0];
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
                // b waits a cycle: results come every other cycle, so the write port is free then
                reg          b_en;
                reg [IW-1:0] b_idx;
                reg [DW-1:0] b_pos;
                always @(posedge clk) begin
                    if (o_valid) begin
                        wr_idx_q <= o_x_m1[IW-1:0];
                        wr_pos_q <= new_a;
                        b_idx    <= o_x[IW-1:0];
                        b_pos    <= new_b;
                    end else begin
                        wr_idx_q <= b_idx;
                        wr_pos_q <= b_pos;
                    end
                    if (reset) begin
                        wr_en_q <= 1'b0;
                        b_en    <= 1'b0;
                    end else if (o_valid) begin
                        wr_en_q <= ok && !o_pin_a && o_x != {XW{1'b0}};   // a is this unit's from x = 1
                        b_en    <= ok && !o_pin_b && o_x != X_K;          // b is this unit's up to x = K-1
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
