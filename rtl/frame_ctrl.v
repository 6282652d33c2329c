`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * frame_ctrl - the frame FSM of strand_core: phases, substeps, the mouse sample,
 * the init walk and the frame-done interrupt.
 *
 * A frame (on `step`, when idle): the mouse is sampled; with GRAB the scan for the
 * node to hold runs first (phase GRAB); then SUBSTEPS times: with EN_SPRINGS a spring
 * pass (FORCE); the Verlet pass of every unit (VERLET, ends when FV rises); with
 * EN_CONSTRAINTS ITER constraint passes (CONSTRAIN, ends on the sequencer's done);
 * with EN_GROUND a ground pass (GROUND, ends when FV rises). Each phase starts in
 * the cycle the one before ends. frame_done pulses for one cycle at the end and
 * sets irq, which a write of IRQ_ACK clears (a frame ending in the same cycle wins).
 *
 * CMD = 1 (when idle) starts the init walk (phase INIT, N cycles): node i, in
 * {unit, node} order, is laid at START + i STEP with its previous position PREV away
 * (init_pos, init_prev; node_unit puts a pinned node at rest; the STEP and PREV
 * registers are read a cycle ahead, so one written during the walk acts from the
 * second cycle after). A graph has no walk
 * (its nodes are loaded one by one): there CMD does nothing and none of it is built.
 *
 * The mouse's in-touch box around the sampled pointer (EN_MOUSE, not GRAB): touch_lo =
 * mouse_q - BOX and touch_hi = mouse_q + BOX per axis, exact in W+1 bits, registered
 * from the pointer and the BOX register of the cycle before (so a node's in-touch test
 * is two comparisons, not a subtraction and then a comparison). The constants are
 * written between frames, and the first test of a frame comes cycles after its
 * sample.
 *
 * Phases: 0 IDLE, 1 INIT, 2 VERLET, 3 CONSTRAIN, 4 FORCE, 5 GROUND, 6 GRAB. Every
 * phase takes a number of cycles fixed by the parameters (model/timing.c).
 */
module frame_ctrl #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             step,          // start a frame (when idle)
    input  wire             cmd_init,      // start the init walk (when idle)
    input  wire             irq_ack,       // clear irq
    input  wire [DIM*W-1:0] mouse,         // the pointer and the button, sampled at a frame's start
    input  wire             mouse_down,
    input  wire [DIM*W-1:0] start_pos,     // START, STEP, PREV: the init walk's layout
    input  wire [DIM*W-1:0] step_pos,
    input  wire [DIM*W-1:0] prev_off,
    input  wire [DIM*W-1:0] box,           // BOX: the mouse's in-touch half-widths

    input  wire             fv,            // every unit finished its pass
    input  wire             seq_done,      // the constraint passes are over
    input  wire             force_done,    // the spring pass is over
    input  wire             scan_end,      // the grab scan is over

    output reg  [2:0]       phase,
    output wire             frame_start,   // this cycle starts a frame
    output wire             verlet_start,  // one-cycle starts of the passes
    output wire             ground_start,
    output wire             seq_start,
    output wire             force_start,
    output reg              frame_done,    // one-cycle pulse
    output reg              irq,           // level: a frame ended since the last IRQ_ACK
    output reg  [DIM*W-1:0] mouse_q,
    output reg              mouse_down_q,
    output wire [DIM*(W+1)-1:0] touch_lo,  // mouse_q - BOX, per axis (W+1 bits each, exact)
    output wire [DIM*(W+1)-1:0] touch_hi,  // mouse_q + BOX

    output wire             init_we_d,     // the init walk writes node init_addr_d in the next cycle
    output wire [AW-1:0]    init_addr_d,   //   (strand_core registers both beside each unit)
    output wire [AW-1:0]    init_addr_next, // the node the walk writes after that one (outside the walk: its second node)
    output wire [DIM*W-1:0] init_pos,
    output wire [DIM*W-1:0] init_prev
);

`include "strand_addr.vh"

    localparam [2:0] PH_IDLE = 3'd0, PH_INIT = 3'd1, PH_VERLET = 3'd2, PH_CONSTRAIN = 3'd3, PH_FORCE = 3'd4,
                     PH_GROUND = 3'd5, PH_GRAB = 3'd6;
    localparam [0:0] HAS_GRAB = EN_MOUSE && GRAB;
    localparam integer N_LAST_I   = M * K - 1;
    localparam integer SUB_LAST_I = SUBSTEPS - 1;
    localparam [CW-1:0] N_LAST    = N_LAST_I[CW-1:0];
    localparam [SW-1:0] SUB_LAST  = SUB_LAST_I[SW-1:0];

    reg [SW-1:0] substep_q;
    // the init walk starts. A step in the same cycle wins (the CMD is ignored, as in any
    // busy phase): so the command's address decode is not on frame_start's path, which
    // fans out to every unit's pass start
    wire         walk = cmd_init && !GRAPH && !step;
    wire         walk_end;                   // its last node is written now

    // A substep: [FORCE] VERLET [CONSTRAIN] [GROUND]; each phase starts in the cycle the one before ends.
    // FUSE: [FORCE] CONSTRAIN [GROUND], the Verlet step taken by the constraint pass's first sweep.
    localparam [2:0] PH_BODY = FUSE != 0 ? PH_CONSTRAIN : PH_VERLET;  // the phase after FORCE (or the frame's start)
    wire verlet_end    = phase == PH_VERLET && fv;
    wire body_end      = EN_CONSTRAINTS ? phase == PH_CONSTRAIN && seq_done : verlet_end;
    wire substep_end   = EN_GROUND ? phase == PH_GROUND && fv : body_end;
    wire substep_start = (HAS_GRAB ? scan_end : frame_start) || (substep_end && substep_q != SUB_LAST);
    assign frame_start  = phase == PH_IDLE && step;
    assign ground_start = body_end && EN_GROUND;
    assign force_start  = substep_start && EN_SPRINGS;
    wire   body_start   = (substep_start && !EN_SPRINGS) || (phase == PH_FORCE && force_done);
    assign verlet_start = body_start && FUSE == 0;
    assign seq_start    = FUSE != 0 ? body_start : verlet_end && EN_CONSTRAINTS;

    // ---- the init walk (chains): the node, its position and previous position ----
    genvar k;
    generate
        if (!GRAPH) begin : g_walk
            reg [AW-1:0]    addr_q;
            reg [AW-1:0]    after_q;   // next_node(addr_q), kept a cycle ahead (below)
            reg [AW-1:0]    ahead_q;   // init_addr_next: next_node(after_q)
            reg [CW-1:0]    count_q;
            reg [DIM*W-1:0] pos_q;
            // The walk's next position and its previous position are formed a cycle ahead and
            // registered: pos_ahead_q is the position after pos_d (pos_d + STEP), prev_q is
            // pos_d + PREV (init_prev), each with the register as it stands. So each adder
            // starts from flip-flops, neither follows the other on one path, the sum reaches
            // every unit's memory from a flip-flop, and the register write port's data reaches
            // neither adder. A STEP or PREV written during the walk acts on it a cycle later
            // than a constant read directly would (the cycle model does the same)
            reg [DIM*W-1:0] pos_ahead_q, prev_q;
            wire [DIM*W-1:0] ahead_d, pos_d, prev_d;
            // walking_q: phase == PH_INIT, a copy of the walk's own (the walk enters INIT only
            // from IDLE, by walk, and leaves it only at walk_end), so that the phase register,
            // placed by the frame's logic, is not on the walk's paths (into the adders below)
            reg walking_q;
            (* keep *) always @(posedge clk)
                if (reset) walking_q <= 1'b0;
                else if (phase == PH_IDLE && walk) walking_q <= 1'b1;
                else if (walk_end) walking_q <= 1'b0;
            assign pos_d = reset ? {(DIM*W){1'b0}} : walking_q ? pos_ahead_q : start_pos;
            for (k = 0; k < DIM; k = k + 1) begin : g_lane
                /* verilator lint_off PINCONNECTEMPTY */
                // saturation flags are not needed: the saturated value is the result
                fx_add #(.W(W), .SUB(0)) u_next (.sub(1'b0), .a(pos_d[k*W +: W]), .b(step_pos[k*W +: W]), .y(ahead_d[k*W +: W]), .sat());
                fx_add #(.W(W), .SUB(0)) u_prev (.sub(1'b0), .a(pos_d[k*W +: W]), .b(prev_off[k*W +: W]), .y(prev_d[k*W +: W]), .sat());
                /* verilator lint_on PINCONNECTEMPTY */
            end
            always @(posedge clk) begin
                pos_q       <= pos_d;   // read only in the walk: outside it, the walk's start
                pos_ahead_q <= ahead_d;
                prev_q      <= prev_d;
            end
            assign init_prev = prev_q;
            // The next address, also out: node_unit looks up the next node's pinned flag a
            // cycle ahead, so that the lookup is not on the memory's write path. after_q holds
            // the address after addr_q, so that no incrementer sits before that lookup.
            // Outside the walk every register holds what the walk's first cycle needs (its
            // end puts them back), so that the walk starts without loading any of them: the
            // command's decode, which decides that start, reaches only the phase. The first
            // node's flag cannot come from that lookup (in the cycle before the walk the
            // address ahead is already the second node), so node_unit also keeps node 0's
            // flag, and each unit picks it for the write of its node 0 (strand_core registers
            // that choice beside the unit from init_addr_d).
            assign init_addr_next = ahead_q;
            localparam [AW-1:0] ADDR_ZERO = {AW{1'b0}};
            localparam [AW-1:0] ADDR_ONE  = next_node(ADDR_ZERO);
            // The walk's write in the next cycle (phase == PH_INIT then, and addr_q's next
            // value), given a cycle ahead: each unit registers its own copy, so that no one
            // register of the walk fans out across the device to every unit's write port and
            // written flags.
            assign init_we_d   = !reset && (walking_q ? !walk_end : phase == PH_IDLE && walk);
            assign init_addr_d = reset || (walking_q && walk_end) ? ADDR_ZERO : walking_q ? after_q : addr_q;
            always @(posedge clk) begin
                if (reset) begin
                    addr_q  <= ADDR_ZERO;
                    after_q <= ADDR_ONE;
                    ahead_q <= ADDR_ONE;
                    count_q <= {CW{1'b0}};
                end else if (walking_q) begin
                    addr_q  <= walk_end ? ADDR_ZERO : after_q;
                    after_q <= walk_end ? ADDR_ONE : next_node(after_q);
                    ahead_q <= walk_end ? ADDR_ONE : next_node(after_q);
                    count_q <= walk_end ? {CW{1'b0}} : count_q + 1'b1;
                end
            end
            assign walk_end  = walking_q && count_q == N_LAST;
            assign init_pos  = pos_q;
        end else begin : g_no_walk
            assign walk_end  = 1'b0;
            assign init_we_d   = 1'b0;
            assign init_addr_d = {AW{1'b0}};
            assign init_addr_next = {AW{1'b0}};
            assign init_pos  = {(DIM*W){1'b0}};
            assign init_prev = {(DIM*W){1'b0}};
            wire unused_walk = &{1'b0, start_pos, step_pos, prev_off};
        end
    endgenerate

    // ---- the in-touch box around the pointer ----
    generate
        if (EN_MOUSE && !GRAB) begin : g_touch_box
            for (k = 0; k < DIM; k = k + 1) begin : g_axis
                wire [W:0] m = {mouse_q[k*W + W-1], mouse_q[k*W +: W]}, b = {box[k*W + W-1], box[k*W +: W]};
                reg  [W:0] lo_q, hi_q;
                always @(posedge clk) begin
                    lo_q <= m - b;
                    hi_q <= m + b;
                end
                assign touch_lo[k*(W+1) +: W+1] = lo_q;
                assign touch_hi[k*(W+1) +: W+1] = hi_q;
            end
        end else begin : g_no_touch_box
            assign touch_lo = {(DIM*(W+1)){1'b0}};
            assign touch_hi = {(DIM*(W+1)){1'b0}};
            wire unused_box = &{1'b0, box};
        end
    endgenerate

    always @(posedge clk) begin
        frame_done <= 1'b0;
        if (reset) begin
            phase        <= PH_IDLE;
            substep_q    <= {SW{1'b0}};
            mouse_q      <= {(DIM*W){1'b0}};
            mouse_down_q <= 1'b0;
            frame_done   <= 1'b0;
            irq          <= 1'b0;
        end else begin
            case (phase)
                PH_IDLE: begin
                    if (walk) begin
                        phase <= PH_INIT;
                    end else if (step) begin
                        phase        <= HAS_GRAB ? PH_GRAB : EN_SPRINGS ? PH_FORCE : PH_BODY;
                        substep_q    <= {SW{1'b0}};
                        mouse_q      <= mouse;
                        mouse_down_q <= mouse_down;
                    end
                end
                PH_INIT:   if (walk_end) phase <= PH_IDLE;
                PH_FORCE:  if (force_done) phase <= PH_BODY;
                PH_GRAB:   if (scan_end) phase <= EN_SPRINGS ? PH_FORCE : PH_BODY;
                PH_VERLET: if (seq_start) phase <= PH_CONSTRAIN;
                default:   ;
            endcase
            if (ground_start) phase <= PH_GROUND;
            if (substep_end) begin
                if (substep_q == SUB_LAST) begin
                    phase      <= PH_IDLE;
                    frame_done <= 1'b1;
                end else begin
                    phase     <= EN_SPRINGS ? PH_FORCE : PH_BODY;
                    substep_q <= substep_q + 1'b1;
                end
            end
            if (irq_ack) irq <= 1'b0;
            if (substep_end && substep_q == SUB_LAST) irq <= 1'b1;
        end
    end

endmodule

`resetall
