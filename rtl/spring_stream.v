`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * spring_stream - the pipelined spring pass over a chain of M x K nodes (ARCH = 1 with
 * EN_SPRINGS): every unit streams its own links through its own spring_force_pipe, one
 * spring a clock.
 *
 * Order: the springs' forces depend on positions and previous positions only, which the
 * spring pass does not write, so every link of the chain can be in flight at once; only
 * the gathering of the forces has an order. A node i takes -F from the link (i-1, i) and
 * then +F from (i, i+1), saturating, as model/engine_body.h spring_edge() gathers them
 * link after link. Each unit issues its links in that order and keeps the node between
 * its two results in a register (`carry`), so a node's force is written once, final, and
 * no write waits for a read.
 *
 * A pass is one sweep; counting its first cycle as t = 0 (every unit in step; LS is
 * spring_force_pipe's latency, model/timing.c hw_spring_pipe_latency):
 *   t = 0        port A reads node K-1: the left neighbour's of the next unit
 *   t = 1 .. K   port A reads node t-1 (position, previous position, force); data at t+1
 *   t = 1        each unit takes its left neighbour's node K-1 (left)
 *   t = 2        each unit takes its right neighbour's node 0 (right)
 *   t = x + 2    slot x = 0 .. K issues the link (x-1, x): node x-1 (slot 0: left) is A,
 *                node x (slot K: right) is B; the link before the chain's first node and
 *                the one after its last do not exist (they issue, and their force is 0)
 *   t = x + 2 + LS  its force F (0 for a zero length): node x-1's force becomes
 *                carry + F and is written the cycle after (x >= 1); carry becomes node
 *                x's force (read with it) - F.
 * The last write lands in cycle K + LS + 3; done is high the cycle after (S = K + LS + 4
 * cycles, model/timing.c hw_spring_sweep). A link across a unit border is computed by
 * both units alike, and each gathers it into its own end.
 *
 * Observation: uidx 0, nidx port A's address, counter the slots issued (0 .. K+1).
 *
 * Ports: port A of every unit at one address (rd_idx; data the next cycle, per unit in
 * rd_pos_all, rd_prev_all, rd_acc_all); one force write per unit per cycle at most
 * (wr_en[u], wr_idx_all, wr_acc_all).
 */
module spring_stream #(
`include "strand_params.vh"
) (
    input  wire               clk,
    input  wire               reset,      // synchronous, active high
    input  wire               start,      // one-cycle pulse: run the pass
    output reg                done,       // one-cycle pulse after it
    input  wire [W-1:0]       rest_len,
    input  wire [W-1:0]       ks,
    input  wire [W-1:0]       kd,

    output reg  [IW-1:0]      rd_idx,     // port A address of every unit
    input  wire [M*DIM*W-1:0] rd_pos_all,
    input  wire [M*DIM*W-1:0] rd_prev_all,
    input  wire [M*DIM*W-1:0] rd_acc_all,

    output wire [M-1:0]       wr_en,
    output wire [M*IW-1:0]    wr_idx_all,
    output wire [M*DIM*W-1:0] wr_acc_all,

    output wire [UW-1:0]      uidx,       // observation: 0
    output wire [IW-1:0]      nidx,       //   port A's address
    output reg  [CW-1:0]      counter     //   slots issued
);

    localparam integer DW    = DIM * W;
