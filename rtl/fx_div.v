`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_div - iterative unsigned fixed-point divider, one quotient bit per clock.
 *
 * Computes  result = fx_div(fmt, num, den)  of model/fixed.c:
 * round(num * 2^F / den) for unsigned W-bit num and den, rounded at the last
 * resolved bit, saturated to 2^(W-1)-1.
 *
 * Ports:   num, den    unsigned W bits (magnitudes; fx_div_signed() handles signs
 *                      outside this unit). Both in Q(W-F).F read as unsigned.
 *          result      Q(W-F).F, W bits, MSB always 0 (0 .. 2^(W-1)-1).
 *          div_by_zero den was 0; result is then 2^(W-1)-1, to be ignored.
 *          sat         den != 0 and the quotient was clamped to 2^(W-1)-1: either
 *                      num * 2^F >= den * 2^(W-1), or rounding carried the
 *                      quotient up to 2^(W-1).
 *
 * Algorithm: restoring long division of the dividend num * 2^F (M = W-1).
 *   At start, acc = floor(num * 2^F / 2^M) = num >> (M-F). If acc >= den the
 *   quotient needs more than M bits (this includes den = 0) and the result is
 *   2^(W-1)-1; the unit still runs the full iteration count. Otherwise acc < den,
 *   and the dividend bits below 2^M (num[M-1-F:0] followed by F zeros) enter a
 *   shift register that feeds one bit per iteration, top first. Each iteration:
 *       t = 2*acc + next dividend bit
 *       if t >= den: acc <- t - den, q <- 2q+1     else acc <- t, q <- 2q
 *   This is fx_div()'s "rem >= den << b" divided by 2^b (acc = floor(rem / 2^b)),
 *   with den fixed and the remainder shifted instead of a shifted divisor.
 *   acc < den holds throughout, so acc needs W bits. Iterations 1..DIV_BITS
 *   resolve quotient bits W-2 .. LSB = W-1-DIV_BITS; iteration DIV_BITS+1 is the
 *   same step for the bit worth half an LSB (a zero is shifted in once the
 *   dividend is exhausted, which is fx_div()'s "2 * rem >= den" when LSB = 0),
 *   and its outcome is the rounding bit: result = (q_trunc + round_bit) << LSB,
 *   clamped.
 * Rounding: to nearest at bit LSB; an exact half rounds up, as fx_div() does.
 * Overflow: saturates to 2^(W-1)-1 (sat = 1, or div_by_zero = 1 when den = 0).
 *
 * Timing (the cycle model mirrors this exactly). Call "edge 0" the rising edge
 * at which start is seen high while busy is low; num and den are sampled there.
 *   edges 1 .. DIV_BITS      one quotient-bit iteration each
 *   edge  DIV_BITS+1         the rounding iteration; result and flags are loaded
 *   busy  = 1 after edges 0 .. DIV_BITS   (DIV_BITS+1 cycles)
 *   done  = 1 after edge DIV_BITS+1, for exactly one cycle; busy = 0 then.
 * So done is high DIV_BITS+1 edges after the edge that sampled start, for every
 * operand pair (den = 0 and saturating ones included). start is ignored while
 * busy is high; it is accepted in the done cycle, so back-to-back operations
 * take DIV_BITS+2 cycles each. result and the flags change only at the final
 * edge of an operation and hold until the final edge of the next one. reset
 * (synchronous, active high) clears busy, done, result and the flags.
 */
module fx_div #(
    parameter integer W        = 32,   // total width in bits, 8..32
    parameter integer F        = 16,   // fraction bits, 1..W-2
    parameter integer DIV_BITS = W - 1 // quotient magnitude bits resolved, 1..W-1
) (
    input  wire         clk,
    input  wire         reset,       // synchronous, active high
    input  wire         start,       // sample num, den and begin (ignored while busy)
    input  wire [W-1:0] num,         // unsigned dividend, Q(W-F).F
    input  wire [W-1:0] den,         // unsigned divisor, Q(W-F).F
    output wire         busy,        // an operation is in progress
    output wire         done,        // one-cycle pulse: result and flags are new
    output wire [W-1:0] result,      // quotient, Q(W-F).F, 0 .. 2^(W-1)-1
    output wire         div_by_zero, // den was 0 (result = 2^(W-1)-1)
    output wire         sat          // den != 0, quotient clamped to 2^(W-1)-1
);

    // FS and DB are clamped copies of F and DIV_BITS so that elaboration gets as far
    // as reporting them.
    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("fx_div: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(F_must_be_1_to_W_minus_2, F >= 1 && F <= W - 2, ("fx_div: F must be 1..W-2 (W=%0d F=%0d) in %m", W, F))
    `STRAND_CHECK(DIV_BITS_must_be_1_to_W_minus_1, DIV_BITS >= 1 && DIV_BITS <= W - 1,
                  ("fx_div: DIV_BITS must be 1..W-1 (W=%0d DIV_BITS=%0d) in %m", W, DIV_BITS))

    localparam integer M        = W - 1;               // magnitude bits of the quotient
    localparam integer FS       = (F < 1) ? 1 : (F > W - 2) ? W - 2 : F; // F, clamped
    localparam integer DB       = (DIV_BITS < 1) ? 1 : (DIV_BITS > M) ? M : DIV_BITS; // DIV_BITS, clamped
    localparam integer NIT      = DB + 1;              // iterations per operation
    localparam integer LSB      = M - DB;              // weight of the last resolved bit
    localparam integer XB       = (NIT < M) ? NIT : M; // dividend bits fed in
    localparam integer CW       = $clog2(NIT);         // iteration counter width
    localparam integer CNT_LOAD = NIT - 1;             // counter value after edge 0

    // Registers.
    reg           busy_q, busy_d;
    reg           done_q, done_d;
    reg [CW-1:0]  cnt_q, cnt_d;      // iterations left after the current one
    reg [XB-1:0]  x_q, x_d;          // dividend bits not consumed yet, top first
    reg [W-1:0]   acc_q, acc_d;      // partial remainder, < den
    reg [W-1:0]   den_q, den_d;
    reg [NIT-1:0] q_q, q_d;          // quotient bits resolved so far
    reg           dbz_q, dbz_d;      // den = 0
    reg           big_q, big_d;      // quotient >= 2^(W-1) (or den = 0)
    reg [W-1:0]   result_q, result_d;
    reg           dbz_out_q, dbz_out_d;
    reg           sat_q, sat_d;

    // Operand preparation at start.
    wire [W-1:0] acc_init = num >> (M - FS);            // floor(num * 2^F / 2^M)
    wire [M-1:0] low_bits = num[M-1:0] << FS;           // dividend bits M-1 .. 0

