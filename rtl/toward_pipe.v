`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * toward_pipe - toward, pipelined: a new (P, C, rest) every clock, its result a fixed
 * number of cycles later.
 *
 * Computes exactly what toward computes (and model/engine_body.h toward() and the core
 * of pair_edge()): with d = C - P (saturating, per axis) and t = d rest / |d|, the vector
 * of length rest along d (model/engine_fixed.c along),
 *     T = P + t          excess = 0 (the centred rule's point)
 *     T = d - t          excess = 1 (the pairwise rule's excess)
 * ok = 0 when |d| = 0: the caller skips T. t comes from one of two datapaths:
 *
 * MANTISSA = 0, the full-width root and divide (model/fixed.h fx_sqrt, fx_div, fx_mul):
 *     len = fx_sqrt(d.x^2 + d.y^2 [+ d.z^2])   the exact 2W-bit sum of exact squares
 *     r   = fx_div(rest, len),   t = round(d * r)
 * The root and the divider are fx_sqrt_pipe and fx_div_pipe, the restoring digit-by-digit
 * root and divide of fx_sqrt and fx_div unrolled into one stage per resolved bit (so
 * SQRT_BITS and DIV_BITS stay the accuracy knobs, and the results are those of the
 * serial datapath bit for bit). Every other step has a stage of its own, so no path
 * holds more than a half-word sum and one multiplier block, one 2W-bit sum, one root or
 * divide stage, the rounding or one W-bit add: the W x W multiplies are fx_mul_pipe
 * (three partial products, then their sum). The multipliers are not shared: DIM for the
 * squares, DIM for the products.
 *
 * MANTISSA = MB > 0, the normalised datapath (model/fixed.h fx_along): t from
 * fx_along_pipe, on MB-bit mantissas that share one exponent, a reciprocal root from a
 * seed table and one Newton step; SQRT_BITS and DIV_BITS do not matter.
 *
 * Stages, counting the cycle in which an operation is on the inputs as cycle 0:
 *   1 d = C - P
 *   MANTISSA = 0:  2, 3 the squares        4 their sum (the radicand)
 *                  5 .. LSQ + 5            the root (fx_sqrt_pipe, latency LSQ)
 *                  LSQ + 6 ..              the quotient (fx_div_pipe, latency LDV)
 *                  LSQ + LDV + 7, + 8      the products d * r      + 9   their rounding
 *   MANTISSA > 0:  2 .. LA + 2             fx_along_pipe (latency LA = 21)
 *   LATENCY - 1   T                        LATENCY  on the outputs
 * LSQ = ceil((SQRT_BITS + 1) / STEPS) + 1 and LDV = ceil((DIV_BITS + 1) / STEPS) + 1
 * (pipe_latency.vh), so LATENCY = LSQ + LDV + 11 (SQRT_BITS + DIV_BITS + 15 with STEPS =
 * 1), or LA + 3 = 24 with a mantissa (model/timing.c hw_toward_pipe_latency): an operation
 * on the inputs in cycle 0 has out_valid, out_t, out_ok and out_tag in cycle LATENCY.
 * Throughput one operation per clock; no operation waits for another.
 *
 * P, d, rest and the caller's tag (and C, with CARRY) ride beside the root and the
 * divider in delay_line rings (LUT or block RAM), not in a register per stage.
 *
 * Ports: p, c are DIM lanes of signed Q(W-F).F (lane k at bits k W +: W); rest unsigned
 * Q(W-F).F; tag: TAG_W bits the caller gets back with the result. Only the valid bits
 * are reset. With IN_REG = 0 every input but in_valid comes in cycle 1, from the
 * caller's registers (which then are this pipe's first stage).
 */
module toward_pipe #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,      // 0: the full-width root and divide; 6 .. 20: fx_along_pipe
    parameter integer STEPS     = 1,      // root and divide iterations a pipeline stage
    parameter integer DIM       = 2,
    parameter integer TAG_W     = 1,
    parameter [0:0]   CARRY     = 1'b0,   // 1: P and C come out beside T (out_p, out_c)
    parameter [0:0]   IN_REG    = 1'b1,   // 0: the caller's registers are cycle 1's (below)
    parameter integer BLOCK_MIN = 64      // delay rings: strand_ram's block RAM threshold
) (
    input  wire             clk,
    input  wire             reset,        // synchronous, active high: the valid bits
    input  wire             in_valid,
    input  wire             in_excess,    // 0: T = P + d*r, 1: T = d - d*r
    input  wire [DIM*W-1:0] in_p,
    input  wire [DIM*W-1:0] in_c,
    input  wire [W-1:0]     in_rest,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output reg  [DIM*W-1:0] out_t,
    output reg              out_ok,       // 0: zero length, no direction
    output reg  [TAG_W-1:0] out_tag,
    output wire [DIM*W-1:0] out_p,        // CARRY: the operation's P and C (else 0)
    output wire [DIM*W-1:0] out_c
);

    `STRAND_CHECK(toward_pipe_W, W >= 8 && W <= 32, ("toward_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(toward_pipe_DIM, DIM == 2 || DIM == 3, ("toward_pipe: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

`include "pipe_latency.vh"
    localparam integer LSQ     = sqrt_pipe_latency(SQRT_BITS, STEPS);
    localparam integer LDV     = div_pipe_latency(DIV_BITS, STEPS);
    localparam integer LATENCY = MANTISSA > 0 ? along_pipe_latency(MANTISSA) + 3 : LSQ + LDV + 11;
    localparam integer T_DIV   = LSQ + 6;                   // cycle the divider's operands are on its inputs
    localparam integer T_MUL   = LSQ + LDV + 7;             // cycle the quotient is there
    localparam integer CW_     = CARRY ? DIM * W : 1;       // C in the ring (CARRY), else one unused bit
    localparam integer SIDE_W  = CW_ + TAG_W + 1 + 2 * DIM * W;   // [C], tag, excess, P, d
    // the streams time their writes by pipe_latency.vh: it must count these stages
    `STRAND_CHECK(toward_pipe_latency_formula, LATENCY == toward_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA),
                  ("toward_pipe: its stages (%0d) and pipe_latency.vh (%0d) disagree in %m", LATENCY,
                   toward_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA)))

    // ---- the valid bits: bit i is the operation in cycle i + 1 ----
    reg [LATENCY-1:0] v_q;
    always @(posedge clk)
        if (reset) v_q <= {LATENCY{1'b0}};
        else v_q <= {v_q[LATENCY-2:0], in_valid};
    assign out_valid = v_q[LATENCY-1];

    // ---- cycle 1: d = C - P ----
    // IN_REG = 0: the caller registers P, C, rest, the tag and excess itself and gives them
    // in cycle 1 (in_valid still in cycle 0), so that it can choose among registered words
    // there; the latency is the same
    reg [DIM*W-1:0] p1, c1, c2;
    reg [W-1:0]     rest1;
    reg [TAG_W-1:0] tag1;
    reg             excess1;
    generate
        if (IN_REG) begin : g_in_reg
            always @(posedge clk) {p1, c1, rest1, tag1, excess1} <= {in_p, in_c, in_rest, in_tag, in_excess};
        end else begin : g_in_late
            always @* {p1, c1, rest1, tag1, excess1} = {in_p, in_c, in_rest, in_tag, in_excess};
        end
    endgenerate
    wire [DIM*W-1:0] d1;
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_d
            /* verilator lint_off PINCONNECTEMPTY */
            fx_add #(.W(W), .SUB(1)) u_d (.sub(1'b1), .a(c1[k*W +: W]), .b(p1[k*W +: W]), .y(d1[k*W +: W]), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
        end
    endgenerate

    // ---- cycle 2: d, P, rest and the tag registered, into the datapath and the rings ----
    reg [DIM*W-1:0] d2, p2;
    reg [W-1:0]     rest2;
    reg [TAG_W-1:0] tag2;
    reg             excess2;
    always @(posedge clk) begin
        d2      <= d1;
        p2      <= p1;
        c2      <= c1;
        rest2   <= rest1;
        tag2    <= tag1;
        excess2 <= excess1;
    end

    // ---- cycle LATENCY - 1: t (rounded into Q.F) and the operation's other values, from
    // either datapath; T; LATENCY: the outputs ----
    wire [DIM*W-1:0] t_f, p_f, d_f;
    wire [CW_-1:0]   c_f;
    wire [TAG_W-1:0] tag_f;
    wire             excess_f, ok_f;
    generate
        if (MANTISSA > 0) begin : g_norm
            // fx_along_pipe from cycle 2; the operation's values in a ring to cycle LATENCY - 1
            wire [SIDE_W-1:0] side;
            wire              ok_a;
            fx_along_pipe #(.W(W), .MB(MANTISSA), .DIM(DIM), .BLOCK_MIN(BLOCK_MIN)) u_along (
                .clk(clk), .reset(reset), .d(d2), .rest(rest2), .t(t_f), .ok(ok_a));
            delay_line #(.WIDTH(SIDE_W), .DELAY(LATENCY - 3), .BLOCK_MIN(BLOCK_MIN)) u_side_ring (
                .clk(clk), .reset(reset), .in({CARRY ? c2[CW_-1:0] : {CW_{1'b0}}, tag2, excess2, p2, d2}), .out(side));
            assign {c_f, tag_f, excess_f, p_f, d_f} = side;
            assign ok_f = ok_a;
        end else begin : g_full
            // ---- cycle 2: the squares start (two cycles); P, d, rest and the tag enter their rings ----
            wire [DIM*2*W-1:0] sq4;  // the exact squares, in cycle 4 (a square is summed unrounded)
            for (k = 0; k < DIM; k = k + 1) begin : g_sq
                fx_mul_pipe #(.W(W)) u_sq (.clk(clk), .a(d2[k*W +: W]), .b(d2[k*W +: W]), .prod(sq4[k*2*W +: 2*W]));
            end
            wire [W-1:0]      rest_div;
            wire [SIDE_W-1:0] side;
            delay_line #(.WIDTH(W), .DELAY(T_DIV - 2), .BLOCK_MIN(BLOCK_MIN)) u_rest_ring (
                .clk(clk), .reset(reset), .in(rest2), .out(rest_div));
            delay_line #(.WIDTH(SIDE_W), .DELAY(T_MUL - 2), .BLOCK_MIN(BLOCK_MIN)) u_side_ring (
                .clk(clk), .reset(reset), .in({CARRY ? c2[CW_-1:0] : {CW_{1'b0}}, tag2, excess2, p2, d2}), .out(side));

            // ---- cycle 4: the radicand (each square <= 2^(2W-2): three fit 2W bits) ----
            reg [2*W-1:0] radicand5;
            always @(posedge clk)
                radicand5 <= sq4[0 +: 2*W] + sq4[2*W +: 2*W] + (DIM == 3 ? sq4[(DIM-1)*2*W +: 2*W] : {2*W{1'b0}});

            // ---- cycles 5 .. : the root, then the quotient ----
            wire [W-1:0] len, ratio;
            wire         dz;
            /* verilator lint_off PINCONNECTEMPTY */
            // saturation flags: the saturated value is the result
            fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS), .STEPS(STEPS)) u_sqrt (.clk(clk), .radicand(radicand5), .result(len), .sat());
            fx_div_pipe #(.W(W), .F(F), .DIV_BITS(DIV_BITS), .STEPS(STEPS)) u_div (
                .clk(clk), .num(rest_div), .den(len), .result(ratio), .div_by_zero(dz), .sat());
            /* verilator lint_on PINCONNECTEMPTY */

            // ---- cycle T_MUL: the products d * r start (two cycles); at T_MUL + 2 their
            // rounding, registered (cycle T_MUL + 3 = LATENCY - 1); the operation's other values
            // follow in s1 .. s3 ----
            wire [CW_-1:0]   c_m      = side[SIDE_W-1 -: CW_];
            wire [TAG_W-1:0] tag_m    = side[SIDE_W-CW_-1 -: TAG_W];
            wire             excess_m = side[2*DIM*W];
            wire [DIM*W-1:0] p_m      = side[DIM*W +: DIM*W];
            wire [DIM*W-1:0] d_m      = side[0 +: DIM*W];
            reg  [DIM*W-1:0] p_s1, p_s2, p_s3, d_s1, d_s2, d_s3, round_s3;
            reg  [CW_-1:0]   c_s1, c_s2, c_s3;
            reg  [TAG_W-1:0] tag_s1, tag_s2, tag_s3;
            reg              excess_s1, excess_s2, excess_s3, dz_s1, dz_s2, dz_s3;
            wire [DIM*2*W-1:0] prod_s2;
            wire [DIM*W-1:0] round_s2;
            for (k = 0; k < DIM; k = k + 1) begin : g_prod
                fx_mul_pipe #(.W(W)) u_mul (.clk(clk), .a(d_m[k*W +: W]), .b(ratio), .prod(prod_s2[k*2*W +: 2*W]));
                /* verilator lint_off PINCONNECTEMPTY */
                fx_round #(.W(W), .F(F)) u_round (.prod(prod_s2[k*2*W +: 2*W]), .y(round_s2[k*W +: W]), .sat());
                /* verilator lint_on PINCONNECTEMPTY */
            end
            always @(posedge clk) begin
                {p_s1, d_s1, c_s1, tag_s1, excess_s1, dz_s1} <= {p_m, d_m, c_m, tag_m, excess_m, dz};
                {p_s2, d_s2, c_s2, tag_s2, excess_s2, dz_s2} <= {p_s1, d_s1, c_s1, tag_s1, excess_s1, dz_s1};
                {p_s3, d_s3, c_s3, tag_s3, excess_s3, dz_s3} <= {p_s2, d_s2, c_s2, tag_s2, excess_s2, dz_s2};
                round_s3 <= round_s2;
            end
            assign {t_f, p_f, d_f, c_f, tag_f, excess_f} = {round_s3, p_s3, d_s3, c_s3, tag_s3, excess_s3};
            assign ok_f = !dz_s3;
        end
    endgenerate

    reg [DIM*W-1:0] p_out;
    reg [CW_-1:0]   c_out;
    wire [DIM*W-1:0] t_sum;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_t
            /* verilator lint_off PINCONNECTEMPTY */
            fx_add #(.W(W), .SUB(-1)) u_t (.sub(excess_f), .a(excess_f ? d_f[k*W +: W] : p_f[k*W +: W]),
                                          .b(t_f[k*W +: W]), .y(t_sum[k*W +: W]), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
        end
    endgenerate
    always @(posedge clk) begin
        out_t   <= t_sum;
        out_ok  <= ok_f;
        out_tag <= tag_f;
        p_out   <= p_f;
        c_out   <= c_f;
    end

    generate
        if (CARRY) begin : g_carry
            assign out_p = p_out;
            assign out_c = c_out;
        end else begin : g_no_carry
            assign out_p = {(DIM*W){1'b0}};
            assign out_c = {(DIM*W){1'b0}};
            wire unused_carry = &{1'b0, p_out, c_out, c2};
        end
    endgenerate

endmodule

`resetall
