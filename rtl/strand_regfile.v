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
 * box_neg is -box per axis, exact in W+1 bits, formed once here for every unit's
 * in-touch test.
 */
module strand_regfile #(
`include "strand_params.vh"
) (
    input  wire             clk,
    input  wire             reset,
    input  wire             cfg_we,
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]     cfg_data,

    output wire [DIM*W-1:0] gdt2,       // g h^2
    output wire [DIM*W-1:0] box,        // the mouse's in-touch half-widths
    output wire [DIM*W-1:0] box_neg,    // -box: low W bits ...
    output wire [DIM-1:0]   box_neg_top,//   ... and the top bit
    output wire [DIM*W-1:0] start_pos,  // the init walk: node 0, the step, the previous-position offset
    output wire [DIM*W-1:0] step_pos,
    output wire [DIM*W-1:0] prev_off,
    output wire [DIM*W-1:0] load_pos,   // a NODE write's position and previous position
    output wire [DIM*W-1:0] load_prev,
    output reg  [W-1:0]     rest_len,
    output reg  [W-1:0]     impulse,
    output reg  [W-1:0]     damping,
    output reg  [W-1:0]     ks,
    output reg  [W-1:0]     kd,
    output reg  [W-1:0]     ground,
    output reg  [W-1:0]     friction,
    output reg  [W-1:0]     edge_rest,

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

    // ---- the scalar constants ----
    always @(posedge clk) begin
        if (reset) begin
            rest_len  <= {W{1'b0}};
            impulse   <= {W{1'b0}};
            damping   <= {W{1'b0}};
            ks        <= {W{1'b0}};
            kd        <= {W{1'b0}};
            ground    <= {W{1'b0}};
            friction  <= {W{1'b0}};
            edge_rest <= {W{1'b0}};
        end else if (cfg_we) begin
            case (cfg_addr)
                `STRAND_REG_DIST:      rest_len  <= cfg_data;
                `STRAND_REG_IMPULSE:   impulse   <= cfg_data;
                `STRAND_REG_DAMPING:   damping   <= cfg_data;
                `STRAND_REG_KS:        ks        <= cfg_data;
                `STRAND_REG_KD:        kd        <= cfg_data;
                `STRAND_REG_GROUND:    ground    <= cfg_data;
                `STRAND_REG_FRICTION:  friction  <= cfg_data;
                `STRAND_REG_EDGE_REST: edge_rest <= cfg_data;
                default: ;
            endcase
        end
    end

    // ---- the per-axis constants: one lane per axis, each register at its axis's address ----
    localparam [3*AB-1:0] A_GDT2  = {`STRAND_REG_GDT2_Z,  `STRAND_REG_GDT2_Y,  `STRAND_REG_GDT2_X};
    localparam [3*AB-1:0] A_BOX   = {`STRAND_REG_BOX_Z,   `STRAND_REG_BOX_Y,   `STRAND_REG_BOX_X};
    localparam [3*AB-1:0] A_START = {`STRAND_REG_START_Z, `STRAND_REG_START_Y, `STRAND_REG_START_X};
    localparam [3*AB-1:0] A_STEP  = {`STRAND_REG_STEP_Z,  `STRAND_REG_STEP_Y,  `STRAND_REG_STEP_X};
    localparam [3*AB-1:0] A_PREV  = {`STRAND_REG_PREV_Z,  `STRAND_REG_PREV_Y,  `STRAND_REG_PREV_X};
    localparam [3*AB-1:0] A_LOAD  = {`STRAND_REG_LOAD_Z,  `STRAND_REG_LOAD_Y,  `STRAND_REG_LOAD_X};
    localparam [3*AB-1:0] A_LOADP = {`STRAND_REG_LOAD_PZ, `STRAND_REG_LOAD_PY, `STRAND_REG_LOAD_PX};
    genvar k;
    generate
        for (k = 0; k < DIM; k = k + 1) begin : g_lane
            reg [W-1:0] gdt2_q, box_q, start_q, step_q, prev_q, load_q, loadp_q;
            always @(posedge clk) begin
                if (reset) begin
                    gdt2_q  <= {W{1'b0}};
                    box_q   <= {W{1'b0}};
                    start_q <= {W{1'b0}};
                    step_q  <= {W{1'b0}};
                    prev_q  <= {W{1'b0}};
                    load_q  <= {W{1'b0}};
                    loadp_q <= {W{1'b0}};
                end else if (cfg_we) begin
                    if (cfg_addr == A_GDT2[k*AB +: AB])  gdt2_q  <= cfg_data;
                    if (cfg_addr == A_BOX[k*AB +: AB])   box_q   <= cfg_data;
                    if (cfg_addr == A_START[k*AB +: AB]) start_q <= cfg_data;
                    if (cfg_addr == A_STEP[k*AB +: AB])  step_q  <= cfg_data;
                    if (cfg_addr == A_PREV[k*AB +: AB])  prev_q  <= cfg_data;
                    if (cfg_addr == A_LOAD[k*AB +: AB])  load_q  <= cfg_data;
                    if (cfg_addr == A_LOADP[k*AB +: AB]) loadp_q <= cfg_data;
                end
            end
            wire [W:0] neg = {W+1{1'b0}} - {box_q[W-1], box_q};  // exact
            assign gdt2[k*W +: W]      = gdt2_q;
            assign box[k*W +: W]       = box_q;
            assign box_neg[k*W +: W]   = neg[W-1:0];
            assign box_neg_top[k]      = neg[W];
            assign start_pos[k*W +: W] = start_q;
            assign step_pos[k*W +: W]  = step_q;
            assign prev_off[k*W +: W]  = prev_q;
            assign load_pos[k*W +: W]  = load_q;
            assign load_prev[k*W +: W] = loadp_q;
        end
    endgenerate

endmodule

`resetall
