`default_nettype none
`timescale 1ns / 1ps

/*
 * ulx3s_top - Strand on a ULX3S (ECP5-85F, 25 MHz): the host link is the FTDI UART at
 * 115200 baud (ftdi_txd in, ftdi_rxd out; ulx3s.lpf). btn[1] (F1) resets the core; led[0]
 * is on during reset, led[1] while a finished frame waits to be acknowledged (the irq).
 * wifi_gpio0 is held high so that the ESP32 does not reset the FPGA.
 */
module ulx3s_top (
    input  wire       clk_25mhz,
    input  wire       ftdi_txd,   // from the host
    output wire       ftdi_rxd,   // to the host
    input  wire [6:0] btn,        // btn[0] is active low, the others active high
    output wire [7:0] led,
    output wire       wifi_gpio0
);
    reg [10:0] por = 11'd0;
    always @(posedge clk_25mhz) if (!por[10]) por <= por + 1'b1;
    reg [1:0] btn_sync = 2'b00;
    always @(posedge clk_25mhz) btn_sync <= {btn_sync[0], btn[1]};
    wire reset = !por[10] || btn_sync[1];
    wire irq;
    strand_uart #(.DEBUG(1'b0), .CLKS_PER_BIT(217)) u_strand (
        .clk(clk_25mhz), .reset(reset), .rx(ftdi_txd), .tx(ftdi_rxd), .irq(irq));
    assign led = {6'd0, irq, reset};
    assign wifi_gpio0 = 1'b1;
    wire unused = &{1'b0, btn[6:2], btn[0]};
endmodule

`resetall
