`default_nettype none
`timescale 1ns / 1ps

/*
 * uart_tx - an 8N1 serial transmitter (the host link of the board tops).
 *
 * Algorithm: a byte taken while ready (start and ready in the same cycle) is sent as a
 * start bit (low), 8 data bits LSB first and a stop bit (high), each CLKS_PER_BIT cycles;
 * ready is high again the cycle after the stop bit ends. The line idles high.
 * Latency: the start bit is on the line the cycle after the byte is taken.
 * Throughput: one byte every 10 bit times.
 */
module uart_tx #(
    parameter integer CLKS_PER_BIT = 104
) (
    input  wire       clk,
    input  wire       reset,   // synchronous, active high
    input  wire       start,   // with ready: send data
    input  wire [7:0] data,
    output wire       ready,
    output reg        tx       // the serial line
);
    localparam integer CW = $clog2(CLKS_PER_BIT + 1);
    localparam integer  FULL_I = CLKS_PER_BIT - 1;
    localparam [CW-1:0] FULL = FULL_I[CW-1:0];
    reg [CW-1:0] count;
    reg [3:0]    bits_left;   // bits still to send after the one on the line
    reg [8:0]    shift;       // the data bits and the stop bit
    reg          busy;
    assign ready = !busy;
    always @(posedge clk) begin
        if (reset) begin
            busy <= 1'b0;
            tx   <= 1'b1;
            count <= {CW{1'b0}};
            bits_left <= 4'd0;
        end else if (!busy) begin
            if (start) begin
                busy      <= 1'b1;
                tx        <= 1'b0;           // the start bit
                shift     <= {1'b1, data};
                count     <= FULL;
                bits_left <= 4'd9;
            end
        end else if (count != 0) begin
            count <= count - 1'b1;
        end else if (bits_left != 0) begin
            tx        <= shift[0];
            shift     <= {1'b1, shift[8:1]};
            count     <= FULL;
            bits_left <= bits_left - 1'b1;
        end else begin
            busy <= 1'b0;                    // the stop bit has been on the line a bit time
        end
    end
endmodule

`resetall
