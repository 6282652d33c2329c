`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_uart - the board tops' serial link (rtl/boards/uart_rx.v, uart_tx.v,
 * uart_axil_bridge.v) on the line faults a real cable gives, under Icarus.
 *
 *  1. 64 random bytes, uart_tx to uart_rx back to back: each arrives once, in order.
 *  2. Senders 3 % slow and 3 % fast (bit times of CPB - 1 and CPB + 1 cycles).
 *  3. A framing error (the stop bit low for a whole bit, then idle) and a break (the line
 *     low for three frames): no byte, and the next frame arrives as sent (the receiver
 *     waits for the line to go high again).
 *  4. Glitches: the line low for fewer cycles than half a bit gives no byte.
 *  5. The bridge (its own receiver and transmitter) against a behavioural AXI4-Lite slave:
 *     a write, a read of it back, a slave error passed on as the response byte, and a
 *     command byte that is neither 'W' nor 'R' answered with 0xFF, after which the next
 *     command works.
 * Prints one PASS line, or FAIL lines and exits with $fatal.
 */
module tb_uart;
    localparam integer CPB = 32;                // clocks per bit: short, so that the bench is quick
    reg clk = 1'b0, reset = 1'b1;
    always #5 clk = ~clk;
    integer errors = 0;
    integer i, base, seed;

    // ---- 1-4: uart_tx and a hand-driven line into uart_rx ----
    reg        tx_start = 1'b0;
    reg  [7:0] tx_data = 8'd0;
    wire       tx_ready, tx_line;
    uart_tx #(.CLKS_PER_BIT(CPB)) u_tx (.clk(clk), .reset(reset), .start(tx_start), .data(tx_data),
                                        .ready(tx_ready), .tx(tx_line));
    reg        manual = 1'b0, manual_line = 1'b1;
    wire       line = manual ? manual_line : tx_line;
    wire       rx_valid;
    wire [7:0] rx_data;
    uart_rx #(.CLKS_PER_BIT(CPB)) u_rx (.clk(clk), .reset(reset), .rx(line), .valid(rx_valid), .data(rx_data));

    reg [7:0] got [0:255];
    integer   n_got = 0;
    always @(posedge clk) if (rx_valid) begin
        got[n_got[7:0]] <= rx_data;
        n_got <= n_got + 1;
    end


    // one frame by hand: bit time `period` cycles, the stop bit at `stop`
    task send_manual(input [7:0] b, input integer period, input stop);
        integer i;
        begin
            manual = 1'b1;
            manual_line = 1'b0;
            repeat (period) @(posedge clk);
            for (i = 0; i < 8; i = i + 1) begin
                manual_line = b[i];
                repeat (period) @(posedge clk);
            end
            manual_line = stop;
            repeat (period) @(posedge clk);
            manual_line = 1'b1;
        end
    endtask

    task idle(input integer bits);
        begin
            manual_line = 1'b1;
            repeat (bits * CPB) @(posedge clk);
        end
    endtask

    task expect_bytes(input integer n, input [8*40-1:0] what);
        begin
            if (n_got != n) begin
                $display("FAIL tb_uart %0s: %0d bytes received, %0d expected", what, n_got, n);
                errors = errors + 1;
            end
        end
    endtask

    task expect_byte(input integer k, input [7:0] b, input [8*40-1:0] what);
        begin
            if (got[k] !== b) begin
                $display("FAIL tb_uart %0s: byte %0d is %02x, %02x was sent", what, k, got[k], b);
                errors = errors + 1;
            end
        end
    endtask

    // after a line fault that began when `base` bytes had come: none more, then a good
    // frame arrives as sent
    task nothing_then_a_frame(input [7:0] b, input [8*40-1:0] what);
        begin
            expect_bytes(base, what);
            send_manual(b, CPB, 1'b1);
            idle(2);
            expect_bytes(base + 1, what);
            expect_byte(base, b, what);
        end
    endtask

    // ---- 5: the bridge and a behavioural AXI4-Lite slave ----
    reg        h_start = 1'b0;
    reg  [7:0] h_data = 8'd0;
    wire       h_ready, h_line, br_tx;
    uart_tx #(.CLKS_PER_BIT(CPB)) u_host_tx (.clk(clk), .reset(reset), .start(h_start), .data(h_data),
                                             .ready(h_ready), .tx(h_line));
    wire       a_valid;
    wire [7:0] a_data;
    uart_rx #(.CLKS_PER_BIT(CPB)) u_host_rx (.clk(clk), .reset(reset), .rx(br_tx), .valid(a_valid), .data(a_data));
    wire [12:0] awaddr, araddr;
    wire [31:0] wdata;
    wire        awvalid, wvalid, bready, arvalid, rready;
    reg         bvalid = 1'b0, rvalid = 1'b0;
    reg  [1:0]  bresp = 2'b00, rresp = 2'b00;
    reg  [31:0] rdata = 32'd0;
    uart_axil_bridge #(.CLKS_PER_BIT(CPB), .AW(13)) u_bridge (
        .clk(clk), .reset(reset), .rx(h_line), .tx(br_tx),
        .m_axil_awaddr(awaddr), .m_axil_awvalid(awvalid), .m_axil_awready(1'b1),
        .m_axil_wdata(wdata), .m_axil_wvalid(wvalid), .m_axil_wready(1'b1),
        .m_axil_bresp(bresp), .m_axil_bvalid(bvalid), .m_axil_bready(bready),
        .m_axil_araddr(araddr), .m_axil_arvalid(arvalid), .m_axil_arready(1'b1),
        .m_axil_rdata(rdata), .m_axil_rresp(rresp), .m_axil_rvalid(rvalid), .m_axil_rready(rready));
    // 16 words at 0x000..0x03C; any other address answers SLVERR (2'b10)
    reg [31:0] mem [0:15];
    always @(posedge clk) begin
        if (awvalid && wvalid && !bvalid) begin
            if (awaddr < 13'h40) mem[awaddr[5:2]] <= wdata;
            bresp  <= awaddr < 13'h40 ? 2'b00 : 2'b10;
            bvalid <= 1'b1;
        end else if (bvalid && bready) bvalid <= 1'b0;
        if (arvalid && !rvalid) begin
            rdata  <= araddr < 13'h40 ? mem[araddr[5:2]] : 32'hDEAD_BEEF;
            rresp  <= araddr < 13'h40 ? 2'b00 : 2'b10;
            rvalid <= 1'b1;
        end else if (rvalid && rready) rvalid <= 1'b0;
    end
    reg [7:0] ans [0:15];
    integer   n_ans = 0;
    always @(posedge clk) if (a_valid) begin
        ans[n_ans[3:0]] <= a_data;
        n_ans <= n_ans + 1;
    end

    // one byte through a transmitter once it is ready: u_host_tx (to the bridge) or u_tx
    task send(input to_bridge, input [7:0] b);
        begin
            @(posedge clk);
            while (!(to_bridge ? h_ready : tx_ready)) @(posedge clk);
            if (to_bridge) {h_data, h_start} <= {b, 1'b1};
            else {tx_data, tx_start} <= {b, 1'b1};
            @(posedge clk);
            {h_start, tx_start} <= 2'b00;
        end
    endtask

    task host(input [7:0] b);
        send(1'b1, b);
    endtask

    // wait until n answer bytes have come (or time out), then check them
    task answers(input integer n);
        integer t;
        begin
            t = 0;
            while (n_ans < n && t < 40 * CPB * 10) begin
                @(posedge clk);
                t = t + 1;
            end
            repeat (2 * CPB * 10) @(posedge clk);    // and nothing more comes
        end
    endtask

    task expect_answer(input integer k, input [7:0] b, input [8*40-1:0] what);
        begin
            if (k >= n_ans || ans[k] !== b) begin
                $display("FAIL tb_uart bridge %0s: answer byte %0d is %02x, %02x expected (%0d bytes)", what, k,
                         k < n_ans ? ans[k] : 8'hxx, b, n_ans);
                errors = errors + 1;
            end
        end
    endtask

    reg [7:0] sent [0:63];
    initial begin
        seed = 7;
        repeat (4) @(posedge clk);
        reset <= 1'b0;
        repeat (4) @(posedge clk);

        // 1. back to back
        for (i = 0; i < 64; i = i + 1) begin
            sent[i] = $random(seed);
            send(1'b0, sent[i]);
        end
        repeat (12 * CPB) @(posedge clk);
        expect_bytes(64, "back to back");
        for (i = 0; i < 64; i = i + 1) expect_byte(i, sent[i], "back to back");

        // 2. 3 % slow and fast senders
        base = n_got;
        send_manual(8'hC3, CPB + 1, 1'b1);
        idle(2);
        send_manual(8'h3C, CPB - 1, 1'b1);
        idle(2);
        expect_bytes(base + 2, "baud off by 3 %");
        expect_byte(base, 8'hC3, "3 % slow");
        expect_byte(base + 1, 8'h3C, "3 % fast");

        // 3. a framing error, then a good frame
        base = n_got;
        send_manual(8'hA5, CPB, 1'b0);
        idle(3);
        nothing_then_a_frame(8'h5A, "a framing error");

        // a break: the line low for three frames (a cable pulled), then a good frame
        base = n_got;
        manual_line = 1'b0;
        repeat (30 * CPB) @(posedge clk);
        idle(3);
        nothing_then_a_frame(8'h96, "a break");

        // 4. glitches shorter than half a bit
        base = n_got;
        for (i = 1; i < CPB / 2 - 2; i = i + 3) begin
            manual_line = 1'b0;
            repeat (i) @(posedge clk);
            idle(2);
        end
        expect_bytes(base, "glitches");
        manual = 1'b0;

        // 5. the bridge: write 0x12345678 to 0x008, read it back, an error, a bad command
        host("W"); host(8'h00); host(8'h08); host(8'h12); host(8'h34); host(8'h56); host(8'h78);
        answers(1);
        expect_answer(0, 8'h00, "write OKAY");
        host("R"); host(8'h00); host(8'h08);
        answers(6);
        expect_answer(1, 8'h00, "read OKAY");
        expect_answer(2, 8'h12, "read data");
        expect_answer(3, 8'h34, "read data");
        expect_answer(4, 8'h56, "read data");
        expect_answer(5, 8'h78, "read data");
        host("W"); host(8'h01); host(8'h00); host(8'h00); host(8'h00); host(8'h00); host(8'h01);
        answers(7);
        expect_answer(6, 8'h02, "write SLVERR");
        host(8'h3F);
        answers(8);
        expect_answer(7, 8'hFF, "a bad command");
        host("R"); host(8'h00); host(8'h08);
        answers(13);
        expect_answer(8, 8'h00, "read after a bad command");
        expect_answer(12, 8'h78, "read after a bad command");
        if (n_ans != 13) begin
            $display("FAIL tb_uart bridge: %0d answer bytes, 13 expected", n_ans);
            errors = errors + 1;
        end

        if (errors == 0)
            $display("PASS tb_uart: 64 bytes back to back, senders 3 %% slow and fast, a framing error, a break, glitches, and the bridge's write, read, slave error and bad command (%0d clocks a bit)", CPB);
        else
            $fatal(1, "FAIL tb_uart: %0d errors", errors);
        $finish;
    end
endmodule

`resetall
