`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"

/*
 * strand_core - the rope and soft-body engine: M node units of K nodes, a constraint
 * sequencer, a spring pass and the mouse, composed of named blocks:
 *
 *     strand_regfile   the register write port: run-time constants, command strobes
 *     frame_ctrl       phases, substeps, the mouse sample, the init walk, irq
 *     grab_scan        GRAB: which node the pointer holds
 *     node_unit x M    storage (node_lane x DIM, strand_ram) and the per-node FSM:
 *                      Verlet, mouse impulse, ground pass
 *     chain_sequencer  the centred rule (RULE 0) over the chain, through `toward`
 *     pair_sequencer   the pairwise rule (RULE 1) over links or a rod memory (GRAPH),
 *                      and, SPRING mode, the spring pass over links or a spring memory
 *     chain_stream     ARCH 1: the pipelined constraint pass over a chain (red/black)
 *     graph_stream     ARCH 1, GRAPH: the pipelined pass over the rod memory, by colour
 *     spring_stream    ARCH 1, a chain with springs: the pipelined spring pass
 *
 * Ports: what a system integrator needs. After reset: write the constants and pins
 * (cfg_*), then lay the nodes out (CMD = 1: the init walk, N cycles; or, for a graph,
 * one NODE write per node and one EDGE write per edge), then pulse step once per
 * frame (when busy is low); frame_done pulses at the end of each frame and sets irq
 * until a write of IRQ_ACK. The mouse is sampled when a frame starts. rd_addr
 * ({unit, node}) reads a node's position two cycles later (0 for a node not written
 * since reset, or an address past the last node; writes of the cycle rd_addr is
 * presented are not seen).
 *
 * dbg (DEBUG = 1, for verification; else one constant bit) shows, LSB first: phase
 * [3], FV, FEC, the walk's uidx [UW], nidx [IW] and counter [CW], and the
 * write-back lanes, WB of them (WB = M, or 2 M with PAIR: lane u (1 + PAIR) + l shows
 * unit u's write port l): valid [WB], index [WB IW], x [WB W], y [WB W], z [WB W] (z 0
 * in 2D).
 * tb/sim_top.v unpacks it; the cycle model predicts all of it.
 *
 * Phases: 0 IDLE, 1 INIT, 2 VERLET, 3 CONSTRAIN, 4 FORCE, 5 GROUND, 6 GRAB; every
 * phase takes a number of cycles fixed by the parameters (model/timing.c). The
 * parameters (one table: scripts/gen_params.py) and the register map
 * (scripts/gen_regs.py) are generated into build/gen.
 */
module strand_core #(
`include "strand_params.vh"
) (
    input  wire            clk,
    input  wire            reset,       // synchronous, active high

    input  wire            cfg_we,      // register write port
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]    cfg_data,

    input  wire            step,        // start a frame (when not busy)
    output wire            busy,        // a frame or the init walk is under way
    output wire            frame_done,  // one-cycle pulse: the frame is finished
    output wire            irq,         // level: a frame finished since the last IRQ_ACK write

    input  wire [W-1:0]    mouse_x,     // sampled when a frame starts
    input  wire [W-1:0]    mouse_y,
    input  wire [W-1:0]    mouse_z,     // DIM = 3
    input  wire            mouse_down,

    input  wire [AW-1:0]   rd_addr,     // position read port: {unit, node} in,
    output wire [W-1:0]    rd_x,        // its position two cycles later
    output wire [W-1:0]    rd_y,
    output wire [W-1:0]    rd_z,        // DIM = 3; else 0

    output wire [DBG_W-1:0] dbg         // DEBUG: the observation port (above)
);

`include "strand_params_check.vh"

    localparam [2:0] PH_IDLE = 3'd0, PH_FORCE = 3'd4, PH_GRAB = 3'd6;
    localparam [0:0] HAS_GRAB = EN_MOUSE && GRAB;
    localparam integer DW = DIM * W;
    localparam [UW:0] M_COUNT = M[UW:0];

    // ---- registers ----
    wire [DW-1:0]  box, start_pos, step_pos, prev_off, load_pos, load_prev;
    wire [W-1:0]   rest_len, impulse, ks, kd, ground, friction, edge_rest;
    wire [`STRAND_FX_SLOTS*W-1:0] fx_consts;  // the effects table's constants (strand_regs.vh)
    wire           cmd_init, pin_we, node_we_any, edge_we_any, irq_ack;
    strand_regfile #(
