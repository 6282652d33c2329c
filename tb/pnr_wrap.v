`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"

/*
 * pnr_wrap - strand_axil with its bus behind shift registers, so that place and route
 * can measure it on a device whatever its pin count (make synth: ECP5, iCE40 UP5K).
 *
 * Five pins besides the clock: reset, sin, load, sout (and nothing else). reset and load
 * are registered once where they enter, as a board's synchronisers would. Every AXI4-Lite
 * input of the shell comes from a register that `load` fills from a serial shift
 * register (sin, one bit a cycle); every output goes to a register that `load`
 * captures and that shifts out on sout. So every path that ends or starts at the
 * shell is register to register in the one clock domain, and the fmax nextpnr reports
 * is the core's and the shell's own. This is a measurement fixture, not a way to
 * drive the core (a board top does that with a real link).
 */
module pnr_wrap #(
`include "strand_params.vh"
) (
    input  wire clk,
    input  wire reset,
    input  wire sin,
    input  wire load,
    output wire sout
);
    localparam integer A = AXIL_AW;
    // awaddr, awprot, awvalid, wdata, wstrb, wvalid, bready, araddr, arprot, arvalid, rready
    localparam integer IN_W  = 2 * A + 2 * 3 + 32 + 4 + 5;
    // awready, wready, bresp, bvalid, arready, rdata, rresp, rvalid, irq
    localparam integer OUT_W = 1 + 1 + 2 + 1 + 1 + 32 + 2 + 1 + 1;

    // reset and load through a register, as a board's synchronisers give them: the pins'
    // own delay is then not on the paths of the registers they clear or enable
    reg reset_q, load_q;
    always @(posedge clk) begin
        reset_q <= reset;
        load_q  <= load;
    end

    reg  [IN_W-1:0]  shift_in, in_q;
    reg  [OUT_W-1:0] out_q;
    wire [OUT_W-1:0] outs;
    always @(posedge clk) begin
        shift_in <= {shift_in[IN_W-2:0], sin};
        if (load_q) in_q <= shift_in;
        out_q <= load_q ? outs : {1'b0, out_q[OUT_W-1:1]};
    end
    assign sout = out_q[0];

    wire [A-1:0]  awaddr, araddr;
    wire [2:0]    awprot, arprot;
    wire [31:0]   wdata;
    wire [3:0]    wstrb;
    wire          awvalid, wvalid, bready, arvalid, rready;
    assign {awaddr, awprot, awvalid, wdata, wstrb, wvalid, bready, araddr, arprot, arvalid, rready} = in_q;

    strand_axil #(
`include "strand_params_pass.vh"
    ) u_axil (
        .clk(clk), .reset(reset_q),
        .s_axil_awaddr(awaddr), .s_axil_awprot(awprot), .s_axil_awvalid(awvalid), .s_axil_awready(outs[0]),
        .s_axil_wdata(wdata), .s_axil_wstrb(wstrb), .s_axil_wvalid(wvalid), .s_axil_wready(outs[1]),
        .s_axil_bresp(outs[3:2]), .s_axil_bvalid(outs[4]), .s_axil_bready(bready),
        .s_axil_araddr(araddr), .s_axil_arprot(arprot), .s_axil_arvalid(arvalid), .s_axil_arready(outs[5]),
        .s_axil_rdata(outs[37:6]), .s_axil_rresp(outs[39:38]), .s_axil_rvalid(outs[40]), .s_axil_rready(rready),
        .irq(outs[41]));
endmodule

`resetall
