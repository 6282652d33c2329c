`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_shr - the low OUT_W bits of a word shifted right by a variable amount: a log shifter
 * whose stages keep only the bits the later stages can still bring down.
 *
 * Computes  y = (a >> s)[OUT_W-1:0]  (SIGNED: a >>> s, the sign copied in from the top),
 * for s in 0 .. 2^SB - 1. Combinational (0 cycles).
 *
 * Algorithm: the shift's bits from the highest: stage b moves the word down by 2^b when
 * s[b] is set. After stage b the remaining stages move it by at most 2^b - 1, so only the
 * low OUT_W + 2^b - 1 bits can still reach y: each stage keeps those and no more (a plain
 * `>>>` of the whole word leaves that pruning to synthesis, which on the ECP5 left twice
 * the LUT4s of this form for fx_along_pipe's 18 bits out of 49). Bits above the word's
 * top are its sign (SIGNED) or zero.
 */
module fx_shr #(
    parameter integer IN_W   = 32,   // the word's width
    parameter integer OUT_W  = 16,   // the bits kept, 1 .. IN_W
    parameter integer SB     = 5,    // shift bits: s is 0 .. 2^SB - 1
    parameter [0:0]   SIGNED = 1'b1  // 1: arithmetic shift
) (
    input  wire [IN_W-1:0]  a,
    input  wire [SB-1:0]    s,
    output wire [OUT_W-1:0] y
);

    `STRAND_CHECK(fx_shr_widths, OUT_W >= 1 && OUT_W <= IN_W && SB >= 1 && SB <= 7,
                  ("fx_shr: OUT_W must be 1 .. IN_W and SB 1 .. 7 (IN_W=%0d OUT_W=%0d SB=%0d) in %m", IN_W, OUT_W, SB))

    localparam integer TOP = IN_W + (1 << SB);   // the word with room for every shift's fill
    wire fill = SIGNED && a[IN_W-1];
    wire [TOP-1:0] word = {{(1 << SB){fill}}, a};

    genvar b;
    generate
        for (b = SB - 1; b >= 0; b = b - 1) begin : g_stage
            // in: the bits still needed before this stage; out: after it
            localparam integer IN_K  = b == SB - 1 ? TOP : OUT_W + (1 << (b + 1)) - 1;
            localparam integer OUT_K = OUT_W + (1 << b) - 1;
            wire [IN_K-1:0]  in;
            wire [OUT_K-1:0] out;
            if (b == SB - 1) begin : g_first
                assign in = word;
            end else begin : g_next
                assign in = g_stage[b+1].out;
            end
            assign out = s[b] ? in[(1 << b) +: OUT_K] : in[OUT_K-1:0];
            if (IN_K > OUT_K + (1 << b)) begin : g_unused
                wire unused_top = &{1'b0, in[IN_K-1:OUT_K + (1 << b)]};
            end
        end
    endgenerate
    assign y = g_stage[0].out;

endmodule

`resetall
