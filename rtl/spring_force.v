`default_nettype none
`timescale 1ns / 1ps

/*
 * spring_force - the force of one damped spring on its first end (references 001, 004).
 *
 * Computes model/engine_body.h spring_edge(), whose order of operations it keeps:
 * with d = B - A and the Verlet velocities v_a = A - A-, v_b = B - B-
 * (every difference a saturating fx_sub),
 *     len = fx_sqrt(d.x^2 + d.y^2 [+ d.z^2])     radicand: exact 2W-bit sum of squares
 *     u.k = fx_div_signed(d.k, len)              |d.k| / len on the unsigned divider, sign restored
 *     vn  = (v_b.x - v_a.x) u.x + (v_b.y - v_a.y) u.y [+ (v_b.z - v_a.z) u.z]
 *     f   = ks (len - rest) + kd vn
 *     F.k = f u.k                                 the force on A; B takes -F
 * Every product is fx_mul (rounded ties-to-even, saturating), every sum fx_add.
 * ks and kd are scaled by the model (init()) so that F is a position change per
 * substep. valid = 0 when len = 0 (no direction): the caller writes nothing.
 *
 * DIM = 3 adds a z lane (one more square, divide and two more products).
 *
 * Datapath: one W x W multiplier shared by the DIM squares and 2 DIM + 2 products (its
 * exact 2W-bit product for the squares), one fx_sqrt, one fx_div used for u.x, u.y (, u.z).
 *
 * Timing, fixed whatever the data (the cycle model mirrors it). Counting the cycle
 * in which start is high as cycle 0: cycles 1 .. DIM square the lanes, the last
 * starts the root; the root is there in cycle SQRT_BITS+DIM+2 and starts the divider
 * for u.x; each u.k is there DIV_BITS+2 cycles after its divide started and starts
 * the next; then 2 DIM + 2 cycles form the products; done is high in cycle
 * LATENCY = SQRT_BITS + DIM DIV_BITS + 5 DIM + 5, for one cycle (2D: SQRT_BITS +
 * 2 DIV_BITS + 15). Each lane's force is new from the cycle after its product, the
 * last lane's and valid from cycle LATENCY: read them at done. They hold until the
 * next operation forms them. start is accepted only when idle or in the done cycle.
 */
module spring_force #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1, // quotient bits resolved
    parameter integer DIM       = 2      // 2, or 3: a z lane
) (
    input  wire         clk,
    input  wire         reset,    // synchronous, active high
    input  wire         start,    // sample the ends and the constants
    input  wire [W-1:0] a_x,      // A and its previous position
    input  wire [W-1:0] a_y,
    input  wire [W-1:0] a_px,
    input  wire [W-1:0] a_py,
    input  wire [W-1:0] a_z,      // DIM = 3 only
    input  wire [W-1:0] a_pz,
    input  wire [W-1:0] b_x,      // B and its previous position
    input  wire [W-1:0] b_y,
    input  wire [W-1:0] b_px,
    input  wire [W-1:0] b_py,
    input  wire [W-1:0] b_z,      // DIM = 3 only
    input  wire [W-1:0] b_pz,
    input  wire [W-1:0] rest_len, // rest length, unsigned Q(W-F).F
    input  wire [W-1:0] ks,       // scaled stiffness, signed Q(W-F).F
    input  wire [W-1:0] kd,       // scaled damping
    output wire         busy,
    output wire         done,     // one-cycle pulse: f_x, f_y, valid are new
    output reg  [W-1:0] f_x,      // the force on A
    output reg  [W-1:0] f_y,
    output reg  [W-1:0] f_z,      // DIM = 3; else 0
    output reg          valid     // 0: zero length, no force
);

    // Bad parameters stop elaboration: $error for Yosys (0.23 has no $fatal),
    // $fatal for the simulators (Icarus carries on after $error).
    initial begin
        if (W < 8 || W > 32) begin
`ifdef SYNTHESIS
            $error("spring_force: W must be 8..32 (W=%0d) in %m", W);
`else
            $fatal(1, "spring_force: W must be 8..32 (W=%0d) in %m", W);
