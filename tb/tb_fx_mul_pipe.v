`default_nettype none
`timescale 1ns / 1ps

/*
 * tb_fx_mul_pipe - self-checking testbench for rtl/fx_mul_pipe.v: values and latency.
 *
 * Reads the vectors of fx_mul (tb/gen_vectors.c, unit mul; record: flags {0,0,0,sat},
 * a, b, y) and streams them, one pair a clock, into fx_mul_pipe, whose exact product
 * goes through fx_round: the pair driven in cycle c must give y and sat in cycle c + L (2),
 * whatever came before and after it. So the split into partial products is checked
 * against model/fixed.c's fx_mul on every operand pair at W = 8 and on edge and random
 * pairs at wider (and odd) widths, and so is the one-block product (W <= ONE_BLOCK_W). Plusargs: +vectors=FILE +n=COUNT
 * +latency=L (tb/unit_latency.c: model/timing.c) +name=NAME.
 * Prints one line, "PASS NAME (N vectors)" or "FAIL NAME: ...", and ends with $fatal
 * (exit status 1) on failure.
 */
module tb_fx_mul_pipe;

    parameter integer W    = 32;      // width under test
    parameter integer F    = 16;      // fraction bits under test
    parameter integer ONE_BLOCK_W = 18; // fx_mul_pipe's: 0 checks the split at any width
    parameter integer MAXN = 1 << 18; // capacity of the vector memory

    localparam integer FD  = 4 * ((W + 3) / 4);  // a W-bit field padded to hex digits
    localparam integer RW  = 4 + 3 * FD;         // record width
    integer            LAT;  // cycles from the operands driven to the result: +latency=, from model/timing.c

    reg [RW-1:0]    mem [0:MAXN-1];
    reg [8*64-1:0]  name;
    reg [8*256-1:0] file;
    reg [8*96-1:0]  note;  // the PASS line's figures
    integer         n, c, v;

    reg             clk = 1'b0;
    reg  [W-1:0]    a = {W{1'b0}}, b = {W{1'b0}};
    wire [2*W-1:0]  prod;
    wire [W-1:0]    y;
    wire            sat;

    fx_mul_pipe #(.W(W), .ONE_BLOCK_W(ONE_BLOCK_W)) dut (.clk(clk), .a(a), .b(b), .prod(prod));
    fx_round #(.W(W), .F(F)) u_round (.prod(prod), .y(y), .sat(sat));

    initial forever #5 clk = !clk;

`include "bench_vectors.vh"

    initial begin
        load_vectors("tb_fx_mul_pipe");
        load_latency(LAT, 1, 64);
        // cycle c: drive pair c (sampled at the edge ending cycle c), check pair c - LAT
        for (c = 0; c < n + LAT; c = c + 1) begin
            @(negedge clk);
            v = c - LAT;
            if (v >= 0 && (y !== mem[v][0 +: W] || sat !== mem[v][RW-4])) begin
                $display("FAIL %0s: vector %0d a=%h b=%h: y=%h sat=%b, expected %h %b", name, v,
                         mem[v][2*FD +: W], mem[v][FD +: W], y, sat, mem[v][0 +: W], mem[v][RW-4]);
                $fatal(1);
            end
            a = c < n ? mem[c][2*FD +: W] : {W{1'b0}};
            b = c < n ? mem[c][FD +: W] : {W{1'b0}};
        end
        $sformat(note, ", one a clock, latency %0d", LAT);
        finish_bench(0, "", note);
    end
endmodule

`resetall
