`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_avg - self-checking testbench for rtl/fx_avg.v (fx_avg, and fx_half as b = 0).
 *
 * Reads vectors written by tb/gen_vectors.c (record: flags 0, a, b, y) and checks y
 * for each. Plusargs: +vectors=FILE +n=COUNT +name=NAME.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_fx_avg;

    parameter integer W    = 32;      // width under test
    parameter integer MAXN = 1 << 18; // capacity of the vector memory

    localparam integer FD = 4 * ((W + 3) / 4); // a W-bit field padded to hex digits
    localparam integer RW = 4 + 3 * FD;        // record width

    reg [RW-1:0]    mem [0:MAXN-1];
    reg [8*64-1:0]  name;
    reg [8*256-1:0] file;
    reg [8*600-1:0] fail_msg;
    integer         n, i, errors;
    integer         bad_i;
    reg [W-1:0]     bad_got, bad_exp;

    reg  [W-1:0]    a, b;
    wire [W-1:0]    y;
    reg  [W-1:0]    y_exp;

    fx_avg #(.W(W)) dut (.a(a), .b(b), .y(y));

    // Watchdog: one vector takes 2 ns.
    initial begin
        #(64'd2 * MAXN + 64'd1000);
        $display("FAIL %0s: timeout", name);
        $fatal(1, "timeout");
    end

`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_fx_avg");
        errors = 0;
        bad_i = -1;
        for (i = 0; i < n; i = i + 1) begin
            a     = mem[i][2*FD +: W];
            b     = mem[i][FD +: W];
            y_exp = mem[i][0 +: W];
            #1;
            if (y !== y_exp) begin
                if (errors == 0) begin
                    bad_i = i; bad_got = y; bad_exp = y_exp;
                end
                errors = errors + 1;
            end
            #1;
        end
        if (errors != 0)
            $sformat(fail_msg, "%0d of %0d vectors wrong; first #%0d a=%h b=%h: y=%h, expected %h",
                     errors, n, bad_i, mem[bad_i][2*FD +: W], mem[bad_i][FD +: W], bad_got, bad_exp);
        finish_bench(errors, fail_msg, "");
    end

endmodule

`resetall
