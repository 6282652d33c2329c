`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"

/*
 * strand_regfile - the register write port of strand_core: the run-time constants
 * and the command strobes.
 *
 * cfg_we / cfg_addr / cfg_data write one register per cycle (addresses and meanings
 * in the generated strand_regs.vh, from scripts/gen_regs.py). The constants reset
 * to 0 and take a write in the cycle after it; an axis's constants come out as DIM
 * lanes (lane k at bits k W +: W, x first; the z registers exist only with DIM = 3).
 * PIN, NODE, EDGE, CMD and IRQ_ACK are strobes: they act in the cycle of the write
 * (strand_core decides which may act when).
 *
 * The effects table's constants (scripts/gen_effects.py: gravity, damping, wind, ...) come out on one bus,
 * fx_consts, whose slots strand_regs.vh names (`STRAND_FX_<CONST>): adding such an effect
 * changes no port here, in strand_core or in node_unit.
 *
 * A register the build does not use (its effect is switched off: KS without springs,
 * START in a graph, LOAD in a chain, ...) reads as 0 and is not built: the register
 * has no reader, so synthesis removes it, even with the hierarchy kept.
 */
module strand_regfile #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             cfg_we,
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]     cfg_data,

    output wire [DIM*W-1:0] box,        // the mouse's in-touch half-widths
    output wire [DIM*W-1:0] start_pos,  // the init walk: node 0, the step, the previous-position offset
    output wire [DIM*W-1:0] step_pos,
    output wire [DIM*W-1:0] prev_off,
    output wire [DIM*W-1:0] load_pos,   // a NODE write's position and previous position
    output wire [DIM*W-1:0] load_prev,
    output wire [W-1:0]     rest_len,
    output wire [W-1:0]     impulse,
    output wire [W-1:0]     ks,
    output wire [W-1:0]     kd,
    output wire [W-1:0]     ground,
    output wire [W-1:0]     friction,
    output wire [W-1:0]     edge_rest,
    output wire [`STRAND_FX_SLOTS*W-1:0] fx_consts,  // the effects table's constants (scripts/gen_effects.py)

    output wire             cmd_init,   // strobes
    output wire             pin_we,
    output wire             node_we,
    output wire             edge_we,
    output wire             irq_ack
);

    localparam integer AB = `STRAND_REG_ADDR_BITS;

    assign cmd_init = cfg_we && cfg_addr == `STRAND_REG_CMD && cfg_data[0];
    assign pin_we   = cfg_we && cfg_addr == `STRAND_REG_PIN;
    assign node_we  = cfg_we && cfg_addr == `STRAND_REG_NODE;
    assign edge_we  = cfg_we && cfg_addr == `STRAND_REG_EDGE;
    assign irq_ack  = cfg_we && cfg_addr == `STRAND_REG_IRQ_ACK;

    // which registers the build uses
    localparam [0:0] USE_REST    = !GRAPH && (EN_CONSTRAINTS || EN_SPRINGS);  // a chain's links
    localparam [0:0] USE_IMPULSE = EN_MOUSE && !GRAB;
    localparam [0:0] USE_BOX     = EN_MOUSE;
    localparam [0:0] USE_LAYOUT  = !GRAPH;   // START, STEP, PREV: the init walk
    localparam [0:0] USE_LOAD    = GRAPH;    // LOAD_*, EDGE_REST: NODE and EDGE writes

    // ---- the scalar constants ----
    reg [W-1:0] rest_q, impulse_q, ks_q, kd_q, ground_q, friction_q, edge_rest_q;
    always @(posedge clk) begin
        if (reset) begin
            rest_q      <= {W{1'b0}};
            impulse_q   <= {W{1'b0}};
            ks_q        <= {W{1'b0}};
            kd_q        <= {W{1'b0}};
            ground_q    <= {W{1'b0}};
            friction_q  <= {W{1'b0}};
            edge_rest_q <= {W{1'b0}};
        end else if (cfg_we) begin
            case (cfg_addr)
                `STRAND_REG_DIST:      rest_q      <= cfg_data;
                `STRAND_REG_IMPULSE:   impulse_q   <= cfg_data;
                `STRAND_REG_KS:        ks_q        <= cfg_data;
                `STRAND_REG_KD:        kd_q        <= cfg_data;
                `STRAND_REG_GROUND:    ground_q    <= cfg_data;
                `STRAND_REG_FRICTION:  friction_q  <= cfg_data;
                `STRAND_REG_EDGE_REST: edge_rest_q <= cfg_data;
                default: ;
            endcase
        end
    end
    assign rest_len  = USE_REST    ? rest_q      : {W{1'b0}};
    assign impulse   = USE_IMPULSE ? impulse_q   : {W{1'b0}};
    assign ks        = EN_SPRINGS  ? ks_q        : {W{1'b0}};
    assign kd        = EN_SPRINGS  ? kd_q        : {W{1'b0}};
    assign ground    = EN_GROUND   ? ground_q    : {W{1'b0}};
    assign friction  = EN_GROUND   ? friction_q  : {W{1'b0}};
    assign edge_rest = USE_LOAD    ? edge_rest_q : {W{1'b0}};

    // ---- the per-axis constants: one lane per axis, each register at its axis's address ----
    localparam [3*AB-1:0] A_BOX   = {`STRAND_REG_BOX_Z,   `STRAND_REG_BOX_Y,   `STRAND_REG_BOX_X};
    localparam [3*AB-1:0] A_START = {`STRAND_REG_START_Z, `STRAND_REG_START_Y, `STRAND_REG_START_X};
    localparam [3*AB-1:0] A_STEP  = {`STRAND_REG_STEP_Z,  `STRAND_REG_STEP_Y,  `STRAND_REG_STEP_X};
    localparam [3*AB-1:0] A_PREV  = {`STRAND_REG_PREV_Z,  `STRAND_REG_PREV_Y,  `STRAND_REG_PREV_X};
    localparam [3*AB-1:0] A_LOAD  = {`STRAND_REG_LOAD_Z,  `STRAND_REG_LOAD_Y,  `STRAND_REG_LOAD_X};
    localparam [3*AB-1:0] A_LOADP = {`STRAND_REG_LOAD_PZ, `STRAND_REG_LOAD_PY, `STRAND_REG_LOAD_PX};
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            reg [W-1:0] box_q, start_q, step_q, prev_q, load_q, loadp_q;
            always @(posedge clk) begin
                if (reset) begin
                    box_q   <= {W{1'b0}};
                    start_q <= {W{1'b0}};
                    step_q  <= {W{1'b0}};
                    prev_q  <= {W{1'b0}};
                    load_q  <= {W{1'b0}};
                    loadp_q <= {W{1'b0}};
                end else if (cfg_we) begin
                    if (cfg_addr == A_BOX[k*AB +: AB])   box_q   <= cfg_data;
                    if (cfg_addr == A_START[k*AB +: AB]) start_q <= cfg_data;
                    if (cfg_addr == A_STEP[k*AB +: AB])  step_q  <= cfg_data;
                    if (cfg_addr == A_PREV[k*AB +: AB])  prev_q  <= cfg_data;
                    if (cfg_addr == A_LOAD[k*AB +: AB])  load_q  <= cfg_data;
                    if (cfg_addr == A_LOADP[k*AB +: AB]) loadp_q <= cfg_data;
                end
            end
            assign box[k*W +: W]       = USE_BOX ? box_q : {W{1'b0}};
            assign start_pos[k*W +: W] = USE_LAYOUT ? start_q : {W{1'b0}};
            assign step_pos[k*W +: W]  = USE_LAYOUT ? step_q : {W{1'b0}};
            assign prev_off[k*W +: W]  = USE_LAYOUT ? prev_q : {W{1'b0}};
            assign load_pos[k*W +: W]  = USE_LOAD ? load_q : {W{1'b0}};
            assign load_prev[k*W +: W] = USE_LOAD ? loadp_q : {W{1'b0}};
        end
    endgenerate

    // ---- the effects table's constants (strand_regs.vh, generated by scripts/gen_effects.py):
    // a register each (a vector's a lane per axis), 0 without the effect ----
    `STRAND_EFFECT_REGFILE

endmodule

`resetall
