`default_nettype none
`timescale 1ns / 1ps

/*
 * uart_rx - an 8N1 serial receiver (the host link of the board tops).
 *
 * Algorithm: the line idles high. A falling edge (high one cycle, low the next, so that
 * a line still low after a framing error or in a break starts nothing) starts a frame;
 * the line is sampled in the middle of the start bit (CLKS_PER_BIT / 2 cycles later: a
 * start bit no longer low there is a glitch and is dropped), then in the middle of each
 * of the 8 data bits (LSB first) and of the stop bit. A frame whose stop bit is high gives valid for one
 * cycle with data; a low stop bit (a framing error) gives nothing. The input passes two
 * flip-flops first (it comes from another clock domain).
 * Latency: valid comes 9.5 bit times after the start edge. Throughput: one byte a frame.
 * CLKS_PER_BIT = clock / baud rate, at least 4 (12 MHz / 115200: 104, 0.2 % off).
 */
module uart_rx #(
    parameter integer CLKS_PER_BIT = 104
) (
    input  wire       clk,
    input  wire       reset,   // synchronous, active high
    input  wire       rx,      // the serial line
    output reg        valid,   // one cycle: data holds a received byte
    output reg  [7:0] data
);
    localparam integer CW = $clog2(CLKS_PER_BIT + 1);
    localparam integer  HALF_I = CLKS_PER_BIT / 2, FULL_I = CLKS_PER_BIT - 1;
    localparam [CW-1:0] HALF = HALF_I[CW-1:0], FULL = FULL_I[CW-1:0];
    reg [1:0]    sync;                 // the two synchronising flip-flops
    reg          line_q;               // the line a cycle ago: a start is a falling edge
    reg [CW-1:0] count;
    reg [3:0]    bit_idx;              // 0: start bit, 1..8: data, 9: stop
    reg          busy;
    wire         line = sync[1];
    always @(posedge clk) begin
        sync   <= reset ? 2'b11 : {sync[0], rx};
        line_q <= reset ? 1'b1 : line;
        valid <= 1'b0;
        if (reset) begin
            busy    <= 1'b0;
            count   <= {CW{1'b0}};
            bit_idx <= 4'd0;
        end else if (!busy) begin
            if (!line && line_q) begin // a start edge: wait half a bit
                busy    <= 1'b1;
                count   <= HALF;
                bit_idx <= 4'd0;
            end
        end else if (count != 0) begin
            count <= count - 1'b1;
        end else begin                 // the middle of a bit
            count <= FULL;
            if (bit_idx == 4'd0) begin
                if (line) busy <= 1'b0;  // a glitch, not a start bit
            end else if (bit_idx <= 4'd8) begin
                data <= {line, data[7:1]};
            end else begin
                busy  <= 1'b0;
                valid <= line;           // the stop bit must be high
            end
            bit_idx <= bit_idx + 1'b1;
        end
    end
endmodule

`resetall
