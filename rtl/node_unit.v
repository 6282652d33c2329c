`default_nettype none
`timescale 1ns / 1ps

/*
 * node_unit - K nodes of the rope and the per-node FSM of reference 000.
 *
 * Holds x, y, px, py (signed Q(W-F).F) and a pinned flag for K nodes. A Verlet pass
 * (started by verlet_start) updates node 0 .. K-1, one node per clock, each with
 * model/engine_body.h verlet_node() and then mouse_node():
 *     v  = x - px;  v = v - v*d (EN_DAMPING);  px = x;  x = x + v;  x = x + g h^2 (EN_GRAVITY)
 *     x = x + acc (EN_SPRINGS: the spring force of this substep, then acc = 0)
 *     mouse (EN_MOUSE, button down, |mouse - x| < box on every axis):
 *         px.x = (mouse.x < px.x) ? x.x + a : x.x - a
 *     grab (EN_MOUSE and GRAB; the top says which node is held): the held node is put
 *         on the pointer, px = its old x; it counts as pinned for the constraints
 *         and the ground
 * A ground pass (EN_GROUND, started by ground_start) walks the nodes the same way
 * with model/engine_body.h ground_node(): a node past the boundary b on the normal
 * axis n is put on it, its velocity along n reversed and, on the other axis o, its
 * previous position pulled toward its position by the friction factor (1 - u):
 *     pz = b + (z - pz);  z = b;  po = po + (o - po) * friction
 * Every operation is a saturating fx_add/fx_mul, in the model's order. Pinned
 * nodes are not written.
 *
 * Storage reads are synchronous (data the cycle after the address), with
 * read-before-write, as a block RAM would behave: swapping in a RAM does not change
 * the timing. Port A serves the Verlet pass and, between passes, the sequencer;
 * port B is the external position read port.
 *
 * Timing (the cycle model mirrors it): verlet_start seen at edge 0 clears
 * verlet_done and presents address 0; edges 1..K write nodes 0..K-1; verlet_done
 * rises at edge K and stays high until the next start. Every write to this unit
 * (Verlet, init or sequencer) shows on the write-back lane in the next cycle.
 */