`include "fx_div_step.vh"

    // Combinational values, computed at the top of the next-state block (one
    // block rather than a chain of assigns keeps event-driven simulation fast).
    reg [W:0]     step;    // one iteration: {quotient bit, new partial remainder}
    reg [NIT-1:0] q_next;  // quotient bits after this iteration
    reg [W:0]     fin;     // last iteration: {clamped, the rounded quotient in place}

    always @* begin
        // One iteration, from the registers.
        step    = div_step(acc_q, x_q[XB-1], den_q);
        q_next  = {q_q[NIT-2:0], step[W]};
        // Rounding and clamping, used on the last iteration.
        fin     = div_result(q_next, big_q);

        // Next state: hold by default.

        busy_d    = busy_q;
        done_d    = 1'b0;
        cnt_d     = cnt_q;
        x_d       = x_q;
        acc_d     = acc_q;
        den_d     = den_q;
        q_d       = q_q;
        dbz_d     = dbz_q;
        big_d     = big_q;
        result_d  = result_q;
        dbz_out_d = dbz_out_q;
        sat_d     = sat_q;
        if (busy_q) begin
            x_d   = x_q << 1;
            acc_d = step[W-1:0];
            q_d   = q_next;
            if (cnt_q == {CW{1'b0}}) begin
                busy_d    = 1'b0;
                done_d    = 1'b1;
                result_d  = fin[W-1:0];
                dbz_out_d = dbz_q;
                sat_d     = fin[W] & !dbz_q;
            end else begin
                cnt_d = cnt_q - 1'b1;
            end
        end else if (start) begin
            busy_d = 1'b1;
            cnt_d  = CNT_LOAD[CW-1:0];
            x_d    = low_bits[M-1 -: XB];
            acc_d  = acc_init;
            den_d  = den;
            q_d    = {NIT{1'b0}};
            dbz_d  = (den == {W{1'b0}});
            big_d  = (acc_init >= den);
        end
    end

    // Control state and output registers: reset.
    always @(posedge clk) begin
        if (reset) begin
            busy_q    <= 1'b0;
            done_q    <= 1'b0;
            result_q  <= {W{1'b0}};
            dbz_out_q <= 1'b0;
            sat_q     <= 1'b0;
        end else begin
            busy_q    <= busy_d;
            done_q    <= done_d;
            result_q  <= result_d;
            dbz_out_q <= dbz_out_d;
            sat_q     <= sat_d;
        end
    end

    // Datapath registers: only read while busy, so no reset.
    always @(posedge clk) begin
        cnt_q <= cnt_d;
        x_q   <= x_d;
        acc_q <= acc_d;
        den_q <= den_d;
        q_q   <= q_d;
        dbz_q <= dbz_d;
        big_q <= big_d;
    end

    // With DIV_BITS < W-2 the low dividend bits cannot change the rounded
    // quotient; they are deliberately not stored. (Verilator skips *unused*.)
    wire unused_low_bits = &{1'b0, low_bits};

    assign busy        = busy_q;
    assign done        = done_q;
    assign result      = result_q;
    assign div_by_zero = dbz_out_q;
    assign sat         = sat_q;

endmodule

`resetall
