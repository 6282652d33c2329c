`default_nettype none
`timescale 1ns / 1ps

/*
 * toward - the point at distance `rest_len` from P in the direction of C, or the
 * excess of C's distance from P over `rest_len`.
 *
 * Computes model/engine_body.h toward() (excess = 0) or the core of pair_edge()
 * (excess = 1): with d = C - P (saturating subtract),
 *     len = fx_sqrt(d.x^2 + d.y^2 [+ d.z^2])   radicand: exact 2W-bit sum of squares
 *     r   = fx_div(rest_len, len)       rest_len / len, unsigned, Q.F
 *     T   = P + d * r                   excess = 0: fx_mul (rounded ties-to-even), fx_add
 *     T   = d - d * r                   excess = 1: the excess e, fx_mul, fx_sub
 * valid = 0 when len = 0 (the divider's divide-by-zero flag): the caller skips T.
 *
 * Ports: p_*, c_* signed Q(W-F).F; rest_len unsigned Q(W-F).F (> 0); t_* signed Q(W-F).F.
 *
 * Datapath: one W x W multiplier, shared by the two squares and the two products
 * (its exact 2W-bit product for the squares, its rounded result for the products),
 * one fx_sqrt and one fx_div.
 *
 * DIM = 3 adds a z lane: one more square (d.z^2, after d.y^2) and one more product.
 *
 * Timing, fixed whatever the data (the cycle model mirrors it). Counting the
 * cycle in which start is high as cycle 0: cycles 1 .. DIM square d.x, d.y (and
 * d.z), the last of them starts the square root; the root is there in cycle
 * SQRT_BITS+DIM+2 and starts the divider in that cycle; the quotient is there
 * DIV_BITS+2 cycles later; the next DIM cycles form T.x, T.y (and T.z); done is
 * high in cycle LATENCY = SQRT_BITS + DIV_BITS + 2 DIM + 5, for one cycle. Each
 * lane's result is new from the cycle after its product (t_x from LATENCY - DIM + 1),
 * the last lane's and valid from cycle LATENCY: read them at done. They hold until
 * the next operation forms them. start is accepted only when idle or in the done cycle.
 */
module toward #(
    parameter integer W         = 32,    // word width, bits
    parameter integer F         = 16,    // fraction bits
    parameter integer SQRT_BITS = W - 1, // root bits resolved
    parameter integer DIV_BITS  = W - 1, // quotient bits resolved
    parameter integer DIM       = 2      // 2, or 3: a z lane
) (
    input  wire         clk,
    input  wire         reset,  // synchronous, active high
    input  wire         start,  // sample P, C, rest_len and excess
    input  wire         excess, // 0: T = P + d*r (centred rule), 1: T = d - d*r (pairwise rule)
    input  wire [W-1:0] p_x,
    input  wire [W-1:0] p_y,
    input  wire [W-1:0] c_x,
    input  wire [W-1:0] c_y,
    input  wire [W-1:0] p_z,    // DIM = 3 only
    input  wire [W-1:0] c_z,
    input  wire [W-1:0] rest_len,
    output wire         busy,
    output wire         done,   // one-cycle pulse: t_x, t_y, valid are new
    output reg  [W-1:0] t_x,
    output reg  [W-1:0] t_y,
    output reg  [W-1:0] t_z,    // DIM = 3; else 0
    output reg          valid   // 0: zero length, no direction
);

    // Bad parameters stop elaboration: $error for Yosys (0.23 has no $fatal),
    // $fatal for the simulators (Icarus carries on after $error).
    initial begin
        if (W < 8 || W > 32) begin
`ifdef SYNTHESIS
            $error("toward: W must be 8..32 (W=%0d) in %m", W);
`else
            $fatal(1, "toward: W must be 8..32 (W=%0d) in %m", W);
