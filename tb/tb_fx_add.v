`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_add - self-checking testbench for rtl/fx_add.v.
 *
 * Reads vectors written by tb/gen_vectors.c (record: flags {0,0,sat,sub}, a, b, y)
 * and checks y and sat for each. Plusargs: +vectors=FILE +n=COUNT +name=NAME.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with
 * $fatal (exit status 1) on failure or timeout.
 */
module tb_fx_add;

    parameter integer W    = 32;      // width under test
    parameter integer MAXN = 1 << 18; // capacity of the vector memory

    localparam integer FD = 4 * ((W + 3) / 4); // a W-bit field padded to hex digits
    localparam integer RW = 4 + 3 * FD;        // record width

    reg [RW-1:0]   mem [0:MAXN-1];
    reg [8*64-1:0] name;
    reg [8*256-1:0] file;
    reg [8*600-1:0] fail_msg;
    integer        n, i, errors;
    integer        bad_i;
    reg [W-1:0]    bad_got, bad_exp;
    reg            bad_sat_got, bad_sat_exp;

    reg            sub;
    reg  [W-1:0]   a, b;
    wire [W-1:0]   y;
    wire           sat;
    reg  [W-1:0]   y_exp;
    reg            sat_exp;

    fx_add #(.W(W)) dut (.sub(sub), .a(a), .b(b), .y(y), .sat(sat));

    // Watchdog: one vector takes 2 ns.
    initial begin
        #(64'd2 * MAXN + 64'd1000);
        $display("FAIL %0s: timeout", name);
        $fatal(1, "timeout");
    end

`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_fx_add");
        errors = 0;
        bad_i = -1;
        for (i = 0; i < n; i = i + 1) begin
            sub     = mem[i][RW-4];
            sat_exp = mem[i][RW-3];
            a       = mem[i][2*FD +: W];
            b       = mem[i][FD +: W];
            y_exp   = mem[i][0 +: W];
            #1;
            if (y !== y_exp || sat !== sat_exp) begin
                if (errors == 0) begin
                    bad_i = i; bad_got = y; bad_exp = y_exp; bad_sat_got = sat; bad_sat_exp = sat_exp;
                end
                errors = errors + 1;
            end
            #1;
        end
        if (errors != 0)
            $sformat(fail_msg, "%0d of %0d vectors wrong; first #%0d %0s a=%h b=%h: y=%h sat=%b, expected y=%h sat=%b",
                     errors, n, bad_i, mem[bad_i][RW-4] ? "sub" : "add",
                     mem[bad_i][2*FD +: W], mem[bad_i][FD +: W], bad_got, bad_sat_got, bad_exp, bad_sat_exp);
        finish_bench(errors, fail_msg, "");
    end

endmodule

`resetall
