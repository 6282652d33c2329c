`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * toward_prev - toward with projection = previous (SHAKE): the correction moves C along
 * the constraint's direction at the start of the substep, to where the length is
 * `rest_len`, and falls back to toward's result (along the current direction) when that
 * direction has no length or its line misses the sphere.
 *
 * Computes model/engine_body.h along_previous() and the callers' use of it, toward()
 * (excess = 0) and pair_edge() (excess = 1). With q = C - P (now) and r = C- - P- (the
 * previous positions, which Verlet keeps), every step a saturating fx_add/fx_sub or an
 * exact product, as in the model:
 *     lr  = fx_sqrt(r.r)                            the start direction's length
 *     u_k = fx_unit_div(r_k, lr)                    the unit vector, Q2.(W-2): sign and magnitude
 *                                                   around an fx_div with F = W-2
 *     s   = sum_k round_(W-2)(q_k u_k)              q along u (summed in axis order, saturating)
 *     p_k = q_k - round_(W-2)(s u_k)                q across u
 *     leg = fx_sqrt(rest^2 - p.p)                   exact 2W-bit squares; miss when p.p > rest^2
 *     o_k = p_k -/+ round_(W-2)(leg u_k)            - when s < 0: the nearer crossing
 *     T_k = P_k + o_k                               excess = 0 (the centred rule's point)
 *     T_k = q_k - o_k                               excess = 1 (the pairwise rule's excess)
 * fallback = (lr = 0) or miss: T and valid are then those of a `toward` instance that
 * runs beside this datapath on the same operands (valid = 0 for a zero current length).
 * Otherwise valid = 1.
 *
 * Datapath: one W x W multiplier (exact product; fx_round with F = W-2 rounds the unit
 * products), one fx_sqrt (both roots), one fx_div with F = W-2 (the DIM unit
 * components), and the `toward` of the fallback with its own. The multiplier is
 * pipelined as in toward: operands registered in the issue cycle, the exact product in
 * the next; a square is used (summed) the cycle after that, a unit product rounded and
 * registered, then used. A phase issues its products on consecutive cycles and the next
 * phase starts the cycle after its last one is used.
 *
 * Timing, fixed whatever the data (model/timing.c hw_toward_latency mirrors it):
 * counting the start cycle as 0,
 *   1 .. DIM                         issue r_k^2; the last is used in DIM + 2, starting the root
 *   D1 = SQRT_BITS + DIM + 4         lr is there; the divider starts on u_0
 *   D2 = D1 + DIM (DIV_BITS + 2)     the last u_k is there
 *   D2 + 1 ..                        issue q_k u_k (DIM), used by D2 + DIM + 3
 *   D2 + DIM + 4 ..                  issue s u_k, used by D2 + 2 DIM + 6
 *   A = D2 + 2 DIM + 7 ..            issue p_k^2 and rest^2 (DIM + 1); the last is used in
 *                                    A + DIM + 2, starting the root of the leg
 *   D3 = A + SQRT_BITS + DIM + 4     the leg is there
 *   D3 + 1 ..                        issue leg u_k, used by D3 + DIM + 3
 *   D3 + DIM + 4                     T formed and chosen (or the fallback's)
 * done is high in cycle LATENCY = D3 + DIM + 5 = 2 SQRT_BITS + DIM DIV_BITS + 7 DIM + 20,
 * for one cycle; t and valid are new then and hold until the next operation's done.
 * start is accepted only when idle or in the done cycle. Throughput: one operation per
 * LATENCY + 1 cycles.
 *
 * Ports: as toward, and pp, pc: P's and C's previous positions (DIM lanes).
 *
 * MANTISSA > 0 (the normalised datapath): u from MANTISSA-bit mantissas (model/engine_fixed.c
 * unit_dir) and the fallback's t from fx_along, through toward_prev_pipe taking this one
 * operation; done is high in cycle LATENCY = toward_prev_pipe's latency + 1
 * (model/timing.c hw_toward_latency), and the rest of the contract is the same. The
 * bit-serial datapath below is MANTISSA = 0.
 */
module toward_prev #(
    parameter integer W         = 32,
    parameter integer F         = 16,
    parameter integer SQRT_BITS = W - 1,
    parameter integer DIV_BITS  = W - 1,
    parameter integer MANTISSA  = 0,    // 0: the bit-serial root and divides; 6 .. 20: the normalised datapath
    parameter integer DIM       = 2
) (
    input  wire             clk,
    input  wire             reset,  // synchronous, active high
    input  wire             start,  // sample the operands
    input  wire             excess, // 0: T = P + o (centred rule), 1: T = q - o (pairwise rule)
    input  wire [DIM*W-1:0] p,
    input  wire [DIM*W-1:0] c,
    input  wire [DIM*W-1:0] pp,     // P's previous position
    input  wire [DIM*W-1:0] pc,     // C's previous position
    input  wire [W-1:0]     rest_len,
    output wire             busy,
    output wire             done,   // one-cycle pulse: t and valid are new
    output reg  [DIM*W-1:0] t,
    output reg              valid   // 0: the fallback found a zero length
);

    `STRAND_CHECK(toward_prev_W, W >= 8 && W <= 32, ("toward_prev: W must be 8..32 (W=%0d) in %m", W))
    `STRAND_CHECK(toward_prev_DIM, DIM == 2 || DIM == 3, ("toward_prev: DIM must be 2 or 3 (DIM=%0d) in %m", DIM))

    genvar k;
    generate
        if (MANTISSA > 0) begin : g_norm
            // one operation at a time through the pipelined normalised datapath
            reg              busy_q, done_q;
            wire             o_valid, o_ok;
            wire [DIM*W-1:0] o_t;
            /* verilator lint_off PINCONNECTEMPTY */
            // the tag, P and C are not needed: one operation is in flight
            toward_prev_pipe #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .MANTISSA(MANTISSA), .DIM(DIM)) u_pipe (
                .clk(clk), .reset(reset), .in_valid(start && !busy_q), .in_excess(excess),
                .in_p(p), .in_c(c), .in_pp(pp), .in_pc(pc), .in_rest(rest_len), .in_tag(1'b0),
                .out_valid(o_valid), .out_t(o_t), .out_ok(o_ok), .out_tag(), .out_p(), .out_c());
            /* verilator lint_on PINCONNECTEMPTY */
            always @(posedge clk) begin
                if (reset) begin
                    busy_q <= 1'b0;
                    done_q <= 1'b0;
                    t      <= {(DIM*W){1'b0}};
                    valid  <= 1'b0;
                end else begin
                    done_q <= o_valid;
                    if (o_valid) begin
                        busy_q <= 1'b0;
                        t      <= o_t;
                        valid  <= o_ok;
                    end
                    if (start && !busy_q) busy_q <= 1'b1;  // busy_q is low in the done cycle
                end
            end
            assign busy = busy_q;
            assign done = done_q;
        end else begin : g_serial
        localparam integer UF = W - 2; // fraction bits of a unit component

        // the steps: a multiply phase issues products, a wait state waits for a root or quotients
        localparam [2:0] S_IDLE  = 3'd0,
                         S_ISSUE = 3'd1, // issue the phase's products, one a cycle
                         S_DRAIN = 3'd2, // wait until the phase's last product is used
                         S_ROOT  = 3'd3, // wait for lr; then start the divider on u_0
                         S_UDIV  = 3'd4, // wait for u_k; start the next
                         S_LEG   = 3'd5, // wait for the leg
                         S_FORM  = 3'd6; // form T, choose it or the fallback's
        // the phases (and the kind of each product in flight)
        localparam [2:0] PH_RSQ  = 3'd0, // r_k^2        (a square: summed)
                         PH_DOT  = 3'd1, // q_k u_k      (a unit product: rounded)
                         PH_PROJ = 3'd2, // s u_k
                         PH_PSQ  = 3'd3, // p_k^2, then rest^2
                         PH_OUT  = 3'd4; // leg u_k
        localparam integer DIM_LAST_I = DIM - 1;
        localparam [1:0]   DIM_LAST = DIM_LAST_I[1:0];
        localparam integer DIM_I = DIM;
        localparam [1:0]   DIM_AX = DIM_I[1:0];   // PH_PSQ's extra product, rest^2

        reg [2:0]       state_q, state_d;
        reg [2:0]       ph_q, ph_d;
        reg [1:0]       ax_q, ax_d;
        reg             done_q;
        reg [DIM*W-1:0] q_q, r_q, p_q;    // q = C - P, r = C- - P-, P
        reg [W-1:0]     rest_q;
        reg             excess_q;
        reg [DIM*W-1:0] u_q, pv_q, o_q;   // the unit vector, p, o
        reg [W-1:0]     s_q;              // q along u
        reg [2*W-1:0]   sum_q;            // the squares so far
        reg             zero_q, miss_q;

        // ---- the multiplier pipeline: issue (operands), product, use ----
        wire         issue_last = ax_q == (ph_q == PH_PSQ ? DIM_AX : DIM_LAST);
        wire [W-1:0] q_ax  = q_q[ax_q * W +: W];
        wire [W-1:0] r_ax  = r_q[ax_q * W +: W];
        wire [W-1:0] u_ax  = u_q[ax_q * W +: W];
        wire [W-1:0] pv_ax = pv_q[ax_q * W +: W];
        wire [W-1:0] root;
        reg  [W-1:0] op_a_d, op_b_d;
        always @* begin
            case (ph_q)
                PH_RSQ:  begin op_a_d = r_ax; op_b_d = r_ax; end
                PH_DOT:  begin op_a_d = q_ax; op_b_d = u_ax; end
                PH_PROJ: begin op_a_d = s_q;  op_b_d = u_ax; end
                PH_PSQ:  if (ax_q == DIM_AX) begin op_a_d = rest_q; op_b_d = rest_q; end
                         else begin op_a_d = pv_ax; op_b_d = pv_ax; end
                default: begin op_a_d = root; op_b_d = u_ax; end  // PH_OUT: the leg
            endcase
        end

        reg  [W-1:0]   op_a, op_b;        // stage 1
        reg            s1_v, s1_last;
        reg  [2:0]     s1_ph;
        reg  [1:0]     s1_ax;
        reg  [2*W-1:0] prod_q;            // stage 2: the exact product (a square is used here)
        reg            s2_v, s2_last;
        reg  [2:0]     s2_ph;
        reg  [1:0]     s2_ax;
        reg  [W-1:0]   round_q;           // stage 3: the rounded unit product (used here)
        reg            s3_v, s3_last;
        reg  [2:0]     s3_ph;
        reg  [1:0]     s3_ax;
        wire [2*W-1:0] mul_exact;
        wire [W-1:0]   mul_round;
        /* verilator lint_off PINCONNECTEMPTY */
        // saturation flags are not needed: the saturated value is the result
        fx_mul #(.W(W), .F(F), .ROUND(1'b0)) u_mul (.a(op_a), .b(op_b), .y(), .prod(mul_exact), .sat());
        fx_round #(.W(W), .F(UF)) u_round (.prod(prod_q), .y(mul_round), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        wire s2_square = s2_ph == PH_RSQ || s2_ph == PH_PSQ;
        wire use_sq    = s2_v && s2_square;
        wire use_prod  = s3_v;
        wire phase_end = (use_sq && s2_last) || (use_prod && s3_last);

        always @(posedge clk) begin
            if (reset) begin
                s1_v <= 1'b0;
                s2_v <= 1'b0;
                s3_v <= 1'b0;
            end else begin
                s1_v <= state_q == S_ISSUE;
                s2_v <= s1_v;
                s3_v <= s2_v && !s2_square;
            end
            // datapath: no reset (the valid bits say what is there)
            op_a    <= op_a_d;
            op_b    <= op_b_d;
            s1_last <= issue_last;
            s1_ph   <= ph_q;
            s1_ax   <= ax_q;
            prod_q  <= mul_exact;
            s2_last <= s1_last;
            s2_ph   <= s1_ph;
            s2_ax   <= s1_ax;
            round_q <= mul_round;
            s3_last <= s2_last;
            s3_ph   <= s2_ph;
            s3_ax   <= s2_ax;
        end

        // ---- the adders: q and r at start; one for a used unit product; T's lanes ----
        wire [DIM*W-1:0] q_new, r_new, t_new;
        wire [W-1:0]     q_s3  = q_q[s3_ax * W +: W];
        wire [W-1:0]     pv_s3 = pv_q[s3_ax * W +: W];
        reg  [W-1:0]     add_a;
        reg              add_sub;
        wire [W-1:0]     add_y;
        always @* begin
            case (s3_ph)
                PH_DOT:  begin add_a = s3_ax == 2'd0 ? {W{1'b0}} : s_q; add_sub = 1'b0; end  // s = 0 + q_0 u_0 + ...
                PH_PROJ: begin add_a = q_s3;  add_sub = 1'b1; end                            // p_k = q_k - s u_k
                default: begin add_a = pv_s3; add_sub = s_q[W-1]; end                        // o_k = p_k -/+ leg u_k: - when s < 0
            endcase
        end
        /* verilator lint_off PINCONNECTEMPTY */
        // saturation flags are not needed: the saturated value is the result

            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                fx_add #(.W(W), .SUB(1)) u_q (.sub(1'b1), .a(c[k*W +: W]), .b(p[k*W +: W]), .y(q_new[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(1)) u_r (.sub(1'b1), .a(pc[k*W +: W]), .b(pp[k*W +: W]), .y(r_new[k*W +: W]), .sat());
                fx_add #(.W(W)) u_t (.sub(excess_q), .a(excess_q ? q_q[k*W +: W] : p_q[k*W +: W]), .b(o_q[k*W +: W]),
                                     .y(t_new[k*W +: W]), .sat());
            end
        fx_add #(.W(W)) u_use (.sub(add_sub), .a(add_a), .b(round_q), .y(add_y), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- the root (lr, then the leg) and the unit divider ----
        wire           sqrt_start = use_sq && s2_last;  // after r's squares, and after rest^2
        wire [2*W-1:0] radicand   = s2_ph == PH_RSQ ? sum_q + prod_q : prod_q - sum_q;  // r.r; rest^2 - p.p
        wire           sqrt_done, div_done;
        wire [W-1:0]   quot;
        wire [W-1:0]   r_div  = r_q[ax_d * W +: W];     // the component the divider starts on
        wire [W-1:0]   r_mag  = r_div[W-1] ? ~r_div + 1'b1 : r_div;  // |r_k|: -2^(W-1) reads 2^(W-1) unsigned
        wire           div_go = (state_q == S_ROOT && sqrt_done) || (state_q == S_UDIV && div_done && ax_q != DIM_LAST);
        wire [W-1:0]   r_now  = r_q[ax_q * W +: W];
        /* verilator lint_off PINCONNECTEMPTY */
        // busy and the flags are not needed: the FSM counts on the fixed latency, and a zero
        // length is seen on the root itself
        fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) u_sqrt (
            .clk(clk), .reset(reset), .start(sqrt_start), .radicand(radicand),
            .busy(), .done(sqrt_done), .result(root), .sat());
        fx_div #(.W(W), .F(UF), .DIV_BITS(DIV_BITS)) u_div (
            .clk(clk), .reset(reset), .start(div_go), .num(r_mag), .den(root),
            .busy(), .done(div_done), .result(quot), .div_by_zero(), .sat());
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- the fallback: toward on the same operands ----
        wire [DIM*W-1:0] cur_t;
        wire             cur_valid;
        /* verilator lint_off PINCONNECTEMPTY */
        // its busy and done are not needed: it finishes before this datapath (LATENCY is longer)
        toward #(.W(W), .F(F), .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_cur (
            .clk(clk), .reset(reset), .start(start && state_q == S_IDLE), .excess(excess),
            .p(p), .c(c), .rest_len(rest_len), .busy(), .done(), .t(cur_t), .valid(cur_valid));
        /* verilator lint_on PINCONNECTEMPTY */

        // ---- control ----
        always @* begin
            state_d = state_q;
            ph_d    = ph_q;
            ax_d    = ax_q;
            case (state_q)
                S_IDLE:  if (start) begin state_d = S_ISSUE; ph_d = PH_RSQ; ax_d = 2'd0; end
                S_ISSUE: if (issue_last) state_d = S_DRAIN; else ax_d = ax_q + 1'b1;
                S_DRAIN: if (phase_end) begin
                             ax_d = 2'd0;
                             case (ph_q)
                                 PH_RSQ:  state_d = S_ROOT;
                                 PH_DOT:  begin state_d = S_ISSUE; ph_d = PH_PROJ; end
                                 PH_PROJ: begin state_d = S_ISSUE; ph_d = PH_PSQ; end
                                 PH_PSQ:  state_d = S_LEG;
                                 default: state_d = S_FORM;  // PH_OUT
                             endcase
                         end
                S_ROOT:  if (sqrt_done) state_d = S_UDIV;
                S_UDIV:  if (div_done) begin
                             if (ax_q == DIM_LAST) begin state_d = S_ISSUE; ph_d = PH_DOT; ax_d = 2'd0; end
                             else ax_d = ax_q + 1'b1;
                         end
                S_LEG:   if (sqrt_done) begin state_d = S_ISSUE; ph_d = PH_OUT; end
                S_FORM:  state_d = S_IDLE;
                default: state_d = S_IDLE;
            endcase
        end

        always @(posedge clk) begin
            if (reset) begin
                state_q <= S_IDLE;
                ph_q    <= PH_RSQ;
                ax_q    <= 2'd0;
                done_q  <= 1'b0;
                t       <= {(DIM*W){1'b0}};
                valid   <= 1'b0;
            end else begin
                state_q <= state_d;
                ph_q    <= ph_d;
                ax_q    <= ax_d;
                done_q  <= state_q == S_FORM;
                if (state_q == S_FORM) begin
                    t     <= zero_q || miss_q ? cur_t : t_new;
                    valid <= zero_q || miss_q ? cur_valid : 1'b1;
                end
            end
        end

        // Datapath registers: each written in its own step, so no reset.
        always @(posedge clk) begin
            if (state_q == S_IDLE && start) begin
                q_q      <= q_new;
                r_q      <= r_new;
                p_q      <= p;
                rest_q   <= rest_len;
                excess_q <= excess;
            end
            if (use_sq && !(s2_ph == PH_PSQ && s2_last)) sum_q <= s2_ax == 2'd0 ? prod_q : sum_q + prod_q;  // not rest^2
            if (use_sq && s2_last && s2_ph == PH_PSQ) miss_q <= sum_q > prod_q;  // p.p > rest^2
            if (state_q == S_ROOT && sqrt_done) zero_q <= root == {W{1'b0}};
            if (state_q == S_UDIV && div_done) u_q[ax_q * W +: W] <= r_now[W-1] ? ~quot + 1'b1 : quot;
            if (use_prod) begin
                case (s3_ph)
                    PH_DOT:  s_q <= add_y;
                    PH_PROJ: pv_q[s3_ax * W +: W] <= add_y;
                    default: o_q[s3_ax * W +: W] <= add_y;
                endcase
            end
        end

        assign busy = state_q != S_IDLE;
        assign done = done_q;
        end
    endgenerate

endmodule

`resetall
