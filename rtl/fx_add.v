`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_add - saturating fixed-point add / subtract.
 *
 * Computes  y = sat(a + b)  when sub = 0  and  y = sat(a - b)  when sub = 1,
 * mirroring fx_add() and fx_sub() in model/fixed.h.
 *
 * Ports:   a, b, y are signed two's complement, W bits, any Q format (the binary
 *          point does not move in an add, so F is not a parameter).
 * Algorithm: both operands are sign-extended to W+1 bits; one adder forms
 *          a + b, or a + ~b + 1 = a - b (b inverted, sub as the carry in). The
 *          W+1-bit result is exact (its range is [-2^W+1, 2^W-1]). If its two top
 *          bits differ the result left the W-bit range and is clamped to
 *          2^(W-1)-1 (positive overflow) or -2^(W-1) (negative overflow).
 * Rounding: none (exact).
 * Overflow: saturates, never wraps; sat = 1 when clamping happened.
 * SUB fixes the operation when it is known when the design is built, so that a
 * synthesis that keeps the hierarchy builds no inverter nor carry in for it.
 * Latency: combinational, 0 cycles; throughput one result per cycle.
 */
module fx_add #(
    parameter integer W   = 32, // total width in bits, 8..32
    parameter integer SUB = -1  // 0: always a + b, 1: always a - b (sub is then ignored), -1: sub chooses
) (
    input  wire         sub, // SUB = -1: 0 a + b, 1 a - b
    input  wire [W-1:0] a,   // signed, W bits
    input  wire [W-1:0] b,   // signed, W bits
    output reg  [W-1:0] y,   // signed, W bits, saturated
    output reg          sat  // 1 when y was clamped
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_add: W must be 8..32 (W=%0d) in %m", W))

    `STRAND_CHECK(SUB_must_be_0_1_or_minus_1, SUB == 0 || SUB == 1 || SUB == -1, ("fx_add: SUB must be 0, 1 or -1 (SUB=%0d) in %m", SUB))

    wire       neg;  // subtract
    generate
        if (SUB == -1) begin : g_either
            assign neg = sub;
        end else begin : g_fixed
            assign neg = SUB == 1;
            wire unused_sub = &{1'b0, sub};  // the operation is fixed
        end
    endgenerate
    wire [W:0] a_ext = {a[W-1], a};
    wire [W:0] b_ext = {b[W-1], b} ^ {(W+1){neg}};       // ~b when subtracting
    wire [W:0] sum   = a_ext + b_ext + {{W{1'b0}}, neg}; // exact in W+1 bits

    always @* begin
        sat = sum[W] ^ sum[W-1];
        if (!sat)
            y = sum[W-1:0];
        else if (sum[W])
            y = {1'b1, {(W-1){1'b0}}}; // below -2^(W-1): clamp to the minimum
        else
            y = {1'b0, {(W-1){1'b1}}}; // above 2^(W-1)-1: clamp to the maximum
    end

endmodule

`resetall
