`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_div_pipe - the divider of fx_div, pipelined: a new num / den every clock.
 *
 * Computes exactly what fx_div (and fx_div() of model/fixed.c) computes:
 * round(num * 2^F / den) for unsigned W-bit num and den, rounded at the last resolved
 * bit, saturated to 2^(W-1)-1, with div_by_zero for den = 0. The algorithm is
 * fx_div's, its DIV_BITS + 1 iterations unrolled, STEPS of them to a pipeline stage, and
 * a stage for the rounding; the iteration itself is the one of fx_div_step.vh, which
 * fx_div uses too. STEPS trades the clock for latency and registers: each stage's path
 * holds STEPS subtracters in a row, and the stages (so the registers that carry the
 * remainder, the divisor and the quotient bits) are STEPS times fewer.
 *
 * Ports:   num, den  unsigned W bits (Q(W-F).F read as unsigned), sampled every edge.
 *          result, div_by_zero, sat: as fx_div's.
 * Latency: operands sampled at edge e give their result after edge e + LAT, LAT =
 *          ceil((DIV_BITS + 1) / STEPS) + 1 (pipe_latency.vh div_pipe_latency): a load
 *          stage, the iteration stages, the rounding stage. With STEPS = 1, DIV_BITS + 2:
 *          one more than fx_div's start-to-done.
 * Throughput: one quotient per clock. No reset; the caller keeps its valid bits.
 * Cost: DIV_BITS + 1 subtracters of W + 2 bits and, per stage, the partial remainder,
 *       the divisor, the quotient bits so far and the dividend bits still to come.
 *       The last stage holds the iterations left over (1 .. STEPS).
 */
module fx_div_pipe #(
    parameter integer W        = 32,   // total width in bits, 8..32
    parameter integer F        = 16,   // fraction bits, 1..W-2
    parameter integer DIV_BITS = W - 1, // quotient magnitude bits resolved, 1..W-1
    parameter integer STEPS    = 1      // iterations a pipeline stage, 1..4
) (
    input  wire         clk,
    input  wire [W-1:0] num,         // unsigned dividend, Q(W-F).F
    input  wire [W-1:0] den,         // unsigned divisor, Q(W-F).F
    output wire [W-1:0] result,      // quotient, Q(W-F).F, 0 .. 2^(W-1)-1
    output wire         div_by_zero, // den was 0 (result = 2^(W-1)-1)
    output wire         sat          // den != 0, quotient clamped to 2^(W-1)-1
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_div_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(F_must_be_1_to_W_minus_2, F >= 1 && F <= W - 2, ("fx_div_pipe: F must be 1..W-2 (W=%0d F=%0d) in %m", W, F))
    `STRAND_CHECK(DIV_BITS_must_be_1_to_W_minus_1, DIV_BITS >= 1 && DIV_BITS <= W - 1,
                  ("fx_div_pipe: DIV_BITS must be 1..W-1 (W=%0d DIV_BITS=%0d) in %m", W, DIV_BITS))
    `STRAND_CHECK(STEPS_must_be_1_to_4, STEPS >= 1 && STEPS <= 4, ("fx_div_pipe: STEPS must be 1..4 (STEPS=%0d) in %m", STEPS))

    localparam integer M   = W - 1;               // magnitude bits of the quotient
    localparam integer FS  = (F < 1) ? 1 : (F > W - 2) ? W - 2 : F;                // F, clamped
    localparam integer DB  = (DIV_BITS < 1) ? 1 : (DIV_BITS > M) ? M : DIV_BITS;  // clamped
    localparam integer NIT = DB + 1;              // iterations: pipeline stages
    localparam integer LSB = M - DB;              // weight of the last resolved bit
    localparam integer XB  = (NIT < M) ? NIT : M; // dividend bits fed in
    localparam integer SPS = (STEPS < 1) ? 1 : STEPS; // iterations a stage, clamped

`include "fx_div_step.vh"

    // after iteration s = 0 (the load) .. NIT-1: x (the dividend bits to come, top first),
    // acc (the partial remainder), den, q (the quotient bits so far), big (the quotient does
    // not fit, or den = 0) and dbz (den = 0); registered when s is a multiple of SPS (split_var: with
    // STEPS > 1 an element is made of the one before it, which Verilator would take for a loop)
    wire [XB-1:0]  x_s   [0:NIT-1] /* verilator split_var */;
    wire [W-1:0]   acc_s [0:NIT-1] /* verilator split_var */;
    wire [W-1:0]   den_s [0:NIT-1] /* verilator split_var */;
    wire [NIT-1:0] q_s   [0:NIT-1] /* verilator split_var */;
    wire           big_s [0:NIT-1] /* verilator split_var */;
    wire           dbz_s [0:NIT-1] /* verilator split_var */;

    wire [W-1:0] acc_init = num >> (M - FS);            // floor(num * 2^F / 2^M)
    wire [M-1:0] low_bits = num[M-1:0] << FS;           // dividend bits M-1 .. 0
    reg  [XB-1:0] x0;
    reg  [W-1:0]  acc0, den0;
    reg           big0, dbz0;
    always @(posedge clk) begin
        x0   <= low_bits[M-1 -: XB];
        acc0 <= acc_init;
        den0 <= den;
        big0 <= acc_init >= den;
        dbz0 <= den == {W{1'b0}};
    end
    assign x_s[0]   = x0;
    assign acc_s[0] = acc0;
    assign den_s[0] = den0;
    assign q_s[0]   = {NIT{1'b0}};
    assign big_s[0] = big0;
    assign dbz_s[0] = dbz0;

    // With DIV_BITS < W-2 the low dividend bits cannot change the rounded quotient.
    wire unused_low_bits = &{1'b0, low_bits};

    genvar s;
    generate
        for (s = 1; s <= NIT; s = s + 1) begin : g_stage
            wire [W:0]     step   = div_step(acc_s[s-1], x_s[s-1][XB-1], den_s[s-1]);
            wire [NIT-1:0] q_next = {q_s[s-1][NIT-2:0], step[W]};
            if (s < NIT && s % SPS != 0) begin : g_chain
                // an iteration inside a stage: straight on to the next one
                assign x_s[s]   = x_s[s-1] << 1;
                assign acc_s[s] = step[W-1:0];
                assign den_s[s] = den_s[s-1];
                assign q_s[s]   = q_next;
                assign big_s[s] = big_s[s-1];
                assign dbz_s[s] = dbz_s[s-1];
            end else if (s < NIT) begin : g_iter
                reg [XB-1:0]  x_q;
                reg [W-1:0]   acc_q, den_q;
                reg [NIT-1:0] q_q;
                reg           big_q, dbz_q;
                always @(posedge clk) begin
                    x_q   <= x_s[s-1] << 1;
                    acc_q <= step[W-1:0];
                    den_q <= den_s[s-1];
                    q_q   <= q_next;
                    big_q <= big_s[s-1];
                    dbz_q <= dbz_s[s-1];
                end
                assign x_s[s]   = x_q;
                assign acc_s[s] = acc_q;
                assign den_s[s] = den_q;
                assign q_s[s]   = q_q;
                assign big_s[s] = big_q;
                assign dbz_s[s] = dbz_q;
            end else begin : g_last
                // the last iteration, then the rounding in a stage of its own (two carry
                // chains in one cycle would set the clock)
                reg [NIT-1:0] q_last;
                reg           big_last, dbz_last;
                reg [W:0]     fin;
                reg           dbz_q;
                always @(posedge clk) begin
                    q_last   <= q_next;
                    big_last <= big_s[s-1];
                    dbz_last <= dbz_s[s-1];
                    fin      <= div_result(q_last, big_last);
                    dbz_q    <= dbz_last;
                end
                assign result      = fin[W-1:0];
                assign sat         = fin[W] & !dbz_q;
                assign div_by_zero = dbz_q;
            end
        end
    endgenerate

endmodule

`resetall
