`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * chain_sequencer - the constraint pass of reference 000 over a chain of M x K nodes.
 *
 * Walks C = node 0 .. N-1 (N = M x K) with registers uidx, nidx (C's unit and
 * node) and counter (nodes finished). It keeps a window of three nodes, U (the
 * previous node, already corrected), C and D (the next node), so each node costs
 * one storage read. For each C it asks the `toward` datapath for the point at
 * `rest_len` from U toward C, then for the point at `rest_len` from D toward C, and writes
 * C := their average (fx_avg), or the one that exists at a rope end or beside a
 * zero length; a pinned C is not written (model/engine_body.h centred_node()).
 * FEC = (counter == N). The pass repeats ITER times.
 *
 * With PROJECTION = 1 (projection = previous) the datapath is toward_prev, which also
 * takes the previous positions of both nodes (read with their positions, held in the
 * window beside them) and moves C along the direction the two had at the substep's start.
 *
 * Every node takes the same number of cycles, pinned, end or zero length alike,
 * so a pass takes 2 + N * (2 * LT + 2) cycles after the start cycle, LT being
 * the datapath's latency (docs/architecture.md derives it).
 *
 * Storage is read through the units' synchronous port A: rd_* address this cycle,
 * data (rd_pos, rd_pinned) next cycle. Positions are DIM lanes (lane k at bits
 * k W +: W); the window, the datapath and the average have one lane per axis.
 */
module chain_sequencer #(
`include "strand_params.vh"
) (
    input  wire          clk,
    input  wire          reset,      // synchronous, active high
    input  wire          start,      // one-cycle pulse: run ITER passes
    output reg           done,       // one-cycle pulse after the last pass
    input  wire [W-1:0]  rest_len,       // rest length

    output reg  [UW-1:0] rd_uidx,    // storage read address (combinational)
    output reg  [IW-1:0] rd_nidx,
    input  wire [DIM*W-1:0] rd_pos,  // its data, the next cycle
    input  wire          rd_pinned,
    input  wire [DIM*W-1:0] rd_prev, // and its previous position (PROJECTION)

    output reg           wr_en,      // write C
    output wire [UW-1:0] wr_uidx,
    output wire [IW-1:0] wr_nidx,
    output wire [DIM*W-1:0] wr_pos,

    output reg  [UW-1:0] uidx,       // C's unit
    output reg  [IW-1:0] nidx,       // C's node within the unit
    output reg  [CW-1:0] counter,    // nodes finished in this pass
    output wire          fec         // counter == M x K
);

    localparam integer N     = M * K;
    localparam integer ITW   = ITER > 1 ? $clog2(ITER) : 1;
    localparam integer N_LAST_I = N - 1;
    localparam integer ITER_LAST_I = ITER - 1;
    localparam [CW-1:0]  N_COUNT   = N[CW-1:0];
    localparam [CW-1:0]  N_LAST    = N_LAST_I[CW-1:0];
    localparam [ITW-1:0] ITER_LAST = ITER_LAST_I[ITW-1:0];

    `STRAND_CHECK(chain_sequencer_M_K, M >= 1 && K >= 1, ("chain_sequencer: M and K must be >= 1 (M=%0d K=%0d) in %m", M, K))
    `STRAND_CHECK(chain_sequencer_CW, (1 << CW) > N, ("chain_sequencer: CW=%0d cannot count to N=%0d in %m", CW, N))
    `STRAND_CHECK(chain_sequencer_UW_IW, (1 << UW) >= M && (1 << IW) >= K, ("chain_sequencer: UW/IW too narrow in %m"))
    `STRAND_CHECK(chain_sequencer_ITER, ITER >= 1, ("chain_sequencer: ITER must be >= 1 (ITER=%0d) in %m", ITER))

    localparam [2:0] S_IDLE   = 3'd0, // waiting for start; node 0 is addressed
                     S_LOAD_C = 3'd1, // node 0 arrives: C; node 1 is addressed
                     S_LOAD_D = 3'd2, // node 1 arrives: D
                     S_UP     = 3'd3, // ask for the point from U
                     S_UP_W   = 3'd4, // wait; on done ask for the point from D
                     S_DN_W   = 3'd5, // wait; on done take the new C; the node after D is addressed
                     S_NEXT   = 3'd6; // write C, slide the window (node 0 addressed after the last node)

    // Node 1 and node 2 as (unit, node) addresses.
    localparam integer N1_U_I = K > 1 ? 0 : 1;
    localparam integer N1_N_I = K > 1 ? 1 : 0;
    localparam integer N2_U_I = K > 2 ? 0 : K == 2 ? 1 : 2;
    localparam integer N2_N_I = K > 2 ? 2 : 0;
    localparam [UW-1:0] N1_U = N1_U_I[UW-1:0];
    localparam [IW-1:0] N1_N = N1_N_I[IW-1:0];
    localparam [UW-1:0] N2_U = N2_U_I[UW-1:0];
    localparam [IW-1:0] N2_N = N2_N_I[IW-1:0];
    localparam integer  TWO_I = 2;
    localparam [CW-1:0] TWO  = TWO_I[CW-1:0];  // (a one-node chain never looks that far)

