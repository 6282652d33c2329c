`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * toward - the point at distance `rest_len` from P in the direction of C, or the
 * excess of C's distance from P over `rest_len`.
 *
 * Computes model/engine_body.h toward() (excess = 0) or the core of pair_edge()
 * (excess = 1): with d = C - P (saturating subtract, per axis),
 *     len = fx_sqrt(d.x^2 + d.y^2 [+ d.z^2])   radicand: exact 2W-bit sum of squares
 *     r   = fx_div(rest_len, len)       rest_len / len, unsigned, Q.F
 *     T   = P + d * r                   excess = 0: fx_mul (rounded ties-to-even), fx_add
 *     T   = d - d * r                   excess = 1: the excess e, fx_mul, fx_sub
 * valid = 0 when len = 0 (the divider's divide-by-zero flag): the caller skips T.
 *
 * Ports: p, c are DIM lanes of signed Q(W-F).F (lane k at bits k W +: W, x first);
 * rest_len unsigned Q(W-F).F (> 0); t as p.
 *
 * MANTISSA > 0 (the normalised datapath, model/fixed.h fx_along): t = d rest / |d| on
 * MANTISSA-bit mantissas, from toward_pipe (fx_along_pipe) taking this one operation;
 * done is high in cycle LATENCY = toward_pipe's latency + 1 (24 + 1: model/timing.c
 * hw_toward_latency), and the rest of the contract below (start, busy, t and valid held
 * until the next operation) is the same. The bit-serial datapath below is MANTISSA = 0.
 *
 * Datapath: one W x W multiplier, shared by the DIM squares and the DIM products
 * (its exact 2W-bit product for the squares, its rounded result for the products),
 * one fx_sqrt and one fx_div; the axis counter `ax` picks the lane. The multiplier
 * is pipelined: its operands are registered in the cycle an operation is issued, its
 * exact product in the next; a square is used (added to the squares) the cycle after;
 * a product is rounded (fx_round) and registered then, and used (added to form T[ax])
 * one cycle later. So a square issued in cycle c is used in cycle c + 2, a product in
 * cycle c + 3, and no path holds more than the multiply, the rounding or one add.
 *
 * Timing, fixed whatever the data (the cycle model mirrors it). Counting the
 * cycle in which start is high as cycle 0: cycles 1 .. DIM issue the squares of
 * d.x, d.y (and d.z); the last is used in cycle DIM + 2, which starts the square
 * root; the root is there in cycle SQRT_BITS+DIM+4 and starts the divider in that
 * cycle; the quotient is there DIV_BITS+2 cycles later; the next DIM cycles issue
 * the products d[ax] * r, the last used three cycles after; done is high in cycle
 * LATENCY = SQRT_BITS + DIV_BITS + 2 DIM + 10 (model/timing.c hw_toward_latency), for
 * one cycle. Each lane's result is new from the cycle after its product is used (lane
 * x from LATENCY - DIM + 1), the last lane's and valid from cycle LATENCY: read them
 * at done. They hold until the next operation forms them. start is accepted only
 * when idle or in the done cycle. Throughput: one operation per LATENCY + 1 cycles.
 */
module toward #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1, // quotient bits resolved
    parameter integer MANTISSA  = 0,     // 0: the bit-serial root and divide; 6 .. 20: the normalised datapath
    parameter integer DIM       = 2      // 2, or 3: a z lane
) (
    input  wire             clk,
    input  wire             reset,  // synchronous, active high
    input  wire             start,  // sample P, C, rest_len and excess
    input  wire             excess, // 0: T = P + d*r (centred rule), 1: T = d - d*r (pairwise rule)
    input  wire [DIM*W-1:0] p,
    input  wire [DIM*W-1:0] c,
    input  wire [W-1:0]     rest_len,
    output wire             busy,
    output wire             done,   // one-cycle pulse: t and valid are new
    output reg  [DIM*W-1:0] t,
    output reg              valid   // 0: zero length, no direction
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("toward: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(DIM_must_be_2_or_3, DIM == 2 || DIM == 3, ("toward: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    genvar k;
    generate
        if (MANTISSA > 0) begin : g_norm
            // one operation at a time through the pipelined normalised datapath
            reg              busy_q, done_q;
            wire             o_valid, o_ok;
            wire [DIM*W-1:0] o_t;
            /* verilator lint_off PINCONNECTEMPTY */
            // the tag, P and C are not needed: one operation is in flight
            toward_pipe #(.W(W), .F(F), .MANTISSA(MANTISSA), .DIM(DIM)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(start && !busy_q), .in_excess(excess),
                .in_p(p), .in_c(c), .in_rest(rest_len), .in_tag(1'b0),
                .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(), .out_p(), .out_c());
            /* verilator lint_on PINCONNECTEMPTY */
            always @(posedge clk) begin
                if (reset) begin
                    busy_q <= 1'b0;
                    done_q <= 1'b0;
                    t      <= {(DIM*W){1'b0}};
                    valid  <= 1'b0;
                end else begin
                    done_q <= o_valid;
                    if (o_valid) begin
                        busy_q <= 1'b0;
                        t      <= o_t;
                        valid  <= o_ok;
                    end
                    if (start && !busy_q) busy_q <= 1'b1;  // busy_q is low in the done cycle
                end
            end
            assign busy = busy_q;
            assign done = done_q;
        end else begin : g_serial
        localparam [2:0] S_IDLE  = 3'd0, // waiting for start
                         S_SQ    = 3'd1, // issue the square of d[ax]
                         S_ROOT  = 3'd2, // the squares are used, the root runs; then start the divider
                         S_DIV   = 3'd3, // wait for the quotient
                         S_MUL   = 3'd4, // issue d[ax] * r
                         S_DRAIN = 3'd5; // the products are used: T[ax] = P[ax] + d[ax] * r (or d[ax] - d[ax] * r)
        localparam integer DIM_LAST_I = DIM - 1;
        localparam [1:0]   DIM_LAST = DIM_LAST_I[1:0];

        reg [2:0]       state_q, state_d;
        reg [1:0]       ax_q, ax_d;       // the lane an operation is issued for
        reg             done_q, done_d;
        reg [DIM*W-1:0] d_q, p_q;
        reg [W-1:0]     rest_q, r_q;
        reg             excess_q;
        reg             dz_q;
        reg [2*W-1:0]   sq_q;             // the squares so far

        wire         ax_last = ax_q == DIM_LAST;
        wire [W-1:0] d_ax    = d_q[ax_q * W +: W];

        // ---- the multiplier pipeline: issue (operands registered), multiply (product
        // registered), use; each stage carries its operation's kind and lane ----
        wire         issue    = state_q == S_SQ || state_q == S_MUL;
        reg  [W-1:0] op_a, op_b;          // stage 1: the operands
        reg          s1_v, s1_sq;         //   valid, a square (else a product)
        reg  [1:0]   s1_ax;
        reg  [2*W-1:0] prod_q;            // stage 2: the exact product (a square is used here)
        reg          s2_v, s2_sq;
        reg  [1:0]   s2_ax;
        wire         s2_last  = s2_ax == DIM_LAST;
        reg  [W-1:0] round_q;             // stage 3: the rounded product (a product is used here)
        reg          s3_v;
        reg  [1:0]   s3_ax;
        wire         s3_last  = s3_ax == DIM_LAST;
        wire [W-1:0]   mul_round;
        wire [2*W-1:0] mul_exact;
        /* verilator lint_off PINCONNECTEMPTY */
        // the multiplier's saturation flag is not used: saturation is the result itself
        fx_mul #(.W(W), .F(F), .ROUND(1'b0)) u_mul (.a(op_a), .b(op_b), .y(), .prod(mul_exact), .sat());
        /* verilator lint_on PINCONNECTEMPTY */
        /* verilator lint_off PINCONNECTEMPTY */
        fx_round #(.W(W), .F(F)) u_round (.prod(prod_q), .y(mul_round), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        always @(posedge clk) begin
            if (reset) begin
                s1_v <= 1'b0;
                s2_v <= 1'b0;
            end else begin
                s1_v <= issue;
                s2_v <= s1_v;
                s3_v <= s2_v && !s2_sq;
            end
            // datapath: no reset (the valid bits say what is there)
            op_a    <= d_ax;
            op_b    <= state_q == S_MUL ? r_q : d_ax;
            s1_sq   <= state_q == S_SQ;
            s1_ax   <= ax_q;
            prod_q  <= mul_exact;
            s2_sq   <= s1_sq;
            s2_ax   <= s1_ax;
            round_q <= mul_round;
            s3_ax   <= s2_ax;
        end

        // ---- the lanes: d = C - P at start; one adder forms T[ax] from a used product ----
        wire [DIM*W-1:0] d_new;
        wire [W-1:0]     t_sum;
        wire [W-1:0]     d_s3 = d_q[s3_ax * W +: W];
        wire [W-1:0]     p_s3 = p_q[s3_ax * W +: W];
        /* verilator lint_off PINCONNECTEMPTY */
        // saturation flags are not needed: the saturated value is the result
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                fx_add #(.W(W), .SUB(1)) u_d (.sub(1'b1), .a(c[k*W +: W]), .b(p[k*W +: W]), .y(d_new[k*W +: W]), .sat());
            end
        fx_add #(.W(W)) u_t (.sub(excess_q), .a(excess_q ? d_s3 : p_s3), .b(round_q), .y(t_sum), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- square root and divider ----
        wire           use_sq     = s2_v && s2_sq;
        wire           use_prod   = s3_v;
        wire           sqrt_start = use_sq && s2_last;
        wire [2*W-1:0] radicand   = sq_q + prod_q; // each square <= 2^(2W-2), so a sum of three fits 2W bits
        wire           sqrt_done, div_done, div_zero;
        wire [W-1:0]   root, quot;
        /* verilator lint_off PINCONNECTEMPTY */
        // busy and saturation flags are not needed: the FSM counts on the fixed latency
        fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
            .clk(clk), .reset(reset), .start(sqrt_start), .radicand(radicand),
            .busy(), .done(sqrt_done), .result(root), .sat());
        fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_div (
            .clk(clk), .reset(reset), .start(state_q == S_ROOT && sqrt_done), .num(rest_q), .den(root),
            .busy(), .done(div_done), .result(quot), .div_by_zero(div_zero), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- control ----
        always @* begin
            state_d = state_q;
            ax_d    = ax_q;
            done_d  = 1'b0;
            case (state_q)
                S_IDLE:  if (start) begin state_d = S_SQ; ax_d = 2'd0; end
                S_SQ:    if (ax_last) state_d = S_ROOT; else ax_d = ax_q + 1'b1;
                S_ROOT:  if (sqrt_done) state_d = S_DIV;
                S_DIV:   if (div_done) begin state_d = S_MUL; ax_d = 2'd0; end
                S_MUL:   if (ax_last) state_d = S_DRAIN; else ax_d = ax_q + 1'b1;
                S_DRAIN: if (use_prod && s3_last) begin state_d = S_IDLE; done_d = 1'b1; end
                default: state_d = S_IDLE;
            endcase
        end

        always @(posedge clk) begin
            if (reset) begin
                state_q <= S_IDLE;
                ax_q    <= 2'd0;
                done_q  <= 1'b0;
                t       <= {(DIM*W){1'b0}};
                valid   <= 1'b0;
            end else begin
                state_q <= state_d;
                ax_q    <= ax_d;
                done_q  <= done_d;
                if (use_prod) t[s3_ax * W +: W] <= t_sum;
                if (use_prod && s3_last) valid <= !dz_q;
            end
        end

        // Datapath registers: written in their own state only, so no reset.
        always @(posedge clk) begin
            if (state_q == S_IDLE && start) begin
                d_q      <= d_new;
                p_q      <= p;
                excess_q <= excess;
                rest_q   <= rest_len;
            end
            if (use_sq) sq_q <= s2_ax == 2'd0 ? prod_q : radicand;
            if (state_q == S_DIV && div_done) begin
                r_q  <= quot;
                dz_q <= div_zero;
            end
        end

        assign busy = state_q != S_IDLE;
        assign done = done_q;
        end
    endgenerate

endmodule

`resetall
