`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * fx_along_pipe - the vector of length rest along d, on normalised mantissas: the
 * normalised distance datapath of model/fixed.c fx_along, bit for bit, one operation a
 * clock.
 *
 * Computes t = d rest / |d| (each lane rounded once into Q(W-F).F, saturated) and
 * ok = (d != 0); the caller forms the centred rule's P + t or the pairwise rule's d - t.
 * The positions keep their W-bit format; the constraint is computed on MB-bit mantissas
 * that share one exponent, because it needs only the relative precision of one link.
 *
 * Ports: d is DIM lanes of signed W-bit words (lane k at bits k W +: W), rest unsigned
 * W bits (both in the scene's Q format: the format cancels, so F is not a parameter);
 * t as d. A mantissa word is MB + 1 bits signed (MB = 17: every product one signed
 * 18 x 18 multiplier block, fx_mul_pipe).
 *
 * Algorithm (fixed.h lists the same six steps; "round" is ties to even, "clamp" keeps an
 * unsigned mantissa below 2^MB, a signed one's positive side below 2^MB):
 *   1 normalise: L = the leading one of |d.x| | |d.y| | |d.z|; m_k = d_k 2^(MB-1-L),
 *     rounded, clamped (a funnel: {d_k, MB zero bits} shifted right by L + 1), so the
 *     largest |m_k| has MB significant bits. rest likewise: R = rest 2^(MB-1-Lr).
 *   2 x = sum m_k^2, exact: x in [2^(2MB-2), 2^(2MB+2)), so its leading one Lx is one of
 *     four places: c = Lx - (2MB-2) is read from x's top three bits.
 *   3 reciprocal root: x' = x 2^-(MB-1+c), rounded, clamped (MB bits); v = x / 4^J in
 *     [1, 4) with J = MB - 1 + c/2 and p = c mod 2 (v >= 2); a ROM of 2^T entries (T = MB/2
 *     + 1), indexed by p and the T - 1 bits of x' below its leading one, holds the seed
 *     Y0 = 2^MB / sqrt(middle of the interval) and C0 = Y0^3 2^-2MB (fx_rsqrt_seed.vh: the
 *     same integer formula as fx_rsqrt_seed, evaluated at elaboration); one Newton step
 *     Y1 = round((3 Y0 2^(MB-1) - x' C0 2^p) / 2^MB), clamped to 0 .. 2^MB - 1, is
 *     2^MB / sqrt(v) within about 1.5 2^-(2T+2) + 2^-MB relative.
 *   4 the ratio's mantissa: Q = R Y1, b = Q's bit 2MB - 1, Qm = Q 2^-(MB-1+b) rounded,
 *     clamped.
 *   5 back into the format: t_k = d_k Qm 2^-(sh+s) with sh = J + 1 - b - (Lr - MB + 1) and
 *     s = L - MB + 1, rounded and saturated to W bits; the shift's range [MB-W, W+MB] is made
 *     all right shifts of at least one bit by a constant left shift of PRE + 1 first.
 * The product takes d, not m_k: Qm 2^-(sh+s) is rest / |d|, so t keeps d's direction exactly
 * and only its length comes from the mantissas (rounded m_k would put every target on a grid of
 * about rest 2^-MB across the link). Error: a few 2^-MB of rest, along d (test_fixed.c holds the
 * model to 6 2^-MB rest + 1 LSB); docs/model.md gives the terms.
 *
 * Why a reciprocal root: the device's multipliers and block RAM do the work the root's and
 * the divider's adder rows did: the table is one DP16KD at MB = 17 and the Newton step one
 * multiplier, the table holding the seed's cube (docs/resources.md has the cells of a unit of
 * each datapath, docs/accuracy.md of every MB).
 *
 * Stages (a value "in cycle n" is held by a register written at the end of cycle n - 1;
 * d and rest are on the inputs in cycle 0):
 *   1 |d_k| OR-ed                    2 L, Lr (leading ones), the zero flag
 *   3 the funnels (m_k, R before rounding)   4 m_k, R rounded
 *   5, 6 the squares (fx_mul_pipe)   7 x     8 c: x' before rounding, the ROM index
 *   9 the ROM word (Y0, C0), x' rounded      10, 11 x' C0
 *   12 Newton's difference           13 Y1   14, 15 Q = R Y1
 *   16 Qm before rounding, the shift 17 Qm   18, 19 d_k Qm
 *   20 the shift back                21 t rounded, saturated, and ok
 * LATENCY = 21 (model/timing.c hw_along_pipe_latency, pipe_latency.vh): an operation on
 * the inputs in cycle 0 has t and ok in cycle 21. Throughput one operation a clock. d and R
 * wait for the ratio in delay_line rings. No reset: the caller's valid bits say
 * what the outputs mean.
 */
module fx_along_pipe #(
    parameter integer W         = 32,  // position word width, 8..32
    parameter integer MB        = 17,  // mantissa significant bits, 6..20
    parameter integer DIM       = 2,   // 2 or 3 lanes
    parameter integer BLOCK_MIN = 64   // delay rings: strand_ram's block RAM threshold
) (
    input  wire             clk,
    input  wire             reset,     // synchronous: the rings' slot counters only
    input  wire [DIM*W-1:0] d,         // signed lanes
    input  wire [W-1:0]     rest,      // unsigned
    output reg  [DIM*W-1:0] t,         // signed lanes, rounded and saturated
    output reg              ok         // 0: d = 0, no direction (t = 0)
);

    `STRAND_CHECK(fx_along_pipe_W, W >= 8 && W <= 32, ("fx_along_pipe: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(fx_along_pipe_MB, MB >= 6 && MB <= 20, ("fx_along_pipe: MB must be 6..20 (MB=%0d) in %m", MB))
    `STRAND_CHECK(fx_along_pipe_DIM, DIM == 2 || DIM == 3, ("fx_along_pipe: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    localparam integer LATENCY = 21;
    localparam integer MW  = MB + 1;                   // a signed mantissa word
    localparam integer WM  = MW < 8 ? 8 : MW;          // fx_mul_pipe's operand width (8 .. 32)
    localparam integer PW  = 2 * WM;                   // its product width
    localparam integer T   = MB / 2 + 1;               // seed table index bits
    localparam integer LB  = $clog2(W);                // a leading-one position 0 .. W - 1
    localparam integer FW  = W + MB;                   // a funnel: {word, MB zero bits}
    localparam integer FB  = $clog2(FW);               // a bit index into a funnel
    localparam integer XW  = 2 * MB + 2;               // x = sum m_k^2 < 2^(2MB+2)
    localparam integer PW2 = W + MB;                   // d_k Qm, signed: |d_k| <= 2^(W-1), Qm < 2^MB
    localparam integer PRE = W > MB ? W - MB : 0;      // -min(0, sh + s): sh + s >= MB - W
    localparam integer EW  = PW2 + PRE + 1;            // d_k Qm 2^(PRE+1): the shift back's word
    localparam integer UB  = $clog2(EW);               // its shift, 1 .. EW - 1
    localparam integer KW  = W + 3 < EW ? W + 3 : EW;  // the bits of the shifted product that matter
    localparam [MB-1:0] TOP = {MB{1'b1}};              // the largest unsigned mantissa
`include "pipe_latency.vh"
`include "fx_rsqrt_seed.vh"
    `STRAND_CHECK(fx_along_pipe_latency_formula, LATENCY == along_pipe_latency(MB),
                  ("fx_along_pipe: its stages (%0d) and pipe_latency.vh (%0d) disagree in %m", LATENCY, along_pipe_latency(MB)))
    localparam integer U0_I = MB + PRE + 1;
    localparam [UB-1:0] U0 = U0_I[UB-1:0];             // u = sh + s + PRE + 1 = U0 + J - (MB - 1) - b - Lr + L

    genvar k;

    // ---- 1: |d_k| OR-ed (the leading one of the OR is the largest lane's) ----
    reg [DIM*W-1:0] d_1;
    reg [W-1:0]     rest_1, any_1;
    wire [DIM*W-1:0] mag_0;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_mag
            assign mag_0[k*W +: W] = d[k*W + W-1] ? -d[k*W +: W] : d[k*W +: W];
        end
    endgenerate
    always @(posedge clk) begin
        d_1    <= d;
        rest_1 <= rest;
        any_1  <= mag_0[0 +: W] | mag_0[W +: W] | (DIM == 3 ? mag_0[(DIM-1)*W +: W] : {W{1'b0}});
    end

    // ---- 2: the leading ones (L of the lanes; Lr of rest, 0 for rest <= 1) and d = 0 ----
    function [LB-1:0] lead(input [W-1:0] v);
        integer i;
        begin
            lead = {LB{1'b0}};
            for (i = 0; i < W; i = i + 1)
                if (v[i]) lead = i[LB-1:0];
        end
    endfunction
    reg [DIM*W-1:0] d_2;
    reg [W-1:0]     rest_2;
    reg [LB-1:0]    l_2, lr_2;
    reg             zero_2;
    always @(posedge clk) begin
        d_2    <= d_1;
        rest_2 <= rest_1;
        l_2    <= lead(any_1);
        lr_2   <= lead(rest_1);
        zero_2 <= any_1 == {W{1'b0}};
    end

    // ---- 3: the funnels: {word, MB zeros} >> (L + 1) keeps MB + 1 bits; below them the half
    // bit (bit L of the funnel) and the sticky OR of bits 0 .. L - 1 ----
    wire [FB-1:0] l_at  = {{(FB-LB){1'b0}}, l_2};     // the half bit's place
    wire [FB-1:0] lr_at = {{(FB-LB){1'b0}}, lr_2};
    reg  [DIM*MW-1:0] q_3;
    reg  [DIM-1:0]    half_3, sticky_3;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_funnel
            wire [FW-1:0] ext = {d_2[k*W +: W], {MB{1'b0}}};
            wire [MW-1:0] kept;
            fx_shr #(.IN_W(FW - 1), .OUT_W(MW), .SB(LB), .SIGNED(1'b1)) u_funnel (.a(ext[FW-1:1]), .s(l_2), .y(kept));
            always @(posedge clk) begin
                q_3[k*MW +: MW] <= kept;
                half_3[k]       <= ext[l_at];
                sticky_3[k]     <= |(ext & ~({FW{1'b1}} << l_at));
            end
        end
    endgenerate
    wire [FW-1:0] rext  = {rest_2, {MB{1'b0}}};
    wire [MB-1:0] rkept;
    fx_shr #(.IN_W(FW - 1), .OUT_W(MB), .SB(LB), .SIGNED(1'b0)) u_rest_funnel (.a(rext[FW-1:1]), .s(lr_2), .y(rkept));
    reg  [MB-1:0] qr_3;
    reg           halfr_3, stickyr_3;
    reg  [LB-1:0] lr_3;
    always @(posedge clk) begin
        qr_3      <= rkept;
        halfr_3   <= rext[lr_at];
        stickyr_3 <= |(rext & ~({FW{1'b1}} << lr_at));
        lr_3      <= lr_2;
        l_3       <= l_2;
    end

    // ---- 4: rounded (ties to even) and clamped: m_k's positive side and R below 2^MB ----
    reg [DIM*MW-1:0] m_4;
    reg [MB-1:0]     r_4;
    reg [LB-1:0]     lr_4, l_3, l_4;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_round
            wire [MW-1:0] q  = q_3[k*MW +: MW];
            wire          up = half_3[k] && (sticky_3[k] || q[0]) && q != {1'b0, TOP};
            always @(posedge clk) m_4[k*MW +: MW] <= q + {{(MW-1){1'b0}}, up};
        end
    endgenerate
    always @(posedge clk) begin
        r_4    <= qr_3 + {{(MB-1){1'b0}}, halfr_3 && (stickyr_3 || qr_3[0]) && qr_3 != TOP};
        lr_4   <= lr_3;
        l_4    <= l_3;
    end

    // ---- 5, 6: the squares; 7: x ----
    /* verilator lint_off UNUSEDSIGNAL */
    // a square is below 2^(2MB): at MB < 7, fx_mul_pipe's narrowest product (16 bits) is wider
    wire [DIM*PW-1:0] sq_6;
    /* verilator lint_on UNUSEDSIGNAL */
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_sq
            wire [WM-1:0] mk = {{(WM-MW){m_4[k*MW + MW-1]}}, m_4[k*MW +: MW]};
            fx_mul_pipe #(.W(WM)) u_sq (.clk(clk), .a(mk), .b(mk), .prod(sq_6[k*PW +: PW]));
        end
    endgenerate
    reg [XW-1:0] x_7;
    always @(posedge clk)
        x_7 <= sq_6[0 +: XW] + sq_6[PW +: XW] + (DIM == 3 ? sq_6[(DIM-1)*PW +: XW] : {XW{1'b0}});

    // ---- 8: c = Lx - (2MB - 2) from x's top three bits; x' = x >> (MB - 1 + c) before
    // rounding, its half and sticky bits; the ROM index {p, the T - 1 bits below x''s lead} ----
    wire [1:0]    xc     = x_7[XW-1] ? 2'd3 : x_7[XW-2] ? 2'd2 : x_7[XW-3] ? 2'd1 : 2'd0;
    // the four shifts spelled out: MB - 1 + c, the half bit MB - 2 + c, the sticky bits below it
    wire [MB-1:0] xkept  = xc == 2'd3 ? x_7[MB+2 +: MB] : xc == 2'd2 ? x_7[MB+1 +: MB] : xc == 2'd1 ? x_7[MB +: MB] : x_7[MB-1 +: MB];
    wire          xhalf  = xc == 2'd3 ? x_7[MB+1] : xc == 2'd2 ? x_7[MB] : xc == 2'd1 ? x_7[MB-1] : x_7[MB-2];
    wire          xlow3  = x_7[MB-3:0] != {(MB-2){1'b0}};
    wire          xbelow = xc == 2'd3 ? xlow3 || x_7[MB-2] || x_7[MB-1] || x_7[MB]
                         : xc == 2'd2 ? xlow3 || x_7[MB-2] || x_7[MB-1]
                         : xc == 2'd1 ? xlow3 || x_7[MB-2] : xlow3;
    reg  [MB-1:0] xt_8;
    reg           xhalf_8, xsticky_8, p_8, jh_8;
    reg  [T-1:0]  idx_8;
    always @(posedge clk) begin
        xt_8      <= xkept;
        xhalf_8   <= xhalf;
        xsticky_8 <= xbelow;
        p_8       <= xc[0];
        jh_8      <= xc[1];
        idx_8     <= {xc[0], xkept[MB-2 -: T-1]};
    end

    // ---- 9: the ROM word {C0, Y0}; x' rounded ----
    reg [2*MB-1:0] rom [0:(1<<T)-1];
    integer ri;
    initial for (ri = 0; ri < (1 << T); ri = ri + 1) rom[ri] = rsqrt_seed_word(ri);
    reg [2*MB-1:0] rom_9;
    reg [MB-1:0]   xr_9;
    reg            p_9, jh_9;
    always @(posedge clk) begin
        rom_9 <= rom[idx_8];
        xr_9  <= xt_8 + {{(MB-1){1'b0}}, xhalf_8 && (xsticky_8 || xt_8[0]) && xt_8 != TOP};
        p_9   <= p_8;
        jh_9  <= jh_8;
    end

    // ---- 10, 11: x' C0; 12: Newton's difference N = 3 Y0 2^(MB-1) - x' C0 2^p
    // (|N| < 2^(2MB+1)); 13: Y1 = N / 2^MB rounded, clamped to 0 .. 2^MB - 1 ----
    wire [MB-1:0] y0_9 = rom_9[MB-1:0];
    wire [MB-1:0] c0_9 = rom_9[2*MB-1:MB];
    /* verilator lint_off UNUSEDSIGNAL */
    // x' C0 is below 2^(2MB): as the squares
    wire [PW-1:0] nprod_11;
    /* verilator lint_on UNUSEDSIGNAL */
    fx_mul_pipe #(.W(WM)) u_newton (.clk(clk), .a({{(WM-MB){1'b0}}, xr_9}), .b({{(WM-MB){1'b0}}, c0_9}), .prod(nprod_11));
    reg [MB-1:0] y0_10, y0_11;
    reg          p_10, p_11;
    reg [5:0]    jh_q;                  // jh in cycles 10 .. 15
    wire         jh_15 = jh_q[5];
    always @(posedge clk) begin
        y0_10 <= y0_9;
        y0_11 <= y0_10;
        p_10  <= p_9;
        p_11  <= p_10;
        jh_q  <= {jh_q[4:0], jh_9};
    end
    wire [XW-1:0] three_y0 = {{(XW-MB){1'b0}}, y0_11} + {{(XW-MB-1){1'b0}}, y0_11, 1'b0};
    wire [XW-1:0] xc0  = p_11 ? {nprod_11[XW-2:0], 1'b0} : nprod_11[XW-1:0];
    // N's bits below MB - 1 are those of -x' C0 2^p (3 Y0 2^(MB-1) has none there), so the
    // rounding's sticky bit comes from the product, beside the difference, not after it
    reg  [XW-1:0] n_12;
    reg           nsticky_12;
    always @(posedge clk) begin
        n_12       <= (three_y0 << (MB - 1)) - xc0;
        nsticky_12 <= xc0[MB-2:0] != {(MB-1){1'b0}};
    end
    // Y1 = floor(N / 2^MB) + up, clamped. N / 2^MB is in [-2^(MB+1), 2^(MB+1)): negative
    // (N's sign) clamps to 0 (-1 + up is at most 0), bit 2MB set is above TOP, and otherwise
    // the MB-bit increment's carry is TOP + 1. The three are found beside the increment, so
    // the stage is one MB-bit carry chain and a multiplexer.
    wire [MB-1:0] n_low  = n_12[2*MB-1:MB];
    wire          n_up   = n_12[MB-1] && (nsticky_12 || n_low[0]);
    wire [MB:0]   n_inc  = {1'b0, n_low} + {{MB{1'b0}}, n_up};
    reg  [MB-1:0] y1_13;
    always @(posedge clk)
        y1_13 <= n_12[XW-1] ? {MB{1'b0}} : (n_12[2*MB] || n_inc[MB]) ? TOP : n_inc[MB-1:0];

    // ---- R, Lr and L wait for Y1 (cycles 4 .. 13, Lr and L to 15); 14, 15: Q = R Y1 ----
    wire [MB+2*LB-1:0] rl_13;
    delay_line #(.WIDTH(MB + 2 * LB), .DELAY(9), .BLOCK_MIN(BLOCK_MIN)) u_r_ring (
        .clk(clk), .reset(reset), .in({l_4, lr_4, r_4}), .out(rl_13));
    reg  [LB-1:0] lr_14, lr_15, l_14, l_15;
    always @(posedge clk) begin
        {l_14, lr_14} <= rl_13[MB +: 2 * LB];
        {l_15, lr_15} <= {l_14, lr_14};
    end
    wire [PW-1:0] q_15;
    fx_mul_pipe #(.W(WM)) u_ratio (.clk(clk), .a({{(WM-MB){1'b0}}, rl_13[MB-1:0]}), .b({{(WM-MB){1'b0}}, y1_13}), .prod(q_15));

    // ---- 16: b = Q's bit 2MB - 1; Qm = Q >> (MB - 1 + b) before rounding; the shift back
    // u = sh + PRE + 1 = 2MB + J - (MB - 1) - b - Lr + PRE, from 1 to EW - 1; 17: Qm ----
    wire          qb     = q_15[2*MB-1];
    wire [MB-1:0] qkept  = qb ? q_15[MB +: MB] : q_15[MB-1 +: MB];
    wire          qhalf  = qb ? q_15[MB-1] : q_15[MB-2];
    wire          qbelow = q_15[MB-3:0] != {(MB-2){1'b0}} || (qb && q_15[MB-2]);
    reg  [MB-1:0] qt_16;
    reg           qhalf_16, qsticky_16;
    reg  [UB-1:0] u_16, u_17, u_18, u_19;
    always @(posedge clk) begin
        qt_16      <= qkept;
        qhalf_16   <= qhalf;
        qsticky_16 <= qbelow;
        u_16       <= U0 + {{(UB-1){1'b0}}, jh_15} - {{(UB-1){1'b0}}, qb} - {{(UB-LB){1'b0}}, lr_15}
                      + {{(UB-LB){1'b0}}, l_15};
    end
    reg [MB-1:0] qm_17;
    always @(posedge clk) begin
        qm_17 <= qt_16 + {{(MB-1){1'b0}}, qhalf_16 && (qsticky_16 || qt_16[0]) && qt_16 != TOP};
        u_17  <= u_16;
        u_18  <= u_17;
        u_19  <= u_18;
    end

    // ---- d and the zero flag wait (cycles 2 .. 17, the flag to 21); 18, 19: d_k Qm. The product
    // takes d itself, not its rounded mantissa m_k, so that t keeps d's direction exactly: only
    // its length, rest / |d|, is computed on mantissas (a rounded m_k would put every target on a
    // grid of rest 2^-MB across the link, coarser than a slow swing's step) ----
    wire [DIM*W:0] dz_17;
    delay_line #(.WIDTH(DIM * W + 1), .DELAY(15), .BLOCK_MIN(BLOCK_MIN)) u_d_ring (
        .clk(clk), .reset(reset), .in({zero_2, d_2}), .out(dz_17));
    reg [2:0] zero_q;                   // the flag in cycles 18 .. 20
    always @(posedge clk) zero_q <= {zero_q[1:0], dz_17[DIM*W]};

    // ---- 20: E = d_k Qm 2^(PRE+1) >> u, its half and sticky bits; 21: rounded, saturated.
    // |t| < 2^(2MB-sh) <= 2^(Lr+2) <= 2^(W+1) (|d_k| 2^-s < 2^MB), so the shift keeps KW = W + 3 bits
    // (the rest are sign copies) and saturation asks whether those above bit W - 1 are all the sign ----
    wire [EW-1:0] below_mask = ~({EW{1'b1}} << (u_19 - 1'b1));   // the bits under the half bit
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_back
            // the product in two stages: operands registered, then the product (W x (MB + 1) bits
            // signed: one multiplier block up to W = 17, two at W = 32)
            reg  signed [W-1:0]   da_18;
            reg         [MB-1:0]  qa_18;
            reg  signed [PW2-1:0] prod_19;
            always @(posedge clk) begin
                da_18   <= dz_17[k*W +: W];
                qa_18   <= qm_17;
                prod_19 <= da_18 * $signed({1'b0, qa_18});
            end
            wire [EW-1:0] e = {prod_19, {(PRE+1){1'b0}}};
            wire [KW-1:0] kept;
            fx_shr #(.IN_W(EW), .OUT_W(KW), .SB(UB), .SIGNED(1'b1)) u_back (.a(e), .s(u_19), .y(kept));
            reg  [KW-1:0] kept_20;
            reg           half_20, sticky_20;
            always @(posedge clk) begin
                kept_20   <= kept;
                half_20   <= e[u_19 - 1'b1];
                sticky_20 <= (e & below_mask) != {EW{1'b0}};
            end
            // Saturation is found beside the W-bit increment, not after a KW-bit one: the value
            // fits unless the bits above W - 1 are not all the sign, or it is 2^(W-1) - 1 and
            // rounds up; a negative value that rounds into range rounds to -2^(W-1), the
            // saturated value itself
            wire          up      = half_20 && (sticky_20 || kept_20[0]);
            wire          neg     = kept_20[KW-1];
            wire          over    = kept_20[KW-1:W-1] != {(KW-W+1){neg}}
                                    || (!neg && kept_20[W-2:0] == {(W-1){1'b1}} && up);
            wire [W-1:0]  rounded = kept_20[W-1:0] + {{(W-1){1'b0}}, up};
            always @(posedge clk)
                t[k*W +: W] <= over ? {neg, {(W-1){!neg}}} : rounded;
        end
    endgenerate
    always @(posedge clk) ok <= !zero_q[2];

endmodule

`resetall
