`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_round - an exact product back to Q(W-F).F: rounded to nearest (ties to even),
 * saturated.
 *
 * Computes  y = sat(round(prod / 2^F))  for the exact signed 2W-bit product of two
 * Q(W-F).F values: the second half of fx_mul() in model/fixed.h, as its own unit so
 * that a pipelined datapath can register the product between the two (fx_mul uses it
 * too: one definition of the rounding).
 *
 * Ports:   prod is signed Q(2W-2F).2F, 2W bits; y is signed Q(W-F).F, W bits.
 * Algorithm: q = prod >>> F is the floor of prod / 2^F (2W-F bits). Of the F dropped
 *          bits, the top one is "half" (worth half an LSB) and the OR of the others is
 *          "sticky". q is incremented when the dropped part is above one half
 *          (half & sticky) or exactly one half and q is odd (half & q[0]).
 *          The increment cannot overflow 2W-F bits for a product of two W-bit values:
 *          the largest q, 2^(2W-2-F), comes from (-2^(W-1))^2 whose dropped bits are
 *          zero. The rounded value is clamped to the W-bit range. Whether it fits is
 *          decided from q's top bits and the increment's carry into them (below), beside
 *          a W-bit increment of q's low bits, not after a 2W-F-bit one: one carry chain.
 * Rounding: to nearest, ties to even (unbiased: a resting rope does not creep).
 * Overflow: saturates to 2^(W-1)-1 or -2^(W-1); sat = 1 when clamping happened.
 * Latency: combinational, 0 cycles; throughput one result per cycle.
 */
module fx_round #(
    parameter integer W = 32, // result width in bits, 8..32
    parameter integer F = 16  // fraction bits, 1..W-2
) (
    input  wire [2*W-1:0] prod, // signed Q(2W-2F).2F
    output reg  [W-1:0]   y,    // signed Q(W-F).F, rounded and saturated
    output reg            sat   // 1 when y was clamped
);

    // FS is a clamped copy of F so that elaboration gets as far as reporting it.
    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_round: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(F_must_be_1_to_W_minus_2, F >= 1 && F <= W - 2, ("fx_round: F must be 1..W-2 (W=%0d F=%0d) in %m", W, F))

    localparam integer FS = (F < 1) ? 1 : (F > W - 2) ? W - 2 : F; // F, clamped
    localparam integer QW = 2 * W - FS;                            // width of the shifted product

    wire [QW-1:0] q    = prod[2*W-1:FS];              // floor(prod / 2^F)
    wire [FS-1:0] drop = prod[FS-1:0];                // bits shifted out
    wire [FS-1:0] rest = drop << 1;                   // dropped bits below "half"
    wire          half   = drop[FS-1];
    wire          sticky = |rest;
    wire          round_up = half & (sticky | q[0]);

    // The range check does not wait for the increment: only a W-bit carry chain follows
    // round_up. Split q as {A, B}: A = bits QW-1 .. W-1 (the bits that must be copies of the
    // sign), B = bits W-2 .. 0. The increment carries into A only when B is all ones; then
    // A + 1 is all zeros when A is all ones, and all ones when A is ones but a zero LSB.
    localparam integer AW = QW - W + 1;                            // A's width, >= 3
    wire [AW-1:0] a_hi   = q[QW-1:W-1];
    wire          carry  = round_up & (&q[W-2:0]);
    wire          a_zero = a_hi == {AW{1'b0}};
    wire          a_ones = a_hi == {AW{1'b1}};
    wire          a_even_ones = a_hi == {{(AW-1){1'b1}}, 1'b0};
    wire          fits   = carry ? (a_ones | a_even_ones) : (a_zero | a_ones);
    wire [W-1:0]  qr_lo  = q[W-1:0] + {{(W-1){1'b0}}, round_up};  // qr's bits W-1 .. 0

    // When qr does not fit, its sign is q's: the increment changes the sign only of
    // q = -1 (to 0, which fits); q = 2^(QW-1) - 1 is out of reach (above).
    always @* begin
        sat = !fits;
        if (fits)
            y = qr_lo;
        else if (q[QW-1])
            y = {1'b1, {(W-1){1'b0}}}; // below the range: minimum
        else
            y = {1'b0, {(W-1){1'b1}}}; // above the range: maximum
    end

endmodule

`resetall
