// stub_strand_core - a stand-in for rtl/strand_core.v in the proof of the AXI4-Lite shell
// (tb/formal/axil.sby): the same ports and parameters, and every output (busy, frame_done,
// irq, the node read port) chosen by the solver in every cycle. The shell's protocol
// properties must hold whatever the core does, so they hold with the real core.
`default_nettype none

`include "strand_regs.vh"

module strand_core #(
`include "strand_params.vh"
) (
    input  wire            clk,
    input  wire            reset,
    input  wire            cfg_we,
    input  wire [`STRAND_REG_ADDR_BITS-1:0] cfg_addr,
    input  wire [W-1:0]    cfg_data,
    input  wire            step,
    output wire            busy,
    output wire            frame_done,
    output wire            irq,
    input  wire [W-1:0]    mouse_x,
    input  wire [W-1:0]    mouse_y,
    input  wire [W-1:0]    mouse_z,
    input  wire            mouse_down,
    input  wire [AW-1:0]   rd_addr,
    output wire [W-1:0]    rd_x,
    output wire [W-1:0]    rd_y,
    output wire [W-1:0]    rd_z,
    output wire [DBG_W-1:0] dbg
);
    (* anyseq *) reg          busy_a, done_a, irq_a;
    (* anyseq *) reg [W-1:0]  x_a, y_a, z_a;
    assign busy = busy_a;
    assign frame_done = done_a;
    assign irq = irq_a;
    assign rd_x = x_a;
    assign rd_y = y_a;
    assign rd_z = z_a;
    assign dbg = {DBG_W{1'b0}};
    wire unused = &{1'b0, clk, reset, cfg_we, cfg_addr, cfg_data, step, mouse_x, mouse_y, mouse_z, mouse_down, rd_addr};
endmodule

`resetall
