`default_nettype none
`timescale 1ns / 1ps

`include "strand_regs.vh"

/*
 * strand_top - the reference-000 rope engine: M node units of K nodes and a
 * constraint sequencer (design.md section 4).
 *
 * A frame (on `step`, when idle): the mouse is sampled; then SUBSTEPS times: with
 * EN_SPRINGS, a spring pass (pair_sequencer, SPRING) gathers every link's force on
 * its ends (phase FORCE); every
 * unit runs its Verlet (+ mouse) pass over its K nodes at once, FV rising when all
 * are done; then the sequencer runs ITER constraint passes over the chain, centred
 * (chain_sequencer, over every node) or pairwise (pair_sequencer, over every link),
 * FEC rising as each pass ends. frame_done pulses for one cycle at the end.
 *
 * Nodes are addressed as {unit, node} (UW + IW bits); that is the format of rd_addr,
 * of a PIN write's data, and, per unit lane, of the write-back bus.
 *
 * Registers (cfg_we/cfg_addr/cfg_data; addresses in the generated strand_regs.vh)
 * reset to 0. After reset: write the constants and pins, then CMD = 1 lays the
 * nodes out (phase INIT, N cycles), then pulse step once per frame.
 *
 * With EN_GROUND, a ground pass ends each substep (phase GROUND; the units walk
 * their nodes as in the Verlet pass, FV rising when all are done).
 *
 * With EN_MOUSE and GRAB, a frame starts with a GRAB phase: the nodes are scanned in
 * order ({unit, node}, N + 1 cycles) for the one nearest the pointer inside the box
 * (model/engine_body.h grab_update()); the held node follows the pointer until the
 * button is released.
 *
 * Phases: 0 IDLE, 1 INIT, 2 VERLET, 3 CONSTRAIN, 4 FORCE, 5 GROUND, 6 GRAB. Every phase takes a number of
 * cycles fixed by the parameters (docs/architecture.md gives the formula).
 */
module strand_top #(
    parameter integer W              = 32,    // word width, bits (8..32)
    parameter integer F              = 16,    // fraction bits (1..W-2)
    parameter integer M              = 4,     // node units
    parameter integer K              = 5,     // nodes per unit
    parameter integer SQRT_BITS      = W - 1, // square-root bits resolved (1..W-1)
    parameter integer DIV_BITS       = W - 1, // quotient bits resolved (1..W-1)
    parameter integer ITER           = 1,     // constraint passes per substep
    parameter integer SUBSTEPS       = 1,     // substeps per frame
    parameter [0:0]   EN_GRAVITY     = 1'b1,  // add g h^2
    parameter [0:0]   EN_DAMPING     = 1'b0,  // Verlet damping
    parameter [0:0]   EN_MOUSE       = 1'b1,  // the mouse: the reference-000 impulse, or (GRAB) the grab form
    parameter [0:0]   GRAB           = 1'b0,  // with EN_MOUSE: the nearest node in the box follows the pointer
    parameter [0:0]   EN_CONSTRAINTS = 1'b1,  // distance constraints between neighbours
    parameter integer RULE           = 0,     // their rule: 0 centred (reference 000), 1 pairwise (002)
    parameter [0:0]   EN_SPRINGS     = 1'b0,  // damped springs on the links (references 001, 004)
    parameter [0:0]   EN_GROUND      = 1'b0,  // ground collision with friction (reference 001)
    parameter integer GROUND_AXIS    = 1,     // its normal axis: 0 x, 1 y, 2 z
    parameter [0:0]   GROUND_ABOVE   = 1'b1,  // 1: nodes stay at or above the boundary, 0: at or below
    parameter integer DIM            = 2,     // 2, or 3: a z lane everywhere
    parameter [0:0]   GRAPH          = 1'b0,  // 0: a chain (implied links), 1: a graph (edge memories)
    parameter integer E_RODS         = 1,     // GRAPH: rods and struts in the constraint memory
    parameter integer E_SPRINGS      = 1,     // GRAPH: springs in the spring memory
    // derived widths (leave at their defaults)
    parameter integer UW             = M > 1 ? $clog2(M) : 1,         // unit index
    parameter integer IW             = K > 1 ? $clog2(K) : 1,         // node index within a unit
    parameter integer CW             = $clog2((M * K > E_RODS ? (M * K > E_SPRINGS ? M * K : E_SPRINGS)
                                                  : (E_RODS > E_SPRINGS ? E_RODS : E_SPRINGS)) + 1), // node / edge counter
    parameter integer SW             = SUBSTEPS > 1 ? $clog2(SUBSTEPS) : 1
) (
    input  wire            clk,
    input  wire            reset,       // synchronous, active high

    input  wire [W-1:0]    mouse_x,     // sampled when a frame starts
    input  wire [W-1:0]    mouse_y,
    input  wire [W-1:0]    mouse_z,     // DIM = 3
    input  wire            mouse_down,

    input  wire            step,        // start a frame (when phase is IDLE)
    output reg             frame_done,  // one-cycle pulse: the frame is finished

    input  wire            cfg_we,      // register write port
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]    cfg_data,

    input  wire [UW+IW-1:0] rd_addr,    // position read port: {unit, node} in,
    output wire [W-1:0]    rd_x,        // its position the next cycle
    output wire [W-1:0]    rd_y,
    output wire [W-1:0]    rd_z,        // DIM = 3; else 0

    output reg  [2:0]      phase,       // 0 idle, 1 init, 2 verlet, 3 constrain, 4 force, 5 ground, 6 grab
    output wire            fv,          // every unit finished its Verlet (or ground) pass
    output wire            fec,         // the constraint pass finished (counter = M x K)
    output wire [UW-1:0]   uidx,        // the sequencer's C (pairwise and springs: a): unit
    output wire [IW-1:0]   nidx,        //                    node
    output wire [CW-1:0]   counter,     // nodes (links) finished in this pass; phase FORCE: the spring pass's

    output wire [M-1:0]    wb_valid,    // per unit: a node of this unit was written
    output wire [M*IW-1:0] wb_idx,      //   its index in the unit
    output wire [M*W-1:0]  wb_x,        //   its new position
    output wire [M*W-1:0]  wb_y,
    output wire [M*W-1:0]  wb_z         // DIM = 3; else 0
);

    localparam integer N = M * K;

    // Bad parameters stop elaboration: $error for Yosys (0.23 has no $fatal),
    // $fatal for the simulators (Icarus carries on after $error).
    initial begin
        if (W < 8 || W > 32) begin
`ifdef SYNTHESIS
            $error("strand_top: W must be 8..32 (W=%0d) in %m", W);