`include "strand_params_pass.vh"
    ) u_regs (
        .clk(clk), .reset(reset), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .box(box), .start_pos(start_pos),
        .step_pos(step_pos), .prev_off(prev_off), .load_pos(load_pos), .load_prev(load_prev),
        .rest_len(rest_len), .impulse(impulse), .ks(ks), .kd(kd), .ground(ground),
        .friction(friction), .edge_rest(edge_rest), .fx_consts(fx_consts),
        .cmd_init(cmd_init), .pin_we(pin_we), .node_we(node_we_any), .edge_we(edge_we_any), .irq_ack(irq_ack));

    // ---- the frame ----
    wire [2:0]    phase;
    wire          frame_start, verlet_start, ground_start, seq_start, force_start;
    wire          fv, seq_done, force_done, scan_end;
    wire [DW-1:0] mouse_q;
    wire [DIM*(W+1)-1:0] touch_lo, touch_hi;  // the in-touch box around the pointer
    wire          mouse_down_q;
    wire          init_we_d;
    wire [AW-1:0] init_addr_d;
    /* verilator lint_off UNUSEDSIGNAL */
    // the units use only its node bits: a unit's w_pin is read only when the walk is in the unit
    wire [AW-1:0] init_addr_next;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [DW-1:0] init_pos, init_prev;
    wire [DW-1:0] mouse_lanes;  // the pointer, one lane per axis
    frame_ctrl #(
`include "strand_params_pass.vh"
    ) u_frame (
        .clk(clk), .reset(reset), .step(step), .cmd_init(cmd_init), .irq_ack(irq_ack),
        .mouse(mouse_lanes), .mouse_down(mouse_down),
        .start_pos(start_pos), .step_pos(step_pos), .prev_off(prev_off),
        .fv(fv), .seq_done(seq_done), .force_done(force_done), .scan_end(scan_end),
        .phase(phase), .frame_start(frame_start), .verlet_start(verlet_start), .ground_start(ground_start),
        .seq_start(seq_start), .force_start(force_start), .frame_done(frame_done), .irq(irq),
        .mouse_q(mouse_q), .mouse_down_q(mouse_down_q), .box(box), .touch_lo(touch_lo), .touch_hi(touch_hi),
        .init_we_d(init_we_d), .init_addr_d(init_addr_d), .init_addr_next(init_addr_next), .init_pos(init_pos), .init_prev(init_prev));
    assign busy = phase != PH_IDLE;
    // NODE and EDGE writes load a graph's body, only when idle (a chain is laid out by CMD)
    wire node_we = node_we_any && phase == PH_IDLE && GRAPH;
    wire edge_we = edge_we_any && phase == PH_IDLE && GRAPH;
    // zero-extended so that a chain's build (no EDGE word: 2 AW may pass W) selects in range
    /* verilator lint_off UNUSEDSIGNAL */
    // b needs bits 2 AW-1 .. AW only
    wire [W+2*AW-1:0] cfg_data_wide = {{(2*AW){1'b0}}, cfg_data};
    /* verilator lint_on UNUSEDSIGNAL */
    wire [AW-1:0] edge_a      = cfg_data[AW-1:0];
    wire [AW-1:0] edge_b      = cfg_data_wide[2*AW-1:AW];
    wire          edge_spring = cfg_data[(2*AW < W ? 2*AW : W-1)];
    wire          edge_last   = cfg_data[(2*AW+1 < W ? 2*AW+1 : W-1)];  // ARCH: the edge ends its colour
    wire [AW-1:0] cfg_node    = cfg_data[AW-1:0];  // PIN and NODE: a node address

    // ---- port A of the units: one reader at a time (the scan, the spring pass, the
    // constraint sequencer); the data of unit rd_sel_q arrive the cycle after ----
    wire [AW-1:0] c_rd, c_wr, f_rd, f_wr, scan_addr;
    wire          c_wr_en, f_wr_en;
    wire [DW-1:0] c_wr_pos, f_wr_pos;
    wire [UW-1:0] c_uidx, f_uidx;
    wire [IW-1:0] c_nidx, f_nidx;
    wire [CW-1:0] c_counter, f_counter;
    wire          fec;
    wire          in_force = phase == PH_FORCE;
    wire          in_scan  = HAS_GRAB && phase == PH_GRAB;
    wire [AW-1:0] seq_rd   = in_scan ? scan_addr : in_force ? f_rd : c_rd;
    reg  [UW-1:0] rd_sel_q;
    always @(posedge clk) rd_sel_q <= seq_rd[AW-1:IW];

    wire [M*DW-1:0] a_pos_all, a_prev_all, a_acc_all, b_pos_all;
    // the spring pass's force writes, per unit (the serial pass writes one unit at a time)
    wire [M-1:0]    acc_we_all;
    wire [M*IW-1:0] acc_idx_all;
    wire [M*DW-1:0] acc_w_all;
    wire [M-1:0]    a_pin_all, done_all;
    // the write-back lanes (DEBUG): lane u (1 + PAIR) + l is unit u's write port l
    localparam integer LANES = 1 + PAIR;
    wire [WB-1:0]    wb_valid_all;
    wire [WB*IW-1:0] wb_idx_all;
    wire [WB*DW-1:0] wb_pos_all;
    // PAIR: the pair reads of every unit (the pipelined constraint pass's)
    wire [M*DW-1:0] pair_pos_e_all, pair_pos_o_all, pair_prev_e_all, pair_prev_o_all;
    wire [M-1:0]    pair_pin_e_all, pair_pin_o_all;
    // FUSE: the pair read is the Verlet step's (and its odd node exists); the step's results of every unit
    wire            pair_fuse, pair_has_o;
    wire [M*DW-1:0] pass_pos_e_all, pass_pos_o_all, pass_prev_e_all, pass_prev_o_all;
    wire [M-1:0]    pass_pin_e_all, pass_pin_o_all, pass_held_e_all, pass_held_o_all;
    // (every other build)
    wire unused_pair = &{1'b0, pair_pos_e_all, pair_pos_o_all, pair_prev_e_all, pair_prev_o_all, pair_pin_e_all, pair_pin_o_all,
                         pass_pos_e_all, pass_pos_o_all, pass_prev_e_all, pass_prev_o_all, pass_pin_e_all, pass_pin_o_all,
                         pass_held_e_all, pass_held_o_all};
    // a unit index past the last unit reads as 0 (the sequencer ignores it: no D past the end)
    wire          sel_ok      = {1'b0, rd_sel_q} < M_COUNT;
    wire [DW-1:0] seq_rd_pos  = sel_ok ? a_pos_all[rd_sel_q * DW +: DW] : {DW{1'b0}};
    wire [DW-1:0] seq_rd_prev = sel_ok ? a_prev_all[rd_sel_q * DW +: DW] : {DW{1'b0}};
    wire [DW-1:0] seq_rd_acc  = sel_ok ? a_acc_all[rd_sel_q * DW +: DW] : {DW{1'b0}};
    wire          seq_rd_pin  = sel_ok && a_pin_all[rd_sel_q];

    // ---- the sequencers ----
    // the constraint pass's write of each unit (the serial sequencers write one unit at a time)
    wire [M-1:0]    seq_we;
    wire [M*IW-1:0] seq_widx;
    wire [M*DW-1:0] seq_wpos;
    // PAIR: the pipelined pass's pair reads and second writes (the link's other end)
    wire            pair_re;
    wire [M*IW-1:0] pair_row_e_all, pair_row_o_all;
    wire [M-1:0]    seq2_we;
    wire [M*IW-1:0] seq2_widx;
    wire [M*DW-1:0] seq2_wpos;
    genvar u;
    /* verilator lint_off PINCONNECTEMPTY */
    // the spring pass's FEC is not an output (FEC is the constraint pass's)
    generate
        if (EN_CONSTRAINTS && ARCH && GRAPH) begin : g_graph_stream
            graph_stream #(
`include "strand_params_pass.vh"
            ) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done),
                .e_we(edge_we && !edge_spring), .e_a(edge_a), .e_b(edge_b), .e_rest(edge_rest), .e_last(edge_last),
                .rd_addr(c_rd), .rd_pos(seq_rd_pos), .rd_pinned(seq_rd_pin),
                .rd_prev(PROJECTION ? seq_rd_prev : {DW{1'b0}}),
                .wr_en(c_wr_en), .wr_addr(c_wr), .wr_pos(c_wr_pos),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec));
            wire unused_rest = &{1'b0, rest_len};  // a graph's edges have their own
        end else if (EN_CONSTRAINTS && ARCH) begin : g_stream
            chain_stream #(
`include "strand_params_pass.vh"
            ) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done), .rest_len(rest_len),
                .pair_re(pair_re), .pair_row_e_all(pair_row_e_all), .pair_row_o_all(pair_row_o_all),
                .pair_pos_e_all(pair_pos_e_all), .pair_pos_o_all(pair_pos_o_all),
                .pair_prev_e_all(PROJECTION ? pair_prev_e_all : {(M*DW){1'b0}}),
                .pair_prev_o_all(PROJECTION ? pair_prev_o_all : {(M*DW){1'b0}}),
                .pair_pin_e_all(pair_pin_e_all), .pair_pin_o_all(pair_pin_o_all),
                .pair_fuse(pair_fuse), .pair_has_o(pair_has_o),
                .pass_pos_e_all(pass_pos_e_all), .pass_pos_o_all(pass_pos_o_all),
                .pass_prev_e_all(PROJECTION ? pass_prev_e_all : {(M*DW){1'b0}}),
                .pass_prev_o_all(PROJECTION ? pass_prev_o_all : {(M*DW){1'b0}}),
                .pass_pin_e_all(pass_pin_e_all), .pass_pin_o_all(pass_pin_o_all),
                .pass_held_e_all(pass_held_e_all), .pass_held_o_all(pass_held_o_all),
                .wr_en(seq_we), .wr_idx_all(seq_widx), .wr_pos_all(seq_wpos),
                .wr2_en(seq2_we), .wr2_idx_all(seq2_widx), .wr2_pos_all(seq2_wpos),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec));
            assign c_rd     = {AW{1'b0}};  // the pass reads pairs, not port A
            assign c_wr     = {AW{1'b0}};  // the units' writes are seq_*
            assign c_wr_en  = 1'b0;
            assign c_wr_pos = {DW{1'b0}};
            wire unused_serial_writes = &{1'b0, c_wr, c_wr_en, c_wr_pos};
        end else if (EN_CONSTRAINTS && RULE == 0) begin : g_centred
            chain_sequencer #(
`include "strand_params_pass.vh"
            ) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done), .rest_len(rest_len),
                .rd_uidx(c_rd[AW-1:IW]), .rd_nidx(c_rd[IW-1:0]), .rd_pos(seq_rd_pos), .rd_pinned(seq_rd_pin),
                .rd_prev(PROJECTION ? seq_rd_prev : {DW{1'b0}}),  // (a kept port would keep its mux)
                .wr_en(c_wr_en), .wr_uidx(c_wr[AW-1:IW]), .wr_nidx(c_wr[IW-1:0]), .wr_pos(c_wr_pos),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec));
        end else if (EN_CONSTRAINTS) begin : g_pairwise
            pair_sequencer #(
`include "strand_params_pass.vh"
                , .SPRING(1'b0), .PASSES(ITER), .E(E_RODS)) u_seq (
                .clk(clk), .reset(reset), .start(seq_start), .done(seq_done), .rest_len(rest_len),
                .e_we(edge_we && !edge_spring), .e_a(edge_a), .e_b(edge_b), .e_rest(edge_rest),
                .ks({W{1'b0}}), .kd({W{1'b0}}),
                .rd_uidx(c_rd[AW-1:IW]), .rd_nidx(c_rd[IW-1:0]), .rd_pos(seq_rd_pos), .rd_pinned(seq_rd_pin),
                .rd_prev(PROJECTION ? seq_rd_prev : {DW{1'b0}}), .rd_acc({DW{1'b0}}),  // previous positions: PROJECTION only
                .wr_en(c_wr_en), .wr_uidx(c_wr[AW-1:IW]), .wr_nidx(c_wr[IW-1:0]), .wr_pos(c_wr_pos),
                .uidx(c_uidx), .nidx(c_nidx), .counter(c_counter), .fec(fec));
        end else begin : g_no_constraints
            assign seq_done  = 1'b0;
            assign c_rd      = {AW{1'b0}};
            assign c_wr      = {AW{1'b0}};
            assign c_wr_en   = 1'b0;
            assign c_wr_pos  = {DW{1'b0}};
            assign c_uidx    = {UW{1'b0}};
            assign c_nidx    = {IW{1'b0}};
            assign c_counter = {CW{1'b0}};
            assign fec       = 1'b0;
            wire unused_constraints = &{1'b0, rest_len, seq_start};
        end

        if (EN_SPRINGS && ARCH && !GRAPH) begin : g_spring_stream
            // the pipelined spring pass: every unit gathers its own nodes' forces
            spring_stream #(
`include "strand_params_pass.vh"
            ) u_force (
                .clk(clk), .reset(reset), .start(force_start), .done(force_done), .rest_len(rest_len),
                .ks(ks), .kd(kd),
                .rd_idx(f_rd[IW-1:0]), .rd_pos_all(a_pos_all), .rd_prev_all(a_prev_all), .rd_acc_all(a_acc_all),
                .wr_en(acc_we_all), .wr_idx_all(acc_idx_all), .wr_acc_all(acc_w_all),
                .uidx(f_uidx), .nidx(f_nidx), .counter(f_counter));
            assign f_rd[AW-1:IW] = {UW{1'b0}};
            assign f_wr     = {AW{1'b0}};  // the units' writes are acc_*_all
            assign f_wr_en  = 1'b0;
            assign f_wr_pos = {DW{1'b0}};
            wire unused_serial_force = &{1'b0, f_wr, f_wr_en, f_wr_pos, seq_rd_prev, seq_rd_acc};
        end else if (EN_SPRINGS) begin : g_springs
            pair_sequencer #(
`include "strand_params_pass.vh"
                , .SPRING(1'b1), .PASSES(1), .E(E_SPRINGS)) u_force (
                .clk(clk), .reset(reset), .start(force_start), .done(force_done), .rest_len(rest_len),
                .e_we(edge_we && edge_spring), .e_a(edge_a), .e_b(edge_b), .e_rest(edge_rest),
                .ks(ks), .kd(kd),
                .rd_uidx(f_rd[AW-1:IW]), .rd_nidx(f_rd[IW-1:0]), .rd_pos(seq_rd_pos), .rd_pinned(seq_rd_pin),
                .rd_prev(seq_rd_prev), .rd_acc(seq_rd_acc),
                .wr_en(f_wr_en), .wr_uidx(f_wr[AW-1:IW]), .wr_nidx(f_wr[IW-1:0]), .wr_pos(f_wr_pos),
                .uidx(f_uidx), .nidx(f_nidx), .counter(f_counter), .fec());
        end else begin : g_no_springs
            assign force_done = 1'b0;
            assign f_rd       = {AW{1'b0}};
            assign f_wr       = {AW{1'b0}};
            assign f_wr_en    = 1'b0;
            assign f_wr_pos   = {DW{1'b0}};
            assign f_uidx     = {UW{1'b0}};
            assign f_nidx     = {IW{1'b0}};
            assign f_counter  = {CW{1'b0}};
            wire unused_springs = &{1'b0, ks, kd, force_start, seq_rd_prev, seq_rd_acc};
        end
    endgenerate
    /* verilator lint_on PINCONNECTEMPTY */
    generate
        if (!(EN_SPRINGS && ARCH && !GRAPH)) begin : g_serial_force_writes
            for (u = 0; u < M; u = u + 1) begin : g_unit_f
                localparam [UW-1:0] U_ID = u;
                assign acc_we_all[u]            = f_wr_en && f_wr[AW-1:IW] == U_ID;
                assign acc_idx_all[u*IW +: IW]  = f_wr[IW-1:0];
                assign acc_w_all[u*DW +: DW]    = f_wr_pos;
            end
        end
        if (!(EN_CONSTRAINTS && ARCH && !GRAPH)) begin : g_serial_writes
            for (u = 0; u < M; u = u + 1) begin : g_unit_w
                localparam [UW-1:0] U_ID = u;
                assign seq_we[u]             = c_wr_en && c_wr[AW-1:IW] == U_ID;
                assign seq_widx[u*IW +: IW]  = c_wr[IW-1:0];
                assign seq_wpos[u*DW +: DW]  = c_wr_pos;
            end
            assign pair_re        = 1'b0;
            assign pair_fuse      = 1'b0;
            assign pair_has_o     = 1'b0;
            assign pair_row_e_all = {(M*IW){1'b0}};
            assign pair_row_o_all = {(M*IW){1'b0}};
            assign seq2_we        = {M{1'b0}};
            assign seq2_widx      = {(M*IW){1'b0}};
            assign seq2_wpos      = {(M*DW){1'b0}};
        end
    endgenerate
    wire unused_graph = &{1'b0, edge_we, edge_a, edge_b, edge_spring, edge_rest, edge_last};  // a chain has no edge memory
    wire unused_port_a = &{1'b0, seq_rd_pos, seq_rd_pin};  // a build with no pass that reads port A

    // ---- GRAB: the scan for the node to hold ----
    wire          grab_valid;  // a node is held
    wire [AW-1:0] grab_a;      // its address
    generate
        if (HAS_GRAB) begin : g_grab
            grab_scan #(
`include "strand_params_pass.vh"
            ) u_scan (
                .clk(clk), .reset(reset), .frame_start(frame_start), .scanning(phase == PH_GRAB),
                .mouse(mouse_q), .mouse_down(mouse_down_q), .box(box),
                .scan_addr(scan_addr), .rd_pos(seq_rd_pos), .rd_pinned(seq_rd_pin),
                .scan_end(scan_end), .held(grab_valid), .held_addr(grab_a));
        end else begin : g_no_grab
            assign scan_end   = 1'b0;
            assign scan_addr  = {AW{1'b0}};
            assign grab_valid = 1'b0;
            assign grab_a     = {AW{1'b0}};
            wire unused_grab = &{1'b0, frame_start};
        end
    endgenerate

    // ---- the units ----
    generate
        for (u = 0; u < M; u = u + 1) begin : g_unit
            localparam [UW-1:0] U_ID = u;
            // the init walk's write in this unit, registered here from frame_ctrl's next-cycle
            // values (keep: one copy per unit, placed beside it, not merged into one register).
            // init_node0_q: the walk writes the unit's node 0 (outside the walk too, where
            // init_addr_d rests at node 0), formed the same way, so that no one register of
            // frame_ctrl reaches every unit's flag select and memory write data in one cycle
            // (the 6-unit build's critical path once, 4.9 ns of routing)
            reg          here_init_q, init_node0_q;
            reg [IW-1:0] init_idx_q;
            (* keep *) always @(posedge clk) begin
                here_init_q  <= init_we_d && init_addr_d[AW-1:IW] == U_ID;
                init_idx_q   <= init_addr_d[IW-1:0];
                init_node0_q <= init_addr_d[IW-1:0] == {IW{1'b0}};
            end
            wire here_init = here_init_q;
            wire here_load = node_we && cfg_node[AW-1:IW] == U_ID;  // NODE: the address is in cfg_data, as for PIN
            wire here_seq  = seq_we[u];
            wire here_acc  = acc_we_all[u];
            node_unit #(
`include "strand_params_pass.vh"
                , .UNIT_ID(u)) u_unit (
                .clk(clk), .reset(reset),
                .verlet_start(verlet_start), .ground_start(ground_start), .verlet_done(done_all[u]),
                .touch_lo(touch_lo), .touch_hi(touch_hi),
                .mouse(mouse_q), .mouse_down(mouse_down_q), .impulse(impulse), .fx_consts(fx_consts),
                .ground(ground), .friction(friction),
                .grab_here(grab_valid && grab_a[AW-1:IW] == U_ID), .grab_idx(grab_a[IW-1:0]),
                .a_idx(seq_rd[IW-1:0]), .a_pos(a_pos_all[u*DW +: DW]), .a_prev(a_prev_all[u*DW +: DW]),
                .a_acc(a_acc_all[u*DW +: DW]), .a_pinned(a_pin_all[u]),
                .acc_we(here_acc), .acc_w(acc_w_all[u*DW +: DW]),
                .w_en(here_init || here_load || here_seq),
                .w_idx(here_init ? init_idx_q : here_load ? cfg_node[IW-1:0] : here_acc ? acc_idx_all[u*IW +: IW] : seq_widx[u*IW +: IW]),
                .w_pos(here_init ? init_pos : here_load ? load_pos : seq_wpos[u*DW +: DW]),
                .w_at_rest(here_init || here_load), .w_prev(here_init ? init_prev : load_prev),
                .rest_idx(GRAPH ? cfg_node[IW-1:0] : init_addr_next[IW-1:0]), .rest_node0(init_node0_q),
                .pin_en(pin_we && cfg_node[AW-1:IW] == U_ID), .pin_idx(cfg_node[IW-1:0]),
                .b_idx(rd_addr[IW-1:0]), .b_pos(b_pos_all[u*DW +: DW]),
                .pair_re(pair_re), .pair_row_e(pair_row_e_all[u*IW +: IW]), .pair_row_o(pair_row_o_all[u*IW +: IW]),
                .pair_pos_e(pair_pos_e_all[u*DW +: DW]), .pair_pos_o(pair_pos_o_all[u*DW +: DW]),
                .pair_prev_e(pair_prev_e_all[u*DW +: DW]), .pair_prev_o(pair_prev_o_all[u*DW +: DW]),
                .pair_pin_e(pair_pin_e_all[u]), .pair_pin_o(pair_pin_o_all[u]),
                .pair_fuse(pair_fuse), .pair_has_o(pair_has_o),
                .pass_pos_e(pass_pos_e_all[u*DW +: DW]), .pass_pos_o(pass_pos_o_all[u*DW +: DW]),
                .pass_prev_e(pass_prev_e_all[u*DW +: DW]), .pass_prev_o(pass_prev_o_all[u*DW +: DW]),
                .pass_pin_e(pass_pin_e_all[u]), .pass_pin_o(pass_pin_o_all[u]),
                .pass_held_e(pass_held_e_all[u]), .pass_held_o(pass_held_o_all[u]),
                .w2_en(seq2_we[u]), .w2_idx(seq2_widx[u*IW +: IW]), .w2_pos(seq2_wpos[u*DW +: DW]),
                .wb_valid(wb_valid_all[u*LANES +: LANES]), .wb_idx(wb_idx_all[u*LANES*IW +: LANES*IW]),
                .wb_pos(wb_pos_all[u*LANES*DW +: LANES*DW]));
        end
    endgenerate
    assign fv = &done_all;

    // ---- the read port: every unit's port B reads node rd_addr's word (memory, then a
    // register: two cycles), and the unit is chosen after, from flip-flops ----
    reg [UW-1:0] rd_u_q, rd_u_q2;
    always @(posedge clk) begin
        rd_u_q  <= rd_addr[AW-1:IW];
        rd_u_q2 <= rd_u_q;
    end
    // an AND-OR select over the units (past the last unit: 0, never X); an indexed part
    // select (rd_u_q2 * DW) became a multiplier block on the path to the bus
    reg [DW-1:0] rd_pos;
    integer ru;
    always @(*) begin
        rd_pos = {DW{1'b0}};
        for (ru = 0; ru < M; ru = ru + 1)
            if ({1'b0, rd_u_q2} == ru[UW:0]) rd_pos = rd_pos | b_pos_all[ru*DW +: DW];
    end
    assign rd_x = rd_pos[0 +: W];
    assign rd_y = rd_pos[W +: W];
    generate
        if (DIM == 3) begin : g_z
            assign rd_z        = rd_pos[2*W +: W];
            assign mouse_lanes = {mouse_z, mouse_y, mouse_x};
        end else begin : g_no_z
            assign rd_z        = {W{1'b0}};
            assign mouse_lanes = {mouse_y, mouse_x};
            wire unused_mouse_z = &{1'b0, mouse_z};  // 2D: no z pointer
        end
    endgenerate

    // ---- the observation port ----
    generate
        if (DEBUG) begin : g_dbg
            wire [UW-1:0] uidx    = in_force ? f_uidx : c_uidx;
            wire [IW-1:0] nidx    = in_force ? f_nidx : c_nidx;
            wire [CW-1:0] counter = in_force ? f_counter : c_counter;
            wire [3*WB*W-1:0] wb_xyz;  // per axis, then per lane
            genvar a, v;
            for (a = 0; a < 3; a = a + 1) begin : g_axis
                for (v = 0; v < WB; v = v + 1) begin : g_lane
                    assign wb_xyz[(a*WB + v)*W +: W] = a < DIM ? wb_pos_all[v*DW + (a < DIM ? a : 0)*W +: W] : {W{1'b0}};
                end
            end
            assign dbg = {wb_xyz, wb_idx_all, wb_valid_all, counter, nidx, uidx, fec, fv, phase};
        end else begin : g_no_dbg
            assign dbg = 1'b0;
            wire unused_dbg = &{1'b0, c_uidx, c_nidx, c_counter, f_uidx, f_nidx, f_counter, fec, wb_valid_all,
                                wb_idx_all, wb_pos_all};
        end
    endgenerate

endmodule

`resetall
