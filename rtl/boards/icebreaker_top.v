`default_nettype none
`timescale 1ns / 1ps

/*
 * icebreaker_top - Strand on an iCEBreaker (iCE40 UP5K, 12 MHz): the host link is the
 * FTDI's second channel at 115200 baud (RX pin 6, TX pin 9; icebreaker.pcf). The button
 * (BTN_N) resets the core; the red LED is on during reset, the green one while a
 * finished frame waits to be acknowledged (the core's irq).
 */
module icebreaker_top (
    input  wire CLK,      // 12 MHz
    input  wire RX,       // from the host
    output wire TX,       // to the host
    input  wire BTN_N,    // the user button, low when pressed
    output wire LEDR_N,
    output wire LEDG_N
);
    // reset: held for 2^10 cycles after configuration, and while the button is pressed
    reg [10:0] por = 11'd0;
    always @(posedge CLK) if (!por[10]) por <= por + 1'b1;
    reg [1:0] btn_sync = 2'b11;
    always @(posedge CLK) btn_sync <= {btn_sync[0], BTN_N};
    wire reset = !por[10] || !btn_sync[1];
    wire irq;
    strand_uart #(.DEBUG(1'b0), .CLKS_PER_BIT(104)) u_strand (
        .clk(CLK), .reset(reset), .rx(RX), .tx(TX), .irq(irq));
    assign LEDR_N = !reset;
    assign LEDG_N = !irq;
endmodule

`resetall
