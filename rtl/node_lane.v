`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"

/*
 * node_lane - one axis of a node unit: the axis's storage and its part of the
 * per-node step (node_unit instantiates DIM of them: x, y, z).
 *
 * Storage (strand_ram, reset-free): pos (positions; port A for the pass and the
 * sequencers, port B for the external read port), prev (previous positions) and,
 * with EN_SPRINGS, acc (the spring force gathered this substep). With PAIR (a chain's
 * pipelined constraint pass) they are bank_rams of two banks, even and odd nodes: the
 * constraint pass reads a pair of neighbours a clock (q_e, q_o, qp_e, qp_o) and writes
 * up to two (the second write port, pos only), and the Verlet and ground passes read a
 * row a clock (nodes 2r and 2r + 1) and write both (pos, prev and the force's clear on
 * both write ports); every other reader still sees one port A.
 *
 * Ways: the per-node step below is built once, or with PAIR twice (way 0 the even
 * node of a row, way 1 the odd one), so a pass takes one node a clock, or with PAIR
 * two. Way 0 writes through write port 1, way 1 through write port 2.
 *
 * The Verlet step of this axis, from port A's data q, qp, qa (model/engine_body.h
 * verlet_node(), every operation a saturating fx_add / fx_mul in the model's order):
 *     v = q - qp;  v = v - v*d (EN_DAMPING);  v = v - (v - w h)*c h (EN_WIND);  n = q + v;  n = n + g h^2 (EN_GRAVITY);
 *     n = n + qa (EN_SPRINGS)
 * The mouse (EN_MOUSE, not GRAB): `touch` says |mouse - n| < box on this axis
 * (touch_lo < n < touch_hi, the box around the pointer that frame_ctrl forms); the
 * impulse itself acts on x only (reference 000, mouse_node()): lane 0 makes
 *     np = in_touch ? (mouse < q ? n + a : n - a) : q
 * The ground pass (EN_GROUND, ground_node()): on the normal axis (AXIS = GROUND_AXIS)
 * `hit` says the node is past the boundary b, and the node is put on it with its
 * velocity reversed: g = b, gp = b + v; on every other axis friction pulls the previous
 * position toward the position: g = q, gp = qp + v * friction.
 *
 * The write of this axis (node_unit decides whether and where): during a pass the
 * pass's result (the grabbed node: the pointer, its old position as previous),
 * else the external data (init walk, NODE loads, the sequencer), a pinned node's
 * previous position = its position (it starts at rest).
 *
 * Timing: a pass is a four-stage pipeline, each stage registered (ARCH = 1: five, a
 * stage R first that registers port A's words). Stage A, the cycle port A's data arrive
 * (ARCH = 1: the cycle after): the velocity v = q - qp (and the ground test). Stage B: the
 * rest of the Verlet step (damping, x + v, gravity, the spring force), or the ground
 * pass's bounce and friction. Stage C: the mouse's in-touch test on this axis and the
 * impulse's sum. Stage W (the write): the impulse chosen (every axis in touch) and the write. So
 * no path holds more than two of the step's adders; a node (with PAIR a row) is written
 * four cycles after its address (ARCH = 1: five). Storage reads are synchronous (address
 * now, data next cycle), read before write.
 */
module node_lane #(
`include "strand_params.vh"
    ,
    parameter integer AXIS = 0   // 0 x, 1 y, 2 z
) (
    input  wire          clk,
    input  wire          reset,      // only for the node memories' simulation check (nothing here is reset)

    // port A, port B, the write port (node_unit's addresses and enables)
    input  wire          a_re,
    input  wire [IW-1:0] a_addr,
    input  wire [IW-1:0] b_addr,
    input  wire          we,         // write pos at widx (write port 1)
    input  wire [IW-1:0] widx,
    input  wire          pos1,       //   the pass's way 0 (else the external data)
    input  wire          pwe,        // write prev at pidx (its port 1: the pass's way 0, else the external data)
    input  wire [IW-1:0] pidx,
    input  wire          acc_clear,  // the Verlet pass consumes the force of a node, the init walk and loads clear it
    input  wire [IW-1:0] acc_clear_idx,
    input  wire          acc_we,     // the spring pass writes the force of node widx
    input  wire [W-1:0]  acc_w,
    // PAIR: a pair read instead of port A (the even bank at row pair_row_e, the odd bank
    // at pair_row_o: the constraint pass's pairs, the Verlet pass's rows), and a second
    // write, to the other bank than the first write's: the constraint pass's position,
    // or the pass's way 1 (position, previous position with wprev2, the force cleared)
    input  wire          pair_re,
    input  wire [IW-1:0] pair_row_e,
    input  wire [IW-1:0] pair_row_o,
    input  wire          we2,        // write pos at widx2 (write port 2): the pass's way 1 (swap2: way 0), else w2_pos
    input  wire [IW-1:0] widx2,
    input  wire          swap2,
    input  wire          pwe2,       // write prev at pidx2: the pass's way 1
    input  wire [IW-1:0] pidx2,
    input  wire          acc_clear2, //   and clear its force
    input  wire [W-1:0]  w2_pos,     // the constraint pass's data (when no pass writes)

    // the pass pipeline (node_unit's stage valids, one set for both ways) and how the write is formed
    input  wire          stage_r,    // ARCH = 1: a pass's node's data arrive now (stage R registers them)
    input  wire          stage_a,    // a pass's node is in stage A (serial: its data arrive now)
    input  wire          stage_b,    //   in stage B
    input  wire          stage_c,    //   in stage C
    input  wire          pass_w,     //   in stage W: write its result
    input  wire          ground_w,   //   the ground pass
    input  wire [PAIR:0] grab_w,     //   the way's node is the grabbed one (GRAB)
    input  wire [PAIR:0] pin_w,      //   the way's node is pinned (FUSE: the sweep gets it unmoved)
    input  wire          w_pin,      // an external write to a pinned node: at rest
    input  wire [W-1:0]  w_pos,      // external write data
    input  wire [W-1:0]  w_prev,

    // the run-time constants and the pointer, of this axis
    input  wire [`STRAND_FX_SLOTS*W-1:0] fx_consts,  // the effects table's constants (strand_regs.vh's slots)
    input  wire [W-1:0]  impulse,    // a (lane 0)
    input  wire [W:0]    touch_lo,   // mouse - box, exact: in touch when touch_lo < n < touch_hi
    input  wire [W:0]    touch_hi,   // mouse + box
    input  wire [W-1:0]  mouse,      // the pointer, sampled at the frame start
    input  wire [PAIR:0] in_touch,   // a way's node: every axis touches and the button is down (lane 0's impulse)
    input  wire [W-1:0]  ground,     // the ground boundary (on the normal axis)
    input  wire [W-1:0]  friction,   // 1 - u

    output wire [W-1:0]  q,          // port A: position, previous position, force
    output wire [W-1:0]  qp,
    output wire [W-1:0]  qa,
    output wire [W-1:0]  b_data,     // port B: position, two cycles after b_addr (node_unit masks unwritten nodes)
    output wire [W-1:0]  q_e,        // PAIR: the banks' words, position and previous position
    output wire [W-1:0]  q_o,        //   (a pair read's, or a port-A read's two rows)
    output wire [W-1:0]  qp_e,
    output wire [W-1:0]  qp_o,
    output wire [PAIR:0] touch,      // stage W, a way's node: |mouse - n| < box on this axis
    output wire [PAIR:0] hit,        // stage W, AXIS = GROUND_AXIS: past the boundary
    output wire [W-1:0]  wdata,      // what this axis writes now through write port 1 (the write-back lane shows it)
    output wire [W-1:0]  wdata2,     //   and through write port 2 (PAIR)
    output wire [(1+PAIR)*W-1:0] sweep_pos,  // FUSE, stage W, each way: the node as the step leaves it (a
    output wire [(1+PAIR)*W-1:0] sweep_prev  //   pinned one unmoved): the fused sweep's words
);

    localparam integer NW = 1 + PAIR;  // ways: nodes a pass takes a clock

    // ---- storage ----
    wire [NW*W-1:0] np_way, gr_way, grp_way;          // stage W: each way's results (below)
    wire [NW*W-1:0] step_pos;                         //   the step's position (the grabbed node: the pointer)
    wire [W-1:0]    qa_e, qa_o;                     // the force memory's banks
    wire [W-1:0]    wprev_data, wprev_data2;
    assign wdata      = pos1 ? (EN_GROUND && ground_w ? gr_way[0 +: W] : step_pos[0 +: W]) : w_pos;
    assign wprev_data = pass_w ? (EN_GROUND && ground_w ? grp_way[0 +: W] : np_way[0 +: W]) : w_pin ? w_pos : w_prev;
    generate
        if (PAIR != 0) begin : g_wdata2
            assign wdata2      = pass_w ? (EN_GROUND && ground_w ? gr_way[W +: W] : swap2 ? step_pos[0 +: W] : step_pos[W +: W]) : w2_pos;
            assign wprev_data2 = EN_GROUND && ground_w ? grp_way[W +: W] : np_way[W +: W];
        end else begin : g_no_wdata2
            assign wdata2      = {W{1'b0}};
            assign wprev_data2 = {W{1'b0}};
            wire unused_w2 = &{1'b0, w2_pos, swap2, pwe2, pidx2, acc_clear2};
        end
    endgenerate

    // positions and previous positions: two banks with PAIR (the second write port and the
    // pair read are the pipelined passes')
    bank_ram #(.WIDTH(W), .DEPTH(K), .ABITS(IW), .BLOCK_MIN(RAM_BLOCK_MIN), .BANKS(1 + PAIR), .B_REG(1'b1), .NO_COLLIDE_A(1'b1)) u_pos (
        .clk(clk), .reset(reset), .we(we), .waddr(widx), .wdata(wdata), .we2(PAIR != 0 && we2), .waddr2(widx2), .wdata2(wdata2),
        .re_a(a_re), .raddr_a(a_addr), .rdata_a(q),
        .pair_re(PAIR != 0 && pair_re), .prow_e(pair_row_e), .prow_o(pair_row_o), .rdata_e(q_e), .rdata_o(q_o),
        .re_b(1'b1), .raddr_b(b_addr), .rdata_b(b_data));
    /* verilator lint_off PINCONNECTEMPTY */
    // the previous positions and the forces have one reader (port A, or the pair read)
    bank_ram #(.WIDTH(W), .DEPTH(K), .ABITS(IW), .BLOCK_MIN(RAM_BLOCK_MIN), .READ_B(1'b0), .BANKS(1 + PAIR), .NO_COLLIDE_A(1'b1)) u_prev (
        .clk(clk), .reset(reset), .we(pwe), .waddr(pidx), .wdata(wprev_data),
        .we2(PAIR != 0 && pwe2), .waddr2(pidx2), .wdata2(wprev_data2),
        .re_a(a_re), .raddr_a(a_addr), .rdata_a(qp),
        .pair_re(PAIR != 0 && pair_re), .prow_e(pair_row_e), .prow_o(pair_row_o), .rdata_e(qp_e), .rdata_o(qp_o),
        .re_b(1'b0), .raddr_b({IW{1'b0}}), .rdata_b());

    // ---- the spring force of this substep (a spring pass gathered it), added in stage B ----
    // The Verlet pass consumes each node's force and clears it (pinned nodes too), so the
    // next spring pass starts from 0, as model/engine_body.h force_pass() does; the init
    // walk and NODE loads clear it too (the memory is not reset).
    generate
        if (EN_SPRINGS) begin : g_acc
            bank_ram #(.WIDTH(W), .DEPTH(K), .ABITS(IW), .BLOCK_MIN(RAM_BLOCK_MIN), .READ_B(1'b0), .BANKS(1 + PAIR), .NO_COLLIDE_A(1'b1)) u_acc (
                .clk(clk), .reset(reset), .we(acc_clear || acc_we), .waddr(acc_clear ? acc_clear_idx : widx),
                .wdata(acc_clear ? {W{1'b0}} : acc_w),
                .we2(PAIR != 0 && acc_clear2), .waddr2(pidx2), .wdata2({W{1'b0}}),
                .re_a(a_re), .raddr_a(a_addr), .rdata_a(qa),
                .pair_re(PAIR != 0 && pair_re), .prow_e(pair_row_e), .prow_o(pair_row_o), .rdata_e(qa_e), .rdata_o(qa_o),
                .re_b(1'b0), .raddr_b({IW{1'b0}}), .rdata_b());
        end else begin : g_no_acc
            assign qa   = {W{1'b0}};
            assign qa_e = {W{1'b0}};
            assign qa_o = {W{1'b0}};
            wire unused_acc = &{1'b0, acc_clear, acc_clear_idx, acc_we, acc_w, acc_clear2};
        end
    endgenerate

    // ---- the per-node step, one copy a way: way 0 takes the even bank's words (with one
    // bank, port A's), way 1 the odd bank's ----
    genvar wy;
    generate
        for (wy = 0; wy < NW; wy = wy + 1) begin : g_way
            wire [W-1:0] q_in  = wy == 0 ? q_e : q_o;   // the words of this way's node
            wire [W-1:0] qp_in = wy == 0 ? qp_e : qp_o;
            wire [W-1:0] qa_in = wy == 0 ? qa_e : qa_o;

            // the pipeline registers (datapath: the stage valids say when they hold a node)
            wire [W-1:0] v;                  // stage A: q - qp
            wire         hit_a;              // stage A: past the ground boundary
            reg  [W-1:0] q_b, qp_b, qa_b, v_b;
            reg          hit_b;
            wire [W-1:0] n;                  // stage B: the Verlet result
            wire [W-1:0] g, gp;              // stage B: the ground pass's result
            reg  [W-1:0] n_c, q_c, g_c, gp_c;
            reg          hit_c;
            reg          left_c;             // the pointer is left of (below) the old position: the impulse adds
            wire [W-1:0] pushed;             // stage C: the previous position the impulse would give (x)
            wire         touch_c;            // stage C: in touch on this axis
            reg  [W-1:0] n_w, q_w, g_w, gp_w, pushed_w;
            reg          hit_w, touch_w;
            wire [W-1:0] np;                 // stage W: the previous position after the mouse impulse
            wire [W-1:0] q_a, qp_a, qa_a;    // stage A's words
            always @(posedge clk) begin
                if (stage_a) begin
                    q_b   <= q_a;
                    qp_b  <= qp_a;
                    qa_b  <= qa_a;
                    v_b   <= v;
                    hit_b <= hit_a;
                end
                if (stage_b) begin
                    n_c    <= n;
                    q_c    <= q_b;
                    g_c    <= g;
                    gp_c   <= gp;
                    hit_c  <= hit_b;
                    left_c <= $signed(mouse) < $signed(q_b);
                end
                if (stage_c) begin
                    n_w      <= n_c;
                    q_w      <= q_c;
                    g_w      <= g_c;
                    gp_w     <= gp_c;
                    hit_w    <= hit_c;
                    touch_w  <= touch_c;
                    pushed_w <= pushed;
                end
            end
            assign hit[wy]   = hit_w;
            assign touch[wy] = touch_w;
            assign np_way[wy*W +: W] = np;
            assign step_pos[wy*W +: W]  = GRAB && grab_w[wy] ? mouse : n_w;
            if (FUSE != 0) begin : g_sweep_words
                // a pinned node is not stepped: its previous position comes along for PROJECTION
                reg [W-1:0] qp_c, qp_w;
                always @(posedge clk) begin
                    if (stage_b) qp_c <= qp_b;
                    if (stage_c) qp_w <= qp_c;
                end
                assign sweep_pos[wy*W +: W]  = pin_w[wy] ? q_w : step_pos[wy*W +: W];
                assign sweep_prev[wy*W +: W] = pin_w[wy] ? qp_w : np;
            end else begin : g_no_sweep_words
                assign sweep_pos[wy*W +: W]  = {W{1'b0}};
                assign sweep_prev[wy*W +: W] = {W{1'b0}};
            end
            assign gr_way[wy*W +: W]  = g_w;
            assign grp_way[wy*W +: W] = gp_w;

            // stage R (ARCH = 1): the words registered the cycle they arrive, so stage A's
            // subtract starts from a flip-flop, not from the block RAM's output
            if (ARCH) begin : g_stage_r
                reg [W-1:0] q_r, qp_r, qa_r;
                always @(posedge clk)
                    if (stage_r) begin
                        q_r  <= q_in;
                        qp_r <= qp_in;
                        qa_r <= qa_in;
                    end
                assign q_a  = q_r;
                assign qp_a = qp_r;
                assign qa_a = qa_r;
            end else begin : g_no_stage_r
                assign q_a  = q_in;
                assign qp_a = qp_in;
                assign qa_a = qa_in;
            end

            // stage A: the velocity (saturation flags are not needed: the saturated value is the result)
            fx_add #(.W(W), .SUB(1)) u_v (.sub(1'b1), .a(q_a), .b(qp_a), .y(v), .sat());

            // stage B: the rest of the Verlet step
            wire [W-1:0] v_d, n1, n_g;
            if (EN_DAMPING) begin : g_damping
                wire [W-1:0] dv;
                fx_mul #(.W(W), .F(F)) u_dv (.a(v_b), .b(fx_consts[`STRAND_FX_DAMPING*W +: W]), .y(dv), .sat(), .prod());
                fx_add #(.W(W), .SUB(1)) u_vd (.sub(1'b1), .a(v_b), .b(dv), .y(v_d), .sat());
            end else begin : g_no_damping
                assign v_d = v_b;
            end
            // the wind (EN_WIND): air drag toward the wind, v -= c h (v - w h)
            wire [W-1:0] v_w;
            if (EN_WIND) begin : g_wind
                wire [W-1:0] rel, dw;
                fx_add #(.W(W), .SUB(1)) u_rel (.sub(1'b1), .a(v_d), .b(fx_consts[(`STRAND_FX_WIND + AXIS)*W +: W]), .y(rel), .sat());
                fx_mul #(.W(W), .F(F)) u_dw (.a(rel), .b(fx_consts[`STRAND_FX_DRAG*W +: W]), .y(dw), .sat(), .prod());
                fx_add #(.W(W), .SUB(1)) u_vw (.sub(1'b1), .a(v_d), .b(dw), .y(v_w), .sat());
            end else begin : g_no_wind
                assign v_w = v_d;
            end
            fx_add #(.W(W), .SUB(0)) u_n1 (.sub(1'b0), .a(q_b), .b(v_w), .y(n1), .sat());
            if (EN_GRAVITY) begin : g_gravity
                fx_add #(.W(W), .SUB(0)) u_g (.sub(1'b0), .a(n1), .b(fx_consts[(`STRAND_FX_GRAVITY + AXIS)*W +: W]), .y(n_g), .sat());
            end else begin : g_no_gravity
                assign n_g = n1;
            end
            if (EN_SPRINGS) begin : g_springs
                fx_add #(.W(W), .SUB(0)) u_f (.sub(1'b0), .a(n_g), .b(qa_b), .y(n), .sat());
            end else begin : g_no_springs
                assign n = n_g;
                wire unused_springs = &{1'b0, qa_b};
            end

            // stages C and W, the mouse: this axis's in-touch test, and the impulse (x only)
            if (EN_MOUSE && !GRAB) begin : g_mouse
                // |sat(mouse - n)| < box  <=>  -box < mouse - n < box, exact (a saturated difference
                // is never inside the box)  <=>  mouse - box < n < mouse + box: two comparisons of
                // n with the box frame_ctrl forms once a frame, no subtraction per node
                wire [W:0] n_x = {n_c[W-1], n_c};
                assign touch_c = $signed(touch_lo) < $signed(n_x) && $signed(n_x) < $signed(touch_hi);
                if (AXIS == 0) begin : g_impulse
                    // px = mouse < x ? n + a : n - a (one adder: a subtract when the pointer is not left
                    // of x, a comparison made in stage B); taken in stage W when every axis touches
                    fx_add #(.W(W)) u_push (.sub(!left_c), .a(n_c), .b(impulse), .y(pushed), .sat());
                    assign np = in_touch[wy] ? pushed_w : q_w;
                end else begin : g_no_impulse
                    assign pushed = q_c;
                    assign np = q_w;
                    wire unused_impulse = &{1'b0, left_c, pushed_w};
                end
            end else begin : g_no_mouse
                assign touch_c = 1'b1;
                assign pushed = q_c;
                assign np = q_w;
                wire unused_mouse = &{1'b0, left_c, pushed_w};
            end

            // the ground pass: collision with friction (the test in stage A, the rest in B)
            if (EN_GROUND && AXIS == GROUND_AXIS) begin : g_normal
                assign hit_a = GROUND_ABOVE ? $signed(q_a) < $signed(ground) : $signed(ground) < $signed(q_a);
                fx_add #(.W(W), .SUB(0)) u_bounce (.sub(1'b0), .a(ground), .b(v_b), .y(gp), .sat());
                assign g = ground;
                wire unused_friction = &{1'b0, qp_b};
            end else if (EN_GROUND) begin : g_tangent
                wire [W-1:0] slip;
                fx_mul #(.W(W), .F(F)) u_slip (.a(v_b), .b(friction), .y(slip), .sat(), .prod());
                fx_add #(.W(W), .SUB(0)) u_fp (.sub(1'b0), .a(qp_b), .b(slip), .y(gp), .sat());
                assign g     = q_b;
                assign hit_a = 1'b0;
            end else begin : g_no_ground
                assign g     = q_b;
                assign gp    = qp_b;
                assign hit_a = 1'b0;
                wire unused_ground = &{1'b0, g_w, gp_w, hit_w};
            end
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

    // the inputs a build without their effect leaves unread: the effects table's bus (each lane
    // reads its own axis of a vector, and only the constants of the effects the build has), ...
    wire unused_fx_consts = &{1'b0, fx_consts};
    generate
        if (!(EN_MOUSE && !GRAB)) begin : g_unused_mouse
            wire unused_mouse = &{1'b0, impulse, touch_lo, touch_hi, in_touch};
        end else if (AXIS != 0) begin : g_unused_impulse
            wire unused_impulse = &{1'b0, impulse, in_touch};
        end
        if (!EN_GROUND) begin : g_unused_ground
            wire unused_ground = &{1'b0, ground, friction, ground_w};
        end else if (AXIS == GROUND_AXIS) begin : g_unused_friction
            wire unused_friction = &{1'b0, friction};
        end else begin : g_unused_boundary
            wire unused_boundary = &{1'b0, ground};
        end
        if (FUSE == 0) begin : g_unused_pin
            wire unused_pin = &{1'b0, pin_w};
        end
        if (!ARCH) begin : g_unused_stage_r
            wire unused_stage_r = &{1'b0, stage_r};
        end
    endgenerate

endmodule

`resetall
