`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_sqrt_pipe - the square root of fx_sqrt, pipelined: a new radicand every clock.
 *
 * Computes exactly what fx_sqrt (and fx_sqrt() of model/fixed.c) computes: the root of
 * an unsigned 2W-bit radicand, rounded to nearest at the last resolved bit, saturated
 * to 2^(W-1)-1. The algorithm is fx_sqrt's, its SQRT_BITS + 1 iterations unrolled,
 * STEPS of them to a pipeline stage, and a stage for the rounding; the iteration itself
 * is the one of fx_sqrt_step.vh, which fx_sqrt uses too, so the two cannot differ.
 * STEPS trades the clock for latency and registers: each stage's path holds STEPS
 * subtracters in a row, and the stages are STEPS times fewer.
 *
 * Ports:   radicand  unsigned, 2W bits, sampled at every rising edge.
 *          result    W bits (0 .. 2^(W-1)-1) and sat, as fx_sqrt's.
 * Latency: a radicand sampled at edge e gives its result and sat after edge e + LAT,
 *          LAT = ceil((SQRT_BITS + 1) / STEPS) + 1 (pipe_latency.vh sqrt_pipe_latency):
 *          one load stage, the iteration stages, the rounding stage. With STEPS = 1,
 *          SQRT_BITS + 2: one more than fx_sqrt's start-to-done.
 * Throughput: one root per clock. No reset: a stage holds whatever entered it; the
 *          caller keeps its own valid bits.
 * Cost: SQRT_BITS + 1 subtracters and, per stage, the partial remainder, the root bits
 *       so far and the radicand bits still to come (the ones that are constant are
 *       removed by synthesis). After s iterations the root q has s bits and the
 *       partial remainder is at most 2q (the radicand's top 2s bits minus q^2), so it
 *       is kept in s + 1 bits: iteration s subtracts s + 2 bits, not SQRT_BITS + 3
 *       (at W = 32 about half the carry cells of full-width stages; the results are
 *       the same, the upper bits being zero).
 */
module fx_sqrt_pipe #(
    parameter integer W         = 32,   // total width in bits, 8..32
    parameter integer SQRT_BITS = W - 1, // root magnitude bits resolved, 1..W-1
    parameter integer STEPS     = 1      // iterations a pipeline stage, 1..4
) (
    input  wire           clk,
    input  wire [2*W-1:0] radicand, // unsigned, 2W bits
    output wire [W-1:0]   result,   // root, 0 .. 2^(W-1)-1
    output wire           sat       // result was clamped to 2^(W-1)-1
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_sqrt_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(SQRT_BITS_must_be_1_to_W_minus_1, SQRT_BITS >= 1 && SQRT_BITS <= W - 1,
                  ("fx_sqrt_pipe: SQRT_BITS must be 1..W-1 (W=%0d SQRT_BITS=%0d) in %m", W, SQRT_BITS))
    `STRAND_CHECK(STEPS_must_be_1_to_4, STEPS >= 1 && STEPS <= 4, ("fx_sqrt_pipe: STEPS must be 1..4 (STEPS=%0d) in %m", STEPS))

    localparam integer M   = W - 1;                 // magnitude bits of the root
    localparam integer SB  = (SQRT_BITS < 1) ? 1 : (SQRT_BITS > M) ? M : SQRT_BITS; // clamped
    localparam integer NIT = SB + 1;                // iterations: pipeline stages
    localparam integer LSB = M - SB;                // weight of the last resolved bit
    localparam integer XB  = (NIT < M) ? NIT : M;   // radicand bit pairs consumed
    localparam integer XW  = 2 * XB;                // radicand bits carried
    localparam integer AW  = SB + 1;                // partial remainder width
    localparam integer TW  = SB + 3;                // trial comparison width
    localparam integer SPS = (STEPS < 1) ? 1 : STEPS; // iterations a stage, clamped

`include "fx_sqrt_step.vh"

    // after iteration s = 0 (the load) .. NIT-1: x (the radicand bits to come, top first),
    // ac (the partial remainder), q (the root bits so far) and big (the root does not fit);
    // registered when s is a multiple of SPS (split_var: with
    // STEPS > 1 an element is made of the one before it, which Verilator would take for a loop)
    wire [XW-1:0]  x_s   [0:NIT-1] /* verilator split_var */;
    wire [AW-1:0]  ac_s  [0:NIT-1] /* verilator split_var */;
    wire [NIT-1:0] q_s   [0:NIT-1] /* verilator split_var */;
    wire           big_s [0:NIT-1] /* verilator split_var */;

    reg [XW-1:0] x0;
    reg          big0;
    always @(posedge clk) begin
        x0   <= radicand[2*M-1 -: XW];
        big0 <= |radicand[2*W-1 -: 2];
    end
    assign x_s[0]   = x0;
    assign ac_s[0]  = {AW{1'b0}};
    assign q_s[0]   = {NIT{1'b0}};
    assign big_s[0] = big0;

    genvar s;
    generate
        for (s = 1; s <= NIT; s = s + 1) begin : g_stage
            wire [AW:0]    step   = sqrt_step(ac_s[s-1], x_s[s-1][XW-1 -: 2], q_s[s-1]);
            wire [NIT-1:0] q_next = {q_s[s-1][NIT-2:0], step[AW]};
            // the partial remainder after s iterations: <= 2q < 2^(s+1), s + 1 bits
            localparam integer AWS = (s + 1 < AW) ? s + 1 : AW;
            if (s < NIT && s % SPS != 0) begin : g_chain
                // an iteration inside a stage: straight on to the next one
                assign x_s[s] = x_s[s-1] << 2;
                if (AWS < AW) begin : g_zx
                    assign ac_s[s] = {{(AW-AWS){1'b0}}, step[AWS-1:0]};
                end else begin : g_full
                    assign ac_s[s] = step[AW-1:0];
                end
                assign q_s[s]   = q_next;
                assign big_s[s] = big_s[s-1];
            end else if (s < NIT) begin : g_iter
                reg [XW-1:0]  x_q;
                reg [AWS-1:0] ac_q;
                reg [NIT-1:0] q_q;
                reg           big_q;
                always @(posedge clk) begin
                    x_q   <= x_s[s-1] << 2;
                    ac_q  <= step[AWS-1:0];
                    q_q   <= q_next;
                    big_q <= big_s[s-1];
                end
                assign x_s[s]   = x_q;
                if (AWS < AW) begin : g_zx
                    assign ac_s[s] = {{(AW-AWS){1'b0}}, ac_q};
                end else begin : g_full
                    assign ac_s[s] = ac_q;
                end
                assign q_s[s]   = q_q;
                assign big_s[s] = big_q;
            end else begin : g_last
                // the last iteration, then the rounding in a stage of its own (two carry
                // chains in one cycle would set the clock)
                reg [NIT-1:0] q_last;
                reg           big_last;
                reg [W:0]     fin_q;  // {sat, result}
                always @(posedge clk) begin
                    q_last   <= q_next;
                    big_last <= big_s[s-1];
                    fin_q    <= sqrt_result(q_last, big_last);
                end
                assign {sat, result} = fin_q;
            end
        end
    endgenerate

    // With SQRT_BITS < W-2 the low radicand bits cannot change the rounded root.
    wire unused_radicand = &{1'b0, radicand};

endmodule

`resetall
