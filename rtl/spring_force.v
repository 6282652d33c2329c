`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * spring_force - the force of one damped spring on its first end (references 001, 004).
 *
 * Computes model/engine_body.h spring_edge(), whose order of operations it keeps:
 * with d = B - A and the Verlet velocities v_a = A - A-, v_b = B - B-
 * (every difference a saturating fx_sub, per axis),
 *     len = fx_sqrt(d.x^2 + d.y^2 [+ d.z^2])     radicand: exact 2W-bit sum of squares
 *     u.k = fx_div_signed(d.k, len)              |d.k| / len on the unsigned divider, sign restored
 *     vn  = (v_b.x - v_a.x) u.x + (v_b.y - v_a.y) u.y [+ (v_b.z - v_a.z) u.z]
 *     f   = ks (len - rest) + kd vn               the two exact products summed, rounded once
 *     F.k = f u.k                                 the force on A; B takes -F
 * Every other product is fx_mul (rounded ties-to-even, saturating), every sum fx_add.
 * f is rounded once (model/fixed.h fx_mac2): rounding kd vn on its own lost the damper,
 * a few LSBs a substep, to rounding (the decay rate 80 % short at 8 substeps, Q16.16).
 * ks and kd are scaled by the model (init()) so that F is a position change per
 * substep. valid = 0 when len = 0 (no direction): the caller writes nothing.
 *
 * Ports: pos_a, prev_a (A's previous position), pos_b, prev_b, f are DIM lanes of signed
 * Q(W-F).F (lane k at bits k W +: W, x first); rest_len unsigned Q(W-F).F.
 *
 * MANTISSA > 0 (the normalised datapath, model/fixed.h fx_spring_dir): the length and the
 * direction from MANTISSA-bit mantissas, u in Q2.(W-2), from spring_force_pipe taking this one
 * spring; done is high in cycle LATENCY = spring_force_pipe's latency + 1 (36 + 1:
 * model/timing.c hw_spring_latency), and the rest of the contract below is the same. The
 * bit-serial datapath below is MANTISSA = 0.
 *
 * Datapath: one W x W multiplier shared by the DIM squares and 2 DIM + 2 products (its
 * exact 2W-bit product for the squares), one fx_sqrt, one fx_div used for each u.k;
 * the axis counter `ax` picks the lane, a 2W-bit register keeps the exact ks (len - rest)
 * until kd vn's exact product is there; their sum (clamped to 2W bits: beyond them f
 * saturates either way) takes the rounder's place for that product. The multiplier is
 * pipelined as in toward.v:
 * operands registered in the cycle an operation is issued, the exact product in the
 * next (a square is used in the cycle after), the rounded product in the cycle after
 * that, used one cycle later (added where the formula adds). An operation that needs
 * an earlier one's result waits for it: ks (len - rest) is issued after the vn
 * products, kd vn when vn is complete, the F.k when f is.
 *
 * Timing, fixed whatever the data (the cycle model mirrors it). Counting the cycle
 * in which start is high as cycle 0: cycles 1 .. DIM issue the squares, the last is
 * used in cycle DIM + 2 and starts the root; the root is there in cycle
 * SQRT_BITS+DIM+4 and starts the divider for u.x; each u.k is there DIV_BITS+2
 * cycles after its divide started and starts the next; then DIM cycles issue the vn
 * products, one ks (len - rest), two wait for vn, one issues kd vn, three wait for
 * f, DIM issue the F.k, and the last is used three cycles later; done is high in cycle
 * LATENCY = SQRT_BITS + DIM DIV_BITS + 5 DIM + 15 (model/timing.c hw_spring_latency),
 * for one cycle. Each lane's force is new from the cycle after its product is used,
 * the last lane's and valid from cycle LATENCY: read them at done. They hold until
 * the next operation forms them. start is accepted only when idle or in the done cycle.
 */
module spring_force #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1, // quotient bits resolved
    parameter integer MANTISSA  = 0,     // 0: the bit-serial root and divides; 6 .. 20: the normalised datapath
    parameter integer DIM       = 2      // 2, or 3: a z lane
) (
    input  wire             clk,
    input  wire             reset,    // synchronous, active high
    input  wire             start,    // sample the ends and the constants
    input  wire [DIM*W-1:0] pos_a,    // A and its previous position
    input  wire [DIM*W-1:0] prev_a,
    input  wire [DIM*W-1:0] pos_b,    // B and its previous position
    input  wire [DIM*W-1:0] prev_b,
    input  wire [W-1:0]     rest_len, // rest length, unsigned Q(W-F).F
    input  wire [W-1:0]     ks,       // scaled stiffness, signed Q(W-F).F
    input  wire [W-1:0]     kd,       // scaled damping
    output wire             busy,
    output wire             done,     // one-cycle pulse: f and valid are new
    output reg  [DIM*W-1:0] f,        // the force on A
    output reg              valid     // 0: zero length, no force
);

    `STRAND_CHECK(W_must_be_8_to_32, W >= 8 && W <= 32, ("spring_force: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(DIM_must_be_2_or_3, DIM == 2 || DIM == 3, ("spring_force: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    genvar k;
    generate
        if (MANTISSA > 0) begin : g_norm
            // one spring at a time through the pipelined normalised datapath
            reg              busy_q, done_q;
            wire             o_valid, o_ok;
            wire [DIM*W-1:0] o_f;
            /* verilator lint_off PINCONNECTEMPTY */
            // the tag is not needed: one spring is in flight
            spring_force_pipe #(.W(W), .F(F), .MANTISSA(MANTISSA), .DIM(DIM)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(start && !busy_q), .in_a(pos_a), .in_ap(prev_a), .in_b(pos_b), .in_bp(prev_b),
                .in_rest(rest_len), .in_ks(ks), .in_kd(kd), .in_tag(1'b0),
                .out_valid(o_valid), .out_f(o_f), .out_ok(o_ok), .out_tag());
            /* verilator lint_on PINCONNECTEMPTY */
            always @(posedge clk) begin
                if (reset) begin
                    busy_q <= 1'b0;
                    done_q <= 1'b0;
                    f      <= {(DIM*W){1'b0}};
                    valid  <= 1'b0;
                end else begin
                    done_q <= o_valid;
                    if (o_valid) begin
                        busy_q <= 1'b0;
                        f      <= o_f;
                        valid  <= o_ok;
                    end
                    if (start && !busy_q) busy_q <= 1'b1;  // busy_q is low in the done cycle
                end
            end
            assign busy = busy_q;
            assign done = done_q;
        end else begin : g_serial
        localparam [3:0] S_IDLE  = 4'd0,  // waiting for start
                         S_SQ    = 4'd1,  // issue the square of d[ax]
                         S_ROOT  = 4'd2,  // the squares are used, the root runs; then divide d.x by it
                         S_DIV   = 4'd3,  // wait for u[ax], then divide the next lane
                         S_VN    = 4'd4,  // issue dv[ax] u[ax]
                         S_KS    = 4'd5,  // issue ks (len - rest)
                         S_KDW   = 4'd6,  // the last vn product is used
                         S_KD    = 4'd7,  // issue kd vn
                         S_FW    = 4'd8,  // wait for f = t + kd vn
                         S_F     = 4'd9,  // issue f u[ax]
                         S_DRAIN = 4'd10; // the last F is used
        // what a product in the pipeline is for
        localparam [2:0] K_SQ = 3'd0, K_VN = 3'd1, K_KS = 3'd2, K_KD = 3'd3, K_F = 3'd4;
        localparam integer DIM_LAST_I = DIM - 1;
        localparam [1:0]   DIM_LAST = DIM_LAST_I[1:0];

        reg [3:0]       state_q, state_d;
        reg [1:0]       ax_q, ax_d;
        reg             done_q, done_d;
        reg [DIM*W-1:0] d_q, dv_q, u_q;
        reg [W-1:0]     rest_q, ks_q, kd_q, len_q, vn_q, f_q;
        reg [2*W-1:0]   t_q;  // ks (len - rest), exact
        reg             dz_q;
        reg [2*W-1:0]   sq_q;   // the squares so far

        wire         ax_last = ax_q == DIM_LAST;
        wire [W-1:0] d_ax  = d_q[ax_q * W +: W];
        wire [W-1:0] dv_ax = dv_q[ax_q * W +: W];
        wire [W-1:0] u_ax  = u_q[ax_q * W +: W];

        // ---- the lanes: d = B - A and dv = (B - B-) - (A - A-) at start ----
        wire [DIM*W-1:0] d_new, dv_new;
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                wire [W-1:0] va, vb;
                /* verilator lint_off PINCONNECTEMPTY */
                // saturation flags are not needed: the saturated value is the result
                fx_add #(.W(W), .SUB(1)) u_d  (.sub(1'b1), .a(pos_b[k*W +: W]), .b(pos_a[k*W +: W]), .y(d_new[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(1)) u_va (.sub(1'b1), .a(pos_a[k*W +: W]), .b(prev_a[k*W +: W]), .y(va), .sat());
                fx_add #(.W(W), .SUB(1)) u_vb (.sub(1'b1), .a(pos_b[k*W +: W]), .b(prev_b[k*W +: W]), .y(vb), .sat());
                fx_add #(.W(W), .SUB(1)) u_dv (.sub(1'b1), .a(vb), .b(va), .y(dv_new[k*W +: W]), .sat());
                /* verilator lint_on PINCONNECTEMPTY */
            end

        // ---- the multiplier pipeline: issue (operands registered), multiply (product
        // registered), use; each stage carries its product's kind and lane ----
        wire [W-1:0]   stretch;  // len - rest
        reg  [W-1:0]   mul_a, mul_b;
        reg            issue;
        reg  [2:0]     kind;
        always @* begin
            issue = 1'b1;
            kind  = K_SQ;
            mul_a = d_ax;
            mul_b = d_ax;
            case (state_q)
                S_SQ:    ;
                S_VN:    begin kind = K_VN; mul_a = dv_ax; mul_b = u_ax;    end
                S_KS:    begin kind = K_KS; mul_a = ks_q;  mul_b = stretch; end
                S_KD:    begin kind = K_KD; mul_a = kd_q;  mul_b = vn_q;    end
                S_F:     begin kind = K_F;  mul_a = f_q;   mul_b = u_ax;    end
                default: issue = 1'b0;
            endcase
        end
        reg  [W-1:0]   op_a, op_b;
        reg            s1_v, s2_v;
        reg  [2:0]     s1_kind, s2_kind;
        reg  [1:0]     s1_ax, s2_ax;
        reg  [2*W-1:0] prod_q;    // stage 2: the exact product (a square is used here)
        reg  [W-1:0]   round_q;   // stage 3: the rounded product (every other product is used here)
        reg            s3_v;
        reg  [2:0]     s3_kind;
        reg  [1:0]     s3_ax;
        wire [W-1:0]   mul_round;
        wire [2*W-1:0] mul_exact;
        wire           s2_last = s2_ax == DIM_LAST;
        wire           s3_last = s3_ax == DIM_LAST;
        wire           use_sq  = s2_v && s2_kind == K_SQ;
        wire           use_vn  = s3_v && s3_kind == K_VN;
        wire           keep_ks = s2_v && s2_kind == K_KS;  // exact: kept for f's sum
        wire           sum_kd  = s2_v && s2_kind == K_KD;  // exact: summed with it, then rounded
        wire           use_kd  = s3_v && s3_kind == K_KD;
        wire           use_f   = s3_v && s3_kind == K_F;
        always @(posedge clk) begin
            if (reset) begin
                s1_v <= 1'b0;
                s2_v <= 1'b0;
            end else begin
                s1_v <= issue;
                s2_v <= s1_v;
                s3_v <= s2_v && s2_kind != K_SQ;
            end
            // datapath: no reset (the valid bits say what is there)
            op_a    <= mul_a;
            op_b    <= mul_b;
            s1_kind <= kind;
            s1_ax   <= ax_q;
            prod_q  <= mul_exact;
            s2_kind <= s1_kind;
            s2_ax   <= s1_ax;
            round_q <= mul_round;
            s3_kind <= s2_kind;
            s3_ax   <= s2_ax;
        end
        wire [W-1:0] acc_sum;  // vn + dv[ax] u[ax]
        // f's exact sum: ks (len - rest) + kd vn, clamped to 2W bits, rounded in place of kd vn
        wire [2*W:0]   mac_wide = {t_q[2*W-1], t_q} + {prod_q[2*W-1], prod_q};
        wire           mac_over = mac_wide[2*W] != mac_wide[2*W-1];
        wire [2*W-1:0] mac      = mac_over ? {mac_wide[2*W], {(2*W-1){!mac_wide[2*W]}}} : mac_wide[2*W-1:0];
        wire [2*W-1:0] round_in = sum_kd ? mac : prod_q;
        /* verilator lint_off PINCONNECTEMPTY */
        // the saturation flags are not needed: the saturated value is the result
        fx_mul #(.W(W), .F(F), .ROUND(1'b0)) u_mul (.a(op_a), .b(op_b), .y(), .prod(mul_exact), .sat());
        fx_round #(.W(W), .F(F)) u_round (.prod(round_in), .y(mul_round), .sat());
        fx_add #(.W(W), .SUB(1)) u_stretch (.sub(1'b1), .a(len_q), .b(rest_q), .y(stretch), .sat());
        fx_add #(.W(W), .SUB(0)) u_acc (.sub(1'b0), .a(vn_q), .b(round_q), .y(acc_sum), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- square root and divider ----
        wire           sqrt_done, div_done, div_zero;
        wire [W-1:0]   root, quot;
        wire [2*W-1:0] radicand = sq_q + prod_q; // each square <= 2^(2W-2), so the sum fits 2W bits
        // a divide starts when the root is there (lane x) and when a lane's quotient is (the next lane)
        wire           div_start = (state_q == S_ROOT && sqrt_done) || (state_q == S_DIV && div_done && !ax_last);
        wire [1:0]     num_ax    = state_q == S_ROOT ? 2'd0 : ax_q + 1'b1;
        wire [W-1:0]   d_num     = d_q[num_ax * W +: W];
        // |d.k|: two's complement magnitude, unsigned (|min| = 2^(W-1) fits W bits)
        wire [W-1:0]   num_k = d_num[W-1] ? -d_num : d_num;
        wire [W-1:0]   den_k = state_q == S_ROOT ? root : len_q;
        wire [W-1:0]   u_k   = d_ax[W-1] ? -quot : quot;  // quot <= max: no overflow
        /* verilator lint_off PINCONNECTEMPTY */
        // busy and saturation flags are not needed: the FSM counts on the fixed latency
        fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
            .clk(clk), .reset(reset), .start(use_sq && s2_last), .radicand(radicand),
            .busy(), .done(sqrt_done), .result(root), .sat());
        fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_div (
            .clk(clk), .reset(reset), .start(div_start), .num(num_k), .den(den_k),
            .busy(), .done(div_done), .result(quot), .div_by_zero(div_zero), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- control ----
        always @* begin
            state_d = state_q;
            ax_d    = ax_q;
            done_d  = 1'b0;
            case (state_q)
                S_IDLE:  if (start) begin state_d = S_SQ; ax_d = 2'd0; end
                S_SQ:    if (ax_last) state_d = S_ROOT; else ax_d = ax_q + 1'b1;
                S_ROOT:  if (sqrt_done) begin state_d = S_DIV; ax_d = 2'd0; end
                S_DIV:   if (div_done) begin
                             if (ax_last) begin state_d = S_VN; ax_d = 2'd0; end else ax_d = ax_q + 1'b1;
                         end
                S_VN:    if (ax_last) state_d = S_KS; else ax_d = ax_q + 1'b1;
                S_KS:    state_d = S_KDW;
                S_KDW:   if (use_vn && s3_last) state_d = S_KD;
                S_KD:    state_d = S_FW;
                S_FW:    if (use_kd) begin state_d = S_F; ax_d = 2'd0; end
                S_F:     if (ax_last) state_d = S_DRAIN; else ax_d = ax_q + 1'b1;
                S_DRAIN: if (use_f && s3_last) begin state_d = S_IDLE; done_d = 1'b1; end
                default: state_d = S_IDLE;
            endcase
        end

        always @(posedge clk) begin
            if (reset) begin
                state_q <= S_IDLE;
                ax_q    <= 2'd0;
                done_q  <= 1'b0;
                f       <= {(DIM*W){1'b0}};
                valid   <= 1'b0;
            end else begin
                state_q <= state_d;
                ax_q    <= ax_d;
                done_q  <= done_d;
                if (use_f) f[s3_ax * W +: W] <= round_q;
                if (use_f && s3_last) valid <= !dz_q;
            end
        end

        // Datapath registers: written in their own state only, so no reset.
        always @(posedge clk) begin
            if (state_q == S_IDLE && start) begin
                d_q    <= d_new;
                dv_q   <= dv_new;
                rest_q <= rest_len;
                ks_q   <= ks;
                kd_q   <= kd;
            end
            if (use_sq) sq_q <= s2_ax == 2'd0 ? prod_q : radicand;
            if (state_q == S_ROOT && sqrt_done) len_q <= root;
            if (state_q == S_DIV && div_done) begin
                u_q[ax_q * W +: W] <= u_k;
                if (ax_q == 2'd0) dz_q <= div_zero;  // len = 0: no direction
            end
            if (use_vn) vn_q <= s3_ax == 2'd0 ? round_q : acc_sum;
            if (keep_ks) t_q <= prod_q;
            if (use_kd) f_q <= round_q;
        end

        assign busy = state_q != S_IDLE;
        assign done = done_q;
        end
    endgenerate

endmodule

`resetall
