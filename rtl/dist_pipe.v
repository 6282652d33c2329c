`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * dist_pipe - the pipelined distance datapath of a build: toward_pipe, or with
 * PROJECTION toward_prev_pipe (the correction along the constraint's direction at the
 * substep's start). One operation a clock; its result LATENCY cycles later
 * (pipe_latency.vh, model/timing.c hw_toward_pipe_latency; LSQ and LDV the root's and the
 * dividers' latencies, SQRT_BITS + 2 and DIV_BITS + 2 with STEPS = 1):
 *     toward_pipe       LSQ + LDV + 11       (STEPS = 1: SQRT_BITS + DIV_BITS + 15); 24 with MANTISSA
 *     toward_prev_pipe  2 LSQ + LDV + 28     (STEPS = 1: 2 SQRT_BITS + DIV_BITS + 34); LSQ + 44 with MANTISSA
 * The ports are toward_prev_pipe's; without PROJECTION the previous positions (in_pp,
 * in_pc) are not used. See those two modules for the arithmetic.
 */
module dist_pipe #(
    parameter integer W          = 32,
    parameter integer F          = 16,
    parameter integer SQRT_BITS  = W - 1,
    parameter integer DIV_BITS   = W - 1,
    parameter integer MANTISSA   = 0,     // 0: the full-width root and divide; 6 .. 20: the normalised datapath
    parameter integer STEPS      = 1,     // root and divide iterations a pipeline stage
    parameter integer DIM        = 2,
    parameter integer TAG_W      = 1,
    parameter [0:0]   CARRY      = 1'b0,  // 1: P and C come out beside T (out_p, out_c)
    parameter [0:0]   PROJECTION = 1'b0,  // 1: toward_prev_pipe
    parameter [0:0]   IN_REG     = 1'b1,  // 0: every input but in_valid in cycle 1 (toward_pipe)
    parameter integer BLOCK_MIN  = 64     // delay rings: strand_ram's block RAM threshold
) (
    input  wire             clk,
    input  wire             reset,        // synchronous, active high: the valid bits
    input  wire             in_valid,
    input  wire             in_excess,    // 0: the point at rest from P toward C; 1: the excess
    input  wire [DIM*W-1:0] in_p,
    input  wire [DIM*W-1:0] in_c,
    input  wire [DIM*W-1:0] in_pp,        // PROJECTION: P's and C's previous positions
    input  wire [DIM*W-1:0] in_pc,
    input  wire [W-1:0]     in_rest,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output wire [DIM*W-1:0] out_t,
    output wire             out_ok,       // 0: zero length, no direction
    output wire [TAG_W-1:0] out_tag,
    output wire [DIM*W-1:0] out_p,        // CARRY: the operation's P and C (else 0)
    output wire [DIM*W-1:0] out_c
);

    generate
        if (PROJECTION) begin : g_previous
            toward_prev_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(STEPS), .DIM(DIM), .TAG_W(TAG_W),
                               .CARRY(CARRY), .IN_REG(IN_REG), .BLOCK_MIN(BLOCK_MIN)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess),
                .in_p(in_p), .in_c(in_c), .in_pp(in_pp), .in_pc(in_pc), .in_rest(in_rest), .in_tag(in_tag),
                .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok), .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
        end else begin : g_current
            toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(STEPS), .DIM(DIM), .TAG_W(TAG_W),
                          .CARRY(CARRY), .IN_REG(IN_REG), .BLOCK_MIN(BLOCK_MIN)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess),
                .in_p(in_p), .in_c(in_c), .in_rest(in_rest), .in_tag(in_tag),
                .out_valid(out_valid), .out_t(out_t), .out_ok(out_ok), .out_tag(out_tag), .out_p(out_p), .out_c(out_c));
            wire unused_prev = &{1'b0, in_pp, in_pc};
        end
    endgenerate

endmodule

`resetall
