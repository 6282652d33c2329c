`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_mul - fixed-point multiply, rounded to nearest (ties to even), saturated.
 *
 * Computes  y = sat(round(a * b / 2^F))  mirroring fx_mul() in model/fixed.h.
 *
 * Ports:   a, b, y are signed two's complement Q(W-F).F, W bits; prod is the
 *          exact signed 2W-bit product a * b, before rounding.
 * Algorithm: p = a * b, the exact signed 2W-bit product (Q(2W-2F).2F), then
 *          fx_round: p / 2^F rounded to nearest (ties to even) and clamped to the
 *          W-bit range (fx_round.v has the details).
 * Rounding: to nearest, ties to even (unbiased: a resting rope does not creep).
 * Overflow: saturates to 2^(W-1)-1 or -2^(W-1); sat = 1 when clamping happened.
 * Latency: combinational, 0 cycles; throughput one result per cycle. The W x W
 *          multiply maps to one DSP block up to 18x18 (W <= 18).
 */
module fx_mul #(
    parameter integer W = 32, // total width in bits, 8..32
    parameter integer F = 16, // fraction bits, 1..W-2
    parameter [0:0]   ROUND = 1'b1 // 0: the exact product only (y and sat are 0): a pipeline rounds it later
) (
    input  wire [W-1:0]   a,    // signed Q(W-F).F
    input  wire [W-1:0]   b,    // signed Q(W-F).F
    output wire [W-1:0]   y,    // signed Q(W-F).F, rounded and saturated
    output wire           sat,  // 1 when y was clamped
    output wire [2*W-1:0] prod  // the exact product, signed Q(2W-2F).2F (sums of squares use it unrounded)
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_mul: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(F_must_be_1_to_W_minus_2, F >= 1 && F <= W - 2, ("fx_mul: F must be 1..W-2 (W=%0d F=%0d) in %m", W, F))

    wire signed [2*W-1:0] p = $signed(a) * $signed(b); // exact product
    assign prod = p;
    generate
        if (ROUND) begin : g_round
            fx_round #(.W(W), .F(F)) u_round (.prod(p), .y(y), .sat(sat));
        end else begin : g_exact
            assign y   = {W{1'b0}};
            assign sat = 1'b0;
        end
    endgenerate

endmodule

`resetall
