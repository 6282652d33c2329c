`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * toward_prev_pipe - toward_prev, pipelined: a new (P, C, P-, C-, rest) every clock, its
 * result a fixed number of cycles later (projection = previous in the pipelined pass).
 *
 * Computes exactly what toward_prev computes (model/engine_body.h along_previous() and
 * its callers), every step the same saturating add or exact product: with q = C - P and
 * r = C- - P-,
 *     lr  = fx_sqrt(r.r)                  u_k = fx_unit_div(r_k, lr)   (Q2.(W-2))
 *     s   = sum_k round_(W-2)(q_k u_k)    p_k = q_k - round_(W-2)(s u_k)
 *     leg = fx_sqrt(rest^2 - p.p)         miss when p.p > rest^2
 *     o_k = p_k -/+ round_(W-2)(leg u_k)  (- when s < 0)
 *     T_k = P_k + o_k (excess = 0)  or  q_k - o_k (excess = 1)
 * and when lr = 0 or miss, the result of a toward_pipe that runs beside it on the same
 * operands (its outputs delayed to this pipe's latency): valid 0 for a zero length.
 *
 * Algorithm: as toward_pipe, every iterative unit unrolled (fx_sqrt_pipe twice, DIM
 * fx_div_pipe with F = W-2 side by side), a multiplier for every product (fx_mul_pipe),
 * and the values needed again later carried in delay_line rings.
 *
 * Stages, counting the cycle in which an operation is on the inputs as cycle 0:
 *   1 q, r        2 |r|, the signs; r's squares start      4 their sum
 *   5 ..          lr, there in T_L = LSQ + 6: the dividers start
 *   T_U = T_L + LDV + 1        u_k signed, registered
 *   T_U + 1       q_k u_k start     T_U + 3 rounded     T_U + 4, + 5 s summed in axis order
 *   T_U + 6       s u_k start       T_U + 8 rounded     T_U + 9 p_k = q_k - s u_k
 *   T_U + 10      p_k^2 and rest^2 start; T_U + 12 p.p; T_U + 13 miss and rest^2 - p.p
 *   T_U + 14 ..   the leg, there in T_G = T_U + LSQ + 15
 *   T_G           leg u_k start     T_G + 2 rounded     T_G + 3 o_k     T_G + 4 T_k
 *   T_G + 5       T or the fallback's, into the output registers
 * LSQ and LDV are the root's and the dividers' latencies (pipe_latency.vh: with
 * STEPS = 1, SQRT_BITS + 2 and DIV_BITS + 2). LATENCY = T_G + 6 = 2 LSQ + LDV + 28,
 * 2 SQRT_BITS + DIV_BITS + 34 with STEPS = 1 (model/timing.c hw_toward_pipe_latency
 * with PROJECTION): an operation on the inputs in cycle 0 has out_valid, out_t, out_ok,
 * out_tag (and out_p, out_c with CARRY) in cycle LATENCY. Throughput one a clock.
 *
 * Ports: toward_pipe's, and in_pp, in_pc: P's and C's previous positions (IN_REG as
 * toward_pipe's: 0, every input but in_valid in cycle 1).
 */
module toward_prev_pipe #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,      // 0: the full-width root and unit divides; 6 .. 20: fx_along_pipe for u
    parameter integer STEPS     = 1,      // root and divide iterations a pipeline stage
    parameter integer DIM       = 2,
    parameter integer TAG_W     = 1,
    parameter [0:0]   CARRY     = 1'b0,   // 1: P and C come out beside T (out_p, out_c)
    parameter [0:0]   IN_REG    = 1'b1,   // 0: the caller's registers are cycle 1's (toward_pipe's)
    parameter integer BLOCK_MIN = 64
) (
    input  wire             clk,
    input  wire             reset,        // synchronous, active high: the valid bits
    input  wire             in_valid,
    input  wire             in_excess,    // 0: T = P + o, 1: T = q - o
    input  wire [DIM*W-1:0] in_p,
    input  wire [DIM*W-1:0] in_c,
    input  wire [DIM*W-1:0] in_pp,
    input  wire [DIM*W-1:0] in_pc,
    input  wire [W-1:0]     in_rest,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output reg  [DIM*W-1:0] out_t,
    output reg              out_ok,       // 0: the fallback found a zero length
    output reg  [TAG_W-1:0] out_tag,
    output wire [DIM*W-1:0] out_p,        // CARRY: the operation's P and C (else 0)
    output wire [DIM*W-1:0] out_c
);

    `STRAND_CHECK(toward_prev_pipe_W, W >= 8 && W <= 32, ("toward_prev_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(toward_prev_pipe_DIM, DIM == 2 || DIM == 3, ("toward_prev_pipe: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    localparam integer DW      = DIM * W;
    localparam integer UF      = W - 2;                    // fraction bits of a unit component
`include "pipe_latency.vh"
    localparam integer LSQ     = sqrt_pipe_latency(SQRT_BITS, STEPS);
    localparam integer LDV     = div_pipe_latency(DIV_BITS, STEPS);
    localparam integer T_L     = LSQ + 6;
    localparam integer T_U     = MANTISSA > 0 ? 2 + along_pipe_latency(MANTISSA) : T_L + LDV + 1;
    localparam integer T_G     = T_U + LSQ + 15;
    localparam integer LATENCY = T_G + 6;
    localparam integer LP0     = toward_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA);  // the fallback toward_pipe's
    localparam integer CW_     = CARRY ? DW : 1;
    localparam integer OUT_W   = CW_ + TAG_W + 1 + 2 * DW;   // [C], tag, excess, P, q
    // the streams time their writes by pipe_latency.vh: it must count these stages
    `STRAND_CHECK(toward_prev_pipe_latency_formula, LATENCY == toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA),
                  ("toward_prev_pipe: its stages (%0d) and pipe_latency.vh (%0d) disagree in %m", LATENCY,
                   toward_prev_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA)))

    // ---- the valid bits ----
    reg [LATENCY-1:0] v_q;
    always @(posedge clk)
        if (reset) v_q <= {LATENCY{1'b0}};
        else v_q <= {v_q[LATENCY-2:0], in_valid};
    assign out_valid = v_q[LATENCY-1];

    // ---- the fallback: toward_pipe on the same operands, its result delayed to T_G + 5 ----
    wire          cur_ok, cur_ok_g;
    wire [DW-1:0] cur_t, cur_t_g;
    /* verilator lint_off PINCONNECTEMPTY */
    // its valid, tag, P and C come with this pipe's own
    toward_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .STEPS(STEPS), .DIM(DIM),
                  .TAG_W(1), .IN_REG(IN_REG), .BLOCK_MIN(BLOCK_MIN)) u_cur (
        .clk(clk), .reset(reset), .in_valid(in_valid), .in_excess(in_excess),
        .in_p(in_p), .in_c(in_c), .in_rest(in_rest), .in_tag(1'b0),
        .out_valid(), .out_t(cur_t), .out_ok(cur_ok), .out_tag(), .out_p(), .out_c());
    /* verilator lint_on PINCONNECTEMPTY */
    delay_line #(.WIDTH(DW + 1), .DELAY(T_G + 5 - LP0), .BLOCK_MIN(BLOCK_MIN)) u_cur_ring (
        .clk(clk), .reset(reset), .in({cur_ok, cur_t}), .out({cur_ok_g, cur_t_g}));

    // ---- cycle 1: q = C - P, r = C- - P- ----
    reg [DW-1:0]    p1, c1, pp1, pc1;
    reg [W-1:0]     rest1;
    reg [TAG_W-1:0] tag1;
    reg             excess1;
    generate
        if (IN_REG) begin : g_in_reg
            always @(posedge clk) {p1, c1, pp1, pc1, rest1, tag1, excess1} <= {in_p, in_c, in_pp, in_pc, in_rest, in_tag, in_excess};
        end else begin : g_in_late   // every input but in_valid in cycle 1, from the caller's registers
            always @* {p1, c1, pp1, pc1, rest1, tag1, excess1} = {in_p, in_c, in_pp, in_pc, in_rest, in_tag, in_excess};
        end
    endgenerate
    wire [DW-1:0] q1, r1;
    genvar k;
    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags: the saturated value is the result
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_qr
            fx_add #(.W(W), .SUB(1)) u_q (.sub(1'b1), .a(c1[k*W +: W]), .b(p1[k*W +: W]), .y(q1[k*W +: W]), .sat());
            fx_add #(.W(W), .SUB(1)) u_r (.sub(1'b1), .a(pc1[k*W +: W]), .b(pp1[k*W +: W]), .y(r1[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- cycle 2: |r| and the signs; r's squares start; the rings ----
    reg [DW-1:0]    q2, r2, p2, c2;
    reg [W-1:0]     rest2;
    reg [TAG_W-1:0] tag2;
    reg             excess2;
    always @(posedge clk) {q2, r2, p2, c2, rest2, tag2, excess2} <= {q1, r1, p1, c1, rest1, tag1, excess1};
    wire [DW-1:0]  rabs2;
    wire [DIM-1:0] rneg2;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_abs
            assign rneg2[k] = r2[k*W + W - 1];
            assign rabs2[k*W +: W] = rneg2[k] ? ~r2[k*W +: W] + 1'b1 : r2[k*W +: W];  // -2^(W-1): 2^(W-1) unsigned
        end
    endgenerate
    wire [DW-1:0]    q_dot, q_proj;
    wire [W-1:0]     rest_sq;
    wire [OUT_W-1:0] out_side;
    delay_line #(.WIDTH(DW), .DELAY(T_U - 1), .BLOCK_MIN(BLOCK_MIN)) u_dot_ring (            // to T_U + 1
        .clk(clk), .reset(reset), .in(q2), .out(q_dot));
    delay_line #(.WIDTH(DW), .DELAY(T_U + 7), .BLOCK_MIN(BLOCK_MIN)) u_proj_ring (         // to T_U + 9
        .clk(clk), .reset(reset), .in(q2), .out(q_proj));
    delay_line #(.WIDTH(W), .DELAY(T_U + 8), .BLOCK_MIN(BLOCK_MIN)) u_rest_ring (          // to T_U + 10
        .clk(clk), .reset(reset), .in(rest2), .out(rest_sq));
    delay_line #(.WIDTH(OUT_W), .DELAY(T_G + 2), .BLOCK_MIN(BLOCK_MIN)) u_out_ring (       // to T_G + 4
        .clk(clk), .reset(reset), .in({CARRY ? c2[CW_-1:0] : {CW_{1'b0}}, tag2, excess2, p2, q2}), .out(out_side));

    // ---- u, the unit vector along r in Q2.(W-2), in T_U + 1 (u1); whether r has no length, in T_G + 5 ----
    reg  [DW-1:0] u1;
    wire          zero_g;
    generate
        if (MANTISSA > 0) begin : g_norm
            // fx_along_pipe(r, 2^(W-2)) from cycle 2 (its rest a constant: synthesis folds that path)
            localparam [W-1:0] ONE_U = {2'b01, {(W-2){1'b0}}};
            wire [DW-1:0] u_a;
            wire          ok_a;
            fx_along_pipe #(.W(W), .MB(MANTISSA), .DIM(DIM), .BLOCK_MIN(BLOCK_MIN)) u_along (
                .clk(clk), .reset(reset), .d(r2), .rest(ONE_U), .t(u_a), .ok(ok_a));
            reg zero_u1;
            always @(posedge clk) begin
                u1      <= u_a;
                zero_u1 <= !ok_a;
            end
            delay_line #(.WIDTH(1), .DELAY(T_G + 5 - (T_U + 1)), .BLOCK_MIN(BLOCK_MIN)) u_zero_ring (
                .clk(clk), .reset(reset), .in(zero_u1), .out(zero_g));
            wire unused_norm = &{1'b0, rabs2, rneg2};
        end else begin : g_full
            wire [DIM*2*W-1:0] rsq4;
            for (k = 0; k < DIM; k = k + 1) begin : g_rsq
                fx_mul_pipe #(.W(W)) u_sq (.clk(clk), .a(r2[k*W +: W]), .b(r2[k*W +: W]), .prod(rsq4[k*2*W +: 2*W]));
            end
            wire [DW-1:0]    rabs_l;
            wire [DIM-1:0]   rneg_u;
            delay_line #(.WIDTH(DW), .DELAY(T_L - 2), .BLOCK_MIN(BLOCK_MIN)) u_abs_ring (
                .clk(clk), .reset(reset), .in(rabs2), .out(rabs_l));
            delay_line #(.WIDTH(DIM), .DELAY(T_U - 2), .BLOCK_MIN(BLOCK_MIN)) u_sign_ring (          // to T_U
                .clk(clk), .reset(reset), .in(rneg2), .out(rneg_u));

            // ---- cycles 4 .. T_L: r.r and its root ----
            reg [2*W-1:0] rad5;   // each square <= 2^(2W-2): three fit 2W bits
            always @(posedge clk)
                rad5 <= rsq4[0 +: 2*W] + rsq4[2*W +: 2*W] + (DIM == 3 ? rsq4[(DIM-1)*2*W +: 2*W] : {2*W{1'b0}});
            wire [W-1:0] lr;
            /* verilator lint_off PINCONNECTEMPTY */
            fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS), .STEPS(STEPS)) u_sqrt_r (.clk(clk), .radicand(rad5), .result(lr), .sat());
            /* verilator lint_on PINCONNECTEMPTY */

            // ---- T_L: the unit dividers; lr = 0 says the start direction has none ----
            wire [DW-1:0] umag;
            /* verilator lint_off PINCONNECTEMPTY */
            for (k = 0; k < DIM; k = k + 1) begin : g_div
                fx_div_pipe #(.W(W), .F(UF), .DIV_BITS(DIV_BITS), .STEPS(STEPS)) u_div (
                    .clk(clk), .num(rabs_l[k*W +: W]), .den(lr), .result(umag[k*W +: W]), .div_by_zero(), .sat());
            end
            /* verilator lint_on PINCONNECTEMPTY */
            reg  zero_l1;
            always @(posedge clk) zero_l1 <= lr == {W{1'b0}};
            delay_line #(.WIDTH(1), .DELAY(T_G + 5 - (T_L + 1)), .BLOCK_MIN(BLOCK_MIN)) u_zero_ring (
                .clk(clk), .reset(reset), .in(zero_l1), .out(zero_g));

            // ---- T_U: u signed (T_U + 1) ----
            for (k = 0; k < DIM; k = k + 1) begin : g_u
                always @(posedge clk)   // |u_k| <= 2^(W-1)-1: its negation fits
                    u1[k*W +: W] <= rneg_u[k] ? ~umag[k*W +: W] + 1'b1 : umag[k*W +: W];
            end
        end
    endgenerate

    // ---- T_U + 1: the products q_k u_k ----
    wire [DIM*2*W-1:0] dprod;
    wire [DW-1:0]      dround;
    reg  [DW-1:0]      dterm;     // T_U + 4
    /* verilator lint_off PINCONNECTEMPTY */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_dot
            fx_mul_pipe #(.W(W)) u_mul (.clk(clk), .a(q_dot[k*W +: W]), .b(u1[k*W +: W]), .prod(dprod[k*2*W +: 2*W]));
            fx_round #(.W(W), .F(UF)) u_round (.prod(dprod[k*2*W +: 2*W]), .y(dround[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) dterm <= dround;
    // s = 0 + t0 + t1 [+ t2], saturating, in axis order: two stages
    wire [W-1:0] s01, s012;
    reg  [W-1:0] s01_q, t2_q, s_q;   // s01_q, t2_q in T_U + 5; s_q in T_U + 6
    /* verilator lint_off PINCONNECTEMPTY */
    fx_add #(.W(W), .SUB(0)) u_s01 (.sub(1'b0), .a(dterm[0 +: W]), .b(dterm[W +: W]), .y(s01), .sat());
    fx_add #(.W(W), .SUB(0)) u_s2 (.sub(1'b0), .a(s01_q), .b(t2_q), .y(s012), .sat());
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) begin
        s01_q <= s01;
        t2_q  <= DIM == 3 ? dterm[(DIM-1)*W +: W] : {W{1'b0}};  // 2D: + 0 changes nothing
        s_q   <= s012;
    end

    // u from T_U + 1 to T_U + 6 and to T_G; s's sign from T_U + 6 to T_G + 3
    wire [DW-1:0] u_proj, u_leg;
    wire          sneg_o;
    delay_line #(.WIDTH(DW), .DELAY(5), .BLOCK_MIN(BLOCK_MIN)) u_u_ring1 (
        .clk(clk), .reset(reset), .in(u1), .out(u_proj));
    delay_line #(.WIDTH(DW), .DELAY(T_G - (T_U + 1)), .BLOCK_MIN(BLOCK_MIN)) u_u_ring2 (
        .clk(clk), .reset(reset), .in(u1), .out(u_leg));
    delay_line #(.WIDTH(1), .DELAY(T_G + 3 - (T_U + 6)), .BLOCK_MIN(BLOCK_MIN)) u_s_ring (
        .clk(clk), .reset(reset), .in(s_q[W-1]), .out(sneg_o));

    // ---- T_U + 6: s u_k; T_U + 9: p_k = q_k - round(s u_k) ----
    wire [DIM*2*W-1:0] sprod;
    wire [DW-1:0]      sround, pv9;
    reg  [DW-1:0]      su_q, pv_q;  // su_q in T_U + 9, pv_q in T_U + 10
    /* verilator lint_off PINCONNECTEMPTY */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_proj
            fx_mul_pipe #(.W(W)) u_mul (.clk(clk), .a(s_q), .b(u_proj[k*W +: W]), .prod(sprod[k*2*W +: 2*W]));
            fx_round #(.W(W), .F(UF)) u_round (.prod(sprod[k*2*W +: 2*W]), .y(sround[k*W +: W]), .sat());
            fx_add #(.W(W), .SUB(1)) u_p (.sub(1'b1), .a(q_proj[k*W +: W]), .b(su_q[k*W +: W]), .y(pv9[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) begin
        su_q <= sround;
        pv_q <= pv9;
    end

    // ---- T_U + 10: p_k^2 and rest^2; T_U + 12: p.p; T_U + 13: miss, rest^2 - p.p ----
    wire [DIM*2*W-1:0] psq;
    wire [2*W-1:0]     hh;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_psq
            fx_mul_pipe #(.W(W)) u_sq (.clk(clk), .a(pv_q[k*W +: W]), .b(pv_q[k*W +: W]), .prod(psq[k*2*W +: 2*W]));
        end
    endgenerate
    fx_mul_pipe #(.W(W)) u_hh (.clk(clk), .a(rest_sq), .b(rest_sq), .prod(hh));
    reg [2*W-1:0] dd13, hh13, rad14;
    reg           miss14;
    always @(posedge clk) begin
        dd13   <= psq[0 +: 2*W] + psq[2*W +: 2*W] + (DIM == 3 ? psq[(DIM-1)*2*W +: 2*W] : {2*W{1'b0}});
        hh13   <= hh;
        rad14  <= hh13 - dd13;
        miss14 <= dd13 > hh13;
    end
    wire [DW-1:0] pv_o;
    wire          miss_g;
    delay_line #(.WIDTH(DW), .DELAY(T_G + 3 - (T_U + 10)), .BLOCK_MIN(BLOCK_MIN)) u_p_ring (
        .clk(clk), .reset(reset), .in(pv_q), .out(pv_o));
    delay_line #(.WIDTH(1), .DELAY(T_G + 5 - (T_U + 14)), .BLOCK_MIN(BLOCK_MIN)) u_miss_ring (
        .clk(clk), .reset(reset), .in(miss14), .out(miss_g));

    // ---- T_U + 14 .. T_G: the leg ----
    wire [W-1:0] leg;
    /* verilator lint_off PINCONNECTEMPTY */
    fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS), .STEPS(STEPS)) u_sqrt_leg (.clk(clk), .radicand(rad14), .result(leg), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- T_G: leg u_k; T_G + 3: o_k; T_G + 4: T_k; T_G + 5: T or the fallback's ----
    wire [DIM*2*W-1:0] lprod;
    wire [DW-1:0]      lround, o3, t4;
    reg  [DW-1:0]      lu_q, o_q, t_q;
    wire [CW_-1:0]     c_o   = out_side[OUT_W-1 -: CW_];
    wire [TAG_W-1:0]   tag_o = out_side[OUT_W-CW_-1 -: TAG_W];
    wire               exc_o = out_side[2*DW];
    wire [DW-1:0]      p_o   = out_side[DW +: DW];
    wire [DW-1:0]      q_o   = out_side[0 +: DW];
    reg  [CW_-1:0]     c5, c_out;
    reg  [DW-1:0]      p5, p_out;
    reg  [TAG_W-1:0]   tag5;
    /* verilator lint_off PINCONNECTEMPTY */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_leg
            fx_mul_pipe #(.W(W)) u_mul (.clk(clk), .a(leg), .b(u_leg[k*W +: W]), .prod(lprod[k*2*W +: 2*W]));
            fx_round #(.W(W), .F(UF)) u_round (.prod(lprod[k*2*W +: 2*W]), .y(lround[k*W +: W]), .sat());
            fx_add #(.W(W)) u_o (.sub(sneg_o), .a(pv_o[k*W +: W]), .b(lu_q[k*W +: W]), .y(o3[k*W +: W]), .sat());
            fx_add #(.W(W)) u_t (.sub(exc_o), .a(exc_o ? q_o[k*W +: W] : p_o[k*W +: W]), .b(o_q[k*W +: W]),
                                 .y(t4[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) begin
        lu_q  <= lround;            // T_G + 3
        o_q   <= o3;                // T_G + 4
        t_q   <= t4;                // T_G + 5
        tag5  <= tag_o;
        p5    <= p_o;
        c5    <= c_o;
        out_t   <= zero_g || miss_g ? cur_t_g : t_q;
        out_ok  <= zero_g || miss_g ? cur_ok_g : 1'b1;
        out_tag <= tag5;
        p_out   <= p5;
        c_out   <= c5;
    end

    generate
        if (CARRY) begin : g_carry
            assign out_p = p_out;
            assign out_c = c_out;
        end else begin : g_no_carry
            assign out_p = {DW{1'b0}};
            assign out_c = {DW{1'b0}};
            wire unused_carry = &{1'b0, p_out, c_out, c2};
        end
    endgenerate

endmodule

`resetall