`include "strand_addr.vh"

    // ---- registers ----
    reg [2:0]     state_q, state_d;
    reg [ITW-1:0] iter_q;
    reg [DIM*W-1:0] u_pos, c_pos, d_pos;    // the window U, C, D
    reg [DIM*W-1:0] u_prev, c_prev, d_prev; //   their previous positions (PROJECTION)
    reg           c_pin, d_pin, has_u, has_d;
    reg [DIM*W-1:0] up_pos;                 // the point from U
    reg           up_ok;
    reg [CW-1:0]  ahead;                    // index of the node after D
    reg [UW-1:0]  ahead_u;                  // and its address
    reg [IW-1:0]  ahead_n;

    wire last_node = counter == N_LAST;
    wire last_iter = iter_q == ITER_LAST;

    // ---- the datapath ----
    wire             t_done, t_valid;
    wire [DIM*W-1:0] t_pos;
    wire             t_start = state_q == S_UP || (state_q == S_UP_W && t_done);
    wire             from_u  = state_q == S_UP;
    /* verilator lint_off PINCONNECTEMPTY */
    // busy is not needed: the FSM waits for done
    generate
        if (PROJECTION) begin : g_previous
            toward_prev #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_toward (
                .clk(clk), .reset(reset), .start(t_start), .excess(1'b0),
                .p(from_u ? u_pos : d_pos), .c(c_pos), .pp(from_u ? u_prev : d_prev), .pc(c_prev),
                .rest_len(rest_len), .busy(), .done(t_done), .t(t_pos), .valid(t_valid));
        end else begin : g_current
            toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_toward (
                .clk(clk), .reset(reset), .start(t_start), .excess(1'b0),
                .p(from_u ? u_pos : d_pos), .c(c_pos), .rest_len(rest_len),
                .busy(), .done(t_done), .t(t_pos), .valid(t_valid));
            wire unused_prev = &{1'b0, u_prev, c_prev, d_prev};
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

    // The new C, valid in S_DN_W when t_done (the point from D is t_pos).
    wire             dn_ok = has_d && t_valid;
    wire [DIM*W-1:0] avg_pos;
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            fx_avg #(.W(W)) u_avg (.a(up_pos[k*W +: W]), .b(t_pos[k*W +: W]), .y(avg_pos[k*W +: W]));
        end
    endgenerate
    wire [DIM*W-1:0] new_pos = up_ok && dn_ok ? avg_pos : up_ok ? up_pos : dn_ok ? t_pos : c_pos;
    wire             moved   = (up_ok || dn_ok) && !c_pin;

    // ---- storage read address: data arrives the cycle after ----
    always @* begin
        rd_uidx = ahead_u;
        rd_nidx = ahead_n;
        case (state_q)
            S_IDLE:   begin rd_uidx = {UW{1'b0}}; rd_nidx = {IW{1'b0}}; end
            S_LOAD_C: begin rd_uidx = N1_U;       rd_nidx = N1_N;       end
            S_LOAD_D: begin rd_uidx = N2_U;       rd_nidx = N2_N;       end  // not yet in ahead_*
            S_NEXT:   if (last_node) begin rd_uidx = {UW{1'b0}}; rd_nidx = {IW{1'b0}}; end
            default:  ;
        endcase
    end

    // ---- next state ----
    always @* begin
        state_d = state_q;
        case (state_q)
            S_IDLE:   if (start) state_d = S_LOAD_C;
            S_LOAD_C: state_d = S_LOAD_D;
            S_LOAD_D: state_d = S_UP;
            S_UP:     state_d = S_UP_W;
            S_UP_W:   if (t_done) state_d = S_DN_W;
            S_DN_W:   if (t_done) state_d = S_NEXT;
            S_NEXT:   state_d = !last_node ? S_UP : last_iter ? S_IDLE : S_LOAD_C;
            default:  state_d = S_IDLE;
        endcase
    end

    // ---- control registers ----
    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            iter_q  <= {ITW{1'b0}};
            uidx    <= {UW{1'b0}};
            nidx    <= {IW{1'b0}};
            counter <= {CW{1'b0}};
            done    <= 1'b0;
            wr_en   <= 1'b0;
        end else begin
            state_q <= state_d;
            done    <= state_q == S_NEXT && last_node && last_iter;
            wr_en   <= state_q == S_DN_W && t_done && moved;
            if (state_q == S_IDLE && start) iter_q <= {ITW{1'b0}};
            if (state_q == S_NEXT && last_node && !last_iter) iter_q <= iter_q + 1'b1;
            if (state_q == S_LOAD_C) begin
                uidx    <= {UW{1'b0}};
                nidx    <= {IW{1'b0}};
                counter <= {CW{1'b0}};
            end
            if (state_q == S_NEXT) begin
                counter <= counter + 1'b1;
                if (!last_node) {uidx, nidx} <= next_node({uidx, nidx});
            end
        end
    end

    // ---- the window and the datapath registers (each written in its own state) ----
    always @(posedge clk) begin
        case (state_q)
            S_LOAD_C: begin
                c_pos <= rd_pos;
                c_prev <= rd_prev;
                c_pin <= rd_pinned;
                has_u <= 1'b0;
            end
            S_LOAD_D: begin
                d_pos   <= rd_pos;
                d_prev  <= rd_prev;
                d_pin   <= rd_pinned;
                has_d   <= N > 1;
                ahead   <= TWO;
                ahead_u <= N2_U;
                ahead_n <= N2_N;
            end
            S_UP_W: if (t_done) begin
                up_pos <= t_pos;
                up_ok  <= has_u && t_valid;
            end
            S_DN_W: if (t_done && moved) c_pos <= new_pos;  // a pinned C stays where it is, in the window too
            S_NEXT: begin
                u_pos <= c_pos;
                u_prev <= c_prev;
                has_u <= 1'b1;
                c_pos <= d_pos;
                c_prev <= d_prev;
                c_pin <= d_pin;
                has_d <= ahead < N_COUNT;
                d_pos <= rd_pos;
                d_prev <= rd_prev;
                d_pin <= rd_pinned;
                ahead <= ahead + 1'b1;
                {ahead_u, ahead_n} <= next_node({ahead_u, ahead_n});
            end
            default: ;
        endcase
    end

    // C's write: the cycle after its new position is known (S_NEXT).
    assign wr_uidx = uidx;
    assign wr_nidx = nidx;
    assign wr_pos  = c_pos;
    assign fec     = counter == N_COUNT;

endmodule

`resetall
