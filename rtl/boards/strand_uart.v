`default_nettype none
`timescale 1ns / 1ps

`include "strand_defs.vh"
`include "params.vh"

/*
 * strand_uart - strand_axil behind a serial link (uart_axil_bridge): the core the board
 * tops instantiate. Its parameters default to the build of the params.vh that
 * `strand hwgen SCENE DIR` writes (make bitstream makes it from SCENE); a board top
 * passes DEBUG = 0 and its clock's CLKS_PER_BIT.
 */
module strand_uart #(
`include "strand_params_scene.vh"
    ,
    parameter integer CLKS_PER_BIT = 104   // clock / baud rate
) (
    input  wire clk,
    input  wire reset,      // synchronous, active high
    input  wire rx,         // from the host
    output wire tx,         // to the host
    output wire irq         // a frame finished (level, until STATUS bit 1 is written 1)
);
    wire [AXIL_AW-1:0] awaddr, araddr;
    wire        awvalid, awready, wvalid, wready, bvalid, bready, arvalid, arready, rvalid, rready;
    wire [31:0] wdata, rdata;
    wire [1:0]  bresp, rresp;
    uart_axil_bridge #(.CLKS_PER_BIT(CLKS_PER_BIT), .AW(AXIL_AW)) u_bridge (
        .clk(clk), .reset(reset), .rx(rx), .tx(tx),
        .m_axil_awaddr(awaddr), .m_axil_awvalid(awvalid), .m_axil_awready(awready),
        .m_axil_wdata(wdata), .m_axil_wvalid(wvalid), .m_axil_wready(wready),
        .m_axil_bresp(bresp), .m_axil_bvalid(bvalid), .m_axil_bready(bready),
        .m_axil_araddr(araddr), .m_axil_arvalid(arvalid), .m_axil_arready(arready),
        .m_axil_rdata(rdata), .m_axil_rresp(rresp), .m_axil_rvalid(rvalid), .m_axil_rready(rready));
    strand_axil #(
`include "strand_params_pass.vh"
    ) u_core (
        .clk(clk), .reset(reset),
        .s_axil_awaddr(awaddr), .s_axil_awprot(3'b000), .s_axil_awvalid(awvalid), .s_axil_awready(awready),
        .s_axil_wdata(wdata), .s_axil_wstrb(4'hF), .s_axil_wvalid(wvalid), .s_axil_wready(wready),
        .s_axil_bresp(bresp), .s_axil_bvalid(bvalid), .s_axil_bready(bready),
        .s_axil_araddr(araddr), .s_axil_arprot(3'b000), .s_axil_arvalid(arvalid), .s_axil_arready(arready),
        .s_axil_rdata(rdata), .s_axil_rresp(rresp), .s_axil_rvalid(rvalid), .s_axil_rready(rready),
        .irq(irq));
endmodule

`resetall
