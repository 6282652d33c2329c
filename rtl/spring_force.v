`default_nettype none
`timescale 1ns / 1ps

/*
 * spring_force - the force of one damped spring on its first end (references 001, 004).
 *
 * Computes model/engine_body.h spring_edge(), whose order of operations it keeps:
 * with d = B - A and the Verlet velocities v_a = A - A-, v_b = B - B-
 * (every difference a saturating fx_sub),
 *     len = fx_sqrt(d.x^2 + d.y^2)               radicand: exact 2W-bit sum of squares
 *     u.k = fx_div_signed(d.k, len)              |d.k| / len on the unsigned divider, sign restored
 *     vn  = (v_b.x - v_a.x) u.x + (v_b.y - v_a.y) u.y
 *     f   = ks (len - rest) + kd vn
 *     F.k = f u.k                                 the force on A; B takes -F
 * Every product is fx_mul (rounded ties-to-even, saturating), every sum fx_add.
 * ks and kd are scaled by the model (init()) so that F is a position change per
 * substep. valid = 0 when len = 0 (no direction): the caller writes nothing.
 *
 * Datapath: one W x W multiplier shared by the two squares and six products (its
 * exact 2W-bit product for the squares), one fx_sqrt, one fx_div used for u.x then u.y.
 *
 * Timing, fixed whatever the data (the cycle model mirrors it). Counting the cycle
 * in which start is high as cycle 0: cycles 1 and 2 square d.x and d.y, cycle 2
 * starts the root; the root is there in cycle SQRT_BITS+4 and starts the divider for
 * u.x; u.x is there DIV_BITS+2 cycles later and starts it for u.y; DIV_BITS+2 cycles
 * later u.y is there; the next six cycles form the six products; done is high in
 * cycle LATENCY = SQRT_BITS + 2 DIV_BITS + 15, for one cycle. f_x is new from cycle
 * LATENCY - 1, f_y and valid from cycle LATENCY: read them at done. They hold until
 * the next operation forms them. start is accepted only when idle or in the done cycle.
 */
module spring_force #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1  // quotient bits resolved
) (
    input  wire         clk,
    input  wire         reset,    // synchronous, active high
    input  wire         start,    // sample the ends and the constants
    input  wire [W-1:0] a_x,      // A and its previous position
    input  wire [W-1:0] a_y,
    input  wire [W-1:0] a_px,
    input  wire [W-1:0] a_py,
    input  wire [W-1:0] b_x,      // B and its previous position
    input  wire [W-1:0] b_y,
    input  wire [W-1:0] b_px,
    input  wire [W-1:0] b_py,
    input  wire [W-1:0] rest_len, // rest length, unsigned Q(W-F).F
    input  wire [W-1:0] ks,       // scaled stiffness, signed Q(W-F).F
    input  wire [W-1:0] kd,       // scaled damping
    output wire         busy,
    output wire         done,     // one-cycle pulse: f_x, f_y, valid are new
    output reg  [W-1:0] f_x,      // the force on A
    output reg  [W-1:0] f_y,
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
                     S_FY   = 4'd11; // F.y = f u.y

    reg [3:0]     state_q, state_d;
    reg           done_q, done_d;
    reg [W-1:0]   dx_q, dy_q, dvx_q, dvy_q, rest_q, ks_q, kd_q;
    reg [W-1:0]   len_q, ux_q, uy_q, vn_q, t_q, f_q;
    reg           dz_q;
    reg [2*W-1:0] sq_q;   // d.x^2

    // ---- the differences of the inputs ----
    wire [W-1:0] dx_new, dy_new, vax, vay, vbx, vby, dvx_new, dvy_new;
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
    fx_add #(.W(W)) u_acc (.sub(1'b0), .a(state_q == S_VNY ? vn_q : t_q), .b(mul_round), .y(acc_sum), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- square root and divider ----
    wire           sqrt_done, div_done, div_zero;
    wire [W-1:0]   root, quot;
    wire [2*W-1:0] radicand = sq_q + mul_exact; // each square <= 2^(2W-2), so the sum fits 2W bits
    wire           div_start = (state_q == S_SQRT && sqrt_done) || (state_q == S_DIVX && div_done);
    // |d.k|: two's complement magnitude, unsigned (|min| = 2^(W-1) fits W bits)
    wire [W-1:0]   num_k = state_q == S_SQRT ? (dx_q[W-1] ? -dx_q : dx_q) : (dy_q[W-1] ? -dy_q : dy_q);
    wire [W-1:0]   den_k = state_q == S_SQRT ? root : len_q;
    wire [W-1:0]   u_k   = (state_q == S_DIVX ? dx_q[W-1] : dy_q[W-1]) ? -quot : quot;  // quot <= max: no overflow
    /* verilator lint_off PINCONNECTEMPTY */
    // busy and saturation flags are not needed: the FSM counts on the fixed latency
    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
        .clk(clk), .reset(reset), .start(state_q == S_SQY), .radicand(radicand),
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
            S_SQY:   state_d = S_SQRT;
            S_SQRT:  if (sqrt_done) state_d = S_DIVX;
            S_DIVX:  if (div_done) state_d = S_DIVY;
            S_DIVY:  if (div_done) state_d = S_VNX;
            S_VNX:   state_d = S_VNY;
            S_VNY:   state_d = S_KS;
            S_KS:    state_d = S_KD;
            S_KD:    state_d = S_FX;
            S_FX:    state_d = S_FY;
            S_FY:    begin state_d = S_IDLE; done_d = 1'b1; end
            default: state_d = S_IDLE;
        endcase
    end

    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            done_q  <= 1'b0;
            f_x     <= {W{1'b0}};
            f_y     <= {W{1'b0}};
            valid   <= 1'b0;
        end else begin
            state_q <= state_d;
            done_q  <= done_d;
            if (state_q == S_FX) f_x <= mul_round;
            if (state_q == S_FY) begin
                f_y   <= mul_round;
                valid <= !dz_q;
            end
        end
    end

    // Datapath registers: written in their own state only, so no reset.
    always @(posedge clk) begin
        if (state_q == S_IDLE && start) begin
            dx_q   <= dx_new;
            dy_q   <= dy_new;
            dvx_q  <= dvx_new;
            dvy_q  <= dvy_new;
            rest_q <= rest_len;
            ks_q   <= ks;
            kd_q   <= kd;
        end
        if (state_q == S_SQX) sq_q <= mul_exact;
        if (state_q == S_SQRT && sqrt_done) len_q <= root;
        if (state_q == S_DIVX && div_done) begin
            ux_q <= u_k;
            dz_q <= div_zero;  // len = 0: no direction
        end
        if (state_q == S_DIVY && div_done) uy_q <= u_k;
        if (state_q == S_VNX) vn_q <= mul_round;
        if (state_q == S_VNY) vn_q <= acc_sum;
        if (state_q == S_KS)  t_q  <= mul_round;
        if (state_q == S_KD)  f_q  <= acc_sum;
    end

    assign busy = state_q != S_IDLE;
    assign done = done_q;

endmodule

`resetall