module node_unit #(
    parameter integer W          = 32, // word width, bits
    parameter integer F          = 16, // fraction bits
    parameter integer K          = 5,  // nodes held by this unit
    parameter integer IW         = 3,  // node index width, >= clog2(K), >= 1
    parameter [0:0]  EN_GRAVITY = 1'b1,  // add g h^2 in the Verlet step
    parameter [0:0]  EN_DAMPING = 1'b0,  // Verlet damping v -= v * d (two multipliers)
    parameter [0:0]  EN_MOUSE = 1'b1,  // reference-000 mouse impulse
    parameter [0:0]  EN_SPRINGS = 1'b0,  // per-node spring force: storage, added in the Verlet step
    parameter [0:0]  EN_GROUND  = 1'b0,  // the ground pass (reference 001): collision with friction
    parameter integer GROUND_AXIS = 1,   // the ground's normal axis: 0 x, 1 y, 2 z (DIM = 3)
    parameter [0:0]  GROUND_ABOVE = 1'b1, // 1: nodes stay at or above the boundary on that axis, 0: below
    parameter integer DIM        = 2,    // 2, or 3: a z lane (storage and datapath)
    parameter [0:0]  GRAB       = 1'b0, // with EN_MOUSE: the grab form (the held node follows the pointer)
    /* verilator lint_off UNUSEDPARAM */
    // read only by the test-only planted fault (STRAND_FAULTS)
    parameter integer UNIT_ID  = 0      // this unit's number
    /* verilator lint_on UNUSEDPARAM */
) (
    input  wire          clk,
    input  wire          reset,        // synchronous, active high: all nodes at 0, unpinned

    input  wire          verlet_start, // one-cycle pulse: run the Verlet pass over all K nodes
    input  wire          ground_start, // one-cycle pulse: run the ground pass (EN_GROUND)
    output wire          verlet_done,  // this unit's FV: high from the end of a pass to the next start
    input  wire [W-1:0]  ground,       // the ground boundary on its axis
    input  wire [W-1:0]  friction,     // 1 - u

    input  wire [W-1:0]  gdt2_x,       // g h^2, per axis
    input  wire [W-1:0]  gdt2_y,
    input  wire [W-1:0]  gdt2_z,       // DIM = 3 only, as every z input
    input  wire [W-1:0]  damping,      // d, 0 <= d < 1
    input  wire [W-1:0]  impulse,      // a
    input  wire [W-1:0]  box_x,        // in-touch half-widths
    input  wire [W-1:0]  box_y,
    input  wire [W-1:0]  box_z,
    input  wire [W-1:0]  mouse_x,      // the pointer, sampled at the frame start
    input  wire [W-1:0]  mouse_y,
    input  wire [W-1:0]  mouse_z,
    input  wire          mouse_down,
    input  wire          grab_here,    // GRAB: this unit holds the grabbed node,
    input  wire [IW-1:0] grab_idx,     //   this one

    // port A between passes: the sequencer's reads, the sequencer's and init's writes
    input  wire [IW-1:0] a_idx,        // node to read; x, y, pinned appear next cycle
    output wire [W-1:0]  a_x,
    output wire [W-1:0]  a_y,
    output wire          a_pinned,     // pinned, or grabbed (constraints do not move it)
    output wire [W-1:0]  a_px,         // previous position (the spring pass's velocities)
    output wire [W-1:0]  a_py,
    output wire [W-1:0]  a_accx,       // the spring force gathered so far (EN_SPRINGS; else 0)
    output wire [W-1:0]  a_accy,
    output wire [W-1:0]  a_z,          // the z lane (DIM = 3; else 0)
    output wire [W-1:0]  a_pz,
    output wire [W-1:0]  a_accz,
    input  wire [W-1:0]  acc_wz,
    input  wire          acc_we,       // the spring pass: write node w_idx's force
    input  wire [W-1:0]  acc_wx,
    input  wire [W-1:0]  acc_wy,
    input  wire          w_en,         // write node w_idx
    input  wire [IW-1:0] w_idx,
    input  wire [W-1:0]  w_x,
    input  wire [W-1:0]  w_y,
    input  wire          w_at_rest,    // also set px, py: the init walk
    input  wire [W-1:0]  w_px,         //   to these, or to w_x, w_y for a pinned node
    input  wire [W-1:0]  w_py,
    input  wire [W-1:0]  w_z,          // DIM = 3
    input  wire [W-1:0]  w_pz,
    input  wire          pin_en,       // pin node pin_idx
    input  wire [IW-1:0] pin_idx,

    // port B: external position reads
    input  wire [IW-1:0] b_idx,
    output reg  [W-1:0]  b_x,
    output reg  [W-1:0]  b_y,
    output wire [W-1:0]  b_z,          // DIM = 3; else 0

    // write-back lane: a write to this unit, shown the cycle after it happens
    output reg           wb_valid,
    output reg  [IW-1:0] wb_idx,
    output reg  [W-1:0]  wb_x,
    output reg  [W-1:0]  wb_y,
    output wire [W-1:0]  wb_z          // DIM = 3; else 0
);

    // Bad parameters stop elaboration: $error for Yosys (0.23 has no $fatal),
    // $fatal for the simulators (Icarus carries on after $error).
    initial begin
        if (K < 1) begin
`ifdef SYNTHESIS
            $error("node_unit: K must be >= 1 (K=%0d) in %m", K);
`else
            $fatal(1, "node_unit: K must be >= 1 (K=%0d) in %m", K);
`endif
        end
        if ((1 << IW) < K) begin
`ifdef SYNTHESIS
            $error("node_unit: IW=%0d cannot index K=%0d nodes in %m", IW, K);