`else
            $fatal(1, "strand_top: W must be 8..32 (W=%0d) in %m", W);
`endif
        end
        if (F < 1 || F > W - 2) begin
`ifdef SYNTHESIS
            $error("strand_top: F must be 1..W-2 (F=%0d) in %m", F);
`else
            $fatal(1, "strand_top: F must be 1..W-2 (F=%0d) in %m", F);
`endif
        end
        if (M < 1 || K < 1) begin
`ifdef SYNTHESIS
            $error("strand_top: M and K must be >= 1 (M=%0d K=%0d) in %m", M, K);
`else
            $fatal(1, "strand_top: M and K must be >= 1 (M=%0d K=%0d) in %m", M, K);
`endif
        end
        if (SQRT_BITS < 1 || SQRT_BITS > W - 1) begin
`ifdef SYNTHESIS
            $error("strand_top: SQRT_BITS must be 1..W-1 in %m");
`else
            $fatal(1, "strand_top: SQRT_BITS must be 1..W-1 in %m");
`endif
        end
        if (DIV_BITS < 1 || DIV_BITS > W - 1) begin
`ifdef SYNTHESIS
            $error("strand_top: DIV_BITS must be 1..W-1 in %m");
`else
            $fatal(1, "strand_top: DIV_BITS must be 1..W-1 in %m");
`endif
        end
        if (ITER < 1 || SUBSTEPS < 1) begin
`ifdef SYNTHESIS
            $error("strand_top: ITER and SUBSTEPS must be >= 1 in %m");
`else
            $fatal(1, "strand_top: ITER and SUBSTEPS must be >= 1 in %m");
`endif
        end
        if (RULE != 0 && RULE != 1) begin
`ifdef SYNTHESIS
            $error("strand_top: RULE must be 0 (centred) or 1 (pairwise) in %m");
`else
            $fatal(1, "strand_top: RULE must be 0 (centred) or 1 (pairwise) in %m");
`endif
        end
        if (GROUND_AXIS < 0 || GROUND_AXIS >= DIM || (DIM != 2 && DIM != 3)) begin
`ifdef SYNTHESIS
            $error("strand_top: DIM must be 2 or 3 and GROUND_AXIS an axis of it (DIM=%0d GROUND_AXIS=%0d) in %m", DIM, GROUND_AXIS);
`else
            $fatal(1, "strand_top: DIM must be 2 or 3 and GROUND_AXIS an axis of it (DIM=%0d GROUND_AXIS=%0d) in %m", DIM, GROUND_AXIS);
`endif
        end
        if (GRAPH && (E_RODS < 1 || E_SPRINGS < 1 || 2 * (UW + IW) + 1 > W || (EN_CONSTRAINTS && RULE != 1))) begin
`ifdef SYNTHESIS
            $error("strand_top: a graph needs E_RODS, E_SPRINGS >= 1, the pairwise rule, and an EDGE word {spring, b, a} within W in %m");
`else
            $fatal(1, "strand_top: a graph needs E_RODS, E_SPRINGS >= 1, the pairwise rule, and an EDGE word {spring, b, a} within W in %m");
`endif
        end
        if (UW + IW > W) begin
