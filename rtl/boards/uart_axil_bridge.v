`default_nettype none
`timescale 1ns / 1ps

/*
 * uart_axil_bridge - a serial link to an AXI4-Lite slave: the host's reads and writes of
 * strand_axil's registers (its address map: rtl/strand_axil.v) over a UART.
 *
 * Protocol (bytes, big-endian fields; `strand board` is the host side):
 *   host  'W' (0x57)  A[15:8] A[7:0]  D[31:24] D[23:16] D[15:8] D[7:0]
 *   board resp                      (0x00 OKAY, 0x02 SLVERR: the slave's BRESP)
 *   host  'R' (0x52)  A[15:8] A[7:0]
 *   board resp  D[31:24] D[23:16] D[15:8] D[7:0]   (RRESP, then RDATA)
 *   any other first byte: the board answers 0xFF and waits for a command again.
 * One transaction at a time: the bridge issues the write (address and data together,
 * all byte strobes) or the read once the command is complete, waits for the response,
 * sends the answer, then takes the next command. Addresses above AW bits are cut.
 */
module uart_axil_bridge #(
    parameter integer CLKS_PER_BIT = 104,
    parameter integer AW           = 13     // the slave's address bits
) (
    input  wire          clk,
    input  wire          reset,             // synchronous, active high
    input  wire          rx,
    output wire          tx,
    // AXI4-Lite master
    output reg  [AW-1:0] m_axil_awaddr,
    output reg           m_axil_awvalid,
    input  wire          m_axil_awready,
    output reg  [31:0]   m_axil_wdata,
    output reg           m_axil_wvalid,
    input  wire          m_axil_wready,
    input  wire [1:0]    m_axil_bresp,
    input  wire          m_axil_bvalid,
    output wire          m_axil_bready,
    output reg  [AW-1:0] m_axil_araddr,
    output reg           m_axil_arvalid,
    input  wire          m_axil_arready,
    input  wire [31:0]   m_axil_rdata,
    input  wire [1:0]    m_axil_rresp,
    input  wire          m_axil_rvalid,
    output wire          m_axil_rready
);
    wire       rx_valid;
    wire [7:0] rx_data;
    reg        tx_start;
    reg  [7:0] tx_data;
    wire       tx_ready;
    uart_rx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_rx (.clk(clk), .reset(reset), .rx(rx), .valid(rx_valid), .data(rx_data));
    uart_tx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_tx (.clk(clk), .reset(reset), .start(tx_start), .data(tx_data),
                                                 .ready(tx_ready), .tx(tx));

    localparam [2:0] S_CMD = 3'd0, S_ARGS = 3'd1, S_BUS = 3'd2, S_SEND = 3'd3;
    localparam [7:0] CMD_W = 8'h57, CMD_R = 8'h52, NAK = 8'hFF;
    reg [2:0]  state;
    reg        is_write;
    reg [2:0]  args_left;        // argument bytes still to come
    reg [47:0] args;             // address (16) and data (32), shifted in
    reg [39:0] answer;           // bytes to send, the first in [39:32]
    reg [2:0]  send_left;
    assign m_axil_bready = state == S_BUS;
    assign m_axil_rready = state == S_BUS;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [15:0] addr16 = is_write ? args[47:32] : args[15:0];   // where the address landed
    /* verilator lint_on UNUSEDSIGNAL */

    always @(posedge clk) begin
        tx_start <= 1'b0;
        if (reset) begin
            state          <= S_CMD;
            m_axil_awvalid <= 1'b0;
            m_axil_wvalid  <= 1'b0;
            m_axil_arvalid <= 1'b0;
            send_left      <= 3'd0;
        end else case (state)
            S_CMD: if (rx_valid) begin
                if (rx_data == CMD_W || rx_data == CMD_R) begin
                    is_write  <= rx_data == CMD_W;
                    args_left <= rx_data == CMD_W ? 3'd6 : 3'd2;
                    state     <= S_ARGS;
                end else begin
                    answer    <= {NAK, 32'd0};
                    send_left <= 3'd1;
                    state     <= S_SEND;
                end
            end
            S_ARGS: if (rx_valid) begin
                args      <= {args[39:0], rx_data};
                args_left <= args_left - 1'b1;
                if (args_left == 3'd1) state <= S_BUS;
            end
            S_BUS: begin
                // issue once on entry (valid low), then hold until each is taken
                if (!m_axil_awvalid && !m_axil_wvalid && !m_axil_arvalid && send_left == 0) begin
                    if (is_write) begin
                        m_axil_awaddr  <= addr16[AW-1:0];
                        m_axil_wdata   <= args[31:0];
                        m_axil_awvalid <= 1'b1;
                        m_axil_wvalid  <= 1'b1;
                    end else begin
                        m_axil_araddr  <= addr16[AW-1:0];
                        m_axil_arvalid <= 1'b1;
                    end
                    send_left <= 3'd7;   // marks "issued" until the response comes
                end
                if (m_axil_awvalid && m_axil_awready) m_axil_awvalid <= 1'b0;
                if (m_axil_wvalid && m_axil_wready) m_axil_wvalid <= 1'b0;
                if (m_axil_arvalid && m_axil_arready) m_axil_arvalid <= 1'b0;
                if (m_axil_bvalid && send_left == 3'd7) begin
                    answer    <= {6'd0, m_axil_bresp, 32'd0};
                    send_left <= 3'd1;
                    state     <= S_SEND;
                end
                if (m_axil_rvalid && send_left == 3'd7) begin
                    answer    <= {6'd0, m_axil_rresp, m_axil_rdata};
                    send_left <= 3'd5;
                    state     <= S_SEND;
                end
            end
            S_SEND: if (tx_ready && !tx_start) begin
                if (send_left == 0) state <= S_CMD;
                else begin
                    tx_data   <= answer[39:32];
                    tx_start  <= 1'b1;
                    answer    <= {answer[31:0], 8'd0};
                    send_left <= send_left - 1'b1;
                end
            end
            default: state <= S_CMD;
        endcase
    end
endmodule

`resetall
