`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_sqrt - iterative fixed-point square root, one result bit per clock.
 *
 * Computes  result = fx_sqrt(fmt, radicand)  of model/fixed.c: the square root of
 * an unsigned 2W-bit radicand, rounded to nearest at the last resolved bit,
 * saturated to 2^(W-1)-1.
 *
 * Ports:   radicand  unsigned, 2W bits. A sum of squares of Q(W-F).F values is in
 *                    Q(2W-2F).2F, and its root is then in Q(W-F).F: the unit does
 *                    not need to know F.
 *          result    W bits, MSB always 0 (0 .. 2^(W-1)-1).
 *          sat       1 when result was clamped to 2^(W-1)-1: radicand >= 2^(2W-2),
 *                    or the rounding step carried the root up to 2^(W-1).
 *
 * Algorithm: restoring digit-by-digit square root (M = W-1 magnitude bits).
 *   If radicand >= 2^(2M) (one of its top two bits set) the root does not fit and
 *   the result is 2^(W-1)-1; the unit still runs the full iteration count.
 *   Otherwise the radicand is consumed two bits per iteration from bit 2M-1 down,
 *   through a shift register. Each iteration:
 *       ac   <- 4*ac + next two radicand bits       (partial remainder)
 *       trial = 4*q + 1                              (shifted trial term)
 *       if ac >= trial: ac <- ac - trial, q <- 2q+1   else q <- 2q
 *   This is fx_sqrt()'s "rem >= (root << (b+1)) + 2^(2b)" divided by 4^b:
 *   ac = floor(rem / 4^b) and q = root / 2^(b+1). Iterations 1..SQRT_BITS resolve
 *   root bits W-2 .. LSB = W-1-SQRT_BITS. Iteration SQRT_BITS+1 is the same step
 *   for the bit worth half an LSB (zero bits are shifted in once the radicand is
 *   exhausted, which reproduces fx_sqrt()'s "rem > root" when LSB = 0). Its
 *   outcome is the rounding bit: result = (q_trunc + round_bit) << LSB, clamped.
 * Rounding: to nearest at bit LSB; an exact half (only possible when LSB > 0)
 *   rounds up, as fx_sqrt() does.
 * Overflow: saturates to 2^(W-1)-1 and sets sat.
 *
 * Timing (the cycle model mirrors this exactly). Call "edge 0" the rising edge
 * at which start is seen high while busy is low; the radicand is sampled there.
 *   edges 1 .. SQRT_BITS     one result-bit iteration each
 *   edge  SQRT_BITS+1        the rounding iteration; result and sat are loaded
 *   busy  = 1 after edges 0 .. SQRT_BITS   (SQRT_BITS+1 cycles)
 *   done  = 1 after edge SQRT_BITS+1, for exactly one cycle; busy = 0 then.
 * So done is high SQRT_BITS+1 edges after the edge that sampled start, for every
 * radicand (saturating ones included). start is ignored while busy is high; it
 * is accepted in the done cycle, so back-to-back operations take SQRT_BITS+2
 * cycles each. result and sat change only at the final edge of an operation and
 * hold until the final edge of the next one. reset (synchronous, active high)
 * clears busy, done, result and sat.
 */
module fx_sqrt #(
    parameter integer W         = 32,   // total width in bits, 8..32
    parameter integer SQRT_BITS = W - 1 // root magnitude bits resolved, 1..W-1
) (
    input  wire           clk,
    input  wire           reset,    // synchronous, active high
    input  wire           start,    // sample radicand and begin (ignored while busy)
    input  wire [2*W-1:0] radicand, // unsigned, 2W bits
    output wire           busy,     // an operation is in progress
    output wire           done,     // one-cycle pulse: result and sat are new
    output wire [W-1:0]   result,   // root, 0 .. 2^(W-1)-1
    output wire           sat       // result was clamped to 2^(W-1)-1
);

    // SB is a clamped copy of SQRT_BITS so that elaboration gets as far as reporting it.
    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_sqrt: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(SQRT_BITS_must_be_1_to_W_minus_1, SQRT_BITS >= 1 && SQRT_BITS <= W - 1,
                  ("fx_sqrt: SQRT_BITS must be 1..W-1 (W=%0d SQRT_BITS=%0d) in %m", W, SQRT_BITS))

    localparam integer M    = W - 1;                 // magnitude bits of the root
    localparam integer SB   = (SQRT_BITS < 1) ? 1 : (SQRT_BITS > M) ? M : SQRT_BITS; // clamped
    localparam integer NIT  = SB + 1;                // iterations per operation
    localparam integer LSB  = M - SB;                // weight of the last resolved bit
    localparam integer XB   = (NIT < M) ? NIT : M;   // radicand bit pairs consumed
    localparam integer XW   = 2 * XB;                // radicand shift register width
    localparam integer AW   = SB + 1;                // stored partial remainder width
    localparam integer TW   = SB + 3;                // trial comparison width
    localparam integer CW   = $clog2(NIT);           // iteration counter width
    localparam integer CNT_LOAD = NIT - 1;           // counter value after edge 0

    // Registers.
    reg           busy_q, busy_d;
    reg           done_q, done_d;
    reg [CW-1:0]  cnt_q, cnt_d;      // iterations left after the current one
    reg [XW-1:0]  x_q, x_d;          // radicand bits not consumed yet, top first
    reg [AW-1:0]  ac_q, ac_d;        // partial remainder
    reg [NIT-1:0] q_q, q_d;          // root bits resolved so far
    reg           big_q, big_d;      // radicand >= 2^(2M): root does not fit
    reg [W-1:0]   result_q, result_d;
    reg           sat_q, sat_d;


`include "fx_sqrt_step.vh"

    // Combinational values, computed at the top of the next-state block (one
    // block rather than a chain of assigns keeps event-driven simulation fast).
    reg [AW:0]    step;    // one iteration: {root bit, new partial remainder}
    reg [NIT-1:0] q_next;  // root bits after this iteration
    reg [W:0]     fin;     // last iteration: {clamped, the rounded root in place}

    always @* begin
        // One iteration, from the registers (q_q[NIT-1] is still 0 here).
        step    = sqrt_step(ac_q, x_q[XW-1 -: 2], q_q);
        q_next  = {q_q[NIT-2:0], step[AW]};
        // Rounding and clamping, used on the last iteration.
        fin     = sqrt_result(q_next, big_q);

        // Next state: hold by default.

        busy_d   = busy_q;
        done_d   = 1'b0;
        cnt_d    = cnt_q;
        x_d      = x_q;
        ac_d     = ac_q;
        q_d      = q_q;
        big_d    = big_q;
        result_d = result_q;
        sat_d    = sat_q;
        if (busy_q) begin
            x_d  = x_q << 2;
            ac_d = step[AW-1:0];
            q_d  = q_next;
            if (cnt_q == {CW{1'b0}}) begin
                busy_d   = 1'b0;
                done_d   = 1'b1;
                result_d = fin[W-1:0];
                sat_d    = fin[W];
            end else begin
                cnt_d = cnt_q - 1'b1;
            end
        end else if (start) begin
            busy_d = 1'b1;
            cnt_d  = CNT_LOAD[CW-1:0];
            x_d    = radicand[2*M-1 -: XW];
            ac_d   = {AW{1'b0}};
            q_d    = {NIT{1'b0}};
            big_d  = |radicand[2*W-1 -: 2];
        end
    end

    // Control state and output registers: reset.
    always @(posedge clk) begin
        if (reset) begin
            busy_q   <= 1'b0;
            done_q   <= 1'b0;
            result_q <= {W{1'b0}};
            sat_q    <= 1'b0;
        end else begin
            busy_q   <= busy_d;
            done_q   <= done_d;
            result_q <= result_d;
            sat_q    <= sat_d;
        end
    end

    // Datapath registers: only read while busy, so no reset.
    always @(posedge clk) begin
        cnt_q <= cnt_d;
        x_q   <= x_d;
        ac_q  <= ac_d;
        q_q   <= q_d;
        big_q <= big_d;
    end

    // With SQRT_BITS < W-2 the low radicand bits cannot change the rounded root;
    // they are deliberately not stored. (Verilator skips signals named *unused*.)
    wire unused_radicand = &{1'b0, radicand};

    assign busy   = busy_q;
    assign done   = done_q;
    assign result = result_q;
    assign sat    = sat_q;

endmodule

`resetall