`ifdef SYNTHESIS
            $error("strand_top: a {unit, node} address (%0d bits) must fit W=%0d in %m", UW + IW, W);
`else
            $fatal(1, "strand_top: a {unit, node} address (%0d bits) must fit W=%0d in %m", UW + IW, W);
`endif
        end
    end

    localparam [2:0] PH_IDLE = 3'd0, PH_INIT = 3'd1, PH_VERLET = 3'd2, PH_CONSTRAIN = 3'd3, PH_FORCE = 3'd4,
                     PH_GROUND = 3'd5, PH_GRAB = 3'd6;
    localparam [0:0] HAS_GRAB = EN_MOUSE && GRAB;

    localparam integer K_LAST_I = K - 1;
    localparam integer N_LAST_I = N - 1;
    localparam integer SUB_LAST_I = SUBSTEPS - 1;
    localparam [IW-1:0] K_LAST   = K_LAST_I[IW-1:0];
    localparam [CW-1:0] N_LAST   = N_LAST_I[CW-1:0];
    localparam [CW-1:0] N_COUNT  = N[CW-1:0];
    localparam [SW-1:0] SUB_LAST = SUB_LAST_I[SW-1:0];
    localparam [UW:0]   M_COUNT  = M[UW:0];

    // ---- run-time registers ----
    reg [W-1:0] gdt2_x, gdt2_y, rest_len, impulse, box_x, box_y, damping;
    reg [W-1:0] start_x, start_y, step_x, step_y, ks, kd, ground, friction, prev_x, prev_y;
    reg [W-1:0] gdt2_z, box_z, start_z, step_z, prev_z;                   // DIM = 3
    reg [W-1:0] load_x, load_y, load_z, load_px, load_py, load_pz, edge_rest;

    wire cmd_init = cfg_we && cfg_addr == `STRAND_REG_CMD && cfg_data[0];
    wire pin_we   = cfg_we && cfg_addr == `STRAND_REG_PIN;
    wire node_we  = cfg_we && cfg_addr == `STRAND_REG_NODE && phase == PH_IDLE;  // only when idle
    wire edge_we  = cfg_we && cfg_addr == `STRAND_REG_EDGE;
    localparam integer AW = UW + IW;
    wire [AW-1:0] edge_a = cfg_data[AW-1:0];
    wire [AW-1:0] edge_b = cfg_data[2*AW-1:AW];
    wire          edge_spring = cfg_data[(2*AW < W ? 2*AW : W-1)];

    always @(posedge clk) begin
        if (reset) begin
            gdt2_x <= {W{1'b0}}; gdt2_y <= {W{1'b0}}; rest_len <= {W{1'b0}}; impulse <= {W{1'b0}};
            box_x <= {W{1'b0}}; box_y <= {W{1'b0}}; damping <= {W{1'b0}};
            start_x <= {W{1'b0}}; start_y <= {W{1'b0}}; step_x <= {W{1'b0}}; step_y <= {W{1'b0}};
            ks <= {W{1'b0}}; kd <= {W{1'b0}}; ground <= {W{1'b0}}; friction <= {W{1'b0}};
            prev_x <= {W{1'b0}}; prev_y <= {W{1'b0}};
            gdt2_z <= {W{1'b0}}; box_z <= {W{1'b0}}; start_z <= {W{1'b0}}; step_z <= {W{1'b0}}; prev_z <= {W{1'b0}};
            load_x <= {W{1'b0}}; load_y <= {W{1'b0}}; load_z <= {W{1'b0}};
            load_px <= {W{1'b0}}; load_py <= {W{1'b0}}; load_pz <= {W{1'b0}}; edge_rest <= {W{1'b0}};
        end else if (cfg_we) begin
            case (cfg_addr)
                `STRAND_REG_GDT2_X:  gdt2_x   <= cfg_data;
                `STRAND_REG_GDT2_Y:  gdt2_y   <= cfg_data;
                `STRAND_REG_DIST:    rest_len <= cfg_data;
                `STRAND_REG_IMPULSE: impulse  <= cfg_data;
                `STRAND_REG_BOX_X:   box_x    <= cfg_data;
                `STRAND_REG_BOX_Y:   box_y    <= cfg_data;
                `STRAND_REG_DAMPING: damping  <= cfg_data;
                `STRAND_REG_START_X: start_x  <= cfg_data;
                `STRAND_REG_START_Y: start_y  <= cfg_data;
                `STRAND_REG_STEP_X:  step_x   <= cfg_data;
                `STRAND_REG_STEP_Y:  step_y   <= cfg_data;
                `STRAND_REG_KS:      ks       <= cfg_data;
                `STRAND_REG_KD:      kd       <= cfg_data;
                `STRAND_REG_GROUND:  ground   <= cfg_data;
                `STRAND_REG_FRICTION: friction <= cfg_data;
                `STRAND_REG_PREV_X:  prev_x   <= cfg_data;
                `STRAND_REG_PREV_Y:  prev_y   <= cfg_data;
                `STRAND_REG_GDT2_Z:  gdt2_z   <= cfg_data;
                `STRAND_REG_BOX_Z:   box_z    <= cfg_data;
                `STRAND_REG_START_Z: start_z  <= cfg_data;
                `STRAND_REG_STEP_Z:  step_z   <= cfg_data;
                `STRAND_REG_PREV_Z:  prev_z   <= cfg_data;
                `STRAND_REG_LOAD_X:  load_x   <= cfg_data;
                `STRAND_REG_LOAD_Y:  load_y   <= cfg_data;
                `STRAND_REG_LOAD_Z:  load_z   <= cfg_data;
                `STRAND_REG_LOAD_PX: load_px  <= cfg_data;
                `STRAND_REG_LOAD_PY: load_py  <= cfg_data;
                `STRAND_REG_LOAD_PZ: load_pz  <= cfg_data;
                `STRAND_REG_EDGE_REST: edge_rest <= cfg_data;
                default: ;
            endcase
        end
    end

    // ---- the frame FSM ----
    reg  [SW-1:0] substep_q;
    reg  [W-1:0]  mouse_x_q, mouse_y_q, mouse_z_q;
    reg           mouse_down_q;
    reg  [UW-1:0] init_u;      // the init walk: node being laid out
    reg  [IW-1:0] init_n;
    reg  [CW-1:0] init_count;
    reg  [W-1:0]  init_x, init_y, init_z;
    wire [W-1:0]  init_x_next, init_y_next, init_px, init_py, init_z_next, init_pz;
    wire          seq_done, force_done;
    wire          fec_seq;

    // A substep: [FORCE] VERLET [CONSTRAIN] [GROUND]; each phase starts in the cycle the one before ends.
    wire frame_start   = phase == PH_IDLE && !cmd_init && step;
    wire verlet_end    = phase == PH_VERLET && fv;
    wire body_end      = EN_CONSTRAINTS ? phase == PH_CONSTRAIN && seq_done : verlet_end;
    wire ground_start  = body_end && EN_GROUND;
    wire substep_end   = EN_GROUND ? phase == PH_GROUND && fv : body_end;
    wire scan_end;  // GRAB: the scan for the node to hold is over
    wire substep_start = (HAS_GRAB ? scan_end : frame_start) || (substep_end && substep_q != SUB_LAST);
    wire force_start   = substep_start && EN_SPRINGS;
    wire verlet_start  = (substep_start && !EN_SPRINGS) || (phase == PH_FORCE && force_done);
    wire seq_start     = verlet_end && EN_CONSTRAINTS;
    wire init_last     = init_count == N_LAST;

    /* verilator lint_off PINCONNECTEMPTY */
    // saturation flags are not needed: the saturated value is the result
    fx_add #(.W(W)) u_init_x (.sub(1'b0), .a(init_x), .b(step_x), .y(init_x_next), .sat());
    fx_add #(.W(W)) u_init_y (.sub(1'b0), .a(init_y), .b(step_y), .y(init_y_next), .sat());
    fx_add #(.W(W)) u_init_px (.sub(1'b0), .a(init_x), .b(prev_x), .y(init_px), .sat());
    fx_add #(.W(W)) u_init_py (.sub(1'b0), .a(init_y), .b(prev_y), .y(init_py), .sat());
    fx_add #(.W(W)) u_init_z  (.sub(1'b0), .a(init_z), .b(step_z), .y(init_z_next), .sat());
    fx_add #(.W(W)) u_init_pz (.sub(1'b0), .a(init_z), .b(prev_z), .y(init_pz), .sat());
    /* verilator lint_on PINCONNECTEMPTY */

    always @(posedge clk) begin
        frame_done <= 1'b0;
        if (reset) begin
            phase        <= PH_IDLE;
            substep_q    <= {SW{1'b0}};
            mouse_x_q    <= {W{1'b0}};
            mouse_y_q    <= {W{1'b0}};
            mouse_z_q    <= {W{1'b0}};
            mouse_down_q <= 1'b0;
            init_u       <= {UW{1'b0}};
            init_n       <= {IW{1'b0}};
            init_count   <= {CW{1'b0}};
            init_x       <= {W{1'b0}};
            init_y       <= {W{1'b0}};
            init_z       <= {W{1'b0}};
            frame_done   <= 1'b0;
        end else begin
            case (phase)
                PH_IDLE: begin
                    if (cmd_init) begin
                        phase      <= PH_INIT;
                        init_u     <= {UW{1'b0}};
                        init_n     <= {IW{1'b0}};
                        init_count <= {CW{1'b0}};
                        init_x     <= start_x;
                        init_y     <= start_y;
                        init_z     <= DIM == 3 ? start_z : {W{1'b0}};
                    end else if (step) begin
                        phase        <= HAS_GRAB ? PH_GRAB : EN_SPRINGS ? PH_FORCE : PH_VERLET;
                        substep_q    <= {SW{1'b0}};
                        mouse_x_q    <= mouse_x;
                        mouse_y_q    <= mouse_y;
                        mouse_z_q    <= DIM == 3 ? mouse_z : {W{1'b0}};
                        mouse_down_q <= mouse_down;
                    end
                end
                PH_INIT: begin
                    init_x     <= init_x_next;
                    init_y     <= init_y_next;
                    init_z     <= init_z_next;
                    init_count <= init_count + 1'b1;
                    if (init_n == K_LAST) begin
                        init_n <= {IW{1'b0}};
                        init_u <= init_u + 1'b1;
                    end else begin
                        init_n <= init_n + 1'b1;
                    end
                    if (init_last) phase <= PH_IDLE;
                end
                PH_FORCE:     if (force_done) phase <= PH_VERLET;
                PH_GRAB:      if (scan_end) phase <= EN_SPRINGS ? PH_FORCE : PH_VERLET;
                PH_VERLET:    if (seq_start) phase <= PH_CONSTRAIN;
                default:      ;
            endcase
            if (ground_start) phase <= PH_GROUND;
            if (substep_end) begin
                if (substep_q == SUB_LAST) begin
                    phase      <= PH_IDLE;
                    frame_done <= 1'b1;
                end else begin
                    phase     <= EN_SPRINGS ? PH_FORCE : PH_VERLET;
                    substep_q <= substep_q + 1'b1;
                end
            end
        end
    end

    // ---- the sequencers ----
    // The constraint sequencer (c_*) and the spring pass (f_*) share port A of the
    // units and their write port; they never run at once.
    wire [UW-1:0] c_rd_u, c_wr_u, c_uidx;
    wire [IW-1:0] c_rd_n, c_wr_n, c_nidx;
    wire [CW-1:0] c_counter;
    wire          c_wr_en;
    wire [W-1:0]  c_wr_x, c_wr_y, c_wr_z;
    wire [UW-1:0] f_rd_u, f_wr_u, f_uidx;
    wire [IW-1:0] f_rd_n, f_wr_n, f_nidx;
    wire [CW-1:0] f_counter;
    wire          f_wr_en;
    wire [W-1:0]  f_wr_x, f_wr_y, f_wr_z;
    wire          in_force = phase == PH_FORCE;
    wire [UW-1:0] scan_u;    // GRAB: the node the scan reads
    wire [IW-1:0] scan_n;
    wire          in_scan  = HAS_GRAB && phase == PH_GRAB;
    wire [UW-1:0] seq_rd_u = in_scan ? scan_u : in_force ? f_rd_u : c_rd_u;
    wire [IW-1:0] seq_rd_n = in_scan ? scan_n : in_force ? f_rd_n : c_rd_n;
    assign uidx    = in_force ? f_uidx : c_uidx;
    assign nidx    = in_force ? f_nidx : c_nidx;
    assign counter = in_force ? f_counter : c_counter;

    wire [M*W-1:0] a_x_all, a_y_all, a_px_all, a_py_all, a_accx_all, a_accy_all, a_z_all, a_pz_all, a_accz_all;
    wire [M-1:0]  a_pin_all, done_all;
    reg  [UW-1:0] rd_sel_q;  // unit whose port-A data the sequencer sees
    // a unit index past the last unit reads as 0 (the sequencer ignores it: no D past the end)
    wire          sel_ok      = {1'b0, rd_sel_q} < M_COUNT;
    wire [W-1:0]  seq_rd_x    = sel_ok ? a_x_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_y    = sel_ok ? a_y_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_px   = sel_ok ? a_px_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_py   = sel_ok ? a_py_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_accx = sel_ok ? a_accx_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_accy = sel_ok ? a_accy_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire          seq_rd_pin  = sel_ok && a_pin_all[rd_sel_q];
    wire [W-1:0]  seq_rd_z    = sel_ok ? a_z_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_pz   = sel_ok ? a_pz_all[rd_sel_q * W +: W] : {W{1'b0}};
    wire [W-1:0]  seq_rd_accz = sel_ok ? a_accz_all[rd_sel_q * W +: W] : {W{1'b0}};

    always @(posedge clk) rd_sel_q <= seq_rd_u;
    wire unused_rd = &{1'b0, seq_rd_x, seq_rd_y, seq_rd_pin, seq_rd_z, seq_rd_pz, seq_rd_accz, edge_we, edge_a, edge_b,
                       edge_spring, edge_rest};  // a build with neither pass reads nothing

    /* verilator lint_off PINCONNECTEMPTY */
    // the pairwise pass's px/py/force inputs and the constants it does not use
    generate
        if (EN_CONSTRAINTS && RULE == 0) begin : g_constraints
            chain_sequencer #(.W(W), .F(F), .M(M), .K(K), .UW(UW), .IW(IW), .CW(CW), .ITER(ITER),
                              .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .DIM(DIM)) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done), .rest_len(rest_len),
                .rd_uidx(c_rd_u), .rd_nidx(c_rd_n), .rd_x(seq_rd_x), .rd_y(seq_rd_y), .rd_z(seq_rd_z),
                .rd_pinned(seq_rd_pin),
                .wr_en(c_wr_en), .wr_uidx(c_wr_u), .wr_nidx(c_wr_n), .wr_x(c_wr_x), .wr_y(c_wr_y), .wr_z(c_wr_z),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec_seq));
        end else if (EN_CONSTRAINTS) begin : g_pairwise
            pair_sequencer #(.W(W), .F(F), .M(M), .K(K), .UW(UW), .IW(IW), .CW(CW), .ITER(ITER),
                             .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .SPRING(1'b0), .DIM(DIM),
                             .GRAPH(GRAPH), .E(E_RODS)) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done), .rest_len(rest_len),
                .e_we(edge_we && !edge_spring), .e_a(edge_a), .e_b(edge_b), .e_rest(edge_rest),
                .ks({W{1'b0}}), .kd({W{1'b0}}),
                .rd_uidx(c_rd_u), .rd_nidx(c_rd_n), .rd_x(seq_rd_x), .rd_y(seq_rd_y), .rd_pinned(seq_rd_pin),
                .rd_px({W{1'b0}}), .rd_py({W{1'b0}}), .rd_accx({W{1'b0}}), .rd_accy({W{1'b0}}),
                .rd_z(seq_rd_z), .rd_pz({W{1'b0}}), .rd_accz({W{1'b0}}),
                .wr_en(c_wr_en), .wr_uidx(c_wr_u), .wr_nidx(c_wr_n), .wr_x(c_wr_x), .wr_y(c_wr_y), .wr_z(c_wr_z),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec_seq));
        end else begin : g_no_constraints
            assign seq_done = 1'b0;
            assign c_rd_u = {UW{1'b0}};
            assign c_rd_n = {IW{1'b0}};
            assign c_wr_en = 1'b0;
            assign c_wr_u = {UW{1'b0}};
            assign c_wr_n = {IW{1'b0}};
            assign c_wr_x = {W{1'b0}};
            assign c_wr_y = {W{1'b0}};
            assign c_wr_z = {W{1'b0}};
            assign c_uidx = {UW{1'b0}};
            assign c_nidx = {IW{1'b0}};
            assign c_counter = {CW{1'b0}};
            assign fec_seq = 1'b0;
            wire unused_seq = &{1'b0, rest_len};
        end

        if (EN_SPRINGS) begin : g_springs
            pair_sequencer #(.W(W), .F(F), .M(M), .K(K), .UW(UW), .IW(IW), .CW(CW), .ITER(1),
                             .SQRT_BITS(SQRT_BITS), .DIV_BITS(DIV_BITS), .SPRING(1'b1), .DIM(DIM),
                             .GRAPH(GRAPH), .E(E_SPRINGS)) u_force (
                .clk(clk), .reset(reset), .start(force_start), .done(force_done), .rest_len(rest_len),
                .e_we(edge_we && edge_spring), .e_a(edge_a), .e_b(edge_b), .e_rest(edge_rest),
                .ks(ks), .kd(kd),
                .rd_uidx(f_rd_u), .rd_nidx(f_rd_n), .rd_x(seq_rd_x), .rd_y(seq_rd_y), .rd_pinned(seq_rd_pin),
                .rd_px(seq_rd_px), .rd_py(seq_rd_py), .rd_accx(seq_rd_accx), .rd_accy(seq_rd_accy),
                .rd_z(seq_rd_z), .rd_pz(seq_rd_pz), .rd_accz(seq_rd_accz),
                .wr_en(f_wr_en), .wr_uidx(f_wr_u), .wr_nidx(f_wr_n), .wr_x(f_wr_x), .wr_y(f_wr_y), .wr_z(f_wr_z),
                .uidx(f_uidx), .nidx(f_nidx), .counter(f_counter), .fec());
        end else begin : g_no_springs
            assign force_done = 1'b0;
            assign f_rd_u = {UW{1'b0}};
            assign f_rd_n = {IW{1'b0}};
            assign f_wr_en = 1'b0;
            assign f_wr_u = {UW{1'b0}};
            assign f_wr_n = {IW{1'b0}};
            assign f_wr_x = {W{1'b0}};
            assign f_wr_y = {W{1'b0}};
            assign f_wr_z = {W{1'b0}};
            assign f_uidx = {UW{1'b0}};
            assign f_nidx = {IW{1'b0}};
            assign f_counter = {CW{1'b0}};
            wire unused_springs = &{1'b0, ks, kd, force_start, seq_rd_px, seq_rd_py, seq_rd_accx, seq_rd_accy};
            // (the z lane's port-A data is in unused_rd)
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */

    // ---- GRAB: the scan for the node to hold, and the held node ----
    // Cycle i of the phase (i = 0 .. N) addresses node i and judges node i - 1, whose
    // data port A returns now, as model/engine_body.h grab_update() does: inside the box
    // on every axis, not pinned, and nearer (L1, saturating sum) than the best so far.
    wire          grab_valid;  // a node is held
    wire [UW+IW-1:0] grab_a;   // its address
    generate
        if (HAS_GRAB) begin : g_grab
            reg [CW-1:0]    scan_i;        // nodes addressed so far
            reg [UW+IW-1:0] scan_a;        // node scan_i's address
            reg [UW+IW-1:0] data_a;        // the address whose data arrives (node scan_i - 1)
            reg             found, held;
            reg [W-1:0]     best;
            reg [UW+IW-1:0] cand, held_a;
            wire [W-1:0] ddx, ddy, ddz, ndx, ndy, ndz, ax, ay, az, dxy, l1_z, l1;
            /* verilator lint_off PINCONNECTEMPTY */
            // saturation flags are not needed: the saturated value is the result
            fx_add #(.W(W)) u_ddx (.sub(1'b1), .a(mouse_x_q), .b(seq_rd_x), .y(ddx), .sat());
            fx_add #(.W(W)) u_ddy (.sub(1'b1), .a(mouse_y_q), .b(seq_rd_y), .y(ddy), .sat());
            fx_add #(.W(W)) u_ddz (.sub(1'b1), .a(mouse_z_q), .b(seq_rd_z), .y(ddz), .sat());
            fx_add #(.W(W)) u_ndx (.sub(1'b1), .a({W{1'b0}}), .b(ddx), .y(ndx), .sat());  // |min| is max
            fx_add #(.W(W)) u_ndy (.sub(1'b1), .a({W{1'b0}}), .b(ddy), .y(ndy), .sat());
            fx_add #(.W(W)) u_ndz (.sub(1'b1), .a({W{1'b0}}), .b(ddz), .y(ndz), .sat());
            assign ax = ddx[W-1] ? ndx : ddx;
            assign ay = ddy[W-1] ? ndy : ddy;
            assign az = ddz[W-1] ? ndz : ddz;
            fx_add #(.W(W)) u_dxy (.sub(1'b0), .a(ax), .b(ay), .y(dxy), .sat());
            fx_add #(.W(W)) u_dz  (.sub(1'b0), .a(dxy), .b(az), .y(l1_z), .sat());
            /* verilator lint_on PINCONNECTEMPTY */
            assign l1 = DIM == 3 ? l1_z : dxy;  // the L1 distance
            wire touch = $signed(ax) < $signed(box_x) && $signed(ay) < $signed(box_y) &&
                         (DIM != 3 || $signed(az) < $signed(box_z));
            wire take = scan_i != {CW{1'b0}} && touch && !seq_rd_pin && (!found || $signed(l1) < $signed(best));
            wire             found_n = found || take;
            wire [UW+IW-1:0] cand_n  = take ? data_a : cand;
            wire [IW-1:0]    scan_n_i = scan_a[IW-1:0];
            // the held node after this cycle: the Verlet pass reads node 0 at the very edge
            // that ends the scan, so the units see the new value already in that cycle
            wire             held_n   = scan_end ? mouse_down_q && (held || found_n) : held;
            wire [UW+IW-1:0] held_a_n = scan_end && mouse_down_q && !held && found_n ? cand_n : held_a;
            assign scan_end = phase == PH_GRAB && scan_i == N_COUNT;
            assign scan_u   = scan_a[UW+IW-1:IW];
            assign scan_n   = scan_a[IW-1:0];
            always @(posedge clk) begin
                if (reset) begin
                    scan_i <= {CW{1'b0}};
                    scan_a <= {(UW+IW){1'b0}};
                    data_a <= {(UW+IW){1'b0}};
                    found  <= 1'b0;
                    best   <= {W{1'b0}};
                    cand   <= {(UW+IW){1'b0}};
                    held   <= 1'b0;
                    held_a <= {(UW+IW){1'b0}};
                end else if (frame_start) begin
                    scan_i <= {CW{1'b0}};
                    scan_a <= {(UW+IW){1'b0}};
                    found  <= 1'b0;
                end else if (phase == PH_GRAB) begin
                    data_a <= scan_a;
                    found  <= found_n;
                    cand   <= cand_n;
                    if (take) best <= l1;
                    // at the scan's end: the button up lets go; pressed with nothing held, the nearest is taken
                    held   <= held_n;
                    held_a <= held_a_n;
                    if (!scan_end) begin
                        scan_i <= scan_i + 1'b1;
                        scan_a <= scan_n_i == K_LAST ? {scan_a[UW+IW-1:IW] + 1'b1, {IW{1'b0}}} : scan_a + 1'b1;
                    end
                end
            end
            assign grab_valid = held_n;
            assign grab_a     = held_a_n;
        end else begin : g_no_grab
            assign scan_end   = 1'b0;
            assign scan_u     = {UW{1'b0}};
            assign scan_n     = {IW{1'b0}};
            assign grab_valid = 1'b0;
            assign grab_a     = {(UW+IW){1'b0}};
        end
    endgenerate

    // ---- the units ----
    wire [UW-1:0] rd_u = rd_addr[UW+IW-1:IW];
    wire [IW-1:0] rd_n = rd_addr[IW-1:0];
    reg  [UW-1:0] rd_u_q;
    wire [M*W-1:0] b_x_all, b_y_all, b_z_all;
    always @(posedge clk) rd_u_q <= rd_u;
    wire rd_ok = {1'b0, rd_u_q} < M_COUNT;  // past the last unit: 0, never X
    assign rd_x = rd_ok ? b_x_all[rd_u_q * W +: W] : {W{1'b0}};
    assign rd_y = rd_ok ? b_y_all[rd_u_q * W +: W] : {W{1'b0}};
    assign rd_z = rd_ok ? b_z_all[rd_u_q * W +: W] : {W{1'b0}};

    wire [UW-1:0] pin_u = cfg_data[UW+IW-1:IW];
    wire [IW-1:0] pin_n = cfg_data[IW-1:0];

    genvar u;
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam [UW-1:0] U_ID = u;
            wire init_we = phase == PH_INIT && init_u == U_ID;
            wire load_we = node_we && pin_u == U_ID;  // NODE: the address is in cfg_data, as for PIN
            wire seq_we  = c_wr_en && c_wr_u == U_ID;
            wire acc_we  = f_wr_en && f_wr_u == U_ID;
            node_unit #(.W(W), .F(F), .K(K), .IW(IW), .EN_GRAVITY(EN_GRAVITY), .EN_DAMPING(EN_DAMPING),
                        .EN_MOUSE(EN_MOUSE), .EN_SPRINGS(EN_SPRINGS), .EN_GROUND(EN_GROUND),
                        .GROUND_AXIS(GROUND_AXIS), .GROUND_ABOVE(GROUND_ABOVE), .DIM(DIM), .GRAB(HAS_GRAB),
                        .UNIT_ID(u)) u_unit (
                .clk(clk), .reset(reset),
                .verlet_start(verlet_start), .ground_start(ground_start), .verlet_done(done_all[u]),
                .ground(ground), .friction(friction),
                .gdt2_x(gdt2_x), .gdt2_y(gdt2_y), .gdt2_z(gdt2_z), .damping(damping), .impulse(impulse),
                .box_x(box_x), .box_y(box_y), .box_z(box_z),
                .mouse_x(mouse_x_q), .mouse_y(mouse_y_q), .mouse_z(mouse_z_q), .mouse_down(mouse_down_q),
                .grab_here(grab_valid && grab_a[UW+IW-1:IW] == U_ID), .grab_idx(grab_a[IW-1:0]),
                .a_idx(seq_rd_n), .a_x(a_x_all[u*W +: W]), .a_y(a_y_all[u*W +: W]), .a_pinned(a_pin_all[u]),
                .a_px(a_px_all[u*W +: W]), .a_py(a_py_all[u*W +: W]),
                .a_accx(a_accx_all[u*W +: W]), .a_accy(a_accy_all[u*W +: W]),
                .a_z(a_z_all[u*W +: W]), .a_pz(a_pz_all[u*W +: W]), .a_accz(a_accz_all[u*W +: W]),
                .acc_we(acc_we), .acc_wx(f_wr_x), .acc_wy(f_wr_y), .acc_wz(f_wr_z),
                .w_en(init_we || load_we || seq_we),
                .w_idx(init_we ? init_n : load_we ? pin_n : acc_we ? f_wr_n : c_wr_n),
                .w_x(init_we ? init_x : load_we ? load_x : c_wr_x), .w_y(init_we ? init_y : load_we ? load_y : c_wr_y),
                .w_z(init_we ? init_z : load_we ? load_z : c_wr_z),
                .w_at_rest(init_we || load_we),
                .w_px(init_we ? init_px : load_px), .w_py(init_we ? init_py : load_py), .w_pz(init_we ? init_pz : load_pz),
                .pin_en(pin_we && pin_u == U_ID), .pin_idx(pin_n),
                .b_idx(rd_n), .b_x(b_x_all[u*W +: W]), .b_y(b_y_all[u*W +: W]), .b_z(b_z_all[u*W +: W]),
                .wb_valid(wb_valid[u]), .wb_idx(wb_idx[u*IW +: IW]), .wb_x(wb_x[u*W +: W]), .wb_y(wb_y[u*W +: W]),
                .wb_z(wb_z[u*W +: W]));
        end
    endgenerate

    assign fv = &done_all;

    // ---- FEC, from the sequencer ----
`ifdef STRAND_FAULTS
    // Test only (the harness's planted-fault check): with +fault_delay, FEC one cycle late.
    reg fault_on;
    initial fault_on = $test$plusargs("fault_delay");
    reg fec_late;
    always @(posedge clk) fec_late <= reset ? 1'b0 : fec_seq;
    assign fec = fault_on ? fec_late : fec_seq;
`else
    assign fec = fec_seq;
`endif

endmodule

`resetall
