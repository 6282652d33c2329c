`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * spring_force_pipe - spring_force, pipelined: a new spring (A, A-, B, B-, rest) every
 * clock, its force a fixed number of cycles later.
 *
 * Computes exactly what spring_force computes (model/engine_body.h spring_edge(), in its
 * order of operations): with d = B - A, v_a = A - A-, v_b = B - B- (saturating, per axis)
 *     len = fx_sqrt(d.d)                        the exact 2W-bit sum of exact squares
 *     u.k = fx_div_signed(d.k, len)             |d.k| / len on fx_div_pipe, sign restored
 *     vn  = sum_k round(dv.k u.k)               dv = v_b - v_a, summed in axis order
 *     f   = round(ks (len - rest) + kd vn)      the two exact products summed (clamped to
 *                                               2W bits), rounded once (fx_mac2)
 *     F.k = round(f u.k)                        the force on A; B takes -F
 * ok = 0 when len = 0 (the dividers' divide-by-zero flag): no force.
 *
 * MANTISSA > 0, the normalised datapath (model/fixed.h fx_spring_dir): u is fx_along_pipe's
 * vector of length 2^(W-2) along d (a unit vector in Q2.(W-2): d's direction exactly, its length
 * from MANTISSA-bit mantissas) and len = d . u, the exact sum of the DIM products rounded once by
 * W - 2 bits; the products with u (vn, the forces) are rounded by W - 2 bits too (fx_mul_unit);
 * ok = 0 also when len <= 0. The stages from T_U on are the same, with T_U = 2 + LA (LA =
 * fx_along_pipe's 21): len's products in T_U + 1 .. T_U + 3, len in T_U + 4, len - rest in
 * T_U + 5; LATENCY = LA + 15 = 36 (hw_spring_pipe_latency).
 *
 * Algorithm: the root and the dividers are fx_sqrt_pipe and fx_div_pipe (the digit-by-
 * digit root and divide of fx_sqrt and fx_div, STEPS resolved bits a stage, so SQRT_BITS
 * and DIV_BITS stay the accuracy knobs and the results are spring_force's bit for bit).
 * DIM dividers run side by side (one per component of u); every multiply is an
 * fx_mul_pipe of its own (DIM squares, DIM vn products, ks and kd, DIM forces). Values
 * needed again later ride beside the root and the dividers in delay_line rings.
 *
 * Stages, counting the cycle in which an operation is on the inputs as cycle 0:
 *   1 d, v_a, v_b        2 dv; |d| and the signs; the squares start (two cycles)
 *   4 their sum          5 .. the root: len there in T_LEN = LSQ + 6
 *   T_LEN                the dividers start; len - rest
 *   T_U = T_LEN + LDV + 1        the quotients; u.k, signed, registered
 *   T_U + 1              the vn products start    T_U + 3  rounded
 *   T_U + 4, + 5         vn summed in axis order  T_U + 6  ks (len - rest) and kd vn start
 *   T_U + 8              their exact sum          T_U + 9  f rounded
 *   T_U + 10             the forces start         T_U + 12 rounded, on the outputs at T_U + 13
 * LSQ and LDV are the root's and the dividers' latencies (pipe_latency.vh: with STEPS = 1,
 * SQRT_BITS + 2 and DIV_BITS + 2). LATENCY = LSQ + LDV + 20, SQRT_BITS + DIV_BITS + 24 with
 * STEPS = 1 (model/timing.c hw_spring_pipe_latency): an operation on the inputs in cycle 0
 * has out_valid, out_f, out_ok and out_tag in cycle LATENCY.
 * Throughput one spring per clock. ks and kd come with each spring and ride beside it.
 *
 * Ports: a, a_p, b, b_p, out_f are DIM lanes of signed Q(W-F).F (lane k at bits k W +: W);
 * rest unsigned Q(W-F).F; ks, kd the scaled stiffness and damping, signed Q(W-F).F; tag: TAG_W bits the caller gets back with the result. Only the
 * valid bits are reset.
 */
module spring_force_pipe #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,      // 0: the full-width root and divides; 6 .. 20: fx_along_pipe
    parameter integer STEPS     = 1,      // root and divide iterations a pipeline stage
    parameter integer DIM       = 2,
    parameter integer TAG_W     = 1,
    parameter integer BLOCK_MIN = 64      // delay rings: strand_ram's block RAM threshold
) (
    input  wire             clk,
    input  wire             reset,        // synchronous, active high: the valid bits
    input  wire             in_valid,
    input  wire [DIM*W-1:0] in_a,
    input  wire [DIM*W-1:0] in_ap,
    input  wire [DIM*W-1:0] in_b,
    input  wire [DIM*W-1:0] in_bp,
    input  wire [W-1:0]     in_rest,
    input  wire [W-1:0]     in_ks,        // scaled stiffness and damping
    input  wire [W-1:0]     in_kd,
    input  wire [TAG_W-1:0] in_tag,
    output wire             out_valid,
    output reg  [DIM*W-1:0] out_f,        // the force on A
    output reg              out_ok,       // 0: zero length, no force
    output wire [TAG_W-1:0] out_tag
);

    `STRAND_CHECK(spring_force_pipe_W, W >= 8 && W <= 32, ("spring_force_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(spring_force_pipe_DIM, DIM == 2 || DIM == 3, ("spring_force_pipe: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    localparam integer DW      = DIM * W;
`include "pipe_latency.vh"
    localparam integer LSQ     = sqrt_pipe_latency(SQRT_BITS, STEPS);
    localparam integer LDV     = div_pipe_latency(DIV_BITS, STEPS);
    localparam integer T_LEN   = LSQ + 6;                // len on the root's output
    localparam integer T_U     = MANTISSA > 0 ? 2 + along_pipe_latency(MANTISSA)   // u on fx_along_pipe's output
                                              : T_LEN + LDV + 1;                   // the quotients on the dividers'
    localparam integer LATENCY = T_U + 13;
    localparam integer F_U     = MANTISSA > 0 ? W - 2 : F;   // u's fraction bits: the products with it round by them
    // the spring stream times its writes by pipe_latency.vh: it must count these stages
    `STRAND_CHECK(spring_force_pipe_latency_formula, LATENCY == spring_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA),
                  ("spring_force_pipe: its stages (%0d) and pipe_latency.vh (%0d) disagree in %m", LATENCY,
                   spring_pipe_latency(SQRT_BITS, DIV_BITS, STEPS, MANTISSA)))

    // ---- the valid bits: bit i is the operation in cycle i + 1 ----
    reg [LATENCY-1:0] v_q;
    always @(posedge clk)
        if (reset) v_q <= {LATENCY{1'b0}};
        else v_q <= {v_q[LATENCY-2:0], in_valid};
    assign out_valid = v_q[LATENCY-1];
    delay_line #(.WIDTH(TAG_W), .DELAY(LATENCY), .BLOCK_MIN(BLOCK_MIN)) u_tag_ring (
        .clk(clk), .reset(reset), .in(in_tag), .out(out_tag));

    // ---- cycle 1: d = B - A, v_a = A - A-, v_b = B - B- ----
    reg [DW-1:0] a1, ap1, b1, bp1;
    reg [W-1:0]  rest1, rest2, ks1, ks2, kd1, kd2;
    always @(posedge clk) begin
        {a1, ap1, b1, bp1, rest1, ks1, kd1} <= {in_a, in_ap, in_b, in_bp, in_rest, in_ks, in_kd};
        {rest2, ks2, kd2} <= {rest1, ks1, kd1};
    end
    wire [DW-1:0] d1, va1, vb1, dv2, dabs2;
    reg  [DW-1:0] d2, va2, vb2;
    reg  [DIM-1:0] dneg2;
    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags: the saturated value is the result
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_diff
            fx_add #(.W(W), .SUB(1)) u_d  (.sub(1'b1), .a(b1[k*W +: W]), .b(a1[k*W +: W]),  .y(d1[k*W +: W]),  .sat());
            fx_add #(.W(W), .SUB(1)) u_va (.sub(1'b1), .a(a1[k*W +: W]), .b(ap1[k*W +: W]), .y(va1[k*W +: W]), .sat());
            fx_add #(.W(W), .SUB(1)) u_vb (.sub(1'b1), .a(b1[k*W +: W]), .b(bp1[k*W +: W]), .y(vb1[k*W +: W]), .sat());
            // cycle 2: dv = v_b - v_a; |d.k| (-2^(W-1) reads 2^(W-1) unsigned) and its sign
            fx_add #(.W(W), .SUB(1)) u_dv (.sub(1'b1), .a(vb2[k*W +: W]), .b(va2[k*W +: W]), .y(dv2[k*W +: W]), .sat());
            assign dabs2[k*W +: W] = d2[k*W + W - 1] ? ~d2[k*W +: W] + 1'b1 : d2[k*W +: W];
            always @(posedge clk) dneg2[k] <= d1[k*W + W - 1];
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) {d2, va2, vb2} <= {d1, va1, vb1};

    // ---- the front: u in T_U + 1 (u1), ok there (ok1), len - rest with ks and kd in T_U + 6,
    // and (MANTISSA) whether len > 0 in T_U + 10; dv rides to T_U ----
    reg  [DW-1:0] u1, dv1;     // in cycle T_U + 1
    reg           ok1;
    wire [W-1:0]  stretch_f, ks_f, kd_f;
    wire          len_ok_f;
    wire [DW-1:0] dv_u;
    generate
        if (MANTISSA > 0) begin : g_norm
            // u = fx_along_pipe(d, 2^(W-2)) from cycle 2 (its rest a constant: synthesis folds that path)
            localparam [W-1:0] ONE_U = {2'b01, {(W-2){1'b0}}};
            wire [DW-1:0] u_a;
            wire          ok_a;
            fx_along_pipe #(.W(W), .MB(MANTISSA), .DIM(DIM), .BLOCK_MIN(BLOCK_MIN)) u_along (
                .clk(clk), .reset(reset), .d(d2), .rest(ONE_U), .t(u_a), .ok(ok_a));
            // d, dv, rest, ks and kd ride to T_U
            wire [DW-1:0] d_u;
            wire [W-1:0]  rest_u, ks_u, kd_u;
            delay_line #(.WIDTH(2 * DW + 3 * W), .DELAY(T_U - 2), .BLOCK_MIN(BLOCK_MIN)) u_d_ring (
                .clk(clk), .reset(reset), .in({kd2, ks2, rest2, dv2, d2}), .out({kd_u, ks_u, rest_u, dv_u, d_u}));
            reg [DW-1:0] d_u1;
            reg [W-1:0]  rest_1, rest_2, rest_3, rest_4, ks_1, ks_2, ks_3, ks_4, ks_5, kd_1, kd_2, kd_3, kd_4, kd_5;
            always @(posedge clk) begin
                u1    <= u_a;
                ok1   <= ok_a;
                dv1   <= dv_u;
                d_u1  <= d_u;
                {rest_1, ks_1, kd_1} <= {rest_u, ks_u, kd_u};
                {rest_2, ks_2, kd_2} <= {rest_1, ks_1, kd_1};
                {rest_3, ks_3, kd_3} <= {rest_2, ks_2, kd_2};
                {rest_4, ks_4, kd_4} <= {rest_3, ks_3, kd_3};
                {ks_5, kd_5}         <= {ks_4, kd_4};
            end
            // T_U + 1 .. + 3: the products d.k u.k (each >= 0: u is parallel to d); their exact sum
            // (below 2^(2W-1)), rounded by W - 2 bits: len in T_U + 4
            wire [DIM*2*W-1:0] lprod;
            for (k = 0; k < DIM; k = k + 1) begin : g_len
                fx_mul_pipe #(.W(W)) u_lmul (.clk(clk), .a(d_u1[k*W +: W]), .b(u1[k*W +: W]), .prod(lprod[k*2*W +: 2*W]));
            end
            wire [2*W-1:0] dot = lprod[0 +: 2*W] + lprod[2*W +: 2*W] + (DIM == 3 ? lprod[(DIM-1)*2*W +: 2*W] : {2*W{1'b0}});
            wire [W-1:0]   len_r;
            /* verilator lint_off PINCONNECTEMPTY */
            fx_round #(.W(W), .F(W - 2)) u_lround (.prod(dot), .y(len_r), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            reg  [W-1:0] len_4, stretch_5, stretch_6, ks_6, kd_6;
            wire [W-1:0] stretch_w;
            /* verilator lint_off PINCONNECTEMPTY */
            fx_add #(.W(W), .SUB(1)) u_stretch (.sub(1'b1), .a(len_4), .b(rest_4), .y(stretch_w), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            reg [5:0] len_pos_q;      // len > 0, from T_U + 5 to T_U + 10
            always @(posedge clk) begin
                len_4     <= len_r;
                stretch_5 <= stretch_w;
                stretch_6 <= stretch_5;
                ks_6      <= ks_5;
                kd_6      <= kd_5;
                len_pos_q <= {len_pos_q[4:0], !len_4[W-1] && len_4 != {W{1'b0}}};
            end
            assign {stretch_f, ks_f, kd_f} = {stretch_6, ks_6, kd_6};
            assign len_ok_f = len_pos_q[5];
            wire unused_norm = &{1'b0, dneg2, dabs2};
        end else begin : g_full
            // ---- cycles 2 .. 4: the squares, their sum; then the root ----
            wire [DIM*2*W-1:0] sq4;
            for (k = 0; k < DIM; k = k + 1) begin : g_sq
                fx_mul_pipe #(.W(W)) u_sq (.clk(clk), .a(d2[k*W +: W]), .b(d2[k*W +: W]), .prod(sq4[k*2*W +: 2*W]));
            end
            reg [2*W-1:0] radicand5;  // each square <= 2^(2W-2): three fit 2W bits
            always @(posedge clk)
                radicand5 <= sq4[0 +: 2*W] + sq4[2*W +: 2*W] + (DIM == 3 ? sq4[(DIM-1)*2*W +: 2*W] : {2*W{1'b0}});
            wire [W-1:0] len;
            /* verilator lint_off PINCONNECTEMPTY */
            fx_sqrt_pipe #(.W(W), .SQRT_BITS(SQRT_BITS), .STEPS(STEPS)) u_sqrt (.clk(clk), .radicand(radicand5), .result(len), .sat());
            /* verilator lint_on PINCONNECTEMPTY */

            // rings from cycle 2: |d|, rest, ks and kd to T_LEN; dv and the signs to T_U
            wire [DW-1:0]  dabs_len;
            wire [W-1:0]   rest_len, ks_len, kd_len;
            wire [DIM-1:0] dneg_u;
            delay_line #(.WIDTH(DW + 3 * W), .DELAY(T_LEN - 2), .BLOCK_MIN(BLOCK_MIN)) u_abs_ring (
                .clk(clk), .reset(reset), .in({kd2, ks2, rest2, dabs2}), .out({kd_len, ks_len, rest_len, dabs_len}));
            delay_line #(.WIDTH(DW + DIM), .DELAY(T_U - 2), .BLOCK_MIN(BLOCK_MIN)) u_dv_ring (
                .clk(clk), .reset(reset), .in({dneg2, dv2}), .out({dneg_u, dv_u}));

            // ---- T_LEN: the dividers start; stretch = len - rest, carried to T_U + 6 with ks and kd ----
            wire [DW-1:0]  qmag;     // |u.k|
            wire [DIM-1:0] dz;
            wire [W-1:0]   stretch_len;
            /* verilator lint_off PINCONNECTEMPTY */
            for (k = 0; k < DIM; k = k + 1) begin : g_div
                fx_div_pipe #(.W(W), .F(F), .DIV_BITS(DIV_BITS), .STEPS(STEPS)) u_div (
                    .clk(clk), .num(dabs_len[k*W +: W]), .den(len), .result(qmag[k*W +: W]), .div_by_zero(dz[k]), .sat());
            end
            fx_add #(.W(W), .SUB(1)) u_stretch (.sub(1'b1), .a(len), .b(rest_len), .y(stretch_len), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            reg [W-1:0] stretch_q, ks_q, kd_q;
            always @(posedge clk) {stretch_q, ks_q, kd_q} <= {stretch_len, ks_len, kd_len};
            delay_line #(.WIDTH(3 * W), .DELAY(T_U + 6 - (T_LEN + 1)), .BLOCK_MIN(BLOCK_MIN)) u_stretch_ring (
                .clk(clk), .reset(reset), .in({kd_q, ks_q, stretch_q}), .out({kd_f, ks_f, stretch_f}));

            // ---- T_U: u.k with its sign ----
            for (k = 0; k < DIM; k = k + 1) begin : g_u
                always @(posedge clk)
                    u1[k*W +: W] <= dneg_u[k] ? ~qmag[k*W +: W] + 1'b1 : qmag[k*W +: W];  // |u.k| <= 2^(W-1)-1
            end
            always @(posedge clk) begin
                dv1 <= dv_u;
                ok1 <= !dz[0];        // every divider has den = len: one flag says it
            end
            wire unused_dz = &{1'b0, dz[DIM-1:1]};
            assign len_ok_f = 1'b1;
        end
    endgenerate

    // ---- T_U + 1: the vn products ----
    wire [DIM*2*W-1:0] vprod;  // in T_U + 3
    wire [DW-1:0]      vround;
    reg  [DW-1:0]      vterm;  // in T_U + 4
    /* verilator lint_off PINCONNECTEMPTY */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_vn
            fx_mul_pipe #(.W(W)) u_vmul (.clk(clk), .a(dv1[k*W +: W]), .b(u1[k*W +: W]), .prod(vprod[k*2*W +: 2*W]));
            fx_round #(.W(W), .F(F_U)) u_vround (.prod(vprod[k*2*W +: 2*W]), .y(vround[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) vterm <= vround;
    // vn = 0 + t0 + t1 [+ t2], saturating, in axis order: two stages
    wire [W-1:0] sum01, sum012;
    reg  [W-1:0] sum01_q, t2_q, vn_q;  // sum01_q, t2_q in T_U + 5; vn_q in T_U + 6
    /* verilator lint_off PINCONNECTEMPTY */
    fx_add #(.W(W), .SUB(0)) u_vn01 (.sub(1'b0), .a(vterm[0 +: W]), .b(vterm[W +: W]), .y(sum01), .sat());
    fx_add #(.W(W), .SUB(0)) u_vn2 (.sub(1'b0), .a(sum01_q), .b(t2_q), .y(sum012), .sat());
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) begin
        sum01_q <= sum01;
        t2_q    <= DIM == 3 ? vterm[(DIM-1)*W +: W] : {W{1'b0}};  // 2D: + 0 changes nothing
        vn_q    <= sum012;
    end

    // ---- T_U + 6: ks (len - rest) and kd vn, exact; T_U + 8 their sum; T_U + 9 f ----
    wire [2*W-1:0] t_ks, t_kd;
    fx_mul_pipe #(.W(W)) u_ks (.clk(clk), .a(ks_f), .b(stretch_f), .prod(t_ks));
    fx_mul_pipe #(.W(W)) u_kd (.clk(clk), .a(kd_f), .b(vn_q), .prod(t_kd));
    wire [2*W:0]   mac_wide = {t_ks[2*W-1], t_ks} + {t_kd[2*W-1], t_kd};
    wire           mac_over = mac_wide[2*W] != mac_wide[2*W-1];
    reg  [2*W-1:0] mac_q;     // clamped to 2W bits: beyond them f saturates either way
    always @(posedge clk) mac_q <= mac_over ? {mac_wide[2*W], {(2*W-1){!mac_wide[2*W]}}} : mac_wide[2*W-1:0];
    wire [W-1:0] f_round;
    reg  [W-1:0] f_q;         // in T_U + 10
    /* verilator lint_off PINCONNECTEMPTY */
    fx_round #(.W(W), .F(F)) u_fround (.prod(mac_q), .y(f_round), .sat());
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) f_q <= f_round;

    // u and ok from T_U + 1 to T_U + 10
    wire [DW-1:0] u_f;
    wire          ok_f;
    delay_line #(.WIDTH(DW + 1), .DELAY(9), .BLOCK_MIN(BLOCK_MIN)) u_u_ring (
        .clk(clk), .reset(reset), .in({ok1, u1}), .out({ok_f, u_f}));

    // ---- T_U + 10: the forces F.k = f u.k; rounded in T_U + 12; out in T_U + 13 ----
    wire [DIM*2*W-1:0] fprod;
    wire [DW-1:0]      fround;
    reg                ok_11, ok_12;
    /* verilator lint_off PINCONNECTEMPTY */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_f
            fx_mul_pipe #(.W(W)) u_fmul (.clk(clk), .a(f_q), .b(u_f[k*W +: W]), .prod(fprod[k*2*W +: 2*W]));
            fx_round #(.W(W), .F(F_U)) u_fr (.prod(fprod[k*2*W +: 2*W]), .y(fround[k*W +: W]), .sat());
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    always @(posedge clk) begin
        ok_11  <= ok_f && len_ok_f;
        ok_12  <= ok_11;
        out_ok <= ok_12;
        out_f  <= fround;
    end

endmodule

`resetall
