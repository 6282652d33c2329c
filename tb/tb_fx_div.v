`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_div - self-checking testbench for rtl/fx_div.v: values and timing.
 *
 * Reads vectors written by tb/gen_vectors.c (record: flags {0,0,sat,dbz}, num, den,
 * y). Plusargs: +vectors=FILE +n=COUNT +latency=L +name=NAME (L: model/timing.c
 * hw_div_latency, from tb/unit_latency.c).
 * The latency contract (start, busy, done) is tb/serial_latency_check.v's, instantiated here;
 * for every vector the bench checks the values, sampling the outputs between edges
 * (inputs are driven on the falling edge; start is sampled at edge 0):
 *   - after edges 0 .. L - 2: result and the flags still hold the previous operation's;
 *   - after edge L - 1 (the done cycle): result and the flags as expected;
 *   - done lasts one cycle (an idle cycle after every 4th vector, and the next
 *     operation, which otherwise starts back to back in the done cycle).
 * Every 3rd operation holds start high with random operands while busy, which
 * must be ignored. After reset, and after a reset in the middle of an operation,
 * busy, done, result and the flags must be 0.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_fx_div;

    parameter integer W         = 32;      // width under test
    parameter integer F         = 16;      // fraction bits under test
    parameter integer DIV_BITS  = W - 1;   // quotient bits resolved under test
    parameter integer MAXN      = 1 << 18; // capacity of the vector memory

    localparam integer FD = 4 * ((W + 3) / 4);     // a W-bit field padded to hex digits
    localparam integer RW = 4 + 3 * FD;            // record width

    reg [RW-1:0]     mem [0:MAXN-1];
    reg [8*64-1:0]   name;
    reg [8*256-1:0]  file;
    reg [8*600-1:0]  fail_msg;
    reg [8*200-1:0]  first_msg;
    integer          n, i, k, errors;
    reg [63:0]       cycles, limit;
    integer          LATENCY;  // start cycle to done cycle: +latency=, from model/timing.c
    wire [31:0]      contract_violations;

    reg              clk = 1'b0;
    reg              reset = 1'b1;
    reg              start = 1'b0;
    reg  [W-1:0]     num = {W{1'b0}};
    reg  [W-1:0]     den = {W{1'b0}};
    wire             busy, done, dbz, sat;
    wire [W-1:0]     result;

    reg  [W-1:0]     num_i, den_i;
    reg  [W-1:0]     y_exp, prev_y;
    reg              sat_exp, prev_sat, dbz_exp, prev_dbz;

    fx_div #(.W(W), .F(F), .DIV_BITS(DIV_BITS)) dut (
        .clk(clk), .reset(reset), .start(start), .num(num), .den(den),
        .busy(busy), .done(done), .result(result), .div_by_zero(dbz), .sat(sat));

    always #5 clk = !clk;

    serial_latency_check #(.DEPTH(72)) contract (.clk(clk), .reset(reset), .latency(LATENCY[15:0]), .start(start),
                                                 .busy(busy), .done(done), .violations(contract_violations));

    // Watchdog in clock cycles: every operation needs LATENCY at most.
    initial cycles = 64'd0;
    always @(posedge clk) begin
        cycles = cycles + 64'd1;
        if (cycles > limit) begin
            $display("FAIL %0s: timeout after %0d cycles", name, cycles);
            $fatal(1, "timeout");
        end
    end

    task check;
        input         cond;
        input integer edge_no;
        begin
            if (!cond) begin
                if (errors == 0)
                    $sformat(first_msg, "vector #%0d num=%h den=%h after edge %0d: busy=%b done=%b result=%h dbz=%b sat=%b, expected result=%h dbz=%b sat=%b",
                             i, num_i, den_i, edge_no, busy, done, result, dbz, sat, y_exp, dbz_exp, sat_exp);
                errors = errors + 1;
            end
        end
    endtask

    // Inputs while busy: idle, or start held high with random operands (ignored).
    task drive_busy;
        begin
            start = (i % 3 == 1);
            num = (i % 3 == 1) ? $random : num_i;
            den = (i % 3 == 1) ? $random : den_i;
        end
    endtask

`include "bench_vectors.vh"

    initial begin
        limit = 64'd1000;
        LATENCY = 2;
        load_vectors("tb_fx_div");
        load_latency(LATENCY, 3, 72);
        limit = n * (LATENCY + 1) + 1000;
        errors = 0;
        i = -1;
        num_i = 0; den_i = 0; y_exp = 0; sat_exp = 0; dbz_exp = 0;

        // Reset.
        repeat (2) @(posedge clk);
        @(negedge clk);
        reset = 1'b0;
        check(result === {W{1'b0}} && dbz === 1'b0 && sat === 1'b0, -1);
        prev_y = {W{1'b0}};
        prev_sat = 1'b0;
        prev_dbz = 1'b0;

        for (i = 0; i < n; i = i + 1) begin
            num_i   = mem[i][2*FD +: W];
            den_i   = mem[i][FD +: W];
            sat_exp = mem[i][RW-3];
            dbz_exp = mem[i][RW-4];
            y_exp   = mem[i][0 +: W];

            // Once, half way: a reset in the middle of an operation.
            if (i == n / 2) begin
                start = 1'b1;
                num = num_i;
                den = den_i;
                @(posedge clk); @(negedge clk);
                start = 1'b0;
                @(posedge clk); @(negedge clk);
                reset = 1'b1;
                @(posedge clk); @(negedge clk);
                reset = 1'b0;
                check(result === {W{1'b0}} && dbz === 1'b0 && sat === 1'b0, -2);
                @(posedge clk); @(negedge clk);
                check(result === {W{1'b0}} && dbz === 1'b0 && sat === 1'b0, -2);
                prev_y = {W{1'b0}};
                prev_sat = 1'b0;
                prev_dbz = 1'b0;
            end

            // Edge 0: start sampled (in the done cycle of the previous operation,
            // or after an idle cycle).
            start = 1'b1;
            num = num_i;
            den = den_i;
            @(posedge clk); @(negedge clk);
            drive_busy;
            check(result === prev_y && dbz === prev_dbz && sat === prev_sat, 0);
            // Edges 1 .. L - 2: iterations, nothing visible changes.
            for (k = 1; k <= LATENCY - 2; k = k + 1) begin
                @(posedge clk); @(negedge clk);
                drive_busy;
                check(result === prev_y && dbz === prev_dbz && sat === prev_sat, k);
            end
            // Edge L - 1: rounding iteration, result loaded, done.
            @(posedge clk); @(negedge clk);
            start = 1'b0;
            check(result === y_exp && dbz === dbz_exp && sat === sat_exp, LATENCY - 1);
            prev_y = y_exp;
            prev_sat = sat_exp;
            prev_dbz = dbz_exp;
            // Every 4th vector: one idle cycle; done must have dropped, result holds.
            if (i % 4 == 3) begin
                @(posedge clk); @(negedge clk);
                check(result === prev_y && dbz === prev_dbz && sat === prev_sat, LATENCY);
            end
        end
        @(posedge clk); @(negedge clk);  // the last done cycle's contract check
        $sformat(fail_msg, "%0d value checks and %0d cycles of the latency contract failed; first value check: %0s",
                 errors, contract_violations, errors != 0 ? first_msg : "none");
        finish_bench(errors + contract_violations, fail_msg, "");
    end

endmodule

`resetall