`endif
        end
    end

    localparam [3:0] S_IDLE = 4'd0,  // waiting for start
                     S_SQX  = 4'd1,  // square d.x
                     S_SQY  = 4'd2,  // square d.y, start the root
                     S_SQRT = 4'd3,  // wait for the root, then divide d.x by it
                     S_DIVX = 4'd4,  // wait for u.x, then divide d.y
                     S_DIVY = 4'd5,  // wait for u.y
                     S_VNX  = 4'd6,  // vn = dv.x u.x
                     S_VNY  = 4'd7,  // vn = vn + dv.y u.y
                     S_KS   = 4'd8,  // t = ks (len - rest)
                     S_KD   = 4'd9,  // f = t + kd vn
                     S_FX   = 4'd10, // F.x = f u.x
                     S_FY   = 4'd11, // F.y = f u.y
                     S_SQZ  = 4'd12, // DIM = 3: square d.z, start the root
                     S_DIVZ = 4'd13, // DIM = 3: wait for u.z
                     S_VNZ  = 4'd14, // DIM = 3: vn = vn + dv.z u.z
                     S_FZ   = 4'd15; // DIM = 3: F.z = f u.z
    localparam [3:0] S_ROOT = DIM == 3 ? S_SQZ : S_SQY;  // starts the root
    localparam [3:0] S_LAST = DIM == 3 ? S_FZ : S_FY;    // the last product

    reg [3:0]     state_q, state_d;
    reg           done_q, done_d;
    reg [W-1:0]   dx_q, dy_q, dvx_q, dvy_q, rest_q, ks_q, kd_q;
    reg [W-1:0]   len_q, ux_q, uy_q, vn_q, t_q, f_q;
    reg           dz_q;
    reg [2*W-1:0] sq_q;   // d.x^2 (+ d.y^2)
    reg [W-1:0]   dz3_q, dvz_q, uz_q;  // DIM = 3 (constant 0 in 2D, removed by synthesis)

    // ---- the differences of the inputs ----
    wire [W-1:0] dx_new, dy_new, vax, vay, vbx, vby, dvx_new, dvy_new, dz_new, vaz, vbz, dvz_new;
    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags are not needed: the saturated value is the result
    fx_add #(.W(W)) u_dx  (.sub(1'b1), .a(b_x), .b(a_x),  .y(dx_new),  .sat());
    fx_add #(.W(W)) u_dy  (.sub(1'b1), .a(b_y), .b(a_y),  .y(dy_new),  .sat());
    fx_add #(.W(W)) u_vax (.sub(1'b1), .a(a_x), .b(a_px), .y(vax),     .sat());
    fx_add #(.W(W)) u_vay (.sub(1'b1), .a(a_y), .b(a_py), .y(vay),     .sat());
    fx_add #(.W(W)) u_vbx (.sub(1'b1), .a(b_x), .b(b_px), .y(vbx),     .sat());
    fx_add #(.W(W)) u_vby (.sub(1'b1), .a(b_y), .b(b_py), .y(vby),     .sat());
    fx_add #(.W(W)) u_dvx (.sub(1'b1), .a(vbx), .b(vax),  .y(dvx_new), .sat());
    fx_add #(.W(W)) u_dvy (.sub(1'b1), .a(vby), .b(vay),  .y(dvy_new), .sat());
    fx_add #(.W(W)) u_dz  (.sub(1'b1), .a(b_z), .b(a_z),  .y(dz_new),  .sat());
    fx_add #(.W(W)) u_vaz (.sub(1'b1), .a(a_z), .b(a_pz), .y(vaz),     .sat());
    fx_add #(.W(W)) u_vbz (.sub(1'b1), .a(b_z), .b(b_pz), .y(vbz),     .sat());
    fx_add #(.W(W)) u_dvz (.sub(1'b1), .a(vbz), .b(vaz),  .y(dvz_new), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- the shared multiplier ----
    reg  [W-1:0]   mul_a, mul_b;
    wire [W-1:0]   mul_round;
    wire [2*W-1:0] mul_exact;
    wire [W-1:0]   stretch;  // len - rest
    /* verilator lint_off PINCONNECTEMPTY */
    fx_mul #(.W(W), .F(F)) u_mul (.a(mul_a), .b(mul_b), .y(mul_round), .prod(mul_exact), .sat());
    fx_add #(.W(W)) u_stretch (.sub(1'b1), .a(len_q), .b(rest_q), .y(stretch), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    always @* begin
        mul_a = dx_q;
        mul_b = dx_q;
        case (state_q)
            S_SQY:   begin mul_a = dy_q;  mul_b = dy_q;    end
            S_SQZ:   begin mul_a = dz3_q; mul_b = dz3_q;   end
            S_VNZ:   begin mul_a = dvz_q; mul_b = uz_q;    end
            S_FZ:    begin mul_a = f_q;   mul_b = uz_q;    end
            S_VNX:   begin mul_a = dvx_q; mul_b = ux_q;    end
            S_VNY:   begin mul_a = dvy_q; mul_b = uy_q;    end
            S_KS:    begin mul_a = ks_q;  mul_b = stretch; end
            S_KD:    begin mul_a = kd_q;  mul_b = vn_q;    end
            S_FX:    begin mul_a = f_q;   mul_b = ux_q;    end
            S_FY:    begin mul_a = f_q;   mul_b = uy_q;    end
            default: ;
        endcase
    end

    // the one adder of the products: vn + dv.y u.y, then t + kd vn
    wire [W-1:0] acc_sum;
    /* verilator lint_off PINCONNECTEMPTY */
    fx_add #(.W(W)) u_acc (.sub(1'b0), .a(state_q == S_KD ? t_q : vn_q), .b(mul_round), .y(acc_sum), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- square root and divider ----
    wire           sqrt_done, div_done, div_zero;
    wire [W-1:0]   root, quot;
    wire [2*W-1:0] radicand = sq_q + mul_exact; // each square <= 2^(2W-2), so the sum fits 2W bits
    wire           div_start = (state_q == S_SQRT && sqrt_done) || (state_q == S_DIVX && div_done) ||
                               (DIM == 3 && state_q == S_DIVY && div_done);
    // the lane a divide is started for (num) and the lane whose quotient arrives (u_k)
    wire [W-1:0]   d_num = state_q == S_SQRT ? dx_q : state_q == S_DIVX ? dy_q : dz3_q;
    wire [W-1:0]   d_quo = state_q == S_DIVX ? dx_q : state_q == S_DIVY ? dy_q : dz3_q;
    // |d.k|: two's complement magnitude, unsigned (|min| = 2^(W-1) fits W bits)
    wire [W-1:0]   num_k = d_num[W-1] ? -d_num : d_num;
    wire [W-1:0]   den_k = state_q == S_SQRT ? root : len_q;
    wire [W-1:0]   u_k   = d_quo[W-1] ? -quot : quot;  // quot <= max: no overflow
    /* verilator lint_off PINCONNECTEMPTY */
    // busy and saturation flags are not needed: the FSM counts on the fixed latency
    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
        .clk(clk), .reset(reset), .start(state_q == S_ROOT), .radicand(radicand),
        .busy(), .done(sqrt_done), .result(root), .sat());
    fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_div (
        .clk(clk), .reset(reset), .start(div_start), .num(num_k), .den(den_k),
        .busy(), .done(div_done), .result(quot), .div_by_zero(div_zero), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- control ----
    always @* begin
        state_d = state_q;
        done_d  = 1'b0;
        case (state_q)
            S_IDLE:  if (start) state_d = S_SQX;
            S_SQX:   state_d = S_SQY;
            S_SQY:   state_d = DIM == 3 ? S_SQZ : S_SQRT;
            S_SQZ:   state_d = S_SQRT;
            S_SQRT:  if (sqrt_done) state_d = S_DIVX;
            S_DIVX:  if (div_done) state_d = S_DIVY;
            S_DIVY:  if (div_done) state_d = DIM == 3 ? S_DIVZ : S_VNX;
            S_DIVZ:  if (div_done) state_d = S_VNX;
            S_VNX:   state_d = S_VNY;
            S_VNY:   state_d = DIM == 3 ? S_VNZ : S_KS;
            S_VNZ:   state_d = S_KS;
            S_KS:    state_d = S_KD;
            S_KD:    state_d = S_FX;
            S_FX:    state_d = S_FY;
            S_FY:    if (DIM == 3) state_d = S_FZ; else begin state_d = S_IDLE; done_d = 1'b1; end
            S_FZ:    begin state_d = S_IDLE; done_d = 1'b1; end
            default: state_d = S_IDLE;
        endcase
    end

    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            done_q  <= 1'b0;
            f_x     <= {W{1'b0}};
            f_y     <= {W{1'b0}};
            f_z     <= {W{1'b0}};
            valid   <= 1'b0;
        end else begin
            state_q <= state_d;
            done_q  <= done_d;
            if (state_q == S_FX) f_x <= mul_round;
            if (state_q == S_FY) f_y <= mul_round;
            if (state_q == S_FZ) f_z <= mul_round;
            if (state_q == S_LAST) valid <= !dz_q;
        end
    end

    // Datapath registers: written in their own state only, so no reset.
    always @(posedge clk) begin
        if (state_q == S_IDLE && start) begin
            dx_q   <= dx_new;
            dy_q   <= dy_new;
            dvx_q  <= dvx_new;
            dvy_q  <= dvy_new;
            dz3_q  <= DIM == 3 ? dz_new : {W{1'b0}};
            dvz_q  <= DIM == 3 ? dvz_new : {W{1'b0}};
            rest_q <= rest_len;
            ks_q   <= ks;
            kd_q   <= kd;
        end
        if (state_q == S_SQX) sq_q <= mul_exact;
        if (state_q == S_SQY && DIM == 3) sq_q <= radicand;  // d.x^2 + d.y^2, d.z^2 follows
        if (state_q == S_SQRT && sqrt_done) len_q <= root;
        if (state_q == S_DIVX && div_done) begin
            ux_q <= u_k;
            dz_q <= div_zero;  // len = 0: no direction
        end
        if (state_q == S_DIVY && div_done) uy_q <= u_k;
        if (state_q == S_DIVZ && div_done) uz_q <= u_k;
        if (state_q == S_VNX) vn_q <= mul_round;
        if (state_q == S_VNY || state_q == S_VNZ) vn_q <= acc_sum;
        if (state_q == S_KS)  t_q  <= mul_round;
        if (state_q == S_KD)  f_q  <= acc_sum;
    end

    assign busy = state_q != S_IDLE;
    assign done = done_q;

endmodule

`resetall