`else
            $fatal(1, "node_unit: IW=%0d cannot index K=%0d nodes in %m", IW, K);
`endif
        end
    end

    localparam integer  K_LAST_I = K - 1;
    localparam [IW:0]   K_COUNT  = K[IW:0];           // node count, one bit wider than an index
    localparam [IW-1:0] K_LAST   = K_LAST_I[IW-1:0];  // index of the last node

    // ---- storage ----
    reg [W-1:0] x_mem  [0:K-1];
    reg [W-1:0] y_mem  [0:K-1];
    reg [W-1:0] px_mem [0:K-1];
    reg [W-1:0] py_mem [0:K-1];
    reg [K-1:0] pinned_q;

    // ---- the pass FSM ----
    reg          running_q, running_d;  // a pass is under way
    reg          done_q, done_d;        // FV
    reg [IW-1:0] vidx_q, vidx_d;        // node whose data port A returns this cycle
    reg          ground_q, ground_d;    // the pass under way is the ground pass

    wire last = vidx_q == K_LAST;
    wire pass_start = verlet_start || (EN_GROUND && ground_start);

    always @* begin
        running_d = running_q;
        done_d    = done_q;
        vidx_d    = vidx_q;
        ground_d  = ground_q;
        if (pass_start) begin
            running_d = 1'b1;
            done_d    = 1'b0;
            vidx_d    = {IW{1'b0}};
            ground_d  = !verlet_start;
        end else if (running_q) begin
            vidx_d = vidx_q + 1'b1;
            if (last) begin
                running_d = 1'b0;
                done_d    = 1'b1;
            end
        end
    end

    always @(posedge clk) begin
        if (reset) begin
            running_q <= 1'b0;
            done_q    <= 1'b0;
            vidx_q    <= {IW{1'b0}};
            ground_q  <= 1'b0;
        end else begin
            running_q <= running_d;
            done_q    <= done_d;
            vidx_q    <= vidx_d;
            ground_q  <= ground_d;
        end
    end

    assign verlet_done = done_q;

    // ---- port A: synchronous read ----
    // During a pass the address runs ahead of vidx by one: node vidx+1 is read
    // while node vidx is written.
    wire [IW-1:0] a_addr = pass_start ? {IW{1'b0}} : running_q ? vidx_q + 1'b1 : a_idx;
    reg  [W-1:0]  q_x, q_y, q_px, q_py;
    reg           q_pin, q_grab;

    always @(posedge clk) begin
        if ({1'b0, a_addr} < K_COUNT) begin
            q_x   <= x_mem[a_addr];
            q_y   <= y_mem[a_addr];
            q_px  <= px_mem[a_addr];
            q_py  <= py_mem[a_addr];
            q_pin <= pinned_q[a_addr];
            q_grab <= GRAB && grab_here && a_addr == grab_idx;
        end
    end

    assign a_x      = q_x;
    assign a_y      = q_y;
    assign a_pinned = q_pin || q_grab;
    assign a_px     = q_px;
    assign a_py     = q_py;

    // ---- the Verlet step of one node, from port A's data ----
    // The per-adder saturation flags are not used: saturation is the result itself.
    /* verilator lint_off PINCONNECTEMPTY */
    wire [W-1:0] vx, vy, vx_d, vy_d, x1, y1, gx, gy, nx, ny;
    fx_add #(.W(W)) u_vx (.sub(1'b1), .a(q_x), .b(q_px), .y(vx), .sat());
    fx_add #(.W(W)) u_vy (.sub(1'b1), .a(q_y), .b(q_py), .y(vy), .sat());

    generate
        if (EN_DAMPING) begin : g_damping
            wire [W-1:0] dvx, dvy;
            fx_mul #(.W(W), .F(F)) u_dvx (.a(vx), .b(damping), .y(dvx), .sat(), .prod());
            fx_mul #(.W(W), .F(F)) u_dvy (.a(vy), .b(damping), .y(dvy), .sat(), .prod());
            fx_add #(.W(W)) u_vxd (.sub(1'b1), .a(vx), .b(dvx), .y(vx_d), .sat());
            fx_add #(.W(W)) u_vyd (.sub(1'b1), .a(vy), .b(dvy), .y(vy_d), .sat());
        end else begin : g_no_damping
            assign vx_d = vx;
            assign vy_d = vy;
            wire unused_damping = &{1'b0, damping};
        end
    endgenerate

    fx_add #(.W(W)) u_x1 (.sub(1'b0), .a(q_x), .b(vx_d), .y(x1), .sat());
    fx_add #(.W(W)) u_y1 (.sub(1'b0), .a(q_y), .b(vy_d), .y(y1), .sat());

    generate
        if (EN_GRAVITY) begin : g_gravity
            fx_add #(.W(W)) u_gx (.sub(1'b0), .a(x1), .b(gdt2_x), .y(gx), .sat());
            fx_add #(.W(W)) u_gy (.sub(1'b0), .a(y1), .b(gdt2_y), .y(gy), .sat());
        end else begin : g_no_gravity
            assign gx = x1;
            assign gy = y1;
            wire unused_gravity = &{1'b0, gdt2_x, gdt2_y};
        end
    endgenerate

    // ---- the spring force of this substep (a pass of spring edges gathered it) ----
    // The Verlet pass consumes each node's force and clears it (pinned nodes too), so
    // the next spring pass starts from 0, as model/engine_body.h force_pass() does.
    generate
        if (EN_SPRINGS) begin : g_springs
            reg [W-1:0] ax_mem [0:K-1];
            reg [W-1:0] ay_mem [0:K-1];
            reg [W-1:0] q_ax, q_ay;
            always @(posedge clk)
                if ({1'b0, a_addr} < K_COUNT) begin
                    q_ax <= ax_mem[a_addr];
                    q_ay <= ay_mem[a_addr];
                end
            integer j;
            always @(posedge clk) begin
                if (reset) begin
                    for (j = 0; j < K; j = j + 1) begin
                        ax_mem[j] <= {W{1'b0}};
                        ay_mem[j] <= {W{1'b0}};
                    end
                end else if (running_q && !ground_q && {1'b0, vidx_q} < K_COUNT) begin
                    ax_mem[vidx_q] <= {W{1'b0}};
                    ay_mem[vidx_q] <= {W{1'b0}};
                end else if (acc_we && {1'b0, w_idx} < K_COUNT) begin
                    ax_mem[w_idx] <= acc_wx;
                    ay_mem[w_idx] <= acc_wy;
                end
            end
            assign a_accx = q_ax;
            assign a_accy = q_ay;
            fx_add #(.W(W)) u_fx (.sub(1'b0), .a(gx), .b(q_ax), .y(nx), .sat());
            fx_add #(.W(W)) u_fy (.sub(1'b0), .a(gy), .b(q_ay), .y(ny), .sat());
        end else begin : g_no_springs
            assign nx = gx;
            assign ny = gy;
            assign a_accx = {W{1'b0}};
            assign a_accy = {W{1'b0}};
            wire unused_springs = &{1'b0, acc_we, acc_wx, acc_wy};
        end
    endgenerate

    // ---- the mouse impulse, after the Verlet step (px is now the old x) ----
    wire [W-1:0] npx;
    wire         touch_z;  // |mouse.z - z| < box.z (DIM = 3; else 1): from g_lane_z
    generate
        if (EN_MOUSE && !GRAB) begin : g_mouse
            wire [W-1:0] ddx, ddy, ndx, ndy, px_plus, px_minus;
            fx_add #(.W(W)) u_ddx (.sub(1'b1), .a(mouse_x), .b(nx), .y(ddx), .sat());
            fx_add #(.W(W)) u_ddy (.sub(1'b1), .a(mouse_y), .b(ny), .y(ddy), .sat());
            // |d| saturates: |min| is max, as fx_neg
            fx_add #(.W(W)) u_ndx (.sub(1'b1), .a({W{1'b0}}), .b(ddx), .y(ndx), .sat());
            fx_add #(.W(W)) u_ndy (.sub(1'b1), .a({W{1'b0}}), .b(ddy), .y(ndy), .sat());
            wire [W-1:0] adx = ddx[W-1] ? ndx : ddx;
            wire [W-1:0] ady = ddy[W-1] ? ndy : ddy;
            wire in_touch = mouse_down && ($signed(adx) < $signed(box_x)) && ($signed(ady) < $signed(box_y)) && touch_z;
            fx_add #(.W(W)) u_pp (.sub(1'b0), .a(nx), .b(impulse), .y(px_plus), .sat());
            fx_add #(.W(W)) u_pm (.sub(1'b1), .a(nx), .b(impulse), .y(px_minus), .sat());
            assign npx = !in_touch ? q_x : ($signed(mouse_x) < $signed(q_x)) ? px_plus : px_minus;
        end else begin : g_no_mouse
            assign npx = q_x;
            wire unused_mouse = &{1'b0, impulse, box_x, box_y, mouse_down, touch_z};  // the pointer: GRAB's
        end
    endgenerate

    // ---- the ground pass: collision with friction ----
    // The z lane (DIM = 3) lives in g_lane_z below; these are its port-A data and velocity.
    wire [W-1:0]  q_z, q_pz, vz;
    wire          unused_lane = &{1'b0, q_z, q_pz, vz};  // read only by some ground builds
    wire          g_hit;            // past the boundary
    wire [W-1:0]  g_x, g_y, g_z, g_px, g_py, g_pz;
    generate
        if (EN_GROUND) begin : g_ground
            wire [W-1:0] n  = GROUND_AXIS == 0 ? q_x : GROUND_AXIS == 1 ? q_y : q_z;  // on the normal axis
            wire [W-1:0] vn = GROUND_AXIS == 0 ? vx : GROUND_AXIS == 1 ? vy : vz;     // n - pn
            wire [W-1:0] npn, fpx, fpy, fpz;
            assign g_hit = GROUND_ABOVE ? $signed(n) < $signed(ground) : $signed(ground) < $signed(n);
            fx_add #(.W(W)) u_npn (.sub(1'b0), .a(ground), .b(vn), .y(npn), .sat());
            // friction on every other axis: po = po + (o - po) * friction
            if (GROUND_AXIS != 0) begin : g_fx
                wire [W-1:0] slip;
                fx_mul #(.W(W), .F(F)) u_slip (.a(vx), .b(friction), .y(slip), .sat(), .prod());
                fx_add #(.W(W)) u_fp (.sub(1'b0), .a(q_px), .b(slip), .y(fpx), .sat());
            end else begin : g_fx_n
                assign fpx = npn;
            end
            if (GROUND_AXIS != 1) begin : g_fy
                wire [W-1:0] slip;
                fx_mul #(.W(W), .F(F)) u_slip (.a(vy), .b(friction), .y(slip), .sat(), .prod());
                fx_add #(.W(W)) u_fp (.sub(1'b0), .a(q_py), .b(slip), .y(fpy), .sat());
            end else begin : g_fy_n
                assign fpy = npn;
            end
            if (DIM == 3 && GROUND_AXIS != 2) begin : g_fz
                wire [W-1:0] slip;
                fx_mul #(.W(W), .F(F)) u_slip (.a(vz), .b(friction), .y(slip), .sat(), .prod());
                fx_add #(.W(W)) u_fp (.sub(1'b0), .a(q_pz), .b(slip), .y(fpz), .sat());
            end else begin : g_fz_n
                assign fpz = npn;
            end
            assign g_x  = GROUND_AXIS == 0 ? ground : q_x;
            assign g_y  = GROUND_AXIS == 1 ? ground : q_y;
            assign g_z  = GROUND_AXIS == 2 ? ground : q_z;
            assign g_px = fpx;
            assign g_py = fpy;
            assign g_pz = fpz;
        end else begin : g_no_ground
            assign g_hit = 1'b0;
            assign g_x = q_x;
            assign g_y = q_y;
            assign g_z = q_z;
            assign g_px = q_px;
            assign g_py = q_py;
            assign g_pz = q_pz;
            wire unused_ground = &{1'b0, ground, friction, ground_start};
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- writes: the pass, else port A's writer; pins ----
    // The grabbed node (GRAB): the Verlet pass puts it on the pointer, px = its old x;
    // the ground pass leaves it alone.
    wire          pass_we = running_q && !q_pin && (!ground_q || (g_hit && !q_grab));
    wire          we      = pass_we || w_en;
    wire [IW-1:0] widx    = running_q ? vidx_q : w_idx;
`ifdef STRAND_FAULTS
    // Test only (the harness's planted-fault check): with +fault_flip, bit 0 of x is
    // flipped in the fifth Verlet write of unit 0 after reset.
    reg fault_on;
    initial fault_on = $test$plusargs("fault_flip");
    reg [2:0] fault_writes;
    always @(posedge clk)
        if (reset) fault_writes <= 3'd0;
        else if (pass_we && fault_writes != 3'd7) fault_writes <= fault_writes + 1'b1;
    wire fault_flip = fault_on && UNIT_ID == 0 && pass_we && fault_writes == 3'd4;
    wire [W-1:0]  wx      = running_q ? (ground_q ? g_x : q_grab ? mouse_x : nx ^ {{(W-1){1'b0}}, fault_flip}) : w_x;
`else
    wire [W-1:0]  wx      = running_q ? (ground_q ? g_x : q_grab ? mouse_x : nx) : w_x;
`endif
    wire [W-1:0]  wy      = running_q ? (ground_q ? g_y : q_grab ? mouse_y : ny) : w_y;
    wire          w_pin   = {1'b0, w_idx} < K_COUNT && pinned_q[w_idx];  // a pinned node starts at rest
    wire [W-1:0]  wpx     = running_q ? (ground_q ? g_px : q_grab ? q_x : npx) : w_pin ? w_x : w_px;
    wire [W-1:0]  wpy     = running_q ? (ground_q ? g_py : q_y) : w_pin ? w_y : w_py;
    wire          wprev   = running_q || w_at_rest;

    integer i;
    always @(posedge clk) begin
        if (reset) begin
            for (i = 0; i < K; i = i + 1) begin
                x_mem[i]  <= {W{1'b0}};
                y_mem[i]  <= {W{1'b0}};
                px_mem[i] <= {W{1'b0}};
                py_mem[i] <= {W{1'b0}};
            end
        end else if (we && {1'b0, widx} < K_COUNT) begin
            x_mem[widx] <= wx;
            y_mem[widx] <= wy;
            if (wprev) begin
                px_mem[widx] <= wpx;
                py_mem[widx] <= wpy;
            end
        end
    end

    always @(posedge clk) begin
        if (reset) pinned_q <= {K{1'b0}};
        else if (pin_en && {1'b0, pin_idx} < K_COUNT) pinned_q[pin_idx] <= 1'b1;
    end

    // ---- port B and the write-back lane ----
    always @(posedge clk) begin
        if (reset) begin
            b_x      <= {W{1'b0}};
            b_y      <= {W{1'b0}};
            wb_valid <= 1'b0;
            wb_idx   <= {IW{1'b0}};
            wb_x     <= {W{1'b0}};
            wb_y     <= {W{1'b0}};
        end else begin
            // an index past the last node reads as 0, never as X
            b_x <= {1'b0, b_idx} < K_COUNT ? x_mem[b_idx] : {W{1'b0}};
            b_y <= {1'b0, b_idx} < K_COUNT ? y_mem[b_idx] : {W{1'b0}};
            // the lane changes only when a node is written
            wb_valid <= we && {1'b0, widx} < K_COUNT;
            if (we && {1'b0, widx} < K_COUNT) begin
                wb_idx <= widx;
                wb_x   <= wx;
                wb_y   <= wy;
            end
        end
    end

    // ---- the z lane (DIM = 3): storage, the Verlet step, the mouse's z test ----
    // The same operations as x and y, in the same order (model/engine_body.h loops
    // over the axes); the mouse impulse itself acts on x only (reference 000).
    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags are not needed: the saturated value is the result
    generate
        if (DIM == 3) begin : g_lane_z
            reg [W-1:0] z_mem  [0:K-1];
            reg [W-1:0] pz_mem [0:K-1];
            reg [W-1:0] qz, qpz, bz, wbz;
            always @(posedge clk)
                if ({1'b0, a_addr} < K_COUNT) begin
                    qz  <= z_mem[a_addr];
                    qpz <= pz_mem[a_addr];
                end
            assign q_z  = qz;
            assign q_pz = qpz;
            assign a_z  = qz;
            assign a_pz = qpz;

            wire [W-1:0] vz_d, z1, gz, nz, qaz;
            fx_add #(.W(W)) u_vz (.sub(1'b1), .a(qz), .b(qpz), .y(vz), .sat());
            if (EN_DAMPING) begin : g_damping_z
                wire [W-1:0] dvz;
                fx_mul #(.W(W), .F(F)) u_dvz (.a(vz), .b(damping), .y(dvz), .sat(), .prod());
                fx_add #(.W(W)) u_vzd (.sub(1'b1), .a(vz), .b(dvz), .y(vz_d), .sat());
            end else begin : g_no_damping_z
                assign vz_d = vz;
            end
            fx_add #(.W(W)) u_z1 (.sub(1'b0), .a(qz), .b(vz_d), .y(z1), .sat());
            if (EN_GRAVITY) begin : g_gravity_z
                fx_add #(.W(W)) u_gz (.sub(1'b0), .a(z1), .b(gdt2_z), .y(gz), .sat());
            end else begin : g_no_gravity_z
                assign gz = z1;
                wire unused_gravity_z = &{1'b0, gdt2_z};
            end
            if (EN_SPRINGS) begin : g_springs_z
                reg [W-1:0] az_mem [0:K-1];
                reg [W-1:0] q_az;
                always @(posedge clk)
                    if ({1'b0, a_addr} < K_COUNT) q_az <= az_mem[a_addr];
                integer j;
                always @(posedge clk) begin
                    if (reset) begin
                        for (j = 0; j < K; j = j + 1) az_mem[j] <= {W{1'b0}};
                    end else if (running_q && !ground_q && {1'b0, vidx_q} < K_COUNT) begin
                        az_mem[vidx_q] <= {W{1'b0}};
                    end else if (acc_we && {1'b0, w_idx} < K_COUNT) begin
                        az_mem[w_idx] <= acc_wz;
                    end
                end
                assign qaz = q_az;
                fx_add #(.W(W)) u_fz (.sub(1'b0), .a(gz), .b(q_az), .y(nz), .sat());
            end else begin : g_no_springs_z
                assign qaz = {W{1'b0}};
                assign nz = gz;
                wire unused_springs_z = &{1'b0, acc_wz};
            end
            assign a_accz = qaz;
            if (EN_MOUSE && !GRAB) begin : g_mouse_z
                wire [W-1:0] ddz, ndz;
                fx_add #(.W(W)) u_ddz (.sub(1'b1), .a(mouse_z), .b(nz), .y(ddz), .sat());
                fx_add #(.W(W)) u_ndz (.sub(1'b1), .a({W{1'b0}}), .b(ddz), .y(ndz), .sat());
                wire [W-1:0] adz = ddz[W-1] ? ndz : ddz;
                assign touch_z = $signed(adz) < $signed(box_z);
            end else begin : g_no_mouse_z
                assign touch_z = 1'b1;
                wire unused_mouse_z = &{1'b0, box_z};
            end

            wire [W-1:0] wz  = running_q ? (ground_q ? g_z : q_grab ? mouse_z : nz) : w_z;
            wire [W-1:0] wpz = running_q ? (ground_q ? g_pz : qz) : w_pin ? w_z : w_pz;
            integer i3;
            always @(posedge clk) begin
                if (reset) begin
                    for (i3 = 0; i3 < K; i3 = i3 + 1) begin
                        z_mem[i3]  <= {W{1'b0}};
                        pz_mem[i3] <= {W{1'b0}};
                    end
                end else if (we && {1'b0, widx} < K_COUNT) begin
                    z_mem[widx] <= wz;
                    if (wprev) pz_mem[widx] <= wpz;
                end
            end
            always @(posedge clk) begin
                if (reset) begin
                    bz  <= {W{1'b0}};
                    wbz <= {W{1'b0}};
                end else begin
                    bz <= {1'b0, b_idx} < K_COUNT ? z_mem[b_idx] : {W{1'b0}};
                    if (we && {1'b0, widx} < K_COUNT) wbz <= wz;
                end
            end
            assign b_z  = bz;
            assign wb_z = wbz;
        end else begin : g_no_lane_z
            assign q_z = {W{1'b0}};
            assign q_pz = {W{1'b0}};
            assign vz = {W{1'b0}};
            assign a_z = {W{1'b0}};
            assign a_pz = {W{1'b0}};
            assign a_accz = {W{1'b0}};
            assign b_z = {W{1'b0}};
            assign wb_z = {W{1'b0}};
            assign touch_z = 1'b1;
            wire unused_z = &{1'b0, gdt2_z, box_z, mouse_z, acc_wz, w_z, w_pz, g_z, g_pz};
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

endmodule

`resetall
