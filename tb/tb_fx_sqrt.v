`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_sqrt - self-checking testbench for rtl/fx_sqrt.v: values and timing.
 *
 * Reads vectors written by tb/gen_vectors.c (record: flags {0,0,0,sat}, radicand,
 * y). Plusargs: +vectors=FILE +n=COUNT +latency=L +name=NAME (L: model/timing.c
 * hw_sqrt_latency, from tb/unit_latency.c).
 * The latency contract (start, busy, done) is tb/serial_latency_check.v's, instantiated here;
 * for every vector the bench checks the values, sampling the outputs between edges
 * (inputs are driven on the falling edge; start is sampled at edge 0):
 *   - after edges 0 .. L - 2: result and sat still hold the previous operation's;
 *   - after edge L - 1 (the done cycle): result and sat as expected;
 *   - done lasts one cycle (an idle cycle after every 4th vector, and the next
 *     operation, which otherwise starts back to back in the done cycle).
 * Every 3rd operation holds start high with random radicands while busy, which
 * must be ignored. After reset, and after a reset in the middle of an operation,
 * busy, done, result and sat must be 0.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_fx_sqrt;

    parameter integer W         = 32;      // width under test
    parameter integer SQRT_BITS = W - 1;   // root bits resolved under test
    parameter integer MAXN      = 1 << 18; // capacity of the vector memory

    localparam integer FD = 4 * ((W + 3) / 4);     // a W-bit field padded to hex digits
    localparam integer RD = 4 * ((2 * W + 3) / 4); // the 2W-bit radicand field
    localparam integer RW = 4 + RD + FD;           // record width

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
    reg  [2*W-1:0]   radicand = {2*W{1'b0}};
    wire             busy, done, sat;
    wire [W-1:0]     result;

    reg  [2*W-1:0]   rad_i;
    reg  [W-1:0]     y_exp, prev_y;
    reg              sat_exp, prev_sat;

    fx_sqrt #(.W(W), .SQRT_BITS(SQRT_BITS)) dut (
        .clk(clk), .reset(reset), .start(start), .radicand(radicand),
        .busy(busy), .done(done), .result(result), .sat(sat));

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
                    $sformat(first_msg, "vector #%0d radicand=%h after edge %0d: busy=%b done=%b result=%h sat=%b, expected result=%h sat=%b",
                             i, rad_i, edge_no, busy, done, result, sat, y_exp, sat_exp);
                errors = errors + 1;
            end
        end
    endtask

    // Inputs while busy: idle, or start held high with a random radicand (ignored).
    task drive_busy;
        begin
            start = (i % 3 == 1);
            radicand = (i % 3 == 1) ? {$random, $random} : rad_i;
        end
    endtask

`include "bench_vectors.vh"

    initial begin
        limit = 64'd1000;
        LATENCY = 2;
        load_vectors("tb_fx_sqrt");
        load_latency(LATENCY, 3, 72);
        limit = n * (LATENCY + 1) + 1000;
        errors = 0;
        i = -1;
        rad_i = 0; y_exp = 0; sat_exp = 0;

        // Reset.
        repeat (2) @(posedge clk);
        @(negedge clk);
        reset = 1'b0;
        check(result === {W{1'b0}} && sat === 1'b0, -1);
        prev_y = {W{1'b0}};
        prev_sat = 1'b0;

        for (i = 0; i < n; i = i + 1) begin
            rad_i   = mem[i][FD +: 2*W];
            sat_exp = mem[i][RW-4];
            y_exp   = mem[i][0 +: W];

            // Once, half way: a reset in the middle of an operation.
            if (i == n / 2) begin
                start = 1'b1;
                radicand = rad_i;
                @(posedge clk); @(negedge clk);
                start = 1'b0;
                @(posedge clk); @(negedge clk);
                reset = 1'b1;
                @(posedge clk); @(negedge clk);
                reset = 1'b0;
                check(result === {W{1'b0}} && sat === 1'b0, -2);
                @(posedge clk); @(negedge clk);
                check(result === {W{1'b0}} && sat === 1'b0, -2);
                prev_y = {W{1'b0}};
                prev_sat = 1'b0;
            end

            // Edge 0: start sampled (in the done cycle of the previous operation,
            // or after an idle cycle).
            start = 1'b1;
            radicand = rad_i;
            @(posedge clk); @(negedge clk);
            drive_busy;
            check(result === prev_y && sat === prev_sat, 0);
            // Edges 1 .. L - 2: iterations, nothing visible changes.
            for (k = 1; k <= LATENCY - 2; k = k + 1) begin
                @(posedge clk); @(negedge clk);
                drive_busy;
                check(result === prev_y && sat === prev_sat, k);
            end
            // Edge L - 1: rounding iteration, result loaded, done.
            @(posedge clk); @(negedge clk);
            start = 1'b0;
            check(result === y_exp && sat === sat_exp, LATENCY - 1);
            prev_y = y_exp;
            prev_sat = sat_exp;
            // Every 4th vector: one idle cycle; done must have dropped, result holds.
            if (i % 4 == 3) begin
                @(posedge clk); @(negedge clk);
                check(result === prev_y && sat === prev_sat, LATENCY);
            end
        end
        @(posedge clk); @(negedge clk);  // the last done cycle's contract check
        $sformat(fail_msg, "%0d value checks and %0d cycles of the latency contract failed; first value check: %0s",
                 errors, contract_violations, errors != 0 ? first_msg : "none");
        finish_bench(errors + contract_violations, fail_msg, "");
    end

endmodule

`resetall