`include "pipe_latency.vh"
    localparam integer LS    = spring_pipe_latency(SQRT_BITS, DIV_BITS, PIPE_STEPS, MANTISSA);  // spring_force_pipe's latency
    localparam integer S     = K + LS + 4;                  // the sweep's cycles
    localparam integer TW    = $clog2(S + 1);
    localparam integer XW    = IW + 1;                      // a slot number, 0 .. K
    localparam integer TAG_W = DW + XW + 1;                 // B's force, x, the link exists
    localparam integer S_LAST_I = S - 1, K_I = K, K2_I = K + 2;
    localparam [TW-1:0] S_LAST = S_LAST_I[TW-1:0];
    localparam [TW-1:0] T_K    = K_I[TW-1:0];
    localparam [TW-1:0] T_K2   = K2_I[TW-1:0];
    localparam [XW-1:0] X_K    = K_I[XW-1:0];
    localparam integer  K_LAST_I = K - 1;
    localparam [IW-1:0] K_LAST = K_LAST_I[IW-1:0];

    `STRAND_CHECK(spring_stream_CW, (1 << CW) > K + 1, ("spring_stream: CW=%0d cannot count K+1=%0d slots in %m", CW, K + 1))

    // ---- the sweep ----
    reg          running;
    reg [TW-1:0] t;
    wire         sweep_end = running && t == S_LAST;
    wire         slot      = running && t >= 2 && t <= T_K2;   // slot x = t - 2 is issued
    localparam [TW-1:0] T_TWO = 2;
    /* verilator lint_off UNUSEDSIGNAL */
    // a slot number and an address need the low bits only
    wire [TW-1:0] t_minus_2 = t - T_TWO;
    wire [TW-1:0] t_minus_1 = t - 1'b1;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [XW-1:0] x          = t_minus_2[XW-1:0];
    wire          take_left  = running && t == 1;
    wire          take_right = running && t == 2;
    always @(posedge clk) begin
        if (reset) begin
            running <= 1'b0;
            t       <= {TW{1'b0}};
            done    <= 1'b0;
            counter <= {CW{1'b0}};
        end else begin
            done <= sweep_end;
            if (start && !running) begin
                running <= 1'b1;
                t       <= {TW{1'b0}};
                counter <= {CW{1'b0}};
            end else if (sweep_end) begin
                running <= 1'b0;
                t       <= {TW{1'b0}};
                counter <= {CW{1'b0}};
            end else if (running) begin
                t <= t + 1'b1;
                if (slot) counter <= counter + 1'b1;
            end
        end
    end

    // port A: node K-1 first, then node 0 .. K-1
    always @* begin
        if (!running || t > T_K) rd_idx = {IW{1'b0}};
        else if (t == {TW{1'b0}}) rd_idx = K_LAST;
        else rd_idx = t_minus_1[IW-1:0];
    end
    assign uidx = {UW{1'b0}};
    assign nidx = rd_idx;

    // ---- the units ----
    genvar u, k;
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam [0:0] FIRST = u == 0;          // node 0 of the chain is here
            localparam [0:0] FINAL = u == M - 1;      // node N-1 is here
            localparam integer UL = u > 0 ? u - 1 : 0, UR = u < M - 1 ? u + 1 : u;

            wire [DW-1:0] own_pos  = rd_pos_all[u*DW +: DW];
            wire [DW-1:0] own_prev = rd_prev_all[u*DW +: DW];
            wire [DW-1:0] own_acc  = rd_acc_all[u*DW +: DW];
            reg  [DW-1:0] left_pos, left_prev, right_pos, right_prev, last_pos, last_prev;
            wire          at_k     = x == X_K;
            wire          at_0     = x == {XW{1'b0}};
            wire [DW-1:0] b_pos    = at_k ? right_pos : own_pos;     // node x
            wire [DW-1:0] b_prev   = at_k ? right_prev : own_prev;
            wire [DW-1:0] a_pos    = at_0 ? left_pos : last_pos;     // node x-1
            wire [DW-1:0] a_prev   = at_0 ? left_prev : last_prev;
            always @(posedge clk) begin
                if (take_left) begin
                    left_pos  <= rd_pos_all[UL*DW +: DW];
                    left_prev <= rd_prev_all[UL*DW +: DW];
                end
                if (take_right) begin
                    right_pos  <= rd_pos_all[UR*DW +: DW];
                    right_prev <= rd_prev_all[UR*DW +: DW];
                end
                if (slot) begin
                    last_pos  <= b_pos;
                    last_prev <= b_prev;
                end
            end
            wire exists = !(FIRST && at_0) && !(FINAL && at_k);

            wire             o_valid, o_ok;
            wire [DW-1:0]    o_f;
            wire [TAG_W-1:0] o_tag;
            spring_force_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(PIPE_STEPS), .DIM(DIM), .TAG_W(TAG_W),
                                .BLOCK_MIN(RAM_BLOCK_MIN)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(slot),
                .in_a(a_pos), .in_ap(a_prev), .in_b(b_pos), .in_bp(b_prev), .in_rest(rest_len),
                .in_ks(ks), .in_kd(kd), .in_tag({own_acc, x, exists}),
                .out_valid(o_valid), .out_f(o_f), .out_ok(o_ok), .out_tag(o_tag));
            wire [DW-1:0] o_acc    = o_tag[TAG_W-1 -: DW];    // node x's force so far (x < K)
            wire [XW-1:0] o_x      = o_tag[1 +: XW];
            wire          o_exists = o_tag[0];
            wire [DW-1:0] force_a  = o_ok && o_exists ? o_f : {DW{1'b0}};  // + 0 and - 0 change nothing
            /* verilator lint_off UNUSEDSIGNAL */
            // a node index (x - 1 < K)
            wire [XW-1:0] o_x_m1   = o_x - 1'b1;
            /* verilator lint_on UNUSEDSIGNAL */

            // node x-1 = carry + F (written next cycle); carry = node x's force - F
            reg  [DW-1:0] carry, wr_acc_q;
            reg  [IW-1:0] wr_idx_q;
            reg           wr_en_q;
            wire [DW-1:0] a_sum, b_sum;
            /* verilator lint_off PINCONNECTEMPTY */
            // saturation flags: the saturated value is the result
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                fx_add #(.W(W), .SUB(0)) u_a (.sub(1'b0), .a(carry[k*W +: W]), .b(force_a[k*W +: W]), .y(a_sum[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(1)) u_b (.sub(1'b1), .a(o_acc[k*W +: W]), .b(force_a[k*W +: W]), .y(b_sum[k*W +: W]), .sat());
            end
            /* verilator lint_on PINCONNECTEMPTY */
            always @(posedge clk) begin
                if (o_valid) begin
                    carry    <= b_sum;
                    wr_acc_q <= a_sum;
                    wr_idx_q <= o_x_m1[IW-1:0];
                end
                if (reset) wr_en_q <= 1'b0;
                else wr_en_q <= o_valid && o_x != {XW{1'b0}};   // node x-1 is this unit's from x = 1
            end
            assign wr_en[u] = wr_en_q;
            assign wr_idx_all[u*IW +: IW] = wr_idx_q;
            assign wr_acc_all[u*DW +: DW] = wr_acc_q;
        end
    endgenerate

endmodule

`resetall
