`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "strand_regs.vh"
`include "params.vh"

/*
 * sim_top - strand_core built for one scene, with its observation port unpacked:
 * the top the Verilator harness and the Icarus frame bench drive.
 *
 * Its parameters default to the build of the params.vh that 'strand hwgen SCENE DIR'
 * writes (DEBUG = 1 there), so the harness builds exactly the effects the scene
 * names. The ports are strand_core's, plus what the dbg port carries as named
 * signals: phase, FV, FEC, the walk (uidx, nidx, counter) and the write-back
 * lanes (wb_*: WB lanes, one a unit, or two with PAIR: lane u (1 + PAIR) + l is unit
 * u's write port l; z 0 in 2D).
 */
module sim_top #(
`include "strand_params_scene.vh"
) (
    input  wire            clk,
    input  wire            reset,
    input  wire [W-1:0]    mouse_x,
    input  wire [W-1:0]    mouse_y,
    input  wire [W-1:0]    mouse_z,
    input  wire            mouse_down,
    input  wire            step,
    output wire            busy,
    output wire            frame_done,
    output wire            irq,
    input  wire            cfg_we,
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]    cfg_data,
    input  wire [AW-1:0]   rd_addr,
    output wire [W-1:0]    rd_x,
    output wire [W-1:0]    rd_y,
    output wire [W-1:0]    rd_z,
    output wire [2:0]      phase,
    output wire            fv,
    output wire            fec,
    output wire [UW-1:0]   uidx,
    output wire [IW-1:0]   nidx,
    output wire [CW-1:0]   counter,
    output wire [WB-1:0]    wb_valid,
    output wire [WB*IW-1:0] wb_idx,
    output wire [WB*W-1:0]  wb_x,
    output wire [WB*W-1:0]  wb_y,
    output wire [WB*W-1:0]  wb_z
);
    `STRAND_CHECK(sim_top_needs_DEBUG, DEBUG == 1'b1, ("sim_top: the build must have DEBUG = 1 (in %m)"))
    wire [DBG_W-1:0] dbg;
    strand_core #(
`include "strand_params_pass.vh"
    ) u_core (
        .clk(clk), .reset(reset), .cfg_we(cfg_we), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .step(step), .busy(busy), .frame_done(frame_done), .irq(irq),
        .mouse_x(mouse_x), .mouse_y(mouse_y), .mouse_z(mouse_z), .mouse_down(mouse_down),
        .rd_addr(rd_addr), .rd_x(rd_x), .rd_y(rd_y), .rd_z(rd_z), .dbg(dbg));
    // the layout strand_core's header gives, LSB first
    assign {wb_z, wb_y, wb_x, wb_idx, wb_valid, counter, nidx, uidx, fec, fv, phase} = dbg;

    // The Q(W-F).F words as real numbers, for the trace only: GTKWave shows a real as a
    // decimal (177.85, where the raw word reads 728484). Nothing reads them, and a synthesis
    // of sim_top (scripts/gatesim.py: Yosys defines SYNTHESIS) leaves them out.
`ifndef SYNTHESIS
    /* verilator lint_off UNUSEDSIGNAL */
    localparam real ONE = 2.0 ** F;
    real mouse_x_val, mouse_y_val, mouse_z_val, rd_x_val, rd_y_val, rd_z_val;
    always @* begin
        mouse_x_val = $itor($signed(mouse_x)) / ONE;
        mouse_y_val = $itor($signed(mouse_y)) / ONE;
        mouse_z_val = $itor($signed(mouse_z)) / ONE;
        rd_x_val    = $itor($signed(rd_x)) / ONE;
        rd_y_val    = $itor($signed(rd_y)) / ONE;
        rd_z_val    = $itor($signed(rd_z)) / ONE;
    end
    genvar u;
    generate
        for (u = 0; u < WB; u = u + 1) begin : g_lane
            real wb_x_val, wb_y_val, wb_z_val;   // write-back lane u
            always @* begin
                wb_x_val = $itor($signed(wb_x[u*W +: W])) / ONE;
                wb_y_val = $itor($signed(wb_y[u*W +: W])) / ONE;
                wb_z_val = $itor($signed(wb_z[u*W +: W])) / ONE;
            end
        end
    endgenerate
    /* verilator lint_on UNUSEDSIGNAL */
`endif
endmodule

`resetall