`endif
        end
    end

    localparam [3:0] S_IDLE = 4'd0, // waiting for start
                     S_SQX  = 4'd1, // square d.x
                     S_SQY  = 4'd2, // square d.y (2D: start the root)
                     S_SQRT = 4'd3, // wait for the root, then start the divider
                     S_DIV  = 4'd4, // wait for the quotient
                     S_MX   = 4'd5, // T.x = P.x + d.x * r
                     S_MY   = 4'd6, // T.y = P.y + d.y * r
                     S_SQZ  = 4'd7, // DIM = 3: square d.z, start the root
                     S_MZ   = 4'd8; // DIM = 3: T.z = P.z + d.z * r
    localparam [3:0] S_ROOT = DIM == 3 ? S_SQZ : S_SQY; // the state that starts the root
    localparam [3:0] S_LAST = DIM == 3 ? S_MZ : S_MY;   // the last product

    reg [3:0]     state_q, state_d;
    reg           done_q, done_d;
    reg [W-1:0]   dx_q, dy_q, px_q, py_q, rest_q, r_q;
    reg [W-1:0]   dz_lane_q, pz_q;  // DIM = 3 (constant 0 in 2D, removed by synthesis)
    reg           excess_q;
    reg           dz_q;
    reg [2*W-1:0] sq_q;   // d.x^2

    // ---- the shared multiplier ----
    reg  [W-1:0]   mul_a, mul_b;
    wire [W-1:0]   mul_round;
    wire [2*W-1:0] mul_exact;
    /* verilator lint_off PINCONNECTEMPTY */
    // the multiplier's saturation flag is not used: saturation is the result itself
    fx_mul #(.W(W), .F(F)) u_mul (.a(mul_a), .b(mul_b), .y(mul_round), .prod(mul_exact), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    always @* begin
        mul_a = dx_q;
        mul_b = dx_q;
        case (state_q)
            S_SQY:   begin mul_a = dy_q; mul_b = dy_q; end
            S_SQZ:   begin mul_a = dz_lane_q; mul_b = dz_lane_q; end
            S_MX:    begin mul_a = dx_q; mul_b = r_q;  end
            S_MY:    begin mul_a = dy_q; mul_b = r_q;  end
            S_MZ:    begin mul_a = dz_lane_q; mul_b = r_q; end
            default: ;
        endcase
    end

    // ---- subtract, add ----
    wire [W-1:0] dx_new, dy_new, dz_new, t_sum;
    /* verilator lint_off PINCONNECTEMPTY */
    fx_add #(.W(W)) u_dx (.sub(1'b1), .a(c_x), .b(p_x), .y(dx_new), .sat());
    fx_add #(.W(W)) u_dy (.sub(1'b1), .a(c_y), .b(p_y), .y(dy_new), .sat());
    fx_add #(.W(W)) u_dz (.sub(1'b1), .a(c_z), .b(p_z), .y(dz_new), .sat());
    wire [W-1:0] t_base = excess_q ? (state_q == S_MZ ? dz_lane_q : state_q == S_MY ? dy_q : dx_q)
                                   : (state_q == S_MZ ? pz_q : state_q == S_MY ? py_q : px_q);
    fx_add #(.W(W)) u_t  (.sub(excess_q), .a(t_base), .b(mul_round), .y(t_sum), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- square root and divider ----
    wire         sqrt_start = state_q == S_ROOT;
    wire [2*W-1:0] radicand = sq_q + mul_exact; // each square <= 2^(2W-2), so a sum of three fits 2W bits
    wire         sqrt_done, div_done, div_zero;
    wire [W-1:0] root, quot;
    /* verilator lint_off PINCONNECTEMPTY */
    // busy and saturation flags are not needed: the FSM counts on the fixed latency
    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
        .clk(clk), .reset(reset), .start(sqrt_start), .radicand(radicand),
        .busy(), .done(sqrt_done), .result(root), .sat());
    fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) u_div (
        .clk(clk), .reset(reset), .start(state_q == S_SQRT && sqrt_done), .num(rest_q), .den(root),
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
            S_SQRT:  if (sqrt_done) state_d = S_DIV;
            S_DIV:   if (div_done) state_d = S_MX;
            S_MX:    state_d = S_MY;
            S_MY:    if (DIM == 3) state_d = S_MZ; else begin state_d = S_IDLE; done_d = 1'b1; end
            S_MZ:    begin state_d = S_IDLE; done_d = 1'b1; end
            default: state_d = S_IDLE;
        endcase
    end

    always @(posedge clk) begin
        if (reset) begin
            state_q <= S_IDLE;
            done_q  <= 1'b0;
            t_x     <= {W{1'b0}};
            t_y     <= {W{1'b0}};
            t_z     <= {W{1'b0}};
            valid   <= 1'b0;
        end else begin
            state_q <= state_d;
            done_q  <= done_d;
            if (state_q == S_MX) t_x <= t_sum;
            if (state_q == S_MY) t_y <= t_sum;
            if (state_q == S_MZ) t_z <= t_sum;
            if (state_q == S_LAST) valid <= !dz_q;
        end
    end

    // Datapath registers: written in their own state only, so no reset.
    always @(posedge clk) begin
        if (state_q == S_IDLE && start) begin
            dx_q   <= dx_new;
            dy_q   <= dy_new;
            px_q   <= p_x;
            py_q   <= p_y;
            dz_lane_q <= DIM == 3 ? dz_new : {W{1'b0}};
            pz_q   <= DIM == 3 ? p_z : {W{1'b0}};
            excess_q <= excess;
            rest_q <= rest_len;
        end
        if (state_q == S_SQX) sq_q <= mul_exact;
        if (state_q == S_SQY && DIM == 3) sq_q <= radicand;  // d.x^2 + d.y^2, d.z^2 follows
        if (state_q == S_DIV && div_done) begin
            r_q  <= quot;
            dz_q <= div_zero;
        end
    end

    assign busy = state_q != S_IDLE;
    assign done = done_q;

endmodule

`resetall
