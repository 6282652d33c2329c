`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_avg - average of two fixed-point values, rounded to nearest, ties to even.
 *
 * Computes  y = round((a + b) / 2)  from the exact W+1-bit sum, mirroring fx_avg()
 * in model/fixed.h; with b = 0 it is fx_half(a).
 *
 * Ports:   a, b, y are signed two's complement, W bits, any Q format.
 * Algorithm: s = a + b in W+1 bits (exact). q = s >>> 1 (floor), the dropped bit
 *          is s[0]. A dropped bit of 1 is exactly half an LSB, a tie, so q is
 *          incremented only when q is odd (ties to even): y = q + (s[0] & q[0]).
 * Rounding: to nearest, ties to even (unbiased).
 * Overflow: cannot happen. The largest sum 2^W-2 is even, giving 2^(W-1)-1; the
 *          largest odd sum 2^W-3 gives q = 2^(W-1)-2, rounded at most to
 *          2^(W-1)-1; the smallest sum -2^W gives -2^(W-1). So the model's clamp
 *          never acts and there is no saturation logic.
 * Latency: combinational, 0 cycles; throughput one result per cycle.
 */
module fx_avg #(
    parameter integer W = 32 // total width in bits, 8..32
) (
    input  wire [W-1:0] a, // signed, W bits
    input  wire [W-1:0] b, // signed, W bits
    output wire [W-1:0] y  // signed, W bits: round((a + b) / 2), ties to even
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_avg: W must be 8..32 (W=%0d) in %m", W))

    wire [W:0]   s = {a[W-1], a} + {b[W-1], b}; // exact sum
    wire [W-1:0] q = s[W:1];                    // floor(s / 2), always fits W bits

    assign y = q + {{(W-1){1'b0}}, s[0] & q[0]};

endmodule

`resetall
